// Small shared helpers for the closed-form physics tests (motion, strike, ball–ball, cushion):
// making balls and tables, running a shot, finding events, and the closed forms of
// docs/physics.md written out again, independently of src/physics/motion.cpp, so that the
// engine is checked against the model and not against itself.
#pragma once

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <span>
#include <vector>

#include "physics/ball_state.hpp"
#include "physics/energy.hpp"
#include "physics/event.hpp"
#include "physics/params.hpp"
#include "physics/shot.hpp"
#include "physics/simulate.hpp"
#include "physics/stroke.hpp"
#include "physics/table.hpp"
#include "physics/vec.hpp"

namespace physics::ptest {

// Tolerances. Each is a floating-point bound, never a physical one:
/// A closed form evaluated in a handful of double operations (a few ulps, with margin).
inline constexpr double kExact = 1e-12;
/// A quantity that also passes through a root solve or a long chain of events.
inline constexpr double kRoot = 1e-9;

inline constexpr double kDeg = std::numbers::pi / 180.0;

inline BallState make_ball(int id, Vec2 pos, Vec2 vel = {}, Vec3 spin = {}) {
    BallState b;
    b.id = id;
    b.pos = pos;
    b.vel = vel;
    b.spin = spin;
    return b;
}

/// The spin of a ball rolling with velocity v: ω_xy = (ẑ × v)/R, plus a z-spin.
inline Vec3 rolling_spin(const Params& p, Vec2 v, double wz = 0.0) {
    return {-v.y / p.ball_radius, v.x / p.ball_radius, wz};
}

inline Vec2 unit(Vec2 v) {
    return (1.0 / norm(v)) * v;
}
inline Vec2 from_angle(double deg) {
    return {std::cos(deg * kDeg), std::sin(deg * kDeg)};
}
/// Angle from a to b, counter-clockwise positive (unit: deg).
inline double angle_deg(Vec2 a, Vec2 b) {
    return std::atan2(cross(a, b), dot(a, b)) / kDeg;
}

/// No cushions, no pockets: collisions and free motion only.
inline Table unbounded_table() {
    return build_table(*table_preset("unbounded"));
}
/// The 9 ft table with closed rails (no pockets).
inline Table closed_table() {
    TableSpec s = *table_preset("9ft");
    s.pockets = false;
    return build_table(s);
}
/// The 9 ft table with its pockets.
inline Table pocket_table() {
    return build_table(*table_preset("9ft"));
}

inline SimOptions options(BallBallModel bb = BallBallModel::frictional,
                          CushionModel c = CushionModel::han2005) {
    SimOptions o;
    o.models.ball_ball = bb;
    o.models.cushion = c;
    return o;
}

inline Shot run(const Table& table, const Params& params, const std::vector<BallState>& balls,
                const Stroke* stroke = nullptr, const SimOptions& opts = {}) {
    return simulate(table, params, std::span<const BallState>(balls), stroke, opts);
}

/// Events of a type (and involving ball `id`, unless −1), in order.
inline std::vector<const Event*> events_of(const Shot& shot, EventType type, int id = -1) {
    std::vector<const Event*> out;
    for (const Event& e : shot.events())
        if (e.type == type && (id < 0 || e.involves(id))) out.push_back(&e);
    return out;
}

/// The first event of a type (involving `id` unless −1) at or after time `after`; null if none.
inline const Event* first_event(const Shot& shot, EventType type, int id = -1,
                                double after = -1.0) {
    for (const Event& e : shot.events())
        if (e.type == type && (id < 0 || e.involves(id)) && e.time >= after) return &e;
    return nullptr;
}

/// The transition of ball `id` from one motion state to another; null if none.
inline const Event* transition_of(const Shot& shot, int id, Motion from, Motion to) {
    for (const Event& e : shot.events())
        if (e.type == EventType::transition && e.involves(id) && e.from == from && e.to == to)
            return &e;
    return nullptr;
}

/// The state of ball `id` just after event e, as the event reports it.
inline BallState after(const Event& e, int id) {
    for (int k = 0; k < e.ball_count; ++k) {
        const EventBall& b = e.balls[static_cast<std::size_t>(k)];
        if (b.id == id) return make_ball(b.id, b.pos, b.vel, b.spin);
    }
    ADD_FAILURE() << "ball " << id << " is not in the event";
    return {};
}

/// The state of ball `id` just before time t (one ulp earlier, so in the segment before an
/// event at t): velocities then differ from the exact pre-event ones by at most |a|·ulp(t).
inline BallState before(const Shot& shot, int id, double t) {
    return shot.state_at(id, std::nextafter(t, -std::numeric_limits<double>::infinity()));
}

/// The state of ball `id` just before event number `index` of the shot: the state after an
/// earlier event at the same instant that involves it (simultaneous events, a break through
/// frozen balls), else the state just before that instant.
inline BallState before_event(const Shot& shot, std::size_t index, int id) {
    const auto& events = shot.events();
    const double t = events[index].time;
    for (std::size_t j = index; j-- > 0 && events[j].time == t;)
        if (events[j].involves(id)) return after(events[j], id);
    return before(shot, id, t);
}

inline double kinetic(const Params& p, const BallState& b) {
    return kinetic_energy(p, b);
}

/// Relative difference of two numbers, scaled by `scale` (or by their size).
inline double rel(double a, double b, double scale = 0.0) {
    const double s = scale > 0 ? scale : std::max(std::fabs(a), std::fabs(b));
    return s > 0 ? std::fabs(a - b) / s : 0.0;
}

#define EXPECT_REL(a, b, tol) \
    EXPECT_LE(::physics::ptest::rel((a), (b)), (tol)) << #a " = " << (a) << ", " #b " = " << (b)
#define EXPECT_VEC_NEAR(a, b, tol)                                                              \
    do {                                                                                        \
        const ::physics::Vec2 va_ = (a), vb_ = (b);                                             \
        EXPECT_LE(::physics::norm(va_ - vb_), (tol))                                            \
            << #a " = (" << va_.x << ", " << va_.y << "), " #b " = (" << vb_.x << ", " << vb_.y \
            << ")";                                                                             \
    } while (0)

// ---- The closed forms of docs/physics.md, "Motion between events" ----

/// Contact slip at the cloth, u = v + R·(ẑ × ω).
inline Vec2 slip(const Params& p, Vec2 v, Vec3 w) {
    return {v.x - p.ball_radius * w.y, v.y + p.ball_radius * w.x};
}

/// A free ball's state t seconds after `s` (no collisions): slide along the slip direction,
/// then roll, then spin in place; z-spin decays linearly throughout.
inline BallState reference_state(const Params& p, BallState s, double t) {
    const double R = p.ball_radius, g = p.gravity;
    auto decay_z = [&](double wz, double dt) {
        const double d = p.spin_decel * dt;
        return wz > 0 ? std::max(wz - d, 0.0) : std::min(wz + d, 0.0);
    };
    const double wz0 = s.spin.z;
    double used = 0.0;  // time already spent
    const Vec2 u = slip(p, s.vel, s.spin);
    if (norm(u) > 1e-9) {  // sliding
        const double ts = 2.0 * norm(u) / (7.0 * p.mu_slide * g);
        const double dt = std::min(t, ts);
        const Vec2 uh = unit(u);
        s.pos = s.pos + dt * s.vel - (0.5 * p.mu_slide * g * dt * dt) * uh;
        s.vel = s.vel - (p.mu_slide * g * dt) * uh;
        const double k = 2.5 * p.mu_slide * g * dt / R;  // ω_xy gains k·(ẑ × û)
        s.spin.x += -k * uh.y;
        s.spin.y += k * uh.x;
        used = dt;
        if (t <= ts) {
            s.spin.z = decay_z(wz0, t);
            return s;
        }
        s.spin.x = -s.vel.y / R;  // rolling from here on (the slip is zero up to rounding)
        s.spin.y = s.vel.x / R;
    }
    const double v = norm(s.vel);
    if (v > 0) {  // rolling
        const double tr = v / (p.mu_roll * g);
        const double dt = std::min(t - used, tr);
        const Vec2 vh = unit(s.vel);
        s.pos = s.pos + dt * s.vel - (0.5 * p.mu_roll * g * dt * dt) * vh;
        s.vel = dt < tr ? s.vel - (p.mu_roll * g * dt) * vh : Vec2{};
        s.spin.x = -s.vel.y / R;
        s.spin.y = s.vel.x / R;
    }
    s.spin.z = decay_z(wz0, t);
    return s;
}

/// Where a free ball comes to rest (no collisions).
inline Vec2 reference_rest(const Params& p, const BallState& s) {
    return reference_state(p, s, 1e6).pos;
}

}  // namespace physics::ptest
