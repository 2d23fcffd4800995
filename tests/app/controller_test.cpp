#include "app/controller.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "app/aim_preview.hpp"
#include "app/plain_words.hpp"
#include "app/seats.hpp"
#include "app_support.hpp"
#include "physics/table.hpp"

namespace {

using app_test::new_session;
using app_test::options;
using app_test::run_until_idle;

TEST(Controller, TheBreakStartsWithTheCueBallPlacedInTheKitchenAndAimedAtTheRack) {
    app::Controller c(new_session(), options());
    ASSERT_TRUE(c.human_to_act());
    EXPECT_EQ(c.session().phase(), game::Phase::shoot);  // placed for the player, still movable
    EXPECT_EQ(c.session().ball_in_hand(), rules::BallInHand::kitchen);
    const physics::Vec2 cue = c.session().state().positions.at(0);
    EXPECT_LT(cue.x, c.session().table().length() / 4);
    EXPECT_NEAR(c.aim().heading_deg, 0.0, 1e-9);  // straight at the apex ball on the foot spot
    ASSERT_NE(c.preview(), nullptr);
    const physics::Vec2 foot = c.session().table().foot_spot();
    std::optional<int> apex;
    for (const auto& [id, pos] : c.session().state().positions)
        if (id != 0 && std::hypot(pos.x - foot.x, pos.y - foot.y) < 1e-9) apex = id;
    ASSERT_TRUE(apex.has_value());
    EXPECT_EQ(c.preview()->first_ball, apex);
    EXPECT_TRUE(c.preview()->view.ghost.has_value());
}

TEST(Controller, AStrikePlaysTheShotBackInRealTimeThenPassesTheTurn) {
    app::Controller c(new_session(), options());
    c.set_power(0.9);
    c.strike();
    ASSERT_TRUE(c.moving());
    EXPECT_FALSE(c.human_to_act());
    EXPECT_EQ(c.session().history().size(), 1u);
    const double end = c.playback().end();
    EXPECT_GT(end, 1.0);
    EXPECT_DOUBLE_EQ(c.playback().time(), -app::stroke_lead);  // the cue's stroke first
    c.update(0.5);
    EXPECT_NEAR(c.playback().time(), 0.5 - app::stroke_lead, 1e-12);
    EXPECT_TRUE(c.moving());
    run_until_idle(c);
    EXPECT_FALSE(c.moving());
    EXPECT_DOUBLE_EQ(c.playback().time(), end);
    EXPECT_FALSE(c.last_shot_words().empty());
    EXPECT_TRUE(c.human_to_act());
}

// The information bar tells a shot's outcome (the turn, the group, the winner) when the balls
// stop, not at the strike while they still roll.
TEST(Controller, TheInformationBarTellsTheOutcomeWhenTheBallsStop) {
    app::Controller c(new_session(), options());
    const std::vector<std::string> before = c.info();
    ASSERT_FALSE(before.empty());
    EXPECT_EQ(before[0], "Ann to break");
    EXPECT_EQ(before, app::info_lines(c.session(), c.call()));
    c.set_power(0.9);
    c.strike();
    c.update(0.5);
    ASSERT_TRUE(c.moving());
    EXPECT_EQ(c.info(), before);
    EXPECT_NE(app::info_lines(c.session(), c.call()), before);  // the session has judged it
    run_until_idle(c);
    EXPECT_EQ(c.info(), app::info_lines(c.session(), c.call()));
    EXPECT_NE(c.info()[0], "Ann to break");
}

TEST(Controller, SkipJumpsToTheEndAndReplayStartsOver) {
    app::Controller c(new_session(), options());
    c.set_power(0.9);
    c.strike();
    c.update(0.1);
    c.skip();
    EXPECT_FALSE(c.moving());
    const auto after = c.balls_now();
    const app::BallOrientations turned = c.orientations();
    const int serial = c.shot_serial();
    c.replay();
    EXPECT_TRUE(c.moving());
    EXPECT_EQ(c.shot_serial(), serial + 1);
    EXPECT_DOUBLE_EQ(c.playback().time(), -app::stroke_lead);
    run_until_idle(c);
    const auto again = c.balls_now();
    ASSERT_EQ(after.size(), again.size());
    for (std::size_t i = 0; i < after.size(); ++i) {
        EXPECT_EQ(after[i].pos.x, again[i].pos.x);
        EXPECT_EQ(after[i].pos.y, again[i].pos.y);
    }
    // A replay ends with the balls turned as they were after the shot.
    for (int id = 0; id <= 15; ++id)
        EXPECT_EQ(c.orientations().of(id), turned.of(id)) << "ball " << id;
}

TEST(Controller, BallInHandRefusesAnIllegalSpotWithTheReason) {
    app::Controller c(new_session(), options());
    const double L = c.session().table().length();
    EXPECT_FALSE(c.move_cue_ball({L / 2, 0.6}));  // in front of the head string on the break
    EXPECT_NE(c.refusal().find("head string"), std::string::npos) << c.refusal();
    EXPECT_TRUE(c.move_cue_ball({0.4, 0.4}));
    EXPECT_TRUE(c.refusal().empty());
    EXPECT_EQ(c.session().state().positions.at(0).x, 0.4);
}

// The reasons as a player says them: no metres, no "2R".
TEST(Controller, BallInHandRefusalsAreInAPlayersWords) {
    app::Controller c(app_test::session_at({{10, {0.4, 0.4}}, {8, {2.0, 0.6}}}, "in_hand"),
                      options());
    EXPECT_FALSE(c.move_cue_ball({0.4056, 0.4}));
    EXPECT_EQ(c.refusal(), "The cue ball can't go on top of the 10.");
    EXPECT_FALSE(c.move_cue_ball({0.01, 0.4}));
    EXPECT_EQ(c.refusal(), "The cue ball must go on the cloth.");
    app::Controller k(app_test::new_session(), options());
    EXPECT_FALSE(k.move_cue_ball({1.2, 0.6}));
    EXPECT_EQ(k.refusal(),
              "The cue ball goes behind the head string (the line across the table) with ball in "
              "hand in the kitchen.");
}

TEST(Controller, TheAimGuidePotsAStraightShotIntoThePocketItNames) {
    const physics::Table table = physics::build_table(*physics::table_preset("9ft"));
    const physics::Params params;
    const double R = params.ball_radius;
    const physics::Pocket& ne = table.pockets[static_cast<std::size_t>(physics::PocketId::NE)];
    // The object ball 0.5 m from the NE pocket, the cue ball 0.8 m behind it on the same line.
    const physics::Vec2 dir = (1.0 / physics::norm(ne.centre - physics::Vec2{1.6, 0.5})) *
                              (ne.centre - physics::Vec2{1.6, 0.5});
    const physics::Vec2 object = ne.centre - 0.5 * dir;
    const physics::Vec2 cue = object - 0.8 * dir;
    physics::BallState balls[2];
    balls[0].id = 0;
    balls[0].pos = cue;
    balls[1].id = 5;
    balls[1].pos = object;
    physics::Stroke k;
    k.speed = 2.0;
    k.heading_deg = std::atan2(dir.y, dir.x) * 180.0 / 3.141592653589793;
    const app::AimPreview p = app::preview_aim(table, params, balls, k);
    ASSERT_EQ(p.first_ball, 5);
    EXPECT_TRUE(p.pots);
    EXPECT_EQ(p.pocket, static_cast<int>(physics::PocketId::NE));
    ASSERT_TRUE(p.view.ghost.has_value());
    EXPECT_NEAR(std::hypot(p.view.ghost->x - object.x, p.view.ghost->y - object.y), 2 * R, 1e-6);
    EXPECT_GE(p.view.cue_path.size(), 2u);
    EXPECT_GE(p.view.object_path.size(), 2u);
    // Aimed square to the line and softly, the 5 is missed: the guide shows the free path.
    k.heading_deg += 90.0;
    k.speed = 0.5;
    const app::AimPreview miss = app::preview_aim(table, params, balls, k);
    EXPECT_FALSE(miss.first_ball.has_value());
    EXPECT_FALSE(miss.view.ghost.has_value());
    EXPECT_GE(miss.view.cue_path.size(), 2u);
}

TEST(Controller, ClickingABallAndAPocketCallsThem) {
    app::Controller c(new_session(), options());
    c.set_power(0.9);
    c.strike();
    run_until_idle(c);
    ASSERT_TRUE(c.human_to_act());
    const rules::GameState& st = c.session().state();
    ASSERT_NE(st.shot, rules::Shot::break_shot);
    int ball = 0;
    for (int id : st.on_table)
        if (id != 8) {
            ball = id;
            break;
        }
    c.click_table(st.positions.at(ball));
    ASSERT_TRUE(c.call_is_manual());
    EXPECT_EQ(c.call().ball, ball);
    const physics::Pocket& ne =
        c.session().table().pockets[static_cast<std::size_t>(physics::PocketId::NE)];
    c.click_table(ne.centre);
    EXPECT_EQ(c.call(), rules::Call::ball_in(ball, static_cast<int>(physics::PocketId::NE)));
    c.click_table(st.positions.at(8));  // the 8 is not callable on an open table
    EXPECT_EQ(c.refusal(), "You may not call the 8 now.");
    EXPECT_EQ(c.call().ball, ball);
    c.clear_call();
    EXPECT_FALSE(c.call_is_manual());
}

TEST(Controller, MouseAimIsPreciseToAHundredthOfADegree) {
    app::Controller c(new_session(), options());
    const double h0 = c.aim().heading_deg;
    c.turn_aim(-0.05);
    EXPECT_NEAR(c.aim().heading_deg, h0 - 0.05, 1e-12);
    c.set_heading(370.0);
    EXPECT_NEAR(c.aim().heading_deg, 10.0, 1e-12);
}

TEST(Controller, ComputerSeatsPlayByThemselvesAndTheSameSeedPlaysTheSameGame) {
    auto play = [](std::uint64_t seed) {
        app::ControllerOptions o = options("random", "random");
        o.seed = seed;
        o.playback_speed = 0.0;
        app::Controller c(new_session(rules::Game::nine_ball, 4), o);
        app_test::play_to_the_end(c);
        EXPECT_EQ(c.session().phase(), game::Phase::game_over);
        EXPECT_TRUE(c.session().winner().has_value());
        EXPECT_GT(c.session().history().size(), 1u);
        return c.session().to_json();
    };
    const std::string a = play(3);
    EXPECT_EQ(a, play(3));
}

TEST(Controller, RestartRacksTheNextGame) {
    app::Controller c(new_session(), options());
    c.set_power(0.9);
    c.strike();
    c.skip();
    c.restart();
    EXPECT_EQ(c.session().game_number(), 1);
    EXPECT_TRUE(c.session().history().empty());
    EXPECT_FALSE(c.playback().has_shot());
    EXPECT_EQ(c.session().state().on_table.size(), 15u);
    EXPECT_TRUE(c.human_to_act());
    EXPECT_TRUE(c.last_shot_words().empty());
}

// Restart before any shot of a game racks that game again: the break stays with its breaker.
TEST(Controller, RestartBeforeAnyShotKeepsTheGameAndTheBreak) {
    app::Controller c(new_session(), options());
    const auto rack = c.session().state().positions;
    c.move_cue_ball({0.4, 0.4});
    c.restart();
    EXPECT_EQ(c.session().game_number(), 0);
    EXPECT_EQ(c.session().to_act(), rules::Player::A);
    EXPECT_EQ(c.session().state().shot, rules::Shot::break_shot);
    auto now = c.session().state().positions;
    now.erase(0);
    auto racked = rack;
    racked.erase(0);
    EXPECT_EQ(now, racked);                                 // the same rack
    EXPECT_NE(c.session().state().positions.at(0).x, 0.4);  // the cue ball back at its spot
}

TEST(Controller, NothingHappensWhenItIsNotTheHumansTurn) {
    app::ControllerOptions o = options("random", "human");
    app::Controller c(new_session(), o);  // the random player breaks
    EXPECT_TRUE(c.computer_thinking());
    const double heading = c.aim().heading_deg;
    c.strike();
    c.turn_aim(10.0);
    EXPECT_EQ(c.aim().heading_deg, heading);
    EXPECT_TRUE(c.session().history().empty());
    run_until_idle(c);
    EXPECT_EQ(c.session().history().size(), 1u);
}

}  // namespace

