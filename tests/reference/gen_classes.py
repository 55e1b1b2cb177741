#!/usr/bin/env python3
"""Independent references for the hard scene classes: peaked phase functions, narrow beams and
cone edges, a light next to the ray, long rays, thick media, lights behind the camera, and the
benchmark's street lamp (isotropic and anisotropic).

Writes classes.jsonl next to this file: scene records (README "Scene records") with
  "category"    the class,
  "in_scatter"  the air-light integral (docs/DESIGN.md §1) by mpmath tanh-sinh quadrature at
                30 digits,
  "scale"       the same integral with F = D·P replaced by its maximum over the segment (the
                error floor of the accuracy targets: error / max(|exact|, tau·scale)).
Every input number is exactly representable in binary32, so one file serves the f32 and the
f64 kernel.

Nothing here uses the kernel's closed forms. The integral is taken in the angle seen from the
light, t = x_h + h·tan(theta), dt/r^2 = dtheta/h (an exact change of variables), with
breakpoints at the light's foot, where a cone edge is crossed, at the beam's extreme cosines, at
theta = ±(pi/2 − 2^-k) (graded toward the ends, where the Henyey–Greenstein peaks and the
extinction's boundary layers sit) and where the extinction exponent has grown by 2^-6 … 600.
Each scene is integrated twice (degree 7 on those intervals, degree 9 with every interval
halved) and kept only if the two agree to 1e-15 of max(|value|, 1e-10·scale).

Usage: python3 tests/reference/gen_classes.py     (mpmath==1.3.0; about 10 minutes, 2 cores)
"""
import math
import os
import random
import struct
import sys
from multiprocessing import Pool

import mpmath as mp

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from gen_reference import angle_breakpoints, light_angle, parse, unit, write_records  # noqa: E402  (the same record reading, D and P as there)

HERE = os.path.dirname(os.path.abspath(__file__))
DPS = 30


def f32(x):
    return struct.unpack("f", struct.pack("f", x))[0]


def f32v(v):
    return [f32(x) for x in v]


def reference(rec):
    """(value, scale) of one record, or None if the two quadratures disagree."""
    mp.mp.dps = DPS
    o, d, t0, t1, ss, st, p, inten, dist, a, D, P, xh, perp, h = parse(rec)
    assert h > 0
    d_el, d_c, th0, th1 = light_angle(d, t0, t1, a, xh, perp, h)

    def F(th):
        # (x − p)/r = sin(th) d + cos(th) n
        c = mp.sin(th) * d_el + mp.cos(th) * d_c
        return D(c) * P(-mp.sin(th))

    # extinction e^{-sigma_t (t - t0 + r)}, divided by its largest value (at theta0) so that
    # mpmath's absolute error control is relative to the integral's scale
    e0 = st * h / mp.cos(th0)

    def weight(th):
        if th >= mp.pi / 2:
            return mp.mpf(0)
        t = xh + h * mp.tan(th)
        return mp.exp(-st * (t - t0) - st * h / mp.cos(th) + e0)

    # the foot, c's peaks and a cone's edges
    pts, add = angle_breakpoints(th0, th1, d_el, d_c, dist, (-1, 0, 1), (-2, -1, 0, 1, 2))
    for k in range(0, 60):
        add(mp.pi / 2 - mp.mpf(2) ** -k)
        add(-mp.pi / 2 + mp.mpf(2) ** -k)
    # extinction: sigma_t (t − t0 + r) = sigma_t h tan(theta/2 + pi/4) + const grows
    # monotonically; breakpoints where it has grown by k from its value at theta0
    big_h = st * h
    if big_h > 0:
        y0 = mp.tan(th0 / 2 + mp.pi / 4)
        for k in [mp.mpf(2) ** j for j in range(-6, 2)] + list(range(2, 41, 2)) + [60, 100, 200, 300, 600]:
            add(2 * mp.atan(y0 + k / big_h) - mp.pi / 2)
    pts = sorted(pts)

    def integrate(f, points, degree):
        return mp.quad(f, points, maxdegree=degree)

    fine = []
    for i in range(len(pts) - 1):
        fine.append(pts[i])
        fine.append((pts[i] + pts[i + 1]) / 2)
    fine.append(pts[-1])
    # largest F: dense samples, the breakpoints, then a golden-section polish
    cand = list(pts) + [th0 + (th1 - th0) * i / 4000 for i in range(4001)]
    best = max(cand, key=F)
    lo, hi = max(th0, best - (th1 - th0) / 4000), min(th1, best + (th1 - th0) / 4000)
    fmax = F(best)
    if hi > lo:
        gr = (mp.sqrt(5) - 1) / 2
        x1, x2 = hi - gr * (hi - lo), lo + gr * (hi - lo)
        for _ in range(80):
            if F(x1) > F(x2):
                hi = x2
            else:
                lo = x1
            x1, x2 = hi - gr * (hi - lo), lo + gr * (hi - lo)
        fmax = max(fmax, F((lo + hi) / 2))
    if fmax == 0:
        return "dark"  # F = 0 on the whole segment (outside a cone): nothing to measure
    f_int = lambda th: weight(th) * F(th) / fmax
    v1 = integrate(f_int, pts, 7)
    v2 = integrate(f_int, fine, 9)
    w2 = integrate(weight, fine, 9)
    pref = ss * inten / h * mp.exp(-e0) * fmax
    scale = pref * w2
    value = pref * v2
    if abs(v1 - v2) * pref > mp.mpf("1e-15") * max(abs(value), mp.mpf("1e-10") * scale):
        return None
    return value, scale


