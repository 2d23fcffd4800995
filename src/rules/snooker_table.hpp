// The geometry the snooker rules ask about: re-spotting colours (WPBSA S3 'Spotting Colours'),
// whether the cue ball is snookered (S2 definitions) or has a clear path to a ball on (S3 R14), and
// a touching ball (S3 'Touching Ball'). Private to the rules module.
#pragma once

#include <map>
#include <optional>
#include <set>
#include <span>
#include <vector>

#include "physics/event.hpp"
#include "rules/snooker.hpp"

namespace rules {

using Positions = std::map<int, physics::Vec2>;

/// The start positions moved to each ball's last position in the events.
Positions last_positions(const Positions& before, std::span<const physics::Event> events);

/// Puts the colours back (highest value first), each on its own spot if free, else on the
/// highest-value free spot, else as near its own spot as possible toward the top cushion
/// (pink and black: toward the baulk cushion when there is no room toward the top).
/// `positions` gains them.
std::vector<Respot> respot_colours(std::vector<int> colours, Positions& positions,
                                   const SnookerTable& table);

/// Whether the cue ball can hit the ball `target` in a straight line at the edge given by
/// `side` (−1, +1; 0 the full ball, fractions between) unobstructed by the balls not in `on`.
bool can_hit(const Positions& pos, int target, double side, const std::set<int>& on, double R);
/// Snookered: no ball on can be hit at both extreme edges (S2 definitions).
bool is_snookered(const Positions& pos, const std::set<int>& on, double R);
/// A clear path: some part of some ball on can be hit in a straight line (S3 R14).
bool has_clear_path(const Positions& pos, const std::set<int>& on, double R);
/// The ball the cue ball rests against, if any (within 1 µm of touching).
std::optional<int> touching_ball(const Positions& pos, double R);

}  // namespace rules
