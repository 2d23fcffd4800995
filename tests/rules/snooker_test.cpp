// Snooker scenarios from the WPBSA Official Rules of Snooker: each names the rule it checks
// (S3 R10 Penalties, S3 R12 Snookered after a Foul, S3 R14 Foul and a Miss, S2 R13 Free Ball,
// S2 R14 Forced off the Table; other rules by their title).
#include "rules/snooker.hpp"

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

namespace sb = physics::snooker_ball;
using F = SnookerFoul;

constexpr int Y = sb::yellow, G = sb::green, BR = sb::brown, BL = sb::blue, PK = sb::pink,
              BK = sb::black;

SnookerTable table() {
    const physics::Table t = physics::build_table(physics::snooker_table_spec());
    return {physics::snooker_markings(t), 0.02625};
}

/// `reds` reds (ids 1…) and every colour from `lowest` on the table; A to play, 20–20.
SnookerState with(int reds, int lowest = Y) {
    SnookerState s;
    s.cue_ball = CueBall::on_table;
    for (int r = 1; r <= reds; ++r) s.on_table.insert(r);
    for (int c = lowest; c <= BK; ++c) s.on_table.insert(c);
    s.scores = {20, 20};
    return s;
}
SnookerState on_colour(int reds, std::optional<int> nominated) {
    SnookerState s = with(reds);
    s.colour_on = true;
    s.nominated = nominated;
    return s;
}
SnookerState free_ball(int reds, int nominated, int lowest = Y) {
    SnookerState s = with(reds, lowest);
    s.free_ball = true;
    s.nominated = nominated;
    return s;
}
SnookerState scores(SnookerState s, int a, int b) {
    s.scores = {a, b};
    return s;
}

Event strike() {
    return event(EventType::strike, {0});
}
Event pot(int ball) {
    return test::pot(ball, P::NE);
}

struct Case {
    std::string name;
    std::string rule;
    SnookerState state;
    std::vector<Event> events;
    bool foul;
    std::vector<F> fouls;
    int foul_points;
    int points;
    std::optional<Player> next;
    std::optional<BallOn> on;  ///< empty: frame over
    std::function<void(const SnookerVerdict&)> more = {};
};

std::ostream& operator<<(std::ostream& os, const Case& c) {
    return os << c.name << " (" << c.rule << ")";
}

