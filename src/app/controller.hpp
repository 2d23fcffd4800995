// The game as the player drives it, without a window: the session, the aim, ball in hand,
// calls, choices, computer players, and the playback of each shot. The app turns input into
// these calls and draws what the queries return (update, then draw).
//
//   human:    aim (turn, power, spin) ─▶ strike ─┐
//   computer: decide (beside the frames) ─▶ show aim ─▶ strike with execution noise ─┤
//                                                                               ▼
//             Session::play ─▶ Playback (real time, skippable) ─▶ next turn / choice / game over
#pragma once

#include <array>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "app/aim_preview.hpp"
#include "app/ball_orientations.hpp"
#include "app/playback.hpp"
#include "app/thinking.hpp"
#include "game/carom_session.hpp"
#include "game/match_player.hpp"
#include "game/player.hpp"
#include "game/practice.hpp"
#include "game/session.hpp"
#include "game/shot_link.hpp"
#include "physics/rack.hpp"
#include "render/renderer.hpp"

namespace app {

/// The stroke the player is preparing.
struct Aim {
    double heading_deg = 0.0;    ///< (unit: deg; 0 = +x, 90 = +y)
    double power = 0.45;         ///< the Power slider (unit: 0–1 of max_cue_speed)
    double side = 0.0;           ///< tip offset right of centre (unit: R)
    double top = 0.0;            ///< tip offset above centre (unit: R)
    double elevation_deg = 0.0;  ///< (unit: deg)
};

struct ControllerOptions {
    std::array<std::string, 2> players{"human", "human"};  ///< seat kinds (seats.hpp)
    double noise = 1.0;           ///< execution-noise scale for computer players
    std::uint64_t seed = 1;       ///< computer players' and noise streams
    double playback_speed = 1.0;  ///< shot time per real second; 0: every shot skips to its end
    double computer_aim_seconds = 0.9;  ///< how long the computer's aim is shown before it strikes
};

/// The cue's stroke shown before each shot's playback (unit: s).
inline constexpr double stroke_lead = 0.15;
inline constexpr double min_cue_speed = 0.3;  ///< the Power slider at 0 (unit: m/s)
inline constexpr double max_cue_speed = 8.0;  ///< the Power slider at 1 (unit: m/s)

/// The Power slider's position (0–1) for a cue speed (unit: m/s).
inline double power_of_speed(double speed) {
    const double p = (speed - min_cue_speed) / (max_cue_speed - min_cue_speed);
    return p < 0.0 ? 0.0 : p > 1.0 ? 1.0 : p;
}

class Controller {
  public:
    Controller(game::Session session, ControllerOptions options);
    ~Controller();
    Controller(const Controller&) = delete;
    Controller& operator=(const Controller&) = delete;

    /// Advances by `dt` real seconds: playback, computer players, pending placements.
    void update(double dt);

    // ---- Queries for drawing
    const game::Session& session() const { return session_; }
    const Playback& playback() const { return playback_; }
    const BallOrientations& orientations() const { return orientations_; }
    /// The balls as they lie now: the shot's at the playback time while it plays, else the
    /// session's (pocketed balls left out).
    std::vector<physics::BallState> balls_now() const;
    /// A shot is being played back (the app keeps drawing frames).
    bool moving() const { return playback_.moving(); }
    /// Something will change without input (playback, a computer thinking or aiming).
    bool busy() const;
    /// The human at the keyboard may act now (aim, strike, place, call, choose).
    bool human_to_act() const;
    bool computer_thinking() const { return thinking_.valid() || match_thinking_.valid(); }
    /// Blocks until a computer player thinking now has decided (headless use and tests; the
    /// decision is taken in by the next update()).
    void wait_for_computer() const;
    /// The stroke being prepared (the human's, or the computer's while it shows its aim).
    const Aim& aim() const { return aim_; }
    /// The aim guide and proposed call for the current aim; empty while the balls move.
    const AimPreview* preview() const;
    /// The call the next stroke will have: the player's own, else the proposal from the aim.
    rules::Call call() const;
    bool call_is_manual() const { return manual_call_.has_value(); }
    /// The text of what the last shot did (empty before the first); during a replay, as it was
    /// at the replayed shot's strike.
    const std::string& last_shot_words() const {
        return replaying() ? words_at_strike_ : last_words_;
    }
    /// The last shot is being shown again (the P key, Replay).
    bool replaying() const { return replaying_ && playback_.moving(); }
    /// The pocketed object balls in the tray, in order: while a shot plays, only those that
    /// have dropped by the playback time.
    std::vector<int> tray() const;
    /// The information bar (whose turn, his group, who won: plain_words' info_lines). While a
    /// shot plays it stays as it was at the strike, so that the outcome shows when the balls stop.
    std::vector<std::string> info() const;
    /// Why the stroke as aimed would be a foul, in a player's words (the guide is drawn red and
    /// nothing is proposed as the call), else empty.
    const std::string& aim_foul() const { return aim_foul_; }
    /// Why the last action was refused (shown in the panel), empty when it was not.
    const std::string& refusal() const { return refusal_; }
    /// Increments when a new shot starts playing (the app starts its sound then).
    int shot_serial() const { return shot_serial_; }
    const std::string& seat_kind(rules::Player p) const {
        return options_.players[rules::index(p)];
    }
    /// The stroke `aim` plays: its elevation raised to the rail's where the rail forces the
    /// cue up (cue_clearance.hpp), as for every stroke played.
    physics::Stroke stroke_of(const Aim& aim) const;
    /// The elevation the rail forces on the cue as aimed now (unit: deg; 0: none).
    double forced_elevation_deg() const;

