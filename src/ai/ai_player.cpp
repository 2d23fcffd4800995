#include <algorithm>

#include "ai/ai.hpp"
#include "ai/internal/level.hpp"
#include "physics/rack.hpp"

namespace ai {

std::uint64_t decision_seed(std::uint64_t seed, std::uint64_t n) {
    physics::SplitMix64 mix(seed ^ (0x9e3779b97f4a7c15ULL * (n + 1)));
    mix.next();
    return mix.next();
}

AiPlayer::AiPlayer(int level, std::uint64_t seed, double noise, int workers, PauseHook pause)
    : settings_{std::clamp(level, min_level, max_level), noise, workers, pause}, seed_(seed) {}

double AiPlayer::execution_noise() const {
    return noise_multiplier(settings_.level);
}

game::Decision AiPlayer::decide(const game::Session& session) {
    last_ = plan(position_of(session), settings_, decision_seed(seed_, decisions_++));
    return last_.decision;
}

}  // namespace ai
