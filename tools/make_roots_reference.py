#!/usr/bin/python3
"""Reference data for the polynomial root tests (tests/physics/roots_test.cpp).

Writes tests/physics/data/roots_reference.json: polynomials of degree <= 4 (random ones built
from known roots, near-double and triple roots, zero and tiny leading coefficients, constants,
linears, roots exactly at an end of the interval, and the contact quartics of two balls or of a
ball and a jaw nose) with their true sign-change roots on an interval.

The double coefficients are taken as exact. Real roots and their multiplicities are found in
exact rational arithmetic (Yun's square-free decomposition, Sturm sequences), refined by exact
bisection to 200 bits, and held as mpmath numbers at 70 digits, so the reference is exact far
below a double's ulp. (Exact bisection rather than mpmath's own solvers: those fail on the
degenerate cases, e.g. a 5e-324 leading coefficient.)

Honest tolerances. A root solver that samples p in double precision can only be asked to be
right where the computed sign of p is right. Horner's rule evaluates p(t) with an error below
gamma_2n * sum |c_i| |t|^i (Higham, "Accuracy and Stability of Numerical Algorithms", 2nd ed.,
section 5.1), gamma_8 ~ 8u = 4 eps for a quartic. With a margin for the last Newton step we call

    eta(t) = 16 * eps * sum |c_i| |t|^i        (eps = 2^-52)

the noise level, and the "bands" are the connected pieces of {t in [lo, hi] : |p(t)| <= eta(t)},
found exactly (their edges are roots of p -+ eta). Outside the bands the sign of p is certain;
inside, any answer is as good as the data allow. For each band we record how many true sign
changes it holds and the true sign of p on each side. A root alone in a band narrower than
1e-12 relative is well conditioned, and the test demands it to 1e-12 relative; an
ill-conditioned one (near-double, triple, tiny slope) is judged by the band alone, i.e. by its
residual |p(t)| <= eta(t).

Run from the repository root:  /usr/bin/python3 tools/make_roots_reference.py
"""

import json
import math
import random
from fractions import Fraction as Q
from pathlib import Path

import mpmath
from mpmath import mp, mpf

mp.dps = 70  # > 200 bits: the refined roots survive conversion

EPS = Q(1, 2**52)
NOISE = 16 * EPS  # eta(t) = NOISE * sum |c_i| |t|^i
WELL = 1e-12  # a root alone in a band narrower than this (relative) is well conditioned
BALL_R = 0.028575  # m
OUT = Path(__file__).resolve().parent.parent / "tests" / "physics" / "data" / "roots_reference.json"


# ---------------------------------------------------------------- exact polynomial arithmetic
# Polynomials are lists of Fractions, lowest order first, without trailing zeros ([] is 0).


def trim(p):
    p = list(p)
    while p and p[-1] == 0:
        p.pop()
    return p


def deg(p):
    return len(p) - 1


def sub(p, q):
    n = max(len(p), len(q))
    return trim([(p[i] if i < len(p) else 0) - (q[i] if i < len(q) else 0) for i in range(n)])


def mul(p, q):
    if not p or not q:
        return []
    r = [Q(0)] * (len(p) + len(q) - 1)
    for i, a in enumerate(p):
        for j, b in enumerate(q):
            r[i + j] += a * b
    return trim(r)


def divmod_poly(p, q):
    p = list(p)
    quot = [Q(0)] * max(1, len(p) - len(q) + 1)
    while len(p) >= len(q) and p:
        k = len(p) - len(q)
        f = p[-1] / q[-1]
        quot[k] = f
        for i, b in enumerate(q):
            p[i + k] -= f * b
        p = trim(p)
    return trim(quot), p


def deriv(p):
    return trim([i * p[i] for i in range(1, len(p))])


def monic(p):
    return [a / p[-1] for a in p]


def gcd(p, q):
    while q:
        p, q = q, divmod_poly(p, q)[1]
    return monic(p)


def value(p, x):
    v = Q(0)
    for a in reversed(p):
        v = v * x + a
    return v


