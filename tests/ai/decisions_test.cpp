// What the AI decides in hand-made positions: it pots an easy straight shot at 0× noise, calls
// what it pots, plays safe when nothing is on, places the cue ball legally, answers choices,
// and decides the same, bit for bit, from the same seed (with one thread or two).
#include <gtest/gtest.h>

#include <cstring>

#include "ai/internal/planner.hpp"
#include "ai/internal/table_value.hpp"
#include "ai/pause.hpp"
#include "ai_support.hpp"

namespace {

using ai_test::play;
using ai_test::position;
using physics::Vec2;
using rules::Game;

bool same_bits(double a, double b) {
    return std::memcmp(&a, &b, sizeof a) == 0;
}

void expect_same(const game::Decision& a, const game::Decision& b) {
    EXPECT_TRUE(same_bits(a.stroke.speed, b.stroke.speed));
    EXPECT_TRUE(same_bits(a.stroke.heading_deg, b.stroke.heading_deg));
    EXPECT_TRUE(same_bits(a.stroke.side, b.stroke.side));
    EXPECT_TRUE(same_bits(a.stroke.top, b.stroke.top));
    EXPECT_TRUE(same_bits(a.stroke.elevation_deg, b.stroke.elevation_deg));
    EXPECT_EQ(a.call, b.call);
    EXPECT_EQ(a.push_out, b.push_out);
    EXPECT_EQ(a.choice, b.choice);
    ASSERT_EQ(a.cue_pos.has_value(), b.cue_pos.has_value());
    if (a.cue_pos) {
        EXPECT_TRUE(same_bits(a.cue_pos->x, b.cue_pos->x));
        EXPECT_TRUE(same_bits(a.cue_pos->y, b.cue_pos->y));
    }
}

// The 9 alone, 0.5 m in front of the cue ball, straight in to the NE corner.
ai::Position straight_shot() {
    const Vec2 pocket{2.54, 1.27};
    const Vec2 obj{2.0, 0.9};
    const Vec2 dir = (1.0 / physics::norm(pocket - obj)) * (pocket - obj);
    return position(Game::nine_ball, {9}, {{0, obj - 0.5 * dir}, {9, obj}});
}

TEST(Decisions, PotsAnEasyStraightShotAtZeroNoise) {
    for (int level = 1; level <= 5; ++level) {
        const ai::Position pos = straight_shot();
        const ai::Plan p = ai::plan(pos, {level, 0.0, 2}, 7);
        const rules::Verdict v = play(pos, p.decision);
        EXPECT_TRUE(v.game_over && v.winner == rules::Player::A) << "level " << level;
        EXPECT_GT(p.expected_success, 0.99);
    }
}

TEST(Decisions, CallsTheBallItPots) {
    // 8-ball, solids: the 2 hangs in the SE corner.
    ai::Position pos =
        position(Game::eight_ball, {2, 8, 10},
                 {{0, {1.9, 0.3}}, {2, {2.45, 0.09}}, {8, {0.8, 1.0}}, {10, {1.2, 1.1}}});
    pos.state.group_a = rules::Group::solids;
    const ai::Plan p = ai::plan(pos, {3, 0.0, 2}, 1);
    ASSERT_TRUE(p.decision.call.is_ball());
    EXPECT_EQ(p.decision.call.ball, 2);
    const rules::Verdict v = play(pos, p.decision);
    EXPECT_FALSE(v.foul);
    EXPECT_EQ(v.next_shooter, rules::Player::A);
    EXPECT_FALSE(v.state.has(2));
}

TEST(Decisions, PlaysSafeWhenNothingIsOn) {
    // 8-ball, solids: the 1 is walled in by stripes towards every pocket; the cue ball is far.
    std::map<int, Vec2> balls{{0, {0.5, 0.3}}, {1, {1.6, 0.75}}, {8, {0.3, 1.1}}};
    const double R = 0.028575, r = 2.0 * R + 0.004;
    const int stripes[] = {9, 10, 11, 12, 13, 14, 15};
    for (int k = 0; k < 7; ++k) {
        const double a = 2.0 * 3.14159265358979 * k / 7.0 + 0.3;
        balls[stripes[k]] = balls[1] + r * Vec2{std::cos(a), std::sin(a)};
    }
    ai::Position pos = position(Game::eight_ball, {1, 8, 9, 10, 11, 12, 13, 14, 15}, balls);
    pos.state.group_a = rules::Group::solids;
    ASSERT_EQ(ai::best_shot_chance(pos, pos.state, 0.21), 0.0) << "the layout has a shot on";
    const ai::Plan p = ai::plan(pos, {5, 0.0, 2}, 3);
    EXPECT_TRUE(p.decision.call.is_safety()) << "called ball " << p.decision.call.ball;
    const rules::Verdict v = play(pos, p.decision);
    EXPECT_FALSE(v.game_over);
}

TEST(Decisions, PlacesTheCueBallInHandLegally) {
    ai::Position pos =
        position(Game::nine_ball, {3, 5, 9}, {{3, {1.0, 0.4}}, {5, {2.0, 1.0}}, {9, {2.3, 0.3}}},
                 rules::CueBall::in_hand);
    const ai::Plan p = ai::plan(pos, {4, 1.0, 2}, 5);
    ASSERT_TRUE(p.decision.cue_pos.has_value());
    EXPECT_TRUE(ai::free_spot(pos, *p.decision.cue_pos));
    const rules::Verdict v = play(pos, p.decision);
    EXPECT_FALSE(v.foul);
    EXPECT_EQ(v.next_shooter, rules::Player::A) << "a ball in hand with the 3 open is a sure pot";

    pos.state.cue_ball = rules::CueBall::in_hand_kitchen;
    const ai::Plan k = ai::plan(pos, {2, 1.0, 2}, 5);
    ASSERT_TRUE(k.decision.cue_pos.has_value());
    EXPECT_LT(k.decision.cue_pos->x, 2.54 / 4.0);
    EXPECT_TRUE(ai::free_spot(pos, *k.decision.cue_pos));
}

TEST(Decisions, AnswersChoicesWithAnOfferedOption) {
    ai::Position pos =
        position(Game::nine_ball, {1, 9}, {{0, {0.5, 0.5}}, {1, {2.3, 1.2}}, {9, {1.0, 0.6}}});
    pos.state.shot = rules::Shot::after_push_out;
    pos.choice = rules::Choice{rules::Player::B,
                               {rules::ChoiceOption::shoot, rules::ChoiceOption::pass_back}};
    const ai::Plan p = ai::plan(pos, {5, 1.0, 2}, 1);
    ASSERT_TRUE(p.decision.choice.has_value());
    EXPECT_TRUE(*p.decision.choice == rules::ChoiceOption::shoot ||
                *p.decision.choice == rules::ChoiceOption::pass_back);
}

TEST(Decisions, PushesOutOnlyWhereAllowedAndLegally) {
    // 9-ball: the 1 hidden behind a wall of balls from the cue ball.
    std::map<int, Vec2> balls{{0, {0.4, 0.635}}, {1, {2.3, 0.635}}, {9, {1.0, 1.1}}};
    const int wall[] = {2, 3, 4, 5, 6, 7, 8};
    for (int k = 0; k < 7; ++k) balls[wall[k]] = {2.15, 0.635 + (k - 3) * 0.06};
    ai::Position pos = position(Game::nine_ball, {1, 2, 3, 4, 5, 6, 7, 8, 9}, balls);
    const ai::Plan normal = ai::plan(pos, {3, 1.0, 2}, 2);
    EXPECT_FALSE(normal.decision.push_out) << "no push-out on a normal shot";
    pos.state.shot = rules::Shot::after_break;
    const ai::Plan after = ai::plan(pos, {3, 1.0, 2}, 2);
    const rules::Verdict v = play(pos, after.decision);
    if (after.decision.push_out) {
        ASSERT_TRUE(v.choice.has_value());
        EXPECT_EQ(v.choice->by, rules::Player::B);
    }
    EXPECT_FALSE(v.game_over);
}

TEST(Decisions, SameSeedSameDecisionWhateverTheThreads) {
    ai::Position pos = position(Game::eight_ball, {1, 4, 8, 11, 14},
                                {{0, {1.0, 0.6}},
                                 {1, {1.7, 0.9}},
                                 {4, {2.2, 0.3}},
                                 {8, {0.6, 1.0}},
                                 {11, {1.5, 0.2}},
                                 {14, {2.0, 0.7}}});
    for (int level : {1, 5}) {
        const ai::Plan a = ai::plan(pos, {level, 1.0, 2}, 42);
        const ai::Plan b = ai::plan(pos, {level, 1.0, 2}, 42);
        const ai::Plan c = ai::plan(pos, {level, 1.0, 1}, 42);
        expect_same(a.decision, b.decision);
        expect_same(a.decision, c.decision);
        EXPECT_EQ(a.simulations, c.simulations);
        EXPECT_TRUE(same_bits(a.expected_success, c.expected_success));
    }
}

// A pause hook (ai/pause.hpp; the web page without threads returns to its frames there) is called
// between steps and changes no bit of the decision, alone or beside a simulation worker.
int pauses = 0;
void count_pause() {
    ++pauses;
}

TEST(Decisions, APauseHookChangesNothing) {
    const ai::Position pos =
        position(Game::nine_ball, {1, 5, 9},
                 {{0, {0.9, 0.5}}, {1, {1.6, 0.8}}, {5, {2.1, 0.4}}, {9, {0.5, 1.0}}});
    for (int workers : {1, 2}) {
        const ai::Plan plain = ai::plan(pos, {5, 1.0, workers}, 7);
        pauses = 0;
        const ai::Plan paused = ai::plan(pos, {5, 1.0, workers, &count_pause}, 7);
        expect_same(plain.decision, paused.decision);
        EXPECT_EQ(plain.simulations, paused.simulations);
        EXPECT_TRUE(same_bits(plain.expected_value, paused.expected_value));
        EXPECT_GT(pauses, 100);  // paused between steps all through the search
    }
}

}  // namespace
