#include "rules/eight_ball.hpp"

#include <optional>

#include "rules/outcome.hpp"

namespace rules {

namespace {

constexpr int eight = 8;

void assign_group(GameState& next, Player p, Group g) {
    next.group_a = p == Player::A ? g : other(g);
}

// The group of the object balls pocketed, when they are all of one group (the 8 aside).
std::optional<Group> single_group_pocketed(const ShotFacts& f) {
    std::optional<Group> found;
    for (const PocketedBall& p : f.pocketed) {
        std::optional<Group> g = group_of(p.ball);
        if (!g) continue;
        if (found && *found != *g) return std::nullopt;
        found = g;
    }
    return found;
}

// A ball whose legal pocketing keeps the shooter at the table: of his group, or on an open
// table any ball but the 8.
bool scores_for_shooter(const GameState& s, int ball) {
    std::optional<Group> mine = s.group(s.shooter);
    return ball != eight && group_of(ball) && (!mine || group_of(ball) == mine);
}

// The ball legally pocketed that keeps the shooter at the table (and, on an open table, decides
// the groups): the called ball in the called pocket when calls count, else the first pocketed
// ball of his group. None on a safety.
std::optional<int> scoring_ball(const Options& o, const GameState& s, const ShotFacts& f) {
    if (s.call.is_safety()) return std::nullopt;
    if (call_counts(o, s)) {
        const Call& c = s.call;
        if (c.is_ball() && scores_for_shooter(s, c.ball) && f.pocket_of(c.ball) == c.pocket)
            return c.ball;
        return std::nullopt;
    }
    for (const PocketedBall& p : f.pocketed)
        if (scores_for_shooter(s, p.ball)) return p.ball;
    return std::nullopt;
}

// Losing on the 8 after the break: off the table; pocketed with a foul, before the group is
// cleared, on a safety or in an uncalled pocket; a scratch on the 8 under the house rule.
bool loses_on_eight(const Options& o, const GameState& s, const ShotFacts& f, bool foul) {
    if (f.went_off_table(eight)) return true;
    const bool on_eight = on_the_eight(s);
    if (std::optional<int> pocket = f.pocket_of(eight)) {
        if (foul || !on_eight || s.call.is_safety()) return true;
        const Call called_eight = Call::ball_in(eight, *pocket);
        return call_counts(o, s) && s.call != called_eight;
    }
    return o.scratch_on_eight_loses && on_eight && f.cue_ball_lost();
}

BallInHand foul_ball_in_hand(const Options& o) {
    return o.foul_ball_in_hand == FoulBallInHand::kitchen ? BallInHand::kitchen
                                                          : BallInHand::anywhere;
}

void spot_eight(Verdict& v, GameState& next) {
    next.on_table.insert(eight);
    v.respot = {eight};
}

Verdict break_shot(const Options& o, const GameState& s, const ShotFacts& f,
                   const FoulList& fouls) {
    const Player breaker = s.shooter, opponent = other(breaker);
    Verdict v = verdict_with(fouls);
    const bool legal = meets_break_requirement(f);
    v.break_result = legal ? BreakResult::legal : BreakResult::illegal;
    GameState next = table_after(s, f);
    next.fouls_in_row[index(breaker)] = v.foul ? s.fouls(breaker) + 1 : 0;
    const bool eight_down = f.was_pocketed(eight), eight_off = f.went_off_table(eight);

    if (o.eight_on_break == EightOnBreak::wins && (eight_down || eight_off)) {
        end_game(v, next, s, eight_down && !v.foul ? breaker : opponent);
        return v;
    }
    const bool assigns = legal && !v.foul && o.groups_on_break;
    if (assigns) {
        if (std::optional<Group> g = single_group_pocketed(f)) assign_group(next, breaker, *g);
    }
    const BallInHand lost_cue = f.cue_ball_lost() ? BallInHand::kitchen : BallInHand::none;

    if (eight_down) {  // only on a legal break: the 8 is a pocketed object ball
        spot_eight(v, next);
        if (!v.foul) {
            next.shooter = breaker;
            offer_choice(v, next,
                         {breaker, {ChoiceOption::spot_8_and_continue, ChoiceOption::rebreak}},
                         false, BallInHand::none);
        } else {
            next.shooter = opponent;
            offer_choice(
                v, next,
                {opponent, {ChoiceOption::spot_8_with_kitchen_ball_in_hand, ChoiceOption::rebreak}},
                true, BallInHand::kitchen);
        }
        return v;
    }
    if (!legal || v.foul) {
        if (eight_off) spot_eight(v, next);
        next.shooter = opponent;
        Choice choice{opponent, {ChoiceOption::accept_table, ChoiceOption::kitchen_ball_in_hand}};
        if (!legal)
            choice.options = {ChoiceOption::accept_table, ChoiceOption::rerack_and_break,
                              ChoiceOption::rerack_offender_breaks};
        offer_choice(v, next, choice, true, lost_cue);
        return v;
    }
    next_turn(v, next, breaker, !f.pocketed.empty());
    return v;
}

Verdict shot_after_break(const Options& o, const GameState& s, const ShotFacts& f,
                         const FoulList& fouls) {
    const Player shooter = s.shooter;
    Verdict v = verdict_with(fouls);
    GameState next = table_after(s, f);
    next.fouls_in_row[index(shooter)] = v.foul ? s.fouls(shooter) + 1 : 0;

    if (loses_on_eight(o, s, f, v.foul)) {
        end_game(v, next, s, other(shooter));
        return v;
    }
    if (f.was_pocketed(eight)) {  // legally, in the called pocket, after clearing the group
        end_game(v, next, s, shooter);
        return v;
    }
    if (v.foul) {
        ball_in_hand_to_opponent(v, next, shooter, foul_ball_in_hand(o));
        return v;
    }
    std::optional<int> scored = scoring_ball(o, s, f);
    if (scored && !s.group_a) assign_group(next, shooter, *group_of(*scored));
    next_turn(v, next, shooter, scored.has_value());
    return v;
}

}  // namespace

std::set<int> eight_ball_legal_first(const GameState& s) {
    std::set<int> legal;
    std::optional<Group> mine = s.group(s.shooter);
    if (mine && on_the_eight(s)) return {eight};
    for (int id : s.on_table)
        if (id != eight && (!mine || group_of(id) == mine)) legal.insert(id);
    return legal;
}

FoulList eight_ball_fouls(const Options& o, const GameState& s, const ShotFacts& f,
                          double head_string_x) {
    const bool on_break = s.shot == Shot::break_shot;
    FoulList fouls;
    fouls.add_if(is_scratch(f), Foul::scratch);
    fouls.add_if(is_cue_ball_off_table(f), Foul::cue_ball_off_table);
    fouls.add_if(is_no_contact(f), Foul::no_contact);
    fouls.add_if(!on_break && is_wrong_ball_first(f, eight_ball_legal_first(s)),
                 Foul::wrong_ball_first);
    fouls.add_if(!on_break && o.rail_after_contact && is_no_rail_after_contact(f),
                 Foul::no_rail_after_contact);
    fouls.add_if(is_ball_off_table(f), Foul::ball_off_table);
    fouls.add_if(is_bad_play_from_kitchen(f, s, head_string_x), Foul::bad_play_from_kitchen);
    return fouls;
}

bool call_counts(const Options& o, const GameState& s) {
    switch (o.call_shots) {
        case CallShots::all:
            return true;
        case CallShots::eight_only:
            return on_the_eight(s);
        case CallShots::none:
            return false;
    }
    return true;
}

Verdict judge_eight_ball(const Options& o, const GameState& s, const ShotFacts& f,
                         double head_string_x) {
    FoulList fouls = eight_ball_fouls(o, s, f, head_string_x);
    return s.shot == Shot::break_shot ? break_shot(o, s, f, fouls)
                                      : shot_after_break(o, s, f, fouls);
}

}  // namespace rules
