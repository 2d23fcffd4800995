// The standard scenes, defined once and shared by tests, benchmarks and the CLI's bench.
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "physics/ball_state.hpp"
#include "physics/params.hpp"
#include "physics/stroke.hpp"
#include "physics/table.hpp"

namespace physics {

struct Scene {
    std::string name;
    TableSpec table;
    std::vector<BallState> balls;
    Stroke stroke;
};

/// "break": a seeded 8-ball rack, cue ball at the head spot, about 9 m/s at the apex ball;
/// "cut": a 2-ball cut shot into a corner pocket; "long_roll": one ball round the table off
/// three cushions (and a fourth, slowly), touching no jaw; "bank": an object ball banked off
/// the south rail into the north side pocket. tests/physics/scenes_test.cpp holds them to it.
std::vector<std::string> standard_scene_names();
Scene standard_scene(std::string_view name, const Params& params = {});

}  // namespace physics
