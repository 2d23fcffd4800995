// `match` (docs/cli.md): plays whole games headlessly between two players and reports the
// results; with --log, one JSON line per shot. The games are played by game::play_game.
#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <fstream>
#include <memory>
#include <string>
#include <vector>

#include "ai/ai.hpp"
#include "cli/commands.hpp"
#include "cli/json_in.hpp"
#include "cli/json_out.hpp"
#include "cli/match_support.hpp"
#include "cli/rules_json.hpp"
#include "cli/shot_output.hpp"
#include "game/autoplay.hpp"
#include "game/random_player.hpp"
#include "game/session.hpp"
#include "game/state_json.hpp"
#include "physics/rack.hpp"
#include "rules/names.hpp"

namespace cli {

namespace {

constexpr std::int64_t max_games = 1'000'000;
constexpr double max_noise = 100.0;

// "random" or "ai:LEVEL" (LEVEL 1–5).
std::string read_player(const std::string& kind) {
    if (kind == "random") return kind;
    if (kind.rfind("ai:", 0) == 0) {
        const std::string level = kind.substr(3);
        if (level.size() == 1 && level[0] >= '1' && level[0] <= '5') return kind;
        throw BadInput("--players", fmt::format("\"{}\": the AI levels are ai:1 to ai:5", kind));
    }
    throw BadInput(
        "--players",
        fmt::format("unknown player \"{}\" (expected \"random\" or \"ai:1\" to \"ai:5\")", kind));
}

std::array<std::string, 2> read_players(const std::string& text) {
    const std::size_t comma = text.find(',');
    if (comma == std::string::npos || text.find(',', comma + 1) != std::string::npos)
        throw BadInput("--players",
                       fmt::format("\"{}\": expected two players separated by a comma, e.g. "
                                   "random,random",
                                   text));
    return {read_player(text.substr(0, comma)), read_player(text.substr(comma + 1))};
}

// A whole number from 0 to 2^64 − 1, in decimal.
std::uint64_t read_seed(const std::string& text) {
    const bool digits =
        !text.empty() && text.size() <= 20 &&
        std::all_of(text.begin(), text.end(), [](char c) { return c >= '0' && c <= '9'; });
    std::uint64_t seed = 0;
    bool fits = digits;
    for (char c : text) {
        if (!fits) break;
        const auto d = static_cast<std::uint64_t>(c - '0');
        fits = seed <= (UINT64_MAX - d) / 10;
        seed = seed * 10 + d;
    }
    if (!fits)
        throw BadInput("--seed", fmt::format("\"{}\": expected a whole number from 0 to {}", text,
                                             UINT64_MAX));
    return seed;
}

// An AI plans for the match's noise scale; play_game strokes with that scale × its level's
// multiplier (game::Player::execution_noise).
std::unique_ptr<game::Player> make_player(const std::string& kind, std::uint64_t seed,
                                          double noise) {
    if (kind.rfind("ai:", 0) == 0)
        return std::make_unique<ai::AiPlayer>(kind[3] - '0', seed, noise);
    return std::make_unique<game::RandomPlayer>(seed);
}

nlohmann::ordered_json log_line(std::int64_t game_index, int shot, const std::string& player,
                                const game::ShotRecord& r) {
    nlohmann::ordered_json j;
    j["game"] = game_index;
    j["shot"] = shot;
    j["seat"] = rules::name(r.shooter());
    j["player"] = player;
    j["state"] = to_json(r.before);
    j["stroke"] = game::to_json(r.stroke);
    j["call"] = game::to_json(r.before.call);
    j["push_out"] = r.push_out();
    j["events"] = events_to_json(r.events);
    j["verdict"] = to_json(r.verdict);
    j["choice"] =
        r.choice ? nlohmann::ordered_json(rules::name(*r.choice)) : nlohmann::ordered_json(nullptr);
    return j;
}

// The options, read and checked.
struct Match {
    rules::Game game;
    std::array<std::string, 2> kinds;  ///< the players of --players
    std::uint64_t seed;
    bool by_seat;  ///< the same kind on both sides: results by seat (A, B), else by kind
};

// The checks every game's match shares.
void check_counts(const MatchOptions& options) {
    if (options.games < 1 || options.games > max_games)
        throw BadInput("--games", fmt::format("{} is out of range: must be from 1 to {}",
                                              options.games, max_games));
    if (options.duplicate && options.games % 2 != 0)
        throw BadInput("--games",
                       fmt::format("{} games with --duplicate: give an even number (each seed is "
                                   "played twice, the sides swapped)",
                                   options.games));
    if (!std::isfinite(options.noise) || options.noise < 0.0 || options.noise > max_noise)
        throw BadInput("--noise", fmt::format("{} is out of range: must be from 0 to {}",
                                              options.noise, max_noise));
}

Match read_match(const MatchOptions& options) {
    std::optional<rules::Game> game = rules::parse<rules::Game>(options.game);
    if (!game)
        throw BadInput("--game", fmt::format("unknown game \"{}\" (expected \"8ball\", "
                                             "\"9ball\", \"snooker\" or \"three_cushion\")",
                                             options.game));
    const std::array<std::string, 2> kinds = read_players(options.players);
    const std::uint64_t seed = read_seed(options.seed);
    check_counts(options);
    if (options.reds) throw BadInput("--reds", "--reds is for --game snooker");
    if (options.target) throw BadInput("--target", "--target is for --game three_cushion");
    return {*game, kinds, seed, kinds[0] == kinds[1]};
}

// Snooker and three-cushion: computer players only (games_match.cpp).
nlohmann::ordered_json read_games_match(const MatchOptions& options) {
    const std::array<std::string, 2> kinds = read_players(options.players);
    std::array<int, 2> levels{};
    for (int seat = 0; seat < 2; ++seat) {
        if (kinds[seat] == "random")
            throw BadInput("--players", fmt::format("{} is played by computer players only: use "
                                                    "ai:1 to ai:5",
                                                    options.game));
        levels[seat] = kinds[seat][3] - '0';
    }
    const std::uint64_t seed = read_seed(options.seed);
    check_counts(options);
    return games_match(options, seed, levels);
}

// What the games add up to.
struct Tally {
    std::map<std::string, std::int64_t> wins;
    std::map<std::string, std::vector<double>> decisions;  ///< seconds per decision
    std::int64_t shots = 0, fouls = 0, break_and_runs = 0, stalemates = 0;
    nlohmann::ordered_json capped = nlohmann::ordered_json::array();

