// The rules' answer to one shot: the fouls, who shoots next and how, choices, the end of the
// game, and the state before the next shot (docs/cli.md, `judge` output).
#pragma once

#include <optional>
#include <vector>

#include "rules/game_state.hpp"

namespace rules {

/// Fouls, in their canonical order: a verdict lists them sorted by this enum.
enum class Foul {
    scratch,                 ///< the cue ball was pocketed
    cue_ball_off_table,      ///< the cue ball left the table
    no_contact,              ///< the cue ball touched no object ball (stands alone)
    wrong_ball_first,        ///< the first ball touched was not a legal one
    no_rail_after_contact,   ///< nothing pocketed and no ball to a cushion after the first contact
    ball_off_table,          ///< an object ball left the table
    bad_play_from_kitchen,   ///< from the kitchen, hit a ball in the kitchen without leaving it
    illegal_break,           ///< 9-ball: too few balls to a cushion on the break, none pocketed
    third_consecutive_foul,  ///< 9-ball: the third foul in a row after a warning loses
};

enum class BallInHand { none, anywhere, kitchen };

/// The break requirement (docs/rules.md) on a break shot; `none` on any other shot.
enum class BreakResult { none, legal, illegal };

/// The options a player may be offered (docs/rules.md names).
enum class ChoiceOption {
    accept_table,                      ///< play the table as it lies
    rerack_and_break,                  ///< re-rack, the chooser breaks
    rerack_offender_breaks,            ///< re-rack, the one who broke breaks again
    spot_8_and_continue,               ///< spot the 8, the breaker shoots on
    rebreak,                           ///< re-rack, the chooser breaks
    spot_8_with_kitchen_ball_in_hand,  ///< spot the 8, the chooser shoots from the kitchen
    kitchen_ball_in_hand,              ///< the chooser shoots with ball in hand in the kitchen
    shoot,                             ///< after a push-out: the chooser shoots
    pass_back,                         ///< after a push-out: the one who pushed shoots again
};

struct Choice {
    Player by = Player::A;
    std::vector<ChoiceOption> options;  ///< the first is what `Verdict::state` describes
    friend bool operator==(const Choice&, const Choice&) = default;
};

struct Verdict {
    bool foul = false;
    std::vector<Foul> fouls;  ///< canonical order; no_contact implies no first ball and no rail
    /// The shooter loses the table (when a choice is pending: if its first option is taken).
    bool turn_passes = false;
    std::optional<Player> next_shooter;  ///< empty while a choice is pending or the game is over
    BallInHand ball_in_hand = BallInHand::none;
    std::optional<Group> group_a;  ///< A's group after the shot; empty: open table
    std::vector<int> respot;       ///< balls spotted (foot spot, long string) after the shot
    std::optional<Choice> choice;  ///< a pending choice
    bool game_over = false;
    std::optional<Player> winner;
    BreakResult break_result = BreakResult::none;
    /// The state before the next shot (with a pending choice: what its first option leads to).
    GameState state;

    bool has(Foul f) const {
        for (Foul g : fouls)
            if (g == f) return true;
        return false;
    }
};

}  // namespace rules
