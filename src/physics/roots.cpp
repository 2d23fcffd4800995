// Real roots of polynomials of degree ≤ 4 on an interval.
//
// Method: recursive derivative isolation with safeguarded Newton iteration, after
//   G. E. Collins and R. Loos, "Polynomial real root isolation by differentiation",
//   Proc. SYMSAC '76, pp. 15–25 (the roots of p' split the line into pieces on which p is
//   monotone, so each piece holds at most one root), and
//   C. Yuksel, "High-Performance Polynomial Root Finding for Graphics", Proc. ACM Comput.
//   Graph. Interact. Tech. 5(3), 2022 (the same isolation done numerically, each monotone
//   piece solved by Newton's method with a bisection fallback),
// with a safeguard in the manner of "rtsafe" (Press et al., Numerical Recipes, 3rd ed., §9.4):
// a Newton step that leaves the bracket, or is not at most half the previous step, is replaced
// by a bisection.
//
// Why this method: the contact polynomials of the physics are often degenerate (a stationary
// pair is a constant, motion parallel to a rail loses the leading terms, a grazing contact is a
// near-double root). Closed forms (Ferrari, Cardano) divide by the leading coefficient and lose
// all accuracy there; isolation never does (the only division by a leading coefficient is the
// root of a linear derivative, whose result is only compared with the interval). Every decision
// ("is there a root in this piece?") is made from the sign of p evaluated at a point, so the
// answers are consistent with p itself: a root is reported exactly where the computed p changes
// sign, and a double root (p touches 0 without changing sign) is not reported.
#include "physics/roots.hpp"

#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>

