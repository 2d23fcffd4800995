// The end of a rack (table_value.hpp's near_rack_end, level.hpp's effort_for with `rack_end`):
// where the shooter's last few balls are left, level 5 searches wider in 8-ball; elsewhere, and at
// lower levels, the effort is the level's own. And 9-ball's level 5, deeper in every decision.
#include <gtest/gtest.h>

#include "ai/internal/level.hpp"
#include "ai/internal/table_value.hpp"
#include "ai_support.hpp"

namespace {

using ai_test::position;
using physics::Vec2;
using rules::Game;

// Balls `on` spread along the long cushion at y = 0.2 m, the cue ball at the table's centre.
ai::Position spread(Game game, const std::set<int>& on) {
    std::map<int, Vec2> at{{0, {1.27, 0.635}}};
    double x = 0.2;
    for (int ball : on) {
        at[ball] = {x, 0.2};
        x += 0.15;
    }
    return position(game, on, at);
}

TEST(NearRackEnd, EightBallCountsTheShootersGroupAndTheEight) {
    ai::Position pos = spread(Game::eight_ball, {1, 2, 3, 4, 8, 9, 10});
    EXPECT_FALSE(ai::near_rack_end(pos.ruleset, pos.state));  // an open table
    pos.state.group_a = rules::Group::stripes;                // A: the 9, the 10 and the 8
    EXPECT_TRUE(ai::near_rack_end(pos.ruleset, pos.state));
    pos.state.shooter = rules::Player::B;  // B: four solids and the 8
    EXPECT_FALSE(ai::near_rack_end(pos.ruleset, pos.state));
    pos.state.on_table = {3, 4, 8, 9, 10};  // B: two solids and the 8
    EXPECT_TRUE(ai::near_rack_end(pos.ruleset, pos.state));
}

TEST(NearRackEnd, NineBallCountsEveryBallOnTheTable) {
    ai::Position pos = spread(Game::nine_ball, {5, 6, 7, 8, 9});
    EXPECT_FALSE(ai::near_rack_end(pos.ruleset, pos.state));
    pos.state.on_table.erase(5);
    EXPECT_TRUE(ai::near_rack_end(pos.ruleset, pos.state));
}

TEST(RackEndEffort, OnlyLevelFiveSearchesWiderAndOnlyInTheSearchAfterTheGrid) {
    for (int level = ai::min_level; level < ai::max_level; ++level)
        EXPECT_EQ(ai::effort_for(Game::eight_ball, level, true),
                  ai::effort_for(Game::eight_ball, level))
            << "level " << level;
    for (int level = ai::min_level; level <= ai::max_level; ++level)  // none in 9-ball
        EXPECT_EQ(ai::effort_for(Game::nine_ball, level, true),
                  ai::effort_for(Game::nine_ball, level))
            << "level " << level;
    const ai::Effort usual = ai::effort_for(Game::eight_ball, ai::max_level);
    const ai::Effort end = ai::effort_for(Game::eight_ball, ai::max_level, true);
    EXPECT_GT(end.shortlist, usual.shortlist);
    EXPECT_GT(end.finalists, usual.finalists);
    EXPECT_GT(end.polish, usual.polish);
    EXPECT_GT(end.deep_finalists, usual.deep_finalists);
    EXPECT_GT(end.deep_samples, usual.deep_samples);
    // The candidates, their draws and the second ply are the usual ones: nothing else differs.
    ai::Effort widened = usual;
    widened.shortlist = end.shortlist;
    widened.finalists = end.finalists;
    widened.polish = end.polish;
    widened.deep_finalists = end.deep_finalists;
    widened.deep_samples = end.deep_samples;
    EXPECT_EQ(end, widened);
    // Each deep draw is one of the one-ply rounds' draws (planner.cpp draws (1 + finalist_rounds) ×
    // samples of them, 160 at level 5 in 8-ball); this holds to the first two rounds' 80.
    EXPECT_LE(end.deep_samples, 2 * end.samples);
}

}  // namespace

// 9-ball: level 5 searches deeper in every decision; the other levels as in 8-ball.
namespace {

TEST(NineBallEffort, OnlyLevelFiveSearchesDeeperAndOnlyAfterTheNoisyRounds) {
    for (int level = ai::min_level; level < ai::max_level; ++level)
        EXPECT_EQ(ai::effort_for(Game::nine_ball, level), ai::effort_for(Game::eight_ball, level))
            << "level " << level;
    const ai::Effort usual = ai::effort_for(Game::eight_ball, ai::max_level);
    const ai::Effort nine = ai::effort_for(Game::nine_ball, ai::max_level);
    EXPECT_GT(nine.polish, usual.polish);
    EXPECT_GT(nine.deep_finalists, usual.deep_finalists);
    EXPECT_GT(nine.deep_samples, usual.deep_samples);
    // The candidates, the noisy rounds and the second ply's strokes are the usual ones.
    EXPECT_EQ(nine.shortlist, usual.shortlist);
    EXPECT_EQ(nine.samples, usual.samples);
    EXPECT_EQ(nine.finalists, usual.finalists);
    EXPECT_EQ(nine.next_pairs, usual.next_pairs);
    EXPECT_EQ(nine.next_speeds, usual.next_speeds);
    EXPECT_EQ(nine.next_spins, usual.next_spins);
    // The halvings' last rounds draw beyond the noisy rounds' 2 × samples: planner.cpp grows its
    // pool of draws to deepest_draws (deep_search_test.cpp).
    EXPECT_GT(ai::deepest_draws(nine), 2 * nine.samples);
    EXPECT_LE(nine.deep_finalists, nine.finalists + nine.polish * 6);
}

}  // namespace
