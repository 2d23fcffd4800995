// Ball–ball collisions. The frictional model: a normal impulse with restitution e_ball and a
// tangential friction impulse −min(μ·J_n, m·|s_t|/7)·ŝ_t at the contact, with s_t the slip of
// the two contact points; m/7 is the impulse that ends the slip exactly ("gearing"), since for
// two equal solid spheres a tangential impulse P changes the slip by 7P/m. μ(v) is the fit of
// Alciatore, TP A.14, to Marlow's data. This yields cut-induced and spin-induced throw.
#include <algorithm>
#include <cmath>

#include "physics/collide.hpp"
#include "physics/energy.hpp"
#include "physics/motion.hpp"

namespace physics::collide {

double ball_ball_friction(const Params& p, double slip_speed) {
    if (p.mu_ball) return *p.mu_ball;
    return 0.00995 + 0.108 * std::exp(-1.088 * slip_speed);
}

namespace {

/// Scales both balls' motion so the pair's energy is not above `budget` (pushing contacts).
void cap_energy(const Params& p, BallState& a, BallState& b, double budget) {
    const double e = kinetic_energy(p, a) + kinetic_energy(p, b);
    if (e <= budget || e <= 0) return;
    const double k = std::sqrt(budget / e) * (1.0 - 1e-15);
    for (BallState* s : {&a, &b}) {
        s->vel = k * s->vel;
        s->spin = k * s->spin;
    }
}

}  // namespace

double rebound_speed(double approach, double push_accel, double restitution, bool pushing) {
    if (pushing) return std::max(kSeparationSpeed, 0.5 * push_accel * kContactTime);
    const bool resting = 2.0 * restitution * approach < push_accel * kContactTime;
    if (approach < kInelasticSpeed || resting) return 0.0;
    return restitution * approach;
}

double ball_ball(const Params& p, BallBallModel model, BallState& a, BallState& b, bool pushing) {
    const double m = p.ball_mass, R = p.ball_radius;
    const double budget = kinetic_energy(p, a) + kinetic_energy(p, b);
    const Vec2 n = (1.0 / norm(b.pos - a.pos)) * (b.pos - a.pos);  // from a to b
    const double approach = std::max(0.0, dot(a.vel - b.vel, n));
    const double push = std::max(
        0.0, dot(motion::acceleration(p, a) - motion::acceleration(p, b), n));
    // Normal impulse on b (and −J_n·n on a); equal masses, reduced mass m/2.
    const double jn = 0.5 * m * (approach + rebound_speed(approach, push, p.e_ball, pushing));
    a.vel = a.vel - (jn / m) * n;
    b.vel = b.vel + (jn / m) * n;
    if (model == BallBallModel::frictional && jn > 0) {
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
    return approach;
}

}  // namespace physics::collide
