// The limits on an input document (docs/cli.md, "Limits"): regular files only, 64 MiB, 64
// levels of nesting, no NUL byte; parsing in linear time. Each is bad input: exit 2, one line.
#include <gtest/gtest.h>
#include <sys/stat.h>

#include <chrono>
#include <string>

#include "cli_process.hpp"

namespace {

using cli_test::CliResult;
using cli_test::run_cli;

void expect_bad_input(const CliResult& r, const std::string& prefix) {
    EXPECT_EQ(r.status, 2) << r.err;
    EXPECT_EQ(r.out, "");
    EXPECT_EQ(r.err.rfind("error: " + prefix, 0), 0u) << r.err;
    EXPECT_EQ(r.err.find('\n'), r.err.size() - 1) << r.err;
}

TEST(InputLimits, ANulByteAndWhatFollowsIsRefused) {
    using namespace std::string_literals;
    expect_bad_input(run_cli("simulate", "{\"balls\":[]}\0{{{{ not json"s),
                     "input: a NUL byte at offset 12");
}

TEST(InputLimits, AFileThatIsNotRegularIsRefused) {
    expect_bad_input(run_cli("simulate /dev/zero"), "/dev/zero: is a device, not a regular file");
    const std::string fifo = cli_test::temp_path("fifo").string();
    ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
    // Without a writer: must not wait for one.
    expect_bad_input(run_cli("judge '" + fifo + "'"), fifo + ": is a FIFO");
    std::remove(fifo.c_str());
}

TEST(InputLimits, StandardInputIsCapped) {
    const std::string big = "[" + std::string(64u << 20, ' ') + "]";
    expect_bad_input(run_cli("simulate", big), "-: the input is larger than 67108864 bytes");
}

TEST(InputLimits, NestingDeeperThanSixtyFourIsRefused) {
    const std::string deep = std::string(65, '[') + std::string(65, ']');
    expect_bad_input(run_cli("decide", deep), "[0][0]");
    EXPECT_NE(run_cli("decide", deep).err.find("nested more than 64 levels"), std::string::npos);
}

TEST(InputLimits, AMillionObjectsInAnArrayParseQuickly) {
    // A parser that rescans the parent array at each object's end would take minutes here.
    std::string text = "[";
    for (int i = 0; i < 1'000'000; ++i) text += i ? ",{}" : "{}";
    text += "]";
    const auto start = std::chrono::steady_clock::now();
    expect_bad_input(run_cli("simulate", text), "input: expected an object, got an array");
    EXPECT_LT(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(),
              10.0);
}

}  // namespace
