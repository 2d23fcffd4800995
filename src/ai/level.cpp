#include "ai/internal/level.hpp"

#include <algorithm>
#include <array>

namespace ai {

namespace {

// Every knob of every level, one block per level, in the order of level.hpp's Effort: the
// candidates; the rounds under noise; the deep search; the value of a table. Levels 1–4 are the
// same in both games; level 5 has an effort per game and, in 8-ball, one near the rack's end.
// level_test.cpp and rack_end_test.cpp pin the relations between the entries; any change of a
// value changes decisions, which a `coolaaber-cli match --log` before and after shows.
// clang-format off
constexpr std::array<Effort, 5> eight_ball{{
    {.pot_pairs = 3, .speeds = 2, .spins = 1, .refine_steps = 2, .max_raise_deg = 0.0,
    .safety_speeds = 2, .safety_contacts = 3, .placements = 1, .combinations = 0,
    .sweep_headings = 36, .centred_kicks = 0, .break_samples = 3, .tuned_breaks = false,
    .shortlist = 4, .samples = 4, .finalists = 1, .finalist_rounds = 1, .centred_pots = false,
    .polish = 0, .distinct_leaves = 0.0,
    .deep_finalists = 0, .deep_samples = 0, .deep_halvings = 0, .fresh_deep_draws = false,
    .next_pairs = 3, .next_speeds = 3, .next_spins = 3, .playout_shots = 1,
    .model_sigma_deg = 0.0, .stuck_ball_cost = 0.0},
    {.pot_pairs = 5, .speeds = 3, .spins = 3, .refine_steps = 2, .max_raise_deg = 0.0,
    .safety_speeds = 2, .safety_contacts = 3, .placements = 1, .combinations = 0,
    .sweep_headings = 48, .centred_kicks = 0, .break_samples = 4, .tuned_breaks = false,
    .shortlist = 8, .samples = 8, .finalists = 2, .finalist_rounds = 1, .centred_pots = false,
    .polish = 2, .distinct_leaves = 0.0,
    .deep_finalists = 0, .deep_samples = 0, .deep_halvings = 0, .fresh_deep_draws = false,
    .next_pairs = 3, .next_speeds = 3, .next_spins = 3, .playout_shots = 1,
    .model_sigma_deg = 0.0, .stuck_ball_cost = 0.0},
    {.pot_pairs = 7, .speeds = 4, .spins = 4, .refine_steps = 2, .max_raise_deg = 0.0,
    .safety_speeds = 3, .safety_contacts = 5, .placements = 3, .combinations = 0,
    .sweep_headings = 72, .centred_kicks = 0, .break_samples = 6, .tuned_breaks = false,
    .shortlist = 14, .samples = 12, .finalists = 4, .finalist_rounds = 1, .centred_pots = false,
    .polish = 3, .distinct_leaves = 0.0,
    .deep_finalists = 3, .deep_samples = 8, .deep_halvings = 0, .fresh_deep_draws = false,
    .next_pairs = 2, .next_speeds = 3, .next_spins = 3, .playout_shots = 1,
    .model_sigma_deg = 0.0, .stuck_ball_cost = 0.0},
    {.pot_pairs = 12, .speeds = 5, .spins = 6, .refine_steps = 2, .max_raise_deg = 0.0,
    .safety_speeds = 3, .safety_contacts = 5, .placements = 4, .combinations = 0,
    .sweep_headings = 120, .centred_kicks = 0, .break_samples = 8, .tuned_breaks = false,
    .shortlist = 32, .samples = 24, .finalists = 6, .finalist_rounds = 1, .centred_pots = false,
    .polish = 3, .distinct_leaves = 0.0,
    .deep_finalists = 6, .deep_samples = 12, .deep_halvings = 0, .fresh_deep_draws = false,
    .next_pairs = 3, .next_speeds = 3, .next_spins = 3, .playout_shots = 1,
    .model_sigma_deg = 0.0, .stuck_ball_cost = 0.0},
    // Level 5: the cue raised against squirt and pots centred in their window, a smaller σ in
    // the shot model to match (model_sigma_test.cpp); leaves kept distinct and stuck balls
    // costed, as the shooter chooses the order of his group; the finalists get three rounds of
    // draws so that the choice among near-sure pots rests on more of them; the table's value
    // played out four shots.
    {.pot_pairs = 14, .speeds = 7, .spins = 9, .refine_steps = 2, .max_raise_deg = 20.0,
    .safety_speeds = 4, .safety_contacts = 7, .placements = 6, .combinations = 0,
    .sweep_headings = 720, .centred_kicks = 12, .break_samples = 12, .tuned_breaks = false,
    .shortlist = 48, .samples = 40, .finalists = 8, .finalist_rounds = 3, .centred_pots = true,
    .polish = 4, .distinct_leaves = 0.5,
    .deep_finalists = 8, .deep_samples = 32, .deep_halvings = 0, .fresh_deep_draws = false,
    .next_pairs = 3, .next_speeds = 4, .next_spins = 4, .playout_shots = 4,
    .model_sigma_deg = 0.14, .stuck_ball_cost = 0.04},
}};

// Level 5 near the end of an 8-ball rack, where the shooter's last few balls decide it and a
// decision has fewer candidates: twice the shortlist, half as many finalists and polished pots
// again, 12 deep finalists of 64 draws; the rest as level 5's. rack_end_test.cpp.
constexpr Effort eight_ball_rack_end{
    .pot_pairs = 14, .speeds = 7, .spins = 9, .refine_steps = 2, .max_raise_deg = 20.0,
    .safety_speeds = 4, .safety_contacts = 7, .placements = 6, .combinations = 0,
    .sweep_headings = 720, .centred_kicks = 12, .break_samples = 12, .tuned_breaks = false,
    .shortlist = 96, .samples = 40, .finalists = 12, .finalist_rounds = 3, .centred_pots = true,
    .polish = 6, .distinct_leaves = 0.5,
    .deep_finalists = 12, .deep_samples = 64, .deep_halvings = 0, .fresh_deep_draws = false,
    .next_pairs = 3, .next_speeds = 4, .next_spins = 4, .playout_shots = 4,
    .model_sigma_deg = 0.14, .stuck_ball_cost = 0.04};

// Level 5 in 9-ball, where a decision has one target ball, so few candidates, and the second ply
// decides: combinations on the 9 and the tuned breaks; 8 pots searched finer; 32 deep finalists
// in two halvings (32 draws each, 32 more for the better 16, 64 more for the best 8) on draws of
// their own; one round more for the finalists and the second ply not played out, as these
// searches cost more per shot. The next ball is always the lowest: no distinct leaves, no
// stuck-ball cost. rack_end_test.cpp, deep_search_test.cpp.
constexpr Effort nine_ball_top{
    .pot_pairs = 14, .speeds = 7, .spins = 9, .refine_steps = 2, .max_raise_deg = 20.0,
    .safety_speeds = 4, .safety_contacts = 7, .placements = 6, .combinations = 3,
    .sweep_headings = 720, .centred_kicks = 12, .break_samples = 12, .tuned_breaks = true,
    .shortlist = 48, .samples = 40, .finalists = 8, .finalist_rounds = 1, .centred_pots = true,
    .polish = 8, .distinct_leaves = 0.0,
    .deep_finalists = 32, .deep_samples = 64, .deep_halvings = 2, .fresh_deep_draws = true,
    .next_pairs = 3, .next_speeds = 4, .next_spins = 4, .playout_shots = 1,
    .model_sigma_deg = 0.14, .stuck_ball_cost = 0.0};

constexpr std::array<Effort, 5> nine_ball{
    {eight_ball[0], eight_ball[1], eight_ball[2], eight_ball[3], nine_ball_top}};

constexpr std::array<double, 5> noise_multipliers{4.0, 3.0, 2.0, 1.5, 1.0};
// clang-format on

std::size_t level_index(int level) {
    return static_cast<std::size_t>(std::clamp(level, min_level, max_level) - min_level);
}

}  // namespace

Effort effort_for(rules::Game game, int level, bool rack_end) {
    const std::size_t i = level_index(level);
    if (game == rules::Game::nine_ball) return nine_ball[i];
    return rack_end && i + 1 == eight_ball.size() ? eight_ball_rack_end : eight_ball[i];
}

double noise_multiplier(int level) {
    return noise_multipliers[level_index(level)];
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

}  // namespace ai
