// The rolling of the balls on the cloth: for each ball of a shot at a playback time, how loud
// its rumble is (following its speed, silent once it stops or drops), at what pitch,
// and where. Pure: the engine turns these into the gains of looping sources.
#pragma once

#include <vector>

#include "physics/shot.hpp"
#include "physics/vec.hpp"

namespace audio {

struct RollOptions {
    bool enabled = true;
    double full = 2.5;           ///< ball speed heard at full loudness (unit: m/s)
    double min_speed = 0.005;    ///< slower balls are silent (unit: m/s)
    double sliding = 1.25;       ///< a sliding ball scrubs the cloth: this much louder
    double pitch_low = 0.85;     ///< pitch of a ball about to stop
    double pitch_per_mps = 0.1;  ///< pitch rises this much per m/s (clamped at 1.3)
};

/// One ball's rumble at a moment.
struct Roll {
    int ball = 0;
    float gain = 0.0f;  ///< linear, 0–1 (0: silent)
    float pitch = 1.0f;
    physics::Vec3 position;  ///< the ball's centre, table frame (unit: m)
};

/// Every ball of `shot` at playback time `t` (unit: s from the strike), in the shot's order.
/// Gain is proportional to the ball's speed on the cloth (amplitude ∝ speed, like the impacts).
std::vector<Roll> rolling_at(const physics::Shot& shot, double t, const RollOptions& options = {});

}  // namespace audio
