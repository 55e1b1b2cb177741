//! Continued fraction of the scaled exponential integral (A&S 5.1.22, even contraction):
//!
//! `e^z E1(z) = 1/(z + 1 − 1²/(z + 3 − 2²/(z + 5 − 3²/(z + 7 − …))))`,
//!
//! convergent for `|arg z| < π`, evaluated bottom-up at a fixed depth. The tail below the last
//! level is not dropped but replaced by the fixed point of its own recurrence,
//! `t = b − (n+1)²/t`, which roughly halves the depth needed for a given accuracy
//! (measured against mpmath; see `Real::E1_CF_DEPTH`).

use super::{banded, cdiv, csqrt, C};
use crate::real::Real;

/// `e^z E1(z)` by the continued fraction at the depth [`Real::E1_CF_DEPTH`] gives for `|z|`.
#[inline]
pub fn e1_scaled_cf<T: Real>(z: C<T>) -> C<T> {
    // |z|² against the squared band bounds (no square root needed).
    let (x, y) = (z.re.abs().to_f64_exact(), z.im.abs().to_f64_exact());
    let r2 = if x.max(y) < 1e150 { x * x + y * y } else { f64::INFINITY };
    e1_scaled_cf_depth(z, banded(r2, T::E1_CF_DEPTH))
}

/// Depths from this on divide plainly (`e1_scaled_cf_depth`, private).
pub const PLAIN_FROM: usize = 6;

/// The continued fraction at an explicit depth `n` (levels `1..=n` plus the tail estimate):
/// `1/t_1`, `t_k = z + 2k − 1 − k²/t_{k+1}`, `t_{n+1}` the tail, bottom-up.
///
/// Deep fractions (`n ≥ 6`: `|z| < 7` in f32, `< 50` in f64 by the depth table) have
/// `|t_k| ≤ |z| + 2n + 1 ≤ 91`, so `k²/t = k² t̄/|t|²` cannot overflow: one division per level
/// (the levels form a chain, so its latency is the fraction's cost). Shallow fractions serve
/// any `|z|` up to the float range, with Smith's division. (The top-down convergents would need
/// one division in all, but lose 7× more in f32 near the imaginary axis.)
#[inline]
pub fn e1_scaled_cf_depth<T: Real>(z: C<T>, n: usize) -> C<T> {
    let one = C::new(T::one(), T::zero());
    let two = T::lit(2.0);
    // Tail: t = (b/2)(1 + √(1 − 4(n+1)²/b²)), b = z + 2n + 1; written with (2(n+1)/b)² so
    // that it cannot overflow for huge |z|.
    let nf = T::from(n).unwrap();
    let b = z + (two * nf + T::one());
    let q = cdiv(C::new(two * (nf + T::one()), T::zero()), b);
    let mut root = sqrt_near_one(one - q * q);
    // Pick the root aligned with b (the dominant fixed point).
    if root.re < T::zero() {
        root = -root;
    }
    let mut t = b * (one + root) / two;
    for k in (1..=n).rev() {
        let kf = T::from(k).unwrap();
        let ratio = if n >= PLAIN_FROM {
            t.conj() * (kf * kf / t.norm_sqr())
        } else {
            cdiv(C::new(kf * kf, T::zero()), t)
        };
        t = z + (two * kf - T::one()) - ratio;
    }
    cdiv(one, t)
}

/// Principal square root of the tail's `w = 1 − q²`. `|q| = 2(n+1)/|z + 2n + 1| ≤ 4/3` for
/// `Re z ≥ 0`, `n ≥ 1`, so `|w| < 3`: `|w| = √(x² + y²)` cannot overflow and needs no `hypot`
/// (Kahan's formula as [`csqrt`] otherwise). Below `|w|² = 2^{−60}`, where `x² + y²` could
/// underflow in f32, [`csqrt`] itself.
#[inline]
fn sqrt_near_one<T: Real>(w: C<T>) -> C<T> {
    let norm_sqr = w.re * w.re + w.im * w.im;
    if !(norm_sqr > T::lit(8.673_617_379_884_035e-19)) {
        return csqrt(w);
    }
    let half = T::lit(0.5);
    let r = norm_sqr.sqrt();
    if w.re >= T::zero() {
        let t = ((r + w.re) * half).sqrt();
        C::new(t, w.im / (t + t))
    } else {
        let t = ((r - w.re) * half).sqrt();
        C::new(w.im.abs() / (t + t), t.copysign(w.im))
    }
}
