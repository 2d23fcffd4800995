#include "app/ball_orientations.hpp"

#include "render/orientation.hpp"

namespace app {

BallOrientations::BallOrientations() { reset(); }

void BallOrientations::reset() {
    for (std::size_t id = 0; id < q_.size(); ++id)
        q_[id] = render::initial_orientation(static_cast<int>(id));
}

void BallOrientations::follow(const physics::Shot& shot, double t0, double t1) {
    for (std::size_t i = 0; i < shot.ball_count(); ++i) {
        const int id = shot.ball_id(i);
        if (id < 0 || id >= static_cast<int>(q_.size())) continue;
        auto& q = q_[static_cast<std::size_t>(id)];
        q = render::integrate_orientation(shot, id, t0, t1, q);
    }
}

}  // namespace app
