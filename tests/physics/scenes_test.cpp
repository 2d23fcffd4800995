// The standard scenes (docs/style.md, rule 8) are shared by the tests, `bench/` and `coolaaber-cli
// bench`: each must be the shot its name and the issue promise, or the benchmark figures
// measure something else.
#include "physics/scenes.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>
#include <vector>

#include "physics/simulate.hpp"

namespace physics {
namespace {

struct Played {
    Scene scene;
    Shot shot;
};

Played play(const char* name) {
    const Params p;
    Scene s = standard_scene(name, p);
    Shot shot = simulate(build_table(s.table), p, s.balls, &s.stroke);
    return {std::move(s), std::move(shot)};
}

std::vector<const Event*> of_type(const Shot& shot, EventType type) {
    std::vector<const Event*> out;
    for (const Event& e : shot.events())
        if (e.type == type) out.push_back(&e);
    return out;
}

TEST(Scenes, EveryNamedSceneExistsAndComesToRest) {
    const Params p;
    for (const std::string& name : standard_scene_names()) {
        const Scene s = standard_scene(name, p);
        const Shot shot = simulate(build_table(s.table), p, s.balls, &s.stroke);
        EXPECT_FALSE(shot.truncated()) << name;
        EXPECT_TRUE(shot.rest_time().has_value()) << name;
        ASSERT_FALSE(shot.events().empty()) << name;
        EXPECT_EQ(shot.events().front().type, EventType::strike) << name;
    }
    EXPECT_THROW(standard_scene("no such scene", p), std::invalid_argument);
}

TEST(Scenes, BreakIsAFullEightBallRackHitAtAboutNineMetresPerSecond) {
    const Played b = play("break");
    EXPECT_EQ(b.scene.balls.size(), 16u);
    EXPECT_EQ(b.scene.table.length, 2.540);  // the 9 ft table
    // The cue ball's speed off the tip, and when it meets the apex ball (it slides the 1.2 m
    // there, losing μs·g·t, about 0.25 m/s).
    const Event& strike = b.shot.events().front();
    EXPECT_NEAR(norm(strike.balls[0].vel), 9.0, 1e-6);
    const std::vector<const Event*> hits = of_type(b.shot, EventType::ball_ball);
    ASSERT_FALSE(hits.empty());
    const Event& first = *hits.front();
    ASSERT_TRUE(first.involves(0));
    const BallState at_apex = b.shot.state_at(0, first.time * (1 - 1e-12));
    EXPECT_GT(norm(at_apex.vel), 8.5);
    EXPECT_LT(norm(at_apex.vel), 9.0);
    // A real break: the rack spreads, balls reach the cushions.
    EXPECT_GT(hits.size(), 30u);
    EXPECT_GE(of_type(b.shot, EventType::cushion).size(), 4u);
}

TEST(Scenes, CutPocketsTheObjectBallInTheNorthEastCorner) {
    const Played c = play("cut");
    ASSERT_EQ(c.scene.balls.size(), 2u);
    const std::vector<const Event*> hits = of_type(c.shot, EventType::ball_ball);
    ASSERT_EQ(hits.size(), 1u);
    // A cut, not a straight shot: the cue ball is deflected by a clear angle.
    const Vec2 in = c.shot.events().front().balls[0].vel;
    const Vec2 out = hits[0]->balls[0].id == 0 ? hits[0]->balls[0].vel : hits[0]->balls[1].vel;
    EXPECT_GT(std::abs(cross(in, out)) / (norm(in) * norm(out)), 0.3);  // > ~17°
    const std::vector<const Event*> pockets = of_type(c.shot, EventType::pocket);
    ASSERT_EQ(pockets.size(), 1u);
    EXPECT_EQ(pockets[0]->balls[0].id, 1);
    EXPECT_EQ(pockets[0]->pocket, static_cast<int>(PocketId::NE));
    EXPECT_NE(c.shot.final_states()[0].motion, Motion::pocketed);  // no scratch
}

TEST(Scenes, LongRollIsOneBallOffAtLeastThreeCushions) {
    const Played r = play("long_roll");
    ASSERT_EQ(r.scene.balls.size(), 1u);
    std::vector<int> rails;
    for (const Event* e : of_type(r.shot, EventType::cushion)) rails.push_back(e->rail);
    ASSERT_GE(rails.size(), 3u);
    // Three different rails (round the table), none of them a jaw, and the ball stays up.
    EXPECT_NE(rails[0], rails[1]);
    EXPECT_NE(rails[1], rails[2]);
    EXPECT_NE(rails[0], rails[2]);
    for (int rail : rails) EXPECT_GE(rail, 0);
    EXPECT_TRUE(of_type(r.shot, EventType::pocket).empty());
    // A long roll: it travels well over a table length.
    double path = 0.0;
    const std::vector<Segment>& segs = r.shot.segments(0);
    for (std::size_t k = 1; k < segs.size(); ++k)
        path += norm(segs[k].start.pos - segs[k - 1].start.pos);
    EXPECT_GT(path, 2.540);
}

TEST(Scenes, BankSendsTheObjectBallOffTheSouthRailIntoTheNorthSidePocket) {
    const Played k = play("bank");
    ASSERT_EQ(k.scene.balls.size(), 2u);
    const std::vector<const Event*> pockets = of_type(k.shot, EventType::pocket);
    ASSERT_EQ(pockets.size(), 1u);
    EXPECT_EQ(pockets[0]->balls[0].id, 3);
    EXPECT_EQ(pockets[0]->pocket, static_cast<int>(PocketId::N));
    // The object ball met a cushion before it dropped.
    bool banked = false;
    for (const Event* e : of_type(k.shot, EventType::cushion))
        banked = banked || (e->involves(3) && e->time < pockets[0]->time);
    EXPECT_TRUE(banked);
}

}  // namespace
}  // namespace physics
