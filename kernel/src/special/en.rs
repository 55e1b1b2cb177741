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
    // Both directions two orders a step, as two interleaved chains (half the latency of one):
    // up, s_{n+2} = ((n − x) + x² s_n)/(n(n+1)); down, s_n = ((x − n) + n(n+1) s_{n+2})/x².
    // On each one's stable side both terms are positive (the one-order steps cancel there).
    let x2 = x * x;
    if pivot < k_max {
        out[pivot] = (T::one() - x * out[pivot - 1]) * reciprocal::<T>(pivot);
    }
    for n in pivot..k_max.saturating_sub(1) {
        let nf = T::from(n).unwrap();
        out[n + 1] = ((nf - x) + x2 * out[n - 1]) * (reciprocal::<T>(n) * reciprocal::<T>(n + 1));
    }
    if pivot == 1 {
        return;
    }
    let inv_x = x.recip();
    let inv_x2 = inv_x * inv_x;
    // s_{n*−1} = (1 − (n*−1) s_{n*})/x
    out[pivot - 2] = (T::one() - T::from(pivot - 1).unwrap() * out[pivot - 1]) * inv_x;
    for n in (1..pivot.saturating_sub(1)).rev() {
        let nf = T::from(n).unwrap();
        out[n - 1] = ((x - nf) + nf * (nf + T::one()) * out[n + 1]) * inv_x2;
    }
}

/// `e^x E_n(x)` by the continued fraction
/// `1/(x + n − 1·n/(x + n + 2 − 2(n+1)/(x + n + 4 − …)))`, outside the `E1` series region,
/// with the complex `E1` fraction's tail estimate and its own depth table,
/// [`Real::EN_CF_DEPTH`] (truncation ≤ 8 unit roundoffs for every pivot `n ≤ min(⌈x⌉,
/// 32)`, tests/reference/gen_e1_tuning.py: shallower than the complex table between 2.5 and 25
/// (f32: 15), deeper beyond 25 (f64), where large `n` converges more slowly than `n = 1`).
///
/// As `b_0 − a_1/(b_1 − a_2/(b_2 − …))` with `b_k = x + n + 2k`, `a_k = k(n + k − 1)` and the
/// tail in place of `b_{m+1}`. Deep fractions (`m ≥ TOP_DOWN_FROM`: `x < 100` in f64, `< 4` in
/// f32) go top-down by the fundamental recurrences, `P_k = b_k P_{k−1} − a_k P_{k−2}` (the same
/// for `Q`), the value `Q_{m+1}/P_{m+1}`: two independent chains of products and one division
/// instead of a division per level, in f64 for f32 too. `0 < P_k ≤ b_k P_{k−1}`, so
/// `P_{m+1} ≤ Π b_k` (the tail `≤ b_{m+1}`): at most 1.4e63 (f64, 37 levels at `x < 5`) and
/// 1.3e20 (f32, 14 levels at `x < 2.5`), far from overflow. Shallow fractions, which serve any
/// `x`, divide bottom-up.
fn en_scaled_cf<T: Real>(x: T, n: usize) -> T {
    let xf = x.to_f64_exact();
    let depth = banded(xf * xf, T::EN_CF_DEPTH);
    let nf = T::from(n).unwrap();
    let two = T::lit(2.0);
    let m = T::from(depth).unwrap();
    // the tail t_{m+1}: the fixed point of t = b − a/t with b = b_{m+1}, a = a_{m+2}
    let b = x + nf + two * (m + T::one());
    let a = (m + two) * (nf + m + T::one());
    let q = a / (b * b);
    let disc = T::one() - T::lit(4.0) * q;
    let tail = if disc > T::zero() { b * (T::one() + disc.sqrt()) / two } else { b };
    if depth >= TOP_DOWN_FROM {
        // in f64 (f32's own rounding here would lose 2.5× more; f64 is as fast on a CPU)
        let (x, nf, tail) = (xf, n as f64, tail.to_f64_exact());
        let (mut p_prev, mut p) = (1.0, x + nf);
        let (mut q_prev, mut q) = (0.0, 1.0);
        for k in 1..=depth + 1 {
            let kf = k as f64;
            let b_k = if k <= depth { x + nf + 2.0 * kf } else { tail };
            let a_k = kf * (nf + kf - 1.0);
            (p_prev, p) = (p, b_k * p - a_k * p_prev);
            (q_prev, q) = (q, b_k * q - a_k * q_prev);
        }
        return T::lit(q / p);
    }
    // level k ≥ 1: t_k = x + n + 2k − a_{k+1}/t_{k+1}
    let mut t = tail;
    for k in (1..=depth).rev() {
        let kf = T::from(k).unwrap();
        t = x + nf + two * kf - (kf + T::one()) * (nf + kf) / t;
    }
    // level 0
    T::one() / (x + nf - nf / t)
}

/// Depths from this on evaluate [`en_scaled_cf`] top-down.
const TOP_DOWN_FROM: usize = 6;
