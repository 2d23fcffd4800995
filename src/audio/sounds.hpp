// The table's sounds, synthesized at start-up (no sample files): each kind has several
// variants made from one seed, so that repeated hits do not sound identical.
#pragma once

#include <array>
#include <cstdint>
#include <string_view>
#include <vector>

#include "audio/pcm.hpp"

namespace audio {

enum class SoundKind : std::uint8_t {
    ball_click,     ///< ball–ball: the bright, short phenolic click
    cushion_thump,  ///< ball–rail: a rubber thump through the wooden rail
    pocket_drop,    ///< a ball dropping into a pocket and rattling against its jaws and liner
    cue_strike,     ///< the leather cue tip striking the cue ball
    jaw_rattle,     ///< a ball knocking on a pocket jaw (a cushion event at a jaw)
    ball_return,    ///< a potted ball clattering down the channel into the ball return
    cloth_roll,     ///< a ball rolling on the cloth: a seamless loop, its gain set by the speed
};
inline constexpr int kSoundKindCount = 7;
std::string_view to_string(SoundKind kind);

/// One sound: `rate` Hz mono, onset at sample 0 (the contact starts there), peak `level(kind)`.
/// The same (kind, seed, rate) gives the same samples.
Pcm synthesize(SoundKind kind, std::uint64_t seed, int rate = 48000);

/// Peak level of each kind at full loudness, which sets their balance (unit: full scale).
float level(SoundKind kind);

struct SoundBankOptions {
    int rate = 48000;        ///< synthesis sample rate (unit: Hz)
    int variants = 6;        ///< variants per kind (≥ 1)
    std::uint64_t seed = 1;  ///< the bank is a pure function of the seed
};

/// Every kind's variants, made once at start-up (tens of milliseconds on one core).
struct SoundBank {
    std::array<std::vector<Pcm>, kSoundKindCount> sounds;

    const Pcm& get(SoundKind kind, int variant) const;
    int variants() const { return static_cast<int>(sounds[0].size()); }
};
SoundBank make_sound_bank(const SoundBankOptions& options = {});

}  // namespace audio
