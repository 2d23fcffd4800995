#include "ai/internal/game_levels.hpp"

#include <algorithm>
#include <array>

namespace ai {

namespace {

// clang-format off
constexpr std::array<SnookerEffort, 5> snooker_levels{{
    // pairs speeds spins refine | safety balls contacts speeds | sweep spots | list draws
    // finals | deep finalists, draws, next pairs speeds spins | σ
    {3,  2, 1, 1,  3, 3, 2,  24, 1,  4,  4, 1,  0,  0, 0, 0, 0,  0.0},
    {5,  3, 2, 2,  4, 4, 2,  36, 2,  6,  6, 2,  0,  0, 0, 0, 0,  0.0},
    {7,  3, 3, 2,  5, 5, 3,  48, 3,  8,  8, 3,  0,  0, 0, 0, 0,  0.0},
    {10, 4, 5, 3,  6, 7, 3,  72, 4, 16, 16, 4,  4, 12, 2, 2, 2,  0.0},
    {16, 5, 7, 3,  8, 9, 3, 120, 6, 32, 32, 8,  6, 24, 3, 3, 3,  0.14},
}};
constexpr std::array<CaromEffort, 5> carom_levels{{
    // headings speeds spins | list centring draws | leave checked, headings
    { 90, 2, 2,   4, 0,  4,  0,  0},
    {120, 2, 3,   6, 0,  6,  0,  0},
    {180, 3, 3,   8, 4,  8,  0,  0},
    {240, 3, 4,  12, 6, 12,  4, 36},
    {360, 3, 5,  16, 8, 16,  6, 48},
}};
// clang-format on

std::size_t slot(int level) {
    return static_cast<std::size_t>(std::clamp(level, 1, 5) - 1);
}

}  // namespace

SnookerEffort snooker_effort(int level) {
    return snooker_levels[slot(level)];
}

CaromEffort carom_effort(int level) {
    return carom_levels[slot(level)];
}

}  // namespace ai
