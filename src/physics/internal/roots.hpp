// Real roots of polynomials of degree ≤ 4 on an interval, robust to degenerate and
// near-double roots: the roots of the derivative split the interval into monotone pieces, and
// each piece with a sign change is solved by safeguarded Newton iteration.
#pragma once

#include <array>

#include "physics/internal/private.hpp"

namespace physics::roots {

/// Coefficients of p(t) = c[0] + c[1]·t + c[2]·t² + c[3]·t³ + c[4]·t⁴ (unused ones zero).
using Poly4 = std::array<double, 5>;

/// Value of p at t (Horner).
double eval(const Poly4& c, double t);

/// The smallest t in (lo, hi] at which p crosses from positive to non-positive: p > 0 just
/// before t, p(t) ≈ 0 and p < 0 just after (or t == hi and p(hi) ≤ 0). Roots of even
/// multiplicity (p touches 0 without changing sign) are not crossings. Returns +infinity if
/// there is none. Works for any degree ≤ 4, including zero or tiny leading coefficients.
double first_downward_crossing(const Poly4& c, double lo, double hi);

/// All roots of odd multiplicity (sign changes) of p in [lo, hi], ascending; returns the count.
int sign_change_roots(const Poly4& c, double lo, double hi, std::array<double, 4>& out);

}  // namespace physics::roots
