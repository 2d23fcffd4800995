// game::CaromSession: three-cushion billiards between two players (UMB rules), game after game.
//
//   starting position ─▶ play(stroke) ─▶ physics::simulate ─▶ judge_three_cushion
//                            ▲                                          │
//                            └──── the same striker after a point, ◀────┘──▶ game over
//                                  else the other's inning
//
// The rules are rules::judge_three_cushion's (docs/rules.md, "Three-cushion"); the session keeps
// whose cue ball is whose (the starter plays the white, the other the yellow), the innings, the
// runs and the games won, and saves and resumes as JSON (docs/game.md). A refused action throws
// game::Refused with the reason in a player's words. Deterministic like game::Session.
#pragma once

#include <array>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "game/snooker_session.hpp"
#include "physics/ball_state.hpp"
#include "physics/params.hpp"
#include "physics/shot.hpp"
#include "physics/stroke.hpp"
#include "physics/table.hpp"
#include "rules/three_cushion.hpp"

namespace game {

struct CaromConfig {
    rules::CaromOptions options;  ///< points to win a game, the equal-innings rule
    physics::TableSpec table = physics::carom_table_spec();
    physics::Params params = *physics::params_preset("carom");
    std::array<std::string, 2> names{"A", "B"};
    rules::Player first_starter = rules::Player::A;  ///< opens the first game (the white)
};

class CaromSession {
  public:
    /// A new session: game 0 in the UMB starting position. Throws std::invalid_argument for an
    /// invalid table, parameters or target.
    explicit CaromSession(CaromConfig config);

    const CaromConfig& config() const { return config_; }
    const physics::Table& table() const { return table_; }
    /// shoot, or frame_over when the game is over (next_game() starts another).
    MatchPhase phase() const { return over_ ? MatchPhase::frame_over : MatchPhase::shoot; }
    const rules::CaromState& state() const { return state_; }
    std::optional<rules::Player> to_act() const;
    const std::string& name(rules::Player p) const { return config_.names[rules::index(p)]; }
    std::vector<physics::BallState> balls() const;
    /// The striker's cue ball (0 the white, 1 the yellow).
    int cue_ball() const { return state_.cue_ball(state_.shooter); }
    const std::optional<rules::CaromVerdict>& last_verdict() const { return last_; }
    const physics::Shot* last_shot() const { return last_shot_ ? &*last_shot_ : nullptr; }
    /// The game's winner; empty before the end and for a draw.
    std::optional<rules::Player> winner() const { return winner_; }
    bool game_over() const { return over_; }
    const std::array<int, 2>& games_won() const { return games_; }
    int game_number() const { return game_; }
    rules::Player starter_of_game(int n) const;
    /// Points per inning (0 before the first inning).
    double average(rules::Player p) const;

    /// Plays the stroke on the striker's cue ball (the stroke's `ball` is set to it).
    const rules::CaromVerdict& play(const physics::Stroke& stroke);
    /// Starts the next game (after the end of one), the other player opening.
    void next_game();

    std::string to_json() const;
    /// Throws game::LoadError naming the field, e.g. "carom.state.scores.A: ...".
    static CaromSession from_json(const std::string& text);
    void save_file(const std::filesystem::path& path) const;
    static CaromSession load_file(const std::filesystem::path& path);

  private:
    struct Restored {};
    CaromSession(CaromConfig config, Restored);
    void set_up_game();

    CaromConfig config_;
    physics::Table table_;
    physics::CaromSpots spots_;
    int game_ = 0;
    std::array<int, 2> games_{0, 0};
    rules::CaromState state_;
    bool over_ = false;
    std::optional<rules::Player> winner_;
    std::optional<rules::CaromVerdict> last_;
    std::optional<physics::Shot> last_shot_;

    friend struct CaromJson;
};

/// "white", "yellow", "red".
std::string carom_ball_name(int id);

}  // namespace game
