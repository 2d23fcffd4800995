// Sharing a shot from the game (game/shot_link.hpp, docs/app.md "Shot links"): which shot the
// Copy shot link button shares, and the session that an opened link sets up.
#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <string>

#include "game/session.hpp"
#include "game/shot_link.hpp"

namespace app {

class Controller;
struct ControllerOptions;

/// The shot to share, or why there is none.
struct ShotToShare {
    std::optional<game::AnyShot> shot;
    std::string why_not;     ///< in a player's words, when `shot` is empty
    bool last_shot = false;  ///< the shot played last (else the position now, as aimed)
};

/// Pool: the last shot of this game (the position before it and its stroke); before the first
/// shot of a game, the position now with the stroke as aimed (the cue ball must be on the table).
ShotToShare shot_to_share(const game::Session& session, const physics::Stroke& aimed);

/// Whatever the controller plays: pool as above; snooker and three-cushion the match's last
/// stroke from the match just before it, or before a frame's or game's first stroke the match
/// now with the stroke and nomination as aimed (a cue ball in hand placed first). Practice
/// shares its position as pool's; on the snooker and carom tables it has no link.
ShotToShare shot_to_share(const Controller& controller);

/// The session a shared shot opens: its game, house rules, table, physics and position, with
/// the players' `names` and a `seed` for the racks of the games after it.
game::Session session_of(const game::SharedShot& shot, const std::array<std::string, 2>& names,
                         std::uint64_t seed);

/// Sets the controller up at a shared shot's position and plays its stroke at once, whoever's
/// seat it is: pool in session_of's session with `names`; a match as it was shared (its own
/// names and scores). `options` gives the seats, the noise and the seed.
void open_shot(Controller& controller, game::AnyShot shot, const std::array<std::string, 2>& names,
               const ControllerOptions& options);

/// The information bar's line after a link was copied.
std::string copied_notice(const ShotToShare& share);

}  // namespace app
