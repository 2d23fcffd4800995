// Judging a candidate with the real physics and the rules: simulate the stroke on a copy of the
// table (physics::simulate), judge the events (rules::judge), and value the verdict for the
// shooter (table_value.hpp). Under noise, the same candidate is played with several draws of the
// execution-noise model (game::StrokeNoise at the planned scale); every candidate sees the same
// draws (common random numbers), so their means compare fairly.
#pragma once

#include <cstdint>
#include <optional>
#include <vector>

#include "ai/internal/candidates.hpp"
#include "ai/internal/parallel.hpp"
#include "ai/internal/position.hpp"
#include "ai/internal/private.hpp"
#include "physics/stroke.hpp"

namespace ai {

/// One draw of the execution noise: a standard normal deviate per stroke component.
struct NoiseDraw {
    double heading = 0.0, elevation = 0.0, speed = 0.0, side = 0.0, top = 0.0;
};

/// `n` draws from `seed` (the AI's own; it never sees the game's stream): quasi-random
/// (quasi_random.hpp), so that every run of the first k draws covers the normal distribution of
/// each component evenly.
std::vector<NoiseDraw> noise_draws(std::uint64_t seed, int n);

/// The stroke with the draw's errors at `scale` × the standard σ (game/stroke_noise.hpp), kept
/// within the bounds of a stroke, as the game does.
physics::Stroke with_draw(const physics::Stroke& stroke, const NoiseDraw& draw, double scale);

/// One simulated play of a candidate.
struct Trial {
    double value = 0.0;    ///< what the outcome is worth to the shooter (0 lost … 1 won)
    double shallow = 0.0;  ///< the same, one ply deep (= value unless valued by lookahead.hpp)
    bool success = false;  ///< pots: the shooter stays at the table (or wins); safeties: no foul
    bool stays = false;    ///< the shooter stays at the table or wins, whatever the stroke's kind
    bool foul = false;
    std::int64_t simulations = 1;  ///< physics simulations this trial ran (the second ply's too)
    /// Evaluator::nominal with `with_leave` only: the ball of the shooter's likeliest next pot
    /// where the balls stop, when he stays at the table with the cue ball on it; else −1.
    int leave = -1;
};

/// The mean of a candidate's trials.
struct Score {
    double value = 0.0;  ///< the one-ply mean, plus the mean deep correction once valued deeper
    double success = 0.0;
    int samples = 0;        ///< one-ply draws
    bool foul = false;      ///< the noiseless stroke fouls
    int leave = -1;         ///< the noiseless stroke's Trial::leave
    bool stays = false;     ///< the noiseless stroke's Trial::stays
    double deep_sum = 0.0;  ///< score_deep: the sum of the two- less the one-ply values
    int deep_draws = 0;     ///< score_deep: the draws of that sum
};

class Evaluator {
  public:
    /// `scale`: the execution noise the shooter plans for; `sigma_deg`: the heading σ of the
    /// shot model used to value the positions left; `stuck_cost`: what each stuck ball of the
    /// player at the table takes off its value (table_value.hpp's `position_value`).
    Evaluator(const Position& pos, double scale, double sigma_deg, double stuck_cost = 0.0)
        : pos_(pos), scale_(scale), sigma_deg_(sigma_deg), stuck_cost_(stuck_cost) {}

    /// Plays the candidate without noise; a kick gets its call from what it pockets. With
    /// `with_leave`, the trial's `leave` is found too.
    Trial nominal(Candidate& c, bool with_leave = false) const;
    /// Plays the candidate with one noise draw.
    Trial trial(const Candidate& c, const NoiseDraw& draw) const;
    /// Plays the candidate with one noise draw (none at scale 0) and, where the shooter stays at
    /// the table, values the table two plies deep (lookahead.hpp) with `effort`'s second ply.
    Trial deep_trial(const Candidate& c, const NoiseDraw& draw, const Effort& effort) const;
    /// Plays the candidate without noise, as `nominal` (its call kept), and where the shooter
    /// stays at the table with no choice pending sets `after` to the state he comes back to.
    Trial nominal_to(const Candidate& c, std::optional<rules::GameState>& after) const;

    double scale() const { return scale_; }
    /// The position its candidates are played from.
    const Position& position() const { return pos_; }

  private:
    Trial play(const Candidate& c, const physics::Stroke& stroke, bool assign_call,
               rules::Call* call, const Effort* deeper = nullptr, bool with_leave = false,
               std::optional<rules::GameState>* after = nullptr) const;

    const Position& pos_;
    double scale_;
    double sigma_deg_;
    double stuck_cost_;
};

/// Scores each candidate of `which` in `candidates` with the draws [first, first + count),
/// adding to `scores` (running means); `workers` threads (and pause hook). Returns the simulations
/// run.
std::int64_t score_under_noise(const Evaluator& eval, const std::vector<Candidate>& candidates,
                               const std::vector<std::size_t>& which,
                               const std::vector<NoiseDraw>& draws, std::size_t first,
                               std::size_t count, std::vector<Score>& scores, Workers workers);

/// Scores each candidate of `which` two plies deep (Evaluator::deep_trial) with the draws
/// [first, first + count), which `scores` must already hold one ply deep: each score's value is
/// its one-ply mean moved by the mean difference between its two- and one-ply values on the
/// draws valued deeper so far (a control variate: the outcome the two share cancels, and the
/// difference is far less noisy than either). A draw beyond the score's one-ply draws adds its
/// one-ply value to the one-ply mean too. `workers` threads (and pause hook). Returns the
/// simulations run.
std::int64_t score_deep(const Evaluator& eval, const std::vector<Candidate>& candidates,
                        const std::vector<std::size_t>& which, const std::vector<NoiseDraw>& draws,
                        std::size_t first, std::size_t count, const Effort& effort,
                        std::vector<Score>& scores, Workers workers);

}  // namespace ai
