// Tests of the parts that need no GL: orientation integration, the table mesh against the
// physics geometry, the procedural textures, the ball colours.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>

#include "physics/rack.hpp"
#include "physics/simulate.hpp"
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
            const double along = physics::dot(p - l.a, l.dir), off = physics::dot(p - l.a, l.normal);
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
        const glm::vec2 drop{static_cast<float>(p.drop_point.x), static_cast<float>(p.drop_point.y)};
        EXPECT_NEAR(glm::length(holes[i].centre - drop), holes[i].radius, 1e-5f);
        EXPECT_GT(holes[i].radius, static_cast<float>(physics::Params{}.ball_radius));
    }
}

TEST(Textures, AreDeterministicAndVaried) {
    const render::TextureData a = render::make_cloth_texture(64), b = render::make_cloth_texture(64);
    EXPECT_EQ(a.pixels, b.pixels);
    const auto [lo, hi] = std::minmax_element(a.pixels.begin(), a.pixels.end());
    EXPECT_GT(*hi - *lo, 40);
    const render::TextureData w = render::make_wood_texture(128, 32);
    EXPECT_EQ(w.pixels.size(), 128u * 32u * 3u);
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
