#include "app/ball_orientations.hpp"

#include <cmath>

#include "render/orientation.hpp"

namespace app {

BallOrientations::BallOrientations() {
    reset();
}

void BallOrientations::reset() {
    for (std::size_t id = 0; id < q_.size(); ++id)
        q_[id] = render::initial_orientation(static_cast<int>(id));
    steps_ = 0;
    finished_ = false;
}

// One step from t0 to t1 with ω at the middle (exact for constant ω).
void BallOrientations::turn(const physics::Shot& shot, double t0, double t1) {
    const double mid = 0.5 * (t0 + t1);
    for (std::size_t i = 0; i < shot.ball_count(); ++i) {
        const int id = shot.ball_id(i);
        if (id < 0 || id >= static_cast<int>(q_.size())) continue;
        const physics::BallState s = shot.state_at(id, mid);
        if (s.motion == physics::Motion::pocketed) continue;
        auto& q = q_[static_cast<std::size_t>(id)];
        q = render::advance(q, s.spin, t1 - t0);
    }
}

void BallOrientations::follow(const physics::Shot& shot, double t, double end) {
    if (steps_ == 0) finished_ = false;
    const long last_full = static_cast<long>(std::floor(end / step));
    const long target = std::min(last_full, static_cast<long>(std::floor(std::min(t, end) / step)));
    for (; steps_ < target; ++steps_)
        turn(shot, static_cast<double>(steps_) * step, static_cast<double>(steps_ + 1) * step);
    if (t >= end && !finished_) {
        const double from = static_cast<double>(steps_) * step;
        if (end > from) turn(shot, from, end);
        finished_ = true;
    }
}

}  // namespace app
