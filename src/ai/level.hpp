// The five levels of the computer opponent: how hard it searches and how well it strokes.
// Level 1 is a beginner (4× the execution noise, a small search), level 5 the strongest (1×, the
// largest search that fits about a second per decision on two cores). docs/ai.md.
#pragma once

#include "rules/game_state.hpp"

namespace ai {

inline constexpr int min_level = 1;
inline constexpr int max_level = 5;

/// Search effort of one level. Counts are per decision unless stated.
struct Effort {
    double noise_multiplier =
        1.0;                  ///< the player's own execution noise, × the game's scale (unit: 1)
    int pot_pairs = 6;        ///< (ball, pocket) pairs tried, the easiest first
    int speeds = 3;           ///< speeds per aim
    int spins = 3;            ///< spins per aim (follow, stun, draw, then side)
    int safety_speeds = 3;    ///< speeds per safety contact
    int safety_contacts = 5;  ///< contact points across each legal ball for safeties
    int sweep_headings = 72;  ///< headings of the kick/bank sweep (only when nothing is simpler)
    /// Of the sweep's kicks and banks that pot without noise, the best few moved to the middle
    /// of their window of headings, at their speed and a little slower and faster
    /// (heading_window.hpp); 0: none.
    int centred_kicks = 0;
    int shortlist = 12;  ///< candidates evaluated under noise, the best nominal ones
    int samples = 12;    ///< noisy simulations per shortlisted candidate
    int finalists = 3;   ///< the best few get `finalist_rounds` × `samples` more
    /// How many times `samples` more draws the finalists get (8-ball, level 5: 3, so that the
    /// choice among near-sure pots rests on 160 draws rather than 80; docs/ai.md, stop 37).
    int finalist_rounds = 1;
    int placements = 3;     ///< ball-in-hand spots searched in full
    int break_samples = 6;  ///< noisy simulations per break candidate
    int polish = 0;         ///< the best few pots after the noisy rounds, searched around finer
    /// Under noise, the shortlist's pots (and the finer search's) that pot without noise turned
    /// to the middle of their window of headings before the noisy rounds (heading_window.hpp).
    bool centred_pots = false;
    int deep_finalists = 0;  ///< the best few after the noisy rounds, valued two plies deep
    /// Noisy plays per deep finalist, each valued by lookahead.hpp (8-ball, level 5: 32, 64 at
    /// the rack's end; docs/ai.md, "Twice the deep draws in 8-ball", stop 38).
    int deep_samples = 0;
    /// Rounds of the deep search after the first that keep the better half of the deep
    /// finalists only (0: one round, every deep finalist played with `deep_samples` draws).
    /// With h of them: every deep finalist gets `deep_samples` / 2 draws, then the better half
    /// more up to `deep_samples`, and each later round the better half again twice the draws
    /// so far. Two halvings play as many deep trials as one round and give the best quarter
    /// twice the draws (`deepest_draws`).
    int deep_halvings = 0;
    int next_pairs = 3;   ///< second ply: (ball, pocket) pairs tried
    int next_speeds = 3;  ///< second ply: speeds per aim
    int next_spins = 3;   ///< second ply: spins per aim
    /// The second ply played out: how many of the shooter's next shots it follows, each the
    /// best of its pots by the one-ply value, without noise (1: the next shot only). Level 5
    /// follows 4 in 8-ball; 9-ball keeps 1 (`nine_ball_effort`; docs/ai.md, stops 24 and 25).
    int playout_shots = 1;
    int refine_steps = 2;  ///< secant steps of the heading refinement (aim.hpp) per pot
    /// Pots under noise: the cue raised up to this so that the swerve of a side-offset error
    /// cancels its squirt (aim.hpp's `compensating_elevation`); 0: a level cue (unit: deg).
    double max_raise_deg = 0.0;
    /// The heading σ at 1× that the shot model (ghost_ball.hpp's `aim_chance`: the chance of
    /// the next pots, which values the table a stroke leaves) assumes where it is below the
    /// cue's own (`heading_sigma_deg`: 0.21° with the squirt of a side-offset error); 0: the
    /// cue's own. Level 5 raises its cue against the squirt and centres its pots in their
    /// window, and the engine pots its raised strokes as the model does at about 0.12°
    /// (`shot_calibration`, maximum likelihood), those with side spin meant at about 0.25°: it
    /// assumes 0.14° (docs/ai.md, stop 40) (unit: deg).
    double model_sigma_deg = 0.0;
    /// 8-ball: of the shortlist, the finalists and the deep finalists, up to this share goes
    /// first to the best stroke of each distinct leave (the ball of the next pot it leaves,
    /// played without noise; selection.hpp), so that strokes leaving another ball than the
    /// easiest reach the second ply too.
    double distinct_leaves = 0.0;
    /// 8-ball: what each ball that the player at the table must still pocket, but that has no
    /// clear path to any pocket from where it lies, takes off the value of his table
    /// (table_value.hpp's `stuck_balls`) (unit: chance of winning).
    double stuck_ball_cost = 0.0;
    /// 9-ball: combinations on the 9 (the lowest ball sent into it, the 9 into a pocket) tried,
    /// the likeliest first, each at a few speeds and spins (candidates.hpp), with ball in hand
    /// from a spot found for them too (placement.hpp).
    int combinations = 0;
    /// 9-ball: breaks among the few tuned offline (candidates.hpp's `tuned_breaks`) rather than
    /// the broad set (in 8-ball they scratched more and cleared no more racks: docs/ai.md).
    bool tuned_breaks = false;
    /// 9-ball: the deep search plays noise draws of its own, after those of the one-ply rounds,
    /// rather than those again: a finalist reached the deep search by its luck on the one-ply
    /// draws, and the same draws would carry that luck into its deep value (docs/ai.md, stop 23;
    /// in 8-ball not shown to help).
    bool fresh_deep_draws = false;
};

/// The effort of `level` (clamped to 1–5).
Effort effort_for_level(int level);

/// The most noise draws a deep finalist of `effort` gets (`Effort::deep_halvings`).
int deepest_draws(const Effort& effort);

/// The noise draws a decision of `effort` needs: those of the one-ply rounds (the shortlist's
/// and the finalists', or the breaks'), and the deep search's, after them where it has draws
/// of its own (`Effort::fresh_deep_draws`), else among them.
int draw_pool(const Effort& effort);

/// The effort of `level` near the end of an 8-ball rack (table_value.hpp's `near_rack_end`; the
/// planner uses it in 8-ball only): level 5 searches wider there (twice the shortlist, half as
/// many finalists and polished pots again, 12 deep finalists of 64 draws), where the shooter's
/// last few balls decide the rack and a decision has fewer candidates; other levels as elsewhere.
Effort rack_end_effort(int level);

/// The effort of `level` in 9-ball (the planner's choice for every 9-ball decision): level 5
/// searches deeper there (8 pots searched finer instead of 4; 32 deep finalists instead of 8,
/// in two halvings: 32 draws each, 32 more for the better 16, 64 more for the best 8), where
/// each decision has few candidates (one target ball) and the second ply decides, but does not
/// play the second ply out (2 shots gained no more than noise there, for twice the time), and
/// its finalists get one round of draws more, not 8-ball's three; other levels as elsewhere.
/// docs/ai.md, stops 19, 20, 22 and 25.
Effort nine_ball_effort(int level);

/// `effort` for a game of `game`: the 8-ball-only parts (distinct leaves, the stuck-ball cost,
/// the finalists' extra rounds of draws) set to 0 (1) in 9-ball, where the next ball is always
/// the lowest; the 9-ball-only parts
/// (combinations on the 9, the tuned breaks, the deep search's own draws) off in 8-ball.
Effort for_game(Effort effort, rules::Game game);

}  // namespace ai
