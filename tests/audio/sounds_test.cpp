// The synthesized sounds, as plain buffers (no OpenAL).
#include "audio/sounds.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace audio {
namespace {

constexpr SoundKind kKinds[] = {SoundKind::ball_click, SoundKind::cushion_thump,
                                SoundKind::pocket_drop, SoundKind::cue_strike,
                                SoundKind::jaw_rattle};

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

TEST(Sounds, PocketDropRollsOnAfterTheKnock) {
    const Pcm drop = synthesize(SoundKind::pocket_drop, 1);
    EXPECT_GT(drop.duration(), 1.0);
    const double roll = energy(drop, 0.3, 0.8), knock = energy(drop, 0.0, 0.05);
    EXPECT_GT(roll, 0.01 * knock);  // audible rolling ...
    EXPECT_LT(roll, knock);         // ... under the knock
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
