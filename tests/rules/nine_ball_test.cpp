// 9-ball (docs/rules.md "9-ball (WPA)"), one scenario per rule.
#include "scenario.hpp"

namespace rules::test {
namespace {

using F = Foul;
using C = ChoiceOption;
using BIH = BallInHand;
constexpr BreakResult legal = BreakResult::legal;
constexpr BreakResult illegal = BreakResult::illegal;
const Choice push_out_choice{B, {C::shoot, C::pass_back}};

void next_shot_is(const Verdict& v, Shot shot) {
    EXPECT_EQ(v.state.shot, shot);
}

std::vector<Scenario> break_scenarios() {
    return {
        {"break_pocketing_a_ball_continues",
         nine_ball(),
         nine_break(),
         {hit(0, 1), rail(2), pot(5, P::N)},
         {.next = A, .break_result = legal},
         [](const Verdict& v) {
             next_shot_is(v, Shot::after_break);
             EXPECT_FALSE(v.state.has(5));
         }},
        {"break_four_balls_to_cushion_passes",
         nine_ball(),
         nine_break(),
         four_rail_break(),
         {.turn_passes = true, .next = B, .break_result = legal},
         [](const Verdict& v) { next_shot_is(v, Shot::after_break); }},
        {"break_not_hitting_the_one_first",
         nine_ball(),
         nine_break(),
         four_rail_break(2),
         {.fouls = {F::wrong_ball_first},
          .turn_passes = true,
          .next = B,
          .ball_in_hand = BIH::anywhere,
          .break_result = illegal},
         [](const Verdict& v) {
             next_shot_is(v, Shot::normal);
             EXPECT_EQ(v.state.cue_ball, CueBall::in_hand);
         }},
        {"break_too_few_balls_to_cushion",
         nine_ball(),
         nine_break(),
         {hit(0, 1), rail(1), rail(2), rail(3)},
         {.fouls = {F::illegal_break},
          .turn_passes = true,
          .next = B,
          .ball_in_hand = BIH::anywhere,
          .break_result = illegal}},
        {"break_both_wrong_ball_and_too_few_cushions",
         nine_ball(),
         nine_break(),
         {hit(0, 2), rail(2)},
         {.fouls = {F::wrong_ball_first, F::illegal_break},
          .turn_passes = true,
          .next = B,
          .ball_in_hand = BIH::anywhere,
          .break_result = illegal}},
        {"break_without_contact",
         nine_ball(),
         nine_break(),
         {rail(0)},
         {.fouls = {F::no_contact},
          .turn_passes = true,
          .next = B,
          .ball_in_hand = BIH::anywhere,
          .break_result = illegal}},
        {"nine_on_a_legal_break_wins",
         nine_ball(),
         nine_break(),
         {hit(0, 1), pot(9, P::SE)},
         {.winner = A, .break_result = legal}},
        {"nine_on_a_break_with_a_scratch_is_spotted",
         nine_ball(),
         nine_break(),
         {hit(0, 1), pot(9, P::SE), pot(0, P::SW)},
         {.fouls = {F::scratch},
          .turn_passes = true,
          .next = B,
          .ball_in_hand = BIH::anywhere,
          .respot = {9},
          .break_result = legal},
         [](const Verdict& v) { EXPECT_TRUE(v.state.has(9)); }},
        {"break_scratch_counts_as_a_foul",
         nine_ball(),
         nine_break(),
         [] {
             auto e = four_rail_break();
             e.push_back(pot(0, P::N));
             return e;
         }(),
         {.fouls = {F::scratch},
          .turn_passes = true,
          .next = B,
          .ball_in_hand = BIH::anywhere,
          .break_result = legal},
         [](const Verdict& v) { EXPECT_EQ(v.state.fouls_in_row[0], 1); }},
    };
}

std::vector<Scenario> shot_scenarios() {
    return {
        {"lowest_ball_must_be_hit_first",
         nine_ball(),
         nine_table(),
         {hit(0, 2), rail(2)},
         {.fouls = {F::wrong_ball_first},
          .turn_passes = true,
          .next = B,
          .ball_in_hand = BIH::anywhere}},
        {"lowest_ball_is_the_lowest_left",
         nine_ball(),
         nine_table().balls({4, 6, 9}),
         {hit(0, 4), pot(4, P::N)},
         {.next = A}},
        {"combination_on_the_nine_wins",
         nine_ball(),
         nine_table(),
         {hit(0, 1), hit(1, 9), pot(9, P::NE)},
         {.winner = A}},
        {"carom_of_the_cue_ball_into_the_nine_wins",
         nine_ball(),
         nine_table().balls({3, 9}),
         {hit(0, 3), hit(0, 9), pot(9, P::S)},
         {.winner = A}},
        {"legal_pocket_continues",
         nine_ball(),
         nine_table(),
         {hit(0, 1), hit(1, 4), pot(4, P::S)},
         {.next = A},
         [](const Verdict& v) { EXPECT_FALSE(v.state.has(4)); }},
        {"miss_passes",
         nine_ball(),
         nine_table(),
         {hit(0, 1), rail(1)},
         {.turn_passes = true, .next = B}},
        {"no_rail_after_contact",
         nine_ball(),
         nine_table(),
         {hit(0, 1)},
         {.fouls = {F::no_rail_after_contact},
          .turn_passes = true,
          .next = B,
          .ball_in_hand = BIH::anywhere}},
        {"nine_pocketed_on_a_foul_is_spotted",
         nine_ball(),
         nine_table(),
         {hit(0, 2), hit(2, 9), pot(9, P::N)},
         {.fouls = {F::wrong_ball_first},
          .turn_passes = true,
          .next = B,
          .ball_in_hand = BIH::anywhere,
          .respot = {9}}},
        {"nine_with_a_scratch_is_spotted",
         nine_ball(),
         nine_table(),
         {hit(0, 1), hit(1, 9), pot(9, P::N), pot(0, P::S)},
         {.fouls = {F::scratch},
          .turn_passes = true,
          .next = B,
          .ball_in_hand = BIH::anywhere,
          .respot = {9}}},
        {"nine_off_the_table_is_spotted",
         nine_ball(),
         nine_table(),
         {hit(0, 1), hit(1, 9), off(9), rail(1)},
         {.fouls = {F::ball_off_table},
          .turn_passes = true,
          .next = B,
          .ball_in_hand = BIH::anywhere,
          .respot = {9}}},
        {"other_ball_off_the_table_stays_out",
         nine_ball(),
         nine_table(),
         {hit(0, 1), hit(1, 5), off(5), rail(1)},
         {.fouls = {F::ball_off_table},
          .turn_passes = true,
          .next = B,
          .ball_in_hand = BIH::anywhere},
         [](const Verdict& v) { EXPECT_FALSE(v.state.has(5)); }},
        {"other_ball_pocketed_on_a_foul_stays_down",
         nine_ball(),
         nine_table(),
         {hit(0, 3), hit(3, 5), pot(5, P::SW)},
         {.fouls = {F::wrong_ball_first},
          .turn_passes = true,
          .next = B,
          .ball_in_hand = BIH::anywhere},
         [](const Verdict& v) { EXPECT_FALSE(v.state.has(5)); }},
        {"after_break_without_push_out_is_a_normal_shot",
         nine_ball(),
         nine_table().shot(Shot::after_break),
         {hit(0, 2)},
         {.fouls = {F::wrong_ball_first, F::no_rail_after_contact},
          .turn_passes = true,
          .next = B,
          .ball_in_hand = BIH::anywhere},
         [](const Verdict& v) { next_shot_is(v, Shot::normal); }},
        {"after_push_out_is_a_normal_shot",
         nine_ball(),
         nine_table().shot(Shot::after_push_out),
         {hit(0, 1), rail(1)},
         {.turn_passes = true, .next = B},
         [](const Verdict& v) { next_shot_is(v, Shot::normal); }},
        {"house_rule_switches_do_not_apply",
         Ruleset{Game::nine_ball, {.rail_after_contact = false}, {}},
         nine_table(),
         {hit(0, 1)},
         {.fouls = {F::no_rail_after_contact},
          .turn_passes = true,
          .next = B,
          .ball_in_hand = BIH::anywhere}},
    };
}

std::vector<Scenario> push_out_scenarios() {
    auto push = [] { return nine_table().shot(Shot::push_out); };
    return {
        {"push_out_without_contact_or_rail_is_legal",
         nine_ball(),
         push(),
         {roll(0)},
         {.turn_passes = true, .choice = push_out_choice},
         [](const Verdict& v) {
             EXPECT_EQ(v.state.shooter, B);
             next_shot_is(v, Shot::after_push_out);
         }},
        {"push_out_any_ball_first",
         nine_ball(),
         push(),
         {hit(0, 5)},
         {.turn_passes = true, .choice = push_out_choice}},
        {"push_out_pocketing_the_nine_spots_it",
         nine_ball(),
         push(),
         {hit(0, 9), pot(9, P::N)},
         {.turn_passes = true, .respot = {9}, .choice = push_out_choice}},
        {"push_out_pocketed_ball_stays_down",
         nine_ball(),
         push(),
         {hit(0, 5), pot(5, P::N)},
         {.turn_passes = true, .choice = push_out_choice},
         [](const Verdict& v) { EXPECT_FALSE(v.state.has(5)); }},
        {"push_out_scratch_is_a_foul",
         nine_ball(),
         push(),
         {hit(0, 5), pot(0, P::N)},
         {.fouls = {F::scratch}, .turn_passes = true, .next = B, .ball_in_hand = BIH::anywhere},
         [](const Verdict& v) { next_shot_is(v, Shot::normal); }},
        {"push_out_ball_off_the_table_is_a_foul",
         nine_ball(),
         push(),
         {hit(0, 5), off(5)},
         {.fouls = {F::ball_off_table},
          .turn_passes = true,
          .next = B,
          .ball_in_hand = BIH::anywhere}},
        {"legal_push_out_resets_the_foul_count",
         nine_ball(),
         push().fouls(2, 1).warned(true, false),
         {hit(0, 5)},
         {.turn_passes = true, .choice = push_out_choice},
         [](const Verdict& v) {
             EXPECT_EQ(v.state.fouls_in_row, (std::array<int, 2>{0, 1}));
             EXPECT_EQ(v.state.warned, (std::array<bool, 2>{false, false}));
         }},
        {"third_foul_on_a_push_out_loses",
         nine_ball(),
         push().fouls(2, 0).warned(true, false),
         {hit(0, 5), pot(0, P::N)},
         {.fouls = {F::scratch, F::third_consecutive_foul}, .turn_passes = true, .winner = B}},
    };
}

std::vector<Scenario> three_foul_scenarios() {
    return {
        {"first_foul_counts",
         nine_ball(),
         nine_table(),
         {hit(0, 2), rail(2)},
         {.fouls = {F::wrong_ball_first},
          .turn_passes = true,
          .next = B,
          .ball_in_hand = BIH::anywhere},
         [](const Verdict& v) {
             EXPECT_EQ(v.state.fouls_in_row[0], 1);
             EXPECT_FALSE(v.state.warned[0]);
         }},
        {"second_foul_warns",
         nine_ball(),
         nine_table().fouls(1, 0),
         {hit(0, 2), rail(2)},
         {.fouls = {F::wrong_ball_first},
          .turn_passes = true,
          .next = B,
          .ball_in_hand = BIH::anywhere},
         [](const Verdict& v) {
             EXPECT_EQ(v.state.fouls_in_row[0], 2);
             EXPECT_TRUE(v.state.warned[0]);
         }},
        {"third_foul_after_a_warning_loses",
         nine_ball(),
         nine_table().fouls(2, 0).warned(true, false),
         {hit(0, 2), rail(2)},
         {.fouls = {F::wrong_ball_first, F::third_consecutive_foul},
          .turn_passes = true,
          .winner = B}},
        {"third_foul_by_b_loses",
         nine_ball(),
         nine_table().shooter(B).fouls(0, 2).warned(false, true),
         {rail(0)},
         {.fouls = {F::no_contact, F::third_consecutive_foul}, .turn_passes = true, .winner = A}},
        {"third_foul_without_a_warning_is_ordinary",
         nine_ball(),
         nine_table().fouls(2, 0),
         {hit(0, 2), rail(2)},
         {.fouls = {F::wrong_ball_first},
          .turn_passes = true,
          .next = B,
          .ball_in_hand = BIH::anywhere},
         [](const Verdict& v) {
             EXPECT_EQ(v.state.fouls_in_row[0], 3);
             EXPECT_TRUE(v.state.warned[0]);
         }},
        {"legal_shot_clears_the_count_and_the_warning",
         nine_ball(),
         nine_table().fouls(2, 0).warned(true, false),
         {hit(0, 1), rail(1)},
         {.turn_passes = true, .next = B},
         [](const Verdict& v) {
             EXPECT_EQ(v.state.fouls_in_row[0], 0);
             EXPECT_FALSE(v.state.warned[0]);
         }},
        {"opponents_count_is_untouched",
         nine_ball(),
         nine_table().shooter(B).fouls(2, 1).warned(true, false),
         {hit(0, 2), rail(2)},
         {.fouls = {F::wrong_ball_first},
          .turn_passes = true,
          .next = A,
          .ball_in_hand = BIH::anywhere},
         [](const Verdict& v) {
             EXPECT_EQ(v.state.fouls_in_row, (std::array<int, 2>{2, 2}));
             EXPECT_EQ(v.state.warned, (std::array<bool, 2>{true, true}));
         }},
    };
}

std::vector<Scenario> all_scenarios() {
    std::vector<Scenario> all;
    for (auto part : {break_scenarios, shot_scenarios, push_out_scenarios, three_foul_scenarios}) {
        auto s = part();
        all.insert(all.end(), s.begin(), s.end());
    }
    return all;
}

class NineBall : public ::testing::TestWithParam<Scenario> {};

TEST_P(NineBall, Verdict) {
    run(GetParam());
}

INSTANTIATE_TEST_SUITE_P(Rules, NineBall, ::testing::ValuesIn(all_scenarios()), scenario_name);

TEST(NineBallPushOut, AllowedOnlyRightAfterTheBreak) {
    EXPECT_TRUE(push_out_allowed(Game::nine_ball, nine_table().shot(Shot::after_break)));
    EXPECT_FALSE(push_out_allowed(Game::nine_ball, nine_table().shot(Shot::normal)));
    EXPECT_FALSE(push_out_allowed(Game::nine_ball, nine_table().shot(Shot::after_push_out)));
    EXPECT_FALSE(push_out_allowed(Game::eight_ball, eight_open().shot(Shot::after_break)));
}

}  // namespace
}  // namespace rules::test