    explicit Tally(const Match& m) {
        for (int seat = 0; seat < 2; ++seat) {
            const std::string key = m.by_seat ? (seat == 0 ? "A" : "B") : m.kinds[seat];
            wins[key] = 0;
            decisions[key];
        }
    }

    // Game `k`, `who[seat]` the index in --players of the player sitting there.
    void add(const Match& m, std::int64_t k, const std::array<int, 2>& who,
             const game::GameReport& report) {
        shots += report.shots;
        fouls += report.fouls;
        stalemates += report.stalemates;
        if (report.break_and_run) ++break_and_runs;
        if (report.capped) capped.push_back(k);
        auto key = [&](int seat) {
            return m.by_seat ? std::string(seat == 0 ? "A" : "B") : m.kinds[who[seat]];
        };
        if (report.winner) ++wins[key(static_cast<int>(rules::index(*report.winner)))];
        for (int seat = 0; seat < 2; ++seat) {
            std::vector<double>& d = decisions[key(seat)];
            d.insert(d.end(), report.decision_seconds[seat].begin(),
                     report.decision_seconds[seat].end());
        }
    }
};

// Plays game `k` of the match, writing its shots to `log` when it is open.
void play_one(const MatchOptions& options, const Match& m, std::int64_t k, std::ofstream& log,
              Tally& tally) {
    const std::int64_t seed_index = options.duplicate ? k / 2 : k;
    const bool swapped = options.duplicate && k % 2 == 1;
    const std::uint64_t game_seed = derive(m.seed, static_cast<std::uint64_t>(seed_index));
    const std::array<int, 2> who = swapped ? std::array{1, 0} : std::array{0, 1};
    std::array<std::unique_ptr<game::Player>, 2> players;
    for (int seat = 0; seat < 2; ++seat)
        players[seat] =
            make_player(m.kinds[who[seat]], derive(game_seed, 1 + who[seat]), options.noise);

    game::Config config;
    config.game = m.game;
    config.seed = game_seed;
    config.names = {m.kinds[who[0]], m.kinds[who[1]]};
    config.keep_events = log.is_open();
    game::Session session(config);

    int shot_number = 0;
    game::ShotObserver observer;
    if (log.is_open())
        observer = [&](const game::Session& s, const game::ShotRecord& r) {
            nlohmann::ordered_json line = log_line(k, ++shot_number, s.name(r.shooter()), r);
            log << write_document(line, false);
        };
    const game::GameReport report =
        game::play_game(session, {players[0].get(), players[1].get()}, {}, options.noise,
                        derive(game_seed, 100), observer);
    tally.add(m, k, who, report);
}

nlohmann::ordered_json summary(const MatchOptions& options, const Match& m, Tally& tally,
                               double seconds) {
    nlohmann::ordered_json out;
    out["game"] = options.game;
    out["games"] = options.games;
    out["players"] = m.kinds;
    nlohmann::ordered_json wins_json = nlohmann::ordered_json::object();
    for (const auto& [key, n] : tally.wins) wins_json[key] = n;
    out["wins"] = std::move(wins_json);
    out["shots"] = tally.shots;
    out["fouls"] = tally.fouls;
    out["break_and_runs"] = tally.break_and_runs;
    out["stalemates"] = tally.stalemates;
    out["capped"] = tally.capped.size();
    out["capped_games"] = std::move(tally.capped);
    out["seconds"] = seconds;
    nlohmann::ordered_json decision_json = nlohmann::ordered_json::object();
    for (auto& [key, times] : tally.decisions) {
        std::sort(times.begin(), times.end());
        decision_json[key] = times.empty()
                                 ? nlohmann::ordered_json{{"median", nullptr}, {"p95", nullptr}}
                                 : nlohmann::ordered_json{{"median", quantile(times, 0.5)},
                                                          {"p95", quantile(times, 0.95)}};
    }
    out["decision_seconds"] = std::move(decision_json);
    return out;
}

}  // namespace

nlohmann::ordered_json match_command(const MatchOptions& options) {
    using clock = std::chrono::steady_clock;
    if (options.game == "snooker" || options.game == "three_cushion")
        return read_games_match(options);
    const auto start = clock::now();
    const Match m = read_match(options);
    std::ofstream log;
    if (!options.log.empty()) {
        log.open(options.log, std::ios::binary | std::ios::trunc);
        if (!log)
            throw BadInput("--log", fmt::format("cannot write \"{}\": check the path and its "
                                                "permissions",
                                                options.log));
    }
    Tally tally(m);
    for (std::int64_t k = 0; k < options.games; ++k) play_one(options, m, k, log, tally);
    if (log.is_open()) {
        log.flush();
        if (!log) throw BadInput("--log", fmt::format("cannot write \"{}\"", options.log));
    }
    return summary(options, m, tally, std::chrono::duration<double>(clock::now() - start).count());
}

}  // namespace cli
