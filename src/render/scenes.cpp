#include "render/scenes.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "physics/rack.hpp"
#include "physics/scenes.hpp"
#include "physics/simulate.hpp"
#include "render/orientation.hpp"

namespace render {

namespace {

std::vector<BallView> views_at(const physics::Shot& shot, double t, double radius) {
    std::vector<BallView> out;
    for (std::size_t i = 0; i < shot.ball_count(); ++i) {
        const int id = shot.ball_id(i);
        const physics::BallState s = shot.state_at(id, t);
        if (s.motion == physics::Motion::pocketed) continue;
        out.push_back(
            ball_view(s, radius, integrate_orientation(shot, id, 0.0, t, initial_orientation(id))));
    }
    return out;
}

// The cue ball (the scene's first ball) aimed full at the apex ball on the foot spot: the cue
// (elevation, pull-back in m) and the aim guide; returns the heading (unit: rad).
float aim_at_apex(DemoScene& s, float elevation, float pull_back) {
    const BallView& cue = s.balls.front();
    const glm::vec2 c{cue.centre.x, cue.centre.y};
    const physics::Vec2 foot = s.table.foot_spot();
    const glm::vec2 apex{static_cast<float>(foot.x), static_cast<float>(foot.y)};
    const glm::vec2 d = glm::normalize(apex - c);
    const float heading = std::atan2(d.y, d.x);
    s.cue = CueView{c, heading, elevation, pull_back};
    const float R = static_cast<float>(s.ball_radius);
    const glm::vec2 ghost = apex - 2.0f * R * d;
    s.aim.cue_path = {c, ghost};
    s.aim.ghost = ghost;
    s.aim.object_path = {apex, apex + 0.4f * d};
    s.show_aim = true;
    return heading;
}

}  // namespace

DemoScene racked_scene(float aspect) {
    DemoScene s;
    const physics::Params params;
    s.table = physics::build_table(*physics::table_preset("9ft"));
    s.ball_radius = params.ball_radius;
    for (const physics::BallState& b :
         physics::rack(physics::RackType::eight_ball, s.table, params, 7))
        s.balls.push_back(ball_view(b, s.ball_radius, initial_orientation(b.id)));
    s.camera = overhead_camera(s.table, aspect);
    return s;
}

DemoScene mid_game_scene(float aspect, double t) {
    DemoScene s;
    const physics::Params params;
    const physics::Scene scene = physics::standard_scene("break", params);
    s.table = physics::build_table(scene.table);
    s.ball_radius = params.ball_radius;
    const physics::Shot shot = physics::simulate(s.table, params, scene.balls, &scene.stroke);
    s.balls = views_at(shot, t, s.ball_radius);
    s.camera = overhead_camera(s.table, aspect);
    return s;
}

DemoScene mid_roll_scene(float aspect, double t) {
    DemoScene s;
    const physics::Params params;
    s.table = physics::build_table(*physics::table_preset("9ft"));
    s.ball_radius = params.ball_radius;
    // The cue ball drives the 11 (a stripe) straight up the table; the 11 slides, then rolls.
    physics::BallState cue;
    cue.id = 0;
    cue.pos = {0.55, 0.60};
    physics::BallState eleven;
    eleven.id = 11;
    eleven.pos = {0.95, 0.62};
    const physics::BallState balls[] = {cue, eleven};
    physics::Stroke stroke;
    stroke.speed = 2.6;
    stroke.heading_deg = 2.0;
    const physics::Shot shot = physics::simulate(s.table, params, balls, &stroke);
    s.balls = views_at(shot, t, s.ball_radius);
    // Low and close beside the 11's path, looking at it.
    const physics::BallState now = shot.state_at(11, t);
    const glm::vec2 p{static_cast<float>(now.pos.x), static_cast<float>(now.pos.y)};
    s.camera.target = {p, static_cast<float>(s.ball_radius)};
    s.camera.eye = {p + glm::vec2(0.12f, -0.30f), 0.16f};
    s.camera.up = {0, 0, 1};
    s.camera.fovy_deg = 30.0f;
    s.camera.near_m = 0.02f;
    s.camera.far_m = 8.0f;
    (void)aspect;
    return s;
}

DemoScene cue_view_scene(float aspect) {
    DemoScene s = racked_scene(aspect);
    const float heading = aim_at_apex(s, 0.08f, 0.06f);
    const BallView& cue = s.balls.front();
    s.camera = cue_ball_camera({cue.centre.x, cue.centre.y}, heading);
    return s;
}

DemoScene aim_overhead_scene(float aspect) {
    DemoScene s = racked_scene(aspect);
    // The cue ball off the long axis, aimed at the apex ball: the cue crosses the lamps' line.
    BallView& cue = s.balls.front();
    const float L = static_cast<float>(s.table.length()), W = static_cast<float>(s.table.width());
    cue.centre = {0.3f * L, 0.22f * W, cue.centre.z};
    aim_at_apex(s, 0.10f, 0.10f);
    return s;
}

DemoScene cushion_scene(float aspect) {
    DemoScene s;
    const physics::Params params;
    s.table = physics::build_table(*physics::table_preset("9ft"));
    s.ball_radius = params.ball_radius;
    const float R = static_cast<float>(s.ball_radius), L = static_cast<float>(s.table.length()),
                W = static_cast<float>(s.table.width());
    const glm::vec3 spots[] = {{0.30f * L, W - R - 0.001f, R},
                               {0.30f * L + 0.09f, W - R - 0.001f, R},
                               {0.30f * L + 0.20f, W - R - 0.03f, R}};
    const int ids[] = {3, 10, 8};
    for (int k = 0; k < 3; ++k)
        s.balls.push_back({ids[k], spots[k], glm::quat(initial_orientation(ids[k]))});
    s.camera.target = {0.30f * L + 0.10f, W - 0.02f, 0.02f};
    s.camera.eye = {0.30f * L - 0.05f, W - 0.45f, 0.17f};
    s.camera.up = {0, 0, 1};
    s.camera.fovy_deg = 32.0f;
    s.camera.near_m = 0.02f;
    s.camera.far_m = 8.0f;
    (void)aspect;
    return s;
}

DemoScene ball_in_hand_scene(float aspect) {
    DemoScene s = mid_game_scene(aspect, 3.0);
    s.tray = {3, 9, 14, 6, 11};
    std::erase_if(s.balls, [&](const BallView& b) {
        return b.id == 0 || std::find(s.tray.begin(), s.tray.end(), b.id) != s.tray.end();
    });
    const float L = static_cast<float>(s.table.length()), W = static_cast<float>(s.table.width());
    s.ball_in_hand = BallInHandView{{0.14f * L, 0.58f * W}, false, true};
    return s;
}

}  // namespace render
