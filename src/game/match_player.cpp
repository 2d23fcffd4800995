#include "game/match_player.hpp"

#include <cmath>
#include <memory>
#include <numbers>
#include <vector>

#include "physics/rack.hpp"

namespace game {

namespace {

namespace sb = physics::snooker_ball;

physics::Stroke random_stroke_at(physics::Vec2 from, physics::Vec2 to, double spread_deg,
                                 physics::SplitMix64& rng) {
    const physics::Vec2 d = to - from;
    physics::Stroke k;
    k.speed = 1.0 + 5.0 * rng.uniform();
    k.heading_deg =
        std::atan2(d.y, d.x) * 180.0 / std::numbers::pi + spread_deg * (rng.uniform() - 0.5);
    k.side = 0.4 * (rng.uniform() - 0.5);
    return k;
}

// The balls on: the reds, the colours (a colour on), or the lowest colour left.
std::vector<int> balls_on(const rules::SnookerState& st) {
    std::vector<int> out;
    for (int id : st.on_table) {
        if (st.colour_on ? physics::is_colour(id) : physics::is_red(id)) out.push_back(id);
        if (!st.colour_on && st.reds() == 0 && out.empty()) out.push_back(id);
    }
    return out;
}

physics::Vec2 random_in_d(const SnookerSession& s, physics::SplitMix64& rng) {
    const physics::SnookerMarkings& m = s.marks().marks;
    for (int tries = 0; tries < 10000; ++tries) {
        const double a = std::numbers::pi * (0.5 + rng.uniform()), r = m.d_radius * rng.uniform();
        const physics::Vec2 p = m.d_centre() + physics::Vec2{r * std::cos(a), r * std::sin(a)};
        if (!s.check_cue_ball(p)) return p;
    }
    return m.d_centre();
}

MatchDecision random_snooker(const SnookerSession& s, physics::SplitMix64& rng) {
    MatchDecision d;
    if (s.phase() == MatchPhase::choose) {
        d.after_foul = s.choices()[static_cast<std::size_t>(rng.below(s.choices().size()))];
        return d;
    }
    rules::SnookerState st = s.state();
    if (st.cue_ball == rules::CueBall::in_hand) {
        d.cue_pos = random_in_d(s, rng);
        st.positions[sb::cue] = *d.cue_pos;
    }
    std::vector<int> targets = balls_on(st);
    if (targets.empty())
        for (int id : st.on_table) targets.push_back(id);
    const int target = targets[static_cast<std::size_t>(rng.below(targets.size()))];
    if (st.colour_on) d.nominate = target;
    d.stroke = random_stroke_at(st.positions.at(sb::cue), st.positions.at(target), 10.0, rng);
    return d;
}

MatchDecision random_carom(const CaromSession& s, physics::SplitMix64& rng) {
    const rules::CaromState& st = s.state();
    const int cue = s.cue_ball();
    const int other = cue == physics::carom_ball::white ? physics::carom_ball::yellow
                                                        : physics::carom_ball::white;
    const int target = st.opening || rng.below(2) == 0 ? physics::carom_ball::red : other;
    MatchDecision d;
    d.stroke = random_stroke_at(st.positions.at(cue), st.positions.at(target), 40.0, rng);
    d.stroke.speed += 1.0;
    return d;
}

}  // namespace

SnookerPlayer random_snooker_player(std::uint64_t seed) {
    auto rng = std::make_shared<physics::SplitMix64>(seed);
    return {[rng](const SnookerSession& s) { return random_snooker(s, *rng); }, 1.0};
}

CaromPlayer random_carom_player(std::uint64_t seed) {
    auto rng = std::make_shared<physics::SplitMix64>(seed);
    return {[rng](const CaromSession& s) { return random_carom(s, *rng); }, 1.0};
}

void apply(SnookerSession& s, const MatchDecision& d, const physics::Stroke& stroke) {
    if (s.phase() == MatchPhase::choose) {
        s.choose(d.after_foul.value_or(rules::AfterFoul::play));
        return;
    }
    if (d.cue_pos) s.place_cue_ball(*d.cue_pos);
    if (s.may_nominate()) s.nominate(d.nominate);
    s.play(stroke);
}

void apply(CaromSession& s, const MatchDecision&, const physics::Stroke& stroke) {
    s.play(stroke);
}

}  // namespace game
