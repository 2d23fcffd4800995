// The deep round of the search (evaluate.hpp's score_deep, level.hpp's deep halvings): valuing
// two plies deep in several rounds of draws comes to the same score as one round, a draw beyond
// the one-ply draws counts in the one-ply mean too, without noise one play is exact, and the
// halvings' schedule plays as many deep trials as one round while its best quarter gets twice
// the draws; level 5's deep search in 9-ball plays draws of its own, after the one-ply rounds'.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "ai/internal/candidates.hpp"
#include "ai/internal/evaluate.hpp"
#include "ai/internal/level.hpp"
#include "ai_support.hpp"

namespace {

using ai_test::position;
using physics::Vec2;
using rules::Game;

constexpr double sigma = 0.21;  // the shot model's heading σ at 1×, default cue (heading_sigma_deg)

// The 1 half a metre from the NE corner's mouth, the cue ball behind it, the 9 further up the
// table: the shooter stays at the table after most draws, so the second ply values them.
ai::Position one_then_nine() {
    const Vec2 pocket{2.54, 1.27};
    const Vec2 dir{std::sqrt(0.5), std::sqrt(0.5)};
    const Vec2 one = pocket - 0.56 * dir;
    return position(Game::nine_ball, {1, 9}, {{0, one - 0.4 * dir}, {1, one}, {9, {0.9, 0.4}}});
}

struct Fixture {
    ai::Position pos = one_then_nine();
    ai::Effort effort = ai::effort_for(Game::nine_ball, ai::max_level);
    ai::Evaluator eval{pos, 1.0, sigma};
    std::vector<ai::NoiseDraw> draws = ai::noise_draws(7, 16);
    std::vector<ai::Candidate> cands;
    std::vector<std::size_t> which;

    Fixture() {
        std::int64_t sims = 0;
        cands = ai::pot_candidates(pos, pos.state.positions.at(0), false, effort, sigma, sims);
        for (std::size_t i = 0; i < cands.size() && i < 3; ++i) which.push_back(i);
    }

