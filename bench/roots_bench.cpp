// Cost of one contact-time query: the first downward crossing of a ball–ball quartic
// |Δr(t)|² − (2R)² on a motion segment. Target: ≤ 100 ns median for a typical quartic.
#include <benchmark/benchmark.h>

#include "physics/internal/roots.hpp"

namespace {

using physics::roots::Poly4;

constexpr double kBallDiameter = 2 * 0.028575;  // m

/// Coefficients of |Δp + Δv·t + ½Δa·t²|² − D², as detect.cpp builds them.
Poly4 contact_quartic(double px, double py, double vx, double vy, double ax, double ay) {
    const double D = kBallDiameter;
    return {px * px + py * py - D * D, 2.0 * (px * vx + py * vy),
            vx * vx + vy * vy + px * ax + py * ay, vx * ax + vy * ay, 0.25 * (ax * ax + ay * ay)};
}

void run(benchmark::State& state, const Poly4& c, double horizon) {
    Poly4 coeffs = c;
    double hi = horizon;
    for (auto _ : state) {
        benchmark::DoNotOptimize(coeffs);
        benchmark::DoNotOptimize(hi);
        benchmark::DoNotOptimize(physics::roots::first_downward_crossing(coeffs, 0.0, hi));
    }
}

/// A sliding cue ball (3 m/s, slip slightly off its velocity, 2 m/s² friction) meets a slowly
/// rolling object ball (0.1 m/s²) 0.8 m away, a little off centre.
void BM_QuarticCollision(benchmark::State& state) {
    run(state, contact_quartic(0.8, 0.02, -3.2, 0.15, 1.95, -0.25), 1.5);
}

/// Two balls rolling the same way with the same deceleration: the t⁴ and t³ terms are rounding
/// noise (1e-34, 1e-17), so the quartic is a quadratic in disguise.
void BM_QuarticDegenerateQuadratic(benchmark::State& state) {
    Poly4 c = contact_quartic(0.5, 0.01, -2.0, 0.0, 0.0, 0.0);
    c[3] = 3e-17;
    c[4] = 2.5e-34;
    run(state, c, 2.0);
}

/// A grazing hit: the line of motion passes the object ball at D·(1 − 1e-9), so contact begins
/// and ends 2·10⁻⁵ of a time unit apart, a near-double root.
void BM_QuarticNearDoubleRoot(benchmark::State& state) {
    run(state, contact_quartic(0.6, kBallDiameter * (1 - 1e-9), -4.0, 0.0, 2.0, 0.0), 2.0);
}

/// A miss: the cue ball passes 10 cm wide. Most pairs of a shot are like this.
void BM_QuarticNoContact(benchmark::State& state) {
    run(state, contact_quartic(0.8, 0.1, -3.0, 0.0, 2.0, 0.1), 1.5);
}

BENCHMARK(BM_QuarticCollision);
BENCHMARK(BM_QuarticDegenerateQuadratic);
BENCHMARK(BM_QuarticNearDoubleRoot);
BENCHMARK(BM_QuarticNoContact);

}  // namespace
