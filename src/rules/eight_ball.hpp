// 8-ball (WPA World Standardized Rules with the house-rule switches of options.hpp).
#pragma once

#include <set>

#include "rules/fouls.hpp"
#include "rules/game_state.hpp"
#include "rules/options.hpp"
#include "rules/shot_facts.hpp"
#include "rules/verdict.hpp"

namespace rules {

/// The balls the cue ball may legally hit first: the shooter's group; on an open table any
/// ball but the 8; the 8 once the group is cleared.
std::set<int> eight_ball_legal_first(const GameState& s);

/// The fouls of an 8-ball shot. On the break any ball may be hit first and the break
/// requirement replaces the rail rule.
FoulList eight_ball_fouls(const Options& o, const GameState& s, const ShotFacts& f,
                          double head_string_x);

/// Whether this shot's call counts: every shot (`all`), shots at the 8 (`eight_only`), none.
bool call_counts(const Options& o, const GameState& s);

/// The verdict on an 8-ball shot; positions in the state are left as they were.
Verdict judge_eight_ball(const Options& o, const GameState& s, const ShotFacts& f,
                         double head_string_x);

}  // namespace rules
