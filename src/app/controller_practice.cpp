// The controller in practice mode (game/practice.hpp), on any game's table: the practice holds
// the position and plays the shots; the session mirrors the position (A always to shoot, the
// cue ball on the table) so that drawing, aiming and the aim guide work as in a game.
#include <fmt/format.h>

#include "app/controller.hpp"
#include "physics/markings.hpp"

namespace app {

namespace {

game::Session mirror_of(const game::Practice& p, const game::Config& was) {
    game::Config c;
    c.game = p.pool_game();
    c.table = p.table_spec();
    c.params = p.params();
    c.names = {"You", "You"};
    c.seed = was.seed;
    rules::GameState s = rules::initial_state(c.game, rules::Player::A);
    s.shot = rules::Shot::normal;
    s.cue_ball = rules::CueBall::on_table;
    s.positions = p.balls();
    s.on_table.clear();
    for (const auto& [id, pos] : p.balls())
        if (id != 0) s.on_table.insert(id);
    return game::Session::at_position(std::move(c), std::move(s));
}

std::string practice_words(const game::Practice& p, const physics::Shot& shot) {
    std::vector<std::string> down;
    for (const physics::BallState& b : shot.final_states())
        if (b.motion == physics::Motion::pocketed)
            down.push_back(b.id == 0 ? fmt::format("the cue ball (back {})", p.return_words())
                                     : "the " + p.ball_name(b.id));
    if (down.empty()) return "Nothing was pocketed.";
    return fmt::format("Pocketed {}.", fmt::join(down, ", "));
}

}  // namespace

void Controller::start_practice(game::Practice practice, ControllerOptions options) {
    options.players = {"human", "human"};
    game::Config was = session_.config();
    was.seed = options.seed;
    replace(mirror_of(practice, was), std::move(options));
    practice_ = std::move(practice);
    begin_turn();
}

void Controller::mirror_practice() {
    session_ = mirror_of(*practice_, session_.config());
}

void Controller::play_practice(const physics::Stroke& stroke) {
    const physics::Shot* shot = nullptr;
    try {
        shot = &practice_->play(stroke);
    } catch (const std::invalid_argument& e) {
        refusal_ = e.what();
        return;
    }
    start_playback(*shot, info());
}

void Controller::finish_practice_shot() {
    last_words_ = practice_words(*practice_, playback_.shot());
    mirror_practice();
    begin_turn();
}

bool Controller::hint_available() const {
    // The pool AI plays the pool tables only; snooker's and three-cushion's players need a
    // match's state (the ball on, the scores), which practice has not.
    return !practice_ || practice_->on_pool_table();
}

std::vector<int> Controller::practice_targets() const {
    std::vector<int> reds, all;
    for (const auto& [id, pos] : practice_->balls()) {
        if (id == 0) continue;
        all.push_back(id);
        if (physics::is_red(id)) reds.push_back(id);
    }
    // From the D, the reds rather than a baulk colour; three-cushion: the red, as the opening.
    if (practice_->game() == physics::RackType::three_cushion &&
        practice_->balls().count(physics::carom_ball::red))
        return {physics::carom_ball::red};
    return practice_->game() == physics::RackType::snooker && !reds.empty() ? reds : all;
}

bool Controller::move_ball(int id, physics::Vec2 pos) {
    if (!practice_ || !human_to_act()) return false;
    if (std::optional<std::string> why = practice_->check_move(id, pos)) {
        refusal_ = *why;
        return false;
    }
    practice_->move(id, pos);
    refusal_.clear();
    mirror_practice();
    refresh_preview();
    return true;
}

void Controller::try_again() {
    if (!practice_ || busy() || !practice_->can_try_again()) return;
    practice_->try_again();
    mirror_practice();
    playback_.clear();
    orientations_.reset();
    last_words_ = "The position before the last shot is back.";
    refusal_.clear();
    begin_turn();
}

}  // namespace app
