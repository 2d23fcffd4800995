// Test helpers for the rules: hand-made events, a state builder, and table-driven scenarios
// whose expectations name every field of the verdict.
#pragma once

#include <gtest/gtest.h>

#include <functional>
#include <limits>
#include <optional>
#include <ostream>
#include <set>
#include <string>
#include <vector>

#include "physics/event.hpp"
#include "physics/table.hpp"
#include "rules/judge.hpp"
#include "rules/names.hpp"

namespace rules::test {

using physics::Event;
using physics::EventType;
using P = physics::PocketId;

inline constexpr double nan = std::numeric_limits<double>::quiet_NaN();
inline constexpr Player A = Player::A;
inline constexpr Player B = Player::B;

inline int pocket(P p) {
    return static_cast<int>(p);
}

// Events without positions carry NaN (as the CLI reads an event without "pos").
inline Event event(EventType type, std::initializer_list<int> balls) {
    Event e;
    e.type = type;
    e.ball_count = static_cast<std::uint8_t>(balls.size());
    std::size_t k = 0;
    for (int id : balls) e.balls[k++] = {id, {nan, nan}, {}, {}};
    return e;
}
inline Event hit(int a, int b) {
    return event(EventType::ball_ball, {a, b});
}
inline Event rail(int ball) {
    return event(EventType::cushion, {ball});
}
inline Event pot(int ball, P p) {
    Event e = event(EventType::pocket, {ball});
    e.pocket = pocket(p);
    return e;
}
inline Event off(int ball) {
    return event(EventType::off_table, {ball});
}
inline Event roll(int ball) {
    return event(EventType::transition, {ball});
}
/// The same event with its first ball (and its second) at the given positions.
inline Event at(Event e, physics::Vec2 p0) {
    e.balls[0].pos = p0;
    return e;
}
inline Event at(Event e, physics::Vec2 p0, physics::Vec2 p1) {
    e.balls[0].pos = p0;
    e.balls[1].pos = p1;
    return e;
}

/// The events of a break that sends balls 1–4 to a cushion (the break requirement).
inline std::vector<Event> four_rail_break(int first = 1) {
    return {hit(0, first), rail(1), rail(2), rail(3), rail(4)};
}

/// A state, built field by field.
class StateBuilder {
  public:
    explicit StateBuilder(GameState s) : s_(std::move(s)) {}
    StateBuilder& shooter(Player p) {
        s_.shooter = p;
        return *this;
    }
    StateBuilder& breaker(Player p) {
        s_.breaker = p;
        return *this;
    }
    StateBuilder& shot(Shot k) {
        s_.shot = k;
        return *this;
    }
    StateBuilder& group_a(Group g) {
        s_.group_a = g;
        return *this;
    }
    StateBuilder& balls(std::set<int> ids) {
        s_.on_table = std::move(ids);
        return *this;
    }
    StateBuilder& cue(CueBall c) {
        s_.cue_ball = c;
        return *this;
    }
    StateBuilder& call(int ball, P p) {
        s_.call = Call::ball_in(ball, pocket(p));
        return *this;
    }
    StateBuilder& safety() {
        s_.call = Call::safety();
        return *this;
    }
    StateBuilder& fouls(int a, int b) {
        s_.fouls_in_row = {a, b};
        return *this;
    }
    StateBuilder& warned(bool a, bool b) {
        s_.warned = {a, b};
        return *this;
    }
    StateBuilder& pos(int id, double x, double y) {
        s_.positions[id] = {x, y};
        return *this;
    }
    operator GameState() const { return s_; }
    const GameState& get() const { return s_; }

