// Practice in the controller (docs/app.md, "Practice"): the session mirrors the practice
// position, any ball is dragged to a legal place, shots need no rules, Try again undoes them.
#include <gtest/gtest.h>

#include "app/controller.hpp"
#include "app_support.hpp"

namespace app {
namespace {

using app_test::options;
using app_test::run_until_idle;

void start(Controller& c) {
    c.start_practice(game::Practice(rules::Game::eight_ball, {}, {}, 8), options());
}

TEST(PracticeController, TheSessionMirrorsThePracticePosition) {
    Controller c(app_test::new_session(), options("ai:2", "ai:3"));
    c.start_practice(game::Practice(rules::Game::nine_ball, {}, {}, 8), options("ai:2", "ai:3"));
    ASSERT_TRUE(c.practicing());
    EXPECT_EQ(c.session().state().positions, c.practice()->balls());
    EXPECT_EQ(c.session().config().game, rules::Game::nine_ball);
    EXPECT_TRUE(c.human_to_act()) << "both seats are the player's";
    EXPECT_EQ(c.call(), rules::Call::nothing()) << "nothing is called in practice";
    EXPECT_EQ(c.info().front(), "Practice: drag any ball with the left button");
}

TEST(PracticeController, AnyBallMovesToALegalPlaceOnlyWithThePlayersWords) {
    Controller c(app_test::new_session(), options());
    start(c);
    EXPECT_TRUE(c.move_ball(7, {0.5, 0.3}));
    EXPECT_EQ(c.session().state().positions.at(7), (physics::Vec2{0.5, 0.3}));
    const physics::Vec2 one = c.session().state().positions.at(1);
    EXPECT_FALSE(c.move_ball(7, one));
    EXPECT_EQ(c.refusal(), "The 7 can't go on top of the 1.");
    EXPECT_EQ(c.session().state().positions.at(7), (physics::Vec2{0.5, 0.3}));
}

TEST(PracticeController, AShotPlaysWithoutRulesAndTryAgainUndoesIt) {
    Controller c(app_test::new_session(), options());
    start(c);
    const std::map<int, physics::Vec2> before = c.session().state().positions;
    c.set_power(1.0);
    c.strike();
    EXPECT_TRUE(c.moving());
    run_until_idle(c);
    EXPECT_NE(c.session().state().positions, before);
    EXPECT_EQ(c.session().state().positions, c.practice()->balls());
    EXPECT_TRUE(c.human_to_act()) << "no turns: the player shoots again";
    EXPECT_TRUE(c.session().history().empty()) << "no rules, no game record";
    for (int id = 1; id <= 15; ++id)
        EXPECT_EQ(c.practice()->balls().count(id) == 1, c.session().state().has(id)) << id;
    c.try_again();
    EXPECT_EQ(c.session().state().positions, before);
    EXPECT_FALSE(c.practice()->can_try_again());
}

TEST(PracticeController, RestartRacksAgainAndANewGameEndsPractice) {
    Controller c(app_test::new_session(), options());
    start(c);
    ASSERT_TRUE(c.move_ball(7, {0.5, 0.3}));
    c.restart();
    EXPECT_TRUE(c.practicing());
    EXPECT_EQ(c.practice()->balls().size(), 16u);
    EXPECT_NE(c.session().state().positions.at(7), (physics::Vec2{0.5, 0.3}));
    c.replace(app_test::new_session(), options());
    EXPECT_FALSE(c.practicing());
    EXPECT_FALSE(c.move_ball(7, {0.5, 0.3}));
}

}  // namespace
}  // namespace app

namespace app {
namespace {

TEST(PracticeController, HintGivesAnAimAtThePracticePosition) {
    Controller c(app_test::new_session(), app_test::options());
    c.start_practice(game::Practice(rules::Game::nine_ball, {}, {}, 8), app_test::options());
    ASSERT_TRUE(c.move_ball(0, {1.2, 0.4}));
    c.hint();
    c.wait_for_computer();
    c.update(0.01);
    EXPECT_FALSE(c.computer_thinking());
    EXPECT_TRUE(c.human_to_act());
    EXPECT_TRUE(c.refusal().empty()) << c.refusal();
    EXPECT_EQ(c.session().state().positions.at(0), (physics::Vec2{1.2, 0.4}));
}

}  // namespace
}  // namespace app
