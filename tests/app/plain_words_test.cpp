#include "app/plain_words.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "app/controller.hpp"
#include "app_support.hpp"

namespace {

TEST(PlainWords, TheInformationBarSaysWhoBreaksAndWhere) {
    const game::Session s = app_test::new_session();
    const std::vector<std::string> lines = app::info_lines(s, rules::Call::nothing());
    ASSERT_GE(lines.size(), 1u);
    EXPECT_EQ(lines[0], "Ann to break");
    EXPECT_EQ(lines.back(), "Ball in hand: drag the cue ball behind the head string");
}

// The 5 is potted in the NE corner, but the call was the SE corner: no foul, the turn passes,
// and the words say why.
TEST(PlainWords, ABallThatWasNotTheCallSaysSoAndWhatFollows) {
    const physics::Table table = app_test::new_session().table();
    const physics::Pocket& ne = table.pockets[static_cast<std::size_t>(physics::PocketId::NE)];
    const physics::Pocket& se = table.pockets[static_cast<std::size_t>(physics::PocketId::SE)];
    const physics::Vec2 from{1.6, 0.5};
    const physics::Vec2 dir = (1.0 / physics::norm(ne.centre - from)) * (ne.centre - from);
    const physics::Vec2 object = ne.centre - 0.5 * dir, cue = object - 0.8 * dir;
    app::Controller c(
        app_test::session_at({{0, cue}, {5, object}, {3, {0.5, 1.0}}, {8, {0.5, 0.3}}}),
        app_test::options());
    c.set_power(0.25);
    c.set_spin(0.0, -0.4);  // draw: the cue ball stays out of the pocket
    c.set_heading(std::atan2(dir.y, dir.x) * 180.0 / std::numbers::pi);
    c.click_table(se.centre);
    ASSERT_EQ(c.call(), rules::Call::ball_in(5, static_cast<int>(physics::PocketId::SE)));
    c.strike();
    app_test::run_until_idle(c);
    EXPECT_EQ(c.last_shot_words(),
              "Ann pocketed the 5. It was not the call (the 5 in the SE corner pocket): Bob's "
              "turn.");
    EXPECT_EQ(c.info()[0], "Bob's turn");
}

// A replay shows the shot as it was: the panel's words at its strike, the tray without the
// ball until it drops.
TEST(PlainWords, AReplayShowsTheWordsAndTheTrayAsTheyWere) {
    const physics::Table table = app_test::new_session().table();
    const physics::Pocket& ne = table.pockets[static_cast<std::size_t>(physics::PocketId::NE)];
    const physics::Vec2 from{1.6, 0.5};
    const physics::Vec2 dir = (1.0 / physics::norm(ne.centre - from)) * (ne.centre - from);
    const physics::Vec2 object = ne.centre - 0.5 * dir, cue = object - 0.8 * dir;
    app::Controller c(
        app_test::session_at({{0, cue}, {5, object}, {3, {0.5, 1.0}}, {8, {0.5, 0.3}}}),
        app_test::options());
    c.set_power(0.25);
    c.set_spin(0.0, -0.4);
    c.set_heading(std::atan2(dir.y, dir.x) * 180.0 / std::numbers::pi);
    const std::vector<int> tray_before = c.tray();
    const std::vector<std::string> info_before = c.info();
    c.strike();
    c.update(0.2);
    ASSERT_TRUE(c.moving());
    EXPECT_EQ(c.tray(), tray_before);  // the 5 still rolls
    app_test::run_until_idle(c);
    const std::vector<std::string> info_after = c.info();
    const std::string words_after = c.last_shot_words();
    ASSERT_NE(info_after, info_before);
    std::vector<int> tray_after = tray_before;
    tray_after.push_back(5);
    ASSERT_EQ(c.tray(), tray_after);
    EXPECT_FALSE(c.replaying());

    c.replay();
    c.update(0.2);
    ASSERT_TRUE(c.replaying());
    EXPECT_EQ(c.tray(), tray_before);
    EXPECT_EQ(c.info(), info_before);
    EXPECT_EQ(c.last_shot_words(), "");  // nothing had been played before it
    app_test::run_until_idle(c);
    EXPECT_FALSE(c.replaying());
    EXPECT_EQ(c.tray(), tray_after);
    EXPECT_EQ(c.info(), info_after);
    EXPECT_EQ(c.last_shot_words(), words_after);
}

TEST(PlainWords, NineBallNamesTheBallToHit) {
    const game::Session s = app_test::new_session(rules::Game::nine_ball);
    const std::vector<std::string> lines = app::info_lines(s, rules::Call::nothing());
    EXPECT_EQ(lines[1], "Ball to hit: the 1");
}

TEST(PlainWords, TheEndOfAGameNamesTheWinner) {
    game::Session s = app_test::new_session(rules::Game::nine_ball, 3);
    app::ControllerOptions o = app_test::options("random", "random");
    o.playback_speed = 0.0;
    app::Controller c(std::move(s), o);
    app_test::play_to_the_end(c);
    ASSERT_EQ(c.session().phase(), game::Phase::game_over);
    const std::vector<std::string> lines = app::info_lines(c.session(), rules::Call::nothing());
    EXPECT_EQ(lines[0], c.session().name(*c.session().winner()) + " wins!");
    EXPECT_NE(c.last_shot_words().find("wins the game"), std::string::npos) << c.last_shot_words();
}

TEST(PlainWords, EveryFoulAndChoiceHasWords) {
    for (int f = 0; f <= static_cast<int>(rules::Foul::third_consecutive_foul); ++f)
        EXPECT_NE(app::foul_words(static_cast<rules::Foul>(f)), "foul");
    for (int o = 0; o <= static_cast<int>(rules::ChoiceOption::pass_back); ++o)
        EXPECT_NE(app::choice_words(static_cast<rules::ChoiceOption>(o)), "?");
    EXPECT_EQ(app::pocket_words(static_cast<int>(physics::PocketId::N)), "N side");
    EXPECT_EQ(app::pocket_words(static_cast<int>(physics::PocketId::SW)), "SW corner");
}

}  // namespace
