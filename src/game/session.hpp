// game::Session: a game of pool between two players, from the rack to the winner.
//
//   rack ─▶ [place cue ball] ─▶ [call, push-out] ─▶ play(stroke) ─▶ physics::simulate
//                 ▲                                                        │
//                 │                 choose(option) ◀── pending choice ◀── rules::judge
//                 └──────────── next shooter ◀────────── verdict ──────────┘──▶ game over
//
// The session owns the whole flow: it racks (seeded), keeps whose turn it is, the groups, the
// call, ball in hand, the pending choice of the rules, the three-foul warning (in the rules'
// state), the winner, and the history of shots; it saves and resumes as JSON (docs/game.md).
// Every action is checked: one that the rules or the table do not allow throws game::Refused
// with the reason and leaves the session unchanged. Deterministic: the same config and the same
// actions give the same game, bit for bit.
#pragma once

#include <array>
#include <cstdint>
#include <filesystem>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "game/shot_record.hpp"
#include "physics/ball_state.hpp"
#include "physics/params.hpp"
#include "physics/shot.hpp"
#include "physics/stroke.hpp"
#include "physics/table.hpp"
#include "rules/game_state.hpp"
#include "rules/judge.hpp"
#include "rules/options.hpp"
#include "rules/verdict.hpp"

namespace game {

/// What a session is played with; fixed for its lifetime.
struct Config {
    rules::Game game = rules::Game::eight_ball;
    rules::Options options;                      ///< 8-ball house rules (9-ball ignores them)
    physics::TableSpec table;                    ///< the table (default: the 9 ft preset)
    physics::Params params;                      ///< the physics
    std::array<std::string, 2> names{"A", "B"};  ///< the players' names, by rules::index(Player)
    std::uint64_t seed = 1;                      ///< every rack of the session derives from it
    rules::Player first_breaker = rules::Player::A;  ///< who breaks the first game
    bool keep_events = false;  ///< keep every shot's physics events in the history (and saves)
};

/// What the session waits for.
enum class Phase {
    place_cue_ball,  ///< ball in hand: the shooter places the cue ball (place_cue_ball)
    shoot,           ///< the shooter may call, declare a push-out, move a cue ball in hand, play
    choose,          ///< a player picks an option of the rules' pending choice (choose)
    game_over,       ///< restart() starts the next game
};

/// The balls at rest where a state puts them, by id (the cue ball when it has a position).
std::vector<physics::BallState> balls_at_rest(const rules::GameState& state);

/// An action that the rules or the table do not allow; what() says why. The session is unchanged.
class Refused : public std::runtime_error {
  public:
    using std::runtime_error::runtime_error;
};

/// An object ball that left the table in this rack, and who was shooting.
struct Pocketed {
    int ball = 0;
    int pocket = -1;  ///< physics::PocketId; −1: driven off the table
    rules::Player by = rules::Player::A;
    friend bool operator==(const Pocketed&, const Pocketed&) = default;
};

class Session {
  public:
    /// A new session: game 0 racked, the first breaker to place the cue ball in the kitchen.
    /// Throws std::invalid_argument for an invalid table or parameters.
    explicit Session(Config config);
    /// A session whose first game goes on from `state` (a shared shot's position, read and
    /// checked by read_shot_link): no history, nothing pocketed listed, the state's shooter to
    /// act. Throws std::invalid_argument for an invalid table or parameters.
    static Session at_position(Config config, rules::GameState state);

    // ---- What the table looks like
    const Config& config() const { return config_; }
    const rules::Ruleset& ruleset() const { return ruleset_; }
    const physics::Table& table() const { return table_; }
    Phase phase() const;
    /// The state before the next shot: shooter, groups, balls on the table and their positions
    /// (the cue ball's once it is on the table or placed), the call, the push-out, the foul
    /// counts and warnings. While a choice is pending: the table as it lies (rules::Verdict).
    const rules::GameState& state() const { return state_; }
    /// Who must act now: the chooser of a pending choice, else the shooter; empty when over.
    std::optional<rules::Player> to_act() const;
    const std::string& name(rules::Player p) const { return config_.names[rules::index(p)]; }
    /// Where ball in hand may go: `anywhere`, `kitchen`, or `none` (the cue ball is on the table).
    rules::BallInHand ball_in_hand() const;
    /// The balls at rest, by id: the cue ball (when on the table or placed) and the object balls
    /// on the table.
    std::vector<physics::BallState> balls() const;
    /// The object balls that left the table in this rack, in order.
    const std::vector<Pocketed>& pocketed() const { return pocketed_; }
    /// The rules' pending choice (phase choose), else empty.
    std::optional<rules::Choice> choice() const;
    /// Whether a push-out may be declared now (9-ball, the shot right after a foul-free break).
    bool push_out_available() const;
    /// The player warned of a third consecutive foul (9-ball).
    bool warned(rules::Player p) const { return state_.is_warned(p); }
    std::optional<rules::Player> winner() const { return winner_; }
    /// Games won in this session, by rules::index(Player).
    const std::array<int, 2>& score() const { return score_; }
    int game_number() const { return game_number_; }  ///< 0 for the first game
    int rack_number() const { return rack_number_; }  ///< 0, then +1 for each re-rack
    /// Who breaks game `n`: the first breaker in even games, the other player in odd ones.
    rules::Player breaker_of_game(int n) const;
    /// The shots of this game, oldest first.
    const std::vector<ShotRecord>& history() const { return history_; }
    /// The latest stroke's simulation, for playback; null before the first stroke, after a
    /// restart and after loading (history() keeps what it needs to simulate it again).
    const physics::Shot* last_shot() const { return last_shot_ ? &*last_shot_ : nullptr; }

