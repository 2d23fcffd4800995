#include "physics/portable_math.hpp"

#include <array>
#include <cmath>
#include <cstddef>
#include <limits>

namespace physics::portable {

namespace {

// Only + − × ÷ (and floor and ldexp, which are exact): -ffp-contract=off keeps the compiler
// from fusing them, so the bits are the same wherever IEEE doubles are.

constexpr double kHalfPi = 0x1.921fb54442d18p+0;
constexpr double kPi = 0x1.921fb54442d18p+1;
constexpr double kSixthPi = 0x1.0c152382d7366p-1;
constexpr double kSqrt3 = 0x1.bb67ae8584caap+0;
constexpr double kTanTwelfthPi = 0.2679491924311228;  // 2 − √3
// π/2 in three parts of 33, 33 and 53 bits: k·part is exact for |k| < 2²⁰ (Cody and Waite).
constexpr double kHalfPi1 = 0x1.921fb544p+0;
constexpr double kHalfPi2 = 0x1.0b4611a6p-34;
constexpr double kHalfPi3 = 0x1.3198a2e037073p-69;
// ln 2 in a part of 32 bits and the rest.
constexpr double kLn2High = 0x1.62e42ffp-1;
constexpr double kLn2Low = -0x1.718432a1b0e26p-35;

/// 1/n! for n = 0 … N−1 (n! is exact in a double up to 22!).
template <std::size_t N>
constexpr std::array<double, N> inverse_factorials() {
    std::array<double, N> c{};
    double f = 1.0;
    for (std::size_t n = 0; n < N; ++n) {
        if (n > 0) f *= static_cast<double>(n);
        c[n] = 1.0 / f;
    }
    return c;
}
constexpr auto kInvFact = inverse_factorials<22>();

/// Taylor series of sin on |r| ≤ π/4, to r¹⁹ (the next term is below 2⁻⁷² of r).
double sin_kernel(double r) {
    const double z = r * r;
    double p = 0.0;
    for (std::size_t n = 19; n >= 3; n -= 2) p = p * z + ((n / 2) % 2 ? -kInvFact[n] : kInvFact[n]);
    return r + r * z * p;
}

/// Taylor series of cos on |r| ≤ π/4, to r²⁰.
double cos_kernel(double r) {
    const double z = r * r;
    double p = 0.0;
    for (std::size_t n = 20; n >= 4; n -= 2) p = p * z + ((n / 2) % 2 ? -kInvFact[n] : kInvFact[n]);
    return (1.0 - 0.5 * z) + z * z * p;
}

/// x = k·π/2 + r with |r| ≤ π/4 (a little more for very large x); returns k mod 4.
int reduce(double x, double& r) {
    const double k = std::floor(x * (1.0 / kHalfPi) + 0.5);
    r = ((x - k * kHalfPi1) - k * kHalfPi2) - k * kHalfPi3;
    const double quadrant = k - 4.0 * std::floor(k * 0.25);
    return static_cast<int>(quadrant);
}

/// atan on [0, 2 − √3] by its series, to u²⁹ (the next term is below 2⁻⁶⁰ of u).
double atan_kernel(double u) {
    const double z = u * u;
    double p = 0.0;
    for (int n = 14; n >= 1; --n) p = p * z + (n % 2 ? -1.0 : 1.0) / (2.0 * n + 1.0);
    return u + u * z * p;
}

/// atan on [0, 1]: beyond tan(π/12), atan t = π/6 + atan((t·√3 − 1)/(t + √3)).
double atan_unit(double t) {
    if (t <= kTanTwelfthPi) return atan_kernel(t);
    return kSixthPi + atan_kernel((t * kSqrt3 - 1.0) / (t + kSqrt3));
}

}  // namespace

double sin(double x) {
    if (!std::isfinite(x)) return std::numeric_limits<double>::quiet_NaN();
    double r;
    switch (reduce(x, r)) {
        case 0:
            return sin_kernel(r);
        case 1:
            return cos_kernel(r);
        case 2:
            return -sin_kernel(r);
        default:
            return -cos_kernel(r);
    }
}

double cos(double x) {
    if (!std::isfinite(x)) return std::numeric_limits<double>::quiet_NaN();
    double r;
    switch (reduce(x, r)) {
        case 0:
            return cos_kernel(r);
        case 1:
            return -sin_kernel(r);
        case 2:
            return -cos_kernel(r);
        default:
            return sin_kernel(r);
    }
}

double tan(double x) {
    if (!std::isfinite(x)) return std::numeric_limits<double>::quiet_NaN();
    double r;
    const int q = reduce(x, r);
    const double s = sin_kernel(r), c = cos_kernel(r);
    return q % 2 == 0 ? s / c : -c / s;
}

double atan(double x) {
    if (std::isnan(x)) return x;
    const double t = std::fabs(x);
    const double a = t <= 1.0 ? atan_unit(t) : kHalfPi - atan_unit(1.0 / t);
    return x < 0 ? -a : a;
}

double atan2(double y, double x) {
    if (std::isnan(x) || std::isnan(y)) return std::numeric_limits<double>::quiet_NaN();
    if (x == 0.0) {
        if (y == 0.0) return std::signbit(x) ? std::copysign(kPi, y) : std::copysign(0.0, y);
        return y > 0 ? kHalfPi : -kHalfPi;
    }
    const double a = atan(y / x);
    if (x > 0) return a;
    return std::signbit(y) ? a - kPi : a + kPi;
}

double exp(double x) {
    if (std::isnan(x)) return x;
    if (x > 709.782712893384) return std::numeric_limits<double>::infinity();
    if (x < -745.2) return 0.0;
    // x = k·ln 2 + r with |r| ≤ ln 2 / 2; eʳ by its series to r¹⁴ (the next term is below 2⁻⁶²).
    const double k = std::floor(x * (1.0 / 0x1.62e42fefa39efp-1) + 0.5);
    const double r = (x - k * kLn2High) - k * kLn2Low;
    double p = 0.0;
    for (std::size_t n = 14; n >= 2; --n) p = p * r + kInvFact[n];
    const double er = 1.0 + (r + r * r * p);
    return std::ldexp(er, static_cast<int>(k));
}

}  // namespace physics::portable
