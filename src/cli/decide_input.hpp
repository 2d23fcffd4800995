// What `decide` needs beyond what `judge` reads: the AI plans from every ball's position, so a
// state that the judge may take partial must be whole here (pool and snooker states alike).
#pragma once

#include <fmt/format.h>

#include <string>

#include "cli/json_in.hpp"
#include "rules/game_state.hpp"

namespace cli {

/// Every object ball on the table has a position, and the cue ball one when it is on the
/// table; else BadInput naming `<state>.positions` and the fix.
template <class State>
void require_positions(const JsonIn& state, const State& s) {
    const std::string path = state.path() + ".positions";
    for (int id : s.on_table)
        if (!s.positions.count(id))
            throw BadInput(path, fmt::format("ball {} is on the table but has no position: give "
                                             "every ball's position, e.g. \"{}\": [1.9, 0.6]",
                                             id, id));
    if (s.cue_ball == rules::CueBall::on_table && !s.positions.count(0))
        throw BadInput(path,
                       "the cue ball is on the table (cue_ball \"on_table\"): give its "
                       "position as \"0\": [x, y]");
}

}  // namespace cli
