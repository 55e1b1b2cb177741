#!/usr/bin/env python3
"""References for surface radiance from air-light (docs/DESIGN.md §11), by nested quadrature.

Writes surface.jsonl next to this file: JSON-lines records
  {"surface": {"position": [..], "normal": [..], "brdf": {"kind": "lambert", "albedo": ρ}
               or {"kind": "phong", "k_s": k, "exponent": n, "view": [..]}},
   "medium": .., "light": {"position", "intensity", "distribution"}, "phase": ..,
   "category": the class, "surface_air_light": the value, "scale": the same integral with f_r
   replaced by its maximum (a Lambertian BRDF of that value; for a Lambertian record the value
   itself), the floor of the error measure where a lobe leaves the value many decades smaller}
with surface_air_light = ∫_{n·ω>0} L_a(s, ω) f_r(ω) (n·ω) dω, L_a the in-scattered radiance
along the ray from s in direction ω, t ∈ [0, ∞) (docs/DESIGN.md §1), f_r = ρ/π or
k (n+2)/(2π) max(0, r·ω)^n, r the mirror image of the view direction about the normal.

Independent of the kernel's method: every level is composite Gauss–Legendre in float64 on
panels placed by hand. Directions are taken about the light's direction ℓ from s (γ from ℓ, φ
about it); the outer integral over γ is split where the hemisphere's arc at γ changes kind, at a
Phong lobe's peak and arcs, and graded towards γ = 0 and around the lobe (and a two-lobed light's
axis, by its width 1/√p); the middle one over φ numerically on the arcs where f_r (n·ω) > 0 (no
closed form), graded about the lobe and the axis's azimuths; the inner
one, L_a, in the angle θ seen from the light (t − x_h = h tan θ), split at the foot, where the
extinction exponent has grown by 1, 2, 4, …, 64, and at a spot cone's edges. Each record is
computed twice, with 16 and 24 nodes per panel and 2 and 3 panels per piece over γ and φ (one
panel per piece over θ, whose pieces are octaves) — where those disagree, 24 and 3 against 32
and 4 —
and kept only if the two agree to 1e-11 and L_a along one random direction of its hemisphere
agrees to 1e-11 with mpmath's tanh-sinh (gen_extended.point_light).

Usage: python3 tests/reference/gen_surface.py     (numpy and mpmath; some minutes)
"""
import math
import random
import struct

import numpy as np

from gen_reference import write_jsonl


def f32(x):
    return struct.unpack("f", struct.pack("f", x))[0]


def f32v(v):
    return [f32(x) for x in v]


def unit(v):
    v = np.asarray(v, dtype=float)
    return v / np.linalg.norm(v)


def phase_np(ph):
    k = ph["kind"]
    hg = lambda g, mu: (1 - g * g) / (4 * np.pi * (1 + g * g - 2 * g * mu) ** 1.5)
    if k == "isotropic":
        return lambda mu: np.full_like(mu, 1 / (4 * np.pi))
    if k == "rayleigh":
        return lambda mu: 3 / (16 * np.pi) * (1 + mu * mu)
    if k == "henyey_greenstein":
        return lambda mu: hg(ph["g"], mu)
    if k == "two_lobe_henyey_greenstein":
        return lambda mu: ph["w"] * hg(ph["g1"], mu) + (1 - ph["w"]) * hg(ph["g2"], mu)
    raise ValueError(k)


def dist_np(d):
    k = d["kind"]
    if k == "isotropic":
        return lambda c: np.ones_like(c)
    if k == "two_lobed":
        return lambda c: c ** int(d["power"])
    if k == "spot":
        ci, co = d["cos_inner"], d["cos_outer"]

        def spot(c):
            x = np.clip((c - co) / (ci - co), 0.0, 1.0)
            return x * x * (3 - 2 * x)

        return spot
    raise ValueError(k)


def composite(a, b, q, m):
    """Nodes and weights of m Gauss–Legendre panels of q nodes on each [a_i, b_i] (arrays of the
    same shape S): arrays of shape S + (m*q,)."""
    x, w = np.polynomial.legendre.leggauss(q)
    a, b = np.asarray(a, float), np.asarray(b, float)
    edges = a[..., None] + (b - a)[..., None] * np.linspace(0, 1, m + 1)
    lo, hi = edges[..., :-1], edges[..., 1:]
    half = (hi - lo)[..., None] / 2
    nodes = (lo + hi)[..., None] / 2 + half * x
    weights = half * w
    shape = a.shape + (m * q,)
    return nodes.reshape(shape), weights.reshape(shape)


