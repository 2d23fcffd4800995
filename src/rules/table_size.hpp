// The few table dimensions the rules use: the head string (kitchen) and the foot spot and long
// string (spotting). Frame: docs/cli.md (x from the head cushion to the foot cushion).
#pragma once

#include "physics/vec.hpp"

namespace rules {

struct TableSize {
    double length = 2.540;          ///< L, cushion nose to cushion nose along x (unit: m)
    double width = 1.270;           ///< W (unit: m)
    double ball_radius = 0.028575;  ///< R (unit: m)

    /// A ball lies in the kitchen when its centre is at x < L/4 (unit: m).
    double head_string_x() const { return length / 4.0; }
    /// (3L/4, W/2) (unit: m)
    physics::Vec2 foot_spot() const { return {3.0 * length / 4.0, width / 2.0}; }
};

}  // namespace rules
