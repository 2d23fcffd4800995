// The synthesized sounds, as plain buffers (no OpenAL).
#include "audio/sounds.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <vector>

namespace audio {
namespace {

// The struck sounds (cloth_roll, a loop with no onset, is tested on its own).
constexpr SoundKind kKinds[] = {SoundKind::ball_click,  SoundKind::cushion_thump,
                                SoundKind::pocket_drop, SoundKind::cue_strike,
                                SoundKind::jaw_rattle,  SoundKind::ball_return};

double energy(const Pcm& p, double t0, double t1) {
    double e = 0.0;
    const auto a = static_cast<std::size_t>(t0 * p.rate);
    const auto b = std::min(p.samples.size(), static_cast<std::size_t>(t1 * p.rate));
    for (std::size_t i = a; i < b; ++i) e += double(p.samples[i]) * p.samples[i];
    return e;
}

/// Zero crossings per second: a rough brightness.
double crossings_per_second(const Pcm& p, double t1) {
    int n = 0;
    const auto b = std::min(p.samples.size(), static_cast<std::size_t>(t1 * p.rate));
    for (std::size_t i = 1; i < b; ++i) n += (p.samples[i - 1] < 0) != (p.samples[i] < 0);
    return n / t1;
}

}  // namespace

TEST(Sounds, SameSeedSameSamplesOtherSeedOtherSamples) {
    for (SoundKind k : kKinds) {
        EXPECT_EQ(synthesize(k, 7).samples, synthesize(k, 7).samples) << to_string(k);
        EXPECT_NE(synthesize(k, 7).samples, synthesize(k, 8).samples) << to_string(k);
    }
}

TEST(Sounds, FiniteAtTheirLevelAndStartingAtOnce) {
    for (SoundKind k : kKinds) {
        const Pcm p = synthesize(k, 3);
        ASSERT_FALSE(p.samples.empty());
        for (float s : p.samples) ASSERT_TRUE(std::isfinite(s)) << to_string(k);
        EXPECT_FLOAT_EQ(peak(p), level(k)) << to_string(k);
        // The onset is at sample 0: within 2 ms the sound is up to a fifth of its peak.
        Pcm head = p;
        head.samples.resize(static_cast<std::size_t>(0.002 * p.rate));
        EXPECT_GT(peak(head), 0.2f * peak(p)) << to_string(k);
    }
}

TEST(Sounds, ClickIsShortAndBrighterThanAThump) {
    const Pcm click = synthesize(SoundKind::ball_click, 1);
    const Pcm thump = synthesize(SoundKind::cushion_thump, 1);
    // 99 % of a click's energy within 20 ms.
    EXPECT_GT(energy(click, 0.0, 0.02), 0.99 * energy(click, 0.0, 1.0));
    const double bright = crossings_per_second(click, 0.01);
    const double dull = crossings_per_second(thump, 0.05);
    std::printf("zero crossings: click %.0f /s, thump %.0f /s\n", bright, dull);
    EXPECT_GT(bright, 4.0 * dull);
    EXPECT_GT(bright, 5000.0);
}

namespace {

/// Energy of the first difference in 5 ms frames (a pre-emphasis: a knock's attack stands
/// out over the low ringing of the ones before), for counting the knocks of a rattle.
std::vector<double> frame_energy(const Pcm& p, double frame = 0.005) {
    const auto n = static_cast<std::size_t>(frame * p.rate);
    std::vector<double> e;
    for (std::size_t a = 1; a + n <= p.samples.size(); a += n) {
        double sum = 0.0;
        for (std::size_t i = a; i < a + n; ++i) {
            const double d = double(p.samples[i]) - p.samples[i - 1];
            sum += d * d;
        }
        e.push_back(sum);
    }
    return e;
}

/// Times of the frames whose energy is over 4× the largest of the 4 before: the attacks of
/// separate knocks after the first (knocks closer than 20 ms count as one).
std::vector<double> knocks(const Pcm& p) {
    const std::vector<double> e = frame_energy(p);
    std::vector<double> at;
    for (std::size_t k = 1; k < e.size(); ++k) {
        double before = 0.0;
        for (std::size_t j = (k >= 4 ? k - 4 : 0); j < k; ++j) before = std::max(before, e[j]);
        if (e[k] > 4.0 * before && e[k] > 1e-6 * e[0]) at.push_back(0.005 * double(k));
    }
    return at;
}

/// The RMS frequency, sqrt(mean square of the derivative / mean square), a rough brightness
/// that a little hiss does not swing as much as it swings zero crossings (unit: Hz).
double rms_frequency(const Pcm& p) {
    double x2 = 0.0, d2 = 0.0;
    for (std::size_t i = 1; i < p.samples.size(); ++i) {
        const double d = double(p.samples[i]) - p.samples[i - 1];
        x2 += double(p.samples[i]) * p.samples[i];
        d2 += d * d;
    }
    return std::sqrt(d2 / x2) * p.rate / (2.0 * std::numbers::pi);
}

}  // namespace

TEST(Sounds, PocketDropKnocksThenRattlesAndIsOverInHalfASecond) {
    const Pcm drop = synthesize(SoundKind::pocket_drop, 1);
    EXPECT_LE(drop.duration(), 0.5);
    const std::vector<double> n = knocks(drop);
    std::printf("pocket drop: %zu knocks after the first, the first at %.3f s\n", n.size(),
                n.empty() ? 0.0 : n.front());
    EXPECT_GE(n.size(), 2u);  // the ball bouncing in the pocket, not one thud
    EXPECT_LT(n.back(), 0.3);
    // Each bounce softer: the last 0.2 s hold far less than the first 0.1 s.
    EXPECT_LT(energy(drop, 0.3, 0.5), 0.1 * energy(drop, 0.0, 0.1));
}

TEST(Sounds, BallReturnRunsThenClacks) {
    const Pcm run = synthesize(SoundKind::ball_return, 1);
    const double knock = energy(run, 0.0, 0.05), rolling = energy(run, 0.1, 0.4);
    std::printf("ball return: knock %.3g, run %.3g\n", knock, rolling);
    EXPECT_GT(rolling, 0.01 * knock);  // an audible run ...
    EXPECT_LT(rolling, 2.0 * knock);   // ... not louder than the drop into the channel
    // The clack into the tray: the brightest frame after 0.3 s.
    const Pcm late = [&] {
        Pcm p = run;
        p.samples.erase(p.samples.begin(), p.samples.begin() + static_cast<long>(0.3 * p.rate));
        return p;
    }();
    const std::vector<double> k = knocks(run);
    std::printf("ball return: knocks after the first at");
    for (double t : k) std::printf(" %.3f", t);
    std::printf(" s; brightness after 0.3 s %.0f Hz\n", rms_frequency(late));
    ASSERT_FALSE(k.empty());
    EXPECT_GT(k.back(), 0.3);  // the clack into the tray, at the end of the run
    EXPECT_GT(rms_frequency(late), 1000.0);
}

TEST(Sounds, ClothRollIsASeamlessLowRumble) {
    const Pcm roll = synthesize(SoundKind::cloth_roll, 1);
    EXPECT_NEAR(roll.duration(), 1.0, 1e-3);
    EXPECT_FLOAT_EQ(peak(roll), level(SoundKind::cloth_roll));
    // Seamless: the step from the last sample to the first is no bigger than the steps inside.
    double largest = 0.0;
    for (std::size_t i = 1; i < roll.samples.size(); ++i)
        largest = std::max(largest, double(std::abs(roll.samples[i] - roll.samples[i - 1])));
    EXPECT_LE(std::abs(roll.samples.front() - roll.samples.back()), largest);
    // Low (a click's RMS frequency is over 3 kHz); steady: no 0.1 s differs 4× from another.
    EXPECT_LT(rms_frequency(roll), 500.0);
    EXPECT_GT(rms_frequency(synthesize(SoundKind::ball_click, 1)), 3000.0);
    double lo = 1e9, hi = 0.0;
    for (double t = 0.0; t < 0.95; t += 0.1) {
        lo = std::min(lo, energy(roll, t, t + 0.1));
        hi = std::max(hi, energy(roll, t, t + 0.1));
    }
    std::printf("cloth roll: RMS frequency %.0f Hz, 0.1 s energies %.3g–%.3g\n",
                rms_frequency(roll), lo, hi);
    EXPECT_LT(hi, 4.0 * lo);
}

TEST(Sounds, BankHasDistinctVariants) {
    SoundBankOptions o;
    o.variants = 4;
    const SoundBank bank = make_sound_bank(o);
    EXPECT_EQ(bank.variants(), 4);
    for (SoundKind k : kKinds)
        for (int v = 1; v < 4; ++v)
            EXPECT_NE(bank.get(k, 0).samples, bank.get(k, v).samples) << to_string(k) << v;
}

TEST(Pcm, Int16ClipsAndRounds) {
    Pcm p;
    p.samples = {0.0f, 0.5f, -1.0f, 2.0f};
    const auto s = to_int16(p);
    EXPECT_EQ(s, (std::vector<std::int16_t>{0, 16384, -32767, 32767}));
}

}  // namespace audio
