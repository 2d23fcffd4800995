// A player who plays at random, but always legally: random strokes, random ball-in-hand
// placements, random calls of his own balls, random choices, now and then a push-out. The
// opponent for soak tests and the baseline for the AI.
#pragma once

#include <cstdint>

#include "game/player.hpp"
#include "physics/rack.hpp"

namespace game {

struct RandomPlayerSettings {
    double min_speed = 1.0;       ///< cue speed range (unit: m/s)
    double max_speed = 8.0;       ///< (unit: m/s)
    double max_offset = 0.3;      ///< largest |side| and |top| (unit: fraction of R)
    double max_elevation = 5.0;   ///< (unit: deg)
    double push_out_odds = 0.25;  ///< chance of declaring a push-out when one is allowed
};

class RandomPlayer final : public Player {
  public:
    explicit RandomPlayer(std::uint64_t seed, RandomPlayerSettings settings = {})
        : rng_(seed), settings_(settings) {}
    std::string kind() const override { return "random"; }
    Decision decide(const Session& session) override;

  private:
    physics::Vec2 place(const Session& session);
    rules::Call call(const Session& session);
    physics::Stroke stroke();

    physics::SplitMix64 rng_;
    RandomPlayerSettings settings_;
};

}  // namespace game
