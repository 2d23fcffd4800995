// `bench`: times the standard scenes (physics/scenes.hpp) and the other games' scenes (a snooker
// break, a three-cushion point) and reports median and p95 per scene.
#include <fmt/format.h>
#include <sys/utsname.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <string>
#include <thread>
#include <vector>

#include "cli/commands.hpp"
#include "cli/json_in.hpp"
#include "physics/cue_strike.hpp"
#include "physics/markings.hpp"
#include "physics/rack.hpp"
#include "physics/scenes.hpp"
#include "physics/simulate.hpp"

namespace cli {

namespace {

// A scene stops early (reporting the runs it made) once it has used this much time.
constexpr double scene_budget_s = 30.0;

// The value below which a fraction q of the sorted samples lie (nearest rank).
double quantile(const std::vector<double>& sorted, double q) {
    std::size_t rank = static_cast<std::size_t>(std::ceil(q * static_cast<double>(sorted.size())));
    return sorted[std::clamp<std::size_t>(rank, 1, sorted.size()) - 1];
}

std::string machine() {
    utsname u{};
    std::string arch = uname(&u) == 0 ? u.machine : "unknown";
    unsigned cores = std::thread::hardware_concurrency();
    return fmt::format("{}, {} core{}", arch, cores, cores == 1 ? "" : "s");
}

// The three-cushion scene's stroke (see game_scenes).
physics::Stroke three_cushion_stroke(const physics::Params& params) {
    physics::Stroke s;
    s.speed = physics::cue_speed_for_ball_speed(params, 2.8);
    s.heading_deg = 176.0;
    s.side = 0.4;
    s.top = 0.2;
    return s;
}

struct BenchScene {
    std::string name;
    physics::Params params;
    physics::Scene scene;
};

// The snooker and three-cushion scenes, each on its own table and ball set.
std::vector<BenchScene> game_scenes() {
    std::vector<BenchScene> out;
    {
        // "snooker_break": the full rack, the cue ball on the baulk line between the brown and
        // the yellow, struck full at the apex red at 8 m/s: all 22 balls on the move.
        BenchScene b{"snooker_break", *physics::params_preset("snooker"), {}};
        b.scene.name = b.name;
        b.scene.table = physics::snooker_table_spec();
        const physics::Table table = physics::build_table(b.scene.table);
        b.scene.balls = physics::snooker_rack(table, b.params);
        physics::Vec2 cue = b.scene.balls.front().pos, apex{1e9, 0.0};
        for (const physics::BallState& s : b.scene.balls)
            if (physics::is_red(s.id) && s.pos.x < apex.x) apex = s.pos;
        b.scene.stroke.speed = physics::cue_speed_for_ball_speed(b.params, 8.0);
        b.scene.stroke.heading_deg =
            std::atan2(apex.y - cue.y, apex.x - cue.x) * 180.0 / 3.14159265358979323846;
        out.push_back(std::move(b));
    }
    {
        // "three_cushion": the UMB opening position and a stroke that scores from it (the
        // level-5 player's choice at noise 0): the white off the bottom cushion onto the red,
        // round the table onto the yellow.
        BenchScene c{"three_cushion", *physics::params_preset("carom"), {}};
        c.scene.name = c.name;
        c.scene.table = physics::carom_table_spec();
        c.scene.balls = physics::carom_rack(physics::build_table(c.scene.table));
        c.scene.stroke = three_cushion_stroke(c.params);
        out.push_back(std::move(c));
    }
    return out;
}

// Times `runs` simulations of a scene (fewer if it runs past its budget).
nlohmann::ordered_json time_scene(const std::string& name, const physics::Params& params,
                                  const physics::Scene& scene, std::int64_t runs) {
    using clock = std::chrono::steady_clock;
    const physics::Table table = physics::build_table(scene.table);
    // One untimed run to warm caches; it also gives the event count.
    const std::size_t events =
        physics::simulate(table, params, scene.balls, &scene.stroke).events().size();
    std::vector<double> us;
    us.reserve(static_cast<std::size_t>(runs));
    const clock::time_point scene_start = clock::now();
    for (std::int64_t r = 0; r < runs; ++r) {
        const clock::time_point t0 = clock::now();
        physics::Shot shot = physics::simulate(table, params, scene.balls, &scene.stroke);
        const clock::time_point t1 = clock::now();
        if (shot.events().size() != events)
            throw std::logic_error(
                fmt::format("scene {}: {} events, then {}: the simulation is not deterministic",
                            name, events, shot.events().size()));
        us.push_back(std::chrono::duration<double, std::micro>(t1 - t0).count());
        if (std::chrono::duration<double>(t1 - scene_start).count() > scene_budget_s) break;
    }
    std::sort(us.begin(), us.end());
    nlohmann::ordered_json s;
    // Rounded to 0.1 µs: finer digits are noise.
    s["median_us"] = std::round(quantile(us, 0.5) * 10.0) / 10.0;
    s["p95_us"] = std::round(quantile(us, 0.95) * 10.0) / 10.0;
    s["events"] = events;
    s["runs"] = us.size();
    return s;
}

}  // namespace

nlohmann::ordered_json bench_command(std::int64_t runs) {
    if (runs < 1 || runs > max_bench_runs)
        throw BadInput("--runs", fmt::format("{} is out of range: must be from 1 to {}", runs,
                                             max_bench_runs));
    const physics::Params params;
    nlohmann::ordered_json scenes = nlohmann::ordered_json::object();
    for (const std::string& name : physics::standard_scene_names())
        scenes[name] = time_scene(name, params, physics::standard_scene(name, params), runs);
    for (const BenchScene& g : game_scenes())
        scenes[g.name] = time_scene(g.name, g.params, g.scene, runs);
    nlohmann::ordered_json out;
    out["scenes"] = std::move(scenes);
    out["machine"] = machine();
#ifdef NDEBUG
    out["build"] = "release";
#else
    out["build"] = "debug";
#endif
    return out;
}

}  // namespace cli
