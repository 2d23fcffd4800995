#include "rules/nine_ball.hpp"

#include "rules/outcome.hpp"

namespace rules {

namespace {

constexpr int nine = 9;

// Consecutive fouls: a foul counts and, after the second, warns; a legal shot clears both.
// Returns whether this foul is the third after a warning.
bool count_fouls(GameState& next, const GameState& s, bool foul) {
    const std::size_t i = index(s.shooter);
    if (!foul) {
        next.fouls_in_row[i] = 0;
        next.warned[i] = false;
        return false;
    }
    next.fouls_in_row[i] = s.fouls_in_row[i] + 1;
    next.warned[i] = next.fouls_in_row[i] >= 2;
    return next.fouls_in_row[i] >= 3 && s.warned[i];
}

}  // namespace

std::optional<int> lowest_ball(const GameState& s) {
    if (s.on_table.empty()) return std::nullopt;
    return *s.on_table.begin();
}

FoulList nine_ball_fouls(const GameState& s, const ShotFacts& f, double head_string_x) {
    const bool on_break = s.shot == Shot::break_shot;
    const bool push_out = s.shot == Shot::push_out;
    FoulList fouls;
    fouls.add_if(is_scratch(f), Foul::scratch);
    fouls.add_if(is_cue_ball_off_table(f), Foul::cue_ball_off_table);
    fouls.add_if(is_ball_off_table(f), Foul::ball_off_table);
    if (push_out) return fouls;  // first-contact and cushion rules suspended
    fouls.add_if(is_no_contact(f), Foul::no_contact);
    if (std::optional<int> lowest = lowest_ball(s))
        fouls.add_if(is_wrong_ball_first(f, {*lowest}), Foul::wrong_ball_first);
    if (on_break)
        fouls.add_if(!meets_break_requirement(f), Foul::illegal_break);
    else
        fouls.add_if(is_no_rail_after_contact(f), Foul::no_rail_after_contact);
    fouls.add_if(is_bad_play_from_kitchen(f, s, head_string_x), Foul::bad_play_from_kitchen);
    return fouls;
}

Verdict judge_nine_ball(const GameState& s, const ShotFacts& f, double head_string_x) {
    const Player shooter = s.shooter;
    const bool on_break = s.shot == Shot::break_shot;
    const bool push_out = s.shot == Shot::push_out;

    FoulList fouls = nine_ball_fouls(s, f, head_string_x);
    GameState next = table_after(s, f);
    const bool third = count_fouls(next, s, !fouls.empty());
    fouls.add_if(third, Foul::third_consecutive_foul);
    Verdict v = verdict_with(fouls);
    if (on_break) {
        const bool legal =
            f.first_contact && f.first_contact == lowest_ball(s) && meets_break_requirement(f);
        v.break_result = legal ? BreakResult::legal : BreakResult::illegal;
    }

    if (third) {
        end_game(v, next, s, other(shooter));
        return v;
    }
    if (!v.foul && !push_out && f.was_pocketed(nine)) {
        end_game(v, next, s, shooter);
        return v;
    }
    if (f.was_pocketed(nine) || f.went_off_table(nine)) {  // on a foul or a push-out
        next.on_table.insert(nine);
        v.respot = {nine};
    }
    if (v.foul) {
        ball_in_hand_to_opponent(v, next, shooter, BallInHand::anywhere);
    } else if (push_out) {
        next.shooter = other(shooter);
        next.shot = Shot::after_push_out;
        offer_choice(v, next, {other(shooter), {ChoiceOption::shoot, ChoiceOption::pass_back}},
                     true, BallInHand::none);
    } else {
        if (on_break) next.shot = Shot::after_break;
        next_turn(v, next, shooter, !f.pocketed.empty());
    }
    return v;
}

}  // namespace rules
