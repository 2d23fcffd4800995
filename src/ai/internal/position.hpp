// What the planner reads from a position (ai.hpp's Position): the balls the shooter wants, the
// legal first contacts, the layout to simulate, and the free spots for a cue ball in hand.
#pragma once

#include <optional>
#include <vector>

#include "ai/ai.hpp"
#include "ai/internal/private.hpp"
#include "physics/ball_state.hpp"
#include "rules/game_state.hpp"

namespace ai {

/// The object balls the shooter of `s` wants to pocket next (8-ball: his group, any but the 8 on
/// an open table, the 8 once his group is cleared; 9-ball: the lowest ball).
std::vector<int> target_balls(const rules::Ruleset& rules, const rules::GameState& s);

/// 9-ball: the ball a combination on the 9 starts from (the lowest ball, while the 9 is on the
/// table and is not the lowest); empty in 8-ball.
std::optional<int> combination_first_ball(const rules::Ruleset& rules, const rules::GameState& s);

/// Whether the cue ball may hit `ball` first (the legal first contacts of `s`).
bool legal_first(const rules::Ruleset& rules, const rules::GameState& s, int ball);

/// The balls at rest for physics::simulate: the cue ball at `cue` and every object ball.
std::vector<physics::BallState> layout(const rules::GameState& s, physics::Vec2 cue);

/// Whether `p` is a free spot for the cue ball in hand in `s` (on the surface, no overlap, in the
/// kitchen when the ball in hand is in the kitchen).
bool free_spot(const Position& pos, physics::Vec2 p);

}  // namespace ai
