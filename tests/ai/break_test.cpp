// The break (candidates.hpp's `tuned_breaks`, `broad_breaks`, `break_candidate`): from just
// behind the head string, full on the apex ball, hard; level 5 breaks with one of the tuned
// breaks in 9-ball, the levels below (and 8-ball) with one of the broad set.
#include <gtest/gtest.h>

#include <cmath>

#include "ai/internal/candidates.hpp"
#include "ai/internal/level.hpp"
#include "ai/internal/planner.hpp"
#include "ai_support.hpp"
#include "physics/rack.hpp"

namespace {

using physics::Vec2;
using rules::Game;

ai::Position racked(Game game, std::uint64_t seed) {
    ai::Position pos;
    pos.ruleset.game = game;
    pos.table = physics::build_table(physics::TableSpec{});
    pos.state = rules::initial_state(game, rules::Player::A);
    pos.state.positions.clear();
    for (const physics::BallState& b :
         physics::rack(game == Game::eight_ball ? physics::RackType::eight_ball
                                                : physics::RackType::nine_ball,
                       pos.table, pos.params, seed))
        if (b.id != 0) pos.state.positions[b.id] = b.pos;
    return pos;
}

int apex_ball(const ai::Position& pos) {
    int apex = -1;
    double x = 1e9;
    for (const auto& [id, p] : pos.state.positions)
        if (id != 0 && p.x < x) {
            x = p.x;
            apex = id;
        }
    return apex;
}

TEST(Breaks, EveryTunedBreakStartsInTheKitchenAndHitsTheApexBallFirst) {
    for (Game game : {Game::eight_ball, Game::nine_ball}) {
        const ai::Position pos = racked(game, 5);
        const std::vector<ai::Candidate> breaks = ai::break_candidates(pos, true);
        ASSERT_EQ(breaks.size(), ai::tuned_breaks.size());
        for (const ai::Candidate& c : breaks) {
            ASSERT_TRUE(c.cue_pos.has_value());
            EXPECT_EQ(c.kind, ai::Kind::break_shot);
            EXPECT_LT(c.cue_pos->x, pos.ruleset.table.head_string_x());
            rules::GameState s = pos.state;
            s.positions[0] = *c.cue_pos;
            const physics::Shot shot =
                physics::simulate(pos.table, pos.params, ai::layout(s, *c.cue_pos), &c.stroke);
            bool first_found = false;
            for (const physics::Event& e : shot.events())
                if (e.type == physics::EventType::ball_ball) {
                    EXPECT_TRUE(e.balls[0].id == 0 || e.balls[1].id == 0);
                    EXPECT_TRUE(e.balls[0].id == apex_ball(pos) || e.balls[1].id == apex_ball(pos));
                    first_found = true;
                    break;
                }
            EXPECT_TRUE(first_found);
        }
    }
}

TEST(Breaks, AreFullOnTheApexBallAndHard) {
    for (const ai::BreakSpec& spec : ai::tuned_breaks) {
        EXPECT_EQ(spec.contact, 0.0);
        EXPECT_GE(spec.speed, 9.5);
        EXPECT_LE(spec.speed, 10.0);  // about 30 mph off the tip: a strong player's break
        EXPECT_LE(std::abs(spec.offset), 0.1);
    }
}

TEST(Breaks, ATakenSpotIsLeftOut) {
    ai::Position pos = racked(Game::nine_ball, 5);
    const Vec2 middle{pos.ruleset.table.head_string_x() - 2.0 * pos.params.ball_radius,
                      pos.table.width() / 2.0};
    pos.state.positions[7] = middle;  // a ball (moved by hand) on the middle spot
    EXPECT_FALSE(ai::break_candidate(pos, {0.0, 0.0, 9.5}).has_value());
    EXPECT_TRUE(ai::break_candidate(pos, {0.15, 0.0, 9.5}).has_value());
}

// Whether the planner's break in `pos` at `level` is one of `break_candidates(pos, tuned)`.
bool breaks_with_one_of(const ai::Position& pos, int level, bool tuned) {
    const ai::Plan p = ai::plan(pos, {level, 1.0, 2}, 4);
    EXPECT_EQ(p.kind, ai::Kind::break_shot);
    bool found = false;
    for (const ai::Candidate& c : ai::break_candidates(pos, tuned)) {
        double heading = std::fmod(c.stroke.heading_deg, 360.0);  // as the planner gives it
        if (heading < 0.0) heading += 360.0;
        found =
            found || (c.stroke.speed == p.decision.stroke.speed &&
                      heading == p.decision.stroke.heading_deg && c.cue_pos == p.decision.cue_pos);
    }
    return found;
}

TEST(Breaks, LevelFiveBreaksWithATunedBreakInNineBallTheOthersWithTheBroadSet) {
    const ai::Position nine = racked(Game::nine_ball, 9);
    EXPECT_TRUE(breaks_with_one_of(nine, ai::max_level, true));
    EXPECT_TRUE(ai::effort_for(Game::nine_ball, ai::max_level).tuned_breaks);
    for (int level = ai::min_level; level < ai::max_level; ++level) {
        EXPECT_FALSE(ai::effort_for(Game::nine_ball, level).tuned_breaks) << "level " << level;
        EXPECT_TRUE(breaks_with_one_of(nine, level, false)) << "level " << level;
    }
    // 8-ball: the broad set at every level.
    const ai::Position eight = racked(Game::eight_ball, 9);
    EXPECT_FALSE(ai::effort_for(Game::eight_ball, ai::max_level).tuned_breaks);
    EXPECT_TRUE(breaks_with_one_of(eight, ai::max_level, false));
    EXPECT_EQ(ai::break_candidates(eight, false).size(), ai::broad_breaks().size());
}

}  // namespace
