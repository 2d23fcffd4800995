// Soak test of the physics engine: N random legal shots (racks broken at up to ~12 m/s, and
// 1-16 balls placed at random with random speed, spin and elevation: the property tests'
// random_shot, on the 7ft, 8ft and 9ft tables in turn), each checked after every event and
// halfway between events for the engine's invariants:
//   overlap     two balls closer than 2R − 1e-9 m
//   energy      kinetic + rotational energy rising after the strike (beyond 1e-9 relative)
//   off_bed     a ball that is not pocketed off the playing surface (Table::on_surface)
//   non_finite  a NaN or infinite position, velocity or spin
//   truncated   a shot cut at the event cap, or one that never ends
//   events      a shot with more events than --max-events (chatter; 10,000 by default: the
//               most seen in 4·10⁶ shots is 4,094, a ball wedged in a slow cluster after a
//               break, pushed and let go every few ms)
// Prints one JSON line (shots, violations by kind, events, throughput) and exits 1 on any
// violation, listing the first 20 on stderr with the command that reproduces the first shot
// alone; 2 on bad arguments. Each shot k has its own generator seeded from (seed, k), so any shot
// can be rerun alone: coolaaber-soak --seed S --from k --shots 1.
//
//   coolaaber-soak [--shots N] [--seed S] [--from K] [--max-events M]
#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "physics/energy.hpp"
#include "physics/simulate.hpp"
#include "random_layout.hpp"

namespace {

using namespace physics;

enum Kind { overlap, energy, off_bed, non_finite, truncated, events, kKinds };
constexpr std::array<const char*, kKinds> kKindNames = {"overlap",    "energy",    "off_bed",
                                                        "non_finite", "truncated", "events"};

struct Options {
    std::uint64_t shots = 1000000;
    std::uint64_t seed = 45;
    std::uint64_t from = 0;
    std::size_t max_events = 10000;
};

struct Violation {
    Kind kind;
    std::string detail;
};

/// A number for a message, to 17 significant digits (a time that reruns, a tiny overlap).
std::string number(double v) {
    char text[32];
    std::snprintf(text, sizeof text, "%.17g", v);
    return text;
}

/// The invariants at one instant; the first broken one, if any.
std::optional<Violation> check_state(const Table& t, const Params& p,
                                     const std::vector<BallState>& st, double time) {
    const double R = p.ball_radius;
    auto at = [&](const std::string& what) { return what + " at t=" + number(time); };
    for (std::size_t i = 0; i < st.size(); ++i) {
        const BallState& a = st[i];
        if (a.motion == Motion::pocketed) continue;
        for (double v : {a.pos.x, a.pos.y, a.vel.x, a.vel.y, a.spin.x, a.spin.y, a.spin.z})
            if (!std::isfinite(v))
                return Violation{non_finite, at("ball " + std::to_string(a.id) + " not finite")};
        if (!t.on_surface(a.pos, R))
            return Violation{off_bed, at("ball " + std::to_string(a.id) + " off the bed")};
        for (std::size_t j = 0; j < i; ++j) {
            if (st[j].motion == Motion::pocketed) continue;
            const double gap = norm(a.pos - st[j].pos) - 2 * R;
            if (gap < -1e-9)
                return Violation{overlap,
                                 at("balls " + std::to_string(st[j].id) + " and " +
                                    std::to_string(a.id) + " overlap by " + number(-gap) + " m")};
        }
    }
    return std::nullopt;
}

/// Checks a shot at each event and halfway between events; the first broken invariant.
std::optional<Violation> check_shot(const Table& t, const Params& p, const Shot& shot,
                                    std::size_t max_events) {
    if (shot.events().size() > max_events)
        return Violation{events, std::to_string(shot.events().size()) + " events or more"};
    if (shot.truncated()) return Violation{truncated, "truncated"};
    double energy_then = kinetic_energy(p, shot.states_at(0.0));
    double last = 0.0;
    auto check_at = [&](double time) -> std::optional<Violation> {
        const std::vector<BallState> st = shot.states_at(time);
        if (auto v = check_state(t, p, st, time)) return v;
        const double e = kinetic_energy(p, st);
        if (e > energy_then * (1 + 1e-9) + 1e-12)
            return Violation{energy, "energy rose to " + number(e) + " J from " +
                                         number(energy_then) + " J at t=" + number(time)};
        energy_then = e;
        return std::nullopt;
    };
    for (const Event& e : shot.events()) {
        if (e.time > last) {
            if (auto v = check_at(0.5 * (last + e.time))) return v;
        }
        if (auto v = check_at(e.time)) return v;
        last = e.time;
    }
    return std::nullopt;
}

/// The shot's own seed, from the run's seed and its number (SplitMix64's finaliser).
std::uint64_t shot_seed(std::uint64_t seed, std::uint64_t k) {
    SplitMix64 mix(seed ^ (k * 0x9e3779b97f4a7c15ULL));
    return mix.next();
}

std::optional<std::uint64_t> parse_count(std::string_view text) {
    if (text.empty() || text.size() > 19) return std::nullopt;
    std::uint64_t v = 0;
    for (char c : text) {
        if (c < '0' || c > '9') return std::nullopt;
        v = v * 10 + static_cast<std::uint64_t>(c - '0');
    }
    return v;
}

std::optional<Options> parse(int argc, char** argv) {
    Options o;
    for (int i = 1; i < argc; ++i) {
        const std::string_view flag = argv[i];
        std::optional<std::uint64_t> v;
        if (i + 1 < argc) v = parse_count(argv[i + 1]);
        if (flag != "--shots" && flag != "--seed" && flag != "--from" && flag != "--max-events") {
            std::fprintf(stderr,
                         "error: unknown argument '%s' (usage: coolaaber-soak [--shots N] "
                         "[--seed S] [--from K] [--max-events M])\n",
                         argv[i]);
            return std::nullopt;
        }
        if (!v) {
            std::fprintf(stderr, "error: %s needs a whole number (e.g. %s 1000)\n", argv[i],
                         argv[i]);
            return std::nullopt;
        }
        ++i;
        if (flag == "--shots") o.shots = *v;
        if (flag == "--seed") o.seed = *v;
        if (flag == "--from") o.from = *v;
        if (flag == "--max-events") o.max_events = static_cast<std::size_t>(*v);
    }
    return o;
}

// What a run found: violations by kind, the events, and the first failing shot.
struct Tally {
    std::array<std::uint64_t, kKinds> count{};
    std::uint64_t total_events = 0, max_events_seen = 0, first_bad = 0, bad_shots = 0;
    std::optional<Violation> first;
    double seconds = 0.0;

