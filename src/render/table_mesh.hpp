// The table's triangles, built from the physics geometry so that what you see is what the
// balls hit: cushion noses on the physics cushion lines at the physics nose height, jaw
// facings and rounded noses where the physics has them, the pocket holes behind the drop
// lines. Frame: the table frame, cloth at z = 0 (unit: m).
#pragma once

#include <glm/glm.hpp>
#include <vector>

#include "physics/table.hpp"

namespace render {

/// Sizes of the parts the physics does not define (unit: m).
struct TableDims {
    float cushion_height = 0.0363f;  ///< nose height, from the physics spec (unit: m)
    float cushion_width = 0.050f;    ///< nose to the back of the cushion (unit: m)
    float rail_width = 0.140f;       ///< wooden rail top, beyond the cushion (unit: m)
    float rail_height = 0.044f;      ///< rail top above the cloth (unit: m)
    float apron_depth =
        0.30f;  ///< how far the table's wooden sides reach below the cloth (unit: m)
    /// The ball-return tray along the south side, against the apron (y < 0): inner width, floor
    /// height (below the cloth), wall thickness (unit: m).
    float tray_width = 0.064f;
    float tray_floor = -0.045f;
    float tray_wall = 0.008f;
};

/// The tray's length along x (unit: m): room for 15 balls in a row, centred on the table.
float tray_length(double ball_radius);
/// Centre of the k-th ball (k from 0) in the tray (unit: m).
glm::vec3 tray_slot(const physics::Table& table, double ball_radius, int k);
TableDims table_dims(const physics::Table& table);

/// A pocket hole as drawn: a disc whose near edge lies on the physics drop line.
struct PocketHole {
    glm::vec2 centre;  ///< (unit: m)
    float radius;      ///< (unit: m)
};
std::vector<PocketHole> pocket_holes(const physics::Table& table);

struct Vertex {
    glm::vec3 pos;  ///< (unit: m)
    glm::vec3 normal;
    glm::vec2 uv;  ///< texture coordinates (unit: m along the surface)
};

/// Triangle lists, one per material.
struct TableMesh {
    std::vector<Vertex> cloth;     ///< the slate's cloth, the whole table's footprint at z = 0
    std::vector<Vertex> cushions;  ///< cloth-covered rubber: noses, tops, jaw facings
    std::vector<Vertex> rails;     ///< wooden rail tops and the table's sides
};
TableMesh build_table_mesh(const physics::Table& table);

}  // namespace render
