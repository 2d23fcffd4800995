// The first downward crossing of a quartic by its pieces of constant convexity.
//
// The roots of p'' (a quadratic: closed form) cut [lo, hi] into at most three pieces, on each of
// which p is convex or concave (they alternate). Going right from p(lo) > 0, with p > 0 shown up
// to the start x of each piece:
//  - concave piece [x, e]: p's minimum there is at an end, so it holds a crossing iff p(e) < 0,
//    and then exactly one;
//  - convex piece: p falls to its minimum m (where p' = 0, or e) and rises again, so it holds a
//    crossing iff p(m) < 0, and the crossing lies left of any point y with p(y) < 0. m is found
//    by Newton's iteration on p' (started from the root of p'’s Taylor parabola at x), until an
//    iterate y has p(y) < 0 (then [x, y] holds the crossing as its one sign change), or a
//    rigorous lower bound on p(m) from an iterate near m is positive (no crossing).
// The crossing is then refined by Halley's iteration in its bracket, the last step (Chebyshev's,
// of the same order) with the compensated value of p (the compensated Horner scheme of Graillat,
// Langlois, Louvet 2005), so a root is right to about an ulp even where the plain value of p is
// rounding noise. A contact quartic's usual hit is decided before the pieces are computed: the
// first piece's first point (or, at a grazing contact, its second) is sampled, and if p < 0
// there and p'' > 0 up to it, that bracket is refined at once, as the pieces would have it.
//
// Anything else — p(lo) ≤ 0 (touching bodies: the walk's conventions apply), a value that is 0
// or in the noise band where its sign is needed (a touch, a near-double root closer than the
// noise), an overflow, no decision after kMaxSteps — is answered `unsure`, and roots.cpp falls
// back to the general isolation (Collins–Loos), which handles every case. So this path takes
// only the cases whose signs are certain: a clean hit, a miss, a grazing hit whose dip is deeper
// than the rounding noise, a quadratic in disguise.
//
// Cost: about six evaluations of p and its derivatives and two square roots for a hit, instead
// of the roots of the cubic p' (each by its own Newton iteration) and two Taylor start points.
//
// The plain evaluation is Estrin's form, as in roots.cpp; no allocation, and no FMA but one, in
// the build for CPUs that have it: the exact error of a product in the compensated value, the
// same double as Dekker's TwoProduct gives without it (below). Same input, same bits, on any
// x86-64.
#include "physics/internal/roots_convex_pieces.hpp"

#include <cmath>
#include <limits>

// The fast path is built twice: for any x86-64 (SSE2), and for CPUs with FMA (and the AVX it
// implies), where the exact error of each product in the compensated value is one fused
// multiply-add, fma(s, t, −s·t), instead of Dekker's TwoProduct (two splits, four products,
// four sums). Both are the exact error, the same double, wherever Dekker's is exact, and the FMA
// build falls back to Dekker's wherever that is not shown (fused_value), so the two builds give
// the same bits everywhere. The choice is made once per process from the CPU's features. Only
// GCC on x86-64 gets the second build (the per-function target is GCC's); elsewhere the first
// is the only one. -ffp-contract=off holds in both: no other product is fused.
// (-DCOOLAABER_FUSED_PRODUCT=0 leaves it out, to compare the other build's results.)
#ifndef COOLAABER_FUSED_PRODUCT
#if defined(__GNUC__) && !defined(__clang__) && defined(__x86_64__)
#define COOLAABER_FUSED_PRODUCT 1
#else
#define COOLAABER_FUSED_PRODUCT 0
#endif
#endif

