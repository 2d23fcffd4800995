// Ball in hand: where to put the cue ball. Spots are searched, not fixed: behind each pottable
// ball on the line from its pocket, at a few distances and angles (straight in, and cut enough
// to send the cue ball on), or on a grid of the kitchen; ranked by the analytic chance of the
// shot from there. The planner then plays out the best few in full.
#pragma once

#include <vector>

#include "ai/internal/position.hpp"
#include "ai/internal/private.hpp"
#include "physics/vec.hpp"

namespace ai {

/// Up to `count` free spots for the cue ball, the most promising first (different balls and
/// pockets before more of the same). Never empty: with nothing pottable, spots near the legal
/// balls for a safety, and at worst the first free spot of a scan of the table.
std::vector<physics::Vec2> cue_spots(const Position& pos, int count, double sigma_deg);

/// 9-ball: up to `count` free spots (anywhere on the table) from which a combination on the 9
/// is likeliest (the lowest ball sent into the 9, ghost_ball.hpp's `combination_chance`), one
/// per pocket, the best first; none worth less than `min_chance`.
std::vector<physics::Vec2> combination_spots(const Position& pos, int count, double sigma_deg,
                                             double min_chance);

}  // namespace ai
