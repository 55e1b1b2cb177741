//! Complex helpers the kernel needs beyond `num_complex`: an overflow-safe square root and
//! division.

use crate::real::Real;
use num_complex::Complex;

/// The complex numbers the kernel computes with.
pub type C<T> = Complex<T>;

/// `|z|² = x² + y²` where it can neither overflow nor lose `|z|` to underflow
/// (`2^{−60} < |z|² < 2^{60}`, safe in f32 and f64), else `None`: there `|z|` needs `hypot`.
/// Inside the range a component whose square underflows is below `2^{−33}|z|`, so dropping it
/// changes nothing.
#[inline]
pub(crate) fn norm_sqr_in_range<T: Real>(z: C<T>) -> Option<T> {
    let n = z.re * z.re + z.im * z.im;
    (n > T::lit(8.673_617_379_884_035e-19) && n < T::lit(1.152_921_504_606_847e18)).then_some(n)
}

/// Principal square root, `Re ≥ 0`, by Kahan's formula, which neither overflows nor loses the
/// small component: `|z|` as `√(x² + y²)` where that is safe (`2^{−60} < |z|² < 2^{60}`), by
/// `hypot` elsewhere.
#[inline]
pub fn csqrt<T: Real>(z: C<T>) -> C<T> {
    let (x, y) = (z.re, z.im);
    if x == T::zero() && y == T::zero() {
        return C::new(T::zero(), y);
    }
    let half = T::lit(0.5);
    let r = norm_sqr_in_range(z).map_or_else(|| x.hypot(y), |n| n.sqrt());
    if x >= T::zero() {
        let t = ((r + x) * half).sqrt();
        C::new(t, y / (t + t))
    } else {
        let t = ((r - x) * half).sqrt();
        C::new(y.abs() / (t + t), t.copysign(y))
    }
}

/// `a / b` by Smith's algorithm: no overflow of `|b|²` for huge `|b|`, no underflow for tiny.
/// Two divisions (the ratio and one reciprocal of the denominator): one rounding more per
/// component than dividing twice by it.
#[inline]
pub fn cdiv<T: Real>(a: C<T>, b: C<T>) -> C<T> {
    if b.re.abs() >= b.im.abs() {
        let r = b.im / b.re;
        let inv = (b.re + b.im * r).recip();
        C::new((a.re + a.im * r) * inv, (a.im - a.re * r) * inv)
    } else {
        let r = b.re / b.im;
        let inv = (b.re * r + b.im).recip();
        C::new((a.re * r + a.im) * inv, (a.im * r - a.re) * inv)
    }
}
