// The room round the table: its size, and the triangles of the floor, the walls, the ceiling,
// the table's body and legs and the lamps' shades, generated at start-up. Frame: the table
// frame (cloth at z = 0, x along the table), lengths in m.
#pragma once

#include <glm/glm.hpp>
#include <vector>

#include "physics/table.hpp"
#include "render/solid_mesh.hpp"

namespace render {

/// The room's box and the table's stand (unit: m).
struct RoomDims {
    glm::vec2 lo{0.0f}, hi{0.0f};  ///< the walls' inner faces (x, y)
    float floor_z = -0.79f;        ///< the floor (the cloth is 0.79 m above it)
    float ceiling_z = 1.95f;       ///< the ceiling
    float body_depth = 0.30f;      ///< the table's body below the cloth (the apron)
    float leg_size = 0.14f;        ///< the legs' square section
};

/// A room with space for a full cue stroke (1.6 m) round the table on every side.
RoomDims room_dims(const physics::Table& table);

/// A lamp over the table: the centre of its shade's opening and the opening's radius (unit: m).
struct Lamp {
    glm::vec3 pos;
    float radius;
};
/// Three shaded lamps along the table's long axis, 1 m above the cloth.
std::vector<Lamp> table_lamps(const physics::Table& table);

/// The room's triangles, lit per vertex by the room program: floor, walls (panelled below),
/// ceiling, the table's underside and legs. Every face is wound counter-clockwise seen from the
/// side it faces (into the room; out of the legs), so with back faces culled a camera outside
/// the room or above the ceiling sees through them. Large faces are cut in cells of about
/// `cell` m so the light varies across them.
std::vector<SolidVertex> room_mesh(const physics::Table& table, float cell = 0.5f);
/// The lamps' shades, the bar they hang from and its rods to the ceiling (drawn only for an eye
/// below the shades: from above they would hide the table).
std::vector<SolidVertex> fixtures_mesh(const physics::Table& table);
/// The lamps' glowing openings (discs facing down), drawn unlit.
std::vector<SolidVertex> lamp_glow_mesh(const physics::Table& table);

}  // namespace render
