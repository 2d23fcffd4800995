// What one frame shows of the game, built from the controller (read only): the balls with
// their orientations, the cue along the aim, the aim guide. Holds the storage that
// render::FrameView's spans point into.
#pragma once

#include <optional>
#include <vector>

#include "app/controller.hpp"
#include "app/settings.hpp"
#include "render/renderer.hpp"

namespace app {

struct SceneFrame {
    std::vector<render::BallView> balls;
    std::optional<render::CueView> cue;
    render::AimView aim;
    bool show_aim = false;
    std::vector<int> tray;  ///< pocketed object balls, in order
    std::optional<render::BallInHandView> ball_in_hand;

    /// The view for the renderer; valid while this SceneFrame lives unchanged.
    render::FrameView view(const render::Camera& camera) const;
};

/// The guide at the level `aim_guide`, and the call's marks whatever the level.
/// `dragged_to`: where the player is dragging the cue ball in hand (shown red when it may
/// not go there), else empty.
SceneFrame build_scene(const Controller& controller, AimGuide aim_guide,
                       std::optional<physics::Vec2> dragged_to = std::nullopt);

}  // namespace app
