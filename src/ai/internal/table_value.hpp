// The value of a position for the player at the table: the chance of his best next shot (one shot
// ahead, from the analytic model of ghost_ball.hpp), turned into a rough chance of winning, less
// a cost for each of his balls that cannot reach any pocket as the balls lie (where the level
// counts them: level.hpp's `Effort::stuck_ball_cost`).
#pragma once

#include <optional>
#include <vector>

#include "ai/internal/ghost_ball.hpp"
#include "ai/internal/position.hpp"
#include "ai/internal/private.hpp"
#include "rules/verdict.hpp"

namespace ai {

/// The chance of the best direct pot for the shooter of `s` (his target balls into any pocket);
/// with ball in hand, from the best spot found for it. 0 when nothing is on.
double best_shot_chance(const Position& base, const rules::GameState& s, double sigma_deg);

/// The chance of the best direct pot of `ball` with the cue ball free to go anywhere (just behind
/// its ghost ball, straight in or at a slight angle, wherever that spot is free); 0 when the
/// ball has no clear path to any pocket.
double ball_chance_anywhere(const Position& base, const rules::GameState& s, int ball,
                            double sigma_deg);

/// The best direct pot from the cue ball at `cue`, if any is on, and its chance.
struct BestAim {
    Aim aim;
    double chance = 0.0;
};
std::optional<BestAim> best_aim(const Position& base, const rules::GameState& s, physics::Vec2 cue,
                                double sigma_deg);

/// A rough chance of winning for the player at the table whose best shot has chance `q`: with
/// nothing on he plays safe and the game is about even; with a sure shot he is well ahead.
inline double table_value(double q) {
    return 0.5 + 0.45 * q;
}
/// The balls the shooter of `s` must still pocket, in any order, before the game can be his:
/// 8-ball: those of his group on the table and the 8 (none while the table is open); 9-ball:
/// every ball on the table.
std::vector<int> balls_to_clear(const rules::Ruleset& rules, const rules::GameState& s);

/// Whether the shooter of `s` is near the end of the rack: 8-ball, three balls or fewer to clear
/// (two of his group and the 8, after the group is set); 9-ball, four balls or fewer on the table.
bool near_rack_end(const rules::Ruleset& rules, const rules::GameState& s);

/// How many of `balls_to_clear` have no clear path to any pocket from where they lie (another
/// ball in the way, or a cluster): he will have to free them before he can pot them.
int stuck_balls(const Position& base, const rules::GameState& s);

/// What his stuck balls take off the value of the table to the shooter of `s`: `stuck_cost` per
/// stuck ball (0, and none counted, when `stuck_cost` is 0).
double stuck_penalty(const Position& base, const rules::GameState& s, double stuck_cost);

/// The value of the table to the shooter of `s`: T(his best shot's chance) less his
/// `stuck_penalty`.
double position_value(const Position& base, const rules::GameState& s, double sigma_deg,
                      double stuck_cost);

/// What each ball pocketed adds for the shooter who stays at the table (progress), up to two.
inline constexpr double progress_bonus = 0.02;

/// What the rules' option `option` is worth to `chooser` (a rough chance of winning), given the
/// state that the first option leads to; tables valued by `position_value` with `stuck_cost`.
double option_value(const Position& base, const rules::GameState& first_option_state,
                    rules::ChoiceOption option, rules::Player chooser, double sigma_deg,
                    double stuck_cost);

/// What staying at the table from `before` to `after` is worth to the shooter whose table is
/// worth `value` to him: `value` plus the progress bonus for the balls pocketed (at most 1).
double staying_value(const rules::GameState& before, const rules::GameState& after, double value);

/// What a verdict is worth to `me` (the shooter of the shot from `before`): 1 won, 0 lost, else
/// the value of the table to whoever has it next (`position_value` with `stuck_cost`, with a
/// bonus for balls pocketed when it is me).
double verdict_value(const Position& base, const rules::GameState& before, const rules::Verdict& v,
                     double sigma_deg, double stuck_cost);

}  // namespace ai
