//! Area lights: a disc, a parallelogram (rectangle) and a sphere of uniform radiance, as the integral
//! over the emitter of the point-light kernel (docs/DESIGN.md §12; Packard 2004
//! integrates area lights over the emitter in the same way).
//!
//! An emitter of radiance `L_e` is a surface of Lambertian elements: `dA` at `q` with normal
//! `n(q)` is a point light of intensity `L_e dA` and distribution `max(0, n·ω)`
//! ([`Lambertian`]), so `L = ∫_A L_point(q) dA(q)`, `L_point` the point light of intensity `L_e`
//! ([`Scene::in_scatter`]). An [`Emission`] other than Lambert's cosine law raises that
//! distribution to a power (`max(0, n·ω)ᵖ`, a focused panel), still on the emitting side only. Near the ray's line `L_point ∝ 1/ρ` (`ρ` the distance from `q` to
//! it): integrable over an area, so a ray through the emitter sees a finite glow, but a peak.
//! So the emitter is taken in polar coordinates about its point nearest the ray segment, the
//! focus `f` (`dA = r dr dψ` cancels a `1/ρ` at `f`), with `r = ρ₀ sinh w` where the focus is
//! within a quarter of the emitter's size from the ray (`ρ₀`: their distance; `dr/ρ` is then
//! smooth in `w`); a rectangle as the triangles from `f` to its edges. All elements of a flat
//! emitter share its plane, so the part of the ray each one lights is the same: `L_point` has
//! no kinks over the emitter. A sphere's elements light only what lies outside their tangent
//! planes (nothing inside the sphere); it is taken in spherical coordinates about the point
//! where the ray segment enters or leaves it (two hemispheres if it does both), or else about
//! its point nearest the segment, the `β` integral split at the horizons of the segment's ends,
//! where `L_point` has kinks (docs/DESIGN.md §12). Both levels are globally adaptive Gauss–Kronrod (QUADPACK's QAG,
//! as [`crate::extended`]), the inner to a tenth of the outer tolerance, each point light to a
//! tenth as well, at most [`MAX_AREA_PANELS`] panels each.

pub mod outer;

use crate::error::{check_non_negative, check_vector, ErrorKind, InputError};
use crate::extended::{adaptive, edges_between, inner_control, outer_rule, outer_tolerance, working_tolerance};
use crate::combined::Physics;
use crate::geometry::{basis, cross, dot, length, normalize, sphere_miss, sub, Canonical};
use crate::light::{Lambertian, LightDistribution, Omni};
use crate::scalar::Scalar;
use crate::phase::PhaseFunction;
use crate::real::Real;
use crate::scene::{default_panels, validate, Medium, PointLight, Ray, Scene};

/// The shape of an area light.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Emitter<T: Real> {
    /// A disc emitting on the side its normal points to.
    Disc {
        /// Centre.
        center: T::Vec3,
        /// Normal of the emitting side (any length but zero).
        normal: T::Vec3,
        /// Radius `≥ 0`.
        radius: T,
    },
    /// The parallelogram `corner + u·edge_u + v·edge_v`, `u, v ∈ [0, 1]`, emitting on the side
    /// of `edge_u × edge_v` (a rectangle when the edges are perpendicular).
    Rectangle {
        /// One corner.
        corner: T::Vec3,
        /// The first edge from it.
        edge_u: T::Vec3,
        /// The second edge from it (not parallel to the first).
        edge_v: T::Vec3,
    },
    /// A sphere emitting outward from every point of its surface (docs/DESIGN.md §12: zero on
    /// the part of the ray inside it, which no element faces).
    Sphere {
        /// Centre.
        center: T::Vec3,
        /// Radius `≥ 0`.
        radius: T,
    },
}

/// How every element of an emitter shares its light among the directions of its emitting side:
/// `dA` emits the intensity `L_e·dA·D(c)` at the cosine `c` to its normal, nothing behind it.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub enum Emission {
    /// `D = c`, Lambert's cosine law: uniform radiance `L_e` in every direction.
    #[default]
    Lambertian,
    /// `D = cᵖ`, `1 ≤ p ≤ 1024`: a focused panel (louvres, a diffuser film), radiance
    /// `L_e·c^{p−1}`; `p = 1` is [`Emission::Lambertian`].
    CosineLobe {
        /// The power `p`.
        power: u32,
    },
}