std::vector<Case> cases() {
    const auto O = std::nullopt;
    using enum BallOn;
    std::vector<Case> list = {
        // Reds and colours (S3 'Mode of Play').
        {"red_potted_continues",
         "S3 Mode of Play",
         with(15),
         {strike(), hit(0, 1), pot(1)},
         false,
         {},
         0,
         1,
         A,
         colour},
        {"two_reds_score_two",
         "S3 Mode of Play",
         with(15),
         {strike(), hit(0, 1), pot(1), pot(2)},
         false,
         {},
         0,
         2,
         A,
         colour},
        {"red_missed_pocket_turn_passes",
         "S3 Mode of Play",
         with(15),
         {strike(), hit(0, 1), rail(1)},
         false,
         {},
         0,
         0,
         B,
         red},
        {"nominated_colour_potted",
         "S3 Mode of Play",
         on_colour(14, BK),
         {strike(), hit(0, BK), pot(BK)},
         false,
         {},
         0,
         7,
         A,
         red,
         [](const SnookerVerdict& v) {
             EXPECT_EQ(v.respotted.size(), 1u);
             EXPECT_TRUE(v.state.has(BK));
         }},
        {"colour_unnominated_first_hit_counts",
         "S3 Mode of Play",
         on_colour(14, O),
         {strike(), hit(0, PK), pot(PK)},
         false,
         {},
         0,
         6,
         A,
         red},
        {"colour_after_last_red_respotted",
         "S3 Mode of Play",
         on_colour(0, BL),
         {strike(), hit(0, BL), pot(BL)},
         false,
         {},
         0,
         5,
         A,
         yellow,
         [](const SnookerVerdict& v) { EXPECT_TRUE(v.state.has(BL)); }},
        {"last_red_then_colour_on",
         "S3 Mode of Play",
         with(1),
         {strike(), hit(0, 1), pot(1)},
         false,
         {},
         0,
         1,
         A,
         colour},
        {"colours_in_order_yellow_stays_down",
         "S3 Mode of Play",
         with(0),
         {strike(), hit(0, Y), pot(Y)},
         false,
         {},
         0,
         2,
         A,
         green,
         [](const SnookerVerdict& v) {
             EXPECT_FALSE(v.state.has(Y));
             EXPECT_TRUE(v.respotted.empty());
         }},
        {"colours_in_order_brown",
         "S3 Mode of Play",
         with(0, BR),
         {strike(), hit(0, BR), pot(BR)},
         false,
         {},
         0,
         4,
         A,
         blue},
        {"colour_missed_turn_passes_red_on",
         "S3 Mode of Play",
         on_colour(5, G),
         {strike(), hit(0, G), rail(G)},
         false,
         {},
         0,
         0,
         B,
         red},
        {"break_points_accumulate",
         "S3 Mode of Play",
         [] {
             auto s = on_colour(5, BK);
             s.break_points = 9;
             return s;
         }(),
         {strike(), hit(0, BK), pot(BK)},
         false,
         {},
         0,
         7,
         A,
         red,
         [](const SnookerVerdict& v) { EXPECT_EQ(v.state.break_points, 16); }},
        {"turn_passing_resets_break",
         "S3 Mode of Play",
         [] {
             auto s = with(5);
             s.break_points = 9;
             return s;
         }(),
         {strike(), hit(0, 1)},
         false,
         {},
         0,
         0,
         B,
         red,
         [](const SnookerVerdict& v) { EXPECT_EQ(v.state.break_points, 0); }},
        // Fouls and their values (S3 R10).
        {"no_contact_on_red_is_4",
         "S3 R10 Penalties",
         with(15),
         {strike(), rail(0)},
         true,
         {F::no_contact},
         4,
         0,
         B,
         red},
        {"wrong_ball_first_black_is_7",
         "S3 R10 Penalties",
         with(15),
         {strike(), hit(0, BK)},
         true,
         {F::wrong_ball_first},
         7,
         0,
         B,
         red},
        {"wrong_ball_first_yellow_is_4",
         "S3 R10 Penalties",
         with(15),
         {strike(), hit(0, Y)},
         true,
         {F::wrong_ball_first},
         4,
         0,
         B,
         red},
        {"wrong_ball_first_pink_is_6",
         "S3 R10 Penalties",
         with(15),
         {strike(), hit(0, PK)},
         true,
         {F::wrong_ball_first},
         6,
         0,
         B,
         red},
        {"in_off_red_is_4",
         "S3 R10 Penalties",
         with(15),
         {strike(), hit(0, 1), pot(0)},
         true,
         {F::in_off},
         4,
         0,
         B,
         red,
         [](const SnookerVerdict& v) { EXPECT_EQ(v.state.cue_ball, CueBall::in_hand); }},
        {"in_off_from_black_is_7",
         "S3 R10 Penalties",
         on_colour(10, BK),
         {strike(), hit(0, BK), pot(0)},
         true,
         {F::in_off},
         7,
         0,
         B,
         red},
        {"in_off_ball_in_hand_in_d",
         "S3 Play from in-hand",
         with(3),
         {strike(), hit(0, 2), pot(0)},
         true,
         {F::in_off},
         4,
         0,
         B,
         red,
         [](const SnookerVerdict& v) { EXPECT_EQ(v.state.positions.count(0), 0u); }},
        {"red_potted_with_in_off_not_scored",
         "S3 R10 Penalties",
         with(15),
         {strike(), hit(0, 1), pot(1), pot(0)},
         true,
         {F::in_off},
         4,
         0,
         B,
         red,
         [](const SnookerVerdict& v) { EXPECT_FALSE(v.state.has(1)); }},
        {"colour_nominated_blue_missed_hit_red_is_7",
         "S3 R10 Penalties",
         on_colour(10, BL),
         {strike(), hit(0, 3)},
         true,
         {F::wrong_ball_first},
         7,
         0,
         B,
         red},
        {"nominated_green_hit_black_is_7",
         "S3 R10 Penalties",
         on_colour(10, G),
         {strike(), hit(0, BK)},
         true,
         {F::wrong_ball_first},
         7,
         0,
         B,
         red},
        {"nominated_brown_hit_yellow_is_4",
         "S3 R10 Penalties",
         on_colour(10, BR),
         {strike(), hit(0, Y)},
         true,
         {F::wrong_ball_first},
         4,
         0,
         B,
         red},
        {"nominated_pink_no_contact_is_6",
         "S3 R10 Penalties",
         on_colour(10, PK),
         {strike(), rail(0)},
         true,
         {F::no_contact},
         6,
         0,
         B,
         red},
        {"red_and_colour_potted_foul",
         "S3 R10 Penalties",
         with(15),
         {strike(), hit(0, 1), pot(1), pot(G)},
         true,
         {F::ball_not_on_potted},
         4,
         0,
         B,
         red,
         [](const SnookerVerdict& v) {
             EXPECT_TRUE(v.state.has(G));
             EXPECT_FALSE(v.state.has(1));
         }},
        {"red_and_black_potted_is_7",
         "S3 R10 Penalties",
         with(15),
         {strike(), hit(0, 1), pot(1), pot(BK)},
         true,
         {F::ball_not_on_potted},
         7,
         0,
         B,
         red},
        {"two_colours_potted_foul",
         "S3 R10 Penalties",
         on_colour(8, Y),
         {strike(), hit(0, Y), pot(Y), pot(BL)},
         true,
         {F::ball_not_on_potted},
         5,
         0,
         B,
         red,
         [](const SnookerVerdict& v) {
             EXPECT_TRUE(v.state.has(Y));
             EXPECT_TRUE(v.state.has(BL));
         }},
        {"red_potted_on_colour_foul",
         "S3 R10 Penalties",
         on_colour(8, G),
         {strike(), hit(0, G), pot(3)},
         true,
         {F::ball_not_on_potted},
         4,
         0,
         B,
         red},
        {"out_of_order_colour_potted",
         "S3 R10 Penalties",
         with(0),
         {strike(), hit(0, Y), pot(G)},
         true,
         {F::ball_not_on_potted},
         4,
         0,
         B,
         yellow,
         [](const SnookerVerdict& v) { EXPECT_TRUE(v.state.has(G)); }},
        {"colours_wrong_ball_first_pink_on_yellow",
         "S3 R10 Penalties",
         with(0),
         {strike(), hit(0, PK)},
         true,
         {F::wrong_ball_first},
         6,
         0,
         B,
         yellow},
        {"colours_on_blue_no_contact_is_5",
         "S3 R10 Penalties",
         with(0, BL),
         {strike(), rail(0)},
         true,
         {F::no_contact},
         5,
         0,
         B,
         blue},
        {"cue_ball_off_table",
         "S2 R14 Forced off the Table",
         with(15),
         {strike(), hit(0, 1), off(0)},
         true,
         {F::cue_ball_off_table},
         4,
         0,
         B,
         red,
         [](const SnookerVerdict& v) { EXPECT_EQ(v.state.cue_ball, CueBall::in_hand); }},
        {"colour_off_table_respotted",
         "S2 R14 Forced off the Table",
         with(15),
         {strike(), hit(0, 1), hit(1, PK), off(PK)},
         true,
         {F::ball_off_table},
         6,
         0,
         B,
         red,
         [](const SnookerVerdict& v) { EXPECT_TRUE(v.state.has(PK)); }},
        {"red_off_table_stays_off",
         "S2 R14 Forced off the Table",
         with(15),
         {strike(), hit(0, 1), off(1)},
         true,
         {F::ball_off_table},
         4,
         0,
         B,
         red,
         [](const SnookerVerdict& v) { EXPECT_FALSE(v.state.has(1)); }},
        {"no_contact_and_in_off",
         "S3 R10 Penalties",
         with(15),
         {strike(), pot(0)},
         true,
         {F::in_off, F::no_contact},
         4,
         0,
         B,
         red},
        {"foul_points_to_opponent",
         "S3 R10 Penalties",
         scores(with(15), 30, 12),
         {strike(), hit(0, BK)},
         true,
         {F::wrong_ball_first},
         7,
         0,
         B,
         red,
         [](const SnookerVerdict& v) {
             EXPECT_EQ(v.state.scores, (std::array<int, 2>{30, 19}));
         }},
        {"offender_may_be_asked_again",
         "S3 'Play Again'",
         with(15),
         {strike(), hit(0, Y)},
         true,
         {F::wrong_ball_first},
         4,
         0,
         B,
         red,
         [](const SnookerVerdict& v) { EXPECT_TRUE(v.may_ask_to_play_again); }},
        {"legal_stroke_no_play_again",
         "S3 'Play Again'",
         with(15),
         {strike(), hit(0, 1)},
         false,
         {},
         0,
         0,
         B,
         red,
         [](const SnookerVerdict& v) { EXPECT_FALSE(v.may_ask_to_play_again); }},
        {"colour_potted_on_foul_respotted_in_colours",
         "S3 R10 Penalties",
         with(0, G),
         {strike(), hit(0, BK), pot(BK)},
         true,
         {F::wrong_ball_first, F::ball_not_on_potted},
         7,
         0,
         B,
         green,
         [](const SnookerVerdict& v) { EXPECT_TRUE(v.state.has(BK)); }},
        // Free ball (S2 R13, S3 R12).
        {"free_ball_potted_scores_as_red",
         "S3 R12 Snookered after a Foul",
         free_ball(10, BL),
         {strike(), hit(0, BL), pot(BL)},
         false,
         {},
         0,
         1,
         A,
         colour,
         [](const SnookerVerdict& v) { EXPECT_TRUE(v.state.has(BL)); }},
        {"free_ball_and_red_score_two",
         "S3 R12 Snookered after a Foul",
         free_ball(10, BL),
         {strike(), hit(0, BL), pot(BL), pot(4)},
         false,
         {},
         0,
         2,
         A,
         colour},
        {"free_ball_not_hit_first_foul",
         "S3 R12 Snookered after a Foul",
         free_ball(10, BL),
         {strike(), hit(0, 4)},
         true,
         {F::wrong_ball_first},
         4,
         0,
         B,
         red},
        {"free_ball_in_colours_scores_ball_on",
         "S3 R12 Snookered after a Foul",
         free_ball(0, PK, BR),
         {strike(), hit(0, PK), pot(PK)},
         false,
         {},
         0,
         4,
         A,
         brown,
         [](const SnookerVerdict& v) { EXPECT_TRUE(v.state.has(PK)); }},
        {"free_ball_and_ball_on_only_ball_on",
         "S3 R12 Snookered after a Foul",
         free_ball(0, PK, BR),
         {strike(), hit(0, PK), pot(PK), pot(BR)},
         false,
         {},
         0,
         4,
         A,
         blue,
         [](const SnookerVerdict& v) {
             EXPECT_TRUE(v.state.has(PK));
             EXPECT_FALSE(v.state.has(BR));
         }},
        {"free_ball_missed_penalty_of_ball_on",
         "S3 R12 Snookered after a Foul",
         free_ball(0, BK, G),
         {strike(), rail(0)},
         true,
         {F::no_contact},
         4,
         0,
         B,
         green},
        // Touching ball and push stroke.
        {"push_stroke",
         "S3 R10 Penalties (push stroke)",
         with(15),
         [] {
             auto s = strike();
             auto h = hit(0, 1);
             h.time = 0.0004;
             return std::vector<Event>{s, h};
         }(),
         true,
         {F::push_stroke},
         4,
         0,
         B,
         red},
        {"contact_after_tip_time_legal",
         "S3 R10 Penalties (push stroke)",
         with(15),
         [] {
             auto s = strike();
             auto h = hit(0, 1);
             h.time = 0.01;
             return std::vector<Event>{s, h};
         }(),
         false,
         {},
         0,
         0,
         B,
         red},
        // The end of the frame.
        {"last_black_potted_wins",
         "S3 Mode of Play (end of frame)",
         scores(with(0, BK), 60, 40),
         {strike(), hit(0, BK), pot(BK)},
         false,
         {},
         0,
         7,
         O,
         O,
         [](const SnookerVerdict& v) {
             EXPECT_TRUE(v.frame_over);
             EXPECT_EQ(v.winner, A);
         }},
        {"last_black_potted_behind_loses",
         "S3 Mode of Play (end of frame)",
         scores(with(0, BK), 30, 50),
         {strike(), hit(0, BK), pot(BK)},
         false,
         {},
         0,
         7,
         O,
         O,
         [](const SnookerVerdict& v) { EXPECT_EQ(v.winner, B); }},
        {"foul_on_last_black_ends_frame",
         "S3 Mode of Play (end of frame)",
         scores(with(0, BK), 60, 40),
         {strike(), rail(0)},
         true,
         {F::no_contact},
         7,
         0,
         O,
         O,
         [](const SnookerVerdict& v) {
             EXPECT_TRUE(v.frame_over);
             EXPECT_EQ(v.winner, A);
         }},
        {"tie_on_last_black_respots_black",
         "S3 Mode of Play (re-spotted black)",
         scores(with(0, BK), 43, 50),
         {strike(), hit(0, BK), pot(BK)},
         false,
         {},
         0,
         7,
         B,
         black,
         [](const SnookerVerdict& v) {
             EXPECT_TRUE(v.respotted_black);
             EXPECT_FALSE(v.frame_over);
             EXPECT_TRUE(v.state.respotted_black);
             EXPECT_EQ(v.state.cue_ball, CueBall::in_hand);
             ASSERT_EQ(v.respotted.size(), 1u);
             EXPECT_EQ(v.respotted[0].spot, BK);
         }},
        {"tie_by_foul_on_last_black",
         "S3 Mode of Play (re-spotted black)",
         scores(with(0, BK), 50, 43),
         {strike(), rail(0)},
         true,
         {F::no_contact},
         7,
         0,
         B,
         black,
         [](const SnookerVerdict& v) { EXPECT_TRUE(v.respotted_black); }},
        {"respotted_black_potted_wins",
         "S3 Mode of Play (re-spotted black)",
         [] {
             auto s = scores(with(0, BK), 50, 50);
             s.respotted_black = true;
             return s;
         }(),
         {strike(), hit(0, BK), pot(BK)},
         false,
         {},
         0,
         7,
         O,
         O,
         [](const SnookerVerdict& v) { EXPECT_EQ(v.winner, A); }},
        {"respotted_black_foul_loses",
         "S3 Mode of Play (re-spotted black)",
         [] {
             auto s = scores(with(0, BK), 50, 50);
             s.respotted_black = true;
             return s;
         }(),
         {strike(), hit(0, BK), pot(0)},
         true,
         {F::in_off},
         7,
         0,
         O,
         O,
         [](const SnookerVerdict& v) { EXPECT_EQ(v.winner, B); }},
        {"respotted_black_missed_passes",
         "S3 Mode of Play (re-spotted black)",
         [] {
             auto s = scores(with(0, BK), 50, 50);
             s.respotted_black = true;
             return s;
         }(),
         {strike(), hit(0, BK)},
         false,
         {},
         0,
         0,
         B,
         black},
        {"pink_potted_black_left",
         "S3 Mode of Play",
         with(0, PK),
         {strike(), hit(0, PK), pot(PK)},
         false,
         {},
         0,
         6,
         A,
         black},
        {"no_miss_without_positions",
         "S3 R14 Foul and a Miss",
         with(15),
         {strike(), hit(0, BK)},
         true,
         {F::wrong_ball_first},
         7,
         0,
         B,
         red,
         [](const SnookerVerdict& v) { EXPECT_FALSE(v.miss); }},
        {"three_reds_score_three",
         "S3 Mode of Play",
         with(15),
         {strike(), hit(0, 1), pot(1), pot(2), pot(3)},
         false,
         {},
         0,
         3,
         A,
         colour},
        {"free_ball_other_colour_potted_foul",
         "S3 R12 Snookered after a Foul",
         free_ball(10, BL),
         {strike(), hit(0, BL), pot(PK)},
         true,
         {F::ball_not_on_potted},
         6,
         0,
         B,
         red},
        {"cue_off_table_on_black_is_7",
         "S2 R14 Forced off the Table",
         on_colour(10, BK),
         {strike(), hit(0, BK), off(0)},
         true,
         {F::cue_ball_off_table},
         7,
         0,
         B,
         red},
        {"green_on_brown_first_is_4",
         "S3 R10 Penalties",
         with(0, G),
         {strike(), hit(0, BR)},
         true,
         {F::wrong_ball_first},
         4,
         0,
         B,
         green},
        {"ball_on_potted_with_in_off_respotted",
         "S3 R10 Penalties",
         with(0, BR),
         {strike(), hit(0, BR), pot(BR), pot(0)},
         true,
         {F::in_off},
         4,
         0,
         B,
         brown,
         [](const SnookerVerdict& v) { EXPECT_TRUE(v.state.has(BR)); }},
        {"in_off_in_colours_from_pink_is_6",
         "S3 R10 Penalties",
         with(0, PK),
         {strike(), hit(0, PK), pot(0)},
         true,
         {F::in_off},
         6,
         0,
         B,
         pink},
        {"points_remaining_all",
         "S3 Mode of Play",
         with(15),
         {strike(), hit(0, 1)},
         false,
         {},
         0,
         0,
         B,
         red,
         [](const SnookerVerdict& v) { EXPECT_EQ(points_remaining(v.state), 147); }},
        {"points_remaining_colour_on",
         "S3 Mode of Play",
         with(15),
         {strike(), hit(0, 1), pot(1)},
         false,
         {},
         0,
         1,
         A,
         colour,
         [](const SnookerVerdict& v) { EXPECT_EQ(points_remaining(v.state), 14 * 8 + 7 + 27); }},
    };
    return list;
}

