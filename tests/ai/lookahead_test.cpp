// The second ply (lookahead.hpp) and the finer search around the best pots (pot_variants): a
// table with nothing on is worth exactly a safety, a sure game-winning pot nearly a win, a long
// one less; variants stay near the pot they come from and inside the miscue limit.
#include "ai/lookahead.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "ai/candidates.hpp"
#include "ai/level.hpp"
#include "ai/table_value.hpp"
#include "ai_support.hpp"

namespace {

using ai_test::position;
using physics::Vec2;
using rules::Game;

constexpr double sigma = 0.21;  // heading σ of the shot model at 1× (ai::heading_sigma_deg)

double value_of(const ai::Position& pos) {
    std::int64_t sims = 0;
    const ai::Effort effort = ai::for_game(ai::effort_for_level(5), pos.ruleset.game);
    return ai::next_turn_value(pos, pos.state, effort, 1.0, sigma, sims);
}

// The 9 `d` metres from the NE corner's mouth on its axis, the cue ball 0.3 m behind it.
ai::Position nine_on_the_axis(double d) {
    const Vec2 pocket{2.54, 1.27};
    const Vec2 dir{std::sqrt(0.5), std::sqrt(0.5)};
    const Vec2 nine = pocket - (d + 0.06) * dir;
    return position(Game::nine_ball, {9}, {{0, nine - 0.3 * dir}, {9, nine}});
}

TEST(NextTurnValue, NothingOnIsWorthASafety) {
    // The 1 boxed in by four balls: no direct pot anywhere.
    const Vec2 one{1.27, 0.635};
    const double g = 2.0 * 0.028575 + 1e-4;
    ai::Position pos = position(Game::nine_ball, {1, 2, 3, 4, 5, 9},
                                {{0, {0.4, 0.3}},
                                 {1, one},
                                 {2, one + Vec2{g, 0}},
                                 {3, one + Vec2{-g, 0}},
                                 {4, one + Vec2{0, g}},
                                 {5, one + Vec2{0, -g}},
                                 {9, {2.2, 1.0}}});
    EXPECT_EQ(value_of(pos), ai::table_value(0.0));
}

TEST(NextTurnValue, ASureWinningPotIsNearlyAWinAndALongOneLess) {
    const double near = value_of(nine_on_the_axis(0.15));
    const double far = value_of(nine_on_the_axis(2.0));
    EXPECT_GT(near, 0.95);
    EXPECT_LT(far, near - 0.1);
    EXPECT_GE(far, ai::table_value(0.0));
}

TEST(NextTurnValue, CountsItsSimulations) {
    const ai::Position pos = nine_on_the_axis(0.5);
    std::int64_t sims = 0;
    ai::next_turn_value(pos, pos.state, ai::effort_for_level(5), 1.0, sigma, sims);
    EXPECT_GT(sims, 0);
}

TEST(PotVariants, StayNearThePotAndInsideTheMiscueLimit) {
    const ai::Position pos = nine_on_the_axis(0.8);
    std::int64_t sims = 0;
    const std::vector<ai::Candidate> pots = ai::pot_candidates(
        pos, pos.state.positions.at(0), false, ai::effort_for_level(5), sigma, sims);
    ASSERT_FALSE(pots.empty());
    for (const ai::Candidate& c : pots) {
        const std::vector<ai::Candidate> vs = ai::pot_variants(pos, c, sims);
        EXPECT_FALSE(vs.empty());
        for (const ai::Candidate& v : vs) {
            EXPECT_EQ(v.kind, ai::Kind::pot);
            EXPECT_EQ(v.stroke.side, c.stroke.side);
            EXPECT_TRUE(v.stroke.speed != c.stroke.speed || v.stroke.top != c.stroke.top);
            EXPECT_GE(v.stroke.speed, 0.8 * c.stroke.speed);
            EXPECT_LE(v.stroke.speed, 1.2 * c.stroke.speed);
            EXPECT_LE(std::hypot(v.stroke.side, v.stroke.top), 0.44 + 1e-12);
            EXPECT_LT(std::fabs(v.stroke.heading_deg - c.aim->heading_deg), 3.0 + 1e-9);
        }
    }
}

}  // namespace
