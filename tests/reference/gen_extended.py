#!/usr/bin/env python3
"""References for segment lights (docs/DESIGN.md §10), by nested mpmath quadrature.

Writes extended.jsonl next to this file: JSON-lines scene records (docs/DESIGN.md §6) whose
light is a segment, {"shape": "segment", "a": [..], "b": [..], "intensity": I,
"distribution": {..}}, with
  "category"    the class (near: the emitter passes close to the ray; far; behind: the emitter
                behind the camera; end_on: the emitter along the ray's line, behind the camera;
                thick: optical distances up to 30; short: a tube much shorter than its distance),
  "in_scatter"  L = ∫_0^ℓ L_point(a + s e) ds, L_point the air-light integral of a point light of
                intensity I (docs/DESIGN.md §1).
The inner integral is taken in the angle θ seen from the light (t − x_h = h tan θ, split at the
foot, where a cone's edge is crossed and where the extinction exponent has grown by 1, 2, 4,
…, 64), the outer one over s split at the emitter's closest approach to the ray line s* (and at
s* ± 10^k ρ*/sin α, the peak's widths), and where the light's foot passes the ray's ends; both by
tanh-sinh, and the outer once more by Gauss–Legendre: a record is kept only where the two outer
rules agree to 1e-12.

Usage: python3 tests/reference/gen_extended.py      (mpmath==1.3.0; some minutes on 2 cores)
"""
import math
import os
import random
import sys
from multiprocessing import Pool

import mpmath as mp

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from gen_reference import angle_breakpoints, f32, light_angle, norm, parse, unit, write_records  # noqa: E402

DPS = 20


def point_light(o, d, t0, t1, ss, st, p, inten, dist, a, D, P):
    """L_point for a light at p (mpf vectors; d and a unit)."""
    op = [p[i] - o[i] for i in range(3)]
    xh = sum(op[i] * d[i] for i in range(3))
    perp = [o[i] + xh * d[i] - p[i] for i in range(3)]
    h = norm(perp)
    if h == 0:
        # on the ray's line, outside the segment: ∫ e^{−σt(t − t0 + |t − x_h|)} F / (t − x_h)² dt
        sgn = 1 if t0 > xh else -1
        f = lambda t: mp.exp(-st * (t - t0 + abs(t - xh))) / (t - xh) ** 2 * D(sgn * sum(d[i] * a[i] for i in range(3))) * P(-sgn)
        return ss * inten * mp.quad(f, [t0, t1])
    d_el, d_c, th0, th1 = light_angle(d, t0, t1, a, xh, perp, h)

    def f(th):
        if th >= mp.pi / 2:
            return mp.mpf(0)
        c = mp.sin(th) * d_el + mp.cos(th) * d_c
        t = xh + h * mp.tan(th)
        return mp.exp(-st * (t - t0) - st * h / mp.cos(th)) * D(c) * P(-mp.sin(th))

    # the foot and a cone's edges
    pts, add = angle_breakpoints(th0, th1, d_el, d_c, dist, (), (-1, 0, 1))
    big_h = st * h
    if big_h > 0:
        y0 = mp.tan(th0 / 2 + mp.pi / 4)
        for k in (1, 2, 4, 8, 16, 32, 64):
            add(2 * mp.atan(y0 + k / big_h) - mp.pi / 2)
    return ss * inten / h * mp.quad(f, sorted(pts))


def reference(rec):
    mp.mp.dps = DPS
    # the ray, medium, distribution and phase as gen_reference reads them (a point light at a)
    lt = rec["light"]
    point = {**rec, "light": {"position": lt["a"], "intensity": lt["intensity"], "distribution": lt.get("distribution")}}
    o, d, t0, t1, ss, st, _, inten, dist, ax, D, P, _, _, _ = parse(point)
    la, lb = [mp.mpf(x) for x in lt["a"]], [mp.mpf(x) for x in lt["b"]]
    ab = [lb[i] - la[i] for i in range(3)]
    length = norm(ab)
    e = [x / length for x in ab]

    def g(s):
        p = [la[i] + s * e[i] for i in range(3)]
        return point_light(o, d, t0, t1, ss, st, p, inten, dist, ax, D, P)

    # the emitter's closest approach to the ray's line, the peak's width, the foot's crossings
    w0 = [la[i] - o[i] for i in range(3)]
    c = sum(e[i] * d[i] for i in range(3))
    ae, ad = sum(e[i] * w0[i] for i in range(3)), sum(d[i] * w0[i] for i in range(3))
    pts = {mp.mpf(0), length}

    def add(s):
        if 0 < s < length:
            pts.add(s)

    sin2 = 1 - c * c
    if sin2 > 0:
        s_star = (c * ad - ae) / sin2
        t_star = (ad - c * ae) / sin2
        gap = [w0[i] + s_star * e[i] - t_star * d[i] for i in range(3)]
        width = norm(gap) / mp.sqrt(sin2)
        add(s_star)
        for k in range(-3, 4):
            add(s_star + 10 ** k * width)
            add(s_star - 10 ** k * width)
    if c != 0:
        add((t0 - ad) / c)
        if t1 != mp.inf:
            add((t1 - ad) / c)
    pts = sorted(pts)
    v1 = mp.quad(g, pts, maxdegree=6)
    v2 = mp.quad(g, pts, method="gauss-legendre", maxdegree=6)
    if abs(v1 - v2) > mp.mpf("1e-12") * abs(v1):
        return None
    return v1


