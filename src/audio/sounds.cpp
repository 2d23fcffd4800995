#include "audio/sounds.hpp"

#include <cassert>

#include "audio/rng.hpp"
#include "audio/synth.hpp"

namespace audio {
namespace {

using synth::Biquad;
using synth::Contact;
using synth::Mode;

/// A mode whose frequency, decay and amplitude are jittered for one variant.
Mode vary(Rng& rng, double freq, double decay, double amp) {
    return {freq * rng.jitter(0.06), decay * rng.jitter(0.15), amp * rng.jitter(0.2)};
}

Pcm blank(int rate, double seconds) {
    Pcm p;
    p.rate = rate;
    p.samples.assign(static_cast<std::size_t>(seconds * rate), 0.0f);
    return p;
}

// Phenolic resin balls ring high and die fast: most energy at 3–8 kHz within ~10 ms, over a
// near-instant contact (~0.1 ms, so the attack is a few tens of µs) with a bright noise tick.
Pcm ball_click(std::uint64_t seed, int rate) {
    Rng rng(seed);
    Pcm p = blank(rate, 0.08);
    const Contact hit{0.0, 3e-5};
    const Mode modes[] = {vary(rng, 3300, 0.0070, 1.0), vary(rng, 5100, 0.0045, 0.7),
                          vary(rng, 7400, 0.0030, 0.5), vary(rng, 10400, 0.0020, 0.3),
                          vary(rng, 1150, 0.0080, 0.2)};
    synth::add_modes(p, hit, modes, 5, rng);
    synth::add_noise_burst(p, hit, 0.0012 * rng.jitter(0.2), 0.8,
                           Biquad::bandpass(rate, 6000 * rng.jitter(0.1), 0.8), rng, 0.02);
    return p;
}

// The ball sinks into the rubber for a few ms (a slower attack), the rail's wood booms low,
// with a duller knock on top.
Pcm cushion_thump(std::uint64_t seed, int rate) {
    Rng rng(seed);
    Pcm p = blank(rate, 0.3);
    const Contact hit{0.0, 6e-4};
    const Mode modes[] = {vary(rng, 95, 0.060, 1.0),   vary(rng, 160, 0.045, 0.8),
                          vary(rng, 245, 0.035, 0.55), vary(rng, 420, 0.025, 0.4),
                          vary(rng, 780, 0.012, 0.35), vary(rng, 1600, 0.006, 0.25),
                          vary(rng, 3300, 0.004, 0.2)};  // the ball itself rings a little
    synth::add_modes(p, hit, modes, 7, rng);
    synth::add_noise_burst(p, hit, 0.006 * rng.jitter(0.2), 1.2,
                           Biquad::lowpass(rate, 1600 * rng.jitter(0.1), 0.7), rng, 0.05);
    return p;
}

// A hard knock as the ball lands in the pocket, then the rumble of it rolling down the return
// track; the rumble fades in slowly so that it adds no second onset.
Pcm pocket_drop(std::uint64_t seed, int rate) {
    Rng rng(seed);
    Pcm p = blank(rate, 1.3);
    const Contact hit{0.0, 2e-4};
    const Mode modes[] = {vary(rng, 140, 0.070, 1.0), vary(rng, 265, 0.050, 0.8),
                          vary(rng, 520, 0.030, 0.5), vary(rng, 1100, 0.015, 0.35),
                          vary(rng, 2300, 0.006, 0.2)};
    synth::add_modes(p, hit, modes, 5, rng);
    synth::add_noise_burst(p, hit, 0.010 * rng.jitter(0.2), 0.8,
                           Biquad::lowpass(rate, 1500 * rng.jitter(0.1), 0.7), rng, 0.08);
    synth::Rumble roll;
    roll.start = 0.10 * rng.jitter(0.2);
    roll.rise = 0.25;
    roll.hold = 0.25 * rng.jitter(0.3);
    roll.fall = 0.45;
    roll.amp = 1.0;  // band-passed noise is weak: this puts the rumble about 25 dB under the knock
    roll.wobble = 0.4;
    roll.wobble_hz = 3.0 * rng.jitter(0.2);
    synth::add_rumble(p, roll, Biquad::bandpass(rate, 220 * rng.jitter(0.1), 1.5),
                      Biquad::lowpass(rate, 450, 0.7), rng);
    return p;
}

// Leather on phenolic: duller than a ball click (a softer, ~1 ms contact) with the shaft's
// woody ring around 600 Hz.
Pcm cue_strike(std::uint64_t seed, int rate) {
    Rng rng(seed);
    Pcm p = blank(rate, 0.12);
    const Contact hit{0.0, 2e-4};
    const Mode modes[] = {vary(rng, 620, 0.025, 0.5), vary(rng, 1500, 0.012, 1.0),
                          vary(rng, 2900, 0.008, 0.6), vary(rng, 4300, 0.005, 0.3)};
    synth::add_modes(p, hit, modes, 4, rng);
    synth::add_noise_burst(p, hit, 0.003 * rng.jitter(0.2), 0.5,
                           Biquad::bandpass(rate, 2500 * rng.jitter(0.1), 1.0), rng, 0.03);
    return p;
}

// A jaw is a short rubber facing backed by the pocket's hard plate: a harder, woodier knock
// than a rail, with a quick buzz of the ball against the facing (ticks within 15 ms).
Pcm jaw_rattle(std::uint64_t seed, int rate) {
    Rng rng(seed);
    Pcm p = blank(rate, 0.2);
    const Contact hit{0.0, 3e-4};
    const Mode modes[] = {vary(rng, 185, 0.040, 1.0), vary(rng, 330, 0.030, 0.8),
                          vary(rng, 730, 0.020, 0.6), vary(rng, 1350, 0.012, 0.45),
                          vary(rng, 2600, 0.006, 0.3)};
    synth::add_modes(p, hit, modes, 5, rng);
    synth::add_noise_burst(p, hit, 0.005 * rng.jitter(0.2), 0.7,
                           Biquad::bandpass(rate, 1800 * rng.jitter(0.1), 0.9), rng, 0.04);
    double t = 0.0, amp = 0.35;
    for (int k = 0; k < 3; ++k) {
        t += rng.uniform(0.003, 0.005);
        const Mode tick[] = {vary(rng, 2600, 0.003, amp), vary(rng, 4100, 0.002, amp * 0.6)};
        synth::add_modes(p, {t, 1e-4}, tick, 2, rng);
        amp *= 0.6;
    }
    return p;
}

}  // namespace

std::string_view to_string(SoundKind kind) {
    switch (kind) {
        case SoundKind::ball_click:
            return "ball_click";
        case SoundKind::cushion_thump:
            return "cushion_thump";
        case SoundKind::pocket_drop:
            return "pocket_drop";
        case SoundKind::cue_strike:
            return "cue_strike";
        case SoundKind::jaw_rattle:
            return "jaw_rattle";
    }
    return "?";
}

float level(SoundKind kind) {
    switch (kind) {
        case SoundKind::ball_click:
            return 0.70f;
        case SoundKind::cushion_thump:
            return 0.55f;
        case SoundKind::pocket_drop:
            return 0.60f;
        case SoundKind::cue_strike:
            return 0.50f;
        case SoundKind::jaw_rattle:
            return 0.50f;
    }
    return 0.5f;
}

Pcm synthesize(SoundKind kind, std::uint64_t seed, int rate) {
    Pcm p;
    switch (kind) {
        case SoundKind::ball_click:
            p = ball_click(seed, rate);
            break;
        case SoundKind::cushion_thump:
            p = cushion_thump(seed, rate);
            break;
        case SoundKind::pocket_drop:
            p = pocket_drop(seed, rate);
            break;
        case SoundKind::cue_strike:
            p = cue_strike(seed, rate);
            break;
        case SoundKind::jaw_rattle:
            p = jaw_rattle(seed, rate);
            break;
    }
    normalize(p, level(kind));
    return p;
}

const Pcm& SoundBank::get(SoundKind kind, int variant) const {
    const auto& v = sounds[static_cast<std::size_t>(kind)];
    assert(!v.empty() && "SoundBank is empty: build it with make_sound_bank()");
    return v[static_cast<std::size_t>(variant) % v.size()];
}

SoundBank make_sound_bank(const SoundBankOptions& options) {
    assert(options.variants >= 1 && "SoundBankOptions::variants must be at least 1");
    SoundBank bank;
    for (int k = 0; k < kSoundKindCount; ++k) {
        for (int v = 0; v < options.variants; ++v) {
            const std::uint64_t seed =
                mix_seed(options.seed, static_cast<std::uint64_t>(k * 1000 + v));
            bank.sounds[static_cast<std::size_t>(k)].push_back(
                synthesize(static_cast<SoundKind>(k), seed, options.rate));
        }
    }
    return bank;
}

}  // namespace audio
