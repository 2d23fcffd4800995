// The fast path of roots::first_downward_crossing for a quartic: the interval is cut at the
// inflection points (roots of p'', a quadratic, in closed form) into pieces on which p is convex
// or concave, and each piece is decided without the roots of p'. Used by roots.cpp only.
#pragma once

#include "physics/internal/private.hpp"
#include "physics/internal/roots.hpp"

namespace physics::roots::convex_pieces {

enum class Outcome {
    none,    ///< no downward crossing in (lo, hi]
    root,    ///< the first downward crossing is `t`
    unsure,  ///< not decided here (p(lo) ≤ 0, a value in the noise band, ...): ask the walk
};

struct Answer {
    Outcome outcome = Outcome::unsure;
    double t = 0.0;
};

/// The first downward crossing of p (degree 4: c[4] ≠ 0) in (lo, hi], for finite lo < hi, or
/// `unsure` where that needs the general isolation. Never wrong where it answers (see the .cpp).
/// Runs the FMA build where the CPU has FMA (fused_product_available()), else the other.
Answer first_downward_crossing(const Poly4& c, double lo, double hi);

/// Whether this CPU runs fused_product's build (x86-64 with AVX and FMA; GCC only).
bool fused_product_available();

/// The two builds of the fast path, bit-identical (see the .cpp), for the tests that compare
/// them: Dekker's TwoProduct in the compensated value, for any CPU; and the FMA's exact product
/// error, to be called only where fused_product_available() (elsewhere it is the first).
/// compensated_value: that build's compensated value of p(t).
namespace split_product {
Answer first_downward_crossing(const Poly4& c, double lo, double hi);
double compensated_value(const Poly4& c, double t);
}  // namespace split_product
namespace fused_product {
Answer first_downward_crossing(const Poly4& c, double lo, double hi);
double compensated_value(const Poly4& c, double t);
}  // namespace fused_product

}  // namespace physics::roots::convex_pieces
