// The flow around a verdict: positions carried to the next state, choices resolved.
#include <stdexcept>

#include "scenario.hpp"

namespace rules::test {
namespace {

using C = ChoiceOption;

TEST(Positions, BallsMoveToTheirLastEventPosition) {
    GameState s = eight_groups().pos(0, 0.5, 0.5).pos(3, 1.0, 0.5).pos(4, 1.5, 0.5);
    std::vector<Event> e{at(hit(0, 3), {0.94, 0.5}, physics::Vec2{1.0, 0.5}),
                         at(rail(3), {1.2, 1.24}), at(roll(3), {1.3, 1.0}),
                         at(roll(0), {0.96, 0.5})};
    Verdict v = judge(eight_ball(), s, e);
    EXPECT_EQ(v.state.positions.at(0).x, 0.96);
    EXPECT_EQ(v.state.positions.at(3).x, 1.3);
    EXPECT_EQ(v.state.positions.at(3).y, 1.0);
    EXPECT_EQ(v.state.positions.at(4).x, 1.5);  // did not move
}

TEST(Positions, PocketedBallsAndACueBallInHandAreDropped) {
    GameState s = eight_groups().pos(0, 0.5, 0.5).pos(3, 1.0, 0.5);
    std::vector<Event> e{hit(0, 3), pot(3, P::SW), at(pot(0, P::N), {1.27, 1.27})};
    Verdict v = judge(eight_ball(), s, e);
    EXPECT_EQ(v.state.positions.count(3), 0u);
    EXPECT_EQ(v.state.positions.count(0), 0u);
    EXPECT_EQ(v.state.cue_ball, CueBall::in_hand);
}

TEST(Positions, SpottedBallIsPlaced) {
    const TableSize t;
    // Ball 2 sits on the foot spot: the 9 goes right behind it.
    GameState s = nine_table().pos(0, 0.5, 0.6).pos(2, 1.905, 0.635);
    std::vector<Event> e{hit(0, 2), hit(2, 9), pot(9, P::NE)};
    Verdict v = judge(nine_ball(), s, e);
    ASSERT_EQ(v.respot, (std::vector<int>{9}));
    EXPECT_NEAR(v.state.positions.at(9).x, 1.905 + 2 * t.ball_radius, 1e-12);
    EXPECT_DOUBLE_EQ(v.state.positions.at(9).y, 0.635);
}

Verdict eight_on_the_break() {
    return judge(eight_ball(), eight_break().shooter(B).breaker(B).fouls(0, 1),
                 std::vector<Event>{hit(0, 1), pot(8, P::N)});
}

TEST(ResolveChoice, SpotEightAndContinue) {
    Resolution r = resolve_choice(eight_ball(), eight_on_the_break(), C::spot_8_and_continue);
    EXPECT_FALSE(r.rerack);
    EXPECT_EQ(r.state.shooter, B);
    EXPECT_TRUE(r.state.has(8));
    EXPECT_EQ(r.ball_in_hand, BallInHand::none);
}

TEST(ResolveChoice, RebreakByTheChooser) {
    Resolution r = resolve_choice(eight_ball(), eight_on_the_break(), C::rebreak);
    EXPECT_TRUE(r.rerack);
    EXPECT_EQ(r.state.shooter, B);
    EXPECT_EQ(r.state.breaker, B);
    EXPECT_EQ(r.state.shot, Shot::break_shot);
    EXPECT_EQ(r.state.on_table, range(1, 15));
    EXPECT_EQ(r.state.cue_ball, CueBall::in_hand_kitchen);
    EXPECT_EQ(r.state.fouls_in_row[0], 0);
    EXPECT_EQ(r.ball_in_hand, BallInHand::kitchen);
}

TEST(ResolveChoice, IllegalBreakOptions) {
    Verdict v = judge(eight_ball(), eight_break(), std::vector<Event>{hit(0, 1), rail(1)});
    ASSERT_TRUE(v.choice);
    Resolution accept = resolve_choice(eight_ball(), v, C::accept_table);
    EXPECT_EQ(accept.state.shooter, B);
    EXPECT_EQ(accept.state.cue_ball, CueBall::on_table);
    Resolution mine = resolve_choice(eight_ball(), v, C::rerack_and_break);
    EXPECT_TRUE(mine.rerack);
    EXPECT_EQ(mine.state.breaker, B);
    Resolution theirs = resolve_choice(eight_ball(), v, C::rerack_offender_breaks);
    EXPECT_TRUE(theirs.rerack);
    EXPECT_EQ(theirs.state.breaker, A);
    EXPECT_EQ(theirs.state.shooter, A);
    EXPECT_THROW(resolve_choice(eight_ball(), v, C::pass_back), std::invalid_argument);
}

TEST(ResolveChoice, BreakFoulKitchenBallInHand) {
    std::vector<Event> e = four_rail_break();
    e.push_back(off(5));
    GameState s = eight_break().pos(0, 0.4, 0.6);
    Verdict v = judge(eight_ball(), s, e);
    Resolution r = resolve_choice(eight_ball(), v, C::kitchen_ball_in_hand);
    EXPECT_EQ(r.state.shooter, B);
    EXPECT_EQ(r.state.cue_ball, CueBall::in_hand_kitchen);
    EXPECT_EQ(r.ball_in_hand, BallInHand::kitchen);
    EXPECT_EQ(r.state.positions.count(0), 0u);
}

TEST(ResolveChoice, PushOutShootOrPassBack) {
    Verdict v =
        judge(nine_ball(), nine_table().shot(Shot::push_out), std::vector<Event>{hit(0, 5)});
    Resolution shoot = resolve_choice(nine_ball(), v, C::shoot);
    EXPECT_EQ(shoot.state.shooter, B);
    EXPECT_EQ(shoot.state.shot, Shot::after_push_out);
    Resolution back = resolve_choice(nine_ball(), v, C::pass_back);
    EXPECT_EQ(back.state.shooter, A);
    EXPECT_EQ(back.state.shot, Shot::after_push_out);
}

TEST(ResolveChoice, NothingPending) {
    Verdict v = judge(nine_ball(), nine_table(), std::vector<Event>{hit(0, 1), rail(1)});
    EXPECT_THROW(resolve_choice(nine_ball(), v, C::shoot), std::invalid_argument);
}

TEST(Stalemate, ReracksForTheOriginalBreaker) {
    GameState s = eight_groups().shooter(B).breaker(A).balls({3, 8, 12}).fouls(1, 0);
    Resolution r = stalemate(eight_ball(), s);
    EXPECT_TRUE(r.rerack);
    EXPECT_EQ(r.state.shooter, A);
    EXPECT_EQ(r.state.breaker, A);
    EXPECT_EQ(r.state.on_table, range(1, 15));
    EXPECT_FALSE(r.state.group_a.has_value());
}

TEST(Judge, IsDeterministicAndPure) {
    GameState s = eight_open();
    std::vector<Event> e{hit(0, 3), pot(3, P::SW)};
    Verdict a = judge(eight_ball(), s, e), b = judge(eight_ball(), s, e);
    EXPECT_EQ(a.state.on_table, b.state.on_table);
    EXPECT_EQ(a.state.group_a, b.state.group_a);
    EXPECT_TRUE(s.has(3));  // the input is untouched
}

TEST(InitialState, RacksEveryBallOfTheGame) {
    EXPECT_EQ(initial_state(Game::nine_ball, B).on_table, range(1, 9));
    EXPECT_EQ(initial_state(Game::nine_ball, B).shooter, B);
    EXPECT_EQ(initial_state(Game::eight_ball, A).on_table, range(1, 15));
}

}  // namespace
}  // namespace rules::test
