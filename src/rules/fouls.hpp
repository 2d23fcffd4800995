// Each foul of docs/rules.md as a small named predicate over the shot's facts and the state
// before the shot. Which of them apply to a shot is the business of each game's rules.
#pragma once

#include <set>
#include <vector>

#include "rules/game_state.hpp"
#include "rules/shot_facts.hpp"
#include "rules/verdict.hpp"

namespace rules {

/// The cue ball was pocketed.
bool is_scratch(const ShotFacts& f);
/// The cue ball left the table.
bool is_cue_ball_off_table(const ShotFacts& f);
/// The cue ball touched no object ball.
bool is_no_contact(const ShotFacts& f);
/// The cue ball's first contact was not one of `legal_first` (false when it touched nothing).
bool is_wrong_ball_first(const ShotFacts& f, const std::set<int>& legal_first);
/// After the first contact nothing was pocketed and no ball touched a cushion (false when the
/// cue ball touched nothing).
bool is_no_rail_after_contact(const ShotFacts& f);
/// An object ball left the table.
bool is_ball_off_table(const ShotFacts& f);
/// With ball in hand in the kitchen, the cue ball's first contact was a ball whose centre lay in
/// the kitchen (x < head string) at the start, and the cue ball had not left the kitchen.
bool is_bad_play_from_kitchen(const ShotFacts& f, const GameState& s, double head_string_x);

/// The break requirement: an object ball pocketed, or at least four distinct object balls to a
/// cushion.
bool meets_break_requirement(const ShotFacts& f);

/// A set of fouls, read out in the canonical order. `no_contact` stands alone: it removes the
/// fouls it implies (wrong_ball_first, no_rail_after_contact, bad_play_from_kitchen,
/// illegal_break); fouls of the cue ball itself (scratch, off the table) stay.
class FoulList {
  public:
    void add_if(bool condition, Foul foul) {
        if (condition) fouls_.insert(foul);
    }
    bool empty() const { return fouls_.empty(); }
    bool has(Foul foul) const { return fouls_.count(foul) != 0; }
    std::vector<Foul> canonical() const;

  private:
    std::set<Foul> fouls_;
};

}  // namespace rules
