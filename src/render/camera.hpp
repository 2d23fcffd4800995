// Cameras: where the eye is and what it sees. Frame: the table frame (x east, y north, z up),
// cloth at z = 0, lengths in m.
#pragma once

#include <glm/glm.hpp>

#include "physics/table.hpp"

namespace render {

struct Camera {
    glm::vec3 eye{1.27f, 0.635f, 3.0f};     ///< (unit: m)
    glm::vec3 target{1.27f, 0.635f, 0.0f};  ///< (unit: m)
    glm::vec3 up{0.0f, 1.0f, 0.0f};
    float fovy_deg = 40.0f;  ///< vertical field of view (unit: deg)
    float near_m = 0.05f;    ///< (unit: m)
    float far_m = 20.0f;     ///< (unit: m)

    glm::mat4 view() const;
    glm::mat4 projection(float aspect) const;
};

/// The overhead camera: straight down on the whole table (rails and the ball-return tray
/// along the south side included), long side horizontal, as close as the aspect (width /
/// height) allows.
Camera overhead_camera(const physics::Table& table, float aspect);

/// Behind the cue ball, looking along `heading` (unit: rad, from +x counter-clockwise),
/// `distance` back and `height` above the cloth (unit: m).
Camera cue_ball_camera(glm::vec2 cue_ball, float heading, float distance = 0.7f,
                       float height = 0.28f);

/// A free orbit camera looking at `target` along the heading `yaw_rad` (from +x counter-
/// clockwise, as cue_ball_camera's heading), down by `pitch_rad` (0 level, π/2 straight
/// down), from `distance_m` away. Up is the view's "up" in the vertical plane, so it stays
/// well defined looking straight down.
Camera orbit_camera(glm::vec3 target, float yaw_rad, float pitch_rad, float distance_m);

/// Between two cameras, t in [0, 1] (0: a, 1: b; clamped): the target moves in a straight
/// line, the eye swings round it (direction slerped, distance interpolated geometrically),
/// up, field of view and clip planes are interpolated. Linear in t: easing is the caller's.
Camera lerp(const Camera& a, const Camera& b, float t);

}  // namespace render
