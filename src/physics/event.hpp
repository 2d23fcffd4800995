// An event of a shot: what happened, when, to which balls, and their states just after it.
#pragma once

#include <array>
#include <cstdint>
#include <string_view>

#include "physics/ball_state.hpp"

namespace physics {

enum class EventType : std::uint8_t {
    strike,      ///< the cue hit the cue ball
    miscue,      ///< the cue slipped off the cue ball (tip offset beyond miscue_limit)
    transition,  ///< a ball changed motion state
    ball_ball,   ///< two balls collided
    cushion,     ///< a ball hit a rail, a jaw facing or a jaw nose
    pocket,      ///< a ball fell into a pocket
    off_table,   ///< reserved for a 3D engine
};

std::string_view to_string(EventType t);

/// One ball's state just after an event.
struct EventBall {
    int id = 0;
    Vec2 pos;
    Vec2 vel;
    Vec3 spin;
};

struct Event {
    double time = 0.0;  ///< (unit: s) from the strike
    EventType type = EventType::transition;
    std::uint8_t ball_count = 1;
    std::array<EventBall, 2> balls{};
    double speed = 0.0;  ///< normal approach speed of a collision (unit: m/s)
    Motion from = Motion::stationary, to = Motion::stationary;  ///< for transitions
    int rail = -1;    ///< cushion events on a rail: the rail index
    int pocket = -1;  ///< pocket events: the pocket; cushion events on a jaw: its pocket

    int ball(int k) const { return balls[static_cast<std::size_t>(k)].id; }
    bool involves(int id) const {
        return balls[0].id == id || (ball_count > 1 && balls[1].id == id);
    }
};

}  // namespace physics
