//! Region selection for the complex exponential integral (in the style of Julia's
//! `SpecialFunctions.expint`): power series inside an ellipse around the origin, continued
//! fraction outside. Each side takes its iteration count from a table by band of `|z|` (the
//! fewest terms that band needs), so no loop waits on convergence: at most 29 series terms or
//! 39 fraction levels in f64, 13 or 14 in f32 (tests/reference/gen_e1_tuning.py derives every
//! count from the bounds below).
//!
//! The ellipse semi-axes (`Real::E1_SERIES_ELLIPSE`) sit where both methods meet their
//! budget: along the real axis the series loses `≈ e^{2x}` ulps to cancellation (so it must
//! stop early: `x < 2.5` in f64, `x < 1.3` in f32), along the imaginary axis it does not, and
//! there the fraction converges slowest (so the series reaches further: `|y| < 4`, `< 2.1`).

use super::{complex::norm_sqr_in_range, continued_fraction::e1_scaled_cf, series::ein, C, EULER_GAMMA};
use crate::real::Real;

/// `true` where `E1(z)` is evaluated by its power series.
#[inline]
pub fn in_series_region<T: Real>(z: C<T>) -> bool {
    let (a, b) = T::E1_SERIES_ELLIPSE;
    let x = z.re * T::lit(1.0 / a);
    let y = z.im * T::lit(1.0 / b);
    x * x + y * y < T::one()
}

/// `E1(z)` by the series: `−γ − ln z + Ein(z)`, for `z` in the series region
/// ([`in_series_region`]).
#[inline]
pub(crate) fn e1_by_series<T: Real>(z: C<T>) -> C<T> {
    ein(z) - ln_in_series_region(z) - T::lit(EULER_GAMMA)
}

/// `ln z` with `ln|z| = ½ ln(x² + y²)` where that is safe ([`norm_sqr_in_range`]: everywhere in
/// the series ellipse but within `2^{−30}` of 0), `num_complex`'s `hypot`-based `ln` elsewhere.
#[inline]
fn ln_in_series_region<T: Real>(z: C<T>) -> C<T> {
    match norm_sqr_in_range(z) {
        Some(n) => C::new(n.ln() * T::lit(0.5), z.im.atan2(z.re)),
        None => z.ln(),
    }
}

/// NaN, the value outside the domain `Re z ≥ 0`.
#[inline]
fn outside<T: Real>() -> C<T> {
    C::new(T::nan(), T::nan())
}

/// The exponential integral `E1(z) = ∫_z^∞ e^{−t}/t dt` for `Re z ≥ 0` (principal branch).
/// `E1(0) = +∞`. Underflows to 0 where `Re z` exceeds the exponent range; use
/// [`e1_scaled`] there. For `Re z < 0` (or a NaN part) it returns NaN: the fixed term counts
/// were derived for the right half-plane only, and near the negative real axis neither the
/// series budget nor the fraction's would hold (A&S 5.1.11, 5.1.22).
#[inline]
pub fn e1<T: Real>(z: C<T>) -> C<T> {
    if !(z.re >= T::zero()) || z.im.is_nan() {
        return outside();
    }
    if in_series_region(z) {
        e1_by_series(z)
    } else {
        e1_scaled_cf(z) * (-z).exp()
    }
}

/// The scaled exponential integral `e^z E1(z)` for `Re z ≥ 0`; it behaves like `1/z` for large
/// `|z|` and never overflows there. NaN for `Re z < 0`, as [`e1`].
#[inline]
pub fn e1_scaled<T: Real>(z: C<T>) -> C<T> {
    if !(z.re >= T::zero()) || z.im.is_nan() {
        return outside();
    }
    if in_series_region(z) {
        e1_by_series(z) * z.exp()
    } else {
        e1_scaled_cf(z)
    }
}

/// The exponential integral `Ei(z) = −E1(−z) + iπ·sign(Im z)` (A&S 5.1.7), for `Re z ≤ 0`
/// (NaN elsewhere, as [`e1`]); on the negative real axis it is the real `−E1(−z)`.
#[inline]
pub fn ei<T: Real>(z: C<T>) -> C<T> {
    let s = if z.im > T::zero() {
        T::PI()
    } else if z.im < T::zero() {
        -T::PI()
    } else {
        T::zero()
    };
    -e1(-z) + C::new(T::zero(), s)
}
