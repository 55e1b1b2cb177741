//! Phase functions `P(μ)`, normalised over the sphere (`∫ P dω = 1`); `μ` is the cosine of
//! the scattering angle, `μ = 1` for light going straight on towards the viewer (docs/DESIGN.md §1).
//!
//! Implement [`PhaseFunction`] to add your own: write `eval` once over [`Scalar`] and the
//! kernel gets both values (Chebyshev interpolation) and exact Taylor coefficients (jets).

use crate::error::{check_asymmetry, check_finite, InputError};
use crate::real::Real;
use crate::scalar::Scalar;

/// A phase function of the scattering cosine.
pub trait PhaseFunction<T: Real> {
    /// `P(μ)` for `μ ∈ [−1, 1]`.
    fn eval<S: Scalar<T>>(&self, mu: S) -> S;
    /// `P(μ)` given `1 − μ` and `1 + μ` to full relative accuracy as well (the error-controlled
    /// path knows them exactly as `2y²/(1+y²)` and `2/(1+y²)`). Near a lobe's peak `μ → ±1`,
    /// forming `1 ∓ μ` from `μ` loses `ε/(1 ∓ μ)` of it, which a peaked phase function
    /// amplifies (Henyey–Greenstein at `g = 0.99`: `3/(1 − g)²`-fold). Phase functions peaked
    /// at the poles override this; the default ignores the sides and calls [`eval`](Self::eval).
    fn eval_sides<S: Scalar<T>>(&self, mu: S, one_minus_mu: S, one_plus_mu: S) -> S {
        let _ = (one_minus_mu, one_plus_mu);
        self.eval(mu)
    }
    /// [`eval_sides`](Self::eval_sides) at each of `N` cosines, with its values: what a rule
    /// of `N` samples calls (the light-angle route, `crate::angle`). The default evaluates one
    /// by one; an enum of phase functions overrides it to dispatch once for all `N`.
    fn eval_sides_each<const N: usize>(&self, mu: &[T; N], one_minus_mu: &[T; N], one_plus_mu: &[T; N]) -> [T; N] {
        core::array::from_fn(|i| self.eval_sides(mu[i], one_minus_mu[i], one_plus_mu[i]))
    }
    /// `true` if `P` is constant: the kernel then skips the expansion.
    fn is_isotropic(&self) -> bool {
        false
    }
    /// Where `P`, continued to complex `μ`, is singular ([`Singularities`]), or `None` when
    /// that is not known (the default). A lobe that peaks at `μ = ±1` has a singularity just
    /// beyond: Henyey–Greenstein at `(1 + g²)/(2g)`. With them the error-controlled path knows
    /// how fast its panels' coefficients must fall and trusts their tail (docs/DESIGN.md §4.1);
    /// without, it assumes nothing.
    fn singularities(&self) -> Option<Singularities<T>> {
        None
    }
    /// Checks the parameters; the checked API calls it.
    fn validate(&self) -> Result<(), InputError> {
        Ok(())
    }
}

/// `1/(4π)`.
#[inline]
fn inv_4pi<T: Real>() -> T {
    T::FRAC_1_PI() * T::lit(0.25)
}

/// `(1 − μ, 1 + μ)` formed from `μ` (for [`PhaseFunction::eval`]).
#[inline]
fn sides<T: Real, S: Scalar<T>>(mu: S) -> (S, S) {
    (mu.scale(-T::one()).shift(T::one()), mu.shift(T::one()))
}

/// `(1 + g² − 2gμ)^{−3/2}`, the Henyey–Greenstein kernel without its constant, from
/// `1 − μ` and `1 + μ`.
#[inline]
fn hg_kernel<T: Real, S: Scalar<T>>(g: T, one_minus_mu: S, one_plus_mu: S) -> S {
    // 1 + g² − 2gμ as two non-negative terms, so that it never cancels at the lobe's peak
    // (μ = ±1 with |g| → 1, where 1 + g² ≈ 2gμ rounded to 0 and gave +∞):
    // g ≥ 0: (1 − g)² + 2g(1 − μ); g < 0: (1 + g)² − 2g(1 + μ).
    let base = if g >= T::zero() {
        let a = T::one() - g;
        one_minus_mu.scale(g + g).shift(a * a)
    } else {
        let b = T::one() + g;
        one_plus_mu.scale(-(g + g)).shift(b * b)
    };
    (base * base.sqrt()).recip()
}

