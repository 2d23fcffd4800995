// Every ball's orientation across the shots of a game: integrated from each shot's exact
// angular velocity during playback, so the balls visibly roll, slide and spin, and keep how
// they lie from one shot to the next.
#pragma once

#include <array>

#include <glm/gtc/quaternion.hpp>

#include "physics/shot.hpp"

namespace app {

class BallOrientations {
  public:
    BallOrientations();
    /// Turns every ball of `shot` from shot time t0 to t1 (unit: s).
    void follow(const physics::Shot& shot, double t0, double t1);
    /// Back to each ball's starting orientation (a new rack).
    void reset();
    const glm::dquat& of(int id) const { return q_[static_cast<std::size_t>(id)]; }

  private:
    std::array<glm::dquat, 16> q_;
};

}  // namespace app
