// Real roots of polynomials of degree ≤ 4 on an interval.
//
// Method: recursive derivative isolation with safeguarded Newton iteration, after
//   G. E. Collins and R. Loos, "Polynomial real root isolation by differentiation",
//   Proc. SYMSAC '76, pp. 15–25 (the sign changes of p' split the interval into pieces on which
//   p is monotone, so each piece holds at most one root), and
//   C. Yuksel, "High-Performance Polynomial Root Finding for Graphics", Proc. ACM Comput.
//   Graph. Interact. Tech. 5(3), 2022 (the same isolation done numerically, each monotone
//   piece solved by Newton's method with a bisection fallback),
// safeguarded in the manner of "rtsafe" (Press et al., Numerical Recipes, 3rd ed., §9.4): the
// bracket always holds the sign change, and a Newton step that leaves it, or converges only
// linearly (at a triple root, say), gives way to a bisection — or first to one step of
// Schröder's variant, Newton on p/p', which restores fast convergence at multiple roots.
//
// Why this method: the contact polynomials of the physics are often degenerate (a stationary
// pair is a constant, motion parallel to a rail loses the leading terms, a grazing contact is a
// near-double root). Closed forms (Ferrari, Cardano) divide by the leading coefficient and lose
// all accuracy there; isolation never needs to: the roots it divides out are only candidates
// compared with the interval, so a tiny leading coefficient just puts them far away. Every
// decision ("is there a root in this piece?") is made from the sign of p evaluated at a point,
// so the answers agree with p itself: a root is reported where the computed p changes sign, and
// a double root (p touches 0 without changing sign) is not reported. Where p is below its own
// rounding noise the sign means nothing; such values count as 0 (see value_or_noise_zero).
//
// A quartic (degree 4) is first given to a faster path (roots_convex_pieces.cpp): its interval
// is cut at the inflection points, and each convex or concave piece is decided from a few
// evaluations, its crossing refined by Halley's iteration with a compensated last step (so its
// roots are correctly rounded where well conditioned); it answers only where every sign it uses
// is certain, and leaves the rest (touching starts, noise-level dips, an infinite horizon) to
// the isolation below, which decides every case.
//
// Cost of the isolation: the critical points of p' (roots of the quadratic p'') come from the
// closed form; those of p (roots of the cubic p') are needed only until the sign of p there is
// certain, often after one Newton step; first_downward_crossing stops at the first crossing and
// never looks for later critical points; and Newton starts from the root of a Taylor parabola
// at an end of the piece, so two or three steps reach full precision. Polynomials are evaluated
// in Estrin's form (Knuth, TAOCP vol. 2, §4.6.4), which shortens the dependency chain of each
// Newton step, and whose rounding error is no larger than Horner's. No allocation, no
// exceptions, no FMA: the same input gives the same bits everywhere.
#include "physics/internal/roots.hpp"

#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>

#include "physics/internal/roots_convex_pieces.hpp"

