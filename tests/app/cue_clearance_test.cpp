// The cue can't pass through the rail: a stroke from a cue ball near a rail, aimed away from
// it, is played at the elevation the rail forces, and the aim guide simulates that stroke.
#include "app/cue_clearance.hpp"

#include <gtest/gtest.h>

#include "app/aim_preview.hpp"
#include "app/controller.hpp"
#include "app_support.hpp"
#include "physics/params.hpp"

namespace {

const double R = physics::Params{}.ball_radius;

TEST(CueClearance, AgainstARailTheCueIsRaisedAndTheChosenElevationIsKeptAboveIt) {
    const physics::Table table = physics::build_table(physics::TableSpec{});
    const physics::Vec2 frozen{1.0, R + 0.001};  // against the south cushion
    physics::Stroke k;
    k.heading_deg = 90.0;  // away from it: the cue lies over the south rail
    const double forced = app::rail_forced_elevation_deg(table, R, frozen, k);
    std::printf("frozen to the rail: %.2f deg forced\n", forced);
    EXPECT_GT(forced, 5.0);
    EXPECT_LT(forced, 40.0);
    EXPECT_DOUBLE_EQ(app::over_the_rail(table, R, frozen, k).elevation_deg, forced);
    k.elevation_deg = 45.0;  // higher than the rail needs: as chosen
    EXPECT_DOUBLE_EQ(app::over_the_rail(table, R, frozen, k).elevation_deg, 45.0);
    k.elevation_deg = 0.0;
    k.heading_deg = -90.0;  // into the rail: the cue lies over the open table
    EXPECT_LT(app::rail_forced_elevation_deg(table, R, frozen, k), 2.0);
    // A low hit needs the butt higher than a centre hit.
    k.heading_deg = 90.0;
    k.top = -0.5;
    EXPECT_GT(app::rail_forced_elevation_deg(table, R, frozen, k), forced);
}

TEST(CueClearance, TheStrokePlayedAndTheAimGuideUseTheForcedElevation) {
    app::Controller c(
        app_test::session_at({{0, {1.0, R + 0.001}}, {5, {1.6, 1.0}}, {8, {2.2, 0.3}}}),
        app_test::options());
    ASSERT_TRUE(c.human_to_act());
    c.set_elevation(0.0);
    c.set_heading(80.0);
    const double forced = c.forced_elevation_deg();
    EXPECT_GT(forced, 5.0);
    EXPECT_DOUBLE_EQ(c.stroke_of(c.aim()).elevation_deg, forced);
    ASSERT_NE(c.preview(), nullptr);
    const std::vector<physics::Event> guide = c.preview()->events;

    c.strike();
    ASSERT_EQ(c.session().history().size(), 1u);
    EXPECT_DOUBLE_EQ(c.session().history().back().stroke.elevation_deg, forced);
    const std::vector<physics::Event>& played = c.playback().shot().events();
    ASSERT_EQ(guide.size(), played.size());
    for (std::size_t i = 0; i < guide.size(); ++i) {
        EXPECT_EQ(guide[i].time, played[i].time) << i;
        EXPECT_EQ(guide[i].type, played[i].type) << i;
        EXPECT_EQ(guide[i].balls[0].pos, played[i].balls[0].pos) << i;
    }
}

}  // namespace
