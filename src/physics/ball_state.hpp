// The state of one ball at one instant.
#pragma once

#include <cstdint>
#include <optional>
#include <string_view>

#include "physics/vec.hpp"

namespace physics {

/// Motion states (docs/physics.md). The closed form of the motion depends on it.
enum class Motion : std::uint8_t { stationary, spinning, sliding, rolling, pocketed };

std::string_view to_string(Motion m);
std::optional<Motion> motion_from_string(std::string_view s);

struct BallState {
    int id = 0;  ///< 0 cue ball, 1–15 object balls
    Vec2 pos;    ///< centre (unit: m), table frame; z is R
    Vec2 vel;    ///< velocity of the centre (unit: m/s)
    Vec3 spin;   ///< angular velocity ω (unit: rad/s)
    Motion motion = Motion::stationary;
    int pocket = -1;  ///< pocket index (see table.hpp) when motion is pocketed
};

}  // namespace physics