impl Emission {
    /// The largest cosine-lobe power.
    pub const MAX_POWER: u32 = 1024;

    /// Checks the parameters: `light.emission.power`.
    pub fn validate(&self) -> Result<(), InputError> {
        match *self {
            Emission::CosineLobe { power } if !(1..=Self::MAX_POWER).contains(&power) => Err(InputError::new("light.emission.power", ErrorKind::LobePower)),
            _ => Ok(()),
        }
    }

    /// The power `p` of `D = cᵖ`.
    fn power(&self) -> u32 {
        match *self {
            Emission::Lambertian => 1,
            Emission::CosineLobe { power } => power,
        }
    }
}

/// One element of an emitter as a point light's distribution: [`Lambertian`] about its normal,
/// raised to its [`Emission`]'s power (one kink, `c = 0`, where a ray crosses the plane).
#[derive(Clone, Copy, Debug)]
struct Element<T: Real> {
    lambertian: Lambertian<T>,
    power: u32,
}

impl<T: Real> LightDistribution<T> for Element<T> {
    fn axis(&self) -> [T; 3] {
        self.lambertian.axis()
    }
    fn eval<S: Scalar<T>>(&self, c: S) -> S {
        let d = self.lambertian.eval(c);
        if self.power == 1 {
            d
        } else {
            d.powi(self.power as i32)
        }
    }
    fn kinks(&self) -> [Option<T>; 2] {
        self.lambertian.kinks()
    }
    fn dark_below(&self) -> Option<T> {
        self.lambertian.dark_below()
    }
    fn polynomial_degree(&self) -> Option<u32> {
        Some(self.power)
    }
}

/// An area light: an emitter of radiance `L_e` along its normals (uniform in every direction,
/// Lambertian, unless its [`Emission`] says otherwise).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct AreaLight<T: Real> {
    /// The shape.
    pub emitter: Emitter<T>,
    /// Radiance `L_e ≥ 0` of every point along its normal (with the default Lambertian
    /// emission, in every direction of its emitting side).
    pub radiance: T,
    /// How each element shares its light among directions (default: Lambertian).
    pub emission: Emission,
}

impl<T: Real> AreaLight<T> {
    /// A Lambertian emitter: radiance `L_e` in every direction of its emitting side.
    pub fn new(emitter: Emitter<T>, radiance: T) -> Self {
        AreaLight { emitter, radiance, emission: Emission::Lambertian }
    }
}

/// The most Gauss–Kronrod panels of each of the two integrals over the emitter.
pub const MAX_AREA_PANELS: usize = 48;

/// A validated scene with an area light.
#[derive(Clone, Copy, Debug)]
pub struct AreaScene<T: Real, P> {
    ray: Ray<T>,
    light: AreaLight<T>,
    medium: Medium<T>,
    phase: P,
}

fn axpy<T: Real>(p: [T; 3], s: T, v: [T; 3]) -> [T; 3] {
    [p[0] + s * v[0], p[1] + s * v[1], p[2] + s * v[2]]
}

