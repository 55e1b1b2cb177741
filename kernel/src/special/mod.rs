//! Special functions (docs/DESIGN.md §3, paper §4.1–4.2; §11 for `E(m)`).
//!
//! * [`e1`](fn@e1), [`e1_scaled`], [`ei`]: complex `E1(z)`, `e^z E1(z)` and `Ei(z)` for `Re z ≥ 0`
//!   (for `Ei`: `Re z ≤ 0`), the production path: power series inside an ellipse around the
//!   origin, continued fraction outside, each with a fixed term count chosen by band of `|z|`
//!   ([`Real::E1_SERIES_BANDS`](crate::Real::E1_SERIES_BANDS),
//!   [`Real::E1_CF_DEPTH`](crate::Real::E1_CF_DEPTH)).
//! * [`ein_divided_difference`]: `(Ein(b) − Ein(a))/(b − a)` without cancellation, for
//!   differences of `E1` at nearby points with the logarithm split off.
//! * [`en_scaled`]: real `e^x E_n(x)`, `n = 1, 2, …`.
//! * [`elliptic_e`]: the complete elliptic integral of the second kind, `E(m)`.
//! * [`paper`]: the paper's own power/asymptotic `Ei` (eq. 21–27, fig. 2), kept for comparison.

mod complex;
mod continued_fraction;
mod e1;
mod elliptic;
mod en;
pub mod paper;
mod series;

pub use complex::{cdiv, csqrt, C};
pub use continued_fraction::{e1_scaled_cf, PLAIN_FROM};
pub(crate) use e1::e1_by_series;
pub use e1::{e1, e1_scaled, ei, in_series_region};
pub use elliptic::elliptic_e;
pub use en::en_scaled;
pub(crate) use series::ein_at_most;
pub use series::{ein, ein_divided_difference, ein_real, EIN_COEFFS};

/// The count of the first band `(bound, count)` with `|z| < bound`, given `|z|²` (the last
/// band's for larger `|z|`, or a NaN): the iteration tables of [`crate::Real`].
#[inline]
pub(crate) fn banded(r2: f64, bands: &[(f64, usize)]) -> usize {
    let mut count = 0;
    for &(bound, n) in bands {
        count = n;
        if r2 < bound * bound {
            break;
        }
    }
    count
}

/// Euler–Mascheroni constant γ (A&S 6.1.3).
pub const EULER_GAMMA: f64 = 0.577_215_664_901_532_860_606_512_090_082;

#[cfg(test)]
mod tests {
    use super::*;

    /// Published values: `E1(0.5)`, `E1(1)` (A&S table 5.1), and on the imaginary axis
    /// `E1(i) = −Ci(1) + i(Si(1) − π/2)` (A&S 5.2.23, Ci(1), Si(1) from table 5.2); `E_2(1) =
    /// e^{−1} − E1(1)` (A&S 5.1.14).
    #[test]
    fn exponential_integrals_against_published_tables() {
        let close = |a: f64, b: f64, tol: f64| (a - b).abs() <= tol * b.abs();
        assert!(close(e1(C::new(0.5f64, 0.0)).re, 0.559_773_594_776_161, 1e-14));
        assert!(close(e1(C::new(1.0f64, 0.0)).re, 0.219_383_934_395_520, 1e-14));
        let z = e1(C::new(0.0f64, 1.0));
        assert!(close(z.re, -0.337_403_922_900_968, 1e-14) && close(z.im, 0.946_083_070_367_183 - core::f64::consts::FRAC_PI_2, 1e-14), "{z:?}");
        let z32 = e1(C::new(0.0f32, 1.0));
        assert!(close(z32.re as f64, -0.337_403_922_900_968, 1e-6) && close(z32.im as f64, -0.624_713_256_427_714, 1e-6), "{z32:?}");
        // far out, e^x E1(x) ~ (1/x) Σ (−1)^k k!/x^k (A&S 5.1.51): at x = 1e4 the terms
        // after 24/x⁴ are below 1e-17
        let x = 1e4f64;
        let s = e1_scaled(C::new(x, 0.0)).re;
        assert!(close(s, (1.0 - 1.0 / x + 2.0 / (x * x) - 6.0 / (x * x * x) + 24.0 / (x * x * x * x)) / x, 1e-15));
        let mut en = [0.0f64; 3];
        en_scaled(1.0, &mut en);
        assert!(close(en[1] * (-1.0f64).exp(), (-1.0f64).exp() - 0.219_383_934_395_520, 1e-14));
        // outside the domain: NaN, not a wrong number
        assert!(e1(C::new(-2.53f64, 0.043)).re.is_nan());
    }

    /// f32's fractions (top-down in f64, the tail and `|B|²` formed without rescaling) up to
    /// the end of f32's range, on both axes and between them: `e^z E1(z)` against A&S 5.1.51's
    /// `(1/z)(1 − 1/z + 2/z² − 6/z³)`, whose truncation `24/|z|⁴` is below 3e-39 of the value
    /// for `|z| ≥ 1e10`. Allowed: two f32 epsilons of the value (the output's rounding and the
    /// fraction's) plus two subnormal spacings, for values below f32's normal range (`1/z` at
    /// `|z| > 8.5e37`).
    #[test]
    fn f32_fractions_to_the_end_of_the_range() {
        for (re, im) in [(3.4e38f32, 0.0f32), (3.0e38, 3.0e38), (0.0, 3.4e38), (0.0, -3.4e38), (2.5e38, -1e38), (1e-30, 3e38), (1e20, 1e-20), (1e15, 0.0), (1e10, -1e10)] {
            let w = e1_scaled(C::new(re, im));
            let inv = C::new(1.0, 0.0) / C::new(re as f64, im as f64);
            let want = inv * (C::new(1.0, 0.0) - inv + inv * inv * 2.0 - inv * inv * inv * 6.0);
            let err = (C::new(w.re as f64, w.im as f64) - want).norm();
            let bound = 2.0 * f32::EPSILON as f64 * want.norm() + 2.0 * f32::from_bits(1) as f64;
            assert!(err <= bound, "z = {re:e} + {im:e}i: {w:?} against {want:?} (error {err:.2e}, bound {bound:.2e})");
        }
    }
}
