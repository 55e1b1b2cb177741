//! Power series of `Ein(z) = ∫₀ᶻ (1 − e^{−t})/t dt = Σ_{k≥1} (−1)^{k+1} z^k / (k·k!)`
//! (A&S 5.1.11: `E1(z) = −γ − ln z + Ein(z)`), with a fixed number of terms.

use super::{banded, C};
use crate::real::Real;

/// `Ein(z)` by its power series, as many terms as [`Real::E1_SERIES_BANDS`] gives for `|z|`
/// (accurate inside the series ellipse of [`in_series_region`](super::in_series_region)), by
/// Horner's rule on the tabulated coefficients: complex multiply-adds, no divisions.
#[inline]
pub fn ein<T: Real>(z: C<T>) -> C<T> {
    ein_at_most(z, EIN_COEFFS.len())
}

/// [`ein`] with at most `most` terms: fewer where a caller's tolerance allows (the surface's open
/// ray, `crate::surface`), never more than the bands give at `z`.
#[inline]
pub(crate) fn ein_at_most<T: Real>(z: C<T>, most: usize) -> C<T> {
    let mut sum = C::new(T::zero(), T::zero());
    for &c in EIN_COEFFS[..series_terms(z).min(most).min(EIN_COEFFS.len())].iter().rev() {
        sum = sum * z + T::lit(c);
    }
    sum * z
}

/// The series terms [`Real::E1_SERIES_BANDS`] gives at `z` (compared as `|z|²`, no square root).
#[inline]
fn series_terms<T: Real>(z: C<T>) -> usize {
    banded(z.norm_sqr().to_f64_exact(), T::E1_SERIES_BANDS)
}

/// `(−1)^{k+1}/(k·k!)`, `k = 1 … 40`: the coefficients of `Ein(x) = Σ c_k x^k`, each from
/// its predecessor by `c_k = −c_{k−1}·(k−1)/k²` in f64 (at most `k` roundings: the 40th is
/// within 40 ulps, and its term `x^40/(40·40!)` is below 1e-40 of the sum where it is used).
pub const EIN_COEFFS: [f64; 40] = {
    let mut c = [0.0; 40];
    c[0] = 1.0;
    let mut k = 2;
    while k <= 40 {
        c[k - 1] = -c[k - 2] * ((k - 1) as f64) / ((k * k) as f64);
        k += 1;
    }
    c
};

/// `Ein(x)` for real `x` by Horner's rule on the tabulated coefficients, as many as
/// [`Real::E1_SERIES_BANDS`] gives for `|x|` (the real axis of the series ellipse: `0 ≤ x < 2.5`
/// in f64, `< 1.3` in f32): no divisions.
#[inline]
pub fn ein_real<T: Real>(x: T) -> T {
    let mut sum = T::zero();
    for &c in EIN_COEFFS[..series_terms(C::new(x, T::zero())).min(40)].iter().rev() {
        sum = sum * x + T::lit(c);
    }
    sum * x
}

/// `(Ein(b) − Ein(a)) / (b − a)`, by the series of divided differences
/// `Σ (−1)^{k+1} h_{k−1}(a, b) / (k·k!)` with `h_m(a, b) = Σ_{j≤m} a^j b^{m−j}`, so that the
/// difference of `Ein` at two nearby points keeps its relative accuracy. Meant for
/// `|a|, |b| ≤ 1`. Terms by band of `R = max(|a|, |b|)` ([`Real::E1_DD_BANDS`]): `|h_{k−1}| ≤
/// k R^{k−1}` bounds the dropped terms by `Σ_{k>n} R^{k−1}/k!`, and the value, `Ein'` averaged
/// over the segment, is at least `min_{|ξ|=R} |(1 − e^{−ξ})/ξ|` (≥ 0.63 for `R ≤ 1`);
/// tests/reference/gen_e1_tuning.py takes the fewest terms keeping their ratio ≤ 8 unit
/// roundoffs.
#[inline]
pub fn ein_divided_difference<T: Real>(a: C<T>, b: C<T>) -> C<T> {
    let one = C::new(T::one(), T::zero());
    let mut h = one; // h_0
    let mut a_pow = one; // a^m
    let mut sum = C::new(T::zero(), T::zero());
    let terms = banded(a.norm_sqr().max(b.norm_sqr()).to_f64_exact(), T::E1_DD_BANDS);
    for &c in EIN_COEFFS[..terms.min(40)].iter() {
        sum = sum + h * T::lit(c);
        // advance to h_k = b·h_{k−1} + a^k
        a_pow = a_pow * a;
        h = h * b + a_pow;
    }
    sum
}
