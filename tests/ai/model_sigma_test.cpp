// The heading σ the shot model assumes (ai::model_sigma_deg, Effort::model_sigma_deg): the cue's
// own, except at level 5, which raises its cue against the squirt and assumes less. The engine's
// own pots say which is nearer the truth.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <vector>

#include "ai/internal/candidates.hpp"
#include "ai/internal/evaluate.hpp"
#include "ai/internal/ghost_ball.hpp"
#include "ai/internal/level.hpp"
#include "ai/internal/planner.hpp"
#include "ai_support.hpp"

namespace {

using physics::Vec2;

physics::Params without_squirt() {
    physics::Params p;
    p.cue_endmass = 1e-9;
    return p;
}

TEST(ModelSigma, LevelFiveAssumesLessThanTheCuesOwn) {
    const physics::Params params;
    const ai::Effort five = ai::effort_for(rules::Game::nine_ball, 5);
    EXPECT_DOUBLE_EQ(ai::model_sigma_deg(params, five, 1.0), 0.14);
    EXPECT_LT(ai::model_sigma_deg(params, five, 1.0), ai::heading_sigma_deg(params));
    EXPECT_DOUBLE_EQ(ai::model_sigma_deg(params, five, 5.0), 0.70);
    EXPECT_DOUBLE_EQ(ai::model_sigma_deg(params, five, 0.0), 0.0);
}

TEST(ModelSigma, LevelsOneToFourAssumeTheCuesOwn) {
    const physics::Params params;
    for (int level = 1; level <= 4; ++level)
        for (rules::Game game : {rules::Game::eight_ball, rules::Game::nine_ball}) {
            const double m = ai::noise_multiplier(level);
            EXPECT_DOUBLE_EQ(ai::model_sigma_deg(params, ai::effort_for(game, level), m),
                             ai::heading_sigma_deg(params) * m)
                << "level " << level;
        }
}

// Without squirt the cue's own σ (the noise model's 0.125°) is below level 5's 0.14°: kept.
TEST(ModelSigma, NeverAboveTheCuesOwn) {
    const physics::Params params = without_squirt();
    EXPECT_DOUBLE_EQ(ai::model_sigma_deg(params, ai::effort_for(rules::Game::nine_ball, 5), 1.0),
                     ai::heading_sigma_deg(params));
}

struct Tally {
    double potted = 0.0;   // the share of the draws potted, summed over the strokes
    double at_cue = 0.0;   // the model's chance at the cue's own σ, summed
    double at_five = 0.0;  // the same at level 5's σ
    int strokes = 0;
};

// Every direct pot of the 9 from `cue`, each of `effort`'s strokes played on every draw.
void tally_pots(Vec2 cue, Vec2 object, const ai::Effort& effort,
                const std::vector<ai::NoiseDraw>& draws, Tally& t) {
    const ai::Position pos =
        ai_test::position(rules::Game::nine_ball, {9}, {{0, cue}, {9, object}});
    const double R = pos.params.ball_radius;
    const double cue_sigma = ai::heading_sigma_deg(pos.params);
    const double five_sigma = ai::model_sigma_deg(pos.params, effort, 1.0);
    const std::vector<physics::BallState> balls = ai::layout(pos.state, cue);
    std::int64_t sims = 0;
    for (const ai::RankedAim& r : ai::ranked_aims(pos, cue, cue_sigma))
        for (const ai::Candidate& c : ai::pot_strokes(pos, cue, false, r, effort, sims)) {
            for (const ai::NoiseDraw& draw : draws) {
                const physics::Stroke s = ai::with_draw(c.stroke, draw, 1.0);
                const physics::Shot shot = physics::simulate(pos.table, pos.params, balls, &s);
                for (const physics::Event& e : shot.events())
                    if (e.type == physics::EventType::pocket && e.balls[0].id == 9 &&
                        e.pocket == r.aim.pocket)
                        t.potted += 1.0 / static_cast<double>(draws.size());
            }
            t.at_cue += ai::aim_chance(r.aim, R, cue_sigma);
            t.at_five += ai::aim_chance(r.aim, R, five_sigma);
            ++t.strokes;
        }
}

// Level 5's raised stun and follow pots, each played on 32 noise draws at 1×, over layouts with
// the 9 on a grid and the cue ball 0.5–1.1 m from it: the share potted lies nearer the model's
// chance at level 5's σ than at the cue's own, which under-rates them.
TEST(ModelSigma, TheEnginePotsLevelFivesRaisedStrokesNearerItsSigma) {
    ai::Effort effort = ai::effort_for(rules::Game::nine_ball, 5);
    effort.speeds = 2;  // 1.3 and 2.1 × the speed that just gets the ball there
    effort.spins = 2;   // stun and follow: no side, so raised
    const std::vector<ai::NoiseDraw> draws = ai::noise_draws(7, 32);
    const physics::Table table = physics::build_table(physics::TableSpec{});
    Tally t;
    for (double x : {0.5, 1.0, 1.5, 2.0})
        for (double y : {0.35, 0.9})
            for (double d : {0.5, 0.8, 1.1})
                for (double angle_deg : {20.0, 160.0, 250.0}) {
                    const double a = angle_deg * M_PI / 180.0;
                    const Vec2 cue{x + d * std::cos(a), y + d * std::sin(a)};
                    if (cue.x < 0.1 || cue.x > table.length() - 0.1 || cue.y < 0.1 ||
                        cue.y > table.width() - 0.1)
                        continue;
                    tally_pots(cue, {x, y}, effort, draws, t);
                }
    ASSERT_GT(t.strokes, 100);
    const double engine = t.potted / t.strokes, cue = t.at_cue / t.strokes,
                 five = t.at_five / t.strokes;
    EXPECT_LT(std::abs(engine - five), std::abs(engine - cue))
        << "potted " << engine << ", the model at level 5's σ " << five << ", at the cue's " << cue
        << " (" << t.strokes << " strokes)";
    EXPECT_GT(engine, cue + 0.05) << "the cue's own σ no longer under-rates raised pots";
}

}  // namespace
