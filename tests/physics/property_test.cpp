// Property test: random layouts and strokes, with the engine's invariants checked after every
// event (docs/physics.md, "Things that break event-based engines").
#include <gtest/gtest.h>

#include <cmath>

#include "physics/energy.hpp"
#include "physics/simulate.hpp"
#include "random_layout.hpp"

namespace physics {
namespace {

struct Violation {
    std::string what;
};

/// Checks the invariants at one event: no overlap deeper than 1e-9 m, no ball off the table
/// unless pocketed, no NaN. Returns an empty string when all hold.
std::string check_state(const Table& t, const Params& p, const std::vector<BallState>& st) {
    for (std::size_t i = 0; i < st.size(); ++i) {
        const BallState& a = st[i];
        if (a.motion == Motion::pocketed) continue;
        if (!std::isfinite(a.pos.x) || !std::isfinite(a.pos.y) || !std::isfinite(a.vel.x) ||
            !std::isfinite(a.vel.y) || !std::isfinite(a.spin.x) || !std::isfinite(a.spin.y) ||
            !std::isfinite(a.spin.z))
            return "ball " + std::to_string(a.id) + " has a NaN or infinity";
        if (!t.on_surface(a.pos, p.ball_radius))
            return "ball " + std::to_string(a.id) + " is off the table";
        for (std::size_t j = 0; j < i; ++j) {
            if (st[j].motion == Motion::pocketed) continue;
            const double gap = norm(a.pos - st[j].pos) - 2 * p.ball_radius;
            if (gap < -1e-9)
                return "balls " + std::to_string(a.id) + " and " + std::to_string(st[j].id) +
                       " overlap by " + std::to_string(-gap) + " m";
        }
    }
    return {};
}

TEST(PhysicsProperty, TenThousandRandomShotsKeepEveryInvariant) {
    const Params p;
    const Table t = build_table(*table_preset("9ft"));
    SplitMix64 rng(20261122);
    SimOptions options;
    options.max_events = 20000;
    std::size_t events = 0, truncated = 0, pocketed = 0;
    constexpr int kShots = 10000;
    for (int k = 0; k < kShots; ++k) {
        const testing::RandomShot s = testing::random_shot(t, p, rng, k);
        ASSERT_FALSE(validate_layout(t, p, s.balls)) << "shot " << k;
        const Shot shot = simulate(t, p, s.balls, &s.stroke, options);
        events += shot.events().size();
        truncated += shot.truncated() ? 1 : 0;
        double energy = kinetic_energy(p, shot.states_at(0.0));
        double last_time = 0.0;
        for (const Event& e : shot.events()) {
            ASSERT_GE(e.time, last_time) << "shot " << k << ": events out of order";
            if (e.time > last_time) {
                // Between events: halfway to this one, the closed forms only lose energy.
                const double mid = kinetic_energy(p, shot.states_at(0.5 * (last_time + e.time)));
                ASSERT_LE(mid, energy * (1 + 1e-9) + 1e-12)
                    << "shot " << k << ": energy rose between t=" << last_time
                    << " and t=" << e.time;
                energy = mid;
            }
            last_time = e.time;
            const std::vector<BallState> st = shot.states_at(e.time);
            const std::string bad = check_state(t, p, st);
            ASSERT_TRUE(bad.empty()) << "shot " << k << " at t=" << e.time << " after "
                                     << to_string(e.type) << ": " << bad;
            // Energy never rises, at an event or between events.
            const double now = kinetic_energy(p, st);
            ASSERT_LE(now, energy * (1 + 1e-9) + 1e-12)
                << "shot " << k << ": energy rose at t=" << e.time << " (" << to_string(e.type)
                << ")";
            energy = now;
        }
        for (const BallState& b : shot.final_states()) pocketed += b.motion == Motion::pocketed;
        if (!shot.truncated()) {
            for (const BallState& b : shot.final_states())
                ASSERT_TRUE(b.motion == Motion::stationary || b.motion == Motion::pocketed)
                    << "shot " << k << ": ball " << b.id << " still moving at rest time";
        }
    }
    // Chatter must be rare enough never to hit a cap of 20,000 events.
    EXPECT_EQ(truncated, 0u);
    EXPECT_GT(pocketed, 1000u) << "random play pockets balls";
    RecordProperty("events", static_cast<int>(events));
    std::printf("%d shots, %zu events (%.1f per shot), %zu balls pocketed\n", kShots, events,
                static_cast<double>(events) / kShots, pocketed);
}

TEST(PhysicsProperty, EventCapTruncatesAndReportsIt) {
    const Params p;
    const Table t = build_table(*table_preset("9ft"));
    auto balls = rack(RackType::eight_ball, t, p, 3);
    Stroke s;
    s.speed = 8.0;
    SimOptions options;
    options.max_events = 10;
    const Shot shot = simulate(t, p, balls, &s, options);
    EXPECT_TRUE(shot.truncated());
    EXPECT_EQ(shot.events().size(), 10u);
    EXPECT_FALSE(shot.rest_time().has_value());
    // Final states are the states at the last event.
    const double last = shot.events().back().time;
    const auto fin = shot.final_states();
    const auto at = shot.states_at(last);
    for (std::size_t i = 0; i < fin.size(); ++i) {
        EXPECT_EQ(fin[i].pos, at[i].pos);
        EXPECT_EQ(fin[i].vel, at[i].vel);
    }
}

}  // namespace
}  // namespace physics