/// The singularities of a phase function continued to complex `μ`
/// ([`PhaseFunction::singularities`]).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Singularities<T> {
    /// Up to two real cosines outside `[−1, 1]` where `P` is singular (`±∞` for none).
    pub cosines: [T; 2],
    /// Their order `α`: `P ~ (μ − μ*)^{−α}` there (Henyey–Greenstein `3/2`, Schlick `2`).
    pub order: T,
    /// `P ~ μ^d` as `μ → ∞` (Rayleigh `2`; `0` or less: bounded). Along a ray `μ(y)` has poles
    /// at `y = ±i`, where this makes a pole of order `d`.
    pub growth: T,
}

/// `(1 + g²)/(2g) = ±(1 + (1 − |g|)²/(2|g|))`, where the Henyey–Greenstein kernel
/// `(1 + g² − 2gμ)^{−3/2}` is singular (`+∞` at `g = 0`), its offset from `±1` without cancellation.
fn hg_singular_cosine<T: Real>(g: T) -> T {
    let a = g.abs();
    if a == T::zero() {
        return T::infinity();
    }
    let gap = (T::one() - a) * (T::one() - a) / (a + a);
    (T::one() + gap).copysign(g)
}

/// No singularity at finite `μ`; `P ~ μ^growth` at infinity.
fn polynomial<T: Real>(growth: f64) -> Option<Singularities<T>> {
    Some(Singularities { cosines: [T::infinity(), T::infinity()], order: T::zero(), growth: T::lit(growth) })
}

/// Henyey–Greenstein's kernel `(1 + g² − 2gμ)^{−3/2}` at `g` and `g2`: order `3/2` at its
/// cosines, `μ^{−3/2}` at infinity (times `μ^extra`, Cornette–Shanks' `1 + μ²`).
fn hg_singularities<T: Real>(g: T, g2: Option<T>, extra: f64) -> Option<Singularities<T>> {
    let second = g2.map_or(T::infinity(), hg_singular_cosine);
    Some(Singularities { cosines: [hg_singular_cosine(g), second], order: T::lit(1.5), growth: T::lit(extra - 1.5) })
}

/// `1 − g²` as `(1 − g)(1 + g)`: exact factors, no cancellation for `|g| → 1`.
fn one_minus_sq<T: Real>(g: T) -> T {
    (T::one() - g) * (T::one() + g)
}

/// Isotropic scattering, `P = 1/(4π)`.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Isotropic;

impl<T: Real> PhaseFunction<T> for Isotropic {
    fn eval<S: Scalar<T>>(&self, _mu: S) -> S {
        S::cst(inv_4pi())
    }
    fn is_isotropic(&self) -> bool {
        true
    }
    fn singularities(&self) -> Option<Singularities<T>> {
        polynomial(0.0)
    }
}

/// Rayleigh scattering, `P = 3/(16π) (1 + μ²)`.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Rayleigh;

impl<T: Real> PhaseFunction<T> for Rayleigh {
    fn eval<S: Scalar<T>>(&self, mu: S) -> S {
        (mu * mu).shift(T::one()).scale(T::lit(3.0 / 16.0) * T::FRAC_1_PI())
    }
    fn singularities(&self) -> Option<Singularities<T>> {
        polynomial(2.0)
    }
}

/// Henyey–Greenstein, `P = (1 − g²) / (4π (1 + g² − 2gμ)^{3/2})`, `|g| < 1`.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct HenyeyGreenstein<T> {
    /// Asymmetry: mean cosine of the scattering angle; `g > 0` scatters forward.
    pub g: T,
}

