// Every ball's orientation across the shots of a game: integrated from each shot's exact
// angular velocity during playback, so the balls visibly roll, slide and spin, and keep how
// they lie from one shot to the next. The integration runs on a fixed grid of shot time, so
// the result does not depend on the frame rate: a shot skipped, played at any speed or
// replayed ends with the balls turned exactly alike.
#pragma once

#include <array>
#include <glm/gtc/quaternion.hpp>

#include "physics/shot.hpp"

namespace app {

class BallOrientations {
  public:
    BallOrientations();
    /// Back to each ball's starting orientation (a new rack).
    void reset();
    /// A shot starts: following restarts from its strike.
    void begin_shot() { steps_ = 0; }
    /// Turns every ball of `shot` on to shot time t (unit: s); at t ≥ `end`, exactly to `end`.
    void follow(const physics::Shot& shot, double t, double end);
    const glm::dquat& of(int id) const { return q_[static_cast<std::size_t>(id)]; }

    static constexpr double step = 1.0 / 480.0;  ///< the integration grid (unit: s)

  private:
    void turn(const physics::Shot& shot, double t0, double t1);

    std::array<glm::dquat, 16> q_;
    long steps_ = 0;         ///< grid steps of the current shot done
    bool finished_ = false;  ///< the last partial step to the end is done
};

}  // namespace app