namespace {

TEST(Controller, AHintSetsTheAimOfTheStrongestAiWithoutStriking) {
    app::Controller c(new_session(), options());
    c.set_power(0.9);
    c.strike();
    run_until_idle(c);
    ASSERT_TRUE(c.human_to_act());
    const std::size_t shots = c.session().history().size();
    c.hint();
    EXPECT_TRUE(c.computer_thinking());
    EXPECT_FALSE(c.human_to_act());
    run_until_idle(c);
    EXPECT_TRUE(c.human_to_act());
    EXPECT_EQ(c.session().history().size(), shots);  // nothing was struck
    ASSERT_NE(c.preview(), nullptr);
    EXPECT_TRUE(c.call_is_manual());  // 8-ball after the break: the AI calls a ball or a safety
    // The hint's spin and elevation are for this shot only: the next turn has the player's own.
    const app::Aim hinted = c.aim();
    EXPECT_TRUE(hinted.side != 0.0 || hinted.top != 0.0) << "this hint has no spin to carry";
    c.strike();
    run_until_idle(c);
    ASSERT_TRUE(c.human_to_act());
    EXPECT_EQ(c.aim().side, 0.0);
    EXPECT_EQ(c.aim().top, 0.0);
    EXPECT_EQ(c.aim().elevation_deg, 0.0);
}

}  // namespace
