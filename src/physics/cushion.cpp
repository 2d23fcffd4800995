// Ball–cushion collisions (rails, jaw facings, jaw noses).
//
// `han2005`: after Han, "Dynamics in carom and three cushion billiards", J. Mech. Sci. Tech.
// 19(4), 2005. The cushion nose touches the ball above its centre, at height h: the contact
// normal N = (cos θ·n, sin θ) with sin θ = (h − R)/R. The normal impulse P_N = (1 + e)·m·c,
// c = v_n·cos θ the contact's approach speed (Han eq. 17); the tangential impulse at the contact
// opposes its slip s and is capped by Coulomb friction and by the end of slip:
// |P_T| = min(μ·P_N, |s|/A), A = 7/(2m) (Han eqs. 16, 20). The cloth absorbs the vertical part
// of the impulse. Two additions keep the event loop finite: P_N is at least what stops the
// ball's horizontal approach (Han's impulse alone leaves it approaching when e < 1/cos²θ − 1),
// and slow contacts (kSlowSpeed) are perfectly inelastic and frictionless.
//
// `simple`: v_n → −e·v_n, tangential velocity and spin unchanged.
#include <algorithm>
#include <cmath>

#include "physics/energy.hpp"
#include "physics/internal/collide.hpp"
#include "physics/internal/motion.hpp"

namespace physics::collide {

namespace {

double han2005(const Params& p, double h, Vec2 n, BallState& b, bool pushing) {
    const double m = p.ball_mass, R = p.ball_radius;
    const double inertia = 0.4 * m * R * R;
    const double sin_t = std::clamp((h - R) / R, 0.0, 0.999);
    const double cos_t = std::sqrt(1.0 - sin_t * sin_t);
    const Vec3 normal{cos_t * n.x, cos_t * n.y, sin_t};  // centre → contact
    const Vec3 contact = R * normal;
    const double vn = std::max(0.0, dot(b.vel, n));
    const double c = vn * cos_t;
    // Impulse magnitude along −normal. The one that leaves the ball's horizontal normal speed
    // at −w is m·(v_n + w)/cos θ; w = 0 just stops the approach.
    const double push = std::max(0.0, push_speed(p, b, n));
    const double w =
        !pushing && vn < kSlowSpeed ? 0.0 : rebound_speed(vn, push, p.e_cushion, pushing);
    double pn = m * (vn + w) / cos_t;
    if (w > 0 && !pushing) pn = std::max((1.0 + p.e_cushion) * m * c, m * vn / cos_t);
    const Vec3 u = lift(b.vel) + cross(b.spin, contact);
    const Vec3 slip = u - dot(u, normal) * normal;
    const double s = norm(slip);
    Vec3 impulse = (-pn) * normal;
    if (s > 0 && w > 0 && !pushing) {  // slow and resting contacts are frictionless
        const double pt = std::min(p.mu_cushion * pn, s / (3.5 / m));
        impulse = impulse - (pt / s) * slip;
    }
    b.vel = b.vel + (1.0 / m) * flat(impulse);
    b.spin = b.spin + (1.0 / inertia) * cross(contact, impulse);
    return vn;
}

double simple(const Params& p, Vec2 n, BallState& b, bool pushing) {
    const double vn = std::max(0.0, dot(b.vel, n));
    const double push = std::max(0.0, push_speed(p, b, n));
    const double w =
        !pushing && vn < kSlowSpeed ? 0.0 : rebound_speed(vn, push, p.e_cushion, pushing);
    b.vel = b.vel - (vn + w) * n;
    return vn;
}

}  // namespace

double cushion(const Params& p, CushionModel model, double nose_height, Vec2 toward, BallState& b,
               bool pushing) {
    const double budget = kinetic_energy(p, b);
    const double vn = model == CushionModel::han2005 ? han2005(p, nose_height, toward, b, pushing)
                                                     : simple(p, toward, b, pushing);
    if (pushing) {
        const double e = kinetic_energy(p, b);
        if (e > budget && e > 0) {
            const double k = std::sqrt(budget / e) * (1.0 - 1e-15);
            b.vel = k * b.vel;
            b.spin = k * b.spin;
        }
    }
    // Leave the contact settled and not approaching (as for ball–ball contacts).
    const double snap = (pushing || vn < kSlowSpeed) ? motion::kSnapSlip : motion::kRollSlip;
    b = motion::settle(p, b, snap);
    for (int round = 0; round < 32; ++round) {
        const double again = dot(b.vel, toward);
        if (again <= 0) break;
        b.vel = b.vel - again * toward;
        b = motion::settle(p, b, snap);
    }
    return vn;
}

}  // namespace physics::collide
