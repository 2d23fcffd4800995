#include "ai/internal/heading_window.hpp"

#include <algorithm>
#include <numeric>

#include "ai/internal/aim.hpp"
#include "ai/internal/parallel.hpp"
#include "game/session.hpp"

namespace ai {

namespace {

constexpr double min_kick_raise_deg = 1.0;  // below this a kick stays on a level cue (unit: deg)

// Whether `c` turned to `heading_deg` pots as `call` says (the shooter stays at the table with
// that call: a kick's is that of what it pots; in 9-ball there is none).
bool pots_at(const Evaluator& eval, Candidate c, double heading_deg, const rules::Call& call,
             std::int64_t& simulations) {
    c.stroke.heading_deg = heading_deg;
    const Trial t = eval.nominal(c);
    simulations += t.simulations;
    return t.stays && c.call == call;
}

// The kick `c` (centred on a level cue) raised to where a side error's swerve cancels its squirt,
// the ball's speed kept, and centred again; empty where raising does not help or it no longer
// pots.
std::optional<Candidate> raised_kick(const Evaluator& eval, const Candidate& c,
                                     double max_raise_deg, std::int64_t& simulations) {
    const Position& pos = eval.position();
    const physics::Vec2 cue = c.cue_pos ? *c.cue_pos : pos.state.positions.at(0);
    const std::vector<physics::BallState> balls = layout(pos.state, cue);
    const double e = kick_compensating_elevation(pos.table, pos.params, balls, c.stroke,
                                                 max_raise_deg, simulations);
    if (e < min_kick_raise_deg) return std::nullopt;
    Candidate r = c;
    r.stroke.speed = std::min(speed_for_elevation(c.stroke, e), game::max_stroke_speed);
    r.stroke.elevation_deg = e;
    return centred(eval, r, kick_window_search, simulations);
}

}  // namespace

HeadingWindow heading_window(const Evaluator& eval, const Candidate& c, const WindowSearch& search,
                             std::int64_t& simulations) {
    const double h = c.stroke.heading_deg;
    // The last heading that pots going `direction` (±1) from h.
    const auto edge = [&](double direction) {
        double in = 0.0, step = search.first_step_deg;  // offsets from h
        for (;;) {
            const double out = std::min(in + step, search.reach_deg);
            if (!pots_at(eval, c, h + direction * out, c.call, simulations)) {
                double bad = out;
                for (int b = 0; b < search.halvings; ++b) {
                    const double mid = 0.5 * (in + bad);
                    (pots_at(eval, c, h + direction * mid, c.call, simulations) ? in : bad) = mid;
                }
                return h + direction * in;
            }
            in = out;
            if (in >= search.reach_deg) return h + direction * in;  // potting all the way
            step *= search.growth;
        }
    };
    const double low = edge(-1.0);
    return HeadingWindow{low, edge(1.0)};
}

std::optional<Candidate> centred(const Evaluator& eval, const Candidate& c,
                                 const WindowSearch& search, std::int64_t& simulations) {
    Candidate m = c;
    if (m.kind == Kind::kick) {  // a kick's call is what it pots without noise
        const Trial t = eval.nominal(m);
        simulations += t.simulations;
        if (!t.stays) return std::nullopt;
    } else if (!pots_at(eval, m, m.stroke.heading_deg, m.call, simulations)) {
        return std::nullopt;
    }
    const HeadingWindow w = heading_window(eval, m, search, simulations);
    m.stroke.heading_deg = 0.5 * (w.low_deg + w.high_deg);
    if (!pots_at(eval, m, m.stroke.heading_deg, m.call, simulations)) return std::nullopt;
    return m;
}

std::vector<Candidate> centred_kicks(const Evaluator& eval, const std::vector<Candidate>& kicks,
                                     const std::vector<Score>& nominal, std::size_t count,
                                     double max_raise_deg, std::int64_t& simulations,
                                     Workers workers) {
    std::vector<std::size_t> potting;
    for (std::size_t i = 0; i < kicks.size(); ++i)
        if (kicks[i].kind == Kind::kick && nominal[i].stays) potting.push_back(i);
    std::stable_sort(potting.begin(), potting.end(), [&](std::size_t a, std::size_t b) {
        return nominal[a].value > nominal[b].value;
    });
    if (potting.size() > count) potting.resize(count);
    // Each kick's variants in slots of their own (parallel.hpp), in a fixed order.
    std::vector<std::vector<Candidate>> found(potting.size());
    std::vector<std::int64_t> sims(potting.size(), 0);
    parallel_for(potting.size(), workers, [&](std::size_t k) {
        const Candidate& kick = kicks[potting[k]];
        for (double factor : kick_speed_factors) {
            Candidate c = kick;
            c.stroke.speed = kick.stroke.speed * factor;
            std::optional<Candidate> m = centred(eval, c, kick_window_search, sims[k]);
            if (!m) continue;
            found[k].push_back(*m);
            if (max_raise_deg <= 0.0) continue;
            if (std::optional<Candidate> r = raised_kick(eval, *m, max_raise_deg, sims[k]))
                found[k].push_back(*r);
        }
    });
    simulations += std::accumulate(sims.begin(), sims.end(), std::int64_t{0});
    std::vector<Candidate> out;
    const auto tried = [&](const Candidate& c) {
        const auto same = [&](const Candidate& o) {
            return o.stroke.speed == c.stroke.speed &&
                   o.stroke.heading_deg == c.stroke.heading_deg &&
                   o.stroke.elevation_deg == c.stroke.elevation_deg;
        };
        return std::any_of(kicks.begin(), kicks.end(), same) ||
               std::any_of(out.begin(), out.end(), same);
    };
    for (const std::vector<Candidate>& v : found)
        for (const Candidate& c : v)
            if (!tried(c)) out.push_back(c);
    return out;
}

}  // namespace ai
