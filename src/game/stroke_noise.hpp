// Execution noise: no player strikes exactly the stroke he means. Gaussian errors on each
// component of the stroke, from a seeded stream (so a noisy match replays exactly).
#pragma once

#include "physics/rack.hpp"
#include "physics/stroke.hpp"

namespace game {

/// The standard deviations at noise scale 1.
struct StrokeNoise {
    double heading_deg = 0.125;  ///< (unit: deg)
    double elevation_deg = 0.1;  ///< (unit: deg)
    double speed = 0.075;        ///< (unit: m/s)
    double offset = 0.0175;      ///< side and top (unit: fraction of R; 0.5 mm on a 2 1/4 in ball)
};

/// A standard normal deviate (Box–Muller on SplitMix64; deterministic for a given build).
double standard_normal(physics::SplitMix64& rng);

/// The stroke as executed: each component plus a Gaussian error of σ × `scale`, then kept
/// within what a stroke can be (speed 0–20 m/s, offsets within ±1 R, elevation 0–90°).
/// `scale` 0 returns the stroke unchanged (and draws nothing).
physics::Stroke with_noise(const physics::Stroke& stroke, double scale, physics::SplitMix64& rng,
                           const StrokeNoise& sigma = {});

}  // namespace game
