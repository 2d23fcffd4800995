#include "render/room.hpp"

#include <cmath>

#include "render/table_mesh.hpp"

namespace render {

RoomDims room_dims(const physics::Table& table) {
    const TableDims d = table_dims(table);
    const float out = d.cushion_width + d.rail_width;
    const float L = static_cast<float>(table.length()), W = static_cast<float>(table.width());
    const float space = 1.75f;  // a cue's length and the player's stance behind it
    RoomDims r;
    r.lo = {-out - space, -out - space};
    r.hi = {L + out + space, W + out + space};
    r.body_depth = d.apron_depth;
    return r;
}

namespace {

constexpr glm::vec3 kFloor{0.30f, 0.19f, 0.11f};   // oak planks (sRGB)
constexpr glm::vec3 kWall{0.36f, 0.30f, 0.22f};    // warm plaster
constexpr glm::vec3 kPanel{0.22f, 0.10f, 0.055f};  // mahogany wainscot
constexpr glm::vec3 kCeiling{0.20f, 0.19f, 0.17f};
constexpr glm::vec3 kTableWood{0.24f, 0.075f, 0.035f};  // the table's legs and body
constexpr glm::vec3 kShade{0.05f, 0.16f, 0.09f};        // the lamps' green enamel
constexpr glm::vec3 kBrass{0.55f, 0.42f, 0.20f};

/// A flat rectangle from corner `o` along `u` and `v` (its normal u x v), cut into cells.
void add_grid(std::vector<SolidVertex>& out, glm::vec3 o, glm::vec3 u, glm::vec3 v,
              glm::vec3 colour, float cell) {
    const int nu = std::max(1, static_cast<int>(std::ceil(glm::length(u) / cell)));
    const int nv = std::max(1, static_cast<int>(std::ceil(glm::length(v) / cell)));
    const glm::vec3 n = glm::normalize(glm::cross(u, v));
    for (int i = 0; i < nu; ++i)
        for (int j = 0; j < nv; ++j) {
            const auto at = [&](int a, int b) {
                return SolidVertex{o + u * (static_cast<float>(a) / static_cast<float>(nu)) +
                                       v * (static_cast<float>(b) / static_cast<float>(nv)),
                                   n, colour};
            };
            out.insert(out.end(), {at(i, j), at(i + 1, j), at(i + 1, j + 1), at(i, j),
                                   at(i + 1, j + 1), at(i, j + 1)});
        }
}

/// An axis-aligned box's four sides and bottom (not its top), cut into cells.
void add_post(std::vector<SolidVertex>& out, glm::vec3 lo, glm::vec3 hi, glm::vec3 colour,
              float cell) {
    const glm::vec3 dx{hi.x - lo.x, 0, 0}, dy{0, hi.y - lo.y, 0}, dz{0, 0, hi.z - lo.z};
    add_grid(out, lo, dx, dz, colour, cell);             // south
    add_grid(out, lo + dx, dy, dz, colour, cell);        // east
    add_grid(out, lo + dx + dy, -dx, dz, colour, cell);  // north
    add_grid(out, lo + dy, -dy, dz, colour, cell);       // west
    add_grid(out, lo + dy, dx, -dy, colour, cell);       // bottom
}

void add_lamp(std::vector<SolidVertex>& out, const Lamp& lamp) {
    const glm::vec3 top = lamp.pos + glm::vec3(0, 0, 0.17f);
    add_lathe(out, lamp.pos, top, lamp.radius, 0.05f, kShade, kShade, 32);
    add_lathe(out, top, top + glm::vec3(0, 0, 0.02f), 0.05f, 0.0f, kShade, kShade, 16);
    add_lathe(out, top, top + glm::vec3(0, 0, 0.06f), 0.012f, 0.012f, kBrass, kBrass, 8);
    // The shade's rolled rim.
    add_lathe(out, lamp.pos - glm::vec3(0, 0, 0.006f), lamp.pos, lamp.radius + 0.004f, lamp.radius,
              kBrass, kBrass, 32);
}

}  // namespace

std::vector<Lamp> table_lamps(const physics::Table& table) {
    const float L = static_cast<float>(table.length()), W = static_cast<float>(table.width());
    std::vector<Lamp> lamps;
    for (int i = 0; i < 3; ++i)
        lamps.push_back({{L * (0.5f + 0.3f * static_cast<float>(i - 1)), W / 2, 1.0f}, 0.16f});
    return lamps;
}

std::vector<SolidVertex> room_mesh(const physics::Table& table, float cell) {
    const RoomDims r = room_dims(table);
    const TableDims d = table_dims(table);
    const float L = static_cast<float>(table.length()), W = static_cast<float>(table.width());
    const float out_w = d.cushion_width + d.rail_width;
    std::vector<SolidVertex> m;
    const glm::vec3 lo{r.lo, r.floor_z}, size{r.hi - r.lo, r.ceiling_z - r.floor_z};
    const glm::vec3 ex{size.x, 0, 0}, ey{0, size.y, 0};
    add_grid(m, lo, ex, ey, kFloor, cell);                                     // floor
    add_grid(m, lo + glm::vec3(0, 0, size.z), ey, ex, kCeiling, 2.0f * cell);  // ceiling
    // The walls, each facing into the room: a panelled dado up to 1 m, plaster above.
    const float dado = 1.0f;
    const glm::vec3 corners[4] = {lo, lo + ex, lo + ex + ey, lo + ey};
    for (int k = 0; k < 4; ++k) {
        const glm::vec3 a = corners[k], b = corners[(k + 1) % 4];
        add_grid(m, b, a - b, {0, 0, dado}, kPanel, cell);
        add_grid(m, b + glm::vec3(0, 0, dado), a - b, {0, 0, size.z - dado}, kWall, cell);
    }
    // The table's underside below the apron, and six legs.
    const float under = -r.body_depth;
    add_grid(m, {-out_w, W + out_w, under}, {L + 2 * out_w, 0, 0}, {0, -(W + 2 * out_w), 0},
             kTableWood, 0.5f);
    const float s = r.leg_size, inset = 0.12f;
    for (float fx : {0.0f, 0.5f, 1.0f})
        for (float fy : {0.0f, 1.0f}) {
            const glm::vec2 c{-out_w + inset + fx * (L + 2 * out_w - 2 * inset),
                              -out_w + inset + fy * (W + 2 * out_w - 2 * inset)};
            add_post(m, {c - 0.5f * s, r.floor_z}, {c + 0.5f * s, under}, kTableWood, 0.2f);
        }
    return m;
}

std::vector<SolidVertex> fixtures_mesh(const physics::Table& table) {
    const RoomDims r = room_dims(table);
    std::vector<SolidVertex> m;
    const std::vector<Lamp> lamps = table_lamps(table);
    for (const Lamp& lamp : lamps) add_lamp(m, lamp);
    const float bar_z = lamps.front().pos.z + 0.23f;
    const glm::vec3 a = lamps.front().pos, b = lamps.back().pos;
    add_box(m, {a.x - 0.1f, a.y - 0.02f, bar_z}, {b.x + 0.1f, b.y + 0.02f, bar_z + 0.04f}, kShade);
    for (const Lamp& end : {lamps.front(), lamps.back()})
        add_lathe(m, {end.pos.x, end.pos.y, bar_z + 0.04f}, {end.pos.x, end.pos.y, r.ceiling_z},
                  0.006f, 0.006f, kBrass, kBrass, 8);
    return m;
}

std::vector<SolidVertex> lamp_glow_mesh(const physics::Table& table) {
    std::vector<SolidVertex> m;
    const glm::vec3 down{0, 0, -1}, glow{1.0f, 0.95f, 0.82f};
    for (const Lamp& lamp : table_lamps(table))
        for (int i = 0; i < 32; ++i) {
            const float a0 = 6.2831853f * static_cast<float>(i) / 32.0f;
            const float a1 = 6.2831853f * static_cast<float>(i + 1) / 32.0f;
            const glm::vec3 p0 = lamp.pos + lamp.radius * glm::vec3(std::cos(a0), std::sin(a0), 0);
            const glm::vec3 p1 = lamp.pos + lamp.radius * glm::vec3(std::cos(a1), std::sin(a1), 0);
            m.insert(m.end(), {{lamp.pos + glm::vec3(0, 0, 0.03f), down, glow},
                               {p0, down, glow},
                               {p1, down, glow}});
        }
    return m;
}

}  // namespace render