class SnookerScenario : public ::testing::TestWithParam<Case> {};

TEST_P(SnookerScenario, Verdict) {
    const Case& c = GetParam();
    const SnookerVerdict v = judge_snooker({}, table(), c.state, c.events);
    EXPECT_EQ(v.foul, c.foul);
    EXPECT_EQ(v.fouls, c.fouls);
    EXPECT_EQ(v.foul_points, c.foul_points);
    EXPECT_EQ(v.points_scored, c.points);
    EXPECT_EQ(v.next_shooter, c.next);
    if (c.on) {
        EXPECT_EQ(v.ball_on, *c.on);
    }
    EXPECT_EQ(v.frame_over, !c.on.has_value());
    if (c.more) c.more(v);
}

INSTANTIATE_TEST_SUITE_P(Wpbsa, SnookerScenario, ::testing::ValuesIn(cases()),
                         [](const auto& param_info) { return param_info.param.name; });

// Scenarios that need ball positions: re-spotting, free ball, miss, touching ball.
const SnookerTable kTable = table();
const physics::SnookerMarkings& kMarks = kTable.marks;
constexpr double R = 0.02625;

physics::Vec2 at(int colour) {
    return kMarks.spot(colour);
}
SnookerState placed(SnookerState s) {
    for (int id : s.on_table)
        s.positions[id] = id <= 15 ? physics::Vec2{2.9, 0.1 + 0.06 * id} : at(id);
    return s;
}

