// Checks of a ball layout: what makes a table state impossible.
#pragma once

#include <optional>
#include <span>
#include <string>

#include "physics/ball_state.hpp"
#include "physics/params.hpp"
#include "physics/table.hpp"

namespace physics {

/// Distance below 2R − this is an overlap; between it and 2R the balls are touching (frozen).
inline constexpr double overlap_tolerance = 1e-9;  // (unit: m)

struct LayoutError {
    std::size_t index;    ///< index of the offending ball in the given span
    std::string field;    ///< "id", "pos", "vel" or "spin"
    std::string message;  ///< e.g. "ball overlaps ball 5"
};

/// Empty if the layout is valid: ids 0–max_ball_id unique, centres on the surface, no overlaps,
/// finite numbers, pocketed balls excluded from the checks.
std::optional<LayoutError> validate_layout(const Table& table, const Params& params,
                                           std::span<const BallState> balls);

/// Sets each ball's motion from its velocity and spin (stationary, spinning, rolling, sliding).
Motion classify_motion(const Params& params, Vec2 vel, Vec3 spin);

}  // namespace physics
