// game::SnookerSession: a snooker match between two players, frame by frame, from the set-up
// to the winner of the match (best of N frames).
//
//   set-up ─▶ place the cue ball in the D ─▶ [nominate] ─▶ play(stroke) ─▶ physics::simulate
//                       ▲                                                        │
//                       │        choose(play / play again / replace) ◀── foul ◀── judge_snooker
//                       └───────────── next striker ◀──────────── verdict ───────┘──▶ frame over
//
// The rules are rules::judge_snooker's (docs/rules.md, "Snooker"); the session keeps the turn,
// the cue ball in hand (in the D at the break and after an in-off), the nomination, the
// after-foul choice of the incoming player, the frames won and the match's winner. It saves and
// resumes as JSON (docs/game.md, "Snooker and three-cushion saves"). A refused action throws
// game::Refused with the reason in a player's words and leaves the session unchanged.
// Deterministic: the same config and the same actions give the same match, bit for bit.
#pragma once

#include <array>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "physics/ball_state.hpp"
#include "physics/params.hpp"
#include "physics/shot.hpp"
#include "physics/stroke.hpp"
#include "physics/table.hpp"
#include "rules/snooker.hpp"

namespace game {

struct SnookerConfig {
    rules::SnookerOptions options;  ///< the miss rule (on: as in professional play)
    int best_of = 1;                ///< frames in the match (odd, 1–35)
    physics::TableSpec table = physics::snooker_table_spec();
    physics::Params params = *physics::params_preset("snooker");
    std::array<std::string, 2> names{"A", "B"};
    rules::Player first_breaker = rules::Player::A;  ///< breaks the first frame
};

/// What a snooker or three-cushion session waits for.
enum class MatchPhase {
    place_cue_ball,  ///< the striker places the cue ball in hand (in the D)
    shoot,           ///< the striker may nominate, move a cue ball in hand, play
    choose,          ///< after a foul the incoming player chooses (choose)
    frame_over,      ///< next_frame() sets up the next frame (game)
    match_over,      ///< the match is won
};

class SnookerSession {
  public:
    /// A new match: frame 0 set up, the first breaker to place the cue ball in the D.
    /// Throws std::invalid_argument for an invalid table, parameters or best_of.
    explicit SnookerSession(SnookerConfig config);

    const SnookerConfig& config() const { return config_; }
    const physics::Table& table() const { return table_; }
    const rules::SnookerTable& marks() const { return marks_; }
    MatchPhase phase() const;
    /// The state before the next stroke (while a choice is pending: as the balls lie).
    const rules::SnookerState& state() const { return state_; }
    std::optional<rules::Player> to_act() const;
    const std::string& name(rules::Player p) const { return config_.names[rules::index(p)]; }
    std::vector<physics::BallState> balls() const;
    /// The after-foul options open to the incoming player (phase choose), else empty.
    const std::vector<rules::AfterFoul>& choices() const { return choices_; }
    /// The state the last stroke was played from.
    const rules::SnookerState& before() const { return before_; }
    /// The verdict of the last stroke (empty before the first stroke of a frame).
    const std::optional<rules::SnookerVerdict>& last_verdict() const { return last_; }
    /// The last stroke's simulation, for playback; null before it and after loading.
    const physics::Shot* last_shot() const { return last_shot_ ? &*last_shot_ : nullptr; }
    const std::array<int, 2>& frames_won() const { return frames_; }
    int frame_number() const { return frame_; }  ///< 0 for the first frame
    /// The frames a player needs to win the match.
    int frames_needed() const { return config_.best_of / 2 + 1; }
    std::optional<rules::Player> frame_winner() const { return frame_winner_; }
    std::optional<rules::Player> match_winner() const;
    rules::Player breaker_of_frame(int n) const;
    /// The points still on the table for the striker (rules::points_remaining).
    int points_remaining() const { return rules::points_remaining(state_); }
    /// The ball on before any nomination.
    rules::BallOn ball_on() const { return rules::ball_on(state_); }
    /// Whether the striker may (colour on, free ball) or must not nominate now.
    bool may_nominate() const;

    // ---- Actions
    /// Why the cue ball in hand may not go to `pos` (none in hand, outside the D, on a ball),
    /// or empty.
    std::optional<std::string> check_cue_ball(physics::Vec2 pos) const;
    void place_cue_ball(physics::Vec2 pos);
    /// Nominates a colour (a colour on) or the free ball (after a foul that left a snooker);
    /// empty withdraws it (a colour on: the first colour hit counts as nominated; a free
    /// ball: declined, the balls on are played).
    void nominate(std::optional<int> ball);
    /// Simulates the stroke on the cue ball, judges it and applies the verdict.
    const rules::SnookerVerdict& play(const physics::Stroke& stroke);
    /// The incoming player's choice after a foul (one of choices()).
    void choose(rules::AfterFoul choice);
    /// Sets up the next frame (phase frame_over), the other player breaking.
    void next_frame();

    // ---- Save and resume
    std::string to_json() const;
    /// Throws game::LoadError naming the field, e.g. "snooker.state.on_table[2]: ...".
    static SnookerSession from_json(const std::string& text);
    void save_file(const std::filesystem::path& path) const;
    static SnookerSession load_file(const std::filesystem::path& path);

  private:
    struct Restored {};
    SnookerSession(SnookerConfig config, Restored);
    void set_up_frame();
    void require_striker(const char* action) const;

    SnookerConfig config_;
    physics::Table table_;
    rules::SnookerTable marks_;
    int frame_ = 0;
    std::array<int, 2> frames_{0, 0};
    rules::SnookerState state_;
    rules::SnookerState before_;  ///< the state the last stroke was played from
    std::vector<rules::AfterFoul> choices_;
    int pending_misses_ = 0;  ///< the verdict's misses, while a choice is pending
    std::optional<rules::Player> frame_winner_;
    std::optional<rules::SnookerVerdict> last_;
    std::optional<physics::Shot> last_shot_;

    friend struct SnookerJson;
};

/// "red", "yellow" … "black", "the cue ball" for ids; "a colour" for BallOn::colour.
std::string snooker_ball_name(int id);
std::string ball_on_name(rules::BallOn on);

}  // namespace game
