// A shot as link text: the position, the table and the stroke, so that whoever opens the link
// plays exactly that shot (the engine is deterministic on every platform, docs/physics.md).
// The link is "shot=1.<checksum>.<base64url of the JSON>", alone or as the fragment of the
// web page's address (docs/game.md, "Shot links").
#pragma once

#include <string>
#include <string_view>
#include <variant>
#include <vector>

#include "game/carom_session.hpp"
#include "game/snooker_session.hpp"
#include "physics/ball_state.hpp"
#include "physics/params.hpp"
#include "physics/stroke.hpp"
#include "physics/table.hpp"
#include "rules/game_state.hpp"
#include "rules/options.hpp"

namespace game {

struct SharedShot {
    rules::Game game = rules::Game::eight_ball;
    rules::Options options;
    physics::TableSpec table;
    physics::Params params;
    rules::GameState state;  ///< who shoots, the call, and every ball's position
    physics::Stroke stroke;

    /// The balls at rest where the state puts them, by id: what the stroke is played on.
    std::vector<physics::BallState> balls() const;
};

/// A snooker shot: the match as it stood just before the stroke (its save format: the scores,
/// the names, the nomination and a placed cue ball in hand included), and the stroke.
struct SharedSnookerShot {
    SnookerSession before;
    physics::Stroke stroke;
};

/// A three-cushion shot: the game just before the stroke, and the stroke (on the striker's ball).
struct SharedCaromShot {
    CaromSession before;
    physics::Stroke stroke;
};

/// Any shot a link holds.
using AnyShot = std::variant<SharedShot, SharedSnookerShot, SharedCaromShot>;

/// The link text of a shot: "shot=1.<8 hex digits>.<base64url>".
std::string shot_link(const SharedShot& shot);
std::string shot_link(const SharedSnookerShot& shot);
std::string shot_link(const SharedCaromShot& shot);
std::string shot_link(const AnyShot& shot);

/// The link text of a payload, the JSON of docs/game.md "Shot links" (for tools and fuzzing:
/// shot_link writes the payload itself).
std::string link_of_payload(std::string_view payload);

/// Reads a link: the text after "#" of an address, or the link text alone (spaces around it
/// ignored). A link cut short, altered or holding an impossible table or position: LoadError
/// saying which ("link: …", or the JSON path of the bad field under "link.shot").
AnyShot read_any_shot_link(std::string_view text);
/// read_any_shot_link for an 8-ball or 9-ball shot; a snooker or three-cushion link is a
/// LoadError ("link.shot.game").
SharedShot read_shot_link(std::string_view text);

}  // namespace game
