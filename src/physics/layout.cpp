#include "physics/layout.hpp"

#include <cmath>

#include "physics/internal/motion.hpp"

namespace physics {

Motion classify_motion(const Params& params, Vec2 vel, Vec3 spin) {
    BallState s;
    s.vel = vel;
    s.spin = spin;
    return motion::settle(params, s).motion;
}

std::optional<LayoutError> validate_layout(const Table& table, const Params& params,
                                           std::span<const BallState> balls) {
    const double R = params.ball_radius;
    auto finite = [](double v) { return std::isfinite(v); };
    for (std::size_t i = 0; i < balls.size(); ++i) {
        const BallState& b = balls[i];
        if (b.id < 0 || b.id > max_ball_id)
            return LayoutError{i, "id",
                               "ball ids are 0 (cue ball) to " + std::to_string(max_ball_id)};
        for (std::size_t j = 0; j < i; ++j)
            if (balls[j].id == b.id)
                return LayoutError{i, "id", "ball " + std::to_string(b.id) + " is given twice"};
        if (!finite(b.vel.x) || !finite(b.vel.y))
            return LayoutError{i, "vel", "velocity must be finite"};
        if (!finite(b.spin.x) || !finite(b.spin.y) || !finite(b.spin.z))
            return LayoutError{i, "spin", "spin must be finite"};
        if (b.motion == Motion::pocketed) continue;
        if (!table.on_surface(b.pos, R))
            return LayoutError{i, "pos",
                               "ball is off the table (its centre must lie at least R = " +
                                   std::to_string(R) + " m inside the cushions)"};
    }
    for (std::size_t i = 0; i < balls.size(); ++i) {
        if (balls[i].motion == Motion::pocketed) continue;
        for (std::size_t j = 0; j < i; ++j) {
            if (balls[j].motion == Motion::pocketed) continue;
            double d = norm(balls[i].pos - balls[j].pos);
            if (d < 2 * R - overlap_tolerance)
                return LayoutError{i, "pos",
                                   "ball overlaps ball " + std::to_string(balls[j].id) +
                                       " (centres must be at least 2R apart)"};
        }
    }
    return std::nullopt;
}

}  // namespace physics