TEST(SnookerRespot, OwnSpotWhenFree) {  // S3 'Spotting Colours' (a)
    SnookerState s = placed(on_colour(5, BK));
    s.positions[0] = {1.0, 0.5};
    const SnookerVerdict v =
        judge_snooker({}, kTable, s, std::vector<Event>{strike(), hit(0, BK), pot(BK)});
    ASSERT_EQ(v.respotted.size(), 1u);
    EXPECT_EQ(v.respotted[0].spot, BK);
    EXPECT_EQ(v.state.positions.at(BK), at(BK));
}

TEST(SnookerRespot, HighestFreeSpotWhenOwnOccupied) {  // S3 'Spotting Colours' (b)
    SnookerState s = placed(on_colour(5, BK));
    s.positions[0] = {1.0, 0.5};
    s.positions[3] = at(BK) + physics::Vec2{0.01, 0.0};  // a red over the black spot
    s.positions[PK] = {2.0, 1.5};                        // the pink off its spot
    const SnookerVerdict v =
        judge_snooker({}, kTable, s, std::vector<Event>{strike(), hit(0, BK), pot(BK)});
    ASSERT_EQ(v.respotted.size(), 1u);
    EXPECT_EQ(v.respotted[0].spot, PK);
    EXPECT_EQ(v.state.positions.at(BK), at(PK));
}

