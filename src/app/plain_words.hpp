// The rules' names in plain words for the information bar and the choice buttons.
#pragma once

#include <string>

#include "game/session.hpp"
#include "rules/verdict.hpp"

namespace app {

/// e.g. "the cue ball went into a pocket".
std::string foul_words(rules::Foul f);
/// A button's text, e.g. "Play the table as it lies".
std::string choice_words(rules::ChoiceOption o);
/// "SW corner", "N side", ...
std::string pocket_words(int pocket);
/// "solids (1-7)", "stripes (9-15)".
std::string group_words(rules::Group g);

/// What the last shot did, in one or two sentences: the balls pocketed, the fouls, the result
/// (e.g. "Anna pocketed the 3 and the 11. Foul: the cue ball went into a pocket."), and why the
/// turn passed when balls dropped that were not the call.
std::string shot_words(const game::Session& session, const game::ShotRecord& record);

/// Why the cue ball in hand may not go to `pos`, as a player says it ("The cue ball can't go on
/// top of the 10."); empty when it may.
std::string placement_words(const game::Session& session, physics::Vec2 pos);

/// The information bar: whose turn it is and his group (or the ball to hit), ball in hand,
/// the call, a pending choice, the three-foul warning, the winner. One line per entry.
std::vector<std::string> info_lines(const game::Session& session, const rules::Call& call);

}  // namespace app
