#include "app/input.hpp"

#include <gtest/gtest.h>

#include "app/camera_rig.hpp"
#include "app/picking.hpp"
#include "app_support.hpp"
#include "render/camera.hpp"

namespace {

struct Fixture {
    app::Controller c{app_test::new_session(), app_test::options()};
    app::CameraRig rig;
    render::Camera camera = render::overhead_camera(c.session().table(), 980.0f / 720.0f);
    app::TableInput input{c, rig, [this](double x, double y) {
                              return app::table_point(camera, 980, 720, x, y,
                                                      c.session().config().params.ball_radius);
                          }};
};

TEST(Input, HoldingTheRightButtonAimsAndReleasingStrikes) {
    Fixture f;
    const double h0 = f.c.aim().heading_deg;
    f.input.press(app::MouseButton::right, 500, 300);
    f.input.motion(520, 300, false);  // 20 px to the right: 2 degrees clockwise
    EXPECT_NEAR(f.c.aim().heading_deg, h0 - 2.0, 1e-9);
    f.input.motion(520, 380, false);  // vertical motion does not aim
    EXPECT_NEAR(f.c.aim().heading_deg, h0 - 2.0, 1e-9);
    EXPECT_TRUE(f.c.session().history().empty());
    f.input.release(app::MouseButton::right, 520, 380);
    EXPECT_EQ(f.c.session().history().size(), 1u);
    EXPECT_NEAR(f.c.session().history()[0].stroke.heading_deg, h0 - 2.0, 1e-9);
}

TEST(Input, TheLeftButtonAimsWithoutStrikingAndShiftIsFiner) {
    Fixture f;
    const double h0 = f.c.aim().heading_deg;
    f.input.press(app::MouseButton::left, 500, 100);
    f.input.motion(495, 100, true);  // Shift: 0.01 degree per pixel
    EXPECT_NEAR(f.c.aim().heading_deg, h0 + 0.05, 1e-9);
    f.input.release(app::MouseButton::left, 495, 100);
    EXPECT_TRUE(f.c.session().history().empty());
}

TEST(Input, DraggingTheCueBallInHandMovesIt) {
    Fixture f;
    const physics::Vec2 cue = f.c.session().state().positions.at(0);
    // The cue ball's pixel: search the overhead view for the point that maps onto it.
    double bx = 0, by = 0, best = 1e9;
    for (int x = 0; x < 980; x += 2)
        for (int y = 0; y < 720; y += 2) {
            const auto p = app::table_point(f.camera, 980, 720, x, y,
                                            f.c.session().config().params.ball_radius);
            if (p && physics::norm(*p - cue) < best) {
                best = physics::norm(*p - cue);
                bx = x;
                by = y;
            }
        }
    f.input.press(app::MouseButton::left, bx, by);
    ASSERT_TRUE(f.input.moving_cue_ball());
    f.input.motion(bx - 40, by + 30, false);
    f.input.release(app::MouseButton::left, bx - 40, by + 30);
    const physics::Vec2 moved = f.c.session().state().positions.at(0);
    EXPECT_LT(moved.x, cue.x - 0.05);
    EXPECT_LT(moved.y, cue.y - 0.03);  // screen down is south
    EXPECT_TRUE(f.c.session().history().empty());
}

TEST(Picking, TheCentreOfTheViewIsWhereTheCameraLooks) {
    const physics::Table table = physics::build_table(*physics::table_preset("9ft"));
    const render::Camera cam = render::overhead_camera(table, 4.0f / 3.0f);
    const auto p = app::table_point(cam, 800, 600, 400, 300, 0.0);
    ASSERT_TRUE(p.has_value());
    EXPECT_NEAR(p->x, cam.target.x, 1e-4);
    EXPECT_NEAR(p->y, cam.target.y, 1e-4);
    const auto right = app::table_point(cam, 800, 600, 700, 300, 0.0);
    ASSERT_TRUE(right.has_value());
    EXPECT_GT(right->x, p->x);  // x is to the right
    const auto up = app::table_point(cam, 800, 600, 400, 100, 0.0);
    EXPECT_GT(up->y, p->y);  // y is up the screen
}

TEST(Picking, APointIsSeenAtThePixelThatPicksIt) {
    const physics::Table table = physics::build_table(*physics::table_preset("9ft"));
    const render::Camera cam = render::overhead_camera(table, 4.0f / 3.0f);
    const auto px = app::screen_point(cam, 800, 600, {0.7, 0.4}, 0.0285);
    ASSERT_TRUE(px.has_value());
    const auto back = app::table_point(cam, 800, 600, (*px)[0], (*px)[1], 0.0285);
    ASSERT_TRUE(back.has_value());
    EXPECT_NEAR(back->x, 0.7, 1e-4);
    EXPECT_NEAR(back->y, 0.4, 1e-4);
}

TEST(CameraRig, ChangeViewGlidesToTheCueBallViewAndBack) {
    const physics::Table table = physics::build_table(*physics::table_preset("9ft"));
    app::CameraRig rig;
    const render::Camera over = rig.camera(table, 1.5f);
    rig.set_anchor({0.6f, 0.6f}, 0.0f, false, over);
    rig.next_view(over);
    EXPECT_EQ(rig.mode(), app::CameraMode::cue_ball);
    EXPECT_TRUE(rig.animating());
    rig.update(0.35);
    const render::Camera mid = rig.camera(table, 1.5f);
    EXPECT_GT(glm::distance(mid.eye, over.eye), 0.1f);
    rig.update(1.0);
    EXPECT_FALSE(rig.animating());
    const render::Camera cue = rig.camera(table, 1.5f);
    EXPECT_LT(cue.eye.x, 0.6f);  // behind the cue ball, looking along +x
    EXPECT_GT(cue.target.x, 0.6f);
    rig.next_view(cue);
    EXPECT_EQ(rig.mode(), app::CameraMode::overhead);
}

}  // namespace
