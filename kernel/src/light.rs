//! Light distributions `D(c)`: the angular profile of a point light, `c` the cosine between
//! the direction from the light to the lit point and the light's axis (docs/DESIGN.md §1). The
//! radiant intensity towards that direction is `I·D(c)`.
//!
//! Implement [`LightDistribution`] to add your own; as with phase functions, one generic
//! `eval` gives both values and Taylor coefficients.

use crate::error::{check_finite, check_vector, ErrorKind, InputError};
use crate::real::Real;
use crate::scalar::Scalar;

/// An angular distribution of a point light about its axis.
pub trait LightDistribution<T: Real> {
    /// The axis (any length but zero; the kernel normalises it). Ignored when
    /// [`is_isotropic`](Self::is_isotropic).
    fn axis(&self) -> [T; 3];
    /// `D(c)` for `c ∈ [−1, 1]`.
    fn eval<S: Scalar<T>>(&self, c: S) -> S;
    /// `D` at each of `N` cosines, in place, with [`eval`](Self::eval)'s values: what a rule of
    /// `N` samples calls (the light-angle route, `crate::angle`). The default evaluates one
    /// by one; a distribution whose evaluation branches on its parameters alone may take each
    /// branch once for all `N` (the two-lobed `c^p`'s squarings).
    fn eval_each<const N: usize>(&self, cs: &mut [T; N]) {
        for c in cs.iter_mut() {
            *c = self.eval(*c);
        }
    }
    /// `true` if `D` is constant: the kernel then skips the expansion.
    fn is_isotropic(&self) -> bool {
        false
    }
    /// Cosines where `D` is not smooth (a cone's edges). The kernel splits the integration at
    /// the points where `c` crosses them, so each piece gets a polynomial of its own.
    fn kinks(&self) -> [Option<T>; 2] {
        [None, None]
    }
    /// A cosine below which `D` vanishes (`D(c) = 0` for every `c < bound`), if there is one:
    /// the error-controlled path spends no panel on a piece of the ray the light does not
    /// reach (outside a spot's cone, behind a flat emitter).
    fn dark_below(&self) -> Option<T> {
        None
    }
    /// `Some(p)` if `D` is a polynomial in `c` of degree at most `p` on each piece between its
    /// [`kinks`](Self::kinks): along a ray `D(c(y))` is then singular only where `c` is, at
    /// `y = ±i`, with a pole of order `p`, and the error-controlled path knows how fast its
    /// panels' coefficients must fall. The default `None` keeps the estimate that assumes
    /// nothing.
    fn polynomial_degree(&self) -> Option<u32> {
        None
    }
    /// Checks the parameters; the checked API calls it.
    fn validate(&self) -> Result<(), InputError> {
        Ok(())
    }
}

/// `Some(p)` if `D` is one polynomial of degree at most `p` in `c` over all of `[−1, 1]`: a
/// declared [`LightDistribution::polynomial_degree`] with no kinks and no dark side (a
/// `TwoLobed` `c^p`; a spot cone's pieces are polynomials, the whole is not). Then a
/// quantity affine in `c` along every ray enters as a polynomial of degree `p`: the light-angle
/// route's samples are analytic (crate::angle), a hemisphere's `L_a` is a polynomial in the
/// azimuth's cosine (crate::surface).
pub(crate) fn whole_polynomial_degree<T: Real, D: LightDistribution<T> + ?Sized>(light: &D) -> Option<u32> {
    light.polynomial_degree().filter(|_| light.kinks().iter().all(Option::is_none) && light.dark_below().is_none())
}

/// The same intensity in every direction, `D = 1`.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Omni;

impl<T: Real> LightDistribution<T> for Omni {
    fn axis(&self) -> [T; 3] {
        [T::zero(), T::zero(), T::one()]
    }
    fn eval<S: Scalar<T>>(&self, _c: S) -> S {
        S::cst(T::one())
    }
    fn is_isotropic(&self) -> bool {
        true
    }
    fn polynomial_degree(&self) -> Option<u32> {
        Some(0)
    }
}

/// The paper's two-lobed distribution `D = c^p`, `p` even (a beam both ways along the axis,
/// like a lighthouse lamp).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct TwoLobed<T: Real> {
    /// Beam axis.
    pub axis: T::Vec3,
    /// Exponent `p`, even; larger is narrower.
    pub power: u32,
}

impl<T: Real> TwoLobed<T> {
    /// The largest accepted power `p`.
    pub const MAX_POWER: u32 = 1024;
}

