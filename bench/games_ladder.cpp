// The snooker and three-cushion players' strength (docs/ai.md, "Snooker and three-cushion"): not
// a test, a measurement.
//   games_ladder snooker       [--pairs 2:1,3:2,4:3,5:4] [--games N] [--reds R] [--seed S]
//   games_ladder three_cushion [--pairs ...] [--games N] [--target T] [--seed S]
//   games_ladder ... --pairs 5:5   level 5 against itself: its breaks or its average
// Each pair plays N games (N even) with duplicate seeds: each seed twice, the seats swapped,
// so that both levels break off (open) from the same noise stream. The execution noise is the
// game's 1× times each level's multiplier. Prints one JSON line per pair: wins of each level
// (with a 95 % Wilson interval of the higher level's share), draws and capped games, snooker
// breaks (mean, highest, of visits that scored) or three-cushion averages (points per inning,
// high run), decision times (median, p95) per level, strokes per game.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <numeric>
#include <string>
#include <vector>

#include "ai/games_play.hpp"
#include "physics/rack.hpp"

namespace {

struct Args {
    std::string game = "snooker";
    std::vector<std::pair<int, int>> pairs{{2, 1}, {3, 2}, {4, 3}, {5, 4}};
    int games = 20;
    int reds = 15;
    int target = 15;
    std::uint64_t seed = 1;
};

[[noreturn]] void usage(const char* why) {
    std::fprintf(stderr,
                 "games_ladder: %s\nusage: games_ladder snooker|three_cushion [--pairs 2:1,3:2] "
                 "[--games N (even)] [--reds R] [--target T] [--seed S]\n",
                 why);
    std::exit(2);
}

std::vector<std::pair<int, int>> read_pairs(const std::string& text) {
    std::vector<std::pair<int, int>> out;
    std::size_t at = 0;
    while (at < text.size()) {
        const std::size_t comma = std::min(text.find(',', at), text.size());
        const std::string p = text.substr(at, comma - at);
        if (p.size() != 3 || p[1] != ':' || p[0] < '1' || p[0] > '5' || p[2] < '1' || p[2] > '5')
            usage("--pairs: levels as HIGH:LOW, e.g. 2:1,3:2");
        out.push_back({p[0] - '0', p[2] - '0'});
        at = comma + 1;
    }
    return out;
}

Args read_args(int argc, char** argv) {
    Args a;
    if (argc < 2) usage("name the game");
    a.game = argv[1];
    if (a.game != "snooker" && a.game != "three_cushion") usage("snooker or three_cushion");
    for (int i = 2; i + 1 < argc; i += 2) {
        const std::string k = argv[i], v = argv[i + 1];
        if (k == "--pairs")
            a.pairs = read_pairs(v);
        else if (k == "--games")
            a.games = std::atoi(v.c_str());
        else if (k == "--reds")
            a.reds = std::atoi(v.c_str());
        else if (k == "--target")
            a.target = std::atoi(v.c_str());
        else if (k == "--seed")
            a.seed = std::strtoull(v.c_str(), nullptr, 10);
        else
            usage(("unknown flag " + k).c_str());
    }
    if (a.games < 2 || a.games % 2) usage("--games: an even number, at least 2");
    if (a.reds < 1 || a.reds > 15) usage("--reds: 1 to 15");
    if (a.target < 1) usage("--target: at least 1");
    return a;
}

std::uint64_t derive(std::uint64_t seed, std::uint64_t tag) {
    physics::SplitMix64 mix(seed ^ (0xd1b54a32d192ed03ULL * (tag + 1)));
    mix.next();
    return mix.next();
}

double quantile(std::vector<double> v, double q) {
    if (v.empty()) return 0.0;
    std::sort(v.begin(), v.end());
    const auto rank = static_cast<std::size_t>(std::ceil(q * static_cast<double>(v.size())));
    return v[std::clamp<std::size_t>(rank, 1, v.size()) - 1];
}

// The 95 % Wilson interval of a share of k in n.
std::pair<double, double> wilson(double k, double n) {
    if (n <= 0) return {0.0, 1.0};
    const double z = 1.96, p = k / n, d = 1 + z * z / n;
    const double c = (p + z * z / (2 * n)) / d;
    const double h = z * std::sqrt(p * (1 - p) / n + z * z / (4 * n * n)) / d;
    return {c - h, c + h};
}

// What one level (index 0: the first of the pair, 1: the second) adds up over a pair's games.
struct Side {
    double wins = 0;
    std::vector<int> breaks;
    long points = 0, innings = 0;
    int high_run = 0;
    std::vector<double> seconds;
};

struct Tally {
    std::array<Side, 2> side;  ///< by level: 0 the pair's first, 1 its second
    int draws = 0, capped = 0;
    long strokes = 0;
};

// Game k of a pair: seat A is the first level on even k, the second on odd k (the same seed).
void play_game(const Args& a, const std::array<int, 2>& level, int k, Tally& t) {
    const std::uint64_t game_seed = derive(a.seed, static_cast<std::uint64_t>(k / 2));
    const std::array<int, 2> who = k % 2 == 1 ? std::array{1, 0} : std::array{0, 1};
    std::array<ai::Seat, 2> seats;
    for (int s = 0; s < 2; ++s) seats[s] = {level[who[s]], derive(game_seed, 1 + who[s])};
    std::optional<rules::Player> winner;
    std::array<std::vector<double>, 2> secs;
    if (a.game == "snooker") {
        ai::SnookerFrameSetup setup;
        setup.reds = a.reds;
        const ai::SnookerFrameReport r =
            ai::play_snooker_frame(setup, seats, derive(game_seed, 100));
        winner = r.winner;
        t.capped += r.capped;
        t.strokes += r.strokes;
        secs = r.decision_seconds;
        for (int s = 0; s < 2; ++s) {
            Side& d = t.side[who[s]];
            d.breaks.insert(d.breaks.end(), r.breaks[s].begin(), r.breaks[s].end());
            d.points += r.scores[s];
        }
    } else {
        ai::CaromGameSetup setup;
        setup.options.target = a.target;
        const ai::CaromGameReport r =
            ai::play_three_cushion_game(setup, seats, derive(game_seed, 100));
        winner = r.winner;
        t.capped += !r.over;
        t.strokes += r.strokes;
        secs = r.decision_seconds;
        for (int s = 0; s < 2; ++s) {
            Side& d = t.side[who[s]];
            d.points += r.scores[s];
            d.innings += r.innings[s];
            d.high_run = std::max(d.high_run, r.high_run[s]);
        }
    }
    if (winner)
        t.side[who[rules::index(*winner)]].wins += 1;
    else
        ++t.draws;
    for (int s = 0; s < 2; ++s)
        t.side[who[s]].seconds.insert(t.side[who[s]].seconds.end(), secs[s].begin(), secs[s].end());
}

void print_side(const Args& a, const Side& d, int level, bool first) {
    std::printf(", \"level%d_%s\": {", level, first ? "first" : "second");
    if (a.game == "snooker") {
        const double sum = std::accumulate(d.breaks.begin(), d.breaks.end(), 0.0);
        std::printf(
            "\"points_per_frame\": %.2f, \"scoring_visits\": %zu, \"mean_break\": %.2f, "
            "\"highest_break\": %d, ",
            double(d.points) / a.games, d.breaks.size(),
            d.breaks.empty() ? 0.0 : sum / double(d.breaks.size()),
            d.breaks.empty() ? 0 : *std::max_element(d.breaks.begin(), d.breaks.end()));
    } else {
        std::printf("\"points\": %ld, \"innings\": %ld, \"average\": %.3f, \"high_run\": %d, ",
                    d.points, d.innings, d.innings ? double(d.points) / double(d.innings) : 0.0,
                    d.high_run);
    }
    std::printf("\"decisions\": %zu, \"decision_median_s\": %.4f, \"decision_p95_s\": %.4f}",
                d.seconds.size(), quantile(d.seconds, 0.5), quantile(d.seconds, 0.95));
}

void play_pair(const Args& a, int hi, int lo) {
    Tally t;
    for (int k = 0; k < a.games; ++k) {
        play_game(a, {hi, lo}, k, t);
        std::fprintf(stderr, "%d:%d game %d/%d\n", hi, lo, k + 1, a.games);
    }
    const double share = (t.side[0].wins + 0.5 * t.draws) / a.games;
    const auto [low, high] = wilson(t.side[0].wins + 0.5 * t.draws, a.games);
    std::printf(
        "{\"game\": \"%s\", \"pair\": \"%d:%d\", \"games\": %d, \"reds\": %d, "
        "\"target\": %d, \"wins\": [%g, %g], \"draws\": %d, \"capped\": %d, "
        "\"first_share\": %.3f, \"first_share_95\": [%.3f, %.3f], "
        "\"strokes_per_game\": %.1f",
        a.game.c_str(), hi, lo, a.games, a.reds, a.target, t.side[0].wins, t.side[1].wins, t.draws,
        t.capped, share, low, high, double(t.strokes) / a.games);
    print_side(a, t.side[0], hi, true);
    print_side(a, t.side[1], lo, false);
    std::printf("}\n");
    std::fflush(stdout);
}

}  // namespace

int main(int argc, char** argv) {
    const Args a = read_args(argc, argv);
    for (const auto& [hi, lo] : a.pairs) play_pair(a, hi, lo);
}
