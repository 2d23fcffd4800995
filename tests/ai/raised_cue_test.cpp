// Raising the cue so that the swerve of a side-offset error cancels its squirt
// (ai::compensating_elevation, Effort::max_raise_deg).
#include <gtest/gtest.h>

#include <cmath>
#include <optional>

#include "ai/internal/aim.hpp"
#include "ai/internal/candidates.hpp"
#include "ai/internal/ghost_ball.hpp"
#include "ai/internal/level.hpp"
#include "ai_support.hpp"
#include "game/stroke_noise.hpp"

namespace {

using physics::Vec2;

constexpr Vec2 kCue{1.0, 0.6};
constexpr Vec2 kObject{2.0, 0.9};  // 1.04 m from the cue ball, a cut into the far corner

ai::Position two_balls() {
    return ai_test::position(rules::Game::nine_ball, {1}, {{0, kCue}, {1, kObject}});
}

// The pot of ball 1 with the smallest cut.
ai::Aim straightest_pot(const ai::Position& pos) {
    std::optional<ai::Aim> best;
    for (int pocket = 0; pocket < 6; ++pocket) {
        const std::optional<ai::Aim> a =
            ai::direct_aim(pos.table, pos.params.ball_radius, kCue, 1, pocket, pos.state.positions);
        if (a && (!best || a->cut_deg < best->cut_deg)) best = a;
    }
    EXPECT_TRUE(best.has_value());
    return *best;
}

// The direction of ball 1 just after the cue ball strikes it (unit: rad).
double departure(const ai::Position& pos, const physics::Stroke& stroke) {
    const std::vector<physics::BallState> balls = ai::layout(pos.state, kCue);
    const physics::Shot shot = physics::simulate(pos.table, pos.params, balls, &stroke);
    for (const physics::Event& e : shot.events()) {
        if (e.type != physics::EventType::ball_ball) continue;
        const physics::EventBall& b = e.balls[0].id == 1 ? e.balls[0] : e.balls[1];
        return std::atan2(b.vel.y, b.vel.x);
    }
    ADD_FAILURE() << "the cue ball never reached ball 1";
    return 0.0;
}

// How far ball 1's direction turns between side errors of −σ and +σ (unit: rad).
double side_error_turn(const ai::Position& pos, physics::Stroke stroke) {
    const double sigma = game::StrokeNoise{}.offset;
    const double side = stroke.side;
    stroke.side = side + sigma;
    const double plus = departure(pos, stroke);
    stroke.side = side - sigma;
    return plus - departure(pos, stroke);
}

struct Raised {
    double level_turn, raised_turn, elevation_deg;
};

Raised raise(double speed, double top) {
    const ai::Position pos = two_balls();
    const ai::Aim aim = straightest_pot(pos);
    std::int64_t sims = 0;
    physics::Stroke st{.speed = speed, .heading_deg = 0.0, .side = 0.0, .top = top};
    st.heading_deg = ai::refine_heading(pos.table, pos.params, kCue, kObject, aim, st, 2, sims);
    Raised r{side_error_turn(pos, st), 0.0, 0.0};
    r.elevation_deg =
        ai::compensating_elevation(pos.table, pos.params, kCue, kObject, aim, st, 20.0, sims);
    st.elevation_deg = r.elevation_deg;
    st.heading_deg = ai::refine_heading(pos.table, pos.params, kCue, kObject, aim, st, 2, sims);
    r.raised_turn = side_error_turn(pos, st);
    return r;
}

// A soft pot a metre long: on a level cue a side error of one σ turns the object ball by the
// squirt; on the raised cue the swerve takes nearly all of it back.
TEST(RaisedCue, ASoftLongPotCancelsTheSquirtOfASideError) {
    for (double top : {0.0, 0.3, -0.35}) {
        const Raised r = raise(1.0, top);
        EXPECT_GT(r.elevation_deg, 3.0) << "top " << top;
        EXPECT_LE(r.elevation_deg, 20.0) << "top " << top;
        EXPECT_GT(std::fabs(r.level_turn), 1e-3) << "top " << top;
        EXPECT_LT(std::fabs(r.raised_turn), 0.15 * std::fabs(r.level_turn)) << "top " << top;
    }
}

// A hard pot: the ball reaches the object ball before the swerve builds up, so the cue goes
// up to the limit and the error shrinks only a little, but never grows.
TEST(RaisedCue, AHardPotGoesToTheLimitAndNeverDoesWorse) {
    const Raised r = raise(6.0, 0.0);
    EXPECT_DOUBLE_EQ(r.elevation_deg, 20.0);
    EXPECT_LT(std::fabs(r.raised_turn), std::fabs(r.level_turn));
}

// Level 5 raises its cue for pots under noise, but not with side spin meant (on a raised cue
// that spin curves the ball by an amount the speed's error changes); without noise every pot
// is on a level cue, and the levels below 5 keep a level cue.
TEST(RaisedCue, OnlyUnderNoiseAndAtLevelFive) {
    const ai::Position pos = two_balls();
    const ai::Effort effort = ai::effort_for(rules::Game::nine_ball, 5);
    ASSERT_GT(effort.max_raise_deg, 0.0);
    std::int64_t sims = 0;
    const double sigma = ai::heading_sigma_deg(pos.params);
    int raised = 0;
    for (const ai::Candidate& c : ai::pot_candidates(pos, kCue, false, effort, sigma, sims)) {
        EXPECT_GE(c.stroke.elevation_deg, 0.0);
        EXPECT_LE(c.stroke.elevation_deg, effort.max_raise_deg);
        raised += c.stroke.elevation_deg > 0.0;
        if (c.stroke.side != 0.0) {
            EXPECT_EQ(c.stroke.elevation_deg, 0.0);
        }
    }
    EXPECT_GT(raised, 0);
    for (const ai::Candidate& c : ai::pot_candidates(pos, kCue, false, effort, 0.0, sims))
        EXPECT_EQ(c.stroke.elevation_deg, 0.0);
    for (int level = 1; level < 5; ++level)
        EXPECT_EQ(ai::effort_for(rules::Game::nine_ball, level).max_raise_deg, 0.0)
            << "level " << level;
}

}  // namespace
