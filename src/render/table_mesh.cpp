#include "render/table_mesh.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace render {

namespace {

glm::vec2 v2(physics::Vec2 p) {
    return {static_cast<float>(p.x), static_cast<float>(p.y)};
}

void add_tri(std::vector<Vertex>& out, const Vertex& a, const Vertex& b, const Vertex& c) {
    out.push_back(a);
    out.push_back(b);
    out.push_back(c);
}

/// A quad a-b-c-d (counter-clockwise seen from its front) with a flat normal.
void add_quad(std::vector<Vertex>& out, glm::vec3 a, glm::vec3 b, glm::vec3 c, glm::vec3 d,
              glm::vec2 ua, glm::vec2 ub, glm::vec2 uc, glm::vec2 ud) {
    glm::vec3 n = glm::cross(b - a, d - a);
    if (glm::length(n) < 1e-12f) n = glm::cross(c - b, d - b);
    if (glm::length(n) < 1e-12f) return;
    n = glm::normalize(n);
    add_tri(out, {a, n, ua}, {b, n, ub}, {c, n, uc});
    add_tri(out, {a, n, ua}, {c, n, uc}, {d, n, ud});
}

/// One cushion: its nose line from one pocket's jaw round to the next pocket's jaw.
struct CushionOutline {
    std::vector<glm::vec2> nose;    ///< points of the nose line at nose height
    std::vector<glm::vec2> normal;  ///< outward (toward the balls) at each point
    glm::vec2 rail_normal;          ///< the rail face's normal (toward the balls)
    glm::vec2 rail_point;           ///< a point on the rail face
};

const physics::CushionLine* nearest_facing(const physics::Table& t, physics::Vec2 p) {
    const physics::CushionLine* best = nullptr;
    double best_d = std::numeric_limits<double>::max();
    for (const auto& l : t.lines) {
        if (l.pocket < 0) continue;
        double d = physics::norm(l.a - p);
        if (d < best_d) best_d = d, best = &l;
    }
    return best_d < 0.05 ? best : nullptr;
}

const physics::JawNose* nearest_nose(const physics::Table& t, physics::Vec2 p) {
    const physics::JawNose* best = nullptr;
    double best_d = std::numeric_limits<double>::max();
    for (const auto& n : t.noses) {
        double d = physics::norm(n.centre - p);
        if (d < best_d) best_d = d, best = &n;
    }
    return best && best_d < best->radius * 1.01 + 1e-6 ? best : nullptr;
}

/// Points of the nose arc from p to q around c (the short way).
void add_arc(CushionOutline& o, glm::vec2 c, glm::vec2 p, glm::vec2 q, int steps) {
    float a0 = std::atan2(p.y - c.y, p.x - c.x);
    float a1 = std::atan2(q.y - c.y, q.x - c.x);
    float da = a1 - a0;
    while (da > 3.14159265f) da -= 6.2831853f;
    while (da < -3.14159265f) da += 6.2831853f;
    const float r = glm::length(p - c);
    for (int i = 1; i < steps; ++i) {
        float a = a0 + da * static_cast<float>(i) / static_cast<float>(steps);
        glm::vec2 dir{std::cos(a), std::sin(a)};
        o.nose.push_back(c + r * dir);
        o.normal.push_back(dir);
    }
}

CushionOutline outline_of(const physics::Table& t, const physics::CushionLine& rail) {
    CushionOutline o;
    o.rail_normal = v2(rail.normal);
    o.rail_point = v2(rail.a);
    const physics::CushionLine* fa = nearest_facing(t, rail.a);
    const physics::CushionLine* fb = nearest_facing(t, rail.b);
    const physics::JawNose* na = nearest_nose(t, rail.a);
    const physics::JawNose* nb = nearest_nose(t, rail.b);
    if (fa) {
        o.nose.push_back(v2(fa->b));
        o.normal.push_back(v2(fa->normal));
        o.nose.push_back(v2(fa->a));
        o.normal.push_back(v2(fa->normal));
        if (na) add_arc(o, v2(na->centre), v2(fa->a), v2(rail.a), 5);
    }
    o.nose.push_back(v2(rail.a));
    o.normal.push_back(v2(rail.normal));
    o.nose.push_back(v2(rail.b));
    o.normal.push_back(v2(rail.normal));
    if (fb) {
        if (nb) add_arc(o, v2(nb->centre), v2(rail.b), v2(fb->a), 5);
        o.nose.push_back(v2(fb->a));
        o.normal.push_back(v2(fb->normal));
        o.nose.push_back(v2(fb->b));
        o.normal.push_back(v2(fb->normal));
    }
    return o;
}

void add_cushion(std::vector<Vertex>& out, const CushionOutline& o, const TableDims& d) {
    const std::size_t n = o.nose.size();
    // Rows of the profile, from the cloth under the nose up over the top to the rail.
    struct Row {
        float back;
        float z;
    };  // back: distance behind the nose point; z: height
    const Row rows[] = {
        {0.012f, 0.0f}, {0.0f, d.cushion_height}, {0.006f, d.cushion_height + 0.0045f}};
    auto at = [&](std::size_t i, const Row& r) {
        return glm::vec3(o.nose[i] - r.back * o.normal[i], r.z);
    };
    // The back of the cushion: the nose point pushed straight back to cushion_width behind the rail
    // face.
    auto back = [&](std::size_t i) {
        float depth = glm::dot(o.rail_point - o.nose[i], o.rail_normal);
        return glm::vec3(o.nose[i] - (d.cushion_width - depth) * o.rail_normal, d.rail_height);
    };
    float along = 0.0f;
    for (std::size_t i = 0; i + 1 < n; ++i) {
        float next = along + glm::length(o.nose[i + 1] - o.nose[i]);
        for (std::size_t r = 0; r + 1 < std::size(rows); ++r)
            add_quad(out, at(i, rows[r]), at(i + 1, rows[r]), at(i + 1, rows[r + 1]),
                     at(i, rows[r + 1]), {along, 0.01f * float(r)}, {next, 0.01f * float(r)},
                     {next, 0.01f * float(r + 1)}, {along, 0.01f * float(r + 1)});
        const Row& top = rows[std::size(rows) - 1];
        add_quad(out, at(i, top), at(i + 1, top), back(i + 1), back(i), {along, 0.03f},
                 {next, 0.03f}, {next, 0.08f}, {along, 0.08f});
        along = next;
    }
    // The cut ends behind the jaw facings.
    for (std::size_t i : {std::size_t{0}, n - 1}) {
        glm::vec3 b = back(i);
        glm::vec3 f0 = at(i, rows[0]), f1 = at(i, rows[1]), f2 = at(i, rows[2]);
        glm::vec3 b0{b.x, b.y, 0.0f};
        if (i == 0) {
            add_quad(out, b0, f0, f1, b, {0, 0}, {0.05f, 0}, {0.05f, 0.04f}, {0, 0.04f});
            add_tri(out, {b, glm::normalize(glm::cross(f1 - b, f2 - b)), {0, 0.04f}},
                    {f1, glm::normalize(glm::cross(f1 - b, f2 - b)), {0.05f, 0.04f}},
                    {f2, glm::normalize(glm::cross(f1 - b, f2 - b)), {0.05f, 0.05f}});
        } else {
            add_quad(out, f0, b0, b, f1, {0.05f, 0}, {0, 0}, {0, 0.04f}, {0.05f, 0.04f});
            add_tri(out, {f1, glm::normalize(glm::cross(b - f1, f2 - f1)), {0.05f, 0.04f}},
                    {b, glm::normalize(glm::cross(b - f1, f2 - f1)), {0, 0.04f}},
                    {f2, glm::normalize(glm::cross(b - f1, f2 - f1)), {0.05f, 0.05f}});
        }
    }
}

}  // namespace

