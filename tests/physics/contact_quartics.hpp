// Random two-ball contact quartics for the root-solver tests: |Δp + Δv t + ½Δa t²|² − D², the
// balls up to 2 m apart, 0.01–12 m/s, either sliding (2 m/s², along a random slip direction)
// or rolling (0.1 m/s², against the velocity), aimed roughly at each other so that about half
// collide; optionally every n-th aimed to pass at D·(1 − g), g from 1e-3 to 1e-9: a grazing,
// near-double root. Deterministic on every platform (SplitMix64, not <random>).
#pragma once

#include <cmath>
#include <cstdint>

#include "physics/internal/roots.hpp"

namespace physics::roots::test {

/// SplitMix64 (Steele, Lea, Flood 2014).
struct SplitMix64 {
    std::uint64_t state;
    double uniform(double lo, double hi) {
        std::uint64_t z = (state += 0x9E3779B97F4A7C15ull);
        z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
        z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
        z ^= z >> 31;
        return lo + (hi - lo) * static_cast<double>(z >> 11) * 0x1.0p-53;
    }
};

inline constexpr double kDiameter = 2 * 0.028575;  // (unit: m)

struct ContactQuartic {
    Poly4 c;
    double hi;  ///< the horizon: when the ball stops (unit: s)
};

/// Case `k` of a run: the balls at least `min_dist` apart; with `graze_every` > 0, case k is
/// grazing where k is a multiple of it.
inline ContactQuartic random_contact_quartic(SplitMix64& rng, int k, double min_dist,
                                             int graze_every = 0) {
    const double dist = rng.uniform(min_dist, 2.0), bearing = rng.uniform(0, 6.2832);
    const double px = dist * std::cos(bearing), py = dist * std::sin(bearing);
    const double speed = rng.uniform(0.01, 12.0);
    double heading = bearing + rng.uniform(-0.1, 0.1) + (k % 2 ? 3.1416 : 0.0);
    if (graze_every > 0 && k % graze_every == 0) {
        const double g = std::pow(10.0, -rng.uniform(3.0, 9.0));
        heading = bearing + 3.14159265358979 + std::asin(kDiameter * (1 - g) / dist);
    }
    const double vx = -speed * std::cos(heading), vy = -speed * std::sin(heading);
    const bool sliding = k % 3 != 0;
    const double decel = sliding ? 2.0 : 0.1;
    const double slip = sliding ? heading + rng.uniform(-1.0, 1.0) : heading;
    const double ax = decel * std::cos(slip), ay = decel * std::sin(slip);
    return {{px * px + py * py - kDiameter * kDiameter, 2.0 * (px * vx + py * vy),
             vx * vx + vy * vy + px * ax + py * ay, vx * ax + vy * ay, 0.25 * (ax * ax + ay * ay)},
            speed / decel};
}

}  // namespace physics::roots::test