    // ---- Human actions (ignored when it is not a human's turn; refusals go to refusal())
    void turn_aim(double delta_deg);
    void set_heading(double deg);
    void set_power(double power);
    void set_spin(double side, double top);
    void set_elevation(double deg);
    /// Moves the cue ball in hand to `pos`; false (and refusal()) when it may not go there.
    bool move_cue_ball(physics::Vec2 pos);
    /// Why the cue ball in hand may not go to `pos`, or empty.
    std::optional<std::string> check_cue_ball(physics::Vec2 pos) const {
        return snooker_ ? snooker_->check_cue_ball(pos) : session_.check_cue_ball(pos);
    }
    /// A click on the table at `pos` (unit: m): on an object ball, calls it; near a pocket,
    /// calls that pocket (for the called ball, or the proposed one).
    void click_table(physics::Vec2 pos);
    void call_safety();
    void clear_call();
    void set_push_out(bool declare);
    void strike();
    void choose(rules::ChoiceOption option);
    /// Asks the strongest AI what it would play here: its stroke, call and cue-ball placement
    /// become the human's aim (nothing is struck). No-op in a build without the AI.
    void hint();

    // ---- Anyone
    void skip();     ///< the shot being played back jumps to its end
    void replay();   ///< the last shot again from its strike
    void restart();  ///< a new rack (the next game of the session)
    /// Replaces the session (a New Game with other rules or names, or a loaded game).
    void replace(game::Session session, ControllerOptions options);
    /// Plays a shared shot's stroke at once, whoever's seat it is, on a session just set up at
    /// the shot's position (app/shot_sharing.hpp), as any shot: Replay shows it again, and play
    /// goes on from where it left the balls.
    void play_shared(const physics::Stroke& stroke);

    // ---- Practice (docs/app.md, "Practice"): one player, no rules; session() mirrors the
    // practice position (the state's positions, A always to shoot) for drawing and aiming.
    /// Replaces the game by practice at `practice`'s position (both seats human).
    void start_practice(game::Practice practice, ControllerOptions options);
    bool practicing() const { return practice_.has_value(); }
    const game::Practice* practice() const { return practice_ ? &*practice_ : nullptr; }
    /// Practice: moves ball `id` to `pos`; false (and refusal()) where it may not lie.
    bool move_ball(int id, physics::Vec2 pos);
    /// Practice: the position before the last shot again.
    void try_again();
    /// Whether Hint has a player for the table: everywhere but practice on the snooker and
    /// three-cushion tables.
    bool hint_available() const;

    // ---- Snooker and three-cushion (docs/app.md, "Snooker and three-cushion"): the match
    // session holds the game; session() mirrors its table (the balls, the striker, a cue ball in
    // hand) so that drawing, aiming and the aim guide work as in pool.
    /// Seats whose kind has a player for the game (app/seats.hpp: snooker_computer,
    /// carom_computer) are played by it; the others are human.
    void start_snooker(game::SnookerSession match, ControllerOptions options);
    void start_carom(game::CaromSession match, ControllerOptions options);
    const game::SnookerSession* snooker() const { return snooker_ ? &*snooker_ : nullptr; }
    const game::CaromSession* carom() const { return carom_ ? &*carom_ : nullptr; }
    /// The balls and cloth marks to draw.
    render::GameLook look() const;
    /// The ball the stroke strikes: 0, or the yellow (1) of three-cushion's second player.
    int cue_ball_id() const { return carom_ ? carom_->cue_ball() : 0; }
    /// Snooker: the nomination the next stroke will have: the player's own, else the colour
    /// (or free ball) the aim meets first; empty when nothing is nominated.
    std::optional<int> nomination() const;
    bool nomination_is_manual() const { return manual_nomination_.has_value(); }
    /// Snooker: nominates `ball` (a click on it, or the panel's list); empty: back to the
    /// nomination proposed from the aim.
    void nominate(std::optional<int> ball);
    /// Snooker: the incoming player's choice after a foul.
    void choose_after_foul(rules::AfterFoul choice);
    /// Snooker: the next frame; three-cushion: the next game.
    void next_frame();
    /// The last stroke of a match and where its cue ball lay (the cue's stroke drawn before
    /// playback); empty in pool (the session's history has it) and before the first stroke.
    struct StrokeShown {
        physics::Vec2 cue_ball;
        physics::Stroke stroke;
    };
    const std::optional<StrokeShown>& match_stroke() const { return match_stroke_; }
    /// The match's last stroke as a shot to share (the match just before it, and the stroke);
    /// empty in pool, before the first stroke and in a new frame or game.
    const std::optional<game::AnyShot>& last_match_shot() const { return last_match_shot_; }

