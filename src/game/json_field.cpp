#include "game/json_field.hpp"

#include <fmt/format.h>

#include <cmath>
#include <set>
#include <vector>

namespace game {

LoadError::LoadError(std::string path, const std::string& message)
    : std::runtime_error(fmt::format("{}: {}", path, message)),
      path_(std::move(path)),
      detail_(message) {}

namespace {

std::string type_name(const nlohmann::json& v) {
    if (v.is_number()) return "a number";
    if (v.is_string()) return "a string";
    if (v.is_boolean()) return "a boolean";
    if (v.is_null()) return "null";
    if (v.is_array()) return "an array";
    return "an object";
}

std::string one_line(std::string s) {
    for (char& c : s)
        if (c == '\n' || c == '\r' || c == '\t') c = ' ';
    return s;
}

/// Follows the parser's position so that a key given twice in one object is reported by its
/// path (nlohmann keeps only the last one, which would hide the first).
class DuplicateKeyCheck {
  public:
    explicit DuplicateKeyCheck(std::string root) : root_(std::move(root)) {}

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
                    throw LoadError(path(), "field given twice in one object");
                break;
            }
            case E::value:
                if (!frames_.empty() && !frames_.back().object) ++frames_.back().index;
                break;
        }
        return true;
    }

  private:
    struct Frame {
        bool object;
        std::set<std::string> keys;
        std::string key;
        long index;
    };

    std::string path() const {
        std::string p = root_;
        for (const Frame& f : frames_) p += f.object ? "." + f.key : fmt::format("[{}]", f.index);
        return p;
    }

    std::string root_;
    std::vector<Frame> frames_;
};

}  // namespace

nlohmann::json parse_save_document(const std::string& text, const std::string& root) {
    try {
        return nlohmann::json::parse(text, DuplicateKeyCheck{root});
    } catch (const nlohmann::json::exception& e) {
        std::string what = e.what();
        auto pos = what.find("] ");
        throw LoadError(
            root, one_line(fmt::format("not a valid JSON document ({})",
                                       pos == std::string::npos ? what : what.substr(pos + 2))));
    }
}

void Field::fail(const std::string& message) const {
    throw LoadError(path_, message);
}

std::string Field::child(std::string_view key) const {
    return fmt::format("{}.{}", path_, key);
}

void Field::expect_object(std::initializer_list<std::string_view> required,
                          std::initializer_list<std::string_view> optional) const {
    if (!value_->is_object()) fail(fmt::format("expected an object, got {}", type_name(*value_)));
    for (const auto& [key, _] : value_->items()) {
        bool known = false;
        for (std::string_view k : required) known = known || key == k;
        for (std::string_view k : optional) known = known || key == k;
        if (!known) {
            std::string list;
            for (auto keys : {required, optional})
                for (std::string_view k : keys) list += (list.empty() ? "" : ", ") + std::string(k);
            throw LoadError(child(key), fmt::format("unknown field (expected here: {})", list));
        }
    }
    for (std::string_view k : required)
        if (!value_->contains(k)) throw LoadError(child(k), "missing field");
}

Field Field::at(std::string_view key) const {
    if (!value_->is_object()) fail(fmt::format("expected an object, got {}", type_name(*value_)));
    auto it = value_->find(key);
    if (it == value_->end()) throw LoadError(child(key), "missing field");
    return Field(*it, child(key));
}

std::optional<Field> Field::find(std::string_view key) const {
    if (!value_->is_object()) fail(fmt::format("expected an object, got {}", type_name(*value_)));
    auto it = value_->find(key);
    if (it == value_->end()) return std::nullopt;
    return Field(*it, child(key));
}

std::size_t Field::array_size() const {
    if (!value_->is_array()) fail(fmt::format("expected an array, got {}", type_name(*value_)));
    return value_->size();
}

Field Field::at(std::size_t index) const {
    if (index >= array_size()) fail(fmt::format("missing element {}", index));
    return Field((*value_)[index], fmt::format("{}[{}]", path_, index));
}

double Field::number() const {
    if (!value_->is_number()) fail(fmt::format("expected a number, got {}", type_name(*value_)));
    const double v = value_->get<double>();
    if (!std::isfinite(v)) fail("expected a finite number");
    return v;
}

double Field::number_in(double lo, double hi) const {
    const double v = number();
    if (!(v >= lo && v <= hi))
        fail(fmt::format("{} is out of range: must be from {} to {}", v, lo, hi));
    return v;
}

std::int64_t Field::integer_in(std::int64_t lo, std::int64_t hi) const {
    if (!value_->is_number_integer())
        fail(fmt::format("expected an integer, got {}", value_->is_number_float()
                                                            ? "a number with a fraction"
                                                            : type_name(*value_)));
    if (value_->is_number_unsigned() && value_->get<std::uint64_t>() > std::uint64_t(INT64_MAX))
        fail(fmt::format("integer is out of range: must be from {} to {}", lo, hi));
    const std::int64_t v = value_->get<std::int64_t>();
    if (v < lo || v > hi) fail(fmt::format("{} is out of range: must be from {} to {}", v, lo, hi));
    return v;
}

std::uint64_t Field::unsigned_integer() const {
    if (value_->is_number_unsigned()) return value_->get<std::uint64_t>();
    if (value_->is_number_integer()) fail("must not be negative");
    fail(fmt::format("expected an integer from 0 to 18446744073709551615, got {}",
                     type_name(*value_)));
}

bool Field::boolean() const {
    if (!value_->is_boolean())
        fail(fmt::format("expected true or false, got {}", type_name(*value_)));
    return value_->get<bool>();
}

std::string Field::string() const {
    if (!value_->is_string()) fail(fmt::format("expected a string, got {}", type_name(*value_)));
    return value_->get<std::string>();
}

}  // namespace game