TEST(SnookerRespot, HighestValueColourFirst) {  // S3 'Spotting Colours' (c)
    SnookerState s = placed(with(5));
    s.positions[0] = {1.0, 0.5};
    const SnookerVerdict v =
        judge_snooker({}, kTable, s, std::vector<Event>{strike(), hit(0, 1), pot(G), pot(BK)});
    ASSERT_EQ(v.respotted.size(), 2u);
    EXPECT_EQ(v.respotted[0].ball, BK);
    EXPECT_EQ(v.respotted[1].ball, G);
}

TEST(SnookerRespot, NearOwnSpotTowardTopWhenAllOccupied) {  // S3 'Spotting Colours' (d)
    SnookerState s = placed(with(3));
    s.positions[0] = {1.0, 0.5};
    s.positions[1] = at(BK) + physics::Vec2{0.0, 0.001};  // a red over the black spot
    s.positions[BK] = {1.5, 1.2};
    const SnookerVerdict v =
        judge_snooker({}, kTable, s, std::vector<Event>{strike(), hit(0, BK), pot(BK)});
    ASSERT_EQ(v.respotted.size(), 1u);
    const Respot r = v.respotted[0];
    EXPECT_FALSE(r.spot.has_value());
    EXPECT_GT(r.pos.x, at(BK).x);  // toward the top cushion
    EXPECT_DOUBLE_EQ(r.pos.y, at(BK).y);
    EXPECT_NEAR(physics::norm(r.pos - s.positions[1]), 2 * R, 1e-9);
}

