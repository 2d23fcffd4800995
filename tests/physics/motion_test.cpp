// Motion between events against the closed forms of docs/physics.md: sliding (friction along
// the slip), rolling, spin decay, draw, curving slides, and Shot::state_at.
#include "physics/internal/motion.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "physics/rack.hpp"
#include "physics/scenes.hpp"
#include "test_support.hpp"

namespace physics::ptest {
namespace {

const Params kP{};
const double kG = kP.gravity;
const double kR = kP.ball_radius;

// A centre-hit (stun) ball: ω = 0, so u0 = v0. Slide time 2|u0|/(7·μs·g), distance
// 12·v0²/(49·μs·g), speed 5/7·v0 at the transition; then a roll of (5/7·v0)²/(2·μr·g).
TEST(Motion, StunBallSlidesThenRollsByTheClosedForms) {
    const Table table = unbounded_table();
    for (double v0 : {0.05, 0.5, 1.0, 2.7, 8.0}) {
        for (double heading : {0.0, 37.0, 180.0, 251.0}) {
            SCOPED_TRACE(testing::Message() << "v0 " << v0 << " heading " << heading);
            const Vec2 dir = from_angle(heading);
            const Vec2 r0{0.3, -0.2};
            const Shot shot = run(table, kP, {make_ball(0, r0, v0 * dir)});
            ASSERT_EQ(shot.events().size(), 2u);
            const Event& slide_end = shot.events()[0];
            const Event& stop = shot.events()[1];
            ASSERT_EQ(slide_end.type, EventType::transition);
            EXPECT_EQ(slide_end.from, Motion::sliding);
            EXPECT_EQ(slide_end.to, Motion::rolling);
            EXPECT_EQ(stop.from, Motion::rolling);
            EXPECT_EQ(stop.to, Motion::stationary);

            const double ts = 2.0 * v0 / (7.0 * kP.mu_slide * kG);
            EXPECT_REL(slide_end.time, ts, kExact);
            const BallState s = after(slide_end, 0);
            const double dist = 12.0 * v0 * v0 / (49.0 * kP.mu_slide * kG);
            EXPECT_REL(dot(s.pos - r0, dir), dist, kExact);
            EXPECT_LE(std::fabs(cross(dir, s.pos - r0)), kExact * dist);
            const double v1 = 5.0 / 7.0 * v0;
            EXPECT_REL(norm(s.vel), v1, kExact);
            EXPECT_REL(dot(s.vel, dir), v1, kExact);
            // Rolling at once: ω_xy = (ẑ × v)/R.
            EXPECT_LE(norm(slip(kP, s.vel, s.spin)), kExact * v0);

            const double tr = v1 / (kP.mu_roll * kG);
            EXPECT_REL(stop.time, ts + tr, kExact);
            const BallState rest = after(stop, 0);
            EXPECT_REL(norm(rest.pos - r0), dist + v1 * v1 / (2.0 * kP.mu_roll * kG), kExact);
            EXPECT_EQ(rest.vel, (Vec2{0, 0}));
            EXPECT_EQ(rest.spin, (Vec3{0, 0, 0}));
        }
    }
}

// Rolling: deceleration μr·g along v; stops after |v|/(μr·g), having gone v²/(2·μr·g).
TEST(Motion, RollingBallStopsByTheClosedForms) {
    const Table table = unbounded_table();
    for (double v0 : {0.01, 0.3, 1.0, 4.0}) {
        for (double heading : {0.0, 90.0, 200.0, 333.0}) {
            SCOPED_TRACE(testing::Message() << "v0 " << v0 << " heading " << heading);
            const Vec2 v = v0 * from_angle(heading);
            const Vec2 r0{-1.0, 2.0};
            const Shot shot = run(table, kP, {make_ball(0, r0, v, rolling_spin(kP, v))});
            ASSERT_EQ(shot.events().size(), 1u);
            const Event& stop = shot.events()[0];
            EXPECT_EQ(stop.from, Motion::rolling);
            EXPECT_EQ(stop.to, Motion::stationary);
            const double T = v0 / (kP.mu_roll * kG);
            EXPECT_REL(stop.time, T, kExact);
            const double d = v0 * v0 / (2.0 * kP.mu_roll * kG);
            EXPECT_VEC_NEAR(after(stop, 0).pos, r0 + (d / v0) * v, kExact * (1.0 + d));
            // Half-way in time: speed v0/2, distance 3/4·d.
            const BallState mid = shot.state_at(0, 0.5 * T);
            EXPECT_REL(norm(mid.vel), 0.5 * v0, kExact);
            EXPECT_REL(norm(mid.pos - r0), 0.75 * d, kExact);
            EXPECT_LE(norm(slip(kP, mid.vel, mid.spin)), kExact * v0);
        }
    }
}

// A ball with only z-spin is `spinning`; the spin decays at spin_decel and the ball stays put.
TEST(Motion, ZSpinDecaysInPlace) {
    const Table table = unbounded_table();
    for (double wz : {-40.0, -1.0, 0.3, 25.0}) {
        SCOPED_TRACE(testing::Message() << "wz " << wz);
        const Vec2 r0{0.7, 0.4};
        const Shot shot = run(table, kP, {make_ball(0, r0, {}, {0, 0, wz})});
        EXPECT_EQ(shot.state_at(0, 0.0).motion, Motion::spinning);
        ASSERT_EQ(shot.events().size(), 1u);
        const Event& e = shot.events()[0];
        EXPECT_EQ(e.from, Motion::spinning);
        EXPECT_EQ(e.to, Motion::stationary);
        const double T = std::fabs(wz) / kP.spin_decel;
        EXPECT_REL(e.time, T, kExact);
        for (double f : {0.0, 0.25, 0.5, 0.99, 1.0, 2.0}) {
            const BallState s = shot.state_at(0, f * T);
            EXPECT_EQ(s.pos, r0);  // exactly: nothing moves the centre
            EXPECT_EQ(s.vel, (Vec2{0, 0}));
            const double expect = f >= 1.0 ? 0.0 : wz - std::copysign(kP.spin_decel * f * T, wz);
            EXPECT_NEAR(s.spin.z, expect, kExact * std::fabs(wz));
        }
    }
}

// Spin about z never enters the cloth slip: side spin alone does not curve a ball, rolling or
// sliding.
TEST(Motion, SideSpinAloneDoesNotCurve) {
    const Table table = unbounded_table();
    for (double wz : {-60.0, 35.0}) {
        for (bool rolling : {true, false}) {
            SCOPED_TRACE(testing::Message() << "wz " << wz << (rolling ? " rolling" : " stun"));
            const Vec2 dir = unit({1.0, 0.5});
            const Vec2 v = 2.0 * dir;
            const Vec3 spin = rolling ? rolling_spin(kP, v, wz) : Vec3{0, 0, wz};
            const Vec2 r0{0.1, 0.2};
            const Shot shot = run(table, kP, {make_ball(0, r0, v, spin)});
            const double end = *shot.rest_time();
            for (int k = 0; k <= 40; ++k) {
                const BallState s = shot.state_at(0, end * k / 40.0);
                EXPECT_LE(std::fabs(cross(dir, s.pos - r0)), kExact * (1.0 + norm(s.pos - r0)))
                    << "t " << end * k / 40.0;
                if (norm(s.vel) > 0) {
                    EXPECT_LE(std::fabs(cross(dir, unit(s.vel))), kExact);
                }
            }
            // The z-spin decays on its own clock meanwhile.
            const double t1 = 0.5 * std::fabs(wz) / kP.spin_decel;
            EXPECT_NEAR(shot.state_at(0, t1).spin.z, 0.5 * wz, kExact * std::fabs(wz));
        }
    }
}

// Draw: backspin ω_y < 0 on a ball going +x. The slip u = v0 − R·ω_y > v0 points forward, so
// friction decelerates the ball at μs·g through v = 0 and on until the slip ends at
// t = 2u0/(7·μs·g), with velocity (5·v0 + 2·R·ω_y)/7 < 0 when R·ω_y < −5/2·v0: it comes back.
// (With friction along v instead of along the slip, it would stop at v = 0 and stay.)
TEST(Motion, DrawShotComesBack) {
    const Table table = unbounded_table();
    const double mu = kP.mu_slide;
    for (double v0 : {0.8, 2.0}) {
        for (double k : {3.0, 5.0}) {  // R·ω_y = −k·v0
            SCOPED_TRACE(testing::Message() << "v0 " << v0 << " k " << k);
            const double wy = -k * v0 / kR;
            const Shot shot = run(table, kP, {make_ball(0, {0, 0}, {v0, 0}, {0, wy, 0})});
            const double u0 = v0 - kR * wy;
            const double ts = 2.0 * u0 / (7.0 * mu * kG);
            const Event* roll = transition_of(shot, 0, Motion::sliding, Motion::rolling);
            ASSERT_NE(roll, nullptr);
            EXPECT_REL(roll->time, ts, kExact);
            const BallState s = after(*roll, 0);
            const double vf = (5.0 * v0 + 2.0 * kR * wy) / 7.0;
            EXPECT_LT(vf, 0.0);
            EXPECT_REL(s.vel.x, vf, kExact);
            EXPECT_EQ(s.vel.y, 0.0);
            EXPECT_REL(s.pos.x, v0 * ts - 0.5 * mu * kG * ts * ts, kExact);
            // Furthest point: v = 0 at t = v0/(μs·g), x = v0²/(2·μs·g), still sliding.
            const BallState turn = shot.state_at(0, v0 / (mu * kG));
            EXPECT_NEAR(turn.vel.x, 0.0, kExact * v0);
            EXPECT_REL(turn.pos.x, v0 * v0 / (2.0 * mu * kG), kExact);
            EXPECT_EQ(turn.motion, Motion::sliding);
            // It rolls back, past the point where it was struck when the backspin is strong.
            const Vec2 rest = shot.final_states()[0].pos;
            const double x_rest = s.pos.x - vf * vf / (2.0 * kP.mu_roll * kG);
            EXPECT_REL(rest.x, x_rest, kExact);
            EXPECT_LT(rest.x, s.pos.x);
        }
    }
}

// A curving slide: velocity and slip not parallel. The friction is −μs·m·g·û with û fixed, so
// r(t) = r0 + v0·t − ½·μs·g·t²·û: the path bends away from the slip (toward −û).
TEST(Motion, CurvingSlideFollowsTheParabola) {
    const Table table = unbounded_table();
    const double mu = kP.mu_slide;
    // Spin about +x: the bottom of the ball moves +y, so the slip has a +y part, and the ball
    // is pushed toward −y while it goes +x (a massé-like curve).
    const Vec2 v0{1.5, 0.0};
    const Vec3 w0{30.0, 10.0, 4.0};
    const Vec2 r0{0.0, 0.0};
    const Vec2 u0 = slip(kP, v0, w0);
    ASSERT_GT(std::fabs(cross(unit(u0), unit(v0))), 0.3);  // really not parallel
    const Vec2 uh = unit(u0);
    const Shot shot = run(table, kP, {make_ball(0, r0, v0, w0)});
    const double ts = 2.0 * norm(u0) / (7.0 * mu * kG);
    const Event* roll = transition_of(shot, 0, Motion::sliding, Motion::rolling);
    ASSERT_NE(roll, nullptr);
    EXPECT_REL(roll->time, ts, kExact);
    for (double f : {0.1, 0.3, 0.5, 0.8, 1.0}) {
        const double t = f * ts;
        const BallState s = shot.state_at(0, t);
        const Vec2 expect = r0 + t * v0 - (0.5 * mu * kG * t * t) * uh;
        EXPECT_VEC_NEAR(s.pos, expect, kExact * (1.0 + norm(expect)));
        EXPECT_VEC_NEAR(s.vel, v0 - (mu * kG * t) * uh, kExact * norm(v0));
        // The slip keeps its direction and shrinks at 7/2·μs·g.
        const Vec2 u = slip(kP, s.vel, s.spin);
        EXPECT_VEC_NEAR(u, (1.0 - f) * u0, kExact * norm(u0));
        // The path bends toward −û: below the straight line for this slip.
        if (f > 0) {
            EXPECT_LT(cross(unit(v0), s.pos - r0), 0.0);
        }
    }
    // After the slide the ball rolls straight along its velocity at the transition.
    const BallState s1 = after(*roll, 0);
    const Vec2 rest = shot.final_states()[0].pos;
    EXPECT_LE(std::fabs(cross(unit(s1.vel), rest - s1.pos)), kExact * (1.0 + norm(rest)));
}

// Shot::state_at is the closed form at any time, for a ball that slides (with a curve and
// z-spin), rolls, stops, and keeps spinning.
// Settling resolves a slip below the snap at once into its slide's end state (v − 2/7·u,
// rolling), which loses (1/7)·m·|u|²: never a gain, however small the slip or slow the ball.
TEST(Motion, SettlingATinySlipNeverAddsEnergy) {
    SplitMix64 rng(45);
    for (int k = 0; k < 100000; ++k) {
        const double speed = std::pow(10.0, -4.0 + 4.7 * rng.uniform());
        const double slip = std::pow(10.0, -13.0 + 8.6 * rng.uniform());  // up to 4e-5 m/s
        const Vec2 v = speed * from_angle(360.0 * rng.uniform());
        const Vec2 u = slip * from_angle(360.0 * rng.uniform());
        // cloth_slip = v + R·perp(ω_xy): the rolling spin of v − u leaves the slip u.
        const Vec3 w = rolling_spin(kP, v - u, 30.0 * (2 * rng.uniform() - 1));
        BallState s = make_ball(1, {0.5, 0.5}, v, w);
        s.motion = Motion::sliding;
        const double before = kinetic(kP, s);
        const BallState settled = motion::settle(kP, s, motion::kSnapSlip);
        ASSERT_EQ(settled.motion, Motion::rolling);
        ASSERT_LE(kinetic(kP, settled), before * (1 + 1e-14))
            << "speed " << speed << " m/s, slip " << slip << " m/s";
    }
}

TEST(Motion, StateAtMatchesTheClosedFormAtAnyTime) {
    const Table table = unbounded_table();
    const BallState b0 = make_ball(0, {0.25, -0.5}, {1.2, -0.7}, {-20.0, 35.0, 90.0});
    const Shot shot = run(table, kP, {b0});
    const double end = *shot.rest_time();
    ASSERT_GT(end, 1.0);
    for (int k = 0; k <= 100; ++k) {
        const double t = end * (k / 90.0);  // past the end too
        SCOPED_TRACE(testing::Message() << "t " << t);
        const BallState s = shot.state_at(0, t);
        const BallState r = reference_state(kP, b0, t);
        EXPECT_VEC_NEAR(s.pos, r.pos, kExact * (1.0 + norm(r.pos)));
        EXPECT_VEC_NEAR(s.vel, r.vel, kExact * norm(b0.vel));
        EXPECT_NEAR(s.spin.x, r.spin.x, kExact * norm(b0.spin));
        EXPECT_NEAR(s.spin.y, r.spin.y, kExact * norm(b0.spin));
        EXPECT_NEAR(s.spin.z, r.spin.z, kExact * norm(b0.spin));
    }
    // The last event is the end of the roll or of the z-spin, whichever comes later.
    const BallState rolling = after(*transition_of(shot, 0, Motion::sliding, Motion::rolling), 0);
    const double roll_end = transition_of(shot, 0, Motion::sliding, Motion::rolling)->time +
                            norm(rolling.vel) / (kP.mu_roll * kG);
    EXPECT_REL(end, std::max(roll_end, 90.0 / kP.spin_decel), kExact);
}

// Across every event of a busy shot (the standard break), positions are continuous; across
// transitions velocities and spins are too; and state_at at an event's time is the state the
// event reports.
TEST(Motion, StateAtIsContinuousAcrossEvents) {
    const Scene scene = standard_scene("break", kP);
    const Table table = build_table(scene.table);
    const Shot shot = run(table, kP, scene.balls, &scene.stroke);
    ASSERT_FALSE(shot.truncated());
    ASSERT_GT(shot.events().size(), 50u);
    const auto& events = shot.events();
    for (std::size_t i = 1; i < events.size(); ++i) {
        const Event& e = events[i];
        if (e.type == EventType::pocket) continue;  // the ball leaves the table
        for (int k = 0; k < e.ball_count; ++k) {
            const int id = e.ball(k);
            // Skip a ball with a second event at the same instant: its state "after" is the later.
            bool again = false;
            for (std::size_t j = i + 1; j < events.size() && events[j].time == e.time; ++j)
                again = again || events[j].involves(id);
            if (again) continue;
            SCOPED_TRACE(testing::Message() << "event " << i << " ball " << id);
            const BallState pre = before(shot, id, e.time);
            const BallState at = shot.state_at(id, e.time);
            const BallState post = after(e, id);
            EXPECT_LE(norm(pre.pos - at.pos), 1e-12);
            EXPECT_EQ(at.pos, post.pos);
            EXPECT_EQ(at.vel, post.vel);
            EXPECT_EQ(at.spin, post.spin);
            if (e.type == EventType::transition) {
                // |a|·ulp(t) and the clean snap of a settled state.
                EXPECT_LE(norm(pre.vel - at.vel), 1e-12);
                if (e.to != Motion::stationary && e.to != Motion::spinning) {
                    EXPECT_LE(norm(pre.spin - at.spin), 1e-9);
                }
            }
        }
    }
}

}  // namespace
}  // namespace physics::ptest
