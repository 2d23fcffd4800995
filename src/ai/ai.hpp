// The computer opponent's public interface, the one header of src/ai that the app and the CLI
// include: a player for a game::Session (AiPlayer), and one decision in a position (plan), at
// levels 1–5, seeded and reproducible. The other headers of src/ai are the planner's own
// (candidates, evaluation, placement, the levels' table, …): for the AI, its tests and its
// benchmarks only. docs/ai.md describes the pipeline and the levels.
#pragma once

#include <cstdint>
#include <optional>
#include <string>

#include "ai/pause.hpp"
#include "game/player.hpp"
#include "physics/params.hpp"
#include "physics/table.hpp"
#include "rules/game_state.hpp"
#include "rules/judge.hpp"
#include "rules/verdict.hpp"

namespace game {
class Session;
}

namespace ai {

inline constexpr int min_level = 1;
inline constexpr int max_level = 5;

/// What the AI decides from: the rules, the table, the physics and the game's state before the
/// shot (with every ball's position), plus a pending choice of the rules, if any. Built from a
/// game::Session (`position_of`), or directly (the CLI's `decide`).
struct Position {
    rules::Ruleset ruleset;
    physics::Table table;
    physics::Params params;
    /// The state before the shot; with a pending choice, the table as it lies (what the first
    /// option leads to). Positions of every object ball on the table, and of the cue ball when it
    /// is on the table (a cue ball in hand is placed by the AI).
    rules::GameState state;
    std::optional<rules::Choice> choice;  ///< a choice pending for the player to act
};

Position position_of(const game::Session& session);

/// Whether the cue ball is to be placed (ball in hand) rather than played from where it lies.
bool cue_in_hand(const rules::GameState& s);

/// What sort of stroke a decision is.
enum class Kind { pot, safety, kick, break_shot, push_out };

struct PlanSettings {
    int level = max_level;  ///< 1 (beginner) to 5 (strongest)
    double noise = 1.0;     ///< the game's execution-noise scale (the level's multiplier on top)
    int workers = 2;        ///< threads that share the simulations
    PauseHook pause = nullptr;  ///< called between the search's steps (ai/pause.hpp), or none
};

struct Plan {
    game::Decision decision;
    double expected_success = 0.0;  ///< pots: chance to stay at the table; safeties: of no foul
    double expected_value = 0.0;    ///< the planner's value of the stroke (a rough chance to win)
    std::int64_t simulations = 0;   ///< physics simulations run for this decision
    Kind kind = Kind::pot;          ///< what sort of stroke it is (a choice: Kind::pot, unused)
};

/// The AI's decision in `pos` (planner.hpp describes its steps). The same position, settings and
/// seed give the same decision, bit for bit, whatever the threads' timing
/// (decisions_test.cpp's SameSeedSameDecisionWhateverTheThreads).
Plan plan(const Position& pos, const PlanSettings& settings, std::uint64_t seed);

/// The execution-noise scale a player of `settings` strokes with: noise × the level's multiplier.
double planned_scale(const PlanSettings& settings);

/// The computer opponent as a game::Player. It plans for the execution noise it will get (the
/// game's scale × its level's multiplier, execution_noise()) and never sees the game's noise
/// stream.
class AiPlayer final : public game::Player {
  public:
    /// `noise`: the execution-noise scale of the game it plays in (the match's --noise).
    /// `pause`: PlanSettings::pause.
    AiPlayer(int level, std::uint64_t seed, double noise = 1.0, int workers = 2,
             PauseHook pause = nullptr);

    std::string kind() const override { return "ai:" + std::to_string(settings_.level); }
    game::Decision decide(const game::Session& session) override;
    /// The level's multiplier of the game's execution noise (4× at level 1 … 1× at level 5).
    double execution_noise() const override;

    /// The plan behind the latest decision (its expected success and simulations).
    const Plan& last_plan() const { return last_; }

  private:
    PlanSettings settings_;
    std::uint64_t seed_;
    std::uint64_t decisions_ = 0;
    Plan last_;
};

/// The seed of the n-th decision of a player seeded with `seed`.
std::uint64_t decision_seed(std::uint64_t seed, std::uint64_t n);

}  // namespace ai
