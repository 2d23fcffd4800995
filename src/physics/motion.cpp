#include "physics/internal/motion.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace physics::motion {

namespace {

/// Spin about z decays linearly toward zero at spin_decel.
double decay_z(double wz, double drop) {
    return wz > 0 ? std::max(wz - drop, 0.0) : std::min(wz + drop, 0.0);
}

Vec2 unit_or_zero(Vec2 v) {
    double n = norm(v);
    return n > 0 ? (1.0 / n) * v : Vec2{};
}

}  // namespace

Vec2 cloth_slip(const Params& p, Vec2 vel, Vec3 spin) {
    return vel + p.ball_radius * perp(flat(spin));
}

Vec2 acceleration(const Params& p, const BallState& s) {
    switch (s.motion) {
        case Motion::sliding:
            // Friction opposes the slip, not the velocity.
            return (-p.mu_slide * p.gravity) * unit_or_zero(cloth_slip(p, s.vel, s.spin));
        case Motion::rolling:
            return (-p.mu_roll * p.gravity) * unit_or_zero(s.vel);
        default:
            return {};
    }
}

double duration(const Params& p, const BallState& s) {
    switch (s.motion) {
        case Motion::sliding:
            // |u| falls at (7/2)·μ_slide·g (the slip's own deceleration).
            return 2.0 * norm(cloth_slip(p, s.vel, s.spin)) / (7.0 * p.mu_slide * p.gravity);
        case Motion::rolling:
            return norm(s.vel) / (p.mu_roll * p.gravity);
        case Motion::spinning:
            return std::fabs(s.spin.z) / p.spin_decel;
        default:
            return std::numeric_limits<double>::infinity();
    }
}

BallState evolve(const Params& p, const BallState& s, double dt) {
    if (s.motion == Motion::stationary || s.motion == Motion::pocketed || dt <= 0) return s;
    dt = std::min(dt, duration(p, s));
    BallState out = s;
    out.spin.z = decay_z(s.spin.z, p.spin_decel * dt);
    if (s.motion == Motion::spinning) return out;
    const Vec2 a = acceleration(p, s);
    out.pos = s.pos + dt * s.vel + (0.5 * dt * dt) * a;
    out.vel = s.vel + dt * a;
    if (s.motion == Motion::sliding) {
        // ω_xy gains (5·μ·g / 2R)·t·(ẑ × û); with a = −μ·g·û this is −(5 / 2R)·t·(ẑ × a).
        Vec2 dw = (-2.5 * dt / p.ball_radius) * perp(a);
        out.spin.x = s.spin.x + dw.x;
        out.spin.y = s.spin.y + dw.y;
    } else {
        // Rolling: ω_xy = (ẑ × v) / R.
        Vec2 w = (1.0 / p.ball_radius) * perp(out.vel);
        out.spin.x = w.x;
        out.spin.y = w.y;
    }
    return out;
}

BallState transition(const Params& p, const BallState& s) {
    BallState end = evolve(p, s, duration(p, s));
    switch (s.motion) {
        case Motion::sliding:
            end.motion = Motion::rolling;  // settle() decides if it is already at rest
            break;
        case Motion::rolling:
            end.vel = {};
            end.spin.x = end.spin.y = 0.0;
            end.motion = end.spin.z != 0.0 ? Motion::spinning : Motion::stationary;
            break;
        case Motion::spinning:
            end.spin.z = 0.0;
            end.motion = Motion::stationary;
            break;
        default:
            break;
    }
    return settle(p, end);
}

BallState settle(const Params& p, BallState s, double snap_slip) {
    if (s.motion == Motion::pocketed) return s;
    const double R = p.ball_radius;
    if (std::fabs(s.spin.z) < 1e-9) s.spin.z = 0.0;
    const bool still = norm(s.vel) < kRestSpeed && norm(flat(s.spin)) * R < kRestSpeed;
    if (still) {
        s.vel = {};
        s.spin.x = s.spin.y = 0.0;
        s.motion = s.spin.z != 0.0 ? Motion::spinning : Motion::stationary;
        return s;
    }
    const Vec2 u = cloth_slip(p, s.vel, s.spin);
    const double slip = norm(u);
    if (slip < std::max(snap_slip, kRollSlip)) {
        // The slide's end state: v falls by μg·t along û while u falls by 7/2·μg·t. Taken for
        // every slip, however small: setting the spin from v alone can add energy.
        s.vel = s.vel - (2.0 / 7.0) * u;
        Vec2 w = (1.0 / R) * perp(s.vel);
        s.spin.x = w.x;
        s.spin.y = w.y;
        s.motion = Motion::rolling;
        return s;
    }
    s.motion = Motion::sliding;
    return s;
}

}  // namespace physics::motion
