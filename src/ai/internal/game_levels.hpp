// The search effort of the snooker and three-cushion players per level (game_levels.cpp holds
// the table). The execution noise per level is the pool player's (level.hpp's
// `noise_multiplier`): 4× at level 1 … 1× at level 5.
#pragma once

#include "ai/internal/private.hpp"

namespace ai {

struct SnookerEffort {
    int pot_pairs = 0;        ///< (ball, pocket) pairs tried, the likeliest first
    int speeds = 0;           ///< speeds per pot
    int spins = 0;            ///< spins per pot (stun, follow, draw, then side)
    int refine_steps = 0;     ///< secant steps of the heading refinement per pot
    int safety_balls = 0;     ///< balls on tried for safeties, the nearest first
    int safety_contacts = 0;  ///< contacts from thin to full (both sides) per ball
    int safety_speeds = 0;    ///< speeds per safety contact
    int sweep_headings = 0;   ///< headings of the escape sweep (when snookered or nothing works)
    int placements = 0;       ///< spots in the D played out with a ball in hand
    int shortlist = 0;        ///< candidates played under noise, the best nominal ones
    int samples = 0;          ///< noise draws per shortlisted candidate
    int finalists = 0;        ///< the best few get `samples` more draws
    int deep_finalists = 0;   ///< the best few then valued two plies deep (0: none)
    int deep_samples = 0;     ///< noise draws of each deep finalist
    int next_pairs = 0;       ///< second ply: (ball, pocket) pairs tried
    int next_speeds = 0;      ///< second ply: speeds per pot
    int next_spins = 0;       ///< second ply: spins per pot
    double model_sigma_deg = 0.0;  ///< the shot model's heading σ at 1×; 0: the cue's own
};

struct CaromEffort {
    int headings = 0;   ///< headings of the sweep, all round
    int speeds = 0;     ///< speeds per heading
    int spins = 0;      ///< spins per heading (side with follow, then centre, then draw)
    int shortlist = 0;  ///< strokes that score without noise played under noise
    /// The shortlist's strokes moved to the middle of their window of scoring headings, found
    /// on a sweep this many times finer around each; 0: the sweep's run's middle.
    int centring = 0;
    int samples = 0;  ///< noise draws per shortlisted stroke
    /// The best few by their chance under noise valued by the position they leave (a coarse
    /// sweep from where the balls stop after the noiseless point); 0: not valued.
    int leave_checked = 0;
    int leave_headings = 0;  ///< headings of that coarse sweep (at two speeds and two spins)
};

/// The effort of `level` (clamped to 1–5).
SnookerEffort snooker_effort(int level);
CaromEffort carom_effort(int level);

}  // namespace ai
