#include "render/camera.hpp"

#include <algorithm>
#include <cmath>
#include <glm/gtc/matrix_transform.hpp>

#include "render/room.hpp"
#include "render/table_mesh.hpp"

namespace render {

glm::mat4 Camera::view() const {
    return glm::lookAt(eye, target, up);
}

glm::mat4 Camera::projection(float aspect) const {
    return glm::perspective(glm::radians(fovy_deg), aspect, near_m, far_m);
}

Camera overhead_camera(const physics::Table& table, float aspect) {
    const TableDims dims = table_dims(table);
    const float margin = 0.04f;
    const float out = dims.cushion_width + dims.rail_width;
    const float half_x = static_cast<float>(table.length()) / 2 + out + margin;
    // From the tray's outer wall on the south side to the north rail's edge.
    const float y0 = -out - dims.tray_width - 2 * dims.tray_wall - margin;
    const float y1 = static_cast<float>(table.width()) + out + margin;
    const float half_y = (y1 - y0) / 2;
    Camera c;
    c.fovy_deg = 36.0f;
    const float t = std::tan(glm::radians(c.fovy_deg) / 2);
    // A tall view turns the table a quarter: the long side up the screen, the head string
    // (the break) at the bottom, nearer the player, the tray at the right.
    const bool tall = aspect < 1.0f;
    const float across = tall ? half_y : half_x, up_down = tall ? half_x : half_y;
    // Distance to the rail top so that both half extents fit.
    const float d = std::max(up_down / t, across / (t * aspect));
    const glm::vec3 centre{static_cast<float>(table.length()) / 2, (y0 + y1) / 2, 0.0f};
    c.target = centre;
    c.eye = centre + glm::vec3(0, 0, d + dims.rail_height);
    c.up = tall ? glm::vec3{1, 0, 0} : glm::vec3{0, 1, 0};
    c.near_m = std::max(0.05f, d * 0.5f);
    c.far_m = d + 3.0f;
    return c;
}

namespace {

/// How far from `p` along `d` (a unit vector) the ray leaves the box [lo, hi] (p inside it).
float exit_distance(glm::vec2 p, glm::vec2 d, glm::vec2 lo, glm::vec2 hi) {
    float t = 1e9f;
    for (int k = 0; k < 2; ++k) {
        if (d[k] > 1e-6f) t = std::min(t, (hi[k] - p[k]) / d[k]);
        if (d[k] < -1e-6f) t = std::min(t, (lo[k] - p[k]) / d[k]);
    }
    return std::max(t, 0.0f);
}

}  // namespace

float cue_view_min_height(const physics::Table& table, float ball_radius, glm::vec2 cue_ball,
                          float heading, float distance) {
    const TableDims dims = table_dims(table);
    const float L = static_cast<float>(table.length()), W = static_cast<float>(table.width());
    const float out = dims.cushion_width + dims.rail_width;
    const glm::vec2 back{-std::cos(heading), -std::sin(heading)};
    const float clear = dims.rail_height + 0.012f;  // the rail top and a margin
    // The line of sight to the ball's upper half (1.5 R) crosses the cushion first where it
    // leaves the cloth: that is where it is lowest over the cushions and rails.
    const float seen = 1.5f * ball_radius;
    const float leave = exit_distance(cue_ball, back, {0.0f, 0.0f}, {L, W});
    float h = 0.0f;
    if (leave < distance)
        h = seen + (clear - seen) * distance / std::max(leave, 0.25f * ball_radius);
    // Over the table's footprint the eye itself stays above the rails.
    const glm::vec2 eye = cue_ball + distance * back;
    if (eye.x > -out && eye.x < L + out && eye.y > -out && eye.y < W + out)
        h = std::max(h, dims.rail_height + 0.06f);
    return h;
}

Camera cue_ball_camera(const physics::Table& table, float ball_radius, const CueCameraAim& aim) {
    const RoomDims room = room_dims(table);
    const glm::vec2 dir{std::cos(aim.heading), std::sin(aim.heading)};
    // Come forward from the walls (0.3 m from each).
    const glm::vec2 margin{0.3f, 0.3f};
    float distance = std::min(
        aim.distance, exit_distance(aim.cue_ball, -dir, room.lo + margin, room.hi - margin));
    distance = std::max(distance, 0.05f);
    float h = std::max(
        aim.height, cue_view_min_height(table, ball_radius, aim.cue_ball, aim.heading, distance));
    // Above the cue's line by a few degrees, so a raised cue is seen from above.
    const float over_cue = std::clamp(aim.cue_elevation, 0.0f, 1.4f) + glm::radians(6.0f);
    h = std::max(h, ball_radius + distance * std::tan(std::min(over_cue, 1.45f)) + 0.03f);
    // Under the ceiling: come forward along the same line of sight.
    const float top = room.ceiling_z - 0.3f;
    if (h > top) {
        distance *= (top - ball_radius) / (h - ball_radius);
        h = top;
    }
    Camera c;
    c.eye = glm::vec3(aim.cue_ball - distance * dir, h);
    // The cue ball 9 degrees below the view's centre (the lower part of a 45 degree view).
    const float to_ball = std::atan2(h - ball_radius, distance);
    const float pitch = std::max(to_ball - glm::radians(9.0f), glm::radians(2.0f));
    const glm::vec3 forward{std::cos(pitch) * dir, -std::sin(pitch)};
    c.target = c.eye + forward * std::min(h / std::sin(pitch), 6.0f);
    c.up = {0, 0, 1};
    c.fovy_deg = 45.0f;
    c.near_m = 0.02f;
    c.far_m = 14.0f;
    return c;
}

Camera orbit_camera(glm::vec3 target, float yaw_rad, float pitch_rad, float distance_m) {
    Camera c;
    const float cp = std::cos(pitch_rad), sp = std::sin(pitch_rad);
    const glm::vec3 forward{cp * std::cos(yaw_rad), cp * std::sin(yaw_rad), -sp};
    c.target = target;
    c.eye = target - distance_m * forward;
    c.up = {sp * std::cos(yaw_rad), sp * std::sin(yaw_rad), cp};
    c.fovy_deg = 45.0f;
    c.near_m = std::clamp(0.02f * distance_m, 0.01f, 0.1f);
    c.far_m = distance_m + 8.0f;
    return c;
}

Camera lerp(const Camera& a, const Camera& b, float t) {
    t = std::clamp(t, 0.0f, 1.0f);
    Camera c;
    c.target = glm::mix(a.target, b.target, t);
    const glm::vec3 da = a.eye - a.target, db = b.eye - b.target;
    const float la = glm::length(da), lb = glm::length(db);
    if (la > 1e-6f && lb > 1e-6f) {
        // The eye's direction from the target by slerp, its distance geometrically.
        const glm::vec3 ua = da / la, ub = db / lb;
        const float cos_w = std::clamp(glm::dot(ua, ub), -1.0f, 1.0f);
        const float w = std::acos(cos_w);
        glm::vec3 u;
        if (w < 1e-4f) {
            u = glm::normalize(glm::mix(ua, ub, t));
        } else if (w > 3.1415f) {
            // Opposite directions: swing over the top.
            const glm::vec3 side = glm::normalize(
                glm::cross(ua, std::abs(ua.z) < 0.9f ? glm::vec3(0, 0, 1) : glm::vec3(1, 0, 0)));
            const glm::vec3 over = glm::cross(side, ua);
            u = std::cos(w * t) * ua + std::sin(w * t) * over;
        } else {
            u = (std::sin((1 - t) * w) * ua + std::sin(t * w) * ub) / std::sin(w);
        }
        c.eye = c.target + la * std::pow(lb / la, t) * u;
    } else {
        c.eye = glm::mix(a.eye, b.eye, t);
    }
    // Up: interpolated, then made square to the view so lookAt never degenerates.
    const glm::vec3 f = c.target - c.eye;
    glm::vec3 up = glm::mix(a.up, b.up, t);
    if (glm::length(f) > 1e-6f) {
        const glm::vec3 fn = glm::normalize(f);
        up -= glm::dot(up, fn) * fn;
        if (glm::length(up) < 1e-4f) up = glm::cross(glm::cross(fn, b.up), fn);
    }
    c.up = glm::length(up) > 1e-6f ? glm::normalize(up) : b.up;
    c.fovy_deg = glm::mix(a.fovy_deg, b.fovy_deg, t);
    c.near_m = a.near_m * std::pow(b.near_m / a.near_m, t);
    c.far_m = glm::mix(a.far_m, b.far_m, t);
    return c;
}

}  // namespace render
