// Reading the physics parts of an input document (tables, models, balls, racks, strokes) with
// the checks of docs/cli.md: every bad value throws BadInput naming its JSON path. Parameters
// are game::read_params (game/state_json.hpp), shared with the saved games.
#pragma once

#include <vector>

#include "cli/json_in.hpp"
#include "physics/ball_state.hpp"
#include "physics/params.hpp"
#include "physics/stroke.hpp"
#include "physics/table.hpp"

namespace cli {

/// Sanity bounds on input values: far outside anything physical, they keep every number the
/// engine computes finite (docs/cli.md lists them).
namespace limits {
inline constexpr double max_coordinate = 1000.0;  ///< |x|, |y| of a ball (unit: m)
inline constexpr double max_ball_speed = 100.0;   ///< |vel| of a ball (unit: m/s)
inline constexpr double max_ball_spin = 10000.0;  ///< |spin| of a ball (unit: rad/s)
inline constexpr double max_cue_speed = 20.0;     ///< strike speed (unit: m/s)
}  // namespace limits

/// `table` (game::read_table with the CLI's optional fields): a preset name ("7ft", "8ft",
/// "9ft", "snooker12ft", "carom10ft", "unbounded") or an object {"preset": "9ft", "length": ...,
/// ...}; validated for a ball of radius `ball_radius`.
physics::TableSpec read_table(const JsonIn& in, double ball_radius);

/// `params`: a ball set ("pool", "snooker", "carom"), or an object of overrides of `base`
/// (or of the set its "preset" names).
physics::Params read_params(const JsonIn& in, const physics::Params& base);

/// `models`: {"ball_ball": "frictional" | "frictionless", "cushion": "han2005" | "simple"}.
physics::Models read_models(const JsonIn& in);

/// `balls`: [{"id": 0, "pos": [x, y], "vel": [vx, vy], "spin": [wx, wy, wz]}, ...], with
/// unique ids 0–21, checked against the table (physics::validate_layout): no overlaps, every
/// centre on the playing surface. Motion states are set from velocity and spin.
std::vector<physics::BallState> read_balls(const JsonIn& in, const physics::Table& table,
                                           const physics::Params& params);

/// `rack`: {"game": "8ball" | "9ball" | "snooker" | "three_cushion", "seed": 7,
/// "cue_pos": [x, y]} → the racked balls (physics::rack).
std::vector<physics::BallState> read_rack(const JsonIn& in, const physics::Table& table,
                                          const physics::Params& params);

/// `strike`: {"speed", "heading_deg", "side", "top", "elevation_deg", "ball"} (speed required;
/// `ball`, the struck ball, default 0).
physics::Stroke read_stroke(const JsonIn& in);

}  // namespace cli
