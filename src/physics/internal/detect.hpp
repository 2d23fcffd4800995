// Event prediction: when will a ball next touch another ball, a cushion face, a jaw nose or a
// pocket's drop line, given closed-form motion? Each is the first root of a polynomial of
// degree ≤ 4 in the time from now. Private to physics.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

#include "physics/internal/motion.hpp"
#include "physics/internal/private.hpp"
#include "physics/internal/roots.hpp"
#include "physics/table.hpp"

namespace physics::detect {

/// Balls (or a ball and a cushion) closer than this are touching (unit: m).
inline constexpr double kTouchGap = 1e-10;
/// Normal speeds below this count as zero when deciding whether a touching pair approaches
/// (unit: m/s).
inline constexpr double kApproachEps = 1e-12;

/// A ball's motion from now on, up to a horizon: kinematics now, and how far it can get.
struct Mover {
    motion::Kinematics k;
    double horizon = 0.0;       ///< how far ahead to look (unit: s); may be infinite
    double reach = 0.0;         ///< bound on the distance travelled within the horizon (unit: m)
    bool decelerating = false;  ///< acceleration opposes velocity (rolling): a tighter bound

    /// The same motion looked at only up to `h`.
    Mover within(double h) const;
};

inline Mover make_mover(const motion::Kinematics& k, double horizon,
                        bool decelerating_along_velocity);

/// Bound on the distance a ball with speed ≤ `speed` and acceleration of size `accel` travels
/// within `horizon` (decelerating: accel opposes the velocity, so it stops).
/// (Inline: the event loop calls it twice per ball pair.)
inline double reach_bound(double speed, double accel, double horizon, bool decelerating) {
    double reach;
    if (std::isinf(horizon)) {
        reach = (speed == 0 && accel == 0) ? 0.0 : std::numeric_limits<double>::infinity();
    } else if (decelerating && accel > 0) {
        const double h = std::min(horizon, speed / accel);  // it stops, then stays
        reach = speed * h - 0.5 * accel * h * h;
    } else {
        reach = speed * horizon + 0.5 * accel * horizon * horizon;
    }
    return std::max(0.0, reach) * (1.0 + 1e-9) + 1e-12;
}

/// A predicted contact: `tau` seconds from now (infinity: none). `pushing`: the contact is now,
/// with no approach speed but an acceleration into it.
struct Prediction {
    double tau = std::numeric_limits<double>::infinity();
    bool pushing = false;
};

/// `screened`: as for circle_contact (the event loop tests |Δp| against 2R + both reaches first).
inline Prediction ball_ball(const Mover& a, const Mover& b, double R, double horizon,
                            bool screened = false);
inline Prediction line(const Mover& m, const CushionLine& l, double R);
inline Prediction nose(const Mover& m, const JawNose& n, double R);
/// Crossing of a pocket's drop line, within `lateral` of the pocket's axis.
inline double drop(const Mover& m, const Pocket& pk, double lateral);

// ---- definitions (inline: the event loop calls these ~10,000 times per break) ----

namespace detail {

inline constexpr double kInf = std::numeric_limits<double>::infinity();
/// Normal accelerations below this are into contact (unit: m/s²).
inline constexpr double kPushAccel = -1e-12;

inline Vec2 position(const motion::Kinematics& k, double t) {
    return k.p + t * k.v + (0.5 * t * t) * k.a;
}

/// Smallest value of q(τ) = a0 + a1·τ + a2·τ² on [0, h] (h finite), in closed form.
inline double min_on(double a0, double a1, double a2, double h) {
    const double end = a0 + (a1 + a2 * h) * h;
    double m = a0 < end ? a0 : end;
    if (a2 > 0.0 && a1 < 0.0 && -a1 < 2.0 * a2 * h) {
        const double vertex = a0 - a1 * a1 / (4.0 * a2);
        if (vertex < m) m = vertex;
    }
    return m;
}

/// Clearance kept by the pruning bounds below (unit: m), far above any rounding in them.
inline constexpr double kClear = 1e-6;

/// True if q(τ) = a0 + a1·τ + a2·τ² provably stays positive on [0, h] by far more than the
/// rounding of evaluating it: then the root solver, whose every decision is the sign of q
/// evaluated at a point of [0, h] (with values below γ·Σ|a_i|τ^i counted as 0), can find no
/// crossing, and returns +infinity; this returns the same without running it.
inline bool quadratic_stays_positive(double a0, double a1, double a2, double h) {
    if (!std::isfinite(h) || !(h >= 0.0)) return false;
    const double size = std::fabs(a0) + (std::fabs(a1) + std::fabs(a2) * h) * h;
    return std::isfinite(size) && min_on(a0, a1, a2, h) > 1e-12 * size + 1e-300;
}

/// True if q(τ) = a0 + a1·τ + a2·τ² starts at or below 0 (a ball overlapping a face by
/// rounding, or touching it) and its slope a1 + 2a2·τ provably stays positive on [0, h]: h
/// finite, a1 ≥ 1e-290, and max(0, −2a2)·h ≤ 0.75·a1. Then the root solver on [0, h] returns
/// +infinity (a crossing from ≤ 0 is upward): its walk's one critical point, −a1/(2a2), is
/// negative or at least h/0.75 before its one rounding, so not inside (0, h), and the one piece
/// [0, h] starts at q(0) = a0 ≤ 0 (degree 1, a2 = 0, has no critical point at all); this
/// returns the same without running it.
inline bool leaves_from_overlap(double a0, double a1, double a2, double h) {
    if (!(a0 <= 0.0 && a0 > -kInf && a1 >= 1e-290 && a1 < kInf && h < kInf)) return false;
    if (!(std::fabs(a2) < kInf)) return false;
    return (a2 < 0.0 ? -2.0 * a2 * h : 0.0) <= 0.75 * a1;
}

/// True if |Δp + Δv·τ + ½Δa·τ²| provably stays above D + kClear for all τ in [0, h], by two
/// lower bounds on the distance: its projection on Δp (|x| ≥ x·u/|u|) and on Δv's normal (the
/// velocity term vanishes there). Then the exact contact quartic is ≥ 2·D·kClear on [0, h], far
/// above the rounding of its computed coefficients and of any evaluation of it (both below
/// ~64ε·(|Δp| + |Δv|h + ½|Δa|h²)², checked), so the solver sees only positive values and finds no
/// crossing: skipping it returns exactly what it would. Only ever true for a pair not touching.
inline bool surely_apart(Vec2 dp, Vec2 dv, Vec2 da, double dist, double D, double h) {
    if (!std::isfinite(h) || !(h >= 0.0) || !(D > 0.0)) return false;
    const double h2 = h * h;
    const double K = norm2(dp) + norm2(dv) * h2 + 0.25 * norm2(da) * (h2 * h2);
    // (|Δp| + |Δv|h + ½|Δa|h²)² ≤ 3K; this also keeps the bounds' own rounding (~8ε·|u|·√(3K))
    // below kClear·|u|, which the extra kClear in `clear` absorbs.
    if (!(1e-12 * (3.0 * K + D * D) < 2.0 * D * kClear)) return false;
    const double clear = D + 2.0 * kClear;
    if (min_on(norm2(dp), dot(dp, dv), 0.5 * dot(dp, da), h) > clear * dist) return true;
    const Vec2 w = perp(dv);
    double wp = dot(w, dp), wa = 0.5 * dot(w, da);
    if (wp < 0.0) {
        wp = -wp;
        wa = -wa;
    }
    return wp + (wa < 0.0 ? wa * h2 : 0.0) > clear * norm(dv);
}

/// True if p, from p(0) = c[0] ≤ 0, opens at once: with u = −2·c[0] and t1 = 2u/c1 ≤ h,
/// |c2|·t ≤ c1/4 and |c3|·t² ≤ c1/4 on [0, t1] (c4 ≥ 0), so p − p(0) ≥ c1·t/2 ≥ 0 there and
/// p(t1) ≥ −p(0). The usual pair after a collision; with no downward crossing it then stays
/// open, and sinks_from_overlap need not look further (about 120 times a break).
inline bool opens_at_once(const roots::Poly4& c, double h) {
    if (!(c[1] > 0.0)) return false;
    const double u = -2.0 * c[0];
    return 2.0 * u <= h * c[1] && 8.0 * std::fabs(c[2]) * u <= c[1] * c[1] &&
           16.0 * std::fabs(c[3]) * (u * u) <= c[1] * (c[1] * c[1]);
}

/// For a pair touching with an overlap by rounding (p(0) = c[0] ≤ 0), in which the quartic
/// has no downward crossing (it never turns positive, so has none to cross): true if p still
/// falls more than `drop` below p(0) within the horizon, at its end or at a minimum (a root of
/// p'). That is a contact now, reached through a gap that opens less than the overlap, or not
/// at all: a slow separation pulled back, a third-order approach
/// (Traps.TouchingPairSeparatingTooSlowlyToOpenIsStillAContact). Not inlined: it is rarely
/// asked, and inlined it slows circle_contact's common paths (about 4 % on a break).
[[gnu::noinline]] inline bool sinks_from_overlap(const roots::Poly4& c, double h, double drop) {
    if (!(h > 0.0 && h < kInf) || opens_at_once(c, h)) return false;
    const double floor = c[0] - drop;
    if (roots::eval(c, h) < floor) return true;
    std::array<double, 4> at{};
    const int n =
        roots::sign_change_roots({c[1], 2.0 * c[2], 3.0 * c[3], 4.0 * c[4], 0.0}, 0.0, h, at);
    for (int k = 0; k < n; ++k)
        if (roots::eval(c, at[static_cast<std::size_t>(k)]) < floor) return true;
    return false;
}

/// Contact of a moving point with a fixed or moving circle of radius D about another point:
/// f(τ) = |Δp + Δv·τ + ½Δa·τ²|² − D², a quartic. `screened`: the caller has already found
/// |Δp|² ≤ (D + reach)² (up to rounding), so the first test below could not reject.
inline Prediction circle_contact(Vec2 dp, Vec2 dv, Vec2 da, double D, double reach, double horizon,
                                 bool screened = false) {
    // Out of reach, decided without a square root where the margin is clear: |Δp|² above
    // (D + reach)²·(1 + 1e-9) means |Δp| − D > reach by ~5e-10·(D + reach), far above the
    // rounding of either test, so the test below would return the same none.
    const double limit = D + reach;
    if (!screened && norm2(dp) > limit * limit * (1.0 + 1e-9)) return {};
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
    if (dist - D > 4.0 * kClear && surely_apart(dp, dv, da, dist, D, horizon)) return {};
    const roots::Poly4 c{dot(dp, dp) - D * D, 2.0 * dot(dp, dv), dot(dv, dv) + dot(dp, da),
                         dot(dv, da), 0.25 * dot(da, da)};
    const double tau = roots::first_downward_crossing(c, 0.0, horizon);
    if (std::isinf(tau) && dist - D <= kTouchGap && !(c[0] > 0.0) &&
        sinks_from_overlap(c, horizon, 2.0 * dist * kTouchGap))
        return {0.0, true};
    return {tau, false};
}

}  // namespace detail

inline Mover Mover::within(double h) const {
    return h >= horizon ? *this : make_mover(k, h, decelerating);
}

inline Mover make_mover(const motion::Kinematics& k, double horizon,
                        bool decelerating_along_velocity) {
    return {k, horizon, reach_bound(norm(k.v), norm(k.a), horizon, decelerating_along_velocity),
            decelerating_along_velocity};
}

inline Prediction ball_ball(const Mover& a, const Mover& b, double R, double horizon,
                            bool screened) {
    if (a.reach == 0 && b.reach == 0) return {};
    return detail::circle_contact(b.k.p - a.k.p, b.k.v - a.k.v, b.k.a - a.k.a, 2.0 * R,
                                  a.reach + b.reach, horizon, screened);
}

inline Prediction nose(const Mover& m, const JawNose& n, double R) {
    if (m.reach == 0) return {};
    return detail::circle_contact(n.centre - m.k.p, -1.0 * m.k.v, -1.0 * m.k.a, R + n.radius,
                                  m.reach, m.horizon);
}

inline Prediction line(const Mover& m, const CushionLine& l, double R) {
    if (m.reach == 0) return {};
    // Signed gap between the ball's surface and the face: s(τ) = s0 + s1·τ + ½·s2·τ².
    const double s0 = dot(m.k.p - l.a, l.normal) - R;
    if (s0 > m.reach) return {};
    // The contact point must lie on the face: a ball that cannot get within the face's length
    // (its reach bounds how far `along` moves; 1e-9 m is far above the rounding of within())
    // fails within() at every root the solver could return, so the answer is none.
    const double along0 = dot(m.k.p - l.a, l.dir);
    const double slack = m.reach * (1.0 + 1e-9) + 1e-9;
    if (along0 + slack < 0.0 || along0 - slack > l.length) return {};
    const double s1 = dot(m.k.v, l.normal), s2 = dot(m.k.a, l.normal);
    auto within = [&](double t) {
        const double along = dot(detail::position(m.k, t) - l.a, l.dir);
        return along >= 0.0 && along <= l.length;
    };
    if (s0 <= kTouchGap && s0 >= -1e-6 && within(0.0)) {
        if (s1 < -kApproachEps) return {0.0, false};
        if (s1 <= kApproachEps && s2 < detail::kPushAccel && s1 < -0.5 * s2 * m.horizon)
            return {0.0, true};
    }
    if (detail::quadratic_stays_positive(s0, s1, 0.5 * s2, m.horizon)) return {};
    if (detail::leaves_from_overlap(s0, s1, 0.5 * s2, m.horizon)) return {};
    const double t = roots::first_downward_crossing({s0, s1, 0.5 * s2, 0.0, 0.0}, 0.0, m.horizon);
    // From an overlap by rounding the gap may never turn positive, and so have no crossing,
    // and still close: a contact now (as circle_contact's sinks_from_overlap;
    // Traps.BallLeavingARailTooSlowlyToOpenStaysOnTheBed).
    if (std::isinf(t) && s0 <= 0.0 && s0 >= -1e-6 && within(0.0) && m.horizon < detail::kInf &&
        detail::min_on(s0, s1, 0.5 * s2, m.horizon) < s0 - kTouchGap)
        return {0.0, true};
    if (std::isinf(t) || !within(t)) return {};
    return {t, false};
}

inline double drop(const Mover& m, const Pocket& pk, double lateral) {
    if (m.reach == 0) return detail::kInf;
    // Depth past the drop line, d(τ); the ball falls when d crosses 0 upward.
    const double d0 = dot(m.k.p - pk.drop_point, pk.inward);
    if (-d0 > m.reach) return detail::kInf;
    // Too far from the pocket's axis at every point it can reach: the lateral test below fails
    // at any crossing (1e-9 m is far above its rounding).
    if (std::fabs(cross(pk.inward, m.k.p - pk.drop_point)) - (m.reach * (1.0 + 1e-9) + 1e-9) >
        lateral)
        return detail::kInf;
    const double d1 = dot(m.k.v, pk.inward), d2 = dot(m.k.a, pk.inward);
    if (d0 < 0.0 && detail::quadratic_stays_positive(-d0, -d1, -0.5 * d2, m.horizon))
        return detail::kInf;
    double t =
        d0 >= 0.0 ? 0.0
                  : roots::first_downward_crossing({-d0, -d1, -0.5 * d2, 0.0, 0.0}, 0.0, m.horizon);
    if (std::isinf(t)) return detail::kInf;
    if (std::fabs(cross(pk.inward, detail::position(m.k, t) - pk.drop_point)) > lateral)
        return detail::kInf;
    return t;
}

}  // namespace physics::detect