class Scene:
    def __init__(self, rec):
        s = rec["surface"]
        self.s = np.array(s["position"], float)
        self.n = unit(s["normal"])
        self.brdf = s["brdf"]
        lt = rec["light"]
        self.p = np.array(lt["position"], float)
        self.I = lt["intensity"]
        dist = lt.get("distribution") or {"kind": "isotropic"}
        self.dist = dist
        self.axis = unit(dist.get("axis", [0, 0, 1]))
        self.D = dist_np(dist)
        self.P = phase_np(rec.get("phase") or {"kind": "isotropic"})
        self.ss, self.st = rec["medium"]["sigma_s"], rec["medium"]["sigma_t"]
        op = self.p - self.s
        self.d = np.linalg.norm(op)
        self.l = op / self.d
        u = np.zeros(3)
        u[np.argmin(np.abs(self.l))] = 1
        self.e1 = unit(np.cross(self.l, u))
        self.e2 = np.cross(self.l, self.e1)
        if self.brdf["kind"] == "phong":
            v = unit(self.brdf["view"])
            self.r = unit(2 * np.dot(self.n, v) * self.n - v)

    def polar(self, v):
        x, y = np.dot(v, self.e1), np.dot(v, self.e2)
        return math.atan2(math.hypot(x, y), np.dot(v, self.l)), math.atan2(y, x)

    def directions(self, g, phi):
        return (np.cos(g)[..., None] * self.l
                + np.sin(g)[..., None] * (np.cos(phi)[..., None] * self.e1 + np.sin(phi)[..., None] * self.e2))

    def brdf_cos(self, w):
        cos = np.maximum(w @ self.n, 0.0)
        if self.brdf["kind"] == "lambert":
            return cos * self.brdf["albedo"] / np.pi
        n = self.brdf["exponent"]
        lobe = np.maximum(w @ self.r, 0.0) ** n
        return cos * self.brdf["k_s"] * (n + 2) / (2 * np.pi) * lobe

    def air_light_rays(self, W, q, m):
        """L_a for unit directions W (shape (M, 3))."""
        op = self.p - self.s
        xh = W @ op
        perp = xh[:, None] * W - op
        h = np.linalg.norm(perp, axis=1)
        d_el = W @ self.axis
        d_c = (perp / h[:, None]) @ self.axis
        th0 = np.arctan2(-xh, h)
        top = np.full_like(th0, np.pi / 2)
        pts = [th0, np.clip(np.zeros_like(th0), th0, top), top]
        big_h = self.st * h
        if self.st > 0:
            y0 = np.tan(th0 / 2 + np.pi / 4)
            for k in (1, 2, 4, 8, 16, 32, 64):
                pts.append(np.clip(2 * np.arctan(y0 + k / big_h) - np.pi / 2, th0, top))
        if self.dist["kind"] == "spot":
            R = np.hypot(d_el, d_c)
            phi = np.arctan2(d_el, d_c)
            for kk in (self.dist["cos_inner"], self.dist["cos_outer"]):
                acos = np.arccos(np.clip(kk / np.maximum(R, 1e-300), -1, 1))
                for sgn in (1, -1):
                    for turn in (-1, 0, 1):
                        pts.append(np.clip(phi + sgn * acos + 2 * np.pi * turn, th0, top))
        if self.dist["kind"] == "two_lobed":
            phi = np.arctan2(d_el, d_c)
            for turn in (-1, 0, 1):
                pts.append(np.clip(phi + np.pi * turn, th0, top))
        pts = np.sort(np.stack(pts, axis=1), axis=1)
        # octaves towards θ = π/2 (t = ∞), where e^{−σt h tan(θ/2 + π/4)} turns over within
        # ~σt h of the end (down to a 64th of that), and towards θ0 (a forward lobe's peak)
        start = np.maximum(th0, 0.0)
        octaves = [np.clip(np.pi / 2 - (np.pi / 2 - start) * 0.5 ** j, th0, top) for j in range(1, 48)]
        octaves = [np.where(np.pi / 2 - o >= big_h / 64, o, top) for o in octaves]
        octaves += [np.clip(th0 + (np.minimum(0.0, top) - th0) * 0.5 ** j, th0, top) for j in range(1, 12)]
        # the octaves tile [θ0, π/2] into pieces each smooth on its own scale: one panel each
        pts = np.sort(np.concatenate([pts, np.stack(octaves, axis=1)], axis=1), axis=1)
        th, wt = composite(pts[:, :-1], pts[:, 1:], q, 1)
        s, c = np.sin(th), np.cos(th)
        hh = h[:, None, None]
        t = xh[:, None, None] + hh * np.tan(th)
        r = hh / c
        f = self.D(s * d_el[:, None, None] + c * d_c[:, None, None]) * self.P(-s)
        with np.errstate(over="ignore", invalid="ignore"):
            e = np.where(self.st > 0, np.exp(-self.st * (t + r)), 1.0)
        total = np.sum(wt * f * e, axis=(1, 2))
        return self.ss * self.I / h * total

    def value(self, q, m):
        an, _ = self.polar(self.n)
        cuts = {abs(np.pi / 2 - an), np.pi - abs(np.pi / 2 - an)}
        lobe_w = None
        if self.brdf["kind"] == "phong":
            ar, _ = self.polar(self.r)
            cuts |= {abs(np.pi / 2 - ar), np.pi - abs(np.pi / 2 - ar), ar}
            lobe_w = 1 / math.sqrt(self.brdf["exponent"] + 1)
            for k in (0.1, 0.3, 1, 3):
                cuts |= {ar - k * lobe_w, ar + k * lobe_w}
        if self.brdf["kind"] == "phong":
            # where the two arcs' ends meet: the great circles n·ω = 0 and r·ω = 0 cross at ±u
            u = np.cross(self.n, self.r)
            if np.linalg.norm(u) > 1e-12:
                u = unit(u)
                cuts |= {math.acos(np.clip(np.dot(u, self.l), -1, 1)), math.acos(np.clip(-np.dot(u, self.l), -1, 1))}
        # a beam c^p: where the axis and its opposite lie from ℓ, graded by the lobe's width 1/√p
        beam_w = None
        if self.dist["kind"] == "two_lobed" and self.dist["power"] > 0:
            beam_w = 1 / math.sqrt(self.dist["power"])
            ga, _ = self.polar(self.axis)
            for c in (ga, np.pi - ga):
                cuts.add(c)
                for k in (0.3, 1, 3):
                    cuts |= {c - k * beam_w, c + k * beam_w}
        # towards the light: the extinction's and a forward lobe's peaks
        for k in range(-5, 1):
            cuts |= {10.0 ** k, 3 * 10.0 ** k}
        cuts = sorted(c for c in cuts if 0 < c < np.pi)
        edges = np.array([0.0] + cuts + [np.pi])
        # γ = a + (b − a)(3x² − 2x³) on each piece: where an arc opens or closes the middle
        # integral goes like |γ − γ*|^{3/2}, smooth in x
        a, b = edges[:-1, None], edges[1:, None]
        X, XW = composite(np.zeros(len(edges) - 1), np.ones(len(edges) - 1), q, m)
        G = a + (b - a) * (3 * X ** 2 - 2 * X ** 3)
        GW = XW * (b - a) * 6 * X * (1 - X)
        G, GW = G.ravel(), GW.ravel()
        omni = self.dist["kind"] == "isotropic"
        total = 0.0
        for g, gw in zip(G, GW):
            phis = self.phi_edges(g, lobe_w, beam_w)
            if not phis:
                continue
            a, b = np.array([x[0] for x in phis]), np.array([x[1] for x in phis])
            F, FW = composite(a, b, q, m)
            F, FW = F.ravel(), FW.ravel()
            W = self.directions(np.full_like(F, g), F)
            geo = self.brdf_cos(W)
            if omni:
                la = self.air_light_rays(W[:1], q, m)[0]
                inner = la * np.sum(FW * geo)
            else:
                keep = geo > 0
                la = np.zeros_like(geo)
                if keep.any():
                    la[keep] = self.air_light_rays(W[keep], q, m)
                inner = np.sum(FW * geo * la)
            total += gw * math.sin(g) * inner
        return total

    def phi_edges(self, g, lobe_w, beam_w=None):
        """The intervals of φ where f_r (n·ω) may be positive, tiled by the arcs' ends and (for
        a Phong lobe) graded about its peak, and (for a beam) about the azimuths of its axis,
        where L_a, a polynomial in cos(φ − φ_a), peaks."""
        edges = []
        if beam_w is not None:
            _, phi_a = self.polar(self.axis)
            for c in (phi_a, phi_a + math.pi):
                edges.append(c)
                for k in (0.3, 1, 3):
                    if k * beam_w < math.pi / 2:
                        edges += [c - k * beam_w, c + k * beam_w]

        def arc(v):
            a_, phi_c = self.polar(v)
            A, B = math.cos(a_) * math.cos(g), math.sin(a_) * math.sin(g)
            if B <= abs(A):
                return (phi_c, math.pi if A > 0 else 0.0)
            return (phi_c, math.acos(max(-1.0, min(1.0, -A / B))))

        phi_n, psi_n = arc(self.n)
        if psi_n == 0:
            return []
        if psi_n < math.pi:
            edges += [phi_n - psi_n, phi_n + psi_n]
        if lobe_w is not None:
            phi_r, psi_r = arc(self.r)
            if psi_r == 0:
                return []
            if psi_r < math.pi:
                edges += [phi_r - psi_r, phi_r + psi_r]
            a_r, _ = self.polar(self.r)
            width = lobe_w / math.sqrt(max(math.sin(a_r) * math.sin(g), 1e-12))
            edges.append(phi_r)
            for k in (0.1, 0.3, 1, 3):
                if k * width < math.pi:
                    edges += [phi_r - k * width, phi_r + k * width]
        lo, hi = phi_n - math.pi, phi_n + math.pi
        wrapped = sorted({lo, hi} | {lo + (e - lo) % (2 * math.pi) for e in edges})
        out = []
        for a, b in zip(wrapped[:-1], wrapped[1:]):
            if b > a:
                # n·ω and r·ω keep their signs between the edges: a piece is kept by their signs
                # at its middle, not by f_r (n·ω) there, whose (r·ω)ⁿ may underflow to 0
                mid = self.directions(np.array([g]), np.array([(a + b) / 2]))[0]
                if mid @ self.n > 0 and (lobe_w is None or mid @ self.r > 0):
                    out.append((a, b))
        return out


