#include "render/solid_mesh.hpp"

#include <cmath>

namespace render {

void add_lathe(std::vector<SolidVertex>& out, glm::vec3 a, glm::vec3 b, float ra, float rb,
               glm::vec3 ca, glm::vec3 cb, int sides) {
    const glm::vec3 axis = glm::normalize(b - a);
    const glm::vec3 helper = std::abs(axis.z) < 0.9f ? glm::vec3(0, 0, 1) : glm::vec3(1, 0, 0);
    const glm::vec3 u = glm::normalize(glm::cross(axis, helper)), v = glm::cross(axis, u);
    for (int i = 0; i < sides; ++i) {
        const float t0 = 6.2831853f * static_cast<float>(i) / static_cast<float>(sides);
        const float t1 = 6.2831853f * static_cast<float>(i + 1) / static_cast<float>(sides);
        const glm::vec3 n0 = std::cos(t0) * u + std::sin(t0) * v,
                        n1 = std::cos(t1) * u + std::sin(t1) * v;
        const SolidVertex p0{a + ra * n0, n0, ca}, p1{a + ra * n1, n1, ca}, q0{b + rb * n0, n0, cb},
            q1{b + rb * n1, n1, cb};
        out.insert(out.end(), {p0, p1, q1, p0, q1, q0});
    }
}

void add_sectors(std::vector<SolidVertex>& out, glm::vec3 a, glm::vec3 b, float ra, float rb,
                 glm::vec3 base, glm::vec3 inlay, int sectors, float share) {
    const glm::vec3 axis = glm::normalize(b - a);
    const glm::vec3 helper = std::abs(axis.z) < 0.9f ? glm::vec3(0, 0, 1) : glm::vec3(1, 0, 0);
    const glm::vec3 u = glm::normalize(glm::cross(axis, helper)), v = glm::cross(axis, u);
    const float step = 6.2831853f / static_cast<float>(sectors);
    // Each sector: base, inlay, base, as angular bands; the base bands 2 facets, the inlay 1.
    const float edges[4] = {0.0f, 0.5f - 0.5f * share, 0.5f + 0.5f * share, 1.0f};
    for (int k = 0; k < sectors; ++k) {
        for (int band = 0; band < 3; ++band) {
            const glm::vec3 colour = band == 1 ? inlay : base;
            const float width = edges[band + 1] - edges[band];
            const float facets = band == 1 ? 1.0f : 2.0f;
            for (float f = 0.0f; f < facets; f += 1.0f) {
                const float w0 = edges[band] + width * f / facets;
                const float w1 = edges[band] + width * (f + 1.0f) / facets;
                const float t0 = step * (static_cast<float>(k) + w0);
                const float t1 = step * (static_cast<float>(k) + w1);
                const glm::vec3 n0 = std::cos(t0) * u + std::sin(t0) * v,
                                n1 = std::cos(t1) * u + std::sin(t1) * v;
                const SolidVertex p0{a + ra * n0, n0, colour}, p1{a + ra * n1, n1, colour},
                    q0{b + rb * n0, n0, colour}, q1{b + rb * n1, n1, colour};
                out.insert(out.end(), {p0, p1, q1, p0, q1, q0});
            }
        }
    }
}

void add_ribbon(std::vector<SolidVertex>& out, const std::vector<glm::vec2>& line, float half_width,
                float z, glm::vec3 colour) {
    for (std::size_t i = 0; i + 1 < line.size(); ++i) {
        const glm::vec2 d = line[i + 1] - line[i];
        if (glm::length(d) < 1e-6f) continue;
        const glm::vec2 s = half_width * glm::normalize(glm::vec2(-d.y, d.x));
        const glm::vec3 up{0, 0, 1};
        const SolidVertex a{{line[i] - s, z}, up, colour}, b{{line[i + 1] - s, z}, up, colour},
            c{{line[i + 1] + s, z}, up, colour}, e{{line[i] + s, z}, up, colour};
        out.insert(out.end(), {a, b, c, a, c, e});
    }
}

void add_box(std::vector<SolidVertex>& out, glm::vec3 lo, glm::vec3 hi, glm::vec3 colour) {
    const glm::vec3 p[8] = {{lo.x, lo.y, lo.z}, {hi.x, lo.y, lo.z}, {hi.x, hi.y, lo.z},
                            {lo.x, hi.y, lo.z}, {lo.x, lo.y, hi.z}, {hi.x, lo.y, hi.z},
                            {hi.x, hi.y, hi.z}, {lo.x, hi.y, hi.z}};
    const int faces[6][4] = {{0, 1, 2, 3}, {4, 5, 6, 7}, {0, 1, 5, 4},
                             {1, 2, 6, 5}, {2, 3, 7, 6}, {3, 0, 4, 7}};
    const glm::vec3 normals[6] = {{0, 0, -1}, {0, 0, 1}, {0, -1, 0},
                                  {1, 0, 0},  {0, 1, 0}, {-1, 0, 0}};
    for (int f = 0; f < 6; ++f) {
        const auto v = [&](int k) { return SolidVertex{p[faces[f][k]], normals[f], colour}; };
        out.insert(out.end(), {v(0), v(1), v(2), v(0), v(2), v(3)});
    }
}

void add_patch(std::vector<SolidVertex>& out, glm::vec2 lo, glm::vec2 hi, float z,
               glm::vec3 colour) {
    const glm::vec3 up{0, 0, 1};
    const SolidVertex a{{lo.x, lo.y, z}, up, colour}, b{{hi.x, lo.y, z}, up, colour},
        c{{hi.x, hi.y, z}, up, colour}, d{{lo.x, hi.y, z}, up, colour};
    out.insert(out.end(), {a, b, c, a, c, d});
}

void add_half_disc(std::vector<SolidVertex>& out, glm::vec2 centre, float radius, float a0,
                   float a1, float z, glm::vec3 colour) {
    const glm::vec3 up{0, 0, 1};
    const int n = 32;
    for (int i = 0; i < n; ++i) {
        const float t0 = a0 + (a1 - a0) * static_cast<float>(i) / n;
        const float t1 = a0 + (a1 - a0) * static_cast<float>(i + 1) / n;
        const glm::vec2 p0 = centre + radius * glm::vec2(std::cos(t0), std::sin(t0));
        const glm::vec2 p1 = centre + radius * glm::vec2(std::cos(t1), std::sin(t1));
        out.insert(out.end(), {SolidVertex{{centre, z}, up, colour},
                               SolidVertex{{p0, z}, up, colour}, SolidVertex{{p1, z}, up, colour}});
    }
}

void add_ring(std::vector<SolidVertex>& out, glm::vec2 centre, float radius, float half_width,
              float z, glm::vec3 colour) {
    std::vector<glm::vec2> circle;
    for (int i = 0; i <= 48; ++i) {
        const float t = 6.2831853f * static_cast<float>(i) / 48.0f;
        circle.push_back(centre + radius * glm::vec2(std::cos(t), std::sin(t)));
    }
    add_ribbon(out, circle, half_width, z, colour);
}

}  // namespace render
