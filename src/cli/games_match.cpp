// `match` for snooker frames and three-cushion games between two computer players (docs/cli.md,
// "match: snooker and three-cushion"): the frames and games are ai::play_snooker_frame's and
// ai::play_three_cushion_game's (ai/games_play.hpp); this file seats the players, logs the
// strokes and adds up the results.
#include <fmt/format.h>

#include <chrono>
#include <fstream>
#include <map>
#include <numeric>

#include "ai/games_play.hpp"
#include "cli/commands.hpp"
#include "cli/games_json.hpp"
#include "cli/json_in.hpp"
#include "cli/json_out.hpp"
#include "cli/match_support.hpp"
#include "game/state_json.hpp"
#include "rules/names.hpp"

namespace cli {

namespace {

using nlohmann::ordered_json;

// One player's figures over the match.
struct Figures {
    std::int64_t wins = 0, points = 0, innings = 0;
    int high_run = 0;
    std::vector<int> breaks;
    std::vector<double> seconds;
};

struct Seating {
    std::array<ai::Seat, 2> seats;
    std::array<std::string, 2> keys;  ///< whose figures each seat adds to
    std::uint64_t noise_seed;
};

// Game `k`: the seed (each seed twice with --duplicate, the sides swapped) and the seats.
Seating seating(const MatchOptions& o, std::uint64_t seed, const std::array<int, 2>& levels,
                std::int64_t k) {
    const std::int64_t seed_index = o.duplicate ? k / 2 : k;
    const bool swapped = o.duplicate && k % 2 == 1;
    const std::uint64_t game_seed = derive(seed, static_cast<std::uint64_t>(seed_index));
    const std::array<int, 2> who = swapped ? std::array{1, 0} : std::array{0, 1};
    const bool by_seat = levels[0] == levels[1];
    Seating s;
    for (int seat = 0; seat < 2; ++seat) {
        s.seats[seat] = {levels[who[seat]], derive(game_seed, 1 + who[seat])};
        s.keys[seat] = by_seat ? (seat == 0 ? "A" : "B") : fmt::format("ai:{}", levels[who[seat]]);
    }
    s.noise_seed = derive(game_seed, 100);
    return s;
}

ordered_json log_line(std::int64_t k, int n, const std::string& player, const ordered_json& before,
                      const physics::Stroke& executed, ordered_json verdict) {
    ordered_json j;
    j["game"] = k;
    j["stroke_number"] = n;
    j["player"] = player;
    j["state"] = before;
    j["stroke"] = game::to_json(executed);
    j["stroke"]["ball"] = executed.ball;
    j["verdict"] = std::move(verdict);
    return j;
}

void add_snooker(const MatchOptions& o, const Seating& s, std::int64_t k, std::ofstream& log,
                 std::map<std::string, Figures>& f, std::int64_t& strokes, std::int64_t& fouls,
                 std::int64_t& capped) {
    ai::SnookerFrameSetup setup;
    setup.noise = o.noise;
    setup.reds = static_cast<int>(o.reds.value_or(15));
    int n = 0;
    const ai::SnookerFrameReport r =
        ai::play_snooker_frame(setup, s.seats, s.noise_seed, [&](const ai::SnookerStroke& x) {
            if (!log.is_open()) return;
            ordered_json line =
                log_line(k, ++n, s.keys[rules::index(x.before.shooter)],
                         snooker_state_json(x.before), x.executed, snooker_verdict_json(x.verdict));
            line["plan"] = {
                {"kind", x.plan.kind == ai::Kind::pot      ? "pot"
                         : x.plan.kind == ai::Kind::safety ? "safety"
                                                           : "kick"},
                {"nominated", x.plan.nominated ? ordered_json(*x.plan.nominated) : ordered_json()},
                {"expected_success", x.plan.expected_success},
                {"expected_value", x.plan.expected_value}};
            line["after_foul"] =
                x.after_foul
                    ? ordered_json(x.after_foul == rules::AfterFoul::play         ? "play"
                                   : x.after_foul == rules::AfterFoul::play_again ? "play_again"
                                                                                  : "replace")
                    : ordered_json(nullptr);
            log << write_document(line, false);
        });
    strokes += r.strokes;
    fouls += r.fouls;
    capped += r.capped;
    for (int seat = 0; seat < 2; ++seat) {
        Figures& g = f[s.keys[seat]];
        g.points += r.scores[seat];
        g.breaks.insert(g.breaks.end(), r.breaks[seat].begin(), r.breaks[seat].end());
        g.seconds.insert(g.seconds.end(), r.decision_seconds[seat].begin(),
                         r.decision_seconds[seat].end());
    }
    if (r.winner) ++f[s.keys[rules::index(*r.winner)]].wins;
}

void add_carom(const MatchOptions& o, const Seating& s, std::int64_t k, std::ofstream& log,
               std::map<std::string, Figures>& f, std::int64_t& strokes, std::int64_t& fouls,
               std::int64_t& capped) {
    ai::CaromGameSetup setup;
    setup.noise = o.noise;
    if (o.target) setup.options.target = static_cast<int>(*o.target);
    int n = 0;
    const ai::CaromGameReport r =
        ai::play_three_cushion_game(setup, s.seats, s.noise_seed, [&](const ai::CaromStroke& x) {
            if (!log.is_open()) return;
            ordered_json line =
                log_line(k, ++n, s.keys[rules::index(x.before.shooter)], carom_state_json(x.before),
                         x.executed, carom_verdict_json(x.verdict));
            line["plan"] = {{"expected_success", x.plan.expected_success},
                            {"expected_value", x.plan.expected_value}};
            log << write_document(line, false);
        });
    strokes += r.strokes;
    fouls += r.fouls;
    capped += !r.over;
    for (int seat = 0; seat < 2; ++seat) {
        Figures& g = f[s.keys[seat]];
        g.points += r.scores[seat];
        g.innings += r.innings[seat];
        g.high_run = std::max(g.high_run, r.high_run[seat]);
        g.seconds.insert(g.seconds.end(), r.decision_seconds[seat].begin(),
                         r.decision_seconds[seat].end());
    }
    if (r.winner) ++f[s.keys[rules::index(*r.winner)]].wins;
}

ordered_json figures_json(bool snooker, Figures& g) {
    ordered_json j;
    j["wins"] = g.wins;
    j["points"] = g.points;
    if (snooker) {
        const double sum = std::accumulate(g.breaks.begin(), g.breaks.end(), 0.0);
        j["breaks"] = g.breaks.size();
        j["mean_break"] = g.breaks.empty() ? 0.0 : sum / static_cast<double>(g.breaks.size());
        j["highest_break"] =
            g.breaks.empty() ? 0 : *std::max_element(g.breaks.begin(), g.breaks.end());
    } else {
        j["innings"] = g.innings;
        j["average"] =
            g.innings ? static_cast<double>(g.points) / static_cast<double>(g.innings) : 0.0;
        j["high_run"] = g.high_run;
    }
    std::sort(g.seconds.begin(), g.seconds.end());
    j["decision_seconds"] = g.seconds.empty() ? ordered_json{{"median", nullptr}, {"p95", nullptr}}
                                              : ordered_json{{"median", quantile(g.seconds, 0.5)},
                                                             {"p95", quantile(g.seconds, 0.95)}};
    return j;
}

}  // namespace

ordered_json games_match(const MatchOptions& o, std::uint64_t seed,
                         const std::array<int, 2>& levels) {
    using clock = std::chrono::steady_clock;
    const auto start = clock::now();
    const bool snooker = o.game == "snooker";
    if (snooker && o.target) throw BadInput("--target", "--target is for --game three_cushion");
    if (!snooker && o.reds) throw BadInput("--reds", "--reds is for --game snooker");
    if (o.reds && (*o.reds < 1 || *o.reds > 15))
        throw BadInput("--reds", fmt::format("{} is out of range: must be from 1 to 15", *o.reds));
    if (o.target && (*o.target < 1 || *o.target > 1000))
        throw BadInput("--target",
                       fmt::format("{} is out of range: must be from 1 to 1000", *o.target));
    std::ofstream log;
    if (!o.log.empty()) {
        log.open(o.log, std::ios::binary | std::ios::trunc);
        if (!log)
            throw BadInput("--log", fmt::format("cannot write \"{}\": check the path and its "
                                                "permissions",
                                                o.log));
    }
    std::map<std::string, Figures> figures;
    std::int64_t strokes = 0, fouls = 0, capped = 0;
    for (std::int64_t k = 0; k < o.games; ++k) {
        const Seating s = seating(o, seed, levels, k);
        for (const std::string& key : s.keys) figures[key];
        if (snooker)
            add_snooker(o, s, k, log, figures, strokes, fouls, capped);
        else
            add_carom(o, s, k, log, figures, strokes, fouls, capped);
    }
    if (log.is_open()) {
        log.flush();
        if (!log) throw BadInput("--log", fmt::format("cannot write \"{}\"", o.log));
    }
    ordered_json out;
    out["game"] = o.game;
    out["games"] = o.games;
    out["players"] = {fmt::format("ai:{}", levels[0]), fmt::format("ai:{}", levels[1])};
    if (snooker) out["reds"] = o.reds.value_or(15);
    if (!snooker) out["target"] = o.target.value_or(rules::CaromOptions{}.target);
    ordered_json by = ordered_json::object();
    for (auto& [key, g] : figures) by[key] = figures_json(snooker, g);
    out["results"] = std::move(by);
    out["strokes"] = strokes;
    out["fouls"] = fouls;
    out["capped"] = capped;
    out["seconds"] = std::chrono::duration<double>(clock::now() - start).count();
    return out;
}

}  // namespace cli
