// Practice in the controller (docs/app.md, "Practice"): the session mirrors the practice
// position, any ball is dragged to a legal place, shots need no rules, Try again undoes them.
#include <gtest/gtest.h>

#include "app/controller.hpp"
#include "app_support.hpp"
#include "physics/markings.hpp"

namespace app {
namespace {

using app_test::options;
using app_test::run_until_idle;

void start(Controller& c) {
    c.start_practice(game::Practice(physics::RackType::eight_ball, {}, {}, 8), options());
}

TEST(PracticeController, TheSessionMirrorsThePracticePosition) {
    Controller c(app_test::new_session(), options("ai:2", "ai:3"));
    c.start_practice(game::Practice(physics::RackType::nine_ball, {}, {}, 8),
                     options("ai:2", "ai:3"));
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
    c.start_practice(game::Practice(physics::RackType::nine_ball, {}, {}, 8), app_test::options());
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

// ---- Practice on the snooker and three-cushion tables

namespace app {
namespace {

namespace sb = physics::snooker_ball;

TEST(PracticeTablesController, SnookerIsDrawnAsSnookerAndAimedAtTheNearestRed) {
    Controller c(app_test::new_session(), app_test::options());
    c.start_practice(game::Practice::on_own_table(physics::RackType::snooker, 8),
                     app_test::options());
    EXPECT_EQ(c.look(), render::GameLook::snooker);
    EXPECT_EQ(c.session().state().positions, c.practice()->balls());
    EXPECT_EQ(c.session().state().positions.size(), 22u);
    EXPECT_EQ(c.session().config().params.ball_radius, c.practice()->params().ball_radius);
    EXPECT_EQ(c.session().config().table.length, physics::snooker_table_spec().length);
    ASSERT_NE(c.preview(), nullptr);
    ASSERT_TRUE(c.preview()->first_ball);
    EXPECT_TRUE(physics::is_red(*c.preview()->first_ball))
        << "from the D, the reds rather than a baulk colour: " << *c.preview()->first_ball;
    EXPECT_EQ(c.cue_ball_id(), 0);
}

TEST(PracticeTablesController, SnookerBallsMoveByNameAndAPocketedCueBallComesBackInTheD) {
    Controller c(app_test::new_session(), app_test::options());
    c.start_practice(game::Practice::on_own_table(physics::RackType::snooker, 8),
                     app_test::options());
    const physics::Vec2 pink = c.session().state().positions.at(sb::pink);
    EXPECT_FALSE(c.move_ball(4, pink));
    EXPECT_EQ(c.refusal(), "The red can't go on top of the pink.");
    ASSERT_TRUE(c.move_ball(0, {0.20, 0.20}));
    c.set_heading(225.0);
    c.set_power(power_of_speed(1.5));
    c.strike();
    app_test::run_until_idle(c);
    EXPECT_EQ(c.last_shot_words(), "Pocketed the cue ball (back in the D).");
    EXPECT_TRUE(
        physics::snooker_markings(c.session().table()).in_d(c.session().state().positions.at(0)));
    c.try_again();
    EXPECT_EQ(c.session().state().positions.at(0), (physics::Vec2{0.20, 0.20}));
    c.restart();
    EXPECT_EQ(c.practice()->game(), physics::RackType::snooker) << "the same game's table";
    EXPECT_EQ(c.session().state().positions.size(), 22u);
    EXPECT_EQ(c.look(), render::GameLook::snooker);
}

TEST(PracticeTablesController, HintIsOnlyWhereAPlayerKnowsTheTable) {
    for (physics::RackType game : {physics::RackType::snooker, physics::RackType::three_cushion}) {
        Controller c(app_test::new_session(), app_test::options());
        c.start_practice(game::Practice::on_own_table(game, 8), app_test::options());
        EXPECT_FALSE(c.hint_available());
        const Aim before = c.aim();
        c.hint();
        EXPECT_FALSE(c.computer_thinking()) << "nothing is asked";
        EXPECT_EQ(c.refusal(), "No hint here: in practice Hint knows the pool tables only.")
            << "the H key says why";
        EXPECT_EQ(c.aim().heading_deg, before.heading_deg);
    }
    Controller pool(app_test::new_session(), app_test::options());
    pool.start_practice(game::Practice::on_own_table(physics::RackType::nine_ball, 8),
                        app_test::options());
    EXPECT_TRUE(pool.hint_available());
}

TEST(PracticeTablesController, ThreeCushionPlaysTheWhiteAndTriesAgain) {
    Controller c(app_test::new_session(), app_test::options());
    c.start_practice(game::Practice::on_own_table(physics::RackType::three_cushion, 8),
                     app_test::options());
    EXPECT_EQ(c.look(), render::GameLook::carom);
    ASSERT_NE(c.preview(), nullptr);
    EXPECT_EQ(c.preview()->first_ball, physics::carom_ball::red) << "aimed as the opening";
    const std::map<int, physics::Vec2> start = c.session().state().positions;
    EXPECT_EQ(start.size(), 3u);
    EXPECT_FALSE(c.move_ball(1, start.at(2)));
    EXPECT_EQ(c.refusal(), "The yellow can't go on top of the red.");
    c.set_power(0.8);
    c.strike();
    app_test::run_until_idle(c);
    EXPECT_EQ(c.last_shot_words(), "Nothing was pocketed.");
    EXPECT_EQ(c.session().state().positions.size(), 3u);
    EXPECT_NE(c.session().state().positions, start);
    c.try_again();
    EXPECT_EQ(c.session().state().positions, start);
    c.replace(app_test::new_session(), app_test::options());
    EXPECT_EQ(c.look(), render::GameLook::pool) << "practice over: the pool table again";
}

}  // namespace
}  // namespace app
