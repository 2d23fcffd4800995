// Fingerprints of the physics engine's results, for checking that a change to src/physics
// leaves every result bit-identical: one FNV-1a hash per shot over the bit patterns of every
// event and every segment, for the standard scenes and for N random shots (the property
// tests' random_shot: breaks and random layouts and strokes) on each of the 7ft, 8ft and 9ft
// tables. Build it against each engine and compare the outputs (docs/physics.md, Performance):
// the target `physics_fingerprint` (tools/CMakeLists.txt), or for an older checkout by hand:
//   g++ -std=c++20 -O3 -DNDEBUG -ffp-contract=off -fno-math-errno -Isrc -Itests/physics
//       tools/physics_fingerprint.cpp src/physics/*.cpp -o /tmp/fingerprint   (one line)
//   /tmp/fingerprint 10000 12345 > after.txt   (shots per table, seed; events on stderr)
//   cmp before.txt after.txt
// A third argument `--positions` adds every final ball position, to measure how far apart two
// builds' results lie where their hashes differ (native and WebAssembly, docs/physics.md).
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>

#include "physics/scenes.hpp"
#include "physics/simulate.hpp"
#include "random_layout.hpp"

namespace {

using namespace physics;

/// FNV-1a over 64-bit words, byte by byte.
struct Fnv {
    std::uint64_t h = 1469598103934665603ULL;
    void mix(std::uint64_t v) {
        for (int i = 0; i < 8; ++i) {
            h ^= (v >> (8 * i)) & 0xff;
            h *= 1099511628211ULL;
        }
    }
    void mix(double d) {
        std::uint64_t bits;
        std::memcpy(&bits, &d, sizeof bits);  // std::bit_cast, which Emscripten's libc++ lacks
        mix(bits);
    }
    void mix(int v) { mix(static_cast<std::uint64_t>(static_cast<std::int64_t>(v))); }
};

/// Every event (time, type, speed, rail, pocket, balls) and every segment (start time and
/// state) of a shot, and whether it was truncated.
std::uint64_t fingerprint(const Shot& shot, long& events) {
    Fnv f;
    for (const Event& e : shot.events()) {
        ++events;
        f.mix(e.time);
        f.mix(static_cast<int>(e.type));
        f.mix(e.speed);
        f.mix(e.rail);
        f.mix(e.pocket);
        for (int k = 0; k < e.ball_count; ++k) {
            const EventBall& b = e.balls[static_cast<std::size_t>(k)];
            f.mix(b.id);
            for (double d : {b.pos.x, b.pos.y, b.vel.x, b.vel.y, b.spin.x, b.spin.y, b.spin.z})
                f.mix(d);
        }
    }
    for (std::size_t i = 0; i < shot.ball_count(); ++i) {
        for (const Segment& s : shot.segments(i)) {
            const BallState& b = s.start;
            f.mix(s.t0);
            f.mix(static_cast<int>(b.motion));
            f.mix(b.pocket);
            for (double d : {b.pos.x, b.pos.y, b.vel.x, b.vel.y, b.spin.x, b.spin.y, b.spin.z})
                f.mix(d);
        }
    }
    f.mix(shot.truncated() ? 1 : 0);
    return f.h;
}

}  // namespace

/// Every ball's final position, exactly (hexadecimal floating point), for measuring how far two
/// builds' results lie apart where their hashes differ.
void print_positions(const Shot& shot) {
    for (const BallState& b : shot.final_states()) std::printf(" %a %a", b.pos.x, b.pos.y);
}

int main(int argc, char** argv) {
    const int shots = argc > 1 ? std::atoi(argv[1]) : 1000;
    const std::uint64_t seed = argc > 2 ? std::strtoull(argv[2], nullptr, 10) : 12345;
    const bool positions = argc > 3 && std::string(argv[3]) == "--positions";
    const Params p;
    long events = 0;
    for (const std::string& name : standard_scene_names()) {
        const Scene sc = standard_scene(name, p);
        const Shot shot = simulate(build_table(sc.table), p, sc.balls, &sc.stroke);
        std::printf("%s %016llx", name.c_str(),
                    static_cast<unsigned long long>(fingerprint(shot, events)));
        if (positions) print_positions(shot);
        std::printf("\n");
    }
    for (const char* preset : {"7ft", "8ft", "9ft"}) {
        const Table t = build_table(*table_preset(preset));
        SplitMix64 rng(seed);
        for (int k = 0; k < shots; ++k) {
            const testing::RandomShot rs = testing::random_shot(t, p, rng, k);
            const Shot shot = simulate(t, p, rs.balls, &rs.stroke);
            std::printf("%s %d %016llx", preset, k,
                        static_cast<unsigned long long>(fingerprint(shot, events)));
            if (positions) print_positions(shot);
            std::printf("\n");
        }
    }
    std::fprintf(stderr, "%ld events\n", events);
}
