// What the AI decides from: the rules, the table, the physics and the game's state before the
// shot (with every ball's position), plus a pending choice of the rules, if any. Built from a
// game::Session, or directly (the CLI's `decide`).
#pragma once

#include <optional>
#include <vector>

#include "physics/ball_state.hpp"
#include "physics/params.hpp"
#include "physics/table.hpp"
#include "rules/game_state.hpp"
#include "rules/judge.hpp"
#include "rules/verdict.hpp"

namespace game {
class Session;
}

namespace ai {

struct Position {
    rules::Ruleset ruleset;
    physics::Table table;
    physics::Params params;
    /// The state before the shot; with a pending choice, the table as it lies (what the first
    /// option leads to). Positions of every object ball on the table, and of the cue ball when it
    /// is on the table (a cue ball in hand is placed by the AI).
    rules::GameState state;
    std::optional<rules::Choice> choice;  ///< a choice pending for the player to act
};

Position position_of(const game::Session& session);

/// Whether the cue ball is to be placed (ball in hand) rather than played from where it lies.
bool cue_in_hand(const rules::GameState& s);

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
