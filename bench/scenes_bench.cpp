// The standard scenes (physics/scenes.hpp), the same ones `coolaaber-cli bench` runs.
#include <benchmark/benchmark.h>

#include "physics/scenes.hpp"
#include "physics/simulate.hpp"

namespace {

void BM_Scene(benchmark::State& state, const char* name) {
    const physics::Params params;
    const physics::Scene scene = physics::standard_scene(name, params);
    const physics::Table table = physics::build_table(scene.table);
    std::size_t events = 0;
    for (auto _ : state) {
        physics::Shot shot = physics::simulate(table, params, scene.balls, &scene.stroke);
        events = shot.events().size();
        benchmark::DoNotOptimize(shot);
    }
    state.counters["events"] = static_cast<double>(events);
}

BENCHMARK_CAPTURE(BM_Scene, break, "break")->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(BM_Scene, cut, "cut")->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(BM_Scene, long_roll, "long_roll")->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(BM_Scene, bank, "bank")->Unit(benchmark::kMicrosecond);

}  // namespace