# ---------------------------------------------------------------- scene generation
def geometry(rng, h, foot, t_min, t_max):
    """A ray along a random direction (f32 components), the light at perpendicular distance
    about h from the ray line with its foot near ray parameter `foot`; all inputs in f32."""
    d = f32v(unit(rng))
    dn = math.sqrt(sum(x * x for x in d))
    du = [x / dn for x in d]
    o = f32v([rng.uniform(-20, 20) for _ in range(3)])
    q = unit(rng)
    dq = sum(q[i] * du[i] for i in range(3))
    q = [q[i] - dq * du[i] for i in range(3)]
    qn = math.sqrt(sum(x * x for x in q))
    p = f32v([o[i] + foot * du[i] + h * q[i] / qn for i in range(3)])
    tmax = None if t_max is None else f32(t_max)
    return {"origin": o, "dir": d, "t_min": f32(t_min), "t_max": tmax}, p, q


def record(rng, category, ray, p, st, phase, light):
    return {
        "category": category,
        "ray": ray,
        "medium": {"sigma_s": f32(rng.uniform(0.01, 1.0)), "sigma_t": f32(st)},
        "light": {"position": p, "intensity": f32(rng.uniform(0.5, 500)), "distribution": light},
        "phase": phase,
    }


OMNI = {"kind": "isotropic"}


def hg(g):
    return {"kind": "henyey_greenstein", "g": f32(g)}


def beam_axis(rng, ray_dir, q, spread):
    """An axis near the plane of the ray and the light (so the beam crosses the ray)."""
    ang = rng.uniform(0, 2 * math.pi)
    v = [math.cos(ang) * ray_dir[i] + math.sin(ang) * q[i] for i in range(3)]
    w = unit(rng)
    v = [v[i] + spread * w[i] for i in range(3)]
    return f32v(v)


