//! Extended lights: a segment (a fluorescent tube, a neon sign's stroke) as the integral over
//! the emitter of the point-light kernel (docs/DESIGN.md §10; Packard 2004 steps over the light
//! in the same way).
//!
//! A segment light `a → b` of intensity `I` per unit length sheds
//! `L = ∫_0^ℓ L_point(a + s·e) ds`, `ℓ = |b − a|`, `e = (b − a)/ℓ`, `L_point` the point light of
//! intensity `I` and the segment's distribution ([`crate::Scene::in_scatter`]). As a function of
//! `s`, `L_point` behaves like `1/ρ(s)` near the emitter's closest approach to the ray line,
//! `ρ(s)² = ρ*² + (s − s*)² sin²α` (`α` the angle between the lines): so the outer integral is
//! taken in `w` with `s = s* + (ρ*/sin α) sinh w`, where `ds/ρ = dw/sin α` and the peak is
//! smooth, split where the light's foot passes the ray's ends (and a light with an axis at its
//! lobe's shoulders, `LOBE_SHOULDER`), by globally adaptive
//! Gauss–Kronrod 7/15 (3/7 at tolerances of 1e-4 and looser, 2/5 at 1e-1; QUADPACK's QAG
//! strategy) to a relative tolerance, with a bounded number of panels.
//!
//! An emitter that meets the ray segment gives `+∞` (as a point light on it does); one that
//! meets the ray's line outside the segment, or lies along it, is finite and integrated through
//! the point light's on-line limit — and one along the line behind the camera (seen end-on) has
//! a closed form in `E1`, taken where its error bound meets the tolerance
//! (`SegmentScene::end_on`).

use crate::error::{check_vector, InputError};
use crate::combined::Physics;
use crate::geometry::{dot, length, normalize, sub, Canonical};
use crate::light::LightDistribution;
use crate::panels::Control;
use crate::phase::PhaseFunction;
use crate::real::Real;
use crate::scene::{default_control, default_panels, validate, Medium, PointLight, Ray, Scene};

/// Gauss–Kronrod 7/15 on `[−1, 1]` (QUADPACK `qk15`, Piessens et al. 1983, to 33 digits):
/// `(x_i, Kronrod weight, Gauss weight or 0)` for the non-negative nodes, `x` descending; the
/// rule uses `±x_i`. The Gauss 7-point rule is the nodes with a Gauss weight.
#[allow(clippy::excessive_precision)] // the published digits, rounded once by the compiler
pub const GAUSS_KRONROD_15: [(f64, f64, f64); 8] = [
    (0.991455371120812639206854697526329, 0.022935322010529224963732008058970, 0.0),
    (0.949107912342758524526189684047851, 0.063092092629978553290700663189204, 0.129484966168869693270611432679082),
    (0.864864423359769072789712788640926, 0.104790010322250183839876322541518, 0.0),
    (0.741531185599394439863864773280788, 0.140653259715525918745189590510238, 0.279705391489276667901467771423780),
    (0.586087235467691130294144845693013, 0.169004726639267902826583426598550, 0.0),
    (0.405845151377397166906606412076961, 0.190350578064785409913256402421014, 0.381830050505118944950369775488975),
    (0.207784955007898467600689403773245, 0.204432940075298892414161999234649, 0.0),
    (0.0, 0.209482141084727828012999174891714, 0.417959183673469387755102040816327),
];

/// Gauss–Kronrod 3/7 on `[−1, 1]`, as [`GAUSS_KRONROD_15`]: the Kronrod extension of the
/// 3-point Gauss rule (nodes `±√(3/5)`, `0`; weights `5/9`, `8/9`), to 33 digits (Piessens et al.
/// 1983's construction; exact to degree 11, which `tests` checks against `2/(k+1)`).
#[allow(clippy::excessive_precision)] // the published digits, rounded once by the compiler
pub const GAUSS_KRONROD_7: [(f64, f64, f64); 4] = [
    (0.960491268708020283423507092629080, 0.104656226026467265193823857192073, 0.0),
    (0.774596669241483377035853079956480, 0.268488089868333440728569280666710, 0.555555555555555555555555555555556),
    (0.434243749346802558002071502844628, 0.401397414775962222905051818618432, 0.0),
    (0.0, 0.450916538658474142345110087045571, 0.888888888888888888888888888888889),
];

