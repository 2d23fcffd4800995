// Shot links in snooker and three-cushion (app/shot_sharing.hpp, docs/app.md "Shot links"):
// Copy shot link shares the match's last stroke from the match just before it (or, before a
// frame's first stroke, the match as aimed), and an opened link plays exactly that shot.
#include <gtest/gtest.h>

#include "app/controller.hpp"
#include "app/shot_sharing.hpp"
#include "app_support.hpp"

namespace app {
namespace {

using app_test::options;
using app_test::run_until_idle;
namespace sb = physics::snooker_ball;

game::SnookerSession snooker_match() {
    game::SnookerConfig c;
    c.names = {"Ann", "Bob"};
    return game::SnookerSession(c);
}

ControllerOptions instant() {
    ControllerOptions o = options();
    o.playback_speed = 0.0;
    return o;
}

TEST(MatchShotSharing, BeforeTheBreakItIsTheMatchAsAimedWithTheCueBallInTheD) {
    Controller c(app_test::new_session(), instant());
    c.start_snooker(snooker_match(), instant());
    c.set_heading(3.0);
    c.set_power(0.6);
    const ShotToShare share = shot_to_share(c);
    ASSERT_TRUE(share.shot) << share.why_not;
    EXPECT_FALSE(share.last_shot);
    const auto& s = std::get<game::SharedSnookerShot>(*share.shot);
    EXPECT_EQ(s.before.state().positions, c.snooker()->state().positions);
    EXPECT_EQ(s.stroke.heading_deg, c.stroke_of(c.aim()).heading_deg);
    EXPECT_NE(copied_notice(share).find("the shot as aimed (22 balls)"), std::string::npos)
        << copied_notice(share);
}

TEST(MatchShotSharing, AnOpenedSnookerLinkPlaysTheLastStrokeBitForBit) {
    Controller c(app_test::new_session(), instant());
    c.start_snooker(snooker_match(), instant());
    c.set_heading(1.5);  // the break, up the table into the reds
    c.set_power(0.5);
    c.strike();
    run_until_idle(c);
    const ShotToShare share = shot_to_share(c);
    ASSERT_TRUE(share.shot && share.last_shot) << share.why_not;
    const std::string link = game::shot_link(*share.shot);

    Controller opened(app_test::new_session(), instant());
    open_shot(opened, game::read_any_shot_link(link), {"Cy", "Di"}, instant());
    ASSERT_TRUE(opened.snooker());
    run_until_idle(opened);
    EXPECT_EQ(opened.snooker()->to_json(), c.snooker()->to_json()) << "the same match after it";
    EXPECT_EQ(opened.last_shot_words(), c.last_shot_words());
    EXPECT_EQ(opened.snooker()->name(rules::Player::A), "Ann") << "the match's own names";
}

TEST(MatchShotSharing, AThreeCushionLinkPlaysOnTheStrikersBallWhoeverSitsThere) {
    game::CaromConfig cfg;
    cfg.names = {"Ann", "Bob"};
    Controller c(app_test::new_session(), instant());
    c.start_carom(game::CaromSession(cfg), instant());
    c.set_heading(40.0);
    c.set_power(0.7);
    c.strike();
    run_until_idle(c);
    const std::string link = game::shot_link(*shot_to_share(c).shot);

    Controller opened(app_test::new_session(), instant());
    open_shot(opened, game::read_any_shot_link(link), {"Cy", "Di"}, options("ai:1", "ai:1"));
    run_until_idle(opened, 1.0 / 30.0, 0.5);  // the link's stroke, before a computer's next
    ASSERT_TRUE(opened.carom());
    ASSERT_TRUE(opened.last_match_shot());
    EXPECT_EQ(opened.carom()->state().positions, c.carom()->state().positions);
    EXPECT_EQ(opened.carom()->state().scores, c.carom()->state().scores);
}

TEST(MatchShotSharing, AfterTheChoiceTheFoulIsStillTheShotToShare) {
    Controller c(app_test::new_session(), instant());
    c.start_snooker(snooker_match(), instant());
    c.set_heading(180.0);  // a foul: no ball hit
    c.strike();
    run_until_idle(c);
    ASSERT_TRUE(c.last_match_shot());
    c.choose_after_foul(rules::AfterFoul::play);
    EXPECT_TRUE(shot_to_share(c).last_shot) << "the foul is still the last shot";
}

TEST(MatchShotSharing, PracticeSharesPoolPositionsButNotTheSnookerTables) {
    Controller c(app_test::new_session(), instant());
    c.start_practice(game::Practice::on_own_table(physics::RackType::snooker, 3), instant());
    const ShotToShare snooker = shot_to_share(c);
    EXPECT_FALSE(snooker.shot);
    EXPECT_NE(snooker.why_not.find("no shot links"), std::string::npos) << snooker.why_not;
    c.start_practice(game::Practice::on_own_table(physics::RackType::nine_ball, 3), instant());
    const ShotToShare pool = shot_to_share(c);
    ASSERT_TRUE(pool.shot) << pool.why_not;
    EXPECT_TRUE(std::holds_alternative<game::SharedShot>(*pool.shot));
}

}  // namespace
}  // namespace app
