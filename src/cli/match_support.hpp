// What the pool and the other games' `match` share (match_command.cpp, games_match.cpp): the
// seeds derived for each game and player, and the quantiles of decision times.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

#include "physics/rack.hpp"

namespace cli {

/// The value below which a fraction q of the sorted samples lie (nearest rank).
inline double quantile(const std::vector<double>& sorted, double q) {
    const auto rank = static_cast<std::size_t>(std::ceil(q * static_cast<double>(sorted.size())));
    return sorted[std::clamp<std::size_t>(rank, 1, sorted.size()) - 1];
}

/// A seed derived from `seed` and a small tag, so that each game and each player draws from
/// its own stream.
inline std::uint64_t derive(std::uint64_t seed, std::uint64_t tag) {
    physics::SplitMix64 mix(seed ^ (0xd1b54a32d192ed03ULL * (tag + 1)));
    mix.next();
    return mix.next();
}

}  // namespace cli
