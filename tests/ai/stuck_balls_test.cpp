// The stuck-ball cost of the table value (table_value.hpp, level.hpp's Effort::stuck_ball_cost):
// which balls the player at the table must still pocket, which of them cannot reach any pocket,
// what they take off his table's value, and that only 8-ball counts them.
#include <gtest/gtest.h>

#include <vector>

#include "ai/internal/level.hpp"
#include "ai/internal/lookahead.hpp"
#include "ai/internal/table_value.hpp"
#include "ai_support.hpp"

namespace {

using ai_test::position;
using physics::Vec2;
using rules::Game;

constexpr double sigma = 0.21;  // the shot model's heading σ at 1×, default cue (heading_sigma_deg)
constexpr double gap = 2.0 * 0.028575 + 1e-4;  // two ball radii and a tenth of a millimetre

// 8-ball, player A on stripes: the 9 boxed in by the solids 1–4 at the table's centre, the 8
// and the 10 free, the cue ball in the corner of the head.
ai::Position boxed_nine(bool with_ten) {
    const Vec2 nine{1.27, 0.635};
    std::set<int> on{1, 2, 3, 4, 8, 9};
    std::map<int, Vec2> at{{0, {0.4, 0.3}},
                           {1, nine + Vec2{gap, 0}},
                           {2, nine + Vec2{-gap, 0}},
                           {3, nine + Vec2{0, gap}},
                           {4, nine + Vec2{0, -gap}},
                           {8, {2.2, 1.0}},
                           {9, nine}};
    if (with_ten) {
        on.insert(10);
        at[10] = {2.2, 0.3};
    }
    ai::Position pos = position(Game::eight_ball, on, at);
    pos.state.group_a = rules::Group::stripes;
    return pos;
}

TEST(BallsToClear, AreTheShootersGroupAndTheEightOrEveryBallIn9Ball) {
    ai::Position pos = boxed_nine(true);
    EXPECT_EQ(ai::balls_to_clear(pos.ruleset, pos.state), (std::vector<int>{8, 9, 10}));
    pos.state.shooter = rules::Player::B;  // B has the solids
    EXPECT_EQ(ai::balls_to_clear(pos.ruleset, pos.state), (std::vector<int>{1, 2, 3, 4, 8}));
    pos.state.group_a.reset();  // an open table: no group yet
    EXPECT_TRUE(ai::balls_to_clear(pos.ruleset, pos.state).empty());
    pos.ruleset.game = Game::nine_ball;
    EXPECT_EQ(ai::balls_to_clear(pos.ruleset, pos.state), (std::vector<int>{1, 2, 3, 4, 8, 9, 10}));
}

TEST(StuckBalls, CountsTheBallsWithNoPathToAnyPocket) {
    const ai::Position pos = boxed_nine(true);
    EXPECT_EQ(ai::stuck_balls(pos, pos.state), 1);  // the 9; the 8 and the 10 are free
    ai::Position freed = pos;                       // the four solids moved to the head rail
    for (int ball = 1; ball <= 4; ++ball) freed.state.positions[ball] = {0.2 * ball, 1.2};
    EXPECT_EQ(ai::stuck_balls(freed, freed.state), 0);
}

TEST(PositionValue, TakesTheCostOffForEachStuckBall) {
    const ai::Position pos = boxed_nine(true);
    const double plain = ai::table_value(ai::best_shot_chance(pos, pos.state, sigma));
    EXPECT_EQ(ai::position_value(pos, pos.state, sigma, 0.0), plain);
    EXPECT_DOUBLE_EQ(ai::position_value(pos, pos.state, sigma, 0.04), plain - 0.04);
}

TEST(EffortFor, CountsStuckBallsAndDistinctLeavesIn8BallOnly) {
    for (bool rack_end : {false, true}) {
        const ai::Effort eight = ai::effort_for(Game::eight_ball, 5, rack_end);
        EXPECT_GT(eight.stuck_ball_cost, 0.0);
        EXPECT_GT(eight.distinct_leaves, 0.0);
    }
    const ai::Effort nine = ai::effort_for(Game::nine_ball, 5);
    EXPECT_EQ(nine.stuck_ball_cost, 0.0);
    EXPECT_EQ(nine.distinct_leaves, 0.0);
    EXPECT_EQ(nine.shortlist, ai::effort_for(Game::eight_ball, 5).shortlist);
}

TEST(NextTurnValue, NothingOnWithAStuckBallIsWorthLessThanASafety) {
    // The only stripe is boxed in: nothing on, and one ball to free.
    const ai::Position pos = boxed_nine(false);
    const ai::Effort effort = ai::effort_for(Game::eight_ball, 5);
    std::int64_t sims = 0;
    EXPECT_DOUBLE_EQ(ai::next_turn_value(pos, pos.state, effort, 1.0, sigma, sims),
                     ai::table_value(0.0) - effort.stuck_ball_cost);
}

}  // namespace
