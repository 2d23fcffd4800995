// Three-cushion billiards (UMB rules): a pure function of the state before a stroke and the
// stroke's events (docs/rules.md, "Three-cushion"). Balls: physics/markings.hpp (0 white, the
// first shooter's cue ball; 1 yellow, the other player's; 2 red).
#pragma once

#include <array>
#include <map>
#include <optional>
#include <span>
#include <vector>

#include "physics/event.hpp"
#include "physics/markings.hpp"
#include "rules/game_state.hpp"

namespace rules {

struct CaromOptions {
    int target = 15;             ///< points to win a game
    bool equal_innings = false;  ///< the second player gets an equalizing inning (UMB)
    friend bool operator==(const CaromOptions&, const CaromOptions&) = default;
};

struct CaromState {
    Player shooter = Player::A;
    Player starter = Player::A;  ///< who played the opening stroke; plays the white
    bool opening = true;         ///< the opening stroke: the red must be hit first
    bool equalizing = false;     ///< the second player's equalizing inning
    std::array<int, 2> scores{0, 0};
    std::array<int, 2> innings{1, 0};  ///< innings begun, by index(Player)
    int run = 0;                       ///< points in the current inning
    std::array<int, 2> high_run{0, 0};
    std::map<int, physics::Vec2> positions;  ///< ball centres (unit: m)

    /// The player's cue ball: the starter's is the white, the other's the yellow.
    int cue_ball(Player p) const {
        return p == starter ? physics::carom_ball::white : physics::carom_ball::yellow;
    }
};

enum class CaromFoul {
    wrong_cue_ball,  ///< the striker struck a ball other than his own
    ball_off_table,  ///< a ball left the table
    push_stroke,     ///< the cue ball met a ball while the tip was still on it (push, double hit)
    red_not_first,   ///< the opening stroke did not hit the red first
};

struct CaromVerdict {
    bool point = false;
    bool foul = false;
    std::vector<CaromFoul> fouls;
    int cushions = 0;  ///< cue-ball cushion contacts before it met the second ball (or in all)
    std::optional<Player> next_shooter;  ///< empty when the game is over
    bool game_over = false;
    std::optional<Player> winner;  ///< empty when the game is over in a draw
    std::vector<int> respotted;    ///< balls put back on their spots (off the table)
    CaromState state;              ///< before the next stroke
};

/// Judges one stroke on a table whose spots are `spots`, balls of radius `ball_radius`.
CaromVerdict judge_three_cushion(const CaromOptions& options, const physics::CaromSpots& spots,
                                 double ball_radius, const CaromState& s,
                                 std::span<const physics::Event> events);

}  // namespace rules
