#include "ai/planner.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>

#include "ai/candidates.hpp"
#include "ai/evaluate.hpp"
#include "ai/ghost_ball.hpp"
#include "ai/heading_window.hpp"
#include "ai/level.hpp"
#include "ai/parallel.hpp"
#include "ai/placement.hpp"
#include "ai/selection.hpp"
#include "ai/table_value.hpp"
#include "rules/eight_ball.hpp"

namespace ai {

namespace {

constexpr double good_enough = 0.5;  // below this nominal value, kicks and banks are tried too
constexpr double miss_value = 0.4;   // a rough value of missing a pot, for the shortlist only
constexpr double min_combination_chance = 0.3;  // ball in hand: a spot for a combination on the 9

struct Search {
    const Position& pos;
    Effort effort;
    Evaluator eval;
    std::vector<NoiseDraw> draws;
    int workers;
    std::int64_t simulations = 0;
};

double normalized(double heading_deg) {
    double h = std::fmod(heading_deg, 360.0);
    if (h < 0.0) h += 360.0;
    return h;
}

// Noiseless play of the candidates at `which`: their nominal scores (with their leaves where the
// search keeps places for distinct ones).
void score_nominal(Search& s, std::vector<Candidate>& cands, std::vector<Score>& nominal,
                   const std::vector<std::size_t>& which) {
    nominal.resize(cands.size());
    const bool with_leave = s.effort.distinct_leaves > 0.0;
    parallel_for(which.size(), s.workers, [&](std::size_t k) {
        const std::size_t i = which[k];
        const Trial t = s.eval.nominal(cands[i], with_leave);
        // A pot that works without noise still misses now and then: rank by its chance.
        const double value = cands[i].kind == Kind::pot && s.eval.scale() > 0.0
                                 ? cands[i].prior * t.value + (1.0 - cands[i].prior) * miss_value
                                 : t.value;
        nominal[i] = Score{value, t.success ? 1.0 : 0.0, 1, t.foul, t.leave};
        nominal[i].stays = t.stays;
    });
    s.simulations += static_cast<std::int64_t>(which.size());
}

// The indices [from, end).
std::vector<std::size_t> indices_from(std::size_t from, std::size_t end) {
    std::vector<std::size_t> v(end - from);
    std::iota(v.begin(), v.end(), from);
    return v;
}

std::vector<std::size_t> all_indices(std::size_t n) {
    return indices_from(0, n);
}

// Noiseless play of candidates [from, end).
void score_nominal(Search& s, std::vector<Candidate>& cands, std::vector<Score>& nominal,
                   std::size_t from) {
    score_nominal(s, cands, nominal, indices_from(from, cands.size()));
}

// Under noise, the pots of `which` that pot without noise turned to the middle of their window
// of headings (heading_window.hpp), and played again without noise.
void centre_pots(Search& s, std::vector<Candidate>& cands, std::vector<Score>& nominal,
                 const std::vector<std::size_t>& which) {
    if (!s.effort.centred_pots || s.eval.scale() == 0.0) return;
    std::vector<std::int64_t> sims(which.size(), 0);
    std::vector<char> moved(which.size(), 0);
    parallel_for(which.size(), s.workers, [&](std::size_t k) {
        Candidate& c = cands[which[k]];
        if (c.kind != Kind::pot || !nominal[which[k]].stays) return;
        if (std::optional<Candidate> m = centred(s.eval, c, pot_window_search, sims[k])) {
            c = *m;
            moved[k] = 1;
        }
    });
    s.simulations += std::accumulate(sims.begin(), sims.end(), std::int64_t{0});
    std::vector<std::size_t> again;
    for (std::size_t k = 0; k < which.size(); ++k)
        if (moved[k]) again.push_back(which[k]);
    score_nominal(s, cands, nominal, again);
}

// Shortlist under noise, then more draws for the finalists; with `deeper` (where the level has
// it) the best pots are searched around finer and the best few valued two plies deep. Returns
// the index of the best; `cands`, `nominal` and `noisy` grow by the variants.
std::size_t choose_under_noise(Search& s, std::vector<Candidate>& cands,
                               std::vector<Score>& nominal, std::vector<Score>& noisy,
                               std::size_t shortlist, bool deeper) {
    // The share of each round kept for distinct leaves (selection.hpp): 8-ball only (for_game in
    // level.hpp), where the shooter chooses the order of his balls.
    const double share = deeper ? s.effort.distinct_leaves : 0.0;
    std::vector<std::size_t> list =
        distinct_best_of(nominal, nominal, all_indices(cands.size()), shortlist, share);
    centre_pots(s, cands, nominal, list);
    noisy.assign(cands.size(), Score{});
    const std::size_t n = s.eval.scale() == 0.0 ? 1 : static_cast<std::size_t>(s.effort.samples);
    s.simulations += score_under_noise(s.eval, cands, list, s.draws, 0, n, noisy, s.workers);
    std::size_t drawn = n;
    if (s.eval.scale() > 0.0 && s.effort.finalists > 1) {
        std::vector<std::size_t> finals = distinct_best_of(
            noisy, nominal, list, static_cast<std::size_t>(s.effort.finalists), share);
        const std::size_t more =
            static_cast<std::size_t>(std::max(s.effort.finalist_rounds, 1)) * n;
        s.simulations +=
            score_under_noise(s.eval, cands, finals, s.draws, n, more, noisy, s.workers);
        list = finals;
        drawn = n + more;
    }
    if (deeper && s.effort.polish > 0) {
        const std::size_t from = cands.size();
        for (std::size_t i : best_of(noisy, list, static_cast<std::size_t>(s.effort.polish))) {
            std::vector<Candidate> more = pot_variants(s.pos, cands[i], s.effort, s.simulations);
            cands.insert(cands.end(), more.begin(), more.end());
        }
        score_nominal(s, cands, nominal, from);
        const std::vector<std::size_t> added = indices_from(from, cands.size());
        centre_pots(s, cands, nominal, added);
        noisy.resize(cands.size());
        s.simulations +=
            score_under_noise(s.eval, cands, added, s.draws, 0, drawn, noisy, s.workers);
        list.insert(list.end(), added.begin(), added.end());
    }
    if (deeper && s.effort.deep_finalists > 0) {
        list = distinct_best_of(noisy, nominal, list,
                                static_cast<std::size_t>(s.effort.deep_finalists), share);
        // Without noise one exact play; else one round of deep_samples draws, or successive
        // halving: half of them first, then the better half of each round as many again. With
        // draws of its own (level.hpp) they come after the `drawn` of the one-ply rounds.
        const bool noisy_play = s.eval.scale() != 0.0;
        const int halvings = noisy_play ? std::max(s.effort.deep_halvings, 0) : 0;
        const std::size_t first = noisy_play && s.effort.fresh_deep_draws ? drawn : 0;
        std::size_t done = 1;
        if (noisy_play) {
            const int m = s.effort.deep_samples;
            done = static_cast<std::size_t>(std::max(halvings > 0 ? m / 2 : m, 1));
        }
        s.simulations +=
            score_deep(s.eval, cands, list, s.draws, first, done, s.effort, noisy, s.workers);
        for (int h = 0; h < halvings && list.size() > 1; ++h, done *= 2) {
            list = best_of(noisy, list, (list.size() + 1) / 2);
            s.simulations += score_deep(s.eval, cands, list, s.draws, first + done, done, s.effort,
                                        noisy, s.workers);
        }
    }
    return best_of(noisy, list, 1).front();
}

game::Decision decision_of(const Candidate& c) {
    game::Decision d;
    d.cue_pos = c.cue_pos;
    d.call = c.call;
    d.push_out = c.kind == Kind::push_out;
    d.stroke = c.stroke;
    d.stroke.heading_deg = normalized(c.stroke.heading_deg);
    return d;
}

Plan plan_choice(const Position& pos, double sigma_deg, double stuck_cost) {
    Plan p;
    const rules::Choice& c = *pos.choice;
    double best = -1.0;
    for (rules::ChoiceOption o : c.options) {
        const double v = option_value(pos, pos.state, o, c.by, sigma_deg, stuck_cost);
        if (v > best) {
            best = v;
            p.decision.choice = o;
        }
    }
    p.expected_success = best;
    p.expected_value = best;
    return p;
}

// The level's effort for `pos`: level 5 searches wider near the end of an 8-ball rack
// (rack_end_effort; in 9-ball that wider search was not shown to help: docs/ai.md, stop 17) and
// deeper in every 9-ball decision (nine_ball_effort; stop 19).
Effort effort_for(const Position& pos, int level) {
    if (pos.ruleset.game == rules::Game::nine_ball)
        return for_game(nine_ball_effort(level), pos.ruleset.game);
    const bool rack_end = near_rack_end(pos.ruleset, pos.state);
    return for_game(rack_end ? rack_end_effort(level) : effort_for_level(level), pos.ruleset.game);
}

Plan plan_break(Search& s) {
    std::vector<Candidate> cands = break_candidates(s.pos, s.effort.tuned_breaks);
    std::vector<Score> scores(cands.size());
    const std::size_t n =
        s.eval.scale() == 0.0 ? 1 : static_cast<std::size_t>(s.effort.break_samples);
    s.simulations += score_under_noise(s.eval, cands, all_indices(cands.size()), s.draws, 0, n,
                                       scores, s.workers);
    const std::size_t best = best_of(scores, all_indices(cands.size()), 1).front();
    Plan p;
    p.decision = decision_of(cands[best]);
    p.kind = cands[best].kind;
    p.expected_success = scores[best].success;
    p.expected_value = scores[best].value;
    p.simulations = s.simulations;
    return p;
}

}  // namespace

double planned_scale(const PlanSettings& settings) {
    return settings.noise * effort_for_level(settings.level).noise_multiplier;
}

double model_sigma_deg(const physics::Params& params, const Effort& effort, double scale) {
    const double cue = heading_sigma_deg(params);
    return (effort.model_sigma_deg > 0.0 ? std::min(effort.model_sigma_deg, cue) : cue) * scale;
}

Plan plan(const Position& pos, const PlanSettings& settings, std::uint64_t seed) {
    const Effort effort = effort_for(pos, settings.level);
    const double scale = planned_scale(settings);
    const double sigma_deg = model_sigma_deg(pos.params, effort, scale);
    if (pos.choice) return plan_choice(pos, sigma_deg, effort.stuck_ball_cost);

    Search s{pos, effort, Evaluator(pos, scale, sigma_deg, effort.stuck_ball_cost),
             noise_draws(seed, draw_pool(effort)), std::max(settings.workers, 1)};
    if (pos.state.shot == rules::Shot::break_shot) return plan_break(s);

    const bool in_hand = cue_in_hand(pos.state);
    std::vector<physics::Vec2> spots;
    if (in_hand)
        spots = cue_spots(pos, effort.placements, sigma_deg);
    else
        spots = {pos.state.positions.at(0)};

    std::vector<Candidate> cands;
    for (physics::Vec2 cue : spots) {
        std::vector<Candidate> pots =
            pot_candidates(pos, cue, in_hand, effort, sigma_deg, s.simulations);
        std::vector<Candidate> safe = safety_candidates(pos, cue, in_hand, effort);
        std::vector<Candidate> combos =
            combination_candidates(pos, cue, in_hand, effort, sigma_deg, s.simulations);
        cands.insert(cands.end(), pots.begin(), pots.end());
        cands.insert(cands.end(), safe.begin(), safe.end());
        cands.insert(cands.end(), combos.begin(), combos.end());
    }
    if (in_hand && effort.combinations > 0)  // spots of their own for combinations on the 9
        for (physics::Vec2 cue : combination_spots(pos, 2, sigma_deg, min_combination_chance)) {
            std::vector<Candidate> combos =
                combination_candidates(pos, cue, true, effort, sigma_deg, s.simulations);
            cands.insert(cands.end(), combos.begin(), combos.end());
        }
    std::vector<Score> nominal;
    score_nominal(s, cands, nominal, 0);
    const auto legal_best = [&] {
        double best = -1.0;
        for (const Score& sc : nominal)
            if (!sc.foul) best = std::max(best, sc.value);
        return best;
    };
    const bool pot_works = std::any_of(cands.begin(), cands.end(), [&](const Candidate& c) {
        return c.kind == Kind::pot &&
               nominal[static_cast<std::size_t>(&c - cands.data())].success > 0.0;
    });
    if (legal_best() < good_enough || !pot_works) {
        const std::size_t from = cands.size();
        for (physics::Vec2 cue : spots) {
            std::vector<Candidate> kicks = kick_candidates(pos, cue, in_hand, effort);
            cands.insert(cands.end(), kicks.begin(), kicks.end());
            if (in_hand) break;  // one spot is enough for a sweep
        }
        score_nominal(s, cands, nominal, from);
        if (effort.centred_kicks > 0) {  // the kicks that pot, centred in their windows
            const std::vector<Candidate> kicks(cands.begin() + static_cast<std::ptrdiff_t>(from),
                                               cands.end());
            const std::vector<Score> kick_scores(
                nominal.begin() + static_cast<std::ptrdiff_t>(from), nominal.end());
            // Raised against the squirt only under noise (without it a level cue is exact).
            const double raise = s.eval.scale() > 0.0 ? effort.max_raise_deg : 0.0;
            const std::vector<Candidate> centred = centred_kicks(
                s.eval, kicks, kick_scores, static_cast<std::size_t>(effort.centred_kicks), raise,
                s.simulations, s.workers);
            const std::size_t at = cands.size();
            cands.insert(cands.end(), centred.begin(), centred.end());
            score_nominal(s, cands, nominal, at);
        }
    }
    if (cands.empty()) {  // cannot happen with a legal ball on the table; be safe anyway
        Candidate c;
        c.kind = Kind::safety;
        c.cue_pos = in_hand ? std::optional<physics::Vec2>(spots.front()) : std::nullopt;
        c.call = safety_call(pos);
        c.stroke.speed = 1.5;
        cands.push_back(c);
        nominal.push_back(Score{});
    }

    std::vector<Score> noisy;
    const std::size_t best = choose_under_noise(s, cands, nominal, noisy,
                                                static_cast<std::size_t>(effort.shortlist), true);
    Candidate chosen = cands[best];
    double chosen_value = noisy[best].value, chosen_success = noisy[best].success;

    if (rules::push_out_allowed(pos.ruleset.game, pos.state) && !in_hand &&
        chosen_value < good_enough) {
        std::vector<Candidate> pushes = push_out_candidates(pos, pos.state.positions.at(0));
        std::vector<Score> push_nominal;
        score_nominal(s, pushes, push_nominal, 0);
        std::vector<Score> push_noisy;
        const std::size_t p =
            choose_under_noise(s, pushes, push_nominal, push_noisy,
                               static_cast<std::size_t>(effort.shortlist / 2 + 1), false);
        if (push_noisy[p].value > chosen_value) {
            chosen = pushes[p];
            chosen_value = push_noisy[p].value;
            chosen_success = push_noisy[p].success;
        }
    }

    Plan out;
    out.decision = decision_of(chosen);
    out.kind = chosen.kind;
    out.expected_success = chosen_success;
    out.expected_value = chosen_value;
    out.simulations = s.simulations;
    return out;
}

}  // namespace ai