// The cue ball behind the brown, the reds far off to the right: snookered on every red.
SnookerState snookered_position() {
    SnookerState s = with(1);
    s.positions = {{1, {1.5, 0.3}}};
    for (int c = Y; c <= BK; ++c) s.positions[c] = at(c);
    s.positions[0] = at(BR) + physics::Vec2{-0.06, 0.0};
    s.positions[1] = at(BR) + physics::Vec2{0.6, 0.0};
    return s;
}

// The same table with the cue ball in the open, a clear path to the red.
SnookerState open_position() {
    SnookerState s = snookered_position();
    s.positions[0] = {1.2, 0.3};
    return s;
}

TEST(SnookerFreeBall, AwardedWhenSnookeredAfterFoul) {  // S3 R12 Snookered after a Foul
    SnookerState s = snookered_position();
    s.shooter = B;
    // B fouls without moving anything that matters: the cue ball stays where it lies.
    std::vector<Event> e{strike(), hit(0, Y)};
    e[1].balls[0].pos = s.positions[0];
    e[1].balls[1].pos = s.positions[Y];
    const SnookerVerdict v = judge_snooker({}, kTable, s, e);
    EXPECT_TRUE(v.foul);
    EXPECT_TRUE(v.free_ball);
    EXPECT_TRUE(v.state.free_ball);
}