def spot_check(sc, rec, rng):
    """The inner integral L_a along a random direction of the hemisphere against mpmath's
    tanh-sinh (gen_extended.point_light): their relative difference."""
    import mpmath as mp
    from gen_extended import point_light
    from gen_reference import dist_fn, phase_fn

    while True:
        w = unit(random_unit(rng))
        if np.dot(w, sc.n) > 0:
            break
    mp.mp.dps = 20
    mine = sc.air_light_rays(w[None, :], 24, 3)[0]
    dist = rec["light"].get("distribution") or {"kind": "isotropic"}
    axis = [mp.mpf(x) for x in sc.axis]
    theirs = point_light([mp.mpf(x) for x in sc.s], [mp.mpf(x) for x in w], mp.mpf(0), mp.inf, mp.mpf(sc.ss), mp.mpf(sc.st),
                         [mp.mpf(x) for x in sc.p], mp.mpf(sc.I), dist, axis, dist_fn(dist), phase_fn(rec.get("phase") or {"kind": "isotropic"}))
    return abs(mine - float(theirs)) / abs(float(theirs))


def reference(rec, rng):
    sc = Scene(rec)
    coarse, fine = sc.value(16, 2), sc.value(24, 3)
    if not (abs(coarse - fine) <= 1e-11 * abs(fine)):
        # not resolved at the first pair: the finer of them against 32 nodes and 4 panels
        coarse, fine = fine, sc.value(32, 4)
    check = spot_check(sc, rec, rng)
    if not (abs(coarse - fine) <= 1e-11 * abs(fine)) or not (check <= 1e-11):
        return None, coarse, fine, check
    return fine, coarse, fine, check