def scenes():
    rng = random.Random(20261129)
    out = []

    def shape(i):
        """A geometry of one of five kinds, cycling: straddling, light ahead near the line
        (looking into the light), infinite ray, segment after the foot, light behind."""
        kind = i % 5
        h = 10 ** rng.uniform(-1.5, 0.7)
        st = 10 ** rng.uniform(-3, -0.5)
        if kind == 0:
            t1 = rng.uniform(5, 60)
            return geometry(rng, h, rng.uniform(0.1, 0.9) * t1, 0.0, t1), st
        if kind == 1:
            t1 = rng.uniform(2, 30)
            return geometry(rng, h * 0.1, t1 + rng.uniform(0.5, 20), 0.0, t1), st
        if kind == 2:
            return geometry(rng, h, rng.uniform(-5, 30), 0.0, None), st
        if kind == 3:
            t0 = rng.uniform(0, 10)
            return geometry(rng, h, t0 - rng.uniform(0, 5), t0, t0 + rng.uniform(1, 40)), st
        return geometry(rng, h, -rng.uniform(1, 30), 0.0, rng.uniform(5, 60)), st

    def add(category, n, make):
        for i in range(n):
            (ray, p, q), st = shape(i)
            phase, light = make(i, ray, q)
            out.append(record(rng, category, ray, p, st, phase, light))

    for g in (0.8, 0.9, 0.99):
        add(f"hg_{g}", 30, lambda i, ray, q, g=g: (hg(g if i % 3 else -g), OMNI))
    add("schlick_0.95", 20, lambda i, ray, q: ({"kind": "schlick", "k": f32(0.95 if i % 2 else -0.95)}, OMNI))
    add("cornette_shanks_0.95", 20, lambda i, ray, q: ({"kind": "cornette_shanks", "g": f32(0.95 if i % 2 else -0.9)}, OMNI))
    add("two_lobe_hg", 20, lambda i, ray, q: ({"kind": "two_lobe_henyey_greenstein", "g1": f32(0.95), "g2": f32(-0.8), "w": f32(rng.uniform(0.2, 0.9))}, OMNI))
    for pw in (16, 64):
        add(f"beam_c{pw}", 30, lambda i, ray, q, pw=pw: (
            [OMNI, hg(0.6), {"kind": "rayleigh"}][i % 3],
            {"kind": "two_lobed", "axis": beam_axis(rng, ray["dir"], q, 0.05 * (i % 4)), "power": pw}))
    add("rayleigh_beam", 20, lambda i, ray, q: ({"kind": "rayleigh"}, {"kind": "two_lobed", "axis": f32v(unit(rng)), "power": 2 * rng.randint(1, 32)}))

    def narrow_spot(i, ray, q):
        co = rng.uniform(0.5, 0.995)
        ci = min(co + 10 ** rng.uniform(-3, -1.5), 1.0)
        return ([OMNI, hg(0.8)][i % 2], {"kind": "spot", "axis": beam_axis(rng, ray["dir"], q, 0.1), "cos_inner": f32(ci), "cos_outer": f32(co)})
    add("spot_narrow", 30, narrow_spot)

    def phase_mix(i):
        return [hg(0.9), hg(-0.7), {"kind": "rayleigh"}, {"kind": "schlick", "k": f32(0.8)}][i % 4]

    # a light 1e-4 from the ray line, 1 to 50 units away
    for i in range(30):
        t1 = rng.uniform(5, 60)
        ray, p, q = geometry(rng, 1e-4, rng.uniform(-0.2, 1.2) * t1, 0.0, t1 if i % 3 else None)
        li = OMNI if i % 2 else {"kind": "two_lobed", "axis": f32v(unit(rng)), "power": 4}
        out.append(record(rng, "near_light", ray, p, 10 ** rng.uniform(-3, 0), phase_mix(i), li))
    # long rays: 10^3..10^6
    for i in range(30):
        t1 = 10 ** rng.uniform(3, 6)
        ray, p, q = geometry(rng, 10 ** rng.uniform(-1, 1), rng.uniform(-50, 200), 0.0, t1)
        li = OMNI if i % 2 else {"kind": "spot", "axis": f32v(unit(rng)), "cos_inner": f32(0.9), "cos_outer": f32(0.7)}
        out.append(record(rng, "long_ray", ray, p, 10 ** rng.uniform(-4, -1), phase_mix(i), li))
    # thick: sigma_t h from 1 to 1e3
    for i in range(30):
        h = 10 ** rng.uniform(-1, 1)
        ray, p, q = geometry(rng, h, rng.uniform(-2, 12), 0.0, rng.uniform(1, 20) if i % 4 else None)
        li = OMNI if i % 2 else {"kind": "two_lobed", "axis": f32v(unit(rng)), "power": 8}
        out.append(record(rng, "thick", ray, p, 10 ** rng.uniform(0, 3) / h, phase_mix(i), li))
    # light behind the camera
    for i in range(30):
        back = 10 ** rng.uniform(0, 2)
        ray, p, q = geometry(rng, 10 ** rng.uniform(-1, 0.5), -back, 0.0, rng.uniform(1, 50) if i % 3 else None)
        li = OMNI if i % 2 else {"kind": "spot", "axis": f32v(unit(rng)), "cos_inner": f32(0.95), "cos_outer": f32(0.8)}
        out.append(record(rng, "behind", ray, p, min(10 ** rng.uniform(-2, 0), 300 / back), phase_mix(i), li))
    # the benchmark's street lamp: camera at the origin looking down +x through a row of lamps
    # 1–4 units off the rays, thin to moderate fog; isotropic, and a c^4 beam pointing down in
    # Henyey–Greenstein g = 0.5 fog
    for aniso in (False, True):
        for i in range(32):
            d = f32v([1.0, 0.2 * rng.random() - 0.1, 0.2 * rng.random() - 0.1])
            ray = {"origin": [0.0, 0.0, 0.0], "dir": d, "t_min": 0.0, "t_max": f32(5.0 + 60.0 * rng.random())}
            p = f32v([40.0 * rng.random() - 5.0, 1.0 + 3.0 * rng.random(), rng.random()])
            li = {"kind": "two_lobed", "axis": [0.0, -1.0, 0.0], "power": 4} if aniso else OMNI
            ph = hg(0.5) if aniso else {"kind": "isotropic"}
            rec = record(rng, "street_aniso" if aniso else "street_iso", ray, p, 0.01 + 0.3 * rng.random(), ph, li)
            rec["medium"]["sigma_s"] = f32(0.05)
            rec["light"]["intensity"] = f32(100.0)
            out.append(rec)
    return out


def run_scene(rec):
    res = reference(rec)
    if res is None or res == "dark":
        return res
    rec = dict(rec)
    rec["in_scatter"], rec["scale"] = float(res[0]), float(res[1])
    return rec


def main():
    recs = scenes()
    with Pool(2) as pool:
        done = pool.map(run_scene, recs, chunksize=2)
    kept = [r for r in done if isinstance(r, dict)]
    dark = sum(1 for r in done if r == "dark")
    cats = write_records("classes.jsonl", kept)
    print(f"classes: {len(kept)} kept, {dark} dark (F = 0 on the segment), {len(done) - len(kept) - dark} dropped (quadratures disagreed); {cats}")


if __name__ == "__main__":
    main()