  private:
    /// `nominate_now`: the nomination is taken from the aim (or the player's own) first; a
    /// shared shot's session already holds its nomination.
    void play_match(const physics::Stroke& stroke, bool nominate_now = true);
    /// After any game's stroke was played: its playback starts, and what the panel said before
    /// it (`info_before`, the last shot's words) is kept for Replay.
    void start_playback(const physics::Shot& shot, std::vector<std::string> info_before);
    void finish_match_shot();
    /// A computer seat's turn in a match: thinking, then its aim shown, then the stroke; false
    /// when there is none.
    bool update_match_computer(double dt);
    void apply_match_computer(const game::MatchDecision& d);
    /// Hint in a match: the level-5 player's decision, seeded `seed`, becomes the aim.
    void match_hint(std::uint64_t seed);
    void apply_match_hint(const game::MatchDecision& d);
    bool match_computer_to_act() const;
    void mirror_match();
    void begin_match_turn();
    /// Aims at the nearest of `targets` that the cue ball can hit with a clear path (full or
    /// thin), else the nearest.
    void aim_at_open_ball(const std::vector<int>& targets);
    std::vector<std::string> match_info() const;
    physics::Vec2 default_d_spot() const;
    void play_practice(const physics::Stroke& stroke);
    void finish_practice_shot();
    void mirror_practice();
    /// The balls the aim turns to at a practice turn on the snooker and three-cushion tables:
    /// the reds while there are any, the red (as the opening stroke); else every ball (on the
    /// pool tables the rules' legal targets are).
    std::vector<int> practice_targets() const;
    void begin_turn();
    void refresh_preview();
    void play(const physics::Stroke& stroke);
    /// `stroke` as the cue can play it from where the cue ball lies (over_the_rail).
    physics::Stroke played(const physics::Stroke& stroke) const;
    void finish_shot();
    void prepare_human_ball_in_hand();
    void launch_computer();
    void apply_computer(const game::Decision& d);
    void apply_hint(const game::Decision& d);
    void stop_thinking();
    physics::Vec2 default_cue_spot() const;
    void aim_at_target();

    game::Session session_;
    ControllerOptions options_;
    std::array<std::unique_ptr<game::Player>, 2> computers_;
    physics::SplitMix64 noise_rng_;
    Playback playback_;
    BallOrientations orientations_;
    BallOrientations at_strike_;  ///< the orientations when the shot on show was struck (replays)
    Aim aim_;
    Aim human_aim_;  ///< the humans' power, spin and elevation, kept while a computer aims
    std::optional<AimPreview> preview_;
    std::optional<rules::Call> manual_call_;
    Thinking<game::Decision> thinking_;
    std::optional<game::Decision> computer_decision_;  ///< decided, shown before the strike
    std::unique_ptr<game::Player> hint_player_;        ///< the AI asked for a hint
    bool hinting_ = false;  ///< thinking_ (in a match, match_thinking_) is a hint for the human
    int hints_ = 0;
    double computer_aim_left_ = 0.0;
    bool settled_ = true;  ///< the last shot's playback has reached its end and been taken in
    int dry_shots_ = 0;    ///< computer-only games: shots with no ball down (stalemate rule)
    std::string last_words_;
    std::vector<std::string> info_at_strike_;  ///< info() while the last shot plays
    std::string words_at_strike_;              ///< last_shot_words() at its strike
    bool replaying_ = false;
    std::string refusal_;
    std::string aim_foul_;
    int shot_serial_ = 0;
    std::optional<game::Practice> practice_;
    std::optional<game::SnookerSession> snooker_;
    std::optional<game::CaromSession> carom_;
    std::optional<int> manual_nomination_;  ///< the player's own nomination
    std::array<std::optional<game::SnookerPlayer>, 2> snooker_players_;  ///< computer seats
    std::array<std::optional<game::CaromPlayer>, 2> carom_players_;
    Thinking<game::MatchDecision> match_thinking_;
    std::optional<game::MatchDecision> match_decision_;  ///< decided, shown before the strike
    std::optional<StrokeShown> match_stroke_;
    std::optional<game::AnyShot> last_match_shot_;
};

}  // namespace app