impl<T: Real> PhaseFunction<T> for HenyeyGreenstein<T> {
    fn eval<S: Scalar<T>>(&self, mu: S) -> S {
        let (minus, plus) = sides(mu);
        self.eval_sides(mu, minus, plus)
    }
    fn eval_sides<S: Scalar<T>>(&self, _mu: S, one_minus_mu: S, one_plus_mu: S) -> S {
        let g = self.g;
        hg_kernel(g, one_minus_mu, one_plus_mu).scale(one_minus_sq(g) * inv_4pi::<T>())
    }
    fn is_isotropic(&self) -> bool {
        self.g == T::zero()
    }
    fn singularities(&self) -> Option<Singularities<T>> {
        hg_singularities(self.g, None, 0.0)
    }
    fn validate(&self) -> Result<(), InputError> {
        check_asymmetry(self.g, "phase.g")
    }
}

/// Schlick's rational approximation of Henyey–Greenstein,
/// `P = (1 − k²) / (4π (1 − kμ)²)`, `|k| < 1` (`k ≈ 1.55g − 0.55g³` mimics HG with `g`).
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Schlick<T> {
    /// Asymmetry parameter; `k > 0` scatters forward.
    pub k: T,
}

impl<T: Real> PhaseFunction<T> for Schlick<T> {
    fn eval<S: Scalar<T>>(&self, mu: S) -> S {
        let k = self.k;
        let d = mu.scale(-k).shift(T::one());
        (d * d).recip().scale(one_minus_sq(k) * inv_4pi::<T>())
    }
    fn eval_sides<S: Scalar<T>>(&self, _mu: S, one_minus_mu: S, one_plus_mu: S) -> S {
        // 1 − kμ = (1 − k) + k(1 − μ) for k ≥ 0, (1 + k) − k(1 + μ) for k < 0: no cancellation
        let k = self.k;
        let d = if k >= T::zero() { one_minus_mu.scale(k).shift(T::one() - k) } else { one_plus_mu.scale(-k).shift(T::one() + k) };
        (d * d).recip().scale(one_minus_sq(k) * inv_4pi::<T>())
    }
    fn is_isotropic(&self) -> bool {
        self.k == T::zero()
    }
    fn singularities(&self) -> Option<Singularities<T>> {
        // (1 − kμ)^{−2}: a double pole at μ = 1/k = ±(1 + (1 − |k|)/|k|)
        let a = self.k.abs();
        let mu = if a == T::zero() { T::infinity() } else { (T::one() + (T::one() - a) / a).copysign(self.k) };
        Some(Singularities { cosines: [mu, T::infinity()], order: T::lit(2.0), growth: T::lit(-2.0) })
    }
    fn validate(&self) -> Result<(), InputError> {
        check_asymmetry(self.k, "phase.k")
    }
}

/// Cornette–Shanks, `P = 3(1 − g²)(1 + μ²) / (8π (2 + g²)(1 + g² − 2gμ)^{3/2})`, `|g| < 1`:
/// Henyey–Greenstein with a Rayleigh-like `1 + μ²` factor, normalised.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct CornetteShanks<T> {
    /// Asymmetry parameter.
    pub g: T,
}

impl<T: Real> PhaseFunction<T> for CornetteShanks<T> {
    fn eval<S: Scalar<T>>(&self, mu: S) -> S {
        let (minus, plus) = sides(mu);
        self.eval_sides(mu, minus, plus)
    }
    fn eval_sides<S: Scalar<T>>(&self, mu: S, one_minus_mu: S, one_plus_mu: S) -> S {
        let g = self.g;
        let k = T::lit(3.0 / 8.0) * T::FRAC_1_PI() * one_minus_sq(g) / (T::lit(2.0) + g * g);
        (hg_kernel(g, one_minus_mu, one_plus_mu) * (mu * mu).shift(T::one())).scale(k)
    }
    fn singularities(&self) -> Option<Singularities<T>> {
        hg_singularities(self.g, None, 2.0)
    }
    fn validate(&self) -> Result<(), InputError> {
        check_asymmetry(self.g, "phase.g")
    }
}

/// Two Henyey–Greenstein lobes, `P = w·HG(g1) + (1 − w)·HG(g2)`, `w ∈ [0, 1]`
/// (a forward and a back lobe, as engines use for fog and clouds).
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct TwoLobeHenyeyGreenstein<T> {
    /// Asymmetry of the first lobe.
    pub g1: T,
    /// Asymmetry of the second lobe.
    pub g2: T,
    /// Weight of the first lobe.
    pub w: T,
}

