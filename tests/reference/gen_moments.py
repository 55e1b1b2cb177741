#!/usr/bin/env python3
"""References for the moment computations, by mpmath quadrature at 40 digits.

Writes moments.jsonl next to this file:
  {"kind": "legendre", "lambda": λ, "k": k, "value": M_k}
      M_k(λ) = ∫_{-1}^{1} e^{−λ(1+ξ)} P_k(ξ) dξ, k = 0..15, λ over 0 … 1e8 (every λ exact in
      binary32), the exponential's Legendre moments of the panel integration;
  {"kind": "monomial", "big_h": H, "y_lo": a, "y_hi": b, "k": k, "value": m_k}
      m_k = ∫_a^b e^{−H(y − a)} (y − c)^k / (1 + y²) dy, c = (a + b)/2, k = 0..15: the
      monomial moments of the fixed-term path's first half (before the light's foot);
  {"kind": "far_end", "precision": "f32"|"f64", "second": s, "big_h": H, "y_lo": a, "y_hi": b,
   "value": m_0, "scale": |S(z_s)| + e^{−HΔv}|S(z_e)|}
      m_0 = ∫_{v_s}^{v_e} e^{−H(v − v_s)} dv/(1 + v²) (y = v on the first half, y = 1/v on the
      second; inputs exact in the precision), S(z) = e^z E1(z), z = H(v − i): halves whose far
      end's weight e^{−HΔv} lies from ε/8 to 64ε of the precision, either side of where the
      isotropic moment leaves that end out (airlight::integrals::FAR_END_NEGLIGIBLE); at H = 1
      a first half reaching past the foot (v_e > 1, as the isotropic whole line does) with its
      near end in E1's series region.

Usage: python3 tests/reference/gen_moments.py      (mpmath==1.3.0; about 20 seconds)
"""
import math
import os
import sys

import mpmath as mp

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from gen_reference import f32, write_jsonl  # noqa: E402

mp.mp.dps = 40


LAMBDAS = [0.0, 1e-8, 1e-3, 0.1, 0.5, 0.999, 1.0, 1.001, 1.5, 2.0, 3.0, 5.0, 7.9, 8.0, 8.1, 11.9, 12.0,
           12.1, 15.9, 16.0, 16.1, 20.0, 50.0, 100.0, 1e3, 1e5, 1e8]
MONOMIAL = [(40.0, 0.5, 0.5625), (64.0, 0.25, 0.28125), (256.0, 0.0625, 0.078125)]


def main():
    out = []
    for lam in LAMBDAS:
        lam = f32(lam)
        L = mp.mpf(lam)
        for k in range(16):
            f = lambda x: mp.exp(-L * (1 + x)) * mp.legendre(k, x)
            pts = [-1, 1] if L < 10 else [-1] + [-1 + mp.mpf(j) / L for j in (1, 4, 16, 64) if j < 2 * L] + [1]
            v = mp.quad(f, pts)
            out.append({"kind": "legendre", "lambda": lam, "k": k, "value": float(v)})
    for h, a, b in MONOMIAL:
        H, A, B = mp.mpf(h), mp.mpf(a), mp.mpf(b)
        c = (A + B) / 2
        for k in range(16):
            v = mp.quad(lambda y: mp.exp(-H * (y - A)) * (y - c) ** k / (1 + y * y), [A, B])
            out.append({"kind": "monomial", "big_h": h, "y_lo": a, "y_hi": b, "k": k, "value": float(v)})
    for prec, eps, rnd in (("f32", 2.0 ** -23, f32), ("f64", 2.0 ** -52, float)):
        for second, big_h, v_s in ((False, 80.0, 0.25), (False, 1.0, 0.5), (True, 5.0, 2.0)):
            for ratio in (0.125, 0.25, 0.5, 1.0, 4.0, 64.0):
                H = rnd(big_h)
                v_e = v_s + math.log(1.0 / (ratio * eps)) / H
                # the half's ends in y, exact in the precision; v from them
                lo, hi = (rnd(1.0 / v_e), rnd(1.0 / v_s)) if second else (rnd(v_s), rnd(v_e))
                vs, ve = (1 / mp.mpf(hi), 1 / mp.mpf(lo)) if second else (mp.mpf(lo), mp.mpf(hi))
                Hm = mp.mpf(H)
                m0 = mp.quad(lambda v: mp.exp(-Hm * (v - vs)) / (1 + v * v), [vs, ve])
                S = lambda v: mp.exp(Hm * mp.mpc(v, -1)) * mp.e1(Hm * mp.mpc(v, -1))
                scale = abs(S(vs)) + mp.exp(-Hm * (ve - vs)) * abs(S(ve))
                out.append({"kind": "far_end", "precision": prec, "second": second, "big_h": H, "y_lo": lo, "y_hi": hi,
                            "value": float(m0), "scale": float(scale)})
    print(f"moments: {write_jsonl('moments.jsonl', out)} lines")


if __name__ == "__main__":
    main()
