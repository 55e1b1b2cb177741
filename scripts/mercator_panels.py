#!/usr/bin/env python3
"""A model of the Mercator panels of kernel/src/area/outer.rs (`MERCATOR_CUTS`, docs/DESIGN.md §12).

Off a flat emitter, the chords from a phase lobe's point `q_L` that enter by an edge at the
distance `h` start at `θ ≈ h cosh u / L`, `u = asinh(tan δ)` the Mercator angle of their
direction (`δ` from the edge's normal through `q_L`, `dψ = sech u du`). Their `θ` integral under a
Henyey–Greenstein lobe `s` wide is flat while `θ ≪ s` and falls as `s/θ` beyond: in `u` a step
about one wide at `u_c = ln(2 L s / h)`, modelled here as `G(u) = 1/√(1 + e^{2(u − u_c)})`. The
rule integrates `sech u · G(u)` from 0 to `U` (the wedge's end) by Gauss–Legendre 12 on each
piece between the cuts; the reference is scipy's quad on unit-wide pieces. Printed: the largest
relative error over `U` ∈ {3, 5, 8, 12, 20, 30} and `u_c` ∈ {0 … 20}, in one panel and cut.

Usage: python3 scripts/mercator_panels.py    (numpy, scipy; seconds)
"""
import numpy as np
from scipy.integrate import quad

NODES, WEIGHTS = np.polynomial.legendre.leggauss(12)
CUTS = [-30.0, -14.0, -6.0, -2.0, 2.0, 6.0, 14.0, 30.0]


def gauss(f, a, b):
    u = 0.5 * (b - a) * (NODES + 1.0) + a
    return 0.5 * (b - a) * (WEIGHTS * f(u)).sum()


def main():
    worst = {"one panel": 0.0, "cut at MERCATOR_CUTS": 0.0}
    for end in [3, 5, 8, 12, 20, 30]:
        for step in [0, 1, 2, 3, 4, 6, 8, 10, 14, 20]:
            f = lambda u: 1.0 / np.cosh(u) / np.sqrt(1.0 + np.exp(2.0 * (u - step)))
            exact = sum(quad(f, a, min(a + 1.0, end), epsabs=1e-17, epsrel=1e-14, limit=200)[0] for a in np.arange(0.0, end, 1.0))
            one = gauss(f, 0.0, end)
            cut = sum(gauss(f, max(0.0, a), min(end, b)) for a, b in zip(CUTS[:-1], CUTS[1:]) if max(0.0, a) < min(end, b))
            worst["one panel"] = max(worst["one panel"], abs(one / exact - 1.0))
            worst["cut at MERCATOR_CUTS"] = max(worst["cut at MERCATOR_CUTS"], abs(cut / exact - 1.0))
    for name, err in worst.items():
        print(f"{name}: largest relative error {err:.1e}")


if __name__ == "__main__":
    main()
