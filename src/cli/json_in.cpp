#include "cli/json_in.hpp"

#include <cmath>

#include <fmt/format.h>

namespace cli {

BadInput::BadInput(std::string path, const std::string& message)
    : std::runtime_error(fmt::format("{}: {}", path, message)), path_(std::move(path)),
      detail_(message) {}

void JsonIn::fail(const std::string& message) const { throw BadInput(path_, message); }

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
    if (it == value_->end()) throw BadInput(child_path(key), "missing required field");
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
    if (!value_->is_boolean()) fail(fmt::format("expected true or false, got {}", type_name(*value_)));
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

nlohmann::json parse_document(const std::string& text) {
    try {
        return nlohmann::json::parse(text);
    } catch (const nlohmann::json::parse_error& e) {
        std::string what = e.what();
        auto pos = what.find("parse error");
        throw BadInput("input", fmt::format("not valid JSON ({})",
                                            pos == std::string::npos ? what : what.substr(pos)));
    }
}

}  // namespace cli
