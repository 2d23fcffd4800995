// The scenes the render tests, the goldens and the benchmark draw, defined once. Each is a
// table plus what FrameView needs, built from the physics engine's own racks and shots.
#pragma once

#include <optional>
#include <vector>

#include "physics/table.hpp"
#include "render/camera.hpp"
#include "render/renderer.hpp"

namespace render {

struct DemoScene {
    physics::Table table;
    double ball_radius = 0.028575;  ///< (unit: m)
    std::vector<BallView> balls;
    Camera camera;
    std::optional<CueView> cue;
    AimView aim;
    bool show_aim = false;

    FrameView frame() const { return {balls, camera, cue, show_aim ? &aim : nullptr}; }
};

/// 9 ft table, 8-ball rack with seed 7, cue ball on the head spot, overhead camera.
DemoScene racked_scene(float aspect);
/// The break (physics standard scene "break") at time t (unit: s): balls moving, rolling and
/// spinning, orientations integrated from the shot. Overhead camera.
DemoScene mid_game_scene(float aspect, double t = 0.35);
/// One ball mid-roll with follow, seen from low and close, so its rotation shows.
DemoScene mid_roll_scene(float aspect, double t = 0.6);
/// The racked table seen from behind the cue ball, with the cue stick and the aim guide.
DemoScene cue_view_scene(float aspect);

}  // namespace render