    std::vector<ai::Score> one_ply(std::size_t count) const {
        std::vector<ai::Score> scores(cands.size());
        ai::score_under_noise(eval, cands, which, draws, 0, count, scores, 2);
        return scores;
    }
};

TEST(ScoreDeep, RoundsOfDrawsComeToOneRound) {
    const Fixture f;
    ASSERT_EQ(f.which.size(), 3u);
    std::vector<ai::Score> once = f.one_ply(8), twice = f.one_ply(8);
    ai::score_deep(f.eval, f.cands, f.which, f.draws, 0, 8, f.effort, once, 2);
    ai::score_deep(f.eval, f.cands, f.which, f.draws, 0, 4, f.effort, twice, 2);
    ai::score_deep(f.eval, f.cands, f.which, f.draws, 4, 4, f.effort, twice, 1);
    for (std::size_t i : f.which) {
        EXPECT_NEAR(twice[i].value, once[i].value, 1e-12) << "candidate " << i;
        EXPECT_EQ(twice[i].deep_draws, 8);
        EXPECT_EQ(twice[i].samples, 8);  // no draw beyond the one-ply ones
        EXPECT_EQ(twice[i].success, once[i].success);
    }
}

TEST(ScoreDeep, DrawsBeyondTheOnePlyOnesCountInItsMean) {
    const Fixture f;
    std::vector<ai::Score> scores = f.one_ply(4);
    ai::score_deep(f.eval, f.cands, f.which, f.draws, 0, 12, f.effort, scores, 2);
    bool some_deeper = false;
    for (std::size_t i : f.which) {
        // One-ply mean over 12 draws plus the mean correction over the same 12: the mean of
        // the two-ply values themselves.
        double deep = 0.0, shallow = 0.0, success = 0.0;
        for (std::size_t d = 0; d < 12; ++d) {
            const ai::Trial t = f.eval.deep_trial(f.cands[i], f.draws[d], f.effort);
            deep += t.value;
            shallow += t.shallow;
            success += t.success ? 1.0 : 0.0;
        }
        EXPECT_EQ(scores[i].samples, 12) << "candidate " << i;
        EXPECT_EQ(scores[i].deep_draws, 12);
        EXPECT_NEAR(scores[i].value, deep / 12.0, 1e-12);
        EXPECT_NEAR(scores[i].success, success / 12.0, 1e-12);
        some_deeper = some_deeper || std::abs(deep - shallow) > 1e-9;
    }
    EXPECT_TRUE(some_deeper);  // the second ply did value something
}

TEST(ScoreDeep, WithoutNoiseOnePlayIsExact) {
    const Fixture f;
    const ai::Evaluator exact{f.pos, 0.0, sigma};  // at scale 0 every draw plays the stroke
    std::vector<ai::Score> scores(f.cands.size());
    ai::score_under_noise(exact, f.cands, f.which, f.draws, 0, 1, scores, 1);
    ai::score_deep(exact, f.cands, f.which, f.draws, 0, 1, f.effort, scores, 1);
    for (std::size_t i : f.which) {
        const ai::Trial t = exact.deep_trial(f.cands[i], f.draws[5], f.effort);
        EXPECT_EQ(scores[i].samples, 1) << "candidate " << i;
        EXPECT_EQ(scores[i].deep_draws, 1);
        EXPECT_NEAR(scores[i].value, t.value, 1e-12);
    }
}

TEST(DeepHalvings, PlayAsManyTrialsAsOneRoundAndGiveTheBestQuarterTwiceTheDraws) {
    ai::Effort e = ai::effort_for(Game::nine_ball, ai::max_level);
    ASSERT_EQ(e.deep_halvings, 2);
    const int f = e.deep_finalists, m = e.deep_samples;
    // Every deep finalist m / 2 draws, the better half up to m, the better quarter up to 2 m.
    const int trials = f * (m / 2) + (f / 2) * (m / 2) + (f / 4) * m;
    EXPECT_EQ(trials, f * m);
    EXPECT_EQ(ai::deepest_draws(e), 2 * m);
    e.deep_halvings = 0;
    EXPECT_EQ(ai::deepest_draws(e), m);
    e.deep_halvings = 3;
    EXPECT_EQ(ai::deepest_draws(e), 4 * m);
    for (int level = ai::min_level; level < ai::max_level; ++level)
        EXPECT_EQ(ai::effort_for(Game::nine_ball, level).deep_halvings, 0) << "level " << level;
    for (bool rack_end : {false, true})  // 8-ball: one round
        EXPECT_EQ(ai::effort_for(Game::eight_ball, ai::max_level, rack_end).deep_halvings, 0);
}

TEST(DeepDraws, LevelFiveIn9BallPlaysDrawsOfItsOwnAfterTheOnePlyRounds) {
    const ai::Effort nine = ai::effort_for(Game::nine_ball, ai::max_level);
    EXPECT_TRUE(nine.fresh_deep_draws);
    EXPECT_EQ(ai::draw_pool(nine),
              (1 + nine.finalist_rounds) * nine.samples + ai::deepest_draws(nine));
    // 8-ball, the end of the rack included, and levels 1-4: among the one-ply draws.
    for (bool rack_end : {false, true}) {
        const ai::Effort eight = ai::effort_for(Game::eight_ball, ai::max_level, rack_end);
        EXPECT_FALSE(eight.fresh_deep_draws);
        EXPECT_EQ(ai::draw_pool(eight),
                  std::max({(1 + eight.finalist_rounds) * eight.samples, 2 * eight.break_samples,
                            ai::deepest_draws(eight)}));
    }
    for (int level = ai::min_level; level < ai::max_level; ++level) {
        const ai::Effort e = ai::effort_for(Game::nine_ball, level);
        EXPECT_FALSE(e.fresh_deep_draws) << "level " << level;
        EXPECT_EQ(ai::draw_pool(e),
                  std::max({2 * e.samples, 2 * e.break_samples, ai::deepest_draws(e)}));
    }
}

// 8-ball, level 5: the finalists get three rounds of draws more, not one (160 draws each in
// all); 9-ball and levels 1-4 one round.
TEST(FinalistDraws, ThreeMoreRoundsIn8BallAtLevelFiveOnly) {
    for (bool rack_end : {false, true}) {
        const ai::Effort eight = ai::effort_for(Game::eight_ball, ai::max_level, rack_end);
        EXPECT_EQ(eight.finalist_rounds, 3);
        EXPECT_EQ(ai::draw_pool(eight), 4 * eight.samples);
    }
    EXPECT_EQ(ai::effort_for(Game::nine_ball, ai::max_level).finalist_rounds, 1);
    for (int level = ai::min_level; level < ai::max_level; ++level)
        for (Game game : {Game::eight_ball, Game::nine_ball})
            EXPECT_EQ(ai::effort_for(game, level).finalist_rounds, 1) << "level " << level;
}

TEST(DeepDraws, OwnDrawsExtendTheOnePlyMeanByEachOfThem) {
    // A finalist with 4 one-ply draws, valued deep on the next 8: 12 draws in its one-ply mean,
    // 8 in its deep correction, none counted twice.
    const Fixture f;
    std::vector<ai::Score> scores = f.one_ply(4);
    ai::score_deep(f.eval, f.cands, f.which, f.draws, 4, 8, f.effort, scores, 2);
    for (std::size_t i : f.which) {
        double shallow = 0.0, correction = 0.0;
        for (std::size_t d = 0; d < 12; ++d) {
            const ai::Trial t = d < 4 ? f.eval.trial(f.cands[i], f.draws[d])
                                      : f.eval.deep_trial(f.cands[i], f.draws[d], f.effort);
            shallow += t.shallow;
            if (d >= 4) correction += t.value - t.shallow;
        }
        EXPECT_EQ(scores[i].samples, 12) << "candidate " << i;
        EXPECT_EQ(scores[i].deep_draws, 8);
        EXPECT_NEAR(scores[i].value, shallow / 12.0 + correction / 8.0, 1e-12);
    }
}

}  // namespace
