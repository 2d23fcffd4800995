#include "ai/aim.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <optional>

#include "physics/simulate.hpp"

namespace ai {

namespace {

// The object ball's direction error just after the first contact (unit: rad; + is
// counter-clockwise of the wanted direction); empty when the cue ball does not hit it first.
std::optional<double> direction_error(const physics::Table& table, const physics::Params& params,
                                      physics::Vec2 cue, physics::Vec2 object, const Aim& aim,
                                      const physics::Stroke& stroke) {
    std::array<physics::BallState, 2> balls{};
    balls[0].pos = cue;
    balls[1].id = aim.ball;
    balls[1].pos = object;
    physics::SimOptions options;
    options.max_events = 10;  // the contact comes within the first few events
    const physics::Shot shot = physics::simulate(table, params, balls, &stroke, options);
    for (const physics::Event& e : shot.events()) {
        if (e.type == physics::EventType::cushion) return std::nullopt;
        if (e.type != physics::EventType::ball_ball) continue;
        const physics::EventBall& b = e.balls[0].id == aim.ball ? e.balls[0] : e.balls[1];
        const physics::Vec2 v = b.vel;
        if (physics::norm2(v) == 0.0) return std::nullopt;
        return std::atan2(physics::cross(aim.object_dir, v), physics::dot(aim.object_dir, v));
    }
    return std::nullopt;
}

}  // namespace

double refine_heading(const physics::Table& table, const physics::Params& params,
                      physics::Vec2 cue, physics::Vec2 object, const Aim& aim,
                      physics::Stroke stroke, int iterations, std::int64_t& simulations) {
    const double R = params.ball_radius;
    // Turning the stroke by dh turns the object ball by about −gain·dh.
    const double cos_cut = std::max(std::cos(aim.cut_deg * deg), 0.05);
    const double gain = aim.cue_distance / (2.0 * R * cos_cut);
    double h0 = aim.heading_deg;
    stroke.heading_deg = h0;
    ++simulations;
    std::optional<double> e0 = direction_error(table, params, cue, object, aim, stroke);
    if (!e0) return aim.heading_deg;
    double h1 = h0 + *e0 / gain / deg;
    for (int k = 0; k < iterations; ++k) {
        stroke.heading_deg = h1;
        ++simulations;
        std::optional<double> e1 = direction_error(table, params, cue, object, aim, stroke);
        if (!e1) return h0;
        if (std::fabs(*e1) < 1e-6 || *e1 == *e0) return h1;
        const double h2 = h1 - *e1 * (h1 - h0) / (*e1 - *e0);
        h0 = h1;
        e0 = e1;
        // Never wander far from the ghost-ball heading: the shot model would not hold.
        h1 = std::clamp(h2, aim.heading_deg - 3.0, aim.heading_deg + 3.0);
    }
    return h1;
}

}  // namespace ai
