#include "cli/flags.hpp"

#include <fmt/format.h>

#include <charconv>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <system_error>

#include "cli/json_in.hpp"

namespace cli {

std::int64_t read_integer_flag(std::string_view flag, const std::string& text) {
    std::int64_t value = 0;
    const char* end = text.data() + text.size();
    const auto [ptr, ec] = std::from_chars(text.data(), end, value, 10);
    if (text.empty() || ec == std::errc::invalid_argument || ptr != end)
        throw BadInput(std::string(flag),
                       fmt::format("\"{}\" is not a whole number: write it in decimal digits, "
                                   "e.g. 100",
                                   text));
    if (ec == std::errc::result_out_of_range)
        throw BadInput(std::string(flag),
                       fmt::format("{} is too large: at most 9223372036854775807 (each verb "
                                   "says its own range)",
                                   text));
    return value;
}

namespace {

std::size_t skip_digits(std::string_view t, std::size_t i) {
    while (i < t.size() && t[i] >= '0' && t[i] <= '9') ++i;
    return i;
}

/// [-]digits[.digits][(e|E)[±]digits], with a digit before or after the point; not spaces, '+',
/// hexadecimal or words, which strtod alone would take.
bool is_decimal(std::string_view t) {
    std::size_t i = t.starts_with('-') ? 1 : 0;
    const std::size_t int_end = skip_digits(t, i);
    std::size_t end = int_end;
    if (end < t.size() && t[end] == '.') end = skip_digits(t, end + 1);
    if (end - i < 1 + (end > int_end ? 1 : 0)) return false;  // no digit at all
    if (end < t.size() && (t[end] == 'e' || t[end] == 'E')) {
        std::size_t e = end + 1;
        if (e < t.size() && (t[e] == '+' || t[e] == '-')) ++e;
        end = skip_digits(t, e);
        if (end == e) return false;
    }
    return end == t.size();
}

}  // namespace

double read_number_flag(std::string_view flag, const std::string& text) {
    if (!is_decimal(text))
        throw BadInput(
            std::string(flag),
            fmt::format("\"{}\" is not a number: write a decimal number, e.g. 0.5", text));
    // strtod, not from_chars: Emscripten's libc++ has no from_chars for doubles. The CLI
    // never changes the C locale, so the point is '.'.
    const double value = std::strtod(text.c_str(), nullptr);
    if (!std::isfinite(value))
        throw BadInput(std::string(flag),
                       fmt::format("{} is not a finite number: write a decimal number "
                                   "within ±1.8e308, e.g. 0.5",
                                   text));
    return value;
}

std::string read_file_flag(std::string_view flag, const std::string& text) {
    if (text.empty())
        throw BadInput(std::string(flag), "an empty file name: give the file to write");
    if (text[0] == '-')
        throw BadInput(std::string(flag),
                       fmt::format("\"{}\" looks like a flag, not a file name: give the file "
                                   "(./{} for a file of that name)",
                                   text, text));
    // Opening a FIFO or a device to write could block, or write where no file is wanted.
    std::error_code ec;
    const std::filesystem::file_status status = std::filesystem::status(text, ec);
    if (std::filesystem::exists(status) && !std::filesystem::is_regular_file(status))
        throw BadInput(
            std::string(flag),
            fmt::format("\"{}\" exists and is not a regular file: give a file to write", text));
    return text;
}

}  // namespace cli
