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
    #[inline(always)]
    fn powi(self, n: i32) -> Self {
        num_traits::Float::powi(self, n)
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
