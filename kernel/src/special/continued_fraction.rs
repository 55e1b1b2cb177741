//! Continued fraction of the scaled exponential integral (A&S 5.1.22, even contraction):
//!
//! `e^z E1(z) = 1/(z + 1 − 1²/(z + 3 − 2²/(z + 5 − 3²/(z + 7 − …))))`,
//!
//! convergent for `|arg z| < π`, evaluated bottom-up at a fixed depth (f32's fractions
//! top-down in f64: products only, one division). The tail below the last
//! level is not dropped but replaced by the fixed point of its own recurrence,
//! `t = b − (n+1)²/t`, which roughly halves the depth needed for a given accuracy
//! (measured against mpmath; see `Real::E1_CF_DEPTH`).

use super::{banded, cdiv, csqrt, C};
use crate::real::Real;

/// `e^z E1(z)` by the continued fraction at the depth [`Real::E1_CF_DEPTH`] gives for `|z|`
/// ([`Real::E1_CF_DEPTH_NEAR_REAL`] within 45° of the real axis).
#[inline]
pub fn e1_scaled_cf<T: Real>(z: C<T>) -> C<T> {
    // |z|² against the squared band bounds (no square root needed).
    let (x, y) = (z.re.abs().to_f64_exact(), z.im.abs().to_f64_exact());
    let r2 = if x.max(y) < 1e150 { x * x + y * y } else { f64::INFINITY };
    let near_real = z.re >= T::zero() && y <= x;
    // each table searched as a constant (the compiler unrolls a constant's search)
    let depth = if near_real { banded(r2, T::E1_CF_DEPTH_NEAR_REAL) } else { banded(r2, T::E1_CF_DEPTH) };
    if T::epsilon() > T::lit(1e-10) && r2.is_finite() {
        // f32's fractions: top-down in f64 (one division in all; the convergents' extra
        // rounding is f64's, far below f32's ulp)
        let w = e1_scaled_cf_convergents(C::new(z.re.to_f64_exact(), z.im.to_f64_exact()), depth);
        return C::new(T::lit(w.re), T::lit(w.im));
    }
    e1_scaled_cf_depth(z, depth)
}

/// The same fraction as [`e1_scaled_cf_depth`] (levels `1..=n`, then its tail), top-down by
/// the fundamental recurrences `A_k = b_k A_{k−1} + a_k A_{k−2}` (the same for `B`), `b_k = z +
/// 2k − 1`, `a_k = −(k−1)²`, `b_{n+1}` the tail: products only, one division at the end, so no
/// chain of division latencies. Used in f64 for all of f32's fractions: `|B| ≤ (|z| + 2n +
/// 2)^{n+1}` stays below `1e24` where the f32 tables go deepest (`n = 14`, `|z| < 2.5`) and below
/// `(3.5e38)² ≈ 1.2e77` for the largest f32 `|z|` (one level beyond 30): nothing overflows.
fn e1_scaled_cf_convergents(z: C<f64>, n: usize) -> C<f64> {
    let (mut a_prev, mut a_cur) = (C::new(1.0, 0.0), C::new(0.0, 0.0));
    let (mut b_prev, mut b_cur) = (C::new(0.0, 0.0), C::new(1.0, 0.0));
    for k in 1..=n + 1 {
        let b_k = if k <= n { z + (2 * k - 1) as f64 } else { tail(z, n) };
        let a_k = if k == 1 { 1.0 } else { -(((k - 1) * (k - 1)) as f64) };
        let a_next = b_k * a_cur + a_prev * a_k;
        let b_next = b_k * b_cur + b_prev * a_k;
        (a_prev, a_cur, b_prev, b_cur) = (a_cur, a_next, b_cur, b_next);
    }
    cdiv(a_cur, b_cur)
}

/// The fixed point of the tail below level `n`: `t = (b/2)(1 + √(1 − 4(n+1)²/b²))`, `b = z +
/// 2n + 1`, the root aligned with `b` (the dominant fixed point), written with `(2(n+1)/b)²`
/// so that it cannot overflow for huge `|z|`.
#[inline]
fn tail<T: Real>(z: C<T>, n: usize) -> C<T> {
    let one = C::new(T::one(), T::zero());
    let two = T::lit(2.0);
    let nf = T::from(n).unwrap();
    let b = z + (two * nf + T::one());
    let q = cdiv(C::new(two * (nf + T::one()), T::zero()), b);
    let mut root = csqrt(one - q * q);
    if root.re < T::zero() {
        root = -root;
    }
    b * (one + root) / two
}

/// Depths from this on divide plainly (`e1_scaled_cf_depth`, private).
pub const PLAIN_FROM: usize = 6;

/// The continued fraction at an explicit depth `n` (levels `1..=n` plus the tail estimate):
/// `1/t_1`, `t_k = z + 2k − 1 − k²/t_{k+1}`, `t_{n+1}` the tail, bottom-up.
///
/// Deep fractions (`n ≥ 6`: `|z| < 7` in f32, `< 50` in f64 by the depth table) have
/// `|t_k| ≤ |z| + 2n + 1 ≤ 91`, so `k²/t = k² t̄/|t|²` cannot overflow: one division per level
/// (the levels form a chain, so its latency is the fraction's cost). Shallow fractions serve
/// any `|z|` up to the float range, with Smith's division. (The top-down convergents need one
/// division in all but lose 7× more in f32 near the imaginary axis; [`e1_scaled_cf`] takes them
/// in f64 for all of f32's fractions, where that loss is f64's: in the kernel this serves f64,
/// and it is what the f32 shaders mirror.)
#[inline]
pub fn e1_scaled_cf_depth<T: Real>(z: C<T>, n: usize) -> C<T> {
    let one = C::new(T::one(), T::zero());
    let two = T::lit(2.0);
    let mut t = tail(z, n);
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
