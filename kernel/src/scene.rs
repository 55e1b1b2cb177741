//! The world-space API on glam vectors: a ray, a point light, a medium and a phase function
//! in; in-scattered radiance, the surface term (paper eq. 7) and total radiance (eq. 2) out.

use crate::combined::{in_scatter_canonical, in_scatter_counted, Method, Physics};
use crate::error::{check_finite, check_non_negative, check_vector, ErrorKind, InputError};
use crate::expansion::Expansion;
use crate::geometry::{dot, length, normalize, sub, Canonical};
use crate::integrals::{PaperEq27, Production};
use crate::light::LightDistribution;
use crate::march::{gauss_angle, ray_march, GaussAngle, Steps};
use crate::panels::Control;
use crate::phase::PhaseFunction;
use crate::real::Real;

/// Expansion terms on the CPU (the paper's software renderer used 6).
pub const CPU_TERMS: usize = 6;
/// Gauss–Legendre nodes per panel in the default shader: the f32 default path's count (the
/// paper's GPU version used one 4-term expansion per half; panels of 4 nodes need 3–4× the
/// panels of 8, were slower on 14 of the 16 scene classes of tests/reference/classes.jsonl and
/// 2–3× slower on lavapipe, BENCHMARKS.md); the shaders are also emitted with 12.
pub const SHADER_NODES: usize = 8;
/// The shaders' error control (they compute [`Scene::in_scatter_panels`] with
/// [`SHADER_NODES`] or 12 nodes and this control): tolerance `1e-3`, the shaders' accuracy
/// target, on each piece; `floor` the f32 `τ` (docs/DESIGN.md §8); at most 16 panels per piece
/// (the shader's fixed worst-case loop). Unlike the CPU defaults, the tolerance is not a tenth
/// of the target: the estimate's margin is measured instead — over every scene of
/// tests/reference/classes.jsonl the 8-node shader's largest error is 3.9e-4 (`thick`; 1.2e-4
/// at 12 nodes), and at `1e-4` the anisotropic street lamp took 1.7× the GPU time for the same
/// largest error on its rays (BENCHMARKS.md, GPU).
pub const SHADER_CONTROL: Control<f32> = Control { tolerance: 1e-3, floor: 1e-4, max_panels: 16 };

/// A ray segment `x(t) = origin + t·d`, `t ∈ [t_min, t_max]`, with `d = dir/|dir|` (so `t` is
/// a distance). `t_max` may be `+∞`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Ray<T: Real> {
    /// Ray origin (the camera, usually).
    pub origin: T::Vec3,
    /// Direction; any non-zero length that does not overflow, normalised by the library.
    pub dir: T::Vec3,
    /// Segment start.
    pub t_min: T,
    /// Segment end, `+∞` for an unbounded ray.
    pub t_max: T,
}

/// A homogeneous participating medium.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Medium<T> {
    /// Scattering coefficient `σs ≥ 0` (per unit length).
    pub sigma_s: T,
    /// Extinction coefficient `σt ≥ 0`; independent of `σs` (`σt = 0` is the no-extinction
    /// model of Macklin and Packard).
    pub sigma_t: T,
}

/// A point light with an angular distribution.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct PointLight<T: Real, D> {
    /// Position of the light.
    pub position: T::Vec3,
    /// Radiant intensity `I ≥ 0` along the distribution's maximum.
    pub intensity: T,
    /// Angular distribution `D(c)`.
    pub distribution: D,
}

/// A validated scene: construction checks every field, so evaluation cannot fail.
#[derive(Clone, Copy, Debug)]
pub struct Scene<T: Real, D, P> {
    ray: Ray<T>,
    light: PointLight<T, D>,
    medium: Medium<T>,
    phase: P,
    canonical: Canonical<T>,
    canonical_fixed: Canonical<T>,
}

