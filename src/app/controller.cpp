#include "app/controller.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <numbers>

#include "app/cue_clearance.hpp"
#include "app/match_words.hpp"
#include "app/plain_words.hpp"
#include "app/seats.hpp"
#include "game/stroke_noise.hpp"
#include "render/pockets.hpp"
#include "rules/eight_ball.hpp"
#include "rules/judge.hpp"

namespace app {

namespace {

constexpr int stalemate_after = 100;  // computer-only games: dry shots before a re-rack

std::uint64_t derive(std::uint64_t seed, std::uint64_t tag) {
    physics::SplitMix64 mix(seed ^ (0x9e3779b97f4a7c15ULL * (tag + 1)));
    return mix.next();
}

// The object balls the shooter may hit first.
std::vector<int> legal_targets(const game::Session& s) {
    const rules::GameState& st = s.state();
    if (st.on_table.empty()) return {};
    if (s.config().game == rules::Game::nine_ball) return {*st.on_table.begin()};
    if (st.shot == rules::Shot::break_shot) return {st.on_table.begin(), st.on_table.end()};
    const std::set<int> legal = rules::eight_ball_legal_first(st);
    return {legal.begin(), legal.end()};
}

// With ball in hand in the kitchen, a ball behind the head string is no target: the cue ball
// must cross the head string before it touches a ball (rules::Foul::bad_play_from_kitchen).
bool behind_head_string(const game::Session& s, physics::Vec2 p) {
    return s.ball_in_hand() == rules::BallInHand::kitchen &&
           p.x < s.ruleset().table.head_string_x();
}

bool calls_count(const game::Session& s) {
    const rules::GameState& st = s.state();
    return s.config().game == rules::Game::eight_ball && st.shot != rules::Shot::break_shot &&
           rules::call_counts(s.config().options, st);
}

}  // namespace

Controller::Controller(game::Session session, ControllerOptions options)
    : session_(std::move(session)),
      options_(std::move(options)),
      noise_rng_(derive(options_.seed, 7)) {
    for (std::size_t i = 0; i < 2; ++i)
        computers_[i] =
            make_computer(options_.players[i], derive(options_.seed, i), options_.noise);
    begin_turn();
}

Controller::~Controller() {
    stop_thinking();
}

void Controller::replace(game::Session session, ControllerOptions options) {
    stop_thinking();
    practice_.reset();
    snooker_.reset();
    carom_.reset();
    last_match_shot_.reset();
    session_ = std::move(session);
    options_ = std::move(options);
    for (std::size_t i = 0; i < 2; ++i)
        computers_[i] =
            make_computer(options_.players[i], derive(options_.seed, i), options_.noise);
    noise_rng_ = physics::SplitMix64(derive(options_.seed, 7));
    playback_.clear();
    orientations_.reset();
    settled_ = true;
    dry_shots_ = 0;
    last_words_.clear();
    begin_turn();
}

physics::Stroke Controller::stroke_of(const Aim& a) const {
    physics::Stroke k;
    k.speed = min_cue_speed + (max_cue_speed - min_cue_speed) * std::clamp(a.power, 0.0, 1.0);
    k.heading_deg = a.heading_deg;
    k.side = a.side;
    k.top = a.top;
    k.elevation_deg = a.elevation_deg;
    k.ball = cue_ball_id();
    return played(k);
}

physics::Stroke Controller::played(const physics::Stroke& stroke) const {
    const auto cue = session_.state().positions.find(stroke.ball);
    if (cue == session_.state().positions.end()) return stroke;
    return over_the_rail(session_.table(), session_.config().params.ball_radius, cue->second,
                         stroke);
}

double Controller::forced_elevation_deg() const {
    const auto cue = session_.state().positions.find(cue_ball_id());
    if (cue == session_.state().positions.end()) return 0.0;
    return rail_forced_elevation_deg(session_.table(), session_.config().params.ball_radius,
                                     cue->second, stroke_of(aim_));
}

std::vector<physics::BallState> Controller::balls_now() const {
    if (playback_.moving()) {
        std::vector<physics::BallState> out = playback_.states();
        std::erase_if(
            out, [](const physics::BallState& b) { return b.motion == physics::Motion::pocketed; });
        return out;
    }
    return session_.balls();
}

void Controller::play_shared(const physics::Stroke& stroke) {
    stop_thinking();  // the shot is the link's, whoever's seat it is
    computer_decision_.reset();
    aim_.heading_deg = stroke.heading_deg;
    aim_.power = power_of_speed(stroke.speed);
    aim_.side = stroke.side;
    aim_.top = stroke.top;
    aim_.elevation_deg = stroke.elevation_deg;
    if (snooker_ || carom_) return play_match(stroke, false);
    play(stroke);
}

bool Controller::busy() const {
    return playback_.moving() || thinking_.valid() || computer_decision_.has_value() ||
           match_thinking_.valid() || match_decision_.has_value();
}

bool Controller::human_to_act() const {
    if (busy() || !settled_) return false;
    if (snooker_ || carom_) return !match_computer_to_act();
    const std::optional<rules::Player> p = session_.to_act();
    return p && !computers_[rules::index(*p)];
}

const AimPreview* Controller::preview() const {
    if (playback_.moving() || !preview_) return nullptr;
    return &*preview_;
}

rules::Call Controller::call() const {
    if (practice_ || !calls_count(session_)) return rules::Call::nothing();
    if (computer_decision_) return computer_decision_->call;
    if (manual_call_) return *manual_call_;
    if (preview_ && preview_->first_ball && preview_->pocket && aim_foul_.empty()) {
        const std::vector<int> legal = legal_targets(session_);
        if (std::find(legal.begin(), legal.end(), *preview_->first_ball) != legal.end())
            return rules::Call::ball_in(*preview_->first_ball, *preview_->pocket);
    }
    return rules::Call::nothing();
}

// ---- Turns

void Controller::begin_turn() {
    if (snooker_ || carom_) return begin_match_turn();
    manual_call_.reset();
    preview_.reset();
    const std::optional<rules::Player> p = session_.to_act();
    if (!p) return;
    if (computers_[rules::index(*p)]) {
        launch_computer();
        return;
    }
    if (session_.phase() == game::Phase::place_cue_ball) prepare_human_ball_in_hand();
    aim_ = human_aim_;
    aim_at_target();
    refresh_preview();
}

physics::Vec2 Controller::default_cue_spot() const {
    const physics::Table& t = session_.table();
    const double R = session_.config().params.ball_radius;
    std::vector<physics::Vec2> tries;
    const auto last = session_.state().positions.find(0);
    if (last != session_.state().positions.end()) tries.push_back(last->second);
    const physics::Vec2 head = t.head_spot();
    tries.push_back({head.x - 1e-3, head.y});  // just behind the head string
    for (const physics::Vec2& p : tries)
        if (!session_.check_cue_ball(p)) return p;
    // A crowded kitchen: the free spot nearest the head spot.
    std::optional<physics::Vec2> best;
    double best_d = 1e9;
    for (double x = R; x < t.length() - R; x += R / 2)
        for (double y = R; y < t.width() - R; y += R / 2) {
            const physics::Vec2 p{x, y};
            const double d = physics::norm(p - head);
            if (d < best_d && !session_.check_cue_ball(p)) {
                best_d = d;
                best = p;
            }
        }
    return best.value_or(head);
}

void Controller::prepare_human_ball_in_hand() {
    try {
        session_.place_cue_ball(default_cue_spot());
    } catch (const game::Refused& e) {
        refusal_ = e.what();
    }
}

void Controller::aim_at_target() {
    const auto cue = session_.state().positions.find(0);
    if (cue == session_.state().positions.end()) return;
    if (practice_ && !practice_->on_pool_table()) return aim_at_open_ball(practice_targets());
    std::optional<physics::Vec2> best;
    double best_d = 1e9;
    for (int id : legal_targets(session_)) {
        const auto it = session_.state().positions.find(id);
        if (it == session_.state().positions.end() || behind_head_string(session_, it->second))
            continue;
        const double d = physics::norm(it->second - cue->second);
        if (d < best_d) {
            best_d = d;
            best = it->second;
        }
    }
    if (!best) return;
    const physics::Vec2 d = *best - cue->second;
    aim_.heading_deg = std::atan2(d.y, d.x) * 180.0 / std::numbers::pi;
}

void Controller::refresh_preview() {
    aim_foul_.clear();
    if (session_.phase() != game::Phase::shoot) {
        preview_.reset();
        return;
    }
    const std::vector<physics::BallState> balls = session_.balls();
    preview_ = preview_aim(session_.table(), session_.config().params, balls, stroke_of(aim_));
    // The rules' own verdict on the shot as aimed; only what the player can see coming is
    // said (where the cue ball meets its first ball), not what the exact simulation foresees.
    if (practice_ || carom_) return;  // no rules, no fouls; carom: no foul to see coming
    if (snooker_) {
        aim_foul_ = snooker_aim_foul(*snooker_, nomination(), preview_->events);
        return;
    }
    const rules::Verdict v = rules::judge(session_.ruleset(), session_.state(), preview_->events);
    if (v.has(rules::Foul::bad_play_from_kitchen) && preview_->first_ball)
        aim_foul_ = fmt::format(
            "Foul as aimed: the {} lies in the kitchen. From the kitchen the cue ball must "
            "cross the head string before it touches a ball.",
            *preview_->first_ball);
}

// ---- The stroke and its playback

void Controller::play(const physics::Stroke& stroke) {
    if (practice_) return play_practice(stroke);
    if (snooker_ || carom_) return play_match(stroke);
    std::vector<std::string> info_before = info_lines(session_, call());
    const game::ShotRecord* record = nullptr;
    try {
        record = &session_.play(stroke);
    } catch (const game::Refused& e) {
        refusal_ = e.what();
        computer_decision_.reset();  // never retried frame after frame
        return;
    }
    dry_shots_ = record->summary.down.empty() ? dry_shots_ + 1 : 0;
    computer_decision_.reset();
    start_playback(*session_.last_shot(), std::move(info_before));
}

void Controller::start_playback(const physics::Shot& shot, std::vector<std::string> info_before) {
    refusal_.clear();
    info_at_strike_ = std::move(info_before);
    words_at_strike_ = last_words_;
    replaying_ = false;
    preview_.reset();
    playback_.start(shot, stroke_lead);
    orientations_.begin_shot();
    at_strike_ = orientations_;
    ++shot_serial_;
    settled_ = false;
    if (options_.playback_speed <= 0.0) skip();
}

std::vector<std::string> Controller::info() const {
    if (practice_)
        return {"Practice: drag any ball with the left button",
                "Try again puts back the position "
                "before the last shot"};
    if (snooker_ || carom_) return settled_ && !replaying() ? match_info() : info_at_strike_;
    return settled_ && !replaying() ? info_lines(session_, call()) : info_at_strike_;
}

std::vector<int> Controller::tray() const {
    std::vector<int> out;
    for (const game::Pocketed& p : session_.pocketed()) out.push_back(p.ball);
    if (!playback_.moving()) return out;
    for (const physics::Event& e : playback_.shot().events())
        if (e.type == physics::EventType::pocket &&
            e.time + render::kDropSeconds > playback_.time())  // still dropping, or to come
            std::erase(out, e.ball(0));
    return out;
}

void Controller::finish_shot() {
    settled_ = true;
    if (practice_) return finish_practice_shot();
    if (snooker_ || carom_) return finish_match_shot();
    if (!session_.history().empty()) last_words_ = shot_words(session_, session_.history().back());
    const bool all_computers = computers_[0] && computers_[1];
    const game::Phase ph = session_.phase();
    if (all_computers && dry_shots_ >= stalemate_after &&
        (ph == game::Phase::shoot || ph == game::Phase::place_cue_ball)) {
        session_.declare_stalemate();
        dry_shots_ = 0;
        last_words_ += " Stalemate: the balls are racked again.";
        orientations_.reset();
    }
    begin_turn();
}

void Controller::update(double dt) {
    if (playback_.moving()) {
        playback_.advance(options_.playback_speed > 0.0 ? dt * options_.playback_speed
                                                        : playback_.end());
        orientations_.follow(playback_.shot(), playback_.time(), playback_.end());
        if (!playback_.moving() && !settled_) finish_shot();
        return;
    }
    if ((snooker_ || carom_) && update_match_computer(dt)) return;
    if (thinking_.valid() && thinking_.ready()) {
        game::Decision d;
        try {
            d = thinking_.get();
        } catch (const std::exception& e) {
            refusal_ = std::string("the computer player failed: ") + e.what();
            hinting_ = false;
            return;
        }
        if (hinting_)
            apply_hint(d);
        else
            apply_computer(d);
        return;
    }
    if (computer_decision_) {
        computer_aim_left_ -= dt;
        if (computer_aim_left_ <= 0.0 || options_.playback_speed <= 0.0) {
            const rules::Player p = *session_.to_act();
            const double scale = options_.noise * computers_[rules::index(p)]->execution_noise();
            // Played as planned: the AI's simulations don't lift the cue over the rail, so
            // lifting it here would play a stroke it never weighed (docs/app.md).
            play(game::with_noise(computer_decision_->stroke, scale, noise_rng_));
        }
    }
}

void Controller::hint() {
    if (!human_to_act() || session_.phase() != game::Phase::shoot) return;
    if (!hint_available()) {
        refusal_ = "No hint here: in practice Hint knows the pool tables only.";
        return;
    }
    const std::uint64_t seed = derive(options_.seed, 100 + static_cast<std::uint64_t>(hints_++));
    if (snooker_ || carom_) return match_hint(seed);
    hint_player_ = make_computer("ai:5", seed, options_.noise);
    game::Player* player = hint_player_.get();
    const game::Session* s = &session_;
    hinting_ = true;
    thinking_ = Thinking<game::Decision>::start([player, s] { return player->decide(*s); });
}

void Controller::apply_hint(const game::Decision& d) {
    hinting_ = false;
    if (d.cue_pos && session_.ball_in_hand() != rules::BallInHand::none) {
        try {
            session_.place_cue_ball(*d.cue_pos);
        } catch (const game::Refused&) {
            // keep the cue ball where the player put it
        }
    }
    // The hint's stroke is this shot's aim only: the player's own spin and elevation come back
    // at the next turn.
    aim_ = Aim{d.stroke.heading_deg, power_of_speed(d.stroke.speed), d.stroke.side, d.stroke.top,
               d.stroke.elevation_deg};
    if (d.call.is_ball() || d.call.is_safety()) manual_call_ = d.call;
    refresh_preview();
}

void Controller::launch_computer() {
    game::Player* player = computers_[rules::index(*session_.to_act())].get();
    const game::Session* s = &session_;
    thinking_ = Thinking<game::Decision>::start([player, s] { return player->decide(*s); });
}

void Controller::wait_for_computer() const {
    if (thinking_.valid()) thinking_.wait();
    if (match_thinking_.valid()) match_thinking_.wait();
}

void Controller::stop_thinking() {
    if (thinking_.valid()) thinking_.wait();
    thinking_ = {};
    hinting_ = false;
    computer_decision_.reset();
    if (match_thinking_.valid()) match_thinking_.wait();
    match_thinking_ = {};
    match_decision_.reset();
}

void Controller::apply_computer(const game::Decision& d) {
    try {
        if (session_.phase() == game::Phase::choose) {
            session_.choose(d.choice.value_or(session_.choice()->options.front()));
            orientations_.reset();
            begin_turn();
            return;
        }
        if (d.cue_pos) session_.place_cue_ball(*d.cue_pos);
        session_.set_call(d.call);
        if (d.push_out) session_.set_push_out(true);
    } catch (const game::Refused& e) {
        refusal_ = std::string("the computer player's decision was refused: ") + e.what();
        return;
    }
    aim_ = Aim{d.stroke.heading_deg, power_of_speed(d.stroke.speed), d.stroke.side, d.stroke.top,
               d.stroke.elevation_deg};
    refresh_preview();
    computer_decision_ = d;
    computer_aim_left_ = options_.computer_aim_seconds;
}

// ---- Human actions

void Controller::turn_aim(double delta_deg) {
    set_heading(aim_.heading_deg + delta_deg);
}

void Controller::set_heading(double deg) {
    if (!human_to_act()) return;
    aim_.heading_deg = std::remainder(deg, 360.0);
    refresh_preview();
}

void Controller::set_power(double power) {
    human_aim_.power = std::clamp(power, 0.0, 1.0);
    if (!human_to_act()) return;
    aim_.power = human_aim_.power;
    refresh_preview();
}

void Controller::set_spin(double side, double top) {
    if (!human_to_act()) return;
    aim_.side = human_aim_.side = side;
    aim_.top = human_aim_.top = top;
    refresh_preview();
}

void Controller::set_elevation(double deg) {
    if (!human_to_act()) return;
    aim_.elevation_deg = human_aim_.elevation_deg = std::clamp(deg, 0.0, 60.0);
    refresh_preview();
}

bool Controller::move_cue_ball(physics::Vec2 pos) {
    if (snooker_) {
        if (!human_to_act() || snooker_->phase() != game::MatchPhase::shoot ||
            snooker_->state().cue_ball != rules::CueBall::in_hand)
            return false;
        if (std::optional<std::string> why = snooker_->check_cue_ball(pos)) {
            refusal_ = *why;
            return false;
        }
        snooker_->place_cue_ball(pos);
        mirror_match();
        refusal_.clear();
        refresh_preview();
        return true;
    }
    if (!human_to_act() || session_.ball_in_hand() == rules::BallInHand::none) return false;
    if (std::string why = placement_words(session_, pos); !why.empty()) {
        refusal_ = std::move(why);
        return false;
    }
    session_.place_cue_ball(pos);
    refusal_.clear();
    refresh_preview();
    return true;
}

void Controller::click_table(physics::Vec2 pos) {
    if (snooker_ && human_to_act() && snooker_->may_nominate()) {  // a click on a ball nominates it
        const double R = snooker_->config().params.ball_radius;
        for (int id : snooker_->state().on_table)
            if (physics::norm(snooker_->state().positions.at(id) - pos) <= 1.3 * R)
                return nominate(id);
        return;
    }
    if (!human_to_act() || !calls_count(session_)) return;
    const double R = session_.config().params.ball_radius;
    const std::vector<int> legal = legal_targets(session_);
    const rules::Call now = call();
    for (int id : session_.state().on_table) {
        const physics::Vec2 p = session_.state().positions.at(id);
        if (physics::norm(p - pos) > 1.3 * R) continue;
        if (std::find(legal.begin(), legal.end(), id) == legal.end()) {
            refusal_ = fmt::format("You may not call the {} now.", id);
            return;
        }
        const int pocket = now.is_ball()                  ? now.pocket
                           : preview_ && preview_->pocket ? *preview_->pocket
                                                          : 0;
        manual_call_ = rules::Call::ball_in(id, pocket);
        refusal_.clear();
        return;
    }
    for (const physics::Pocket& p : session_.table().pockets) {
        if (physics::norm(p.centre - pos) > 0.12) continue;
        const std::optional<int> ball = now.is_ball() ? std::optional<int>(now.ball)
                                        : preview_    ? preview_->first_ball
                                                      : std::nullopt;
        if (!ball || std::find(legal.begin(), legal.end(), *ball) == legal.end()) {
            refusal_ = "Click the ball to call first, then the pocket.";
            return;
        }
        manual_call_ = rules::Call::ball_in(*ball, p.id);
        refusal_.clear();
        return;
    }
}

void Controller::call_safety() {
    if (human_to_act() && calls_count(session_)) manual_call_ = rules::Call::safety();
}

void Controller::clear_call() {
    manual_call_.reset();
}

void Controller::set_push_out(bool declare) {
    if (!human_to_act()) return;
    try {
        session_.set_push_out(declare);
        refusal_.clear();
    } catch (const game::Refused& e) {
        refusal_ = e.what();
    }
}

void Controller::strike() {
    if (!human_to_act() || session_.phase() != game::Phase::shoot) return;
    try {
        session_.set_call(call());
    } catch (const game::Refused& e) {
        refusal_ = e.what();
        return;
    }
    play(stroke_of(aim_));
}

void Controller::choose(rules::ChoiceOption option) {
    if (!human_to_act() || session_.phase() != game::Phase::choose) return;
    const int rack = session_.rack_number();
    try {
        session_.choose(option);
    } catch (const game::Refused& e) {
        refusal_ = e.what();
        return;
    }
    refusal_.clear();
    if (session_.rack_number() != rack) orientations_.reset();
    begin_turn();
}

void Controller::skip() {
    if (!playback_.moving()) return;
    playback_.skip_to_end();
    orientations_.follow(playback_.shot(), playback_.time(), playback_.end());
    if (!settled_) finish_shot();
}

void Controller::replay() {
    if (busy() || !settled_ || !playback_.has_shot()) return;
    orientations_ = at_strike_;
    playback_.restart(stroke_lead);
    replaying_ = true;
    ++shot_serial_;
}

void Controller::restart() {
    if (snooker_) return start_snooker(game::SnookerSession(snooker_->config()), options_);
    if (carom_) return start_carom(game::CaromSession(carom_->config()), options_);
    if (practice_) {  // a new rack to practise on
        const game::Practice& p = *practice_;
        start_practice(
            game::Practice(p.game(), p.table_spec(), p.params(), session_.config().seed + 1),
            options_);
        return;
    }
    stop_thinking();
    session_.restart();
    playback_.clear();
    orientations_.reset();
    settled_ = true;
    dry_shots_ = 0;
    last_words_.clear();
    refusal_.clear();
    begin_turn();
}

}  // namespace app