    void add(std::uint64_t k, const Shot& shot, std::optional<Violation> v) {
        total_events += shot.events().size();
        max_events_seen = std::max<std::uint64_t>(max_events_seen, shot.events().size());
        if (!v) return;
        ++count[v->kind];
        if (bad_shots++ < 20)
            std::fprintf(stderr, "shot %llu: %s: %s\n", static_cast<unsigned long long>(k),
                         kKindNames[v->kind], v->detail.c_str());
        if (!first) {
            first = v;
            first_bad = k;
        }
    }
};

// Shot k is the property tests' random shot k on the 7ft, 8ft or 9ft table in turn, drawn from
// its own seed (so that it can be rerun alone).
Tally run(const Options& o) {
    const Params p;
    const std::array<Table, 3> tables = {build_table(*table_preset("7ft")),
                                         build_table(*table_preset("8ft")),
                                         build_table(*table_preset("9ft"))};
    SimOptions sim;
    sim.max_events = o.max_events + 1;  // one more: a shot over the bound is seen, not cut
    Tally tally;
    const auto start = std::chrono::steady_clock::now();
    for (std::uint64_t k = o.from; k < o.from + o.shots; ++k) {
        const Table& t = tables[k % 3];
        SplitMix64 rng(shot_seed(o.seed, k));
        const testing::RandomShot rs = testing::random_shot(t, p, rng, static_cast<int>(k % 10));
        const Shot shot = simulate(t, p, rs.balls, &rs.stroke, sim);
        tally.add(k, shot, check_shot(t, p, shot, o.max_events));
    }
    tally.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return tally;
}

// The run as one JSON line on standard output.
void print_summary(const Options& o, const Tally& t) {
    std::uint64_t bad = 0;
    std::string kinds;
    for (int k = 0; k < kKinds; ++k) {
        bad += t.count[static_cast<std::size_t>(k)];
        kinds += std::string(k ? "," : "") + "\"" + kKindNames[static_cast<std::size_t>(k)] +
                 "\":" + std::to_string(t.count[static_cast<std::size_t>(k)]);
    }
    std::printf(
        "{\"shots\":%llu,\"seed\":%llu,\"from\":%llu,\"violations\":%llu,\"by_kind\":{%s},"
        "\"events\":%llu,\"max_events_per_shot\":%llu,\"seconds\":%.2f,"
        "\"shots_per_s\":%.0f}\n",
        static_cast<unsigned long long>(o.shots), static_cast<unsigned long long>(o.seed),
        static_cast<unsigned long long>(o.from), static_cast<unsigned long long>(bad),
        kinds.c_str(), static_cast<unsigned long long>(t.total_events),
        static_cast<unsigned long long>(t.max_events_seen), t.seconds,
        t.seconds > 0 ? static_cast<double>(o.shots) / t.seconds : 0.0);
}

}  // namespace

int main(int argc, char** argv) {
    const std::optional<Options> opt = parse(argc, argv);
    if (!opt) return 2;
    const Tally t = run(*opt);
    print_summary(*opt, t);
    if (!t.first) return 0;
    const char* table = t.first_bad % 3 == 0 ? "7ft" : t.first_bad % 3 == 1 ? "8ft" : "9ft";
    std::fprintf(stderr,
                 "first violation: shot %llu (%s table): %s: %s\n"
                 "reproduce: coolaaber-soak --seed %llu --from %llu --shots 1\n",
                 static_cast<unsigned long long>(t.first_bad), table, kKindNames[t.first->kind],
                 t.first->detail.c_str(), static_cast<unsigned long long>(opt->seed),
                 static_cast<unsigned long long>(t.first_bad));
    return 1;
}