/// Gauss–Kronrod 2/5 on `[−1, 1]`, as [`GAUSS_KRONROD_15`]: the Kronrod extension of the
/// 2-point Gauss rule (nodes `±1/√3`, weights 1), exact to degree 7; the nodes to 36 digits. Its node `±√(6/7)` and
/// weights `98/495`, `27/55`, `28/45` solve the moment equations of degrees 0, 2, 4, 6 with
/// the Gauss nodes kept (`tests` checks them against `2/(k+1)`).
#[allow(clippy::excessive_precision)] // the digits, rounded once by the compiler
pub const GAUSS_KRONROD_5: [(f64, f64, f64); 3] = [
    (0.925820099772551461566566776583999523, 98.0 / 495.0, 0.0),
    (0.577350269189625764509148780501957456, 27.0 / 55.0, 1.0),
    (0.0, 28.0 / 45.0, 0.0),
];

/// `(Kronrod 15, Gauss 7)` estimates of `∫_a^b f`.
pub fn gauss_kronrod_15<T: Real>(f: &mut impl FnMut(T) -> T, a: T, b: T) -> (T, T) {
    gauss_kronrod(&GAUSS_KRONROD_15, f, a, b)
}

/// `(Kronrod, Gauss)` estimates of `∫_a^b f` by a rule of [`GAUSS_KRONROD_15`]'s form.
pub fn gauss_kronrod<T: Real>(rule: &[(f64, f64, f64)], f: &mut impl FnMut(T) -> T, a: T, b: T) -> (T, T) {
    let half = T::lit(0.5);
    let (c, hw) = ((a + b) * half, (b - a) * half);
    let (mut k, mut g) = (T::zero(), T::zero());
    for &(x, wk, wg) in rule {
        let s = if x == 0.0 { f(c) } else { f(c - hw * T::lit(x)) + f(c + hw * T::lit(x)) };
        k = k + T::lit(wk) * s;
        g = g + T::lit(wg) * s;
    }
    (k * hw, g * hw)
}

/// A segment light: every point of `a → b` emits `intensity` per unit length with the
/// distribution `D` (the same axis for every point).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SegmentLight<T: Real, D> {
    /// One end.
    pub a: T::Vec3,
    /// The other end (`a` itself: no emitter, `L = 0`).
    pub b: T::Vec3,
    /// Radiant intensity per unit length `I ≥ 0` along the distribution's maximum.
    pub intensity: T,
    /// Angular distribution `D(c)` of every point.
    pub distribution: D,
}

/// The most Gauss–Kronrod panels of one segment light (each 15 point-light evaluations).
pub const MAX_SEGMENT_PANELS: usize = 48;

/// The most Gauss–Kronrod panels of one segment light in the shaders
/// ([`SegmentScene::in_scatter_panels_counted`]; `7·(2·6 − 1) = 77` point lights at most):
/// within 2.4e-6 of the mpmath values of tests/reference/extended.jsonl in f32 (4 panels:
/// 1.6e-3), and few enough loop iterations for those tubes on Mesa's lavapipe, which ends all
/// loops after 65 535 in total (codegen/shaders/shader/airlight.wgsl).
pub const SHADER_SEGMENT_PANELS: usize = 6;

/// The default relative tolerance of the outer integral's estimate of every integral over an
/// emitter or a hemisphere (segment, area and surface lights; `|K − G|` summed over the panels,
/// itself far above the Kronrod sum's error on a resolved panel): a tenth of the precision's
/// target (docs/DESIGN.md §8: 1e-9 in f64, 1e-4 in f32).
pub fn outer_tolerance<T: Real>() -> T {
    T::lit(if T::epsilon() < T::lit(1e-10) { 1e-10 } else { 1e-5 })
}

