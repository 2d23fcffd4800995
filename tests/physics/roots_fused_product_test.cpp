// The two builds of the quartic fast path (src/physics/roots_convex_pieces.cpp) give the same
// bits: the one with Dekker's TwoProduct in the compensated value (any x86-64) and the one with
// the FMA's exact product error (CPUs with FMA). Compared where this CPU runs both: on the
// reference cases, on random contact quartics (grazing ones among them), on the same scaled to
// huge and tiny magnitudes, and, for the compensated value alone, on coefficients and points of
// every magnitude and class (0, subnormal, infinite, NaN), where the FMA build must fall back.
#include <gtest/gtest.h>

#include <array>
#include <bit>
#include <cmath>
#include <cstdint>
#include <fstream>
#include <limits>
#include <nlohmann/json.hpp>
#include <string>

#include "contact_quartics.hpp"
#include "physics/internal/roots_convex_pieces.hpp"

namespace physics::roots {
namespace {

using convex_pieces::Answer;
using test::SplitMix64;

constexpr double kInf = std::numeric_limits<double>::infinity();

std::uint64_t bits(double x) {
    return std::bit_cast<std::uint64_t>(x);
}

/// Both builds' answers for p on (lo, hi]: the same outcome and the same bits of t.
void expect_same_answer(const Poly4& c, double lo, double hi) {
    const Answer split = convex_pieces::split_product::first_downward_crossing(c, lo, hi);
    const Answer fused = convex_pieces::fused_product::first_downward_crossing(c, lo, hi);
    EXPECT_EQ(split.outcome, fused.outcome);
    EXPECT_EQ(bits(split.t), bits(fused.t)) << split.t << " vs " << fused.t;
}

/// Both builds' compensated values of p(t): the same bits (NaNs included).
void expect_same_value(const Poly4& c, double t) {
    const double split = convex_pieces::split_product::compensated_value(c, t);
    const double fused = convex_pieces::fused_product::compensated_value(c, t);
    EXPECT_EQ(bits(split), bits(fused)) << split << " vs " << fused << " at t = " << t;
}

/// 64 random bits (two draws of 53).
std::uint64_t random_bits(SplitMix64& rng) {
    const auto high = static_cast<std::uint64_t>(rng.uniform(0.0, 0x1p53));
    const auto low = static_cast<std::uint64_t>(rng.uniform(0.0, 0x1p53));
    return (high << 11) ^ low;
}

/// A double of any class: a random bit pattern (every exponent, subnormals, infinities, NaNs
/// with payloads), or one of the special values.
double any_double(SplitMix64& rng) {
    static constexpr std::array<double, 8> kSpecial{0.0,
                                                    -0.0,
                                                    kInf,
                                                    -kInf,
                                                    std::numeric_limits<double>::quiet_NaN(),
                                                    std::numeric_limits<double>::denorm_min(),
                                                    0x1p-400,
                                                    0x1p400};
    const std::uint64_t r = random_bits(rng);
    if (r % 8 == 0) return kSpecial[(r >> 3) % kSpecial.size()];
    return std::bit_cast<double>(random_bits(rng));
}

/// p scaled to c_i·2^(a − b·i), whose value at t·2^b is p(t)·2^a: the same shape at every
/// magnitude, overflowing and underflowing for large |a| or |b|.
Poly4 scaled(const Poly4& c, int a, int b) {
    Poly4 s{};
    for (int i = 0; i < 5; ++i) s[i] = std::ldexp(c[i], a - b * i);
    return s;
}

class FusedProduct : public ::testing::Test {
  protected:
    void SetUp() override {
        if (!convex_pieces::fused_product_available()) {
            GTEST_SKIP() << "this CPU has no FMA: only one build runs here";
        }
    }
};

TEST_F(FusedProduct, SameBitsOnTheReferenceCases) {
    std::ifstream in(std::string(COOLAABER_TEST_DATA) + "/roots_reference.json");
    ASSERT_TRUE(in) << "roots_reference.json missing";
    const auto doc = nlohmann::json::parse(in);
    int compared = 0;
    for (const auto& j : doc.at("cases")) {
        Poly4 c{};
        for (int i = 0; i < 5; ++i) c[i] = j.at("c").at(i).get<double>();
        if (c[4] == 0.0 || !j.at("lo").is_number() || !j.at("hi").is_number()) continue;
        const double lo = j.at("lo").get<double>(), hi = j.at("hi").get<double>();
        if (!(hi > lo)) continue;
        SCOPED_TRACE(j.at("name").get<std::string>());
        expect_same_answer(c, lo, hi);
        for (int k = 0; k <= 64; ++k) expect_same_value(c, lo + (hi - lo) * k / 64.0);
        for (const auto& r : j.at("roots")) expect_same_value(c, r.at("t").get<double>());
        ++compared;
    }
    EXPECT_GE(compared, 100);
}

/// Random contact quartics, every fifth grazing (1e-3 to 1e-9 of the diameter), each also
/// scaled to magnitudes from 2⁻¹¹⁰⁰ to 2¹¹⁰⁰ (value and time), and their compensated values at
/// the root found and near it.
TEST_F(FusedProduct, SameBitsOnRandomContactQuartics) {
    SplitMix64 rng{90210};
    int roots = 0;
    for (int k = 0; k < 100000; ++k) {
        const auto [c, hi] = test::random_contact_quartic(rng, k, test::kDiameter * 1.001, 5);
        SCOPED_TRACE(::testing::Message() << "case " << k);
        expect_same_answer(c, 0.0, hi);
        const Answer a = convex_pieces::split_product::first_downward_crossing(c, 0.0, hi);
        if (a.outcome == convex_pieces::Outcome::root) {
            ++roots;
            expect_same_value(c, a.t);
            expect_same_value(c, std::nextafter(a.t, kInf));
        }
        if (k % 10 == 0) {
            const int value_scale = static_cast<int>(rng.uniform(-1100.0, 1100.0));
            const int time_scale = static_cast<int>(rng.uniform(-300.0, 300.0));
            const Poly4 s = scaled(c, value_scale, time_scale);
            const double s_hi = std::ldexp(hi, time_scale);
            expect_same_answer(s, 0.0, s_hi);
            expect_same_value(s, std::ldexp(a.t, time_scale));
            expect_same_value(s, std::ldexp(rng.uniform(0.0, hi), time_scale));
        }
        if (::testing::Test::HasFailure()) return;
    }
    EXPECT_GT(roots, 20000);
}

/// The compensated value at the edges of the range where the FMA build trusts its products
/// (2⁻⁴⁰⁰ ≤ |s|, |t| ≤ 2⁴⁰⁰), where a Horner value cancels to 0 exactly, and of coefficients
/// and points of every class and magnitude.
TEST_F(FusedProduct, SameBitsForValuesOfEveryMagnitude) {
    for (const double edge : {0x1p-400, 0x1p400}) {
        for (const double t : {edge, std::nextafter(edge, 0.0), std::nextafter(edge, kInf)}) {
            expect_same_value({1.0, -3.0, 0.5, 2.0, 1.0 + 0x1p-52}, t);
            expect_same_value({0.0, 0.0, 0.0, 0.0, 1.0 + 0x1p-52}, t);
            expect_same_value({1.0, -3.0, 0.5, 2.0, t}, 1.0 + 0x1p-52);
            expect_same_value({1.0, -3.0, 0.5, -t * (1.0 + 0x1p-52), t}, 1.0 + 0x1p-52);
        }
    }
    // (t − 1)·(…) with s cancelling to exactly ±0 on the way, at t = 1 and just beside it.
    for (const double t : {1.0, std::nextafter(1.0, 0.0), std::nextafter(1.0, 2.0), -1.0}) {
        expect_same_value({-1.0, 1.0, -1.0, -1.0, 1.0}, t);
        expect_same_value({1.0, -1.0, 1.0, -1.0, 1.0}, t);
        expect_same_value({-0.0, -0.0, -0.0, -1.0, 1.0}, t);
    }
    SplitMix64 rng{4242};
    for (int k = 0; k < 200000; ++k) {
        Poly4 c{};
        for (double& ci : c) ci = any_double(rng);
        const double t = any_double(rng);
        SCOPED_TRACE(::testing::Message() << "case " << k);
        expect_same_value(c, t);
        if (k % 4 == 0 && c[4] != 0.0 && std::isfinite(t)) {
            expect_same_answer(c, 0.0, std::fabs(t));
        }
        if (::testing::Test::HasFailure()) return;
    }
    // Moderate magnitudes, where the FMA build does not fall back: random mantissas and signs,
    // exponents spread over ±200 (so products and sums meet every alignment).
    for (int k = 0; k < 200000; ++k) {
        Poly4 c{};
        for (double& ci : c)
            ci = std::ldexp(rng.uniform(-1.0, 1.0), static_cast<int>(rng.uniform(-200.0, 200.0)));
        const double t =
            std::ldexp(rng.uniform(-1.0, 1.0), static_cast<int>(rng.uniform(-100.0, 100.0)));
        SCOPED_TRACE(::testing::Message() << "moderate case " << k);
        expect_same_value(c, t);
        if (::testing::Test::HasFailure()) return;
    }
}

}  // namespace
}  // namespace physics::roots
