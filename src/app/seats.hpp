// Who sits at each side of the table: a human (the mouse and keyboard) or a computer player
// ("random", or the AI at a level). Computer players are game::Player objects.
#pragma once

#include <cstdint>
#include <memory>
#include <string>

#include "game/player.hpp"

namespace app {

/// A computer player of `kind` ("random", "ai:1" … "ai:5"), seeded; null for "human".
/// Throws std::invalid_argument naming the kind when it is unknown or not built in.
std::unique_ptr<game::Player> make_computer(const std::string& kind, std::uint64_t seed);

/// The factor on the execution noise for a computer of `kind` (its own accuracy): 1 for the
/// strongest level, more for weaker ones.
double own_noise_factor(const std::string& kind);

}  // namespace app
