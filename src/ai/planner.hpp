// The AI's decision in one position (the `decide` verb of docs/cli.md):
//
//   choice pending ─▶ the option worth most (table_value.hpp)
//   break          ─▶ break candidates, each played with noise draws (9-ball, level 5: the tuned)
//   else           ─▶ cue spots (ball in hand: placement.hpp) ─▶ pots + safeties per spot
//                     (9-ball, level 5: + combinations on the 9, with spots of their own)
//                     ─▶ noiseless play of each (the shortlist) ─▶ kicks if nothing is legal or
//                     good ─▶ shortlist × noise draws ─▶ finalists × more draws ─▶ the best mean ─▶
//                     9-ball: a push-out instead, when that is worth more
//
// Reproducible: the same position, settings and seed give the same decision, bit for bit,
// whatever the threads' timing.
#pragma once

#include <cstdint>

#include "ai/candidates.hpp"
#include "ai/level.hpp"
#include "ai/position.hpp"
#include "game/player.hpp"

namespace ai {

struct PlanSettings {
    int level = 5;       ///< 1 (beginner) to 5 (strongest)
    double noise = 1.0;  ///< the game's execution-noise scale (the level's multiplier comes on top)
    int workers = 2;     ///< threads that share the simulations
};

struct Plan {
    game::Decision decision;
    double expected_success = 0.0;  ///< pots: chance to stay at the table; safeties: of no foul
    double expected_value = 0.0;    ///< the planner's value of the stroke (a rough chance to win)
    std::int64_t simulations = 0;   ///< physics simulations run for this decision
    Kind kind = Kind::pot;          ///< what sort of stroke it is (a choice: Kind::pot, unused)
};

Plan plan(const Position& pos, const PlanSettings& settings, std::uint64_t seed);

/// The execution-noise scale a player of `settings` strokes with: noise × the level's multiplier.
double planned_scale(const PlanSettings& settings);

/// The heading σ (deg) the shot model assumes for a player of `effort` who strokes with noise
/// scale `scale`: the cue's own (`heading_sigma_deg`), or `Effort::model_sigma_deg` where that
/// is smaller, × `scale`.
double model_sigma_deg(const physics::Params& params, const Effort& effort, double scale);

}  // namespace ai
