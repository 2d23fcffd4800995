// The state of a game before a shot: who shoots, what is on the table, what was called, and the
// counters the rules carry from shot to shot (docs/rules.md; JSON schema in docs/cli.md).
#pragma once

#include <array>
#include <cstddef>
#include <map>
#include <optional>
#include <set>

#include "physics/vec.hpp"

namespace rules {

enum class Game { eight_ball, nine_ball };

enum class Player { A, B };
constexpr Player other(Player p) {
    return p == Player::A ? Player::B : Player::A;
}
constexpr std::size_t index(Player p) {
    return p == Player::A ? 0 : 1;
}

/// 8-ball groups: solids 1–7, stripes 9–15.
enum class Group { solids, stripes };
constexpr Group other(Group g) {
    return g == Group::solids ? Group::stripes : Group::solids;
}
/// The group of a ball; empty for the cue ball and the 8.
constexpr std::optional<Group> group_of(int ball) {
    if (ball >= 1 && ball <= 7) return Group::solids;
    if (ball >= 9 && ball <= 15) return Group::stripes;
    return std::nullopt;
}

/// Which kind of shot comes next.
enum class Shot {
    break_shot,      ///< "break"
    after_break,     ///< the first shot after a break without a foul (9-ball: push-out allowed)
    push_out,        ///< a declared 9-ball push-out
    after_push_out,  ///< the shot after a push-out
    normal,
};

/// Where the cue ball is before the shot.
enum class CueBall {
    on_table,         ///< where it lies
    in_hand,          ///< to be placed anywhere
    in_hand_kitchen,  ///< to be placed behind the head string (x < L/4)
};

/// The shooter's call: nothing, a safety, or a ball and a pocket.
struct Call {
    enum class Kind { none, safety, ball };
    Kind kind = Kind::none;
    int ball = 0;     ///< the called object ball (kind == ball)
    int pocket = -1;  ///< the called pocket, physics::PocketId (kind == ball)

    static constexpr Call nothing() { return {}; }
    static constexpr Call safety() { return {Kind::safety, 0, -1}; }
    static constexpr Call ball_in(int ball_id, int pocket_id) {
        return {Kind::ball, ball_id, pocket_id};
    }
    constexpr bool is_ball() const { return kind == Kind::ball; }
    constexpr bool is_safety() const { return kind == Kind::safety; }
    friend constexpr bool operator==(const Call&, const Call&) = default;
};

struct GameState {
    Player shooter = Player::A;
    Player breaker = Player::A;  ///< who broke this rack
    Shot shot = Shot::break_shot;
    std::optional<Group> group_a;  ///< player A's group (B has the other); empty: open table
    std::set<int> on_table;  ///< object balls on the table (1–15); the cue ball is `cue_ball`
    CueBall cue_ball = CueBall::in_hand_kitchen;
    Call call;
    std::array<int, 2> fouls_in_row{0, 0};  ///< consecutive fouls, by index(Player)
    std::array<bool, 2> warned{false,
                               false};  ///< warned of a third foul (9-ball), by index(Player)
    /// Ball centres at the start of the shot (unit: m); may be partial. Key 0 is the cue ball.
    std::map<int, physics::Vec2> positions;

    std::optional<Group> group(Player p) const {
        if (!group_a) return std::nullopt;
        return p == Player::A ? *group_a : other(*group_a);
    }
    int fouls(Player p) const { return fouls_in_row[index(p)]; }
    bool is_warned(Player p) const { return warned[index(p)]; }
    bool has(int ball) const { return on_table.count(ball) != 0; }
};

/// A freshly racked table before the break: all object balls of the game on the table, cue ball
/// in hand in the kitchen, `breaker` to shoot. Counters start at zero.
GameState initial_state(Game game, Player breaker);

/// The object balls of a game: 1–15 (8-ball) or 1–9 (9-ball).
int highest_ball(Game game);

/// 8-ball: the shooter's group is assigned and none of its balls is left (he is "on the 8").
bool on_the_eight(const GameState& s);

/// 9-ball: a push-out may be declared on this shot (the shot right after a foul-free break).
bool push_out_allowed(Game game, const GameState& s);

}  // namespace rules
