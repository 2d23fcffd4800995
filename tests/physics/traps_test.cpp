// The traps of event-based engines (docs/physics.md): touching balls, simultaneous events,
// chatter, motion parallel to a rail.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "physics/energy.hpp"
#include "physics/rack.hpp"
#include "physics/simulate.hpp"

namespace physics {
namespace {

BallState at(int id, double x, double y) {
    BallState b;
    b.id = id;
    b.pos = {x, y};
    return b;
}

const Params kParams;
const double R = kParams.ball_radius;

TEST(Traps, FrozenRowTransmitsTheHit) {
    // Newton's cradle: a row of frozen balls; the cue ball hits the first, the last one leaves.
    // With e = 1 and no friction the momentum passes down the row and the near balls stay
    // (but for the follow of the little spin the cue ball gains on its 0.1 mm way).
    Params p = kParams;
    p.e_ball = 1.0;
    const Table t = build_table(*table_preset("unbounded"));
    std::vector<BallState> balls{at(0, 0.5 - 2 * R - 1e-4, 0.0)};
    balls[0].vel = {2.0, 0.0};
    for (int k = 1; k <= 4; ++k) balls.push_back(at(k, 0.5 + (k - 1) * 2 * R, 0.0));
    SimOptions o;
    o.models.ball_ball = BallBallModel::frictionless;
    const Shot shot = simulate(t, p, balls, nullptr, o);
    // The cascade happens at one instant: just after it, only the far ball moves.
    double first_contact = -1;
    for (const Event& e : shot.events())
        if (e.type == EventType::ball_ball && first_contact < 0) first_contact = e.time;
    ASSERT_GT(first_contact, 0);
    const auto after = shot.states_at(first_contact);
    const double v0 = norm(shot.state_at(0, first_contact - 1e-9).vel);
    for (int k = 0; k < 4; ++k) EXPECT_LT(norm(after[static_cast<std::size_t>(k)].vel), 1e-4 * v0);
    EXPECT_NEAR(norm(after[4].vel), v0, 1e-4 * v0) << "the far ball leaves with all the speed";
    EXPECT_GT(shot.final_states().back().pos.x - balls.back().pos.x, 0.3);
}

TEST(Traps, NewtonsCradleWithRestitutionMatchesSequentialImpulses) {
    // Three touching balls in a line, the first sent into the others as a stun ball at v, with
    // e = 0.95. The pairwise sequential-impulse model: 0 hits 1, 1 hits 2, then 0 (left with
    // (1 − e)/2·v) catches 1 (left with (1 − e)/2·(1 + e)/2·v) at 0.6 mm/s and they part: three
    // collisions, final speeds ≈ (0.0244, 0.0250, 0.9506)·v. All three are at t = 0, touching,
    // so the cloth has no time to act; head-on stun balls have no slip at the contact, so the
    // ball–ball friction gives no impulse; each speed is then a few double operations of the
    // model's closed form: kExact (relative). Afterwards the balls part for good (each behind
    // is the slower, and the cloth slows equal balls alike).
    const double v = 1.0, e = kParams.e_ball;
    ASSERT_EQ(e, 0.95);
    const Table t = build_table(*table_preset("unbounded"));
    std::vector<BallState> balls{at(0, 0.0, 0.0), at(1, 2 * R, 0.0), at(2, 4 * R, 0.0)};
    balls[0].vel = {v, 0.0};                                         // stun: no spin
    const double v0 = 0.5 * (1 - e) * v, v1 = 0.5 * (1 + e) * v;     // 0 hits 1
    const double v1b = 0.5 * (1 - e) * v1, v2 = 0.5 * (1 + e) * v1;  // 1 hits 2
    const double mean = 0.5 * (v0 + v1b), gap = v0 - v1b;            // 0 catches 1
    const double expected[3] = {mean - 0.5 * e * gap, mean + 0.5 * e * gap, v2};
    ASSERT_NEAR(gap, 0.000625 * v, 1e-15);
    for (BallBallModel model : {BallBallModel::frictional, BallBallModel::frictionless}) {
        SimOptions o;
        o.models.ball_ball = model;
        const Shot shot = simulate(t, kParams, balls, nullptr, o);
        int collisions = 0;
        for (const Event& ev : shot.events()) collisions += ev.type == EventType::ball_ball;
        EXPECT_EQ(collisions, 3);
        const std::vector<BallState> after = shot.states_at(0.0);
        for (std::size_t k = 0; k < 3; ++k) {
            EXPECT_NEAR(after[k].vel.x, expected[k], 1e-12 * v) << "ball " << k;
            EXPECT_EQ(after[k].vel.y, 0.0) << "ball " << k;
        }
        std::printf("cradle: %d collisions, speeds %.6f %.6f %.6f\n", collisions, after[0].vel.x,
                    after[1].vel.x, after[2].vel.x);
    }
}

TEST(Traps, RackedBallsAreFrozenAndTheBreakSpreadsThem) {
    const Table t = build_table(*table_preset("9ft"));
    const auto balls = rack(RackType::eight_ball, t, kParams, 11);
    int touching = 0;
    for (std::size_t i = 1; i < balls.size(); ++i)
        for (std::size_t j = 1; j < i; ++j) {
            const double gap = norm(balls[i].pos - balls[j].pos) - 2 * R;
            EXPECT_GT(gap, -1e-12);
            touching += gap < 1e-12;
        }
    EXPECT_EQ(touching, 30) << "a tight 15-ball triangle has 30 touching pairs";
    Stroke s;
    s.speed = 7.0;
    const Shot shot = simulate(t, kParams, balls, &s);
    const auto fin = shot.final_states();
    const double back_row = t.foot_spot().x + 4 * std::sqrt(3.0) * R;
    int back = 0;
    for (std::size_t i = 1; i < fin.size(); ++i) {
        if (std::fabs(balls[i].pos.x - back_row) > 1e-9) continue;
        ++back;
        EXPECT_TRUE(fin[i].motion == Motion::pocketed || norm(fin[i].pos - balls[i].pos) > 0.1)
            << "ball " << fin[i].id << " in the back row: the break must reach it";
    }
    EXPECT_EQ(back, 5);
}

TEST(Traps, BallHittingTwoBallsAtOnce) {
    // The cue ball arrives exactly between two touching balls: both contacts at the same time,
    // resolved in a fixed order, none lost; symmetric outcome up to that order.
    const Table t = build_table(*table_preset("unbounded"));
    std::vector<BallState> balls{at(0, 0.0, 0.0), at(1, 0.6, R), at(2, 0.6, -R)};
    Stroke s;
    s.speed = 2.0;
    const Shot shot = simulate(t, kParams, balls, &s);
    int hits1 = 0, hits2 = 0;
    for (const Event& e : shot.events())
        if (e.type == EventType::ball_ball && e.involves(0)) {
            hits1 += e.involves(1);
            hits2 += e.involves(2);
        }
    EXPECT_GE(hits1, 1);
    EXPECT_GE(hits2, 1);
    // Both contacts at the same instant (ball 1 first: the tie order), none lost.
    ASSERT_GE(shot.events().size(), 3u);
    EXPECT_EQ(shot.events()[1].type, EventType::ball_ball);
    EXPECT_EQ(shot.events()[2].type, EventType::ball_ball);
    EXPECT_EQ(shot.events()[1].time, shot.events()[2].time);
    EXPECT_TRUE(shot.events()[1].involves(1));
    EXPECT_TRUE(shot.events()[2].involves(2));
    const auto fin = shot.final_states();
    EXPECT_GT(fin[1].pos.y, R);
    EXPECT_LT(fin[2].pos.y, -R);
}

TEST(Traps, RollingAlongARailTouchingItMakesNoEvents) {
    const Table t = build_table(*table_preset("9ft"));
    // Frozen to the south rail, rolling past the side pocket's mouth, stopping before the far
    // corner: the side pocket's noses are tangent to the rail line, so it passes them.
    BallState b = at(0, 0.5, R);
    b.vel = {0.6, 0.0};
    b.spin = {0.0, 0.6 / R, 0.0};  // rolling
    const std::vector<BallState> balls{b};
    const Shot shot = simulate(t, kParams, balls, nullptr);
    for (const Event& e : shot.events()) EXPECT_NE(e.type, EventType::cushion);
    EXPECT_NEAR(shot.final_states()[0].pos.y, R, 1e-12);
    EXPECT_GT(shot.final_states()[0].pos.x, t.length() / 2 + 0.1);
}

TEST(Traps, SpinDrivingABallIntoAFrozenBallEndsInFewEvents) {
    // Chatter: a ball with heavy topspin frozen behind another keeps pushing it.
    const Table t = build_table(*table_preset("unbounded"));
    BallState a = at(0, 0.0, 0.0);
    a.spin = {0.0, 60.0, 0.0};  // pure topspin, no speed: it drives forward into ball 1
    const std::vector<BallState> balls{a, at(1, 2 * R, 0.0)};
    const Shot shot = simulate(t, kParams, balls, nullptr);
    EXPECT_FALSE(shot.truncated());
    EXPECT_LT(shot.events().size(), 200u);
    const auto fin = shot.final_states();
    EXPECT_GT(fin[1].pos.x, 2 * R + 0.01) << "the pushed ball moves on";
    EXPECT_GE(norm(fin[1].pos - fin[0].pos), 2 * R - 1e-9);
}

TEST(Traps, TouchingPairSeparatingTooSlowlyToOpenIsStillAContact) {
    // A ball touching another, overlapping it by rounding (a few ulps of 2R), leaving it at
    // 1e-8 m/s while its slip's friction (μs·g ≈ 2 m/s²) drives it back (a case the soak
    // found). The gap would peak at ~3e-17 m, below the overlap, so the contact quartic never
    // turns positive and has no downward crossing; unless taken as a pushing contact, the ball
    // drives 52 µm into the other.
    const Table t = build_table(*table_preset("unbounded"));
    const double D = 2 * R, slip = 0.05;
    for (int ulps : {0, 1, 4, 11, 30}) {
        double x = D;
        for (int k = 0; k < ulps; ++k) x = std::nextafter(x, 0.0);
        BallState b = at(1, x, 0.0);
        b.vel = {1e-8, 0.0133};
        b.spin = {-0.0133 / R, -(slip - 1e-8) / R, 0.0};  // contact slip (0.05, 0) m/s: pulls -x
        const std::vector<BallState> balls{at(0, 0.0, 0.0), b};
        const Shot shot = simulate(t, kParams, balls, nullptr);
        EXPECT_FALSE(shot.truncated());
        double worst = 0.0;
        for (double time = 0.0; time < 0.2; time += 1e-5) {
            const std::vector<BallState> st = shot.states_at(time);
            worst = std::min(worst, norm(st[1].pos - st[0].pos) - D);
        }
        EXPECT_GE(worst, -1e-9) << ulps << " ulps of overlap at the start";
    }
}

TEST(Traps, TouchingPairClosingAtThirdOrderIsAContact) {
    // Found by the soak (coolaaber-soak --seed 7 --from 502580): two sliding balls left
    // touching (overlapping by 4.9e-15 m) by a burst of contacts, with no normal speed and a
    // normal acceleration that all but cancels (|Δv|² = −Δp·Δa to 2e-5 relative), so the gap
    // closes at third order, through Δv·Δa < 0. The quartic never turns positive, so it had no
    // crossing: the balls sank 0.7 µm into each other. The states, as the engine had them.
    const Table t = build_table(*table_preset("9ft"));
    BallState a = at(0, 1.9141790957667011, 0.70408281725002719);
    a.vel = {0.33586800526269461, 0.31541061165386619};
    a.spin = {4.6008868763882127, 28.321252114685976, -1.7776498095597364};
    BallState b = at(7, 1.9544933518262815, 0.6635749999999947);
    b.vel = {0.0025388502720917788, -0.016325774522407448};
    b.spin = {-1.1812765420892579, -0.98397347096152687, 0.20754515837659637};
    const std::vector<BallState> balls{a, b};
    const Shot shot = simulate(t, kParams, balls, nullptr);
    EXPECT_FALSE(shot.truncated());
    double worst = 0.0;
    for (double time = 0.0; time < 0.05; time += 1e-5) {
        const std::vector<BallState> st = shot.states_at(time);
        worst = std::min(worst, norm(st[1].pos - st[0].pos) - 2 * R);
    }
    EXPECT_GE(worst, -1e-9);
}

TEST(Traps, BallLeavingARailTooSlowlyToOpenStaysOnTheBed) {
    // The same at a rail: a ball on the south rail's face (overlapping it by rounding), leaving
    // it at 1e-8 m/s, its slip's friction driving it back into the rail.
    const Table t = build_table(*table_preset("9ft"));
    const double slip = 0.05;
    for (int ulps : {0, 1, 4, 11, 30}) {
        double y = R;
        for (int k = 0; k < ulps; ++k) y = std::nextafter(y, 0.0);
        BallState b = at(0, 0.6, y);
        b.vel = {0.0133, 1e-8};
        b.spin = {(slip - 1e-8) / R, 0.0133 / R, 0.0};  // contact slip (0, 0.05) m/s: pulls -y
        const std::vector<BallState> balls{b};
        const Shot shot = simulate(t, kParams, balls, nullptr);
        EXPECT_FALSE(shot.truncated());
        double lowest = R;
        for (double time = 0.0; time < 0.2; time += 1e-5)
            lowest = std::min(lowest, shot.state_at(0, time).pos.y);
        EXPECT_GE(lowest, R - 1e-9) << ulps << " ulps into the rail at the start";
    }
}

TEST(Traps, SlowBallNudgingARailComesToRest) {
    // A slow ball sliding into a rail with spin that drives it back in: no chatter loop.
    const Table t = build_table(*table_preset("9ft"));
    BallState b = at(0, 1.0, 0.2);
    b.vel = {0.0, -0.01};
    b.spin = {40.0, 0.0, 5.0};  // ω_x > 0 drives the ball toward −y
    const std::vector<BallState> balls{b};
    const Shot shot = simulate(t, kParams, balls, nullptr);
    EXPECT_FALSE(shot.truncated());
    EXPECT_LT(shot.events().size(), 200u);
    EXPECT_GE(shot.final_states()[0].pos.y, R - 1e-9);
}

TEST(Traps, FrictionlessClothEndsAtTheHorizonWithFiniteNumbers) {
    // Found by fuzz_simulate: with mu_slide = 0 a ball left with spin and no velocity slides on
    // the spot forever, touching another; their contact was found again at ever later times
    // (1e89 s, 1e101 s, ...) until the time overflowed into NaNs. A shot ends at the horizon.
    TableSpec spec = *table_preset("7ft");
    spec.pockets = false;
    const Table table = build_table(spec);
    Params p = kParams;
    p.mu_ball = 0.06;
    p.e_cushion = 0.3;
    p.mu_slide = 0.0;
    const std::vector<BallState> balls = rack(RackType::eight_ball, table, p, 6, std::nullopt);
    Stroke stroke;
    stroke.speed = 7.3;
    const Shot shot = simulate(table, p, balls, &stroke);
    EXPECT_TRUE(shot.truncated());
    for (const Event& e : shot.events()) {
        ASSERT_LE(e.time, kHorizon);
        for (int k = 0; k < e.ball_count; ++k)
            ASSERT_TRUE(std::isfinite(e.balls[static_cast<std::size_t>(k)].pos.x));
    }
}

}  // namespace
}  // namespace physics
