// The snooker and three-cushion players (ai/games.hpp): reproducible plans, legal strokes, an
// easy red potted and a colour nominated, an easy three-cushion point, the choice after a foul,
// and whole frames and games between computer players that reach their end with consistent
// scores.
#include "ai/games.hpp"

#include <gtest/gtest.h>

#include <cstring>
#include <numeric>

#include "ai/games_play.hpp"
#include "ai/pause.hpp"
#include "physics/layout.hpp"
#include "physics/markings.hpp"
#include "physics/rack.hpp"
#include "physics/simulate.hpp"

namespace ai {
namespace {

namespace sb = physics::snooker_ball;
using physics::Vec2;

struct SnookerSetup {
    physics::Params params = *physics::params_preset("snooker");
    physics::Table table = physics::build_table(physics::snooker_table_spec());
};

std::vector<physics::BallState> layout(const std::map<int, Vec2>& positions) {
    std::vector<physics::BallState> out;
    for (const auto& [id, p] : positions) {
        physics::BallState b;
        b.id = id;
        b.pos = p;
        out.push_back(b);
    }
    return out;
}

// The colours on their spots, one red 25 cm out of the top-left corner pocket (seen from
// baulk) and the cue ball 60 cm behind it on the line to the pocket: a straight red.
rules::SnookerState easy_red(const SnookerSetup& t) {
    const physics::SnookerMarkings m = physics::snooker_markings(t.table);
    rules::SnookerState s;
    for (int c = sb::yellow; c <= sb::black; ++c) {
        s.on_table.insert(c);
        s.positions[c] = m.spot(c);
    }
    const Vec2 pocket{m.length, m.width};
    const Vec2 dir = (1.0 / physics::norm(Vec2{-1.0, -0.55})) * Vec2{-1.0, -0.55};
    s.on_table.insert(1);
    s.positions[1] = pocket + 0.35 * dir;
    s.positions[sb::cue] = pocket + 0.95 * dir;
    s.cue_ball = rules::CueBall::on_table;
    return s;
}

bool same_stroke(const physics::Stroke& a, const physics::Stroke& b) {
    return std::memcmp(&a.speed, &b.speed, sizeof(double)) == 0 && a.heading_deg == b.heading_deg &&
           a.side == b.side && a.top == b.top && a.elevation_deg == b.elevation_deg &&
           a.ball == b.ball;
}

bool legal_stroke(const physics::Stroke& s, const physics::Params& p) {
    return s.speed > 0.0 && s.speed <= 20.0 && std::hypot(s.side, s.top) <= p.miscue_limit &&
           s.elevation_deg >= 0.0 && s.elevation_deg <= 90.0;
}

rules::SnookerVerdict play(const SnookerPosition& pos, const SnookerPlan& plan) {
    const rules::SnookerState s = with_plan(pos.state, plan);
    const physics::Shot shot =
        physics::simulate(pos.table, pos.params, layout(s.positions), &plan.stroke);
    return rules::judge_snooker(pos.options, pos.snooker, s, shot.events());
}

TEST(SnookerPlayer, SameSeedSamePlanWhateverTheThreads) {
    const SnookerSetup t;
    const SnookerPosition pos =
        snooker_position(t.table, t.params, {}, snooker_start(t.table, t.params, 6));
    const SnookerPlan a = plan_snooker(pos, {3, 1.0, 1}, 42);
    const SnookerPlan b = plan_snooker(pos, {3, 1.0, 2}, 42);
    EXPECT_TRUE(same_stroke(a.stroke, b.stroke));
    EXPECT_EQ(a.cue_pos, b.cue_pos);
    EXPECT_EQ(a.nominated, b.nominated);
    EXPECT_EQ(a.simulations, b.simulations);
    EXPECT_EQ(a.expected_value, b.expected_value);
    // Ball in hand at the break-off: the cue ball goes in the D, clear of the balls.
    ASSERT_TRUE(a.cue_pos);
    EXPECT_TRUE(pos.snooker.marks.in_d(*a.cue_pos));
    EXPECT_TRUE(legal_stroke(a.stroke, t.params));
    EXPECT_FALSE(
        physics::validate_layout(t.table, t.params, layout(with_plan(pos.state, a).positions)));
}

TEST(SnookerPlayer, Level5PotsAnEasyRedThenNominatesAColour) {
    const SnookerSetup t;
    SnookerPosition pos = snooker_position(t.table, t.params, {}, easy_red(t));
    const SnookerPlan plan = plan_snooker(pos, {5, 1.0, 2}, 7);
    EXPECT_EQ(plan.kind, Kind::pot);
    EXPECT_FALSE(plan.nominated);  // a red is on: nothing to nominate
    EXPECT_GT(plan.expected_success, 0.5);
    EXPECT_TRUE(legal_stroke(plan.stroke, t.params));
    const rules::SnookerVerdict v = play(pos, plan);
    EXPECT_FALSE(v.foul);
    EXPECT_EQ(v.points_scored, 1);
    ASSERT_TRUE(v.state.colour_on);
    ASSERT_EQ(v.state.shooter, rules::Player::A);

    pos.state = v.state;
    const SnookerPlan colour = plan_snooker(pos, {5, 1.0, 2}, 8);
    ASSERT_TRUE(colour.nominated);
    EXPECT_TRUE(physics::is_colour(*colour.nominated));
    EXPECT_TRUE(legal_stroke(colour.stroke, t.params));
}

TEST(SnookerPlayer, EscapesASnookerOffACushion) {
    // The only red behind the black, the cue ball straight behind them: no red in view.
    const SnookerSetup t;
    const physics::SnookerMarkings m = physics::snooker_markings(t.table);
    rules::SnookerState s;
    s.on_table = {1, sb::black};
    s.positions[sb::black] = m.spot(sb::black);
    s.positions[1] = m.spot(sb::black) + Vec2{0.12, 0.0};
    s.positions[sb::cue] = m.spot(sb::black) - Vec2{0.5, 0.0};
    s.cue_ball = rules::CueBall::on_table;
    const SnookerPosition pos = snooker_position(t.table, t.params, {}, s);
    const SnookerPlan plan = plan_snooker(pos, {3, 0.0, 2}, 3);
    EXPECT_EQ(plan.kind, Kind::kick);
    EXPECT_FALSE(play(pos, plan).foul);
}

TEST(SnookerPlayer, AfterAFoulChoosesAnOpenOption) {
    const SnookerSetup t;
    const SnookerPosition pos = snooker_position(t.table, t.params, {}, easy_red(t));
    rules::SnookerState before = pos.state;
    // A stroke away from every ball: a foul (no contact), a miss with the red in view.
    physics::Stroke away;
    away.speed = 1.0;
    away.heading_deg = 180.0 + 45.0;
    const physics::Shot shot =
        physics::simulate(t.table, t.params, layout(before.positions), &away);
    const rules::SnookerVerdict v =
        rules::judge_snooker(pos.options, pos.snooker, before, shot.events());
    ASSERT_TRUE(v.foul);
    ASSERT_TRUE(v.may_ask_to_play_again);
    const rules::AfterFoul c = choose_after_foul(pos, v, before, {5, 1.0, 2});
    EXPECT_NO_THROW(rules::resolve_after_foul(v, before, c));
}

TEST(SnookerPlayer, WholeFramesEndWithConsistentScores) {
    SnookerFrameSetup setup;
    setup.reds = 3;
    for (std::uint64_t seed = 1; seed <= 2; ++seed) {
        int points[2] = {0, 0};
        const SnookerFrameReport r = play_snooker_frame(
            setup, {Seat{1, seed}, Seat{2, seed + 10}}, seed, [&](const SnookerStroke& k) {
                const std::size_t me = rules::index(k.before.shooter);
                points[me] += k.verdict.points_scored;
                points[1 - me] += k.verdict.foul_points;
                EXPECT_TRUE(legal_stroke(k.plan.stroke, *physics::params_preset("snooker")));
                EXPECT_EQ(k.verdict.state.scores[0], points[0]);
                EXPECT_EQ(k.verdict.state.scores[1], points[1]);
            });
        EXPECT_FALSE(r.capped) << "seed " << seed;
        ASSERT_TRUE(r.winner);
        EXPECT_GE(r.scores[rules::index(*r.winner)], r.scores[1 - rules::index(*r.winner)]);
        for (int p = 0; p < 2; ++p)
            EXPECT_LE(std::accumulate(r.breaks[p].begin(), r.breaks[p].end(), 0), r.scores[p]);
    }
}

TEST(ThreeCushionPlayer, ScoresTheOpeningAndIsReproducible) {
    const physics::Params params = *physics::params_preset("carom");
    const physics::Table table = physics::build_table(physics::carom_table_spec());
    CaromPosition pos{{}, table, params, {}};
    for (const physics::BallState& b : physics::carom_rack(table))
        pos.state.positions[b.id] = b.pos;
    const CaromPlan a = plan_three_cushion(pos, {5, 1.0, 2}, 11);
    const CaromPlan b = plan_three_cushion(pos, {5, 1.0, 1}, 11);
    EXPECT_TRUE(same_stroke(a.stroke, b.stroke));
    EXPECT_EQ(a.expected_value, b.expected_value);
    EXPECT_EQ(a.stroke.ball, physics::carom_ball::white);
    EXPECT_TRUE(legal_stroke(a.stroke, params));
    EXPECT_GT(a.expected_success, 0.3);
    const physics::Shot shot =
        physics::simulate(table, params, layout(pos.state.positions), &a.stroke);
    const rules::CaromVerdict v = rules::judge_three_cushion(
        pos.options, physics::carom_spots(table), params.ball_radius, pos.state, shot.events());
    EXPECT_TRUE(v.point);
}

// A pause hook (ai/pause.hpp) changes no bit of the snooker or three-cushion plans.
int pauses = 0;
void count_pause() {
    ++pauses;
}

TEST(GamesPauseHook, ChangesNoPlan) {
    const SnookerSetup t;
    const SnookerPosition pos =
        snooker_position(t.table, t.params, {}, snooker_start(t.table, t.params, 6));
    const physics::Params carom = *physics::params_preset("carom");
    const physics::Table carom_table = physics::build_table(physics::carom_table_spec());
    CaromPosition cpos{{}, carom_table, carom, {}};
    for (const physics::BallState& b : physics::carom_rack(carom_table))
        cpos.state.positions[b.id] = b.pos;
    const SnookerPlan a = plan_snooker(pos, {5, 1.0, 1}, 42);
    const CaromPlan c = plan_three_cushion(cpos, {5, 1.0, 1}, 11);
    const SnookerPlan b = plan_snooker(pos, {5, 1.0, 1, &count_pause}, 42);
    const int snooker_pauses = pauses;
    const CaromPlan d = plan_three_cushion(cpos, {5, 1.0, 1, &count_pause}, 11);
    EXPECT_TRUE(same_stroke(a.stroke, b.stroke));
    EXPECT_EQ(a.cue_pos, b.cue_pos);
    EXPECT_EQ(a.nominated, b.nominated);
    EXPECT_EQ(a.simulations, b.simulations);
    EXPECT_EQ(a.expected_value, b.expected_value);
    EXPECT_TRUE(same_stroke(c.stroke, d.stroke));
    EXPECT_EQ(c.expected_value, d.expected_value);
    EXPECT_GT(snooker_pauses, 100);
    EXPECT_GT(pauses - snooker_pauses, 100);
}

TEST(ThreeCushionPlayer, WholeGamesEnd) {
    CaromGameSetup setup;
    setup.options.target = 2;
    const CaromGameReport r = play_three_cushion_game(setup, {Seat{2, 1}, Seat{2, 2}}, 5);
    EXPECT_TRUE(r.over);
    ASSERT_TRUE(r.winner);
    EXPECT_EQ(r.scores[rules::index(*r.winner)], 2);
    EXPECT_LE(r.high_run[0], r.scores[0]);
    EXPECT_LE(r.high_run[1], r.scores[1]);
}

}  // namespace
}  // namespace ai
