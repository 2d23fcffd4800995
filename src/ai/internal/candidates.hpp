// The strokes the AI considers, before any is judged:
//   pots      ghost-ball aims for every target ball and pocket, the easiest first, each at a few
//             speeds and spins, the heading refined for throw and squirt (aim.hpp);
//             9-ball: also combinations on the 9 (the lowest ball into it);
//   safeties  contacts across each legal ball (full to thin) at a few speeds, called "safety";
//   kicks     a sweep of headings all round (banks, kicks, combinations, escapes from a snooker);
//             the call comes from what the stroke does when played without noise;
//   breaks    from a few spots behind the head string, full on the apex ball, hard (9-ball,
//             level 5: `tuned_breaks`, tuned offline);
//   push-outs (9-ball) soft rolls in every direction.
#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <vector>

#include "ai/internal/ghost_ball.hpp"
#include "ai/internal/level.hpp"
#include "ai/internal/position.hpp"
#include "ai/internal/private.hpp"
#include "physics/stroke.hpp"
#include "rules/game_state.hpp"

namespace ai {

struct Candidate {
    Kind kind = Kind::pot;
    physics::Stroke stroke;
    rules::Call call;                      ///< kicks: set after the noiseless simulation
    std::optional<physics::Vec2> cue_pos;  ///< with ball in hand: where the cue ball goes
    double prior = 0.0;                    ///< pots: the analytic chance (ghost_ball.hpp)
    std::optional<Aim> aim;                ///< pots: the ghost-ball aim the stroke is for
};

/// The call a shot needs in `s`: the ball and pocket when calls count (8-ball after the break),
/// else nothing.
rules::Call pot_call(const Position& pos, int ball, int pocket);
/// "safety" when calls count, else nothing.
rules::Call safety_call(const Position& pos);

/// A direct pot and its analytic chance.
struct RankedAim {
    Aim aim;
    double chance = 0.0;
};
/// Every direct pot of a target ball from the cue ball at `cue`, the likeliest first.
std::vector<RankedAim> ranked_aims(const Position& pos, physics::Vec2 cue, double sigma_deg);

/// The strokes tried for one pot: `effort`'s speeds × spins, each heading refined (aim.hpp).
/// Adds the refinement simulations to `simulations`.
std::vector<Candidate> pot_strokes(const Position& pos, physics::Vec2 cue, bool in_hand,
                                   const RankedAim& aim, const Effort& effort,
                                   std::int64_t& simulations);

/// Pots from the cue ball at `cue`: the strokes of `effort.pot_pairs` likeliest pots. Adds the
/// refinement simulations to `simulations`.
std::vector<Candidate> pot_candidates(const Position& pos, physics::Vec2 cue, bool in_hand,
                                      const Effort& effort, double sigma_deg,
                                      std::int64_t& simulations);
/// A combination and its analytic chance.
struct RankedCombination {
    Combination combination;
    double chance = 0.0;
};
/// 9-ball: every combination on the 9 from the cue ball at `cue` (the lowest ball sent into the
/// 9, the 9 into a pocket), the likeliest first; none in 8-ball or when the 9 is the lowest.
std::vector<RankedCombination> ranked_combinations(const Position& pos, physics::Vec2 cue,
                                                   double sigma_deg);

/// The strokes of the `effort.combinations` likeliest combinations on the 9 from `cue`: a few
/// speeds, stun, follow and draw, each heading refined with the three balls alone (aim.hpp).
/// Adds the refinement simulations to `simulations`.
std::vector<Candidate> combination_candidates(const Position& pos, physics::Vec2 cue, bool in_hand,
                                              const Effort& effort, double sigma_deg,
                                              std::int64_t& simulations);

/// Pots close to the pot `c`: its speed a little lower and higher and its follow or draw a
/// little more and less, each heading refined again (a finer search of the stroke around the
/// best few; position play needs finer speeds than the first grid). Adds the refinement
/// simulations to `simulations`.
std::vector<Candidate> pot_variants(const Position& pos, const Candidate& c, const Effort& effort,
                                    std::int64_t& simulations);

std::vector<Candidate> safety_candidates(const Position& pos, physics::Vec2 cue, bool in_hand,
                                         const Effort& effort);
std::vector<Candidate> kick_candidates(const Position& pos, physics::Vec2 cue, bool in_hand,
                                       const Effort& effort);
/// A break: the cue ball just behind the head string, `offset` across the table from its middle
/// (unit: m), sent at the apex ball full (`contact` 0) or off its centre towards the middle
/// (`contact` × a ball's width), at cue speed `speed` (unit: m/s) with a touch of draw.
struct BreakSpec {
    double offset = 0.0;
    double contact = 0.0;
    double speed = 9.5;
};
/// The break of `spec` in `pos`; empty when its spot is taken.
std::optional<Candidate> break_candidate(const Position& pos, const BreakSpec& spec);
/// The breaks level 5 chooses among in 9-ball, tuned offline (bench/break_tuning.cpp): full on
/// the apex ball from the middle or a little off it, hard. Of the spots, contacts and speeds
/// that program plays, these leave the fewest balls with no path to a pocket and pocket the most,
/// with no more scratches than the others. break_test.cpp.
inline constexpr std::array<BreakSpec, 6> tuned_breaks{{{0.0, 0.0, 9.5},
                                                        {0.0, 0.0, 10.0},
                                                        {0.08, 0.0, 9.5},
                                                        {-0.08, 0.0, 9.5},
                                                        {0.08, 0.0, 10.0},
                                                        {-0.08, 0.0, 10.0}}};
/// The broad set the lower levels (and 8-ball) choose among: five spots, full or a quarter of a
/// ball off the apex ball's centre, at 6.5, 8 and 9.5 m/s.
std::vector<BreakSpec> broad_breaks();
/// The breaks tried in `pos`: the tuned ones (`tuned`) or the broad set, those whose spot is free.
std::vector<Candidate> break_candidates(const Position& pos, bool tuned);
std::vector<Candidate> push_out_candidates(const Position& pos, physics::Vec2 cue);

}  // namespace ai
