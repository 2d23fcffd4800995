#include "cli/physics_input.hpp"

#include <fmt/format.h>

#include <array>
#include <climits>
#include <cmath>
#include <optional>
#include <string>
#include <string_view>

#include "game/state_json.hpp"
#include "physics/layout.hpp"
#include "physics/rack.hpp"

namespace cli {

physics::TableSpec read_table(const JsonIn& in, double ball_radius) {
    return game::read_table(in, ball_radius, game::Fields::required);
}

physics::Models read_models(const JsonIn& in) {
    in.expect_object({"ball_ball", "cushion"});
    physics::Models m;
    if (auto v = in.find("ball_ball"))
        m.ball_ball = v->one_of({"frictional", "frictionless"}) == "frictional"
                          ? physics::BallBallModel::frictional
                          : physics::BallBallModel::frictionless;
    if (auto v = in.find("cushion"))
        m.cushion = v->one_of({"han2005", "simple"}) == "han2005" ? physics::CushionModel::han2005
                                                                  : physics::CushionModel::simple;
    return m;
}

namespace {

physics::Vec2 read_position(const JsonIn& in) {
    physics::Vec2 p = game::read_vec2(in);
    if (std::fabs(p.x) > limits::max_coordinate || std::fabs(p.y) > limits::max_coordinate)
        in.fail(fmt::format("[{}, {}] is too far out: coordinates must be within ±{} m", p.x, p.y,
                            limits::max_coordinate));
    return p;
}

// Maps an error of physics::validate_layout to the JSON path of the offending ball.
[[noreturn]] void layout_error(const JsonIn& balls, const physics::LayoutError& e) {
    std::string path = fmt::format("{}[{}]", balls.path(), e.index);
    if (!e.field.empty()) path += "." + e.field;
    throw BadInput(path, e.message);
}

}  // namespace

std::vector<physics::BallState> read_balls(const JsonIn& in, const physics::Table& table,
                                           const physics::Params& params) {
    std::size_t n = in.array_size();
    if (n > 16) in.fail(fmt::format("{} balls given: a table holds at most 16 (ids 0–15)", n));
    std::vector<physics::BallState> balls;
    std::array<std::optional<std::size_t>, 16> seen{};  // index of each id given so far
    for (std::size_t i = 0; i < n; ++i) {
        JsonIn b = in.at(i);
        b.expect_object({"id", "pos", "vel", "spin"});
        physics::BallState s;
        JsonIn id = b.at("id");
        s.id = static_cast<int>(id.integer_in(0, 15));
        auto& first = seen[static_cast<std::size_t>(s.id)];
        if (first)
            id.fail(fmt::format("ball {} is given twice (also {}[{}]): ids must be unique", s.id,
                                in.path(), *first));
        first = i;
        s.pos = read_position(b.at("pos"));
        if (auto v = b.find("vel")) {
            s.vel = game::read_vec2(*v);
            if (!(physics::norm(s.vel) <= limits::max_ball_speed))
                v->fail(fmt::format("speed {} m/s is too fast: at most {} m/s",
                                    physics::norm(s.vel), limits::max_ball_speed));
        }
        if (auto v = b.find("spin")) {
            s.spin = game::read_vec3(*v);
            if (!(physics::norm(s.spin) <= limits::max_ball_spin))
                v->fail(fmt::format("spin {} rad/s is too fast: at most {} rad/s",
                                    physics::norm(s.spin), limits::max_ball_spin));
        }
        s.motion = physics::classify_motion(params, s.vel, s.spin);
        balls.push_back(s);
    }
    if (auto e = physics::validate_layout(table, params, balls)) layout_error(in, *e);
    return balls;
}

std::vector<physics::BallState> read_rack(const JsonIn& in, const physics::Table& table,
                                          const physics::Params& params) {
    in.expect_object({"game", "seed", "cue_pos"});
    physics::RackType type = in.at("game").one_of({"8ball", "9ball"}) == "8ball"
                                 ? physics::RackType::eight_ball
                                 : physics::RackType::nine_ball;
    std::uint64_t seed = 0;
    if (auto v = in.find("seed")) seed = static_cast<std::uint64_t>(v->integer_in(0, INT64_MAX));
    std::optional<physics::Vec2> cue_pos;
    std::optional<JsonIn> cue_in = in.find("cue_pos");
    if (cue_in) cue_pos = read_position(*cue_in);

    std::vector<physics::BallState> balls = physics::rack(type, table, params, seed, cue_pos);
    // Checked with the cue ball last, so that an overlap with it is reported on the cue ball.
    std::vector<physics::BallState> order;
    for (const physics::BallState& b : balls)
        if (b.id != 0) order.push_back(b);
    for (const physics::BallState& b : balls)
        if (b.id == 0) order.push_back(b);
    if (auto e = physics::validate_layout(table, params, order)) {
        const int id = e->index < order.size() ? order[e->index].id : -1;
        if (id == 0 && cue_in) cue_in->fail("cue ball: " + e->message);
        in.fail(fmt::format("ball {} of the rack: {} (use a larger table or smaller balls)", id,
                            e->message));
    }
    return balls;
}

physics::Stroke read_stroke(const JsonIn& in) {
    in.expect_object({"speed", "heading_deg", "side", "top", "elevation_deg"});
    physics::Stroke s;
    s.speed = in.at("speed").number_in(0.0, limits::max_cue_speed);
    if (auto v = in.find("heading_deg")) s.heading_deg = v->number_in(-360.0, 360.0);
    if (auto v = in.find("side")) s.side = v->number_in(-1.0, 1.0);
    if (auto v = in.find("top")) s.top = v->number_in(-1.0, 1.0);
    if (auto v = in.find("elevation_deg")) s.elevation_deg = v->number_in(0.0, 90.0);
    return s;
}

}  // namespace cli
