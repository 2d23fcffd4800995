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

namespace {

// The parameters an override object may set, and where each goes.
constexpr std::array<std::pair<std::string_view, double physics::Params::*>, 13> kParamFields{{
    {"ball_radius", &physics::Params::ball_radius},
    {"ball_mass", &physics::Params::ball_mass},
    {"gravity", &physics::Params::gravity},
    {"mu_slide", &physics::Params::mu_slide},
    {"mu_roll", &physics::Params::mu_roll},
    {"spin_decel", &physics::Params::spin_decel},
    {"e_ball", &physics::Params::e_ball},
    {"e_cushion", &physics::Params::e_cushion},
    {"mu_cushion", &physics::Params::mu_cushion},
    {"cue_mass", &physics::Params::cue_mass},
    {"cue_tip_e", &physics::Params::cue_tip_e},
    {"cue_endmass", &physics::Params::cue_endmass},
    {"miscue_limit", &physics::Params::miscue_limit},
}};

physics::Params ball_set(const JsonIn& in) {
    const std::string name = in.one_of({"pool", "snooker", "carom"});
    return *physics::params_preset(name);
}

}  // namespace

physics::Params read_params(const JsonIn& in, const physics::Params& base) {
    if (in.raw().is_string()) return ball_set(in);
    if (!in.raw().is_object() || !in.has("preset")) {
        const physics::Params read = game::read_params(in, game::Fields::required);
        if (!in.raw().is_object()) return read;
        physics::Params p = base;
        for (const auto& [key, field] : kParamFields)
            if (in.has(key)) p.*field = read.*field;
        if (in.has("mu_ball")) p.mu_ball = read.mu_ball;
        return p;
    }
    nlohmann::json overrides = in.raw();
    overrides.erase("preset");
    return read_params(JsonIn(overrides, in.path()), ball_set(in.at("preset")));
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
    constexpr std::size_t most = physics::max_ball_id + 1;
    if (n > most)
        in.fail(fmt::format("{} balls given: a table holds at most {} (ids 0–{})", n, most,
                            physics::max_ball_id));
    std::vector<physics::BallState> balls;
    std::array<std::optional<std::size_t>, physics::max_ball_id + 1>
        seen{};  // index of each id given so far
    for (std::size_t i = 0; i < n; ++i) {
        JsonIn b = in.at(i);
        b.expect_object({"id", "pos", "vel", "spin"});
        physics::BallState s;
        JsonIn id = b.at("id");
        s.id = static_cast<int>(id.integer_in(0, physics::max_ball_id));
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
    const std::string game = in.at("game").one_of({"8ball", "9ball", "snooker", "three_cushion"});
    const physics::RackType type = game == "8ball"     ? physics::RackType::eight_ball
                                   : game == "9ball"   ? physics::RackType::nine_ball
                                   : game == "snooker" ? physics::RackType::snooker
                                                       : physics::RackType::three_cushion;
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
    in.expect_object({"speed", "heading_deg", "side", "top", "elevation_deg", "ball"});
    physics::Stroke s;
    s.speed = in.at("speed").number_in(0.0, limits::max_cue_speed);
    if (auto v = in.find("heading_deg")) s.heading_deg = v->number_in(-360.0, 360.0);
    if (auto v = in.find("side")) s.side = v->number_in(-1.0, 1.0);
    if (auto v = in.find("top")) s.top = v->number_in(-1.0, 1.0);
    if (auto v = in.find("elevation_deg")) s.elevation_deg = v->number_in(0.0, 90.0);
    if (auto v = in.find("ball")) s.ball = static_cast<int>(v->integer_in(0, physics::max_ball_id));
    return s;
}

}  // namespace cli
