// The aim guide's levels, the call it proposes and the marks on the cloth; the warning before a
// shot that would be a foul (ball in hand in the kitchen).
#include "app/aim_guide.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "app/controller.hpp"
#include "app/scene_frame.hpp"
#include "app_support.hpp"

namespace {

using app_test::options;
using app_test::run_until_idle;
using app_test::session_at;

double heading_to(physics::Vec2 from, physics::Vec2 to) {
    return std::atan2(to.y - from.y, to.x - from.x) * 180.0 / std::numbers::pi;
}

const glm::vec3 gold{1.0f, 0.8f, 0.2f};

bool has_mark(const render::AimView& v, glm::vec3 colour, physics::Vec2 near, double within) {
    for (const render::AimMark& m : v.marks)
        if (m.colour == colour && std::hypot(m.centre.x - near.x, m.centre.y - near.y) < within)
            return true;
    return false;
}

// Ball in hand in the kitchen with the 3 in the kitchen, nearer than any other ball.
game::Session kitchen_with_the_3() {
    return session_at({{3, {0.3, 0.9}}, {1, {1.5, 0.4}}, {8, {2.0, 0.6}}, {12, {1.8, 1.0}}},
                      "in_hand_kitchen");
}

TEST(AimGuide, FromTheKitchenABallInTheKitchenIsNeverProposedAndAnAimAtItIsMarkedAFoul) {
    app::Controller c(kitchen_with_the_3(), options());
    ASSERT_TRUE(c.human_to_act());
    const rules::GameState& st = c.session().state();
    const physics::Vec2 cue = st.positions.at(0);
    // The aim starts at the nearest ball outside the kitchen: the 1, not the 3.
    EXPECT_NEAR(c.aim().heading_deg, heading_to(cue, st.positions.at(1)), 1e-9);
    EXPECT_TRUE(c.aim_foul().empty());

    c.set_heading(heading_to(cue, st.positions.at(3)));
    ASSERT_TRUE(c.preview() && c.preview()->first_ball == 3);
    EXPECT_EQ(c.aim_foul(),
              "Foul as aimed: the 3 lies in the kitchen. From the kitchen the cue ball must cross "
              "the head string before it touches a ball.");
    EXPECT_EQ(c.call(), rules::Call::nothing());  // never an illegal call
    const app::SceneFrame f = app::build_scene(c, app::AimGuide::lines);
    EXPECT_TRUE(f.show_aim);
    EXPECT_TRUE(f.aim.illegal);
    EXPECT_TRUE(has_mark(f.aim, {1.0f, 0.2f, 0.15f}, st.positions.at(3), 1e-6));
    // The warning was true: struck as aimed, the shot is that foul.
    c.set_power(0.3);
    c.strike();
    run_until_idle(c);
    ASSERT_EQ(c.session().history().size(), 1u);
    EXPECT_TRUE(c.session().history().back().verdict.has(rules::Foul::bad_play_from_kitchen));
}

// The 5 half a metre from the NE pocket, the cue ball 0.8 m behind it on the same line.
struct StraightIn {
    physics::Vec2 object, cue;
    int ne = static_cast<int>(physics::PocketId::NE);
};

StraightIn straight_in(const physics::Table& table) {
    const physics::Pocket& ne = table.pockets[static_cast<std::size_t>(physics::PocketId::NE)];
    const physics::Vec2 from{1.6, 0.5};
    const physics::Vec2 dir = (1.0 / physics::norm(ne.centre - from)) * (ne.centre - from);
    StraightIn s;
    s.object = ne.centre - 0.5 * dir;
    s.cue = s.object - 0.8 * dir;
    return s;
}

TEST(AimGuide, TheCallFollowsTheGuideAndIsMarkedOnTheCloth) {
    const StraightIn s = straight_in(app_test::new_session().table());
    app::Controller c(session_at({{0, s.cue}, {5, s.object}, {8, {0.5, 0.3}}}), options());
    c.set_power(0.25);
    c.set_heading(heading_to(s.cue, s.object));
    ASSERT_TRUE(c.preview());
    EXPECT_TRUE(c.preview()->pots);
    EXPECT_EQ(c.preview()->object_end, app::PathEnd::pocket);
    EXPECT_EQ(c.call(), rules::Call::ball_in(5, s.ne));
    const physics::Pocket& ne = c.session().table().pockets[static_cast<std::size_t>(s.ne)];
    const physics::Vec2 mouth = 0.5 * (ne.mouth_a + ne.mouth_b);
    for (app::AimGuide level : {app::AimGuide::off, app::AimGuide::ghost, app::AimGuide::lines,
                                app::AimGuide::practice}) {
        const app::SceneFrame f = app::build_scene(c, level);
        EXPECT_TRUE(f.show_aim);  // the call's marks show at every level
        EXPECT_TRUE(has_mark(f.aim, gold, s.object, 1e-6)) << static_cast<int>(level);
        EXPECT_TRUE(has_mark(f.aim, gold, mouth, 1e-6)) << static_cast<int>(level);
        EXPECT_FALSE(f.aim.illegal);
    }
    // Aimed straight up the table, the 5 runs to the N rail between the pockets: no pocket is
    // in its direction, so none is called, and the guide's path ends at the rail.
    app::Controller up(session_at({{0, {1.0, 0.3}}, {5, {1.0, 0.6}}, {8, {0.5, 0.3}}}), options());
    up.set_power(0.3);
    up.set_heading(90.0);
    ASSERT_TRUE(up.preview() && up.preview()->first_ball == 5);
    EXPECT_FALSE(up.preview()->pocket.has_value());
    EXPECT_EQ(up.preview()->object_end, app::PathEnd::rail);
    EXPECT_EQ(up.call(), rules::Call::nothing());
    EXPECT_TRUE(app::build_scene(up, app::AimGuide::practice).aim.marks.empty());
}

TEST(AimGuide, APathEndingAtAJawIsMarkedAsNotDropping) {
    const StraightIn s = straight_in(app_test::new_session().table());
    app::Controller c(session_at({{0, s.cue}, {5, s.object}, {8, {0.5, 0.3}}}), options());
    c.set_power(0.25);
    const double straight = heading_to(s.cue, s.object);
    const glm::vec3 green{0.3f, 0.95f, 0.4f}, orange{1.0f, 0.45f, 0.1f};
    bool found = false;
    for (double d = 0.1; d < 3.0 && !found; d += 0.1) {
        c.set_heading(straight + d);
        if (c.preview()->object_end != app::PathEnd::jaw || c.preview()->pots) continue;
        found = true;
        const render::AimView v = app::build_scene(c, app::AimGuide::practice).aim;
        const glm::vec2 end = v.object_path.back();
        EXPECT_TRUE(has_mark(v, orange, {end.x, end.y}, 1e-6));
        EXPECT_FALSE(has_mark(v, green, {end.x, end.y}, 1.0));
    }
    EXPECT_TRUE(found) << "no cut of the 5 hits the NE pocket's jaw and stays out";
    c.set_heading(straight);
    const render::AimView v = app::build_scene(c, app::AimGuide::practice).aim;
    const glm::vec2 end = v.object_path.back();
    EXPECT_TRUE(has_mark(v, green, {end.x, end.y}, 1e-6));
}

TEST(AimGuide, EachLevelShowsItsShareOfTheGuide) {
    const StraightIn s = straight_in(app_test::new_session().table());
    app::Controller c(session_at({{0, s.cue}, {5, s.object}, {8, {0.5, 0.3}}}), options());
    c.set_power(0.25);
    c.set_heading(heading_to(s.cue, s.object) + 2.0);  // a cut: the lines are not along the aim
    const app::AimPreview& p = *c.preview();
    ASSERT_EQ(p.first_ball, 5);
    const float R = static_cast<float>(c.session().config().params.ball_radius);
    const render::AimView off = app::guide_view(p, app::AimGuide::off, false, R);
    EXPECT_TRUE(off.cue_path.empty() && !off.ghost && off.object_path.empty() &&
                off.cue_after.empty());
    const render::AimView ghost = app::guide_view(p, app::AimGuide::ghost, false, R);
    EXPECT_EQ(ghost.cue_path, p.view.cue_path);
    EXPECT_EQ(ghost.ghost, p.view.ghost);
    EXPECT_TRUE(ghost.object_path.empty() && ghost.cue_after.empty());
    const render::AimView lines = app::guide_view(p, app::AimGuide::lines, false, R);
    ASSERT_EQ(lines.object_path.size(), 2u);
    ASSERT_EQ(lines.cue_after.size(), 2u);
    EXPECT_NEAR(glm::length(lines.object_path[1] - lines.object_path[0]), app::object_line_length,
                1e-6);
    EXPECT_NEAR(glm::length(lines.cue_after[1] - lines.cue_after[0]), app::tangent_line_length,
                1e-6);
    // The tangent line: square to the object ball's line, on the side the cue ball goes.
    const glm::vec2 a = glm::normalize(lines.object_path[1] - lines.object_path[0]);
    const glm::vec2 b = glm::normalize(lines.cue_after[1] - lines.cue_after[0]);
    EXPECT_LT(std::fabs(glm::dot(a, b)), 1e-5f);
    EXPECT_GT(glm::dot(b, p.view.cue_after.back() - p.view.cue_after.front()), 0.0f);
    const render::AimView practice = app::guide_view(p, app::AimGuide::practice, false, R);
    EXPECT_EQ(practice.object_path, p.view.object_path);
    EXPECT_EQ(practice.cue_after, p.view.cue_after);
    EXPECT_TRUE(app::guide_view(p, app::AimGuide::practice, true, R).illegal);
}

}  // namespace