  private:
    GameState s_;
};

inline std::set<int> range(int lo, int hi) {
    std::set<int> ids;
    for (int i = lo; i <= hi; ++i) ids.insert(i);
    return ids;
}
inline std::set<int> all_but(int highest, std::set<int> gone) {
    std::set<int> ids;
    for (int i = 1; i <= highest; ++i)
        if (!gone.count(i)) ids.insert(i);
    return ids;
}

/// 8-ball, before the break (A breaks).
inline StateBuilder eight_break() {
    return StateBuilder(initial_state(Game::eight_ball, A));
}
/// 8-ball, open table after the break, A to shoot with the cue ball on the table and ball 3
/// called in the SW pocket.
inline StateBuilder eight_open() {
    return StateBuilder(initial_state(Game::eight_ball, A))
        .shot(Shot::normal)
        .cue(CueBall::on_table)
        .call(3, P::SW);
}
/// 8-ball, A has solids, B stripes; A to shoot.
inline StateBuilder eight_groups() {
    return eight_open().group_a(Group::solids);
}
/// 8-ball, A has solids and has cleared them: on the 8, the 8 called in NE.
inline StateBuilder eight_on_eight() {
    return eight_open().group_a(Group::solids).balls({8, 9, 10, 11}).call(8, P::NE);
}
/// 9-ball, before the break (A breaks).
inline StateBuilder nine_break() {
    return StateBuilder(initial_state(Game::nine_ball, A));
}
/// 9-ball, A to shoot, cue ball on the table, all balls up.
inline StateBuilder nine_table() {
    return StateBuilder(initial_state(Game::nine_ball, A))
        .shot(Shot::normal)
        .cue(CueBall::on_table);
}

/// What a verdict must say; every field is compared.
struct Expect {
    std::vector<Foul> fouls{};
    bool turn_passes = false;
    std::optional<Player> next{};
    BallInHand ball_in_hand = BallInHand::none;
    std::optional<Group> group_a{};
    std::vector<int> respot{};
    std::optional<Choice> choice{};
    std::optional<Player> winner{};  ///< set: the game is over
    BreakResult break_result = BreakResult::none;
};

struct Scenario {
    std::string name;
    Ruleset rules;
    GameState before;
    std::vector<Event> events;
    Expect expect;
    /// Further checks, e.g. of the next state.
    std::function<void(const Verdict&)> also = nullptr;
};

inline Ruleset eight_ball(Options o = {}) {
    return {Game::eight_ball, o, {}};
}
inline Ruleset nine_ball() {
    return {Game::nine_ball, {}, {}};
}

inline std::string describe(const std::vector<Foul>& fouls) {
    std::string s = "[";
    for (Foul f : fouls) {
        if (s.size() > 1) s.append(", ");
        s.append(name(f));
    }
    s.append("]");
    return s;
}
inline std::string describe(const std::optional<Choice>& c) {
    if (!c) return "null";
    std::string s = "{by ";
    s.append(name(c->by));
    s.append(":");
    for (ChoiceOption o : c->options) {
        s.append(" ");
        s.append(name(o));
    }
    s.append("}");
    return s;
}
template <typename E>
std::string describe(const std::optional<E>& e) {
    return e ? std::string(name(*e)) : "null";
}

/// Checks a verdict against an expectation and the invariants of the contract.
inline void check(const Verdict& v, const Expect& x) {
    EXPECT_EQ(describe(v.fouls), describe(x.fouls));
    EXPECT_EQ(v.foul, !x.fouls.empty());
    EXPECT_EQ(v.turn_passes, x.turn_passes);
    EXPECT_EQ(describe(v.next_shooter), describe(x.next));
    EXPECT_EQ(name(v.ball_in_hand), name(x.ball_in_hand));
    EXPECT_EQ(describe(v.group_a), describe(x.group_a));
    EXPECT_EQ(v.respot, x.respot);
    EXPECT_EQ(describe(v.choice), describe(x.choice));
    EXPECT_EQ(v.game_over, x.winner.has_value());
    EXPECT_EQ(describe(v.winner), describe(x.winner));
    EXPECT_EQ(name(v.break_result), name(x.break_result));

    // Invariants of the contract.
    if (v.choice || v.game_over) {
        EXPECT_FALSE(v.next_shooter.has_value());
    }
    if (v.game_over) {
        EXPECT_EQ(v.ball_in_hand, BallInHand::none);
    }
    if (v.next_shooter) {
        EXPECT_EQ(v.state.shooter, *v.next_shooter);
    }
    if (!v.game_over) {
        EXPECT_EQ(v.state.group_a, v.group_a);
        EXPECT_EQ(v.state.call, Call::nothing());
        const bool in_hand = v.state.cue_ball != CueBall::on_table;
        EXPECT_EQ(in_hand, v.ball_in_hand != BallInHand::none);
        if (v.ball_in_hand == BallInHand::kitchen) {
            EXPECT_EQ(v.state.cue_ball, CueBall::in_hand_kitchen);
        }
        for (int id : v.respot) EXPECT_TRUE(v.state.has(id)) << "respotted ball " << id;
    }
}

inline void PrintTo(const Scenario& s, std::ostream* os) {
    *os << s.name;
}

/// The scenario's verdict, checked.
inline Verdict run(const Scenario& s) {
    Verdict v = judge(s.rules, s.before, s.events);
    check(v, s.expect);
    if (s.also) s.also(v);
    return v;
}

inline std::string scenario_name(const ::testing::TestParamInfo<Scenario>& info) {
    return info.param.name;
}

}  // namespace rules::test
