// The state of one ball at one instant.
#pragma once

#include <cstdint>
#include <map>
#include <optional>
#include <string_view>
#include <vector>

#include "physics/vec.hpp"

namespace physics {

/// Motion states (docs/physics.md). The closed form of the motion depends on it.
enum class Motion : std::uint8_t { stationary, spinning, sliding, rolling, pocketed };

std::string_view to_string(Motion m);
std::optional<Motion> motion_from_string(std::string_view s);

/// The largest ball id: pool uses 0–15, snooker 0–21 (15 reds, then yellow 16 … black 21).
inline constexpr int max_ball_id = 21;

struct BallState {
    int id = 0;  ///< 0 cue ball, then object balls up to max_ball_id (docs/physics.md, "Ball sets")
    Vec2 pos;    ///< centre (unit: m), table frame; z is R
    Vec2 vel;    ///< velocity of the centre (unit: m/s)
    Vec3 spin;   ///< angular velocity ω (unit: rad/s)
    Motion motion = Motion::stationary;
    int pocket = -1;  ///< pocket index (see table.hpp) when motion is pocketed
};

/// Balls at rest at `positions` (ball id → centre), in id order.
inline std::vector<BallState> balls_at_rest(const std::map<int, Vec2>& positions) {
    std::vector<BallState> out;
    out.reserve(positions.size());
    for (const auto& [id, p] : positions) {
        BallState b;
        b.id = id;
        b.pos = p;
        out.push_back(b);
    }
    return out;
}

}  // namespace physics