/// The tolerance an outer integral works to: the one asked for, but no finer than its inner ray
/// integrals' own ([`Real::PANEL_TOLERANCE`]: 1e-11 in f64, 1e-5 in f32). Below that the outer
/// estimate `|K − G|` measures the rays' error, not the rule's, and refining chases it to the
/// panel bound — for a surface point in f32, into directions within ~1e-4 of the light, where
/// the world-space geometry of a ray is ill-conditioned: asked for 1e-7 it returned values 2–4×
/// too large (tests/surface.rs `tolerance_below_the_rays_floor_does_not_hurt`).
pub(crate) fn working_tolerance<T: Real>(tolerance: T) -> T {
    tolerance.max(T::lit(T::PANEL_TOLERANCE))
}

/// The panel edges of an outer integral over `[lo, hi]`: `lo`, the `cuts` strictly inside in
/// increasing order (repeats dropped), `hi`; the array (`K > cuts.len() + 1`) and the index of
/// `hi` in it.
pub(crate) fn edges_between<T: Real, const K: usize>(lo: T, hi: T, cuts: &mut [T]) -> ([T; K], usize) {
    cuts.sort_unstable_by(|x, y| x.partial_cmp(y).unwrap_or(core::cmp::Ordering::Equal));
    let mut edges = [lo; K];
    let mut n = 0;
    for &c in cuts.iter() {
        if c > edges[n] && c < hi {
            n += 1;
            edges[n] = c;
        }
    }
    n += 1;
    edges[n] = hi;
    (edges, n)
}

/// The Gauss–Kronrod rule of an outer integral at `tolerance`: 7 points per panel where 1e-4 of
/// the value will do (on the classes of tests/reference/extended.jsonl at 1e-3 it is faster on 8
/// of 12, slower where the peak is sharp: BENCHMARKS.md, segment lights), 15 below.
pub(crate) fn outer_rule<T: Real>(tolerance: T) -> &'static [(f64, f64, f64)] {
    if tolerance >= T::lit(1e-4) {
        &GAUSS_KRONROD_7
    } else {
        &GAUSS_KRONROD_15
    }
}

/// A segment's outer rule: [`GAUSS_KRONROD_5`] where a tenth of the value will do, else
/// [`outer_rule`]'s. Over tests/reference/extended.jsonl at tolerance 1e-1 it leaves at most
/// 3e-3 (a near tube, as the 7-point rule) with 27 % fewer instructions per behind-the-camera
/// tube (BENCHMARKS.md, segment lights); on surfaces the 5-point estimate let 1.3e-1 through at
/// 1e-1 (an anisotropic Lambertian point), so their outer integrals keep the 7-point rule but on
/// the pieces of a Phong lobe's extent, slices of its peak of a known width (docs/DESIGN.md §11).
pub(crate) fn segment_rule<T: Real>(tolerance: T) -> &'static [(f64, f64, f64)] {
    if tolerance >= T::lit(1e-1) {
        &GAUSS_KRONROD_5
    } else {
        outer_rule(tolerance)
    }
}

/// The control of each inner ray integral (a point light's, a ray's from a surface) under an
/// outer integral at `tolerance`: a tenth of it, the default's where that is finer.
pub(crate) fn inner_control<T: Real>(tolerance: T) -> Control<T> {
    Control { tolerance: (tolerance * T::lit(0.1)).max(T::lit(T::PANEL_TOLERANCE)), ..default_control() }
}

/// A validated scene with a segment light.
#[derive(Clone, Copy, Debug)]
pub struct SegmentScene<T: Real, D, P> {
    ray: Ray<T>,
    light: SegmentLight<T, D>,
    medium: Medium<T>,
    phase: P,
}

