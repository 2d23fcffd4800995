// physics::portable against the C library (glibc here, correctly rounded in almost every case):
// sin, cos and exp within 2 ulp over the engine's arguments; tan (a quotient of two) and atan
// (π/6 plus a transformed argument) within 4; and the special values.
#include "physics/portable_math.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <functional>
#include <limits>

#include "physics/rack.hpp"

namespace physics {
namespace {

/// The distance between two doubles of the same sign, in units in the last place.
double ulps(double a, double b) {
    if (a == b) return 0.0;
    return std::fabs(a - b) / (std::nextafter(std::fabs(b), INFINITY) - std::fabs(b));
}

/// The largest error of `f` against `reference` over `n` arguments drawn uniformly in [lo, hi].
double worst_ulps(const std::function<double(double)>& f,
                  const std::function<double(double)>& reference, double lo, double hi, int n) {
    SplitMix64 rng(17);
    double worst = 0.0;
    for (int k = 0; k < n; ++k) {
        const double u = rng.uniform();
        const double x = lo + (hi - lo) * u;
        worst = std::max(worst, ulps(f(x), reference(x)));
    }
    return worst;
}

constexpr double kTwoUlps = 2.0;
constexpr double kFourUlps = 4.0;

TEST(PortableMath, SinCosTanAgreeWithTheCLibrary) {
    // Headings in degrees reach ±3600 (the saved game's range): ±63 rad; angles in the table's
    // geometry are within a quarter turn.
    for (auto [lo, hi] : {std::pair{-0.8, 0.8}, std::pair{-7.0, 7.0}, std::pair{-63.0, 63.0}}) {
        EXPECT_LE(worst_ulps(
                      portable::sin, [](double x) { return std::sin(x); }, lo, hi, 200000),
                  kTwoUlps);
        EXPECT_LE(worst_ulps(
                      portable::cos, [](double x) { return std::cos(x); }, lo, hi, 200000),
                  kTwoUlps);
    }
    EXPECT_LE(worst_ulps(
                  portable::tan, [](double x) { return std::tan(x); }, -1.5, 1.5, 200000),
              kFourUlps);
}

TEST(PortableMath, AtanAtan2ExpAgreeWithTheCLibrary) {
    for (auto [lo, hi] : {std::pair{-1.0, 1.0}, std::pair{-50.0, 50.0}})
        EXPECT_LE(worst_ulps(
                      portable::atan, [](double x) { return std::atan(x); }, lo, hi, 200000),
                  kFourUlps);
    for (auto [lo, hi] : {std::pair{-1.0, 1.0}, std::pair{-700.0, 700.0}})
        EXPECT_LE(worst_ulps(
                      portable::exp, [](double x) { return std::exp(x); }, lo, hi, 200000),
                  kTwoUlps);
    SplitMix64 rng(18);
    double worst = 0.0;
    for (int k = 0; k < 200000; ++k) {
        const double y = 4.0 * rng.uniform() - 2.0;
        const double x = 4.0 * rng.uniform() - 2.0;
        worst = std::max(worst, ulps(portable::atan2(y, x), std::atan2(y, x)));
    }
    EXPECT_LE(worst, kFourUlps);
}

TEST(PortableMath, SpecialValues) {
    EXPECT_EQ(portable::sin(0.0), 0.0);
    EXPECT_EQ(portable::cos(0.0), 1.0);
    EXPECT_EQ(portable::exp(0.0), 1.0);
    EXPECT_EQ(portable::atan(0.0), 0.0);
    EXPECT_EQ(portable::exp(-1000.0), 0.0);
    EXPECT_TRUE(std::isinf(portable::exp(1000.0)));
    constexpr double inf = std::numeric_limits<double>::infinity();
    EXPECT_TRUE(std::isnan(portable::sin(inf)));
    EXPECT_DOUBLE_EQ(portable::atan(inf), std::atan(inf));
    for (double y : {0.0, -0.0, 1.0, -1.0})
        for (double x : {0.0, -0.0, 1.0, -1.0})
            EXPECT_DOUBLE_EQ(portable::atan2(y, x), std::atan2(y, x)) << y << ", " << x;
}

}  // namespace
}  // namespace physics
