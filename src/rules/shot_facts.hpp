// What the rules need to know about a shot, distilled from its event log once, so that every
// foul and every rule is a small predicate over these facts (docs/style.md rule 4).
#pragma once

#include <optional>
#include <set>
#include <span>
#include <vector>

#include "physics/event.hpp"

namespace rules {

struct PocketedBall {
    int ball = 0;
    int pocket = -1;  ///< physics::PocketId
    friend bool operator==(const PocketedBall&, const PocketedBall&) = default;
};

struct ShotFacts {
    /// The first object ball the cue ball touched; empty: it touched none.
    std::optional<int> first_contact;
    /// Whether the cue ball's centre was at x ≥ the head string in any event up to and including
    /// its first contact (positions of events that carry none, NaN, are skipped).
    bool cue_left_kitchen = false;
    /// Whether any ball (the cue ball included) touched a cushion after the first contact.
    bool cushion_after_contact = false;
    /// The distinct object balls that touched a cushion at any time in the shot.
    std::set<int> object_balls_to_cushion;
    std::vector<PocketedBall> pocketed;  ///< object balls pocketed, in event order
    std::vector<int> off_table;          ///< object balls driven off the table, in event order
    bool cue_pocketed = false;
    bool cue_off_table = false;

    bool was_pocketed(int ball) const;
    bool went_off_table(int ball) const;
    /// Where a ball was pocketed; empty if it was not.
    std::optional<int> pocket_of(int ball) const;
    /// The cue ball was pocketed or left the table.
    bool cue_ball_lost() const { return cue_pocketed || cue_off_table; }
};

/// Distils a shot's events. Only ball_ball, cushion, pocket and off_table events count, except
/// that the cue ball's position in any event (a transition too) counts for the kitchen rule.
/// A ball counts as pocketed or off the table once, at its first such event.
ShotFacts distill(std::span<const physics::Event> events, double head_string_x);

}  // namespace rules
