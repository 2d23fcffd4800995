#include "ai/level.hpp"

#include <algorithm>
#include <array>

namespace ai {

Effort effort_for_level(int level) {
    // One level per block reads better than one field per line.
    // clang-format off
    static constexpr std::array<Effort, 5> levels{{
        {.noise_multiplier = 4.0, .pot_pairs = 3, .speeds = 2, .spins = 1, .safety_speeds = 2,
         .safety_contacts = 3, .sweep_headings = 36, .shortlist = 4, .samples = 4, .finalists = 1,
         .placements = 1, .break_samples = 3},
        {.noise_multiplier = 3.0, .pot_pairs = 5, .speeds = 3, .spins = 3, .safety_speeds = 2,
         .safety_contacts = 3, .sweep_headings = 48, .shortlist = 8, .samples = 8, .finalists = 2,
         .placements = 1, .break_samples = 4, .polish = 2},
        {.noise_multiplier = 2.0, .pot_pairs = 7, .speeds = 4, .spins = 4, .safety_speeds = 3,
         .safety_contacts = 5, .sweep_headings = 72, .shortlist = 14, .samples = 12, .finalists = 4,
         .placements = 3, .break_samples = 6, .polish = 3, .deep_finalists = 3, .deep_samples = 8,
         .next_pairs = 2, .next_speeds = 3, .next_spins = 3},
        {.noise_multiplier = 1.5, .pot_pairs = 12, .speeds = 5, .spins = 6, .safety_speeds = 3,
         .safety_contacts = 5, .sweep_headings = 120, .shortlist = 32, .samples = 24, .finalists = 6,
         .placements = 4, .break_samples = 8, .polish = 3, .deep_finalists = 6, .deep_samples = 12,
         .next_pairs = 3, .next_speeds = 3, .next_spins = 3},
        {.noise_multiplier = 1.0, .pot_pairs = 14, .speeds = 7, .spins = 9, .safety_speeds = 4,
         .safety_contacts = 7, .sweep_headings = 720, .centred_kicks = 12, .shortlist = 48,
         .samples = 40, .finalists = 8, .finalist_rounds = 3, .placements = 6,
         .break_samples = 12, .polish = 4,
         .centred_pots = true, .deep_finalists = 8, .deep_samples = 32,
         .next_pairs = 3, .next_speeds = 4, .next_spins = 4, .playout_shots = 4,
         .max_raise_deg = 20.0, .model_sigma_deg = 0.14,
         .distinct_leaves = 0.5, .stuck_ball_cost = 0.04, .combinations = 3, .tuned_breaks = true,
         .fresh_deep_draws = true},
    }};
    // clang-format on
    return levels[static_cast<std::size_t>(std::clamp(level, min_level, max_level) - 1)];
}

int deepest_draws(const Effort& effort) {
    if (effort.deep_halvings <= 0) return effort.deep_samples;
    return effort.deep_samples << (effort.deep_halvings - 1);
}

int draw_pool(const Effort& effort) {
    const int one_ply = std::max((1 + std::max(effort.finalist_rounds, 1)) * effort.samples,
                                 2 * effort.break_samples);
    return effort.fresh_deep_draws ? one_ply + deepest_draws(effort)
                                   : std::max(one_ply, deepest_draws(effort));
}

Effort rack_end_effort(int level) {
    Effort effort = effort_for_level(level);
    if (level >= max_level) {
        effort.shortlist = 96;
        effort.finalists = 12;
        effort.polish = 6;
        effort.deep_finalists = 12;
        effort.deep_samples = 64;
    }
    return effort;
}

Effort nine_ball_effort(int level) {
    Effort effort = effort_for_level(level);
    if (level >= max_level) {
        effort.polish = 8;
        effort.deep_finalists = 32;
        effort.deep_samples = 64;
        effort.deep_halvings = 2;
        effort.playout_shots = 1;
        effort.finalist_rounds = 1;
    }
    return effort;
}

Effort for_game(Effort effort, rules::Game game) {
    if (game != rules::Game::eight_ball) {
        effort.distinct_leaves = 0.0;
        effort.stuck_ball_cost = 0.0;
        effort.finalist_rounds = 1;
    } else {
        effort.combinations = 0;
        effort.tuned_breaks = false;
        effort.fresh_deep_draws = false;
    }
    return effort;
}

}  // namespace ai
