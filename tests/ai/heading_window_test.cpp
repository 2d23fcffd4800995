// Kicks and banks that pot without noise, moved to the middle of their window of headings
// (ai::heading_window, ai::centred_kicks).
#include "ai/internal/heading_window.hpp"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <optional>

#include "ai/internal/candidates.hpp"
#include "ai/internal/evaluate.hpp"
#include "ai/internal/ghost_ball.hpp"
#include "ai/internal/level.hpp"
#include "ai_support.hpp"

namespace {

// 9-ball: the 2 sits between the cue ball and the 1, which lies near the bottom right corner
// pocket, so the 1 can only be potted off a cushion: the sweep finds several kicks that do.
ai::Position snookered() {
    return ai_test::position(rules::Game::nine_ball, {1, 2},
                             {{0, {1.00, 0.40}}, {2, {1.70, 0.30}}, {1, {2.35, 0.15}}});
}

struct Sweep {
    std::vector<ai::Candidate> kicks;
    std::vector<ai::Score> nominal;
};

Sweep sweep(const ai::Position& pos, const ai::Evaluator& eval) {
    Sweep s;
    s.kicks = ai::kick_candidates(pos, pos.state.positions.at(0), false,
                                  ai::effort_for(rules::Game::nine_ball, 5));
    for (ai::Candidate& c : s.kicks) {
        const ai::Trial t = eval.nominal(c);
        ai::Score score;
        score.value = t.value;
        score.stays = t.stays;
        s.nominal.push_back(score);
    }
    return s;
}

// How many of the draws pot `kick` (the shooter stays at the table).
int potted(const ai::Evaluator& eval, const ai::Candidate& kick,
           const std::vector<ai::NoiseDraw>& draws) {
    int n = 0;
    for (const ai::NoiseDraw& d : draws) n += eval.trial(kick, d).stays;
    return n;
}

// The window holds the sweep's heading, its edges still pot and the middle does too; moved
// there, the kicks pot more often under the execution noise of level 5 than at the sweep's
// headings, which often lie near an edge (here 793 against 716 of 11 × 128 draws).
TEST(KickWindow, TheMiddleOfTheWindowPotsMoreOftenUnderNoise) {
    const ai::Position pos = snookered();
    const ai::Evaluator eval(pos, 1.0, ai::heading_sigma_deg(pos.params));
    const Sweep s = sweep(pos, eval);
    const std::vector<ai::NoiseDraw> draws = ai::noise_draws(7, 128);
    int kicks = 0, before = 0, after = 0;
    for (std::size_t i = 0; i < s.kicks.size(); ++i) {
        if (!s.nominal[i].stays) continue;
        ++kicks;
        const ai::Candidate& kick = s.kicks[i];
        std::int64_t sims = 0;
        const ai::HeadingWindow w = ai::heading_window(eval, kick, ai::kick_window_search, sims);
        EXPECT_GT(sims, 0);
        EXPECT_LE(w.low_deg, kick.stroke.heading_deg);
        EXPECT_GE(w.high_deg, kick.stroke.heading_deg);
        EXPECT_LE(w.high_deg - w.low_deg, 2.0 * ai::kick_window_search.reach_deg + 1e-9);
        ai::Candidate middle = kick;
        for (double at : {w.low_deg, w.high_deg, 0.5 * (w.low_deg + w.high_deg)}) {
            middle.stroke.heading_deg = at;
            EXPECT_TRUE(eval.nominal(middle).stays) << at;
        }
        before += potted(eval, kick, draws);
        after += potted(eval, middle, draws);
    }
    EXPECT_GE(kicks, 5);
    EXPECT_GT(after, before + kicks * 128 / 20);  // at least 5 points more
}

// The centred kicks are kicks that pot without noise, at most three (speeds) per kick centred,
// none on a heading and speed the sweep tried.
TEST(KickWindow, CentredKicksPotWithoutNoiseAndAreNew) {
    const ai::Position pos = snookered();
    const ai::Evaluator eval(pos, 1.0, ai::heading_sigma_deg(pos.params));
    const Sweep s = sweep(pos, eval);
    std::int64_t sims = 0;
    const std::size_t count = 4;
    const std::vector<ai::Candidate> centred =
        ai::centred_kicks(eval, s.kicks, s.nominal, count, 0.0, sims, 2);
    EXPECT_GE(centred.size(), count);
    EXPECT_LE(centred.size(), count * ai::kick_speed_factors.size());
    EXPECT_GT(sims, 0);
    for (ai::Candidate c : centred) {
        EXPECT_EQ(c.kind, ai::Kind::kick);
        EXPECT_TRUE(eval.nominal(c).stays);
        for (const ai::Candidate& k : s.kicks)
            EXPECT_FALSE(k.stroke.speed == c.stroke.speed &&
                         k.stroke.heading_deg == c.stroke.heading_deg);
    }
    // The same every time (two workers share the search).
    std::int64_t again = 0;
    const std::vector<ai::Candidate> twice =
        ai::centred_kicks(eval, s.kicks, s.nominal, count, 0.0, again, 2);
    ASSERT_EQ(twice.size(), centred.size());
    for (std::size_t i = 0; i < centred.size(); ++i) {
        EXPECT_EQ(twice[i].stroke.heading_deg, centred[i].stroke.heading_deg);
        EXPECT_EQ(twice[i].stroke.speed, centred[i].stroke.speed);
    }
    EXPECT_EQ(again, sims);
}

// With a raise allowed, each centred kick comes on a level cue and, where raising helps, on a
// cue raised to where a side error's swerve cancels its squirt, the ball's speed kept; the
// raised kicks pot without noise and more often under the execution noise of level 5 than the
// same kicks centred on a level cue (here 8 raised: 875 against 765 of 8 × 128 draws).
TEST(KickWindow, RaisedKicksPotMoreOftenUnderNoise) {
    const ai::Position pos = snookered();
    const ai::Evaluator eval(pos, 1.0, ai::heading_sigma_deg(pos.params));
    const Sweep s = sweep(pos, eval);
    const double max_raise = ai::effort_for(rules::Game::nine_ball, 5).max_raise_deg;
    std::int64_t sims = 0;
    const std::vector<ai::Candidate> centred =
        ai::centred_kicks(eval, s.kicks, s.nominal, 12, max_raise, sims, 2);
    const std::vector<ai::NoiseDraw> draws = ai::noise_draws(7, 128);
    int raised = 0, level_potted = 0, raised_potted = 0;
    for (std::size_t i = 0; i < centred.size(); ++i) {
        ai::Candidate c = centred[i];
        EXPECT_TRUE(eval.nominal(c).stays);
        if (c.stroke.elevation_deg == 0.0) continue;
        ++raised;
        EXPECT_LE(c.stroke.elevation_deg, max_raise);
        // Its level twin comes just before it, at the same ball speed.
        ASSERT_GT(i, 0U);
        const ai::Candidate& level = centred[i - 1];
        EXPECT_EQ(level.stroke.elevation_deg, 0.0);
        EXPECT_NEAR(c.stroke.speed * std::cos(c.stroke.elevation_deg * ai::deg), level.stroke.speed,
                    1e-9);
        level_potted += potted(eval, level, draws);
        raised_potted += potted(eval, c, draws);
    }
    EXPECT_GE(raised, 5);
    EXPECT_GT(raised_potted, level_potted);
}

// Pots: over six layouts of a cue ball and the 9, the pots of level 5 that pot without noise,
// turned to the middle of their window, pot more often under its noise (16,951 against 16,684
// of 324 × 100 draws; in one layout 10 fewer, in the others 10 to 99 more).
TEST(PotWindow, TheMiddleOfTheWindowPotsMoreOftenUnderNoise) {
    struct Layout {
        physics::Vec2 cue, nine;
    };
    constexpr std::array<Layout, 6> layouts{{{{0.5, 0.4}, {1.6, 0.5}},
                                             {{1.9, 0.9}, {1.0, 0.3}},
                                             {{0.3, 1.0}, {2.0, 0.9}},
                                             {{1.2, 0.2}, {1.3, 0.9}},
                                             {{2.2, 0.4}, {0.8, 0.9}},
                                             {{0.7, 0.7}, {1.27, 0.2}}}};
    const std::vector<ai::NoiseDraw> draws = ai::noise_draws(3, 100);
    int pots = 0, before = 0, after = 0;
    for (const Layout& l : layouts) {
        const ai::Position pos =
            ai_test::position(rules::Game::nine_ball, {9}, {{0, l.cue}, {9, l.nine}});
        const double sigma = ai::heading_sigma_deg(pos.params);
        const ai::Evaluator eval(pos, 1.0, sigma);
        std::int64_t sims = 0;
        for (ai::Candidate c : ai::pot_candidates(
                 pos, l.cue, false, ai::effort_for(rules::Game::nine_ball, 5), sigma, sims)) {
            const std::optional<ai::Candidate> m =
                ai::centred(eval, c, ai::pot_window_search, sims);
            if (!m) continue;  // it misses without noise, or the middle of its window does
            ++pots;
            ai::Candidate middle = *m;
            EXPECT_TRUE(eval.nominal(middle).stays);
            EXPECT_NEAR(m->stroke.heading_deg, c.stroke.heading_deg,
                        ai::pot_window_search.reach_deg);
            EXPECT_EQ(m->stroke.speed, c.stroke.speed);
            EXPECT_EQ(m->stroke.side, c.stroke.side);
            before += potted(eval, c, draws);
            after += potted(eval, *m, draws);
        }
    }
    EXPECT_GT(pots, 250);  // 324
    EXPECT_GT(after, before);
}

// Without a kick that pots there is nothing to centre.
TEST(KickWindow, NothingToCentreWhenNoKickPots) {
    const ai::Position pos = snookered();
    const ai::Evaluator eval(pos, 1.0, ai::heading_sigma_deg(pos.params));
    Sweep s = sweep(pos, eval);
    for (ai::Score& score : s.nominal) score.stays = false;
    std::int64_t sims = 0;
    EXPECT_TRUE(ai::centred_kicks(eval, s.kicks, s.nominal, 12, 20.0, sims, 2).empty());
    EXPECT_EQ(sims, 0);
}

}  // namespace
