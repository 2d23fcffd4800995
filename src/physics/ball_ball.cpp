// Ball–ball collisions. The frictional model: a normal impulse with restitution e_ball and a
// tangential friction impulse −min(μ·J_n, m·|s_t|/7)·ŝ_t at the contact, with s_t the slip of
// the two contact points; m/7 is the impulse that ends the slip exactly ("gearing"), since for
// two equal solid spheres a tangential impulse P changes the slip by 7P/m. μ(v) is the fit of
// Alciatore, TP A.14, to Marlow's data. This yields cut-induced and spin-induced throw.
#include <algorithm>
#include <cmath>

#include "physics/energy.hpp"
#include "physics/internal/collide.hpp"
#include "physics/internal/motion.hpp"
#include "physics/portable_math.hpp"

namespace physics::collide {

double ball_ball_friction(const Params& p, double slip_speed) {
    if (p.mu_ball) return *p.mu_ball;
    return 0.00995 + 0.108 * portable::exp(-1.088 * slip_speed);
}

namespace {

/// Keeps the pair's energy at or below `budget` after a pushing contact, taking the excess
/// from the spins first, which leaves the momentum exact; from the velocities only if the spins
/// cannot pay.
void cap_energy(const Params& p, BallState& a, BallState& b, double budget) {
    const double e = kinetic_energy(p, a) + kinetic_energy(p, b);
    if (e <= budget || e <= 0) return;
    const double inertia = 0.4 * p.ball_mass * p.ball_radius * p.ball_radius;
    const double spin_e = 0.5 * inertia * (norm2(a.spin) + norm2(b.spin));
    const double excess = (e - budget) * (1.0 + 1e-12);
    if (spin_e > excess) {
        const double k = std::sqrt((spin_e - excess) / spin_e);
        a.spin = k * a.spin;
        b.spin = k * b.spin;
        return;
    }
    const double k = std::sqrt(budget / e) * (1.0 - 1e-15);
    for (BallState* s : {&a, &b}) {
        s->vel = k * s->vel;
        s->spin = k * s->spin;
    }
}

}  // namespace

double push_speed(const Params& p, const BallState& s, Vec2 toward) {
    return dot(motion::acceleration(p, s), toward) * std::min(kContactTime, motion::duration(p, s));
}

double rebound_speed(double approach, double push, double restitution, bool pushing) {
    if (pushing) return std::max(kSeparationSpeed, 0.5 * push);
    const bool resting = 2.0 * restitution * approach < push;
    return resting ? 0.0 : restitution * approach;
}

double ball_ball(const Params& p, BallBallModel model, BallState& a, BallState& b, bool pushing,
                 bool after_slow) {
    const double m = p.ball_mass, R = p.ball_radius;
    const double budget = kinetic_energy(p, a) + kinetic_energy(p, b);
    const Vec2 n = (1.0 / norm(b.pos - a.pos)) * (b.pos - a.pos);  // from a to b
    const double approach = std::max(0.0, dot(a.vel - b.vel, n));
    // Whether a bounce rests: the pair's relative acceleration into the contact (balls that
    // slow alike do not push). How fast a pushing contact parts: each ball's push, summed, so
    // that a ball wedged in a slow cluster is let go for long enough (fewer events, none of
    // them found missing by the soak; the energy is capped below).
    const double pa = push_speed(p, a, n), pb = push_speed(p, b, -n);
    const double push = pushing ? std::max(0.0, pa) + std::max(0.0, pb) : std::max(0.0, pa + pb);
    // Normal impulse on b (and −J_n·n on a); equal masses, reduced mass m/2.
    const double rebound = after_slow && !pushing && approach < kSlowSpeed
                               ? 0.0
                               : rebound_speed(approach, push, p.e_ball, pushing);
    const double jn = 0.5 * m * (approach + rebound);
    a.vel = a.vel - (jn / m) * n;
    b.vel = b.vel + (jn / m) * n;
    // Slow and pushing contacts are frictionless: their friction impulse is negligible, and it
    // would keep turning spin into approach between wedged balls.
    const bool slow = pushing || approach < kSlowSpeed;
    if (model == BallBallModel::frictional && jn > 0 && !slow) {
        const Vec3 n3 = lift(n);
        // Slip of a's contact point (at +R·n) relative to b's (at −R·n).
        const Vec3 s = lift(a.vel - b.vel) + R * cross(a.spin + b.spin, n3);
        const Vec3 st = s - dot(s, n3) * n3;
        const double slip = norm(st);
        if (slip > 0) {
            const double mag = std::min(ball_ball_friction(p, slip) * jn, m * slip / 7.0);
            const Vec3 impulse = (-mag / slip) * st;  // on a, at its contact point
            const double inertia = 0.4 * m * R * R;
            // The cloth takes the vertical part of the impulse (balls stay on the table).
            a.vel = a.vel + (1.0 / m) * flat(impulse);
            b.vel = b.vel - (1.0 / m) * flat(impulse);
            const Vec3 dw = (R / inertia) * cross(n3, impulse);  // the same for both balls
            a.spin = a.spin + dw;
            b.spin = b.spin + dw;
        }
    }
    if (pushing) cap_energy(p, a, b, budget);
    // Leave the contact settled (tiny slips resolved, see motion::settle) and not approaching:
    // settling can turn a little of the slip back into approach, which a further inelastic
    // normal impulse removes; the correction shrinks by 2/7 each round.
    const double snap = slow ? motion::kSnapSlip : motion::kRollSlip;
    a = motion::settle(p, a, snap);
    b = motion::settle(p, b, snap);
    for (int round = 0; round < 32; ++round) {
        const double again = dot(a.vel - b.vel, n);
        if (again <= 0) break;
        a.vel = a.vel - (0.5 * again) * n;
        b.vel = b.vel + (0.5 * again) * n;
        a = motion::settle(p, a, snap);
        b = motion::settle(p, b, snap);
    }
    return approach;
}

}  // namespace physics::collide
