#!/usr/bin/env python3
"""Prints the minimax polynomials of kernel/src/real.rs, each coefficient rounded once to the
target precision, with the largest error of the rounded polynomial over 20 001 points of its
interval (evaluated exactly), which the kernel's docs quote:

* `sin_cos_quarter`, on x in [0, π/2], in z = x²:
    sin x ≈ x·S(z),  S of degree n_s − 1, minimax in the relative error of S against sin(√z)/√z
                     (so sin keeps its relative accuracy as x → 0),
    cos x ≈ C(z),    C of degree n_c − 1, minimax in the absolute error (cos x near π/2 needs
                     only that: it is a distance from a pole of the light angle),
  for f64 (n_s = n_c = 9) and f32 (n_s = 5, n_c = 6);
* `exp_nonpositive`, on r in [−ln 2/2, ln 2/2] (what is left of x after x = k ln 2 + r):
    e^r ≈ E(r),      E of degree n_e − 1, minimax in the relative error,
  for f32 (n_e = 7; f64 takes the library's exp, which measured faster than 12 terms);
* `atan_nonnegative`, on t in [0, 1] (t = min(a, 1/a)), in z = t²:
    atan t ≈ t·A(z), A of degree n_a − 1, minimax in the relative error of A against
                     atan(√z)/√z,
  for f32 (n_a = 10; 11 is no better once rounded to f32; f64 takes the library's atan).

All by the Remez exchange at 40 digits (mpmath).

Usage: python3 scripts/gen_minimax.py           prints the tables (mpmath==1.3.0; ≈ 1 min)
       python3 scripts/gen_minimax.py --check   exits 1 where kernel/src/real.rs differs
                                                (scripts/test-all.sh runs it)
"""
import os
import re
import struct
import sys

import mpmath as mp

mp.mp.dps = 40
QUARTER = (mp.mpf(0), (mp.pi / 2) ** 2)  # z = x² for x in [0, π/2]
HALF_LN2 = (-mp.log(2) / 2, mp.log(2) / 2)


def sinc(z):
    return mp.mpf(1) if z == 0 else mp.sin(mp.sqrt(z)) / mp.sqrt(z)


def cosr(z):
    return mp.cos(mp.sqrt(z))


def atanc(z):
    return mp.mpf(1) if z == 0 else mp.atan(mp.sqrt(z)) / mp.sqrt(z)


def remez(f, weight, n, interval, iterations=30):
    """Coefficients a_0..a_{n-1} of the degree-(n-1) polynomial minimising max |w (p − f)| on the interval."""
    lo, hi = interval
    at = lambda t: lo + (hi - lo) * (1 - mp.cos(mp.pi * t)) / 2  # Chebyshev-spaced, t in [0, 1]
    m = n + 1
    ref = [at(mp.mpf(i) / (m - 1)) for i in range(m)]
    grid = [at(mp.mpf(i) / 4000) for i in range(4001)]
    for _ in range(iterations):
        rows = [[z ** j for j in range(n)] + [(-1) ** i / weight(z)] for i, z in enumerate(ref)]
        sol = mp.lu_solve(mp.matrix(rows), mp.matrix([f(z) for z in ref]))
        a = [sol[j] for j in range(n)]
        err = [weight(z) * (sum(a[j] * z ** j for j in range(n)) - f(z)) for z in grid]
        # the extrema of alternating sign, one per run of equal sign, the largest of each run
        runs = []
        for z, e in zip(grid, err):
            if runs and (e > 0) == (runs[-1][1] > 0):
                if abs(e) > abs(runs[-1][1]):
                    runs[-1] = (z, e)
            else:
                runs.append((z, e))
        while len(runs) > m:
            # drop the smaller end
            runs = runs[1:] if abs(runs[0][1]) < abs(runs[-1][1]) else runs[:-1]
        if len(runs) < m:
            break
        ref = [z for z, _ in runs]
    return a


def round_to(x, bits):
    v = float(x)
    return struct.unpack("f", struct.pack("f", v))[0] if bits == 32 else v


def worst(a, f, weight, points):
    return max(abs(weight(z) * (sum(mp.mpf(c) * z ** j for j, c in enumerate(a)) - f(z))) for z in points)


def in_kernel(text, name):
    """The table `name` as kernel/src/real.rs (its `text`) has it."""
    m = re.search(r"const " + name + r": \[f64; \d+\] = \[(.*?)\];", text, re.S)
    return None if m is None else [float(v) for v in m.group(1).replace("\n", " ").split(",") if v.strip()]


def main():
    check = "--check" in sys.argv[1:]
    real_rs = open(os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "kernel", "src", "real.rs")).read() if check else ""
    # the error is measured at 20 001 points: x evenly over [0, π/2] (z = x²), r evenly over its interval
    quarter = [(mp.pi / 2 * i / 20000) ** 2 for i in range(20001)]
    half_ln2 = [HALF_LN2[0] + (HALF_LN2[1] - HALF_LN2[0]) * i / 20000 for i in range(20001)]
    unit = [(mp.mpf(i) / 20000) ** 2 for i in range(20001)]
    relative_sin, absolute, relative_exp = (lambda z: 1 / sinc(z)), (lambda z: mp.mpf(1)), (lambda r: 1 / mp.exp(r))
    relative_atan = lambda z: 1 / atanc(z)
    differences = 0
    for bits, n_s, n_c, n_e, n_a in ((64, 9, 9, 0, 0), (32, 5, 6, 7, 10)):
        s = [round_to(c, bits) for c in remez(sinc, relative_sin, n_s, QUARTER)]
        c = [round_to(c, bits) for c in remez(cosr, absolute, n_c, QUARTER)]
        e = [round_to(c, bits) for c in remez(mp.exp, relative_exp, n_e, HALF_LN2)] if n_e else []
        es, ec = worst(s, sinc, relative_sin, quarter), worst(c, cosr, absolute, quarter)
        a = [round_to(c, bits) for c in remez(atanc, relative_atan, n_a, (mp.mpf(0), mp.mpf(1)))] if n_a else []
        ee = f", exp relative {mp.nstr(worst(e, mp.exp, relative_exp, half_ln2), 3)}" if e else ""
        ea = f", atan relative {mp.nstr(worst(a, atanc, relative_atan, unit), 3)}" if a else ""
        print(f"// f{bits}: sin relative {mp.nstr(es, 3)}, cos absolute {mp.nstr(ec, 3)}{ee}{ea}")
        tables = ((f"SIN_F{bits}", s), (f"COS_F{bits}", c)) + (((f"EXP_F{bits}", e),) if e else ()) + (((f"ATAN_F{bits}", a),) if a else ())
        for name, table in tables:
            print(f"const {name}: [f64; {len(table)}] = [{', '.join(repr(v) for v in table)}];")
            kernel = in_kernel(real_rs, name) if check else table
            if kernel != table:
                print(f"  <-- kernel/src/real.rs has {kernel}")
                differences += 1
    if check:
        print(f"{differences} differences from kernel/src/real.rs")
        sys.exit(1 if differences else 0)


if __name__ == "__main__":
    main()
