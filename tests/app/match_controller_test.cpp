// Snooker and three-cushion in the controller (docs/app.md, "Snooker and three-cushion"): the
// session mirrors the match's table, the cue ball in hand goes in the D, the nomination comes
// from the aim, the after-foul choice, computer seats through app/seats.hpp, the words.
#include <gtest/gtest.h>

#include <functional>
#include <set>

#include "app/controller.hpp"
#include "app/match_words.hpp"
#include "app_support.hpp"
#include "game/json_field.hpp"

namespace app {
namespace {

using app_test::options;
using app_test::run_until_idle;
namespace sb = physics::snooker_ball;

game::SnookerSession snooker_match(int best_of = 1) {
    game::SnookerConfig c;
    c.names = {"Ann", "Bob"};
    c.best_of = best_of;
    return game::SnookerSession(c);
}

game::CaromSession carom_game(int target = 15) {
    game::CaromConfig c;
    c.names = {"Ann", "Bob"};
    c.options.target = target;
    return game::CaromSession(c);
}

TEST(MatchController, SnookerStartsWithTheCueBallPlacedInTheDAndTheTableMirrored) {
    Controller c(app_test::new_session(), options());
    c.start_snooker(snooker_match(), options());
    ASSERT_TRUE(c.snooker());
    EXPECT_EQ(c.look(), render::GameLook::snooker);
    const auto& pos = c.session().state().positions;
    ASSERT_TRUE(pos.count(sb::cue));
    EXPECT_TRUE(c.snooker()->marks().marks.in_d(pos.at(sb::cue)));
    EXPECT_EQ(pos, c.snooker()->state().positions);
    EXPECT_TRUE(c.human_to_act());
    EXPECT_EQ(c.info().front(), "Ann to play — on: a red");
    EXPECT_FALSE(c.move_cue_ball({1.5, 0.9}));
    EXPECT_EQ(c.refusal(), "The cue ball in hand goes in the D.");
    const physics::Vec2 d = c.snooker()->marks().marks.d_centre();
    EXPECT_TRUE(c.move_cue_ball({d.x - 0.1, d.y}));
    EXPECT_EQ(c.session().state().positions.at(sb::cue), (physics::Vec2{d.x - 0.1, d.y}));
}

TEST(MatchController, AFoulIsWordedAndTheChoiceGoesToTheOpponent) {
    ControllerOptions o = options();
    o.playback_speed = 0.0;
    Controller c(app_test::new_session(), o);
    c.start_snooker(snooker_match(), o);
    c.set_heading(180.0);  // into the baulk cushion: no ball hit
    c.set_power(0.1);
    c.strike();
    run_until_idle(c);
    EXPECT_EQ(c.last_shot_words().rfind("Foul: 4 points to Bob — the cue ball hit no ball", 0), 0u)
        << c.last_shot_words();
    ASSERT_EQ(c.snooker()->phase(), game::MatchPhase::choose);
    EXPECT_TRUE(c.human_to_act()) << "Bob chooses";
    EXPECT_EQ(c.info().front(), "Foul by Ann: Bob chooses");
    c.strike();
    EXPECT_EQ(c.refusal(), "First Bob chooses: play from here, or ask Ann to play again.");
    c.choose_after_foul(rules::AfterFoul::play_again);
    EXPECT_EQ(c.last_shot_words(), "Bob asks Ann to play again.");
    EXPECT_EQ(c.snooker()->state().shooter, rules::Player::A);
}

TEST(MatchController, RandomSeatsPlayASnookerFrameToTheEnd) {
    ControllerOptions o = options("random", "random");
    o.playback_speed = 0.0;
    Controller c(app_test::new_session(), o);
    c.start_snooker(snooker_match(), o);
    EXPECT_FALSE(c.human_to_act());
    for (int i = 0; i < 200000 && !c.snooker()->frame_winner(); ++i) {
        c.wait_for_computer();
        c.update(0.05);
    }
    ASSERT_TRUE(c.snooker()->frame_winner());
    EXPECT_NE(c.last_shot_words().find("wins the frame"), std::string::npos) << c.last_shot_words();
}

TEST(MatchController, ThreeCushionStrikesTheStrikersOwnBallAndSaysWhy) {
    ControllerOptions o = options();
    o.playback_speed = 0.0;
    Controller c(app_test::new_session(), o);
    c.start_carom(carom_game(), o);
    EXPECT_EQ(c.look(), render::GameLook::carom);
    EXPECT_EQ(c.cue_ball_id(), physics::carom_ball::white);
    EXPECT_EQ(c.info().front(), "Ann to play the white — inning 1");
    c.set_heading(180.0);
    c.set_power(0.05);
    c.strike();
    run_until_idle(c);
    EXPECT_EQ(c.last_shot_words(), "Foul: the opening stroke must hit the red first. Bob to play.");
    EXPECT_EQ(c.cue_ball_id(), physics::carom_ball::yellow);
    EXPECT_EQ(c.stroke_of(c.aim()).ball, physics::carom_ball::yellow);
    EXPECT_EQ(c.info().front(), "Bob to play the yellow — inning 1");
}

TEST(MatchController, RandomSeatsPlayAThreeCushionGameToTheEnd) {
    ControllerOptions o = options("random", "random");
    o.playback_speed = 0.0;
    Controller c(app_test::new_session(), o);
    c.start_carom(carom_game(2), o);
    for (int i = 0; i < 200000 && !c.carom()->game_over(); ++i) {
        c.wait_for_computer();
        c.update(0.05);
    }
    ASSERT_TRUE(c.carom()->game_over());
    c.next_frame();
    EXPECT_EQ(c.carom()->game_number(), 1);
}

// The computer's seats are the AI's players (app/seats.cpp): a level-5 snooker player breaks
// from the D without a foul; a level-5 three-cushion player opens on the red.
TEST(MatchController, ComputerSeatsPlaySnookerStrokesThroughTheAi) {
    ControllerOptions o = options("ai:5", "ai:5");
    o.playback_speed = 0.0;
    Controller c(app_test::new_session(), o);
    c.start_snooker(snooker_match(), o);
    EXPECT_FALSE(c.human_to_act());
    EXPECT_EQ(c.snooker()->config().names[0], "Ann");
    for (int i = 0; i < 20000 && c.shot_serial() == 0; ++i) {
        c.wait_for_computer();
        c.update(0.05);
    }
    ASSERT_EQ(c.shot_serial(), 1);
    ASSERT_TRUE(c.snooker()->last_verdict());
    EXPECT_FALSE(c.snooker()->last_verdict()->foul) << c.last_shot_words();
    EXPECT_TRUE(c.snooker()->marks().marks.in_d(c.snooker()->before().positions.at(sb::cue)))
        << "the break is played from the D";
}

TEST(MatchController, ComputerSeatsScoreTheThreeCushionOpening) {
    ControllerOptions o = options("ai:5", "human");
    o.playback_speed = 0.0;
    o.noise = 0.0;  // the plan as struck: it scores (with noise, a point is a chance)
    Controller c(app_test::new_session(), o);
    c.start_carom(carom_game(), o);
    EXPECT_FALSE(c.human_to_act());
    for (int i = 0; i < 20000 && c.shot_serial() == 0; ++i) {
        c.wait_for_computer();
        c.update(0.05);
    }
    ASSERT_EQ(c.shot_serial(), 1);
    run_until_idle(c);
    EXPECT_EQ(c.last_shot_words().rfind("Point", 0), 0u) << c.last_shot_words();
}

// Hint in a match: the level-5 player's decision becomes the human's aim, and Strike plays it.
TEST(MatchController, HintAimsForTheHumanInSnookerAndThreeCushion) {
    ControllerOptions o = options();
    o.playback_speed = 0.0;
    for (const bool snooker : {true, false}) {
        Controller c(app_test::new_session(), o);
        if (snooker)
            c.start_snooker(snooker_match(), o);
        else
            c.start_carom(carom_game(), o);
        const Aim before = c.aim();
        c.hint();
        EXPECT_TRUE(c.computer_thinking());
        EXPECT_FALSE(c.human_to_act()) << "not while the hint is thought of";
        c.wait_for_computer();
        c.update(0.05);
        ASSERT_TRUE(c.human_to_act());
        EXPECT_NE(c.aim().heading_deg, before.heading_deg) << "the hint's aim";
        c.strike();
        run_until_idle(c);
        EXPECT_EQ(c.shot_serial(), 1) << "Strike played the hinted aim";
    }
}

TEST(MatchController, ANewPoolGameAfterSnookerIsPoolAgain) {
    Controller c(app_test::new_session(), options());
    c.start_snooker(snooker_match(), options());
    c.replace(app_test::new_session(rules::Game::nine_ball), options());
    EXPECT_FALSE(c.snooker());
    EXPECT_EQ(c.look(), render::GameLook::pool);
    EXPECT_EQ(c.cue_ball_id(), 0);
    EXPECT_EQ(c.session().config().game, rules::Game::nine_ball);
    EXPECT_EQ(c.info().front(), "Ann to break");
}

TEST(MatchWords, SnookersRequiredWhenBehindByMoreThanRemains) {
    nlohmann::json doc = nlohmann::json::parse(snooker_match().to_json());
    doc["state"]["scores"] = {{"A", 10}, {"B", 160}};
    const game::SnookerSession s = game::SnookerSession::from_json(doc.dump());
    EXPECT_EQ(snookers_required(s, rules::Player::A), 3);  // 150 behind, 147 remaining
    EXPECT_EQ(snookers_required(s, rules::Player::B), 0);
    const std::vector<std::string> info = snooker_info(s, std::nullopt);
    EXPECT_NE(std::find(info.begin(), info.end(), "Ann needs snookers (3 points more than remain)"),
              info.end());
    EXPECT_NE(std::find(info.begin(), info.end(), "Ann 10 – 160 Bob · break 0 · 147 remaining"),
              info.end());
}

// The words of the first stroke from the start (after an opening that hits the red and scores
// nothing) whose verdict `want` accepts, searching headings, speeds and side spin.
std::string carom_words_for(
    const std::function<bool(const rules::CaromVerdict&, const physics::Shot&)>& want) {
    game::CaromSession start = carom_game();
    for (double heading = 0.0; heading < 360.0; heading += 0.5)
        for (double speed : {3.0, 5.0, 7.0})
            for (double side : {0.0, 0.3, -0.3}) {
                game::CaromSession s = start;
                physics::Stroke k;
                k.heading_deg = heading;
                k.speed = speed;
                k.side = side;
                const rules::CaromVerdict& v = s.play(k);
                if (want(v, *s.last_shot())) return carom_shot_words(s, *s.last_shot());
            }
    return "none found";
}

TEST(MatchWords, ThreeCushionSaysHowManyCushionsCameBeforeTheSecondBall) {
    const std::string point =
        carom_words_for([](const rules::CaromVerdict& v, const physics::Shot&) {
            return v.point && v.cushions == 3;
        });
    EXPECT_EQ(point, "Point: three cushions before the second ball. Run 1.");
    // Both object balls met (counted here from the events), two cushions before the second.
    const std::string two =
        carom_words_for([](const rules::CaromVerdict& v, const physics::Shot& shot) {
            std::set<int> met;
            for (const physics::Event& e : shot.events())
                if (e.type == physics::EventType::ball_ball && e.involves(0))
                    met.insert(e.ball(0) == 0 ? e.ball(1) : e.ball(0));
            return !v.foul && met.size() == 2 && v.cushions == 2;
        });
    EXPECT_EQ(two, "No point: only two cushions before the second ball. Bob to play.");
}

}  // namespace
}  // namespace app
