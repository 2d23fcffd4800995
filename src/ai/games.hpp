// The computer players of snooker and three-cushion billiards: one decision in a position (a
// plan), at levels 1–5, seeded and reproducible, and the answer to the choice after a foul in
// snooker. ai.hpp is the pool player's; this header is the other games'. A session that holds a
// rules::SnookerState or rules::CaromState with its table, parameters and options calls these
// directly. docs/ai.md ("Snooker and three-cushion") describes the search and the levels.
#pragma once

#include <cstdint>
#include <optional>

#include "ai/ai.hpp"
#include "physics/params.hpp"
#include "physics/stroke.hpp"
#include "physics/table.hpp"
#include "rules/snooker.hpp"
#include "rules/three_cushion.hpp"

namespace ai {

/// What a snooker decision is made from. `state.positions` holds every object ball on the
/// table and, when the cue ball is on the table, the cue ball (key 0); a cue ball in hand is
/// placed in the D by the plan. A free ball on offer (`state.free_ball`) is taken: the plan
/// nominates it.
struct SnookerPosition {
    rules::SnookerOptions options;
    rules::SnookerTable snooker;  ///< the marks and the ball radius the rules use
    physics::Table table;
    physics::Params params;
    rules::SnookerState state;
};

/// The position with `snooker` built from the table's marks and the parameters' ball radius.
SnookerPosition snooker_position(const physics::Table& table, const physics::Params& params,
                                 const rules::SnookerOptions& options,
                                 const rules::SnookerState& state);

struct SnookerPlan {
    physics::Stroke stroke;
    /// The nominated ball where one is needed: a colour when a colour is on, the free ball when
    /// one is on offer; else empty.
    std::optional<int> nominated;
    std::optional<physics::Vec2> cue_pos;  ///< where the cue ball in hand goes (in the D)
    Kind kind = Kind::pot;                 ///< pot, safety or kick (an escape from a snooker)
    double expected_success = 0.0;         ///< pots: chance to stay at the table; else of no foul
    double expected_value = 0.0;   ///< the planner's value: points ahead, this visit and next
    std::int64_t simulations = 0;  ///< physics simulations run for this decision
};

/// The AI's stroke in `pos`. The same position, settings and seed give the same plan, bit for
/// bit, whatever the threads' timing.
SnookerPlan plan_snooker(const SnookerPosition& pos, const PlanSettings& settings,
                         std::uint64_t seed);

/// `s` ready to be played with `plan`: the nomination set, the cue ball placed.
rules::SnookerState with_plan(rules::SnookerState s, const SnookerPlan& plan);

/// After a foul (`v.may_ask_to_play_again`), the incoming player's choice: play from where
/// the balls lie, make the offender play again, or (after a miss) have the balls replaced as
/// they were `before` the stroke. Chosen by the value of the table each leaves (no simulation).
rules::AfterFoul choose_after_foul(const SnookerPosition& pos, const rules::SnookerVerdict& v,
                                   const rules::SnookerState& before, const PlanSettings& settings);

/// What a three-cushion decision is made from: the state's positions hold the three balls;
/// the shooter strikes `state.cue_ball(state.shooter)`.
struct CaromPosition {
    rules::CaromOptions options;
    physics::Table table;
    physics::Params params;
    rules::CaromState state;
};

struct CaromPlan {
    physics::Stroke stroke;         ///< its `ball` the shooter's cue ball
    double expected_success = 0.0;  ///< the chance of a point under the level's noise
    double expected_value = 0.0;    ///< the planner's value (a point, plus the position it leaves)
    std::int64_t simulations = 0;
};

/// The AI's stroke in `pos`, reproducible as plan_snooker's.
CaromPlan plan_three_cushion(const CaromPosition& pos, const PlanSettings& settings,
                             std::uint64_t seed);

}  // namespace ai