TableDims table_dims(const physics::Table& table) {
    TableDims d;
    d.cushion_height = static_cast<float>(table.spec.cushion_height);
    d.rail_height = d.cushion_height + 0.008f;
    return d;
}

float tray_length(double ball_radius) {
    return 15.0f * (2.0f * static_cast<float>(ball_radius) + 0.002f) + 0.01f;
}

glm::vec3 tray_slot(const physics::Table& table, double ball_radius, int k) {
    const TableDims d = table_dims(table);
    const float R = static_cast<float>(ball_radius);
    const float x0 =
        static_cast<float>(table.length()) / 2 - tray_length(ball_radius) / 2 + 0.005f + R + 0.001f;
    const float y = -(d.cushion_width + d.rail_width) - d.tray_wall - d.tray_width / 2;
    return {x0 + static_cast<float>(k) * (2 * R + 0.002f), y, d.tray_floor + R};
}

std::vector<PocketHole> pocket_holes(const physics::Table& table) {
    std::vector<PocketHole> holes;
    for (const auto& p : table.pockets) {
        const float mouth = static_cast<float>(physics::norm(p.mouth_b - p.mouth_a));
        const float r = 0.5f * mouth * (p.id == 1 || p.id == 4 ? 0.98f : 1.06f);
        holes.push_back({v2(p.drop_point) + r * v2(p.inward), r});
    }
    return holes;
}