def random_unit(rng):
    while True:
        v = [rng.gauss(0, 1) for _ in range(3)]
        n = math.sqrt(sum(x * x for x in v))
        if n > 1e-3:
            return [x / n for x in v]


def scenes():
    rng = random.Random(20261130)
    out = []
    iso = {"kind": "isotropic"}

    def rec(category, d, st, brdf, phase=iso, dist=iso, normal=None, light_dir=None):
        ldir = light_dir or random_unit(rng)
        normal = normal or random_unit(rng)
        # the light on the lit side unless the class says otherwise
        if light_dir is None and sum(a * b for a, b in zip(ldir, normal)) < 0:
            ldir = [-x for x in ldir]
        s = f32v([rng.uniform(-5, 5) for _ in range(3)])
        p = f32v([s[i] + d * ldir[i] for i in range(3)])
        r = {
            "category": category,
            "surface": {"position": s, "normal": f32v(normal), "brdf": brdf},
            "medium": {"sigma_s": f32(st * rng.uniform(0.3, 1.0)), "sigma_t": f32(st)},
            "light": {"position": p, "intensity": f32(rng.uniform(1, 100)), "distribution": dist},
            "phase": phase,
        }
        return r

    lam = lambda: {"kind": "lambert", "albedo": f32(rng.uniform(0.1, 0.9))}
    hg = lambda g: {"kind": "henyey_greenstein", "g": f32(g)}
    # Lambertian, isotropic: thin to thick media (σt d from 1e-2 to 30)
    for i in range(6):
        out.append(rec("lambert_thin", rng.uniform(1, 10), 10 ** rng.uniform(-3, -1.5), lam()))
    for i in range(6):
        d = rng.uniform(0.5, 5)
        out.append(rec("lambert_thick", d, 10 ** rng.uniform(0, 1.5) / d, lam()))
    # the light close to the surface (d from 1e-3 to 1e-1), and grazing: the light near or below
    # the horizon of the normal
    for i in range(6):
        out.append(rec("near", 10 ** rng.uniform(-3, -1), 10 ** rng.uniform(-2, 0.5), lam(), phase=hg(rng.uniform(-0.5, 0.8))))
    for i in range(6):
        normal = random_unit(rng)
        t = random_unit(rng)
        tang = unit(np.cross(normal, t))
        elev = rng.uniform(-0.3, 0.1)
        ldir = list(unit(math.cos(elev) * tang + math.sin(elev) * np.array(normal)))
        out.append(rec("grazing", rng.uniform(0.5, 5), 10 ** rng.uniform(-2, 0), lam(), phase=hg(rng.uniform(0, 0.9)), normal=normal, light_dir=ldir))
    # anisotropic media up to |g| = 0.95, and lights with an axis
    for i in range(6):
        g = [0.5, 0.8, 0.9, 0.95, -0.7, 0.95][i]
        out.append(rec("aniso", rng.uniform(0.5, 5), 10 ** rng.uniform(-2, 0), lam(), phase=hg(g)))
    for i in range(2):
        dist = {"kind": "two_lobed", "axis": f32v(random_unit(rng)), "power": 4} if i % 2 == 0 else {
            "kind": "spot", "axis": f32v(random_unit(rng)), "cos_inner": f32(0.9), "cos_outer": f32(0.7)}
        out.append(rec("distribution", rng.uniform(0.5, 3), 10 ** rng.uniform(-2, -0.5), lam(), phase=hg(0.6), dist=dist))
    # Phong lobes, n from 1 to 200
    for i, n in enumerate([1, 10, 50, 200, 200, 100]):
        brdf = {"kind": "phong", "k_s": f32(rng.uniform(0.2, 1)), "exponent": f32(n), "view": f32v(random_unit(rng))}
        phase = hg(0.8) if i % 2 else iso
        out.append(rec("phong", rng.uniform(0.5, 5), 10 ** rng.uniform(-2, 0), brdf, phase=phase))
    # beams: two-lobed lights of higher powers, on Lambertian and Phong surfaces, and a spot
    for i, power in enumerate([8, 16, 32, 16, 8]):
        dist = {"kind": "two_lobed", "axis": f32v(random_unit(rng)), "power": power}
        brdf = lam() if i < 3 else {"kind": "phong", "k_s": f32(rng.uniform(0.2, 1)), "exponent": f32([20, 100][i - 3]), "view": f32v(random_unit(rng))}
        out.append(rec("distribution", rng.uniform(0.5, 3), 10 ** rng.uniform(-2, -0.5), brdf, phase=[hg(0.6), iso, hg(0.8)][i % 3], dist=dist))
    # a narrow lobe (n = 200) whose power underflows to 0 in the middle of the inner panels
    # beside its peak (a kernel that skipped a panel by its middle value lost 10 % of this one)
    brdf = {"kind": "phong", "k_s": f32(0.5), "exponent": f32(200), "view": f32v([0.4800154600048302, -0.8282420150061308, -0.289137203996538])}
    out.append(rec("phong", 4.227641570555167, 0.10149658089770577, brdf, phase=hg(0.8), normal=[0.9946258620707324, -0.09965683633554595, 0.02806972517931515],
                   light_dir=[0.9926508176418308, 0.06650704566422262, 0.1010997878930601]))

    # lobes narrower than the class above (n = 500, 1000) clear of the horizon and the light,
    # which the kernel integrates about their own axis at loose tolerances, and a Phong point in
    # a thick medium (σt·d = 10), whose rays it interpolates graded to the layer at the light's
    # direction (docs/DESIGN.md §11); each placed from a seed of its own, so that the records
    # above stay as they were
    def placed(category, d, st, brdf, phase, light_dir, seed):
        own = random.Random(seed)
        s = f32v([own.uniform(-5, 5) for _ in range(3)])
        p = f32v([s[i] + d * light_dir[i] for i in range(3)])
        return {
            "category": category,
            "surface": {"position": s, "normal": f32v([0.0, 0.0, 1.0]), "brdf": brdf},
            "medium": {"sigma_s": f32(st * own.uniform(0.3, 1.0)), "sigma_t": f32(st)},
            "light": {"position": p, "intensity": f32(own.uniform(1, 100)), "distribution": iso},
            "phase": phase,
        }

    phong = lambda k, n, view: {"kind": "phong", "k_s": f32(k), "exponent": f32(n), "view": f32v(list(unit(view)))}
    out.append(placed("phong_narrow", 2.0, 0.05, phong(0.6, 500, [0.5, 0.0, 0.866]), iso, list(unit([-0.2, 0.8, 0.6])), 1))
    out.append(placed("phong_narrow", 3.0, 0.2, phong(0.4, 1000, [0.3, -0.4, 0.866]), hg(0.3), list(unit([0.7, 0.3, 0.65])), 2))
    out.append(placed("phong_thick", 2.0, 5.0, phong(0.5, 40, [0.4, 0.2, 0.9]), iso, list(unit([-0.3, 0.5, 0.8])), 3))
    # broad lobes (n = 4, 5, 6), where the kernel does not cut its outer integral at the mirror
    # direction's arcs' ends (docs/DESIGN.md §11): a mirror direction near the horizon, so that
    # those ends fall inside the outer range and the lobe
    out.append(placed("phong_broad", 1.5, 0.3, phong(0.5, 4, [0.8, 0.1, 0.59]), iso, list(unit([0.3, 0.6, 0.75])), 4))
    out.append(placed("phong_broad", 3.0, 0.5, phong(0.7, 5, [-0.2, 0.9, 0.39]), hg(0.3), list(unit([-0.5, -0.4, 0.77])), 5))
    out.append(placed("phong_broad", 2.0, 1.2, phong(0.4, 6, [0.6, -0.7, 0.39]), hg(0.8), list(unit([0.1, 0.2, 0.97])), 6))
    return out


def main():
    lines = []
    rng = random.Random(7)
    for r in scenes():
        value, coarse, fine, check = reference(r, rng)
        status = "kept" if value is not None else "DROPPED"
        print(f"{r['category']:>14} {status} {fine:.17e} (coarse {abs(coarse - fine) / abs(fine):.1e}, L_a vs mpmath {check:.1e})", flush=True)
        if value is not None:
            r["surface_air_light"] = value
            brdf = r["surface"]["brdf"]
            if brdf["kind"] == "phong":
                peak = {"kind": "lambert", "albedo": brdf["k_s"] * (brdf["exponent"] + 2) / 2}
                r["scale"] = Scene({**r, "surface": {**r["surface"], "brdf": peak}}).value(24, 3)
            else:
                r["scale"] = value
            lines.append(r)
    print(f"{write_jsonl('surface.jsonl', lines)} records")


if __name__ == "__main__":
    main()
