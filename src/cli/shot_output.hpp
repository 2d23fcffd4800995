// Writing a simulated shot as the `simulate` output document (docs/cli.md).
#pragma once

#include <nlohmann/json.hpp>
#include <span>

#include "physics/event.hpp"
#include "physics/shot.hpp"

namespace cli {

/// One event: time, type, balls, the type's own fields, then pos, vel, spin per ball.
nlohmann::ordered_json event_to_json(const physics::Event& event);

/// Every event of a shot, in time order.
nlohmann::ordered_json events_to_json(std::span<const physics::Event> events);

/// The whole output: events, final, samples (at `sample_times`, in the order given),
/// rest_time, event_count, truncated.
nlohmann::ordered_json shot_to_json(const physics::Shot& shot,
                                    std::span<const double> sample_times);

}  // namespace cli
