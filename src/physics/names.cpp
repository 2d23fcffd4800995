// Names of motion states and event types, as the CLI and logs print them.
#include <array>

#include "physics/ball_state.hpp"
#include "physics/event.hpp"

namespace physics {

namespace {
constexpr std::array<std::string_view, 5> kMotionNames = {"stationary", "spinning", "sliding",
                                                          "rolling", "pocketed"};
constexpr std::array<std::string_view, 7> kEventNames = {
    "strike", "miscue", "transition", "ball_ball", "cushion", "pocket", "off_table"};
}  // namespace

std::string_view to_string(Motion m) {
    return kMotionNames[static_cast<std::size_t>(m)];
}

std::optional<Motion> motion_from_string(std::string_view s) {
    for (std::size_t i = 0; i < kMotionNames.size(); ++i)
        if (kMotionNames[i] == s) return static_cast<Motion>(i);
    return std::nullopt;
}

std::string_view to_string(EventType t) {
    return kEventNames[static_cast<std::size_t>(t)];
}

}  // namespace physics
