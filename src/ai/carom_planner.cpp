// The three-cushion player's decision (games.hpp's plan_three_cushion): a sweep over headings,
// speeds and spins from the cue ball, each stroke simulated and judged; the middle of each run of
// scoring headings kept; the widest played under noise; the likeliest, with the position each
// leaves where the level has time for it, wins. docs/ai.md, "Three-cushion".
#include <algorithm>
#include <array>
#include <numeric>

#include "ai/games.hpp"
#include "ai/internal/evaluate.hpp"
#include "ai/internal/game_levels.hpp"
#include "ai/internal/level.hpp"
#include "ai/internal/parallel.hpp"
#include "physics/cue_strike.hpp"
#include "physics/markings.hpp"
#include "physics/simulate.hpp"

namespace ai {

namespace {

struct Spin {
    double side, top;
};
// Running side (either way) with a little follow, then centre, then less side: the first
// `effort.spins`. Side spin changes the angle off each cushion, so it opens other paths.
constexpr std::array<Spin, 5> spins{{{0.4, 0.2}, {-0.4, 0.2}, {0.0, 0.2}, {0.2, 0.0}, {-0.2, 0.0}}};
constexpr std::array<double, 3> ball_speeds{2.8, 3.8, 2.0};  // (unit: m/s)
constexpr double leave_weight = 0.5;  // a leave where every stroke scores adds half a point

struct Outcome {
    bool point = false;
    bool foul = false;
    double fallback = 0.0;  ///< without a point: both balls met, cushions toward three
    rules::CaromState after;
};

Outcome play(const CaromPosition& pos, const rules::CaromState& s, const physics::Stroke& stroke) {
    const physics::Shot shot =
        physics::simulate(pos.table, pos.params, physics::balls_at_rest(s.positions), &stroke);
    const rules::CaromVerdict v = rules::judge_three_cushion(
        pos.options, physics::carom_spots(pos.table), pos.params.ball_radius, s, shot.events());
    Outcome o;
    o.point = v.point;
    o.foul = v.foul;
    int met = 0;
    for (const physics::Event& e : shot.events())
        if (e.type == physics::EventType::ball_ball && e.involves(stroke.ball)) ++met;
    o.fallback = o.foul ? -1.0 : 0.2 * std::min(met, 2) + 0.03 * std::min(v.cushions, 3);
    o.after = v.state;
    return o;
}

// The sweep's strokes from the shooter's cue ball: headings × speeds × spins, heading fastest.
std::vector<physics::Stroke> sweep(const CaromPosition& pos, const rules::CaromState& s,
                                   int headings, int speeds, int n_spins) {
    std::vector<physics::Stroke> out;
    for (int k = 0; k < std::min<int>(speeds, ball_speeds.size()); ++k)
        for (int j = 0; j < std::min<int>(n_spins, spins.size()); ++j)
            for (int i = 0; i < headings; ++i) {
                physics::Stroke st;
                st.ball = s.cue_ball(s.shooter);
                st.speed =
                    physics::cue_speed_for_ball_speed(pos.params, ball_speeds[std::size_t(k)]);
                st.side = spins[std::size_t(j)].side;
                st.top = spins[std::size_t(j)].top;
                st.heading_deg = 360.0 * i / headings;
                out.push_back(st);
            }
    return out;
}

std::vector<Outcome> play_all(const CaromPosition& pos, const rules::CaromState& s,
                              const std::vector<physics::Stroke>& strokes, Workers workers) {
    std::vector<Outcome> out(strokes.size());
    parallel_for(strokes.size(), workers,
                 [&](std::size_t i) { out[i] = play(pos, s, strokes[i]); });
    return out;
}

struct Run {
    physics::Stroke stroke;  ///< at the middle of the run's headings
    int width = 0;           ///< scoring headings in a row
};

// The runs of scoring headings in each (speed, spin) row of the sweep, the row wrapping round.
std::vector<Run> scoring_runs(const std::vector<physics::Stroke>& strokes,
                              const std::vector<Outcome>& o, int headings) {
    std::vector<Run> runs;
    const int h = headings;
    for (std::size_t row = 0; row < strokes.size() / std::size_t(h); ++row) {
        const auto at = [&](int i) {
            return o[row * std::size_t(h) + std::size_t((i % h + h) % h)];
        };
        int start = 0;  // a heading that does not score, so that no run is cut at the wrap
        while (start < h && at(start).point) ++start;
        if (start == h) start = 0;
        for (int i = start + 1; i <= start + h; ++i) {
            if (!at(i).point) continue;
            int end = i;
            while (end + 1 <= start + h && at(end + 1).point) ++end;
            Run r;
            r.stroke = strokes[row * std::size_t(h)];
            r.width = end - i + 1;
            r.stroke.heading_deg = 360.0 * (0.5 * (i + end)) / h;
            if (r.stroke.heading_deg >= 360.0) r.stroke.heading_deg -= 360.0;
            runs.push_back(r);
            i = end;
        }
    }
    return runs;
}

// Moves each run's stroke to the middle of its window of scoring headings, found on a sweep
// `fine` times finer around it: a heading near a window's edge misses with much of the noise.
void centre_runs(const CaromPosition& pos, std::vector<Run>& runs, int headings, int fine,
                 Workers workers, std::int64_t& simulations) {
    const double step = 360.0 / headings / fine;
    std::vector<std::vector<char>> scores(runs.size());
    std::vector<std::pair<std::size_t, int>> jobs;  // (run, offset in fine steps)
    std::vector<int> reach(runs.size());
    for (std::size_t r = 0; r < runs.size(); ++r) {
        reach[r] = (runs[r].width / 2 + 1) * fine;
        scores[r].resize(std::size_t(2 * reach[r] + 1));
        for (int k = -reach[r]; k <= reach[r]; ++k) jobs.push_back({r, k});
    }
    parallel_for(jobs.size(), workers, [&](std::size_t j) {
        const auto [r, k] = jobs[j];
        physics::Stroke s = runs[r].stroke;
        s.heading_deg += k * step;
        scores[r][std::size_t(k + reach[r])] = play(pos, pos.state, s).point;
    });
    simulations += std::int64_t(jobs.size());
    for (std::size_t r = 0; r < runs.size(); ++r) {
        // The longest run of scoring fine headings; its middle.
        int best_len = 0, best_mid = 0;
        for (int i = 0; i < int(scores[r].size());) {
            if (!scores[r][std::size_t(i)]) {
                ++i;
                continue;
            }
            int e = i;
            while (e + 1 < int(scores[r].size()) && scores[r][std::size_t(e + 1)]) ++e;
            if (e - i + 1 > best_len) {
                best_len = e - i + 1;
                best_mid = i + e - 2 * reach[r];  // twice the middle's offset
            }
            i = e + 1;
        }
        if (best_len > 0) runs[r].stroke.heading_deg += 0.5 * best_mid * step;
    }
}

// Each run's chance of a point under the level's noise (1 without noise): the same draws for
// every run.
std::vector<double> point_rates(const CaromPosition& pos, const std::vector<Run>& runs,
                                const CaromEffort& effort, double scale, std::uint64_t seed,
                                Workers workers, std::int64_t& simulations) {
    std::vector<double> rate(runs.size(), 1.0);
    if (scale == 0.0) return rate;
    const std::size_t n = std::size_t(effort.samples);
    const std::vector<NoiseDraw> draws = noise_draws(seed, int(n));
    std::vector<char> pt(runs.size() * n);
    parallel_for(pt.size(), workers, [&](std::size_t j) {
        pt[j] = play(pos, pos.state, with_draw(runs[j / n].stroke, draws[j % n], scale)).point;
    });
    simulations += std::int64_t(pt.size());
    for (std::size_t r = 0; r < runs.size(); ++r)
        rate[r] = std::accumulate(pt.begin() + long(r * n), pt.begin() + long((r + 1) * n), 0.0) /
                  double(n);
    return rate;
}

// The runs' values: the chance of a point, raised for the likeliest few by the position the
// noiseless point leaves (the share of a coarse sweep from there that scores, a quarter
// counting in full).
std::vector<double> with_leaves(const CaromPosition& pos, const std::vector<Run>& runs,
                                const std::vector<double>& rate, const CaromEffort& effort,
                                Workers workers, std::int64_t& simulations) {
    std::vector<double> value = rate;
    std::vector<std::size_t> order(runs.size());
    std::iota(order.begin(), order.end(), 0);
    std::stable_sort(order.begin(), order.end(),
                     [&](std::size_t a, std::size_t b) { return rate[a] > rate[b]; });
    for (std::size_t k = 0; k < std::min(order.size(), std::size_t(effort.leave_checked)); ++k) {
        const std::size_t r = order[k];
        const Outcome o = play(pos, pos.state, runs[r].stroke);
        if (!o.point) continue;
        const std::vector<physics::Stroke> next = sweep(pos, o.after, effort.leave_headings, 2, 2);
        const std::vector<Outcome> t = play_all(pos, o.after, next, workers);
        simulations += 1 + std::int64_t(next.size());
        const double scoring =
            double(std::count_if(t.begin(), t.end(), [](const Outcome& x) { return x.point; }));
        value[r] = rate[r] * (1.0 + leave_weight * std::min(1.0, 4.0 * scoring / double(t.size())));
    }
    return value;
}

}  // namespace

CaromPlan plan_three_cushion(const CaromPosition& pos, const PlanSettings& settings,
                             std::uint64_t seed) {
    const CaromEffort effort = carom_effort(settings.level);
    const double scale = planned_scale(settings);
    const Workers workers{std::max(settings.workers, 1), settings.pause};
    CaromPlan plan;
    const std::vector<physics::Stroke> strokes =
        sweep(pos, pos.state, effort.headings, effort.speeds, effort.spins);
    const std::vector<Outcome> nominal = play_all(pos, pos.state, strokes, workers);
    plan.simulations = static_cast<std::int64_t>(strokes.size());
    std::vector<Run> runs = scoring_runs(strokes, nominal, effort.headings);
    if (runs.empty()) {  // nothing scores: the stroke that comes nearest, without a foul
        std::size_t b = 0;
        for (std::size_t i = 1; i < nominal.size(); ++i)
            if (nominal[i].fallback > nominal[b].fallback) b = i;
        plan.stroke = strokes[b];
        plan.expected_value = nominal[b].fallback;
        return plan;
    }
    std::stable_sort(runs.begin(), runs.end(),
                     [](const Run& a, const Run& b) { return a.width > b.width; });
    runs.resize(std::min(runs.size(), std::size_t(std::max(effort.shortlist, 1))));
    if (effort.centring > 1)
        centre_runs(pos, runs, effort.headings, effort.centring, workers, plan.simulations);
    const std::vector<double> rate =
        point_rates(pos, runs, effort, scale, seed, workers, plan.simulations);
    const std::vector<double> value =
        with_leaves(pos, runs, rate, effort, workers, plan.simulations);
    std::size_t b = 0;
    for (std::size_t r = 1; r < runs.size(); ++r)
        if (value[r] > value[b]) b = r;
    plan.stroke = runs[b].stroke;
    plan.expected_success = rate[b];
    plan.expected_value = value[b];
    return plan;
}

}  // namespace ai
