#include "ai/internal/position.hpp"

#include "game/session.hpp"
#include "physics/layout.hpp"
#include "rules/eight_ball.hpp"
#include "rules/nine_ball.hpp"

namespace ai {

Position position_of(const game::Session& session) {
    Position p{session.ruleset(), session.table(), session.config().params, session.state(),
               session.choice()};
    if (cue_in_hand(p.state)) p.state.positions.erase(0);
    return p;
}

bool cue_in_hand(const rules::GameState& s) {
    return s.cue_ball != rules::CueBall::on_table;
}

std::vector<int> target_balls(const rules::Ruleset& rules, const rules::GameState& s) {
    if (rules.game == rules::Game::nine_ball) {
        if (std::optional<int> low = rules::lowest_ball(s)) return {*low};
        return {};
    }
    const std::set<int> legal = rules::eight_ball_legal_first(s);
    return {legal.begin(), legal.end()};
}

std::optional<int> combination_first_ball(const rules::Ruleset& rules, const rules::GameState& s) {
    if (rules.game != rules::Game::nine_ball || !s.has(9)) return std::nullopt;
    const std::optional<int> low = rules::lowest_ball(s);
    if (!low || *low == 9) return std::nullopt;
    return low;
}

bool legal_first(const rules::Ruleset& rules, const rules::GameState& s, int ball) {
    if (rules.game == rules::Game::nine_ball) return rules::lowest_ball(s) == ball;
    return rules::eight_ball_legal_first(s).count(ball) != 0;
}

std::vector<physics::BallState> layout(const rules::GameState& s, physics::Vec2 cue) {
    std::vector<physics::BallState> balls;
    balls.reserve(s.on_table.size() + 1);
    physics::BallState c;
    c.pos = cue;
    balls.push_back(c);
    for (int id : s.on_table) {
        auto it = s.positions.find(id);
        if (it == s.positions.end()) continue;
        physics::BallState b;
        b.id = id;
        b.pos = it->second;
        balls.push_back(b);
    }
    return balls;
}

bool free_spot(const Position& pos, physics::Vec2 p) {
    const double R = pos.params.ball_radius;
    if (!std::isfinite(p.x) || !std::isfinite(p.y)) return false;
    if (pos.state.cue_ball == rules::CueBall::in_hand_kitchen &&
        !(p.x < pos.ruleset.table.head_string_x() - 1e-6))
        return false;
    if (!pos.table.on_surface(p, R)) return false;
    for (const auto& [id, q] : pos.state.positions)
        if (id != 0 && physics::norm(q - p) < 2.0 * R + 1e-6) return false;
    return true;
}

}  // namespace ai
