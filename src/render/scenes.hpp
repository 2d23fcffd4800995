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
    double ball_radius = 0.028575;   ///< (unit: m)
    GameLook look = GameLook::pool;  ///< the game's balls and cloth marks (RenderSettings::look)
    std::vector<BallView> balls;
    Camera camera;
    std::optional<CueView> cue;
    AimView aim;
    bool show_aim = false;
    std::optional<BallInHandView> ball_in_hand;
    std::vector<int> tray;

    FrameView frame() const {
        return {balls, camera, cue, show_aim ? &aim : nullptr, ball_in_hand, tray};
    }
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
/// The cue ball 4 mm off the head rail, aimed at the apex ball, seen from the cue-ball view:
/// the view rises over the rail, the rail forces the cue's butt up; tip above centre.
DemoScene rail_view_scene(float aspect);
/// The cue raised 25 degrees, tip low and right of centre, in the cue-ball view (raised too).
DemoScene raised_cue_scene(float aspect);
/// A corner pocket close up: one ball dropping into it, one in the jaws.
DemoScene pocket_scene(float aspect);
/// The room from a corner, standing: the table, its legs and body, the lamps, the walls.
DemoScene room_scene(float aspect);
/// The same aim as cue_view_scene (cue stick and aim guide) seen from the overhead camera,
/// so the cue's shadow on the cloth shows.
DemoScene aim_overhead_scene(float aspect);
/// Two balls frozen to the north cushion and one a little off it, seen from low and close:
/// their shadows fall on the cushion's nose and face.
DemoScene cushion_scene(float aspect);
/// After a scratch: the break's balls at rest-ish (t = 3 s), five object balls in the
/// ball-return tray, the cue ball in hand behind the head string (kitchen shaded) on an
/// illegal spot (red). Overhead camera.
DemoScene ball_in_hand_scene(float aspect);

/// The 12 ft snooker table set up (WPBSA), the cue ball in the D: the baulk line, the D, the
/// colour spots, snooker pockets and ball colours. Overhead camera.
DemoScene snooker_scene(float aspect);
/// The same set-up seen from behind the cue ball in the D, aimed at the reds.
DemoScene snooker_cue_view_scene(float aspect);
/// The 10 ft carom table in the UMB starting position: no pockets, the spots, the diamonds,
/// white, yellow and red. Overhead camera.
DemoScene carom_scene(float aspect);

}  // namespace render
