// The snooker player's decision (games.hpp's plan_snooker): spots in the D, candidates, their
// noiseless plays, the shortlist under noise, the best mean. docs/ai.md, "Snooker".
#include <algorithm>
#include <numeric>

#include "ai/internal/ghost_ball.hpp"
#include "ai/internal/level.hpp"
#include "ai/internal/parallel.hpp"
#include "ai/internal/snooker_search.hpp"

namespace ai {

namespace {

namespace sb = physics::snooker_ball;
using physics::Vec2;

struct Search {
    const SnookerPosition& pos;
    SnookerEffort effort;
    Workers workers;
    double scale, sigma_deg;
    SnookerEvaluator eval;
    std::int64_t simulations = 0;
};

// Where the cue ball is played from: where it lies, or the best few spots of the D.
std::vector<Vec2> cue_spots(Search& k) {
    const rules::SnookerState& s = k.pos.state;
    if (s.cue_ball == rules::CueBall::on_table && s.positions.count(sb::cue))
        return {s.positions.at(sb::cue)};
    std::vector<Vec2> spots = d_spots(k.pos, s);
    std::vector<double> value(spots.size());
    for (std::size_t i = 0; i < spots.size(); ++i) {
        rules::SnookerState at = s;
        at.positions[sb::cue] = spots[i];
        at.cue_ball = rules::CueBall::on_table;
        value[i] = table_value(k.pos, at, k.sigma_deg);
    }
    std::vector<std::size_t> order(spots.size());
    std::iota(order.begin(), order.end(), 0);
    std::stable_sort(order.begin(), order.end(),
                     [&](std::size_t a, std::size_t b) { return value[a] > value[b]; });
    std::vector<Vec2> out;
    for (std::size_t i = 0; i < order.size() && out.size() < std::size_t(k.effort.placements); ++i)
        out.push_back(spots[order[i]]);
    if (out.empty()) out.push_back(k.pos.snooker.marks.d_centre() - Vec2{0.05, 0.0});
    return out;
}

// Plays every candidate once without noise, in parallel; returns their trials.
std::vector<SnookerTrial> play_nominal(Search& k, std::vector<SnookerCandidate>& cands) {
    std::vector<SnookerTrial> out(cands.size());
    parallel_for(cands.size(), k.workers,
                 [&](std::size_t i) { out[i] = k.eval.nominal(cands[i]); });
    k.simulations += static_cast<std::int64_t>(cands.size());
    return out;
}

struct Mean {
    double value = 0.0, success = 0.0;
    int n = 0;
};

// Adds the draws [first, first + count) to the means of the candidates `which`.
void score(Search& k, const std::vector<SnookerCandidate>& cands,
           const std::vector<std::size_t>& which, const std::vector<NoiseDraw>& draws,
           std::size_t first, std::size_t count, std::vector<Mean>& means) {
    std::vector<SnookerTrial> t(which.size() * count);
    parallel_for(t.size(), k.workers, [&](std::size_t j) {
        t[j] = k.eval.trial(cands[which[j / count]], draws[first + j % count]);
    });
    k.simulations += static_cast<std::int64_t>(t.size());
    for (std::size_t j = 0; j < t.size(); ++j) {
        Mean& m = means[which[j / count]];
        const SnookerCandidate& c = cands[which[j / count]];
        m.value += t[j].value;
        m.success += c.kind == Kind::pot ? t[j].stays : !t[j].foul;
        ++m.n;
    }
}

// The indices of the `n` best by `key`, best first (ties: the earlier).
template <typename Key>
std::vector<std::size_t> best(std::size_t size, std::size_t n, const Key& key) {
    std::vector<std::size_t> order(size);
    std::iota(order.begin(), order.end(), 0);
    std::stable_sort(order.begin(), order.end(),
                     [&](std::size_t a, std::size_t b) { return key(a) > key(b); });
    order.resize(std::min(n, size));
    return order;
}

std::vector<SnookerCandidate> candidates(Search& k, const std::vector<Vec2>& spots) {
    const bool in_hand = k.pos.state.cue_ball == rules::CueBall::in_hand;
    std::vector<SnookerCandidate> out;
    for (Vec2 cue : spots) {
        std::vector<SnookerCandidate> pots =
            snooker_pots(k.pos, cue, in_hand, k.effort, k.sigma_deg, k.simulations);
        std::vector<SnookerCandidate> safe = snooker_safeties(k.pos, cue, in_hand, k.effort);
        out.insert(out.end(), pots.begin(), pots.end());
        out.insert(out.end(), safe.begin(), safe.end());
    }
    return out;
}

struct Played {
    std::vector<SnookerCandidate> cands;
    std::vector<SnookerTrial> nominal;
};

// The candidates from every spot played once without noise; when every one fouls (snookered,
// or nothing legal), the escapes of the sweep from the first spot too.
Played play_candidates(Search& k, const std::vector<Vec2>& spots) {
    Played p;
    p.cands = candidates(k, spots);
    p.nominal = play_nominal(k, p.cands);
    const bool all_foul = std::all_of(p.nominal.begin(), p.nominal.end(),
                                      [](const SnookerTrial& t) { return t.foul; });
    if (all_foul) {
        const bool in_hand = k.pos.state.cue_ball == rules::CueBall::in_hand;
        std::vector<SnookerCandidate> esc =
            snooker_escapes(k.pos, spots.front(), in_hand, k.effort);
        std::vector<SnookerTrial> t = play_nominal(k, esc);
        p.cands.insert(p.cands.end(), esc.begin(), esc.end());
        p.nominal.insert(p.nominal.end(), t.begin(), t.end());
    }
    if (p.cands.empty()) throw std::logic_error("plan_snooker: no candidate stroke");
    return p;
}

SnookerPlan to_plan(const SnookerCandidate& c, const Mean& m, std::int64_t simulations) {
    SnookerPlan p;
    p.stroke = c.stroke;
    p.nominated = c.nominated;
    p.cue_pos = c.cue_pos;
    p.kind = c.kind;
    p.expected_value = m.n ? m.value / m.n : 0.0;
    p.expected_success = m.n ? m.success / m.n : 0.0;
    p.simulations = simulations;
    return p;
}

// The best few by their means valued two plies deep on the same draws; the best deep mean wins.
SnookerPlan deep_choice(Search& k, const std::vector<SnookerCandidate>& cands,
                        const std::vector<Mean>& means, const std::vector<NoiseDraw>& draws) {
    const std::vector<std::size_t> list =
        best(cands.size(), static_cast<std::size_t>(k.effort.deep_finalists),
             [&](std::size_t i) { return means[i].n ? means[i].value / means[i].n : -1e9; });
    const std::size_t n =
        std::min(draws.size(), static_cast<std::size_t>(std::max(k.effort.deep_samples, 1)));
    std::vector<SnookerTrial> t(list.size() * n);
    parallel_for(t.size(), k.workers, [&](std::size_t j) {
        t[j] = k.eval.deep_trial(cands[list[j / n]], draws[j % n], k.effort);
    });
    std::vector<Mean> deep(list.size());
    for (std::size_t j = 0; j < t.size(); ++j) {
        Mean& m = deep[j / n];
        m.value += t[j].value;
        m.success += cands[list[j / n]].kind == Kind::pot ? t[j].stays : !t[j].foul;
        ++m.n;
        k.simulations += t[j].simulations;
    }
    const std::size_t b =
        best(list.size(), 1, [&](std::size_t i) { return deep[i].value / deep[i].n; }).front();
    return to_plan(cands[list[b]], deep[b], k.simulations);
}

}  // namespace

SnookerPosition snooker_position(const physics::Table& table, const physics::Params& params,
                                 const rules::SnookerOptions& options,
                                 const rules::SnookerState& state) {
    return {options, {physics::snooker_markings(table), params.ball_radius}, table, params, state};
}

SnookerPlan plan_snooker(const SnookerPosition& pos, const PlanSettings& settings,
                         std::uint64_t seed) {
    const SnookerEffort effort = snooker_effort(settings.level);
    const double scale = planned_scale(settings);
    const double sigma_1x =
        effort.model_sigma_deg > 0.0 ? effort.model_sigma_deg : heading_sigma_deg(pos.params);
    const double sigma = sigma_1x * scale;
    Search k{pos,   effort, {std::max(settings.workers, 1), settings.pause},
             scale, sigma,  {pos, scale, sigma}};
    Played p = play_candidates(k, cue_spots(k));
    const auto nominal_value = [&](std::size_t i) { return p.nominal[i].value; };
    if (scale == 0.0) {
        const std::size_t b = best(p.cands.size(), 1, nominal_value).front();
        const SnookerTrial& t = p.nominal[b];
        const bool success = p.cands[b].kind == Kind::pot ? t.stays : !t.foul;
        return to_plan(p.cands[b], {t.value, success ? 1.0 : 0.0, 1}, k.simulations);
    }
    // The shortlist on the same draws; the finalists on as many more.
    const std::size_t n = static_cast<std::size_t>(effort.samples);
    const std::vector<NoiseDraw> draws = noise_draws(seed, static_cast<int>(2 * n));
    std::vector<Mean> means(p.cands.size());
    const std::vector<std::size_t> list =
        best(p.cands.size(), static_cast<std::size_t>(effort.shortlist), nominal_value);
    score(k, p.cands, list, draws, 0, n, means);
    const auto mean_value = [&](std::size_t i) {
        return means[i].n ? means[i].value / means[i].n : -1e9;
    };
    const std::vector<std::size_t> finals =
        best(p.cands.size(), static_cast<std::size_t>(effort.finalists), mean_value);
    if (finals.size() > 1) score(k, p.cands, finals, draws, n, n, means);
    if (effort.deep_finalists > 1) return deep_choice(k, p.cands, means, draws);
    const std::size_t b = best(p.cands.size(), 1, mean_value).front();
    return to_plan(p.cands[b], means[b], k.simulations);
}

rules::SnookerState with_plan(rules::SnookerState s, const SnookerPlan& plan) {
    if (plan.cue_pos) {
        s.positions[sb::cue] = *plan.cue_pos;
        s.cue_ball = rules::CueBall::on_table;
    }
    if (plan.nominated) s.nominated = plan.nominated;
    return s;
}

rules::AfterFoul choose_after_foul(const SnookerPosition& pos, const rules::SnookerVerdict& v,
                                   const rules::SnookerState& before,
                                   const PlanSettings& settings) {
    if (!v.may_ask_to_play_again) return rules::AfterFoul::play;
    const SnookerEffort effort = snooker_effort(settings.level);
    const double sigma =
        (effort.model_sigma_deg > 0.0 ? effort.model_sigma_deg : heading_sigma_deg(pos.params)) *
        planned_scale(settings);
    // The chooser's value: his own table when he plays, less the offender's when he does not.
    rules::AfterFoul choice = rules::AfterFoul::play;
    double top = table_value(pos, v.state, sigma);
    for (rules::AfterFoul c : {rules::AfterFoul::play_again, rules::AfterFoul::replace}) {
        if (c == rules::AfterFoul::replace && !v.miss) continue;
        const double value = -table_value(pos, rules::resolve_after_foul(v, before, c), sigma);
        if (value > top) {
            top = value;
            choice = c;
        }
    }
    return choice;
}

}  // namespace ai
