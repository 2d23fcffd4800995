// The AI's strength benchmark (docs/ai.md): not a test, a measurement.
//   ai_strength shots   [--n N] [--level L] [--noise X] [--seed S]   cue ball + one object ball
//   ai_strength runouts [--n N] [--level L] [--noise X] [--seed S] [--game 8ball|9ball]
//                       [--paired 1] [--from F] [--cue-endmass KG]
//     --paired 1: each rack its own noise and decision streams, and "rack I 0|1" on stderr, so
//     that two arms of a tuning run play the same racks (until their decisions differ) and
//     can be compared rack by rack; --from F starts at rack F (to split a run over cores).
//     --cue-endmass KG: the cue's effective end mass (physics::Params, default 0.015): the
//     squirt that the tip-offset noise causes; 1e-9 plays as a simulator without squirt
//     (the Computer Olympiad's). The racks do not depend on it.
// Prints one JSON object: counts, rates with 95 % Wilson intervals, time per decision (median,
// p95) and simulations per decision. Ladder games go through `coolaaber-cli match --duplicate`.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include "ai/internal/ghost_ball.hpp"
#include "ai/internal/planner.hpp"
#include "ai/internal/position.hpp"
#include "ai/internal/table_value.hpp"
#include "game/stroke_noise.hpp"
#include "physics/rack.hpp"
#include "physics/simulate.hpp"
#include "rules/judge.hpp"
#include "two_ball_layout.hpp"

