//! Complex helpers the kernel needs beyond `num_complex`: an overflow-safe square root.

use crate::real::Real;
use num_complex::Complex;

/// The complex numbers the kernel computes with.
pub type C<T> = Complex<T>;

/// Principal square root, `Re ≥ 0`, computed from `hypot` so that it neither overflows nor
/// loses the small component (Kahan's formula).
#[inline]
pub fn csqrt<T: Real>(z: C<T>) -> C<T> {
    let (x, y) = (z.re, z.im);
    if x == T::zero() && y == T::zero() {
        return C::new(T::zero(), y);
    }
    let half = T::lit(0.5);
    let r = x.hypot(y);
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
