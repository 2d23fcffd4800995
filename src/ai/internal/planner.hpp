// How the AI decides in one position (ai.hpp's `plan`; the `decide` verb of docs/cli.md):
//
//   choice pending ─▶ the option worth most (table_value.hpp)
//   break          ─▶ break candidates, each played with noise draws (9-ball, level 5: the tuned)
//   else           ─▶ cue spots (ball in hand: placement.hpp) ─▶ pots + safeties per spot
//                     (9-ball, level 5: + combinations on the 9, with spots of their own)
//                     ─▶ noiseless play of each (the shortlist) ─▶ kicks if nothing is legal or
//                     good ─▶ shortlist × noise draws ─▶ finalists × more draws ─▶ the best pots
//                     searched around finer ─▶ the best few valued two plies deep (lookahead.hpp)
//                     ─▶ the best mean ─▶ 9-ball: a push-out instead, when that is worth more
//
// How much of each the level searches: level.hpp's Effort, one table in level.cpp.
#pragma once

#include "ai/ai.hpp"
#include "ai/internal/level.hpp"
#include "ai/internal/private.hpp"
#include "physics/params.hpp"

namespace ai {

/// The heading σ (deg) the shot model assumes for a player of `effort` who strokes with noise
/// scale `scale`: the cue's own (`heading_sigma_deg`), or `Effort::model_sigma_deg` where that
/// is smaller, × `scale`.
double model_sigma_deg(const physics::Params& params, const Effort& effort, double scale);

}  // namespace ai
