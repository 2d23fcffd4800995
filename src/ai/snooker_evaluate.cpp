// Playing a snooker candidate with the real physics and judging it with the real rules
// (snooker_search.hpp's SnookerEvaluator).
#include <algorithm>
#include <cmath>

#include "ai/internal/snooker_search.hpp"
#include "physics/simulate.hpp"

namespace ai {

namespace {

namespace sb = physics::snooker_ball;

// The first ball the cue ball meets in the events, if any.
std::optional<int> first_hit(std::span<const physics::Event> events) {
    for (const physics::Event& e : events)
        if (e.type == physics::EventType::ball_ball && e.involves(sb::cue))
            return e.ball(0) == sb::cue ? e.ball(1) : e.ball(0);
    return std::nullopt;
}

// A nomination the rules accept in `s` for a stroke that meets `hit` first: that ball where it
// may be nominated, else the highest ball that may (the stroke fouls anyway).
int nomination_for(const rules::SnookerState& s, std::optional<int> hit) {
    const std::vector<int> targets = snooker_targets(s);
    if (hit && std::find(targets.begin(), targets.end(), *hit) != targets.end()) return *hit;
    return targets.empty() ? sb::black : targets.back();
}

// What missing the next pot costs: the table to the opponent (unit: points).
constexpr double miss_value = -1.0;

// The striker's chance to win the frame from the scores of `s` and the points left on the
// table: even scores 1/2, a lead that the points left cannot make up near 1.
double win_chance(const rules::SnookerState& s, rules::Player me) {
    const double lead = s.score(me) - s.score(rules::other(me));
    return 0.5 + 0.5 * std::tanh(1.5 * lead / (rules::points_remaining(s) + 7.0));
}

}  // namespace

rules::SnookerState SnookerEvaluator::start(const SnookerCandidate& c) const {
    rules::SnookerState s = pos_.state;
    if (c.cue_pos) {
        s.positions[sb::cue] = *c.cue_pos;
        s.cue_ball = rules::CueBall::on_table;
    }
    if (needs_nomination(s)) s.nominated = c.nominated;
    return s;
}

SnookerTrial SnookerEvaluator::play(const rules::SnookerState& s, const physics::Stroke& stroke,
                                    const SnookerEffort* deeper) const {
    const physics::Shot shot = physics::simulate(
        pos_.table, pos_.params, snooker_layout(s, s.positions.at(sb::cue)), &stroke);
    const rules::SnookerVerdict v =
        rules::judge_snooker(pos_.options, pos_.snooker, s, shot.events());
    const rules::Player me = s.shooter;
    SnookerTrial t;
    t.foul = v.foul;
    // Points ahead plus what the frame is worth times the change in the chance to win it, so
    // that the frame's end and a lead the opponent cannot make up weigh the same.
    const double points = v.points_scored - v.foul_points;
    const double before = win_chance(s, me);
    if (v.frame_over) {
        t.stays = v.winner == me;
        t.value = points + 2.0 * frame_value * ((t.stays ? 1.0 : 0.0) - before);
        return t;
    }
    t.value = points + 2.0 * frame_value * (win_chance(v.state, me) - before);
    if (v.state.shooter == me) {
        t.stays = true;
        t.value += deeper && v.state.positions.count(sb::cue)
                       ? deep_value(v.state, *deeper, t)
                       : table_value(pos_, v.state, sigma_deg_);
    } else {
        t.value -= table_value(pos_, v.state, sigma_deg_);
    }
    return t;
}

double SnookerEvaluator::deep_value(const rules::SnookerState& s, const SnookerEffort& effort,
                                    SnookerTrial& t) const {
    SnookerPosition next = pos_;
    next.state = s;
    const SnookerEvaluator eval(next, scale_, sigma_deg_);
    SnookerEffort pots;
    pots.pot_pairs = effort.next_pairs;
    pots.speeds = effort.next_speeds;
    pots.spins = effort.next_spins;
    pots.refine_steps = 1;
    std::vector<SnookerCandidate> cands =
        snooker_pots(next, s.positions.at(sb::cue), false, pots, sigma_deg_, t.simulations);
    // With no pot worth more, a safety: about even, unless snookered.
    const double one_ply = table_value(pos_, s, sigma_deg_);
    double best = std::min(one_ply, 0.0);
    for (SnookerCandidate& c : cands) {
        const SnookerTrial r = eval.nominal(c);
        ++t.simulations;
        const double v = r.stays ? c.prior * r.value + (1.0 - c.prior) * miss_value : r.value;
        best = std::max(best, v);
    }
    return best;
}

SnookerTrial SnookerEvaluator::nominal(SnookerCandidate& c) const {
    rules::SnookerState s = start(c);
    if (needs_nomination(s) && !c.nominated) {
        const physics::Shot probe = physics::simulate(
            pos_.table, pos_.params, snooker_layout(s, s.positions.at(sb::cue)), &c.stroke);
        c.nominated = nomination_for(s, first_hit(probe.events()));
        s.nominated = c.nominated;
    }
    return play(s, c.stroke);
}

SnookerTrial SnookerEvaluator::trial(const SnookerCandidate& c, const NoiseDraw& draw) const {
    return play(start(c), with_draw(c.stroke, draw, scale_));
}

SnookerTrial SnookerEvaluator::deep_trial(const SnookerCandidate& c, const NoiseDraw& draw,
                                          const SnookerEffort& effort) const {
    return play(start(c), with_draw(c.stroke, draw, scale_), &effort);
}

}  // namespace ai
