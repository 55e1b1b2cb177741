//! Polynomial expansion of `F = D(c)·P(μ)` over one half's sub-interval (docs/DESIGN.md §4).
//!
//! Both expansions return coefficients `a_k` of `F ≈ Σ_{k<N} a_k s^k` in the local offset
//! `s = y − y_c` from the sub-interval's midpoint, which is what [`crate::integrals`] integrates.
//! * [`Expansion::Taylor`]: the paper's choice (app. B, eq. 42) — Taylor coefficients at the
//!   midpoint, here computed exactly by jet arithmetic instead of hand-derived derivatives.
//! * [`Expansion::Chebyshev`]: the polynomial interpolating `F` at the `N` Chebyshev nodes of
//!   the sub-interval; near-best in the max norm over the whole interval, from `N` plain
//!   evaluations. It is the default: see the error table in the README.

mod chebyshev;
#[allow(clippy::excessive_precision)]
pub mod gauss_table;
#[allow(clippy::excessive_precision)]
pub mod laguerre_table;
mod jet;

pub use chebyshev::chebyshev_coefficients;
pub(crate) use chebyshev::chebyshev_series;
pub use jet::Jet;

use crate::real::Real;
use crate::scalar::Scalar;

/// The last four coefficients `a_{N−4} … a_{N−1}` of the discrete Laguerre transform of an
/// `N`-node rule's samples `g_i` ([`laguerre_table`], whose row `k`, column `i` is
/// `w_i L_k(x_i)`): `a_k = Σ_i w_i L_k(x_i) g_i`, the coefficients an error estimate reads.
pub(crate) fn last_laguerre_coefficients<T: Real>(transform: &[f64], samples: &[T]) -> [T; 4] {
    let n = samples.len();
    core::array::from_fn(|j| {
        let row = &transform[(n - 4 + j) * n..(n - 3 + j) * n];
        row.iter().zip(samples).fold(T::zero(), |acc, (&t, &s)| acc + T::lit(t) * s)
    })
}

/// How `F` is turned into a polynomial on each sub-interval.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum Expansion {
    /// Interpolation at Chebyshev nodes (default).
    #[default]
    Chebyshev,
    /// Taylor series at the sub-interval's midpoint (the paper's method).
    Taylor,
}

/// A function of the bounded variable `y` that can be evaluated on plain numbers and on jets.
pub trait Expandable<T: Real> {
    /// `F(y)`.
    fn eval<S: Scalar<T>>(&self, y: S) -> S;
    /// `(F(y), 1/(1 + y²))`: the panels need both, and an integrand that forms `1/(1 + y²)`
    /// on its way to `F` returns it instead of having it divided out again.
    fn eval_over(&self, y: T) -> (T, T) {
        (self.eval(y), (T::one() + y * y).recip())
    }
    /// `(F(1/v), 1/(1 + v²))`: the second half's v-panels sample in `v = 1/y`; an integrand
    /// that can be written in `v` directly saves the reciprocal.
    fn eval_over_reciprocal(&self, v: T) -> (T, T) {
        let y = v.recip();
        let (f, inv) = self.eval_over(y);
        (f, y * y * inv)
    }
    /// `(F, 1/(1 + y²))` at each of `N` points, with [`eval_over`](Self::eval_over)'s values, or
    /// [`eval_over_reciprocal`](Self::eval_over_reciprocal)'s at `v = 1/y` where `reciprocal`:
    /// what a panel of `N` samples calls. The default evaluates one by one; an integrand whose
    /// evaluation branches on its parameters alone may take each branch once for all `N`.
    fn eval_over_each<const N: usize>(&self, points: &[T; N], reciprocal: bool) -> [(T, T); N] {
        core::array::from_fn(|i| if reciprocal { self.eval_over_reciprocal(points[i]) } else { self.eval_over(points[i]) })
    }
    /// `(t, α)`: heights `t > 0` such that `F/(1 + y²)`, continued to complex `y`, may be
    /// singular at `y = ±it` with order `α` (`~ (y ∓ it)^{−α}`; three at most; those of the
    /// built-in integrands all lie on the imaginary axis), or `None` when they are not known (the
    /// default). The panels' error estimate takes the least decay rate of the Legendre
    /// coefficients from them.
    fn singularities(&self) -> Option<[(T, T); 3]> {
        None
    }
}

impl Expansion {
    /// Coefficients of `F ≈ Σ a_k (y − y_c)^k` on `[y_c − r, y_c + r]`.
    pub fn coefficients<T: Real, F: Expandable<T>, const N: usize>(self, f: &F, y_c: T, r: T) -> [T; N] {
        match self {
            Expansion::Taylor => f.eval(Jet::<T, N>::variable(y_c)).c,
            Expansion::Chebyshev => chebyshev_coefficients(|y| f.eval(y), y_c, r),
        }
    }
}
