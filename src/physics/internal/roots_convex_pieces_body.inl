// The body of the quartic fast path (see roots_convex_pieces.cpp, which includes it twice: once
// built for any x86-64, once for CPUs with FMA, inside the namespace of each build; each build
// defines accurate_value() before it, and gets first_downward_crossing and compensated_value
// from it). Not a header: no include guard, nothing of its own to
// include (roots_convex_pieces.cpp includes <cmath> and <limits> first).
namespace {

constexpr double kEps = std::numeric_limits<double>::epsilon();
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
/// A piece not decided after this many steps (p(m) within the noise, or p' flat) is left to
/// the walk; so is a refinement not converged after as many (it never happens).
constexpr int kMaxSteps = 40;
/// A bracket on the minimum this narrow (relative) with its sign still unknown: p(m) is within
/// the rounding noise (a touch, or a near-double root below it): the walk's conventions decide.
constexpr double kCriticalWidth = 1e-10;

struct Sample {
    double f, df, half_d2f;  ///< p, p', p''/2
};

Sample sample(const Poly4& c, double t) {
    const double t2 = t * t;
    return {(c[0] + c[1] * t) + t2 * ((c[2] + c[3] * t) + c[4] * t2),
            (c[1] + (2.0 * c[2]) * t) + t2 * ((3.0 * c[3]) + (4.0 * c[4]) * t),
            (c[2] + (3.0 * c[3]) * t) + (6.0 * c[4]) * t2};
}

/// p'''(t).
double third_derivative(const Poly4& c, double t) {
    return (6.0 * c[3]) + (24.0 * c[4]) * t;
}

/// Σ|c_i||t|^i: the scale of p's rounding error at t (Higham §5.1: below 2N·ε times this).
double size(const Poly4& c, double t) {
    const double a = std::fabs(t);
    double s = std::fabs(c[4]);
    for (int i = 3; i >= 0; --i) s = s * a + std::fabs(c[i]);
    return s;
}

/// p(t) < 0 by more than the rounding bound of its evaluation (as roots.cpp's noise test).
bool clearly_negative(const Poly4& c, double t, double f) {
    return f < 0.0 && -f > 4.0 * kEps * size(c, t);
}

/// Cold: the paths that end here (rare in the physics) are laid out off the hot ones' way (about
/// 3-4 % less time for a hit or a grazing root; the arithmetic is the same).
[[gnu::cold]] Answer unsure() {
    return {};
}

/// Where to start in a bracket [a, y] with p(y) = s.f < 0: the nearer root of the Taylor
/// parabola at y, p − p'·u + (p''/2)·u² = 0 going left (u = y − t ≥ 0), for p'' > 0 as
/// (p' + √(p'² − 2p·p''))/p'', a product by a reciprocal computed beside the square root, so that
/// only a sum and a product wait for it: free of cancellation where p' ≥ 0, and losing at most
/// 12 bits where −2p·p'' ≥ 2⁻¹⁰·p'² (near the minimum, as at a grazing contact); else as
/// 2|p| / (−p' + √…). It is exact for a quadratic and close for a grazing contact, whose root
/// sits near the minimum. (NaN where it has none: then the midpoint.) Inlined, as last_step.
[[gnu::always_inline]] inline double start_left_of(double y, const Sample& s) {
    const double disc = s.df * s.df - 4.0 * s.half_d2f * s.f;
    if (!(disc >= 0.0)) return kNaN;
    if (s.half_d2f > 0.0 && (s.df >= 0.0 || -4.0 * s.half_d2f * s.f >= 0x1p-10 * (s.df * s.df))) {
        const double inverse_d2f = 0.5 / s.half_d2f;
        return y - (s.df + std::sqrt(disc)) * inverse_d2f;
    }
    const double denominator = -s.df + std::sqrt(disc);
    return denominator > 0.0 ? y - 2.0 * -s.f / denominator : kNaN;
}

/// The step from x to the nearer root of the Taylor parabola of p' there, d1 + d2·v + (d3/2)·v²
/// (d1 = p' < 0 < d2 = p'', d3 = p''', disc = d2² − 2·d1·d3 ≥ 0): −2·d1 / (d2 + √disc), free of
/// cancellation; or, where |2·d1·d3| ≥ 2⁻²⁰·d2² (then √disc − d2 loses at most 23 of its bits,
/// enough for a point to sample), (√disc − d2)/d3, whose reciprocal is computed beside the
/// square root, so that only a sum and a product wait for it.
double newton_on_slope(double d1, double d2, double d3, double disc) {
    if (std::fabs(2.0 * d1 * d3) >= 0x1p-20 * (d2 * d2) && d2 > 0.0) {
        const double inverse_d3 = 1.0 / d3;
        return (std::sqrt(disc) - d2) * inverse_d3;
    }
    return -2.0 * d1 / (d2 + std::sqrt(disc));
}

/// Halley's step at a sample: x − p·p' / (p'² − p·p''/2).
double halley_step(const Sample& s) {
    return s.f * s.df / (s.df * s.df - s.f * s.half_d2f);
}

/// The last step from x, with the compensated value f of p there (where it is finite): Chebyshev's
/// step n + n²·(p''/2)/p', n = f/p', the same order (cubic) as Halley's and, for the tiny last
/// step, the same to far below an ulp of x; its reciprocal 1/p' does not wait for f, so the step
/// is two products and a sum after f (Halley's division waits for it). Kept in [a, b]. s: p, p'
/// and p''/2 at x in plain arithmetic (p only where the compensated value overflows). Inlined
/// (at its two calls): a call passes s through memory and spills the live registers around it;
/// inlined (with start_left_of), the FMA build's hit and grazing root take 7-10 % less time, the
/// other build's about 2 % (the same arithmetic, the same bits).
[[gnu::always_inline]] inline double last_step(const Poly4& c, double x, const Sample& s, double a,
                                               double b) {
    const double inverse_slope = 1.0 / s.df;
    const double bend = s.half_d2f * inverse_slope;
    const double accurate = accurate_value(c, x);
    const double f = std::isfinite(accurate) ? accurate : s.f;
    const double n = f * inverse_slope;
    const double step = n + n * (n * bend);
    const double t = std::isfinite(step) ? x - step : x;
    return t < a ? a : (t > b ? b : t);
}

/// p'' > 0 on [0, y] (y > 0, c4 > 0; sy: the sample at y), shown by one of: p''/2 = c2 + 3c3·t +
/// 6c4·t² rising from c2 > 0 (c3 ≥ 0); its discriminant negative; or its vertex −c3/(4c4) at or
/// beyond y, so that it falls on [0, y] to p''(y)/2 > 0. The margins (2⁻²⁰ relative) are far
/// above the rounding of these few operations.
bool convex_up_to(const Poly4& c, double y, const Sample& sy) {
    if (!(c[2] > 0.0)) return false;
    if (c[3] >= 0.0) return true;
    if (3.0 * (c[3] * c[3]) < (1.0 - 0x1p-20) * (8.0 * c[2] * c[4])) return true;
    return -c[3] >= (1.0 + 0x1p-20) * (4.0 * c[4] * y) &&
           sy.half_d2f > 0x1p-20 * (c[2] + (3.0 * -c[3]) * y + (6.0 * c[4]) * (y * y));
}

/// The one sign change of p in [a, b], given p(a) > 0 > p(b) (both beyond the noise), from x0:
/// Halley's iteration kept in the bracket (a step that leaves it is replaced by bisection).
/// Its error after a step s is about A·|s|³, A = |(p''/2p')² − p'''/6p'| (cubic convergence);
/// with a margin of 2, once that predicts that a step (from x, or from the next iterate) lands
/// within a tenth of an ulp of the root, that step is the last and is taken with the compensated
/// value of p, so the root is right to about an ulp even where p's plain value is rounding noise
/// (there the iterates before it only need to reach the noise band). The result is kept in
/// [a, b] as given: there p's sign is certain.
Answer refine(const Poly4& c, double a, double b, double x0) {
    const double a0 = a, b0 = b;
    double x = x0 > a && x0 < b ? x0 : a + 0.5 * (b - a);
    Sample s = sample(c, x);
    for (int i = 0; i < kMaxSteps; ++i) {
        if (s.f > 0.0) {
            a = x;
        } else if (s.f < 0.0) {
            b = x;
        }
        const double step = halley_step(s);
        const double next = x - step;
        const double gain =
            (2.0 * (s.half_d2f * s.half_d2f) + std::fabs(third_derivative(c, x) * s.df) / 3.0) /
            (s.df * s.df);                                            // 2A
        const double error = gain * (step * step) * std::fabs(step);  // of next
        const double tolerance = 0.1 * kEps * std::fabs(x);
        if (error <= tolerance || !(b - a > 4.0 * kEps * std::fabs(x))) {
            return {Outcome::root, last_step(c, x, s, a0, b0)};
        }
        const bool in = next > a && next < b;
        if (in && gain * (error * error) * error <= tolerance) {
            // The step from next is the last: it needs p' and p''/2 there, which the Taylor
            // expansion at x gives from what is known (d = next − x is tiny), without the
            // latency and the instructions of another sample.
            const double d = next - x, d3f = third_derivative(c, x);
            const double half_d3f = 0.5 * d3f;
            const Sample at_next{s.f + d * (s.df + d * s.half_d2f),
                                 s.df + d * (2.0 * s.half_d2f + d * (half_d3f + d * (4.0 * c[4]))),
                                 s.half_d2f + d * (half_d3f + d * (6.0 * c[4]))};
            return {Outcome::root, last_step(c, next, at_next, a0, b0)};
        }
        x = in ? next : a + 0.5 * (b - a);
        s = sample(c, x);
    }
    return unsure();
}

/// A convex piece [x, e] with p(x) = sl.f > 0: `none` if p > 0 on all of it, its first crossing,
/// or `unsure`. m (the minimum) is sought by Newton's iteration on p', in a bracket [l, r]
/// (p'(l) < 0 < p'(r)), from the root of the Taylor parabola of p' at x (or, if p's own Taylor
/// parabola at x reaches 0, from a little beyond that root: exact for a quadratic in disguise).
/// At each iterate y:
///  - p(y) < 0: the crossing is the one sign change in [x, y];
///  - no crossing if p(m) > 0 is certain: near y, with δ = −p'/p'' (Newton's step on p'), take
///    J = [y − 2|δ|, y + 2|δ|]; there p'' ≥ M = p''(y) − |p'''(y)|·2|δ| − 12|c4|·4δ² (Taylor),
///    so if M > 0 and |p'(y)| ≤ M·2|δ|, p' has its root m in J, and p ≥ p(y) − p'(y)²/(2M) on J,
///    which holds the minimum of the piece (p' < 0 left of J, > 0 right of it).
/// The first point convex_piece samples on a convex piece from x, where p(x) = sl.f > 0 >
/// p'(x) = sl.df: if p's Taylor parabola at x reaches 0, a little beyond that root (`start`,
/// where the crossing is expected: exact for a quadratic in disguise); else the root of the
/// Taylor parabola of p' (Newton's step on p' corrected for curvature), or Newton's step on p'.
struct FirstPoint {
    double y;
    double start = kNaN;
};
[[gnu::always_inline]] inline FirstPoint first_point(const Poly4& c, double x, const Sample& sl) {
    const double d1 = sl.df, d2 = 2.0 * sl.half_d2f, d3 = third_derivative(c, x);
    const double disc_p = sl.df * sl.df - 4.0 * sl.half_d2f * sl.f;
    const double disc_d = d2 * d2 - 2.0 * d1 * d3;
    if (disc_p >= 0.0) {
        const double u = 2.0 * sl.f / (-sl.df + std::sqrt(disc_p));
        return {x + (1.0 + 0x1p-20) * u, x + u};
    }
    if (disc_d >= 0.0) return {x + newton_on_slope(d1, d2, d3, disc_d)};
    return {x - d1 / d2};
}

/// first_point() from x and the sample there, if already taken.
struct Probe {
    FirstPoint point;
    Sample at_y;
};

Answer convex_piece(const Poly4& c, double x, Sample sl, double e, const Probe* probe) {
    if (!(sl.df < 0.0)) return std::isnan(sl.df) ? unsure() : Answer{Outcome::none};
    double l = x, r = e;
    bool have_r = false;  // p'(r) > 0 is known
    const FirstPoint first = probe != nullptr ? probe->point : first_point(c, x, sl);
    double y = first.y;
    double start = first.start;  // where the crossing is expected, if y is the parabola's guess
    const Sample* known = probe != nullptr ? &probe->at_y : nullptr;  // the sample at y, if taken
    for (int i = 0; i < kMaxSteps; ++i) {
        if (!(y > l && y < r)) {
            known = nullptr;
            if (have_r) {
                y = l + 0.5 * (r - l);
            } else {
                // The step reaches e: p may fall all the way.
                const Sample se = sample(c, e);
                if (!(se.df > 0.0)) {
                    if (se.f > 0.0) return {Outcome::none};
                    if (clearly_negative(c, e, se.f)) return refine(c, x, e, start_left_of(e, se));
                    return unsure();
                }
                have_r = true;
                y = e - se.df / (2.0 * se.half_d2f);
                if (!(y > l && y < r)) y = l + 0.5 * (r - l);
            }
        }
        const Sample sy = known != nullptr ? *known : sample(c, y);
        known = nullptr;
        if (!(sy.f > 0.0)) {
            if (!clearly_negative(c, y, sy.f)) return unsure();
            return refine(c, x, y, start > x && start < y ? start : start_left_of(y, sy));
        }
        start = kNaN;
        if (sy.df < 0.0) {
            l = y;
        } else if (sy.df > 0.0) {
            r = y;
            have_r = true;
        } else {
            return std::isnan(sy.df) ? unsure() : Answer{Outcome::none};  // m = y, p(m) > 0
        }
        const double d2 = 2.0 * sy.half_d2f;
        const double delta = -sy.df / d2;
        const double w = 2.0 * std::fabs(delta);
        const double m_low =
            d2 - std::fabs(third_derivative(c, y)) * w - 12.0 * std::fabs(c[4]) * (w * w);
        if (m_low > 0.0 && std::fabs(sy.df) <= m_low * w) {
            const double bound = sy.f - sy.df * sy.df / (2.0 * m_low);
            if (bound > 0.0 && bound > 8.0 * kEps * size(c, y)) return {Outcome::none};
        }
        if (have_r && !(r - l > kCriticalWidth * std::fabs(r))) return unsure();  // p(m) ≈ 0
        y += delta;
    }
    return unsure();
}

/// p and its first two derivatives at lo, where p(lo) > 0 and all is finite; else false (the
/// walk decides). At lo = 0 (the physics' case) the Taylor coefficients are the c_i themselves,
/// the same values as sample() gives there, without its latency. Only c1 is checked there: a
/// non-finite c0 fails the test of p(lo), and a non-finite c2, c3 or c4 (c4 ≠ 0) makes the
/// discriminant of p'' non-finite, which is answered `unsure`.
[[gnu::always_inline]] inline bool sample_start(const Poly4& c, double lo, double hi, Sample& sx) {
    if (lo == 0.0) {
        if (!std::isfinite(c[1])) return false;
        sx = {c[0], c[1], c[2]};
    } else {
        sx = sample(c, lo);
    }
    return sx.f > 0.0 && std::isfinite(sx.f) && std::isfinite(hi);
}

/// The usual contact (a ball–ball quartic, c4 = |Δa|²/4 > 0, approaching: p'(0) < 0), decided
/// before the inflection points are computed where it can be: the first convex piece's first
/// point y, sampled; if p(y) < 0 and p'' > 0 on [0, y], [0, y] holds the first crossing as its
/// one sign change, exactly as convex_piece() would find it (the same point, sample and
/// bracket: the same bits), without the work of the pieces. Sets `answer` where decided; fills
/// `probe` where y was sampled, for convex_piece to start from.
[[gnu::always_inline]] inline bool usual_contact(const Poly4& c, double hi, const Sample& sx,
                                                 Probe& probe, bool& probed, Answer& answer) {
    probe.point = first_point(c, 0.0, sx);
    const double y = probe.point.y;
    if (!(y > 0.0 && y < hi)) return false;
    probe.at_y = sample(c, y);
    probed = true;
    const Sample& sy = probe.at_y;
    if (!(sy.f > 0.0) && convex_up_to(c, y, sy)) {
        if (!clearly_negative(c, y, sy.f)) {
            answer = unsure();
            return true;
        }
        const double start = probe.point.start;
        answer = refine(c, 0.0, y, start > 0.0 && start < y ? start : start_left_of(y, sy));
        return true;
    }
    // Past the minimum (p' > 0) with a dip that its Taylor parabola puts near or below 0 (a
    // grazing contact; a miss's stays well above), convex_piece's next point is the Newton step
    // on p' back towards the minimum, y2 < y, still where p'' > 0 is shown: if p(y2) < 0, it
    // would refine [0, y2] from there (its bound at y cannot have ruled out a crossing that
    // p(y2) < 0 proves), and so is that done here.
    if (sy.f > 0.0 && sy.df > 0.0 && sy.half_d2f > 0.0 &&
        sy.df * sy.df >= 2.0 * sy.half_d2f * sy.f && convex_up_to(c, y, sy)) {
        const double y2 = y + -sy.df / (2.0 * sy.half_d2f);
        if (y2 > 0.0 && y2 < y) {
            const Sample s2 = sample(c, y2);
            if (!(s2.f > 0.0)) {
                answer = clearly_negative(c, y2, s2.f) ? refine(c, 0.0, y2, start_left_of(y2, s2))
                                                       : unsure();
                return true;
            }
        }
    }
    return false;
}

/// The ends of the pieces: the roots of p'' = 2c2 + 6c3·t + 12c4·t² inside (lo, hi), by the
/// cancellation-free closed form (Press et al. §5.6: the one of smaller magnitude as c/q, the
/// other from the vertex; a tiny c4 sends it far away, harmlessly), then hi. Returns their
/// count, or 0 where the discriminant is not finite (`unsure`).
[[gnu::always_inline]] inline int piece_ends(const Poly4& c, double lo, double hi,
                                             double (&ends)[3]) {
    int n_ends = 0;
    const double qa = 12.0 * c[4], qb = 6.0 * c[3], qc = 2.0 * c[2];
    const double disc = qb * qb - 4.0 * qa * qc;
    if (!std::isfinite(disc)) return 0;
    if (disc > 0.0) {
        const double q = -0.5 * (qb + std::copysign(std::sqrt(disc), qb));
        const double near = qc / q;
        const double far = 2.0 * (-qb / (2.0 * qa)) - near;
        const double r0 = near < far ? near : far, r1 = near < far ? far : near;
        if (r0 > lo && r0 < hi) ends[n_ends++] = r0;
        if (r1 > lo && r1 < hi && r1 != r0) ends[n_ends++] = r1;
    }
    ends[n_ends++] = hi;
    return n_ends;
}

/// Goes right through the pieces from x (p(x) = sx.f > 0), each concave or convex, until one
/// holds a crossing or the last ends with p > 0. `probe`: the first piece's first point, if
/// sampled (usual_contact).
[[gnu::always_inline]] inline Answer walk_pieces(const Poly4& c, double x, Sample sx,
                                                 const double (&ends)[3], int n_ends,
                                                 const Probe* probe) {
    bool sampled = true;
    for (int k = 0; k < n_ends; ++k) {
        const double e = ends[k];
        const double mid = x + 0.5 * (e - x);
        const double curvature = (c[2] + (3.0 * c[3]) * mid) + (6.0 * c[4]) * (mid * mid);
        if (curvature < 0.0) {  // concave: the minimum is at an end
            const Sample se = sample(c, e);
            if (se.f > 0.0) {
                x = e;
                sx = se;
                sampled = true;
                continue;
            }
            if (clearly_negative(c, e, se.f)) return refine(c, x, e, start_left_of(e, se));
            return unsure();
        }
        if (!(curvature > 0.0)) return unsure();
        if (!sampled) {  // (the pieces alternate, so this only guards against rounding)
            sx = sample(c, x);
            if (!(sx.f > 0.0)) return unsure();
        }
        const Answer piece = convex_piece(c, x, sx, e, k == 0 ? probe : nullptr);
        if (piece.outcome != Outcome::none) return piece;
        // p > 0 up to e; the next piece is concave and needs only the value at its far end.
        x = e;
        sampled = false;
    }
    return {Outcome::none};
}

}  // namespace

Answer first_downward_crossing(const Poly4& c, double lo, double hi) {
    Sample sx;
    if (!sample_start(c, lo, hi, sx)) return unsure();
    Probe probe{};
    bool probed = false;
    if (lo == 0.0 && sx.df < 0.0 && c[4] > 0.0) {
        Answer answer;
        if (usual_contact(c, hi, sx, probe, probed, answer)) return answer;
    }
    double ends[3];
    const int n_ends = piece_ends(c, lo, hi, ends);
    if (n_ends == 0) return unsure();
    return walk_pieces(c, lo, sx, ends, n_ends, probed ? &probe : nullptr);
}

/// This build's compensated value of p(t) (for the test that compares the builds).
double compensated_value(const Poly4& c, double t) {
    return accurate_value(c, t);
}