impl<T, P> AreaScene<T, P>
where
    T: Real,
    P: PhaseFunction<T> + Clone,
{
    /// Validates and builds a scene.
    ///
    /// # Errors
    /// [`InputError`] naming the first invalid field: `light.center`, `light.normal` (also zero),
    /// `light.radius` (negative or non-finite; a disc's or a sphere's), `light.corner`, `light.edge_u`, `light.edge_v`
    /// (also zero or parallel to `edge_u`), `light.radiance`, `light.emission.power`
    /// ([`Emission::validate`]), then the ray, medium and phase function as [`Scene::new`] names
    /// them.
    pub fn new(ray: Ray<T>, light: AreaLight<T>, medium: Medium<T>, phase: P) -> Result<Self, InputError> {
        let anchor = match light.emitter {
            Emitter::Disc { center, normal, radius } => {
                check_vector(T::vec3_to_array(center), "light.center", false)?;
                check_vector(T::vec3_to_array(normal), "light.normal", true)?;
                check_non_negative(radius, "light.radius")?;
                center
            }
            Emitter::Rectangle { corner, edge_u, edge_v } => {
                check_vector(T::vec3_to_array(corner), "light.corner", false)?;
                check_vector(T::vec3_to_array(edge_u), "light.edge_u", true)?;
                check_vector(T::vec3_to_array(edge_v), "light.edge_v", true)?;
                let (u, v) = (normalize(T::vec3_to_array(edge_u)), normalize(T::vec3_to_array(edge_v)));
                if !(length(cross(u, v)) > T::epsilon()) {
                    return Err(InputError::new("light.edge_v", ErrorKind::ZeroVector));
                }
                corner
            }
            Emitter::Sphere { center, radius } => {
                check_vector(T::vec3_to_array(center), "light.center", false)?;
                check_non_negative(radius, "light.radius")?;
                center
            }
        };
        check_non_negative(light.radiance, "light.radiance")?;
        light.emission.validate()?;
        let point = PointLight { position: anchor, intensity: light.radiance, distribution: Omni };
        validate(&ray, &point, &medium, &phase)?;
        Ok(AreaScene { ray, light, medium, phase })
    }

    /// The ray.
    pub fn ray(&self) -> &Ray<T> {
        &self.ray
    }
    /// The area light.
    pub fn light(&self) -> &AreaLight<T> {
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

    /// In-scattered radiance of the area light, error-controlled to [`outer_tolerance`].
    pub fn in_scatter(&self) -> T {
        self.in_scatter_counted(outer_tolerance()).0
    }

    /// The same to a relative tolerance of the outer estimate (no finer than
    /// [`Real::PANEL_TOLERANCE`], the point lights' own), and the point lights evaluated.
    pub fn in_scatter_counted(&self, tolerance: T) -> (T, usize) {
        let tolerance = working_tolerance(tolerance);
        if self.light.radiance == T::zero() || self.medium.sigma_s == T::zero() {
            return (T::zero(), 0);
        }
        let o = T::vec3_to_array(self.ray.origin);
        let d = normalize(T::vec3_to_array(self.ray.dir));
        let (t0, t1) = (self.ray.t_min, self.ray.t_max);
        // the ray segment's point nearest to x
        let nearest = |x: [T; 3]| {
            let t = dot(sub(x, o), d).max(t0).min(t1);
            axpy(o, t, d)
        };
        let inner = inner_control(tolerance);
        let rule = outer_rule(tolerance);
        let inner_tolerance = tolerance * T::lit(0.1);
        let mut evaluated = 0;
        // a sphere's elements take their canonical form from its place about the ray's line
        // ([`ElementForm`]) where that is known, the others from their positions; every
        // element's light is the same but for its axis, which the canonical form carries
        let form = match self.light.emitter {
            Emitter::Sphere { center, radius } => ElementForm::new(o, T::vec3_to_array(self.ray.dir), d, (t0, t1), T::vec3_to_array(center), radius),
            _ => None,
        };
        // the element at `q` with the normal `n` as its point light
        let element = |q: [T; 3], n: [T; 3]| PointLight { position: T::vec3_from_array(q), intensity: self.light.radiance, distribution: Element { lambertian: Lambertian { axis: T::vec3_from_array(n) }, power: self.light.emission.power() } };
        let any_element = element(o, d);
        let phys = Physics::new(&any_element, &self.medium, &self.phase);
        let mut point = |q: [T; 3], n: [T; 3]| -> T {
            evaluated += 1;
            if let Some(form) = &form {
                return default_panels(&form.at(n), &phys, inner).0;
            }
            match Scene::new(self.ray, element(q, n), self.medium, self.phase.clone()) {
                Ok(scene) => scene.in_scatter_controlled(inner).0,
                Err(_) => T::zero(),
            }
        };
        let value = match self.light.emitter {
            Emitter::Disc { center, normal, radius } => {
                if !(radius > T::zero()) {
                    return (T::zero(), 0);
                }
                let (c, n) = (T::vec3_to_array(center), normalize(T::vec3_to_array(normal)));
                let (a1, a2) = basis(n);
                // the focus: the plane's point nearest the ray segment, drawn into the disc
                let f = project(nearest(pierce(o, d, t0, t1, c, n).unwrap_or(c)), c, n);
                let off = sub(f, c);
                let dist = length(off);
                let f = if dist > radius { axpy(c, radius / dist, off) } else { f };
                let off = sub(f, c);
                let k = dot(off, off) - radius * radius;
                // r to the circle along e: the positive root of r² + 2br + k = 0, b = off·e
                let r_max = |e: [T; 3]| {
                    let b = dot(off, e);
                    let disc = (b * b - k).max(T::zero()).sqrt();
                    if b > T::zero() {
                        (-k / (b + disc)).max(T::zero())
                    } else {
                        disc - b
                    }
                };
                // on the rim only the half-plane towards the centre holds the disc
                let (lo, hi) = if k >= -(T::epsilon() * radius * radius) && dist > T::zero() {
                    let towards = (-dot(off, a2)).atan2(-dot(off, a1));
                    (towards - T::FRAC_PI_2(), towards + T::FRAC_PI_2())
                } else {
                    (T::zero(), T::PI() + T::PI())
                };
                let rho0 = length(sub(f, nearest(f)));
                polar(rule, &mut point, f, n, a1, a2, &[lo, hi], &|e, _| r_max(e), rho0, radius, tolerance, inner_tolerance)
            }
            Emitter::Rectangle { corner, edge_u, edge_v } => {
                let (p0, eu, ev) = (T::vec3_to_array(corner), T::vec3_to_array(edge_u), T::vec3_to_array(edge_v));
                let n = normalize(cross(eu, ev));
                let (a1, a2) = basis(n);
                // the focus: the plane's point nearest the ray segment, clamped into [0, 1]²
                let x = project(nearest(pierce(o, d, t0, t1, p0, n).unwrap_or(axpy(axpy(p0, T::lit(0.5), eu), T::lit(0.5), ev))), p0, n);
                let w = sub(x, p0);
                // (u, v) by the dual basis of (eu, ev) in the plane
                let (uu, uv, vv) = (dot(eu, eu), dot(eu, ev), dot(ev, ev));
                let det = uu * vv - uv * uv;
                let (wu, wv) = (dot(w, eu), dot(w, ev));
                let clamp = |x: T| x.max(T::zero()).min(T::one());
                let (u, v) = (clamp((wu * vv - wv * uv) / det), clamp((wv * uu - wu * uv) / det));
                let f = axpy(axpy(p0, u, eu), v, ev);
                let corners = [p0, axpy(p0, T::one(), eu), axpy(axpy(p0, T::one(), eu), T::one(), ev), axpy(p0, T::one(), ev)];
                let angle = |p: [T; 3]| {
                    let q = sub(p, f);
                    dot(q, a2).atan2(dot(q, a1))
                };
                // the triangles (f, C_i, C_{i+1}) that have an area, as ψ ranges, each with the
                // edge it reaches: its outward normal m and distance h = (C_i − f)·m
                let mut edges = [T::zero(); 5];
                let mut lines = [([T::zero(); 3], T::zero()); 4];
                let mut count = 0;
                let mut start = T::zero();
                let line = |i: usize| {
                    let (ci, cj) = (corners[i % 4], corners[(i + 1) % 4]);
                    let m = normalize(cross(sub(cj, ci), n));
                    (ci, cj, m, dot(sub(ci, f), m))
                };
                let thin = T::epsilon() * (uu.max(vv)).sqrt();
                // start after a triangle without area (f on its edge), so that the others follow
                // each other around f without a gap
                let first = (0..4).find(|&i| !(line(i + 3).3 > thin)).unwrap_or(0);
                for i in first..first + 4 {
                    let (ci, cj, m, h) = line(i);
                    if !(h > thin) {
                        continue;
                    }
                    let (mut psi_i, mut psi_j) = (angle(ci), angle(cj));
                    if count == 0 {
                        start = psi_i;
                        edges[0] = psi_i;
                    }
                    // unwrap: increasing from the first triangle's start
                    while psi_i < start - T::lit(1e-9) {
                        psi_i = psi_i + T::PI() + T::PI();
                    }
                    while psi_j <= psi_i {
                        psi_j = psi_j + T::PI() + T::PI();
                    }
                    edges[count + 1] = psi_j;
                    lines[count] = (m, h);
                    count += 1;
                }
                if count == 0 {
                    return (T::zero(), 0);
                }
                let r_max = |e: [T; 3], psi: T| {
                    // the triangle holding ψ
                    let mut i = 0;
                    while i + 1 < count && psi > edges[i + 1] {
                        i += 1;
                    }
                    let (m, h) = lines[i];
                    let c = dot(e, m);
                    if c > T::zero() {
                        h / c
                    } else {
                        T::zero()
                    }
                };
                let size = (uu.max(vv)).sqrt();
                let rho0 = length(sub(f, nearest(f)));
                polar(rule, &mut point, f, n, a1, a2, &edges[..=count], &r_max, rho0, size, tolerance, inner_tolerance)
            }
            Emitter::Sphere { center, radius } => {
                if !(radius > T::zero()) {
                    return (T::zero(), 0);
                }
                let c = T::vec3_to_array(center);
                let sphere = Sphere { c, radius, o, d, t0, t1 };
                match sphere.foci() {
                    Foci::None => return (T::zero(), 0),
                    Foci::One(a) => sphere.cap(rule, &mut point, a, None, tolerance, inner_tolerance),
                    Foci::Two(entry, exit) => {
                        // the hemispheres n·d ≤ 0 (the entry's) and n·d ≥ 0, each a cap about
                        // its pierce point, each to the tolerance: their sum is within it
                        sphere.cap(rule, &mut point, entry, Some(-T::one()), tolerance, inner_tolerance)
                            + sphere.cap(rule, &mut point, exit, Some(T::one()), tolerance, inner_tolerance)
                    }
                }
            }
        };
        (value, evaluated)
    }
}

/// The canonical form of a sphere's element at `c + R n` with the normal `n` as its light's
/// axis, from the sphere's place about the ray's line ([`sphere_miss`]): with `m` the unit
/// vector from the centre's foot on the line to the centre, `w = m × d`, the element lies
/// `(h_c + R n·m) m + R (n·w) w` from its own foot, and `h_c + R n·m = (h_c − R) + R|n + m|²/2`
/// has no cancellation — where `c + R n` rounded carries `ε|c|` into the distance of an element
/// next to the ray (in f32, on the part behind a sphere a ray misses by 1e-5 of its radius,
/// 2.2e-4 off: docs/DESIGN.md §12).
struct ElementForm<T> {
    d: [T; 3],
    m: [T; 3],
    w: [T; 3],
    /// The centre's foot `x_h` on the line, the miss `h_c − R`, the radius, the segment.
    x_h: T,
    miss: T,
    radius: T,
    t0: T,
    t1: T,
}

impl<T: Real> ElementForm<T> {
    /// `None` where [`sphere_miss`] is (the centre on the line, or beyond the exact products'
    /// range).
    fn new(o: [T; 3], dir: [T; 3], d: [T; 3], (t0, t1): (T, T), c: [T; 3], radius: T) -> Option<Self> {
        let (_, m, miss) = sphere_miss(o, dir, c, radius)?;
        Some(ElementForm { d, m, w: normalize(cross(m, d)), x_h: dot(sub(c, o), d), miss, radius, t0, t1 })
    }

    /// The element with the unit normal `n`.
    fn at(&self, n: [T; 3]) -> Canonical<T> {
        let (nd, nw) = (dot(n, self.d), dot(n, self.w));
        let s = [n[0] + self.m[0], n[1] + self.m[1], n[2] + self.m[2]];
        let s2 = dot(s, s);
        let g = self.miss + self.radius * s2 * T::lit(0.5);
        let across = self.radius * nw;
        let h = g.hypot(across);
        // d_c = −(g m + R (n·w) w)·n / h, n·m = |n + m|²/2 − 1
        let d_c = if h > T::zero() { (g * (T::one() - s2 * T::lit(0.5)) - across * nw) / h } else { T::zero() };
        Canonical { h, x_h: self.x_h + self.radius * nd, d_el: nd, d_c, t0: self.t0, t1: self.t1 }
    }
}

/// The sphere and the ray segment `o + t d`, `t ∈ [t0, t1]` (`d` a unit vector).
struct Sphere<T> {
    c: [T; 3],
    radius: T,
    o: [T; 3],
    d: [T; 3],
    t0: T,
    t1: T,
}

/// Where the sphere's integral is centred (unit vectors from the centre).
enum Foci<T> {
    /// The segment lies inside the sphere: no element faces any of it.
    None,
    /// One pole: the point nearest the segment, or the one pierce point the segment holds.
    One([T; 3]),
    /// The segment enters and leaves the sphere: the entry and exit points.
    Two([T; 3], [T; 3]),
}

impl<T: Real> Sphere<T> {
    /// The poles of the spherical coordinates: where the ray segment meets the sphere, else
    /// the direction of the segment's point nearest the centre. A ray that meets the sphere
    /// within a thousandth of its radius of tangency has one pole (its two pierce points are
    /// a thousandth of a radian from it).
    fn foci(&self) -> Foci<T> {
        let (o, d, c, radius) = (self.o, self.d, self.c, self.radius);
        let tc = dot(sub(c, o), d);
        let rho_c = length(sub(c, axpy(o, tc, d)));
        let at = |t: T| normalize(sub(axpy(o, t, d), c));
        if rho_c < radius {
            let half = ((radius - rho_c) * (radius + rho_c)).sqrt();
            let (t_in, t_out) = (tc - half, tc + half);
            if t_in <= self.t0 && self.t1 <= t_out {
                return Foci::None;
            }
            let (has_in, has_out) = (self.t0 < t_in && t_in < self.t1, self.t0 < t_out && t_out < self.t1);
            if has_in && has_out && half > T::lit(1e-3) * radius {
                return Foci::Two(at(t_in), at(t_out));
            }
            if has_in != has_out {
                return Foci::One(at(if has_in { t_in } else { t_out }));
            }
        }
        let nearest = tc.max(self.t0).min(self.t1);
        let a = at(nearest);
        // a segment through the centre (only when it also starts or ends there): any pole
        if length(a) > T::zero() { Foci::One(a) } else { Foci::One(basis(d).0) }
    }

    /// `∫∫ point(c + R n, n) R² sin β dβ dψ` over the cap about the unit `a`: `n = cos β a +
    /// sin β e_ψ`, `ψ ∈ [0, 2π]`, `β` from 0 to `π`, or, with `side = s`, to where `s n·d`
    /// turns negative (`s a·d > 0`: the hemisphere holding `a`). `L_point` has kinks where
    /// an element's tangent plane passes an end of the ray segment (`n·(x − c) = R`; the far
    /// end of an infinite ray: `n·d = 0`): the `β` integral is split there. `β = (ρ₀/R) sinh
    /// w` where the ray passes within a quarter radius of the pole (`ρ₀`), as [`polar`].
    fn cap(
        &self,
        rule: &[(f64, f64, f64)],
        point: &mut impl FnMut([T; 3], [T; 3]) -> T,
        a: [T; 3],
        side: Option<T>,
        tolerance: T,
        inner_tolerance: T,
    ) -> T {
        let (c, radius, d) = (self.c, self.radius, self.d);
        let (b1, b2) = basis(a);
        let pole = axpy(c, radius, a);
        let t = dot(sub(pole, self.o), d).max(self.t0).min(self.t1);
        let rho0 = length(sub(pole, axpy(self.o, t, d)));
        let scale = if rho0 < radius * T::lit(0.25) { (rho0 / radius).max(T::epsilon()) } else { T::zero() };
        let to_w = |beta: T| if scale > T::zero() { (beta / scale).asinh() } else { beta };
        // the ends' horizons: a finite end x (offset p = x − c from the centre), the far end of
        // an infinite ray as the direction d
        let start = sub(axpy(self.o, self.t0, d), c);
        let end = if self.t1.is_finite() { Some(sub(axpy(self.o, self.t1, d), c)) } else { None };
        let two_pi = T::PI() + T::PI();
        let mut outer = |psi: T| {
            let (s, co) = psi.sin_cos();
            let e: [T; 3] = core::array::from_fn(|i| co * b1[i] + s * b2[i]);
            let beta_max = match side {
                Some(sign) => (sign * dot(a, d)).atan2(-sign * dot(e, d)),
                None => T::PI(),
            };
            // n(β)·p = A cos β + B sin β = |(A, B)| cos(β − φ), φ = atan2(B, A)
            let mut cuts = [T::infinity(); 4];
            let mut crossing = |p: [T; 3], level: T, slot: usize| {
                let (big_a, big_b) = (dot(a, p), dot(e, p));
                let norm = big_a.hypot(big_b);
                if norm > level {
                    let (phi, delta) = (big_b.atan2(big_a), (level / norm).acos());
                    for (k, beta) in [phi - delta, phi + delta].into_iter().enumerate() {
                        // into (−π, π]: β ∈ [0, π] is where the half great circle runs
                        let beta = if beta > T::PI() { beta - two_pi } else if beta <= -T::PI() { beta + two_pi } else { beta };
                        if beta > T::zero() && beta < beta_max {
                            cuts[slot + k] = to_w(beta);
                        }
                    }
                }
            };
            crossing(start, radius, 0);
            match end {
                Some(p) => crossing(p, radius, 2),
                None => crossing(d, T::zero(), 2),
            }
            let (edges, n): ([T; 6], usize) = edges_between(T::zero(), to_w(beta_max), &mut cuts);
            let mut radial = |w: T| {
                let (beta, dbeta) = if scale > T::zero() { (scale * w.sinh(), scale * w.cosh()) } else { (w, T::one()) };
                let (sb, cb) = beta.sin_cos();
                let n: [T; 3] = core::array::from_fn(|i| cb * a[i] + sb * e[i]);
                on_the_ray_is_zero(point(axpy(c, radius, n), n)) * radius * radius * sb * dbeta
            };
            adaptive(rule, &mut radial, &edges[..=n], inner_tolerance, MAX_AREA_PANELS).0
        };
        // knots: the quarters, and the meridians where a horizon's crossing appears or swings
        // fast (a singularity of the ψ integrand): for a finite end, with `A = a·p` and `p⊥`
        // the rest of `p`, where the horizon touches the meridian (`e_ψ·p = √(R² − A²)`, for
        // `|A| < R`), or `ψ_p ± π/2` where the horizon passes within a quarter radius of a
        // pole (`R ≤ |A| < 1.25 R`); for the far end of an infinite ray, whose horizon is the
        // great circle `n·d = 0`, `ψ_d ± π/2` where it passes near the poles (`|a·d| < 1/4`; at
        // `a·d = 0` it is those two meridians)
        let quarter = T::FRAC_PI_2();
        let mut cuts = [quarter, T::PI(), T::PI() + quarter, T::infinity(), T::infinity(), T::infinity(), T::infinity()];
        let near = radius * T::lit(1.25);
        let horizons = [(start, radius, near), end.map_or((d, T::zero(), T::lit(0.25)), |p| (p, radius, near))];
        for (slot, (p, level, near)) in horizons.into_iter().enumerate() {
            let big_a = dot(a, p).abs();
            let (p1, p2) = (dot(b1, p), dot(b2, p));
            let across = p1.hypot(p2);
            let touch = ((level - big_a).max(T::zero()) * (level + big_a)).sqrt();
            let delta = if big_a < level && touch < across {
                (touch / across).acos()
            } else if big_a >= level && big_a < near {
                quarter
            } else {
                continue;
            };
            let psi_p = p2.atan2(p1);
            for (k, psi) in [psi_p - delta, psi_p + delta].into_iter().enumerate() {
                // into [0, 2π)
                cuts[3 + 2 * slot + k] = psi - two_pi * (psi / two_pi).floor();
            }
        }
        let (knots, n): ([T; 9], usize) = edges_between(T::zero(), two_pi, &mut cuts);
        adaptive(rule, &mut outer, &knots[..=n], tolerance, MAX_AREA_PANELS).0
    }
}

/// A node's point light, `0` where it lies on the ray within rounding (the point light's `+∞`):
/// such a node is within rounding of the focus or pole on the ray, where the weight `r dr` (or
/// `sin β dβ`) vanishes as fast as `L_point ∝ 1/ρ` grows, so that its true term is of the
/// rounding's size — an emitter the ray passes through has a finite glow. Without it a ray
/// through a rectangle's focus computed exactly gave `+∞` at tolerances from 1e-5 on
/// (tests/area.rs `a_ray_through_the_focus_is_finite`).
fn on_the_ray_is_zero<T: Real>(value: T) -> T {
    if value.is_infinite() {
        T::zero()
    } else {
        value
    }
}

/// Where the ray's line meets the plane through `c` with unit normal `n` (`None`: parallel),
/// as the ray segment's point nearest to that meeting point (`t` clamped into `[t0, t1]`).
fn pierce<T: Real>(o: [T; 3], d: [T; 3], t0: T, t1: T, c: [T; 3], n: [T; 3]) -> Option<[T; 3]> {
    let dn = dot(d, n);
    if !(dn.abs() > T::epsilon()) {
        return None;
    }
    let t = (dot(sub(c, o), n) / dn).max(t0).min(t1);
    t.is_finite().then(|| axpy(o, t, d))
}

/// `x` projected onto the plane through `c` with unit normal `n`.
fn project<T: Real>(x: [T; 3], c: [T; 3], n: [T; 3]) -> [T; 3] {
    axpy(x, -dot(sub(x, c), n), n)
}

/// `∫∫ point(f + r e_ψ) r dr dψ` over `ψ` between `edges` and `r ∈ [0, r_max(e_ψ, ψ)]`, `e_ψ =
/// cos ψ a₁ + sin ψ a₂`; `r = ρ₀ sinh w` when the ray passes within a quarter of `size` of `f`.
#[allow(clippy::too_many_arguments)]
fn polar<T: Real>(
    rule: &[(f64, f64, f64)],
    point: &mut impl FnMut([T; 3], [T; 3]) -> T,
    f: [T; 3],
    n: [T; 3],
    a1: [T; 3],
    a2: [T; 3],
    edges: &[T],
    r_max: &dyn Fn([T; 3], T) -> T,
    rho0: T,
    size: T,
    tolerance: T,
    inner_tolerance: T,
) -> T {
    let scale = if rho0 < size * T::lit(0.25) { rho0.max(size * T::epsilon()) } else { T::zero() };
    // each ψ range in quarters at most π/2 wide, so that the outer rule starts resolved
    let mut knots = [T::zero(); 24];
    let mut count = 0;
    for pair in edges.windows(2) {
        let parts = ((pair[1] - pair[0]) / T::FRAC_PI_2()).ceil().max(T::one()).min(T::lit(4.0)).to_usize().unwrap_or(1);
        for j in 0..parts {
            if count < knots.len() - 1 {
                knots[count] = pair[0] + (pair[1] - pair[0]) * T::from(j).unwrap_or(T::zero()) / T::from(parts).unwrap_or(T::one());
                count += 1;
            }
        }
    }
    knots[count] = edges[edges.len() - 1];
    let mut outer = |psi: T| {
        let (s, c) = psi.sin_cos();
        let e: [T; 3] = core::array::from_fn(|i| c * a1[i] + s * a2[i]);
        let reach = r_max(e, psi);
        if !(reach > T::zero()) {
            return T::zero();
        }
        let mut radial = |w: T| {
            let (r, dr) = if scale > T::zero() { (scale * w.sinh(), scale * w.cosh()) } else { (w, T::one()) };
            on_the_ray_is_zero(point(axpy(f, r, e), n)) * r * dr
        };
        let w_hi = if scale > T::zero() { (reach / scale).asinh() } else { reach };
        adaptive(rule, &mut radial, &[T::zero(), w_hi], inner_tolerance, MAX_AREA_PANELS).0
    };
    adaptive(rule, &mut outer, &knots[..=count], tolerance, MAX_AREA_PANELS).0
}