def run(rec):
    v = reference(rec)
    if v is None:
        return None
    rec["in_scatter"] = float(v)
    return rec


def scenes():
    rng = random.Random(20261130)
    out = []
    phases = [{"kind": "isotropic"}, {"kind": "henyey_greenstein", "g": f32(0.8)}, {"kind": "rayleigh"}]
    dists = [None, {"kind": "two_lobed", "axis": [0.0, -1.0, 0.0], "power": 4},
             {"kind": "spot", "axis": [0.0, -1.0, 0.0], "cos_inner": f32(0.9), "cos_outer": f32(0.6)}]

    def add(category, ray, a, b, st, i, dist=None):
        rec = {"category": category, "ray": ray, "medium": {"sigma_s": f32(0.05), "sigma_t": f32(st)},
               "light": {"shape": "segment", "a": [f32(x) for x in a], "b": [f32(x) for x in b], "intensity": f32(10.0)},
               "phase": phases[i % 3]}
        dist = dist or dists[(i // 3) % 3]
        if dist is not None:
            rec["light"]["distribution"] = dist
        out.append(rec)

    ray = lambda t1: {"origin": [0.0, 0.0, 0.0], "dir": [1.0, 0.0, 0.0], "t_min": 0.0, "t_max": t1}
    for i in range(6):
        # a tube across the ray, 1e-3 … 1e-1 from it
        off = 10 ** rng.uniform(-3, -1)
        x = rng.uniform(5, 25)
        add("near", ray(f32(30.0) if i % 2 else None), [x, off, -2.0], [x + rng.uniform(-1, 1), off, 2.0], 10 ** rng.uniform(-2, -0.5), i)
    for i in range(6):
        # a tube 1–4 above the ray, in front, of any orientation
        c = [rng.uniform(2, 40), rng.uniform(1, 4), rng.uniform(-2, 2)]
        u = unit(rng)
        half = rng.uniform(0.5, 3)
        add("far", ray(f32(rng.uniform(10, 60)) if i % 2 else None), [c[k] - half * u[k] for k in range(3)], [c[k] + half * u[k] for k in range(3)], 10 ** rng.uniform(-2, -0.5), i)
    for i in range(4):
        # behind the camera
        c = [-rng.uniform(1, 10), rng.uniform(0.5, 3), rng.uniform(-1, 1)]
        u = unit(rng)
        add("behind", ray(f32(rng.uniform(10, 60))), [c[k] - u[k] for k in range(3)], [c[k] + u[k] for k in range(3)], 10 ** rng.uniform(-2, -0.5), i)
    along = [None, {"kind": "two_lobed", "axis": [1.0, 0.0, 0.0], "power": 4},
             {"kind": "spot", "axis": [1.0, 0.0, 0.0], "cos_inner": f32(0.9), "cos_outer": f32(0.6)}]
    for i in range(3):
        # along the ray's line, behind the camera (seen end-on), shining along it
        s0 = rng.uniform(0.5, 3)
        add("end_on", ray(f32(rng.uniform(10, 60)) if i % 2 else None), [-s0, 0.0, 0.0], [-s0 - rng.uniform(0.5, 5), 0.0, 0.0], 10 ** rng.uniform(-2, -0.5), i, along[i])
    for i in range(6):
        # thick: optical distances up to 30
        c = [rng.uniform(2, 10), rng.uniform(0.5, 2), rng.uniform(-1, 1)]
        u = unit(rng)
        add("thick", ray(f32(rng.uniform(5, 20))), [c[k] - u[k] for k in range(3)], [c[k] + u[k] for k in range(3)], 10 ** rng.uniform(0, 1), i)
    for i in range(3):
        # a short tube far away: close to a point light of intensity I·ℓ
        c = [rng.uniform(10, 40), rng.uniform(2, 5), rng.uniform(-1, 1)]
        u = unit(rng)
        add("short", ray(f32(60.0)), [c[k] - 0.005 * u[k] for k in range(3)], [c[k] + 0.005 * u[k] for k in range(3)], 0.05, i)
    return out


def main():
    with Pool(2) as pool:
        done = pool.map(run, scenes(), chunksize=1)
    kept = [r for r in done if r is not None]
    cats = write_records("extended.jsonl", kept)
    print(f"extended: {len(kept)} kept, {len(done) - len(kept)} dropped (the outer rules disagreed); {cats}")


if __name__ == "__main__":
    main()
