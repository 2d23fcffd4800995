// The stroke a real cue can play: near a rail (or with its butt over the far rail) the cue
// can't lie flat, so the stroke is played at least at the elevation the rail forces. The
// geometry (the cue's taper over the cushion's and rail's profile) is the drawn cue's,
// render::rail_forced_elevation, so the cue drawn, the aim guide and the shot played agree.
#pragma once

#include "physics/stroke.hpp"
#include "physics/table.hpp"
#include "physics/vec.hpp"

namespace app {

/// The least elevation the rail allows for `stroke` from `cue_ball` (unit: deg; 0 when the
/// cue can lie flat), with the tip at the stroke's spin offset.
double rail_forced_elevation_deg(const physics::Table& table, double ball_radius,
                                 physics::Vec2 cue_ball, const physics::Stroke& stroke);

/// `stroke` with its elevation raised to the rail's where the rail forces it.
physics::Stroke over_the_rail(const physics::Table& table, double ball_radius,
                              physics::Vec2 cue_ball, physics::Stroke stroke);

}  // namespace app
