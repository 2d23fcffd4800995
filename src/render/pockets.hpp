// The pockets below the cloth: a leather liner round each hole (up to the rail top where the
// hole cuts the cushion and rail) and a net bag under it; and where a ball dropping into a
// pocket is drawn. Frame: the table frame, cloth at z = 0 (unit: m).
#pragma once

#include <glm/glm.hpp>
#include <vector>

#include "physics/table.hpp"
#include "render/solid_mesh.hpp"

namespace render {

constexpr float kLinerDepth = 0.085f;  ///< the liner's bottom below the cloth (unit: m)
constexpr float kNetDepth = 0.20f;     ///< the net's bottom below the cloth (unit: m)

/// The liners and nets of all the pockets.
std::vector<SolidVertex> pocket_mesh(const physics::Table& table);

/// How long a pocketed ball is drawn dropping before it joins the tray (unit: s).
constexpr double kDropSeconds = 0.6;

/// The centre of a ball `seconds` after it crossed the drop line at `from` (xy): it slides to the
/// nearest hole's centre and falls under gravity until it lies in the net.
glm::vec3 dropping_ball_centre(const physics::Table& table, float ball_radius, glm::vec2 from,
                               float seconds);

}  // namespace render
