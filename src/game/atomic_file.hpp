// Writing a file so that it is either the old one or the new one, never half-written.
#pragma once

#include <filesystem>
#include <string>

namespace game {

/// Writes `text` to a temporary file beside `path` and renames it over `path`. Throws
/// std::runtime_error naming the path and the reason (the old file untouched) when it cannot.
void write_file_atomically(const std::filesystem::path& path, const std::string& text);

}  // namespace game
