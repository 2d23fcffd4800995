// The shot pipeline: strike, then jump from event to event until every ball is at rest.
#pragma once

#include <span>

#include "physics/ball_state.hpp"
#include "physics/params.hpp"
#include "physics/shot.hpp"
#include "physics/stroke.hpp"
#include "physics/table.hpp"

namespace physics {

/// Simulates a shot. `balls` must be a valid layout (validate_layout); ball `stroke->ball` is
/// struck when `stroke` is given (it must then be at rest). Deterministic: the same input gives a
/// bit-identical Shot.
Shot simulate(const Table& table, const Params& params, std::span<const BallState> balls,
              const Stroke* stroke, const SimOptions& options = {});

}  // namespace physics
