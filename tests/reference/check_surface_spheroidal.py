#!/usr/bin/env python3
"""An independent check of surface.jsonl's Lambertian records under lights without an axis: each
value re-derived as one volume integral in prolate spheroidal coordinates (docs/DESIGN.md §11),
by mpmath's tanh-sinh, where gen_surface.py integrates over directions and along each ray.

A surface point s with unit normal n receives from the medium
  L = ∫_{n·ω>0} L_a(s, ω) (ρ/π)(n·ω) dω,  L_a(s, ω) = σs I ∫_0^∞ P(μ) e^{−σt(t + r)} / r² dt,
and with x = s + tω (dt dω = dV/t²) that is an integral over the half-space n·(x − s) > 0:
  L = (ρ/π) σs I ∫ (n·x̂)⁺ P(μ) e^{−σt(|x − s| + |x − L|)} / (|x − s|² |x − L|²) dV.
In prolate spheroidal coordinates about the foci s and the light L (a = d/2, d = |L − s|):
|x − s| = a(ξ + η), |x − L| = a(ξ − η), ξ ≥ 1, −1 ≤ η ≤ 1, azimuth φ about ℓ = (L − s)/d, and
dV = a³(ξ² − η²) dξ dη dφ, so
  L = (ρ σs I/(π a)) ∫_1^∞ e^{−σt d ξ} ∫_{−1}^{1} P(μ) W / (ξ² − η²) dη dξ,
with the scattering cosine μ = (2 − ξ² − η²)/(ξ² − η²) (law of cosines at x; +1 on the segment
between s and L, → −1 far away), and W the φ-integral of (n·x̂)⁺: n·x̂ = A + B cos(φ − φ_n),
A = cos α (ξη + 1)/(ξ + η), B = sin α √((ξ² − 1)(1 − η²))/(ξ + η) (α the normal's angle from ℓ),
W = 2(Aψ + B sin ψ), ψ = arccos(−A/B) (2πA where B ≤ |A|, A > 0; 0 where A ≤ −B). The extinction
is e^{−σt d ξ} alone: the medium enters through one factor, the geometry and the phase function
through the rest. The inner integral is split at W's kinks, the real roots in (−1, 1) of
B² = A²: η²(ξ² − sin²α) + 2 cos²α ξ η + cos²α − sin²α(ξ² − 1) = 0; tanh-sinh takes the
endpoint singularities (1/(ξ² − η²) at ξ → 1, η → ±1; the square root of W at η → ±1). With
σt = 0 and isotropic scattering it is the closed form L = ρ σs I (E(sin²α) + cos α)/(2π d)
(tests/surface.rs `non_absorbing_isotropic_closed_forms`).

Checked: |value − reference| ≤ 1e-10 of the reference. The references are kept where two
resolutions agree to 1e-11 (gen_surface.py); tanh-sinh at 15 digits adds less (over all 30 such
records the two agreed within 1.1e-13, `--all`).

Usage: python3 tests/reference/check_surface_spheroidal.py [--all]
  (the first such record of each class, about two minutes; --all: every one, about ten)
"""
import json
import os
import sys

from mpmath import acos, exp, inf, mp, mpf, pi, quad, sqrt

HERE = os.path.dirname(os.path.abspath(__file__))
TOLERANCE = 1e-10


def phase(ph):
    """The phase function P(μ) of a record (per steradian), as gen_surface.phase_np, for the kinds
    the checked records have (a new kind fails loudly)."""
    k = ph["kind"]
    if k == "isotropic":
        return lambda mu: 1 / (4 * pi)
    if k == "henyey_greenstein":
        g = mpf(ph["g"])
        return lambda mu: (1 - g * g) / (4 * pi * (1 + g * g - 2 * g * mu) ** 1.5)
    raise ValueError(k)


def spheroidal(r):
    """The record's surface air-light by the spheroidal double integral (module docs)."""
    s = [mpf(v) for v in r["surface"]["position"]]
    light = [mpf(v) for v in r["light"]["position"]]
    n = [mpf(v) for v in r["surface"]["normal"]]
    norm = sqrt(sum(v * v for v in n))
    n = [v / norm for v in n]
    to_light = [light[i] - s[i] for i in range(3)]
    d = sqrt(sum(v * v for v in to_light))
    cos_a = sum(n[i] * to_light[i] for i in range(3)) / d
    sin_a = sqrt(max(0, 1 - cos_a * cos_a))
    albedo = mpf(r["surface"]["brdf"]["albedo"])
    sigma_s, sigma_t = mpf(r["medium"]["sigma_s"]), mpf(r["medium"]["sigma_t"])
    intensity = mpf(r["light"]["intensity"])
    p = phase(r["phase"])
    tau = sigma_t * d

    def inner(xi):
        def f(eta):
            # (a node rounded onto the corner ξ = 1, η = ±1: a set of measure zero)
            if xi + eta == 0 or xi == eta:
                return 0
            a = cos_a * (xi * eta + 1) / (xi + eta)
            b = sin_a * sqrt(max(0, (xi * xi - 1) * (1 - eta * eta))) / (xi + eta)
            if b <= abs(a):
                w = 2 * pi * a if a > 0 else 0
            else:
                x = -a / b
                w = 2 * (a * acos(x) + b * sqrt(1 - x * x))
            mu = (2 - xi * xi - eta * eta) / (xi * xi - eta * eta)
            return p(mu) * w / (xi * xi - eta * eta)

        qa, qb, qc = xi * xi - sin_a * sin_a, 2 * cos_a * cos_a * xi, cos_a * cos_a - sin_a * sin_a * (xi * xi - 1)
        disc = qb * qb - 4 * qa * qc
        points = {mpf(-1), mpf(0), mpf(1)}
        if disc > 0 and qa > 0:
            for e in ((-qb - sqrt(disc)) / (2 * qa), (-qb + sqrt(disc)) / (2 * qa)):
                if -1 < e < 1:
                    points.add(e)
        return quad(f, sorted(points))

    # ξ: graded towards the segment (ξ → 1) and out to the extinction's scale 1/τ
    breaks = {mpf(1), 1 + mpf(10) ** -6, 1 + mpf(10) ** -3, mpf("1.1"), mpf(2), mpf(5), mpf(20)}
    breaks |= {x for x in (10 / tau, 40 / tau) if x > 20}
    outer = quad(lambda xi: exp(-tau * xi) * inner(xi), sorted(breaks) + [inf])
    return albedo / pi * sigma_s * intensity / (d / 2) * outer


def main():
    mp.dps = 15
    every = "--all" in sys.argv[1:]
    with open(os.path.join(HERE, "surface.jsonl")) as f:
        records = [json.loads(line) for line in f]
    seen, failures, worst = set(), [], 0.0
    for r in records:
        if r["light"]["distribution"]["kind"] != "isotropic" or r["surface"]["brdf"]["kind"] != "lambert":
            continue
        if not every and r["category"] in seen:
            continue
        seen.add(r["category"])
        value = spheroidal(r)
        error = float(abs(value / r["surface_air_light"] - 1))
        worst = max(worst, error)
        print(f"{r['category']:>14} {r['phase']['kind']:>18}: {float(value):.15e} against {r['surface_air_light']:.15e}, {error:.1e}", flush=True)
        if not error <= TOLERANCE:
            failures.append(r["category"])
    print(f"largest difference {worst:.1e} (at most {TOLERANCE:.0e})")
    if failures:
        sys.exit(f"spheroidal check failed: {failures}")


if __name__ == "__main__":
    main()
