// A computer player of snooker or three-cushion: one function per game that, given the session
// in its current phase (its to_act() is this player), says what to do: the after-foul choice,
// or where the cue ball in hand goes in the D, the nomination and the stroke. The random
// players below are the tests' and the baseline; the AI's levels plug in the same way
// (app/seats.hpp).
#pragma once

#include <cstdint>
#include <functional>
#include <optional>

#include "game/carom_session.hpp"
#include "game/snooker_session.hpp"
#include "physics/stroke.hpp"
#include "physics/vec.hpp"

namespace game {

struct MatchDecision {
    std::optional<rules::AfterFoul> after_foul;  ///< phase choose: the option taken
    std::optional<physics::Vec2> cue_pos;        ///< snooker, cue ball in hand: where in the D
    std::optional<int> nominate;                 ///< snooker: a colour, or the free ball
    physics::Stroke stroke;                      ///< as intended (before execution noise)
};

/// A snooker player: the function and its execution noise (a multiple of the game's scale,
/// as game::Player::execution_noise).
struct SnookerPlayer {
    std::function<MatchDecision(const SnookerSession&)> decide;
    double execution_noise = 1.0;
};
struct CaromPlayer {
    std::function<MatchDecision(const CaromSession&)> decide;
    double execution_noise = 1.0;
};

/// Random strokes at a ball on (a colour on: a random colour, nominated), a random free place
/// in the D, a random after-foul choice. Deterministic for a seed.
SnookerPlayer random_snooker_player(std::uint64_t seed);
/// Random strokes near one of the object balls (the red on the opening stroke).
CaromPlayer random_carom_player(std::uint64_t seed);

/// Takes `d` in `s`: the after-foul choice, or the placement and the nomination, then plays
/// `stroke` (the decision's stroke after execution noise). Throws game::Refused as the
/// session does.
void apply(SnookerSession& s, const MatchDecision& d, const physics::Stroke& stroke);
void apply(CaromSession& s, const MatchDecision& d, const physics::Stroke& stroke);

}  // namespace game
