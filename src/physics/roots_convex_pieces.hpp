// The fast path of roots::first_downward_crossing for a quartic: the interval is cut at the
// inflection points (roots of p'', a quadratic, in closed form) into pieces on which p is convex
// or concave, and each piece is decided without the roots of p'. Used by roots.cpp only.
#pragma once

#include "physics/roots.hpp"

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
Answer first_downward_crossing(const Poly4& c, double lo, double hi);

}  // namespace physics::roots::convex_pieces
