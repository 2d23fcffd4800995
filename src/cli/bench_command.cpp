// `bench`: times the standard scenes (physics/scenes.hpp) and reports median and p95 per scene.
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

}  // namespace

nlohmann::ordered_json bench_command(std::int64_t runs) {
    if (runs < 1 || runs > max_bench_runs)
        throw BadInput("--runs", fmt::format("{} is out of range: must be from 1 to {}", runs,
                                             max_bench_runs));
    using clock = std::chrono::steady_clock;
    const physics::Params params;
    nlohmann::ordered_json scenes = nlohmann::ordered_json::object();
    for (const std::string& name : physics::standard_scene_names()) {
        const physics::Scene scene = physics::standard_scene(name, params);
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
        scenes[name] = std::move(s);
    }
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
