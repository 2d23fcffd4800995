#include "game/session.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <utility>

#include "game/state_json.hpp"
#include "physics/layout.hpp"
#include "physics/rack.hpp"
#include "physics/simulate.hpp"
#include "rules/names.hpp"
#include "rules/spotting.hpp"

namespace game {

namespace {

physics::Table checked_table(const Config& c) {
    if (std::optional<std::string> e = physics::validate_table_spec(c.table, c.params.ball_radius))
        throw std::invalid_argument("game::Session: table: " + *e);
    if (!c.table.bounded) throw std::invalid_argument("game::Session: table: must have cushions");
    return physics::build_table(c.table);
}

// Whether every option of the verdict's choice gives the same next shot (e.g. after a scratch
// on a legal 8-ball break, the table as it lies is already ball in hand in the kitchen): then
// there is nothing to choose (docs/game.md, "Choices").
bool options_lead_to_one_position(const rules::Ruleset& rules, const rules::Verdict& v) {
    std::optional<std::string> first;
    for (rules::ChoiceOption o : v.choice->options) {
        const rules::Resolution r = rules::resolve_choice(rules, v, o);
        if (r.rerack) return false;
        const std::string position =
            to_json(r.state).dump() + std::to_string(static_cast<int>(r.ball_in_hand));
        if (first && *first != position) return false;
        first = position;
    }
    return true;
}

std::string options_list(const rules::Choice& c) {
    std::string list;
    for (rules::ChoiceOption o : c.options)
        list += fmt::format("{}\"{}\"", list.empty() ? "" : ", ", rules::name(o));
    return list;
}

// After a truncated simulation (the event cap) the balls' last event positions are not one
// instant; use the shot's final snapshot, and spot again the balls the verdict spots.
void settle_truncated(rules::Verdict& v, const physics::Shot& shot, const rules::TableSize& size) {
    std::map<int, physics::Vec2>& pos = v.state.positions;
    for (const physics::BallState& b : shot.final_states())
        if (pos.count(b.id) && b.motion != physics::Motion::pocketed) pos[b.id] = b.pos;
    for (int id : v.respot) pos.erase(id);
    for (int id : v.respot) pos[id] = rules::spot_position(pos, size);
}

}  // namespace

std::uint64_t rack_seed(std::uint64_t session_seed, int game, int rack) {
    physics::SplitMix64 mix(session_seed);
    std::uint64_t s = mix.next();
    s ^= 0x9e3779b97f4a7c15ULL * static_cast<std::uint64_t>(game + 1);
    physics::SplitMix64 by_game(s);
    s = by_game.next() ^ (0xbf58476d1ce4e5b9ULL * static_cast<std::uint64_t>(rack + 1));
    return physics::SplitMix64(s).next();
}

Session::Session(Config config, Restored)
    : config_(std::move(config)),
      table_(checked_table(config_)),
      ruleset_{config_.game,
               config_.options,
               {config_.table.length, config_.table.width, config_.params.ball_radius}} {}

Session::Session(Config config) : Session(std::move(config), Restored{}) {
    rack(rules::initial_state(config_.game, breaker_of_game(0)));
}

Session Session::at_position(Config config, rules::GameState state) {
    Session s(std::move(config), Restored{});
    s.state_ = std::move(state);
    return s;
}

rules::Player Session::breaker_of_game(int n) const {
    return n % 2 == 0 ? config_.first_breaker : rules::other(config_.first_breaker);
}

void Session::rack(rules::GameState s) {
    const physics::RackType type = config_.game == rules::Game::eight_ball
                                       ? physics::RackType::eight_ball
                                       : physics::RackType::nine_ball;
    const std::vector<physics::BallState> balls = physics::rack(
        type, table_, config_.params, rack_seed(config_.seed, game_number_, rack_number_));
    s.positions.clear();
    for (const physics::BallState& b : balls)
        if (b.id != 0) s.positions[b.id] = b.pos;
    s.cue_ball = rules::CueBall::in_hand_kitchen;
    state_ = std::move(s);
    pocketed_.clear();
}

Phase Session::phase() const {
    if (winner_) return Phase::game_over;
    if (pending_) return Phase::choose;
    if (state_.cue_ball != rules::CueBall::on_table && !state_.positions.count(0))
        return Phase::place_cue_ball;
    return Phase::shoot;
}

std::optional<rules::Player> Session::to_act() const {
    if (winner_) return std::nullopt;
    if (pending_) return pending_->choice->by;
    return state_.shooter;
}

rules::BallInHand Session::ball_in_hand() const {
    switch (state_.cue_ball) {
        case rules::CueBall::in_hand:
            return rules::BallInHand::anywhere;
        case rules::CueBall::in_hand_kitchen:
            return rules::BallInHand::kitchen;
        case rules::CueBall::on_table:
            break;
    }
    return rules::BallInHand::none;
}

std::vector<physics::BallState> balls_at_rest(const rules::GameState& state) {
    return physics::balls_at_rest(state.positions);
}

std::vector<physics::BallState> Session::balls() const {
    return balls_at_rest(state_);
}

std::optional<rules::Choice> Session::choice() const {
    if (!pending_) return std::nullopt;
    return pending_->choice;
}

bool Session::push_out_available() const {
    return phase() == Phase::shoot &&
           (rules::push_out_allowed(config_.game, state_) || state_.shot == rules::Shot::push_out);
}

std::optional<std::string> Session::check_cue_ball(physics::Vec2 pos) const {
    if (winner_) return "the game is over: restart() starts the next one";
    if (pending_)
        return fmt::format("a choice is pending: {} must choose first ({})",
                           name(pending_->choice->by), options_list(*pending_->choice));
    if (state_.cue_ball == rules::CueBall::on_table)
        return "no ball in hand: the cue ball is played from where it lies";
    if (!std::isfinite(pos.x) || !std::isfinite(pos.y))
        return "the position must be two finite numbers";
    const double R = config_.params.ball_radius;
    const double head_string = table_.length() / 4.0;
    if (state_.cue_ball == rules::CueBall::in_hand_kitchen && !(pos.x < head_string))
        return fmt::format(
            "ball in hand in the kitchen: place the cue ball behind the head string "
            "(x < {} m; x = {} m)",
            head_string, pos.x);
    if (!table_.on_surface(pos, R))
        return fmt::format(
            "off the playing surface: the cue ball's centre must lie at least R = {} m inside "
            "the cushions",
            R);
    for (const auto& [id, p] : state_.positions) {
        if (id == 0) continue;
        const double d = physics::norm(p - pos);
        if (d < 2.0 * R - physics::overlap_tolerance)
            return fmt::format(
                "the cue ball would overlap ball {} (centres {:.4f} m apart; at least 2R = {} m)",
                id, d, 2.0 * R);
    }
    return std::nullopt;
}

void Session::place_cue_ball(physics::Vec2 pos) {
    if (std::optional<std::string> why = check_cue_ball(pos)) throw Refused(*why);
    state_.positions[0] = pos;
}

void Session::require_shooting(const char* action) const {
    if (winner_) throw Refused(fmt::format("cannot {}: the game is over", action));
    if (pending_)
        throw Refused(fmt::format("cannot {}: a choice is pending: {} must choose first ({})",
                                  action, name(pending_->choice->by),
                                  options_list(*pending_->choice)));
}

void Session::set_call(const rules::Call& call) {
    require_shooting("call");
    using Kind = rules::Call::Kind;
    if (call.kind != Kind::none) {
        if (config_.game == rules::Game::nine_ball)
            throw Refused("9-ball has no calls: the call must be nothing");
        if (state_.shot == rules::Shot::break_shot) throw Refused("nothing is called on the break");
    }
    if (call.kind == Kind::ball) {
        if (!state_.has(call.ball))
            throw Refused(fmt::format("ball {} is not on the table", call.ball));
        if (call.pocket < 0 || call.pocket > 5)
            throw Refused(
                fmt::format("unknown pocket {}: pockets are 0 (SW) to 5 (NE)", call.pocket));
        if (call.ball == 8 && !rules::on_the_eight(state_))
            throw Refused("the 8 can be called only once the shooter's group is cleared");
    }
    state_.call = call;
}

void Session::set_push_out(bool declare) {
    require_shooting("declare a push-out");
    if (state_.shot == rules::Shot::push_out) {
        if (!declare) state_.shot = rules::Shot::after_break;
        return;
    }
    if (!declare) return;
    if (!rules::push_out_allowed(config_.game, state_))
        throw Refused(
            "a push-out may be declared only in 9-ball, on the shot right after a break "
            "without a foul");
    if (phase() != Phase::shoot) throw Refused("place the cue ball first");
    state_.shot = rules::Shot::push_out;
}

void Session::record_pocketed(const rules::GameState& before, const ShotSummary& summary,
                              const rules::Verdict& v) {
    auto listed = [&](int id) {
        return std::any_of(pocketed_.begin(), pocketed_.end(),
                           [id](const Pocketed& p) { return p.ball == id; });
    };
    for (const BallDown& d : summary.down)
        if (d.ball != 0 && before.has(d.ball) && !v.state.has(d.ball) && !listed(d.ball))
            pocketed_.push_back({d.ball, d.pocket, before.shooter});
    for (int id : before.on_table)  // a ball the events do not show leaving (none expected)
        if (!v.state.has(id) && !listed(id)) pocketed_.push_back({id, -1, before.shooter});
    std::erase_if(pocketed_, [&](const Pocketed& p) { return v.state.has(p.ball); });
}

const ShotRecord& Session::play(const physics::Stroke& stroke) {
    require_shooting("play");
    if (phase() == Phase::place_cue_ball)
        throw Refused("ball in hand: place the cue ball first (place_cue_ball)");
    const bool finite = std::isfinite(stroke.speed) && std::isfinite(stroke.heading_deg) &&
                        std::isfinite(stroke.side) && std::isfinite(stroke.top) &&
                        std::isfinite(stroke.elevation_deg);
    if (!finite) throw Refused("the stroke's numbers must be finite");
    if (stroke.speed < 0.0 || stroke.speed > max_stroke_speed)
        throw Refused(fmt::format("stroke speed {} m/s: must be from 0 to {}", stroke.speed,
                                  max_stroke_speed));
    if (std::fabs(stroke.side) > 1.0 || std::fabs(stroke.top) > 1.0)
        throw Refused("the tip offsets (side, top) must be from -1 to 1 (fractions of R)");
    if (stroke.elevation_deg < 0.0 || stroke.elevation_deg > 90.0)
        throw Refused("the cue elevation must be from 0 to 90 degrees");

    const std::vector<physics::BallState> layout = balls();
    physics::Shot shot = physics::simulate(table_, config_.params, layout, &stroke);
    rules::Verdict v = rules::judge(ruleset_, state_, shot.events());
    if (shot.truncated()) settle_truncated(v, shot, ruleset_.table);

    ShotRecord record;
    record.rack = rack_number_;
    record.before = state_;
    record.stroke = stroke;
    record.summary = summarize(shot.events(), shot.rest_time(), shot.truncated());
    if (config_.keep_events) record.events = shot.events();
    record.verdict = v;

    record_pocketed(state_, record.summary, v);
    state_ = v.state;
    if (v.game_over) {
        winner_ = v.winner;
        ++score_[rules::index(*v.winner)];
    } else if (v.choice) {
        pending_ = std::move(v);
    }
    history_.push_back(std::move(record));
    last_shot_ = std::move(shot);
    if (pending_ && options_lead_to_one_position(ruleset_, *pending_))
        choose(pending_->choice->options.front());
    return history_.back();
}

void Session::choose(rules::ChoiceOption option) {
    if (!pending_) throw Refused("no choice is pending");
    const rules::Choice& c = *pending_->choice;
    if (std::find(c.options.begin(), c.options.end(), option) == c.options.end())
        throw Refused(fmt::format("\"{}\" is not offered: {} may choose {}", rules::name(option),
                                  name(c.by), options_list(c)));
    rules::Resolution r = rules::resolve_choice(ruleset_, *pending_, option);
    if (!history_.empty()) history_.back().choice = option;
    pending_.reset();
    if (r.rerack) {
        ++rack_number_;
        rack(std::move(r.state));
    } else {
        state_ = std::move(r.state);
    }
}

void Session::declare_stalemate() {
    if (winner_) throw Refused("cannot declare a stalemate: the game is over");
    rules::Resolution r = rules::stalemate(ruleset_, state_);
    pending_.reset();
    ++rack_number_;
    rack(std::move(r.state));
}

void Session::restart() {
    if (history_.empty() && !winner_) {  // nothing played: the same game, racked again
        pending_.reset();
        rack_number_ = 0;
        rack(rules::initial_state(config_.game, breaker_of_game(game_number_)));
        return;
    }
    ++game_number_;
    rack_number_ = 0;
    winner_.reset();
    pending_.reset();
    history_.clear();
    last_shot_.reset();
    rack(rules::initial_state(config_.game, breaker_of_game(game_number_)));
}

}  // namespace game
