// Plays a whole game between two players without a window (soak tests, `coolaaber-cli match`):
//
//   until the game is over:  decide (to_act) ─▶ choose | place, call, push-out, play(noisy stroke)
//                            no ball down for `stalemate_after` shots ─▶ declare_stalemate
//                            `max_shots` reached ─▶ the game is capped (no winner)
#pragma once

#include <array>
#include <cstdint>
#include <functional>
#include <optional>
#include <vector>

#include "game/player.hpp"
#include "game/session.hpp"

namespace game {

struct PlayLimits {
    int max_shots = 500;        ///< a game still on after this many shots ends without a winner
    int stalemate_after = 100;  ///< shots in a row with no object ball leaving the table before
                                ///< a stalemate (re-rack, the original breaker breaks)
};

struct GameReport {
    std::optional<rules::Player> winner;  ///< empty when capped
    int shots = 0;
    int fouls = 0;  ///< shots with a foul
    int stalemates = 0;
    bool capped = false;
    bool break_and_run = false;  ///< the breaker of the last rack won without the other shooting
    std::array<std::vector<double>, 2> decision_seconds;  ///< each decision's time, by seat
};

/// Called once per shot, when the shot is settled: after play(), or after the choice it offered
/// was taken (the record then holds the choice).
using ShotObserver = std::function<void(const Session&, const ShotRecord&)>;
/// Called before each decision (a choice, or a turn at the table).
using TurnObserver = std::function<void(const Session&)>;

/// Plays the session's current game to its end. `seats[index(p)]` decides for player p. Every
/// stroke gets execution noise of scale `noise` × its player's execution_noise() from a stream
/// seeded with `noise_seed`.
GameReport play_game(Session& session, const std::array<Player*, 2>& seats,
                     const PlayLimits& limits = {}, double noise = 0.0,
                     std::uint64_t noise_seed = 0, const ShotObserver& on_shot = {},
                     const TurnObserver& before_decision = {});

/// The breaker of the last rack won it without the other player taking a shot.
bool is_break_and_run(const Session& session);

}  // namespace game
