#!/usr/bin/env python3
"""A design study for the bounded area-light method (kernel/src/area/outer.rs, docs/DESIGN.md
§12) in forward-scattering fog: a sphere seen along rays whose phase-function lobe (about the
ray's own direction d) falls on or near it, where the method's rule over the sphere's cap (polar
about the centre's direction, `sin β = sin α sin φ`) misses the lobe.

The alternative measured here, where d lies inside the cap: polar coordinates about d itself,
`ω = cos θ d + sin θ (cos ψ u + sin ψ v)`, `θ = s tan γ` from 0 to the cap's rim in each `ψ`
(`s` a multiple of the lobe's width `κ = √(2(μ* − 1))`, `μ*` the phase function's forward
singularity: Henyey–Greenstein `(1 − g)/√g`), Gauss–Legendre in `γ` and `ψ`. Both rules under the
same ray rule (Gauss–Legendre 24 on four panels per piece in the angle from the centre, split at
its foot and the sphere's entry and exit); the reference is the peak rule at 64 × 64 nodes and 32
on the ray, and its distance from 96 × 96 and 48 is printed beside it. Rays from the origin, the
sphere (centre (6, 1.5, −0.5), radius 0.8, radiance 2, σs = 0.05, σt = 0.08) towards its centre,
its limb, just past the limb and beyond.

Usage: python3 scripts/area_lobe_study.py    (numpy; a few minutes)
"""
import math
import os
import sys

import numpy as np

ROOT = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..")
sys.path.insert(0, os.path.join(ROOT, "tests", "reference"))
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from gen_surface import phase_np  # noqa: E402  (the references' own phase functions)


from area_ray_outer import basis, sphere_radiance, unit  # noqa: E402  (the method's rule, as the study of it has it)


def cap_rule(x, c, radius, radiance, phase, d, sigma_t, n_phi, n_psi):
    """The method's rule: polar about the centre's direction, sin β = sin α sin φ."""
    rule = [np.polynomial.legendre.leggauss(k) for k in (n_phi, n_psi)]
    return sphere_radiance(x, c, radius, {"L": radiance, "p": 1, "P": lambda mu: phase(np.minimum(mu, 1.0))}, d, sigma_t, rule)


def peak_rule(x, c, radius, radiance, phase, d, sigma_t, n_theta, n_psi, scale):
    """Polar about d where d is inside the cap (else the method's rule)."""
    v = c - x
    dist_c = np.linalg.norm(v)
    a = v / dist_c
    sin_a = radius / dist_c
    cos_a = math.sqrt(max(1 - sin_a * sin_a, 0))
    cos_p = a @ d
    if cos_p <= cos_a:
        return cap_rule(x, c, radius, radiance, phase, d, sigma_t, n_theta, n_psi)
    u, w = basis(d)
    off = a - cos_p * d
    sin_p = np.linalg.norm(off)
    psi_a = math.atan2(off @ w, off @ u) if sin_p > 0 else 0.0
    xp, wp = np.polynomial.legendre.leggauss(n_psi)
    psi, w_psi = psi_a + (xp + 1) * np.pi, wp * np.pi
    # the rim in each ψ: cos θ cos β_p + sin θ sin β_p cos(ψ − ψ_a) = cos α
    big_a, big_b = cos_p, sin_p * np.cos(psi - psi_a)
    theta_max = np.arctan2(big_b, big_a) + np.arccos(np.clip(cos_a / np.hypot(big_a, big_b), -1, 1))
    xg, wg = np.polynomial.legendre.leggauss(n_theta)
    g_max = np.arctan(theta_max / scale)
    g = g_max[:, None] * (xg[None, :] + 1) / 2
    w_g = g_max[:, None] / 2 * wg[None, :]
    theta = scale * np.tan(g)
    d_theta = scale / np.cos(g) ** 2
    toward_a = np.cos(theta) * cos_p + np.sin(theta) * sin_p * np.cos(psi - psi_a)[:, None]
    dist = dist_c * toward_a - np.sqrt(np.maximum(radius * radius - dist_c * dist_c * (1 - toward_a * toward_a), 0))
    f = radiance * np.exp(-sigma_t * dist) * phase(np.cos(theta)) * np.sin(theta) * d_theta
    return np.sum(w_psi[:, None] * w_g * f)


def ray_integral(d, phase, inside, n_ray):
    """σs ∫ e^{−σt t} S(t d) dt from the origin to ∞ by `inside(x)` = S(x)."""
    o, c, radius, sigma_s, sigma_t = np.zeros(3), np.array([6.0, 1.5, -0.5]), 0.8, 0.05, 0.08
    x_h = (c - o) @ d
    h_eff = math.hypot(np.linalg.norm(c - o - x_h * d), radius)
    t_end = 40 / sigma_t + np.linalg.norm(c - o) + radius
    knots, hidden = [0.0, t_end, x_h], []
    b = (o - c) @ d
    disc = b * b - ((o - c) @ (o - c) - radius * radius)
    if disc > 0:
        hidden = [(-b - math.sqrt(disc), -b + math.sqrt(disc))]
        knots += list(hidden[0])
    knots = sorted(k for k in knots if 0.0 <= k <= t_end)
    xn, wn = np.polynomial.legendre.leggauss(n_ray)
    total = 0.0
    for lo, hi in zip(knots[:-1], knots[1:]):
        if any(a <= 0.5 * (lo + hi) <= b for a, b in hidden):
            continue
        t_lo, t_hi = math.atan2(lo - x_h, h_eff), math.atan2(hi - x_h, h_eff)
        for k in range(4):
            a, b = t_lo + (t_hi - t_lo) * k / 4, t_lo + (t_hi - t_lo) * (k + 1) / 4
            th = a + (b - a) * (xn + 1) / 2
            t = x_h + h_eff * np.tan(th)
            s = np.array([inside(o + ti * d) for ti in t])
            total += np.sum(wn * (b - a) / 2 * h_eff / np.cos(th) ** 2 * np.exp(-sigma_t * t) * s)
    return sigma_s * total


def main():
    c, radius, radiance, sigma_t = np.array([6.0, 1.5, -0.5]), 0.8, 2.0, 0.08
    print("| ray towards | g | reference | finer | cap rule 16 × 32 | peak rule 16 × 32, s = κ | s = 2κ | 16 × 16, s = κ |")
    print("|---|---|---|---|---|---|---|---|")
    for label, towards in (("centre", c), ("half the radius off", c + [0, 0.5, 0]), ("the limb", c + [0, 0.75, 0.2]),
                           ("just past the limb", c + [0, 0.9, 0]), ("past the limb", c + [0, 1.2, 0])):
        d = unit(towards)
        for g in (0.5, 0.9, 0.95, 0.99):
            phase = phase_np({"kind": "henyey_greenstein", "g": g})
            kappa = (1 - g) / math.sqrt(g)
            peak = lambda n1, n2, s: (lambda x: peak_rule(x, c, radius, radiance, phase, d, sigma_t, n1, n2, s))
            reference = ray_integral(d, phase, peak(64, 64, kappa), 32)
            finer = ray_integral(d, phase, peak(96, 96, kappa), 48)
            errors = [abs(ray_integral(d, phase, f, 24) / reference - 1) for f in (
                lambda x: cap_rule(x, c, radius, radiance, phase, d, sigma_t, 16, 32), peak(16, 32, kappa), peak(16, 32, 2 * kappa), peak(16, 16, kappa))]
            print(f"| {label} | {g} | {reference:.8e} | {abs(finer / reference - 1):.1e} | " + " | ".join(f"{e:.1e}" for e in errors) + " |")


if __name__ == "__main__":
    main()
