// The cue strike: from a stroke to the cue ball's velocity and spin (Alciatore, TP A.30 and A.31).
#pragma once

#include "physics/params.hpp"
#include "physics/stroke.hpp"
#include "physics/vec.hpp"

namespace physics {

struct StrikeResult {
    Vec2 vel;                 ///< cue ball velocity just after the strike (unit: m/s)
    Vec3 spin;                ///< cue ball angular velocity (unit: rad/s)
    bool miscue = false;      ///< the tip offset exceeded miscue_limit
    double squirt_deg = 0.0;  ///< deflection of the cue ball from the stroke line (unit: deg)
};

StrikeResult strike(const Params& params, const Stroke& stroke);

/// The squirt's rate of change with the side offset at a centre hit (TP A.31 at small offsets):
/// a side offset `a` (fraction of R) near 0 sends the cue ball off the stroke line by about
/// `a` times this (unit: rad per unit of offset).
double squirt_per_side_offset(const Params& params);

/// The cue speed that gives a centre-hit cue ball the speed `ball_speed` (inverse of TP A.30).
double cue_speed_for_ball_speed(const Params& params, double ball_speed);

}  // namespace physics
