#include "render/cue_stick.hpp"

#include <algorithm>
#include <array>
#include <cmath>

#include "render/table_mesh.hpp"

namespace render {

namespace {

/// One turned section of the cue: from `s0` to `s1` along it (unit: m from the tip), radii and
/// colours (sRGB) at both ends, and optionally `points` inlaid sectors of a second colour whose
/// share of the circumference goes from `share0` at s0 to `share1` at s1 (the forearm's points).
struct Section {
    float s0, s1, r0, r1;
    glm::vec3 c0, c1;
    int points = 0;
    glm::vec3 inlay{0.0f};
    float share0 = 0.0f, share1 = 0.0f;
};

constexpr glm::vec3 kTip{0.16f, 0.26f, 0.52f};      // blue chalk on leather
constexpr glm::vec3 kIvory{0.93f, 0.91f, 0.85f};    // ferrule
constexpr glm::vec3 kMaple{0.88f, 0.76f, 0.54f};    // shaft
constexpr glm::vec3 kSteel{0.72f, 0.72f, 0.74f};    // joint collar, rings
constexpr glm::vec3 kEbony{0.07f, 0.045f, 0.035f};  // forearm, sleeve
constexpr glm::vec3 kWrap{0.10f, 0.12f, 0.16f};     // Irish linen
constexpr glm::vec3 kRose{0.30f, 0.08f, 0.05f};     // rosewood sleeve
constexpr glm::vec3 kBumper{0.03f, 0.03f, 0.03f};

const std::array<Section, 14> kSections = {{
    {0.000f, 0.011f, 0.0062f, 0.0063f, kTip, kTip},
    {0.011f, 0.036f, 0.0064f, 0.0064f, kIvory, kIvory},
    {0.036f, 0.740f, 0.0064f, 0.0102f, kMaple, glm::vec3(0.84f, 0.71f, 0.49f)},
    {0.740f, 0.746f, 0.0104f, 0.0104f, kIvory, kIvory},
    {0.746f, 0.770f, 0.0106f, 0.0106f, kSteel, kSteel},
    {0.770f, 0.776f, 0.0107f, 0.0107f, kIvory, kIvory},
    {0.776f, 1.040f, 0.0107f, 0.0126f, kMaple, kMaple, 4, kEbony, 0.0f, 0.8f},
    {1.040f, 1.046f, 0.0127f, 0.0127f, kSteel, kSteel},
    {1.046f, 1.300f, 0.0128f, 0.0136f, kWrap, kWrap},
    {1.300f, 1.306f, 0.0137f, 0.0137f, kSteel, kSteel},
    {1.306f, 1.440f, 0.0138f, 0.0144f, kRose, kRose, 8, kIvory, 0.12f, 0.12f},
    {1.440f, 1.446f, 0.0144f, 0.0144f, kSteel, kSteel},
    {1.446f, 1.466f, 0.0144f, 0.0142f, kBumper, kBumper},
    {1.466f, kCueLength, 0.0142f, 0.0135f, kBumper, kBumper},
}};

/// How far the cue may be drawn back (the Power slider's most): the butt clears the rail at
/// every pull-back, so the forced elevation does not change with the power.
constexpr float kMostPullBack = 0.25f;

/// Horizontal distance from `p` along the unit vector `d` to leaving the box [lo, hi] (0 when
/// outside it already).
float leave_box(glm::vec2 p, glm::vec2 d, glm::vec2 lo, glm::vec2 hi) {
    if (p.x <= lo.x || p.y <= lo.y || p.x >= hi.x || p.y >= hi.y) return 0.0f;
    float t = 1e9f;
    for (int k = 0; k < 2; ++k) {
        if (d[k] > 1e-6f) t = std::min(t, (hi[k] - p[k]) / d[k]);
        if (d[k] < -1e-6f) t = std::min(t, (lo[k] - p[k]) / d[k]);
    }
    return t;
}

/// Whether the cue at `elevation` clears every step of the cushion's and rail's profile.
bool clears(const physics::Table& table, float ball_radius, glm::vec2 cue_ball, float heading,
            glm::vec2 tip_offset, float elevation) {
    const TableDims d = table_dims(table);
    const CueAxis a = cue_axis(cue_ball, ball_radius, heading, elevation, tip_offset, 0.0f);
    const glm::vec2 back{-std::cos(heading), -std::sin(heading)};
    const glm::vec2 lo{0.0f, 0.0f};
    const glm::vec2 hi{static_cast<float>(table.length()), static_cast<float>(table.width())};
    // The profile behind the nose line: the nose, the top of the cushion's roll, its back at
    // rail height (beyond it the rail top, as high).
    const float steps[3][2] = {{0.0f, d.cushion_height},
                               {0.006f, d.cushion_height + 0.0045f},
                               {d.cushion_width, d.rail_height}};
    const float c = std::cos(elevation), t = std::tan(elevation);
    for (const auto& [inset, height] : steps) {
        const glm::vec2 grow{inset, inset};
        const float x = leave_box(glm::vec2(a.tip), back, lo - grow, hi + grow);
        if (x / c > kCueLength + kMostPullBack) continue;  // the cue ends before it
        const float underside = a.tip.z + x * t - cue_radius(x / c) / c;
        if (underside < height + 0.002f) return false;
    }
    return true;
}

}  // namespace

float cue_radius(float s) {
    for (const Section& k : kSections)
        if (s <= k.s1)
            return k.r0 + (k.r1 - k.r0) * std::clamp((s - k.s0) / (k.s1 - k.s0), 0.0f, 1.0f);
    return kSections.back().r1;
}

CueAxis cue_axis(glm::vec2 cue_ball, float ball_radius, float heading, float elevation,
                 glm::vec2 tip_offset, float pull_back) {
    const float ch = std::cos(heading), sh = std::sin(heading);
    const glm::vec3 f{ch * std::cos(elevation), sh * std::cos(elevation), -std::sin(elevation)};
    const glm::vec3 right{sh, -ch, 0.0f};
    const glm::vec3 up = glm::cross(right, f);
    // Offsets beyond the ball's edge are kept on it.
    glm::vec2 o = tip_offset;
    if (glm::length(o) > 0.95f) o *= 0.95f / glm::length(o);
    const float depth = std::sqrt(std::max(0.0f, 1.0f - glm::dot(o, o)));
    const glm::vec3 centre{cue_ball, ball_radius};
    const glm::vec3 contact = centre + ball_radius * (o.x * right + o.y * up - depth * f);
    return {contact - pull_back * f, f};
}

float rail_forced_elevation(const physics::Table& table, float ball_radius, glm::vec2 cue_ball,
                            float heading, glm::vec2 tip_offset) {
    const float most = 1.0471976f;  // 60 degrees
    if (clears(table, ball_radius, cue_ball, heading, tip_offset, 0.0f)) return 0.0f;
    if (!clears(table, ball_radius, cue_ball, heading, tip_offset, most)) return most;
    float lo = 0.0f, hi = most;
    for (int i = 0; i < 24; ++i) {
        const float mid = 0.5f * (lo + hi);
        (clears(table, ball_radius, cue_ball, heading, tip_offset, mid) ? hi : lo) = mid;
    }
    return hi;
}

float drawn_cue_elevation(const physics::Table& table, float ball_radius, glm::vec2 cue_ball,
                          float heading, float chosen, glm::vec2 tip_offset) {
    return std::max(chosen,
                    rail_forced_elevation(table, ball_radius, cue_ball, heading, tip_offset));
}

glm::vec4 cue_shadow_rect(const physics::Table& table, const CueAxis& axis) {
    const glm::vec3 a = axis.tip, b = axis.tip - kCueLength * axis.dir;
    const float reach = 0.05f + 1.6f * std::max(a.z, b.z);
    const float L = static_cast<float>(table.length()), W = static_cast<float>(table.width());
    const float in = table_dims(table).cushion_width;
    return {std::max(std::min(a.x, b.x) - reach, -in), std::max(std::min(a.y, b.y) - reach, -in),
            std::min(std::max(a.x, b.x) + reach, L + in),
            std::min(std::max(a.y, b.y) + reach, W + in)};
}

std::vector<SolidVertex> cue_mesh(const CueAxis& axis) {
    std::vector<SolidVertex> out;
    const auto at = [&](float s) { return axis.tip - s * axis.dir; };
    // The tip's domed face.
    add_lathe(out, at(-0.0015f), at(0.0f), 0.0035f, kSections[0].r0, kTip, kTip, 24);
    for (const Section& k : kSections) {
        if (k.points == 0) {
            add_lathe(out, at(k.s0), at(k.s1), k.r0, k.r1, k.c0, k.c1, 16);
            continue;
        }
        // Inlaid points, in rows whose inlay share steps from share0 to share1.
        const int rows = 5;
        for (int r = 0; r < rows; ++r) {
            const float u0 = static_cast<float>(r) / rows, u1 = static_cast<float>(r + 1) / rows;
            const float share = k.share0 + (k.share1 - k.share0) * 0.5f * (u0 + u1);
            add_sectors(out, at(k.s0 + u0 * (k.s1 - k.s0)), at(k.s0 + u1 * (k.s1 - k.s0)),
                        k.r0 + u0 * (k.r1 - k.r0), k.r0 + u1 * (k.r1 - k.r0), k.c0, k.inlay,
                        k.points, share);
        }
    }
    // The bumper's end.
    add_lathe(out, at(kCueLength), at(kCueLength + 0.002f), kSections.back().r1, 0.004f, kBumper,
              kBumper, 24);
    return out;
}

}  // namespace render
