// The CLI reads its documents with the project's one JSON reader (game/json_field.hpp): every
// value knows its JSON path, so bad input gives one line naming the field and what is wrong,
// and exit status 2 (docs/cli.md).
#pragma once

#include <nlohmann/json.hpp>
#include <string_view>

#include "game/json_field.hpp"

namespace cli {

/// Bad input: printed as "error: <path>: <message>", exit status 2.
using BadInput = game::LoadError;

/// A JSON value of the input and its path (e.g. "balls[3].pos").
using JsonIn = game::Field;

/// Parses an input document within the limits of docs/cli.md; bad input throws BadInput with
/// path "input" (or the path of a duplicated key or a too-deep value).
inline nlohmann::json parse_document(std::string_view text) {
    return game::parse_document(text, "");
}

}  // namespace cli
