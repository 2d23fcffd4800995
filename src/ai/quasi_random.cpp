#include "ai/internal/quasi_random.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace ai {

double radical_inverse(std::uint64_t i, std::uint64_t base) {
    const double inv = 1.0 / static_cast<double>(base);
    double f = inv, r = 0.0;
    for (; i > 0; i /= base, f *= inv) r += f * static_cast<double>(i % base);
    return r;
}

double normal_quantile(double u) {
    u = std::clamp(u, 1e-12, 1.0 - 1e-12);
    const auto cdf = [](double z) { return 0.5 * std::erfc(-z / std::numbers::sqrt2); };
    // Bisection on [−8, 8] (Φ⁻¹(1e-12) ≈ −7.03) to about 1e-11, then two Newton steps.
    double lo = -8.0, hi = 8.0;
    for (int k = 0; k < 40; ++k) {
        const double mid = 0.5 * (lo + hi);
        (cdf(mid) < u ? lo : hi) = mid;
    }
    double z = 0.5 * (lo + hi);
    for (int k = 0; k < 2; ++k) {
        const double pdf = std::exp(-0.5 * z * z) / std::sqrt(2.0 * std::numbers::pi);
        z -= (cdf(z) - u) / pdf;
    }
    return z;
}

}  // namespace ai
