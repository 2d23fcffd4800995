// Cameras: where the eye is and what it sees. Frame: the table frame (x east, y north, z up),
// cloth at z = 0, lengths in m.
#pragma once

#include <glm/glm.hpp>

#include "physics/table.hpp"

namespace render {

struct Camera {
    glm::vec3 eye{1.27f, 0.635f, 3.0f};  ///< (unit: m)
    glm::vec3 target{1.27f, 0.635f, 0.0f};  ///< (unit: m)
    glm::vec3 up{0.0f, 1.0f, 0.0f};
    float fovy_deg = 40.0f;  ///< vertical field of view (unit: deg)
    float near_m = 0.05f;    ///< (unit: m)
    float far_m = 20.0f;     ///< (unit: m)

    glm::mat4 view() const;
    glm::mat4 projection(float aspect) const;
};

/// The overhead camera: straight down on the whole table (rails included), long side
/// horizontal, as close as the aspect (width / height) allows.
Camera overhead_camera(const physics::Table& table, float aspect);

/// Behind the cue ball, looking along `heading` (unit: rad, from +x counter-clockwise),
/// `distance` back and `height` above the cloth (unit: m).
Camera cue_ball_camera(glm::vec2 cue_ball, float heading, float distance = 0.7f, float height = 0.28f);

}  // namespace render
