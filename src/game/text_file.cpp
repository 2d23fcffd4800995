#include "game/text_file.hpp"

#include <fcntl.h>
#include <fmt/format.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>

namespace game {

namespace {

std::string too_large(std::size_t max_bytes) {
    return fmt::format("larger than {} bytes ({} MiB), the most a document may have", max_bytes,
                       max_bytes >> 20);
}

std::string kind_of(mode_t mode) {
    if (S_ISDIR(mode)) return "a directory";
    if (S_ISFIFO(mode)) return "a FIFO (named pipe)";
    if (S_ISCHR(mode) || S_ISBLK(mode)) return "a device";
    if (S_ISSOCK(mode)) return "a socket";
    return "not a regular file";
}

// Closes the descriptor on every way out.
struct Descriptor {
    int fd;
    ~Descriptor() {
        if (fd >= 0) ::close(fd);
    }
};

}  // namespace

std::string read_regular_file(const std::filesystem::path& path, std::size_t max_bytes) {
    const std::string name = path.string();
    // O_NONBLOCK: opening a FIFO for reading would otherwise wait for a writer, forever.
    const Descriptor file{::open(path.c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC)};
    if (file.fd < 0)
        throw LoadError(name, fmt::format("cannot open the file ({}): check its name and "
                                          "permissions",
                                          std::strerror(errno)));
    struct stat info {};
    if (::fstat(file.fd, &info) != 0)
        throw LoadError(name, fmt::format("cannot read the file ({})", std::strerror(errno)));
    if (!S_ISREG(info.st_mode))
        throw LoadError(name, fmt::format("is {}, not a regular file: give a regular JSON file",
                                          kind_of(info.st_mode)));
    if (static_cast<std::uintmax_t>(info.st_size) > max_bytes)
        throw LoadError(name, fmt::format("the file is {}", too_large(max_bytes)));
    std::string text;
    char buffer[1 << 16];
    while (true) {
        const ssize_t n = ::read(file.fd, buffer, sizeof buffer);
        if (n == 0) break;
        if (n < 0) {
            if (errno == EINTR) continue;
            throw LoadError(name, fmt::format("cannot read the file ({})", std::strerror(errno)));
        }
        // A file that grows while it is read is held to the same limit.
        if (text.size() + static_cast<std::size_t>(n) > max_bytes)
            throw LoadError(name, fmt::format("the file is {}", too_large(max_bytes)));
        text.append(buffer, static_cast<std::size_t>(n));
    }
    return text;
}

std::string read_stream(std::istream& in, const std::string& name, std::size_t max_bytes) {
    std::string text;
    char buffer[1 << 16];
    while (in) {
        in.read(buffer, sizeof buffer);
        const auto n = static_cast<std::size_t>(in.gcount());
        if (text.size() + n > max_bytes)
            throw LoadError(name, fmt::format("the input is {}", too_large(max_bytes)));
        text.append(buffer, n);
    }
    if (in.bad()) throw LoadError(name, "cannot read the input");
    return text;
}

}  // namespace game
