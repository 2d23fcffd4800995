#include "rules/judge.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <stdexcept>
#include <string>

#include "rules/eight_ball.hpp"
#include "rules/names.hpp"
#include "rules/nine_ball.hpp"
#include "rules/shot_facts.hpp"
#include "rules/spotting.hpp"

namespace rules {

namespace {

// The positions before the next shot: the start positions, moved to each ball's last position
// in the events (a complete event log ends every ball's motion with a transition to rest);
// balls no longer on the table, and a cue ball in hand, dropped; spotted balls placed.
std::map<int, physics::Vec2> positions_after(const GameState& before,
                                             std::span<const physics::Event> events,
                                             const Verdict& v, const TableSize& table) {
    std::map<int, physics::Vec2> pos = before.positions;
    for (const physics::Event& e : events) {
        for (int k = 0; k < e.ball_count && k < 2; ++k) {
            const physics::EventBall& b = e.balls[static_cast<std::size_t>(k)];
            if (std::isfinite(b.pos.x) && std::isfinite(b.pos.y)) pos[b.id] = b.pos;
        }
    }
    const GameState& next = v.state;
    std::erase_if(pos, [&](const auto& entry) {
        const int id = entry.first;
        const bool respotted = std::find(v.respot.begin(), v.respot.end(), id) != v.respot.end();
        if (id == 0) return next.cue_ball != CueBall::on_table;
        return respotted || !next.has(id);
    });
    for (int id : v.respot) pos[id] = spot_position(pos, table);
    return pos;
}

bool offered(const Verdict& v, ChoiceOption option) {
    return v.choice && std::find(v.choice->options.begin(), v.choice->options.end(), option) !=
                           v.choice->options.end();
}

Resolution rerack(const Ruleset& rules, const GameState& now, Player breaker) {
    Resolution r;
    r.state = initial_state(rules.game, breaker);
    r.state.fouls_in_row = now.fouls_in_row;
    r.state.warned = now.warned;
    r.rerack = true;
    r.ball_in_hand = BallInHand::kitchen;
    return r;
}

}  // namespace

Verdict judge(const Ruleset& rules, const GameState& s, std::span<const physics::Event> events) {
    const double head_string_x = rules.table.head_string_x();
    const ShotFacts facts = distill(events, head_string_x);
    Verdict v = rules.game == Game::eight_ball
                    ? judge_eight_ball(rules.options, s, facts, head_string_x)
                    : judge_nine_ball(s, facts, head_string_x);
    v.state.positions = positions_after(s, events, v, rules.table);
    return v;
}

Resolution resolve_choice(const Ruleset& rules, const Verdict& v, ChoiceOption option) {
    if (!offered(v, option))
        throw std::invalid_argument("resolve_choice: option \"" + std::string(name(option)) +
                                    "\" is not offered by the verdict");
    const Player chooser = v.choice->by;
    Resolution r{v.state, false, v.ball_in_hand};
    switch (option) {
        case ChoiceOption::accept_table:
        case ChoiceOption::spot_8_and_continue:
        case ChoiceOption::spot_8_with_kitchen_ball_in_hand:
        case ChoiceOption::shoot:
            break;  // what the verdict's state describes
        case ChoiceOption::kitchen_ball_in_hand:
            r.state.cue_ball = CueBall::in_hand_kitchen;
            r.state.positions.erase(0);
            r.ball_in_hand = BallInHand::kitchen;
            break;
        case ChoiceOption::pass_back:
            r.state.shooter = other(chooser);
            break;
        case ChoiceOption::rerack_and_break:
        case ChoiceOption::rebreak:
            return rerack(rules, v.state, chooser);
        case ChoiceOption::rerack_offender_breaks:
            return rerack(rules, v.state, v.state.breaker);
    }
    return r;
}

Resolution stalemate(const Ruleset& rules, const GameState& s) {
    return rerack(rules, s, s.breaker);
}

}  // namespace rules
