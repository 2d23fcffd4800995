// Shot links in the game (app/shot_sharing.hpp, docs/app.md "Shot links"): which shot Copy shot
// link shares, and that an opened link plays exactly that shot from exactly that position.
#include "app/shot_sharing.hpp"

#include <gtest/gtest.h>

#include "app/controller.hpp"
#include "app_support.hpp"
#include "game/json_field.hpp"

namespace app {
namespace {

using app_test::options;
using app_test::run_until_idle;
using app_test::session_at;

const std::map<int, physics::Vec2> kBalls{{0, {0.7, 0.5}}, {1, {1.6, 0.55}}, {8, {2.0, 0.9}}};

const game::SharedShot& pool(const ShotToShare& share) {
    return std::get<game::SharedShot>(*share.shot);
}

physics::Stroke stroke(double speed, double heading_deg) {
    physics::Stroke s;
    s.speed = speed;
    s.heading_deg = heading_deg;
    s.side = 0.25;
    s.top = -0.3;
    return s;
}

TEST(ShotSharing, BeforeTheFirstShotItIsThePositionWithTheStrokeAsAimed) {
    const game::Session s = session_at(kBalls);
    const ShotToShare share = shot_to_share(s, stroke(2.5, 3.0));
    ASSERT_TRUE(share.shot) << share.why_not;
    EXPECT_EQ(pool(share).state.positions, s.state().positions);
    EXPECT_EQ(pool(share).stroke.speed, 2.5);
    EXPECT_EQ(pool(share).stroke.heading_deg, 3.0);
    EXPECT_EQ(pool(share).game, rules::Game::eight_ball);
}

TEST(ShotSharing, AfterAShotItIsThatShotFromWhereItWasPlayed) {
    Controller c(session_at(kBalls), options());
    c.set_heading(4.0);
    c.set_power(0.4);
    const physics::Stroke played = c.stroke_of(c.aim());
    c.strike();
    run_until_idle(c);
    ASSERT_EQ(c.session().history().size(), 1u);
    const ShotToShare share = shot_to_share(c.session(), stroke(1.0, 90.0));
    ASSERT_TRUE(share.shot) << share.why_not;
    EXPECT_EQ(pool(share).state.positions, session_at(kBalls).state().positions);
    EXPECT_EQ(pool(share).stroke.heading_deg, played.heading_deg);
    EXPECT_EQ(pool(share).stroke.speed, played.speed);
    EXPECT_NE(copied_notice(share).find("the last shot"), std::string::npos);
}

TEST(ShotSharing, ACueBallInHandNotYetPlacedHasNoLink) {
    const game::Session s = app_test::new_session();  // the break: ball in hand in the kitchen
    const ShotToShare share = shot_to_share(s, stroke(2.0, 0.0));
    EXPECT_FALSE(share.shot);
    EXPECT_NE(share.why_not.find("Place the cue ball"), std::string::npos) << share.why_not;
}

TEST(ShotSharing, AnOpenedLinkPlaysExactlyThatShotAndCanBeReplayed) {
    const physics::Stroke s = stroke(3.0, 2.0);
    const std::string link = game::shot_link(pool(shot_to_share(session_at(kBalls), s)));
    game::Session reference = session_at(kBalls);
    reference.play(s);

    const game::SharedShot shot = game::read_shot_link(link);
    Controller c(session_of(shot, {"Cy", "Di"}, 77), options());
    EXPECT_EQ(c.session().name(rules::Player::A), "Cy");
    c.play_shared(shot.stroke);
    EXPECT_TRUE(c.moving());
    run_until_idle(c);
    ASSERT_EQ(c.session().history().size(), 1u);
    EXPECT_EQ(c.session().state().positions, reference.state().positions) << "bit for bit";
    EXPECT_EQ(c.session().state().on_table, reference.state().on_table);
    EXPECT_EQ(c.session().state().shooter, reference.state().shooter);
    c.replay();
    EXPECT_TRUE(c.replaying());
    run_until_idle(c);
    EXPECT_EQ(c.session().history().size(), 1u) << "a replay plays nothing new";
}

TEST(ShotSharing, AComputerSeatDoesNotTakeTheSharedShot) {
    Controller c(session_of(game::read_shot_link(game::shot_link(
                                pool(shot_to_share(session_at(kBalls), stroke(2.0, 1.0))))),
                            {"Cy", "Di"}, 5),
                 options("ai:1", "human"));
    c.play_shared(stroke(2.0, 1.0));
    ASSERT_EQ(c.session().history().size(), 1u);
    EXPECT_EQ(c.session().history().back().stroke.heading_deg, 1.0);
    EXPECT_EQ(c.session().history().back().stroke.speed, 2.0);
}

}  // namespace
}  // namespace app