namespace {

struct Args {
    std::string mode = "shots";
    int n = 100;
    int level = 5;
    double noise = 1.0;
    std::uint64_t seed = 1;
    std::string game = "8ball";
    bool paired = false;  // runouts: each rack its own noise and decision streams
    int from = 0;         // runouts: the first rack's index
    double cue_endmass = physics::Params{}.cue_endmass;  // (unit: kg)
};

struct Interval {
    double rate, lo, hi;
};

// Wilson score interval at 95 %.
Interval wilson(int k, int n) {
    if (n == 0) return {0, 0, 0};
    const double z = 1.96, p = static_cast<double>(k) / n, nn = n;
    const double centre = (p + z * z / (2 * nn)) / (1 + z * z / nn);
    const double half = z * std::sqrt(p * (1 - p) / nn + z * z / (4 * nn * nn)) / (1 + z * z / nn);
    return {p, centre - half, centre + half};
}

double quantile(std::vector<double> v, double q) {
    if (v.empty()) return 0.0;
    std::sort(v.begin(), v.end());
    const auto rank = static_cast<std::size_t>(std::ceil(q * static_cast<double>(v.size())));
    return v[std::clamp<std::size_t>(rank, 1, v.size()) - 1];
}

struct Timing {
    std::vector<double> seconds;
    std::vector<double> sims;
    void add(double s, std::int64_t n) {
        seconds.push_back(s);
        sims.push_back(static_cast<double>(n));
    }
    void print() const {
        std::printf(
            "\"decisions\": %zu, \"seconds_median\": %.4f, \"seconds_p95\": %.4f, "
            "\"simulations_median\": %.0f, \"simulations_p95\": %.0f",
            seconds.size(), quantile(seconds, 0.5), quantile(seconds, 0.95), quantile(sims, 0.5),
            quantile(sims, 0.95));
    }
};

ai::Position base_position(rules::Game game, double cue_endmass) {
    ai::Position p;
    p.ruleset.game = game;
    p.params.cue_endmass = cue_endmass;
    p.table = physics::build_table(physics::TableSpec{});
    p.state = rules::initial_state(game, rules::Player::A);
    return p;
}

// AI_VERBOSE=1: one line per shot on stderr (for failure analysis): the best pot's chance from
// the cue ball and from anywhere (ball in hand), what was played, the verdict; with
// AI_VERBOSE_LAYOUT=1 also every ball's position and player A's group.
void print_shot(const ai::Position& pos, const ai::Plan& plan, const rules::GameState& s,
                const physics::Stroke& stroke, const rules::Verdict& v) {
    const double sigma = ai::heading_sigma_deg(pos.params);
    rules::GameState anywhere = pos.state;  // the same table with the cue ball in hand
    anywhere.cue_ball = rules::CueBall::in_hand;
    anywhere.positions.erase(0);
    std::fprintf(stderr, "in_hand_q %.2f ", ai::best_shot_chance(pos, anywhere, sigma));
    if (std::getenv("AI_VERBOSE_LAYOUT")) {
        std::fprintf(stderr, "anywhere");
        for (int ball : pos.state.on_table)
            std::fprintf(stderr, " %d:%.3f", ball,
                         ai::ball_chance_anywhere(pos, anywhere, ball, sigma));
        std::fprintf(stderr, " layout");
        for (const auto& [id, p] : pos.state.positions)
            std::fprintf(stderr, " %d:%.4f,%.4f", id, p.x, p.y);
        std::fprintf(stderr, " group_a %d ",
                     pos.state.group_a ? static_cast<int>(*pos.state.group_a) : -1);
    }
    std::fprintf(stderr,
                 "q %.2f kind %d balls %zu call %d/%d speed %.2f side %.2f top %.2f exp %.2f "
                 "value %.3f sims %lld -> foul %d next %d over %d\n",
                 ai::best_shot_chance(pos, pos.state, sigma), static_cast<int>(plan.kind),
                 pos.state.on_table.size(), s.call.ball, s.call.pocket, stroke.speed, stroke.side,
                 stroke.top, plan.expected_success, plan.expected_value,
                 static_cast<long long>(plan.simulations), v.foul ? 1 : 0,
                 v.next_shooter ? static_cast<int>(*v.next_shooter) : -1, v.game_over ? 1 : 0);
}

// One shot: plan, execute with the game's noise, simulate, judge.
struct Played {
    rules::Verdict verdict;
};

Played play(const ai::Position& pos, const ai::PlanSettings& settings, std::uint64_t seed,
            physics::SplitMix64& noise_rng, Timing& timing) {
    const auto t0 = std::chrono::steady_clock::now();
    const ai::Plan plan = ai::plan(pos, settings, seed);
    timing.add(std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count(),
               plan.simulations);
    rules::GameState s = pos.state;
    if (plan.decision.cue_pos) s.positions[0] = *plan.decision.cue_pos;
    s.call = plan.decision.call;
    if (plan.decision.push_out) s.shot = rules::Shot::push_out;
    const physics::Stroke stroke =
        game::with_noise(plan.decision.stroke, ai::planned_scale(settings), noise_rng);
    const physics::Shot shot =
        physics::simulate(pos.table, pos.params, ai::layout(s, s.positions.at(0)), &stroke);
    rules::Verdict v = rules::judge(pos.ruleset, s, shot.events());
    if (std::getenv("AI_VERBOSE")) print_shot(pos, plan, s, stroke, v);
    return {v};
}

// Cue ball and the 9 alone (9-ball: potting it wins), at random; binned by the model's chance
// of the best direct pot at 1× noise.
void shots(const Args& a) {
    physics::SplitMix64 rng(a.seed);
    physics::SplitMix64 noise_rng(a.seed ^ 0xabcdefULL);
    const ai::PlanSettings settings{a.level, a.noise, 2};
    std::vector<int> made(5, 0), tried(5, 0);
    Timing timing;
    for (int i = 0; i < a.n; ++i) {
        ai::Position pos = base_position(rules::Game::nine_ball, a.cue_endmass);
        pos.state.shot = rules::Shot::normal;
        pos.state.cue_ball = rules::CueBall::on_table;
        pos.state.on_table = {9};
        pos.state.positions = bench::two_ball_layout(pos.table, pos.params.ball_radius, rng);
        const double q = ai::best_shot_chance(pos, pos.state, ai::heading_sigma_deg(pos.params));
        const int bin = std::clamp(static_cast<int>((1.0 - q) * 5.0), 0, 4);  // 0: easiest
        const Played p =
            play(pos, settings, a.seed * 7919 + static_cast<std::uint64_t>(i), noise_rng, timing);
        ++tried[static_cast<std::size_t>(bin)];
        if (p.verdict.game_over && p.verdict.winner == rules::Player::A)
            ++made[static_cast<std::size_t>(bin)];
    }
    std::printf("{\"mode\": \"shots\", \"level\": %d, \"noise\": %g, \"layouts\": %d, \"bins\": [",
                a.level, a.noise, a.n);
    int all = 0;
    for (int b = 0; b < 5; ++b) {
        const Interval w =
            wilson(made[static_cast<std::size_t>(b)], tried[static_cast<std::size_t>(b)]);
        all += made[static_cast<std::size_t>(b)];
        std::printf(
            "%s{\"model_chance\": \"%.1f-%.1f\", \"layouts\": %d, \"potted\": %d, "
            "\"rate\": %.3f, \"ci95\": [%.3f, %.3f]}",
            b ? ", " : "", 1.0 - 0.2 * (b + 1), 1.0 - 0.2 * b, tried[static_cast<std::size_t>(b)],
            made[static_cast<std::size_t>(b)], w.rate, w.lo, w.hi);
    }
    const Interval w = wilson(all, a.n);
    std::printf("], \"potted\": %d, \"rate\": %.3f, \"ci95\": [%.3f, %.3f], ", all, w.rate, w.lo,
                w.hi);
    timing.print();
    std::printf("}\n");
}

// A rack, broken by the AI; then ball in hand anywhere with whatever is left (the table open in
// 8-ball) and the AI shoots until it misses, fouls or wins. A break that pockets the 8 (9) is
// racked again.
void runouts(const Args& a) {
    const rules::Game game = a.game == "9ball" ? rules::Game::nine_ball : rules::Game::eight_ball;
    physics::SplitMix64 noise_rng(a.seed ^ 0x5eedULL);
    const ai::PlanSettings settings{a.level, a.noise, 2};
    int cleared = 0, racks = 0;
    Timing timing, break_timing;
    std::uint64_t decision = 0;
    for (int i = a.from; racks < a.n; ++i) {
        if (a.paired) {  // this rack's own streams: arms of a tuning run play the same racks
            noise_rng = physics::SplitMix64(a.seed * 7919ULL + static_cast<std::uint64_t>(i));
            decision = static_cast<std::uint64_t>(i) * 1000ULL;
        }
        ai::Position pos = base_position(game, a.cue_endmass);
        const std::vector<physics::BallState> balls = physics::rack(
            game == rules::Game::eight_ball ? physics::RackType::eight_ball
                                            : physics::RackType::nine_ball,
            pos.table, pos.params, a.seed * 1000003ULL + static_cast<std::uint64_t>(i));
        for (const physics::BallState& b : balls)
            if (b.id != 0) pos.state.positions[b.id] = b.pos;
        const Played broken =
            play(pos, settings, ++decision * 31 + a.seed, noise_rng, break_timing);
        rules::GameState s = broken.verdict.state;
        const int key = game == rules::Game::eight_ball ? 8 : 9;
        if (broken.verdict.game_over || !s.has(key)) continue;
        ++racks;
        s.shooter = rules::Player::A;
        s.shot = rules::Shot::normal;
        s.group_a.reset();
        s.cue_ball = rules::CueBall::in_hand;
        s.positions.erase(0);
        s.call = rules::Call::nothing();
        s.fouls_in_row = {0, 0};
        s.warned = {false, false};
        bool won = false;
        for (int shot = 0; shot < 30; ++shot) {
            pos.state = s;
            const Played p = play(pos, settings, ++decision * 31 + a.seed, noise_rng, timing);
            if (p.verdict.game_over) {
                if (p.verdict.winner == rules::Player::A) won = true;
                break;
            }
            if (p.verdict.choice || p.verdict.next_shooter != rules::Player::A) break;
            s = p.verdict.state;
        }
        cleared += won ? 1 : 0;
        if (a.paired) std::fprintf(stderr, "rack %d %d\n", i, won ? 1 : 0);
    }
    const Interval w = wilson(cleared, racks);
    std::printf(
        "{\"mode\": \"runouts\", \"game\": \"%s\", \"level\": %d, \"noise\": %g, "
        "\"racks\": %d, \"cleared\": %d, \"rate\": %.3f, \"ci95\": [%.3f, %.3f], ",
        a.game.c_str(), a.level, a.noise, racks, cleared, w.rate, w.lo, w.hi);
    timing.print();
    std::printf(", \"break_seconds_median\": %.4f}\n", quantile(break_timing.seconds, 0.5));
}

}  // namespace