TEST(SnookerFreeBall, NotAwardedWhenBallOnVisible) {  // S3 R12 Snookered after a Foul
    SnookerState s = open_position();
    std::vector<Event> e{strike(), hit(0, Y)};
    const SnookerVerdict v = judge_snooker({}, kTable, s, e);
    EXPECT_TRUE(v.foul);
    EXPECT_FALSE(v.free_ball);
}

TEST(SnookerMiss, CalledWithAClearPath) {  // S3 R14 Foul and a Miss
    SnookerState s = open_position();
    const SnookerVerdict v = judge_snooker({}, kTable, s, std::vector<Event>{strike(), hit(0, Y)});
    EXPECT_TRUE(v.miss);
}

TEST(SnookerMiss, OffInACasualGame) {  // S3 R14, the project's casual switch
    SnookerState s = open_position();
    const SnookerVerdict v =
        judge_snooker({.miss_rule = false}, kTable, s, std::vector<Event>{strike(), hit(0, Y)});
    EXPECT_FALSE(v.miss);
    EXPECT_TRUE(v.may_ask_to_play_again);
}

TEST(SnookerMiss, NotCalledWhenSnookersNeeded) {  // S3 R14 (needing snookers)
    SnookerState s = open_position();
    s.scores = {0, 40};  // 8 + 27 left: A needs snookers
    const SnookerVerdict v = judge_snooker({}, kTable, s, std::vector<Event>{strike(), hit(0, Y)});
    EXPECT_TRUE(v.foul);
    EXPECT_FALSE(v.miss);
}

TEST(SnookerMiss, ReplaceRestoresTheBallsForTheOffender) {  // S3 R14 (replace)
    SnookerState s = open_position();
    std::vector<Event> e{strike(), hit(0, Y)};
    e[1].balls[0].pos = {2.0, 0.9};
    const SnookerVerdict v = judge_snooker({}, kTable, s, e);
    ASSERT_TRUE(v.miss);
    const SnookerState again = resolve_after_foul(v, s, AfterFoul::replace);
    EXPECT_EQ(again.shooter, A);
    EXPECT_EQ(again.positions, s.positions);
    EXPECT_EQ(again.scores, (std::array<int, 2>{20, 24}));
    const SnookerState play_again = resolve_after_foul(v, s, AfterFoul::play_again);
    EXPECT_EQ(play_again.shooter, A);
    EXPECT_EQ(play_again.positions.at(0), (physics::Vec2{2.0, 0.9}));
}

TEST(SnookerMiss, ThirdMissInFullViewLosesTheFrame) {  // S3 R14 (three misses)
    SnookerState s = open_position();
    const SnookerVerdict first =
        judge_snooker({}, kTable, s, std::vector<Event>{strike(), hit(0, Y)});
    ASSERT_TRUE(first.miss);
    EXPECT_EQ(first.misses, 1);
    EXPECT_EQ(resolve_after_foul(first, s, AfterFoul::replace).misses, 1);
    EXPECT_EQ(resolve_after_foul(first, s, AfterFoul::play_again).misses, 0);
    EXPECT_EQ(first.state.misses, 0);  // the opponent plays: a new count
    s.misses = 2;
    const SnookerVerdict third =
        judge_snooker({}, kTable, s, std::vector<Event>{strike(), hit(0, Y)});
    EXPECT_EQ(third.misses, 3);
    EXPECT_TRUE(third.frame_over);
    EXPECT_EQ(third.winner, B);
    EXPECT_FALSE(third.may_ask_to_play_again);
}

