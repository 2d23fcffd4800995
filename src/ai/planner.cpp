#include "ai/internal/planner.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <utility>

#include "ai/internal/candidates.hpp"
#include "ai/internal/evaluate.hpp"
#include "ai/internal/ghost_ball.hpp"
#include "ai/internal/heading_window.hpp"
#include "ai/internal/level.hpp"
#include "ai/internal/parallel.hpp"
#include "ai/internal/placement.hpp"
#include "ai/internal/selection.hpp"
#include "ai/internal/table_value.hpp"
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
    Workers workers;
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
void score_nominal_from(Search& s, std::vector<Candidate>& cands, std::vector<Score>& nominal,
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

// The one-ply rounds: the shortlist `list` under noise, then, where the level has finalists, more
// draws for the best few, which `list` becomes. Returns the draws each of `list` got.
std::size_t noisy_rounds(Search& s, const std::vector<Candidate>& cands,
                         const std::vector<Score>& nominal, std::vector<Score>& noisy,
                         std::vector<std::size_t>& list, double share) {
    noisy.assign(cands.size(), Score{});
    const std::size_t n = s.eval.scale() == 0.0 ? 1 : static_cast<std::size_t>(s.effort.samples);
    s.simulations += score_under_noise(s.eval, cands, list, s.draws, 0, n, noisy, s.workers);
    if (!(s.eval.scale() > 0.0 && s.effort.finalists > 1)) return n;
    std::vector<std::size_t> finals =
        distinct_best_of(noisy, nominal, list, static_cast<std::size_t>(s.effort.finalists), share);
    const std::size_t more = static_cast<std::size_t>(std::max(s.effort.finalist_rounds, 1)) * n;
    s.simulations += score_under_noise(s.eval, cands, finals, s.draws, n, more, noisy, s.workers);
    list = finals;
    return n + more;
}

// The best few pots of `list` searched around finer (candidates.hpp's pot_variants): the variants
// played without noise, centred, played on the same `drawn` draws, and added to `list`.
void polish_pots(Search& s, std::vector<Candidate>& cands, std::vector<Score>& nominal,
                 std::vector<Score>& noisy, std::vector<std::size_t>& list, std::size_t drawn) {
    const std::size_t from = cands.size();
    for (std::size_t i : best_of(noisy, list, static_cast<std::size_t>(s.effort.polish))) {
        std::vector<Candidate> more = pot_variants(s.pos, cands[i], s.effort, s.simulations);
        cands.insert(cands.end(), more.begin(), more.end());
    }
    score_nominal_from(s, cands, nominal, from);
    const std::vector<std::size_t> added = indices_from(from, cands.size());
    centre_pots(s, cands, nominal, added);
    noisy.resize(cands.size());
    s.simulations += score_under_noise(s.eval, cands, added, s.draws, 0, drawn, noisy, s.workers);
    list.insert(list.end(), added.begin(), added.end());
}

// The deep finalists of `list` (which it becomes) valued two plies deep (lookahead.hpp). Without
// noise one exact play; else one round of deep_samples draws, or successive halving: half of
// them first, then the better half of each round as many again. With draws of its own
// (Effort::fresh_deep_draws) they come after the `drawn` of the one-ply rounds.
void deep_search(Search& s, const std::vector<Candidate>& cands, const std::vector<Score>& nominal,
                 std::vector<Score>& noisy, std::vector<std::size_t>& list, std::size_t drawn,
                 double share) {
    list = distinct_best_of(noisy, nominal, list, static_cast<std::size_t>(s.effort.deep_finalists),
                            share);
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

// Shortlist under noise, then more draws for the finalists; with `deeper` (where the level has
// it) the best pots are searched around finer and the best few valued two plies deep. Returns
// the index of the best; `cands`, `nominal` and `noisy` grow by the variants.
std::size_t choose_under_noise(Search& s, std::vector<Candidate>& cands,
                               std::vector<Score>& nominal, std::vector<Score>& noisy,
                               std::size_t shortlist, bool deeper) {
    // The share of each round kept for distinct leaves (selection.hpp): 0 in 9-ball's effort,
    // where the next ball is always the lowest.
    const double share = deeper ? s.effort.distinct_leaves : 0.0;
    std::vector<std::size_t> list =
        distinct_best_of(nominal, nominal, all_indices(cands.size()), shortlist, share);
    centre_pots(s, cands, nominal, list);
    const std::size_t drawn = noisy_rounds(s, cands, nominal, noisy, list, share);
    if (deeper && s.effort.polish > 0) polish_pots(s, cands, nominal, noisy, list, drawn);
    if (deeper && s.effort.deep_finalists > 0)
        deep_search(s, cands, nominal, noisy, list, drawn, share);
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

// The level's effort for `pos`: its game's, and in 8-ball the rack end's near the end of a rack.
Effort effort_at(const Position& pos, int level) {
    return effort_for(pos.ruleset.game, level, near_rack_end(pos.ruleset, pos.state));
}

// The plan that plays `c`, valued by its score under noise.
Plan plan_of(const Candidate& c, const Score& score, std::int64_t simulations) {
    Plan p;
    p.decision = decision_of(c);
    p.kind = c.kind;
    p.expected_success = score.success;
    p.expected_value = score.value;
    p.simulations = simulations;
    return p;
}

Plan plan_break(Search& s) {
    std::vector<Candidate> cands = break_candidates(s.pos, s.effort.tuned_breaks);
    std::vector<Score> scores(cands.size());
    const std::size_t n =
        s.eval.scale() == 0.0 ? 1 : static_cast<std::size_t>(s.effort.break_samples);
    s.simulations += score_under_noise(s.eval, cands, all_indices(cands.size()), s.draws, 0, n,
                                       scores, s.workers);
    const std::size_t best = best_of(scores, all_indices(cands.size()), 1).front();
    return plan_of(cands[best], scores[best], s.simulations);
}

// Pots, safeties and combinations on the 9 from each of `spots`; with ball in hand, combinations
// from spots of their own too (placement.hpp's combination_spots).
std::vector<Candidate> direct_candidates(Search& s, const std::vector<physics::Vec2>& spots,
                                         bool in_hand, double sigma_deg) {
    const Position& pos = s.pos;
    const Effort& effort = s.effort;
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
    if (in_hand && effort.combinations > 0)
        for (physics::Vec2 cue : combination_spots(pos, 2, sigma_deg, min_combination_chance)) {
            std::vector<Candidate> combos =
                combination_candidates(pos, cue, true, effort, sigma_deg, s.simulations);
            cands.insert(cands.end(), combos.begin(), combos.end());
        }
    return cands;
}

// Whether the candidates leave nothing simpler worth playing: no legal stroke worth
// `good_enough` without noise, or no pot that pots.
bool needs_kicks(const std::vector<Candidate>& cands, const std::vector<Score>& nominal) {
    double legal_best = -1.0;
    bool pot_works = false;
    for (std::size_t i = 0; i < cands.size(); ++i) {
        if (!nominal[i].foul) legal_best = std::max(legal_best, nominal[i].value);
        if (cands[i].kind == Kind::pot && nominal[i].success > 0.0) pot_works = true;
    }
    return legal_best < good_enough || !pot_works;
}

// Kicks and banks added to `cands` and played without noise: the sweep from the cue ball (one
// spot is enough with ball in hand), then the best of those that pot centred in their windows.
void add_kicks(Search& s, std::vector<Candidate>& cands, std::vector<Score>& nominal,
               const std::vector<physics::Vec2>& spots, bool in_hand) {
    const std::size_t from = cands.size();
    for (physics::Vec2 cue : spots) {
        std::vector<Candidate> kicks = kick_candidates(s.pos, cue, in_hand, s.effort);
        cands.insert(cands.end(), kicks.begin(), kicks.end());
        if (in_hand) break;
    }
    score_nominal_from(s, cands, nominal, from);
    if (s.effort.centred_kicks <= 0) return;
    const std::vector<Candidate> kicks(cands.begin() + static_cast<std::ptrdiff_t>(from),
                                       cands.end());
    const std::vector<Score> kick_scores(nominal.begin() + static_cast<std::ptrdiff_t>(from),
                                         nominal.end());
    // Raised against the squirt only under noise (without it a level cue is exact).
    const double raise = s.eval.scale() > 0.0 ? s.effort.max_raise_deg : 0.0;
    const std::vector<Candidate> centred =
        centred_kicks(s.eval, kicks, kick_scores, static_cast<std::size_t>(s.effort.centred_kicks),
                      raise, s.simulations, s.workers);
    const std::size_t at = cands.size();
    cands.insert(cands.end(), centred.begin(), centred.end());
    score_nominal_from(s, cands, nominal, at);
}

// A safety at the first spot, where no candidate came up (not with a legal ball on the table).
Candidate fallback_safety(const Position& pos, const std::vector<physics::Vec2>& spots,
                          bool in_hand) {
    Candidate c;
    c.kind = Kind::safety;
    c.cue_pos = in_hand ? std::optional<physics::Vec2>(spots.front()) : std::nullopt;
    c.call = safety_call(pos);
    c.stroke.speed = 1.5;
    return c;
}

// 9-ball: the best push-out, where one is allowed, with its score under noise; its search is
// half the shortlist's, not deeper.
std::pair<Candidate, Score> best_push_out(Search& s) {
    std::vector<Candidate> pushes = push_out_candidates(s.pos, s.pos.state.positions.at(0));
    std::vector<Score> push_nominal;
    score_nominal_from(s, pushes, push_nominal, 0);
    std::vector<Score> push_noisy;
    const std::size_t p =
        choose_under_noise(s, pushes, push_nominal, push_noisy,
                           static_cast<std::size_t>(s.effort.shortlist / 2 + 1), false);
    return {pushes[p], push_noisy[p]};
}

// A stroke from the table (not a break): the candidates from each cue spot, kicks when nothing
// simpler is worth playing, the search under noise, and a push-out when that is worth more.
Plan plan_stroke(Search& s, double sigma_deg) {
    const Position& pos = s.pos;
    const bool in_hand = cue_in_hand(pos.state);
    const std::vector<physics::Vec2> spots =
        in_hand ? cue_spots(pos, s.effort.placements, sigma_deg)
                : std::vector<physics::Vec2>{pos.state.positions.at(0)};
    std::vector<Candidate> cands = direct_candidates(s, spots, in_hand, sigma_deg);
    std::vector<Score> nominal;
    score_nominal_from(s, cands, nominal, 0);
    if (needs_kicks(cands, nominal)) add_kicks(s, cands, nominal, spots, in_hand);
    if (cands.empty()) {
        cands.push_back(fallback_safety(pos, spots, in_hand));
        nominal.push_back(Score{});
    }
    std::vector<Score> noisy;
    const std::size_t best = choose_under_noise(s, cands, nominal, noisy,
                                                static_cast<std::size_t>(s.effort.shortlist), true);
    std::pair<Candidate, Score> chosen{cands[best], noisy[best]};
    if (rules::push_out_allowed(pos.ruleset.game, pos.state) && !in_hand &&
        chosen.second.value < good_enough) {
        std::pair<Candidate, Score> push = best_push_out(s);
        if (push.second.value > chosen.second.value) chosen = push;
    }
    return plan_of(chosen.first, chosen.second, s.simulations);
}

}  // namespace

double planned_scale(const PlanSettings& settings) {
    return settings.noise * noise_multiplier(settings.level);
}

double model_sigma_deg(const physics::Params& params, const Effort& effort, double scale) {
    const double cue = heading_sigma_deg(params);
    return (effort.model_sigma_deg > 0.0 ? std::min(effort.model_sigma_deg, cue) : cue) * scale;
}

Plan plan(const Position& pos, const PlanSettings& settings, std::uint64_t seed) {
    const Effort effort = effort_at(pos, settings.level);
    const double scale = planned_scale(settings);
    const double sigma_deg = model_sigma_deg(pos.params, effort, scale);
    if (pos.choice) return plan_choice(pos, sigma_deg, effort.stuck_ball_cost);

    Search s{pos,
             effort,
             Evaluator(pos, scale, sigma_deg, effort.stuck_ball_cost),
             noise_draws(seed, draw_pool(effort)),
             {std::max(settings.workers, 1), settings.pause}};
    if (pos.state.shot == rules::Shot::break_shot) return plan_break(s);
    return plan_stroke(s, sigma_deg);
}

}  // namespace ai
