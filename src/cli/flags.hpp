// Reading the values of command-line flags strictly: a flag's value is written one way only
// (decimal digits, a decimal number, a file name), so that a typo is an error rather than
// another value (`--runs 0x5`, `--noise ''`, `--log --bogus`). Bad values throw BadInput
// naming the flag.
#pragma once

#include <cstdint>
#include <string>
#include <string_view>

namespace cli {

/// A whole number in decimal digits, with an optional leading '-' (no '+', no hex, no spaces).
std::int64_t read_integer_flag(std::string_view flag, const std::string& text);

/// A finite decimal number such as 0.5, 2 or 1e-3 (no '+', no hex, no "inf" or "nan").
double read_number_flag(std::string_view flag, const std::string& text);

/// A file name: not empty, and not starting with '-' (a flag given where its value belongs).
std::string read_file_flag(std::string_view flag, const std::string& text);

}  // namespace cli
