// JSON ↔ rules types (docs/cli.md, `judge`): reading a game's options, state and a shot's
// events with every check of the contract (bad input names its JSON path), and writing states
// and verdicts in the contract's field order. The readers and writers are game/state_json.hpp's,
// which the session's save files use too: one schema for both.
#pragma once

#include <nlohmann/json.hpp>
#include <vector>

#include "cli/json_in.hpp"
#include "physics/event.hpp"
#include "physics/params.hpp"
#include "physics/table.hpp"
#include "rules/game_state.hpp"
#include "rules/options.hpp"
#include "rules/verdict.hpp"

namespace cli {

/// `game`: "8ball" or "9ball".
rules::Game read_game(const JsonIn& in);

/// `options`: the house-rule switches; omitted ones take their defaults. `call_shots`,
/// `eight_on_break` and `foul_ball_in_hand` are strings, the other three JSON booleans.
rules::Options read_options(const JsonIn& in);

/// `state`: a game state before a shot, checked for the game and the table: object balls of the
/// game only, the 8 (9) on the table, groups only in 8-ball after the break, a call only in
/// 8-ball after the break and of a ball on the table (the 8 only once the shooter's group is
/// cleared), a push-out only in 9-ball with the cue ball on the table, positions only of balls on
/// the table, on the playing surface and not overlapping, a cue ball in hand in the kitchen
/// placed in the kitchen. `groups`, `call`, `fouls_in_row`, `warned`, `positions` are optional.
rules::GameState read_state(const JsonIn& in, rules::Game game, const physics::Table& table,
                            const physics::Params& params);

/// `events`: a shot's events as `simulate` prints them. `type` and `balls` are required, and
/// `pocket` on a pocket event; every ball must be the cue ball or on the table in `s`. An event
/// without `pos` carries NaN positions (the kitchen rule then learns nothing from it).
std::vector<physics::Event> read_events(const JsonIn& in, rules::Game game,
                                        const rules::GameState& s);

/// A state, with the same schema `read_state` reads.
nlohmann::ordered_json to_json(const rules::GameState& s);
/// The house-rule switches, every one of them.
nlohmann::ordered_json to_json(const rules::Options& o);
/// null or {"by": "B", "options": [...]}.
nlohmann::ordered_json to_json(const std::optional<rules::Choice>& c);
/// The `judge` output document.
nlohmann::ordered_json to_json(const rules::Verdict& v);

}  // namespace cli
