#!/usr/bin/env python3
"""Derives the complex E1 tuning of kernel/src/real.rs (E1_SERIES_TERMS, E1_SERIES_BANDS,
E1_CF_DEPTH, E1_CF_DEPTH_NEAR_REAL) from the region bounds, and shows each choice's measured truncation error, so the tables can be
reproduced and re-derived when a bound moves.

What the kernel evaluates (kernel/src/special/): for Re z >= 0,
  * inside the ellipse (Re z / a)^2 + (Im z / b)^2 < 1 (E1_SERIES_ELLIPSE = (a, b)):
      E1(z) = -gamma - ln z + Ein(z),  Ein(z) = sum_{k=1}^{n} (-1)^(k+1) z^k / (k k!)   (A&S 5.1.11)
    with n from E1_SERIES_BANDS, the first band (R, n) with |z| < R (the last, unbounded band
    is E1_SERIES_TERMS, the ellipse's own count);
  * outside it, e^z E1(z) by the continued fraction (A&S 5.1.22, even contraction)
      1/(z + 1 - 1^2/(z + 3 - 2^2/(z + 5 - ...)))
    cut at depth d, the tail t_{d+1} replaced by the fixed point of t = b - (d+1)^2/t,
    b = z + 2d + 1; d from E1_CF_DEPTH, the first band (R, d) with |z| < R.

Derived here, in mpmath at 50 digits against mpmath's own e1 (so only truncation is measured,
not the float rounding the kernel's tests cover):
  * n: the fewest series terms whose truncation error, relative to |E1(z)|, is at most
    TOLERANCE = 8 unit roundoffs u (u = 2^-53, 2^-24) on the ellipse's boundary (where |z|, and so the
    truncation, is largest; 64 points on the quarter ellipse, Im z >= 0 by symmetry);
  * per series band: the same on the band's outer circle |z| = R and at 3/4 and 1/2 of it
    (32 angles each, points outside the ellipse skipped): the truncation, ~|z|^(n+1), is
    largest on the outer circle, and |E1| does not grow towards it faster than that;
  * per divided-difference band (E1_DD_BANDS, R = the band's bound, 1 for the last): the fewest
    terms n of (Ein(b) - Ein(a))/(b - a) = sum_k c_k h_(k-1)(a, b) with the bound on what is
    dropped, sum_(k>n) R^(k-1)/k! (|c_k| = 1/(k k!), |h_(k-1)| <= k R^(k-1)), at most 8u of the
    smallest |Ein'| = |(1 - e^-x)/x| on |x| = R (the value is Ein' averaged over the segment;
    its minimum modulus on the disc is on the circle, 128 points);
  * per band: the smallest depth whose relative error is at most 8u over the band's inner
    edge (|z| = previous bound, or the ellipse for the first band; 48 angles in [0, pi/2],
    points inside the ellipse skipped), where the fraction converges slowest;
  * E1_CF_DEPTH_NEAR_REAL, the same within 45 degrees of the real axis (|Im z| <= Re z, 48
    angles in [0, pi/4]): the fraction converges faster away from the imaginary axis, slowest
    at the sector's edge (a precision whose table is `Self::E1_CF_DEPTH` by choice, f32, gets
    the truncation the main depths leave in the sector printed instead);
  * EN_CF_DEPTH, the real e^x E_n(x) of special/en.rs: beyond the series region's real edge
    (the ellipse's semi-axis a) the routine starts from the fraction
      1/(x + n - 1 n/(x + n + 2 - 2(n+1)/(x + n + 4 - ...)))   (A&S 5.1.22)
    at its pivot order n = min(ceil x, the orders asked for), the tail replaced by its fixed
    point as above. On the real axis it converges much faster than near the imaginary one, but
    more slowly for large n than for n = 1. Per band of x (the same bounds as E1_CF_DEPTH):
    the smallest depth whose relative error is at most 8u at 9 points of the band (its inner
    edge, where the error is largest, and 8 more; the last, unbounded band at 1, 1.5, 2 and 4
    times its edge) for
    every pivot 1 <= n <= min(ceil x, EN_MAX_ORDER).
The band bounds and ellipse are the kernel's choices (e1.rs module docs: where the series'
cancellation along the real axis, ~e^{2x} ulps, and the fraction's depth along the imaginary
axis balance); this script takes them as given and checks what they imply.

Usage: python3 tests/reference/gen_e1_tuning.py    (mpmath==1.3.0; about a minute)
Exit status 1 when a derived number differs from the one in kernel/src/real.rs.
"""
import math
import os
import re
import sys

import mpmath as mp

mp.mp.dps = 50

# The criterion: truncation at most 8 unit roundoffs (4 ulp) relative to the value — below the
# rounding the evaluation itself leaves (the series' cancellation, the fraction's levels), and
# 1e5 (f32) / 1e6 (f64) times below the kernel's accuracy targets.
TOLERANCE = 8

ROOT = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..")


