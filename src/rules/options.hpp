// House-rule switches (docs/rules.md, "House-rule switches"); the defaults are WPA. Each
// switch changes only what it names. They are 8-ball switches: 9-ball ignores them.
#pragma once

namespace rules {

/// Which shots must be called.
enum class CallShots {
    all,         ///< every shot after the break names a ball and a pocket (or a safety)
    eight_only,  ///< only shots at the 8
    none,        ///< nothing is called
};

/// What the 8 pocketed on the break does.
enum class EightOnBreak {
    spot_or_rebreak,  ///< WPA: a choice (the breaker's, or the opponent's after a foul)
    wins,             ///< wins on a legal break without a foul; loses with a foul or off the table
};

/// Where ball in hand goes after an ordinary (not break) foul.
enum class FoulBallInHand { anywhere, kitchen };

struct Options {
    CallShots call_shots = CallShots::all;
    EightOnBreak eight_on_break = EightOnBreak::spot_or_rebreak;
    FoulBallInHand foul_ball_in_hand = FoulBallInHand::anywhere;
    bool scratch_on_eight_loses = false;  ///< a scratch (or cue ball off the table) on the 8 loses
    bool groups_on_break = false;         ///< one group only pocketed on a legal break assigns it
    bool rail_after_contact = true;       ///< the no_rail_after_contact foul applies

    friend bool operator==(const Options&, const Options&) = default;
};

}  // namespace rules
