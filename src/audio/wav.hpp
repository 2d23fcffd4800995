// Writes 32-bit float WAV files (RIFF WAVE, format 3 = IEEE float), for listening to renders.
#pragma once

#include <span>
#include <string>

namespace audio {

/// Interleaved samples with `channels` channels at `rate` Hz. False if the file can't be written.
bool write_wav(const std::string& path, std::span<const float> interleaved, int channels, int rate);

}  // namespace audio