impl<T: Real> PhaseFunction<T> for TwoLobeHenyeyGreenstein<T> {
    fn eval<S: Scalar<T>>(&self, mu: S) -> S {
        let (minus, plus) = sides(mu);
        self.eval_sides(mu, minus, plus)
    }
    fn eval_sides<S: Scalar<T>>(&self, mu: S, one_minus_mu: S, one_plus_mu: S) -> S {
        let a = HenyeyGreenstein { g: self.g1 }.eval_sides(mu, one_minus_mu, one_plus_mu).scale(self.w);
        let b = HenyeyGreenstein { g: self.g2 }.eval_sides(mu, one_minus_mu, one_plus_mu).scale(T::one() - self.w);
        a + b
    }
    fn is_isotropic(&self) -> bool {
        self.g1 == T::zero() && self.g2 == T::zero()
    }
    fn singularities(&self) -> Option<Singularities<T>> {
        hg_singularities(self.g1, Some(self.g2), 0.0)
    }
    fn validate(&self) -> Result<(), InputError> {
        check_asymmetry(self.g1, "phase.g1")?;
        check_asymmetry(self.g2, "phase.g2")?;
        check_finite(self.w, "phase.w")?;
        if self.w < T::zero() || self.w > T::one() {
            return Err(InputError::new("phase.w", crate::error::ErrorKind::NotAFraction));
        }
        Ok(())
    }
}

/// Any of the built-in phase functions, chosen at run time (scene files, the CLI, shaders).
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum AnyPhase<T> {
    /// [`Isotropic`].
    Isotropic,
    /// [`Rayleigh`].
    Rayleigh,
    /// [`HenyeyGreenstein`].
    HenyeyGreenstein(HenyeyGreenstein<T>),
    /// [`Schlick`].
    Schlick(Schlick<T>),
    /// [`CornetteShanks`].
    CornetteShanks(CornetteShanks<T>),
    /// [`TwoLobeHenyeyGreenstein`].
    TwoLobeHenyeyGreenstein(TwoLobeHenyeyGreenstein<T>),
}

