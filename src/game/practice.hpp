// game::Practice: one player alone at any game's table (8-ball, 9-ball, snooker,
// three-cushion), no rules: any ball may be moved anywhere it can lie (on the cloth, touching no
// other ball), a stroke is played with the real physics and the balls pocketed leave the table
// (a pocketed cue ball comes back), and "try again" puts back the position before a shot.
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
#include "physics/rack.hpp"
#include "physics/shot.hpp"
#include "physics/stroke.hpp"
#include "physics/table.hpp"
#include "rules/game_state.hpp"

namespace game {

class Practice {
  public:
    /// The starting position of `game` on `table` with `params`' balls: the 8-ball or 9-ball
    /// rack (from `seed`) with the cue ball on the head spot, the snooker set-up with the cue
    /// ball in the D, the three-cushion starting position. Throws std::invalid_argument for an
    /// invalid table or parameters, or a table that does not suit the game (three-cushion is
    /// played without pockets, the others with).
    Practice(physics::RackType game, physics::TableSpec table, physics::Params params,
             std::uint64_t seed);
    /// `game`'s starting position on its own table and balls: pool on the 9 ft table, snooker
    /// on the 12 ft table with the snooker balls, three-cushion on the 10 ft carom table with
    /// the carom balls.
    static Practice on_own_table(physics::RackType game, std::uint64_t seed);

    /// Whose table and balls these are: the game set out, or for a loaded position the one
    /// its table and balls say (docs/game.md, "Practice").
    physics::RackType game() const { return game_; }
    /// An 8-ball or 9-ball table (not snooker's or three-cushion's).
    bool on_pool_table() const {
        return game_ == physics::RackType::eight_ball || game_ == physics::RackType::nine_ball;
    }
    /// The pool game whose balls these are (8-ball for the other tables).
    rules::Game pool_game() const {
        return game_ == physics::RackType::nine_ball ? rules::Game::nine_ball
                                                     : rules::Game::eight_ball;
    }
    /// A ball as the player names it: "cue ball", "5", "red", "pink", "white", "yellow".
    std::string ball_name(int id) const;
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
    /// comes back to its home (return_words(): the head spot, in the D, or the free place
    /// nearest it). Returns the shot (for playback). Throws std::invalid_argument for a stroke
    /// outside the session's bounds.
    const physics::Shot& play(const physics::Stroke& stroke);
    /// Where a pocketed cue ball comes back, in a player's words ("on the head spot").
    std::string return_words() const;
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
    Practice(physics::RackType game, physics::TableSpec table, physics::Params params);
    /// check_move for ball `id` wherever it is (or is not yet): the cloth, the other balls.
    std::optional<std::string> check_place(int id, physics::Vec2 pos) const;
    /// Ball `id`'s home if it may come back there (the cue ball; on a table without pockets,
    /// every ball), else the free place nearest it (snooker's cue ball: in the D).
    physics::Vec2 free_spot_near_home(int id) const;
    bool may_lie_at(int id, physics::Vec2 p) const;

    physics::RackType game_ = physics::RackType::eight_ball;
    physics::TableSpec spec_;
    physics::Params params_;
    physics::Table table_;
    std::map<int, physics::Vec2> balls_;
    std::map<int, physics::Vec2> home_;  ///< where a ball that leaves the table comes back
    std::vector<std::map<int, physics::Vec2>> before_;  ///< the positions before each shot
    std::optional<physics::Shot> last_shot_;
};

}  // namespace game