    // ---- Actions
    /// Why the cue ball may not be placed at `pos` (no ball in hand; off the playing surface;
    /// overlapping a ball; in front of the head string with ball in hand in the kitchen), or
    /// empty when it may.
    std::optional<std::string> check_cue_ball(physics::Vec2 pos) const;
    /// Places the cue ball in hand (again, if it was placed): see check_cue_ball.
    void place_cue_ball(physics::Vec2 pos);
    /// Sets the call of the next shot: nothing, a safety, or a ball on the table and a pocket
    /// (8-ball after the break; the 8 only once the shooter's group is cleared).
    void set_call(const rules::Call& call);
    /// Declares (or withdraws) a push-out for the next shot; see push_out_available().
    void set_push_out(bool declare);
    /// Plays a stroke: simulates it with the real physics, judges it and applies the verdict
    /// (respots, the next shooter, ball in hand, a pending choice, the end of the game).
    /// Returns the shot's record.
    const ShotRecord& play(const physics::Stroke& stroke);
    /// Takes an option of the pending choice; a re-rack racks the balls again.
    void choose(rules::ChoiceOption option);
    /// Neither player can make progress: the balls are racked again and the original breaker
    /// breaks (rules::stalemate).
    void declare_stalemate();
    /// Starts the next game (game_number() + 1): new rack, breaker_of_game(), empty history.
    /// The score is kept; a game abandoned before its end counts for nobody. Before the first
    /// shot of a game it racks that game again instead (the same breaker, the same rack).
    void restart();

    // ---- Save and resume (docs/game.md, "Save format")
    /// The whole session as one JSON document (history included).
    std::string to_json() const;
    /// A session from to_json()'s document. Every field is checked: a corrupt or foreign
    /// document throws game::LoadError naming the field by its path, e.g.
    /// "session.state.on_table[3]: ball 17 does not exist".
    static Session from_json(const std::string& text);
    /// Writes to_json() to a temporary file beside `path` and renames it over `path`, so `path`
    /// is either the old file or the new one, never half-written. Throws std::runtime_error
    /// (the old file untouched) when it cannot.
    void save_file(const std::filesystem::path& path) const;
    /// Reads a session saved by save_file; never modifies the file. Throws game::LoadError.
    static Session load_file(const std::filesystem::path& path);

  private:
    struct Restored {};
    Session(Config config, Restored);
    /// Racks the object balls for the current game and rack number; `s` is the state to shoot
    /// from (its positions are replaced by the rack's).
    void rack(rules::GameState s);
    void require_shooting(const char* action) const;
    void record_pocketed(const rules::GameState& before, const ShotSummary& summary,
                         const rules::Verdict& v);

    Config config_;
    physics::Table table_;
    rules::Ruleset ruleset_;
    int game_number_ = 0;
    int rack_number_ = 0;
    std::array<int, 2> score_{0, 0};
    rules::GameState state_;
    std::optional<rules::Verdict> pending_;  ///< the verdict whose choice is pending
    std::optional<rules::Player> winner_;
    std::vector<Pocketed> pocketed_;
    std::vector<ShotRecord> history_;
    std::optional<physics::Shot> last_shot_;
};

/// The seed of a rack: a deterministic mix of the session's seed, the game and the rack number.
std::uint64_t rack_seed(std::uint64_t session_seed, int game, int rack);

/// Bounds of a stroke the session accepts (those of the `simulate` contract).
inline constexpr double max_stroke_speed = 20.0;  ///< (unit: m/s)

}  // namespace game
