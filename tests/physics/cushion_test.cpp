// Ball–cushion collisions: the simple model's mirror bounce, Han 2005 on a rolling ball, the
// energy audit and mirror symmetry for both models, balls running along a rail, and jaw noses.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <vector>

#include "physics/rack.hpp"
#include "test_support.hpp"

namespace physics::ptest {
namespace {

const Params kP{};
const double kR = kP.ball_radius;

// Simple model, e_cushion = 1: the normal velocity flips, the tangential part and the spin are
// kept: angle in = angle out, speed kept.
TEST(Cushion, SimpleElasticBounceMirrorsTheVelocity) {
    Params p;
    p.e_cushion = 1.0;
    const Table table = closed_table();
    const SimOptions o = options(BallBallModel::frictional, CushionModel::simple);
    for (double incidence : {0.0, 20.0, 45.0, 70.0, -60.0}) {  // from the rail's normal
        for (bool rolling : {true, false}) {
            SCOPED_TRACE(testing::Message()
                         << "incidence " << incidence << (rolling ? " rolling" : " stun"));
            // Toward the south rail (normal +y), from the middle of the table.
            const Vec2 dir{std::sin(incidence * kDeg), -std::cos(incidence * kDeg)};
            const Vec2 v = 1.8 * dir;
            const Vec2 r0{0.8, 0.35};
            const BallState b =
                make_ball(0, r0, v, rolling ? rolling_spin(p, v, 12.0) : Vec3{0, 0, 12.0});
            const Shot shot = run(table, p, {b}, nullptr, o);
            const Event* e = first_event(shot, EventType::cushion);
            ASSERT_NE(e, nullptr);
            EXPECT_TRUE(e->rail == static_cast<int>(RailId::SW_S) ||
                        e->rail == static_cast<int>(RailId::S_SE));  // the south rail
            const BallState in = before(shot, 0, e->time), out = after(*e, 0);
            EXPECT_NEAR(out.pos.y, kR, kRoot);
            EXPECT_VEC_NEAR(out.vel, (Vec2{in.vel.x, -in.vel.y}), kExact * norm(in.vel));
            EXPECT_REL(norm(out.vel), norm(in.vel), kExact);
            EXPECT_NEAR(std::atan2(out.vel.x, out.vel.y), std::atan2(in.vel.x, -in.vel.y), 1e-12);
            EXPECT_LE(norm(out.spin - in.spin), kExact * norm(in.spin));
            EXPECT_REL(e->speed, -in.vel.y, kExact);
        }
    }
}

// Han 2005, a ball rolling head-on into a rail (the W rail, normal +x) at speed V, contact at
// height h above the cloth, sin θ = (h − R)/R. Contact velocity: c = V·cos θ normal to the
// nose, slip |s| = V·(1 + sin θ) pointing down and into the cushion. P_N = (1 + e)·m·c (Han
// eq. 17, floored at m·V/cos θ, which just stops the horizontal approach), P_T = min(μ·P_N,
// |s|/A) with A = 7/(2m); the horizontal part of −P_N·N − P_T·ŝ is (P_N·cos θ + P_T·sin θ) outward.
// So the ball comes back, slower than e·V: only cos²θ of the normal impulse acts horizontally
// ((1 + e)·cos²θ − 1 = 0.715 of V for e = 0.85), and the friction on the topspin adds back only
// P_T·sin θ/m (0.096·V).
TEST(Cushion, Han2005RollingBallHeadOn) {
    const Table table = closed_table();
    const double m = kP.ball_mass;
    const double sin_t = (table.spec.cushion_height - kR) / kR;
    const double cos_t = std::sqrt(1.0 - sin_t * sin_t);
    for (double e_c : {0.6, 0.85, 0.95}) {
        for (double V : {0.3, 1.0, 3.0}) {
            SCOPED_TRACE(testing::Message() << "e " << e_c << " V " << V);
            Params p;
            p.e_cushion = e_c;
            const Vec2 v{-V, 0.0};
            // Placed so that it arrives rolling at speed V: start a little further out.
            const double D = 0.4;
            const double v0 = std::sqrt(V * V + 2.0 * p.mu_roll * p.gravity * D);
            const BallState b = make_ball(0, {kR + D, 0.6}, {-v0, 0}, rolling_spin(p, {-v0, 0}));
            const Shot shot = run(table, p, {b}, nullptr, options());
            const Event* e = first_event(shot, EventType::cushion);
            ASSERT_NE(e, nullptr);
            EXPECT_EQ(e->rail, static_cast<int>(RailId::W));
            const BallState in = before(shot, 0, e->time), out = after(*e, 0);
            EXPECT_REL(in.vel.x, v.x, kRoot);
            const double pn = std::max((1.0 + e_c) * m * V * cos_t, m * V / cos_t);
            const double pt = std::min(p.mu_cushion * pn, V * (1.0 + sin_t) / (3.5 / m));
            const double rebound = -V + (pn * cos_t + pt * sin_t) / m;
            EXPECT_GT(out.vel.x, 0.0);  // it comes back
            EXPECT_LT(out.vel.x, e_c * V);
            EXPECT_NEAR(out.vel.y, 0.0, kExact * V);
            EXPECT_REL(out.vel.x, rebound, kRoot);
            EXPECT_LT(kinetic(p, out), kinetic(p, in));
            if (e_c == 0.85 && V == 1.0)
                std::printf(
                    "[ info     ] han2005, rolling head-on at 1 m/s, e 0.85: rebound %.4f m/s\n",
                    out.vel.x);
        }
    }
}

// Han 2005, side spin at a rail: the cushion's friction opposes the contact's slip, so running
// english (spin whose contact point moves backward along the rail: ω_z < 0 for a ball going
// +x into the south rail) widens the rebound angle and reverse english narrows it. The simple
// model ignores spin: the same angle every time.
TEST(Cushion, RunningEnglishWidensTheRebound) {
    const Table table = closed_table();
    const Vec2 v = 1.5 * unit({1.0, -1.0});
    auto rebound_deg = [&](double wz, CushionModel model) {
        const BallState b = make_ball(0, {0.6, 0.4}, v, rolling_spin(kP, v, wz));
        const Shot shot = run(table, kP, {b}, nullptr, options(BallBallModel::frictional, model));
        const Event* e = first_event(shot, EventType::cushion);
        EXPECT_NE(e, nullptr);
        if (!e) return 0.0;
        EXPECT_EQ(e->rail, static_cast<int>(RailId::SW_S));
        const Vec2 out = after(*e, 0).vel;
        EXPECT_GT(out.y, 0.0);
        return std::atan2(out.x, out.y) / kDeg;  // from the rail's normal
    };
    const double none = rebound_deg(0.0, CushionModel::han2005);
    const double running = rebound_deg(-40.0, CushionModel::han2005);
    const double reverse = rebound_deg(40.0, CushionModel::han2005);
    std::printf(
        "[ info     ] han2005 rebound at 45 deg in: %.2f deg plain, %.2f running, %.2f reverse\n",
        none, running, reverse);
    EXPECT_GT(running, none);
    EXPECT_LT(reverse, none);
    EXPECT_NEAR(rebound_deg(-40.0, CushionModel::simple), rebound_deg(40.0, CushionModel::simple),
                1e-9);
}

/// A random ball somewhere on the table, moving with random spin.
BallState random_ball(const Table& t, SplitMix64& rng, int id = 0) {
    const Vec2 pos{kR + 0.05 + rng.uniform() * (t.length() - 2 * kR - 0.1),
                   kR + 0.05 + rng.uniform() * (t.width() - 2 * kR - 0.1)};
    const double speed = 0.2 + 5.0 * rng.uniform();
    const Vec2 v = speed * from_angle(360.0 * rng.uniform());
    const double s = 1.5 * speed / kR;
    const Vec3 w{s * (2 * rng.uniform() - 1), s * (2 * rng.uniform() - 1),
                 60.0 * (2 * rng.uniform() - 1)};
    return make_ball(id, pos, v, w);
}

// Any model: a bounce (rail, jaw facing or jaw nose) never gains kinetic energy.
TEST(Cushion, NoEnergyGainedAtABounce) {
    int checked = 0;
    for (bool pockets : {false, true}) {
        const Table table = pockets ? pocket_table() : closed_table();
        for (CushionModel model : {CushionModel::han2005, CushionModel::simple}) {
            for (double e_c : {0.85, 1.0}) {
                for (double mu_c : {0.2, 0.5}) {
                    Params p;
                    p.e_cushion = e_c;
                    p.mu_cushion = mu_c;
                    SplitMix64 rng(
                        static_cast<std::uint64_t>(1000 * e_c + 10 * mu_c + (pockets ? 7 : 0)));
                    for (int k = 0; k < 40; ++k) {
                        const BallState b = random_ball(table, rng);
                        const Shot shot =
                            run(table, p, {b}, nullptr, options(BallBallModel::frictional, model));
                        ASSERT_FALSE(shot.truncated());
                        for (const Event* e : events_of(shot, EventType::cushion)) {
                            const BallState in = before(shot, 0, e->time), out = after(*e, 0);
                            EXPECT_LE(kinetic(p, out), kinetic(p, in) * (1.0 + kExact))
                                << "t " << e->time << " rail " << e->rail << " pocket " << e->pocket
                                << " e " << e_c << " mu " << mu_c;
                            ++checked;
                        }
                    }
                }
            }
        }
    }
    EXPECT_GT(checked, 500);
}

// Mirror symmetry about the table's long centre line y = W/2: the mirror image of a shot gives
// the mirror image of its events. Under y → W − y: v_y → −v_y, and ω (a pseudovector) →
// (−ω_x, ω_y, −ω_z); rails SW-S ↔ NW-N, S-SE ↔ N-NE; pockets SW ↔ NW, S ↔ N, SE ↔ NE.
BallState mirror(const BallState& b, double W) {
    return make_ball(b.id, {b.pos.x, W - b.pos.y}, {b.vel.x, -b.vel.y},
                     {-b.spin.x, b.spin.y, -b.spin.z});
}
int mirror_rail(int r) {
    switch (static_cast<RailId>(r)) {
        case RailId::SW_S:
            return static_cast<int>(RailId::NW_N);
        case RailId::NW_N:
            return static_cast<int>(RailId::SW_S);
        case RailId::S_SE:
            return static_cast<int>(RailId::N_NE);
        case RailId::N_NE:
            return static_cast<int>(RailId::S_SE);
        default:
            return r;
    }
}
int mirror_pocket(int pk) {
    return pk < 0 ? pk : (pk + 3) % 6;
}

void expect_mirrored(const Shot& a, const Shot& b, double W) {
    ASSERT_EQ(a.events().size(), b.events().size());
    for (std::size_t i = 0; i < a.events().size(); ++i) {
        const Event& x = a.events()[i];
        const Event& y = b.events()[i];
        SCOPED_TRACE(testing::Message() << "event " << i << " t " << x.time);
        ASSERT_EQ(x.type, y.type);
        EXPECT_LE(std::fabs(x.time - y.time), kRoot * (1.0 + x.time));
        EXPECT_EQ(mirror_rail(x.rail), y.rail);
        EXPECT_EQ(mirror_pocket(x.pocket), y.pocket);
        EXPECT_EQ(x.from, y.from);
        EXPECT_EQ(x.to, y.to);
        ASSERT_EQ(x.ball_count, y.ball_count);
        for (int k = 0; k < x.ball_count; ++k) {
            const BallState s = after(x, x.ball(k));
            const BallState m = mirror(after(y, x.ball(k)), W);
            EXPECT_VEC_NEAR(s.pos, m.pos, kRoot);
            EXPECT_VEC_NEAR(s.vel, m.vel, kRoot * (1.0 + norm(s.vel)));
            EXPECT_LE(norm(s.spin - m.spin), kRoot * (1.0 + norm(s.spin)));
        }
    }
}

TEST(Cushion, MirrorSymmetry) {
    const Table table = pocket_table();
    const double W = table.width();
    for (CushionModel model : {CushionModel::han2005, CushionModel::simple}) {
        SplitMix64 rng(model == CushionModel::han2005 ? 5 : 6);
        for (int k = 0; k < 40; ++k) {
            SCOPED_TRACE(testing::Message() << "shot " << k);
            std::vector<BallState> balls{random_ball(table, rng, 0)};
            if (k % 4 == 0) {  // an object ball somewhere (kept if it does not overlap)
                const BallState o = random_ball(table, rng, 1);
                if (norm(o.pos - balls[0].pos) > 3 * kR) balls.push_back(make_ball(1, o.pos));
            }
            std::vector<BallState> mirrored;
            for (const BallState& b : balls) mirrored.push_back(mirror(b, W));
            const SimOptions o = options(BallBallModel::frictional, model);
            const Shot a = run(table, kP, balls, nullptr, o);
            const Shot b = run(table, kP, mirrored, nullptr, o);
            expect_mirrored(a, b, W);
        }
    }
    // A struck shot and its mirror: heading → −heading, side → −side.
    Stroke st;
    st.speed = 4.0;
    st.heading_deg = 23.0;
    st.side = 0.3;
    st.top = -0.2;
    Stroke ms = st;
    ms.heading_deg = -st.heading_deg;
    ms.side = -st.side;
    const BallState cue = make_ball(0, {0.6, 0.4});
    const Shot a = run(table, kP, {cue}, &st);
    const Shot b = run(table, kP, {mirror(cue, W)}, &ms);
    EXPECT_GT(events_of(a, EventType::cushion).size(), 2u);
    expect_mirrored(a, b, W);
}

// A ball rolling (or sliding with side spin) along a rail, touching it, generates no cushion
// events: the contact polynomial is identically zero, not a root.
TEST(Cushion, BallAlongARailTouchingItHasNoCushionEvents) {
    const Table table = closed_table();
    const double L = table.length(), W = table.width();
    struct Case {
        Vec2 pos, vel;
    };
    for (const Case& c : {Case{{0.5, kR}, {0.5, 0}},          // along SW-S and on past S-SE
                          Case{{2.0, W - kR}, {-0.5, 0}},     // along N-NE and NW-N
                          Case{{kR, 0.2}, {0, 0.4}},          // along W
                          Case{{L - kR, 1.0}, {0, -0.4}}}) {  // along E
        for (bool rolling : {true, false}) {
            SCOPED_TRACE(testing::Message() << "at (" << c.pos.x << ", " << c.pos.y << ")"
                                            << (rolling ? " rolling" : " sliding"));
            const Vec3 w = rolling ? rolling_spin(kP, c.vel, 20.0) : Vec3{0, 0, -20.0};
            for (CushionModel model : {CushionModel::han2005, CushionModel::simple}) {
                const Shot shot = run(table, kP, {make_ball(0, c.pos, c.vel, w)}, nullptr,
                                      options(BallBallModel::frictional, model));
                EXPECT_TRUE(events_of(shot, EventType::cushion).empty());
                EXPECT_FALSE(shot.truncated());
                const BallState rest = shot.final_states()[0];
                // It stayed on its line, touching the rail.
                EXPECT_LE(std::fabs(cross(unit(c.vel), rest.pos - c.pos)), kExact);
                EXPECT_GT(norm(rest.pos - c.pos), 0.3);
            }
        }
    }
}

// A ball that hits a jaw nose head-on, far off the pocket's axis (45° to it), bounces off the
// nose and stays out.
TEST(Cushion, BallHittingAJawNoseFarOffAxisStaysOut) {
    const Table table = pocket_table();
    const double L = table.length();
    int tested = 0;
    for (const JawNose& nose : table.noses) {
        // The side pockets' noses: S (1) and N (4). Come from over the mouth at 45° to the axis.
        if (nose.pocket != static_cast<int>(PocketId::S) &&
            nose.pocket != static_cast<int>(PocketId::N))
            continue;
        const double to_mouth = nose.centre.x > L / 2 ? -1.0 : 1.0;  // toward the mouth's middle
        const double into = nose.pocket == static_cast<int>(PocketId::S) ? -1.0 : 1.0;
        const Vec2 d = unit({-to_mouth, into});  // 45° off the axis (0, into)
        for (CushionModel model : {CushionModel::han2005, CushionModel::simple}) {
            for (bool rolling : {false, true}) {
                SCOPED_TRACE(testing::Message()
                             << "nose of pocket " << nose.pocket << " at x " << nose.centre.x
                             << (rolling ? " rolling" : " stun"));
                const Vec2 start = nose.centre - (kR + nose.radius + 0.3) * d;
                const Vec2 v = 1.5 * d;
                const BallState b = make_ball(0, start, v, rolling ? rolling_spin(kP, v) : Vec3{});
                const Shot shot =
                    run(table, kP, {b}, nullptr, options(BallBallModel::frictional, model));
                const Event* e = first_event(shot, EventType::cushion);
                ASSERT_NE(e, nullptr);
                EXPECT_EQ(e->pocket, nose.pocket);
                EXPECT_EQ(e->rail, -1);
                // On the nose itself, head-on.
                const BallState at = after(*e, 0);
                EXPECT_NEAR(norm(at.pos - nose.centre), kR + nose.radius, kRoot);
                EXPECT_LE(std::fabs(cross(d, at.pos - start)), kRoot);
                EXPECT_LT(dot(at.vel, d), 0.0);  // bounced back
                EXPECT_TRUE(events_of(shot, EventType::pocket).empty());
                const BallState rest = shot.final_states()[0];
                EXPECT_NE(rest.motion, Motion::pocketed);
                EXPECT_TRUE(table.on_surface(rest.pos, kR));
                ++tested;
            }
        }
    }
    EXPECT_EQ(tested, 16);
}

}  // namespace
}  // namespace physics::ptest
