// What the aim guide shows and what the game proposes to call, from the physics engine: the
// stroke as aimed is simulated (without execution noise) on a copy of the table, and the guide
// is read off the exact shot: the cue ball's path to its first contact, the ghost ball there,
// the object ball's path to its next collision or pocket, and the cue ball's path after it.
#pragma once

#include <optional>
#include <span>
#include <vector>

#include "physics/ball_state.hpp"
#include "physics/event.hpp"
#include "physics/params.hpp"
#include "physics/stroke.hpp"
#include "physics/table.hpp"
#include "render/renderer.hpp"

namespace app {

/// Where the object ball's drawn path ends.
enum class PathEnd {
    none,    ///< it stops (or the guide's time runs out) on the cloth
    pocket,  ///< it drops
    jaw,     ///< it hits a pocket's jaw
    rail,    ///< it hits a cushion
    ball,    ///< it hits another ball
};

struct AimPreview {
    render::AimView view;           ///< the whole guide (the practice level)
    std::optional<int> first_ball;  ///< the first object ball the cue ball would touch
    /// The pocket that ball heads to: where it drops in the simulation, else the pocket whose
    /// mouth its direction after the contact points into; empty when it points at none.
    /// physics::PocketId.
    std::optional<int> pocket;
    bool pots = false;  ///< the first ball drops (in `pocket`) if struck exactly as aimed
    PathEnd object_end = PathEnd::none;
    /// Unit vectors: the object ball's direction just after the contact, the cue ball's just
    /// before it.
    glm::vec2 object_dir{0.0f}, cue_dir{0.0f};
    glm::vec2 object_at{0.0f};  ///< the object ball's centre at the contact (unit: m)
    /// The simulated shot's events, for the rules (is the shot as aimed a foul?).
    std::vector<physics::Event> events;
};

/// Simulates `stroke` on `balls` (the cue ball, id 0, at rest among them) and reads the guide.
AimPreview preview_aim(const physics::Table& table, const physics::Params& params,
                       std::span<const physics::BallState> balls, const physics::Stroke& stroke);

}  // namespace app
