#include "cli/json_in.hpp"

#include <fmt/format.h>

#include <cmath>
#include <set>
#include <vector>

namespace cli {

// The document itself (the empty path) is called "input".
BadInput::BadInput(std::string path, const std::string& message)
    : std::runtime_error(fmt::format("{}: {}", path.empty() ? "input" : path, message)),
      path_(path.empty() ? "input" : std::move(path)),
      detail_(message) {}

void JsonIn::fail(const std::string& message) const {
    throw BadInput(path_, message);
}

static std::string type_name(const nlohmann::json& v) {
    if (v.is_number()) return "a number";
    if (v.is_string()) return "a string";
    if (v.is_boolean()) return "a boolean";
    if (v.is_null()) return "null";
    if (v.is_array()) return "an array";
    return "an object";
}

std::string JsonIn::child_path(std::string_view key) const {
    return path_.empty() ? std::string(key) : fmt::format("{}.{}", path_, key);
}

void JsonIn::expect_object(std::initializer_list<std::string_view> allowed) const {
    if (!value_->is_object()) fail(fmt::format("expected an object, got {}", type_name(*value_)));
    for (const auto& [key, _] : value_->items()) {
        bool known = false;
        for (std::string_view a : allowed) known = known || key == a;
        if (!known) {
            std::string list;
            for (std::string_view a : allowed) list += (list.empty() ? "" : ", ") + std::string(a);
            throw BadInput(child_path(key), fmt::format("unknown field (allowed here: {})", list));
        }
    }
}

bool JsonIn::has(std::string_view key) const {
    return value_->is_object() && value_->contains(key);
}

JsonIn JsonIn::at(std::string_view key) const {
    if (!value_->is_object()) fail(fmt::format("expected an object, got {}", type_name(*value_)));
    auto it = value_->find(key);
    if (it == value_->end()) throw BadInput(child_path(key), "missing required field: add it");
    return JsonIn(*it, child_path(key));
}

std::optional<JsonIn> JsonIn::find(std::string_view key) const {
    if (!value_->is_object()) fail(fmt::format("expected an object, got {}", type_name(*value_)));
    auto it = value_->find(key);
    if (it == value_->end()) return std::nullopt;
    return JsonIn(*it, child_path(key));
}

std::size_t JsonIn::array_size() const {
    if (!value_->is_array()) fail(fmt::format("expected an array, got {}", type_name(*value_)));
    return value_->size();
}

JsonIn JsonIn::at(std::size_t index) const {
    if (!value_->is_array()) fail(fmt::format("expected an array, got {}", type_name(*value_)));
    if (index >= value_->size()) fail(fmt::format("missing element {}", index));
    return JsonIn((*value_)[index], fmt::format("{}[{}]", path_, index));
}

double JsonIn::number() const {
    if (!value_->is_number()) fail(fmt::format("expected a number, got {}", type_name(*value_)));
    double v = value_->get<double>();
    if (!std::isfinite(v)) fail("expected a finite number");
    return v;
}

double JsonIn::number_in(double lo, double hi) const {
    double v = number();
    if (v < lo || v > hi) fail(fmt::format("{} is out of range: must be from {} to {}", v, lo, hi));
    return v;
}

double JsonIn::positive() const {
    double v = number();
    if (!(v > 0)) fail(fmt::format("{} is out of range: must be greater than 0", v));
    return v;
}

double JsonIn::positive_up_to(double hi) const {
    double v = number();
    if (!(v > 0) || v > hi)
        fail(fmt::format("{} is out of range: must be greater than 0 and at most {}", v, hi));
    return v;
}

std::int64_t JsonIn::integer() const {
    if (!value_->is_number_integer()) {
        if (value_->is_number_float()) {
            double d = value_->get<double>();
            if (std::isfinite(d) && d == std::floor(d) && std::fabs(d) < 9.0e15)
                return static_cast<std::int64_t>(d);
        }
        fail(fmt::format("expected an integer, got {}", type_name(*value_)));
    }
    if (value_->is_number_unsigned() && value_->get<std::uint64_t>() > INT64_MAX)
        fail("integer is too large");
    return value_->get<std::int64_t>();
}

std::int64_t JsonIn::integer_in(std::int64_t lo, std::int64_t hi) const {
    std::int64_t v = integer();
    if (v < lo || v > hi) fail(fmt::format("{} is out of range: must be from {} to {}", v, lo, hi));
    return v;
}

bool JsonIn::boolean() const {
    if (!value_->is_boolean())
        fail(fmt::format("expected true or false, got {}", type_name(*value_)));
    return value_->get<bool>();
}

std::string JsonIn::string() const {
    if (!value_->is_string()) fail(fmt::format("expected a string, got {}", type_name(*value_)));
    return value_->get<std::string>();
}

std::string JsonIn::one_of(std::initializer_list<std::string_view> choices) const {
    std::string s = string();
    std::string list;
    for (std::string_view c : choices) {
        if (s == c) return s;
        list += (list.empty() ? "\"" : ", \"") + std::string(c) + "\"";
    }
    fail(fmt::format("unknown value \"{}\" (expected one of {})", s, list));
}

namespace {

/// Tracks where the parser is (a JSON path) so that a field given twice in one object is
/// reported by its path: nlohmann keeps only the last one, which would silently ignore the first.
class DuplicateKeyCheck {
  public:
    bool operator()(int /*depth*/, nlohmann::json::parse_event_t event, nlohmann::json& parsed) {
        using E = nlohmann::json::parse_event_t;
        switch (event) {
            case E::object_start:
            case E::array_start:
                if (!frames_.empty() && !frames_.back().object) ++frames_.back().index;
                frames_.push_back({event == E::object_start, {}, {}, -1});
                break;
            case E::object_end:
            case E::array_end:
                if (!frames_.empty()) frames_.pop_back();
                break;
            case E::key: {
                Frame& f = frames_.back();
                f.key = parsed.get<std::string>();
                if (!f.keys.insert(f.key).second)
                    throw BadInput(path(),
                                   "field given twice in one object: keep only one of them");
                break;
            }
            case E::value:
                if (!frames_.empty() && !frames_.back().object) ++frames_.back().index;
                break;
        }
        return true;
    }

