// Quasi-random normal deviates for the AI's noise draws (evaluate.hpp's noise_draws): a Halton
// sequence (one prime base per component), shifted by a seeded uniform per component
// (Cranley–Patterson rotation), mapped through the standard normal quantile. Any run of the
// first n points covers each component's distribution evenly (its empirical CDF is within about
// log(n)/n of the normal's, where n pseudo-random draws stray by about 1/√n), so a stroke whose
// success region happens to hold more of a few draws than its share gains less by it: the
// search over many strokes on the same draws overfits them less. quasi_random_test.cpp.
#pragma once

#include <cstdint>

#include "ai/internal/private.hpp"

namespace ai {

/// The radical inverse of `i` in `base` (≥ 2): its base-`base` digits mirrored about the point,
/// in [0, 1) (the van der Corput sequence of that base).
double radical_inverse(std::uint64_t i, std::uint64_t base);

/// The standard normal quantile Φ⁻¹(u) for u in (0, 1) (u is clamped to [1e-12, 1 − 1e-12]);
/// accurate to about 1e-12.
double normal_quantile(double u);

}  // namespace ai
