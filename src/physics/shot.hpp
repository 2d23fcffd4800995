// A simulated shot: an immutable value holding the event list and every ball's motion as
// piecewise closed-form segments, so the state of any ball at any time is exact.
#pragma once

#include <optional>
#include <span>
#include <vector>

#include "physics/ball_state.hpp"
#include "physics/event.hpp"
#include "physics/params.hpp"

namespace physics {

/// A stretch of one ball's motion with a single closed form, starting at `t0` in `start`.
struct Segment {
    double t0 = 0.0;
    BallState start;
};

class Shot {
  public:
    Shot() = default;
    Shot(Params params, std::vector<Event> events, std::vector<std::vector<Segment>> segments,
         bool truncated);

    const std::vector<Event>& events() const { return events_; }
    /// Balls in the order they were given to simulate().
    std::size_t ball_count() const { return segments_.size(); }
    int ball_id(std::size_t index) const { return segments_[index].front().start.id; }
    const std::vector<Segment>& segments(std::size_t index) const { return segments_[index]; }
    /// Index of a ball id, if the shot has that ball.
    std::optional<std::size_t> index_of(int id) const;

    /// Exact state of ball `id` at time t ≥ 0 (at an event's time: the state after it).
    /// When the shot is truncated, balls stay as they were at the last event.
    BallState state_at(int id, double t) const;
    /// Every ball's state at time t, in input order.
    std::vector<BallState> states_at(double t) const;
    /// Every ball's state once the shot is over.
    std::vector<BallState> final_states() const;

    /// When the last ball came to rest or was pocketed; empty when truncated.
    std::optional<double> rest_time() const;
    bool truncated() const { return truncated_; }
    const Params& params() const { return params_; }

  private:
    Params params_;
    std::vector<Event> events_;
    std::vector<std::vector<Segment>> segments_;
    bool truncated_ = false;
};

}  // namespace physics
