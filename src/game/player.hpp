// Someone at the table: given the session, decides what to do in its current phase. The random
// player (random_player.hpp) and, later, the AI implement it; autoplay.hpp plays whole games.
#pragma once

#include <optional>
#include <string>

#include "physics/stroke.hpp"
#include "physics/vec.hpp"
#include "rules/game_state.hpp"
#include "rules/verdict.hpp"

namespace game {

class Session;

/// What a player does in one turn (the `decide` output of docs/cli.md).
struct Decision {
    std::optional<rules::ChoiceOption> choice;  ///< when a choice is pending: the option taken
    std::optional<physics::Vec2> cue_pos;       ///< with ball in hand: where the cue ball goes
    rules::Call call;                           ///< the call of the stroke
    bool push_out = false;                      ///< declare a push-out (9-ball)
    physics::Stroke stroke;                     ///< the stroke as intended (before execution noise)
};

class Player {
  public:
    virtual ~Player() = default;
    /// How the player is named in a match ("random", "ai:5").
    virtual std::string kind() const = 0;
    /// The decision for the session's current phase (choose, place_cue_ball or shoot); the
    /// session's to_act() is this player.
    virtual Decision decide(const Session& session) = 0;
    /// The player's own execution noise, as a multiple of the game's noise scale (the AI's
    /// levels: 4 at level 1 down to 1 at level 5). play_game strokes with scale × this.
    virtual double execution_noise() const { return 1.0; }
};

}  // namespace game
