// Closed-form motion of one ball between events (docs/physics.md, "Motion between events").
// Private to physics.
#pragma once

#include "physics/ball_state.hpp"
#include "physics/internal/private.hpp"
#include "physics/params.hpp"

namespace physics::motion {

/// A ball whose speed and xy-spin·R are both below this is at rest at once (unit: m/s):
/// rolling, it would stop within 5e-10 m. Without it, jammed clusters creep and chatter.
inline constexpr double kRestSpeed = 1e-5;
/// A slip speed below this is rolling (unit: m/s).
inline constexpr double kRollSlip = 1e-9;
/// A slip speed below this is resolved at once into the exact end state of its slide
/// (v − 2/7·u, rolling): the slide would last under 4 µs and move the ball under 1e-9 m, and
/// such slips (left by collisions in clusters of balls) would otherwise drive chatter.
inline constexpr double kSnapSlip = 5e-5;

/// Position, velocity and the constant acceleration of a ball's centre at one instant.
struct Kinematics {
    Vec2 p, v, a;
};

/// Contact slip at the cloth: u = v + R·(ẑ × ω).
Vec2 cloth_slip(const Params& p, Vec2 vel, Vec3 spin);

/// The constant acceleration of the centre during the segment that starts in `s`.
Vec2 acceleration(const Params& p, const BallState& s);

/// How long the segment starting in `s` lasts before its motion state changes (unit: s);
/// +infinity for stationary and pocketed balls.
double duration(const Params& p, const BallState& s);

/// The state `dt` seconds into the segment starting in `s` (0 ≤ dt ≤ duration; clamped).
BallState evolve(const Params& p, const BallState& s, double dt);

/// The state at the end of the segment, with its new motion state (the transition).
BallState transition(const Params& p, const BallState& s);

/// Classifies a ball's motion from velocity and spin, snapping values within rounding of a
/// state onto it (exact rolling spin, exact zeros) so that every segment starts clean; a tiny
/// slip is resolved at once (kSnapSlip).
/// `snap_slip`: slips below it are resolved at once (kSnapSlip in slow contacts, where chatter
/// lives; kRollSlip, rounding only, elsewhere).
BallState settle(const Params& p, BallState s, double snap_slip = kRollSlip);

}  // namespace physics::motion
