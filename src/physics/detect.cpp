#include "physics/detect.hpp"

#include <algorithm>
#include <cmath>

#include "physics/roots.hpp"

namespace physics::detect {

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();
/// Normal accelerations below this are into contact (unit: m/s²).
constexpr double kPushAccel = -1e-12;

Vec2 position(const motion::Kinematics& k, double t) { return k.p + t * k.v + (0.5 * t * t) * k.a; }

/// Contact of a moving point with a fixed or moving circle of radius D about another point:
/// f(τ) = |Δp + Δv·τ + ½Δa·τ²|² − D², a quartic.
Prediction circle_contact(Vec2 dp, Vec2 dv, Vec2 da, double D, double reach, double horizon) {
    const double dist = norm(dp);
    if (dist - D > reach) return {};
    if (dist - D <= kTouchGap && dist > 0) {
        const double rate = dot(dp, dv) / dist;  // d|Δp|/dt, negative when approaching
        if (rate < -kApproachEps) return {0.0, false};
        // Pushing: no normal speed, and the gap closes within the horizon under the contact's
        // acceleration (d²|Δp|/dt² ≈ curvature / |Δp|).
        const double accel = (norm2(dv) + dot(dp, da)) / dist;
        if (rate <= kApproachEps && accel < kPushAccel && rate < -0.5 * accel * horizon)
            return {0.0, true};
    }
    const roots::Poly4 c{dot(dp, dp) - D * D, 2.0 * dot(dp, dv), dot(dv, dv) + dot(dp, da),
                         dot(dv, da), 0.25 * dot(da, da)};
    return {roots::first_downward_crossing(c, 0.0, horizon), false};
}

}  // namespace

Mover Mover::within(double h) const {
    return h >= horizon ? *this : make_mover(k, h, decelerating);
}

double reach_bound(double speed, double accel, double horizon, bool decelerating) {
    double reach;
    if (std::isinf(horizon)) {
        reach = (speed == 0 && accel == 0) ? 0.0 : kInf;
    } else if (decelerating && accel > 0) {
        const double h = std::min(horizon, speed / accel);  // it stops, then stays
        reach = speed * h - 0.5 * accel * h * h;
    } else {
        reach = speed * horizon + 0.5 * accel * horizon * horizon;
    }
    return std::max(0.0, reach) * (1.0 + 1e-9) + 1e-12;
}

Mover make_mover(const motion::Kinematics& k, double horizon, bool decelerating_along_velocity) {
    return {k, horizon, reach_bound(norm(k.v), norm(k.a), horizon, decelerating_along_velocity),
            decelerating_along_velocity};
}

Prediction ball_ball(const Mover& a, const Mover& b, double R, double horizon) {
    if (a.reach == 0 && b.reach == 0) return {};
    return circle_contact(b.k.p - a.k.p, b.k.v - a.k.v, b.k.a - a.k.a, 2.0 * R, a.reach + b.reach,
                          horizon);
}

Prediction nose(const Mover& m, const JawNose& n, double R) {
    if (m.reach == 0) return {};
    return circle_contact(n.centre - m.k.p, -1.0 * m.k.v, -1.0 * m.k.a, R + n.radius, m.reach,
                          m.horizon);
}

Prediction line(const Mover& m, const CushionLine& l, double R) {
    if (m.reach == 0) return {};
    // Signed gap between the ball's surface and the face: s(τ) = s0 + s1·τ + ½·s2·τ².
    const double s0 = dot(m.k.p - l.a, l.normal) - R;
    if (s0 > m.reach) return {};
    const double s1 = dot(m.k.v, l.normal), s2 = dot(m.k.a, l.normal);
    auto within = [&](double t) {
        const double along = dot(position(m.k, t) - l.a, l.dir);
        return along >= 0.0 && along <= l.length;
    };
    if (s0 <= kTouchGap && s0 >= -1e-6 && within(0.0)) {
        if (s1 < -kApproachEps) return {0.0, false};
        if (s1 <= kApproachEps && s2 < kPushAccel && s1 < -0.5 * s2 * m.horizon) return {0.0, true};
    }
    const double t = roots::first_downward_crossing({s0, s1, 0.5 * s2, 0.0, 0.0}, 0.0, m.horizon);
    if (std::isinf(t) || !within(t)) return {};
    return {t, false};
}

double drop(const Mover& m, const Pocket& pk, double lateral) {
    if (m.reach == 0) return kInf;
    // Depth past the drop line, d(τ); the ball falls when d crosses 0 upward.
    const double d0 = dot(m.k.p - pk.drop_point, pk.inward);
    if (-d0 > m.reach) return kInf;
    const double d1 = dot(m.k.v, pk.inward), d2 = dot(m.k.a, pk.inward);
    double t = d0 >= 0.0 ? 0.0
                         : roots::first_downward_crossing({-d0, -d1, -0.5 * d2, 0.0, 0.0}, 0.0,
                                                          m.horizon);
    if (std::isinf(t)) return kInf;
    if (std::fabs(cross(pk.inward, position(m.k, t) - pk.drop_point)) > lateral) return kInf;
    return t;
}

}  // namespace physics::detect
