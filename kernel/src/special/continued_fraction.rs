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
    let wide = C::new(z.re.to_f64_exact(), z.im.to_f64_exact());
    if T::epsilon() > T::lit(1e-10) && r2.is_finite() {
        // f32's fractions: top-down in f64 (one division in all; the convergents' extra
        // rounding is f64's, far below f32's ulp)
        let w = e1_scaled_cf_convergents(wide, depth);
        return C::new(T::lit(w.re), T::lit(w.im));
    }
    // f64's: bottom-up, from a tail without divisions where the fraction is deep (|z| < 50),
    // so the chain of divisions does not start with three more
    let t = if depth >= PLAIN_FROM {
        let t = tail_in_range(wide, depth);
        C::new(T::lit(t.re), T::lit(t.im))
    } else {
        tail(z, depth)
    };
    bottom_up(z, depth, t)
}

/// The same fraction as [`bottom_up`] (levels `1..=n`, then its tail), top-down by
/// the fundamental recurrences `X_k = b_k X_{k−1} + a_k X_{k−2}` (`X` = `A`, `B`), `b_k = z +
/// 2k − 1`, `a_k = −(k−1)²`, `b_{n+1}` the tail: products only, one division at the end, so no
/// chain of division latencies (the tail's square roots do not wait on the levels). Used in
/// f64 for all of f32's fractions, `|z| < 5e38`: `|B| ≤ (|z| + 2n + 2)^{n+1}` stays below
/// `1e24` where the f32 tables go deepest (`n = 14`, `|z| < 2.5`) and below `(5e38)² = 2.5e77`
/// for the largest `|z|` (one level beyond 30), so `|B|² < 1e155` and the end divides once by
/// it.
fn e1_scaled_cf_convergents(z: C<f64>, n: usize) -> C<f64> {
    let last = tail_in_range(z, n);
    // (X_{k−1}, X_k) at k = 1: A_0 = 0, A_1 = 1, B_0 = 1, B_1 = b_1
    let (mut a_prev, mut a_cur) = (C::new(0.0, 0.0), C::new(1.0, 0.0));
    let (mut b_prev, mut b_cur) = (C::new(1.0, 0.0), z + 1.0);
    // b_k − z = 2k − 1 and k − 1 = √(−a_k), as floats counted up (no conversion per level)
    let (mut odd, mut root) = (1.0, 0.0);
    for _ in 2..=n {
        odd += 2.0;
        root += 1.0;
        let (b_k, square) = (z + odd, root * root);
        (a_prev, a_cur) = (a_cur, b_k * a_cur - a_prev * square);
        (b_prev, b_cur) = (b_cur, b_k * b_cur - b_prev * square);
    }
    // level n + 1: b = the tail, a = −n²
    let square = (root + 1.0) * (root + 1.0);
    let (a_end, b_end) = (last * a_cur - a_prev * square, last * b_cur - b_prev * square);
    a_end * b_end.conj() * (1.0 / b_end.norm_sqr())
}

/// [`tail`] for `|z| < 5e38` (every f32 `z`; f64's deep fractions), in f64 and without
/// `tail`'s divisions: `t = (b + √(b² − 4(n+1)²))/2`, the root aligned with `b` (so `|t| ≥
/// |b|/2`), `b² − 4(n+1)² = (z − 1)(z + 4n + 3)` (no cancellation where `b ≈ 2(n+1)`); its
/// magnitude stays below `2.5e77`, its square below `1e155`.
#[inline]
fn tail_in_range(z: C<f64>, n: usize) -> C<f64> {
    let nf = n as f64;
    let b = z + (2.0 * nf + 1.0);
    let mut root = csqrt((z - 1.0) * (z + (4.0 * nf + 3.0)));
    if root.re * b.re + root.im * b.im < 0.0 {
        root = -root;
    }
    (b + root) * 0.5
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

/// Depths from this on divide plainly (`bottom_up`, private).
pub const PLAIN_FROM: usize = 6;

/// The continued fraction at an explicit depth `n` (levels `1..=n` below the tail `t = t_{n+1}`,
/// [`tail`] or [`tail_in_range`]): `1/t_1`, `t_k = z + 2k − 1 − k²/t_{k+1}`, bottom-up.
///
/// Deep fractions (`n ≥ 6`: `|z| < 7` in f32, `< 50` in f64 by the depth table) have
/// `|t_k| ≤ |z| + 2n + 1 ≤ 91`, so `k²/t = k² t̄/|t|²` cannot overflow: one division per level
/// (the levels form a chain, so its latency is the fraction's cost). Shallow fractions serve
/// any `|z|` up to the float range, with Smith's division. (The top-down convergents need one
/// division in all but lose 7× more in f32 near the imaginary axis; [`e1_scaled_cf`] takes them
/// in f64 for all of f32's fractions, where that loss is f64's: in the kernel this serves f64,
/// and it is what the f32 shaders mirror.)
#[inline]
fn bottom_up<T: Real>(z: C<T>, n: usize, mut t: C<T>) -> C<T> {
    let one = C::new(T::one(), T::zero());
    let two = T::lit(2.0);
    // k as a float counted down (exact: n is far below 2^24), not converted at each level
    let mut kf = T::from(n).unwrap();
    for _ in 0..n {
        let ratio = if n >= PLAIN_FROM {
            t.conj() * (kf * kf / t.norm_sqr())
        } else {
            cdiv(C::new(kf * kf, T::zero()), t)
        };
        t = z + (two * kf - T::one()) - ratio;
        kf = kf - T::one();
    }
    cdiv(one, t)
}
