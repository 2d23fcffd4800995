// `simulate`: reads a table, parameters, balls and an optional stroke, simulates the shot and
// writes its events, final state and samples (docs/cli.md).
#include <fmt/format.h>

#include <optional>
#include <vector>

#include "cli/commands.hpp"
#include "cli/json_in.hpp"
#include "cli/physics_input.hpp"
#include "cli/shot_output.hpp"
#include "game/state_json.hpp"
#include "physics/simulate.hpp"

namespace cli {

namespace {

inline constexpr std::size_t max_sample_times = 10000;
// Beyond any shot's end; keeps positions finite even for a ball that never stops (no friction).
inline constexpr double max_sample_time = 1e6;  // (unit: s)
inline constexpr std::int64_t max_event_cap = 1'000'000;

struct SimulateInput {
    physics::Table table;
    physics::Params params;
    physics::SimOptions options;
    std::vector<physics::BallState> balls;
    std::optional<physics::Stroke> stroke;
    std::vector<double> sample_times;
};

// The struck ball must exist and be at rest.
void check_strikable(const JsonIn& doc, const std::vector<physics::BallState>& balls, int id) {
    for (std::size_t i = 0; i < balls.size(); ++i) {
        const physics::BallState& b = balls[i];
        if (b.id != id) continue;
        if (b.vel.x != 0.0 || b.vel.y != 0.0)
            throw BadInput(fmt::format("balls[{}].vel", i),
                           fmt::format("ball {} must be at rest to be struck: give it no "
                                       "velocity, or drop the strike",
                                       id));
        if (b.spin.x != 0.0 || b.spin.y != 0.0 || b.spin.z != 0.0)
            throw BadInput(fmt::format("balls[{}].spin", i),
                           fmt::format("ball {} must be at rest to be struck: give it no spin, "
                                       "or drop the strike",
                                       id));
        return;
    }
    if (id == 0)
        doc.at("strike").fail("there is no ball 0 (the cue ball) to strike: add a ball with id 0");
    doc.at("strike").at("ball").fail(fmt::format("there is no ball {} to strike", id));
}

// The ball set that goes with the table: snooker balls on a snooker table, carom balls on a
// carom table, pool balls on any other.
physics::Params default_ball_set(const JsonIn& doc) {
    std::string preset;
    if (auto t = doc.find("table")) {
        if (t->raw().is_string()) preset = t->raw().get<std::string>();
        if (t->raw().is_object() && t->raw().contains("preset") && t->raw()["preset"].is_string())
            preset = t->raw()["preset"].get<std::string>();
    }
    if (preset == "snooker12ft") return *physics::params_preset("snooker");
    if (preset == "carom10ft") return *physics::params_preset("carom");
    return {};
}

std::vector<double> read_sample_times(const JsonIn& times) {
    std::vector<double> out;
    std::size_t n = times.array_size();
    if (n > max_sample_times)
        times.fail(fmt::format("{} times given: at most {} are allowed", n, max_sample_times));
    out.reserve(n);
    for (std::size_t i = 0; i < n; ++i) {
        JsonIn t = times.at(i);
        double v = t.number();
        if (!(v >= 0.0 && v <= max_sample_time))
            t.fail(fmt::format("{} is out of range: must be from 0 to {} s", v, max_sample_time));
        out.push_back(v);
    }
    return out;
}

SimulateInput read_input(const JsonIn& doc) {
    doc.expect_object(
        {"table", "params", "models", "balls", "rack", "strike", "sample_times", "max_events"});
    SimulateInput in;
    in.params = default_ball_set(doc);
    if (auto p = doc.find("params")) in.params = read_params(*p, in.params);
    if (auto m = doc.find("models")) in.options.models = read_models(*m);

    physics::TableSpec spec = *physics::table_preset("9ft");
    if (auto t = doc.find("table")) {
        spec = read_table(*t, in.params.ball_radius);
    } else if (auto problem = physics::validate_table_spec(spec, in.params.ball_radius)) {
        // The default table only fails for odd balls.
        throw BadInput("params.ball_radius",
                       fmt::format("too large for the default 9ft table ({})", *problem));
    }
    in.table = physics::build_table(spec);

    std::optional<JsonIn> balls = doc.find("balls");
    std::optional<JsonIn> rack = doc.find("rack");
    if (balls && rack) rack->fail("give either balls or rack, not both");
    if (balls)
        in.balls = read_balls(*balls, in.table, in.params);
    else if (rack)
        in.balls = read_rack(*rack, in.table, in.params);
    else
        throw BadInput("balls", "missing required field: give balls, or rack to rack a game");

    if (auto s = doc.find("strike")) {
        in.stroke = cli::read_stroke(*s);
        if (balls || in.stroke->ball != 0) check_strikable(doc, in.balls, in.stroke->ball);
    }

    if (auto times = doc.find("sample_times")) in.sample_times = read_sample_times(*times);

    if (auto m = doc.find("max_events"))
        in.options.max_events = static_cast<std::size_t>(m->integer_in(1, max_event_cap));
    return in;
}

}  // namespace

nlohmann::ordered_json simulate_command(const nlohmann::json& input) {
    SimulateInput in = read_input(JsonIn(input, ""));
    const physics::Stroke* stroke = in.stroke ? &*in.stroke : nullptr;
    physics::Shot shot = physics::simulate(in.table, in.params, in.balls, stroke, in.options);
    nlohmann::ordered_json out = shot_to_json(shot, in.sample_times);
    if (shot.truncated()) out["rest_time"] = nullptr;
    return out;
}

}  // namespace cli
