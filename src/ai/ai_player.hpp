// The computer opponent as a game::Player: levels 1–5, seeded, reproducible. It plans for the
// execution noise it will get (the game's scale × its level's multiplier, execution_noise())
// and never sees the game's noise stream. docs/ai.md.
#pragma once

#include <cstdint>
#include <string>

#include "ai/planner.hpp"
#include "game/player.hpp"

namespace ai {

class AiPlayer final : public game::Player {
  public:
    /// `noise`: the execution-noise scale of the game it plays in (the match's --noise).
    AiPlayer(int level, std::uint64_t seed, double noise = 1.0, int workers = 2);

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
