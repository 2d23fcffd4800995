// Whole snooker frames and three-cushion games between computer players (games_play.hpp).
#include "ai/games_play.hpp"

#include <chrono>

#include "game/stroke_noise.hpp"
#include "physics/markings.hpp"
#include "physics/rack.hpp"
#include "physics/simulate.hpp"

namespace ai {

namespace {

using clock_type = std::chrono::steady_clock;

double seconds_since(clock_type::time_point t) {
    return std::chrono::duration<double>(clock_type::now() - t).count();
}

struct SnookerTurn {
    SnookerStroke record;
    rules::SnookerState next;
};

// One stroke of the frame: the striker's plan, its execution and the verdict, then the incoming
// player's choice after a foul.
SnookerTurn snooker_turn(const SnookerFrameSetup& setup, const std::array<Seat, 2>& seats,
                         const physics::Table& table, const physics::Params& params,
                         const rules::SnookerState& s, std::uint64_t n, physics::SplitMix64& rng) {
    const std::size_t me = rules::index(s.shooter);
    const PlanSettings settings{seats[me].level, setup.noise, setup.workers};
    const SnookerPosition pos = snooker_position(table, params, setup.options, s);
    SnookerTurn t;
    const auto start = clock_type::now();
    t.record.plan = plan_snooker(pos, settings, decision_seed(seats[me].seed, n));
    t.record.seconds = seconds_since(start);
    t.record.before = with_plan(s, t.record.plan);
    t.record.executed = game::with_noise(t.record.plan.stroke, planned_scale(settings), rng);
    const physics::Shot shot = physics::simulate(
        table, params, physics::balls_at_rest(t.record.before.positions), &t.record.executed);
    t.record.verdict =
        rules::judge_snooker(setup.options, pos.snooker, t.record.before, shot.events());
    t.next = t.record.verdict.state;
    if (t.record.verdict.may_ask_to_play_again && !t.record.verdict.frame_over) {
        const std::size_t them = 1 - me;
        const PlanSettings theirs{seats[them].level, setup.noise, setup.workers};
        t.record.after_foul = choose_after_foul(pos, t.record.verdict, t.record.before, theirs);
        t.next = rules::resolve_after_foul(t.record.verdict, t.record.before, *t.record.after_foul);
    }
    if (!t.next.free_ball) t.next.nominated.reset();
    return t;
}

}  // namespace

rules::SnookerState snooker_start(const physics::Table& table, const physics::Params& params,
                                  int reds) {
    rules::SnookerState s;
    s.cue_ball = rules::CueBall::in_hand;
    for (const physics::BallState& b : physics::snooker_rack(table, params)) {
        if (b.id == 0 || (physics::is_red(b.id) && b.id > reds)) continue;
        s.positions[b.id] = b.pos;
        s.on_table.insert(b.id);
    }
    return s;
}

SnookerFrameReport play_snooker_frame(const SnookerFrameSetup& setup,
                                      const std::array<Seat, 2>& seats, std::uint64_t noise_seed,
                                      const std::function<void(const SnookerStroke&)>& observe) {
    const physics::Params params = *physics::params_preset("snooker");
    const physics::Table table = physics::build_table(physics::snooker_table_spec());
    rules::SnookerState s = snooker_start(table, params, setup.reds);
    physics::SplitMix64 rng(noise_seed);
    SnookerFrameReport report;
    std::array<std::uint64_t, 2> decisions{0, 0};
    for (;;) {
        if (report.strokes >= setup.max_strokes) {
            report.capped = true;
            break;
        }
        const std::size_t me = rules::index(s.shooter);
        SnookerTurn t = snooker_turn(setup, seats, table, params, s, decisions[me]++, rng);
        ++report.strokes;
        const rules::SnookerVerdict& v = t.record.verdict;
        report.fouls += v.foul;
        report.decision_seconds[me].push_back(t.record.seconds);
        const bool visit_over = v.frame_over || t.next.shooter != s.shooter;
        const int visit = s.break_points + (v.foul ? 0 : v.points_scored);
        if (visit_over && visit > 0) report.breaks[me].push_back(visit);
        if (observe) observe(t.record);
        if (v.frame_over) {
            report.winner = v.winner;
            s = v.state;
            break;
        }
        s = t.next;
    }
    report.scores = s.scores;
    return report;
}

CaromGameReport play_three_cushion_game(const CaromGameSetup& setup,
                                        const std::array<Seat, 2>& seats, std::uint64_t noise_seed,
                                        const std::function<void(const CaromStroke&)>& observe) {
    const physics::Params params = *physics::params_preset("carom");
    const physics::Table table = physics::build_table(physics::carom_table_spec());
    const physics::CaromSpots spots = physics::carom_spots(table);
    rules::CaromState s;
    for (const physics::BallState& b : physics::carom_rack(table)) s.positions[b.id] = b.pos;
    physics::SplitMix64 rng(noise_seed);
    CaromGameReport report;
    std::array<std::uint64_t, 2> decisions{0, 0};
    while (report.strokes < setup.max_strokes) {
        const std::size_t me = rules::index(s.shooter);
        const PlanSettings settings{seats[me].level, setup.noise, setup.workers};
        CaromStroke r;
        r.before = s;
        const auto start = clock_type::now();
        r.plan = plan_three_cushion({setup.options, table, params, s}, settings,
                                    decision_seed(seats[me].seed, decisions[me]++));
        r.seconds = seconds_since(start);
        r.executed = game::with_noise(r.plan.stroke, planned_scale(settings), rng);
        const physics::Shot shot =
            physics::simulate(table, params, physics::balls_at_rest(s.positions), &r.executed);
        r.verdict =
            rules::judge_three_cushion(setup.options, spots, params.ball_radius, s, shot.events());
        ++report.strokes;
        report.fouls += r.verdict.foul;
        report.decision_seconds[me].push_back(r.seconds);
        if (observe) observe(r);
        s = r.verdict.state;
        if (r.verdict.game_over) {
            report.over = true;
            report.winner = r.verdict.winner;
            break;
        }
    }
    report.scores = s.scores;
    report.innings = s.innings;
    report.high_run = s.high_run;
    return report;
}

}  // namespace ai
