// Solid geometry with a colour per vertex: the cue stick, the aim guide, the tray, the room.
// Builders append triangles to a list (unit: m, table frame).
#pragma once

#include <glm/glm.hpp>
#include <vector>

namespace render {

/// Vertex of the solid program (position, normal, sRGB colour).
struct SolidVertex {
    glm::vec3 pos, normal, colour;
};

/// A tapered cylinder from a (radius ra) to b (radius rb), colour per end.
void add_lathe(std::vector<SolidVertex>& out, glm::vec3 a, glm::vec3 b, float ra, float rb,
               glm::vec3 ca, glm::vec3 cb, int sides);
/// A tapered cylinder like add_lathe, in `sectors` equal sectors round the axis, each of colour
/// `base` with its middle `share` (0 to 1) of colour `inlay`.
void add_sectors(std::vector<SolidVertex>& out, glm::vec3 a, glm::vec3 b, float ra, float rb,
                 glm::vec3 base, glm::vec3 inlay, int sectors, float share);
/// A flat ribbon on the cloth along a polyline (the aim guide).
void add_ribbon(std::vector<SolidVertex>& out, const std::vector<glm::vec2>& line, float half_width,
                float z, glm::vec3 colour);
/// A box-shaped slab from `lo` to `hi` (axis-aligned), all six faces.
void add_box(std::vector<SolidVertex>& out, glm::vec3 lo, glm::vec3 hi, glm::vec3 colour);
/// A flat quad on the cloth (z) from `lo` to `hi`.
void add_patch(std::vector<SolidVertex>& out, glm::vec2 lo, glm::vec2 hi, float z,
               glm::vec3 colour);
/// A flat half disc on the cloth (z): centre, radius, from angle a0 to a1 (unit: rad).
void add_half_disc(std::vector<SolidVertex>& out, glm::vec2 centre, float radius, float a0,
                   float a1, float z, glm::vec3 colour);
/// A ring on the cloth (z) round `centre`.
void add_ring(std::vector<SolidVertex>& out, glm::vec2 centre, float radius, float half_width,
              float z, glm::vec3 colour);

}  // namespace render
