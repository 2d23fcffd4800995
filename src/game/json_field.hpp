// Reading a save file with precise errors: every value knows its JSON path, so a corrupt or
// foreign file gives one message naming the field, e.g.
// "session.state.on_table[3]: ball 17 does not exist".
#pragma once

#include <cstdint>
#include <initializer_list>
#include <nlohmann/json.hpp>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>

#include "rules/names.hpp"

namespace game {

/// A save file that cannot be loaded. `what()` is "<path>: <message>".
class LoadError : public std::runtime_error {
  public:
    LoadError(std::string path, const std::string& message);
    const std::string& path() const { return path_; }
    const std::string& detail() const { return detail_; }

  private:
    std::string path_;
    std::string detail_;
};

/// Parses a document; malformed JSON, or a key given twice in one object, throws LoadError
/// naming `root` (or the duplicated key's path).
nlohmann::json parse_save_document(const std::string& text, const std::string& root);

/// A JSON value and its path.
class Field {
  public:
    Field(const nlohmann::json& value, std::string path) : value_(&value), path_(std::move(path)) {}

    const nlohmann::json& raw() const { return *value_; }
    const std::string& path() const { return path_; }
    bool is_null() const { return value_->is_null(); }
    [[noreturn]] void fail(const std::string& message) const;

    /// Requires an object holding every key of `required`, any of `optional`, and nothing else.
    void expect_object(std::initializer_list<std::string_view> required,
                       std::initializer_list<std::string_view> optional = {}) const;
    Field at(std::string_view key) const;  ///< a field that must be there
    std::optional<Field> find(std::string_view key) const;

    std::size_t array_size() const;  ///< requires an array
    Field at(std::size_t index) const;

    double number() const;                         ///< a finite number
    double number_in(double lo, double hi) const;  ///< a finite number in [lo, hi]
    std::int64_t integer_in(std::int64_t lo, std::int64_t hi) const;
    std::uint64_t unsigned_integer() const;  ///< 0 to 2^64 − 1
    bool boolean() const;
    std::string string() const;

    /// A name of a rules enum (rules/names.hpp).
    template <typename E>
    E name_of() const {
        const std::string s = string();
        if (std::optional<E> e = rules::parse<E>(s)) return *e;
        std::string list;
        for (std::string_view n : rules::EnumNames<E>::names)
            list += (list.empty() ? "\"" : ", \"") + std::string(n) + "\"";
        fail("unknown value \"" + s + "\" (expected one of " + list + ")");
    }

  private:
    std::string child(std::string_view key) const;

    const nlohmann::json* value_;
    std::string path_;
};

}  // namespace game