impl<T: Real> PhaseFunction<T> for AnyPhase<T> {
    fn eval<S: Scalar<T>>(&self, mu: S) -> S {
        match self {
            AnyPhase::Isotropic => Isotropic.eval(mu),
            AnyPhase::Rayleigh => Rayleigh.eval(mu),
            AnyPhase::HenyeyGreenstein(p) => p.eval(mu),
            AnyPhase::Schlick(p) => p.eval(mu),
            AnyPhase::CornetteShanks(p) => p.eval(mu),
            AnyPhase::TwoLobeHenyeyGreenstein(p) => p.eval(mu),
        }
    }
    fn eval_sides<S: Scalar<T>>(&self, mu: S, one_minus_mu: S, one_plus_mu: S) -> S {
        match self {
            AnyPhase::Isotropic => Isotropic.eval(mu),
            AnyPhase::Rayleigh => Rayleigh.eval(mu),
            AnyPhase::HenyeyGreenstein(p) => p.eval_sides(mu, one_minus_mu, one_plus_mu),
            AnyPhase::Schlick(p) => p.eval_sides(mu, one_minus_mu, one_plus_mu),
            AnyPhase::CornetteShanks(p) => p.eval_sides(mu, one_minus_mu, one_plus_mu),
            AnyPhase::TwoLobeHenyeyGreenstein(p) => p.eval_sides(mu, one_minus_mu, one_plus_mu),
        }
    }
    fn eval_sides_each<const N: usize>(&self, mu: &[T; N], one_minus_mu: &[T; N], one_plus_mu: &[T; N]) -> [T; N] {
        match self {
            AnyPhase::Isotropic => Isotropic.eval_sides_each(mu, one_minus_mu, one_plus_mu),
            AnyPhase::Rayleigh => Rayleigh.eval_sides_each(mu, one_minus_mu, one_plus_mu),
            AnyPhase::HenyeyGreenstein(p) => p.eval_sides_each(mu, one_minus_mu, one_plus_mu),
            AnyPhase::Schlick(p) => p.eval_sides_each(mu, one_minus_mu, one_plus_mu),
            AnyPhase::CornetteShanks(p) => p.eval_sides_each(mu, one_minus_mu, one_plus_mu),
            AnyPhase::TwoLobeHenyeyGreenstein(p) => p.eval_sides_each(mu, one_minus_mu, one_plus_mu),
        }
    }
    fn singularities(&self) -> Option<Singularities<T>> {
        match self {
            AnyPhase::Isotropic => Isotropic.singularities(),
            AnyPhase::Rayleigh => Rayleigh.singularities(),
            AnyPhase::HenyeyGreenstein(p) => p.singularities(),
            AnyPhase::Schlick(p) => p.singularities(),
            AnyPhase::CornetteShanks(p) => p.singularities(),
            AnyPhase::TwoLobeHenyeyGreenstein(p) => p.singularities(),
        }
    }
    fn is_isotropic(&self) -> bool {
        match self {
            AnyPhase::Isotropic => true,
            AnyPhase::Rayleigh => false,
            AnyPhase::HenyeyGreenstein(p) => PhaseFunction::<T>::is_isotropic(p),
            AnyPhase::Schlick(p) => PhaseFunction::<T>::is_isotropic(p),
            AnyPhase::CornetteShanks(_) => false,
            AnyPhase::TwoLobeHenyeyGreenstein(p) => PhaseFunction::<T>::is_isotropic(p),
        }
    }
    fn validate(&self) -> Result<(), InputError> {
        match self {
            AnyPhase::Isotropic | AnyPhase::Rayleigh => Ok(()),
            AnyPhase::HenyeyGreenstein(p) => PhaseFunction::<T>::validate(p),
            AnyPhase::Schlick(p) => PhaseFunction::<T>::validate(p),
            AnyPhase::CornetteShanks(p) => PhaseFunction::<T>::validate(p),
            AnyPhase::TwoLobeHenyeyGreenstein(p) => PhaseFunction::<T>::validate(p),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The declared singular cosines are where the closed forms' denominators vanish:
    /// `1 + g² − 2gμ` (Henyey–Greenstein, Cornette–Shanks, both lobes of the two-lobed one) and
    /// `1 − kμ` (Schlick), to a few ulps of their terms; none for the polynomial ones. Orders
    /// and growth as the closed forms read: `P(2μ)/P(μ) → 2^growth` for large `μ`.
    #[test]
    fn singularities_are_the_poles() {
        let cos = |p: Option<Singularities<f64>>| p.unwrap().cosines;
        for g in [-0.99f64, -0.5, 0.3, 0.9, 0.999] {
            let [mu, none] = cos(HenyeyGreenstein { g }.singularities());
            assert!((1.0 + g * g - 2.0 * g * mu).abs() <= 4.0 * f64::EPSILON * (1.0 + g * g), "HG g = {g}: μ* = {mu}");
            assert!(mu.abs() > 1.0 && none.is_infinite());
            assert_eq!(cos(CornetteShanks { g }.singularities())[0], mu);
            let [a, b] = cos(TwoLobeHenyeyGreenstein { g1: g, g2: -0.5 * g, w: 0.7 }.singularities());
            assert!((1.0 + 0.25 * g * g + g * b).abs() <= 4.0 * f64::EPSILON * (1.0 + g * g) && a == mu);
            let k = g;
            let [mu, _] = cos(Schlick { k }.singularities());
            assert!((1.0 - k * mu).abs() <= 4.0 * f64::EPSILON, "Schlick k = {k}: μ* = {mu}");
        }
        assert!(cos(HenyeyGreenstein { g: 0.0f64 }.singularities())[0].is_infinite());
        for p in [PhaseFunction::<f64>::singularities(&Isotropic), PhaseFunction::<f64>::singularities(&Rayleigh)] {
            assert!(p.unwrap().cosines.iter().all(|m| m.is_infinite()));
        }
        // growth: the ratio at μ = −1e6 and −2e6 (outside [−1, 1], the closed forms continued;
        // forward lobes, whose kernels stay real there)
        let any: [AnyPhase<f64>; 5] = [
            AnyPhase::Rayleigh,
            AnyPhase::HenyeyGreenstein(HenyeyGreenstein { g: 0.6 }),
            AnyPhase::Schlick(Schlick { k: 0.6 }),
            AnyPhase::CornetteShanks(CornetteShanks { g: 0.6 }),
            AnyPhase::TwoLobeHenyeyGreenstein(TwoLobeHenyeyGreenstein { g1: 0.6, g2: 0.3, w: 0.5 }),
        ];
        for p in any {
            let d = p.singularities().unwrap().growth;
            let ratio = (p.eval(-2e6).abs() / p.eval(-1e6).abs()).log2();
            assert!((ratio - d).abs() < 1e-3, "{p:?}: growth {d}, measured {ratio}");
        }
    }

    /// Every phase function integrates to 1 over the sphere, `2π ∫_{−1}^{1} P(μ) dμ = 1`
    /// (composite Simpson, 20 000 intervals; the peaked ones at moderate asymmetry so that
    /// Simpson's error stays below 1e-9).
    #[test]
    fn normalised_over_the_sphere() {
        fn sphere<P: PhaseFunction<f64>>(p: &P) -> f64 {
            let n = 20_000;
            let h = 2.0 / n as f64;
            let mut s = 0.0;
            for i in 0..=n {
                let mu = -1.0 + i as f64 * h;
                let w = if i == 0 || i == n { 1.0 } else if i % 2 == 1 { 4.0 } else { 2.0 };
                s += w * p.eval(mu);
            }
            2.0 * core::f64::consts::PI * s * h / 3.0
        }
        let total = [
            sphere(&Isotropic),
            sphere(&Rayleigh),
            sphere(&HenyeyGreenstein { g: 0.6 }),
            sphere(&HenyeyGreenstein { g: -0.6 }),
            sphere(&Schlick { k: 0.6 }),
            sphere(&CornetteShanks { g: 0.6 }),
            sphere(&TwoLobeHenyeyGreenstein { g1: 0.7, g2: -0.3, w: 0.8 }),
        ];
        for (i, t) in total.iter().enumerate() {
            assert!((t - 1.0).abs() < 1e-9, "phase function {i}: {t}");
        }
    }

    /// Passing `1 ∓ μ` exactly agrees with forming them from `μ` where that is exact.
    #[test]
    fn sides_agree_with_mu() {
        let hg = HenyeyGreenstein { g: 0.9f64 };
        for mu in [-1.0, -0.5, 0.0, 0.25, 0.5, 1.0] {
            assert_eq!(hg.eval_sides(mu, 1.0 - mu, 1.0 + mu), hg.eval(mu));
        }
    }

    /// `AnyPhase::eval_sides_each` dispatches once and gives each variant's `eval_sides`.
    #[test]
    fn eval_sides_each_gives_eval_sides() {
        let mu = [-1.0, -0.5, 0.0, 0.25, 0.999, 1.0];
        let (minus, plus) = (mu.map(|m| 1.0 - m), mu.map(|m| 1.0 + m));
        let any: [AnyPhase<f64>; 6] = [
            AnyPhase::Isotropic,
            AnyPhase::Rayleigh,
            AnyPhase::HenyeyGreenstein(HenyeyGreenstein { g: 0.9 }),
            AnyPhase::Schlick(Schlick { k: -0.6 }),
            AnyPhase::CornetteShanks(CornetteShanks { g: 0.6 }),
            AnyPhase::TwoLobeHenyeyGreenstein(TwoLobeHenyeyGreenstein { g1: 0.6, g2: -0.3, w: 0.5 }),
        ];
        for p in any {
            let each = p.eval_sides_each(&mu, &minus, &plus);
            for i in 0..mu.len() {
                assert_eq!(each[i].to_bits(), p.eval_sides(mu[i], minus[i], plus[i]).to_bits(), "{p:?} at μ = {}", mu[i]);
            }
        }
    }
}
