#include "game/random_player.hpp"

#include <stdexcept>
#include <vector>

#include "game/session.hpp"
#include "rules/eight_ball.hpp"

namespace game {

namespace {

double between(physics::SplitMix64& rng, double lo, double hi) {
    return lo + (hi - lo) * rng.uniform();
}

}  // namespace

physics::Vec2 RandomPlayer::place(const Session& s) {
    const double R = s.config().params.ball_radius;
    const double L = s.table().length(), W = s.table().width();
    // Ball in hand in the kitchen: x < L/4 (a hair less, so that no rounding reaches the string).
    const double x_max = s.ball_in_hand() == rules::BallInHand::kitchen ? L / 4.0 - 1e-6 : L - R;
    for (int attempt = 0; attempt < 1000; ++attempt) {
        const physics::Vec2 p{between(rng_, R, x_max), between(rng_, R, W - R)};
        if (!s.check_cue_ball(p)) return p;
    }
    for (double x = R; x <= x_max; x += R)  // a crowded table: the first free spot
        for (double y = R; y <= W - R; y += R)
            if (!s.check_cue_ball({x, y})) return {x, y};
    throw std::logic_error("RandomPlayer: no free spot for the cue ball");
}

rules::Call RandomPlayer::call(const Session& s) {
    const rules::GameState& st = s.state();
    if (s.config().game != rules::Game::eight_ball || st.shot == rules::Shot::break_shot ||
        !rules::call_counts(s.config().options, st))
        return rules::Call::nothing();
    std::vector<int> candidates;
    if (rules::on_the_eight(st)) {
        candidates = {8};
    } else {
        const std::optional<rules::Group> mine = st.group(st.shooter);
        for (int id : st.on_table)
            if (id != 8 && (!mine || rules::group_of(id) == mine)) candidates.push_back(id);
    }
    if (candidates.empty()) return rules::Call::nothing();
    const int ball = candidates[static_cast<std::size_t>(rng_.below(candidates.size()))];
    return rules::Call::ball_in(ball, static_cast<int>(rng_.below(6)));
}

physics::Stroke RandomPlayer::stroke() {
    physics::Stroke k;
    k.speed = between(rng_, settings_.min_speed, settings_.max_speed);
    k.heading_deg = between(rng_, 0.0, 360.0);
    k.side = between(rng_, -settings_.max_offset, settings_.max_offset);
    k.top = between(rng_, -settings_.max_offset, settings_.max_offset);
    k.elevation_deg = between(rng_, 0.0, settings_.max_elevation);
    return k;
}

Decision RandomPlayer::decide(const Session& s) {
    Decision d;
    if (std::optional<rules::Choice> c = s.choice()) {
        d.choice = c->options[static_cast<std::size_t>(rng_.below(c->options.size()))];
        return d;
    }
    if (s.phase() == Phase::place_cue_ball) d.cue_pos = place(s);
    d.call = call(s);
    if (rules::push_out_allowed(s.config().game, s.state()) &&
        rng_.uniform() < settings_.push_out_odds)
        d.push_out = true;
    d.stroke = stroke();
    return d;
}

}  // namespace game
