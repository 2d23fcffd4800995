#include "game/snooker_session.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <stdexcept>
#include <utility>

#include "game/session.hpp"
#include "physics/layout.hpp"
#include "physics/rack.hpp"
#include "physics/simulate.hpp"

namespace game {

namespace sb = physics::snooker_ball;

namespace {

physics::Table checked_table(const SnookerConfig& c) {
    if (std::optional<std::string> e = physics::validate_table_spec(c.table, c.params.ball_radius))
        throw std::invalid_argument("game::SnookerSession: table: " + *e);
    if (!c.table.pockets || !c.table.bounded)
        throw std::invalid_argument("game::SnookerSession: table: snooker needs pockets");
    if (c.best_of < 1 || c.best_of > 35 || c.best_of % 2 == 0)
        throw std::invalid_argument("game::SnookerSession: best_of: an odd number from 1 to 35");
    return physics::build_table(c.table);
}

}  // namespace

std::string snooker_ball_name(int id) {
    static constexpr std::array<const char*, 6> colours{"yellow", "green", "brown",
                                                        "blue",   "pink",  "black"};
    if (id == sb::cue) return "the cue ball";
    if (physics::is_red(id)) return "red";
    if (physics::is_colour(id)) return colours[static_cast<std::size_t>(id - sb::yellow)];
    return fmt::format("ball {}", id);
}

std::string ball_on_name(rules::BallOn on) {
    if (on == rules::BallOn::red) return "a red";
    if (on == rules::BallOn::colour) return "a colour";
    return "the " + snooker_ball_name(sb::yellow + static_cast<int>(on) -
                                      static_cast<int>(rules::BallOn::yellow));
}

SnookerSession::SnookerSession(SnookerConfig config, Restored)
    : config_(std::move(config)),
      table_(checked_table(config_)),
      marks_{physics::snooker_markings(table_), config_.params.ball_radius} {}

SnookerSession::SnookerSession(SnookerConfig config)
    : SnookerSession(std::move(config), Restored{}) {
    set_up_frame();
}

rules::Player SnookerSession::breaker_of_frame(int n) const {
    return n % 2 == 0 ? config_.first_breaker : rules::other(config_.first_breaker);
}

void SnookerSession::set_up_frame() {
    rules::SnookerState s;
    s.shooter = breaker_of_frame(frame_);
    s.cue_ball = rules::CueBall::in_hand;
    for (const physics::BallState& b : physics::snooker_rack(table_, config_.params))
        if (b.id != sb::cue) {
            s.positions[b.id] = b.pos;
            s.on_table.insert(b.id);
        }
    state_ = s;
    before_ = s;
    choices_.clear();
    pending_misses_ = 0;
    frame_winner_.reset();
    last_.reset();
    last_shot_.reset();
}

MatchPhase SnookerSession::phase() const {
    if (match_winner()) return MatchPhase::match_over;
    if (frame_winner_) return MatchPhase::frame_over;
    if (!choices_.empty()) return MatchPhase::choose;
    if (state_.cue_ball == rules::CueBall::in_hand && !state_.positions.count(sb::cue))
        return MatchPhase::place_cue_ball;
    return MatchPhase::shoot;
}

std::optional<rules::Player> SnookerSession::match_winner() const {
    for (rules::Player p : {rules::Player::A, rules::Player::B})
        if (frames_[rules::index(p)] >= frames_needed()) return p;
    return std::nullopt;
}

std::optional<rules::Player> SnookerSession::to_act() const {
    if (frame_winner_) return std::nullopt;
    if (!choices_.empty()) return rules::other(before_.shooter);
    return state_.shooter;
}

std::vector<physics::BallState> SnookerSession::balls() const {
    return physics::balls_at_rest(state_.positions);
}

bool SnookerSession::may_nominate() const {
    return state_.colour_on || state_.free_ball;
}

void SnookerSession::require_striker(const char* action) const {
    const MatchPhase ph = phase();
    if (ph == MatchPhase::frame_over || ph == MatchPhase::match_over)
        throw Refused(fmt::format("You can't {}: the frame is over.", action));
    if (ph == MatchPhase::choose)
        throw Refused(fmt::format("You can't {} yet: {} chooses first after the foul.", action,
                                  name(*to_act())));
}

std::optional<std::string> SnookerSession::check_cue_ball(physics::Vec2 pos) const {
    if (state_.cue_ball != rules::CueBall::in_hand) return "The cue ball is not in hand.";
    if (!marks_.marks.in_d(pos)) return "The cue ball in hand goes in the D.";
    if (pos.x < config_.params.ball_radius) return "The cue ball must go on the cloth.";
    const double R = config_.params.ball_radius;
    for (const auto& [id, p] : state_.positions)
        if (id != sb::cue && physics::norm(p - pos) < 2.0 * R)
            return fmt::format("The cue ball can't go on top of the {}.", snooker_ball_name(id));
    return std::nullopt;
}

void SnookerSession::place_cue_ball(physics::Vec2 pos) {
    require_striker("place the cue ball");
    if (std::optional<std::string> why = check_cue_ball(pos)) throw Refused(*why);
    state_.positions[sb::cue] = pos;
}

void SnookerSession::nominate(std::optional<int> ball) {
    require_striker("nominate");
    if (!ball) {
        state_.nominated.reset();
        return;
    }
    if (!may_nominate())
        throw Refused(
            fmt::format("There is nothing to nominate: {} is on.", ball_on_name(ball_on())));
    if (!state_.has(*ball))
        throw Refused(fmt::format("The {} is not on the table.", snooker_ball_name(*ball)));
    if (state_.colour_on && !physics::is_colour(*ball))
        throw Refused("After a red, nominate a colour.");
    state_.nominated = ball;
}

const rules::SnookerVerdict& SnookerSession::play(const physics::Stroke& stroke) {
    require_striker("play");
    if (phase() == MatchPhase::place_cue_ball) throw Refused("Place the cue ball in the D first.");
    if (!(stroke.speed > 0.0 && stroke.speed <= max_stroke_speed))
        throw Refused(fmt::format("A stroke's speed is from 0 to {} m/s.", max_stroke_speed));
    rules::SnookerState s = state_;
    if (s.free_ball && !s.nominated) s.free_ball = false;  // the free ball declined
    physics::Stroke k = stroke;
    k.ball = sb::cue;
    physics::Shot shot =
        physics::simulate(table_, config_.params, physics::balls_at_rest(s.positions), &k);
    rules::SnookerVerdict v = rules::judge_snooker(config_.options, marks_, s, shot.events());
    before_ = s;
    state_ = v.state;
    choices_.clear();
    if (v.may_ask_to_play_again && !v.frame_over) {
        choices_ = {rules::AfterFoul::play, rules::AfterFoul::play_again};
        if (v.miss) choices_.push_back(rules::AfterFoul::replace);
    }
    pending_misses_ = v.misses;
    if (v.frame_over) {
        frame_winner_ = v.winner;
        if (v.winner) ++frames_[rules::index(*v.winner)];
    }
    last_shot_ = std::move(shot);
    last_ = std::move(v);
    return *last_;
}

void SnookerSession::choose(rules::AfterFoul choice) {
    if (choices_.empty()) throw Refused("There is no choice to make now.");
    if (std::find(choices_.begin(), choices_.end(), choice) == choices_.end())
        throw Refused(choice == rules::AfterFoul::replace
                          ? "The balls are replaced only after a miss."
                          : "That choice is not open now.");
    rules::SnookerVerdict v;
    v.state = state_;
    v.may_ask_to_play_again = true;
    v.miss =
        std::find(choices_.begin(), choices_.end(), rules::AfterFoul::replace) != choices_.end();
    v.misses = pending_misses_;
    state_ = rules::resolve_after_foul(v, before_, choice);
    choices_.clear();
}

void SnookerSession::next_frame() {
    if (!frame_winner_ && phase() != MatchPhase::frame_over)
        throw Refused("The frame is not over yet.");
    if (match_winner()) throw Refused("The match is over.");
    ++frame_;
    set_up_frame();
}

}  // namespace game
