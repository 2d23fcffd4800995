#include "physics/shot.hpp"

#include <algorithm>

#include "physics/internal/motion.hpp"

namespace physics {

Shot::Shot(Params params, std::vector<Event> events, std::vector<std::vector<Segment>> segments,
           bool truncated)
    : params_(params),
      events_(std::move(events)),
      segments_(std::move(segments)),
      truncated_(truncated) {}

std::optional<std::size_t> Shot::index_of(int id) const {
    for (std::size_t i = 0; i < segments_.size(); ++i)
        if (ball_id(i) == id) return i;
    return std::nullopt;
}

BallState Shot::state_at(int id, double t) const {
    const std::vector<Segment>& segs = segments_.at(index_of(id).value());
    if (truncated_ && !events_.empty()) t = std::min(t, events_.back().time);
    t = std::max(t, 0.0);
    // The last segment starting at or before t: at an event's time, the state after it.
    auto it = std::upper_bound(segs.begin(), segs.end(), t,
                               [](double time, const Segment& s) { return time < s.t0; });
    const Segment& s = *std::prev(it);
    return motion::evolve(params_, s.start, t - s.t0);
}

std::vector<BallState> Shot::states_at(double t) const {
    std::vector<BallState> out;
    out.reserve(segments_.size());
    for (std::size_t i = 0; i < segments_.size(); ++i) out.push_back(state_at(ball_id(i), t));
    return out;
}

std::vector<BallState> Shot::final_states() const {
    std::vector<BallState> out;
    out.reserve(segments_.size());
    for (const auto& segs : segments_) out.push_back(segs.back().start);
    if (truncated_) return states_at(events_.empty() ? 0.0 : events_.back().time);
    return out;
}

std::optional<double> Shot::rest_time() const {
    if (truncated_) return std::nullopt;
    return events_.empty() ? 0.0 : events_.back().time;
}

}  // namespace physics
