// game::Practice: one player alone at a table, no rules: any ball may be moved anywhere it can
// lie (on the cloth, touching no other ball), a stroke is played with the real physics and the
// balls pocketed leave the table, and "try again" puts back the position before a shot.
// A position saves and loads as the `simulate` input of docs/cli.md (table, params, balls).
#pragma once

#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "physics/ball_state.hpp"
#include "physics/params.hpp"
#include "physics/shot.hpp"
#include "physics/stroke.hpp"
#include "physics/table.hpp"
#include "rules/game_state.hpp"

namespace game {

class Practice {
  public:
    /// The rack of `game` (8-ball or 9-ball, from `seed`) with the cue ball on the head spot.
    /// Throws std::invalid_argument for an invalid table or parameters.
    Practice(rules::Game game, physics::TableSpec table, physics::Params params,
             std::uint64_t seed);

    /// Whose balls these are: the game racked, or for a loaded position 8-ball when a ball
    /// above the 9 is on the table, else 9-ball.
    rules::Game game() const { return game_; }
    const physics::TableSpec& table_spec() const { return spec_; }
    const physics::Table& table() const { return table_; }
    const physics::Params& params() const { return params_; }
    /// The balls on the table, by id (0 the cue ball), at rest.
    const std::map<int, physics::Vec2>& balls() const { return balls_; }
    std::vector<physics::BallState> ball_states() const;

    /// Why ball `id` may not go to `pos`, in a player's words ("The 5 can't go on top of the
    /// 10.", "The cue ball must go on the cloth."), or empty when it may.
    std::optional<std::string> check_move(int id, physics::Vec2 pos) const;
    /// Moves ball `id` to `pos`; false (nothing moved) when check_move refuses.
    bool move(int id, physics::Vec2 pos);

    /// Plays `stroke` on the cue ball: the balls pocketed leave the table; a pocketed cue ball
    /// comes back on the head spot (or the free place nearest it). Returns the shot (for
    /// playback). Throws std::invalid_argument for a stroke outside the session's bounds.
    const physics::Shot& play(const physics::Stroke& stroke);
    /// The position before the last shot not yet taken back (any number of shots back).
    bool can_try_again() const { return !before_.empty(); }
    void try_again();

    /// The position as `coolaaber-cli simulate` reads it: {"table", "params", "balls"}, every
    /// number exact.
    std::string to_json() const;
    /// A position from a `simulate` input (a table preset or object, params, balls at rest;
    /// a "strike" is allowed and ignored). Throws LoadError naming the bad field, e.g.
    /// "position.balls[2].pos: ...".
    static Practice from_json(std::string_view text);

  private:
    Practice(physics::TableSpec table, physics::Params params);
    /// check_move for ball `id` wherever it is (or is not yet): the cloth, the other balls.
    std::optional<std::string> check_place(int id, physics::Vec2 pos) const;
    physics::Vec2 free_spot_near_head() const;

    rules::Game game_ = rules::Game::eight_ball;
    physics::TableSpec spec_;
    physics::Params params_;
    physics::Table table_;
    std::map<int, physics::Vec2> balls_;
    std::vector<std::map<int, physics::Vec2>> before_;  ///< the positions before each shot
    std::optional<physics::Shot> last_shot_;
};

}  // namespace game
