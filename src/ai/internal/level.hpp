// The five levels of the computer opponent: how hard it searches and how well it strokes.
// Level 1 is a beginner (4× the execution noise, a small search), level 5 the strongest (1×, the
// largest search that fits about a second per decision on two cores). The values of every level,
// per game, are one table in level.cpp; docs/ai.md gives each level's measured strength.
#pragma once

#include "ai/ai.hpp"
#include "ai/internal/private.hpp"
#include "rules/game_state.hpp"

namespace ai {

/// Search effort of one level, its knobs in the order the planner uses them (planner.hpp).
/// Counts are per decision unless stated. A default Effort searches nothing: the levels' values
/// are all in level.cpp's table.
struct Effort {
    // The candidates.
    int pot_pairs = 0;     ///< (ball, pocket) pairs tried, the easiest first
    int speeds = 0;        ///< speeds per aim
    int spins = 0;         ///< spins per aim (stun, follow, draw, then side)
    int refine_steps = 0;  ///< secant steps of the heading refinement (aim.hpp) per pot
    /// Pots under noise: the cue raised up to this so that the swerve of a side-offset error
    /// cancels its squirt (aim.hpp's `compensating_elevation`); 0: a level cue. Pinned by
    /// raised_cue_test.cpp (unit: deg).
    double max_raise_deg = 0.0;
    int safety_speeds = 0;    ///< speeds per safety contact
    int safety_contacts = 0;  ///< contact points across each legal ball for safeties
    int placements = 0;       ///< ball-in-hand spots searched in full
    /// 9-ball: combinations on the 9 (the lowest ball sent into it, the 9 into a pocket) tried,
    /// the likeliest first, each at a few speeds and spins (candidates.hpp), with ball in hand
    /// from a spot found for them too (placement.hpp). combination_test.cpp.
    int combinations = 0;
    int sweep_headings = 0;  ///< headings of the kick/bank sweep (only when nothing is simpler)
    /// Of the sweep's kicks and banks that pot without noise, the best few moved to the middle
    /// of their window of headings, at their speed and a little slower and faster
    /// (heading_window.hpp); 0: none.
    int centred_kicks = 0;
    int break_samples = 0;  ///< noisy simulations per break candidate
    /// 9-ball: breaks among the few tuned offline (candidates.hpp's `tuned_breaks`) rather than
    /// the broad set (in 8-ball the tuned ones scratch more and clear no more racks).
    /// break_test.cpp.
    bool tuned_breaks = false;

    // The rounds under noise.
    int shortlist = 0;  ///< candidates evaluated under noise, the best nominal ones
    int samples = 0;    ///< noisy simulations per shortlisted candidate
    /// The best few get `finalist_rounds` × `samples` more draws; 1 or less: no finalist round.
    int finalists = 0;
    /// How many times `samples` more draws the finalists get: more rounds let the choice among
    /// near-sure pots rest on more draws (deep_search_test.cpp's FinalistDraws).
    int finalist_rounds = 0;
    /// Under noise, the shortlist's pots (and the finer search's) that pot without noise turned
    /// to the middle of their window of headings before the noisy rounds (heading_window.hpp).
    bool centred_pots = false;
    int polish = 0;  ///< the best few pots after the noisy rounds, searched around finer
    /// 8-ball: of the shortlist, the finalists and the deep finalists, up to this share goes
    /// first to the best stroke of each distinct leave (the ball of the next pot it leaves,
    /// played without noise; selection.hpp), so that strokes leaving another ball than the
    /// easiest reach the second ply too.
    double distinct_leaves = 0.0;

    // The deep search: the best few valued two plies deep (lookahead.hpp).
    int deep_finalists = 0;  ///< how many are valued two plies deep
    int deep_samples = 0;    ///< noisy plays per deep finalist, each valued by lookahead.hpp
    /// Rounds of the deep search after the first that keep the better half of the deep
    /// finalists only (0: one round, every deep finalist played with `deep_samples` draws).
    /// With h of them: every deep finalist gets `deep_samples` / 2 draws, then the better half
    /// more up to `deep_samples`, and each later round the better half again twice the draws
    /// so far. Two halvings play as many deep trials as one round and give the best quarter
    /// twice the draws (`deepest_draws`; deep_search_test.cpp's DeepHalvings).
    int deep_halvings = 0;
    /// 9-ball: the deep search plays noise draws of its own, after those of the one-ply rounds,
    /// rather than those again: a finalist reached the deep search by its luck on the one-ply
    /// draws, and the same draws would carry that luck into its deep value (deep_search_test.cpp).
    bool fresh_deep_draws = false;
    int next_pairs = 0;   ///< second ply: (ball, pocket) pairs tried
    int next_speeds = 0;  ///< second ply: speeds per aim
    int next_spins = 0;   ///< second ply: spins per aim
    /// The second ply played out: how many of the shooter's next shots it follows, each the
    /// best of its pots by the one-ply value, without noise (1: the next shot only).
    /// lookahead_test.cpp's PlayOut.
    int playout_shots = 0;

    // The value of a table (table_value.hpp, ghost_ball.hpp).
    /// The heading σ at 1× that the shot model (ghost_ball.hpp's `aim_chance`: the chance of
    /// the next pots, which values the table a stroke leaves) assumes where it is below the
    /// cue's own (`heading_sigma_deg`: 0.21° with the squirt of a side-offset error); 0: the
    /// cue's own. A raised cue centred in its window pots as the model does at a smaller σ than
    /// the cue's own (`shot_calibration`; model_sigma_test.cpp) (unit: deg).
    double model_sigma_deg = 0.0;
    /// 8-ball: what each ball that the player at the table must still pocket, but that has no
    /// clear path to any pocket from where it lies, takes off the value of his table
    /// (table_value.hpp's `stuck_balls`; stuck_balls_test.cpp) (unit: chance of winning).
    double stuck_ball_cost = 0.0;

    friend bool operator==(const Effort&, const Effort&) = default;
};

/// The effort of `level` (clamped to 1–5) in a game of `game`. `rack_end`: the shooter is near
/// the end of an 8-ball rack (table_value.hpp's `near_rack_end`), where level 5 searches wider;
/// 9-ball has no such variant and ignores it. rack_end_test.cpp, level_test.cpp.
Effort effort_for(rules::Game game, int level, bool rack_end = false);

/// The multiple of the game's execution noise a player of `level` (clamped to 1–5) strokes with:
/// 4× at level 1 … 1× at level 5, the same in both games.
double noise_multiplier(int level);

/// The most noise draws a deep finalist of `effort` gets (`Effort::deep_halvings`).
int deepest_draws(const Effort& effort);

/// The noise draws a decision of `effort` needs: those of the one-ply rounds (the shortlist's
/// and the finalists', or the breaks'), and the deep search's, after them where it has draws
/// of its own (`Effort::fresh_deep_draws`), else among them.
int draw_pool(const Effort& effort);

}  // namespace ai
