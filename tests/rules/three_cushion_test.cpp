// Three-cushion scenarios from the UMB rules: each names the article's subject it checks.
#include "rules/three_cushion.hpp"

#include <gtest/gtest.h>

#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "physics/markings.hpp"
#include "physics/table.hpp"
#include "scenario.hpp"

namespace rules::test {
namespace {

using F = CaromFoul;
constexpr int W = 0, Yl = 1, Rd = 2;

Event strike(int ball = W) {
    return event(EventType::strike, {ball});
}

CaromState normal(Player shooter = A, std::array<int, 2> scores = {3, 2}) {
    CaromState s;
    s.shooter = shooter;
    s.starter = A;
    s.opening = false;
    s.scores = scores;
    s.innings = {5, shooter == A ? 4 : 5};
    return s;
}

struct Case {
    std::string name;
    std::string rule;
    CaromState state;
    std::vector<Event> events;
    bool point;
    std::vector<F> fouls;
    std::optional<Player> next;  ///< empty: game over
    std::array<int, 2> scores;
    std::array<int, 2> innings;
    CaromOptions options = {};
    std::function<void(const CaromVerdict&)> more = {};
};

std::ostream& operator<<(std::ostream& os, const Case& c) {
    return os << c.name << " (" << c.rule << ")";
}

std::vector<Case> cases() {
    const auto O = std::nullopt;
    std::vector<Case> list = {
        {"three_cushions_then_second_ball",
         "UMB point",
         normal(),
         {strike(), hit(0, Rd), rail(0), rail(0), rail(0), hit(0, Yl)},
         true,
         {},
         A,
         {4, 2},
         {5, 4}},
        {"cushions_before_first_ball_count",
         "UMB point",
         normal(),
         {strike(), rail(0), rail(0), rail(0), hit(0, Rd), hit(0, Yl)},
         true,
         {},
         A,
         {4, 2},
         {5, 4}},
        {"same_cushion_twice_counts",
         "UMB point",
         normal(),
         {strike(), hit(0, Yl), rail(0), rail(0), rail(0), hit(0, Rd)},
         true,
         {},
         A,
         {4, 2},
         {5, 4}},
        {"split_cushions_count",
         "UMB point",
         normal(),
         {strike(), rail(0), hit(0, Rd), rail(0), rail(0), hit(0, Yl)},
         true,
         {},
         A,
         {4, 2},
         {5, 4}},
        {"two_cushions_no_point",
         "UMB point",
         normal(),
         {strike(), hit(0, Rd), rail(0), rail(0), hit(0, Yl)},
         false,
         {},
         B,
         {3, 2},
         {5, 5}},
        {"cushion_after_second_ball_not_counted",
         "UMB point",
         normal(),
         {strike(), hit(0, Rd), rail(0), rail(0), hit(0, Yl), rail(0)},
         false,
         {},
         B,
         {3, 2},
         {5, 5},
         {},
         [](const CaromVerdict& v) { EXPECT_EQ(v.cushions, 2); }},
        {"one_ball_only_no_point",
         "UMB point",
         normal(),
         {strike(), hit(0, Rd), rail(0), rail(0), rail(0), rail(0)},
         false,
         {},
         B,
         {3, 2},
         {5, 5}},
        {"no_ball_no_point",
         "UMB point",
         normal(),
         {strike(), rail(0), rail(0), rail(0)},
         false,
         {},
         B,
         {3, 2},
         {5, 5}},
        {"object_ball_cushions_do_not_count",
         "UMB point",
         normal(),
         {strike(), hit(0, Rd), rail(2), rail(2), rail(2), hit(0, Yl)},
         false,
         {},
         B,
         {3, 2},
         {5, 5}},
        {"kiss_between_object_balls_does_not_count",
         "UMB point",
         normal(),
         {strike(), hit(0, Rd), hit(2, Yl), rail(0), rail(0), rail(0)},
         false,
         {},
         B,
         {3, 2},
         {5, 5}},
        {"second_ball_met_twice_first_counts",
         "UMB point",
         normal(),
         {strike(), hit(0, Rd), rail(0), hit(0, Yl), rail(0), rail(0), hit(0, Yl)},
         false,
         {},
         B,
         {3, 2},
         {5, 5}},
        {"b_plays_yellow",
         "UMB cue ball",
         normal(B),
         {strike(Yl), hit(1, Rd), rail(1), rail(1), rail(1), hit(1, W)},
         true,
         {},
         B,
         {3, 3},
         {5, 5}},
        {"wrong_cue_ball_foul",
         "UMB fouls (wrong cue ball)",
         normal(B),
         {strike(W), hit(0, Rd), rail(0), rail(0), rail(0), hit(0, Yl)},
         false,
         {F::wrong_cue_ball},
         A,
         {3, 2},
         {6, 5}},
        {"wrong_cue_ball_a",
         "UMB fouls (wrong cue ball)",
         normal(A),
         {strike(Yl), hit(1, Rd)},
         false,
         {F::wrong_cue_ball},
         B,
         {3, 2},
         {5, 5}},
        {"ball_off_table_foul",
         "UMB fouls (ball off the table)",
         normal(),
         {strike(), hit(0, Rd), off(2)},
         false,
         {F::ball_off_table},
         B,
         {3, 2},
         {5, 5},
         {},
         [](const CaromVerdict& v) { EXPECT_EQ(v.respotted, std::vector<int>{Rd}); }},
        {"point_with_ball_off_table_is_foul",
         "UMB fouls (ball off the table)",
         normal(),
         {strike(), hit(0, Rd), rail(0), rail(0), rail(0), hit(0, Yl), off(1)},
         false,
         {F::ball_off_table},
         B,
         {3, 2},
         {5, 5}},
        {"push_double_hit_foul",
         "UMB fouls (push, double hit)",
         normal(),
         [] {
             auto s = strike();
             auto h = hit(0, Rd);
             h.time = 0.0005;
             return std::vector<Event>{s, h, rail(0), rail(0), rail(0), hit(0, Yl)};
         }(),
         false,
         {F::push_stroke},
         B,
         {3, 2},
         {5, 5}},
        {"opening_must_hit_red_first",
         "UMB opening stroke",
         CaromState{},
         {strike(), hit(0, Yl), rail(0), rail(0), rail(0), hit(0, Rd)},
         false,
         {F::red_not_first},
         B,
         {0, 0},
         {1, 1}},
        {"opening_point_on_red_first",
         "UMB opening stroke",
         CaromState{},
         {strike(), hit(0, Rd), rail(0), rail(0), rail(0), hit(0, Yl)},
         true,
         {},
         A,
         {1, 0},
         {1, 0},
         {},
         [](const CaromVerdict& v) { EXPECT_FALSE(v.state.opening); }},
        {"run_and_high_run",
         "UMB innings",
         [] {
             auto s = normal();
             s.run = 4;
             s.high_run = {4, 1};
             return s;
         }(),
         {strike(), hit(0, Rd), rail(0), rail(0), rail(0), hit(0, Yl)},
         true,
         {},
         A,
         {4, 2},
         {5, 4},
         {},
         [](const CaromVerdict& v) {
             EXPECT_EQ(v.state.run, 5);
             EXPECT_EQ(v.state.high_run[0], 5);
         }},
        {"miss_ends_run",
         "UMB innings",
         [] {
             auto s = normal();
             s.run = 4;
             return s;
         }(),
         {strike(), hit(0, Rd)},
         false,
         {},
         B,
         {3, 2},
         {5, 5},
         {},
         [](const CaromVerdict& v) { EXPECT_EQ(v.state.run, 0); }},
        {"target_reached_wins",
         "UMB game length",
         normal(A, {14, 9}),
         {strike(), hit(0, Rd), rail(0), rail(0), rail(0), hit(0, Yl)},
         true,
         {},
         O,
         {15, 9},
         {5, 4},
         {},
         [](const CaromVerdict& v) {
             EXPECT_TRUE(v.game_over);
             EXPECT_EQ(v.winner, A);
         }},
        {"target_option",
         "UMB game length",
         normal(A, {4, 2}),
         {strike(), hit(0, Rd), rail(0), rail(0), rail(0), hit(0, Yl)},
         true,
         {},
         O,
         {5, 2},
         {5, 4},
         {.target = 5}},
        {"equal_innings_second_player_equalizes",
         "UMB equal innings",
         normal(A, {14, 9}),
         {strike(), hit(0, Rd), rail(0), rail(0), rail(0), hit(0, Yl)},
         true,
         {},
         B,
         {15, 9},
         {5, 5},
         {.target = 15, .equal_innings = true},
         [](const CaromVerdict& v) {
             EXPECT_FALSE(v.game_over);
             EXPECT_TRUE(v.state.equalizing);
         }},
        {"equal_innings_second_player_reaching_wins",
         "UMB equal innings",
         normal(B, {10, 14}),
         {strike(Yl), hit(1, Rd), rail(1), rail(1), rail(1), hit(1, W)},
         true,
         {},
         O,
         {10, 15},
         {5, 5},
         {.target = 15, .equal_innings = true},
         [](const CaromVerdict& v) { EXPECT_EQ(v.winner, B); }},
        {"equalizing_inning_fails_starter_wins",
         "UMB equal innings",
         [] {
             auto s = normal(B, {15, 12});
             s.equalizing = true;
             return s;
         }(),
         {strike(Yl), hit(1, Rd)},
         false,
         {},
         O,
         {15, 12},
         {5, 5},
         {.target = 15, .equal_innings = true},
         [](const CaromVerdict& v) { EXPECT_EQ(v.winner, A); }},
        {"equalizing_inning_equalizes_draw",
         "UMB equal innings",
         [] {
             auto s = normal(B, {15, 14});
             s.equalizing = true;
             return s;
         }(),
         {strike(Yl), hit(1, Rd), rail(1), rail(1), rail(1), hit(1, W)},
         true,
         {},
         O,
         {15, 15},
         {5, 5},
         {.target = 15, .equal_innings = true},
         [](const CaromVerdict& v) {
             EXPECT_TRUE(v.game_over);
             EXPECT_FALSE(v.winner.has_value());
         }},
    };
    return list;
}

class CaromScenario : public ::testing::TestWithParam<Case> {};

TEST_P(CaromScenario, Verdict) {
    const Case& c = GetParam();
    const physics::Table t = physics::build_table(physics::carom_table_spec());
    const CaromVerdict v =
        judge_three_cushion(c.options, physics::carom_spots(t), 0.03075, c.state, c.events);
    EXPECT_EQ(v.point, c.point);
    EXPECT_EQ(v.fouls, c.fouls);
    EXPECT_EQ(v.foul, !c.fouls.empty());
    EXPECT_EQ(v.next_shooter, c.next);
    EXPECT_EQ(v.game_over, !c.next.has_value());
    EXPECT_EQ(v.state.scores, c.scores);
    EXPECT_EQ(v.state.innings, c.innings);
    if (c.more) c.more(v);
}

INSTANTIATE_TEST_SUITE_P(Umb, CaromScenario, ::testing::ValuesIn(cases()),
                         [](const auto& param_info) { return param_info.param.name; });

}  // namespace
}  // namespace rules::test