TableMesh build_table_mesh(const physics::Table& table) {
    TableMesh m;
    const TableDims d = table_dims(table);
    const float L = static_cast<float>(table.length()), W = static_cast<float>(table.width());
    const float in = d.cushion_width, out = d.cushion_width + d.rail_width;
    // Cloth: the whole footprint (holes are painted by the cloth shader).
    add_quad(m.cloth, {-out, -out, 0}, {L + out, -out, 0}, {L + out, W + out, 0},
             {-out, W + out, 0}, {-out, -out}, {L + out, -out}, {L + out, W + out},
             {-out, W + out});
    for (const auto& l : table.lines)
        if (l.rail >= 0) add_cushion(m.cushions, outline_of(table, l), d);

    // Wooden rails: four trapezoids at rail height, a rounded outer edge, and the sides.
    const float h = d.rail_height, bevel = 0.012f;
    const glm::vec2 inner[4] = {{-in, -in}, {L + in, -in}, {L + in, W + in}, {-in, W + in}};
    const glm::vec2 outer[4] = {{-out, -out}, {L + out, -out}, {L + out, W + out}, {-out, W + out}};
    const glm::vec2 dirs[4] = {{0, -1}, {1, 0}, {0, 1}, {-1, 0}};  // outward of each side
    for (int s = 0; s < 4; ++s) {
        const int e = (s + 1) % 4;
        const glm::vec2 o = dirs[s];
        const glm::vec2 along = glm::normalize(outer[e] - outer[s]);
        auto uv = [&](glm::vec2 p, float across) { return glm::vec2(glm::dot(p, along), across); };
        const glm::vec2 os = outer[s] - bevel * (o + glm::vec2(-o.y, o.x) * 0.0f);
        (void)os;
        // Pull the outer edge in by the bevel along both sides' outward directions.
        const glm::vec2 ds = dirs[(s + 3) % 4], de = dirs[e];
        const glm::vec2 b_s = outer[s] - bevel * (o + ds), b_e = outer[e] - bevel * (o + de);
        add_quad(m.rails, {inner[s], h}, {inner[e], h}, {b_e, h}, {b_s, h}, uv(inner[s], 0.0f),
                 uv(inner[e], 0.0f), uv(b_e, d.rail_width - bevel), uv(b_s, d.rail_width - bevel));
        const float hb = h - 0.7f * bevel;
        const glm::vec2 m_s = outer[s] - 0.3f * bevel * (o + ds),
                        m_e = outer[e] - 0.3f * bevel * (o + de);
        add_quad(m.rails, {b_s, h}, {b_e, h}, {m_e, hb}, {m_s, hb}, uv(b_s, 0.13f), uv(b_e, 0.13f),
                 uv(m_e, 0.137f), uv(m_s, 0.137f));
        add_quad(m.rails, {m_s, hb}, {m_e, hb}, {outer[e], h - bevel}, {outer[s], h - bevel},
                 uv(m_s, 0.137f), uv(m_e, 0.137f), uv(outer[e], 0.142f), uv(outer[s], 0.142f));
        add_quad(m.rails, {outer[s], h - bevel}, {outer[e], h - bevel}, {outer[e], -d.apron_depth},
                 {outer[s], -d.apron_depth}, uv(outer[s], 0.15f), uv(outer[e], 0.15f),
                 uv(outer[e], 0.15f + d.apron_depth), uv(outer[s], 0.15f + d.apron_depth));
    }
    return m;
}

}  // namespace render
