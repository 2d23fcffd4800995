// Building blocks of a verdict that 8-ball and 9-ball share: the table after the shot, handing
// the table over, ending the game. Private to the rules module.
#pragma once

#include "rules/fouls.hpp"
#include "rules/game_state.hpp"
#include "rules/shot_facts.hpp"
#include "rules/verdict.hpp"

namespace rules {

/// The state after the shot before anyone decides anything: pocketed and off-table balls
/// removed, the call cleared, the next shot `normal`, the cue ball where it lies (in hand
/// anywhere if it was lost). Shooter, groups and counters as before; positions untouched.
GameState table_after(const GameState& s, const ShotFacts& f);

/// Starts a verdict with the shot's fouls.
Verdict verdict_with(const FoulList& fouls);

/// The shooter keeps the table (`keeps`) or it passes to the opponent, with the cue ball where
/// it lies.
void next_turn(Verdict& v, GameState next, Player shooter, bool keeps);

/// After a foul: the opponent shoots with ball in hand (`where`: anywhere or kitchen).
void ball_in_hand_to_opponent(Verdict& v, GameState next, Player shooter, BallInHand where);

/// A pending choice: `state` is what its first option leads to, `turn_passes` whether the shooter
/// loses the table in that case.
void offer_choice(Verdict& v, GameState next, Choice choice, bool turn_passes, BallInHand where);

/// The game is over: groups stay as they stood before the shot, nothing is spotted.
void end_game(Verdict& v, GameState next, const GameState& before, Player winner);

}  // namespace rules
