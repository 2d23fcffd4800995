#include "render/moving_scale.hpp"

#include <algorithm>

namespace render {

namespace {
constexpr float kStep = 1.0f / 16.0f;  // whole steps, so the small target is rarely remade
}

MovingScale::MovingScale(float highest, float lowest, double budget_ms)
    : highest_(std::clamp(highest, 0.1f, 1.0f)),
      lowest_(std::clamp(std::min(lowest, highest), 0.1f, 1.0f)),
      budget_ms_(budget_ms),
      scale_(highest_) {}

void MovingScale::record(double ms) {
    average_ms_ = average_ms_ < 0.0 ? ms : 0.6 * average_ms_ + 0.4 * ms;
    // The cost grows with the pixels (the scale squared): a step down saves about 15 %, so
    // step down over the budget and up only well under it, never flickering between two.
    if (average_ms_ > budget_ms_ && scale_ > lowest_) {
        scale_ = std::max(lowest_, scale_ - kStep);
        average_ms_ *= 0.85;
    } else if (average_ms_ < 0.7 * budget_ms_ && scale_ < highest_) {
        scale_ = std::min(highest_, scale_ + kStep);
        average_ms_ /= 0.85;
    }
}

}  // namespace render
