// The controller in snooker and three-cushion (game/snooker_session.hpp, carom_session.hpp):
// the match session holds the game and plays the strokes; the pool session mirrors its table
// (the balls, who acts, a cue ball in hand) so that drawing, aiming and the aim guide work as in
// pool. The words are match_words'.
#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <numbers>

#include "app/controller.hpp"
#include "app/match_words.hpp"
#include "app/seats.hpp"
#include "game/stroke_noise.hpp"

namespace app {

namespace {

namespace sb = physics::snooker_ball;

game::Session mirror_of(const physics::TableSpec& table, const physics::Params& params,
                        const std::array<std::string, 2>& names,
                        const std::map<int, physics::Vec2>& positions, rules::Player to_act,
                        bool in_hand, std::uint64_t seed) {
    game::Config c;
    c.game = rules::Game::eight_ball;
    c.options.call_shots = rules::CallShots::none;  // snooker nominates; carom calls nothing
    c.table = table;
    c.params = params;
    c.names = names;
    c.seed = seed;
    rules::GameState s = rules::initial_state(c.game, to_act);
    s.shooter = to_act;
    s.shot = rules::Shot::normal;
    s.cue_ball = in_hand ? rules::CueBall::in_hand : rules::CueBall::on_table;
    s.positions = positions;
    s.on_table.clear();
    for (const auto& [id, pos] : positions)
        if (id != 0) s.on_table.insert(id);
    return game::Session::at_position(std::move(c), std::move(s));
}

std::uint64_t seat_seed(std::uint64_t seed, std::size_t seat) {
    physics::SplitMix64 mix(seed ^ (0x5851f42d4c957f2dULL * (seat + 1)));
    return mix.next();
}

// The balls the striker may aim at first: the balls on (snooker), the two object balls (carom).
std::vector<int> match_targets(const game::SnookerSession* snooker,
                               const game::CaromSession* carom) {
    std::vector<int> out;
    if (carom) {  // the opening stroke must hit the red first
        for (const auto& [id, p] : carom->state().positions)
            if (id != carom->cue_ball() &&
                (!carom->state().opening || id == physics::carom_ball::red))
                out.push_back(id);
        return out;
    }
    const rules::SnookerState& s = snooker->state();
    const rules::BallOn on = snooker->ball_on();
    for (int id : s.on_table) {
        const bool want =
            on == rules::BallOn::red ? physics::is_red(id)
            : on == rules::BallOn::colour
                ? physics::is_colour(id)
                : id == sb::yellow + static_cast<int>(on) - static_cast<int>(rules::BallOn::yellow);
        if (want) out.push_back(id);
    }
    return out;
}

// Whether the cue ball can roll straight to `at` (its centre there) touching no ball but `to`.
bool clear_path(const std::map<int, physics::Vec2>& pos, int from, int to, physics::Vec2 at,
                double R) {
    const physics::Vec2 a = pos.at(from), ab = at - a;
    const double len2 = physics::dot(ab, ab);
    for (const auto& [id, p] : pos) {
        if (id == from || id == to || len2 <= 0.0) continue;
        const double t = std::clamp(physics::dot(p - a, ab) / len2, 0.0, 1.0);
        if (physics::norm(p - (a + t * ab)) < 2.0 * R) return false;
    }
    return true;
}

// Where the cue ball's centre goes to hit ball `to` full, or failing that thin on either side,
// with a clear path; empty when every way is blocked.
std::optional<physics::Vec2> open_contact(const std::map<int, physics::Vec2>& pos, int from, int to,
                                          double R) {
    const physics::Vec2 d = pos.at(to) - pos.at(from);
    const double n = physics::norm(d);
    if (n <= 0.0) return std::nullopt;
    const physics::Vec2 side{-d.y / n, d.x / n};
    for (double k : {0.0, 1.0, -1.0, 1.8, -1.8}) {
        const physics::Vec2 at = pos.at(to) + (k * R) * side - (2.0 * R / n) * d;
        if (clear_path(pos, from, to, at, R)) return at;
    }
    return std::nullopt;
}

}  // namespace

void Controller::start_snooker(game::SnookerSession match, ControllerOptions options) {
    const std::array<std::string, 2> kinds = options.players;
    options.players = {"human", "human"};  // no pool computer players behind the mirror
    replace(session_, std::move(options));
    for (std::size_t i = 0; i < 2; ++i) {
        snooker_players_[i] =
            snooker_computer(kinds[i], seat_seed(options_.seed, i), options_.noise);
        if (snooker_players_[i]) options_.players[i] = kinds[i];
    }
    snooker_ = std::move(match);
    match_stroke_.reset();
    begin_turn();
}

void Controller::start_carom(game::CaromSession match, ControllerOptions options) {
    const std::array<std::string, 2> kinds = options.players;
    options.players = {"human", "human"};
    replace(session_, std::move(options));
    for (std::size_t i = 0; i < 2; ++i) {
        carom_players_[i] = carom_computer(kinds[i], seat_seed(options_.seed, i), options_.noise);
        if (carom_players_[i]) options_.players[i] = kinds[i];
    }
    carom_ = std::move(match);
    match_stroke_.reset();
    begin_turn();
}

bool Controller::match_computer_to_act() const {
    const std::optional<rules::Player> p = snooker_ ? snooker_->to_act() : carom_->to_act();
    if (!p) return true;  // nobody is to act: not a human's turn
    return snooker_ ? snooker_players_[rules::index(*p)].has_value()
                    : carom_players_[rules::index(*p)].has_value();
}

bool Controller::update_match_computer(double dt) {
    if (match_thinking_.valid()) {
        if (!match_thinking_.ready()) return true;
        try {
            const game::MatchDecision d = match_thinking_.get();
            hinting_ ? apply_match_hint(d) : apply_match_computer(d);
        } catch (const std::exception& e) {
            refusal_ = std::string("the computer player failed: ") + e.what();
            hinting_ = false;
        }
        return true;
    }
    if (!match_decision_) return false;
    computer_aim_left_ -= dt;
    if (computer_aim_left_ > 0.0 && options_.playback_speed > 0.0) return true;
    const std::size_t seat =
        rules::index(snooker_ ? snooker_->state().shooter : carom_->state().shooter);
    const double own =
        snooker_ ? snooker_players_[seat]->execution_noise : carom_players_[seat]->execution_noise;
    const physics::Stroke k =
        game::with_noise(match_decision_->stroke, options_.noise * own, noise_rng_);
    match_decision_.reset();
    play_match(k);
    return true;
}

void Controller::apply_match_computer(const game::MatchDecision& d) {
    try {
        if (snooker_ && snooker_->phase() == game::MatchPhase::choose) {
            snooker_->choose(d.after_foul.value_or(rules::AfterFoul::play));
            last_words_ =
                after_foul_words(*snooker_, d.after_foul.value_or(rules::AfterFoul::play));
            orientations_.reset();
            begin_turn();
            return;
        }
        if (snooker_ && d.cue_pos) snooker_->place_cue_ball(*d.cue_pos);
    } catch (const game::Refused& e) {
        refusal_ = std::string("the computer player's decision was refused: ") + e.what();
        return;
    }
    mirror_match();
    if (d.nominate) manual_nomination_ = d.nominate;
    aim_ = Aim{d.stroke.heading_deg, power_of_speed(d.stroke.speed), d.stroke.side, d.stroke.top,
               d.stroke.elevation_deg};
    refresh_preview();
    match_decision_ = d;
    computer_aim_left_ = options_.computer_aim_seconds;
}

void Controller::match_hint(std::uint64_t seed) {
    const bool shoot = snooker_ ? snooker_->phase() == game::MatchPhase::shoot
                                : carom_->phase() == game::MatchPhase::shoot;
    if (!shoot) return;
    hinting_ = true;
    if (snooker_) {
        const auto decide = snooker_computer("ai:5", seed, options_.noise)->decide;
        const game::SnookerSession* s = &*snooker_;
        match_thinking_ = Thinking<game::MatchDecision>::start([decide, s] { return decide(*s); });
    } else {
        const auto decide = carom_computer("ai:5", seed, options_.noise)->decide;
        const game::CaromSession* s = &*carom_;
        match_thinking_ = Thinking<game::MatchDecision>::start([decide, s] { return decide(*s); });
    }
}

void Controller::apply_match_hint(const game::MatchDecision& d) {
    hinting_ = false;
    if (snooker_ && d.cue_pos && snooker_->state().cue_ball == rules::CueBall::in_hand) {
        try {
            snooker_->place_cue_ball(*d.cue_pos);
        } catch (const game::Refused&) {
            // keep the cue ball where the player put it
        }
        mirror_match();
    }
    if (d.nominate) manual_nomination_ = d.nominate;
    // The hint's stroke is this shot's aim only, as in pool.
    aim_ = Aim{d.stroke.heading_deg, power_of_speed(d.stroke.speed), d.stroke.side, d.stroke.top,
               d.stroke.elevation_deg};
    refresh_preview();
}

render::GameLook Controller::look() const {
    if (practice_)
        return practice_->game() == physics::RackType::snooker         ? render::GameLook::snooker
               : practice_->game() == physics::RackType::three_cushion ? render::GameLook::carom
                                                                       : render::GameLook::pool;
    return snooker_ ? render::GameLook::snooker
           : carom_ ? render::GameLook::carom
                    : render::GameLook::pool;
}

void Controller::mirror_match() {
    const std::uint64_t seed = session_.config().seed;
    if (snooker_) {
        const game::SnookerSession& m = *snooker_;
        session_ = mirror_of(m.config().table, m.config().params, m.config().names,
                             m.state().positions, m.to_act().value_or(m.state().shooter),
                             m.state().cue_ball == rules::CueBall::in_hand, seed);
    } else {
        const game::CaromSession& m = *carom_;
        session_ =
            mirror_of(m.config().table, m.config().params, m.config().names, m.state().positions,
                      m.to_act().value_or(m.state().shooter), false, seed);
    }
}

physics::Vec2 Controller::default_d_spot() const {
    const physics::SnookerMarkings& m = snooker_->marks().marks;
    const auto last = snooker_->state().positions.find(sb::cue);
    if (last != snooker_->state().positions.end() && !snooker_->check_cue_ball(last->second))
        return last->second;
    // On the baulk line between the brown and the yellow, as at the break; else the D's free
    // place nearest the brown spot.
    const physics::Vec2 brown = m.spot(sb::brown), yellow = m.spot(sb::yellow);
    const physics::Vec2 between{m.baulk_x - 1e-4, 0.5 * (brown.y + yellow.y)};
    if (!snooker_->check_cue_ball(between)) return between;
    const double R = snooker_->config().params.ball_radius;
    for (double r = 2 * R; r < m.d_radius; r += R / 2)
        for (int k = 0; k < 32; ++k) {
            const double a = std::numbers::pi * (0.5 + k / 31.0);
            const physics::Vec2 p = m.d_centre() + physics::Vec2{r * std::cos(a), r * std::sin(a)};
            if (!snooker_->check_cue_ball(p)) return p;
        }
    return m.d_centre();
}

void Controller::begin_match_turn() {
    manual_call_.reset();
    manual_nomination_.reset();
    preview_.reset();
    aim_foul_.clear();
    if (snooker_ && snooker_->phase() == game::MatchPhase::place_cue_ball)
        snooker_->place_cue_ball(default_d_spot());
    mirror_match();
    const bool shoot = snooker_ ? snooker_->phase() == game::MatchPhase::shoot
                                : carom_->phase() == game::MatchPhase::shoot;
    if (match_computer_to_act() && (snooker_ ? snooker_->to_act() : carom_->to_act())) {
        // A computer seat: it decides beside the frames (app/thinking.hpp); the session is not
        // touched meanwhile.
        if (snooker_) {
            const auto decide = snooker_players_[rules::index(*snooker_->to_act())]->decide;
            const game::SnookerSession* s = &*snooker_;
            match_thinking_ =
                Thinking<game::MatchDecision>::start([decide, s] { return decide(*s); });
        } else {
            const auto decide = carom_players_[rules::index(*carom_->to_act())]->decide;
            const game::CaromSession* s = &*carom_;
            match_thinking_ =
                Thinking<game::MatchDecision>::start([decide, s] { return decide(*s); });
        }
        return;
    }
    if (!shoot) return;
    aim_ = human_aim_;
    aim_at_open_ball(match_targets(snooker(), carom()));
}

void Controller::aim_at_open_ball(const std::vector<int>& targets) {
    const auto& pos = session_.state().positions;
    const physics::Vec2 cue = pos.at(cue_ball_id());
    const double R = session_.config().params.ball_radius;
    double best = 1e9;
    for (int id : targets) {
        // The nearest ball that can be hit with a clear path, full or thin, before any other.
        const std::optional<physics::Vec2> at = open_contact(pos, cue_ball_id(), id, R);
        const physics::Vec2 d = at.value_or(pos.at(id)) - cue;
        const double rank = physics::norm(pos.at(id) - cue) + (at ? 0.0 : 100.0);
        if (rank < best) {
            best = rank;
            aim_.heading_deg = std::atan2(d.y, d.x) * 180.0 / std::numbers::pi;
        }
    }
}

std::optional<int> Controller::nomination() const {
    if (!snooker_ || !snooker_->may_nominate()) return std::nullopt;
    if (manual_nomination_) return *manual_nomination_;
    if (!preview_ || !preview_->first_ball) return std::nullopt;
    const int first = *preview_->first_ball;
    const rules::SnookerState& s = snooker_->state();
    // A colour on: the colour the aim meets first. A free ball: the ball it meets, when that
    // is not already a ball on.
    if (s.colour_on) return physics::is_colour(first) ? std::optional<int>(first) : std::nullopt;
    const std::vector<int> on = match_targets(snooker(), nullptr);
    if (std::find(on.begin(), on.end(), first) != on.end()) return std::nullopt;
    return first;
}

void Controller::nominate(std::optional<int> ball) {
    if (!snooker_ || !human_to_act() || !snooker_->may_nominate()) return;
    if (!ball) {
        manual_nomination_.reset();
        return;
    }
    if (!snooker_->state().has(*ball) ||
        (snooker_->state().colour_on && !physics::is_colour(*ball))) {
        refusal_ = snooker_->state().colour_on ? "After a red, nominate a colour."
                                               : "Nominate a ball on the table.";
        return;
    }
    manual_nomination_ = ball;
    refusal_.clear();
}

void Controller::choose_after_foul(rules::AfterFoul choice) {
    if (!snooker_ || !human_to_act()) return;
    try {
        snooker_->choose(choice);
    } catch (const game::Refused& e) {
        refusal_ = e.what();
        return;
    }
    refusal_.clear();
    last_words_ = after_foul_words(*snooker_, choice);
    if (choice == rules::AfterFoul::replace) orientations_.reset();
    begin_turn();
}

void Controller::next_frame() {
    if (busy()) return;
    try {
        if (snooker_) snooker_->next_frame();
        if (carom_) carom_->next_game();
    } catch (const game::Refused& e) {
        refusal_ = e.what();
        return;
    }
    playback_.clear();
    orientations_.reset();
    last_words_.clear();
    refusal_.clear();
    last_match_shot_.reset();
    begin_turn();
}

void Controller::play_match(const physics::Stroke& stroke, bool nominate_now) {
    std::vector<std::string> info_before = match_info();
    const physics::Vec2 cue_at = session_.state().positions.at(cue_ball_id());
    const physics::Shot* shot = nullptr;
    if (snooker_ && snooker_->phase() == game::MatchPhase::choose) {
        refusal_ = fmt::format("First {} chooses: play from here, or ask {} to play again.",
                               snooker_->name(*snooker_->to_act()),
                               snooker_->name(snooker_->before().shooter));
        return;
    }
    try {
        if (snooker_) {
            if (nominate_now && snooker_->may_nominate()) snooker_->nominate(nomination());
            game::SnookerSession before = *snooker_;
            snooker_->play(stroke);
            last_match_shot_ = game::SharedSnookerShot{std::move(before), stroke};
            shot = snooker_->last_shot();
        } else {
            game::CaromSession before = *carom_;
            carom_->play(stroke);
            last_match_shot_ = game::SharedCaromShot{std::move(before), stroke};
            shot = carom_->last_shot();
        }
    } catch (const game::Refused& e) {
        refusal_ = e.what();
        return;
    }
    match_stroke_ = StrokeShown{cue_at, stroke};
    start_playback(*shot, std::move(info_before));
}

void Controller::finish_match_shot() {
    last_words_ = snooker_ ? snooker_shot_words(*snooker_, playback_.shot())
                           : carom_shot_words(*carom_, playback_.shot());
    begin_turn();
}

std::vector<std::string> Controller::match_info() const {
    return snooker_ ? snooker_info(*snooker_, nomination()) : carom_info(*carom_);
}

}  // namespace app
