#include "app/cue_clearance.hpp"

#include <algorithm>
#include <numbers>

#include "render/cue_stick.hpp"

namespace app {

double rail_forced_elevation_deg(const physics::Table& table, double ball_radius,
                                 physics::Vec2 cue_ball, const physics::Stroke& stroke) {
    constexpr double deg = 180.0 / std::numbers::pi;
    const float forced = render::rail_forced_elevation(
        table, static_cast<float>(ball_radius),
        {static_cast<float>(cue_ball.x), static_cast<float>(cue_ball.y)},
        static_cast<float>(stroke.heading_deg * std::numbers::pi / 180.0),
        {static_cast<float>(stroke.side), static_cast<float>(stroke.top)});
    return static_cast<double>(forced) * deg;
}

physics::Stroke over_the_rail(const physics::Table& table, double ball_radius,
                              physics::Vec2 cue_ball, physics::Stroke stroke) {
    stroke.elevation_deg = std::max(
        stroke.elevation_deg, rail_forced_elevation_deg(table, ball_radius, cue_ball, stroke));
    return stroke;
}

}  // namespace app