namespace physics::roots {

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr double kEps = std::numeric_limits<double>::epsilon();

/// Guard on the iteration count; bisection alone would reach adjacent doubles in ~60 steps for
/// any bracket met in practice.
constexpr int kMaxIterations = 200;
/// Newton's error after a step of size s is about K·s² with K = |p''/2p'| (quadratic
/// convergence). Once that is below an ulp the iterate is final without another evaluation,
/// provided the step is already small enough for the quadratic model to hold.
constexpr double kModelStep = 1e-5;  // relative
/// Relative accuracy of a reported root: a quarter ulp, as far as Newton's model can tell.
constexpr double kRootTolerance = 0.25 * kEps;
/// Relative accuracy of a critical point. It only needs to put p's value there on the right
/// side of 0: an error δ changes p by ½p''δ², here ~1e-20 of p's scale, far below p's own
/// rounding noise, so the full precision of a root would buy nothing.
constexpr double kCriticalTolerance = 1e-10;

/// Coefficients of a polynomial of degree N (c[N] ≠ 0), lowest order first.
template <int N>
using Coeffs = std::array<double, N + 1>;

/// p(t). Estrin's form for the cubic and quartic: shorter latency than Horner, and a rounding
/// error below γ_2N·Σ|c_i||t|^i as Horner's (at most 6 roundings on any term of a quartic).
template <int N>
double value(const Coeffs<N>& c, double t) {
    if constexpr (N == 4) {
        const double t2 = t * t;
        return (c[0] + c[1] * t) + t2 * ((c[2] + c[3] * t) + c[4] * t2);
    } else if constexpr (N == 3) {
        const double t2 = t * t;
        return (c[0] + c[1] * t) + t2 * (c[2] + c[3] * t);
    } else {
        double f = c[N];
        for (int i = N - 1; i >= 0; --i) f = f * t + c[i];
        return f;
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

/// Value at t, rounded to exactly 0 when it is below the rounding error bound of the evaluation,
/// γ_2N·Σ|c_i||t|^i ≈ N·ε·Σ|c_i||t|^i (Higham, "Accuracy and Stability of Numerical
/// Algorithms", 2nd ed., §5.1): there the computed sign is noise. Used at critical points, so
/// that a double root (or the double root of p' at a triple root of p) whose computed value
/// wobbles around 0 counts as a touch, not as a pair of spurious sign changes.
template <int N>
double value_or_noise_zero(const Coeffs<N>& c, double t) {
    const double f = value<N>(c, t);
    double size = std::fabs(c[N]);
    const double abs_t = std::fabs(t);
    for (int i = N - 1; i >= 0; --i) size = size * abs_t + std::fabs(c[i]);
    return std::fabs(f) <= N * kEps * size && size < kInf ? 0.0 : f;  // (not if it overflowed)
}

/// p(t), p'(t) and p''(t)/2 in one pass (Estrin's form for N ≥ 3, else Horner's). p(t) is
/// computed exactly as by value(), so the signs seen by Newton and by the walk agree.
template <int N>
void value_slope_half_curvature(const Coeffs<N>& c, double t, double& f, double& df,
                                double& half_d2f) {
    if constexpr (N == 4) {
        const double t2 = t * t;
        f = (c[0] + c[1] * t) + t2 * ((c[2] + c[3] * t) + c[4] * t2);
        df = (c[1] + (2.0 * c[2]) * t) + t2 * ((3.0 * c[3]) + (4.0 * c[4]) * t);
        half_d2f = (c[2] + (3.0 * c[3]) * t) + (6.0 * c[4]) * t2;
    } else if constexpr (N == 3) {
        const double t2 = t * t;
        f = (c[0] + c[1] * t) + t2 * (c[2] + c[3] * t);
        df = (c[1] + (2.0 * c[2]) * t) + (3.0 * c[3]) * t2;
        half_d2f = c[2] + (3.0 * c[3]) * t;
    } else {
        f = c[N];
        df = 0.0;
        half_d2f = 0.0;
        for (int i = N - 1; i >= 0; --i) {
            half_d2f = half_d2f * t + df;
            df = df * t + f;
            f = f * t + c[i];
        }
    }
}

template <int N>
Coeffs<N - 1> derivative(const Coeffs<N>& c) {
    Coeffs<N - 1> d{};
    for (int i = 1; i <= N; ++i) d[i - 1] = static_cast<double>(i) * c[i];
    return d;
}

bool opposite_signs(double fa, double fb) {
    return (fa < 0.0 && fb > 0.0) || (fa > 0.0 && fb < 0.0);
}

/// One end of a piece: where, and the value of p there.
struct End {
    double x;
    double f;
};

/// Midpoint of a bracket [a, b]. A bracket around 0 is split at 0 first, which finds a root
/// there exactly (p(0) = c[0]) and keeps the precision relative for roots near it. A bracket
/// spanning many binades (|b/a| > 2³², or an end at 0) is split at the geometric mean, by
/// averaging the bit patterns of the ends (a 0 end counting as 2⁻⁵²·|other end|), so that a
/// root anywhere in [1, 1e300] is reached in ~60 bisections, not ~1000.
std::uint64_t bits_of(double x) {
    std::uint64_t bits;
    std::memcpy(&bits, &x, sizeof bits);  // std::bit_cast, which Emscripten's libc++ lacks
    return bits;
}

double from_bits(std::uint64_t bits) {
    double x;
    std::memcpy(&x, &bits, sizeof x);
    return x;
}

double bisect(double a, double b) {
    if (a < 0.0 && b > 0.0) return 0.0;
    const double lo = std::fabs(a) < std::fabs(b) ? std::fabs(a) : std::fabs(b);
    const double hi = std::fabs(a) < std::fabs(b) ? std::fabs(b) : std::fabs(a);
    if (!(hi > 0x1p32 * lo)) return a + 0.5 * (b - a);
    const std::uint64_t low_bits = bits_of(lo > 0.0 ? lo : 0x1p-52 * hi);
    const std::uint64_t high_bits = bits_of(hi);
    const double middle = from_bits(low_bits + (high_bits - low_bits) / 2);
    return a < 0.0 || b < 0.0 ? -middle : middle;
}

/// Moves the infinite end of a bracket to a finite point where p still has that end's sign, by
/// steps doubling away from the finite end `x0` (p is monotone beyond the last critical point,
/// so the root stays inside). Returns the new end, or ±∞ if p keeps its sign until overflow
/// (the root is beyond the doubles); `exact_root` is set if p vanishes at a step.
template <int N>
double finite_end(const Coeffs<N>& c, double& x0, double& f0, double direction, bool& exact_root) {
    exact_root = false;
    for (double step = std::fabs(x0) > 1.0 ? std::fabs(x0) : 1.0;; step *= 2.0) {
        const double x = x0 + direction * step;
        if (!std::isfinite(x)) return direction * kInf;
        const double fx = value<N>(c, x);
        if (fx == 0.0) exact_root = true;
        if (fx == 0.0 || opposite_signs(f0, fx)) return x;
        x0 = x;  // still on x0's side of the root: a tighter bracket
        f0 = fx;
    }
}

/// Never stops a solve early: roots are wanted to full precision.
struct ToFullPrecision {
    bool operator()(double, double, double, double) const { return false; }
};

/// The root of p in [a, b] (a < b), given p(a) = fa and p(b) = fb of strictly opposite signs,
/// starting from `x0` if it lies in [a, b] (else from the regula falsi point). Safeguarded
/// Newton: the bracket always holds the sign change and shrinks with every evaluation.
/// `good_enough(x, p(x), a, b)`, asked at each iterate with the current bracket, may end the
/// search there (a critical point is wanted only as far as it decides a sign).
template <int N, typename GoodEnough = ToFullPrecision>
double solve_in_bracket(const Coeffs<N>& c, double a, double fa, double b, double fb, double x0,
                        double tolerance, GoodEnough good_enough = {}) {
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
    double x = (x0 >= a && x0 <= b) ? x0 : a - fa * ((b - a) / (fb - fa));
    if (!(x >= a && x <= b)) x = bisect(a, b);  // p overflowed to ±∞ at an end
    double last_step = b - a;
    bool schroder = false;  // the last step was Schröder's
    for (int i = 0; i < kMaxIterations; ++i) {
        double f, df, half_d2f;
        value_slope_half_curvature<N>(c, x, f, df, half_d2f);
        if (f == 0.0) return x;
        if ((f < 0.0) == rising) {
            a = x;
        } else {
            b = x;
        }
        if (good_enough(x, f, a, b)) return x;
        const double newton_step = f / df;  // ±∞ or NaN if df = 0: rejected below
        const double newton_x = x - newton_step;
        // Converged once the step is an ulp, or Newton's own error estimate K·s² (K = |p''/2p'|,
        // valid once the step is small) is below the tolerance. The target is clamped into the
        // bracket: with the root within an ulp of an end, rounding can put it just beyond.
        const double scale = std::fabs(x);
        if (std::fabs(newton_step) <= kModelStep * scale &&
            (std::fabs(newton_step) <= kEps * scale ||
             std::fabs(half_d2f) * newton_step * newton_step <=
                 tolerance * scale * std::fabs(df))) {
            return newton_x < a ? a : (newton_x > b ? b : newton_x);
        }
        // Newton's step is taken if it stays in the bracket and is at most half the last one.
        // A longer step means slow (linear) convergence: far from the root, or at a root of
        // multiplicity m (a triple root, or a tight cluster), where each step gains only a
        // factor (m−1)/m. Then the step of Newton's method applied to p/p', whose roots are all
        // simple (E. Schröder, Math. Ann. 2, 1870, pp. 317–365), is tried; failing that, or
        // right after it (it is never taken twice running), bisection.
        double next = newton_x;
        const bool after_schroder = schroder;
        schroder = false;
        if (!(newton_x > a && newton_x < b &&
              2.0 * std::fabs(newton_step) <= std::fabs(last_step))) {
            // But first stop if p(x) is rounding noise: near a multiple or clustered root the
            // computed sign is random in a band around it, and bisecting to adjacent doubles
            // would buy only another point of the same band.
            if (value_or_noise_zero<N>(c, x) == 0.0) return x;
            next = x - f * df / (df * df - 2.0 * f * half_d2f);
            schroder = !after_schroder && next > a && next < b;
            if (!schroder) next = bisect(a, b);
        }
        if (next == a || next == b) return x;  // a and b are adjacent doubles
        last_step = next - x;
        x = next;
    }
    return x;
}

/// How far into a piece, from its end e (direction +1 from the left end, −1 from the right),
/// p reaches 0 according to its Taylor parabola there. Near a critical point, p' ≈ 0 and this
/// is where the osculating parabola crosses 0: exact for a quadratic, and close for a grazing
/// contact, whose root sits near the minimum of the distance. At lo or hi it is a Newton step
/// corrected for curvature. With u ≥ 0 the distance into the piece, p + B·u + h·u² = 0
/// (B = direction·p', h = p''/2), scaled by σ = −sign p, has its smallest positive root at
/// u = 2|p| / (σB + √(B² − 4h·p)): no cancellation, and +∞ where it has no root ahead (then the
/// other end, or regula falsi, is used). If it has no real root at all, a plain Newton step.
template <int N>
double taylor_reach(const Coeffs<N>& c, const End& e, double direction) {
    if (std::isinf(e.x)) return kInf;
    double f, df, half_d2f;
    value_slope_half_curvature<N>(c, e.x, f, df, half_d2f);
    const double toward_zero = e.f < 0.0 ? direction * df : -direction * df;  // σ·B
    const double disc = df * df - 4.0 * half_d2f * e.f;
    if (disc < 0.0) return toward_zero > 0.0 ? std::fabs(e.f) / toward_zero : kInf;
    const double denominator = toward_zero + std::sqrt(disc);
    return denominator > 0.0 ? 2.0 * std::fabs(e.f) / denominator : kInf;
}

/// Where Newton starts in a piece: the Taylor estimate from whichever end it is shorter from,
/// since its error grows with the cube of the distance. (A further correction from the cubic
/// Taylor term saves Newton a step but costs as much on the critical path.)
template <int N>
double start_point(const Coeffs<N>& c, const End& a, const End& b) {
    const double from_a = taylor_reach<N>(c, a, 1.0), from_b = taylor_reach<N>(c, b, -1.0);
    return from_a <= from_b ? a.x + from_a : b.x - from_b;  // ∞ or NaN: regula falsi
}

template <int N, typename GoodEnough = ToFullPrecision>
double solve_piece(const Coeffs<N>& c, const End& a, const End& b, double tolerance,
                   GoodEnough good_enough = {}) {
    return solve_in_bracket<N>(c, a.x, a.f, b.x, b.f, start_point<N>(c, a, b), tolerance,
                               good_enough);
}

/// Calls `visit(x)` for each root of p where its sign changes strictly inside (lo, hi), in
/// increasing order, until it returns true; returns whether it did. These are the critical
/// points of the next level up, which consumes them as they come: first_downward_crossing stops
/// at its first crossing without finding the later critical points. A root found by iteration
/// may be cut short where `good_enough` says so (see walk_sign_changes).
template <int N, typename Visit, typename GoodEnough>
bool for_each_interior_root(const Coeffs<N>& c, double lo, double hi, Visit visit,
                            GoodEnough good_enough);

/// Walks the pieces between lo, the critical points (sign changes of p') and hi, on each of
/// which p is monotone (or, where a critical point was only located as far as needed, changes
/// sign at most once), and calls `on_root(a, b, zero_at)` for each sign change of p, in
/// increasing order, until it returns true; returns whether it did. The ends a, b bracket the
/// change: a.f ≠ 0, and b.f is nonzero of the other sign, or 0 only when b is hi. A value at a
/// critical point that is 0 up to rounding marks a root there only if the signs on both sides
/// differ (a zero at an extremum is a touch, not a crossing); `zero_at` is then the first such
/// zero, else NaN. A zero at lo starts no crossing: lo's own root is the caller's business. The
/// values at lo and hi are taken as computed: a touching pair has a tiny but accurate p(lo).
template <int N, typename OnRoot>
bool walk_sign_changes(const Coeffs<N>& c, double lo, double hi, OnRoot on_root) {
    End a{lo, value_or_limit<N>(c, lo)};
    double zero_at = kNaN;
    auto reach = [&](const End& b, bool last) {
        if (b.f == 0.0) {
            if (std::isnan(zero_at)) zero_at = b.x;
            if (!last) return false;
        }
        if (opposite_signs(a.f, b.f) || (b.f == 0.0 && a.f != 0.0)) {
            if (on_root(a, b, zero_at)) return true;
        }
        a = b;
        zero_at = kNaN;
        return false;
    };
    if constexpr (N > 1) {
        // A critical point c is needed only as far as it decides the sign of p there, and any
        // point x of the bracket around it where that sign is certain serves as well as c: the
        // pieces either side of x still hold one sign change each at most (p runs on to c with
        // the same sign, then turns). The sign of p(c) is certain at an iterate x when
        //  - p(x) has the other sign than p at the previous split point: c, the extremum that
        //    follows it, lies further from 0 still; or
        //  - |p(x)| exceeds |p'(x)|·(bracket width), a bound on |p(c) − p(x)| since p' is
        //    monotone between x and c, where it vanishes.
        // A grazing contact (p(c) ≈ 0) is certified by neither, and gets c to full precision.
        End last_certified{kNaN, kNaN};
        auto certified = [&](double x, double slope, double left, double right) {
            const double px = value_or_noise_zero<N>(c, x);
            if (px == 0.0) return false;
            if ((std::isnan(zero_at) && opposite_signs(a.f, px)) ||
                std::fabs(px) > std::fabs(slope) * (right - left)) {
                last_certified = {x, px};
                return true;
            }
            return false;
        };
        auto split_at = [&](double x) {
            const double px =
                x == last_certified.x ? last_certified.f : value_or_noise_zero<N>(c, x);
            return reach(End{x, px}, false);
        };
        const bool stopped =
            for_each_interior_root<N - 1>(derivative<N>(c), lo, hi, split_at, certified);
        if (stopped) return true;
    }
    return reach(End{hi, value_or_limit<N>(c, hi)}, true);
}

template <int N, typename Visit, typename GoodEnough>
bool for_each_interior_root(const Coeffs<N>& c, double lo, double hi, Visit visit,
                            GoodEnough good_enough) {
    if constexpr (N == 1) {
        // Linear base case: a tiny c[1] gives a huge or infinite candidate, which the comparison
        // with the interval discards (c[1] = 0 gives ±∞ or NaN, discarded alike).
        const double r = -c[0] / c[1];
        return r > lo && r < hi && visit(r);
    } else if constexpr (N == 2) {
        // Quadratic base case (the p'' of a quartic, the p' of a cubic), by the closed form: its
        // roots only split the next level into monotone pieces, so they need no sign
        // bookkeeping. The cancellation-free form (Press et al. §5.6) gives the root of smaller
        // magnitude as c/q; the other one follows from the vertex −b/2a, the linear base case of
        // this quadratic's own derivative, so a tiny leading coefficient sends it far away
        // harmlessly. Falls back to isolation if b² − 4ac overflows.
        const double disc = c[1] * c[1] - 4.0 * c[2] * c[0];
        if (std::isfinite(disc)) {
            if (disc <= 0.0) return false;  // no real roots, or a double root: no sign change
            const double q = -0.5 * (c[1] + std::copysign(std::sqrt(disc), c[1]));
            const double near = c[0] / q;
            const double far = 2.0 * (-c[1] / (2.0 * c[2])) - near;
            const double r0 = near < far ? near : far, r1 = near < far ? far : near;
            if (r0 > lo && r0 < hi && visit(r0)) return true;
            return r1 > lo && r1 < hi && r1 != r0 && visit(r1);
        }
    }
    if constexpr (N >= 2) {
        return walk_sign_changes<N>(c, lo, hi, [&](const End& a, const End& b, double zero_at) {
            if (b.f == 0.0) return false;  // a zero at hi is not interior
            return visit(std::isnan(zero_at)
                             ? solve_piece<N>(c, a, b, kCriticalTolerance, good_enough)
                             : zero_at);
        });
    }
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
    walk_sign_changes<N>(c, lo, hi, [&](const End& a, const End& b, double zero_at) {
        if (a.f < 0.0) return false;  // an upward crossing
        t = std::isnan(zero_at) ? solve_piece<N>(c, a, b, kRootTolerance) : zero_at;
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
        walk_sign_changes<N>(c, lo, hi, [&](const End& a, const End& b, double zero_at) {
            if (b.f != 0.0 && n < 4) {  // a zero at hi is handled below
                out[n++] = std::isnan(zero_at) ? solve_piece<N>(c, a, b, kRootTolerance) : zero_at;
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
Coeffs<N> lowest(const Poly4& c) {
    Coeffs<N> r{};
    for (int i = 0; i <= N; ++i) r[i] = c[i];
    return r;
}

/// True if p provably stays positive on (lo, hi] as computed, so that no evaluation of it there
/// (Estrin's or Horner's form) can see a value ≤ 0, nor one within its noise band: 0 ≤ lo < hi
/// finite, every coefficient finite, p(0) = c[0] ≥ 0, and p's slope at 0 more than what its
/// negative terms can take off by hi: Σ_{i≥2} max(0, −c_i)·hi^(i−1) ≤ 0.75·c[1]. Then at each t
/// of (lo, hi] the negative terms N are at most 0.75·c[1]·t, at most 3/4 of the positive ones P
/// (c[1]·t among them), so p ≥ P/4, and the rounding of any evaluation (below 8ε·(P + N) <
/// 14ε·P) or the noise band (4ε·(P + N)) is far below P/4. Such a p has no downward crossing
/// there: the walk finds no sign change, so first_downward_crossing would return +infinity (a
/// pair separating, a ball leaving a cushion: a rolling ball's slope there is exactly twice
/// what its deceleration takes off by the time it stops).
inline bool rises_throughout(const Poly4& c, double lo, double hi) {
    if (!(c[1] > 0.0)) return false;  // (first: an approaching pair or ball fails here)
    if (!(lo >= 0.0 && hi < kInf && c[0] >= 0.0 && c[1] < kInf)) return false;
    double take = 0.0, power = hi;  // hi^(i−1)
    for (int i = 2; i <= 4; ++i) {
        if (!(std::fabs(c[i]) < kInf)) return false;
        if (c[i] < 0.0) take += -c[i] * power;
        power *= hi;
    }
    return c[0] < kInf && take <= 0.75 * c[1];
}

/// True if the quartic's derivative p' (its coefficients computed as derivative<4> does:
/// d_i = (i + 1)·c[i + 1]) provably stays positive on [0, hi] as computed, so that no
/// evaluation of p' there can see a value ≤ 0, nor one within its noise band: hi finite,
/// every coefficient finite, d_0 = c[1] ≥ 1e-290 (far above underflow), the positive terms at
/// hi below 1e300 (no overflow), and Σ_{i≥1} max(0, −d_i)·hi^i ≤ 0.75·d_0 (as for
/// rises_throughout: then p' ≥ P/4 at every t of [0, hi], P its positive terms, far above the
/// rounding of any evaluation, < 11ε·P, and above the noise band, 3ε·(P + N) < 6ε·P).
/// With p(0) = c[0] ≤ 0 the walk of first_down<4> on [0, hi] then finds no sign change of p'
/// (every critical point candidate, and hi, has p' > 0), so its one piece is [0, hi], whose
/// crossing, if any, is upward (p(0) < 0) or none (p(0) = 0): it returns +infinity; this
/// returns the same without the walk (a touching pair separating, overlapping by rounding).
inline bool slope_stays_positive(const Poly4& c, double hi) {
    if (!(c[1] >= 1e-290 && hi < kInf)) return false;  // (first: an approaching pair fails here)
    double take = 0.0, give = c[1], power = hi;        // hi^i
    for (int i = 1; i <= 3; ++i) {
        const double d = static_cast<double>(i + 1) * c[i + 1];
        if (!(std::fabs(d) < kInf)) return false;
        if (d < 0.0)
            take += -d * power;
        else
            give += d * power;
        power *= hi;
    }
    return c[1] < kInf && give < 1e300 && take <= 0.75 * c[1];
}

}  // namespace

double eval(const Poly4& c, double t) {
    double f = c[4];
    for (int i = 3; i >= 0; --i) f = f * t + c[i];
    return f;
}

double first_downward_crossing(const Poly4& c, double lo, double hi) {
    if (!(hi > lo) || rises_throughout(c, lo, hi)) return kInf;
    switch (degree(c)) {
        case 4: {
            // The usual case (a contact quartic) by its convexity pieces; the walk where they
            // cannot decide (see roots_convex_pieces.cpp), such as a start with p(lo) ≤ 0
            // (touching bodies), which is asked here without the call where lo = 0.
            if (lo == 0.0 && !(c[0] > 0.0)) {
                // (c[0] ≤ 0 and finite, and p' provably positive: none, see slope_stays_positive)
                if (c[0] <= 0.0 && c[0] > -kInf && slope_stays_positive(c, hi)) return kInf;
                return first_down<4>(lowest<4>(c), lo, hi);
            }
            const convex_pieces::Answer r = convex_pieces::first_downward_crossing(c, lo, hi);
            switch (r.outcome) {
                case convex_pieces::Outcome::none:
                    return kInf;
                case convex_pieces::Outcome::root:
                    return r.t;
                case convex_pieces::Outcome::unsure:
                    break;
            }
            return first_down<4>(lowest<4>(c), lo, hi);
        }
        case 3:
            return first_down<3>(lowest<3>(c), lo, hi);
        case 2:
            return first_down<2>(lowest<2>(c), lo, hi);
        case 1:
            return first_down<1>(lowest<1>(c), lo, hi);
        default:
            return kInf;  // a constant never crosses
    }
}

int sign_change_roots(const Poly4& c, double lo, double hi, std::array<double, 4>& out) {
    if (!(hi >= lo)) return 0;
    switch (degree(c)) {
        case 4:
            return all_sign_changes<4>(lowest<4>(c), lo, hi, out);
        case 3:
            return all_sign_changes<3>(lowest<3>(c), lo, hi, out);
        case 2:
            return all_sign_changes<2>(lowest<2>(c), lo, hi, out);
        case 1:
            return all_sign_changes<1>(lowest<1>(c), lo, hi, out);
        default:
            return 0;  // a constant has no sign change (and 0 has none either)
    }
}

}  // namespace physics::roots