def squarefree(p):
    """Yun's algorithm: [(factor, multiplicity)] with p = lc * prod factor^multiplicity."""
    out = []
    a = gcd(p, deriv(p))
    b = divmod_poly(p, a)[0]
    c = divmod_poly(deriv(p), a)[0]
    d = sub(c, deriv(b))
    k = 1
    while deg(b) > 0:
        a = gcd(b, d)
        if deg(a) > 0:
            out.append((a, k))
        b = divmod_poly(b, a)[0]
        c = divmod_poly(d, a)[0]
        d = sub(c, deriv(b))
        k += 1
    return out


# ---------------------------------------------------------------- real roots (Sturm, bisection)


def sturm(p):
    seq = [p, deriv(p)]
    while deg(seq[-1]) > 0:
        r = divmod_poly(seq[-2], seq[-1])[1]
        if not r:
            break
        seq.append([-a for a in r])
    return seq


def sign(x):
    return (x > 0) - (x < 0)


def sign_at(p, x):
    """Sign of p at x; x may be +-inf (a float)."""
    if isinstance(x, float) and math.isinf(x):
        return sign(p[-1]) * (-1 if x < 0 and deg(p) % 2 else 1)
    return sign(value(p, x))


def variations(seq, x):
    signs = [s for s in (sign_at(p, x) for p in seq) if s != 0]
    return sum(1 for u, v in zip(signs, signs[1:]) if u != v)


def root_bound(p):
    return 1 + max(abs(a / p[-1]) for a in p[:-1]) if deg(p) > 0 else Q(1)


def real_roots(f, lo, hi):
    """Distinct real roots of the square-free f in [lo, hi] (lo, hi Fractions or +-inf floats),
    as mpf at mp.dps digits, ascending."""
    if deg(f) < 1:
        return []
    bound = root_bound(f)
    a = max(Q(lo), -bound - 1) if not (isinstance(lo, float) and math.isinf(lo)) else -bound - 1
    b = min(Q(hi), bound + 1) if not (isinstance(hi, float) and math.isinf(hi)) else bound + 1
    if a > b:
        return []
    seq = sturm(f)
    roots = []
    if value(f, a) == 0:
        roots.append(mpf(a.numerator) / a.denominator)
    stack = [(a, b)]  # count roots in (a, b]
    isolated = []
    while stack:
        x, y = stack.pop()
        n = variations(seq, x) - variations(seq, y)
        if n == 0:
            continue
        if n == 1:
            isolated.append((x, y))
            continue
        m = (x + y) / 2
        stack += [(x, m), (m, y)]
    for x, y in isolated:
        roots.append(refine(f, x, y))
    return sorted(roots)


def refine(f, x, y):
    """The single root of the square-free f in (x, y], to 200 bits (relative), by exact
    bisection: slower than Newton at 60 digits, but immune to the huge or tiny coefficients
    of the degenerate cases."""
    if value(f, y) == 0:
        return to_mp(y)
    if x < 0 < y and value(f, Q(0)) == 0:
        return mpf(0)
    sy = sign(value(f, y))
    while y - x > Q(1, 2**200) * max(abs(x), abs(y)) and y - x > Q(1, 2**1300):
        m = (x + y) / 2
        sm = sign(value(f, m))
        if sm == 0:
            return to_mp(m)
        if sm == sy:
            y = m
        else:
            x = m
    return to_mp((x + y) / 2)


def to_mp(q):
    return mpf(q.numerator) / q.denominator


def sign_change_roots(p, lo, hi):
    """True roots of odd multiplicity of p in [lo, hi], ascending (mpf)."""
    roots = []
    for f, k in squarefree(p):
        if k % 2 == 1:
            roots += real_roots(f, lo, hi)
    return sorted(roots)


def all_real_roots(p, lo, hi):
    roots = []
    for f, _ in squarefree(p):
        roots += real_roots(f, lo, hi)
    return sorted(set(roots))


# ---------------------------------------------------------------- noise bands


