// Kinetic energy of balls (translational + rotational), for the energy audit.
#pragma once

#include <span>

#include "physics/ball_state.hpp"
#include "physics/params.hpp"

namespace physics {

/// ½mv² + ½Iω², I = 2/5 mR² (unit: J). Zero for a pocketed ball.
double kinetic_energy(const Params& params, const BallState& ball);
double kinetic_energy(const Params& params, std::span<const BallState> balls);

}  // namespace physics
