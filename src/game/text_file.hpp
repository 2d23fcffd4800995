// Reading a document from a file or a stream, within the size limit of a document
// (game/json_field.hpp): the CLI's input, a saved game and the game's settings all read here.
#pragma once

#include <cstddef>
#include <filesystem>
#include <istream>
#include <string>

#include "game/json_field.hpp"

namespace game {

/// The whole of a regular file. A missing or unreadable file, a directory, a FIFO, a device or
/// anything else that is not a regular file (it could block or never end), or a file larger
/// than `max_bytes`: LoadError naming the path. Never blocks on a FIFO.
std::string read_regular_file(const std::filesystem::path& path,
                              std::size_t max_bytes = max_document_bytes);

/// All of `in` (e.g. standard input) up to `max_bytes`; more, or a read error: LoadError naming
/// `name`.
std::string read_stream(std::istream& in, const std::string& name,
                        std::size_t max_bytes = max_document_bytes);

}  // namespace game
