// A shot as link text: the position, the table and the stroke, so that whoever opens the link
// plays exactly that shot (the engine is deterministic on every platform, docs/physics.md).
// The link is "shot=1.<checksum>.<base64url of the JSON>", alone or as the fragment of the
// web page's address (docs/game.md, "Shot links").
#pragma once

#include <string>
#include <string_view>
#include <vector>

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

/// The link text of a shot: "shot=1.<8 hex digits>.<base64url>".
std::string shot_link(const SharedShot& shot);

/// Reads a link: the text after "#" of an address, or the link text alone (spaces around it
/// ignored). A link cut short, altered or holding an impossible table or position: LoadError
/// saying which ("link: …", or the JSON path of the bad field under "link.shot").
SharedShot read_shot_link(std::string_view text);

}  // namespace game
