// Plays a simulated shot back in real time. The shot is exact (physics::Shot), so playback is
// only a clock: the state of every ball at the playback time, at any speed, skipped to the end
// or replayed from the start, with no simulation of its own.
#pragma once

#include <optional>
#include <vector>

#include "physics/shot.hpp"

namespace app {

class Playback {
  public:
    /// Starts playing `shot`, `lead` seconds before its strike (t = −lead: the cue's stroke).
    void start(physics::Shot shot, double lead = 0.0);
    /// Back to `lead` seconds before the strike of the shot being shown (a replay).
    void restart(double lead = 0.0) { t_ = -lead; }
    /// Moves the clock on by `dt` (unit: s of shot time), at most to the end.
    void advance(double dt);
    void skip_to_end() { t_ = end(); }
    /// Forgets the shot (a new rack).
    void clear() {
        shot_.reset();
        t_ = 0.0;
    }

    bool has_shot() const { return shot_.has_value(); }
    /// A shot is loaded and its balls still move at the playback time.
    bool moving() const { return shot_ && t_ < end(); }
    /// The playback time (unit: s from the strike; negative during the cue's stroke).
    double time() const { return t_; }
    /// When the shot is over: its rest time, or its last event's time when truncated.
    double end() const;
    const physics::Shot& shot() const { return *shot_; }
    /// Every ball of the shot at the playback time (pocketed ones included, as pocketed; at
    /// the strike's positions before it).
    std::vector<physics::BallState> states() const;

  private:
    std::optional<physics::Shot> shot_;
    double t_ = 0.0;
};

}  // namespace app
