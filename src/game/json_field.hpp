// The one JSON reader of the project: every value knows its JSON path, so a bad document gives
// one message naming the field and what is wrong, e.g. "session.state.on_table[3]: ball 17 does
// not exist". The CLI reads its input with it too (cli/json_in.hpp) and maps LoadError to exit
// status 2 (docs/cli.md).
#pragma once

#include <cstddef>
#include <cstdint>
#include <initializer_list>
#include <nlohmann/json.hpp>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>

#include "rules/names.hpp"

namespace game {

/// A document that cannot be read. `what()` is "<path>: <message>"; the empty path (the
/// document itself) is called "input".
class LoadError : public std::runtime_error {
  public:
    LoadError(std::string path, const std::string& message);
    const std::string& path() const { return path_; }
    const std::string& detail() const { return detail_; }

  private:
    std::string path_;
    std::string detail_;
};

/// The limits of a document (docs/cli.md, "Limits"): far above any real input, they bound the
/// time and memory that reading it takes.
inline constexpr std::size_t max_document_bytes = std::size_t{64} << 20;  ///< 64 MiB
inline constexpr std::size_t max_document_depth = 64;  ///< arrays and objects, one in another

/// Parses a document in time linear in its size. Malformed JSON, a NUL byte, a number beyond a
/// double, a key given twice in one object, a document over the limits: LoadError naming
/// `root` (or the path of the duplicated key or of the too-deep value), where the paths of the
/// document's values start ("" for the CLI's documents, "session" for a saved game).
nlohmann::json parse_document(std::string_view text, const std::string& root);

/// A JSON value and its path.
class Field {
  public:
    Field(const nlohmann::json& value, std::string path) : value_(&value), path_(std::move(path)) {}

    const nlohmann::json& raw() const { return *value_; }
    const std::string& path() const { return path_; }
    bool is_null() const { return value_->is_null(); }
    [[noreturn]] void fail(const std::string& message) const;

    // Objects.
    /// Requires an object with no keys outside `allowed` (unknown fields are errors).
    void expect_object(std::initializer_list<std::string_view> allowed) const;
    /// Requires an object holding every key of `required`, any of `optional`, and nothing else.
    void require_fields(std::initializer_list<std::string_view> required,
                        std::initializer_list<std::string_view> optional = {}) const;
    bool has(std::string_view key) const;
    Field at(std::string_view key) const;  ///< a field that must be there
    std::optional<Field> find(std::string_view key) const;

    // Arrays.
    std::size_t array_size() const;  ///< requires an array
    Field at(std::size_t index) const;

    // Scalars.
    double number() const;                         ///< a finite number
    double number_in(double lo, double hi) const;  ///< a finite number in [lo, hi]
    double positive() const;                       ///< a finite number > 0
    double positive_up_to(double hi) const;        ///< a finite number in (0, hi]
    std::int64_t integer() const;                  ///< a whole number (3 or 3.0)
    std::int64_t integer_in(std::int64_t lo, std::int64_t hi) const;
    std::uint64_t unsigned_integer() const;  ///< 0 to 2^64 − 1
    bool boolean() const;
    std::string string() const;
    /// A string that must be one of `choices`.
    std::string one_of(std::initializer_list<std::string_view> choices) const;

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
