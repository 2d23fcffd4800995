// Spotting on the foot spot and the long string (docs/rules.md "Spotting").
#include "rules/spotting.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace rules {
namespace {

const TableSize table;  // 9 ft: foot spot (1.905, 0.635)
const double R = table.ball_radius;

TEST(Spotting, FreeFootSpot) {
    physics::Vec2 p = spot_position({{1, {1.0, 0.3}}}, table);
    EXPECT_DOUBLE_EQ(p.x, 1.905);
    EXPECT_DOUBLE_EQ(p.y, 0.635);
}

TEST(Spotting, OccupiedSpotGoesBehindItFrozen) {
    physics::Vec2 p = spot_position({{1, table.foot_spot()}}, table);
    EXPECT_NEAR(p.x, 1.905 + 2 * R, 1e-12);
    EXPECT_DOUBLE_EQ(p.y, 0.635);
}

TEST(Spotting, BallBesideTheStringPushesLess) {
    const double dy = R;  // a ball half off the long string
    physics::Vec2 p = spot_position({{1, {1.905, 0.635 + dy}}}, table);
    EXPECT_NEAR(p.x, 1.905 + std::sqrt(4 * R * R - dy * dy), 1e-12);
}

TEST(Spotting, ARowBehindTheSpot) {
    std::map<int, physics::Vec2> balls{{1, {1.905, 0.635}}, {2, {1.905 + 2 * R, 0.635}}};
    physics::Vec2 p = spot_position(balls, table);
    EXPECT_NEAR(p.x, 1.905 + 4 * R, 1e-12);
}

TEST(Spotting, GapBigEnoughIsUsed) {
    // A gap of just over one ball between the spot ball and a ball further back.
    std::map<int, physics::Vec2> balls{{1, {1.905, 0.635}}, {2, {1.905 + 4 * R + 1e-6, 0.635}}};
    physics::Vec2 p = spot_position(balls, table);
    EXPECT_NEAR(p.x, 1.905 + 2 * R, 1e-12);
}

TEST(Spotting, NoRoomBehindGoesInFront) {
    std::map<int, physics::Vec2> balls;
    int id = 1;
    for (double x = 1.905; x < table.length; x += 2 * R) balls[id++] = {x, 0.635};
    physics::Vec2 p = spot_position(balls, table);
    EXPECT_NEAR(p.x, 1.905 - 2 * R, 1e-12);
}

}  // namespace
}  // namespace rules