def committed():
    """(ellipse, series terms, depth table) per precision, read from kernel/src/real.rs."""
    text = open(os.path.join(ROOT, "kernel", "src", "real.rs")).read()
    out = {}
    for prec in ("f64", "f32"):
        block = text[text.index(f"impl Real for {prec}"):]
        ell = re.search(r"E1_SERIES_ELLIPSE: \(f64, f64\) = \(([\d.]+), ([\d.]+)\)", block)
        terms = re.search(r"E1_SERIES_TERMS: usize = (\d+)", block)

        def table(name):
            # the first definition after the impl's start is this precision's
            t = re.search(name + r": &'static \[\(f64, usize\)\] =\s*(?:&\[(.*?)\]|Self::E1_CF_DEPTH);", block, re.S)
            if t.group(1) is None:
                return None  # the main table, by choice (real.rs says why)
            return [(math.inf if b.strip() == "f64::INFINITY" else float(b), int(d)) for b, d in re.findall(r"\(([^,]+), (\d+)\)", t.group(1))]

        out[prec] = ((float(ell.group(1)), float(ell.group(2))), int(terms.group(1)), table("E1_SERIES_BANDS"), table("E1_CF_DEPTH"), table("E1_DD_BANDS"), table("EN_CF_DEPTH"), table("E1_CF_DEPTH_NEAR_REAL"))
    return out


def series_error(z, n):
    """|E1 by n series terms - E1| / |E1|."""
    ein = mp.mpf(0)
    term = mp.mpf(1)
    for k in range(1, n + 1):
        term = term * z / k  # z^k / k!
        ein += (-1) ** (k + 1) * term / k
    approx = -mp.euler - mp.log(z) + ein
    exact = mp.e1(z)
    return abs(approx - exact) / abs(exact)


def cf_error(z, d):
    """|e^z E1 by the fraction at depth d - e^z E1| / |e^z E1|."""
    b = z + 2 * d + 1
    q = 2 * (d + 1) / b
    root = mp.sqrt(1 - q * q)
    if mp.re(root) < 0:
        root = -root
    t = b * (1 + root) / 2
    for k in range(d, 0, -1):
        t = z + (2 * k - 1) - k * k / t
    approx = 1 / t
    exact = mp.exp(z) * mp.e1(z)
    return abs(approx - exact) / abs(exact)


# The most orders en_scaled is asked for (integrals.rs t_moments: 32).
EN_MAX_ORDER = 32


def en_cf_error(x, n, d):
    """|e^x E_n(x) by the fraction at depth d - e^x E_n(x)| / e^x E_n(x), as special/en.rs
    evaluates it (the tail t_{d+1} the fixed point of t = b - a/t)."""
    b = x + n + 2 * (d + 1)
    a = (d + 2) * (n + d + 1)
    disc = 1 - 4 * a / (b * b)
    t = b * (1 + mp.sqrt(disc)) / 2 if disc > 0 else b
    for k in range(d, 0, -1):
        t = x + n + 2 * k - (k + 1) * (n + k) / t
    approx = 1 / (x + n - n / t)
    exact = mp.exp(x) * mp.expint(n, x)
    return abs(approx - exact) / exact


def en_depth(lo, hi, unit):
    """The smallest depth for x in [lo, hi) at every pivot the routine can take there, and the
    largest error at it."""
    xs = [mp.mpf(lo) * f for f in (1, 1.5, 2, 4)] if math.isinf(hi) else [mp.mpf(lo) + (mp.mpf(hi) - lo) * i / 9 for i in range(9)]
    cases = [(x, n) for x in xs for n in range(1, min(int(mp.ceil(x)), EN_MAX_ORDER) + 1)]
    d = 0
    while True:
        worst = max(en_cf_error(x, n, d) for x, n in cases)
        if worst <= TOLERANCE * unit:
            return d, worst
        d += 1


def dd_terms(radius, unit):
    """The fewest divided-difference terms for max(|a|, |b|) <= radius, and the bound's ratio."""
    circle = [mp.mpc(radius * math.cos(th), radius * math.sin(th)) for th in (2 * math.pi * i / 128 for i in range(128))]
    smallest = min(abs((1 - mp.exp(-x)) / x) for x in circle)
    n = 1
    while True:
        dropped = mp.nsum(lambda k: mp.mpf(radius) ** (k - 1) / mp.factorial(k), [n + 1, mp.inf])
        if dropped <= TOLERANCE * unit * smallest:
            return n, dropped / smallest
        n += 1


def fewest(error, points, unit):
    """The smallest count (terms or depth) whose largest error over `points` is at most
    TOLERANCE units, and that error."""
    n = 1
    while True:
        worst = max(error(z, n) for z in points)
        if worst <= TOLERANCE * unit:
            return n, worst
        n += 1


def inside(z, ell):
    a, b = ell
    return (mp.re(z) / a) ** 2 + (mp.im(z) / b) ** 2 < 1