namespace physics::roots {

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr double kEps = std::numeric_limits<double>::epsilon();
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

/// Newton stops once a step is below this many units of |x|·ε: the next step would be far
/// below an ulp while convergence is quadratic.
constexpr double kStepUlps = 2.0;
/// Guard on the iteration count. Bisection halves the bracket in the ordering of doubles, so
/// 64 bisections reach adjacent doubles; Newton and bisection alternate at worst.
constexpr int kMaxIterations = 160;

/// Coefficients of a polynomial of degree N (c[N] ≠ 0), lowest order first.
template <int N>
using Coeffs = std::array<double, N + 1>;

template <int N>
double value(const Coeffs<N>& c, double t) {
    double f = c[N];
    for (int i = N - 1; i >= 0; --i) f = f * t + c[i];
    return f;
}

/// Value at t, rounded to exactly 0 when it is below the rounding error bound of Horner's rule,
/// γ_2N·Σ|c_i||t|^i ≈ N·ε·Σ|c_i||t|^i (Higham, "Accuracy and Stability of Numerical
/// Algorithms", 2nd ed., §5.1): there the computed sign is noise. Used at critical points, so
/// that a double root (or the double root of p' at a triple root of p) whose computed value
/// wobbles around 0 counts as a touch, not as a pair of spurious sign changes.
template <int N>
double value_or_noise_zero(const Coeffs<N>& c, double t) {
    double f = c[N], size = std::fabs(c[N]);
    const double abs_t = std::fabs(t);
    for (int i = N - 1; i >= 0; --i) {
        f = f * t + c[i];
        size = size * abs_t + std::fabs(c[i]);
    }
    return std::fabs(f) <= N * kEps * size ? 0.0 : f;
}

/// Value and first derivative at t in one Horner pass.
template <int N>
void value_and_slope(const Coeffs<N>& c, double t, double& f, double& df) {
    f = c[N];
    df = 0.0;
    for (int i = N - 1; i >= 0; --i) {
        df = df * t + f;
        f = f * t + c[i];
    }
}

/// Value at t, or at t = ±∞ an infinity with the sign p takes there, so that sign tests work
/// at an infinite end of the interval (detect passes an infinite horizon for endless motion).
template <int N>
double value_or_limit(const Coeffs<N>& c, double t) {
    if (!std::isinf(t)) return value<N>(c, t);
    const bool flips = t < 0.0 && N % 2 == 1;
    return (c[N] > 0.0) != flips ? kInf : -kInf;
}

template <int N>
Coeffs<N - 1> derivative(const Coeffs<N>& c) {
    Coeffs<N - 1> d{};
    for (int i = 1; i <= N; ++i) d[i - 1] = static_cast<double>(i) * c[i];
    return d;
}

/// Doubles in increasing order map to increasing integers.
std::int64_t ordered_bits(double x) {
    const auto bits = std::bit_cast<std::int64_t>(std::fabs(x));
    return x < 0.0 ? -bits : bits;
}

double from_ordered_bits(std::int64_t k) {
    const double magnitude = std::bit_cast<double>(k < 0 ? -k : k);
    return k < 0 ? -magnitude : magnitude;
}

/// Midpoint of [a, b] in the ordering of doubles, not of reals: a root near 0 in a bracket
/// like [1e-300, 1] is reached in ~64 halvings instead of ~1000. Within one binade it is the
/// ordinary midpoint. A bracket that straddles 0 is split at 0 first.
double bisect(double a, double b) {
    if (a < 0.0 && b > 0.0) return 0.0;
    const std::int64_t ka = ordered_bits(a), kb = ordered_bits(b);
    return from_ordered_bits(ka + (kb - ka) / 2);
}

bool opposite_signs(double fa, double fb) { return (fa < 0.0 && fb > 0.0) || (fa > 0.0 && fb < 0.0); }

/// Moves the infinite end of a bracket to a finite point where p still has that end's sign, by
/// steps doubling away from the finite end `x0` (p is monotone beyond the last critical point,
/// so the root stays inside). Returns the new end, or x0's side ±∞ if p keeps its sign until
/// overflow (the root is beyond the doubles); `exact_root` is set if p vanishes at a step.
template <int N>
double finite_end(const Coeffs<N>& c, double& x0, double& f0, double direction, bool& exact_root) {
    exact_root = false;
    for (double step = std::fmax(1.0, std::fabs(x0));; step *= 2.0) {
        const double x = x0 + direction * step;
        if (!std::isfinite(x)) return direction * kInf;
        const double fx = value<N>(c, x);
        if (fx == 0.0) exact_root = true;
        if (fx == 0.0 || opposite_signs(f0, fx)) return x;
        x0 = x;  // still on x0's side of the root: a tighter bracket
        f0 = fx;
    }
}

/// The root of p in [a, b] (a < b), given p(a) = fa and p(b) = fb of strictly opposite signs and
/// a starting guess (used if it lies strictly inside). Safeguarded Newton: the bracket always
/// holds the sign change and shrinks with every evaluation.
template <int N>
double solve_in_bracket(const Coeffs<N>& c, double a, double fa, double b, double fb,
                        double guess) {
    if (std::isinf(a) && std::isinf(b)) {  // the whole line: split it at 0
        if (c[0] == 0.0) return 0.0;
        if (opposite_signs(fa, c[0])) {
            b = 0.0;
            fb = c[0];
        } else {
            a = 0.0;
            fa = c[0];
        }
    }
    if (std::isinf(a) || std::isinf(b)) {
        bool exact = false;
        if (std::isinf(b)) {
            b = finite_end<N>(c, a, fa, 1.0, exact);
            if (exact || std::isinf(b)) return b;
            fb = value<N>(c, b);
        } else {
            a = finite_end<N>(c, b, fb, -1.0, exact);
            if (exact || std::isinf(a)) return a;
            fa = value<N>(c, a);
        }
    }
    const bool rising = fa < 0.0;  // p < 0 on a's side of the root
    // Regula falsi start: for a monotone piece it lies between the ends, near the root.
    double x = (guess > a && guess < b) ? guess : a - fa * ((b - a) / (fb - fa));
    double last_step = b - a;
    for (int i = 0; i < kMaxIterations; ++i) {
        double f, df;
        value_and_slope<N>(c, x, f, df);
        if (f == 0.0) return x;
        if ((f < 0.0) == rising) {
            a = x;
        } else {
            b = x;
        }
        const double newton_step = f / df;  // ±∞ if df = 0: rejected below
        double next = x - newton_step;
        // Bisect if Newton leaves the bracket, or converges only linearly (a step over half the
        // last one: far from the root, or at a triple root, where Newton's ratio is 2/3).
        if (!(next > a && next < b) || 2.0 * std::fabs(newton_step) > std::fabs(last_step)) {
            next = bisect(a, b);
        }
        last_step = next - x;
        if (std::fabs(last_step) <= kStepUlps * kEps * std::fabs(next)) return next;
        if (next == x) return x;  // a and b are adjacent doubles
        x = next;
    }
    return x;
}

/// Roots of p where its sign changes, strictly inside (lo, hi), ascending; returns the count.
/// Used for critical points: an end of the interval is never needed as a split point.
template <int N>
int interior_roots(const Coeffs<N>& c, double lo, double hi, double* out);

template <>
int interior_roots<1>(const Coeffs<1>& c, double lo, double hi, double* out) {
    // Linear base case, the one place that divides by a leading coefficient: a tiny c[1] gives
    // a huge or infinite candidate, which the comparison discards.
    const double r = -c[0] / c[1];
    if (r > lo && r < hi) {
        out[0] = r;
        return 1;
    }
    return 0;
}

/// Walks the pieces between lo, the critical points (sign changes of p') and hi, on each of
/// which p is monotone, and calls `on_root(a, fa, b, fb, zero_at)` for each sign change of p,
/// in increasing order, until it returns true. [a, b] brackets the change with fa = p(a) ≠ 0;
/// fb = p(b) is nonzero of the other sign, or 0 only when b = hi. A value at a critical point
/// that is 0 up to rounding marks a root there only if the signs on both sides differ (a zero
/// at an extremum is a touch, not a crossing); `zero_at` is then the first such zero, else NaN.
/// A zero at lo starts no crossing: lo's own root is the caller's business. The values at lo
/// and hi are taken as computed: a touching pair has a tiny but accurate p(lo).
template <int N, typename OnRoot>
void walk_sign_changes(const Coeffs<N>& c, double lo, double hi, OnRoot on_root) {
    double critical[N > 1 ? N - 1 : 1];
    int n_critical = 0;
    if constexpr (N > 1) n_critical = interior_roots<N - 1>(derivative<N>(c), lo, hi, critical);
    double a = lo, fa = value_or_limit<N>(c, lo);
    double zero_at = kNaN;
    for (int k = 0; k <= n_critical; ++k) {
        const bool last = k == n_critical;
        const double b = last ? hi : critical[k];
        const double fb = last ? value_or_limit<N>(c, b) : value_or_noise_zero<N>(c, b);
        if (fb == 0.0) {
            if (std::isnan(zero_at)) zero_at = b;
            if (!last) continue;
        }
        if (opposite_signs(fa, fb) || (fb == 0.0 && fa != 0.0)) {
            if (on_root(a, fa, b, fb, zero_at)) return;
        }
        a = b;
        fa = fb;
        zero_at = kNaN;
    }
}

template <int N>
int interior_roots(const Coeffs<N>& c, double lo, double hi, double* out) {
    int n = 0;
    walk_sign_changes<N>(c, lo, hi, [&](double a, double fa, double b, double fb, double zero_at) {
        if (fb != 0.0) {  // a zero at hi is not interior
            out[n++] = std::isnan(zero_at) ? solve_in_bracket<N>(c, a, fa, b, fb, kNaN) : zero_at;
        }
        return false;
    });
    return n;
}

/// True if p (with p(t) = 0) changes sign at t: the lowest nonzero Taylor coefficient about t,
/// found by repeated synthetic division (Horner's shift), has odd order. Decides whether a root
/// exactly at an end of the interval is a sign change, since p cannot be sampled beyond it.
template <int N>
bool changes_sign_at(const Coeffs<N>& c, double t) {
    Coeffs<N> s = c;
    for (int k = 0; k < N; ++k) {
        for (int i = N - 1; i >= k; --i) s[i] += t * s[i + 1];
    }
    for (int k = 1; k <= N; ++k) {
        if (s[k] != 0.0) return k % 2 == 1;
    }
    return false;
}

template <int N>
double first_down(const Coeffs<N>& c, double lo, double hi) {
    double t = kInf;
    walk_sign_changes<N>(c, lo, hi, [&](double a, double fa, double b, double fb, double zero_at) {
        if (fa < 0.0) return false;  // an upward crossing
        t = std::isnan(zero_at) ? solve_in_bracket<N>(c, a, fa, b, fb, kNaN) : zero_at;
        return true;
    });
    return t;
}

template <int N>
int all_sign_changes(const Coeffs<N>& c, double lo, double hi, std::array<double, 4>& out) {
    int n = 0;
    auto root_at_end = [&](double t) {
        return std::isfinite(t) && value<N>(c, t) == 0.0 && changes_sign_at<N>(c, t);
    };
    if (root_at_end(lo)) out[n++] = lo;
    if (hi > lo) {
        walk_sign_changes<N>(c, lo, hi,
                             [&](double a, double fa, double b, double fb, double zero_at) {
                                 if (fb != 0.0 && n < 4) {
                                     out[n++] = std::isnan(zero_at)
                                                    ? solve_in_bracket<N>(c, a, fa, b, fb, kNaN)
                                                    : zero_at;
                                 }
                                 return false;
                             });
        if (root_at_end(hi) && n < 4) out[n++] = hi;
    }
    return n;
}

/// Degree after dropping exactly-zero leading coefficients. Tiny nonzero ones are kept: the
/// isolation does not mind them, and dropping them would change the answer.
int degree(const Poly4& c) {
    int n = 4;
    while (n > 0 && c[n] == 0.0) --n;
    return n;
}

template <int N>
Coeffs<N> leading(const Poly4& c) {
    Coeffs<N> r{};
    for (int i = 0; i <= N; ++i) r[i] = c[i];
    return r;
}

}  // namespace

double eval(const Poly4& c, double t) { return value<4>(c, t); }

double first_downward_crossing(const Poly4& c, double lo, double hi) {
    if (!(hi > lo)) return kInf;
    switch (degree(c)) {
        case 4: return first_down<4>(leading<4>(c), lo, hi);
        case 3: return first_down<3>(leading<3>(c), lo, hi);
        case 2: return first_down<2>(leading<2>(c), lo, hi);
        case 1: return first_down<1>(leading<1>(c), lo, hi);
        default: return kInf;  // a constant never crosses
    }
}

int sign_change_roots(const Poly4& c, double lo, double hi, std::array<double, 4>& out) {
    if (!(hi >= lo)) return 0;
    switch (degree(c)) {
        case 4: return all_sign_changes<4>(leading<4>(c), lo, hi, out);
        case 3: return all_sign_changes<3>(leading<3>(c), lo, hi, out);
        case 2: return all_sign_changes<2>(leading<2>(c), lo, hi, out);
        case 1: return all_sign_changes<1>(leading<1>(c), lo, hi, out);
        default: return 0;  // a constant has no sign change (and 0 has none either)
    }
}

}  // namespace physics::roots