def eta_poly(p, negative_side):
    """eta(t) as a polynomial valid for t >= 0 (or t <= 0)."""
    return [NOISE * abs(a) * (-1 if negative_side and i % 2 else 1) for i, a in enumerate(p)]


def mp_of(x):
    if isinstance(x, Q):
        return mpf(x.numerator) / x.denominator
    return mpf(x)


def in_noise(p, t):
    """|p(t)| <= eta(t), exactly (t an mpf is converted exactly to a Fraction)."""
    tq = to_q(t)
    s = sum(abs(a) * abs(tq) ** i for i, a in enumerate(p))
    return abs(value(p, tq)) <= NOISE * s


def to_q(t):
    """The exact value of an mpf as a Fraction."""
    negative, man, exp, _ = mpf(t)._mpf_
    q = Q(man) * (Q(2) ** exp)
    return -q if negative else q


def bands(p, lo, hi):
    """Connected pieces of {t in [lo, hi]: |p(t)| <= eta(t)}, clipped to a finite window."""
    lo_q = None if isinstance(lo, float) and math.isinf(lo) else Q(lo)
    hi_q = None if isinstance(hi, float) and math.isinf(hi) else Q(hi)
    # Breakpoints: roots of p -+ eta on each side of 0, and the interval's ends.
    cuts = set()
    for neg in (False, True):
        e = eta_poly(p, neg)
        for q in (sub(p, e), sub(p, [-a for a in e])):
            if deg(q) >= 1:
                for r in all_real_roots(q, lo, hi):
                    if (r <= 0) if neg else (r >= 0):
                        cuts.add(r)
    cuts.add(mpf(0))
    pts = sorted(cuts)
    if lo_q is not None:
        pts = [mp_of(lo_q)] + [x for x in pts if x > mp_of(lo_q)]
    if hi_q is not None:
        pts = [x for x in pts if x < mp_of(hi_q)] + [mp_of(hi_q)]
    pts = sorted(set(pts))
    # Each breakpoint and each gap between is in the noise or not; merge runs into bands.
    pieces = []  # (a, b) closed runs
    for i, x in enumerate(pts):
        if in_noise(p, x):
            pieces.append([x, x])
        if i + 1 < len(pts):
            mid = (x + pts[i + 1]) / 2
            if in_noise(p, mid):
                pieces.append([x, pts[i + 1]])
    merged = []
    for a, b in pieces:
        if merged and a <= merged[-1][1]:
            merged[-1][1] = max(merged[-1][1], b)
        else:
            merged.append([a, b])
    return merged


def sign_at_mp(p, t):
    return sign(value(p, to_q(t)))


def floor_double(x):
    d = float(x)
    return math.nextafter(d, -math.inf) if mpf(d) > x else d


def ceil_double(x):
    d = float(x)
    return math.nextafter(d, math.inf) if mpf(d) < x else d


# ---------------------------------------------------------------- one case


def make_case(name, c, lo, hi):
    c = [float(x) for x in c] + [0.0] * (5 - len(c))
    p = trim([Q(x) for x in c])
    hi_json = "inf" if math.isinf(hi) else hi
    case = {"name": name, "c": c, "lo": lo, "hi": hi_json}
    if deg(p) < 1:
        case.update(roots=[], bands=[], first=None)
        return case
    roots = sign_change_roots(p, lo, hi)
    bs = bands(p, lo, hi)
    lo_m, hi_m = mpf(lo), mpf(hi)
    band_list = []
    for a, b in bs:
        inside = [r for r in roots if a <= r <= b]
        left = sign_at_mp(p, a - (abs(a) + 1) * mpf(2) ** -150) if a > lo_m else 0
        right = sign_at_mp(p, b + (abs(b) + 1) * mpf(2) ** -150) if b < hi_m else 0
        band_list.append({"lo": floor_double(a), "hi": ceil_double(b), "roots": len(inside),
                          "left": left, "right": right})
    root_list = []
    for r in roots:
        band = next(bd for bd in zip(bs, band_list) if bd[0][0] <= r <= bd[0][1])
        (a, b), info = band
        width = (b - a) / max(abs(r), mpf(2) ** -1022)
        well = info["roots"] == 1 and (width <= WELL or (a == b))
        root_list.append({"t": float(r), "well": bool(well)})
    # The true first downward crossing in (lo, hi]: the first root where p goes + to -.
    first = None
    for r in roots:
        if r > lo_m and sign_at_mp(p, r - (abs(r) + 1) * mpf(2) ** -150) > 0:
            first = float(r)
            break
    if first is None and not math.isinf(hi) and sign_at_mp(p, hi_m) == 0 and deg(p) > 0:
        # A root exactly at hi of even multiplicity approached from above is a crossing too.
        if hi_m > lo_m and sign_at_mp(p, hi_m - (abs(hi_m) + 1) * mpf(2) ** -150) > 0:
            first = hi
    case.update(roots=root_list, bands=band_list, first=first)
    return case


