// The second ply (lookahead.hpp) and the finer search around the best pots (pot_variants): a
// table with nothing on is worth exactly a safety, a sure game-winning pot nearly a win, a long
// one less; played out over more shots it sees the win or the dead end a pot leads to; variants
// stay near the pot they come from and inside the miscue limit.
#include "ai/internal/lookahead.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "ai/internal/candidates.hpp"
#include "ai/internal/level.hpp"
#include "ai/internal/table_value.hpp"
#include "ai_support.hpp"

namespace {

using ai_test::position;
using physics::Vec2;
using rules::Game;

constexpr double sigma = 0.21;  // the shot model's heading σ at 1×, default cue (heading_sigma_deg)

// Level 5's value of the table in `pos`, the second ply played out `shots` shots.
double played_out(const ai::Position& pos, int shots) {
    std::int64_t sims = 0;
    ai::Effort effort = ai::effort_for(pos.ruleset.game, 5);
    effort.playout_shots = shots;
    return ai::next_turn_value(pos, pos.state, effort, 1.0, sigma, sims);
}

// Level 5's value of the table, played out as far as in 8-ball (these layouts are 9-ball's).
double value_of(const ai::Position& pos) {
    return played_out(pos, ai::effort_for(Game::eight_ball, 5).playout_shots);
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
    ai::next_turn_value(pos, pos.state, ai::effort_for(pos.ruleset.game, 5), 1.0, sigma, sims);
    EXPECT_GT(sims, 0);
}

// The 1 straight in to the S side pocket from 0.4 m, the cue ball 0.3 m behind it; the 9 where
// `nine` says.
ai::Position one_then_nine(Vec2 nine) {
    return position(Game::nine_ball, {1, 9}, {{0, {1.27, 0.7}}, {1, {1.27, 0.4}}, {9, nine}});
}

TEST(PlayOut, OnlyLevelFivePlaysOutFourShotsAndOnlyIn8Ball) {
    // Levels 1-4 keep the second ply (the next shot only); level 5 follows 4 shots in 8-ball (the
    // end of the rack's effort too); 9-ball, whose deeper search costs more per shot, does not.
    for (int level = ai::min_level; level < ai::max_level; ++level) {
        EXPECT_EQ(ai::effort_for(Game::eight_ball, level).playout_shots, 1) << "level " << level;
        EXPECT_EQ(ai::effort_for(Game::nine_ball, level).playout_shots, 1) << "level " << level;
        EXPECT_EQ(ai::effort_for(Game::eight_ball, level, true).playout_shots, 1)
            << "level " << level;
    }
    EXPECT_EQ(ai::effort_for(Game::eight_ball, ai::max_level).playout_shots, 4);
    EXPECT_EQ(ai::effort_for(Game::eight_ball, ai::max_level, true).playout_shots, 4);
    EXPECT_EQ(ai::effort_for(Game::nine_ball, ai::max_level).playout_shots, 1);
    // And the table's value at level 5 is the played-out one.
    const ai::Position pos = one_then_nine({2.3, 0.25});
    EXPECT_EQ(value_of(pos), played_out(pos, 4));
}

TEST(PlayOut, SeesTheWinAnEasyFinishLeads) {
    // After the 1 the 9 is an easy pot: played out, the table is worth about the chance of both
    // pots (a win), more than the one-shot estimate T(q) of the table the 1 leaves.
    const ai::Position pos = one_then_nine({2.3, 0.25});
    const double one = played_out(pos, 1), two = played_out(pos, 2);
    EXPECT_GT(two, one);
    EXPECT_GT(two, 0.9);
    EXPECT_LE(two, 1.0);
    EXPECT_EQ(played_out(pos, 8), two);  // the game ends at the 9: no shot beyond it to play
}

TEST(PlayOut, SeesTheDeadEndTheNextEasyPotLeadsTo) {
    // The 2 is as easy after the 1 as the 9 is above, but the 3 after it is boxed in by four
    // balls: played out two shots, the table is worth less than its one-shot estimate (the
    // shooter pots the 1 and the 2 and then has nothing on), and no less than a safety now.
    const Vec2 three{0.8, 0.9};
    const double g = 2.0 * 0.028575 + 1e-4;
    const ai::Position pos = position(Game::nine_ball, {1, 2, 3, 4, 5, 6, 9},
                                      {{0, {1.27, 0.7}},
                                       {1, {1.27, 0.4}},
                                       {2, {2.3, 0.25}},
                                       {3, three},
                                       {4, three + Vec2{g, 0}},
                                       {5, three + Vec2{-g, 0}},
                                       {6, three + Vec2{0, g}},
                                       {9, three + Vec2{0, -g}}});
    const double one = played_out(pos, 1), three_shots = played_out(pos, 3);
    EXPECT_LT(three_shots, one - 0.05);
    EXPECT_GE(three_shots, ai::table_value(0.0));
}

TEST(PotVariants, StayNearThePotAndInsideTheMiscueLimit) {
    const ai::Position pos = nine_on_the_axis(0.8);
    std::int64_t sims = 0;
    const std::vector<ai::Candidate> pots = ai::pot_candidates(
        pos, pos.state.positions.at(0), false, ai::effort_for(Game::nine_ball, 5), sigma, sims);
    ASSERT_FALSE(pots.empty());
    for (const ai::Candidate& c : pots) {
        const std::vector<ai::Candidate> vs =
            ai::pot_variants(pos, c, ai::effort_for(Game::nine_ball, 5), sims);
        EXPECT_FALSE(vs.empty());
        // The ball's speed (a raised cue drives the ball into the cloth by sin ε of the
        // impulse, and a variant may be raised another way).
        const auto ball_speed = [](const physics::Stroke& st) {
            return st.speed * std::cos(st.elevation_deg * ai::deg);
        };
        for (const ai::Candidate& v : vs) {
            EXPECT_EQ(v.kind, ai::Kind::pot);
            EXPECT_EQ(v.stroke.side, c.stroke.side);
            EXPECT_TRUE(v.stroke.speed != c.stroke.speed || v.stroke.top != c.stroke.top);
            EXPECT_GE(ball_speed(v.stroke), 0.8 * ball_speed(c.stroke));
            EXPECT_LE(ball_speed(v.stroke), 1.2 * ball_speed(c.stroke));
            EXPECT_LE(std::hypot(v.stroke.side, v.stroke.top), 0.44 + 1e-12);
            EXPECT_LT(std::fabs(v.stroke.heading_deg - c.aim->heading_deg), 3.0 + 1e-9);
        }
    }
}

}  // namespace