/// Checks a ray, light, medium and phase function, naming the first bad field.
pub fn validate<T, D, P>(ray: &Ray<T>, light: &PointLight<T, D>, medium: &Medium<T>, phase: &P) -> Result<(), InputError>
where
    T: Real,
    D: LightDistribution<T>,
    P: PhaseFunction<T>,
{
    check_vector(T::vec3_to_array(ray.origin), "ray.origin", false)?;
    check_vector(T::vec3_to_array(ray.dir), "ray.dir", true)?;
    check_finite(ray.t_min, "ray.t_min")?;
    if ray.t_max.is_nan() || ray.t_max == T::neg_infinity() {
        return Err(InputError::new("ray.t_max", ErrorKind::NonFinite));
    }
    if ray.t_min > ray.t_max {
        return Err(InputError::new("ray.t_max", ErrorKind::EmptyRange));
    }
    check_non_negative(medium.sigma_s, "medium.sigma_s")?;
    check_non_negative(medium.sigma_t, "medium.sigma_t")?;
    check_vector(T::vec3_to_array(light.position), "light.position", false)?;
    check_non_negative(light.intensity, "light.intensity")?;
    light.distribution.validate()?;
    phase.validate()
}

impl<T, D, P> Scene<T, D, P>
where
    T: Real,
    D: LightDistribution<T>,
    P: PhaseFunction<T>,
{
    /// Validates and builds a scene.
    ///
    /// # Errors
    /// [`InputError`] naming the first invalid field: non-finite numbers, a zero direction or
    /// axis, negative coefficients or intensity, `t_min > t_max`, `|g| ≥ 1`, an odd two-lobed
    /// power, an inverted spot cone.
    pub fn new(ray: Ray<T>, light: PointLight<T, D>, medium: Medium<T>, phase: P) -> Result<Self, InputError> {
        validate(&ray, &light, &medium, &phase)?;
        let args = (
            T::vec3_to_array(ray.origin),
            T::vec3_to_array(ray.dir),
            ray.t_min,
            ray.t_max,
            T::vec3_to_array(light.position),
            light.distribution.axis(),
        );
        let canonical_fixed = Canonical::new(args.0, args.1, args.2, args.3, args.4, args.5);
        let canonical = canonical_fixed.refined(args.0, args.1, args.4, args.5);
        Ok(Scene { ray, light, medium, phase, canonical, canonical_fixed })
    }

    /// The ray.
    pub fn ray(&self) -> &Ray<T> {
        &self.ray
    }
    /// The light.
    pub fn light(&self) -> &PointLight<T, D> {
        &self.light
    }
    /// The medium.
    pub fn medium(&self) -> &Medium<T> {
        &self.medium
    }
    /// The phase function.
    pub fn phase(&self) -> &P {
        &self.phase
    }
    /// The canonical reduction (docs/DESIGN.md §2) of the scene, by
    /// [`Canonical::new_accurate`] (the fixed-term methods use [`Canonical::new`], as the
    /// shaders do).
    pub fn canonical(&self) -> &Canonical<T> {
        &self.canonical
    }

    fn physics(&self) -> Physics<'_, T, D, P> {
        Physics::new(&self.light, &self.medium, &self.phase)
    }

    /// In-scattered radiance `L_m` (docs/DESIGN.md §1), error-controlled: panels with
    /// [`Real::PANEL_NODES`] Gauss–Legendre nodes each, refined until the estimated error is
    /// below [`Real::PANEL_TOLERANCE`] of `F` on each ([`default_control`]; see
    /// [`crate::panels`]).
    ///
    /// `+∞` exactly when the light lies on the segment (`h = 0`, `t_min ≤ x_h ≤ t_max`) and
    /// `σs·I > 0`, or when the true value exceeds the float range; never NaN.
    pub fn in_scatter(&self) -> T {
        self.in_scatter_controlled(default_control()).0
    }

    /// `L_m` by error-controlled panels with the precision's [`Real::PANEL_NODES`] (8 from a
    /// tolerance of [`FEWER_NODES_FROM`]) and the given control (a looser tolerance trades
    /// accuracy for time), and the number of panels evaluated.
    pub fn in_scatter_controlled(&self, control: Control<T>) -> (T, usize) {
        self.default_panels(&self.canonical, control)
    }

    /// The panels with the precision's [`Real::PANEL_NODES`] over `g` (the scene's canonical
    /// form, or a lit part of it).
    fn default_panels(&self, g: &Canonical<T>, control: Control<T>) -> (T, usize) {
        default_panels(g, &self.physics(), control)
    }

    /// `L_m` by error-controlled panels with `N` Gauss–Legendre nodes each (`N` ∈ {4, 6, 8, 10,
    /// 12, 16}, the tabulated rules; any other count is a compile error).
    ///
    /// ```compile_fail,E0080
    /// use airlight::glam::DVec3;
    /// use airlight::{default_control, light::Omni, phase::Isotropic, Medium, PointLight, Ray, Scene};
    /// let ray = Ray { origin: DVec3::ZERO, dir: DVec3::X, t_min: 0.0, t_max: 25.0 };
    /// let light = PointLight { position: DVec3::new(5.0, 1.0, 0.0), intensity: 100.0, distribution: Omni };
    /// let scene = Scene::new(ray, light, Medium { sigma_s: 0.08, sigma_t: 0.1 }, Isotropic).unwrap();
    /// let _ = scene.in_scatter_panels::<5>(default_control());
    /// ```
    pub fn in_scatter_panels<const N: usize>(&self, control: Control<T>) -> T {
        self.in_scatter_panels_counted::<N>(control).0
    }

    /// [`Scene::in_scatter_panels`] and the number of panels it evaluated.
    pub fn in_scatter_panels_counted<const N: usize>(&self, control: Control<T>) -> (T, usize) {
        panels_with_nodes::<T, D, P, N>(&self.canonical, &self.physics(), control)
    }

    /// `L_m` with one `N`-term expansion per piece (the paper's fixed-cost method).
    ///
    /// ```
    /// use airlight::glam::DVec3;
    /// use airlight::{light::Omni, phase::Isotropic, Expansion, Medium, PointLight, Ray, Scene};
    /// let ray = Ray { origin: DVec3::ZERO, dir: DVec3::X, t_min: 0.0, t_max: 25.0 };
    /// let light = PointLight { position: DVec3::new(5.0, 1.0, 0.0), intensity: 100.0, distribution: Omni };
    /// let scene = Scene::new(ray, light, Medium { sigma_s: 0.08, sigma_t: 0.1 }, Isotropic).unwrap();
    /// assert!(scene.in_scatter_with::<4>(Expansion::Chebyshev) > 0.0);
    /// ```
    ///
    /// `N` must be 1 … 16; anything else is a compile error:
    ///
    /// ```compile_fail,E0080
    /// use airlight::glam::DVec3;
    /// use airlight::{light::Omni, phase::Isotropic, Expansion, Medium, PointLight, Ray, Scene};
    /// let ray = Ray { origin: DVec3::ZERO, dir: DVec3::X, t_min: 0.0, t_max: 25.0 };
    /// let light = PointLight { position: DVec3::new(5.0, 1.0, 0.0), intensity: 100.0, distribution: Omni };
    /// let scene = Scene::new(ray, light, Medium { sigma_s: 0.08, sigma_t: 0.1 }, Isotropic).unwrap();
    /// assert!(scene.in_scatter_with::<0>(Expansion::Chebyshev) > 0.0);
    /// ```
    pub fn in_scatter_with<const N: usize>(&self, expansion: Expansion) -> T {
        in_scatter_canonical::<T, D, P, Production, N>(&self.canonical_fixed, &self.physics(), Method::Fixed(expansion), &Production)
    }

    /// [`Scene::in_scatter_with`] with the term count chosen at run time (a command line's,
    /// a configuration's): `None` outside 1 … 16. The one runtime-to-compile-time dispatch of
    /// the term count; each count it reaches is compiled in.
    pub fn in_scatter_with_terms(&self, terms: usize, expansion: Expansion) -> Option<T> {
        macro_rules! dispatch {
            ($($n:literal)*) => {
                match terms {
                    $($n => Some(self.in_scatter_with::<$n>(expansion)),)*
                    _ => None,
                }
            };
        }
        dispatch!(1 2 3 4 5 6 7 8 9 10 11 12 13 14 15 16)
    }

    /// [`Scene::in_scatter_panels`] with the node count chosen at run time: `None` for a count
    /// without a tabulated rule (4, 6, 8, 10, 12, 16 have one).
    pub fn in_scatter_panels_with_nodes(&self, nodes: usize, control: Control<T>) -> Option<T> {
        macro_rules! dispatch {
            ($($n:literal)*) => {
                match nodes {
                    $($n => Some(self.in_scatter_panels::<$n>(control)),)*
                    _ => None,
                }
            };
        }
        dispatch!(4 6 8 10 12 16)
    }

    /// `L_m` over the sub-segments `lit` of `[t_min, t_max]` only (a shadowed ray, as sums of
    /// differences in the manner of Biri et al.): `Σ e^{−σt(a_i − t_min)} L_m(a_i, b_i)`, each
    /// part by the default error-controlled path ([`Scene::in_scatter`]). Each `(a_i, b_i)` is
    /// clipped to the ray's segment; empty ones and ones with a NaN end contribute nothing.
    pub fn in_scatter_lit(&self, lit: &[(T, T)]) -> T {
        self.lit_sum(lit, &self.canonical, |g| self.default_panels(g, default_control()).0)
    }

    /// [`Scene::in_scatter_lit`] with one `N`-term expansion per piece (the paper's fixed-cost
    /// method, as [`Scene::in_scatter_with`]).
    pub fn in_scatter_lit_with<const N: usize>(&self, lit: &[(T, T)], expansion: Expansion) -> T {
        self.lit_sum(lit, &self.canonical_fixed, |g| in_scatter_canonical::<T, D, P, Production, N>(g, &self.physics(), Method::Fixed(expansion), &Production))
    }

    fn lit_sum(&self, lit: &[(T, T)], canonical: &Canonical<T>, part: impl Fn(&Canonical<T>) -> T) -> T {
        let mut total = T::zero();
        for &(a, b) in lit {
            if a.is_nan() || b.is_nan() {
                continue;
            }
            let a = a.max(self.ray.t_min);
            let b = b.min(self.ray.t_max);
            if !(b > a) {
                continue;
            }
            let g = Canonical { t0: a, t1: b, ..*canonical };
            let part = part(&g);
            if part > T::zero() {
                // an overflowing part (+∞) stays +∞ even where the attenuation underflows
                let attenuation = (-self.medium.sigma_t * (a - self.ray.t_min)).exp();
                total = total + if part.is_infinite() { part } else { attenuation * part };
            }
        }
        total
    }

    /// `L_m` by the paper's algorithm as published, for comparison: Taylor expansion at the
    /// midpoint, the closed forms with the `Ei` of eq. 27 / fig. 2 (absolute tolerance
    /// `precision`, at most `max_iterations` iterations), no stabilised routes.
    pub fn in_scatter_paper<const N: usize>(&self, precision: T, max_iterations: usize) -> T {
        let ei = PaperEq27 { precision, max_iterations };
        in_scatter_canonical::<T, D, P, PaperEq27<T>, N>(&self.canonical_fixed, &self.physics(), Method::Fixed(Expansion::Taylor), &ei)
    }

    /// `L_m` by ray marching with `steps` samples (see [`crate::march`]): the fixed-step
    /// quadrature the analytic form replaces, for comparison. `Steps::Equiangular` needs the
    /// light off the ray line.
    pub fn ray_march(&self, rule: Steps, steps: usize) -> T {
        ray_march(
            T::vec3_to_array(self.ray.origin),
            T::vec3_to_array(self.ray.dir),
            self.ray.t_min,
            self.ray.t_max,
            T::vec3_to_array(self.light.position),
            self.medium.sigma_s,
            self.medium.sigma_t,
            self.light.intensity,
            &self.light.distribution,
            &self.phase,
            rule,
            steps,
        )
    }

    /// `L_m` by Gauss–Legendre in the angle seen from the light ([`crate::march::GaussAngle`]):
    /// the peer the benchmarks compare against. Returns the value and the evaluations used.
    pub fn gauss_angle(&self, rule: GaussAngle<T>) -> (T, usize) {
        gauss_angle(&self.canonical, self.medium.sigma_s, self.medium.sigma_t, self.light.intensity, &self.light.distribution, &self.phase, rule)
    }

    /// The surface term of paper eq. 7 at the segment's end `t_max` (finite):
    /// `L_b = e^{−σt r_b}/r_b² · I·D(c_b) · brdf · max(0, ω_i·n)`, with `ω_i` the unit vector
    /// towards the light and `c_b` the cosine of the light's emission towards the point.
    /// Returns 0 for an infinite segment, a zero normal or a point at the light.
    pub fn surface_radiance(&self, normal: T::Vec3, brdf: T) -> T {
        if !self.ray.t_max.is_finite() {
            return T::zero();
        }
        let o = T::vec3_to_array(self.ray.origin);
        let d = normalize(T::vec3_to_array(self.ray.dir));
        let t = self.ray.t_max;
        let x_b = [o[0] + t * d[0], o[1] + t * d[1], o[2] + t * d[2]];
        let to_light = sub(T::vec3_to_array(self.light.position), x_b);
        let r_b = length(to_light);
        if !(r_b > T::zero()) {
            return T::zero();
        }
        let w_i = [to_light[0] / r_b, to_light[1] / r_b, to_light[2] / r_b];
        let n = normalize(T::vec3_to_array(normal));
        let cos = dot(w_i, n).max(T::zero());
        let c_b = -dot(w_i, normalize(self.light.distribution.axis()));
        let d_b: T = self.light.distribution.eval(c_b);
        (-self.medium.sigma_t * r_b).exp() / (r_b * r_b) * self.light.intensity * d_b * brdf * cos
    }

    /// Total radiance along the ray, paper eq. 2: `e^{−σt(t_max − t_min)} L_b + L_m`, with the
    /// surface term at `t_max` (0 for an infinite segment).
    pub fn radiance(&self, normal: T::Vec3, brdf: T) -> T {
        let span = self.ray.t_max - self.ray.t_min;
        let lb = self.surface_radiance(normal, brdf);
        let transmitted = if lb == T::zero() { T::zero() } else { (-self.medium.sigma_t * span).exp() * lb };
        transmitted + self.in_scatter()
    }
}

