// The cue-ball camera, the cue stick's placement, the pockets and the room: pure geometry,
// no GL.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <vector>

#include "physics/params.hpp"
#include "render/camera.hpp"
#include "render/cue_stick.hpp"
#include "render/pockets.hpp"
#include "render/room.hpp"
#include "render/table_mesh.hpp"

namespace {

const physics::Table& nine_foot() {
    static const physics::Table t = physics::build_table(*physics::table_preset("9ft"));
    return t;
}
const float R = static_cast<float>(physics::Params{}.ball_radius);

/// Cue-ball places over the whole cloth, the rails and corners included.
std::vector<glm::vec2> places(const physics::Table& t) {
    const float L = static_cast<float>(t.length()), W = static_cast<float>(t.width());
    std::vector<glm::vec2> out;
    for (float x : {R + 0.001f, 0.1f, 0.5f * L, L - 0.1f, L - R - 0.001f})
        for (float y : {R + 0.001f, 0.08f, 0.5f * W, W - R - 0.001f}) out.push_back({x, y});
    return out;
}

/// Whether a point is over the cushions or rails (between the cloth's edge and the table's).
bool over_rails(const physics::Table& t, glm::vec2 p) {
    const render::TableDims d = render::table_dims(t);
    const float out = d.cushion_width + d.rail_width;
    const float L = static_cast<float>(t.length()), W = static_cast<float>(t.width());
    const bool in_table = p.x > -out && p.x < L + out && p.y > -out && p.y < W + out;
    const bool on_cloth = p.x > 0 && p.x < L && p.y > 0 && p.y < W;
    return in_table && !on_cloth;
}

TEST(CueBallCamera, FarFromTheRailsItIsWhereItWasAsked) {
    const glm::vec2 c{1.27f, 0.635f};
    const render::Camera cam = render::cue_ball_camera(nine_foot(), R, {c, 0.0f, 0.75f, 0.28f});
    EXPECT_NEAR(cam.eye.x, c.x - 0.75f, 1e-5f);
    EXPECT_NEAR(cam.eye.y, c.y, 1e-5f);
    EXPECT_NEAR(cam.eye.z, 0.28f, 1e-5f);
}

TEST(CueBallCamera, NeverInsideARailOrTheRoomAndSeesTheBallOverTheRail) {
    const physics::Table& t = nine_foot();
    const render::RoomDims room = render::room_dims(t);
    const render::TableDims d = render::table_dims(t);
    int checked = 0;
    for (const glm::vec2 c : places(t))
        for (int k = 0; k < 16; ++k)
            for (float distance : {0.3f, 0.75f, 2.5f}) {
                const float heading = static_cast<float>(k) * std::numbers::pi_v<float> / 8;
                const render::Camera cam =
                    render::cue_ball_camera(t, R, {c, heading, distance, 0.12f + 0.21f * distance});
                const glm::vec3 e = cam.eye;
                EXPECT_GT(e.x, room.lo.x + 0.25f);
                EXPECT_LT(e.x, room.hi.x - 0.25f);
                EXPECT_GT(e.y, room.lo.y + 0.25f);
                EXPECT_LT(e.y, room.hi.y - 0.25f);
                EXPECT_LT(e.z, room.ceiling_z - 0.25f);
                if (over_rails(t, e)) {
                    EXPECT_GT(e.z, d.rail_height + 0.05f);
                }
                // The line of sight to the ball's upper half passes over the rails.
                const glm::vec3 seen{c, 1.5f * R};
                for (int s = 1; s < 200; ++s) {
                    const glm::vec3 p = glm::mix(e, seen, static_cast<float>(s) / 200.0f);
                    if (over_rails(t, p)) {
                        ASSERT_GT(p.z, d.rail_height) << c.x << ' ' << c.y;
                    }
                }
                // The ball is in the view, below its centre.
                const glm::vec3 f = glm::normalize(cam.target - e);
                const glm::vec3 to_ball = glm::normalize(glm::vec3(c, R) - e);
                const float off = std::acos(std::clamp(glm::dot(f, to_ball), -1.0f, 1.0f));
                EXPECT_LT(off, glm::radians(0.5f * cam.fovy_deg - 2.0f));
                ++checked;
            }
    EXPECT_EQ(checked, 20 * 16 * 3);
}

TEST(CueBallCamera, ARaisedCueRaisesTheViewAboveIt) {
    const glm::vec2 c{1.27f, 0.635f};
    const float up = glm::radians(25.0f);
    const render::Camera flat = render::cue_ball_camera(nine_foot(), R, {c, 0.3f, 0.75f, 0.28f});
    const render::Camera raised =
        render::cue_ball_camera(nine_foot(), R, {c, 0.3f, 0.75f, 0.28f, up});
    EXPECT_GT(raised.eye.z, flat.eye.z + 0.1f);
    // Above the cue's axis where the eye is, so the cue is seen from above, not end-on.
    const float back = glm::length(glm::vec2(raised.eye) - c);
    EXPECT_GT(raised.eye.z, R + back * std::tan(up) + 0.03f);
}

TEST(CueStick, TheTipMeetsTheBallAtTheChosenOffset) {
    const glm::vec2 c{1.0f, 0.6f};
    const glm::vec2 offset{0.3f, -0.4f};
    const float heading = 0.7f, elevation = glm::radians(10.0f);
    const render::CueAxis a = render::cue_axis(c, R, heading, elevation, offset, 0.0f);
    const glm::vec3 centre{c, R};
    EXPECT_NEAR(glm::length(a.tip - centre), R, 1e-6f);
    // The axis passes 0.3 R right of and 0.4 R below the centre, as the shooter sees it.
    const glm::vec3 right{std::sin(heading), -std::cos(heading), 0.0f};
    const glm::vec3 up = glm::cross(right, a.dir);
    EXPECT_NEAR(glm::dot(a.tip - centre, right), 0.3f * R, 1e-6f);
    EXPECT_NEAR(glm::dot(a.tip - centre, up), -0.4f * R, 1e-6f);
    EXPECT_NEAR(a.dir.z, -std::sin(elevation), 1e-6f);
    // Drawn back along its own axis.
    const render::CueAxis back = render::cue_axis(c, R, heading, elevation, offset, 0.1f);
    EXPECT_NEAR(glm::length(back.tip - (a.tip - 0.1f * a.dir)), 0.0f, 1e-6f);
}

TEST(CueStick, ItsPartsTaperFromTipToButt) {
    EXPECT_NEAR(render::cue_radius(0.0f), 0.0062f, 2e-4f);
    EXPECT_NEAR(render::cue_radius(render::kCueLength), 0.0135f, 1e-3f);
    EXPECT_LT(render::cue_radius(0.3f), render::cue_radius(1.2f));
    const std::vector<render::SolidVertex> mesh = render::cue_mesh({{0, 0, 0}, {1, 0, 0}});
    ASSERT_FALSE(mesh.empty());
    for (const render::SolidVertex& v : mesh) {
        EXPECT_LE(v.pos.x, 0.0021f);  // nothing ahead of the tip's dome
        EXPECT_GE(v.pos.x, -render::kCueLength - 0.0021f);
    }
}

TEST(CueStick, FarFromTheRailsNothingIsForced) {
    // 2 m from the head rail: the cue (1.47 m, drawn back 0.25 m) ends before it.
    EXPECT_EQ(render::rail_forced_elevation(nine_foot(), R, {2.0f, 0.635f}, 0.0f), 0.0f);
    EXPECT_EQ(render::drawn_cue_elevation(nine_foot(), R, {2.0f, 0.635f}, 0.0f, 0.2f), 0.2f);
    // From mid-table the butt reaches the head rail and rides just over it.
    const float mid = render::rail_forced_elevation(nine_foot(), R, {1.27f, 0.635f}, 0.0f);
    EXPECT_GT(mid, 0.0f);
    EXPECT_LT(mid, glm::radians(3.0f));
}

/// The cushion's and rail's height at `p`: from the nose up over the cushion's roll to the rail
/// top, by how far p lies outside the cloth's rectangle (0 on the cloth).
float profile_height(const physics::Table& t, glm::vec2 p) {
    const render::TableDims d = render::table_dims(t);
    const float L = static_cast<float>(t.length()), W = static_cast<float>(t.width());
    const float inset = std::max(std::max(-p.x, p.x - L), std::max(-p.y, p.y - W));
    if (inset <= 0.0f) return 0.0f;
    const float roll = d.cushion_height + 0.0045f;
    if (inset < 0.006f) return d.cushion_height + (roll - d.cushion_height) * inset / 0.006f;
    if (inset < d.cushion_width)
        return roll + (d.rail_height - roll) * (inset - 0.006f) / (d.cushion_width - 0.006f);
    return d.rail_height;
}

/// The lowest clearance of the cue's underside over the cushions and rails (unit: m).
float clearance(const physics::Table& t, glm::vec2 c, float heading, float elevation) {
    const render::CueAxis a = render::cue_axis(c, R, heading, elevation, {0.0f, 0.0f}, 0.0f);
    float least = 1e9f;
    for (int k = 0; k <= 2000; ++k) {
        const float s = (render::kCueLength + 0.25f) * static_cast<float>(k) / 2000.0f;
        const glm::vec3 p = a.tip - s * a.dir;
        if (!over_rails(t, glm::vec2(p))) continue;
        const float underside =
            p.z - render::cue_radius(std::min(s, render::kCueLength)) / std::cos(elevation);
        least = std::min(least, underside - profile_height(t, glm::vec2(p)));
    }
    return least;
}

TEST(CueStick, ARailBehindTheBallRaisesTheButtOverIt) {
    const physics::Table& t = nine_foot();
    // 4 mm off the head rail, shooting up the table; then at a slant, close to the side rail.
    for (const auto& [c, heading] :
         {std::pair{glm::vec2(R + 0.004f, 0.7f), 0.0f}, std::pair{glm::vec2(0.8f, R + 0.01f), 1.2f},
          std::pair{glm::vec2(0.15f, 0.3f), 0.2f}}) {
        const float forced = render::rail_forced_elevation(t, R, c, heading);
        EXPECT_GT(forced, 0.0f);
        EXPECT_LT(forced, glm::radians(60.0f));
        // 2 mm to spare at the forced elevation; a degree lower, less.
        EXPECT_GE(clearance(t, c, heading, forced), 0.0019f) << c.x << ' ' << c.y;
        EXPECT_LT(clearance(t, c, heading, forced - glm::radians(1.0f)), 0.002f);
    }
}

TEST(CueStick, ItsShadowNeverFallsBeyondTheTable) {
    const physics::Table& t = nine_foot();
    const render::TableDims d = render::table_dims(t);
    const float L = static_cast<float>(t.length()), W = static_cast<float>(t.width());
    int drawn = 0;
    for (const glm::vec2 c : places(t))
        for (int k = 0; k < 8; ++k)
            for (float elevation : {0.0f, 0.44f, 1.0f}) {
                const float heading = static_cast<float>(k) * std::numbers::pi_v<float> / 4;
                const render::CueAxis a =
                    render::cue_axis(c, R, heading, elevation, {0.0f, 0.0f}, 0.0f);
                const glm::vec4 r = render::cue_shadow_rect(t, a);
                if (r.x >= r.z || r.y >= r.w) continue;
                ++drawn;
                EXPECT_GE(r.x, -d.cushion_width - 1e-6f);
                EXPECT_GE(r.y, -d.cushion_width - 1e-6f);
                EXPECT_LE(r.z, L + d.cushion_width + 1e-6f);
                EXPECT_LE(r.w, W + d.cushion_width + 1e-6f);
                // It still covers the cue's tip, on the ball over the cloth.
                EXPECT_LE(r.x, a.tip.x);
                EXPECT_GE(r.z, a.tip.x);
            }
    EXPECT_EQ(drawn, 20 * 8 * 3);
}

TEST(Pockets, TheClothHasHolesWhereThePocketsAre) {
    const physics::Table& t = nine_foot();
    const render::TableMesh mesh = render::build_table_mesh(t);
    const std::vector<render::PocketHole> holes = render::pocket_holes(t);
    double area = 0.0;
    for (std::size_t i = 0; i + 2 < mesh.cloth.size(); i += 3) {
        const glm::vec3 a = mesh.cloth[i].pos, b = mesh.cloth[i + 1].pos, c = mesh.cloth[i + 2].pos;
        area += 0.5 * glm::length(glm::cross(b - a, c - a));
        const glm::vec2 mid = glm::vec2(a + b + c) / 3.0f;
        for (const render::PocketHole& h : holes)
            EXPECT_GT(glm::distance(mid, h.centre), h.radius - 1e-4f);
    }
    const render::TableDims d = render::table_dims(t);
    const double out = d.cushion_width + d.rail_width;
    double expected = (t.length() + 2 * out) * (t.width() + 2 * out);
    for (const render::PocketHole& h : holes) expected -= std::numbers::pi * h.radius * h.radius;
    EXPECT_NEAR(area, expected, 0.002 * expected);
}

TEST(Pockets, ADroppingBallFallsIntoTheNet) {
    const physics::Table& t = nine_foot();
    const render::PocketHole corner = render::pocket_holes(t).front();
    const glm::vec2 from = corner.centre + glm::vec2(0.03f, 0.03f);
    EXPECT_NEAR(glm::distance(render::dropping_ball_centre(t, R, from, 0.0f), glm::vec3(from, R)),
                0.0f, 1e-6f);
    float last = R;
    for (float s = 0.02f; s < 1.0f; s += 0.02f) {
        const glm::vec3 p = render::dropping_ball_centre(t, R, from, s);
        EXPECT_LE(p.z, last);
        EXPECT_GE(p.z - R, -render::kNetDepth - 1e-6f);  // never through the net
        last = p.z;
    }
    const glm::vec3 end = render::dropping_ball_centre(t, R, from, 1.0f);
    EXPECT_NEAR(glm::distance(glm::vec2(end), corner.centre), 0.0f, 1e-5f);
    EXPECT_LT(end.z, -0.1f);
}

TEST(Room, ItHoldsTheTableWithRoomForAStrokeAndTheLampsOverIt) {
    const physics::Table& t = nine_foot();
    const render::RoomDims r = render::room_dims(t);
    const render::TableDims d = render::table_dims(t);
    const float out = d.cushion_width + d.rail_width;
    EXPECT_LT(r.lo.x, -out - 1.6f);
    EXPECT_GT(r.hi.x, static_cast<float>(t.length()) + out + 1.6f);
    EXPECT_LT(r.lo.y, -out - 1.6f);
    EXPECT_GT(r.hi.y, static_cast<float>(t.width()) + out + 1.6f);
    for (const render::Lamp& l : render::table_lamps(t)) {
        EXPECT_GT(l.pos.x, 0.0f);
        EXPECT_LT(l.pos.x, static_cast<float>(t.length()));
        EXPECT_LT(l.pos.z, r.ceiling_z);
    }
    for (const render::SolidVertex& v : render::room_mesh(t)) {
        EXPECT_GE(v.pos.x, r.lo.x - 1e-4f);
        EXPECT_LE(v.pos.x, r.hi.x + 1e-4f);
        EXPECT_GE(v.pos.z, r.floor_z - 1e-4f);
        EXPECT_LE(v.pos.z, r.ceiling_z + 1e-4f);
    }
}

}  // namespace
