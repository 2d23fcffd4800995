// Tests of the quartic fast path of first_downward_crossing (src/physics/roots_convex_pieces):
// where it answers, it agrees with the general isolation (the walk behind sign_change_roots),
// its roots are correctly rounded where they are well conditioned (the last step uses the
// compensated value of p), and it leaves to the walk what it must (touching starts, an infinite
// horizon). The public contract is tested in roots_test.cpp, through first_downward_crossing.
#include "physics/internal/roots_convex_pieces.hpp"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstdint>
#include <fstream>
#include <limits>
#include <nlohmann/json.hpp>
#include <string>

#include "contact_quartics.hpp"
#include "physics/internal/roots.hpp"

namespace physics::roots {
namespace {

using convex_pieces::Outcome;
using test::kDiameter;
using test::SplitMix64;

constexpr double kInf = std::numeric_limits<double>::infinity();

double number_or_inf(const nlohmann::json& j) {
    return j.is_string() ? (j.get<std::string>() == "inf" ? kInf : -kInf) : j.get<double>();
}

/// Distance in ulps of b from a (a finite, nonzero).
double ulps(double a, double b) {
    return std::fabs(a - b) / (std::nextafter(std::fabs(a), kInf) - std::fabs(a));
}

TEST(RootsConvexPieces, WellConditionedRootsAreCorrectlyRounded) {
    std::ifstream in(std::string(COOLAABER_TEST_DATA) + "/roots_reference.json");
    ASSERT_TRUE(in) << "roots_reference.json missing";
    const auto doc = nlohmann::json::parse(in);
    int checked = 0;
    for (const auto& j : doc.at("cases")) {
        Poly4 c{};
        for (int i = 0; i < 5; ++i) c[i] = j.at("c").at(i).get<double>();
        const double lo = number_or_inf(j.at("lo")), hi = number_or_inf(j.at("hi"));
        if (c[4] == 0.0 || !(hi > lo) || j.at("first").is_null()) continue;
        const double first = j.at("first").get<double>();
        bool well = false;
        for (const auto& r : j.at("roots")) well = well || (r.at("t") == first && r.at("well"));
        const convex_pieces::Answer a = convex_pieces::first_downward_crossing(c, lo, hi);
        if (!well || a.outcome != Outcome::root || first == 0.0) continue;
        SCOPED_TRACE(j.at("name").get<std::string>());
        // The reference is the true root rounded to a double: half an ulp from the truth; the
        // last step adds at most about another half.
        EXPECT_LE(ulps(first, a.t), 1.0) << a.t << " vs " << first;
        ++checked;
    }
    EXPECT_GE(checked, 40);  // the fast path does answer most well-conditioned cases
}

/// Random two-ball contact quartics (contact_quartics.hpp; another seed than roots_test.cpp,
/// and every fifth grazing by 1e-3 to 1e-9 of the diameter): where the fast path answers, the
/// walk (sign_change_roots) finds the same: no sign change for `none`, else its first sign
/// change (a downward one, as p(0) > 0) at the same root up to the noise of its plain
/// evaluation.
TEST(RootsConvexPieces, AgreesWithTheWalk) {
    SplitMix64 rng{77031};
    int answered = 0, hits = 0;
    for (int k = 0; k < 20000; ++k) {
        const auto [c, hi] = test::random_contact_quartic(rng, k, kDiameter * 1.001, 5);
        const convex_pieces::Answer a = convex_pieces::first_downward_crossing(c, 0.0, hi);
        if (a.outcome == Outcome::unsure) continue;
        ++answered;
        SCOPED_TRACE(::testing::Message() << "case " << k);
        std::array<double, 4> out{};
        const int n = sign_change_roots(c, 0.0, hi, out);
        if (a.outcome == Outcome::none) {
            EXPECT_EQ(n, 0) << "the walk finds a crossing at " << out[0];
            continue;
        }
        ++hits;
        ASSERT_GE(n, 1) << "the walk finds no crossing; the fast path " << a.t;
        double size = 0.0;
        for (int i = 4; i >= 0; --i) size = size * std::fabs(a.t) + std::fabs(c[i]);
        const double slope = std::fabs(c[1] + a.t * (2 * c[2] + a.t * (3 * c[3] + a.t * 4 * c[4])));
        const double noise = 16.0 * std::numeric_limits<double>::epsilon() * size / slope;
        EXPECT_NEAR(a.t, out[0], 1e-13 * a.t + noise);
    }
    EXPECT_GT(answered, 15000);
    EXPECT_GT(hits, 4000);
}

TEST(RootsConvexPieces, LeavesTouchingStartsAndEndlessHorizonsToTheWalk) {
    // p(0) ≤ 0: overlapping by rounding, or exactly touching: the walk's conventions decide.
    EXPECT_EQ(
        convex_pieces::first_downward_crossing({-1e-18, -1.0, 4.0, 0.5, 1.0}, 0.0, 2.0).outcome,
        Outcome::unsure);
    EXPECT_EQ(convex_pieces::first_downward_crossing({0.0, -1.0, 4.0, 0.5, 1.0}, 0.0, 2.0).outcome,
              Outcome::unsure);
    EXPECT_EQ(
        convex_pieces::first_downward_crossing({1.0, -3.0, 2.0, 0.0, 1e-20}, 0.0, kInf).outcome,
        Outcome::unsure);
    // An exact double root (a touch) is not decided by signs that are all noise there.
    const Poly4 touch{0.25, -1.0, 1.25, -1.0, 1.0};  // (t − 1/2)²·(t² + 1)
    const convex_pieces::Answer a = convex_pieces::first_downward_crossing(touch, 0.0, 2.0);
    EXPECT_NE(a.outcome, Outcome::root);
}

}  // namespace
}  // namespace physics::roots
