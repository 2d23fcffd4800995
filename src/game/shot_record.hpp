// What the session remembers of each shot: the state it was played from, the stroke, what
// happened on the table (a summary, or every physics event), the verdict and the choice taken.
#pragma once

#include <optional>
#include <span>
#include <vector>

#include "physics/event.hpp"
#include "physics/stroke.hpp"
#include "rules/game_state.hpp"
#include "rules/verdict.hpp"

namespace game {

/// A ball that dropped or left the table during a shot.
struct BallDown {
    int ball = 0;     ///< 0 is the cue ball
    int pocket = -1;  ///< physics::PocketId; −1: driven off the table
    friend bool operator==(const BallDown&, const BallDown&) = default;
};

/// The events of a shot in a few numbers (what a score sheet or a log needs).
struct ShotSummary {
    std::optional<int> first_contact;  ///< the first object ball the cue ball touched
    std::vector<BallDown> down;        ///< balls pocketed or off the table, in event order
    int cushions = 0;                  ///< cushion contacts of all balls (jaws included)
    int ball_contacts = 0;             ///< ball–ball collisions
    int events = 0;                    ///< physics events of the shot
    double duration = 0.0;   ///< time until the last ball came to rest (unit: s); 0 if truncated
    bool truncated = false;  ///< the simulation reached its event cap
};

/// Summarizes a shot's events (a ball counts as down once, at its first pocket or off-table
/// event, as the rules count it).
ShotSummary summarize(std::span<const physics::Event> events, std::optional<double> rest_time,
                      bool truncated);

/// One stroke and its consequences.
struct ShotRecord {
    int rack = 0;  ///< the rack of the game it was played in (0, then 1 after a re-rack, ...)
    /// The state it was played from: shooter, call, push-out (`shot`), and every ball's
    /// position, the cue ball's included.
    rules::GameState before;
    physics::Stroke stroke;
    ShotSummary summary;
    std::vector<physics::Event> events;  ///< every physics event, when Config::keep_events
    rules::Verdict verdict;
    std::optional<rules::ChoiceOption> choice;  ///< the option taken on the verdict's choice

    rules::Player shooter() const { return before.shooter; }
    bool push_out() const { return before.shot == rules::Shot::push_out; }
};

}  // namespace game
