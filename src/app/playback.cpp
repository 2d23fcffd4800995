#include "app/playback.hpp"

#include <algorithm>

namespace app {

void Playback::start(physics::Shot shot, double lead) {
    shot_ = std::move(shot);
    t_ = -lead;
}

double Playback::end() const {
    if (!shot_) return 0.0;
    if (const std::optional<double> rest = shot_->rest_time()) return *rest;
    return shot_->events().empty() ? 0.0 : shot_->events().back().time;
}

void Playback::advance(double dt) {
    if (!shot_) return;
    t_ = std::min(end(), t_ + std::max(0.0, dt));
}

std::vector<physics::BallState> Playback::states() const {
    if (!shot_) return {};
    return shot_->states_at(std::max(0.0, t_));
}

}  // namespace app