def fraction_depths(prec, unit, ell, table, widest, where, derive):
    """Checks a fraction depth table on its bands' inner edges at angles in [0, widest] (the
    ellipse's edge for the first band) and returns how many depths differ from the derived
    ones; with `derive` false only prints what the table's depths leave there."""
    a, b = ell
    mismatches = 0
    inner = None
    for bound, depth_now in table:
        angles = [widest * i / 47 for i in range(48)]
        if inner is None:
            # the ellipse's edge: |z| there is the smallest the fraction sees at that angle
            edge = [mp.mpc(a * math.cos(th), b * math.sin(th)) for th in angles]
        else:
            edge = [mp.mpc(inner * math.cos(th), inner * math.sin(th)) for th in angles]
            edge = [z for z in edge if not inside(z, ell)]
        lo = "ellipse" if inner is None else f"{inner:g}"
        inner = bound
        if not derive:
            worst = max(cf_error(z, depth_now) for z in edge)
            print(f"{prec}: fraction for {lo} <= |z| < {bound:g}{where}: depth {depth_now} leaves {float(worst) / unit:.2f} u")
            continue
        if edge:
            d, worst = fewest(cf_error, edge, unit)
        else:
            # the band lies inside the ellipse in this sector: the series serves it
            d, worst = 0, 0.0
        flag = "" if d == depth_now else f"   <-- real.rs has {depth_now}"
        mismatches += d != depth_now
        print(f"{prec}: fraction for {lo} <= |z| < {bound:g}{where}: depth {d}, truncation <= {float(worst) / unit:.2f} u{flag}")
    return mismatches


def main():
    mismatches = 0
    for prec, unit in (("f64", 2.0 ** -53), ("f32", 2.0 ** -24)):
        ell, terms_now, series_now, bands_now, dd_now, en_now, near_now = committed()[prec]
        a, b = ell
        boundary = [mp.mpc(a * math.cos(th), b * math.sin(th)) for th in (math.pi / 2 * i / 63 for i in range(64))]
        n, worst = fewest(series_error, boundary, unit)
        flag = "" if n == terms_now else f"   <-- real.rs has {terms_now}"
        mismatches += n != terms_now
        print(f"{prec}: series inside the ellipse ({a}, {b}): {n} terms, truncation <= {float(worst) / unit:.2f} u{flag}")
        for bound, n_now in series_now:
            if math.isinf(bound):
                flag = "" if n_now == terms_now else f"   <-- the last band has {n_now}, E1_SERIES_TERMS {terms_now}"
                mismatches += n_now != terms_now
                print(f"{prec}: series beyond the last band: the ellipse's count{flag}")
                continue
            circles = [mp.mpc(f * bound * math.cos(th), f * bound * math.sin(th)) for f in (1.0, 0.75, 0.5) for th in (math.pi / 2 * i / 31 for i in range(32))]
            circles = [z for z in circles if inside(z, ell)]
            n, worst = fewest(series_error, circles, unit)
            flag = "" if n == n_now else f"   <-- real.rs has {n_now}"
            mismatches += n != n_now
            print(f"{prec}: series for |z| < {bound:g}: {n} terms, truncation <= {float(worst) / unit:.2f} u{flag}")
        for bound, n_now in dd_now:
            radius = 1.0 if math.isinf(bound) else bound
            n, ratio = dd_terms(radius, unit)
            flag = "" if n == n_now else f"   <-- real.rs has {n_now}"
            mismatches += n != n_now
            edge = "<= 1 (the routine's domain)" if math.isinf(bound) else f"< {radius:g}"
            print(f"{prec}: divided differences for max(|a|, |b|) {edge}: {n} terms, dropped <= {float(ratio) / unit:.2f} u of the value")
        derive_near = near_now is not None
        if not derive_near:
            near_now = bands_now
            print(f"{prec}: E1_CF_DEPTH_NEAR_REAL is E1_CF_DEPTH (not derived); what it leaves within 45 deg:")
        if [b for b, _ in near_now] != [b for b, _ in bands_now]:
            mismatches += 1
            print(f"{prec}: E1_CF_DEPTH_NEAR_REAL's bands differ from E1_CF_DEPTH's   <--")
        mismatches += fraction_depths(prec, unit, ell, bands_now, math.pi / 2, "", True)
        mismatches += fraction_depths(prec, unit, ell, near_now, math.pi / 4, " within 45 deg of the real axis", derive_near)
        if [b for b, _ in en_now] != [b for b, _ in bands_now]:
            mismatches += 1
            print(f"{prec}: EN_CF_DEPTH's bands differ from E1_CF_DEPTH's   <--")
        lo = a
        for bound, depth_now in en_now:
            d, worst = en_depth(lo, bound, unit)
            flag = "" if d == depth_now else f"   <-- real.rs has {depth_now}"
            mismatches += d != depth_now
            print(f"{prec}: real fraction e^x E_n(x) for {lo:g} <= x < {bound:g}: depth {d}, truncation <= {float(worst) / unit:.2f} u{flag}")
            lo = bound
    print(f"{mismatches} differences from kernel/src/real.rs")
    return 1 if mismatches else 0


if __name__ == "__main__":
    sys.exit(main())
