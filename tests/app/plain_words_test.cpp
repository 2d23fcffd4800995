#include "app/plain_words.hpp"

#include <gtest/gtest.h>

#include "app_support.hpp"

namespace {

TEST(PlainWords, TheInformationBarSaysWhoBreaksAndWhere) {
    const game::Session s = app_test::new_session();
    const std::vector<std::string> lines = app::info_lines(s, rules::Call::nothing());
    ASSERT_GE(lines.size(), 1u);
    EXPECT_EQ(lines[0], "Ann to break");
    EXPECT_EQ(lines.back(), "Ball in hand: drag the cue ball behind the head string");
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
