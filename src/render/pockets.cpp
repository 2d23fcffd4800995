#include "render/pockets.hpp"

#include <algorithm>
#include <cmath>

#include "render/table_mesh.hpp"

namespace render {

namespace {

constexpr glm::vec3 kLeather{0.22f, 0.13f, 0.08f};
constexpr glm::vec3 kNetDark{0.06f, 0.05f, 0.045f}, kNetString{0.45f, 0.38f, 0.28f};

/// Facets round a pocket: few, since llvmpipe pays for every triangle even where the cloth
/// hides it.
constexpr int kFacets = 24;

/// A band round the pocket's axis from ring (r0, z0) to ring (r1, z1), kFacets facets; normals
/// toward the axis; colour per facet from `colour(facet)`.
template <typename Colour>
void add_band(std::vector<SolidVertex>& out, glm::vec2 c, float r0, float r1, const float* z0,
              const float* z1, Colour colour) {
    for (int i = 0; i < kFacets; ++i) {
        const float a0 = 6.2831853f * static_cast<float>(i) / kFacets;
        const float a1 = 6.2831853f * static_cast<float>(i + 1) / kFacets;
        const glm::vec2 d0{std::cos(a0), std::sin(a0)}, d1{std::cos(a1), std::sin(a1)};
        const glm::vec3 n0{-d0, 0.3f}, n1{-d1, 0.3f};
        const glm::vec3 col = colour(i);
        const SolidVertex p0{{c + r0 * d0, z0[i]}, n0, col}, p1{{c + r0 * d1, z0[i + 1]}, n1, col},
            q0{{c + r1 * d0, z1[i]}, n0, col}, q1{{c + r1 * d1, z1[i + 1]}, n1, col};
        out.insert(out.end(), {p0, p1, q1, p0, q1, q0});
    }
}

}  // namespace

std::vector<SolidVertex> pocket_mesh(const physics::Table& table) {
    const TableDims d = table_dims(table);
    const float L = static_cast<float>(table.length()), W = static_cast<float>(table.width());
    std::vector<SolidVertex> out;
    for (const PocketHole& h : pocket_holes(table)) {
        // The liner rises to the rail top where the hole cuts into the cushion and the rail,
        // and starts at the cloth where it cuts the slate.
        float top[kFacets + 1], liner_bottom[kFacets + 1];
        for (int i = 0; i <= kFacets; ++i) {
            const float a = 6.2831853f * static_cast<float>(i) / kFacets;
            const glm::vec2 p = h.centre + h.radius * glm::vec2(std::cos(a), std::sin(a));
            const bool under_rail = p.x < 0.0f || p.x > L || p.y < 0.0f || p.y > W;
            top[i] = under_rail ? d.rail_height : 0.0f;
            liner_bottom[i] = -kLinerDepth;
        }
        add_band(out, h.centre, h.radius, h.radius, top, liner_bottom,
                 [](int) { return kLeather; });
        // The net: a bag narrowing to its bottom, its strings in a diamond pattern.
        const float rows[3][2] = {
            {1.0f, -kLinerDepth}, {0.75f, -kNetDepth + 0.02f}, {0.0f, -kNetDepth}};
        for (int r = 0; r < 2; ++r) {
            float z0[kFacets + 1], z1[kFacets + 1];
            std::fill(z0, z0 + kFacets + 1, rows[r][1]);
            std::fill(z1, z1 + kFacets + 1, rows[r + 1][1]);
            add_band(out, h.centre, rows[r][0] * h.radius, rows[r + 1][0] * h.radius, z0, z1,
                     [r](int i) { return (i + r) % 2 == 0 ? kNetString : kNetDark; });
        }
    }
    return out;
}

glm::vec3 dropping_ball_centre(const physics::Table& table, float ball_radius, glm::vec2 from,
                               float seconds) {
    const std::vector<PocketHole> holes = pocket_holes(table);
    const PocketHole* hole = &holes.front();
    for (const PocketHole& h : holes)
        if (glm::distance(h.centre, from) < glm::distance(hole->centre, from)) hole = &h;
    const float t = std::max(seconds, 0.0f);
    // Toward the hole's centre within 0.12 s (the ball tips over the edge), falling meanwhile.
    const float slide = std::min(t / 0.12f, 1.0f);
    const glm::vec2 xy = glm::mix(from, hole->centre, slide * (2.0f - slide));
    const float z = ball_radius - 0.5f * 9.81f * t * t;
    return {xy, std::max(z, -kNetDepth + ball_radius + 0.002f)};  // lying in the net
}

}  // namespace render
