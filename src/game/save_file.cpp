// Saving and loading a session file. Saving writes a temporary file beside the target and
// renames it over the target (atomic on POSIX file systems), after checking that the text reads
// back; loading only reads.
#include <fmt/format.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <chrono>
#include <cstdio>
#include <cstring>
#include <system_error>

#include "game/atomic_file.hpp"
#include "game/json_field.hpp"
#include "game/session.hpp"
#include "game/text_file.hpp"

namespace game {

namespace {

std::filesystem::path temp_beside(const std::filesystem::path& path) {
    static std::atomic<unsigned> counter{0};
    const auto stamp = std::chrono::steady_clock::now().time_since_epoch().count();
    std::filesystem::path tmp = path;
    tmp += fmt::format(".tmp-{}-{}", stamp, counter++);
    return tmp;
}

// Writes all of `text` to a new file `path`; false (with errno's message in `error`) on failure.
bool write_new_file(const std::filesystem::path& path, const std::string& text,
                    std::string& error) {
    std::FILE* f = std::fopen(path.c_str(), "wbx");
    if (!f) {
        error = std::strerror(errno);
        return false;
    }
    const bool written = std::fwrite(text.data(), 1, text.size(), f) == text.size();
    const int saved_errno = errno;
    // On the disk before the rename: a crash then leaves the old file or the whole new one.
    const bool flushed = std::fflush(f) == 0 && ::fsync(::fileno(f)) == 0;
    const bool closed = std::fclose(f) == 0;
    if (!(written && flushed && closed)) {
        error = std::strerror(written ? errno : saved_errno);
        return false;
    }
    return true;
}

// The file a chain of symbolic links ends at (`path` itself when it is no link), so that saving
// replaces that file and keeps the links (e.g. into a folder of dotfiles).
std::filesystem::path link_target(std::filesystem::path path) {
    for (int hops = 0; hops < 40; ++hops) {
        std::error_code ec;
        if (!std::filesystem::is_symlink(std::filesystem::symlink_status(path, ec))) return path;
        const std::filesystem::path to = std::filesystem::read_symlink(path, ec);
        if (ec)
            throw std::runtime_error(fmt::format("cannot save to {}: cannot read the link ({})",
                                                 path.string(), ec.message()));
        path = to.is_absolute() ? to : path.parent_path() / to;
    }
    throw std::runtime_error(
        fmt::format("cannot save to {}: too many links in a chain", path.string()));
}

}  // namespace

void write_file_atomically(const std::filesystem::path& given, const std::string& text) {
    const std::filesystem::path path = link_target(given);
    std::error_code ec;
    // A directory, a FIFO or a device where the file should be is the user's: never replace it.
    const std::filesystem::file_status target = std::filesystem::status(path, ec);
    if (!ec && std::filesystem::exists(target) && !std::filesystem::is_regular_file(target))
        throw std::runtime_error(
            fmt::format("cannot save to {}: it is there and is not a regular file (move it away "
                        "to save here)",
                        path.string()));
    const std::filesystem::path tmp = temp_beside(path);
    std::string error;
    if (!write_new_file(tmp, text, error)) {
        std::error_code ignored;
        std::filesystem::remove(tmp, ignored);
        throw std::runtime_error(fmt::format("cannot save to {}: cannot write {} ({})",
                                             path.string(), tmp.string(), error));
    }
    std::filesystem::rename(tmp, path, ec);
    if (ec) {
        std::error_code ignored;
        std::filesystem::remove(tmp, ignored);
        throw std::runtime_error(fmt::format("cannot save to {}: {}", path.string(), ec.message()));
    }
}

void Session::save_file(const std::filesystem::path& path) const {
    const std::string text = to_json();
    try {
        (void)from_json(text);  // never write a file that would not load
    } catch (const LoadError& e) {
        throw std::logic_error(
            fmt::format("save: the session does not read back ({}); please report this", e.what()));
    }
    write_file_atomically(path, text);
}

Session Session::load_file(const std::filesystem::path& path) {
    return from_json(read_regular_file(path));
}

}  // namespace game
