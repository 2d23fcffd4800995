// Reading JSON input with precise errors: every value knows its JSON path, so a bad document
// gives one line naming the field and what is wrong (docs/cli.md: exit 2).
#pragma once

#include <cstdint>
#include <initializer_list>
#include <nlohmann/json.hpp>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>

namespace cli {

/// Bad input: printed as "error: <path>: <message>", exit status 2.
class BadInput : public std::runtime_error {
  public:
    BadInput(std::string path, const std::string& message);
    const std::string& path() const { return path_; }
    const std::string& detail() const { return detail_; }

  private:
    std::string path_;
    std::string detail_;
};

/// A JSON value and its path (e.g. "balls[3].pos").
class JsonIn {
  public:
    JsonIn(const nlohmann::json& value, std::string path)
        : value_(&value), path_(std::move(path)) {}

    const nlohmann::json& raw() const { return *value_; }
    const std::string& path() const { return path_; }
    bool is_null() const { return value_->is_null(); }

    [[noreturn]] void fail(const std::string& message) const;

    // Objects.
    /// Requires an object with no keys outside `allowed` (unknown fields are errors).
    void expect_object(std::initializer_list<std::string_view> allowed) const;
    bool has(std::string_view key) const;
    /// A required field.
    JsonIn at(std::string_view key) const;
    /// An optional field; absent → empty.
    std::optional<JsonIn> find(std::string_view key) const;

    // Arrays.
    std::size_t array_size() const;  ///< requires an array
    JsonIn at(std::size_t index) const;

    // Scalars.
    double number() const;                         ///< finite number
    double number_in(double lo, double hi) const;  ///< finite number in [lo, hi]
    double positive() const;                       ///< finite number > 0
    double positive_up_to(double hi) const;        ///< finite number in (0, hi]
    std::int64_t integer() const;
    std::int64_t integer_in(std::int64_t lo, std::int64_t hi) const;
    bool boolean() const;
    std::string string() const;
    /// A string that must be one of `choices`.
    std::string one_of(std::initializer_list<std::string_view> choices) const;

  private:
    std::string child_path(std::string_view key) const;

    const nlohmann::json* value_;
    std::string path_;
};

/// Parses a document; malformed JSON throws BadInput with path "input".
nlohmann::json parse_document(const std::string& text);

}  // namespace cli
