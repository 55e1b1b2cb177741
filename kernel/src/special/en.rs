//! Real generalised exponential integrals `E_n(x) = ∫₁^∞ e^{−xt} t^{−n} dt`, scaled by `e^x`.
//!
//! Recurrence `E_{n+1}(x) = (e^{−x} − x E_n(x))/n` (A&S 5.1.14), i.e. for `s_n = e^x E_n(x)`:
//! `s_{n+1} = (1 − x s_n)/n`. Going up multiplies errors by `x/n`, going down by `n/x`: each
//! direction is stable on its own side of `n ≈ x` (Miller's rule). So we start from a pivot
//! order `n* ≈ x` — `s_1` from the complex `E1` routine where `x` is in its series region,
//! otherwise `s_{n*}` from its continued fraction (A&S 5.1.22) — and recur away from it
//! both ways.

use super::e1::in_series_region;
use super::series::ein_real;
use super::EULER_GAMMA;
use super::{banded, C};
use crate::real::{reciprocal, Real};

/// Fills `out[k] = e^x E_{k+1}(x)` for `k = 0..out.len()`, `x ≥ 0`.
/// At `x = 0`: `E_1 = +∞`, `E_n = 1/(n − 1)`.
pub fn en_scaled<T: Real>(x: T, out: &mut [T]) {
    let k_max = out.len();
    if k_max == 0 {
        return;
    }
    if x == T::zero() {
        out[0] = T::infinity();
        for n in 2..=k_max {
            out[n - 1] = T::one() / T::from(n - 1).unwrap();
        }
        return;
    }
    let pivot = if in_series_region(C::new(x, T::zero())) {
        // E1(x) = −γ − ln x + Ein(x) (A&S 5.1.11), in real arithmetic
        out[0] = (ein_real(x) - x.ln() - T::lit(EULER_GAMMA)) * x.exp();
        1
    } else {
        let n = x.ceil().to_usize().unwrap_or(k_max).clamp(1, k_max);
        out[n - 1] = en_scaled_cf(x, n);
        n
    };
    for n in pivot..k_max {
        out[n] = (T::one() - x * out[n - 1]) * reciprocal::<T>(n);
    }
    let inv_x = x.recip();
    for n in (1..pivot).rev() {
        // s_n = (1 − n s_{n+1}) / x
        out[n - 1] = (T::one() - T::from(n).unwrap() * out[n]) * inv_x;
    }
}

/// `e^x E_n(x)` by the continued fraction
/// `1/(x + n − 1·n/(x + n + 2 − 2(n+1)/(x + n + 4 − …)))`, outside the `E1` series region,
/// with the complex `E1` fraction's tail estimate and its own depth table,
/// [`Real::EN_CF_DEPTH`] (truncation ≤ 8 unit roundoffs for every pivot `n ≤ min(⌈x⌉, 32)`,
/// tests/reference/gen_e1_tuning.py: shallower than the complex table between 2.5 and 25
/// (f32: 15), deeper beyond 25 (f64), where large `n` converges more slowly than `n = 1`).
fn en_scaled_cf<T: Real>(x: T, n: usize) -> T {
    let xf = x.to_f64_exact();
    let depth = banded(xf * xf, T::EN_CF_DEPTH);
    let nf = T::from(n).unwrap();
    let two = T::lit(2.0);
    let m = T::from(depth).unwrap();
    // level k ≥ 1: t_k = x + n + 2k − a_{k+1}/t_{k+1}, a_k = k(n + k − 1); the tail t_{m+1}
    // is the fixed point of t = b − a/t with b = x + n + 2(m+1), a = a_{m+2}.
    let b = x + nf + two * (m + T::one());
    let a = (m + two) * (nf + m + T::one());
    let q = a / (b * b);
    let disc = T::one() - T::lit(4.0) * q;
    let mut t = if disc > T::zero() { b * (T::one() + disc.sqrt()) / two } else { b };
    for k in (1..=depth).rev() {
        let kf = T::from(k).unwrap();
        t = x + nf + two * kf - (kf + T::one()) * (nf + kf) / t;
    }
    // level 0
    T::one() / (x + nf - nf / t)
}