# ---------------------------------------------------------------- case families


def from_roots(lead, real, complex_pairs=()):
    """Coefficients (rounded to double) of lead * prod (t - r) * prod (t^2 - 2 re t + |z|^2)."""
    p = [mpf(lead)]
    for r in real:
        p = poly_mul_mp(p, [-mpf(r), mpf(1)])
    for re, im in complex_pairs:
        p = poly_mul_mp(p, [mpf(re) ** 2 + mpf(im) ** 2, -2 * mpf(re), mpf(1)])
    return [float(x) for x in p]


def poly_mul_mp(p, q):
    r = [mpf(0)] * (len(p) + len(q) - 1)
    for i, a in enumerate(p):
        for j, b in enumerate(q):
            r[i + j] += a * b
    return r


def random_families(rng):
    cases = []
    for i in range(40):
        n_real = rng.choice([4, 4, 2, 2, 0])
        lead = rng.choice([-1, 1]) * 10 ** rng.uniform(-3, 3)
        real = sorted(rng.uniform(-1, 6) for _ in range(n_real))
        pairs = [(rng.uniform(-1, 6), 10 ** rng.uniform(-3, 0.5)) for _ in range((4 - n_real) // 2)]
        lo, hi = rng.uniform(-1.5, 1), rng.uniform(3, 7)
        cases.append(make_case(f"random_quartic_{i}", from_roots(lead, real, pairs), lo, hi))
    for i in range(12):
        n_real = rng.choice([3, 1])
        lead = rng.choice([-1, 1]) * 10 ** rng.uniform(-2, 2)
        real = sorted(rng.uniform(0, 5) for _ in range(n_real))
        pairs = [(rng.uniform(0, 5), rng.uniform(0.01, 1))] if n_real == 1 else []
        cases.append(make_case(f"random_cubic_{i}", from_roots(lead, real, pairs), 0.0, 5.0))
    for i in range(8):
        lead = rng.choice([-1, 1]) * 10 ** rng.uniform(-2, 2)
        real = sorted(rng.uniform(0, 5) for _ in range(2))
        cases.append(make_case(f"random_quadratic_{i}", from_roots(lead, real), 0.0, 5.0))
    return cases


def near_double_families(rng):
    cases = []
    for sep in (1e-3, 1e-6, 1e-9):
        for i in range(8):
            r = rng.uniform(0.2, 4)
            lead = rng.choice([-1, 1]) * 10 ** rng.uniform(-2, 2)
            others = ([rng.uniform(-1, 0.1), rng.uniform(4.5, 6)] if i % 2 == 0 else [])
            pairs = [] if i % 2 == 0 else [(rng.uniform(0, 5), rng.uniform(0.1, 2))]
            c = from_roots(lead, sorted([r, r * (1 + sep)] + others), pairs)
            cases.append(make_case(f"near_double_{sep:g}_{i}", c, 0.0, 5.0))
        # The quadratic itself (a grazing cushion approach).
        r = rng.uniform(0.2, 4)
        cases.append(make_case(f"near_double_quadratic_{sep:g}", from_roots(1.0, [r, r * (1 + sep)]),
                               0.0, 5.0))
    # An exact double root (dyadic, so the coefficients are exact): a touch, not a crossing.
    cases.append(make_case("exact_double_root", from_roots(1.0, [0.5, 0.5, 1.25, 3.0]), 0.0, 5.0))
    cases.append(make_case("exact_double_root_quadratic", from_roots(2.0, [1.5, 1.5]), 0.0, 5.0))
    cases.append(make_case("exact_quadruple_root", from_roots(1.0, [0.75] * 4), 0.0, 2.0))
    return cases


def degenerate_families(rng):
    cases = []
    # Leading coefficient exactly 0 (lower degree stored in a quartic's slots).
    for i in range(6):
        real = sorted(rng.uniform(0, 5) for _ in range(3))
        c = from_roots(rng.choice([-1, 1]) * 10 ** rng.uniform(-2, 2), real) + [0.0]
        cases.append(make_case(f"lead_zero_cubic_{i}", c, 0.0, 5.0))
    for i in range(4):
        real = sorted(rng.uniform(0, 5) for _ in range(2))
        c = from_roots(rng.choice([-1, 1]), real) + [0.0, 0.0]
        cases.append(make_case(f"lead_zero_quadratic_{i}", c, 0.0, 5.0))
    # Tiny leading coefficient over a lower-degree polynomial.
    for i, tiny in enumerate([1e-20, -1e-20, 1e-20, 1e-300, 5e-324]):
        real = sorted(rng.uniform(0, 5) for _ in range(2))
        c = from_roots(1.0, real) + [0.0, tiny]
        cases.append(make_case(f"lead_tiny_quadratic_{i}", c, 0.0, 5.0))
        c = from_roots(-2.0, real + [rng.uniform(0, 5)]) + [tiny]
        cases.append(make_case(f"lead_tiny_cubic_{i}", c, 0.0, 5.0))
    cases.append(make_case("lead_tiny_far_root", [1.0, -3.0, 2.0, 0.0, -1e-20], 0.0, 1e6))
    cases.append(make_case("lead_tiny_far_root_inf", [1.0, -3.0, 2.0, 0.0, -1e-20], 0.0, math.inf))
    # Constants (a stationary pair) and linear polynomials.
    for i, k in enumerate([1.0, -1.0, 0.0, 1e-300, -5e-324]):
        cases.append(make_case(f"constant_{i}", [k], 0.0, 10.0))
    for i, (c0, c1) in enumerate([(1.0, -2.0), (-1.0, 2.0), (3.0, -1e-20), (0.1, -0.3),
                                  (1.0, -1.0), (1e-300, -1.0), (2.0, 1.0)]):
        cases.append(make_case(f"linear_{i}", [c0, c1], 0.0, 5.0))
    # Linear with its root exactly at hi, and at lo.
    cases.append(make_case("linear_root_at_hi", [1.0, -0.5], 0.0, 2.0))
    cases.append(make_case("linear_root_at_lo", [0.0, -0.5], 0.0, 2.0))
    return cases


def multiple_root_families(rng):
    cases = []
    for i in range(8):
        r, s = rng.uniform(0.3, 3), rng.uniform(0, 5)
        lead = rng.choice([-1, 1]) * 10 ** rng.uniform(-1, 1)
        cases.append(make_case(f"triple_root_{i}", from_roots(lead, [r, r, r, s]), 0.0, 5.0))
    cases.append(make_case("triple_root_exact", from_roots(1.0, [1.5, 1.5, 1.5, 3.0]), 0.0, 5.0))
    cases.append(make_case("triple_root_exact_down", from_roots(-1.0, [1.5, 1.5, 1.5, 3.0]), 0.0,
                           5.0))
    cases.append(make_case("triple_root_cubic", from_roots(1.0, [0.3, 0.3, 0.3]), 0.0, 1.0))
    cases.append(make_case("triple_root_at_zero", [0.0, 0.0, 0.0, -1.0, 1.0], -1.0, 2.0))
    return cases


def endpoint_families():
    cases = []
    dy = [0.5, 1.25, 2.0, 3.0]  # dyadic roots: exact coefficients, exact zeros
    c = from_roots(1.0, dy)
    cases.append(make_case("root_at_lo", c, 0.5, 2.5))
    cases.append(make_case("root_at_hi", c, 0.0, 2.0))
    cases.append(make_case("root_at_both_ends", c, 1.25, 3.0))
    cases.append(make_case("root_at_hi_down", from_roots(-1.0, dy), 0.75, 1.25))
    cases.append(make_case("root_at_hi_from_above", from_roots(1.0, dy), 0.0, 0.5))
    cases.append(make_case("root_at_lo_down", from_roots(1.0, dy), 1.25, 1.5))
    cases.append(make_case("double_root_at_lo", from_roots(1.0, [0.5, 0.5, 2.0, 3.0]), 0.5, 2.5))
    cases.append(make_case("double_root_at_hi", from_roots(1.0, [0.5, 2.0, 2.0, 3.0]), 0.0, 2.0))
    cases.append(make_case("quadratic_root_at_hi", from_roots(1.0, [0.25, 1.5]), 0.5, 1.5))
    cases.append(make_case("degenerate_interval", c, 1.25, 1.25))
    cases.append(make_case("root_at_zero_lo", [0.0, -1.0, 0.5, 0.0, 0.0], 0.0, 3.0))
    cases.append(make_case("root_at_zero_inside", [0.0, -1.0, 0.5, 0.0, 0.0], -1.0, 3.0))
    return cases


def collision_quartic(dp, dv, da, D):
    """Coefficients of |dp + dv t + da t^2 / 2|^2 - D^2, computed in double as detect.cpp does."""
    dot = lambda a, b: a[0] * b[0] + a[1] * b[1]
    return [dot(dp, dp) - D * D, 2.0 * dot(dp, dv), dot(dv, dv) + dot(dp, da), dot(dv, da),
            0.25 * dot(da, da)]


def unit(angle):
    return (math.cos(angle), math.sin(angle))


def collision_families(rng):
    cases = []
    D = 2 * BALL_R

    def ball(speed, decel, heading=None):
        h = rng.uniform(0, 2 * math.pi) if heading is None else heading
        v = (speed * math.cos(h), speed * math.sin(h))
        # Deceleration along the slip, which need not be along v while sliding.
        g = h + math.pi + (rng.uniform(-1, 1) if decel > 1 else 0.0)
        return v, (decel * math.cos(g), decel * math.sin(g))

    def horizon(v, a):
        s, d = math.hypot(*v), math.hypot(*a)
        return s / d if d > 0 else 10.0

    for i in range(40):
        # Ball 1 heads roughly at ball 2 from up to a table length away; many hit, some miss.
        dist = rng.uniform(0.07, 2.5)
        h = rng.uniform(0, 2 * math.pi)
        dp = (dist * math.cos(h), dist * math.sin(h))
        speed = rng.uniform(0.05, 12.0)
        aim = math.atan2(dp[1], dp[0]) + rng.uniform(-0.03, 0.03)
        v1, a1 = ball(speed, rng.choice([2.0, 0.1]), aim)
        v2, a2 = ((0.0, 0.0), (0.0, 0.0)) if i % 3 else ball(rng.uniform(0, 3), 0.1)
        dv = (v2[0] - v1[0], v2[1] - v1[1])
        da = (a2[0] - a1[0], a2[1] - a1[1])
        T = min(horizon(v1, a1), horizon(v2, a2) if i % 3 == 0 else 10.0)
        cases.append(make_case(f"collision_{i}", collision_quartic(dp, dv, da, D), 0.0, T))
    # Grazing: the miss distance is D (1 - delta): a near-double root of the quartic.
    for i, delta in enumerate([1e-3, 1e-6, 1e-9, 1e-12, 0.0, -1e-9]):
        speed, decel = rng.uniform(1, 12), rng.choice([2.0, 0.1])
        x0 = rng.uniform(0.2, 1.0)
        dp = (x0, D * (1 - delta))  # ball 2 relative to ball 1, which moves along +x
        v1, a1 = (speed, 0.0), (-decel, 0.0)
        dv, da = (-v1[0], -v1[1]), (-a1[0], -a1[1])
        cases.append(make_case(f"collision_grazing_{delta:g}", collision_quartic(dp, dv, da, D),
                               0.0, speed / decel))
    # Touching pairs: a root at t ~ 0 (a frozen ball hit, and one moving away).
    for i, gap in enumerate([1e-9, 1e-12, 1e-15]):
        speed = rng.uniform(0.5, 8)
        dp = (D + gap, 0.0)
        cases.append(make_case(f"collision_touching_approach_{i}",
                               collision_quartic(dp, (-speed, 0.0), (2.0, 0.3), D), 0.0, speed / 2))
        cases.append(make_case(f"collision_touching_recede_{i}",
                               collision_quartic(dp, (speed, 0.0), (-2.0, 0.3), D), 0.0, speed / 2))
    # Stationary pair (a constant), equal velocities (constant), parallel rolling (quadratic).
    cases.append(make_case("collision_stationary_pair",
                           collision_quartic((0.3, 0.1), (0.0, 0.0), (0.0, 0.0), D), 0.0, math.inf))
    cases.append(make_case("collision_same_motion",
                           collision_quartic((0.3, 0.1), (0.0, 0.0), (0.0, 0.0), D), 0.0, 5.0))
    cases.append(make_case("collision_constant_relative_velocity",
                           collision_quartic((0.5, 0.03), (-3.0, 0.0), (0.0, 0.0), D), 0.0, 2.0))
    cases.append(make_case("collision_constant_relative_velocity_inf",
                           collision_quartic((0.5, 0.03), (-3.0, 0.0), (0.0, 0.0), D), 0.0,
                           math.inf))
    # Jaw nose: a ball against a fixed circle of radius R + nose radius.
    for i in range(6):
        nose = 0.005
        dist = rng.uniform(0.05, 0.5)
        h = rng.uniform(0, 2 * math.pi)
        dp = (dist * math.cos(h), dist * math.sin(h))
        speed = rng.uniform(0.1, 6)
        v, a = ball(speed, rng.choice([2.0, 0.1]), h + rng.uniform(-0.2, 0.2))
        cases.append(make_case(f"jaw_nose_{i}", collision_quartic(dp, (-v[0], -v[1]), (-a[0], -a[1]),
                                                                    BALL_R + nose),
                               0.0, horizon(v, a)))
    # Slowly rolling balls, tiny relative acceleration (the 0.1 m/s^2 case at low speed).
    for i in range(6):
        speed = rng.uniform(0.05, 0.3)
        travel = speed**2 / (2 * 0.1)
        dist = D + rng.uniform(0.2, 1.2) * travel  # some reach the other ball, some stop short
        h = rng.uniform(0, 2 * math.pi)
        dp = (dist * math.cos(h), dist * math.sin(h))
        v1, a1 = ball(speed, 0.1, h + rng.uniform(-0.1, 0.1))
        cases.append(make_case(f"collision_slow_roll_{i}",
                               collision_quartic(dp, (-v1[0], -v1[1]), (-a1[0], -a1[1]), D), 0.0,
                               horizon(v1, a1)))
    return cases


def main():
    rng = random.Random(20240611)
    cases = (random_families(rng) + near_double_families(rng) + degenerate_families(rng) +
             multiple_root_families(rng) + endpoint_families() + collision_families(rng))
    doc = {
        "about": "Generated by tools/make_roots_reference.py; see its docstring. Do not edit.",
        "noise_eps_multiple": 16,
        "well_conditioned_tolerance": 1e-12,
        "cases": cases,
    }
    OUT.parent.mkdir(parents=True, exist_ok=True)
    OUT.write_text(json.dumps(doc, indent=None, separators=(",", ":")).replace('{"name"', '\n{"name"')
                   + "\n")
    print(f"wrote {len(cases)} cases to {OUT}")


if __name__ == "__main__":
    main()
