// The cue strike against Alciatore's closed forms: TP A.30 (speed and spin of an off-centre
// hit), TP A.31 (squirt), natural roll at 2/5 R, miscues and cue elevation.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "physics/cue_strike.hpp"
#include "test_support.hpp"

namespace physics::ptest {
namespace {

const Params kP{};

Stroke stroke(double speed, double heading, double side = 0, double top = 0, double elev = 0) {
    Stroke s;
    s.speed = speed;
    s.heading_deg = heading;
    s.side = side;
    s.top = top;
    s.elevation_deg = elev;
    return s;
}

// TP A.30 for a level cue, tip offsets a (side) and b (top) in units of R:
// v = (1 + e)·V / (1 + m/M + 5/2·(a² + b²)), and ω = 5·v·(offset)/(2R) about the axis the
// offset turns it: ω_z from a, the rolling axis ẑ × d from b.
double tp_a30_speed(const Params& p, double V, double a, double b) {
    return (1.0 + p.cue_tip_e) * V / (1.0 + p.ball_mass / p.cue_mass + 2.5 * (a * a + b * b));
}

// TP A.31: tan θ = (5/2)·a·√(1 − a²) / (1 + m/m_e + (5/2)·(1 − a²)), a the side offset (in R).
double tp_a31_squirt_deg(const Params& p, double a) {
    return std::atan(2.5 * a * std::sqrt(1 - a * a) /
                     (1 + p.ball_mass / p.cue_endmass + 2.5 * (1 - a * a))) /
           kDeg;
}

TEST(Strike, CentreHitSpeedIsTpA30) {
    for (double V : {0.5, 2.0, 7.5}) {
        for (double heading : {0.0, 30.0, 135.0, -100.0}) {
            const StrikeResult r = strike(kP, stroke(V, heading));
            const double M = kP.cue_mass, m = kP.ball_mass;
            const double v = (1.0 + kP.cue_tip_e) * M * V / (M + m);
            EXPECT_FALSE(r.miscue);
            EXPECT_REL(norm(r.vel), v, kExact);
            EXPECT_LE(std::fabs(angle_deg(from_angle(heading), r.vel)), 1e-10);
            EXPECT_LE(norm(r.spin), kExact * v / kP.ball_radius);
            EXPECT_EQ(r.squirt_deg, 0.0);
            // The inverse used to aim a ball speed.
            EXPECT_REL(cue_speed_for_ball_speed(kP, v), V, kExact);
        }
    }
}

TEST(Strike, OffCentreSpeedAndSpinAreTpA30) {
    const double V = 3.0, R = kP.ball_radius;
    for (double a : {-0.45, -0.2, 0.0, 0.3}) {
        for (double b : {-0.4, 0.0, 0.25, 0.4}) {
            if (std::hypot(a, b) > kP.miscue_limit) continue;
            SCOPED_TRACE(testing::Message() << "side " << a << " top " << b);
            const StrikeResult r = strike(kP, stroke(V, 0.0, a, b));
            const double v = tp_a30_speed(kP, V, a, b);
            EXPECT_REL(norm(r.vel), v, kExact);
            // Heading 0: the rolling axis ẑ × x̂ is +y. Follow spins about +y, right english
            // about +z (counter-clockwise from above).
            EXPECT_NEAR(r.spin.x, 0.0, kExact * v / R);
            EXPECT_NEAR(r.spin.y, 2.5 * v * b / R, kExact * v / R);
            EXPECT_NEAR(r.spin.z, 2.5 * v * a / R, kExact * v / R);
        }
    }
}

TEST(Strike, SignsOfEnglishFollowAndDraw) {
    EXPECT_GT(strike(kP, stroke(2, 0, 0.3, 0)).spin.z, 0.0);   // right english: ω_z > 0
    EXPECT_LT(strike(kP, stroke(2, 0, -0.3, 0)).spin.z, 0.0);  // left english
    EXPECT_GT(strike(kP, stroke(2, 0, 0, 0.3)).spin.y, 0.0);   // follow, heading 0
    EXPECT_LT(strike(kP, stroke(2, 0, 0, -0.3)).spin.y, 0.0);  // draw
    // Right english stays ω_z > 0 whatever the heading; follow spins about ẑ × heading.
    for (double heading : {45.0, 90.0, 200.0}) {
        const StrikeResult r = strike(kP, stroke(2, heading, 0.3, 0.3));
        EXPECT_GT(r.spin.z, 0.0);
        const Vec2 axis = perp(from_angle(heading));
        EXPECT_GT(dot(flat(r.spin), axis), 0.0);
        EXPECT_LE(std::fabs(cross(axis, flat(r.spin))), kExact * norm(r.spin));
    }
}

// Natural roll: a tip 2/5 R above centre gives ω = v/R at once, no slip, so the ball starts
// rolling and there is no sliding→rolling transition.
TEST(Strike, NaturalRollAtTopTwoFifths) {
    const Table table = unbounded_table();
    for (double V : {0.3, 2.0, 6.0}) {
        for (double heading : {0.0, 60.0, 250.0}) {
            SCOPED_TRACE(testing::Message() << "V " << V << " heading " << heading);
            const Stroke st = stroke(V, heading, 0.0, 0.4);
            const StrikeResult r = strike(kP, st);
            EXPECT_LE(norm(slip(kP, r.vel, r.spin)), kExact * norm(r.vel));
            const Shot shot = run(table, kP, {make_ball(0, {0, 0})}, &st);
            ASSERT_GE(shot.events().size(), 2u);
            EXPECT_EQ(shot.events()[0].type, EventType::strike);
            EXPECT_EQ(shot.state_at(0, 0.0).motion, Motion::rolling);
            EXPECT_EQ(transition_of(shot, 0, Motion::sliding, Motion::rolling), nullptr);
            ASSERT_EQ(shot.events().size(), 2u);
            EXPECT_EQ(shot.events()[1].from, Motion::rolling);
            EXPECT_EQ(shot.events()[1].to, Motion::stationary);
        }
    }
    // Just off 2/5 R the ball slides first.
    const Stroke st = stroke(2.0, 0.0, 0.0, 0.3);
    const Shot shot = run(table, kP, {make_ball(0, {0, 0})}, &st);
    EXPECT_NE(transition_of(shot, 0, Motion::sliding, Motion::rolling), nullptr);
}

// Squirt: the ball leaves off the stroke line, away from the tip: right english sends it left
// (a positive, counter-clockwise angle), by TP A.31.
TEST(Strike, SquirtDeflectsAwayFromTheTip) {
    for (double a : {0.1, 0.3, 0.5}) {
        for (double heading : {0.0, 120.0}) {
            const StrikeResult right = strike(kP, stroke(3.0, heading, a, 0.0));
            const StrikeResult left = strike(kP, stroke(3.0, heading, -a, 0.0));
            const double expect = tp_a31_squirt_deg(kP, a);
            EXPECT_REL(right.squirt_deg, expect, kExact);
            EXPECT_REL(left.squirt_deg, -expect, kExact);
            EXPECT_NEAR(angle_deg(from_angle(heading), right.vel), expect, 1e-10);
            EXPECT_NEAR(angle_deg(from_angle(heading), left.vel), -expect, 1e-10);
        }
    }
    const double at_half = strike(kP, stroke(3.0, 0.0, 0.5, 0.0)).squirt_deg;
    std::printf("[ info     ] squirt at side = 0.5 R: %.4f deg\n", at_half);
    EXPECT_GT(at_half, 1.0);  // "a few degrees"
    EXPECT_LT(at_half, 8.0);
}

// The squirt's slope at a centre hit is the limit of TP A.31's angle over the offset, and grows
// with the cue's end mass (no end mass, no squirt).
TEST(Strike, SquirtPerSideOffsetIsTheSlopeAtACentreHit) {
    for (double end_mass : {0.001, 0.015, 0.03}) {
        Params p;
        p.cue_endmass = end_mass;
        const double a = 1e-5;
        const double slope = strike(p, stroke(3.0, 0.0, a, 0.0)).squirt_deg * kDeg / a;
        EXPECT_REL(squirt_per_side_offset(p), slope, 1e-8);
    }
    Params light = kP, heavy = kP;
    light.cue_endmass = 1e-9;
    heavy.cue_endmass = 2.0 * kP.cue_endmass;
    EXPECT_LT(squirt_per_side_offset(light), 1e-6);
    EXPECT_GT(squirt_per_side_offset(heavy), 1.5 * squirt_per_side_offset(kP));
}

// An offset beyond miscue_limit is a miscue, reported as the first event.
TEST(Strike, MiscueBeyondTheLimit) {
    const Table table = unbounded_table();
    EXPECT_FALSE(strike(kP, stroke(3.0, 0.0, 0.5, 0.0)).miscue);
    EXPECT_FALSE(strike(kP, stroke(3.0, 0.0, 0.0, -0.5)).miscue);
    EXPECT_FALSE(strike(kP, stroke(3.0, 0.0, -0.25, 0.25)).miscue);
    for (const Stroke& st : {stroke(3.0, 0.0, 0.51, 0.0), stroke(3.0, 0.0, 0.0, -0.7),
                             stroke(3.0, 10.0, 0.36, 0.36)}) {
        EXPECT_TRUE(strike(kP, st).miscue);
        const Shot shot = run(table, kP, {make_ball(0, {0, 0})}, &st);
        ASSERT_FALSE(shot.events().empty());
        EXPECT_EQ(shot.events()[0].type, EventType::miscue);
        EXPECT_EQ(first_event(shot, EventType::strike), nullptr);
    }
    // A different limit moves the boundary.
    Params p = kP;
    p.miscue_limit = 0.7;
    EXPECT_FALSE(strike(p, stroke(3.0, 0.0, 0.6, 0.0)).miscue);
}

// Elevation: the horizontal speed is the level speed times cos(elevation).
TEST(Strike, ElevationReducesHorizontalSpeedByCosine) {
    for (double elev : {5.0, 15.0, 30.0, 60.0}) {
        for (double a : {0.0, 0.2}) {
            for (double b : {0.0, -0.3}) {
                const StrikeResult level = strike(kP, stroke(3.0, 40.0, a, b, 0.0));
                const StrikeResult up = strike(kP, stroke(3.0, 40.0, a, b, elev));
                EXPECT_REL(norm(up.vel), norm(level.vel) * std::cos(elev * kDeg), kExact)
                    << "elevation " << elev << " side " << a << " top " << b;
                EXPECT_NEAR(angle_deg(level.vel, up.vel), 0.0, 1e-10);
            }
        }
    }
    // A centre hit from above puts no spin on the ball.
    EXPECT_LE(norm(strike(kP, stroke(3.0, 40.0, 0, 0, 30.0)).spin), 1e-9);
}

// Through simulate, the strike event reports the strike's velocity and spin.
TEST(Strike, StrikeEventCarriesTheResult) {
    const Table table = unbounded_table();
    const Stroke st = stroke(2.5, 33.0, -0.2, 0.1);
    const StrikeResult r = strike(kP, st);
    const Shot shot = run(table, kP, {make_ball(0, {0.5, 0.5})}, &st);
    ASSERT_FALSE(shot.events().empty());
    const Event& e = shot.events()[0];
    EXPECT_EQ(e.type, EventType::strike);
    EXPECT_EQ(e.time, 0.0);
    EXPECT_EQ(e.balls[0].vel, r.vel);
    EXPECT_EQ(e.balls[0].spin, r.spin);
}

}  // namespace
}  // namespace physics::ptest
