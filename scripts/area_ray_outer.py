#!/usr/bin/env python3
"""A design study for area lights within a shader's loop budget (docs/DESIGN.md §12): the other
order of the double integral. The kernel's area lights (kernel/src/area.rs) integrate the
point-light ray integral over the emitter, and every point light is a loop of its own — more
than lavapipe's 65 535 loop iterations hold. Here the ray is outside and the emitter inside:

  L = σs ∫ e^{−σt(t − t0)} S(x(t)) dt,   S(x) = ∫ L_e c^{p−1} P(ω·d) e^{−σt |x − q|} dω

over the directions ω from x to the emitter's points q (`c` the cosine at q between its normal and
the way to x; `p` = 1 Lambertian, or the cosine lobe's power), so that one evaluation is an `exp`
and a phase function, with no loop of its own.

* The ray: globally adaptive Gauss–Kronrod 7/15 (QUADPACK's QAG, kernel/src/extended.rs
  GAUSS_KRONROD_15) in the angle seen from the emitter's centre, `t − x_h = h' tan θ` with
  `h' = hypot(h, size)`, on pieces split at the centre's foot, where the ray crosses a flat
  emitter's plane and where it enters or leaves a sphere (the part inside gets 0); cut where the extinction from `t0` exceeds 16 past the
  emitter's distance from the origin. Until the summed `|K15 − G7|` is within the tolerance of
  the value or the panels reach their bound.
* A flat emitter: polar coordinates about its point `q*` nearest `x`'s foot on the plane (the
  foot itself inside), `r = ρ0 tan γ`, `ρ0 = |x − q*|` (the `1/d³` of `dω = z dA/d³` made smooth),
  a rectangle as the triangles from `q*` to its edges; Gauss–Legendre `n_r × n_ψ` each.
* A sphere: the cap it subtends, half-angle `α`, about the direction of its centre, with
  `sin β = sin α sin φ` (the distance to the surface `D cos β − R cos φ` has no square root left at
  the cap's rim; the emitted cosine is `cos φ`); Gauss–Legendre `n_φ × n_ψ`.

Prints, per configuration, the largest and median relative error over tests/reference/area.jsonl
(nested mpmath/Gauss–Legendre references, tests/reference/gen_area.py), the ray panels taken and
the evaluations of the emitter's integrand (a panel's 15 nodes each take the inner rule, once
per triangle of a rectangle).

Usage: python3 scripts/area_ray_outer.py N_R,N_PSI TOLERANCE,MAX_PANELS …    (numpy)
       e.g. python3 scripts/area_ray_outer.py 8,12 1e-3,8 1e-4,16
"""
import json
import math
import os
import sys

import numpy as np

ROOT = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..")
sys.path.insert(0, os.path.join(ROOT, "tests", "reference"))
from gen_surface import phase_np  # noqa: E402  (the references' own phase functions)

# QUADPACK qk15 (Piessens et al. 1983): (node, Kronrod weight, Gauss weight or 0), node ≥ 0
QK15 = [(0.991455371120812639, 0.022935322010529225, 0.0), (0.949107912342758525, 0.063092092629978553, 0.129484966168869693),
        (0.864864423359769073, 0.104790010322250184, 0.0), (0.741531185599394440, 0.140653259715525919, 0.279705391489276668),
        (0.586087235467691130, 0.169004726639267903, 0.0), (0.405845151377397167, 0.190350578064785410, 0.381830050505118945),
        (0.207784955007898468, 0.204432940075298892, 0.0), (0.0, 0.209482141084727828, 0.417959183673469388)]
GK_X = np.array([x for x, _, _ in QK15] + [-x for x, _, _ in QK15[-2::-1]])
GK_K = np.array([k for _, k, _ in QK15] + [k for _, k, _ in QK15[-2::-1]])
GK_G = np.array([g for _, _, g in QK15] + [g for _, _, g in QK15[-2::-1]])
# the cut: the extinction exponent past the emitter's distance
CUT = 16.0
# evaluations of the integrand S's (the running count)
EVALUATIONS = [0]


def unit(v):
    v = np.asarray(v, float)
    return v / np.linalg.norm(v)


def basis(n):
    a = np.array([1.0, 0, 0]) if abs(n[0]) < 0.9 else np.array([0, 1.0, 0])
    e1 = unit(np.cross(n, a))
    return e1, np.cross(n, e1)


