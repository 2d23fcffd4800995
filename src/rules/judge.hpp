// The rules' entry point: a game's state before a shot + the shot's events → the verdict.
// A pure function: nothing but its arguments goes in, nothing but the verdict comes out.
//
//   events ──distill──▶ ShotFacts ──fouls (predicates)──▶ FoulList
//                                   └─ judge_eight_ball / judge_nine_ball ─▶ Verdict
//   Verdict.state.positions: the start positions, moved to each ball's last event position,
//   balls off the table and a cue ball in hand removed, spotted balls placed.
#pragma once

#include <span>

#include "physics/event.hpp"
#include "rules/game_state.hpp"
#include "rules/options.hpp"
#include "rules/table_size.hpp"
#include "rules/verdict.hpp"

namespace rules {

/// What a game is played by: the game, its house rules, and the table's size.
struct Ruleset {
    Game game = Game::eight_ball;
    Options options;  ///< 8-ball switches; 9-ball ignores them
    TableSize table;
};

/// Judges one shot. `s` must be consistent (the CLI checks it: events only on balls on the
/// table, a call only of a ball on the table, a push-out only in 9-ball right after the break).
Verdict judge(const Ruleset& rules, const GameState& s, std::span<const physics::Event> events);

/// What taking one option of a pending choice leads to.
struct Resolution {
    GameState state;  ///< the state before the next shot
    /// The balls are racked again: `state` is initial_state() for the new breaker (counters
    /// carried over) and has no positions; the session racks and places them.
    bool rerack = false;
    BallInHand ball_in_hand = BallInHand::none;  ///< for the next shooter
};

/// Applies the option `option` of the verdict's pending choice. Throws std::invalid_argument
/// when no choice is pending or the option is not offered.
Resolution resolve_choice(const Ruleset& rules, const Verdict& v, ChoiceOption option);

/// A stalemate (neither player can make progress): re-rack, the original breaker breaks.
Resolution stalemate(const Ruleset& rules, const GameState& s);

}  // namespace rules