namespace physics::roots::convex_pieces {

namespace {

/// x = h + l exactly, each of 26 bits (Dekker 1971, without FMA: the build forbids contraction).
struct Split {
    double h, l;
};
Split split(double x) {
    const double c = 134217729.0 * x;  // 2^27 + 1
    const double h = c - (c - x);
    return {h, x - h};
}

/// The rounding error of a + b = sum (Knuth's TwoSum), exactly.
double sum_error(double a, double b, double sum) {
    const double z = sum - a;
    return (a - (sum - z)) + (b - z);
}

/// p(t) as accurately as if computed in twice the precision, then rounded: the compensated
/// Horner scheme of S. Graillat, Ph. Langlois, N. Louvet ("Compensated Horner scheme", 2005,
/// Algorithm 3.2): at each step s·t + c_i, the error of the product (Dekker's TwoProduct) and of
/// the sum (Knuth's TwoSum) are exact doubles, and they are summed by their own Horner
/// recurrence, added at the end. Its error is below ε·|p(t)| + γ_8²·Σ|c_i||t|^i (their
/// Theorem 3.1). Horner's order, not Estrin's: one running value and one running error keep
/// every intermediate in a register (the Estrin form needed twice as many, and spilled), and its
/// chain (a product and a sum per step, the error terms beside it) is as short. Non-finite if a
/// split overflows (|·| > 2^996).
[[gnu::always_inline]] inline double split_value(const Poly4& c, double t) {
    const Split ts = split(t);
    double s = c[4], error = 0.0;
    for (int i = 3; i >= 0; --i) {
        const double product = s * t;
        const Split ss = split(s);
        const double product_error =
            ((ss.h * ts.h - product) + ss.h * ts.l + ss.l * ts.h) + ss.l * ts.l;
        const double sum = product + c[i];
        error = (i == 3 ? 0.0 : error * t) + (product_error + sum_error(product, c[i], sum));
        s = sum;
    }
    return s + error;
}

}  // namespace

namespace split_product {
namespace {
[[gnu::always_inline]] inline double accurate_value(const Poly4& c, double t) {
    return split_value(c, t);
}
}  // namespace
#include "physics/internal/roots_convex_pieces_body.inl"
}  // namespace split_product

#if COOLAABER_FUSED_PRODUCT
namespace {

/// split_value, out of line: the fused build's fallback, kept off its hot path.
[[gnu::noinline]] double split_value_outlined(const Poly4& c, double t) {
    return split_value(c, t);
}

/// |x| within [2⁻⁴⁰⁰, 2⁴⁰⁰] (so not 0, not subnormal, not NaN or infinite).
bool moderate(double x) {
    const double a = std::fabs(x);
    return a >= 0x1p-400 && a <= 0x1p400;
}

}  // namespace

#pragma GCC push_options
#pragma GCC target("fma")
namespace fused_product {
namespace {

/// split_value's result with each product's error as fma(s, t, −s·t). Where s and t are
/// moderate (2⁻⁴⁰⁰ ≤ |·| ≤ 2⁴⁰⁰: nothing overflows in the splits, and the partial products of
/// Dekker's TwoProduct are exact, l_s·l_t ≥ 2⁻⁹⁰⁴ where nonzero), Dekker's error is exact (Dekker
/// 1971; formally proved by S. Boldo, "Pitfalls of a full floating-point proof", 2006), so it is
/// the same double as the FMA's, which is exact whenever the error is representable; where it is 0,
/// both give +0 (Dekker's first difference h_s·h_t − s·t is +0 or nonzero, and a sum in
/// round-to-nearest is −0 only of two −0s; the FMA's exact 0 is +0 likewise). Elsewhere (a 0,
/// a huge or tiny or non-finite value: never in the physics) Dekker's own result is returned,
/// so the two builds agree everywhere. The range tests are off the value's dependency chain.
[[gnu::always_inline]] inline double fused_value(const Poly4& c, double t) {
    double s = c[4], error = 0.0;
    bool all_moderate = moderate(t);
    for (int i = 3; i >= 0; --i) {
        all_moderate = all_moderate && moderate(s);
        const double product = s * t;
        const double product_error = std::fma(s, t, -product);
        const double sum = product + c[i];
        error = (i == 3 ? 0.0 : error * t) + (product_error + sum_error(product, c[i], sum));
        s = sum;
    }
    if (!all_moderate) [[unlikely]]
        return split_value_outlined(c, t);
    return s + error;
}

[[gnu::always_inline]] inline double accurate_value(const Poly4& c, double t) {
    return fused_value(c, t);
}

}  // namespace
#include "physics/internal/roots_convex_pieces_body.inl"
}  // namespace fused_product
#pragma GCC pop_options

#else  // no second build: its names call the first

namespace fused_product {
Answer first_downward_crossing(const Poly4& c, double lo, double hi) {
    return split_product::first_downward_crossing(c, lo, hi);
}
double compensated_value(const Poly4& c, double t) {
    return split_product::compensated_value(c, t);
}
}  // namespace fused_product

#endif

bool fused_product_available() {
#if COOLAABER_FUSED_PRODUCT
    // No state of the engine's: the CPU's features as libgcc's constructor recorded them (at
    // load time, before any constructor of default priority, so before any call here), a load
    // and a test per query. (AVX too: GCC's FMA target implies the VEX encoding, which needs the
    // OS to save the YMM state; libgcc reports AVX only where XGETBV says it does.)
    return __builtin_cpu_supports("avx") && __builtin_cpu_supports("fma");
#else
    return false;
#endif
}

Answer first_downward_crossing(const Poly4& c, double lo, double hi) {
    return fused_product_available() ? fused_product::first_downward_crossing(c, lo, hi)
                                     : split_product::first_downward_crossing(c, lo, hi);
}

}  // namespace physics::roots::convex_pieces
