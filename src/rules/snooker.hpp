// Snooker (WPBSA Official Rules of Snooker): a pure function of the state before a shot and
// the shot's events, like 8-ball and 9-ball (docs/rules.md, "Snooker"). Ball ids:
// physics/markings.hpp (0 cue ball, 1–15 reds, 16 yellow … 21 black).
#pragma once

#include <array>
#include <map>
#include <optional>
#include <set>
#include <span>
#include <vector>

#include "physics/event.hpp"
#include "physics/markings.hpp"
#include "rules/game_state.hpp"

namespace rules {

struct SnookerOptions {
    bool miss_rule = true;  ///< WPBSA S3 R14; off: a casual game, no miss is called
    friend bool operator==(const SnookerOptions&, const SnookerOptions&) = default;
};

/// What the table and the rules need to know of it: its marks and the ball radius.
struct SnookerTable {
    physics::SnookerMarkings marks;
    double ball_radius = 0.02625;  ///< R (unit: m)
};

/// The ball (or kind of ball) the striker must hit first.
enum class BallOn { red, colour, yellow, green, brown, blue, pink, black };

struct SnookerState {
    Player shooter = Player::A;
    std::set<int> on_table;               ///< object balls on the table (1–21)
    CueBall cue_ball = CueBall::in_hand;  ///< `in_hand`: to be placed in the D
    bool colour_on = false;        ///< a red (or a free ball as a red) was potted: a colour is on
    std::optional<int> nominated;  ///< the nominated colour, or the free ball
    bool free_ball = false;        ///< this shot is a free ball: `nominated` acts as the ball on
    bool respotted_black = false;  ///< the frame is decided on a re-spotted black
    std::array<int, 2> scores{0, 0};  ///< by index(Player)
    int break_points = 0;             ///< the shooter's points in this visit
    int misses = 0;  ///< misses in a row with a ball on in full view, the balls replaced (0–2)
    std::map<int, physics::Vec2> positions;  ///< ball centres (unit: m); key 0 the cue ball

    int score(Player p) const { return scores[index(p)]; }
    bool has(int ball) const { return on_table.count(ball) != 0; }
    int reds() const;
};

/// The fouls, in their canonical order (docs/rules.md, "Snooker").
enum class SnookerFoul {
    in_off,                  ///< the cue ball was pocketed
    cue_ball_off_table,      ///< the cue ball left the table
    no_contact,              ///< the cue ball hit no ball (stands alone)
    wrong_ball_first,        ///< the first ball hit was not on
    ball_not_on_potted,      ///< a ball not on was potted (two balls where not allowed too)
    ball_off_table,          ///< an object ball left the table
    push_stroke,             ///< the cue ball met a ball while the tip was still on it
    snookered_by_free_ball,  ///< the free ball left the incoming striker snookered (S3 R12)
};

/// A colour put back after the shot, and where: its own spot, another colour's spot, or as
/// near as possible to its own spot (`spot` empty).
struct Respot {
    int ball = 0;
    std::optional<int> spot;  ///< the colour whose spot it went to
    physics::Vec2 pos;
    friend bool operator==(const Respot&, const Respot&) = default;
};

struct SnookerVerdict {
    bool foul = false;
    std::vector<SnookerFoul> fouls;
    int foul_points = 0;                 ///< to the opponent
    int points_scored = 0;               ///< by the striker
    std::optional<Player> next_shooter;  ///< empty when the frame is over
    std::vector<Respot> respotted;
    BallOn ball_on = BallOn::red;      ///< for the next stroke
    bool free_ball = false;            ///< the next striker is snookered after a foul
    std::optional<int> touching_ball;  ///< the cue ball rests touching this ball
    bool miss = false;                 ///< foul and a miss
    int misses = 0;  ///< the striker's misses in a row with a ball on in full view (3: frame lost)
    bool may_ask_to_play_again = false;
    bool frame_over = false;
    std::optional<Player> winner;
    bool respotted_black = false;  ///< a tie on the last black: the black is re-spotted
    SnookerState state;            ///< before the next stroke ("play" taken after a foul)

    bool has(SnookerFoul f) const;
};

/// The balls on for a state (before any nomination): reds, the colours, or the lowest colour.
BallOn ball_on(const SnookerState& s);
/// The points left on the table for the striker (8 a red with the black, and the colours).
int points_remaining(const SnookerState& s);

/// Judges one stroke. `s` must be consistent (the CLI checks it).
SnookerVerdict judge_snooker(const SnookerOptions& options, const SnookerTable& table,
                             const SnookerState& s, std::span<const physics::Event> events);

/// After a foul the incoming player may play, ask the offender to play again from where the
/// balls lie, or (after a miss) from where they lay before the stroke.
enum class AfterFoul { play, play_again, replace };
/// The state before the next stroke for that choice; `before` is the state the stroke was
/// played from. Throws std::invalid_argument if the choice is not open.
SnookerState resolve_after_foul(const SnookerVerdict& v, const SnookerState& before,
                                AfterFoul choice);

}  // namespace rules
