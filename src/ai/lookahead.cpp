#include "ai/internal/lookahead.hpp"

#include <algorithm>
#include <optional>
#include <vector>

#include "ai/internal/candidates.hpp"
#include "ai/internal/evaluate.hpp"
#include "ai/internal/table_value.hpp"

namespace ai {

namespace {

// The value of `s` to its shooter over his next `shots` shots: his best pot by the one-ply value
// (as next_turn_value), and where `shots` > 1 the table that pot leaves valued the same way for
// one shot fewer in place of its one-ply value.
double turn_value(const Position& base, const rules::GameState& s, const Effort& effort,
                  double scale, double sigma_deg, std::int64_t& simulations, int shots) {
    auto cue = s.positions.find(0);
    if (cue_in_hand(s) || cue == s.positions.end())
        return position_value(base, s, sigma_deg, effort.stuck_ball_cost);
    const Position next{base.ruleset, base.table, base.params, s, std::nullopt};
    Effort second = effort;
    second.pot_pairs = effort.next_pairs;
    second.speeds = effort.next_speeds;
    second.spins = effort.next_spins;
    second.refine_steps = 1;     // one secant step: the second ply only ranks
    second.max_raise_deg = 0.0;  // played without noise
    std::vector<RankedAim> aims = ranked_aims(next, cue->second, sigma_deg);
    if (aims.size() > static_cast<std::size_t>(second.pot_pairs))
        aims.resize(static_cast<std::size_t>(second.pot_pairs));
    const Evaluator eval(next, scale, sigma_deg, effort.stuck_ball_cost);
    // Nothing on: a safety keeps the game about even (less what his stuck balls cost him).
    const double safe = table_value(0.0) - stuck_penalty(base, s, effort.stuck_ball_cost);
    double best = safe;
    std::optional<Candidate> chosen;
    for (const RankedAim& r : aims) {
        // No stroke of this pot, nor of the less likely ones after it, can beat `best`: a
        // stroke is worth at most chance × 1 + (1 − chance) × the miss (the result is the same).
        if (r.chance + (1.0 - r.chance) * next_miss_value <= best) break;
        for (Candidate& c : pot_strokes(next, cue->second, false, r, second, simulations)) {
            const Trial t = eval.nominal(c);
            ++simulations;
            const double v = c.prior * t.value + (1.0 - c.prior) * next_miss_value;
            if (v > best) {
                best = v;
                chosen = c;
            }
        }
    }
    if (shots <= 1 || !chosen) return best;
    std::optional<rules::GameState> after;
    eval.nominal_to(*chosen, after);
    ++simulations;
    if (!after) return best;  // won, or the turn ends: its one-ply value is exact enough
    const double on = staying_value(
        s, *after, turn_value(base, *after, effort, scale, sigma_deg, simulations, shots - 1));
    return std::max(safe, chosen->prior * on + (1.0 - chosen->prior) * next_miss_value);
}

}  // namespace

double next_turn_value(const Position& base, const rules::GameState& s, const Effort& effort,
                       double scale, double sigma_deg, std::int64_t& simulations) {
    return turn_value(base, s, effort, scale, sigma_deg, simulations,
                      std::max(effort.playout_shots, 1));
}

}  // namespace ai
