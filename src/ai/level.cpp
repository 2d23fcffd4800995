#include "ai/level.hpp"

#include <algorithm>
#include <array>

namespace ai {

Effort effort_for_level(int level) {
    // noise, pairs, speeds, spins, safety speeds, contacts, sweep, shortlist, samples,
    // finalists, placements, break samples
    static constexpr std::array<Effort, 5> levels{{
        {4.0, 3, 2, 1, 2, 3, 36, 4, 4, 1, 1, 3},
        {3.0, 4, 3, 2, 2, 3, 48, 6, 6, 2, 1, 4},
        {2.0, 6, 3, 3, 3, 5, 72, 10, 10, 3, 2, 6},
        {1.5, 10, 5, 5, 3, 5, 120, 24, 20, 4, 4, 8},
        {1.0, 14, 7, 9, 4, 7, 180, 48, 40, 8, 6, 12},
    }};
    return levels[static_cast<std::size_t>(std::clamp(level, min_level, max_level) - 1)];
}

}  // namespace ai
