#include "audio/sounds.hpp"

#include <cassert>
#include <cmath>
#include <numbers>

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

// The ball falls past the jaws: a hard knock as it lands on the pocket's liner, then it rattles
// against the jaws and the leather as it settles (ticks growing closer and softer), all within
// half a second; the run to the ball return is its own sound (ball_return), heard later.
Pcm pocket_drop(std::uint64_t seed, int rate) {
    Rng rng(seed);
    Pcm p = blank(rate, 0.5);
    const Contact hit{0.0, 2e-4};
    const Mode modes[] = {vary(rng, 140, 0.070, 1.0), vary(rng, 265, 0.050, 0.8),
                          vary(rng, 520, 0.030, 0.5), vary(rng, 1100, 0.015, 0.35),
                          vary(rng, 2300, 0.006, 0.2)};
    synth::add_modes(p, hit, modes, 5, rng);
    synth::add_noise_burst(p, hit, 0.010 * rng.jitter(0.2), 0.8,
                           Biquad::lowpass(rate, 1500 * rng.jitter(0.1), 0.7), rng, 0.08);
    // The rattle: a ball bouncing in the pocket, each bounce shorter (restitution about 0.6).
    double t = 0.0, gap = 0.07 * rng.jitter(0.2), amp = 0.45;
    for (int k = 0; k < 6; ++k) {
        t += gap;
        const Mode knock[] = {vary(rng, 330, 0.020, amp), vary(rng, 730, 0.012, amp * 0.8),
                              vary(rng, 2600, 0.004, amp * 0.5), vary(rng, 4100, 0.002, amp * 0.3)};
        synth::add_modes(p, {t, 2e-4}, knock, 4, rng);
        gap *= 0.62 * rng.jitter(0.1);
        amp *= 0.68;
    }
    return p;
}

// Down the channel under the table: the knock of the ball dropping into it, the rumble of its
// run on hard wood (a wobble once per turn), knocks at the channel's bends, and the clack of it
// meeting the balls already in the return.
Pcm ball_return(std::uint64_t seed, int rate) {
    Rng rng(seed);
    Pcm p = blank(rate, 1.0);
    const Contact drop{0.0, 3e-4};
    const Mode knock[] = {vary(rng, 210, 0.040, 1.0), vary(rng, 480, 0.025, 0.7),
                          vary(rng, 1250, 0.010, 0.4), vary(rng, 3100, 0.004, 0.25)};
    synth::add_modes(p, drop, knock, 4, rng);
    synth::Rumble run;
    run.start = 0.01;
    run.rise = 0.04;
    run.hold = 0.45 * rng.jitter(0.2);
    run.fall = 0.12;
    run.amp =
        2.5;  // band-passed noise is weak: this puts the run's peak about 10 dB under the knock
    run.wobble = 0.5;
    run.wobble_hz = 7.0 * rng.jitter(0.2);
    synth::add_rumble(p, run, Biquad::bandpass(rate, 380 * rng.jitter(0.1), 1.2),
                      Biquad::lowpass(rate, 1400, 0.7), rng);
    for (double bend : {0.18, 0.36}) {
        const Mode b[] = {vary(rng, 260, 0.020, 0.35), vary(rng, 900, 0.008, 0.25)};
        synth::add_modes(p, {bend * rng.jitter(0.15), 3e-4}, b, 2, rng);
    }
    // The clack into the row of balls: phenolic on phenolic, duller through the tray.
    const double end = run.start + run.rise + run.hold + 0.02;
    const Mode clack[] = {vary(rng, 3300, 0.006, 0.7), vary(rng, 5100, 0.004, 0.5),
                          vary(rng, 1150, 0.010, 0.3), vary(rng, 420, 0.020, 0.4)};
    synth::add_modes(p, {end, 5e-5}, clack, 4, rng);
    return p;
}

// A ball rolling on worsted cloth: a low rumble (the ball's weight on the cloth and the slate)
// with a faint hiss of the nap, 1 s long and seamless (its tail is cross-faded into its head),
// so that it loops while the ball moves. The engine sets its gain from the ball's speed.
Pcm cloth_roll(std::uint64_t seed, int rate) {
    Rng rng(seed);
    const double loop = 1.0, fade = 0.1;
    Pcm p = blank(rate, loop + fade);
    Biquad band = Biquad::bandpass(rate, 140 * rng.jitter(0.1), 0.9);
    Biquad smooth = Biquad::lowpass(rate, 380, 0.7);
    Biquad nap = Biquad::bandpass(rate, 1800 * rng.jitter(0.1), 1.5);
    for (float& x : p.samples)
        x = static_cast<float>(smooth(band(synth::white(rng))) + 0.03 * nap(synth::white(rng)));
    // Equal-power cross-fade of the last `fade` into the first, then cut to `loop`.
    const auto n = static_cast<std::size_t>(loop * rate), m = static_cast<std::size_t>(fade * rate);
    for (std::size_t i = 0; i < m; ++i) {
        const double u = (static_cast<double>(i) + 0.5) / static_cast<double>(m);
        p.samples[i] = static_cast<float>(p.samples[i] * std::sin(0.5 * std::numbers::pi * u) +
                                          p.samples[n + i] * std::cos(0.5 * std::numbers::pi * u));
    }
    p.samples.resize(n);
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
        case SoundKind::ball_return:
            return "ball_return";
        case SoundKind::cloth_roll:
            return "cloth_roll";
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
        case SoundKind::ball_return:
            return 0.35f;  // under the table, behind the apron's wood
        case SoundKind::cloth_roll:
            return 0.05f;  // a soft bed, well under the impacts
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
        case SoundKind::ball_return:
            p = ball_return(seed, rate);
            break;
        case SoundKind::cloth_roll:
            p = cloth_roll(seed, rate);
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
