//! Truncated power series ("jets"): exact Taylor coefficients of any function written as
//! generic [`Scalar`] code, by the standard recurrences for products, quotients, roots,
//! exponentials and logarithms (Griewank & Walther, *Evaluating Derivatives*, ch. 13).

use crate::real::Real;
use crate::scalar::Scalar;
use core::ops::{Add, Div, Mul, Neg, Sub};

/// `Σ c[k] s^k`, truncated after `N` terms: the Taylor expansion of a quantity in a small
/// offset `s` from the expansion point.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Jet<T: Real, const N: usize> {
    /// Taylor coefficients, `c[k] = f⁽ᵏ⁾(x₀)/k!`.
    pub c: [T; N],
}

impl<T: Real, const N: usize> Jet<T, N> {
    /// The independent variable at `x0`: `x0 + 1·s`.
    pub fn variable(x0: T) -> Self {
        let mut c = [T::zero(); N];
        if N > 0 {
            c[0] = x0;
        }
        if N > 1 {
            c[1] = T::one();
        }
        Jet { c }
    }
}

impl<T: Real, const N: usize> Add for Jet<T, N> {
    type Output = Self;
    #[inline]
    fn add(mut self, o: Self) -> Self {
        for k in 0..N {
            self.c[k] = self.c[k] + o.c[k];
        }
        self
    }
}

impl<T: Real, const N: usize> Sub for Jet<T, N> {
    type Output = Self;
    #[inline]
    fn sub(mut self, o: Self) -> Self {
        for k in 0..N {
            self.c[k] = self.c[k] - o.c[k];
        }
        self
    }
}

impl<T: Real, const N: usize> Neg for Jet<T, N> {
    type Output = Self;
    #[inline]
    fn neg(mut self) -> Self {
        for k in 0..N {
            self.c[k] = -self.c[k];
        }
        self
    }
}

impl<T: Real, const N: usize> Mul for Jet<T, N> {
    type Output = Self;
    /// Cauchy product.
    #[inline]
    fn mul(self, o: Self) -> Self {
        let mut c = [T::zero(); N];
        for k in 0..N {
            let mut s = T::zero();
            for j in 0..=k {
                s = s + self.c[j] * o.c[k - j];
            }
            c[k] = s;
        }
        Jet { c }
    }
}

impl<T: Real, const N: usize> Div for Jet<T, N> {
    type Output = Self;
    /// `q = a / b`: `q_k = (a_k − Σ_{j<k} q_j b_{k−j}) / b_0`.
    #[inline]
    fn div(self, b: Self) -> Self {
        let mut q = [T::zero(); N];
        for k in 0..N {
            let mut s = self.c[k];
            for j in 0..k {
                s = s - q[j] * b.c[k - j];
            }
            q[k] = s / b.c[0];
        }
        Jet { c: q }
    }
}

impl<T: Real, const N: usize> Scalar<T> for Jet<T, N> {
    fn cst(x: T) -> Self {
        let mut c = [T::zero(); N];
        if N > 0 {
            c[0] = x;
        }
        Jet { c }
    }
    #[inline]
    fn value(self) -> T {
        if N > 0 {
            self.c[0]
        } else {
            T::zero()
        }
    }
    fn scale(mut self, k: T) -> Self {
        for x in self.c.iter_mut() {
            *x = *x * k;
        }
        self
    }
    fn shift(mut self, k: T) -> Self {
        if N > 0 {
            self.c[0] = self.c[0] + k;
        }
        self
    }
    /// `r = √a`: `r_k = (a_k − Σ_{0<j<k} r_j r_{k−j}) / (2 r_0)`.
    fn sqrt(self) -> Self {
        let mut r = [T::zero(); N];
        if N == 0 {
            return Jet { c: r };
        }
        r[0] = num_traits::Float::sqrt(self.c[0]);
        let two_r0 = r[0] + r[0];
        for k in 1..N {
            let mut s = self.c[k];
            for j in 1..k {
                s = s - r[j] * r[k - j];
            }
            r[k] = s / two_r0;
        }
        Jet { c: r }
    }
    /// Repeated squaring; a negative power is the reciprocal of the positive one.
    fn powi(self, n: i32) -> Self {
        let mut base = self;
        let mut e = n.unsigned_abs();
        let mut acc = Self::cst(T::one());
        while e > 0 {
            if e & 1 == 1 {
                acc = acc * base;
            }
            e >>= 1;
            if e > 0 {
                base = base * base;
            }
        }
        if n < 0 {
            acc.recip()
        } else {
            acc
        }
    }
    fn powf(self, e: T) -> Self {
        (self.ln().scale(e)).exp()
    }
    /// `x = e^a`: `x_k = Σ_{1≤j≤k} (j/k) a_j x_{k−j}`.
    fn exp(self) -> Self {
        let mut x = [T::zero(); N];
        if N == 0 {
            return Jet { c: x };
        }
        x[0] = num_traits::Float::exp(self.c[0]);
        for k in 1..N {
            let mut s = T::zero();
            for j in 1..=k {
                s = s + T::from(j).unwrap() * self.c[j] * x[k - j];
            }
            x[k] = s / T::from(k).unwrap();
        }
        Jet { c: x }
    }
    /// `l = ln a`: `l_k = (a_k − Σ_{0<j<k} (j/k) l_j a_{k−j}) / a_0`.
    fn ln(self) -> Self {
        let mut l = [T::zero(); N];
        if N == 0 {
            return Jet { c: l };
        }
        l[0] = num_traits::Float::ln(self.c[0]);
        for k in 1..N {
            let mut s = self.c[k];
            for j in 1..k {
                s = s - T::from(j).unwrap() / T::from(k).unwrap() * l[j] * self.c[k - j];
            }
            l[k] = s / self.c[0];
        }
        Jet { c: l }
    }
}
