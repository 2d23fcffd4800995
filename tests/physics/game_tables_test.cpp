// The snooker and carom tables, ball sets and racks (docs/physics.md, "Snooker and carom
// tables"): dimensions, the rounded snooker jaws, the set-ups, and whole breaks.
#include <gtest/gtest.h>

#include <cmath>

#include "physics/layout.hpp"
#include "physics/markings.hpp"
#include "physics/rack.hpp"
#include "physics/simulate.hpp"
#include "physics/table.hpp"

namespace physics {
namespace {

namespace sb = snooker_ball;

const Params kSnooker = *params_preset("snooker");
const Params kCarom = *params_preset("carom");

TEST(GameTables, PresetsHaveTheRulebookDimensions) {
    const TableSpec s = *table_preset("snooker12ft");
    EXPECT_DOUBLE_EQ(s.length, 3.569);
    EXPECT_DOUBLE_EQ(s.width, 1.778);
    EXPECT_TRUE(s.pockets);
    const TableSpec c = *table_preset("carom10ft");
    EXPECT_DOUBLE_EQ(c.length, 2.840);
    EXPECT_DOUBLE_EQ(c.width, 1.420);
    EXPECT_FALSE(c.pockets);
    EXPECT_FALSE(validate_table_spec(s, kSnooker.ball_radius).has_value());
    EXPECT_FALSE(validate_table_spec(c, kCarom.ball_radius).has_value());
    for (std::string_view name : table_preset_names) {
        EXPECT_TRUE(table_preset(name)) << name;
    }
}

TEST(GameTables, BallSets) {
    EXPECT_DOUBLE_EQ(2 * kSnooker.ball_radius, 0.0525);
    EXPECT_DOUBLE_EQ(2 * kCarom.ball_radius, 0.0615);
    EXPECT_GE(kCarom.ball_mass, 0.205);
    EXPECT_LE(kCarom.ball_mass, 0.220);
    EXPECT_LT(kCarom.mu_roll, Params{}.mu_roll);
    EXPECT_GT(kSnooker.mu_roll, Params{}.mu_roll);
    EXPECT_EQ(params_preset("pool")->ball_radius, Params{}.ball_radius);
    EXPECT_FALSE(params_preset("curling"));
}

/// The narrowest gap between two noses of a pocket (unit: m).
double nose_gap(const Table& t, int pocket) {
    std::vector<JawNose> n;
    for (const JawNose& j : t.noses)
        if (j.pocket == pocket) n.push_back(j);
    EXPECT_EQ(n.size(), 2u);
    return norm(n[0].centre - n[1].centre) - n[0].radius - n[1].radius;
}

TEST(GameTables, SnookerPocketsAreNarrowerWithRoundedJaws) {
    const Table snooker = build_table(*table_preset("snooker12ft"));
    const Table pool = build_table(*table_preset("9ft"));
    const double corner = nose_gap(snooker, static_cast<int>(PocketId::SW));
    const double middle = nose_gap(snooker, static_cast<int>(PocketId::S));
    EXPECT_NEAR(corner, 0.089, 0.0005);
    EXPECT_NEAR(middle, 0.105, 0.0005);
    EXPECT_LT(corner / (2 * kSnooker.ball_radius),
              nose_gap(pool, static_cast<int>(PocketId::SW)) / (2 * Params{}.ball_radius));
    for (const JawNose& n : snooker.noses) {
        EXPECT_DOUBLE_EQ(n.radius, 0.035);
    }
}

TEST(GameTables, RoundingMustFitTheJaw) {
    TableSpec s = *table_preset("snooker12ft");
    s.jaw_nose_radius = 0.05;
    s.jaw_depth = 0.04;  // the middle pockets' rounding takes 0.042 m
    const auto problem = validate_table_spec(s, kSnooker.ball_radius);
    ASSERT_TRUE(problem);
    EXPECT_EQ(problem->rfind("jaw_nose_radius:", 0), 0u);
}

TEST(GameTables, SnookerMarks) {
    const SnookerMarkings m = snooker_markings(build_table(*table_preset("snooker12ft")));
    EXPECT_DOUBLE_EQ(m.spot(sb::brown).x, 0.737);
    EXPECT_DOUBLE_EQ(m.spot(sb::yellow).y, 1.778 / 2 - 0.292);  // right of the D from baulk
    EXPECT_DOUBLE_EQ(m.spot(sb::green).y, 1.778 / 2 + 0.292);
    EXPECT_DOUBLE_EQ(m.spot(sb::blue).x, 3.569 / 2);
    EXPECT_DOUBLE_EQ(m.spot(sb::pink).x, 0.75 * 3.569);
    EXPECT_NEAR(m.spot(sb::black).x, 3.569 - 0.324, 1e-12);
    EXPECT_TRUE(m.in_d({0.6, 0.889}));
    EXPECT_FALSE(m.in_d({0.8, 0.889}));
    EXPECT_FALSE(m.in_d({0.44, 0.889}));
    EXPECT_EQ(snooker_value(sb::black), 7);
    EXPECT_EQ(snooker_value(7), 1);
}

TEST(GameTables, SnookerSetUp) {
    const Table t = build_table(*table_preset("snooker12ft"));
    const std::vector<BallState> balls = snooker_rack(t, kSnooker);
    ASSERT_EQ(balls.size(), 22u);
    EXPECT_FALSE(validate_layout(t, kSnooker, balls));
    const SnookerMarkings m = snooker_markings(t);
    EXPECT_TRUE(m.in_d(balls[0].pos));
    for (int c = sb::yellow; c <= sb::black; ++c) {
        EXPECT_EQ(balls[static_cast<std::size_t>(c)].pos, m.spot(c));
    }
    const Vec2 pink = m.spot(sb::pink);
    const Vec2 apex = balls[1].pos;
    EXPECT_NEAR(norm(apex - pink), 2 * kSnooker.ball_radius + 0.001, 1e-12);
    // The reds frozen together: every red touches at least two others.
    for (int i = 1; i <= 15; ++i) {
        int touching = 0;
        for (int j = 1; j <= 15; ++j)
            if (i != j &&
                std::fabs(norm(balls[i].pos - balls[j].pos) - 2 * kSnooker.ball_radius) < 1e-12)
                ++touching;
        EXPECT_GE(touching, 2) << i;
    }
}

TEST(GameTables, CaromStartingPosition) {
    const Table t = build_table(*table_preset("carom10ft"));
    const std::vector<BallState> balls = carom_rack(t);
    ASSERT_EQ(balls.size(), 3u);
    EXPECT_FALSE(validate_layout(t, kCarom, balls));
    EXPECT_EQ(balls[2].pos, (Vec2{0.75 * 2.84, 0.71}));  // red on the top spot
    EXPECT_EQ(balls[1].pos, (Vec2{0.25 * 2.84, 0.71}));  // yellow on the bottom spot
    EXPECT_NEAR(balls[0].pos.y, 0.71 - 0.1825, 1e-12);
    EXPECT_DOUBLE_EQ(balls[0].pos.x, 0.25 * 2.84);
}

TEST(GameTables, SnookerBreakRunsAndIsDeterministic) {
    const Table t = build_table(*table_preset("snooker12ft"));
    const std::vector<BallState> balls = snooker_rack(t, kSnooker);
    const Stroke s{.speed = 7.0, .heading_deg = 5.0, .side = -0.3};
    const Shot a = simulate(t, kSnooker, balls, &s);
    const Shot b = simulate(t, kSnooker, balls, &s);
    EXPECT_FALSE(a.truncated());
    EXPECT_GT(a.events().size(), 30u);
    ASSERT_EQ(a.events().size(), b.events().size());
    for (std::size_t i = 0; i < a.events().size(); ++i) {
        EXPECT_EQ(a.events()[i].time, b.events()[i].time);
        EXPECT_EQ(a.events()[i].balls[0].pos, b.events()[i].balls[0].pos);
    }
    for (const BallState& f : a.final_states())
        if (f.motion != Motion::pocketed) {
            EXPECT_TRUE(t.on_surface(f.pos, kSnooker.ball_radius));
        }
}

TEST(GameTables, StrokeOnTheYellow) {
    const Table t = build_table(*table_preset("carom10ft"));
    const std::vector<BallState> balls = carom_rack(t);
    const Stroke s{.speed = 3.0, .heading_deg = 0.0, .ball = carom_ball::yellow};
    const Shot shot = simulate(t, kCarom, balls, &s);
    ASSERT_FALSE(shot.events().empty());
    EXPECT_EQ(shot.events()[0].type, EventType::strike);
    EXPECT_EQ(shot.events()[0].ball(0), carom_ball::yellow);
    // Straight up the long string the yellow meets the red first.
    for (const Event& e : shot.events())
        if (e.type == EventType::ball_ball) {
            EXPECT_TRUE(e.involves(carom_ball::yellow));
            EXPECT_TRUE(e.involves(carom_ball::red));
            break;
        }
}

}  // namespace
}  // namespace physics
