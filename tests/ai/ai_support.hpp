// Positions for the AI's tests: a 9 ft table with default physics and a state built by hand.
#pragma once

#include <map>
#include <set>

#include "ai/internal/position.hpp"
#include "game/player.hpp"
#include "physics/shot.hpp"
#include "physics/simulate.hpp"
#include "rules/judge.hpp"

namespace ai_test {

inline ai::Position position(rules::Game game, std::set<int> on_table,
                             std::map<int, physics::Vec2> positions,
                             rules::CueBall cue = rules::CueBall::on_table) {
    ai::Position p;
    p.ruleset.game = game;
    p.table = physics::build_table(physics::TableSpec{});
    p.state = rules::initial_state(game, rules::Player::A);
    p.state.shot = rules::Shot::normal;
    p.state.on_table = std::move(on_table);
    p.state.positions = std::move(positions);
    p.state.cue_ball = cue;
    return p;
}

/// The verdict on playing `d` without noise from `pos`.
inline rules::Verdict play(const ai::Position& pos, const game::Decision& d) {
    rules::GameState s = pos.state;
    if (d.cue_pos) s.positions[0] = *d.cue_pos;
    s.call = d.call;
    if (d.push_out) s.shot = rules::Shot::push_out;
    const physics::Shot shot =
        physics::simulate(pos.table, pos.params, ai::layout(s, s.positions.at(0)), &d.stroke);
    return rules::judge(pos.ruleset, s, shot.events());
}

}  // namespace ai_test
