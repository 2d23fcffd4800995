// The cameras the player switches between: the fixed overhead view of the whole table, the
// view bound to the cue ball that turns with the aim, and a free orbit; smooth transitions
// between them, and zoom (the mouse wheel).
#pragma once

#include <glm/glm.hpp>

#include "app/settings.hpp"
#include "physics/table.hpp"
#include "render/camera.hpp"

namespace app {

enum class CameraMode { overhead, cue_ball, free };

class CameraRig {
  public:
    explicit CameraRig(CameraMode mode = CameraMode::overhead) : mode_(mode) {}

    CameraMode mode() const { return mode_; }
    /// Switches to `mode`, blending from `current` (the camera as last drawn).
    void set_mode(CameraMode mode, const render::Camera& current);
    /// The Change View button: overhead → cue ball → overhead (free → overhead).
    void next_view(const render::Camera& current);
    /// Where the cue-ball view looks from: the cue ball and the aim (unit: m, rad). `jump`:
    /// the cue ball moved to a new place (a new turn), so the view glides there. `cue_elevation`:
    /// the cue's elevation as drawn (unit: rad); a raised cue raises the view.
    void set_anchor(glm::vec2 cue_ball, float heading, bool jump, const render::Camera& current,
                    float cue_elevation = 0.0f);
    /// The balls' radius (unit: m; default a standard 57.15 mm ball).
    void set_ball_radius(float radius) { ball_radius_ = radius; }
    /// Mouse wheel: positive steps zoom in.
    void zoom(float steps);
    /// Free view: turn by (dx, dy) pixels of mouse motion.
    void orbit(float dx, float dy);
    void update(double dt);
    bool animating() const { return blend_ < 1.0f; }

    render::Camera camera(const physics::Table& table, float aspect) const;

  private:
    render::Camera target_camera(const physics::Table& table, float aspect) const;
    void begin_blend(const render::Camera& from);

    CameraMode mode_;
    glm::vec2 cue_{0.635f, 0.635f};
    float heading_ = 0.0f;
    float cue_elevation_ = 0.0f;  ///< (unit: rad)
    float ball_radius_ = 0.028575f;
    float overhead_zoom_ = 1.0f;  ///< 1: the whole table; larger: closer
    float cue_distance_ = 0.75f;  ///< (unit: m)
    float yaw_ = 0.9f, pitch_ = 0.75f, orbit_distance_ = 2.6f;  ///< free view (unit: rad, m)
    render::Camera from_;
    float blend_ = 1.0f;  ///< 0 → 1 over a transition
};

}  // namespace app