int main(int argc, char** argv) {
    Args a;
    if (argc > 1) a.mode = argv[1];
    for (int i = 2; i + 1 < argc; i += 2) {
        const std::string k = argv[i], v = argv[i + 1];
        if (k == "--n")
            a.n = std::atoi(v.c_str());
        else if (k == "--level")
            a.level = std::atoi(v.c_str());
        else if (k == "--noise")
            a.noise = std::atof(v.c_str());
        else if (k == "--seed")
            a.seed = std::strtoull(v.c_str(), nullptr, 10);
        else if (k == "--game")
            a.game = v;
        else if (k == "--paired")
            a.paired = v == "1";
        else if (k == "--from")
            a.from = std::atoi(v.c_str());
        else if (k == "--cue-endmass")
            a.cue_endmass = std::atof(v.c_str());
        else {
            std::fprintf(stderr, "unknown option %s\n", k.c_str());
            return 2;
        }
    }
    if (!(a.cue_endmass > 0.0 && a.cue_endmass <= 100.0)) {
        std::fprintf(stderr,
                     "--cue-endmass: must be a mass in kg above 0 and at most 100 "
                     "(e.g. 0.015, or 1e-9 for no squirt)\n");
        return 2;
    }
    if (a.mode == "shots")
        shots(a);
    else if (a.mode == "runouts")
        runouts(a);
    else {
        std::fprintf(stderr,
                     "usage: ai_strength shots|runouts [--n N] [--level L] [--noise X] "
                     "[--seed S] [--game 8ball|9ball] [--paired 1] [--from F] "
                     "[--cue-endmass KG]\n");
        return 2;
    }
    return 0;
}
