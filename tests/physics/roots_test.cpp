// Tests of the polynomial root module: against reference roots computed exactly (rational
// arithmetic refined to 200 bits, tools/make_roots_reference.py), on the contract of
// first_downward_crossing and sign_change_roots with hand-made polynomials, and on random
// two-ball contact quartics checked against a double-double evaluation of p.
//
// Tolerances (see the generator's docstring for the derivation):
//  * a root that is well conditioned (alone in a noise band narrower than 1e-12 relative) must
//    be found within 1e-12 relative;
//  * any root at all must have a residual |p(t)|, evaluated in double-double, within the noise
//    level of evaluating p in double, eta(t) = 16·ε·Σ|c_i||t|^i: that is the best a solver that
//    samples p in double can promise for a near-double or triple root;
//  * where the noise band holds one true sign change, exactly one root is reported there;
//    where it holds a cluster (or a near-touch), the count has the same parity as the truth.
#include "physics/internal/roots.hpp"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstdint>
#include <fstream>
#include <iomanip>
#include <limits>
#include <nlohmann/json.hpp>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include "contact_quartics.hpp"

namespace physics::roots {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr double kEps = std::numeric_limits<double>::epsilon();
constexpr double kNoiseUlps = 16.0;       // eta = kNoiseUlps·ε·Σ|c_i||t|^i
constexpr double kWellTolerance = 1e-12;  // relative, for well-conditioned roots

// ------------------------------------------------------------------ reference data

struct Band {
    double lo, hi;  ///< the band, rounded outward to doubles
    int roots;      ///< true sign changes inside
    int left;       ///< true sign of p just below the band; 0 if the band starts at lo
    int right;      ///< true sign of p just above the band; 0 if the band ends at hi
};

struct RefRoot {
    double t;
    bool well;  ///< alone in a band narrower than 1e-12 relative
};

struct Case {
    std::string name;
    Poly4 c{};
    double lo = 0, hi = 0;
    std::vector<RefRoot> roots;
    std::vector<Band> bands;
    std::optional<double> first;
};

double number_or_inf(const nlohmann::json& j) {
    return j.is_string() ? (j.get<std::string>() == "inf" ? kInf : -kInf) : j.get<double>();
}

std::vector<Case> load_cases() {
    std::ifstream in(std::string(COOLAABER_TEST_DATA) + "/roots_reference.json");
    if (!in) {
        ADD_FAILURE() << "Cannot open roots_reference.json in " << COOLAABER_TEST_DATA
                      << ": run tools/make_roots_reference.py";
        return {};
    }
    const auto doc = nlohmann::json::parse(in);
    std::vector<Case> cases;
    for (const auto& j : doc.at("cases")) {
        Case k;
        k.name = j.at("name").get<std::string>();
        for (int i = 0; i < 5; ++i) k.c[i] = j.at("c").at(i).get<double>();
        k.lo = number_or_inf(j.at("lo"));
        k.hi = number_or_inf(j.at("hi"));
        for (const auto& r : j.at("roots")) k.roots.push_back({r.at("t"), r.at("well")});
        for (const auto& b : j.at("bands")) {
            k.bands.push_back({b.at("lo"), b.at("hi"), b.at("roots"), b.at("left"), b.at("right")});
        }
        if (!j.at("first").is_null()) k.first = j.at("first").get<double>();
        cases.push_back(std::move(k));
    }
    return cases;
}

const std::vector<Case>& reference_cases() {
    static const std::vector<Case> cases = load_cases();
    return cases;
}

// ------------------------------------------------------------------ exact-enough residuals

// Double-double arithmetic (Dekker 1971; no FMA, the build forbids contraction): p(t) to
// about 2^-104 relative to Σ|c_i||t|^i, far below the tolerance it checks.
struct DoubleDouble {
    double hi, lo;
};

DoubleDouble two_sum(double a, double b) {
    const double s = a + b, bb = s - a;
    return {s, (a - (s - bb)) + (b - bb)};
}

DoubleDouble two_product(double a, double b) {
    auto split = [](double x) {
        const double c = 134217729.0 * x;  // 2^27 + 1
        const double h = c - (c - x);
        return DoubleDouble{h, x - h};
    };
    const double p = a * b;
    const DoubleDouble sa = split(a), sb = split(b);
    return {p, ((sa.hi * sb.hi - p) + sa.hi * sb.lo + sa.lo * sb.hi) + sa.lo * sb.lo};
}

double accurate_value(const Poly4& c, double t) {
    DoubleDouble f{c[4], 0.0};
    for (int i = 3; i >= 0; --i) {
        DoubleDouble p = two_product(f.hi, t);
        p.lo += f.lo * t;
        DoubleDouble s = two_sum(p.hi, c[i]);
        s.lo += p.lo;
        f = two_sum(s.hi, s.lo);
    }
    return f.hi + f.lo;
}

/// The noise level of Horner's rule at t: below it the computed sign of p means nothing.
double noise(const Poly4& c, double t) {
    double s = 0.0;
    for (int i = 4; i >= 0; --i) s = s * std::fabs(t) + std::fabs(c[i]);
    return kNoiseUlps * kEps * s;
}

::testing::AssertionResult residual_within_noise(const Poly4& c, double t) {
    const double r = std::fabs(accurate_value(c, t)), eta = noise(c, t);
    if (r <= eta) return ::testing::AssertionSuccess();
    return ::testing::AssertionFailure()
           << "|p(" << t << ")| = " << r << " exceeds the noise level " << eta << " ("
           << r / (kEps * eta / kNoiseUlps) << " ulps of sum |c_i t^i|)";
}

const Band* band_holding(const Case& k, double t) {
    for (const Band& b : k.bands) {
        if (t >= b.lo && t <= b.hi) return &b;
    }
    return nullptr;
}

bool close(double t, double r) {
    return std::fabs(t - r) <= kWellTolerance * std::fabs(r);
}

std::string describe(const Case& k) {
    std::ostringstream s;
    s.precision(17);
    s << k.name << ": c = {" << k.c[0] << ", " << k.c[1] << ", " << k.c[2] << ", " << k.c[3] << ", "
      << k.c[4] << "} on [" << k.lo << ", " << k.hi << "]";
    return s.str();
}

// ------------------------------------------------------------------ reference tests

TEST(RootsReference, DataIsPresent) {
    EXPECT_GE(reference_cases().size(), 200u);
}

TEST(RootsReference, SignChangeRootsMatchTheTruth) {
    for (const Case& k : reference_cases()) {
        SCOPED_TRACE(describe(k));
        std::array<double, 4> out{};
        const int n = sign_change_roots(k.c, k.lo, k.hi, out);
        ASSERT_GE(n, 0);
        ASSERT_LE(n, 4);
        for (int i = 0; i < n; ++i) {
            EXPECT_GE(out[i], k.lo);
            EXPECT_LE(out[i], k.hi);
            if (i > 0) {
                EXPECT_LE(out[i - 1], out[i]) << "roots not ascending";
            }
            EXPECT_TRUE(residual_within_noise(k.c, out[i]));
            EXPECT_NE(band_holding(k, out[i]), nullptr) << "root " << out[i] << " is spurious";
        }
        for (const Band& b : k.bands) {
            int found = 0;
            for (int i = 0; i < n; ++i) found += out[i] >= b.lo && out[i] <= b.hi;
            const bool at_end = b.left == 0 || b.right == 0;  // the sign at lo/hi is noise
            if (b.roots == 1 && !at_end) {
                EXPECT_EQ(found, 1) << "band [" << b.lo << ", " << b.hi << "] holds one root";
            } else if (!at_end) {
                EXPECT_EQ(found % 2, b.roots % 2)
                    << "band [" << b.lo << ", " << b.hi << "] holds " << b.roots << " roots";
            } else {
                EXPECT_LE(std::abs(found - b.roots), 1)
                    << "band [" << b.lo << ", " << b.hi << "] holds " << b.roots << " roots";
            }
        }
        for (const RefRoot& r : k.roots) {
            if (!r.well) continue;
            bool matched = false;
            for (int i = 0; i < n; ++i) matched = matched || close(out[i], r.t);
            EXPECT_TRUE(matched) << "well-conditioned root " << r.t << " not found to "
                                 << kWellTolerance << " relative";
        }
    }
}

/// What first_downward_crossing may answer. Outside the bands the sign of p is certain, so
/// the first band entered from above and left below must be caught; before it, a band may
/// catch the answer only if the computed signs there can go from + to −.
TEST(RootsReference, FirstDownwardCrossingMatchesTheTruth) {
    for (const Case& k : reference_cases()) {
        SCOPED_TRACE(describe(k));
        const double t = first_downward_crossing(k.c, k.lo, k.hi);
        const Band* must = nullptr;
        for (const Band& b : k.bands) {
            if (b.left > 0 && b.right < 0) {
                must = &b;
                break;
            }
        }
        if (std::isinf(t)) {
            EXPECT_GT(t, 0.0);
            EXPECT_EQ(must, nullptr)
                << "missed the crossing in [" << must->lo << ", " << must->hi << "]";
            continue;
        }
        EXPECT_GT(t, k.lo);
        EXPECT_LE(t, k.hi);
        EXPECT_TRUE(residual_within_noise(k.c, t));
        const Band* at = band_holding(k, t);
        ASSERT_NE(at, nullptr) << "crossing " << t << " is spurious";
        if (must != nullptr) {
            EXPECT_LE(at->lo, must->lo) << "crossing " << t << " is too late";
        }
        const bool can_go_down = at->left >= 0 || at->roots != 1;
        EXPECT_TRUE(can_go_down) << "crossing " << t << " is an upward one";
        if (k.first && at == must && must->roots == 1) {
            for (const RefRoot& r : k.roots) {
                if (r.t == *k.first && r.well) {
                    EXPECT_TRUE(close(t, r.t)) << t << " vs " << r.t;
                }
            }
        }
    }
}

// ------------------------------------------------------------------ contract tests

/// (t − a)(t − b)(t − c)(t − d) scaled by s; dyadic roots give exact coefficients.
Poly4 from_roots(double a, double b, double c, double d, double s = 1.0) {
    return {s * a * b * c * d, -s * (a * b * c + a * b * d + a * c * d + b * c * d),
            s * (a * b + a * c + a * d + b * c + b * d + c * d), -s * (a + b + c + d), s};
}

/// Dyadic roots of these small polynomials are well conditioned, but not to the last ulp: the
/// rounding of p near t = 2 is ~1e-14 while |p'(2)| ~ 1, so the computed sign of p is only
/// certain a few ulps away. Hence the 1e-12 relative tolerance, as for the reference data.
::testing::AssertionResult is_root(double t, double r) {
    if (close(t, r)) return ::testing::AssertionSuccess();
    return ::testing::AssertionFailure() << std::setprecision(17) << t << " is not the root " << r
                                         << " to " << kWellTolerance << " relative";
}

TEST(RootsFirstDownwardCrossing, FindsTheEarliestOfSeveral) {
    const Poly4 p = from_roots(0.5, 1.0, 2.0, 3.0);  // + on [0, 0.5): down at 0.5 and at 2
    EXPECT_TRUE(is_root(first_downward_crossing(p, 0.0, 5.0), 0.5));
    EXPECT_TRUE(is_root(first_downward_crossing(p, 0.75, 5.0), 2.0));
}

TEST(RootsFirstDownwardCrossing, IgnoresUpwardCrossings) {
    EXPECT_EQ(first_downward_crossing({-1.0, 1.0, 0, 0, 0}, 0.0, 2.0), kInf);  // t − 1
    const Poly4 p = from_roots(1.0, 2.0, 3.0, 4.0, -1.0);  // − on [0, 1): up at 1, down at 2
    EXPECT_TRUE(is_root(first_downward_crossing(p, 0.0, 5.0), 2.0));
}

TEST(RootsFirstDownwardCrossing, IgnoresTangentTouches) {
    const Poly4 touch_then_cross = from_roots(0.5, 0.5, 2.0, 3.0);  // ≥ 0 near 0.5
    EXPECT_TRUE(is_root(first_downward_crossing(touch_then_cross, 0.0, 5.0), 2.0));
    const Poly4 only_touches = from_roots(0.5, 0.5, 1.5, 1.5);
    EXPECT_EQ(first_downward_crossing(only_touches, 0.0, 5.0), kInf);
    EXPECT_EQ(first_downward_crossing({2.25, -6.0, 4.0, 0, 0}, 0.0, 5.0), kInf);  // (2t − 1.5)²
}

TEST(RootsFirstDownwardCrossing, ReturnsInfinityWhenNone) {
    EXPECT_EQ(first_downward_crossing({1.0, 0.0, 1.0, 0.0, 0.0}, 0.0, 10.0), kInf);  // t² + 1
    EXPECT_EQ(first_downward_crossing({1.0, 0, 0, 0, 0}, 0.0, 10.0), kInf);          // constant
    EXPECT_EQ(first_downward_crossing({0.0, 0, 0, 0, 0}, 0.0, 10.0), kInf);          // zero
    EXPECT_EQ(first_downward_crossing({-1.0, 0, 0, 0, 0}, 0.0, 10.0), kInf);         // negative
    EXPECT_EQ(first_downward_crossing({1.0, -1.0, 0, 0, 0}, 0.0, 0.5), kInf);  // root beyond hi
}

TEST(RootsFirstDownwardCrossing, IntervalIsOpenAtLoAndClosedAtHi) {
    const Poly4 p = from_roots(0.5, 1.25, 2.0, 3.0);
    EXPECT_TRUE(is_root(first_downward_crossing(p, 0.5, 2.5), 2.0))
        << "a root at lo is not in (lo, hi]";
    EXPECT_EQ(first_downward_crossing(p, 0.0, 0.5), 0.5) << "a root at hi is";
    EXPECT_EQ(first_downward_crossing(from_roots(0.5, 0.5, 2.0, 3.0), 0.0, 0.5), 0.5)
        << "p(hi) = 0 after p > 0 ends the interval as a crossing";
    EXPECT_EQ(first_downward_crossing(p, 1.0, 1.0), kInf) << "empty interval";
    EXPECT_EQ(first_downward_crossing(p, 2.0, 1.0), kInf) << "reversed interval";
}

TEST(RootsFirstDownwardCrossing, AcceptsAnInfiniteHorizon) {
    EXPECT_TRUE(is_root(first_downward_crossing({1.0, -0.5, 0, 0, 0}, 0.0, kInf), 2.0));
    EXPECT_EQ(first_downward_crossing({1.0, 0.5, 0, 0, 0}, 0.0, kInf), kInf);
    const double t = first_downward_crossing({1.0, -3.0, 2.0, 0.0, -1e-20}, 1.5, kInf);
    EXPECT_TRUE(residual_within_noise({1.0, -3.0, 2.0, 0.0, -1e-20}, t));
    EXPECT_NEAR(t, std::sqrt(2e20), 1e-6 * std::sqrt(2e20));  // where the t⁴ term wins
}

TEST(RootsFirstDownwardCrossing, TinyLeadingCoefficientChangesNothingNearby) {
    const Poly4 quadratic{1.0, -3.0, 2.0, 0.0, 0.0};  // roots 0.5, 1
    for (double tiny : {1e-20, -1e-20, 1e-300, 5e-324}) {
        Poly4 q = quadratic;
        q[4] = tiny;
        EXPECT_TRUE(is_root(first_downward_crossing(q, 0.0, 10.0), 0.5)) << tiny;
        q[4] = 0.0;
        q[3] = tiny;
        EXPECT_TRUE(is_root(first_downward_crossing(q, 0.0, 10.0), 0.5)) << tiny;
    }
}

TEST(RootsFirstDownwardCrossing, TripleRootIsACrossing) {
    const Poly4 p = from_roots(1.5, 1.5, 1.5, 3.0);  // + before 1.5, − after
    const double t = first_downward_crossing(p, 0.0, 2.0);
    EXPECT_TRUE(residual_within_noise(p, t));
    EXPECT_NEAR(t, 1.5, 1e-5);
}

TEST(RootsSignChangeRoots, ReturnsAllSignChangesAscending) {
    std::array<double, 4> out{};
    ASSERT_EQ(sign_change_roots(from_roots(3.0, 0.5, 2.0, 1.0), 0.0, 5.0, out), 4);
    EXPECT_TRUE(is_root(out[0], 0.5));
    EXPECT_TRUE(is_root(out[1], 1.0));
    EXPECT_TRUE(is_root(out[2], 2.0));
    EXPECT_TRUE(is_root(out[3], 3.0));
    ASSERT_EQ(sign_change_roots(from_roots(3.0, 0.5, 2.0, 1.0), 0.75, 2.5, out), 2);
    EXPECT_TRUE(is_root(out[0], 1.0));
    EXPECT_TRUE(is_root(out[1], 2.0));
}

TEST(RootsSignChangeRoots, SkipsEvenMultiplicities) {
    std::array<double, 4> out{};
    ASSERT_EQ(sign_change_roots(from_roots(0.5, 0.5, 2.0, 3.0), 0.0, 5.0, out), 2);
    EXPECT_TRUE(is_root(out[0], 2.0));
    EXPECT_TRUE(is_root(out[1], 3.0));
    EXPECT_EQ(sign_change_roots(from_roots(0.75, 0.75, 0.75, 0.75), 0.0, 5.0, out), 0);
}

TEST(RootsSignChangeRoots, IncludesOddRootsAtTheEnds) {
    std::array<double, 4> out{};
    const Poly4 p = from_roots(0.5, 1.25, 2.0, 3.0);
    ASSERT_EQ(sign_change_roots(p, 1.25, 3.0, out), 3);
    EXPECT_EQ(out[0], 1.25);
    EXPECT_TRUE(is_root(out[1], 2.0));
    EXPECT_EQ(out[2], 3.0);
    ASSERT_EQ(sign_change_roots(p, 1.25, 1.25, out), 1);
    EXPECT_EQ(out[0], 1.25);
    EXPECT_EQ(sign_change_roots(from_roots(0.5, 0.5, 2.0, 3.0), 0.5, 1.0, out), 0)
        << "a double root at lo is no sign change";
}

TEST(RootsSignChangeRoots, DegenerateDegrees) {
    std::array<double, 4> out{};
    EXPECT_EQ(sign_change_roots({0, 0, 0, 0, 0}, 0.0, 1.0, out), 0);
    EXPECT_EQ(sign_change_roots({3, 0, 0, 0, 0}, 0.0, 1.0, out), 0);
    ASSERT_EQ(sign_change_roots({1.0, -4.0, 0, 0, 0}, 0.0, 1.0, out), 1);
    EXPECT_TRUE(is_root(out[0], 0.25));
    ASSERT_EQ(sign_change_roots({0.0, 0.0, 0.0, -1.0, 1.0}, -1.0, 2.0, out), 2);  // t³(t − 1)
    EXPECT_EQ(out[0], 0.0) << "p(0) = 0 exactly";
    EXPECT_TRUE(is_root(out[1], 1.0));
}

// ------------------------------------------------------------------ property tests

using test::SplitMix64;

/// The sign of p at t where it is certain (|p| above the noise level), else 0.
int clear_sign(const Poly4& c, double t) {
    const double v = accurate_value(c, t), eta = noise(c, t);
    return v > eta ? 1 : (v < -eta ? -1 : 0);
}

/// Two balls (radius 0.028575 m) moving on quadratic paths: random speeds up to 12 m/s, sliding
/// (2 m/s², along a random slip direction) or rolling (0.1 m/s², against the velocity), aimed
/// roughly at each other so that about half collide, some of them grazing.
TEST(RootsProperty, ContactQuarticsHaveNoMissedEarlierCrossing) {
    constexpr int kGrid = 256;
    SplitMix64 rng{20240611};
    int collisions = 0;
    for (int k = 0; k < 4000; ++k) {
        const auto [c, hi] = test::random_contact_quartic(rng, k, test::kDiameter);
        SCOPED_TRACE(::testing::Message() << "case " << k);
        const double t = first_downward_crossing(c, 0.0, hi);
        int last_clear = clear_sign(c, 0.0);
        for (int j = 1; j <= kGrid; ++j) {
            const double s = hi * j / kGrid;
            if (s >= t) break;
            const int sign = clear_sign(c, s);
            ASSERT_FALSE(last_clear > 0 && sign < 0)
                << "missed a crossing before " << s << " (returned " << t << ")";
            if (sign != 0) last_clear = sign;
        }
        if (std::isfinite(t)) {
            ++collisions;
            EXPECT_TRUE(residual_within_noise(c, t));
        }
    }
    EXPECT_GT(collisions, 500);  // the generator does make contacts
}

TEST(RootsEval, IsHorner) {
    const Poly4 p{1.0, -2.0, 3.0, -4.0, 5.0};
    EXPECT_EQ(eval(p, 2.0), 1.0 - 4.0 + 12.0 - 32.0 + 80.0);
    EXPECT_EQ(eval(p, 0.0), 1.0);
}

}  // namespace
}  // namespace physics::roots
