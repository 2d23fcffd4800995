#include "audio/pcm.hpp"

#include <algorithm>
#include <cmath>

namespace audio {

float peak(const Pcm& pcm) {
    float p = 0.0f;
    for (float s : pcm.samples) p = std::max(p, std::abs(s));
    return p;
}

void normalize(Pcm& pcm, float level) {
    const float p = peak(pcm);
    if (p <= 0.0f) return;
    const float k = level / p;
    for (float& s : pcm.samples) s *= k;
}

std::vector<std::int16_t> to_int16(const Pcm& pcm) {
    std::vector<std::int16_t> out(pcm.samples.size());
    for (std::size_t i = 0; i < out.size(); ++i) {
        const float s = std::clamp(pcm.samples[i], -1.0f, 1.0f);
        out[i] = static_cast<std::int16_t>(std::lround(s * 32767.0f));
    }
    return out;
}

}  // namespace audio
