// Command-line flags are read strictly (cli/flags.hpp): a value is written one way only, and
// anything else is bad input naming the flag, one line, exit 2.
#include "cli/flags.hpp"

#include <gtest/gtest.h>
#include <sys/stat.h>

#include <filesystem>
#include <string>

#include "cli/json_in.hpp"
#include "cli_process.hpp"

namespace {

using cli_test::CliResult;
using cli_test::run_cli;

void expect_bad_flag(const std::string& args, const std::string& flag) {
    const CliResult r = run_cli(args);
    EXPECT_EQ(r.status, 2) << args << ": " << r.err;
    EXPECT_EQ(r.out, "") << args;
    EXPECT_EQ(r.err.rfind("error: " + flag + ": ", 0), 0u) << args << ": " << r.err;
    EXPECT_EQ(r.err.find('\n'), r.err.size() - 1) << r.err;
}

TEST(Flags, LenientValuesAreBadInput) {
    const std::string match = "match --game 8ball --players random,random --games 1 ";
    expect_bad_flag(match + "--noise ''", "--noise");
    expect_bad_flag(match + "--noise 0x1", "--noise");
    expect_bad_flag(match + "--noise inf", "--noise");
    expect_bad_flag(match + "--noise ' 1'", "--noise");
    expect_bad_flag(match + "--log ''", "--log");
    expect_bad_flag("match --game 8ball --players random,random --games +1", "--games");
    expect_bad_flag("match --game 8ball --players random,random --games 1.0", "--games");
    expect_bad_flag("bench --runs 0x5", "--runs");
    expect_bad_flag("bench --runs +3", "--runs");
    expect_bad_flag("bench --runs ''", "--runs");
}

TEST(Flags, AFlagWhereAFileNameBelongsIsBadInput) {
    const std::filesystem::path dir = cli_test::temp_path("flags");
    std::filesystem::create_directories(dir);
    const std::string cd = "cd '" + dir.string() + "' && '" + COOLAABER_CLI_PATH + "' ";
    const int status =
        std::system((cd + "match --game 8ball --players random,random --games 1 --log --bogus "
                          ">/dev/null 2>&1")
                        .c_str());
    EXPECT_EQ(WEXITSTATUS(status), 2);
    EXPECT_FALSE(std::filesystem::exists(dir / "--bogus"));
    std::filesystem::remove_all(dir);
}

TEST(Flags, ALogThatIsAFifoOrADirectoryIsRefusedWithoutBlocking) {
    const std::filesystem::path dir = cli_test::temp_path("log-fifo");
    std::filesystem::create_directories(dir);
    const std::filesystem::path fifo = dir / "log.jsonl";
    ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
    const std::string match = "match --game 8ball --players random,random --games 1 --log ";
    expect_bad_flag(match + "'" + fifo.string() + "'", "--log");
    expect_bad_flag(match + "'" + dir.string() + "'", "--log");
    EXPECT_TRUE(std::filesystem::is_fifo(fifo));
    std::filesystem::remove_all(dir);
}

TEST(Flags, AnEmptyInputFileNameIsBadInput) {
    expect_bad_flag("simulate ''", "FILE");
}

TEST(Flags, StrictReaders) {
    EXPECT_EQ(cli::read_integer_flag("--runs", "2000"), 2000);
    EXPECT_EQ(cli::read_integer_flag("--games", "-5"), -5);
    EXPECT_THROW(cli::read_integer_flag("--runs", "99999999999999999999"), cli::BadInput);
    EXPECT_EQ(cli::read_number_flag("--noise", "0.5"), 0.5);
    EXPECT_EQ(cli::read_number_flag("--noise", "1e-3"), 1e-3);
    EXPECT_EQ(cli::read_number_flag("--noise", "-1"), -1.0);  // the range is the verb's to check
    EXPECT_THROW(cli::read_number_flag("--noise", "nan"), cli::BadInput);
    EXPECT_THROW(cli::read_number_flag("--noise", "1,5"), cli::BadInput);
    EXPECT_EQ(cli::read_file_flag("--log", "./-x.jsonl"), "./-x.jsonl");
    EXPECT_THROW(cli::read_file_flag("--log", "-"), cli::BadInput);
}

TEST(Flags, TheDefaultsAndPlainValuesStillWork) {
    EXPECT_EQ(run_cli("bench --runs 2").status, 0);
    EXPECT_EQ(run_cli("match --game 9ball --players random,random --games 2 --noise 0.5").status,
              0);
}

}  // namespace
