#include "ai/internal/evaluate.hpp"

#include <algorithm>
#include <array>
#include <cmath>

#include "ai/internal/ghost_ball.hpp"
#include "ai/internal/lookahead.hpp"
#include "ai/internal/parallel.hpp"
#include "ai/internal/quasi_random.hpp"
#include "ai/internal/table_value.hpp"
#include "game/session.hpp"
#include "game/stroke_noise.hpp"
#include "physics/simulate.hpp"
#include "rules/eight_ball.hpp"

namespace ai {

namespace {

constexpr double truncated_value = 0.25;  // a shot the engine could not finish: avoid it

// The first ball the stroke pockets that scores for the shooter, as a call (kicks, banks,
// combinations): the call that would have made the noiseless stroke legal.
rules::Call call_from_events(const Position& pos, const std::vector<physics::Event>& events) {
    if (pos.ruleset.game != rules::Game::eight_ball) return rules::Call::nothing();
    const rules::GameState& s = pos.state;
    for (const physics::Event& e : events) {
        if (e.type != physics::EventType::pocket) continue;
        const int ball = e.balls[0].id;
        if (ball == 0) continue;
        const bool scores = legal_first(pos.ruleset, s, ball);
        if (scores) return pot_call(pos, ball, e.pocket);
    }
    return safety_call(pos);
}

}  // namespace

std::vector<NoiseDraw> noise_draws(std::uint64_t seed, int n) {
    // A Halton sequence shifted by a seeded uniform per component (quasi_random.hpp): heading
    // in base 2, whose every prefix covers its distribution most evenly, then speed, side, top
    // and elevation, the order of what they change.
    constexpr std::array<std::uint64_t, 5> bases{2, 3, 5, 7, 11};
    physics::SplitMix64 rng(seed);
    std::array<double, 5> shift{};
    for (double& x : shift) x = rng.uniform();
    std::vector<NoiseDraw> draws(static_cast<std::size_t>(std::max(n, 0)));
    for (std::size_t i = 0; i < draws.size(); ++i) {
        std::array<double, 5> z{};
        for (std::size_t k = 0; k < bases.size(); ++k) {
            double u = radical_inverse(i, bases[k]) + shift[k];
            z[k] = normal_quantile(u - std::floor(u));
        }
        draws[i] = {.heading = z[0], .elevation = z[4], .speed = z[1], .side = z[2], .top = z[3]};
    }
    return draws;
}

physics::Stroke with_draw(const physics::Stroke& stroke, const NoiseDraw& d, double scale) {
    if (scale == 0.0) return stroke;
    const game::StrokeNoise sigma;
    physics::Stroke s = stroke;
    s.heading_deg += scale * sigma.heading_deg * d.heading;
    s.elevation_deg += scale * sigma.elevation_deg * d.elevation;
    s.speed += scale * sigma.speed * d.speed;
    s.side += scale * sigma.offset * d.side;
    s.top += scale * sigma.offset * d.top;
    s.elevation_deg = std::clamp(s.elevation_deg, 0.0, 90.0);
    s.speed = std::clamp(s.speed, 0.0, game::max_stroke_speed);
    s.side = std::clamp(s.side, -1.0, 1.0);
    s.top = std::clamp(s.top, -1.0, 1.0);
    return s;
}

Trial Evaluator::play(const Candidate& c, const physics::Stroke& stroke, bool assign_call,
                      rules::Call* call, const Effort* deeper, bool with_leave,
                      std::optional<rules::GameState>* after) const {
    rules::GameState s = pos_.state;
    if (c.cue_pos) s.positions[0] = *c.cue_pos;
    const physics::Vec2 cue = s.positions.at(0);
    if (c.kind == Kind::push_out) s.shot = rules::Shot::push_out;
    const std::vector<physics::BallState> balls = layout(s, cue);
    const physics::Shot shot = physics::simulate(pos_.table, pos_.params, balls, &stroke);
    if (assign_call && call) *call = call_from_events(pos_, shot.events());
    s.call = call ? *call : c.call;
    Trial t;
    if (shot.truncated()) {
        t.value = t.shallow = truncated_value;
        return t;
    }
    const rules::Verdict v = rules::judge(pos_.ruleset, s, shot.events());
    const rules::Player me = s.shooter;
    t.foul = v.foul;
    const bool won = v.game_over && v.winner == me;
    const bool lost = v.game_over && v.winner != me;
    const bool stays =
        !v.game_over && ((v.choice && v.choice->by == me) || (!v.choice && v.next_shooter == me));
    t.shallow = verdict_value(pos_, s, v, sigma_deg_, stuck_cost_);
    t.value = t.shallow;
    if (with_leave && stays && !v.choice && v.state.positions.count(0) != 0) {
        if (std::optional<BestAim> b = best_aim(pos_, v.state, v.state.positions.at(0), sigma_deg_))
            t.leave = b->aim.ball;
    }
    if (after && stays && !v.choice) *after = v.state;
    if (deeper && stays && !v.choice) {
        t.value = staying_value(
            s, v.state, next_turn_value(pos_, v.state, *deeper, scale_, sigma_deg_, t.simulations));
    }
    const bool pot_like = c.kind == Kind::pot || c.kind == Kind::break_shot ||
                          (c.kind == Kind::kick && s.call.is_ball());
    t.stays = won || stays;
    t.success = pot_like ? t.stays : (!v.foul && !lost);
    return t;
}

Trial Evaluator::nominal(Candidate& c, bool with_leave) const {
    if (c.kind == Kind::kick) return play(c, c.stroke, true, &c.call, nullptr, with_leave);
    return play(c, c.stroke, false, nullptr, nullptr, with_leave);
}

Trial Evaluator::nominal_to(const Candidate& c, std::optional<rules::GameState>& after) const {
    after.reset();
    return play(c, c.stroke, false, nullptr, nullptr, false, &after);
}

Trial Evaluator::trial(const Candidate& c, const NoiseDraw& draw) const {
    return play(c, with_draw(c.stroke, draw, scale_), false, nullptr);
}

Trial Evaluator::deep_trial(const Candidate& c, const NoiseDraw& draw, const Effort& effort) const {
    return play(c, with_draw(c.stroke, draw, scale_), false, nullptr, &effort);
}

std::int64_t score_under_noise(const Evaluator& eval, const std::vector<Candidate>& candidates,
                               const std::vector<std::size_t>& which,
                               const std::vector<NoiseDraw>& draws, std::size_t first,
                               std::size_t count, std::vector<Score>& scores, Workers workers) {
    parallel_for(which.size(), workers, [&](std::size_t k) {
        const std::size_t i = which[k];
        Score& s = scores[i];
        double value = s.value * s.samples, success = s.success * s.samples;
        for (std::size_t d = first; d < first + count && d < draws.size(); ++d) {
            const Trial t = eval.trial(candidates[i], draws[d]);
            value += t.value;
            success += t.success ? 1.0 : 0.0;
            ++s.samples;
        }
        if (s.samples > 0) {
            s.value = value / s.samples;
            s.success = success / s.samples;
        }
    });
    std::int64_t sims = 0;
    for (std::size_t k = 0; k < which.size(); ++k)
        sims += static_cast<std::int64_t>(
            std::min(count, draws.size() - std::min(first, draws.size())));
    return sims;
}

std::int64_t score_deep(const Evaluator& eval, const std::vector<Candidate>& candidates,
                        const std::vector<std::size_t>& which, const std::vector<NoiseDraw>& draws,
                        std::size_t first, std::size_t count, const Effort& effort,
                        std::vector<Score>& scores, Workers workers) {
    // Without noise (no draws) one exact play; else the draws [first, first + count) there are.
    const std::size_t begin = draws.empty() ? 0 : std::min(first, draws.size());
    const std::size_t n = draws.empty() ? 1 : std::min(count, draws.size() - begin);
    if (n == 0) return 0;
    std::vector<Trial> trials(which.size() * n);
    const NoiseDraw none;
    parallel_for(trials.size(), workers, [&](std::size_t k) {
        const Candidate& c = candidates[which[k / n]];
        trials[k] = eval.deep_trial(c, draws.empty() ? none : draws[begin + k % n], effort);
    });
    std::int64_t sims = 0;
    for (std::size_t w = 0; w < which.size(); ++w) {  // reduce in index order: same bits always
        Score& s = scores[which[w]];
        double shallow = s.value - (s.deep_draws > 0 ? s.deep_sum / s.deep_draws : 0.0);
        double success = s.success;
        for (std::size_t d = 0; d < n; ++d) {
            const Trial& t = trials[w * n + d];
            s.deep_sum += t.value - t.shallow;
            ++s.deep_draws;
            if (!draws.empty() && begin + d >= static_cast<std::size_t>(s.samples)) {
                shallow = (shallow * s.samples + t.shallow) / (s.samples + 1);
                success = (success * s.samples + (t.success ? 1.0 : 0.0)) / (s.samples + 1);
                ++s.samples;
            }
            sims += t.simulations;
        }
        s.value = shallow + s.deep_sum / s.deep_draws;
        s.success = success;
    }
    return sims;
}

}  // namespace ai