  private:
    // An object or array being read; its current key or index names the child being read.
    struct Frame {
        bool object;
        std::set<std::string> keys;  // keys read so far (objects)
        std::string key;             // last key read (objects)
        long index;                  // index of the last element started (arrays)
    };

    // The path of the value being read (built only for an error message).
    std::string path() const {
        std::string p;
        for (const Frame& f : frames_) {
            if (f.object)
                p += (p.empty() ? "" : ".") + f.key;
            else
                p += fmt::format("[{}]", f.index);
        }
        return p;
    }

    std::vector<Frame> frames_;
};

std::string one_line(std::string s) {
    for (char& c : s)
        if (c == '\n' || c == '\r' || c == '\t') c = ' ';
    return s;
}

}  // namespace

nlohmann::json parse_document(const std::string& text) {
    try {
        return nlohmann::json::parse(text, DuplicateKeyCheck{});
    } catch (const nlohmann::json::parse_error& e) {
        std::string what = e.what();
        auto pos = what.find("parse error");
        throw BadInput("input",
                       one_line(fmt::format("not valid JSON ({}); check the document's syntax",
                                            pos == std::string::npos ? what : what.substr(pos))));
    } catch (const nlohmann::json::out_of_range& e) {
        // e.g. a number too large for a double (1e400).
        std::string what = e.what();
        auto pos = what.find("] ");
        throw BadInput(
            "input", one_line(fmt::format("not a usable JSON document ({}); use finite numbers",
                                          pos == std::string::npos ? what : what.substr(pos + 2))));
    } catch (const nlohmann::json::exception& e) {
        throw BadInput("input", one_line(fmt::format("not a usable JSON document ({})", e.what())));
    }
}

}  // namespace cli