def sphere_radiance(x, c, radius, em, d, st, rule):
    """S(x) of a sphere (x outside it)."""
    (xf, wf), (xp, wp) = rule
    v = c - x
    dist_c = np.linalg.norm(v)
    a = v / dist_c
    e1, e2 = basis(a)
    sin_a = radius / dist_c
    phi, w_phi = (xf + 1) * np.pi / 4, wf * np.pi / 4
    psi, w_psi = (xp + 1) * np.pi, wp * np.pi
    sb = sin_a * np.sin(phi)
    cb = np.sqrt(1 - sb * sb)
    jac = sin_a ** 2 * np.sin(phi) * np.cos(phi) / cb
    dist = dist_c * cb - radius * np.cos(phi)
    mu = cb[:, None] * (a @ d) + sb[:, None] * (np.cos(psi)[None, :] * (e1 @ d) + np.sin(psi)[None, :] * (e2 @ d))
    f = (em["L"] * np.cos(phi) ** (em["p"] - 1) * jac * np.exp(-st * dist))[:, None] * em["P"](mu)
    EVALUATIONS[0] += f.size
    return w_phi @ f @ w_psi


def flat_radiance(x, fl, em, d, st, rule):
    """S(x) of a disc or a parallelogram, polar about q*."""
    (xr, wr), (xp, wp) = rule
    n, e1, e2, origin = fl["n"], fl["e1"], fl["e2"], fl["origin"]
    z = (x - origin) @ n
    if z <= 0:
        return 0.0
    foot = np.array([(x - origin) @ e1, (x - origin) @ e2])
    sectors = []  # (ψ nodes, ψ weights, r_max(ψ), q*)
    if fl["radius"] is not None:
        radius = fl["radius"]
        rf = np.linalg.norm(foot)
        if rf <= radius:
            q = foot
            psi, w_psi = (xp + 1) * np.pi, wp * np.pi
            b = q[0] * np.cos(psi) + q[1] * np.sin(psi)
            r_max = -b + np.sqrt(b * b + radius * radius - rf * rf)
        else:
            q = foot * radius / rf
            pc = math.atan2(-q[1], -q[0])
            psi, w_psi = pc + xp * np.pi / 2, wp * np.pi / 2
            r_max = 2 * radius * np.cos(psi - pc)
        sectors.append((psi, w_psi, r_max, q))
    else:
        V = fl["verts"]
        s = np.linalg.solve(np.array([V[1] - V[0], V[3] - V[0]]).T, foot - V[0])
        if 0 <= s[0] <= 1 and 0 <= s[1] <= 1:
            q = foot
        else:
            cands = []
            for k in range(4):
                A, B = V[k], V[(k + 1) % 4]
                u = np.clip((foot - A) @ (B - A) / ((B - A) @ (B - A)), 0, 1)
                cands.append(A + u * (B - A))
            q = min(cands, key=lambda Q: np.linalg.norm(Q - foot))
        for k in range(4):
            A, B = V[k] - q, V[(k + 1) % 4] - q
            cross = A[0] * B[1] - A[1] * B[0]
            if cross <= 0:
                continue  # an edge through q*
            pa = math.atan2(A[1], A[0])
            span = (math.atan2(B[1], B[0]) - pa) % (2 * np.pi)
            E = B - A
            el = np.linalg.norm(E)
            psi, w_psi = pa + span * (xp + 1) / 2, wp * span / 2
            r_max = (cross / el) / (np.cos(psi) * E[1] / el - np.sin(psi) * E[0] / el)
            sectors.append((psi, w_psi, r_max, q))
    total = 0.0
    for psi, w_psi, r_max, q in sectors:
        off = q - foot
        rho0 = math.sqrt(z * z + off @ off)
        g_max = np.arctan(r_max / rho0)
        g = g_max[:, None] * (xr[None, :] + 1) / 2
        w = g_max[:, None] / 2 * wr[None, :]
        r = rho0 * np.tan(g)
        dr = rho0 / np.cos(g) ** 2
        px = off[0] + r * np.cos(psi)[:, None]
        py = off[1] + r * np.sin(psi)[:, None]
        dist = np.sqrt(z * z + px * px + py * py)
        mu = (px * (e1 @ d) + py * (e2 @ d) - z * (n @ d)) / dist
        f = em["L"] * (z / dist) ** (em["p"] - 1) * np.exp(-st * dist) * em["P"](mu) * z / dist ** 3 * r * dr
        total += np.sum(w_psi[:, None] * w * f)
        EVALUATIONS[0] += f.size
    return total


