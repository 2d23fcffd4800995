// 9-ball (WPA World Standardized Rules): lowest ball first, push-out, three fouls.
#pragma once

#include <optional>

#include "rules/fouls.hpp"
#include "rules/game_state.hpp"
#include "rules/shot_facts.hpp"
#include "rules/verdict.hpp"

namespace rules {

/// The lowest-numbered ball on the table at the start of the shot.
std::optional<int> lowest_ball(const GameState& s);

/// The fouls of a 9-ball shot, `third_consecutive_foul` aside. On a push-out only the cue
/// ball's fouls and balls off the table count; on the break `illegal_break` replaces the rail rule.
FoulList nine_ball_fouls(const GameState& s, const ShotFacts& f, double head_string_x);

/// The verdict on a 9-ball shot; positions in the state are left as they were.
Verdict judge_nine_ball(const GameState& s, const ShotFacts& f, double head_string_x);

}  // namespace rules
