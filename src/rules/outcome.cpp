#include "rules/outcome.hpp"

#include <utility>

namespace rules {

GameState table_after(const GameState& s, const ShotFacts& f) {
    GameState next = s;
    for (const PocketedBall& p : f.pocketed) next.on_table.erase(p.ball);
    for (int id : f.off_table) next.on_table.erase(id);
    next.call = Call::nothing();
    next.shot = Shot::normal;
    next.cue_ball = f.cue_ball_lost() ? CueBall::in_hand : CueBall::on_table;
    return next;
}

Verdict verdict_with(const FoulList& fouls) {
    Verdict v;
    v.fouls = fouls.canonical();
    v.foul = !v.fouls.empty();
    return v;
}

void next_turn(Verdict& v, GameState next, Player shooter, bool keeps) {
    next.shooter = keeps ? shooter : other(shooter);
    v.turn_passes = !keeps;
    v.next_shooter = next.shooter;
    v.ball_in_hand = BallInHand::none;
    v.group_a = next.group_a;
    v.state = std::move(next);
}

void ball_in_hand_to_opponent(Verdict& v, GameState next, Player shooter, BallInHand where) {
    next.shooter = other(shooter);
    next.cue_ball = where == BallInHand::kitchen ? CueBall::in_hand_kitchen : CueBall::in_hand;
    v.turn_passes = true;
    v.next_shooter = next.shooter;
    v.ball_in_hand = where;
    v.group_a = next.group_a;
    v.state = std::move(next);
}

void offer_choice(Verdict& v, GameState next, Choice choice, bool turn_passes, BallInHand where) {
    if (where == BallInHand::kitchen) next.cue_ball = CueBall::in_hand_kitchen;
    if (where == BallInHand::anywhere) next.cue_ball = CueBall::in_hand;
    v.turn_passes = turn_passes;
    v.next_shooter.reset();
    v.ball_in_hand = where;
    v.group_a = next.group_a;
    v.choice = std::move(choice);
    v.state = std::move(next);
}

void end_game(Verdict& v, GameState next, const GameState& before, Player winner) {
    v.game_over = true;
    v.winner = winner;
    v.turn_passes = winner != before.shooter;
    v.next_shooter.reset();
    v.ball_in_hand = BallInHand::none;
    v.group_a = before.group_a;
    v.respot.clear();
    v.choice.reset();
    next.group_a = before.group_a;
    v.state = std::move(next);
}

}  // namespace rules
