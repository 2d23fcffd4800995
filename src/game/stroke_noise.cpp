#include "game/stroke_noise.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "game/session.hpp"

namespace game {

double standard_normal(physics::SplitMix64& rng) {
    const double u1 = 1.0 - rng.uniform();  // (0, 1]: log is finite
    const double u2 = rng.uniform();
    return std::sqrt(-2.0 * std::log(u1)) * std::cos(2.0 * std::numbers::pi * u2);
}

physics::Stroke with_noise(const physics::Stroke& stroke, double scale, physics::SplitMix64& rng,
                           const StrokeNoise& sigma) {
    if (scale == 0.0) return stroke;
    physics::Stroke s = stroke;
    s.heading_deg += scale * sigma.heading_deg * standard_normal(rng);
    s.elevation_deg += scale * sigma.elevation_deg * standard_normal(rng);
    s.speed += scale * sigma.speed * standard_normal(rng);
    s.side += scale * sigma.offset * standard_normal(rng);
    s.top += scale * sigma.offset * standard_normal(rng);
    s.elevation_deg = std::clamp(s.elevation_deg, 0.0, 90.0);
    s.speed = std::clamp(s.speed, 0.0, max_stroke_speed);
    s.side = std::clamp(s.side, -1.0, 1.0);
    s.top = std::clamp(s.top, -1.0, 1.0);
    return s;
}

}  // namespace game
