// Closed-form motion of one ball between events (physics-model.md, "Motion between events").
// Private to physics.
#pragma once

#include "physics/ball_state.hpp"
#include "physics/params.hpp"

namespace physics::motion {

/// Speeds below this are zero (unit: m/s); spins below it divided by R likewise.
inline constexpr double kRestSpeed = 1e-9;
/// A slip speed below this is rolling (unit: m/s).
inline constexpr double kRollSlip = 1e-9;

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
/// state onto it (exact rolling spin, exact zeros) so that every segment starts clean.
BallState settle(const Params& p, BallState s);

}  // namespace physics::motion
