#include "rules/game_state.hpp"

namespace rules {

int highest_ball(Game game) {
    return game == Game::eight_ball ? 15 : 9;
}

GameState initial_state(Game game, Player breaker) {
    GameState s;
    s.shooter = breaker;
    s.breaker = breaker;
    s.shot = Shot::break_shot;
    for (int id = 1; id <= highest_ball(game); ++id) s.on_table.insert(id);
    s.cue_ball = CueBall::in_hand_kitchen;
    return s;
}

bool on_the_eight(const GameState& s) {
    std::optional<Group> mine = s.group(s.shooter);
    if (!mine) return false;
    for (int id : s.on_table)
        if (group_of(id) == mine) return false;
    return true;
}

bool push_out_allowed(Game game, const GameState& s) {
    return game == Game::nine_ball && s.shot == Shot::after_break;
}

}  // namespace rules
