// Who sits at each side of the table: a human (the mouse and keyboard) or a computer player
// ("random", or the AI at a level). Computer players are game::Player objects; each knows its
// own execution noise (game::Player::execution_noise).
#pragma once

#include <array>
#include <cstdint>
#include <memory>
#include <optional>
#include <string>

#include "game/match_player.hpp"
#include "game/player.hpp"

namespace app {

/// A computer player of `kind` ("random", "ai:1" … "ai:5"), seeded, planning for execution
/// noise of scale `noise`; null for "human". Throws std::invalid_argument naming the kind
/// when it is unknown.
std::unique_ptr<game::Player> make_computer(const std::string& kind, std::uint64_t seed,
                                            double noise);

/// The computer player of snooker (three-cushion) of `kind`, seeded, for execution noise of
/// scale `noise`; empty for "human" and for a kind that has no player for the game yet. Today
/// "random"; the AI's levels ("ai:1" … "ai:5") plug in here, one function per game.
std::optional<game::SnookerPlayer> snooker_computer(const std::string& kind, std::uint64_t seed,
                                                    double noise);
std::optional<game::CaromPlayer> carom_computer(const std::string& kind, std::uint64_t seed,
                                                double noise);

/// "Human", "Computer (random)", "Computer (level 3)".
std::string seat_words(const std::string& kind);

/// The names the game shows: a computer seat still under its default name ("Player 2") is
/// called what it is ("Computer (level 3)"; numbered when both seats are the same computer).
std::array<std::string, 2> seat_names(const std::array<std::string, 2>& names,
                                      const std::array<std::string, 2>& kinds);

}  // namespace app