impl<T: Real> LightDistribution<T> for TwoLobed<T> {
    fn axis(&self) -> [T; 3] {
        T::vec3_to_array(self.axis)
    }
    fn eval<S: Scalar<T>>(&self, c: S) -> S {
        c.powi(self.power as i32)
    }
    /// [`Scalar::powi`]'s squarings and products in its order, each step across all `N`
    /// cosines: the same values, the power's bits tested once instead of once per cosine.
    fn eval_each<const N: usize>(&self, cs: &mut [T; N]) {
        let (mut k, mut out) = (self.power, [T::one(); N]);
        loop {
            if k & 1 == 1 {
                for (o, &b) in out.iter_mut().zip(cs.iter()) {
                    *o = *o * b;
                }
            }
            k >>= 1;
            if k == 0 {
                break;
            }
            for b in cs.iter_mut() {
                *b = *b * *b;
            }
        }
        *cs = out;
    }
    fn is_isotropic(&self) -> bool {
        self.power == 0
    }
    fn polynomial_degree(&self) -> Option<u32> {
        Some(self.power)
    }
    fn validate(&self) -> Result<(), InputError> {
        check_vector(T::vec3_to_array(self.axis), "light.distribution.axis", true)?;
        if self.power % 2 != 0 || self.power > Self::MAX_POWER {
            return Err(InputError::new("light.distribution.power", ErrorKind::OddPower));
        }
        Ok(())
    }
}

/// An engine-style spot cone: full intensity inside `cos_inner`, none outside `cos_outer`,
/// and the smoothstep `x²(3 − 2x)`, `x = (c − cos_outer)/(cos_inner − cos_outer)`, between.
///
/// Its edges are only C¹; the kernel splits the integration where a ray crosses them
/// ([`LightDistribution::kinks`]). An edge narrower than the float epsilon (in cosine) is
/// evaluated as a step at its middle.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SpotCone<T: Real> {
    /// Cone axis (the direction the spot points to).
    pub axis: T::Vec3,
    /// Cosine of the half-angle of full intensity.
    pub cos_inner: T,
    /// Cosine of the half-angle where the intensity reaches 0 (`< cos_inner`).
    pub cos_outer: T,
}

impl<T: Real> LightDistribution<T> for SpotCone<T> {
    fn axis(&self) -> [T; 3] {
        T::vec3_to_array(self.axis)
    }
    fn eval<S: Scalar<T>>(&self, c: S) -> S {
        let width = self.cos_inner - self.cos_outer;
        if width <= T::epsilon() {
            // An edge narrower than the precision is a step at its middle (its smoothstep
            // would scale derivatives by 1/width and overflow the expansion).
            let mid = self.cos_outer + width * T::lit(0.5);
            return S::cst(if c.value() >= mid { T::one() } else { T::zero() });
        }
        let x = c.shift(-self.cos_outer).scale(width.recip());
        let xv = x.value();
        if xv <= T::zero() {
            S::cst(T::zero())
        } else if xv >= T::one() {
            S::cst(T::one())
        } else {
            x * x * x.scale(-T::lit(2.0)).shift(T::lit(3.0))
        }
    }
    fn kinks(&self) -> [Option<T>; 2] {
        let width = self.cos_inner - self.cos_outer;
        if width <= T::epsilon() {
            // evaluated as a step: one discontinuity, at its middle
            return [Some(self.cos_outer + width * T::lit(0.5)), None];
        }
        [Some(self.cos_inner), Some(self.cos_outer)]
    }
    fn dark_below(&self) -> Option<T> {
        // as `eval`: a step's middle, else the outer cone
        let width = self.cos_inner - self.cos_outer;
        Some(if width <= T::epsilon() { self.cos_outer + width * T::lit(0.5) } else { self.cos_outer })
    }
    fn polynomial_degree(&self) -> Option<u32> {
        // 0, the smoothstep's cubic or 1 between the kinks
        Some(3)
    }
    fn validate(&self) -> Result<(), InputError> {
        check_vector(T::vec3_to_array(self.axis), "light.distribution.axis", true)?;
        check_finite(self.cos_inner, "light.distribution.cos_inner")?;
        check_finite(self.cos_outer, "light.distribution.cos_outer")?;
        let one = T::one();
        for (c, field) in [(self.cos_inner, "light.distribution.cos_inner"), (self.cos_outer, "light.distribution.cos_outer")] {
            if !(c >= -one && c <= one) {
                return Err(InputError::new(field, ErrorKind::NotACosine));
            }
        }
        if !(self.cos_outer < self.cos_inner) {
            return Err(InputError::new("light.distribution.cos_outer", ErrorKind::InvertedCone));
        }
        Ok(())
    }
}

/// A flat emitter's element of uniform radiance: `D = max(0, c)` about its normal (Lambert's
/// cosine law, emitting on the side the axis points to). Used by the area lights
/// ([`crate::area`]); its one kink, `c = 0`, is where a ray crosses the emitter's plane.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Lambertian<T: Real> {
    /// The normal of the emitting side.
    pub axis: T::Vec3,
}

impl<T: Real> LightDistribution<T> for Lambertian<T> {
    fn axis(&self) -> [T; 3] {
        T::vec3_to_array(self.axis)
    }
    fn eval<S: Scalar<T>>(&self, c: S) -> S {
        if c.value() > T::zero() {
            c
        } else {
            S::cst(T::zero())
        }
    }
    fn kinks(&self) -> [Option<T>; 2] {
        [Some(T::zero()), None]
    }
    fn dark_below(&self) -> Option<T> {
        Some(T::zero())
    }
    fn polynomial_degree(&self) -> Option<u32> {
        Some(1)
    }
    fn validate(&self) -> Result<(), InputError> {
        check_vector(T::vec3_to_array(self.axis), "light.distribution.axis", true)
    }
}

