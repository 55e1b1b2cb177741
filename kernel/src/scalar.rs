//! Numbers that phase functions and light distributions are written over.
//!
//! A [`PhaseFunction`](crate::PhaseFunction) or [`LightDistribution`](crate::LightDistribution)
//! is ordinary generic code over [`Scalar`]. Evaluated on a plain float it gives values (used by
//! the Chebyshev interpolant); evaluated on a [`Jet`](crate::expansion::Jet) it gives exact Taylor
//! coefficients (docs/DESIGN.md §4: derive nothing by hand).

use crate::real::Real;
use core::ops::{Add, Div, Mul, Neg, Sub};

/// Arithmetic that both plain floats and truncated power series support.
pub trait Scalar<T: Real>:
    Copy
    + Add<Output = Self>
    + Sub<Output = Self>
    + Mul<Output = Self>
    + Div<Output = Self>
    + Neg<Output = Self>
{
    /// The constant `x`.
    fn cst(x: T) -> Self;
    /// The value (the constant term of a series). Use it for branch decisions such as a clamp.
    fn value(self) -> T;
    /// `self · k` for a plain number `k`.
    fn scale(self, k: T) -> Self;
    /// `self + k` for a plain number `k`.
    fn shift(self, k: T) -> Self;
    /// Square root.
    fn sqrt(self) -> Self;
    /// `self^n` for an integer `n` (negative allowed).
    fn powi(self, n: i32) -> Self;
    /// `self^e` for a real exponent (`self > 0`).
    fn powf(self, e: T) -> Self;
    /// `e^self`.
    fn exp(self) -> Self;
    /// Natural logarithm (`self > 0`).
    fn ln(self) -> Self;
    /// `1 / self`.
    fn recip(self) -> Self {
        Self::cst(T::one()) / self
    }
}

impl<T: Real> Scalar<T> for T {
    #[inline(always)]
    fn cst(x: T) -> Self {
        x
    }
    #[inline(always)]
    fn value(self) -> T {
        self
    }
    #[inline(always)]
    fn scale(self, k: T) -> Self {
        self * k
    }
    #[inline(always)]
    fn shift(self, k: T) -> Self {
        self + k
    }
    #[inline(always)]
    fn sqrt(self) -> Self {
        num_traits::Float::sqrt(self)
    }
    /// By repeated squaring inline, the products in the order compiler-rt's `__powidf2` /
    /// `__powisf2` takes them (what `powi` calls for a power not known at compile time): the
    /// same value, without the call.
    #[inline(always)]
    fn powi(self, n: i32) -> Self {
        let (mut base, mut k, mut out) = (self, n.unsigned_abs(), T::one());
        loop {
            if k & 1 == 1 {
                out = out * base;
            }
            k >>= 1;
            if k == 0 {
                break;
            }
            base = base * base;
        }
        if n < 0 {
            out.recip()
        } else {
            out
        }
    }
    #[inline(always)]
    fn powf(self, e: T) -> Self {
        num_traits::Float::powf(self, e)
    }
    #[inline(always)]
    fn exp(self) -> Self {
        num_traits::Float::exp(self)
    }
    #[inline(always)]
    fn ln(self) -> Self {
        num_traits::Float::ln(self)
    }
    #[inline(always)]
    fn recip(self) -> Self {
        num_traits::Float::recip(self)
    }
}

#[cfg(test)]
mod tests {
    use super::Scalar;
    use core::hint::black_box;

    /// The inline squaring gives `powi`'s value bit for bit (the library call it replaces), for
    /// every power a distribution uses (`c^p`, `p ≤ 1024`) and negative ones, in both precisions.
    #[test]
    fn powi_matches_the_library_bitwise() {
        let xs = [0.0, -0.0, 1e-3, 0.1, 0.3, 0.5, 0.7072, 0.9, 0.99, 0.999_999, 1.0, -0.37, -0.93, 1.5, -2.25, 7.0];
        for &x in &xs {
            for n in (-40..=64).chain((66..=1024).step_by(34)) {
                let n = black_box(n);
                let (ours, lib) = (Scalar::powi(x, n), f64::powi(x, n));
                assert!(ours.to_bits() == lib.to_bits() || (ours.is_nan() && lib.is_nan()), "f64 {x}^{n}: {ours} vs {lib}");
                let x = x as f32;
                let (ours, lib) = (Scalar::powi(x, n), f32::powi(x, n));
                assert!(ours.to_bits() == lib.to_bits() || (ours.is_nan() && lib.is_nan()), "f32 {x}^{n}: {ours} vs {lib}");
            }
        }
    }
}
