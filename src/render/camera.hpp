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
/// along the south side included), as close as the aspect (width / height) allows; the long
/// side horizontal, or in a tall view (aspect < 1) vertical, the head end at the bottom.
Camera overhead_camera(const physics::Table& table, float aspect);

/// What the cue-ball view is asked for: the player's zoom (distance, height) and the cue.
struct CueCameraAim {
    glm::vec2 cue_ball{0.0f};    ///< cue-ball centre (unit: m)
    float heading = 0.0f;        ///< the stroke's direction, from +x counter-clockwise (unit: rad)
    float distance = 0.7f;       ///< how far behind the cue ball, horizontally (unit: m)
    float height = 0.28f;        ///< eye height above the cloth, at least (unit: m)
    float cue_elevation = 0.0f;  ///< the cue's elevation as drawn (unit: rad)
};

/// Behind the cue ball, looking along the heading, with the cue ball in the lower part of the
/// view. The eye never enters the table, a rail or the room: it comes forward from a wall or
/// the ceiling, and rises until the line from it to the cue ball clears the cushions and rails
/// (a cue ball near a rail is seen over it) and until it looks down on the cue (a raised cue is
/// seen from above, never through the eye).
Camera cue_ball_camera(const physics::Table& table, float ball_radius, const CueCameraAim& aim);

/// The lowest eye height (unit: m) at `distance` behind the cue ball from which the line to the
/// cue ball's upper half clears the cushions and rails, and which stays above the table.
float cue_view_min_height(const physics::Table& table, float ball_radius, glm::vec2 cue_ball,
                          float heading, float distance);

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
