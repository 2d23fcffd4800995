// Spotting a ball (docs/rules.md, "Spotting"): on the foot spot; if that is occupied, on the
// long string behind it (towards the foot cushion) as close to the spot as possible without
// overlapping a ball.
#pragma once

#include <map>

#include "physics/vec.hpp"
#include "rules/table_size.hpp"

namespace rules {

/// Where a spotted ball goes, given the centres of the balls on the table (unit: m). Touching a
/// ball is allowed, overlapping is not. **Decision:** when the long string behind the spot is
/// full up to the foot cushion, the ball goes in front of the spot (towards the head cushion),
/// again as close to the spot as possible.
physics::Vec2 spot_position(const std::map<int, physics::Vec2>& balls, const TableSize& table);

}  // namespace rules
