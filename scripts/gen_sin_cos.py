#!/usr/bin/env python3
"""Prints the polynomial coefficients of `real::sin_cos_quarter` (kernel/src/real.rs): minimax
approximations on x in [0, π/2], in z = x²,

  sin x ≈ x·S(z),  S of degree n_s − 1, minimax in the relative error of S against sin(√z)/√z
                   (so sin keeps its relative accuracy as x → 0),
  cos x ≈ C(z),    C of degree n_c − 1, minimax in the absolute error (cos x near π/2 needs
                   only that: it is a distance from a pole of the light angle),

for f64 (n_s = n_c = 9) and f32 (n_s = 5, n_c = 6), by the Remez exchange at 40 digits (mpmath),
each coefficient then rounded once to the target precision; printed with the largest error of
the rounded polynomial over 20 001 points of [0, π/2] (evaluated exactly), which the kernel's
docs quote.

Usage: python3 scripts/gen_sin_cos.py           prints the tables (mpmath==1.3.0; ≈ 30 s)
       python3 scripts/gen_sin_cos.py --check   exits 1 where kernel/src/real.rs differs
                                                (scripts/test-all.sh runs it)
"""
import os
import re
import struct
import sys

import mpmath as mp

mp.mp.dps = 40
Z = (mp.pi / 2) ** 2


def sinc(z):
    return mp.mpf(1) if z == 0 else mp.sin(mp.sqrt(z)) / mp.sqrt(z)


def cosr(z):
    return mp.cos(mp.sqrt(z))


def remez(f, weight, n, iterations=30):
    """Coefficients a_0..a_{n-1} of the degree-(n-1) polynomial minimising max |w (p − f)| on [0, Z]."""
    m = n + 1
    ref = [Z * (1 - mp.cos(mp.pi * i / (m - 1))) / 2 for i in range(m)]
    grid = [Z * (1 - mp.cos(mp.pi * i / 4000)) / 2 for i in range(4001)]
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


def worst(a, f, weight):
    xs = [mp.pi / 2 * i / 20000 for i in range(20001)]
    return max(abs(weight(x * x) * (sum(mp.mpf(c) * (x * x) ** j for j, c in enumerate(a)) - f(x * x))) for x in xs)


def in_kernel(text, name):
    """The table `name` as kernel/src/real.rs (its `text`) has it."""
    m = re.search(r"const " + name + r": \[f64; \d+\] = \[(.*?)\];", text, re.S)
    return None if m is None else [float(v) for v in m.group(1).replace("\n", " ").split(",") if v.strip()]


def main():
    check = "--check" in sys.argv[1:]
    real_rs = open(os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "kernel", "src", "real.rs")).read() if check else ""
    differences = 0
    for bits, n_s, n_c in ((64, 9, 9), (32, 5, 6)):
        s = [round_to(c, bits) for c in remez(sinc, lambda z: 1 / sinc(z), n_s)]
        c = [round_to(c, bits) for c in remez(cosr, lambda z: mp.mpf(1), n_c)]
        es, ec = worst(s, sinc, lambda z: 1 / sinc(z)), worst(c, cosr, lambda z: mp.mpf(1))
        print(f"// f{bits}: sin relative {mp.nstr(es, 3)}, cos absolute {mp.nstr(ec, 3)}")
        for name, table in ((f"SIN_F{bits}", s), (f"COS_F{bits}", c)):
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
