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

/// The shot to share, or why there is none.
struct ShotToShare {
    std::optional<game::SharedShot> shot;
    std::string why_not;  ///< in a player's words, when `shot` is empty
};

/// The last shot of this game (the position before it and its stroke); before the first shot
/// of a game, the position now with the stroke as aimed (the cue ball must be on the table).
ShotToShare shot_to_share(const game::Session& session, const physics::Stroke& aimed);

/// The session a shared shot opens: its game, house rules, table, physics and position, with
/// the players' `names` and a `seed` for the racks of the games after it.
game::Session session_of(const game::SharedShot& shot, const std::array<std::string, 2>& names,
                         std::uint64_t seed);

/// The information bar's line after a link was copied.
std::string copied_notice(const game::SharedShot& shot, bool last_shot);

}  // namespace app