def evaluate(rec, inner, tolerance, max_panels):
    """The record's in-scattered radiance and the ray panels taken."""
    o, d = np.array(rec["ray"]["origin"]), unit(rec["ray"]["dir"])
    t0 = rec["ray"].get("t_min", 0.0)
    t1 = rec["ray"].get("t_max")
    t1 = math.inf if t1 is None else t1
    ss, st = rec["medium"]["sigma_s"], rec["medium"]["sigma_t"]
    light = rec["light"]
    em = {"L": light["radiance"], "p": (light.get("emission") or {}).get("power", 1), "P": phase_np(rec["phase"])}
    rule = [np.polynomial.legendre.leggauss(k) for k in inner]
    shape = light["shape"]
    if shape == "sphere":
        c, size, n = np.array(light["center"]), light["radius"], None
        radiance = lambda x: sphere_radiance(x, c, size, em, d, st, rule)
    else:
        if shape == "disc":
            c, n, size = np.array(light["center"]), unit(light["normal"]), light["radius"]
            e1, e2 = basis(n)
            fl = {"n": n, "e1": e1, "e2": e2, "origin": c, "radius": size}
        else:
            corner, eu, ev = (np.array(light[k]) for k in ("corner", "edge_u", "edge_v"))
            n = unit(np.cross(eu, ev))
            e1 = unit(eu)
            e2 = np.cross(n, e1)
            verts = [np.zeros(3), eu, eu + ev, ev]
            fl = {"n": n, "e1": e1, "e2": e2, "origin": corner, "radius": None, "verts": [np.array([v @ e1, v @ e2]) for v in verts]}
            c, size = corner + (eu + ev) / 2, np.linalg.norm(eu + ev) / 2
        radiance = lambda x: flat_radiance(x, fl, em, d, st, rule)
    x_h = (c - o) @ d
    h = np.linalg.norm(c - o - x_h * d)
    h_eff = math.hypot(h, size)
    t_end = min(t1, t0 + CUT / st + np.linalg.norm(c - o) + size) if st > 0 else t1
    knots, inside = [t0, t_end, x_h], []
    if n is not None:
        if d @ n != 0:
            knots.append((c - o) @ n / (d @ n))
    else:
        b = (o - c) @ d
        disc = b * b - ((o - c) @ (o - c) - size * size)
        if disc > 0:
            inside = [(-b - math.sqrt(disc), -b + math.sqrt(disc))]
            knots += list(inside[0])
    knots = sorted(k for k in knots if t0 <= k <= t_end)

    def panel(a, b):
        th = 0.5 * (a + b) + 0.5 * (b - a) * GK_X
        t = x_h + h_eff * np.tan(th)
        f = h_eff / np.cos(th) ** 2 * np.exp(-st * (t - t0)) * np.array([radiance(o + ti * d) for ti in t])
        k, g = 0.5 * (b - a) * (GK_K @ f), 0.5 * (b - a) * (GK_G @ f)
        return [abs(k - g), a, b, k]

    panels = []
    for a, b in zip(knots[:-1], knots[1:]):
        if b > a and not any(lo <= 0.5 * (a + b) <= hi for lo, hi in inside):
            panels.append(panel(math.atan2(a - x_h, h_eff), math.atan2(b - x_h, h_eff) if math.isfinite(b) else math.pi / 2))
    while len(panels) < max_panels and sum(p[0] for p in panels) > tolerance * abs(sum(p[3] for p in panels)):
        panels.sort(key=lambda p: -p[0])
        _, a, b, _ = panels.pop(0)
        panels += [panel(a, 0.5 * (a + b)), panel(0.5 * (a + b), b)]
    return ss * sum(p[3] for p in panels), len(panels)


def main(args):
    inner = tuple(int(k) for k in args[0].split(","))
    recs = [json.loads(line) for line in open(os.path.join(ROOT, "tests", "reference", "area.jsonl"))]
    for cfg in args[1:]:
        tol, max_panels = cfg.split(",")
        errors, panels, evaluations = [], [], []
        for rec in recs:
            EVALUATIONS[0] = 0
            value, k = evaluate(rec, inner, float(tol), int(max_panels))
            evaluations.append(EVALUATIONS[0])
            errors.append(abs(value / rec["in_scatter"] - 1))
            panels.append(k)
        w = int(np.argmax(errors))
        print(f"inner {inner[0]}x{inner[1]}, ray tolerance {tol}, at most {max_panels} panels: largest error {max(errors):.1e} "
              f"({recs[w]['category']} {recs[w]['light']['shape']}), median {np.median(errors):.1e}; "
              f"ray panels mean {np.mean(panels):.1f}, most {max(panels)}; evaluations mean {np.mean(evaluations):.0f}, most {max(evaluations)} "
              f"({len(recs)} records)")


if __name__ == "__main__":
    main(sys.argv[1:])
