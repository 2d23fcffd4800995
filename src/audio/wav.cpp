#include "audio/wav.hpp"

#include <cstdint>
#include <cstring>
#include <fstream>

namespace audio {
namespace {

void put_u32(std::ofstream& f, std::uint32_t v) {
    const char b[4] = {static_cast<char>(v & 0xFF), static_cast<char>((v >> 8) & 0xFF),
                       static_cast<char>((v >> 16) & 0xFF), static_cast<char>((v >> 24) & 0xFF)};
    f.write(b, 4);
}

void put_u16(std::ofstream& f, std::uint16_t v) {
    const char b[2] = {static_cast<char>(v & 0xFF), static_cast<char>((v >> 8) & 0xFF)};
    f.write(b, 2);
}

}  // namespace

bool write_wav(const std::string& path, std::span<const float> samples, int channels, int rate) {
    std::ofstream f(path, std::ios::binary);
    if (!f) return false;
    const auto data_bytes = static_cast<std::uint32_t>(samples.size() * 4);
    const auto ch = static_cast<std::uint16_t>(channels);
    f.write("RIFF", 4);
    put_u32(f, 4 + (8 + 18) + (8 + 4) + (8 + data_bytes));
    f.write("WAVE", 4);
    f.write("fmt ", 4);
    put_u32(f, 18);
    put_u16(f, 3);  // WAVE_FORMAT_IEEE_FLOAT
    put_u16(f, ch);
    put_u32(f, static_cast<std::uint32_t>(rate));
    put_u32(f, static_cast<std::uint32_t>(rate) * ch * 4);
    put_u16(f, static_cast<std::uint16_t>(ch * 4));
    put_u16(f, 32);
    put_u16(f, 0);  // cbSize
    f.write("fact", 4);
    put_u32(f, 4);
    put_u32(f, static_cast<std::uint32_t>(samples.size() / ch));
    f.write("data", 4);
    put_u32(f, data_bytes);
    for (float s : samples) {
        std::uint32_t bits;
        std::memcpy(&bits, &s, 4);
        put_u32(f, bits);
    }
    return static_cast<bool>(f);
}

}  // namespace audio
