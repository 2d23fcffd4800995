// The second ply: what a table is worth to the player who stays at it, found by playing his best
// few next pots without noise and valuing what each leaves (table_value.hpp, one ply further),
// weighted by each pot's analytic chance (ghost_ball.hpp). For the finalists of a decision it
// corrects the one-shot estimate T(q) of table_value.hpp (by the mean difference on the same
// draws: evaluate.hpp's score_deep): a shot that leaves an easy pot with no way on to the ball
// after is worth less than one that leaves a route. With `Effort::playout_shots` > 1 the second
// ply is played out: the best next pot, played without noise, leaves a table valued the same
// way again, for up to that many shots, so an easy pot that leads into a dead end a shot later
// is seen as one.
#pragma once

#include <cstdint>

#include "ai/internal/level.hpp"
#include "ai/internal/position.hpp"
#include "ai/internal/private.hpp"
#include "rules/game_state.hpp"

namespace ai {

/// What a missed next pot is worth to the player who missed it: the opponent comes to a table
/// with something on (1 − T(q) for a middling q).
inline constexpr double next_miss_value = 0.25;

/// The value of `s` (cue ball on the table, the shooter of `s` to play) for its shooter: the best
/// of his next pots, each played once without noise by the rules and valued one ply further,
/// times its chance, plus the chance of missing times `next_miss_value`; at least the value of a
/// table with nothing on (he can play safe). `effort`'s pot pairs, speeds and spins are the ones
/// of the second ply (`Effort::next_*`). With `effort.playout_shots` = n > 1 the best pot's own
/// value is that of the table it leaves over n − 1 more shots, found the same way (each further
/// shot the best by the one-ply value). Adds the simulations it runs to `simulations`.
double next_turn_value(const Position& base, const rules::GameState& s, const Effort& effort,
                       double scale, double sigma_deg, std::int64_t& simulations);

}  // namespace ai
