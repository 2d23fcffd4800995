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

/// A pocketless table's cushions meet at the corners: each corner square behind both noses is
/// closed by the two cushions' tops, sloping from the nose up to the rail.
void add_cushion_corners(std::vector<Vertex>& out, float L, float W, const TableDims& d) {
    const float w = d.cushion_width, nose = d.cushion_height + 0.0045f, back = d.rail_height;
    const glm::vec2 corners[4] = {{0, 0}, {L, 0}, {L, W}, {0, W}};
    const glm::vec2 outward[4] = {{-1, -1}, {1, -1}, {1, 1}, {-1, 1}};
    for (int k = 0; k < 4; ++k) {
        const glm::vec2 c = corners[k], o = outward[k];
        const glm::vec3 a{c, nose}, bx{c.x + w * o.x, c.y, back}, by{c.x, c.y + w * o.y, back},
            far{c.x + w * o.x, c.y + w * o.y, back};
        // Counter-clockwise seen from above, so the face points up.
        if (o.x * o.y > 0)
            add_quad(out, a, bx, far, by, {0, 0.03f}, {0.05f, 0.08f}, {0.05f, 0.08f}, {0, 0.08f});
        else
            add_quad(out, a, by, far, bx, {0, 0.03f}, {0.05f, 0.08f}, {0.05f, 0.08f}, {0, 0.08f});
    }
}

/// A flat, upward quad on the cloth from lo to hi (texture coordinates = position).
void add_flat(std::vector<Vertex>& out, glm::vec2 lo, glm::vec2 hi) {
    add_quad(out, {lo, 0.0f}, {hi.x, lo.y, 0.0f}, {hi, 0.0f}, {lo.x, hi.y, 0.0f}, lo, {hi.x, lo.y},
             hi, {lo.x, hi.y});
}

/// The cloth over [lo, hi] less the holes: round each hole a square tile, triangulated as a
/// ring from the hole's circle out to the square; the rest in rectangles between the tiles.
void add_cloth(std::vector<Vertex>& out, glm::vec2 lo, glm::vec2 hi,
               const std::vector<PocketHole>& holes) {
    std::vector<glm::vec4> tiles;  // x0, y0, x1, y1
    for (const PocketHole& h : holes) {
        const float half = h.radius + 0.02f;
        tiles.push_back({glm::max(h.centre - half, lo), glm::min(h.centre + half, hi)});
    }
    std::vector<float> xs = {lo.x, hi.x}, ys = {lo.y, hi.y};
    for (const glm::vec4& t : tiles) {
        xs.insert(xs.end(), {t.x, t.z});
        ys.insert(ys.end(), {t.y, t.w});
    }
    std::sort(xs.begin(), xs.end());
    std::sort(ys.begin(), ys.end());
    for (std::size_t i = 0; i + 1 < xs.size(); ++i)
        for (std::size_t j = 0; j + 1 < ys.size(); ++j) {
            const glm::vec2 a{xs[i], ys[j]}, b{xs[i + 1], ys[j + 1]};
            if (b.x - a.x < 1e-6f || b.y - a.y < 1e-6f) continue;
            const glm::vec2 mid = 0.5f * (a + b);
            const bool in_tile = std::any_of(tiles.begin(), tiles.end(), [&](const glm::vec4& t) {
                return mid.x > t.x && mid.x < t.z && mid.y > t.y && mid.y < t.w;
            });
            if (!in_tile) add_flat(out, a, b);
        }
    const glm::vec3 up{0, 0, 1};
    const int steps = 48;
    for (std::size_t k = 0; k < holes.size(); ++k) {
        const glm::vec4 t = tiles[k];
        const glm::vec2 c = holes[k].centre;
        // The point of the tile's edge in direction d from the centre.
        const auto on_square = [&](glm::vec2 d) {
            float s = 1e9f;
            if (d.x > 1e-6f) s = std::min(s, (t.z - c.x) / d.x);
            if (d.x < -1e-6f) s = std::min(s, (t.x - c.x) / d.x);
            if (d.y > 1e-6f) s = std::min(s, (t.w - c.y) / d.y);
            if (d.y < -1e-6f) s = std::min(s, (t.y - c.y) / d.y);
            return c + s * d;
        };
        for (int i = 0; i < steps; ++i) {
            const float a0 = 6.2831853f * static_cast<float>(i) / steps;
            const float a1 = 6.2831853f * static_cast<float>(i + 1) / steps;
            const glm::vec2 d0{std::cos(a0), std::sin(a0)}, d1{std::cos(a1), std::sin(a1)};
            const glm::vec2 p0 = c + holes[k].radius * d0, p1 = c + holes[k].radius * d1;
            // A corner of the square between the two directions keeps the ring's outer edge on
            // the square.
            std::vector<glm::vec2> rim = {on_square(d0)};
            for (const glm::vec2 corner : {glm::vec2(t.x, t.y), glm::vec2(t.z, t.y),
                                           glm::vec2(t.z, t.w), glm::vec2(t.x, t.w)}) {
                const glm::vec2 e = corner - c;
                const float ang = std::atan2(e.y, e.x) < 0.0f ? std::atan2(e.y, e.x) + 6.2831853f
                                                              : std::atan2(e.y, e.x);
                if (ang > a0 && ang < a1) rim.push_back(corner);
            }
            rim.push_back(on_square(d1));
            // A fan from p0 over the rim, then back to p1.
            for (std::size_t r = 0; r + 1 < rim.size(); ++r)
                add_tri(out, {{p0, 0.0f}, up, p0}, {{rim[r], 0.0f}, up, rim[r]},
                        {{rim[r + 1], 0.0f}, up, rim[r + 1]});
            add_tri(out, {{p0, 0.0f}, up, p0}, {{rim.back(), 0.0f}, up, rim.back()},
                    {{p1, 0.0f}, up, p1});
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
    // Cloth: the whole footprint, with the pockets' holes cut out.
    add_cloth(m.cloth, {-out, -out}, {L + out, W + out}, pocket_holes(table));
    for (const auto& l : table.lines)
        if (l.rail >= 0) add_cushion(m.cushions, outline_of(table, l), d);
    if (table.pockets.empty()) add_cushion_corners(m.cushions, L, W, d);

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
