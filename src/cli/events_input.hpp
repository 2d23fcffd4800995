// Reading the parts of a snooker or three-cushion `judge` document that are not the games' own
// (docs/cli.md, "judge: snooker and three-cushion"): events on any ball set, positions by
// ball id, and per-player pairs. Bad input throws BadInput naming its JSON path.
#pragma once

#include <array>
#include <functional>
#include <map>
#include <nlohmann/json.hpp>
#include <vector>

#include "cli/json_in.hpp"
#include "physics/event.hpp"
#include "physics/params.hpp"
#include "physics/table.hpp"

namespace cli {

/// Which balls an event may name: ids 0 to `highest` for which `present` holds.
struct BallSet {
    int highest = 0;
    std::function<bool(int)> present;
    bool pockets = true;      ///< false: a carom table, a pocket event is bad input
    bool any_struck = false;  ///< true: a strike may be on any ball (carom), else on ball 0
};

/// `events`: as `simulate` prints them (game::read_event checks every field), with ball ids
/// from `balls`.
std::vector<physics::Event> read_events(const JsonIn& in, const BallSet& balls);

/// `positions`: {"0": [x, y], ...} of balls in `balls`, on the table and not overlapping.
std::map<int, physics::Vec2> read_positions(const JsonIn& in, const BallSet& balls,
                                            const physics::Table& table,
                                            const physics::Params& params);

/// {"A": n, "B": n} with each n in [lo, hi].
std::array<int, 2> read_pair(const JsonIn& in, int lo, int hi);
nlohmann::ordered_json pair_to_json(const std::array<int, 2>& v);
nlohmann::ordered_json positions_to_json(const std::map<int, physics::Vec2>& positions);

}  // namespace cli