/// Any of the built-in distributions, chosen at run time.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum AnyDistribution<T: Real> {
    /// [`Omni`].
    Omni,
    /// [`TwoLobed`].
    TwoLobed(TwoLobed<T>),
    /// [`SpotCone`].
    SpotCone(SpotCone<T>),
}

impl<T: Real> LightDistribution<T> for AnyDistribution<T> {
    fn axis(&self) -> [T; 3] {
        match self {
            AnyDistribution::Omni => LightDistribution::<T>::axis(&Omni),
            AnyDistribution::TwoLobed(d) => d.axis(),
            AnyDistribution::SpotCone(d) => d.axis(),
        }
    }
    fn eval<S: Scalar<T>>(&self, c: S) -> S {
        match self {
            AnyDistribution::Omni => Omni.eval(c),
            AnyDistribution::TwoLobed(d) => d.eval(c),
            AnyDistribution::SpotCone(d) => d.eval(c),
        }
    }
    fn eval_each<const N: usize>(&self, cs: &mut [T; N]) {
        match self {
            AnyDistribution::Omni => Omni.eval_each(cs),
            AnyDistribution::TwoLobed(d) => d.eval_each(cs),
            AnyDistribution::SpotCone(d) => d.eval_each(cs),
        }
    }
    fn is_isotropic(&self) -> bool {
        match self {
            AnyDistribution::Omni => true,
            AnyDistribution::TwoLobed(d) => d.is_isotropic(),
            AnyDistribution::SpotCone(_) => false,
        }
    }
    fn kinks(&self) -> [Option<T>; 2] {
        match self {
            AnyDistribution::SpotCone(d) => d.kinks(),
            _ => [None, None],
        }
    }
    fn dark_below(&self) -> Option<T> {
        match self {
            AnyDistribution::SpotCone(d) => d.dark_below(),
            _ => None,
        }
    }
    fn polynomial_degree(&self) -> Option<u32> {
        match self {
            AnyDistribution::Omni => LightDistribution::<T>::polynomial_degree(&Omni),
            AnyDistribution::TwoLobed(d) => d.polynomial_degree(),
            AnyDistribution::SpotCone(d) => d.polynomial_degree(),
        }
    }
    fn validate(&self) -> Result<(), InputError> {
        match self {
            AnyDistribution::Omni => Ok(()),
            AnyDistribution::TwoLobed(d) => d.validate(),
            AnyDistribution::SpotCone(d) => d.validate(),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use glam::DVec3;

    /// The engine smoothstep `x²(3 − 2x)`, `x = (c − cos_outer)/(cos_inner − cos_outer)`: 0 at
    /// the outer edge, 1/2 halfway, 1 from the inner edge on; the two-lobed `c^p` by hand.
    #[test]
    fn distributions_by_hand() {
        let spot = SpotCone::<f64> { axis: DVec3::Z, cos_inner: 0.9, cos_outer: 0.7 };
        let d = |c: f64| -> f64 { spot.eval(c) };
        assert_eq!((d(0.6), d(0.7), d(0.9), d(1.0)), (0.0, 0.0, 1.0, 1.0));
        assert!((d(0.8) - 0.5).abs() < 1e-15 && (d(0.75) - 0.15625).abs() < 1e-15);
        let beam = TwoLobed::<f64> { axis: DVec3::Z, power: 4 };
        let b = |c: f64| -> f64 { beam.eval(c) };
        assert_eq!((b(0.5), b(-0.5), b(1.0)), (0.0625, 0.0625, 1.0));
    }

    /// The two-lobed `eval_each` squares across the cosines in `eval`'s order: the same values
    /// bit for bit, for every power up to 64 and the largest, in both precisions.
    #[test]
    fn eval_each_gives_eval_bitwise() {
        const CS: [f64; 8] = [-1.0, -0.93, -0.37, -1e-3, 0.0, 0.5, 0.7072, 0.999_999];
        for power in (0..=64).step_by(2).chain([1022, 1024]) {
            let beam = AnyDistribution::TwoLobed(TwoLobed::<f64> { axis: DVec3::Z, power });
            let mut each = CS;
            beam.eval_each(&mut each);
            let mut each32 = CS.map(|c| c as f32);
            AnyDistribution::TwoLobed(TwoLobed::<f32> { axis: glam::Vec3::Z, power }).eval_each(&mut each32);
            for (i, &c) in CS.iter().enumerate() {
                let one: f64 = beam.eval(c);
                assert_eq!(each[i].to_bits(), one.to_bits(), "f64 {c}^{power}");
                let one: f32 = TwoLobed::<f32> { axis: glam::Vec3::Z, power }.eval(c as f32);
                assert_eq!(each32[i].to_bits(), one.to_bits(), "f32 {c}^{power}");
            }
        }
    }
}