/// The error control of [`Scene::in_scatter`] for the precision `T`.
pub fn default_control<T: Real>() -> Control<T> {
    Control { tolerance: T::lit(T::PANEL_TOLERANCE), floor: T::lit(T::PANEL_FLOOR), max_panels: T::MAX_PANELS }
}

/// The tolerance from which the default path takes 8 Gauss–Legendre nodes per panel (and in its
/// light-angle route) where the precision's [`Real::PANEL_NODES`] is 16 (f64), as f32 does: at
/// 1e-1 and 1e-2, 8 nodes cost 18 % and 13 % fewer instructions per ray than 16 over every scene
/// of tests/reference/classes.jsonl, at 1e-3 the same, at 1e-4 14 % more (callgrind,
/// docs/DESIGN.md §4.1). Loose tolerances are what the integrals over an emitter or a hemisphere
/// ask of their rays (a tenth of their own, [`crate::extended`]).
pub const FEWER_NODES_FROM: f64 = 1e-2;

/// `L_m` of the canonical problem `g` by error-controlled panels with the precision's
/// [`Real::PANEL_NODES`] (8 from [`FEWER_NODES_FROM`]) and `control`, and the panels evaluated: [`Scene::in_scatter_controlled`]
/// for a problem whose reduction is known without a scene (a surface point's rays,
/// crate::surface).
pub(crate) fn default_panels<T, D, P>(g: &Canonical<T>, phys: &Physics<'_, T, D, P>, control: Control<T>) -> (T, usize)
where
    T: Real,
    D: LightDistribution<T>,
    P: PhaseFunction<T>,
{
    let method = Method::Panels(control);
    if T::PANEL_NODES == 16 && !(control.tolerance >= T::lit(FEWER_NODES_FROM)) {
        in_scatter_counted::<T, D, P, Production, 16>(g, phys, method, &Production)
    } else {
        in_scatter_counted::<T, D, P, Production, 8>(g, phys, method, &Production)
    }
}

/// `L_m` of the canonical problem `g` by error-controlled panels with `N` Gauss–Legendre nodes
/// each (`N` ∈ {4, 6, 8, 10, 12, 16}, the tabulated rules; any other count is a compile error),
/// and the panels evaluated: [`Scene::in_scatter_panels_counted`] without a scene.
pub(crate) fn panels_with_nodes<T, D, P, const N: usize>(g: &Canonical<T>, phys: &Physics<'_, T, D, P>, control: Control<T>) -> (T, usize)
where
    T: Real,
    D: LightDistribution<T>,
    P: PhaseFunction<T>,
{
    const { assert!(matches!(N, 4 | 6 | 8 | 10 | 12 | 16), "panels take 4, 6, 8, 10, 12 or 16 Gauss–Legendre nodes") };
    in_scatter_counted::<T, D, P, Production, N>(g, phys, Method::Panels(control), &Production)
}

/// In-scattered radiance with the defaults (error-controlled panels), checked.
///
/// # Errors
/// [`InputError`] naming the first invalid field (see [`Scene::new`]).
pub fn in_scatter<T, D, P>(ray: Ray<T>, light: PointLight<T, D>, medium: Medium<T>, phase: P) -> Result<T, InputError>
where
    T: Real,
    D: LightDistribution<T>,
    P: PhaseFunction<T>,
{
    Ok(Scene::new(ray, light, medium, phase)?.in_scatter())
}

/// In-scattered radiance with `N` terms, unchecked: invalid input yields `0` (the same defined
/// value the shaders give), never a panic or NaN.
pub fn in_scatter_unchecked<T, D, P, const N: usize>(
    ray: Ray<T>,
    light: PointLight<T, D>,
    medium: Medium<T>,
    phase: P,
    expansion: Expansion,
) -> T
where
    T: Real,
    D: LightDistribution<T>,
    P: PhaseFunction<T>,
{
    match Scene::new(ray, light, medium, phase) {
        Ok(scene) => scene.in_scatter_with::<N>(expansion),
        Err(_) => T::zero(),
    }
}

/// The seeds' closed form for an isotropic light in an isotropic medium *without* extinction
/// (Macklin 2010, Packard 2004): `L = σs I/(4π h) (atan u_1 − atan u_0)`. It equals
/// [`Scene::in_scatter`] exactly when `σt = 0` and both light and phase are isotropic, and is
/// the cheapest analytic glow (the benchmarks' floor). No input checks; `h = 0` gives `+∞`/NaN.
pub fn atan_form<T: Real>(ray: &Ray<T>, light_position: T::Vec3, intensity: T, sigma_s: T) -> T {
    let g = Canonical::new(
        T::vec3_to_array(ray.origin),
        T::vec3_to_array(ray.dir),
        ray.t_min,
        ray.t_max,
        T::vec3_to_array(light_position),
        [T::zero(), T::zero(), T::one()],
    );
    let span = g.u(g.t1).atan() - g.u(g.t0).atan();
    sigma_s * intensity * T::FRAC_1_PI() * T::lit(0.25) / g.h * span
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::light::Omni;
    use crate::phase::{HenyeyGreenstein, Isotropic};
    use glam::DVec3;

    /// Without extinction and with isotropic light and phase the integral is
    /// `σs I/(4π h) (atan u_1 − atan u_0)`, `u = (t − x_h)/h` (docs/DESIGN.md §1 with `σt = 0`):
    /// a light at (5, 2, 0), the ray along +x from 1 to 20, `h = 2`, `x_h = 5`.
    #[test]
    fn without_extinction_it_is_the_atan_form() {
        let ray = Ray { origin: DVec3::ZERO, dir: DVec3::X, t_min: 1.0, t_max: 20.0 };
        let light = PointLight { position: DVec3::new(5.0, 2.0, 0.0), intensity: 3.0, distribution: Omni };
        let s = Scene::new(ray, light, Medium { sigma_s: 0.5, sigma_t: 0.0 }, Isotropic).unwrap();
        let want = 0.5 * 3.0 / (4.0 * core::f64::consts::PI * 2.0) * ((15.0f64 / 2.0).atan() - (-4.0f64 / 2.0).atan());
        for got in [s.in_scatter(), s.in_scatter_with::<6>(Expansion::Chebyshev), s.in_scatter_lit(&[(1.0, 20.0)])] {
            assert!((got - want).abs() <= 1e-14 * want, "{got} vs {want}");
        }
    }

    /// Invalid input is a typed error naming the field.
    #[test]
    fn bad_input_names_its_field() {
        let ray = Ray { origin: DVec3::ZERO, dir: DVec3::X, t_min: 0.0, t_max: 20.0 };
        let light = PointLight { position: DVec3::new(5.0, 2.0, 0.0), intensity: 3.0, distribution: Omni };
        let medium = Medium { sigma_s: 0.5, sigma_t: 0.1 };
        let e = Scene::new(ray, light, medium, HenyeyGreenstein { g: 1.0 }).unwrap_err();
        assert_eq!((e.field, e.kind), ("phase.g", ErrorKind::OutOfRange));
        let e = Scene::new(Ray { dir: DVec3::ZERO, ..ray }, light, medium, Isotropic).unwrap_err();
        assert_eq!((e.field, e.kind), ("ray.dir", ErrorKind::ZeroVector));
        let e = Scene::new(Ray { t_min: 30.0, ..ray }, light, medium, Isotropic).unwrap_err();
        assert_eq!(e.kind, ErrorKind::EmptyRange);
        let e = Scene::new(ray, light, Medium { sigma_s: -1.0, ..medium }, Isotropic).unwrap_err();
        assert_eq!((e.field, e.kind), ("medium.sigma_s", ErrorKind::Negative));
    }
}
