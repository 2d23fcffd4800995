// The AI's noise draws (evaluate.hpp's noise_draws, quasi_random.hpp): reproducible from the
// seed, each component a standard normal, and any first k of them spread over the distribution
// far more evenly than k pseudo-random draws would be.
#include "ai/internal/quasi_random.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <utility>
#include <vector>

#include "ai/internal/evaluate.hpp"

namespace {

double normal_cdf(double z) {
    return 0.5 * std::erfc(-z / std::sqrt(2.0));
}

// The largest gap between the empirical CDF of `xs` and the normal's (Kolmogorov's statistic).
double ks_distance(std::vector<double> xs) {
    std::sort(xs.begin(), xs.end());
    const double n = static_cast<double>(xs.size());
    double d = 0.0;
    for (std::size_t i = 0; i < xs.size(); ++i) {
        const double f = normal_cdf(xs[i]);
        d = std::max({d, f - static_cast<double>(i) / n, static_cast<double>(i + 1) / n - f});
    }
    return d;
}

std::vector<double> component(const std::vector<ai::NoiseDraw>& draws, std::size_t n,
                              double ai::NoiseDraw::*field) {
    std::vector<double> out;
    for (std::size_t i = 0; i < n; ++i) out.push_back(draws[i].*field);
    return out;
}

TEST(RadicalInverse, MirrorsTheDigits) {
    EXPECT_EQ(ai::radical_inverse(0, 2), 0.0);
    EXPECT_EQ(ai::radical_inverse(1, 2), 0.5);
    EXPECT_EQ(ai::radical_inverse(6, 2), 0.375);               // 110 → 0.011
    EXPECT_NEAR(ai::radical_inverse(5, 3), 7.0 / 9.0, 1e-15);  // 12 → 0.21
}

TEST(NormalQuantile, InvertsTheCdf) {
    for (double u : {1e-9, 0.001, 0.025, 0.3, 0.5, 0.8, 0.975, 0.999999})
        EXPECT_NEAR(normal_cdf(ai::normal_quantile(u)), u, 1e-12 + 1e-9 * u) << u;
    EXPECT_NEAR(ai::normal_quantile(0.975), 1.959963984540054, 1e-10);
    EXPECT_NEAR(ai::normal_quantile(0.5), 0.0, 1e-15);
    EXPECT_TRUE(std::isfinite(ai::normal_quantile(0.0)));
    EXPECT_TRUE(std::isfinite(ai::normal_quantile(1.0)));
}

TEST(NoiseDraws, TheSameSeedGivesTheSameDrawsAndAnotherOthers) {
    const auto a = ai::noise_draws(11, 64), b = ai::noise_draws(11, 64),
               c = ai::noise_draws(12, 64);
    ASSERT_EQ(a.size(), 64u);
    bool differs = false;
    for (std::size_t i = 0; i < a.size(); ++i) {
        EXPECT_EQ(a[i].heading, b[i].heading);
        EXPECT_EQ(a[i].top, b[i].top);
        differs = differs || a[i].heading != c[i].heading;
    }
    EXPECT_TRUE(differs);
    // A longer run starts with the shorter one: rounds of draws can take them in turn.
    const auto longer = ai::noise_draws(11, 200);
    EXPECT_EQ(longer[63].speed, a[63].speed);
}

TEST(NoiseDraws, EveryComponentIsAStandardNormal) {
    const auto draws = ai::noise_draws(5, 1024);
    for (double ai::NoiseDraw::*f :
         {&ai::NoiseDraw::heading, &ai::NoiseDraw::elevation, &ai::NoiseDraw::speed,
          &ai::NoiseDraw::side, &ai::NoiseDraw::top}) {
        const std::vector<double> xs = component(draws, draws.size(), f);
        double mean = 0.0, var = 0.0;
        for (double x : xs) mean += x / 1024.0;
        for (double x : xs) var += (x - mean) * (x - mean) / 1023.0;
        EXPECT_NEAR(mean, 0.0, 0.02);
        EXPECT_NEAR(var, 1.0, 0.05);
        EXPECT_LT(ks_distance(xs), 0.02);
    }
}

// The sum of `k`'s digits in `base`.
std::size_t digit_sum(std::size_t k, std::size_t base) {
    std::size_t s = 0;
    for (; k > 0; k /= base) s += k % base;
    return s;
}

TEST(NoiseDraws, TheFirstFewCoverTheDistributionEvenly) {
    // The rounds of the search take 16, 40 and 80 draws. Pseudo-random draws stray from the
    // normal's CDF by about 0.87/√k at the median (Kolmogorov): 0.22, 0.14, 0.10. The first k
    // points of a base-b van der Corput sequence split, by k's base-b digits d_j, into d_j
    // blocks of b^j points equally spaced 1/b^j apart; a rotation keeps them so, and any
    // interval holds within 1 of its share of each block. So each component's KS distance is
    // below digit_sum(k, b)/k whatever the seed's shift: 1/16, 2/40 and 2/80 for the heading
    // (base 2), against 0.22, 0.14 and 0.10.
    const std::vector<std::pair<double ai::NoiseDraw::*, std::size_t>> bases{
        {&ai::NoiseDraw::heading, 2},
        {&ai::NoiseDraw::speed, 3},
        {&ai::NoiseDraw::side, 5},
        {&ai::NoiseDraw::top, 7},
        {&ai::NoiseDraw::elevation, 11}};
    for (std::uint64_t seed = 1; seed <= 50; ++seed) {
        const auto draws = ai::noise_draws(seed, 80);
        for (std::size_t k : {16u, 40u, 80u})
            for (const auto& [field, base] : bases)
                EXPECT_LT(ks_distance(component(draws, k, field)),
                          static_cast<double>(digit_sum(k, base)) / static_cast<double>(k) + 1e-9)
                    << "seed " << seed << ", base " << base << ", first " << k;
    }
}

}  // namespace
