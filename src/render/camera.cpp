#include "render/camera.hpp"

#include <algorithm>
#include <cmath>

#include <glm/gtc/matrix_transform.hpp>

#include "render/table_mesh.hpp"

namespace render {

glm::mat4 Camera::view() const { return glm::lookAt(eye, target, up); }

glm::mat4 Camera::projection(float aspect) const {
    return glm::perspective(glm::radians(fovy_deg), aspect, near_m, far_m);
}

Camera overhead_camera(const physics::Table& table, float aspect) {
    const TableDims dims = table_dims(table);
    const float margin = 0.04f;
    const float half_x = static_cast<float>(table.length()) / 2 + dims.cushion_width + dims.rail_width + margin;
    const float half_y = static_cast<float>(table.width()) / 2 + dims.cushion_width + dims.rail_width + margin;
    Camera c;
    c.fovy_deg = 36.0f;
    const float t = std::tan(glm::radians(c.fovy_deg) / 2);
    // Distance to the rail top so that both half extents fit.
    const float d = std::max(half_y / t, half_x / (t * aspect));
    const glm::vec3 centre{static_cast<float>(table.length()) / 2, static_cast<float>(table.width()) / 2, 0.0f};
    c.target = centre;
    c.eye = centre + glm::vec3(0, 0, d + dims.rail_height);
    c.up = {0, 1, 0};
    c.near_m = std::max(0.05f, d * 0.5f);
    c.far_m = d + 3.0f;
    return c;
}

Camera cue_ball_camera(glm::vec2 cue_ball, float heading, float distance, float height) {
    Camera c;
    const glm::vec2 dir{std::cos(heading), std::sin(heading)};
    c.eye = glm::vec3(cue_ball - distance * dir, height);
    c.target = glm::vec3(cue_ball + 0.9f * dir, 0.0f);
    c.up = {0, 0, 1};
    c.fovy_deg = 45.0f;
    c.near_m = 0.02f;
    c.far_m = 10.0f;
    return c;
}

}  // namespace render
