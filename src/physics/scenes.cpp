#include "physics/scenes.hpp"

#include <cmath>
#include <numbers>
#include <stdexcept>

#include "physics/cue_strike.hpp"
#include "physics/portable_math.hpp"
#include "physics/rack.hpp"

namespace physics {

namespace {

BallState ball(int id, double x, double y) {
    BallState b;
    b.id = id;
    b.pos = {x, y};
    return b;
}

double heading_deg(Vec2 from, Vec2 to) {
    return portable::atan2(to.y - from.y, to.x - from.x) * 180.0 / std::numbers::pi;
}

}  // namespace

std::vector<std::string> standard_scene_names() {
    return {"break", "cut", "long_roll", "bank"};
}

Scene standard_scene(std::string_view name, const Params& params) {
    Scene s;
    s.name = std::string(name);
    s.table = *table_preset("9ft");
    const Table table = build_table(s.table);
    const double R = params.ball_radius;
    const double L = s.table.length, W = s.table.width;
    if (name == "break") {
        // A seeded 8-ball rack, the cue ball on the head spot, about 9 m/s at the apex ball.
        s.balls = rack(RackType::eight_ball, table, params, 7);
        s.stroke.speed = cue_speed_for_ball_speed(params, 9.0);
        s.stroke.heading_deg = 0.0;
    } else if (name == "cut") {
        // An object ball 30 cm out of the north-east corner, cut in from the middle of the table.
        const Vec2 pocket{L, W};
        const Vec2 object{L - 0.3 / std::numbers::sqrt2, W - 0.3 / std::numbers::sqrt2};
        const Vec2 cue{L / 2 + 0.1, W / 2 - 0.2};
        const Vec2 dir = (1.0 / norm(pocket - object)) * (pocket - object);
        const Vec2 ghost = object - (2.0 * R) * dir;
        s.balls = {ball(0, cue.x, cue.y), ball(1, object.x, object.y)};
        s.stroke.speed = cue_speed_for_ball_speed(params, 2.0);
        s.stroke.heading_deg = heading_deg(cue, ghost);
    } else if (name == "long_roll") {
        // One ball sent round the table: the north, foot and south rails (then, slow, the head
        // rail), clear of every jaw; at 25° it rattled in the north-east corner's jaws instead.
        s.balls = {ball(0, L / 4, W / 4)};
        s.stroke.speed = cue_speed_for_ball_speed(params, 3.5);
        s.stroke.heading_deg = 31.0;
        s.stroke.top = 0.3;
    } else if (name == "bank") {
        // An object ball banked off the south rail into the north side pocket: a full hit from
        // 0.3 m, at the heading (the middle of a 2.75° window) that makes the bank.
        const double h = -97.25 * std::numbers::pi / 180.0;
        const Vec2 object{L / 2 + 0.2, W / 2 - 0.2};
        const Vec2 cue = object - 0.3 * Vec2{portable::cos(h), portable::sin(h)};
        s.balls = {ball(0, cue.x, cue.y), ball(3, object.x, object.y)};
        s.stroke.speed = cue_speed_for_ball_speed(params, 2.5);
        s.stroke.heading_deg = -97.25;
    } else {
        throw std::invalid_argument("unknown scene: " + std::string(name));
    }
    return s;
}

}  // namespace physics
