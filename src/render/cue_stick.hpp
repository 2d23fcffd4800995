// The cue stick: where it lies (its tip on the cue ball at the chosen spin offset, its butt
// raised over the rail when the rail forces it) and its parts (tip, ferrule, shaft, joint,
// forearm with inlays, wrap, butt sleeve, bumper). Pure geometry, no GL. Frame: the table
// frame, cloth at z = 0 (unit: m).
#pragma once

#include <glm/glm.hpp>
#include <vector>

#include "physics/table.hpp"
#include "render/solid_mesh.hpp"

namespace render {

constexpr float kCueLength = 1.47f;  ///< (unit: m), a 58-inch cue

/// The cue's radius at `s` metres from the tip (unit: m).
float cue_radius(float s);

/// The cue's axis: its tip's centre and the direction toward the ball (unit vector, pointing
/// down by the elevation).
struct CueAxis {
    glm::vec3 tip{0.0f}, dir{1.0f, 0.0f, 0.0f};
};

/// The cue laid on the ball: its axis through the point `tip_offset` (side right of centre,
/// top above it, as the shooter sees it; unit: R) of the cue ball's face, `pull_back` behind
/// the contact point on the ball's surface.
CueAxis cue_axis(glm::vec2 cue_ball, float ball_radius, float heading, float elevation,
                 glm::vec2 tip_offset, float pull_back);

/// The least elevation (unit: rad, at most 60 degrees) at which the cue, its tip on the cue
/// ball at `tip_offset`, passes over the cushion and the rail behind the ball with 2 mm to
/// spare, drawn back by up to 0.25 m: 0 when the rail is far enough. A cue ball close to a rail
/// forces the butt up; so does the far rail under a long cue from mid-table (about 1.4 degrees).
float rail_forced_elevation(const physics::Table& table, float ball_radius, glm::vec2 cue_ball,
                            float heading, glm::vec2 tip_offset = {0.0f, 0.0f});

/// The elevation the cue is drawn (and must be struck) at: the chosen one, or the rail's if
/// that is higher.
float drawn_cue_elevation(const physics::Table& table, float ball_radius, glm::vec2 cue_ball,
                          float heading, float chosen, glm::vec2 tip_offset = {0.0f, 0.0f});

/// Where the cue's shadow is drawn on the cloth (x0, y0, x1, y1; unit: m): the cue's footprint
/// widened by how far the lamps throw the shadow of its highest point, cut to the cloth and the
/// cushions, so that it never falls beyond the table. Empty (x0 >= x1) when off the table.
glm::vec4 cue_shadow_rect(const physics::Table& table, const CueAxis& axis);

/// The cue's triangles along `axis`, from the tip back.
std::vector<SolidVertex> cue_mesh(const CueAxis& axis);

}  // namespace render
