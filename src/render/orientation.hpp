// Ball orientations: a unit quaternion per ball (ball frame → table frame), integrated from
// the shot's exact angular velocity so the balls visibly roll, slide and spin.
#pragma once

#include <glm/gtc/quaternion.hpp>

#include "physics/shot.hpp"
#include "physics/vec.hpp"

namespace render {

/// Rotates q by a constant angular velocity ω (unit: rad/s, table frame) for dt (unit: s);
/// exact for constant ω.
glm::dquat advance(const glm::dquat& q, physics::Vec3 omega, double dt);

/// Integrates ball `id`'s orientation from t0 to t1 (unit: s) through the shot, sampling
/// ω at the middle of substeps of at most `max_step` (unit: s). Pocketed balls keep q0.
glm::dquat integrate_orientation(const physics::Shot& shot, int id, double t0, double t1,
                                 const glm::dquat& q0, double max_step = 1.0 / 480.0);

/// A fixed, varied starting orientation per ball id, so stripes and numbers do not all face up.
glm::dquat initial_orientation(int id);

}  // namespace render
