// Table geometry: presets, WPA pocket mouths and facing angles, names, the playing surface.
#include "physics/table.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>

#include "physics/layout.hpp"
#include "physics/rack.hpp"

namespace physics {
namespace {

TEST(Table, PresetsHaveWpaDimensions) {
    EXPECT_DOUBLE_EQ(table_preset("9ft")->length, 2.540);
    EXPECT_DOUBLE_EQ(table_preset("9ft")->width, 1.270);
    EXPECT_DOUBLE_EQ(table_preset("8ft")->length, 2.3368);
    EXPECT_DOUBLE_EQ(table_preset("8ft")->width, 1.1684);
    EXPECT_DOUBLE_EQ(table_preset("7ft")->length, 1.9812);
    EXPECT_DOUBLE_EQ(table_preset("7ft")->width, 0.9906);
    EXPECT_FALSE(table_preset("unbounded")->bounded);
    EXPECT_FALSE(table_preset("10ft").has_value());
    for (const char* name : {"7ft", "8ft", "9ft"})
        EXPECT_FALSE(validate_table_spec(*table_preset(name), 0.028575)) << name;
}

TEST(Table, SixPocketsWithWpaMouthsAndNames) {
    const Table t = build_table(*table_preset("9ft"));
    ASSERT_EQ(t.pockets.size(), 6u);
    for (const Pocket& p : t.pockets) {
        const double mouth = norm(p.mouth_b - p.mouth_a);
        const bool side = p.id == 1 || p.id == 4;
        EXPECT_NEAR(mouth, side ? 0.1285 : 0.116, 1e-12) << pocket_name(p.id);
    }
    EXPECT_EQ(pocket_name(0), "SW");
    EXPECT_EQ(pocket_name(5), "NE");
    EXPECT_EQ(pocket_from_name("N"), 4);
    EXPECT_FALSE(pocket_from_name("X"));
    EXPECT_EQ(rail_name(2), "SW-S");
    // 6 rails + 2 facings per pocket, 2 noses per pocket.
    EXPECT_EQ(t.lines.size(), 18u);
    EXPECT_EQ(t.noses.size(), 12u);
}

TEST(Table, JawFacingsAreCutAtTheWpaAngles) {
    const Table t = build_table(*table_preset("9ft"));
    for (const CushionLine& facing : t.lines) {
        if (facing.pocket < 0) continue;
        // The rail this facing meets: the rail line whose end is nearest the facing's start.
        const CushionLine* rail = nullptr;
        double best = 1e9;
        for (const CushionLine& r : t.lines) {
            if (r.rail < 0) continue;
            for (Vec2 end : {r.a, r.b}) {
                const double d = norm(end - facing.a);
                if (d < best) best = d, rail = &r;
            }
        }
        ASSERT_NE(rail, nullptr);
        // Angle between the rail face (pointing away from the pocket) and the facing.
        const Vec2 away = norm(rail->a - facing.a) > norm(rail->b - facing.a) ? rail->a - rail->b
                                                                              : rail->b - rail->a;
        const double cosang = dot(away, facing.dir) / norm(away);
        const double deg = std::acos(cosang) * 180.0 / std::numbers::pi;
        const bool side = facing.pocket == 1 || facing.pocket == 4;
        EXPECT_NEAR(deg, side ? 104.0 : 142.0, 1e-9) << pocket_name(facing.pocket);
    }
}

TEST(Table, NosesAreTangentToBothFaces) {
    const Table t = build_table(*table_preset("9ft"));
    for (const JawNose& n : t.noses) {
        int tangent = 0;
        for (const CushionLine& l : t.lines) {
            const double along = dot(n.centre - l.a, l.dir);
            const double off = dot(n.centre - l.a, l.normal);
            if (along > -1e-9 && along < l.length + 1e-9 && std::fabs(off + n.radius) < 1e-12)
                ++tangent;
        }
        EXPECT_EQ(tangent, 2) << "nose of " << pocket_name(n.pocket);
    }
}

TEST(Table, PlayingSurface) {
    const Table t = build_table(*table_preset("9ft"));
    const double R = 0.028575;
    EXPECT_TRUE(t.on_surface({1.0, 0.6}, R));
    EXPECT_TRUE(t.on_surface({R, R + 0.3}, R));
    EXPECT_FALSE(t.on_surface({R - 1e-6, 0.5}, R));
    EXPECT_FALSE(t.on_surface({1.0, 1.27}, R));
    EXPECT_FALSE(t.on_surface({-0.1, -0.1}, R));
    // In a side pocket's mouth, on the lip, the ball still lies on the table.
    EXPECT_TRUE(t.on_surface({t.length() / 2, R - 0.002}, R));
    const Table closed = [] {
        TableSpec s = *table_preset("9ft");
        s.pockets = false;
        return build_table(s);
    }();
    EXPECT_EQ(closed.lines.size(), 6u);
    EXPECT_TRUE(closed.pockets.empty());
}

/// The least distance from p to the segment [a, b].
double distance_to_segment(Vec2 p, Vec2 a, Vec2 b) {
    const Vec2 d = b - a;
    const double along = std::clamp(dot(p - a, d) / dot(d, d), 0.0, 1.0);
    return norm(p - (a + along * d));
}

TEST(Table, BallEmbeddedInAJawAtAPocketMouthIsNotOnTheBed) {
    // Half inside the S pocket's east jaw, on the NW corner pocket's diagonal (issue 45, part
    // 2, item 3): once accepted, it travelled inside the S–SE rail. Its mirror images too.
    const Table t = build_table(*table_preset("9ft"));
    const double R = 0.028575, L = t.length(), W = t.width();
    for (const Vec2 p :
         {Vec2{1.338, 0.0}, Vec2{L - 1.338, 0.0}, Vec2{1.338, W}, Vec2{L - 1.338, W}})
        EXPECT_FALSE(t.on_surface(p, R)) << p.x << ", " << p.y;
}

TEST(Table, OnTheBedMeansClearOfEveryCushion) {
    // Random points on and around each table: every one on_surface accepts keeps the ball (its
    // centre) at least R from every cushion face and R + r from every jaw nose, up to the
    // touching tolerance (1e-9 m), whichever pocket's mouth it is in.
    const double R = 0.028575, tol = 1e-9;
    for (const char* preset : {"7ft", "8ft", "9ft"}) {
        const Table t = build_table(*table_preset(preset));
        SplitMix64 rng(45);
        int accepted = 0;
        for (int k = 0; k < 400000; ++k) {
            // Half the points within 0.1 m of a cushion line, where the pockets are.
            const Vec2 p = k % 2 == 0
                               ? Vec2{-0.1 + rng.uniform() * (t.length() + 0.2),
                                      -0.1 + rng.uniform() * (t.width() + 0.2)}
                               : [&] {
                                     const CushionLine& l = t.lines[rng.below(t.lines.size())];
                                     return l.a + (rng.uniform() * l.length) * l.dir +
                                            (rng.uniform() * 0.1 - 0.05) * l.normal;
                                 }();
            if (!t.on_surface(p, R)) continue;
            ++accepted;
            for (const CushionLine& l : t.lines)
                ASSERT_GE(distance_to_segment(p, l.a, l.b), R - tol)
                    << preset << " (" << p.x << ", " << p.y << ") rail " << l.rail << " pocket "
                    << l.pocket;
            for (const JawNose& n : t.noses)
                ASSERT_GE(norm(p - n.centre), R + n.radius - tol)
                    << preset << " (" << p.x << ", " << p.y << ") nose of pocket " << n.pocket;
        }
        EXPECT_GT(accepted, 100000) << preset;  // the test looks at the bed, not at nothing
    }
}

TEST(Table, InvalidSpecsNameTheField) {
    TableSpec s = *table_preset("9ft");
    s.corner_mouth = 0.03;
    EXPECT_EQ(validate_table_spec(s, 0.028575)->rfind("corner_mouth", 0), 0u);
    s = *table_preset("9ft");
    s.width = 3.0;
    EXPECT_EQ(validate_table_spec(s, 0.028575)->rfind("width", 0), 0u);
    s = *table_preset("9ft");
    s.cushion_height = 0.01;
    EXPECT_EQ(validate_table_spec(s, 0.028575)->rfind("cushion_height", 0), 0u);
}

TEST(Layout, OverlapsAndOffTableBallsAreRefused) {
    const Table t = build_table(*table_preset("9ft"));
    const Params p;
    const double R = p.ball_radius;
    std::vector<BallState> balls(2);
    balls[0].pos = {1.0, 0.6};
    balls[1].id = 5;
    balls[1].pos = {1.0 + 2 * R - 2e-9, 0.6};
    auto err = validate_layout(t, p, balls);
    ASSERT_TRUE(err);
    EXPECT_EQ(err->index, 1u);
    EXPECT_EQ(err->field, "pos");
    EXPECT_NE(err->message.find("overlaps ball 0"), std::string::npos);
    balls[1].pos = {1.0 + 2 * R - 0.5e-9, 0.6};  // touching within tolerance: frozen, valid
    EXPECT_FALSE(validate_layout(t, p, balls));
    balls[1].pos = {3.0, 0.6};
    err = validate_layout(t, p, balls);
    ASSERT_TRUE(err);
    EXPECT_NE(err->message.find("off the table"), std::string::npos);
    balls[1].pos = {2.0, 0.6};
    balls[1].id = 0;
    err = validate_layout(t, p, balls);
    ASSERT_TRUE(err);
    EXPECT_EQ(err->field, "id");
}

}  // namespace
}  // namespace physics
