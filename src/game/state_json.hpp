// JSON of the rules' and the physics' values in a save file, in the schemas of the CLI contract
// (docs/cli.md: the `judge` state and verdict, the `simulate` stroke and events). Readers
// check every field against the game and the table and throw game::LoadError naming its path.
#pragma once

#include <nlohmann/json.hpp>
#include <optional>

#include "game/json_field.hpp"
#include "physics/event.hpp"
#include "physics/params.hpp"
#include "physics/stroke.hpp"
#include "physics/table.hpp"
#include "rules/game_state.hpp"
#include "rules/options.hpp"
#include "rules/verdict.hpp"

namespace game {

// ---- Writing
nlohmann::ordered_json to_json(physics::Vec2 v);
nlohmann::ordered_json to_json(physics::Vec3 v);
/// null, "safety" or {"ball": 5, "pocket": "N"}.
nlohmann::ordered_json to_json(const rules::Call& c);
/// A state with every field (the `judge` state schema).
/// Every dimension of a table (the inverse of read_table with Fields::all).
nlohmann::ordered_json to_json(const physics::TableSpec& t);
/// Every physical parameter (the inverse of read_params with Fields::all).
nlohmann::ordered_json to_json(const physics::Params& p);
nlohmann::ordered_json to_json(const rules::GameState& s);
/// Every house-rule switch.
nlohmann::ordered_json to_json(const rules::Options& o);
/// null or {"by": "B", "options": [...]}.
nlohmann::ordered_json to_json(const std::optional<rules::Choice>& c);
/// The `judge` output document.
nlohmann::ordered_json to_json(const rules::Verdict& v);
/// {"speed", "heading_deg", "side", "top", "elevation_deg"}.
nlohmann::ordered_json to_json(const physics::Stroke& s);
/// One event as `simulate` prints it.
nlohmann::ordered_json to_json(const physics::Event& e);

// ---- Reading
/// How much of a document must be given: a saved game has `all` the fields `to_json` writes;
/// the CLI's input (docs/cli.md, `judge` and `decide`) may leave out the optional ones
/// (`required`), which then take their defaults.
enum class Fields { all, required };

/// What a state is checked against.
struct TableContext {
    rules::Game game;
    const physics::Table& table;
    const physics::Params& params;
};

physics::Vec2 read_vec2(const Field& f);
physics::Vec3 read_vec3(const Field& f);
/// A table: an object of the table's dimensions (docs/cli.md, `table`), checked for balls of
/// `ball_radius`. With `Fields::required` a preset name ("9ft") or an object of overrides of
/// a preset (`"preset"`, default "9ft"); with `Fields::all` every dimension is given.
physics::TableSpec read_table(const Field& f, double ball_radius, Fields fields);
/// The physical parameters, each within its accepted range (docs/cli.md, `params`); with
/// `Fields::required` every one is optional and keeps its default.
physics::Params read_params(const Field& f, Fields fields);
/// The house-rule switches; with `Fields::required` every switch is optional.
rules::Options read_options(const Field& f, Fields fields);
/// A state: with `Fields::all` every field given, with `Fields::required` only `shooter`,
/// `breaker`, `shot`, `on_table` and `cue_ball`; the checks of the `judge` contract (object balls
/// of the game, the 8 (9) on the table, groups and calls only where they can be, a push-out only in
/// 9-ball with the cue ball on the table); and a position for every ball on the table, for the
/// cue ball when it is on the table (a cue ball in hand may have one: placed), none for another
/// ball, all on the playing surface and not overlapping, a cue ball in hand in the kitchen
/// behind the head string (with `Fields::required` a ball on the table may have no position).
/// `finished`: the game is over, so the 8 (9) may be down.
rules::GameState read_state(const Field& f, const TableContext& t, Fields fields,
                            bool finished = false);
/// A verdict (the `judge` output), its fields consistent with each other.
rules::Verdict read_verdict(const Field& f, const TableContext& t);
/// A stroke within the bounds the session accepts.
physics::Stroke read_stroke(const Field& f);
/// An event. With `Fields::all` every field `to_json` writes; with `Fields::required` only
/// `type`, `balls` and a pocket event's `pocket` (an event without `pos` has NaN positions).
/// A field of another type of event is an error. `before`, when given: the state before the
/// shot, whose balls on the table (and the cue ball) are the only ones an event may name.
physics::Event read_event(const Field& f, rules::Game game, Fields fields,
                          const rules::GameState* before = nullptr);
/// A pocket name ("SW" ... "NE").
int read_pocket(const Field& f);

}  // namespace game
