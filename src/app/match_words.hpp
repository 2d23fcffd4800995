// What the snooker and three-cushion tables say, in each game's words: what a stroke did
// ("Foul: 4 points to Bob — the cue ball went in off the red", "Point: three cushions before
// the second ball", "No point: only two cushions before the second ball"), the information
// bar (who is to play, the ball on, the break, points remaining, snookers required; the
// inning, the run) and the foul the aim would make.
#pragma once

#include <optional>
#include <span>
#include <string>
#include <vector>

#include "game/carom_session.hpp"
#include "game/snooker_session.hpp"
#include "physics/event.hpp"
#include "physics/shot.hpp"

namespace app {

/// The last stroke of `s` (its simulation `shot`) in words.
std::string snooker_shot_words(const game::SnookerSession& s, const physics::Shot& shot);
/// The choice just made after a foul, in words ("Bob asks Ann to play again.").
std::string after_foul_words(const game::SnookerSession& s, rules::AfterFoul choice);
/// The information bar: who acts and what for, the ball on and the nomination, the break,
/// the points remaining, snookers required, the frames.
std::vector<std::string> snooker_info(const game::SnookerSession& s, std::optional<int> nomination);
/// "Foul as aimed: …" when the aim's first ball (from the preview's `events`) is not on,
/// else empty.
std::string snooker_aim_foul(const game::SnookerSession& s, std::optional<int> nomination,
                             std::span<const physics::Event> events);
/// "Foul: 4 points to Bob — the cue ball went in off the red" (the first foul's reason).
std::string snooker_foul_words(const game::SnookerSession& s, const rules::SnookerVerdict& v,
                               const physics::Shot& shot);
/// The points a player is behind by more than remain on the table; 0 when not.
int snookers_required(const game::SnookerSession& s, rules::Player p);

std::string carom_shot_words(const game::CaromSession& s, const physics::Shot& shot);
std::vector<std::string> carom_info(const game::CaromSession& s);

}  // namespace app
