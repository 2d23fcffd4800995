// Runs the built coolaaber-cli as a separate process (COOLAABER_CLI_PATH), feeding it a
// document on standard input and capturing its exit status, stdout and stderr.
#pragma once

#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <atomic>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

namespace cli_test {

struct CliResult {
    int status = -1;  ///< exit status; -1 if the process did not exit normally (a crash)
    std::string out;
    std::string err;
};

inline std::string slurp(const std::filesystem::path& p) {
    std::ifstream in(p, std::ios::binary);
    std::ostringstream s;
    s << in.rdbuf();
    return s.str();
}

/// A fresh temporary file path, unique per process and call.
inline std::filesystem::path temp_path(const std::string& stem) {
    static std::atomic<int> counter{0};
    return std::filesystem::path(::testing::TempDir()) /
           (stem + "-" + std::to_string(::getpid()) + "-" + std::to_string(counter++));
}

/// Runs `coolaaber-cli <args>` with `input` on standard input.
inline CliResult run_cli(const std::string& args, const std::string& input = "") {
    const std::filesystem::path in = temp_path("cli-in"), out = temp_path("cli-out"),
                                err = temp_path("cli-err");
    {
        std::ofstream f(in, std::ios::binary);
        f << input;
    }
    const std::string command = std::string("'") + COOLAABER_CLI_PATH + "' " + args + " < '" +
                                in.string() + "' > '" + out.string() + "' 2> '" + err.string() +
                                "'";
    const int raw = std::system(command.c_str());
    CliResult r;
    r.status = (raw != -1 && WIFEXITED(raw)) ? WEXITSTATUS(raw) : -1;
    r.out = slurp(out);
    r.err = slurp(err);
    std::filesystem::remove(in);
    std::filesystem::remove(out);
    std::filesystem::remove(err);
    return r;
}

}  // namespace cli_test
