#include "app/camera_rig.hpp"

#include <algorithm>
#include <cmath>

#include "render/cue_stick.hpp"

namespace app {

namespace {
constexpr float transition_seconds = 0.7f;
}

void CameraRig::begin_blend(const render::Camera& from) {
    from_ = from;
    blend_ = 0.0f;
}

void CameraRig::set_mode(CameraMode mode, const render::Camera& current) {
    if (mode == mode_) return;
    mode_ = mode;
    begin_blend(current);
}

void CameraRig::next_view(const render::Camera& current) {
    set_mode(mode_ == CameraMode::overhead ? CameraMode::cue_ball : CameraMode::overhead, current);
}

void CameraRig::set_anchor(glm::vec2 cue_ball, float heading, bool jump,
                           const render::Camera& current, float cue_elevation) {
    if (jump && mode_ == CameraMode::cue_ball && glm::distance(cue_ball, cue_) > 1e-3f)
        begin_blend(current);
    cue_ = cue_ball;
    heading_ = heading;
    cue_elevation_ = cue_elevation;
}

void CameraRig::zoom(float steps) {
    switch (mode_) {
        case CameraMode::overhead:
            overhead_zoom_ = std::clamp(overhead_zoom_ * std::pow(1.15f, steps), 1.0f, 4.0f);
            break;
        case CameraMode::cue_ball:
            cue_distance_ = std::clamp(cue_distance_ * std::pow(0.87f, steps), 0.3f, 2.5f);
            break;
        case CameraMode::free:
            orbit_distance_ = std::clamp(orbit_distance_ * std::pow(0.87f, steps), 0.5f, 6.0f);
            break;
    }
}

void CameraRig::orbit(float dx, float dy) {
    if (mode_ != CameraMode::free) return;
    yaw_ -= dx * 0.005f;
    pitch_ = std::clamp(pitch_ + dy * 0.005f, 0.08f, 1.5f);
}

void CameraRig::update(double dt) {
    if (blend_ < 1.0f)
        blend_ = std::min(1.0f, blend_ + static_cast<float>(dt) / transition_seconds);
}

render::Camera CameraRig::target_camera(const physics::Table& table, float aspect) const {
    switch (mode_) {
        case CameraMode::overhead: {
            render::Camera c = render::overhead_camera(table, aspect);
            c.fovy_deg /= overhead_zoom_;
            return c;
        }
        case CameraMode::cue_ball:
            return render::cue_ball_camera(
                table, ball_radius_,
                {cue_, heading_, cue_distance_, 0.12f + 0.21f * cue_distance_,
                 render::drawn_cue_elevation(table, ball_radius_, cue_, heading_, cue_elevation_)});
        case CameraMode::free: {
            const glm::vec3 centre{static_cast<float>(table.length()) / 2,
                                   static_cast<float>(table.width()) / 2, 0.0f};
            return render::orbit_camera(centre, yaw_, pitch_, orbit_distance_);
        }
    }
    return {};
}

render::Camera CameraRig::camera(const physics::Table& table, float aspect) const {
    const render::Camera to = target_camera(table, aspect);
    if (blend_ >= 1.0f) return to;
    const float s = blend_ * blend_ * (3.0f - 2.0f * blend_);  // ease in and out
    return render::lerp(from_, to, s);
}

}  // namespace app
