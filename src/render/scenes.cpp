#include "render/scenes.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "physics/rack.hpp"
#include "physics/scenes.hpp"
#include "physics/simulate.hpp"
#include "render/cue_stick.hpp"
#include "render/orientation.hpp"
#include "render/pockets.hpp"

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
    s.camera =
        cue_ball_camera(s.table, static_cast<float>(s.ball_radius),
                        {{cue.centre.x, cue.centre.y}, heading, 0.75f, 0.2775f, s.cue->elevation});
    return s;
}

DemoScene rail_view_scene(float aspect) {
    DemoScene s = racked_scene(aspect);
    // The cue ball 4 mm off the head rail, the aim up the table at the apex ball: the view
    // rises to see it over the rail, and the rail forces the cue's butt up.
    BallView& cue = s.balls.front();
    cue.centre.x = static_cast<float>(s.ball_radius) + 0.004f;
    cue.centre.y = 0.55f * static_cast<float>(s.table.width());
    const float heading = aim_at_apex(s, 0.0f, 0.04f);
    s.cue->tip_offset = {0.0f, 0.3f};
    const float R = static_cast<float>(s.ball_radius);
    const glm::vec2 c{cue.centre.x, cue.centre.y};
    s.camera = cue_ball_camera(
        s.table, R,
        {c, heading, 0.75f, 0.2775f,
         drawn_cue_elevation(s.table, R, c, heading, s.cue->elevation, s.cue->tip_offset)});
    return s;
}

DemoScene raised_cue_scene(float aspect) {
    DemoScene s = racked_scene(aspect);
    // A masse-like stroke: the cue raised 25 degrees, the tip low and right.
    const float heading = aim_at_apex(s, 0.4363323f, 0.05f);
    s.cue->tip_offset = {0.35f, -0.3f};
    const BallView& cue = s.balls.front();
    s.camera =
        cue_ball_camera(s.table, static_cast<float>(s.ball_radius),
                        {{cue.centre.x, cue.centre.y}, heading, 0.75f, 0.2775f, s.cue->elevation});
    return s;
}

DemoScene pocket_scene(float aspect) {
    DemoScene s = racked_scene(aspect);
    // The foot-right corner pocket close up, the 9 half-way into it and the 3 in the jaws.
    const float L = static_cast<float>(s.table.length()), W = static_cast<float>(s.table.width());
    const float R = static_cast<float>(s.ball_radius);
    s.balls.resize(1);
    s.balls.push_back({9, dropping_ball_centre(s.table, R, {L - 0.02f, W - 0.02f}, 0.12f),
                       initial_orientation(9)});
    s.balls.push_back({3, {L - 0.09f, W - 0.045f, R}, initial_orientation(3)});
    s.camera.target = {L - 0.03f, W - 0.03f, -0.01f};
    s.camera.eye = {L - 0.42f, W - 0.36f, 0.32f};
    s.camera.up = {0, 0, 1};
    s.camera.fovy_deg = 35.0f;
    s.camera.near_m = 0.02f;
    s.camera.far_m = 14.0f;
    (void)aspect;
    return s;
}

DemoScene room_scene(float aspect) {
    DemoScene s = racked_scene(aspect);
    // From a corner of the room, standing: the table, its legs, the lamps and the walls.
    const float L = static_cast<float>(s.table.length()), W = static_cast<float>(s.table.width());
    s.camera.target = {0.5f * L, 0.5f * W, -0.15f};
    s.camera.eye = {-1.3f, -1.25f, 0.9f};
    s.camera.up = {0, 0, 1};
    s.camera.fovy_deg = 50.0f;
    s.camera.near_m = 0.05f;
    s.camera.far_m = 14.0f;
    (void)aspect;
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
    s.ball_in_hand = BallInHandView{{0.14f * L, 0.58f * W}, false, true, std::nullopt};
    return s;
}

namespace {

DemoScene rest_scene(const physics::TableSpec& spec, const physics::Params& params,
                     const std::vector<physics::BallState>& balls, GameLook look, float aspect) {
    DemoScene s;
    s.table = physics::build_table(spec);
    s.ball_radius = params.ball_radius;
    s.look = look;
    for (const physics::BallState& b : balls)
        s.balls.push_back(ball_view(b, s.ball_radius, initial_orientation(b.id)));
    s.camera = overhead_camera(s.table, aspect);
    return s;
}

}  // namespace

DemoScene snooker_scene(float aspect) {
    const physics::Params params = *physics::params_preset("snooker");
    const physics::Table t = physics::build_table(physics::snooker_table_spec());
    return rest_scene(physics::snooker_table_spec(), params, physics::snooker_rack(t, params),
                      GameLook::snooker, aspect);
}

DemoScene snooker_cue_view_scene(float aspect) {
    DemoScene s = snooker_scene(aspect);
    const BallView& cue = s.balls.front();
    s.cue = CueView{{cue.centre.x, cue.centre.y}, 0.0f, 0.08f, 0.06f};
    s.camera = cue_ball_camera(s.table, static_cast<float>(s.ball_radius),
                               {{cue.centre.x, cue.centre.y}, 0.0f, 0.75f, 0.2775f, 0.08f});
    return s;
}

DemoScene carom_scene(float aspect) {
    const physics::Params params = *physics::params_preset("carom");
    const physics::Table t = physics::build_table(physics::carom_table_spec());
    return rest_scene(physics::carom_table_spec(), params, physics::carom_rack(t), GameLook::carom,
                      aspect);
}

}  // namespace render
