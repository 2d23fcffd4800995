#include "game/autoplay.hpp"

#include <chrono>

#include "game/stroke_noise.hpp"

namespace game {

bool is_break_and_run(const Session& s) {
    const std::vector<ShotRecord>& h = s.history();
    if (!s.winner() || h.empty()) return false;
    const int rack = h.back().rack;
    bool first = true;
    for (const ShotRecord& r : h) {
        if (r.rack != rack) continue;
        if (first && r.before.shot != rules::Shot::break_shot) return false;
        first = false;
        if (r.shooter() != *s.winner()) return false;
    }
    return true;
}

GameReport play_game(Session& s, const std::array<Player*, 2>& seats, const PlayLimits& limits,
                     double noise, std::uint64_t noise_seed, const ShotObserver& on_shot,
                     const TurnObserver& before_decision) {
    using clock = std::chrono::steady_clock;
    GameReport report;
    physics::SplitMix64 noise_rng(noise_seed);
    int dry_shots = 0;  // shots in a row with no object ball leaving the table

    while (s.phase() != Phase::game_over) {
        if (report.shots >= limits.max_shots) {
            report.capped = true;
            break;
        }
        if (before_decision) before_decision(s);
        const rules::Player p = *s.to_act();
        const auto start = clock::now();
        const Decision d = seats[rules::index(p)]->decide(s);
        report.decision_seconds[rules::index(p)].push_back(
            std::chrono::duration<double>(clock::now() - start).count());

        if (s.phase() == Phase::choose) {
            const int rack = s.rack_number();
            s.choose(d.choice.value_or(s.choice()->options.front()));
            if (on_shot && !s.history().empty()) on_shot(s, s.history().back());
            if (s.rack_number() != rack) dry_shots = 0;
            continue;
        }
        if (d.cue_pos) s.place_cue_ball(*d.cue_pos);
        s.set_call(d.call);
        if (d.push_out) s.set_push_out(true);
        const std::size_t on_table = s.state().on_table.size();
        const double scale = noise * seats[rules::index(p)]->execution_noise();
        const ShotRecord& r = s.play(with_noise(d.stroke, scale, noise_rng));
        ++report.shots;
        if (r.verdict.foul) ++report.fouls;
        if (on_shot && s.phase() != Phase::choose) on_shot(s, r);

        dry_shots = r.verdict.state.on_table.size() < on_table ? 0 : dry_shots + 1;
        const bool at_table = s.phase() == Phase::shoot || s.phase() == Phase::place_cue_ball;
        if (at_table && dry_shots >= limits.stalemate_after) {
            s.declare_stalemate();
            ++report.stalemates;
            dry_shots = 0;
        }
    }
    if (on_shot && report.capped && s.phase() == Phase::choose) on_shot(s, s.history().back());
    report.winner = s.winner();
    report.break_and_run = is_break_and_run(s);
    return report;
}

}  // namespace game
