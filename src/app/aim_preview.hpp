// What the aim guide shows and what the game proposes to call, from the physics engine: the
// stroke as aimed is simulated (without execution noise) on a copy of the table, and the guide
// is read off the exact shot: the cue ball's path to its first contact, the ghost ball there,
// the object ball's path to its next collision or pocket, and the cue ball's path after it.
#pragma once

#include <optional>
#include <span>

#include "physics/ball_state.hpp"
#include "physics/params.hpp"
#include "physics/stroke.hpp"
#include "physics/table.hpp"
#include "render/renderer.hpp"

namespace app {

struct AimPreview {
    render::AimView view;
    std::optional<int> first_ball;  ///< the first object ball the cue ball would touch
    /// The pocket that ball heads to: where it drops in the simulation, else the pocket most
    /// nearly in its direction of travel after the contact. physics::PocketId.
    std::optional<int> pocket;
    bool pots = false;  ///< the first ball drops (in `pocket`) if struck exactly as aimed
};

/// Simulates `stroke` on `balls` (the cue ball, id 0, at rest among them) and reads the guide.
AimPreview preview_aim(const physics::Table& table, const physics::Params& params,
                       std::span<const physics::BallState> balls, const physics::Stroke& stroke);

}  // namespace app
