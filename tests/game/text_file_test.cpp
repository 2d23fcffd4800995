// Reading a document from a file or a stream (game/text_file.hpp): only regular files, never
// blocking on a FIFO, within the size limit.
#include "game/text_file.hpp"

#include <gtest/gtest.h>
#include <sys/stat.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <sstream>

namespace game {
namespace {

namespace fs = std::filesystem;

fs::path fresh_dir() {
    static int counter = 0;
    const fs::path dir =
        fs::path(::testing::TempDir()) /
        ("text-file-" + std::to_string(::getpid()) + "-" + std::to_string(counter++));
    fs::remove_all(dir);
    fs::create_directories(dir);
    return dir;
}

std::string error_of(const fs::path& path, std::size_t max_bytes = max_document_bytes) {
    try {
        (void)read_regular_file(path, max_bytes);
    } catch (const LoadError& e) {
        EXPECT_EQ(e.path(), path.string());
        return e.detail();
    }
    return "";
}

TEST(ReadRegularFile, ReadsAllOfAFile) {
    const fs::path file = fresh_dir() / "doc.json";
    std::string text(200000, 'x');
    text[100] = '\0';
    std::ofstream(file, std::ios::binary) << text;
    EXPECT_EQ(read_regular_file(file), text);
}

TEST(ReadRegularFile, RefusesWhatIsNotARegularFile) {
    const fs::path dir = fresh_dir();
    EXPECT_EQ(error_of(dir).rfind("is a directory, not a regular file", 0), 0u) << error_of(dir);
    EXPECT_EQ(error_of("/dev/zero").rfind("is a device, not a regular file", 0), 0u);
    // A FIFO without a writer: opening it must not wait for one.
    const fs::path fifo = dir / "fifo";
    ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
    EXPECT_EQ(error_of(fifo).rfind("is a FIFO (named pipe), not a regular file", 0), 0u)
        << error_of(fifo);
    EXPECT_EQ(error_of(dir / "missing.json").rfind("cannot open the file", 0), 0u);
}

TEST(ReadRegularFile, RefusesAFileOverTheLimit) {
    const fs::path file = fresh_dir() / "big.json";
    std::ofstream(file, std::ios::binary) << std::string(1001, ' ');
    EXPECT_EQ(read_regular_file(file, 1001).size(), 1001u);
    EXPECT_EQ(error_of(file, 1000).rfind("the file is larger than 1000 bytes", 0), 0u)
        << error_of(file, 1000);
}

TEST(ReadStream, ReadsUpToTheLimit) {
    std::istringstream in(std::string(300000, 'y'));
    EXPECT_EQ(read_stream(in, "-", 300000).size(), 300000u);
    std::istringstream more(std::string(300001, 'y'));
    try {
        (void)read_stream(more, "-", 300000);
        FAIL();
    } catch (const LoadError& e) {
        EXPECT_EQ(e.path(), "-");
        EXPECT_EQ(e.detail().rfind("the input is larger than 300000 bytes", 0), 0u) << e.detail();
    }
}

}  // namespace
}  // namespace game
