// Ball–ball collisions on the unbounded table against known results: the stun-shot 90° rule,
// the rolling-ball 30° rule, stun/follow/draw on a straight shot, conservation of momentum,
// cut- and spin-induced throw (Alciatore TP A.14), and the energy audit.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <vector>

#include "physics/rack.hpp"
#include "physics/scenes.hpp"
#include "test_support.hpp"

namespace physics::ptest {
namespace {

const Params kP{};
const double kR = kP.ball_radius;
const double kG = kP.gravity;

Params with_e_ball(double e) {
    Params p;
    p.e_ball = e;
    return p;
}

/// A cue ball that starts at the origin going +x and arrives, after sliding a distance D with
/// its slip along +x the whole way, with speed vc and spin (0, wy, wz). While the slip points
/// +x, v falls at μs·g and ω_y rises at 5·μs·g/(2R) (docs/physics.md), so
/// v0 = √(vc² + 2·μs·g·D), t = (v0 − vc)/(μs·g) and ω_y0 = wy − 5·μs·g·t/(2R).
/// Needs vc − R·wy > 0 (still sliding forward at contact) and |wz| > spin_decel·t or wz = 0.
struct Arrival {
    BallState ball;
    double t = 0.0;  ///< time of arrival (unit: s)
};
Arrival sliding_arrival(const Params& p, double D, double vc, double wy = 0.0, double wz = 0.0) {
    const double a = p.mu_slide * p.gravity;
    const double v0 = std::sqrt(vc * vc + 2.0 * a * D);
    const double t = (v0 - vc) / a;
    const double wy0 = wy - 2.5 * a * t / p.ball_radius;
    const double wz0 = wz == 0.0 ? 0.0 : wz + std::copysign(p.spin_decel * t, wz);
    return {make_ball(0, {0, 0}, {v0, 0}, {0, wy0, wz0}), t};
}
/// The same for a ball rolling all the way (deceleration μr·g).
Arrival rolling_arrival(const Params& p, double D, double vc) {
    const double a = p.mu_roll * p.gravity;
    const double v0 = std::sqrt(vc * vc + 2.0 * a * D);
    return {make_ball(0, {0, 0}, {v0, 0}, rolling_spin(p, {v0, 0})), (v0 - vc) / a};
}
/// The object ball placed so that a cue ball arriving at (D, 0) going +x meets it with the
/// line of centres at `cut_deg` to +x (counter-clockwise): a cut to the left for cut_deg > 0.
BallState object_for_cut(double D, double cut_deg) {
    return make_ball(1, Vec2{D, 0} + (2.0 * kR) * from_angle(cut_deg));
}

/// The single ball–ball event of a shot, and the two balls just before and after it.
struct Contact {
    const Event* e = nullptr;
    BallState a0, b0, a1, b1;  ///< cue ball and object ball, before and after
    Vec2 n;                    ///< line of centres, cue → object
};
Contact first_contact(const Shot& shot) {
    Contact c;
    c.e = first_event(shot, EventType::ball_ball);
    if (!c.e) return c;
    c.a0 = before(shot, 0, c.e->time);
    c.b0 = before(shot, 1, c.e->time);
    c.a1 = after(*c.e, 0);
    c.b1 = after(*c.e, 1);
    c.n = unit(c.b1.pos - c.a1.pos);
    return c;
}

// ---- the 90° rule ----

// Frictionless, e = 1, a stun (sliding, ω = 0) cue ball: the cue ball keeps the tangential part
// of its velocity and the object ball takes the normal part, so they leave at exactly 90°.
TEST(BallBall, StunShotNinetyDegreeRule) {
    const Params p = with_e_ball(1.0);
    const SimOptions o = options(BallBallModel::frictionless);
    const Table table = unbounded_table();
    for (double cut : {5.0, 20.0, 30.0, 45.0, 60.0, -75.0}) {
        for (double vc : {0.4, 1.0, 3.0}) {
            SCOPED_TRACE(testing::Message() << "cut " << cut << " vc " << vc);
            const double D = 0.4;
            const Arrival arr = sliding_arrival(p, D, vc);
            const Shot shot = run(table, p, {arr.ball, object_for_cut(D, cut)}, nullptr, o);
            const Contact c = first_contact(shot);
            ASSERT_NE(c.e, nullptr);
            // It arrives when and as planned: still a stun ball.
            EXPECT_REL(c.e->time, arr.t, kRoot);
            EXPECT_REL(c.a0.vel.x, vc, kRoot);
            EXPECT_LE(norm(c.a0.spin) * kR, kRoot * vc);
            EXPECT_REL(angle_deg({1, 0}, c.n), cut, kRoot);
            const double cosine = dot(c.a1.vel, c.b1.vel) / (norm(c.a1.vel) * norm(c.b1.vel));
            EXPECT_LE(std::fabs(cosine), kExact);
            // Closed form: tangential part kept, normal part passed on; energy kept.
            const Vec2 vn = dot(c.a0.vel, c.n) * c.n;
            EXPECT_VEC_NEAR(c.a1.vel, c.a0.vel - vn, kExact * vc);
            EXPECT_VEC_NEAR(c.b1.vel, vn, kExact * vc);
            EXPECT_REL(kinetic(p, c.a1) + kinetic(p, c.b1), kinetic(p, c.a0) + kinetic(p, c.b0),
                       kExact);
        }
    }
}

// With e < 1 the object ball still leaves exactly along the line of centres; the cue ball
// keeps (1 − e)/2 of the normal part, so the angle between them is a little under 90°.
TEST(BallBall, StunShotWithRestitutionObjectBallAlongLineOfCentres) {
    const SimOptions o = options(BallBallModel::frictionless);
    const Table table = unbounded_table();
    for (double e : {0.95, 0.8}) {
        const Params p = with_e_ball(e);
        for (double cut : {15.0, 30.0, 50.0}) {
            SCOPED_TRACE(testing::Message() << "e " << e << " cut " << cut);
            const double D = 0.3, vc = 1.5;
            const Arrival arr = sliding_arrival(p, D, vc);
            const Shot shot = run(table, p, {arr.ball, object_for_cut(D, cut)}, nullptr, o);
            const Contact c = first_contact(shot);
            ASSERT_NE(c.e, nullptr);
            EXPECT_LE(std::fabs(cross(c.n, unit(c.b1.vel))), kExact);
            EXPECT_GT(dot(c.n, c.b1.vel), 0.0);
            const double vn = dot(c.a0.vel, c.n);
            EXPECT_REL(norm(c.b1.vel), 0.5 * (1.0 + e) * vn, kExact);
            EXPECT_VEC_NEAR(c.a1.vel, c.a0.vel - (0.5 * (1.0 + e) * vn) * c.n, kExact * vc);
            const double angle = std::fabs(angle_deg(c.a1.vel, c.b1.vel));
            const double vt = std::fabs(cross(c.n, c.a0.vel));
            const double expect = std::atan2(vt, 0.5 * (1.0 - e) * vn) / kDeg;
            EXPECT_REL(angle, expect, kRoot);
            EXPECT_LT(angle, 90.0);
        }
    }
}

// ---- the 30° rule ----

// A rolling cue ball, frictionless, half-ball hit (cut 30°). Right after contact it keeps its
// tangential velocity v_t (plus (1 − e)/2 of the normal part) and its rolling spin; the slip
// u' = v' + R·(ẑ × ω) then ends with velocity v' − (2/7)·u'. For e = 1 the deflection from the
// original line is atan(5√3/13) = 33.7°; for e = 0.95 about 32°: "about 30°".
TEST(BallBall, RollingCueBallThirtyDegreeRule) {
    const SimOptions o = options(BallBallModel::frictionless);
    const Table table = unbounded_table();
    for (double e : {1.0, 0.95, 0.92}) {
        for (double vc : {0.5, 2.0}) {
            for (double cut : {30.0, -30.0}) {
                SCOPED_TRACE(testing::Message() << "e " << e << " vc " << vc << " cut " << cut);
                const Params p = with_e_ball(e);
                const double D = 0.5;
                const Arrival arr = rolling_arrival(p, D, vc);
                const Shot shot = run(table, p, {arr.ball, object_for_cut(D, cut)}, nullptr, o);
                const Contact c = first_contact(shot);
                ASSERT_NE(c.e, nullptr);
                EXPECT_REL(c.e->time, arr.t, kRoot);
                EXPECT_REL(c.a0.vel.x, vc, kRoot);
                const Vec2 u1 = slip(p, c.a1.vel, c.a1.spin);
                const Vec2 v_final = c.a1.vel - (2.0 / 7.0) * u1;
                const Event* roll = transition_of(shot, 0, Motion::sliding, Motion::rolling);
                ASSERT_NE(roll, nullptr);
                ASSERT_GT(roll->time, c.e->time);
                const BallState s = after(*roll, 0);
                EXPECT_VEC_NEAR(s.vel, v_final, kRoot * vc);
                EXPECT_REL(roll->time - c.e->time, 2.0 * norm(u1) / (7.0 * p.mu_slide * kG), kRoot);
                const double deflection = angle_deg({1, 0}, s.vel);
                // The cue ball goes to the side opposite the object ball.
                EXPECT_LT(deflection * cut, 0.0);
                EXPECT_GE(std::fabs(deflection), 28.0);
                EXPECT_LE(std::fabs(deflection), 34.0);
                if (e == 1.0) {
                    EXPECT_NEAR(std::fabs(deflection),
                                std::atan(5.0 * std::sqrt(3.0) / 13.0) / kDeg, 1e-8);
                }
                if (vc == 2.0 && cut > 0)
                    std::printf(
                        "[ info     ] 30-degree rule, e = %.2f: cue ball deflected %.3f deg\n", e,
                        std::fabs(deflection));
            }
        }
    }
}

// ---- straight shots: stun, follow, draw ----

/// Where a ball sliding along x with velocity v and spin ω_y (no collisions after) comes to
/// rest, measured from where it is: the slip u = v − R·ω_y is constant in sign, friction
/// −μs·g·sgn(u) acts for T = 2|u|/(7·μs·g), leaving v_f = v − μs·g·T·sgn(u) = (5v + 2Rω_y)/7;
/// then it rolls v_f²/(2·μr·g) in the direction of v_f.
double straight_rest_offset(const Params& p, double v, double wy) {
    const double u = v - p.ball_radius * wy;
    const double sg = u > 0 ? 1.0 : -1.0;
    const double T = 2.0 * std::fabs(u) / (7.0 * p.mu_slide * p.gravity);
    const double slide = v * T - 0.5 * sg * p.mu_slide * p.gravity * T * T;
    const double vf = v - sg * p.mu_slide * p.gravity * T;
    const double roll = (vf > 0 ? 1.0 : -1.0) * vf * vf / (2.0 * p.mu_roll * p.gravity);
    return slide + roll;
}

enum class Cue { stun, follow, draw };

TEST(BallBall, HeadOnStunFollowDraw) {
    const Table table = unbounded_table();
    const double D = 0.5, vc = 1.5;
    for (BallBallModel model : {BallBallModel::frictionless, BallBallModel::frictional}) {
        for (Cue kind : {Cue::stun, Cue::follow, Cue::draw}) {
            SCOPED_TRACE(testing::Message()
                         << (model == BallBallModel::frictional ? "frictional " : "frictionless ")
                         << static_cast<int>(kind));
            const Arrival arr = kind == Cue::follow ? rolling_arrival(kP, D, vc)
                                : kind == Cue::stun ? sliding_arrival(kP, D, vc, 0.0)
                                                    : sliding_arrival(kP, D, vc, -2.0 * vc / kR);
            const Shot shot =
                run(table, kP, {arr.ball, object_for_cut(D, 0.0)}, nullptr, options(model));
            const Contact c = first_contact(shot);
            ASSERT_NE(c.e, nullptr);
            EXPECT_REL(c.a0.vel.x, vc, kRoot);
            // Normal impulse: the cue ball keeps (1 − e)/2, the object ball gets (1 + e)/2.
            const double e = kP.e_ball;
            EXPECT_REL(c.a1.vel.x, 0.5 * (1.0 - e) * c.a0.vel.x, kExact);
            EXPECT_REL(c.b1.vel.x, 0.5 * (1.0 + e) * c.a0.vel.x, kExact);
            EXPECT_EQ(c.a1.vel.y, 0.0);
            // The cue ball's rest point, from the post-collision slide.
            const std::vector<BallState> rest = shot.final_states();
            const double moved = rest[0].pos.x - c.a1.pos.x;
            switch (kind) {
                case Cue::stun:
                    EXPECT_GT(moved, 0.0);
                    EXPECT_LT(moved, 0.01);
                    break;  // stops
                case Cue::follow:
                    EXPECT_GT(moved, 0.1);
                    break;  // goes on
                case Cue::draw:
                    EXPECT_LT(moved, -0.1);
                    break;  // comes back
            }
            if (model == BallBallModel::frictionless) {
                // Frictionless: the spin is untouched, and the closed form holds exactly.
                EXPECT_LE(norm(c.a1.spin - c.a0.spin), kExact * vc / kR);
                EXPECT_REL(moved, straight_rest_offset(kP, c.a1.vel.x, c.a1.spin.y), kRoot);
                EXPECT_REL(rest[1].pos.x - c.b1.pos.x,
                           straight_rest_offset(kP, c.b1.vel.x, c.b1.spin.y), kRoot);
            }
            EXPECT_EQ(events_of(shot, EventType::ball_ball).size(), 1u);
        }
    }
}

// ---- conservation and the energy audit ----

/// Checks every ball_ball event of a shot: momentum before = after (to rounding: 1e-12 of the
/// pair's speeds), and kinetic energy after ≤ before. Reports the worst event of each kind once.
/// Returns the number of events checked.
int check_ball_ball_events(const Shot& shot, const Params& p) {
    int checked = 0, bad_momentum = 0, bad_energy = 0;
    double worst_p = 0, worst_e = 0;
    std::size_t worst_p_at = 0, worst_e_at = 0;
    for (std::size_t i = 0; i < shot.events().size(); ++i) {
        const Event& e = shot.events()[i];
        if (e.type != EventType::ball_ball) continue;
        const int a = e.ball(0), b = e.ball(1);
        const BallState a0 = before_event(shot, i, a), b0 = before_event(shot, i, b);
        const BallState a1 = after(e, a), b1 = after(e, b);
        const double dp = norm((a1.vel + b1.vel) - (a0.vel + b0.vel));
        const double scale = norm(a0.vel) + norm(b0.vel);
        if (dp > 1e-12 * scale) {
            ++bad_momentum;
            if (dp / scale > worst_p) worst_p = dp / scale, worst_p_at = i;
        }
        const double k0 = kinetic(p, a0) + kinetic(p, b0), k1 = kinetic(p, a1) + kinetic(p, b1);
        if (k1 > k0 * (1.0 + kExact)) {
            ++bad_energy;
            if (k1 / k0 - 1 > worst_e) worst_e = k1 / k0 - 1, worst_e_at = i;
        }
        ++checked;
    }
    EXPECT_EQ(bad_momentum, 0) << "of " << checked << " ball_ball events; worst: event "
                               << worst_p_at << " at t " << shot.events()[worst_p_at].time
                               << ", |Δp| / (|v_a| + |v_b|) = " << worst_p;
    EXPECT_EQ(bad_energy, 0) << "of " << checked << " ball_ball events; worst: event " << worst_e_at
                             << " at t " << shot.events()[worst_e_at].time << ", energy gained "
                             << worst_e << " (relative)";
    return checked;
}

TEST(BallBall, MomentumConservedAndNoEnergyGainedRandomHits) {
    const Table table = unbounded_table();
    for (BallBallModel model : {BallBallModel::frictional, BallBallModel::frictionless}) {
        SplitMix64 rng(model == BallBallModel::frictional ? 11 : 12);
        int checked = 0;
        for (int k = 0; k < 300; ++k) {
            Params p;
            p.e_ball = 0.9 + 0.1 * rng.uniform();
            const double speed = 0.05 + 6.0 * rng.uniform();
            const Vec2 v = speed * from_angle(360.0 * rng.uniform());
            const double s = speed / kR;
            const Vec3 w{s * (2 * rng.uniform() - 1), s * (2 * rng.uniform() - 1),
                         80.0 * (2 * rng.uniform() - 1)};
            // The object ball ahead, within a ball's width of the line; sometimes moving.
            const double dist = 0.1 + 0.6 * rng.uniform();
            const double off = 1.9 * kR * (2 * rng.uniform() - 1);
            const Vec2 pos = dist * unit(v) + off * perp(unit(v));
            Vec2 vb{}, extra{};
            Vec3 wb{};
            if (k % 3 == 0) {
                vb = (0.5 * rng.uniform()) * from_angle(360.0 * rng.uniform());
                wb = {20 * rng.uniform(), -20 * rng.uniform(), 10 * rng.uniform()};
            }
            std::vector<BallState> balls{make_ball(0, {0, 0}, v, w), make_ball(1, pos, vb, wb)};
            if (k % 4 == 0) {  // a third ball further on
                extra = 2.5 * pos + Vec2{0.01 * rng.uniform(), 0.02 * rng.uniform()};
                balls.push_back(make_ball(2, extra));
            }
            const Shot shot = run(table, p, balls, nullptr, options(model));
            ASSERT_FALSE(shot.truncated());
            checked += check_ball_ball_events(shot, p);
        }
        EXPECT_GT(checked, 150);
    }
}

// A slow contact in a cluster (1.9e-9 m/s at t = 1.226 s) on a pocketless table with odd
// parameters, found by fuzz_simulate: settling the pair's tiny slips used to add 2.5e-9 of
// their energy (motion::settle set a sliding ball's spin from its velocity alone).
TEST(BallBall, NoEnergyGainedWhenASlowContactSettlesTinySlips) {
    TableSpec spec = *table_preset("7ft");
    spec.pockets = false;
    spec.cushion_height = 0.0373;
    spec.corner_shelf = 0.02;
    spec.side_shelf = 0.004;
    spec.jaw_depth = 0.06;
    const Table table = build_table(spec);
    Params p;
    p.mu_ball = 0.06;
    p.e_cushion = 0.3;
    p.mu_slide = 0.25;
    const std::vector<BallState> balls = rack(RackType::nine_ball, table, p, 6, std::nullopt);
    Stroke stroke;
    stroke.speed = 7.3;
    const Shot shot = run(table, p, balls, &stroke, options());
    ASSERT_FALSE(shot.truncated());
    // Energy only: a ball jammed in the cluster is stopped there, which is not momentum-exact.
    int slow = 0;
    for (std::size_t i = 0; i < shot.events().size(); ++i) {
        const Event& e = shot.events()[i];
        if (e.type != EventType::ball_ball) continue;
        const int a = e.ball(0), b = e.ball(1);
        const double k0 =
            kinetic(p, before_event(shot, i, a)) + kinetic(p, before_event(shot, i, b));
        const double k1 = kinetic(p, after(e, a)) + kinetic(p, after(e, b));
        EXPECT_LE(k1, k0 * (1 + kExact)) << "event " << i << " at t " << e.time;
        if (e.speed < 1e-6) ++slow;
    }
    EXPECT_GT(slow, 0) << "the shot still has the slow contact it was found with";
}

// The same audit over the busiest shot, a break (frozen balls, simultaneous contacts).
TEST(BallBall, MomentumConservedAndNoEnergyGainedInABreak) {
    for (BallBallModel model : {BallBallModel::frictional, BallBallModel::frictionless}) {
        const Scene scene = standard_scene("break", kP);
        const Table table = build_table(scene.table);
        const Shot shot = run(table, kP, scene.balls, &scene.stroke, options(model));
        ASSERT_FALSE(shot.truncated());
        EXPECT_GT(check_ball_ball_events(shot, kP), 15);
    }
}

// Two touching balls moving together at the same velocity; the one behind slides with more
// topspin than rolling needs, so friction drives it into the one in front: a "pushing" contact
// (no approach speed, an acceleration into contact; collide.hpp, trap 3). Momentum must still be
// conserved at the contact.
TEST(BallBall, MomentumConservedAtAPushingContact) {
    const Table table = unbounded_table();
    for (BallBallModel model : {BallBallModel::frictional, BallBallModel::frictionless}) {
        for (double v : {0.0, 0.2, 1.0, 3.0}) {
            SCOPED_TRACE(testing::Message() << "v " << v << " model " << static_cast<int>(model));
            const BallState a = make_ball(0, {0, 0}, {v, 0}, {0, (v + 0.5) / kR, 0});
            const BallState b = make_ball(1, {2 * kR, 0}, {v, 0}, rolling_spin(kP, {v, 0}));
            const Shot shot = run(table, kP, {a, b}, nullptr, options(model));
            ASSERT_FALSE(shot.truncated());
            ASSERT_FALSE(events_of(shot, EventType::ball_ball).empty());
            EXPECT_GT(check_ball_ball_events(shot, kP), 0);
        }
    }
}

// ---- throw (frictional model) ----

/// Throw of the object ball: its direction's angle from the line of centres (unit: deg).
double throw_deg(const Contact& c) {
    return angle_deg(c.n, c.b1.vel);
}

// Cut-induced throw, stun cue ball: the contact slip is the cue ball's tangential velocity
// v·sin φ; the friction impulse min(μ·J_n, m·v·sin φ/7) with J_n = (1 + e)/2·m·v·cos φ sends the
// object ball off the line of centres toward the cue ball's tangential direction by
// tan θ = min(μ(v·sin φ), 2·tan φ/(7·(1 + e))), μ(v) = 0.00995 + 0.108·exp(−1.088·v) (TP A.14).
TEST(BallBall, CutInducedThrow) {
    const Table table = unbounded_table();
    double half_ball_slow = 0, half_ball_fast = 0;
    for (double cut : {30.0, -30.0, 10.0, 60.0}) {
        for (double vc : {0.5, 1.0, 3.0}) {
            SCOPED_TRACE(testing::Message() << "cut " << cut << " vc " << vc);
            const double D = 0.3;
            const Arrival arr = sliding_arrival(kP, D, vc);
            const Shot shot = run(table, kP, {arr.ball, object_for_cut(D, cut)});
            const Contact c = first_contact(shot);
            ASSERT_NE(c.e, nullptr);
            ASSERT_LE(norm(c.a0.spin) * kR, kRoot * vc);  // a stun ball
            const double v = norm(c.a0.vel), phi = std::fabs(cut) * kDeg;
            const double mu = 0.00995 + 0.108 * std::exp(-1.088 * v * std::sin(phi));
            const double e = kP.e_ball;
            const double expect =
                std::atan(std::min(mu, 2.0 * std::tan(phi) / (7.0 * (1.0 + e)))) / kDeg;
            const double th = throw_deg(c);
            // Toward the cue ball's tangential direction: opposite to the cut's side.
            EXPECT_LT(th * cut, 0.0);
            EXPECT_REL(std::fabs(th), expect, kRoot);
            if (cut == 30.0 && vc == 1.0) half_ball_slow = std::fabs(th);
            if (cut == 30.0 && vc == 3.0) half_ball_fast = std::fabs(th);
            // Momentum: the cue ball takes the opposite tangential impulse.
            EXPECT_VEC_NEAR(c.a1.vel + c.b1.vel, c.a0.vel, kExact * vc);
        }
    }
    std::printf(
        "[ info     ] cut-induced throw, half-ball stun: %.3f deg at 1 m/s, %.3f deg at 3 m/s\n",
        half_ball_slow, half_ball_fast);
    EXPECT_GE(half_ball_slow, 1.0);
    EXPECT_LE(half_ball_slow, 5.0);
    EXPECT_LT(half_ball_fast, half_ball_slow);  // μ(v) falls with the slip speed
}

// Cut-induced throw with a rolling cue ball: the contact slip also has a vertical part, R·ω × n
// = −v·cos φ·ẑ, so |s| = v and only the fraction sin φ of the friction impulse is horizontal:
// tan θ = sin φ·min(μ(v), 2/(7·(1 + e)·cos φ)). Less throw than with a stun ball (TP A.14's
// well-known result); the object ball also gets a little backspin (the vertical part).
TEST(BallBall, CutInducedThrowRollingCueBallIsSmaller) {
    const Table table = unbounded_table();
    for (double cut : {30.0, -45.0, 15.0}) {
        for (double vc : {0.5, 1.0, 3.0}) {
            SCOPED_TRACE(testing::Message() << "cut " << cut << " vc " << vc);
            const double D = 0.3;
            const Shot rolling =
                run(table, kP, {rolling_arrival(kP, D, vc).ball, object_for_cut(D, cut)});
            const Shot stun =
                run(table, kP, {sliding_arrival(kP, D, vc).ball, object_for_cut(D, cut)});
            const Contact c = first_contact(rolling), cs = first_contact(stun);
            ASSERT_NE(c.e, nullptr);
            ASSERT_NE(cs.e, nullptr);
            const double v = norm(c.a0.vel), phi = std::fabs(cut) * kDeg;
            const double mu = 0.00995 + 0.108 * std::exp(-1.088 * v);
            const double expect =
                std::atan(std::sin(phi) *
                          std::min(mu, 2.0 / (7.0 * (1.0 + kP.e_ball) * std::cos(phi)))) /
                kDeg;
            const double th = throw_deg(c);
            EXPECT_LT(th * cut, 0.0);
            EXPECT_REL(std::fabs(th), expect, kRoot);
            EXPECT_LT(std::fabs(th), std::fabs(throw_deg(cs)));
            // Backspin on the object ball: ω about ẑ × n is negative.
            EXPECT_LT(dot(flat(c.b1.spin), perp(c.n)), 0.0);
        }
    }
}

// Spin-induced throw, straight stun shot with side spin ω_z: the cue ball's contact point moves
// at R·ω_z·(ẑ × n), to the left for right english (ω_z > 0) going +x, and drags the object
// ball with it: right english throws the object ball left (+y), the side opposite the english.
// Closed form: tan θ = min(μ(R·|ω_z|)·J_n/m, R·|ω_z|/7)/(J_n/m), J_n/m = (1 + e)/2·v. The object
// ball picks up the opposite z-spin (gearing).
TEST(BallBall, SpinInducedThrow) {
    const Table table = unbounded_table();
    for (double wz : {30.0, -30.0, 8.0, 80.0}) {
        for (double vc : {0.5, 2.0}) {
            SCOPED_TRACE(testing::Message() << "wz " << wz << " vc " << vc);
            const double D = 0.25;
            const Arrival arr = sliding_arrival(kP, D, vc, 0.0, wz);
            const Shot shot = run(table, kP, {arr.ball, object_for_cut(D, 0.0)});
            const Contact c = first_contact(shot);
            ASSERT_NE(c.e, nullptr);
            EXPECT_REL(c.a0.spin.z, wz, kRoot);
            const double s = kR * std::fabs(c.a0.spin.z);
            const double jn = 0.5 * (1.0 + kP.e_ball) * c.a0.vel.x;
            const double mu = 0.00995 + 0.108 * std::exp(-1.088 * s);
            const double expect = std::atan(std::min(mu * jn, s / 7.0) / jn) / kDeg;
            const double th = throw_deg(c);
            EXPECT_GT(th * wz, 0.0);  // right english (wz > 0): thrown left (+y)
            EXPECT_REL(std::fabs(th), expect, kRoot);
            EXPECT_LT(c.b1.spin.z * wz, 0.0);                           // opposite english, geared
            EXPECT_LT(std::fabs(c.a1.spin.z), std::fabs(c.a0.spin.z));  // cue ball loses some
        }
    }
}

}  // namespace
}  // namespace physics::ptest
