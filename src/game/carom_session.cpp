#include "game/carom_session.hpp"

#include <fmt/format.h>

#include <stdexcept>
#include <utility>

#include "game/session.hpp"
#include "physics/rack.hpp"
#include "physics/simulate.hpp"

namespace game {

namespace {

physics::Table checked_table(const CaromConfig& c) {
    if (std::optional<std::string> e = physics::validate_table_spec(c.table, c.params.ball_radius))
        throw std::invalid_argument("game::CaromSession: table: " + *e);
    if (!c.table.bounded)
        throw std::invalid_argument("game::CaromSession: table: must have cushions");
    if (c.options.target < 1 || c.options.target > 1000)
        throw std::invalid_argument("game::CaromSession: target: from 1 to 1000 points");
    return physics::build_table(c.table);
}

}  // namespace

std::string carom_ball_name(int id) {
    switch (id) {
        case physics::carom_ball::white:
            return "white";
        case physics::carom_ball::yellow:
            return "yellow";
        case physics::carom_ball::red:
            return "red";
        default:
            return fmt::format("ball {}", id);
    }
}

CaromSession::CaromSession(CaromConfig config, Restored)
    : config_(std::move(config)),
      table_(checked_table(config_)),
      spots_(physics::carom_spots(table_)) {}

CaromSession::CaromSession(CaromConfig config) : CaromSession(std::move(config), Restored{}) {
    set_up_game();
}

rules::Player CaromSession::starter_of_game(int n) const {
    return n % 2 == 0 ? config_.first_starter : rules::other(config_.first_starter);
}

void CaromSession::set_up_game() {
    rules::CaromState s;
    s.starter = s.shooter = starter_of_game(game_);
    s.innings = {0, 0};
    s.innings[rules::index(s.starter)] = 1;
    for (const physics::BallState& b : physics::carom_rack(table_)) s.positions[b.id] = b.pos;
    state_ = s;
    over_ = false;
    winner_.reset();
    last_.reset();
    last_shot_.reset();
}

std::optional<rules::Player> CaromSession::to_act() const {
    if (over_) return std::nullopt;
    return state_.shooter;
}

std::vector<physics::BallState> CaromSession::balls() const {
    return physics::balls_at_rest(state_.positions);
}

double CaromSession::average(rules::Player p) const {
    const int innings = state_.innings[rules::index(p)];
    return innings > 0 ? static_cast<double>(state_.scores[rules::index(p)]) / innings : 0.0;
}

const rules::CaromVerdict& CaromSession::play(const physics::Stroke& stroke) {
    if (over_) throw Refused("The game is over: start the next game to play on.");
    if (!(stroke.speed > 0.0 && stroke.speed <= max_stroke_speed))
        throw Refused(fmt::format("A stroke's speed is from 0 to {} m/s.", max_stroke_speed));
    physics::Stroke k = stroke;
    k.ball = cue_ball();
    physics::Shot shot = physics::simulate(table_, config_.params, balls(), &k);
    rules::CaromVerdict v = rules::judge_three_cushion(
        config_.options, spots_, config_.params.ball_radius, state_, shot.events());
    state_ = v.state;
    if (v.game_over) {
        over_ = true;
        winner_ = v.winner;
        if (v.winner) ++games_[rules::index(*v.winner)];
    }
    last_shot_ = std::move(shot);
    last_ = std::move(v);
    return *last_;
}

void CaromSession::next_game() {
    if (!over_) throw Refused("The game is not over yet.");
    ++game_;
    set_up_game();
}

}  // namespace game
