#include "game/json_field.hpp"

#include <fmt/format.h>

#include <cmath>

namespace game {

LoadError::LoadError(std::string path, const std::string& message)
    : std::runtime_error(fmt::format("{}: {}", path.empty() ? "input" : path, message)),
      path_(path.empty() ? "input" : std::move(path)),
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

std::string key_list(std::initializer_list<std::initializer_list<std::string_view>> lists) {
    std::string list;
    for (auto keys : lists)
        for (std::string_view k : keys) list += (list.empty() ? "" : ", ") + std::string(k);
    return list;
}

}  // namespace

void Field::fail(const std::string& message) const {
    throw LoadError(path_, message);
}

std::string Field::child(std::string_view key) const {
    return path_.empty() ? std::string(key) : fmt::format("{}.{}", path_, key);
}

void Field::expect_object(std::initializer_list<std::string_view> allowed) const {
    require_fields({}, allowed);
}

void Field::require_fields(std::initializer_list<std::string_view> required,
                           std::initializer_list<std::string_view> optional) const {
    if (!value_->is_object()) fail(fmt::format("expected an object, got {}", type_name(*value_)));
    for (const auto& [key, _] : value_->items()) {
        bool known = false;
        for (auto keys : {required, optional})
            for (std::string_view k : keys) known = known || key == k;
        if (!known)
            throw LoadError(child(key), fmt::format("unknown field (allowed here: {})",
                                                    key_list({required, optional})));
    }
    for (std::string_view k : required)
        if (!value_->contains(k)) throw LoadError(child(k), "missing field: add it");
}

bool Field::has(std::string_view key) const {
    return value_->is_object() && value_->contains(key);
}

Field Field::at(std::string_view key) const {
    if (std::optional<Field> f = find(key)) return *f;
    throw LoadError(child(key), "missing field: add it");
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

double Field::positive() const {
    const double v = number();
    if (!(v > 0)) fail(fmt::format("{} is out of range: must be greater than 0", v));
    return v;
}

double Field::positive_up_to(double hi) const {
    const double v = number();
    if (!(v > 0) || v > hi)
        fail(fmt::format("{} is out of range: must be greater than 0 and at most {}", v, hi));
    return v;
}

std::int64_t Field::integer() const {
    if (value_->is_number_float()) {
        // A whole number written with a fraction part (3.0) is the integer it names.
        const double d = value_->get<double>();
        if (d != std::floor(d)) fail("expected an integer, got a number with a fraction");
        if (!(std::fabs(d) < 9.0e15))
            fail("integer is too large: write it without a fraction part (3, not 3.0)");
        return static_cast<std::int64_t>(d);
    }
    if (!value_->is_number_integer())
        fail(fmt::format("expected an integer, got {}", type_name(*value_)));
    if (value_->is_number_unsigned() && value_->get<std::uint64_t>() > std::uint64_t(INT64_MAX))
        fail("integer is too large");
    return value_->get<std::int64_t>();
}

std::int64_t Field::integer_in(std::int64_t lo, std::int64_t hi) const {
    const std::int64_t v = integer();
    if (v < lo || v > hi) fail(fmt::format("{} is out of range: must be from {} to {}", v, lo, hi));
    return v;
}

std::uint64_t Field::unsigned_integer() const {
    if (value_->is_number_unsigned()) return value_->get<std::uint64_t>();
    if (value_->is_number_float()) {
        // A whole number written with a fraction part (3.0) is the integer it names.
        const double d = value_->get<double>();
        if (d >= 0.0 && d == std::floor(d) && d < 9.0e15) return static_cast<std::uint64_t>(d);
    }
    const bool negative = value_->is_number() && value_->get<double>() < 0.0;
    fail(fmt::format("expected a whole number from 0 to 18446744073709551615, got {}",
                     !value_->is_number() ? type_name(*value_)
                     : negative           ? "a negative number, " + value_->dump()
                                          : value_->dump()));
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

std::string Field::one_of(std::initializer_list<std::string_view> choices) const {
    const std::string s = string();
    std::string list;
    for (std::string_view c : choices) {
        if (s == c) return s;
        list += (list.empty() ? "\"" : ", \"") + std::string(c) + "\"";
    }
    fail(fmt::format("unknown value \"{}\" (expected one of {})", s, list));
}

}  // namespace game
