// Refining a ghost-ball heading with the real physics: throw (the object ball is dragged along
// by the cue ball's slide and spin at contact) and squirt (side spin pushes the cue ball off the
// stroke line) make the ghost-ball heading miss by a little. A few two-ball simulations
// (cue ball and object ball only) correct it by the secant method.
#pragma once

#include <cstdint>
#include <map>
#include <span>

#include "ai/internal/ghost_ball.hpp"
#include "ai/internal/private.hpp"
#include "physics/ball_state.hpp"
#include "physics/params.hpp"
#include "physics/stroke.hpp"
#include "physics/table.hpp"

namespace ai {

/// The heading (unit: deg) that sends the object ball of `aim` along `aim.object_dir` when the
/// cue ball at `cue` and the object ball at `object` are alone on the table and the cue ball is
/// struck with `stroke` (its heading replaced). Adds the simulations it ran to `simulations`.
double refine_heading(const physics::Table& table, const physics::Params& params, physics::Vec2 cue,
                      physics::Vec2 object, const Aim& aim, physics::Stroke stroke, int iterations,
                      std::int64_t& simulations);

/// The cue's elevation (unit: deg, 0 to `max_deg`) at which the object ball of `aim` leaves
/// along the same line whatever small error the side offset of `stroke` has (cue ball and object
/// ball alone, as above; `stroke` without side spin meant, since side spin would curve its path
/// on a raised cue). On a level cue a side error squirts the cue ball off the stroke line; on a
/// raised one the side spin it gives also curves the cue ball back (swerve), the more the higher
/// the cue and the slower and longer the shot, and the spin throws the object ball a little. The
/// secant method finds where they cancel; where they cannot within `max_deg`, `max_deg`. 0 when
/// raising the cue does not help. Adds its simulations.
double compensating_elevation(const physics::Table& table, const physics::Params& params,
                              physics::Vec2 cue, physics::Vec2 object, const Aim& aim,
                              physics::Stroke stroke, double max_deg, std::int64_t& simulations);

/// The same for a kick or a bank on the whole table (`balls` as physics::simulate takes them, the
/// cue ball's id 0): the elevation at which the first object ball the cue ball strikes, after
/// any cushions, leaves in the same direction whatever small error the side offset has. Along a
/// kick's longer path the squirt of that error misses by more, and the swerve of a raised cue
/// has longer to take it back. Adds its simulations.
double kick_compensating_elevation(const physics::Table& table, const physics::Params& params,
                                   std::span<const physics::BallState> balls,
                                   physics::Stroke stroke, double max_deg,
                                   std::int64_t& simulations);

/// The cue's speed (unit: m/s) that gives the ball the same speed as `stroke` when the cue is
/// raised to `elevation_deg`: a raised cue drives the ball into the cloth by sin ε of the
/// impulse, so the cue's speed × cos ε is what the ball keeps. Not bounded.
double speed_for_elevation(const physics::Stroke& stroke, double elevation_deg);

/// `stroke` (on a level cue or not) raised to `elevation_deg` with the ball's speed kept
/// (`speed_for_elevation`, within `min_speed`–`max_speed`) and its heading refined again for the
/// object ball of `aim`.
physics::Stroke raised_stroke(const physics::Table& table, const physics::Params& params,
                              physics::Vec2 cue, physics::Vec2 object, const Aim& aim,
                              physics::Stroke stroke, double elevation_deg, double min_speed,
                              double max_speed, int refine_steps, std::int64_t& simulations);

/// The same for a combination (cue ball, `c.first` and `c.second` alone on the table, where
/// `balls` has them): the heading that sends `c.second` along `c.second.object_dir`.
double refine_combination_heading(const physics::Table& table, const physics::Params& params,
                                  physics::Vec2 cue, const std::map<int, physics::Vec2>& balls,
                                  const Combination& c, physics::Stroke stroke, int iterations,
                                  std::int64_t& simulations);

}  // namespace ai
