// The snooker player's steps (snooker_planner.cpp puts them together): the balls the striker may
// play, the value of a table to the player at it, the candidates (pots with position, safeties,
// escapes from snookers, spots in the D) and their trials with the real physics and rules.
#pragma once

#include <cstdint>
#include <map>
#include <optional>
#include <vector>

#include "ai/games.hpp"
#include "ai/internal/evaluate.hpp"
#include "ai/internal/game_levels.hpp"
#include "ai/internal/private.hpp"
#include "physics/ball_state.hpp"

namespace ai {

/// What a frame's end is worth beyond its points, in points: winning it is worth more than
/// any break's points, so the player goes for the frame ball.
inline constexpr double frame_value = 30.0;

/// The balls the striker of `s` may aim at first: the balls on; with a colour on, every colour
/// (he nominates the one he plays); with a free ball, every ball (he nominates it).
std::vector<int> snooker_targets(const rules::SnookerState& s);
/// Whether the striker of `s` nominates a ball (a colour on, or a free ball).
bool needs_nomination(const rules::SnookerState& s);

/// The object balls of `s` (the cue ball left out).
std::map<int, physics::Vec2> object_balls(const rules::SnookerState& s);
/// The balls at rest for physics::simulate: the cue ball at `cue` and every object ball.
std::vector<physics::BallState> snooker_layout(const rules::SnookerState& s, physics::Vec2 cue);

/// The heading (unit: deg) from `cue` that meets the ball at `target` at contact `f`: 0 full,
/// ±1 the thinnest either side.
double contact_heading(physics::Vec2 cue, physics::Vec2 target, double f, double R);
/// Whether the cue ball at `cue` can meet `target` (a ball of `balls`) at contact `f` in a
/// straight line: the path to where it touches it passes clear of every other ball.
bool can_meet(physics::Vec2 cue, const std::map<int, physics::Vec2>& balls, int target, double f,
              double R);
/// Whether some ball the striker of `s` may play can be met in a straight line from `cue`.
bool ball_in_view(const rules::SnookerState& s, physics::Vec2 cue, double R);

/// Free spots in the D for a cue ball in hand: a grid of the half disc, every spot clear of
/// the balls by a millimetre.
std::vector<physics::Vec2> d_spots(const SnookerPosition& pos, const rules::SnookerState& s);

/// The points the player at the table of `s` can expect from it, in a rough model: his best
/// direct pot's chance (ghost_ball.hpp's `aim_chance` at `sigma_deg`) × (the ball's value + 2,
/// what the pot leaves him to go on with); with the cue ball in hand, from the best spot of the
/// D; with no ball on in view, −2 (a snookered player gives away points more often than not).
/// Plus the cue ball's lie: up to 1/2 point near a ball on, 0.4 less tight on a cushion.
double table_value(const SnookerPosition& pos, const rules::SnookerState& s, double sigma_deg);

/// A stroke to try: where the cue ball goes (in hand), the stroke, the ball aimed at and the
/// nomination.
struct SnookerCandidate {
    Kind kind = Kind::pot;
    physics::Stroke stroke;
    std::optional<physics::Vec2> cue_pos;  ///< with the cue ball in hand
    int target = -1;                       ///< the ball aimed at; −1 for an escape of the sweep
    std::optional<int> nominated;
    double prior = 0.0;  ///< the shot model's chance (pots)
};

/// Pots of the likeliest (ball, pocket) pairs from `cue`, each at a few speeds and spins, the
/// heading refined with the physics (aim.hpp). Adds the simulations it ran.
std::vector<SnookerCandidate> snooker_pots(const SnookerPosition& pos, physics::Vec2 cue,
                                           bool in_hand, const SnookerEffort& effort,
                                           double sigma_deg, std::int64_t& simulations);
/// Safeties: contacts from thin to full on the nearest balls the striker may play, at a few
/// speeds; the table they leave the opponent decides among them.
std::vector<SnookerCandidate> snooker_safeties(const SnookerPosition& pos, physics::Vec2 cue,
                                               bool in_hand, const SnookerEffort& effort);
/// Escapes: a sweep of headings all round at three speeds, for the cushion paths to a ball on
/// when none is in direct view.
std::vector<SnookerCandidate> snooker_escapes(const SnookerPosition& pos, physics::Vec2 cue,
                                              bool in_hand, const SnookerEffort& effort);

/// One play of a candidate.
struct SnookerTrial {
    /// Points ahead for the striker: this stroke's, the change in the frame's worth to him
    /// (frame_value × twice the change of his chance to win it) and the table's next.
    double value = 0.0;
    bool stays = false;  ///< the striker stays at the table (or wins the frame)
    bool foul = false;
    std::int64_t simulations = 1;  ///< the physics simulations it ran (a deep trial's too)
};

class SnookerEvaluator {
  public:
    /// `scale`: the execution noise planned for; `sigma_deg`: the shot model's heading σ at it.
    SnookerEvaluator(const SnookerPosition& pos, double scale, double sigma_deg)
        : pos_(pos), scale_(scale), sigma_deg_(sigma_deg) {}

    /// Plays the candidate without noise; an escape (or anything with a colour on and no
    /// nomination yet) is nominated from the first ball it hits.
    SnookerTrial nominal(SnookerCandidate& c) const;
    /// Plays the candidate with one noise draw.
    SnookerTrial trial(const SnookerCandidate& c, const NoiseDraw& draw) const;
    /// The same, and where the striker stays at the table it is valued two plies deep: his
    /// likeliest next pots (`effort`'s next_*) are played once without noise from where the
    /// balls stopped, each worth its model chance × what it leads to (one ply, as `nominal`)
    /// plus the rest × the cost of a miss; the best of them, at least a safety's 0.
    SnookerTrial deep_trial(const SnookerCandidate& c, const NoiseDraw& draw,
                            const SnookerEffort& effort) const;
    /// The state the candidate is played from (the nomination and the cue ball placed).
    rules::SnookerState start(const SnookerCandidate& c) const;

  private:
    SnookerTrial play(const rules::SnookerState& s, const physics::Stroke& stroke,
                      const SnookerEffort* deeper = nullptr) const;
    double deep_value(const rules::SnookerState& s, const SnookerEffort& effort,
                      SnookerTrial& t) const;

    const SnookerPosition& pos_;
    double scale_;
    double sigma_deg_;
};

}  // namespace ai