impl<T, D, P> SegmentScene<T, D, P>
where
    T: Real,
    D: LightDistribution<T> + Clone,
    P: PhaseFunction<T> + Clone,
{
    /// Validates and builds a scene.
    ///
    /// # Errors
    /// [`InputError`] naming the first invalid field, as [`Scene::new`]; the ends are `light.a`
    /// and `light.b`.
    pub fn new(ray: Ray<T>, light: SegmentLight<T, D>, medium: Medium<T>, phase: P) -> Result<Self, InputError> {
        // the ends by their own names; the rest as the point light at `a` (`light.intensity`…)
        check_vector(T::vec3_to_array(light.a), "light.a", false)?;
        check_vector(T::vec3_to_array(light.b), "light.b", false)?;
        let point = PointLight { position: light.a, intensity: light.intensity, distribution: light.distribution.clone() };
        validate(&ray, &point, &medium, &phase)?;
        Ok(SegmentScene { ray, light, medium, phase })
    }

    /// The ray.
    pub fn ray(&self) -> &Ray<T> {
        &self.ray
    }
    /// The segment light.
    pub fn light(&self) -> &SegmentLight<T, D> {
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

    /// In-scattered radiance of the segment light, error-controlled to [`outer_tolerance`].
    /// `+∞` when the emitter meets the ray segment and `σs·I > 0`.
    pub fn in_scatter(&self) -> T {
        self.in_scatter_counted(outer_tolerance()).0
    }

    /// The same to a relative tolerance of the outer estimate (no finer than
    /// [`Real::PANEL_TOLERANCE`], the point lights' own), and the panels evaluated.
    pub fn in_scatter_counted(&self, tolerance: T) -> (T, usize) {
        let tolerance = working_tolerance(tolerance);
        if let Some(value) = self.end_on(tolerance) {
            return (value, 0);
        }
        let inner = inner_control(tolerance);
        let phys = Physics { sigma_s: self.medium.sigma_s, sigma_t: self.medium.sigma_t, intensity: self.light.intensity, light: &self.light.distribution, phase: &self.phase };
        self.integrate(tolerance, MAX_SEGMENT_PANELS, true, |node| default_panels(&node.canonical, &phys, inner).0)
    }

    /// What the shaders compute (fixed cost): the outer Gauss–Kronrod rule the default path
    /// takes at `control.tolerance` (7 points per panel at 1e-4 and looser, 15 below), at most
    /// `max_panels` panels (the shaders: [`SHADER_SEGMENT_PANELS`]), every point light as
    /// [`Scene::in_scatter_panels`]`::<N>(control)`; and the panels evaluated.
    pub fn in_scatter_panels_counted<const N: usize>(&self, control: Control<T>, max_panels: usize) -> (T, usize) {
        // each point light reduced from its world position, as the shaders do; no cuts at the
        // lobe's shoulders (`LOBE_SHOULDER`), as the shaders have none
        self.integrate(control.tolerance, max_panels, false, |node| {
            let light = PointLight { position: T::vec3_from_array(node.position), intensity: self.light.intensity, distribution: self.light.distribution.clone() };
            Scene::new(self.ray, light, self.medium, self.phase.clone()).map_or(T::zero(), |scene| scene.in_scatter_panels::<N>(control))
        })
    }

    /// A segment along the ray's line behind the ray's start (seen end-on from the camera) in
    /// closed form. Every point light on it is the point light's on-line limit (its `h → 0` case,
    /// `crate::combined`), with one `F = D(d·axis)·P(−1)`: at a distance `d` behind `t0`, with
    /// `σ = σt` and `T = t1 − t0`, `L_point(d) = σs I F e^{σd} ∫_d^{d+T} e^{−2σr} r^{−2} dr =
    /// σs I F e^{σd} [E_2(2σd)/d − E_2(2σ(d+T))/(d+T)]` (A&S 5.1.4), and by `E_2(x) = e^{−x} −
    /// x E_1(x)` and one integration by parts `∫ e^{σd} E_2(2σd)/d dd = Φ(d) = E_1(σd) − 2e^{σd}
    /// E_1(2σd)` (differentiate to check), so over the emitter's `d ∈ [d0, d1]`
    ///
    /// `L = σs I F {Φ(d1) − Φ(d0) − e^{−σT} [Φ(d1 + T) − Φ(d0 + T)]}`
    ///
    /// (the bracket 0 for `t1 = ∞`), `Φ(d) = e^{−σd} [s_1(σd) − 2 s_1(2σd)]` with
    /// `s_1(x) = e^x E_1(x)`; without extinction `σs I F [ln(d1/d0) − ln((d1 + T)/(d0 + T))]`.
    /// `None` where the segment lies otherwise, or where the differences' error (`s_1`'s tested
    /// accuracy, 2e-13 / 8e-6, times the terms' magnitudes) exceeds half of `tolerance` of the value — a
    /// segment short against its distance, or f32 at its default tolerance: the outer rule then
    /// integrates it as any other.
    fn end_on(&self, tolerance: T) -> Option<T> {
        // each end reduced as the point light there ([`Scene::new`]; the inputs are validated)
        let (origin, dir, axis) = (T::vec3_to_array(self.ray.origin), T::vec3_to_array(self.ray.dir), self.light.distribution.axis());
        let at = |end| Canonical::new_accurate(origin, dir, self.ray.t_min, self.ray.t_max, T::vec3_to_array(end), axis);
        // both ends behind the start and on the line by the point light's own test
        let behind = |g: &Canonical<T>| g.x_h < g.t0 && g.h <= (g.t0 - g.x_h) * T::epsilon() * T::epsilon();
        let ga = Some(at(self.light.a)).filter(behind)?;
        let gb = Some(at(self.light.b)).filter(behind)?;
        if self.light.intensity == T::zero() || self.medium.sigma_s == T::zero() {
            return None;
        }
        let (t0, t1) = (ga.t0, ga.t1);
        let (d0, d1) = ((t0 - ga.x_h).min(t0 - gb.x_h), (t0 - ga.x_h).max(t0 - gb.x_h));
        let span = t1 - t0;
        let f = self.light.distribution.eval(ga.d_el) * self.phase.eval(-T::one());
        let prefactor = self.medium.sigma_s * self.light.intensity * f;
        let sigma = self.medium.sigma_t;
        let (bracket, magnitude) = if sigma == T::zero() {
            // ln(d1/d0) − ln((d1 + T)/(d0 + T)), each as ln(1 + Δ/d)
            let near = ((d1 - d0) / d0).ln_1p();
            let far = if span.is_finite() { ((d1 - d0) / (d0 + span)).ln_1p() } else { T::zero() };
            (near - far, near + far)
        } else {
            // Φ(d) scaled by e^{σ d0}: e^{−σ(d − d0)} [s_1(σd) − 2 s_1(2σd)], and the size of its terms
            let phi = |d: T, extra: T| {
                let (mut one, mut two) = ([T::zero(); 1], [T::zero(); 1]);
                crate::special::en_scaled(sigma * d, &mut one);
                crate::special::en_scaled(T::lit(2.0) * sigma * d, &mut two);
                let weight = (-(sigma * (d - d0) + extra)).exp();
                (weight * (one[0] - T::lit(2.0) * two[0]), weight * (one[0] + T::lit(2.0) * two[0]))
            };
            let (p0, m0) = phi(d0, T::zero());
            let (p1, m1) = phi(d1, T::zero());
            let (mut value, mut size) = (p1 - p0, m0 + m1);
            if span.is_finite() {
                // e^{−σT} Φ(d + T): the weight e^{−σ(d + 2T − d0)}
                let (q0, n0) = phi(d0 + span, sigma * span);
                let (q1, n1) = phi(d1 + span, sigma * span);
                value = value - (q1 - q0);
                size = size + n0 + n1;
            }
            (value, size)
        };
        // each s_1 within E1's tested accuracy plus 2ε per order recurred (tests/expint.rs
        // `en_bound`, s_1 grown by nothing: 1.1e-13 in f64, 6.1e-6 in f32), rounded up for the
        // exponentials and products: the differences' error against half the tolerance of
        // their value
        let accuracy = T::lit(if T::epsilon() < T::lit(1e-10) { 2e-13 } else { 8e-6 });
        if !(bracket > T::zero()) || !(accuracy * magnitude <= T::lit(0.5) * tolerance * bracket) {
            return None;
        }
        // the scaling e^{σ d0} of Φ undone
        let value = prefactor * bracket * (-(sigma * d0)).exp();
        value.is_finite().then_some(value)
    }

    /// `∫ L_point ds` by the outer rule to `tolerance`, each point light by `point_light`; with
    /// `shoulders`, a light with an axis is cut at its lobe's shoulders (`LOBE_SHOULDER`).
    fn integrate(&self, tolerance: T, max_panels: usize, shoulders: bool, point_light: impl Fn(&Node<T>) -> T) -> (T, usize) {
        let a = T::vec3_to_array(self.light.a);
        let ab = sub(T::vec3_to_array(self.light.b), a);
        let len = length(ab);
        if !(len > T::zero()) || self.light.intensity == T::zero() || self.medium.sigma_s == T::zero() {
            return (T::zero(), 0);
        }
        let e = ab.map(|x| x / len);
        let dir = T::vec3_to_array(self.ray.dir);
        let d = dir.map(|x| x / length(dir));
        let w0 = sub(a, T::vec3_to_array(self.ray.origin));
        let (cos_a, along_e, along_d) = (dot(e, d), dot(e, w0), dot(d, w0));
        let sin2 = T::one() - cos_a * cos_a;
        let (t0, t1) = (self.ray.t_min, self.ray.t_max);
        // the emitter's closest approach to the ray's line: s*, the ray's t*, the distance ρ*
        let (s_star, t_star) = if sin2 > T::epsilon() {
            ((cos_a * along_d - along_e) / sin2, (along_d - cos_a * along_e) / sin2)
        } else {
            (T::zero(), along_d)
        };
        let gap = sub(sub(w0, d.map(|x| x * t_star)), e.map(|x| -x * s_star));
        let rho = length(gap);
        let sin_a = sin2.max(T::zero()).sqrt();
        // crossing the ray segment: ρ* within its own rounding (a few ε of the lengths it is
        // formed from) of 0
        let crossing = rho <= T::lit(4.0) * T::epsilon() * (length(w0) + len);
        if crossing && sin_a > T::zero() && s_star >= T::zero() && s_star <= len && t0 <= t_star && t_star <= t1 {
            return (T::infinity(), 0);
        }
        // w ↦ s: sinh about s* at scale ρ*/sin α where the lines are skew and the peak is
        // narrower than the segment and within a length of it (elsewhere the integrand is smooth
        // in s, and the mapped ends, far out on asinh's logarithmic branch, would cancel), else s
        let mut scale = if sin_a > T::zero() && rho > T::zero() { rho / sin_a } else { T::zero() };
        let near = s_star > -len && s_star < len + len && scale < len;
        if !(near && ((len - s_star) / scale).asinh().is_finite() && (s_star / scale).asinh().is_finite()) {
            scale = T::zero();
        }
        let to_w = |s: T| if scale > T::zero() { ((s - s_star) / scale).asinh() } else { s };
        // each node's canonical form from the emitter's line, not from its rounded position:
        // the foot x_h = t* + (s − s*) cos α and the light's offset from the ray's line
        // gap + (s − s*)(e − d cos α), two orthogonal parts (no cancellation), so h = |offset|
        // and d_c = −offset·axis/h keep the accuracy of ρ* (docs/DESIGN.md §10)
        let axis = normalize(self.light.distribution.axis());
        let (across, d_el) = ([e[0] - d[0] * cos_a, e[1] - d[1] * cos_a, e[2] - d[2] * cos_a], dot(d, axis));
        let mut point = |w: T| {
            let (off, ds) = if scale > T::zero() { (scale * w.sinh(), scale * w.cosh()) } else { (w - s_star, T::one()) };
            let s = s_star + off;
            let offset = [gap[0] + off * across[0], gap[1] + off * across[1], gap[2] + off * across[2]];
            let h = length(offset);
            let d_c = if h > T::zero() { -dot(offset, axis) / h } else { T::zero() };
            let canonical = Canonical { h, x_h: t_star + off * cos_a, d_el, d_c, t0, t1 };
            let position = [a[0] + s * e[0], a[1] + s * e[1], a[2] + s * e[2]];
            point_light(&Node { position, canonical }) * ds
        };
        // panels: split at the closest approach and where the light's foot passes a ray end; not
        // at the closest approach where the map is taken and it lies within half a unit of `w`
        // (half the peak's width) of an end: the sliver beyond it adds a panel's point lights
        // and nothing the other panel's rule does not follow (tests/reference/extended.jsonl at
        // tolerance 1e-1, f32: a tube behind the camera 4.4e-8 off in two panels, 3.8e-7 in one,
        // a thick one 2.4e-5 and 2.8e-5; never splitting there took a far tube, its closest
        // approach 1.1 from both ends, from 1.6e-4 to 2.6e-3)
        let (w_lo, w_hi) = (to_w(T::zero()), to_w(len));
        let mut cuts = [T::infinity(); 5];
        let foot_at = |t: T| if cos_a != T::zero() { (t - along_d) / cos_a } else { T::nan() };
        let sliver = scale > T::zero() && (-w_lo).min(w_hi) < T::lit(0.5);
        let star = if sliver { T::nan() } else { s_star };
        for (c, s) in cuts.iter_mut().zip([star, foot_at(t0), foot_at(t1)]) {
            if s > T::zero() && s < len {
                *c = to_w(s);
            }
        }
        // and, where the map is taken for a light with an axis, at its lobe's shoulders
        if shoulders && scale > T::zero() && !self.light.distribution.is_isotropic() {
            cuts[3] = -T::lit(LOBE_SHOULDER);
            cuts[4] = T::lit(LOBE_SHOULDER);
        }
        let (edges, n): ([T; 7], usize) = edges_between(w_lo, w_hi, &mut cuts);
        adaptive(segment_rule(tolerance), &mut point, &edges[..=n], tolerance, max_panels)
    }
}

/// Where the outer integral of a segment lit with an axis is cut besides its closest approach
/// (`w = 0`): at `w = ±2` in the sinh map. A lobe that narrows towards the ray — a beam `c^p`
/// across it, `c = ρ*/r` at the closest approach — makes `L_point` fall like `ρ^{−1−p}` there,
/// the outer integrand like `sech^p w`, a peak of width ≈ 1 in `w` whatever `ρ*`, while beyond
/// `|w| ≈ 2` the map runs `s` exponentially over the rest of the emitter: a panel over both
/// follows the shoulder only by bisection (the near tubes with a `c⁴` beam across the ray of
/// tests/reference/extended.jsonl took 6–10 panels at tolerances 1e-1 … 1e-2 and left up to
/// 3.2e-3 at 3e-2; cut, 4 panels and at most 8.0e-4 at 1e-1). `sech 2 = 0.27` (`c⁴`'s peak
/// there at 5e-3 of its height). An isotropic light's integrand is flat in `w` (`p = 0`), not
/// cut (docs/DESIGN.md §10).
const LOBE_SHOULDER: f64 = 2.0;

/// A node of a segment's outer rule: the point light's position and its canonical form.
struct Node<T> {
    position: [T; 3],
    canonical: Canonical<T>,
}

/// One panel of [`adaptive`]'s list.
#[derive(Clone, Copy)]
struct Listed<T> {
    a: T,
    b: T,
    value: T,
    error: T,
}

/// Globally adaptive Gauss–Kronrod (`rule`) over the panels between `edges`: bisects the panel
/// with the largest `|K − G|` until their sum is at most `tolerance` of the sum of the values (the
/// integrand is non-negative), or `max_panels` panels are held; the sum and the panels
/// evaluated.
pub(crate) fn adaptive<T: Real>(rule: &[(f64, f64, f64)], f: &mut impl FnMut(T) -> T, edges: &[T], tolerance: T, max_panels: usize) -> (T, usize) {
    adaptive_by(|_, _| rule, f, edges, tolerance, max_panels)
}

/// [`adaptive`] with the rule of each panel `[a, b]` chosen by `rule(a, b)`.
pub(crate) fn adaptive_by<'r, T: Real>(rule: impl Fn(T, T) -> &'r [(f64, f64, f64)], f: &mut impl FnMut(T) -> T, edges: &[T], tolerance: T, max_panels: usize) -> (T, usize) {
    let mut list = [Listed { a: T::zero(), b: T::zero(), value: T::zero(), error: T::zero() }; MAX_SEGMENT_PANELS];
    let max_panels = max_panels.clamp(edges.len() - 1, MAX_SEGMENT_PANELS);
    fn evaluate<T: Real>(rule: &[(f64, f64, f64)], f: &mut impl FnMut(T) -> T, a: T, b: T) -> Listed<T> {
        let (c, hw) = ((a + b) * T::lit(0.5), (b - a) * T::lit(0.5));
        let (mut k, mut g) = (T::zero(), T::zero());
        for &(x, wk, wg) in rule {
            let s = if x == 0.0 { f(c) } else { f(c - hw * T::lit(x)) + f(c + hw * T::lit(x)) };
            k = k + T::lit(wk) * s;
            g = g + T::lit(wg) * s;
        }
        Listed { a, b, value: k * hw, error: ((k - g) * hw).abs() }
    }
    let mut count = 0;
    for pair in edges.windows(2) {
        list[count] = evaluate(rule(pair[0], pair[1]), f, pair[0], pair[1]);
        count += 1;
    }
    let mut evaluated = count;
    loop {
        let (mut total, mut errors, mut worst) = (T::zero(), T::zero(), 0);
        for (i, p) in list.iter().enumerate().take(count) {
            total = total + p.value;
            errors = errors + p.error;
            if p.error > list[worst].error {
                worst = i;
            }
        }
        if !(errors > tolerance * total.abs()) || count == max_panels || !total.is_finite() {
            return (total.max(T::zero()), evaluated);
        }
        let Listed { a, b, .. } = list[worst];
        let mid = (a + b) * T::lit(0.5);
        if !(mid > a && mid < b) {
            list[worst].error = T::zero();
            continue;
        }
        list[worst] = evaluate(rule(a, mid), f, a, mid);
        list[count] = evaluate(rule(mid, b), f, mid, b);
        count += 1;
        evaluated += 2;
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Gauss–Kronrod 7/15 (`qk15`): the Kronrod rule exact to degree 22, the Gauss 7-point rule
    /// to 13; through [`gauss_kronrod_15`].
    #[test]
    fn gauss_kronrod_15_degrees() {
        exact_to_degrees(&GAUSS_KRONROD_15, 22, 13);
        let (kr, _) = gauss_kronrod_15(&mut |x: f64| x.powi(22), -1.0, 1.0);
        assert!((kr - 2.0 / 23.0).abs() <= 1e-15);
    }

    /// Both rules of a Gauss–Kronrod pair integrate `x^k` over `[−1, 1]` exactly (`2/(k+1)`,
    /// even `k`; odd powers vanish by symmetry) up to their degrees, and not at the next even one.
    fn exact_to_degrees(rule: &[(f64, f64, f64)], kronrod: i32, gauss: i32) {
        let next_even = |degree: i32| degree + 1 + (degree + 1) % 2;
        for k in 0..=next_even(kronrod) {
            let exact = if k % 2 == 0 { 2.0 / (k as f64 + 1.0) } else { 0.0 };
            let (kr, g) = gauss_kronrod(rule, &mut |x: f64| x.powi(k), -1.0, 1.0);
            for (value, degree, which) in [(kr, kronrod, "Kronrod"), (g, gauss, "Gauss")] {
                if k <= degree || k % 2 == 1 {
                    assert!((value - exact).abs() <= 1e-15, "{which} (degree {degree}), x^{k}: {value} vs {exact}");
                } else if k == next_even(degree) {
                    assert!((value - exact).abs() > 1e-9, "{which} is exact at degree {k}");
                }
            }
        }
    }

    /// Gauss–Kronrod 2/5: its nodes `√(6/7)`, `1/√3`; the Kronrod rule exact to degree 7, the
    /// Gauss 2-point rule to 3.
    #[test]
    fn gauss_kronrod_5_degrees() {
        assert!((GAUSS_KRONROD_5[0].0 - (6.0f64 / 7.0).sqrt()).abs() <= f64::EPSILON);
        assert!((GAUSS_KRONROD_5[1].0 - (1.0f64 / 3.0).sqrt()).abs() <= f64::EPSILON);
        exact_to_degrees(&GAUSS_KRONROD_5, 7, 3);
    }

    /// Gauss–Kronrod 3/7: the Kronrod rule exact to degree 11, the Gauss 3-point rule to 5.
    #[test]
    fn gauss_kronrod_7_degrees() {
        exact_to_degrees(&GAUSS_KRONROD_7, 11, 5);
    }
}
