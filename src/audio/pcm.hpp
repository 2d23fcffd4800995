// A mono buffer of samples: what the synthesis makes and the player uploads.
#pragma once

#include <cstdint>
#include <vector>

namespace audio {

struct Pcm {
    int rate = 48000;            ///< sample rate (unit: Hz)
    std::vector<float> samples;  ///< mono, nominally in [−1, 1]

    double duration() const { return static_cast<double>(samples.size()) / rate; }
};

/// Largest |sample|.
float peak(const Pcm& pcm);
/// Scales the buffer so that its peak is `level` (a silent buffer stays silent).
void normalize(Pcm& pcm, float level);
/// 16-bit signed samples, clipped to the range (what OpenAL's AL_FORMAT_MONO16 takes).
std::vector<std::int16_t> to_int16(const Pcm& pcm);

}  // namespace audio
