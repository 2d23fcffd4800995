// Combinations on the 9 (ghost_ball.hpp's combination_aim, candidates.hpp's
// combination_candidates, placement.hpp's combination_spots): the lowest ball sent into the 9,
// the 9 into a pocket. The geometry is refused where a path is blocked, the refined stroke pots
// the 9 without noise, and level 5 wins a rack with one where a direct pot would not.
#include <gtest/gtest.h>

#include "ai/internal/candidates.hpp"
#include "ai/internal/ghost_ball.hpp"
#include "ai/internal/level.hpp"
#include "ai/internal/placement.hpp"
#include "ai/internal/planner.hpp"
#include "ai_support.hpp"

namespace {

using ai_test::play;
using ai_test::position;
using physics::Vec2;
using rules::Game;

constexpr int SW = static_cast<int>(physics::PocketId::SW);
const double sigma = ai::heading_sigma_deg(physics::Params{});  // the shot model's σ at 1×

// The 9 on the diagonal to the SW corner, the 2 behind it on the same line, the cue ball
// behind the 2: a straight combination. The 3 is on the table too.
ai::Position straight_combination() {
    return position(Game::nine_ball, {2, 3, 9},
                    {{0, {0.95, 0.95}}, {2, {0.42, 0.42}}, {3, {2.0, 1.0}}, {9, {0.25, 0.25}}});
}

TEST(CombinationAim, FindsTheStraightCombinationAndItIsHarderThanAPot) {
    const ai::Position pos = straight_combination();
    const double R = pos.params.ball_radius;
    const std::optional<ai::Combination> c =
        ai::combination_aim(pos.table, R, pos.state.positions.at(0), 2, 9, SW, pos.state.positions);
    ASSERT_TRUE(c.has_value());
    EXPECT_EQ(c->first.ball, 2);
    EXPECT_EQ(c->second.ball, 9);
    EXPECT_LT(c->first.cut_deg, 1.0);
    EXPECT_LT(c->second.cut_deg, 1.0);
    // The first ball is sent to where it meets the 9: its ghost ball.
    EXPECT_NEAR(physics::norm(c->first.aim_point - pos.state.positions.at(9)), 2.0 * R, 1e-9);
    const double q = ai::combination_chance(*c, R, sigma);
    EXPECT_GT(q, 0.3);
    EXPECT_LT(q, 1.0);
    // The 9 potted from the first ball's spot instead (one contact less) is easier.
    const std::optional<ai::Aim> direct =
        ai::direct_aim(pos.table, R, pos.state.positions.at(2), 9, SW,
                       {{3, pos.state.positions.at(3)}, {9, pos.state.positions.at(9)}});
    ASSERT_TRUE(direct.has_value());
    EXPECT_GT(ai::aim_chance(*direct, R, sigma), q);
}

TEST(CombinationAim, RefusesABlockedPathOrASteepCut) {
    ai::Position pos = straight_combination();
    const double R = pos.params.ball_radius;
    const Vec2 cue = pos.state.positions.at(0);
    // A ball between the 2 and the 9.
    std::map<int, Vec2> between = pos.state.positions;
    between[3] = {0.335, 0.34};
    EXPECT_FALSE(ai::combination_aim(pos.table, R, cue, 2, 9, SW, between).has_value());
    // The 2 beside the 9 rather than behind it: a cut of 90° at the 9.
    std::map<int, Vec2> beside = pos.state.positions;
    beside[2] = {0.42, 0.08};
    EXPECT_FALSE(ai::combination_aim(pos.table, R, cue, 2, 9, SW, beside).has_value());
    // The same ball twice is no combination.
    EXPECT_FALSE(ai::combination_aim(pos.table, R, cue, 9, 9, SW, pos.state.positions).has_value());
}

TEST(CombinationCandidates, TheRefinedStrokesPotTheNineWithoutNoise) {
    const ai::Position pos = straight_combination();
    const std::vector<ai::RankedCombination> ranked =
        ai::ranked_combinations(pos, pos.state.positions.at(0), sigma);
    ASSERT_FALSE(ranked.empty());
    EXPECT_EQ(ranked.front().combination.second.pocket, SW);
    const ai::Effort effort = ai::effort_for(Game::nine_ball, ai::max_level);
    std::int64_t sims = 0;
    const std::vector<ai::Candidate> strokes =
        ai::combination_candidates(pos, pos.state.positions.at(0), false, effort, sigma, sims);
    ASSERT_FALSE(strokes.empty());
    EXPECT_GT(sims, 0);
    int stun = 0;
    for (const ai::Candidate& c : strokes) {
        if (c.stroke.top != 0.0 || c.stroke.side != 0.0) continue;
        // A stun stroke pots the 9 at every speed (with follow or draw the cue ball may go on
        // into the pocket or fall short of a cushion: what the search under noise sorts out).
        ++stun;
        game::Decision d;
        d.stroke = c.stroke;
        const rules::Verdict v = play(pos, d);
        EXPECT_TRUE(v.game_over && v.winner == rules::Player::A) << "speed " << c.stroke.speed;
    }
    EXPECT_GE(stun, 3);
}

TEST(CombinationCandidates, NoneInEightBallOrWhenTheNineIsTheLowest) {
    ai::Position eight = straight_combination();
    eight.ruleset.game = Game::eight_ball;
    eight.state.group_a = rules::Group::solids;
    EXPECT_TRUE(ai::ranked_combinations(eight, {0.95, 0.95}, sigma).empty());
    ai::Position nine = position(Game::nine_ball, {9}, {{0, {0.95, 0.95}}, {9, {0.25, 0.25}}});
    EXPECT_TRUE(ai::ranked_combinations(nine, {0.95, 0.95}, sigma).empty());
    // Levels below 5 try none, nor level 5 in 8-ball.
    EXPECT_EQ(ai::effort_for(Game::eight_ball, ai::max_level).combinations, 0);
    EXPECT_EQ(ai::effort_for(Game::eight_ball, ai::max_level, true).combinations, 0);
    std::int64_t sims = 0;
    const ai::Position pos = straight_combination();
    EXPECT_TRUE(ai::combination_candidates(pos, {0.95, 0.95}, false,
                                           ai::effort_for(Game::nine_ball, 4), sigma, sims)
                    .empty());
}

TEST(CombinationSpots, BallInHandFindsASpotForTheCombination) {
    ai::Position pos = straight_combination();
    pos.state.positions.erase(0);
    pos.state.cue_ball = rules::CueBall::in_hand;
    const double R = pos.params.ball_radius;
    const std::vector<Vec2> spots = ai::combination_spots(pos, 2, sigma, 0.3);
    ASSERT_FALSE(spots.empty());
    EXPECT_TRUE(ai::free_spot(pos, spots.front()));
    const std::optional<ai::Combination> c =
        ai::combination_aim(pos.table, R, spots.front(), 2, 9, SW, pos.state.positions);
    ASSERT_TRUE(c.has_value());
    EXPECT_GE(ai::combination_chance(*c, R, sigma), 0.3);
}

TEST(Planner, LevelFiveWinsWithTheCombinationWhereAPotWouldNot) {
    // The 2 cannot be potted in the SW corner (the 9 is in the way) and the 3 is far: the
    // combination wins the rack at once.
    const ai::Position pos = straight_combination();
    const ai::Plan p = ai::plan(pos, {ai::max_level, 0.0, 2}, 3);
    const rules::Verdict v = play(pos, p.decision);
    EXPECT_TRUE(v.game_over && v.winner == rules::Player::A);
    EXPECT_GT(p.expected_value, 0.99);
}

}  // namespace
