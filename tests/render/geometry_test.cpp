// Tests of the parts that need no GL: orientation integration, the table mesh against the
// physics geometry, the procedural textures, the ball colours.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>

#include "physics/rack.hpp"
#include "physics/simulate.hpp"
#include "render/camera.hpp"
#include "render/orientation.hpp"
#include "render/renderer.hpp"
#include "render/table_mesh.hpp"
#include "render/textures.hpp"

namespace {

TEST(Orientation, AdvanceIsExactForConstantSpin) {
    // A quarter turn about z in two halves equals one quarter turn.
    const glm::dquat q0{1, 0, 0, 0};
    const physics::Vec3 w{0, 0, std::numbers::pi / 2};
    const glm::dquat a = render::advance(render::advance(q0, w, 0.5), w, 0.5);
    const glm::dvec3 x = a * glm::dvec3(1, 0, 0);
    EXPECT_NEAR(x.x, 0.0, 1e-12);
    EXPECT_NEAR(x.y, 1.0, 1e-12);
}

TEST(Orientation, RollingBallTurnsByDistanceOverRadius) {
    const physics::Params params;
    const physics::Table table = physics::build_table(*physics::table_preset("9ft"));
    physics::BallState cue;
    cue.pos = {0.5, 0.635};
    const physics::BallState balls[] = {cue};
    physics::Stroke stroke;
    stroke.speed = 1.0;
    stroke.top = 0.4;  // close to natural roll
    const physics::Shot shot = physics::simulate(table, params, balls, &stroke);
    const double t0 = 0.3, t1 = 0.32;  // a turn of less than pi, so the angle does not wrap
    ASSERT_EQ(shot.state_at(0, t0).motion, physics::Motion::rolling);
    const glm::dquat q = render::integrate_orientation(shot, 0, t0, t1, glm::dquat(1, 0, 0, 0));
    const double distance = shot.state_at(0, t1).pos.x - shot.state_at(0, t0).pos.x;
    const double angle = 2.0 * std::acos(std::min(1.0, std::abs(q.w)));
    EXPECT_NEAR(angle, distance / params.ball_radius, 1e-3);
    // Rolling along +x turns the top of the ball toward +x.
    const glm::dvec3 top = q * glm::dvec3(0, 0, 1);
    EXPECT_GT(top.x, 0.0);
}

TEST(TableMesh, CushionNosesLieOnThePhysicsLinesAtNoseHeight) {
    const physics::Table table = physics::build_table(*physics::table_preset("9ft"));
    const render::TableMesh mesh = render::build_table_mesh(table);
    const float h = static_cast<float>(table.spec.cushion_height);
    int on_lines = 0;
    for (const render::Vertex& v : mesh.cushions) {
        if (std::abs(v.pos.z - h) > 1e-6f) continue;
        for (const physics::CushionLine& l : table.lines) {
            const physics::Vec2 p{v.pos.x, v.pos.y};
            const double along = physics::dot(p - l.a, l.dir),
                         off = physics::dot(p - l.a, l.normal);
            if (along > -1e-4 && along < l.length + 1e-4 && std::abs(off) < 1e-5) {
                ++on_lines;
                break;
            }
        }
    }
    EXPECT_GT(on_lines, 100);
}

TEST(TableMesh, PocketHolesStartAtTheDropLines) {
    const physics::Table table = physics::build_table(*physics::table_preset("9ft"));
    const auto holes = render::pocket_holes(table);
    ASSERT_EQ(holes.size(), 6u);
    for (std::size_t i = 0; i < 6; ++i) {
        const physics::Pocket& p = table.pockets[i];
        const glm::vec2 drop{static_cast<float>(p.drop_point.x),
                             static_cast<float>(p.drop_point.y)};
        EXPECT_NEAR(glm::length(holes[i].centre - drop), holes[i].radius, 1e-5f);
        EXPECT_GT(holes[i].radius, static_cast<float>(physics::Params{}.ball_radius));
    }
}

TEST(Textures, AreDeterministicAndVaried) {
    const render::TextureData a = render::make_cloth_texture(64),
                              b = render::make_cloth_texture(64);
    EXPECT_EQ(a.pixels, b.pixels);
    const auto [lo, hi] = std::minmax_element(a.pixels.begin(), a.pixels.end());
    EXPECT_GT(*hi - *lo, 40);
    const render::TextureData w = render::make_wood_texture(128, 32);
    EXPECT_EQ(w.pixels.size(), 128u * 32u * 3u);
}

TEST(NumberAtlas, HoldsEachNumberCentredInItsCell) {
    const int cell = 64;
    const render::TextureData a = render::make_number_atlas(render::kDefaultNumberFont, cell);
    ASSERT_EQ(a.width, render::kNumberCells * cell);
    ASSERT_EQ(a.height, a.width);
    ASSERT_EQ(a.channels, 1);
    for (int n = 0; n < render::kNumberCells * render::kNumberCells; ++n) {
        const int cx = (n % render::kNumberCells) * cell,
                  cy_top = (n / render::kNumberCells) * cell;
        double ink = 0.0, mx = 0.0, my = 0.0;
        for (int y = 0; y < cell; ++y)
            for (int x = 0; x < cell; ++x) {
                const int row = a.height - 1 - (cy_top + y);  // rows are stored bottom to top
                const double v = a.pixels[static_cast<std::size_t>(row) * a.width + cx + x] / 255.0;
                ink += v;
                mx += v * x;
                my += v * y;
            }
        if (n == 0 || n > 15) {
            EXPECT_EQ(ink, 0.0) << "cell " << n;
            continue;
        }
        // Each number covers a fair share of its cell, centred in it, inside the white circle.
        EXPECT_GT(ink, 0.06 * cell * cell) << n;
        EXPECT_LT(ink, 0.40 * cell * cell) << n;
        EXPECT_NEAR(mx / ink, cell / 2.0, 0.12 * cell) << n;
        EXPECT_NEAR(my / ink, cell / 2.0, 0.12 * cell) << n;
        for (int y = 0; y < cell; ++y)
            for (int x = 0; x < cell; ++x) {
                const double r =
                    std::hypot(x + 0.5 - cell / 2.0, y + 0.5 - cell / 2.0) / (cell / 2.0);
                const int row = a.height - 1 - (cy_top + y);
                if (r > 1.0) {
                    EXPECT_EQ(a.pixels[static_cast<std::size_t>(row) * a.width + cx + x], 0) << n;
                }
            }
    }
    // 6 and 9 are underlined (so a turned ball still tells them apart), 8 is not.
    auto ink_below_digits = [&](int n) {
        const int cx = (n % render::kNumberCells) * cell,
                  cy_top = (n / render::kNumberCells) * cell;
        int sum = 0;
        for (int y = cell * 85 / 100; y < cell; ++y)
            for (int x = 0; x < cell; ++x)
                sum += a.pixels[static_cast<std::size_t>(a.height - 1 - (cy_top + y)) * a.width +
                                cx + x];
        return sum;
    };
    EXPECT_GT(ink_below_digits(6), 255 * cell / 8);
    EXPECT_GT(ink_below_digits(9), 255 * cell / 8);
    EXPECT_EQ(ink_below_digits(8), 0);
}

TEST(NumberAtlas, MissingFontIsAClearError) {
    try {
        (void)render::make_number_atlas("/nonexistent/NoSuchFont.ttf");
        FAIL() << "expected an exception";
    } catch (const std::runtime_error& e) {
        EXPECT_NE(std::string(e.what()).find("/nonexistent/NoSuchFont.ttf"), std::string::npos);
        EXPECT_NE(std::string(e.what()).find("fonts-dejavu-core"), std::string::npos);
    }
}

TEST(Cameras, OrbitLooksAtTheTargetFromTheDistance) {
    const glm::vec3 target{1.2f, 0.6f, 0.03f};
    const render::Camera c = render::orbit_camera(target, 0.7f, 0.5f, 1.5f);
    EXPECT_NEAR(glm::length(c.eye - target), 1.5f, 1e-5f);
    const glm::vec3 f = glm::normalize(c.target - c.eye);
    EXPECT_NEAR(f.x, std::cos(0.5f) * std::cos(0.7f), 1e-5f);
    EXPECT_NEAR(f.y, std::cos(0.5f) * std::sin(0.7f), 1e-5f);
    EXPECT_NEAR(f.z, -std::sin(0.5f), 1e-5f);
    EXPECT_NEAR(glm::dot(f, c.up), 0.0f, 1e-5f);
    EXPECT_GT(c.up.z, 0.0f);
    // Straight down: up still defined, along the heading.
    const render::Camera down = render::orbit_camera(target, 0.7f, 1.5707963f, 2.0f);
    EXPECT_NEAR(down.up.x, std::cos(0.7f), 1e-4f);
    EXPECT_NEAR(down.eye.z, target.z + 2.0f, 1e-4f);
}

TEST(Cameras, LerpRunsFromOneCameraToTheOther) {
    const physics::Table table = physics::build_table(*physics::table_preset("9ft"));
    const render::Camera a = render::overhead_camera(table, 16.0f / 9.0f);
    const render::Camera b = render::cue_ball_camera(table, 0.028575f, {{0.6f, 0.6f}, 0.2f});
    for (float t : {0.0f, 1.0f}) {
        const render::Camera c = render::lerp(a, b, t);
        const render::Camera& e = t == 0.0f ? a : b;
        EXPECT_NEAR(glm::length(c.eye - e.eye), 0.0f, 1e-4f) << t;
        EXPECT_NEAR(glm::length(c.target - e.target), 0.0f, 1e-4f) << t;
        EXPECT_NEAR(c.fovy_deg, e.fovy_deg, 1e-4f) << t;
        EXPECT_NEAR(c.near_m, e.near_m, 1e-5f) << t;
    }
    // In between: continuous (small steps move the eye a little), up square to the view.
    render::Camera prev = a;
    for (int i = 1; i <= 100; ++i) {
        const render::Camera c = render::lerp(a, b, static_cast<float>(i) / 100.0f);
        EXPECT_LT(glm::length(c.eye - prev.eye), 0.2f) << i;
        EXPECT_NEAR(glm::dot(glm::normalize(c.target - c.eye), c.up), 0.0f, 1e-4f) << i;
        EXPECT_NEAR(glm::length(c.up), 1.0f, 1e-4f) << i;
        prev = c;
    }
    // Clamped outside [0, 1].
    EXPECT_NEAR(glm::length(render::lerp(a, b, 2.0f).eye - b.eye), 0.0f, 1e-4f);
}

TEST(Cameras, OverheadTurnsTheTableUpright_InATallView) {
    const physics::Table table = physics::build_table(*physics::table_preset("9ft"));
    const float aspect = 390.0f / 464.0f;  // a phone upright, the panel below
    const render::Camera c = render::overhead_camera(table, aspect);
    const glm::mat4 vp = c.projection(aspect) * c.view();
    auto seen = [&](physics::Vec2 p) {
        const glm::vec4 clip =
            vp * glm::vec4(static_cast<float>(p.x), static_cast<float>(p.y), 0.0f, 1.0f);
        return glm::vec2(clip.x / clip.w, clip.y / clip.w);
    };
    const glm::vec2 head = seen(table.head_spot()), foot = seen(table.foot_spot());
    EXPECT_NEAR(head.x, foot.x, 1e-4f);  // the long side vertical
    EXPECT_LT(head.y, foot.y);           // the head end (the break) at the bottom
    // It fills the view's height better than the table lying across it would.
    EXPECT_GT(foot.y - head.y, 0.8f);
}

TEST(Cameras, OverheadShowsTheWholeTableAndTheTray) {
    const physics::Table table = physics::build_table(*physics::table_preset("9ft"));
    const double R = physics::Params{}.ball_radius;
    for (float aspect : {16.0f / 9.0f, 4.0f / 3.0f, 2.0f, 0.84f, 9.0f / 16.0f}) {
        const render::Camera c = render::overhead_camera(table, aspect);
        const glm::mat4 vp = c.projection(aspect) * c.view();
        const render::TableDims d = render::table_dims(table);
        const float out = d.cushion_width + d.rail_width, L = static_cast<float>(table.length()),
                    W = static_cast<float>(table.width());
        std::vector<glm::vec3> corners = {{-out, -out, d.rail_height},
                                          {L + out, W + out, d.rail_height}};
        for (int k : {0, 14}) {
            const glm::vec3 p = render::tray_slot(table, R, k);
            corners.push_back(p + glm::vec3(0, -static_cast<float>(R), static_cast<float>(R)));
        }
        for (const glm::vec3& p : corners) {
            const glm::vec4 clip = vp * glm::vec4(p, 1.0f);
            EXPECT_LE(std::abs(clip.x / clip.w), 1.0f) << aspect;
            EXPECT_LE(std::abs(clip.y / clip.w), 1.0f) << aspect;
        }
        // The tray lies outside the south rail, its balls in a row along x.
        EXPECT_LT(render::tray_slot(table, R, 0).y, -out);
        EXPECT_NEAR(render::tray_slot(table, R, 1).x - render::tray_slot(table, R, 0).x,
                    2 * R + 0.002, 1e-5);
    }
}

TEST(BallColours, StripesShareTheSolidsColours) {
    for (int id = 9; id <= 15; ++id) {
        EXPECT_TRUE(render::is_stripe(id));
        EXPECT_EQ(render::ball_colour(id), render::ball_colour(id - 8));
    }
    EXPECT_FALSE(render::is_stripe(8));
    EXPECT_LT(render::ball_colour(8).x, 0.1f);  // black
    EXPECT_GT(render::ball_colour(1).x, 0.9f);  // yellow
}

}  // namespace
