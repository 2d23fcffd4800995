// Whole snooker frames and three-cushion games between two computer players (games.hpp), through
// the real physics and rules, with the execution noise of each player's level: for the CLI's
// `match`, the strength benchmark (bench/games_ladder.cpp) and the tests. The app plays its
// own sessions; this is the headless loop.
#pragma once

#include <array>
#include <cstdint>
#include <functional>
#include <optional>
#include <vector>

#include "ai/games.hpp"

namespace ai {

/// A computer player: its level and its own seed (each decision's seed derives from it).
struct Seat {
    int level = max_level;
    std::uint64_t seed = 1;
};

struct SnookerFrameSetup {
    rules::SnookerOptions options;
    int reds = 15;           ///< reds racked (1–15; fewer: the front rows of the triangle)
    double noise = 1.0;      ///< the game's execution-noise scale (each level's multiplier on top)
    int max_strokes = 1500;  ///< a frame still on after this many strokes is capped
    int workers = 2;
};

/// One stroke of a frame: the state it was played from (nomination and cue ball placed), the
/// plan, the stroke as executed (with noise) and the verdict.
struct SnookerStroke {
    rules::SnookerState before;
    SnookerPlan plan;
    physics::Stroke executed;
    rules::SnookerVerdict verdict;
    std::optional<rules::AfterFoul> after_foul;  ///< the incoming player's choice after a foul
    double seconds = 0.0;                        ///< the decision's time
};

struct SnookerFrameReport {
    std::optional<rules::Player> winner;  ///< empty when capped
    std::array<int, 2> scores{0, 0};
    int strokes = 0, fouls = 0;
    std::array<std::vector<int>, 2> breaks;  ///< each visit's points (visits that scored)
    std::array<std::vector<double>, 2> decision_seconds;
    bool capped = false;
};

/// The starting state of a frame with `reds` reds: the cue ball in hand, A to break off.
rules::SnookerState snooker_start(const physics::Table& table, const physics::Params& params,
                                  int reds);

/// Plays one frame, seat A breaking off; `noise_seed` seeds the execution noise.
SnookerFrameReport play_snooker_frame(
    const SnookerFrameSetup& setup, const std::array<Seat, 2>& seats, std::uint64_t noise_seed,
    const std::function<void(const SnookerStroke&)>& observe = {});

struct CaromGameSetup {
    rules::CaromOptions options;
    double noise = 1.0;
    int max_strokes = 3000;
    int workers = 2;
};

struct CaromStroke {
    rules::CaromState before;
    CaromPlan plan;
    physics::Stroke executed;
    rules::CaromVerdict verdict;
    double seconds = 0.0;
};

struct CaromGameReport {
    std::optional<rules::Player> winner;  ///< empty: a draw, or capped
    std::array<int, 2> scores{0, 0};
    std::array<int, 2> innings{0, 0};
    std::array<int, 2> high_run{0, 0};
    int strokes = 0, fouls = 0;
    std::array<std::vector<double>, 2> decision_seconds;
    bool over = false;
};

/// Plays one game from the UMB starting position, seat A opening with the white.
CaromGameReport play_three_cushion_game(
    const CaromGameSetup& setup, const std::array<Seat, 2>& seats, std::uint64_t noise_seed,
    const std::function<void(const CaromStroke&)>& observe = {});

}  // namespace ai
