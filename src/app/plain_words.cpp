#include "app/plain_words.hpp"

#include <fmt/format.h>

#include "physics/layout.hpp"
#include "physics/table.hpp"
#include "rules/eight_ball.hpp"

namespace app {

std::string foul_words(rules::Foul f) {
    using F = rules::Foul;
    switch (f) {
        case F::scratch:
            return "the cue ball went into a pocket";
        case F::cue_ball_off_table:
            return "the cue ball left the table";
        case F::no_contact:
            return "the cue ball hit no ball";
        case F::wrong_ball_first:
            return "the first ball hit was not a legal one";
        case F::no_rail_after_contact:
            return "no ball reached a cushion after the contact";
        case F::ball_off_table:
            return "a ball left the table";
        case F::bad_play_from_kitchen:
            return "from the kitchen, the cue ball hit a ball in the kitchen first";
        case F::illegal_break:
            return "illegal break: fewer than four balls reached a cushion";
        case F::third_consecutive_foul:
            return "third foul in a row";
    }
    return "foul";
}

std::string choice_words(rules::ChoiceOption o) {
    using C = rules::ChoiceOption;
    switch (o) {
        case C::accept_table:
            return "Play the table as it lies";
        case C::rerack_and_break:
            return "Re-rack, and I break";
        case C::rerack_offender_breaks:
            return "Re-rack, the breaker breaks again";
        case C::spot_8_and_continue:
            return "Spot the 8 and shoot on";
        case C::rebreak:
            return "Re-rack and break";
        case C::spot_8_with_kitchen_ball_in_hand:
            return "Spot the 8, shoot from the kitchen";
        case C::kitchen_ball_in_hand:
            return "Ball in hand in the kitchen";
        case C::shoot:
            return "Shoot from here";
        case C::pass_back:
            return "Pass the shot back";
    }
    return "?";
}

std::string pocket_words(int pocket) {
    const bool side = pocket == static_cast<int>(physics::PocketId::S) ||
                      pocket == static_cast<int>(physics::PocketId::N);
    return fmt::format("{} {}", physics::pocket_name(pocket), side ? "side" : "corner");
}

std::string group_words(rules::Group g) {
    return g == rules::Group::solids ? "solids (1-7)" : "stripes (9-15)";
}

namespace {

std::string ball_list(const std::vector<int>& balls) {
    std::string out;
    for (std::size_t i = 0; i < balls.size(); ++i) {
        if (i > 0) out += i + 1 == balls.size() ? " and " : ", ";
        out += fmt::format("the {}", balls[i]);
    }
    return out;
}

int lowest_on_table(const rules::GameState& s) {
    return s.on_table.empty() ? 0 : *s.on_table.begin();
}

// Why the turn passed after balls dropped without a foul: the call was not made (8-ball,
// where calls count). Empty when the turn did not pass for that.
std::string call_words(const game::Session& session, const game::ShotRecord& r,
                       const std::vector<int>& down) {
    const rules::Call& call = r.before.call;
    if (session.config().game != rules::Game::eight_ball || down.empty() || r.verdict.foul ||
        r.verdict.game_over || r.verdict.choice || r.verdict.state.shooter == r.shooter() ||
        r.before.shot == rules::Shot::break_shot ||
        !rules::call_counts(session.config().options, r.before))
        return {};
    const std::string next = session.name(r.verdict.state.shooter);
    const std::string what = down.size() == 1 ? "It was" : "They were";
    if (call.is_ball())
        return fmt::format("{} not the call (the {} in the {} pocket): {}'s turn. ", what,
                           call.ball, pocket_words(call.pocket), next);
    if (call.is_safety()) return fmt::format("A safety was called: {}'s turn. ", next);
    return fmt::format("Nothing was called, so it does not count: {}'s turn. ", next);
}

}  // namespace

std::string placement_words(const game::Session& s, physics::Vec2 pos) {
    const std::optional<std::string> why = s.check_cue_ball(pos);
    if (!why) return {};
    if (s.ball_in_hand() == rules::BallInHand::none) return *why;
    if (s.ball_in_hand() == rules::BallInHand::kitchen &&
        !(pos.x < s.ruleset().table.head_string_x()))
        return "The cue ball goes behind the head string (the line across the table) with ball "
               "in hand in the kitchen.";
    const double R = s.config().params.ball_radius;
    for (const auto& [id, p] : s.state().positions)
        if (id != 0 && physics::norm(p - pos) < 2.0 * R - physics::overlap_tolerance)
            return fmt::format("The cue ball can't go on top of the {}.", id);
    if (!s.table().on_surface(pos, R)) return "The cue ball must go on the cloth.";
    return *why;
}

std::string shot_words(const game::Session& session, const game::ShotRecord& r) {
    const std::string& who = session.name(r.shooter());
    std::vector<int> down;
    for (const game::BallDown& d : r.summary.down)
        if (d.ball != 0) down.push_back(d.ball);
    std::string out;
    if (r.push_out()) out = who + " pushed out. ";
    const bool broke = r.before.shot == rules::Shot::break_shot;
    if (!down.empty())
        out += fmt::format("{} {} {}. ", who, broke ? "broke and pocketed" : "pocketed",
                           ball_list(down));
    else if (broke)
        out += fmt::format("{} broke: nothing dropped. ", who);
    else if (!r.verdict.foul)
        out += fmt::format("{} pocketed nothing. ", who);
    if (r.verdict.break_result == rules::BreakResult::illegal) out += "Illegal break. ";
    if (r.verdict.foul) {
        std::string list;
        for (rules::Foul f : r.verdict.fouls) list += (list.empty() ? "" : "; ") + foul_words(f);
        out += fmt::format("Foul by {}: {}. ", who, list);
    }
    out += call_words(session, r, down);
    if (!r.verdict.respot.empty()) out += fmt::format("Spotted: {}. ", ball_list(r.verdict.respot));
    if (r.verdict.game_over && r.verdict.winner)
        out += fmt::format("{} wins the game.", session.name(*r.verdict.winner));
    while (!out.empty() && out.back() == ' ') out.pop_back();
    return out;
}

std::vector<std::string> info_lines(const game::Session& s, const rules::Call& call) {
    std::vector<std::string> lines;
    const rules::GameState& st = s.state();
    const bool eight = s.config().game == rules::Game::eight_ball;
    if (s.phase() == game::Phase::game_over) {
        const rules::Player w = *s.winner();
        lines.push_back(fmt::format("{} wins!", s.name(w)));
        lines.push_back(fmt::format("Games: {} {} - {} {}", s.name(rules::Player::A), s.score()[0],
                                    s.score()[1], s.name(rules::Player::B)));
        lines.push_back("Press Restart for the next game.");
        return lines;
    }
    if (std::optional<rules::Choice> c = s.choice()) {
        lines.push_back(fmt::format("{} to choose:", s.name(c->by)));
        return lines;
    }
    const std::string& who = s.name(st.shooter);
    if (st.shot == rules::Shot::break_shot) {
        lines.push_back(fmt::format("{} to break", who));
    } else {
        lines.push_back(fmt::format("{}'s turn", who));
    }
    if (eight) {
        if (std::optional<rules::Group> g = st.group(st.shooter))
            lines.push_back(rules::on_the_eight(st)
                                ? fmt::format("Group: {}, now on the 8", group_words(*g))
                                : fmt::format("Group: {}", group_words(*g)));
        else if (st.shot != rules::Shot::break_shot)
            lines.push_back("Open table: any ball but the 8");
    } else {
        lines.push_back(fmt::format("Ball to hit: the {}", lowest_on_table(st)));
    }
    switch (s.ball_in_hand()) {
        case rules::BallInHand::anywhere:
            lines.push_back("Ball in hand: drag the cue ball anywhere");
            break;
        case rules::BallInHand::kitchen:
            lines.push_back("Ball in hand: drag the cue ball behind the head string");
            break;
        case rules::BallInHand::none:
            break;
    }
    if (eight && st.shot != rules::Shot::break_shot && rules::call_counts(s.config().options, st)) {
        if (call.is_ball())
            lines.push_back(
                fmt::format("Call: the {} in the {} pocket", call.ball, pocket_words(call.pocket)));
        else if (call.is_safety())
            lines.push_back("Call: safety");
        else
            lines.push_back("Call: none (click a ball, then a pocket)");
    }
    if (st.shot == rules::Shot::push_out) lines.push_back("Push-out declared");
    if (s.warned(st.shooter))
        lines.push_back(fmt::format("Warning: {} has two fouls; a third loses the game", who));
    return lines;
}

}  // namespace app