TEST(SnookerMiss, NoCountWithoutAFullView) {  // S3 R14 (three misses: a full ball on)
    SnookerState s = open_position();
    // The blue 45 mm off the line from the cue ball to the red, a third of the way: the red's
    // far edge can be hit, its near edge cannot.
    const physics::Vec2 c = s.positions[0], to = s.positions[1] - c;
    const physics::Vec2 u = (1.0 / physics::norm(to)) * to, n{u.y, -u.x};
    s.positions[BL] = c + 0.3 * u + 0.045 * n;
    s.misses = 2;
    const SnookerVerdict v = judge_snooker({}, kTable, s, std::vector<Event>{strike(), hit(0, Y)});
    ASSERT_TRUE(v.miss);
    EXPECT_EQ(v.misses, 0);
    EXPECT_FALSE(v.frame_over);
}

TEST(SnookerFreeBall, LeavingTheOpponentSnookeredBehindItIsAFoul) {  // S3 R12
    SnookerState s = snookered_position();
    s.positions[0] = {1.5, 0.3};
    s.positions[1] = {2.6, 0.3};
    s.free_ball = true;
    s.nominated = PK;
    Event h = hit(0, PK);
    h.balls[0].pos = {2.0, 0.3};
    h.balls[1].pos = {2.0 + 2 * R, 0.3};
    Event rest = roll(PK);
    rest.balls[0].pos = {2.3, 0.3};
    const SnookerVerdict v = judge_snooker({}, kTable, s, std::vector<Event>{strike(), h, rest});
    EXPECT_EQ(v.fouls, std::vector<F>{F::snookered_by_free_ball});
    EXPECT_EQ(v.foul_points, 4);
    EXPECT_EQ(v.next_shooter, B);
    // The same stroke leaving the pink off the line is legal.
    rest.balls[0].pos = {2.3, 0.6};
    const SnookerVerdict ok = judge_snooker({}, kTable, s, std::vector<Event>{strike(), h, rest});
    EXPECT_FALSE(ok.foul);
}

TEST(SnookerPlayAgain, NotOpenAfterALegalStroke) {  // S3 'Play Again'
    const SnookerState s = with(15);
    const SnookerVerdict v = judge_snooker({}, kTable, s, std::vector<Event>{strike(), hit(0, 1)});
    EXPECT_THROW(resolve_after_foul(v, s, AfterFoul::play_again), std::invalid_argument);
}

TEST(SnookerTouchingBall, PlayingAwayIsDeemedAHit) {  // S3 'Touching Ball'
    SnookerState s = with(3);
    s.positions = {{0, {1.0, 0.5}}, {1, {1.0 + 2 * R, 0.5}}};
    const SnookerVerdict v = judge_snooker({}, kTable, s, std::vector<Event>{strike(), rail(0)});
    EXPECT_FALSE(v.foul);
}

TEST(SnookerTouchingBall, MovingItIsAPush) {  // S3 'Touching Ball', S3 R10 (push stroke)
    SnookerState s = with(3);
    s.positions = {{0, {1.0, 0.5}}, {1, {1.0 + 2 * R, 0.5}}};
    const SnookerVerdict v = judge_snooker({}, kTable, s, std::vector<Event>{strike(), hit(0, 1)});
    EXPECT_TRUE(v.has(F::push_stroke));
    EXPECT_EQ(v.foul_points, 4);
}

TEST(SnookerTouchingBall, ReportedForTheNextStroke) {  // S3 'Touching Ball'
    SnookerState s = with(3);
    s.positions = {{0, {1.0, 0.5}}, {2, {2.0, 0.5}}};
    std::vector<Event> e{strike(), hit(0, 2)};
    e[1].balls[0].pos = {2.0 - 2 * R, 0.5};
    e[1].balls[1].pos = {2.0, 0.5};
    const SnookerVerdict v = judge_snooker({}, kTable, s, e);
    EXPECT_EQ(v.touching_ball, 2);
}
}  // namespace
}  // namespace rules::test
