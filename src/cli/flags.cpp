#include "cli/flags.hpp"

#include <fmt/format.h>

#include <charconv>
#include <cmath>
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

double read_number_flag(std::string_view flag, const std::string& text) {
    double value = 0.0;
    const char* end = text.data() + text.size();
    const auto [ptr, ec] = std::from_chars(text.data(), end, value, std::chars_format::general);
    if (!text.empty() && ptr == end &&
        (ec == std::errc::result_out_of_range || (ec == std::errc() && !std::isfinite(value))))
        throw BadInput(std::string(flag),
                       fmt::format("{} is not a finite number: write a decimal number "
                                   "within ±1.8e308, e.g. 0.5",
                                   text));
    if (text.empty() || ec != std::errc() || ptr != end)
        throw BadInput(
            std::string(flag),
            fmt::format("\"{}\" is not a number: write a decimal number, e.g. 0.5", text));
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
