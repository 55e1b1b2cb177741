//! The CPU/shader agreement criterion, in one place for `airlight verify`, the agreement
//! tests (tests/tests/gpu_agreement.rs) and the `shader` fuzz target.
//!
//! A record's shader result is judged against the f32 CPU kernel computing what the shader
//! computes — the panels with the same nodes per panel and `airlight::SHADER_CONTROL`:
//!
//! `|gpu − cpu_f32| ≤ NOISE_FACTOR·noise + ALLOWANCE·scale + DENORMAL_FLOOR` (9·noise +
//! 2e-4·scale + 2^-100), statuses equal, no NaN.
//!
//! ## The allowance, from Vulkan's precision rules (f32)
//! The shader and the CPU f32 kernel run the same algorithm; they differ by the accuracy of
//! the built-ins, which Vulkan bounds as: `exp` 3 + 2|x| ulp, `log` 3 ulp (2^-21 absolute in
//! [0.5, 2]), `sin`/`cos` 2^-11 absolute on [−π, π], `atan` 4096 ulp, division 2.5 ulp,
//! `sqrt`/`inverseSqrt` 2 ulp. The shader avoids the three loose ones where they matter (its
//! own `atan`, `log1p`, `sin`/`cos` from + − × ÷, ≈ 2 ulp), so what remains is `exp` of
//! folded exponents `≥ −88` (≤ 179 ulp = 2.1e-5), `log` (3 ulp) and division: ≈ 2.5e-5 per
//! closed form, times the cancellation of a difference (≤ 4 outside the short route:
//! `1/(1 − e^{−0.3})` on its boundary) and two halves: **2e-4** relative for model-exact
//! scenes, and relative to the integrand's *scale* (`L` with `F` replaced by its maximum)
//! for anisotropic ones.
//!
//! ## The noise: f32 conditioning of the same algorithm
//! Both sides carry f32 rounding noise, amplified by the conditioning of the record itself
//! (a light nearly on the ray line: the value goes as `1/h`, and one ulp of an input moves
//! `h` by `ε|p − o|/h`). It is measured per record on the CPU: the largest
//! `|cpu_f32 − cpu_f64|` (same method and control, rounding the only difference) over the
//! record and `PERTURBATIONS` copies with one input moved by one ulp — the spread of f32
//! results over inputs that are the same to f32's precision. That error is the
//! conditioning `κ` of the record times the CPU's per-operation rounding (≤ 1 ulp: correctly
//! rounded arithmetic, libm's `exp`/`ln` within 1 ulp). The shader's error is the same `κ`
//! times *its* per-operation errors, which Vulkan lets be up to 8× larger where the
//! conditioned quantities are formed: `exp` 3 + 2|x| ulp at small arguments (≤ 8 ulp),
//! division 2.5 ulp (against 0.5). So `|gpu − cpu_f32| ≤ noise + 8·noise`: `NOISE_FACTOR = 9`.
//!
//! Discrete choices (route, which panel is split next, when the estimates meet the
//! tolerance, where a cone edge cuts) can fall differently when a decision value sits within
//! rounding of its threshold; the two results are then two valid approximations, each within
//! the method's error `e_N` of the integral, so `noise` also holds `e_N`, estimated as the
//! f64 difference to the default `in_scatter` (error-controlled to 1e-11).
//!
//! Vulkan lets denormals flush to zero: below `2^-100` (the result's last factors, the
//! prefactor `2σsI/h` and the folded exponential, reach `2^26` at most) an intermediate may
//! have flushed, so that absolute floor is added.
//!
//! ## The domain of agreement
//! Flushing can also hit the *geometry*: with inputs near `f32::MAX` or `f32::MIN_POSITIVE`
//! a normalised direction component or a product of two inputs is a denormal, which the
//! shader may read as 0 (lavapipe does; `shaderDenormPreserveFloat32` is optional in
//! Vulkan) — e.g. a ray from `(3.4e38, …)` whose direction's `z` is `−2.2e-39` after scaling:
//! the CPU finds the light 0.74 from the line (2.4e33), lavapipe on it (`+∞`). No Vulkan
//! shader can promise the CPU's value there, so the criterion above is applied to records
//! [`in_domain`]: every finite input number zero or of magnitude in `[2^-40, 2^40]`, whose
//! products of up to three stay in f32's normal range `[2^-126, 2^128)`. Outside it a result
//! is judged by [`judge_defined`]: the same validity, a finite non-negative value (`+∞` as
//! `FLT_MAX` allowed), 0 for invalid records.

use crate::layout::{STATUS_INFINITE, STATUS_INVALID, STATUS_OK};
use airlight::record::SceneRecord;
use airlight::light::AnyDistribution;
use airlight::phase::AnyPhase;
use airlight::{PhaseFunction, PointLight, Ray, Scene, SegmentLight, SegmentScene, Surface, SurfaceScene};

/// Relative allowance (of scale) for the built-ins' accuracy (module docs).
pub const ALLOWANCE: f64 = 2e-4;
/// Absolute floor for denormal flushing (module docs).
pub const DENORMAL_FLOOR: f64 = 1.0 / (1u128 << 100) as f64;
/// The noise's multiplier: the CPU's own share plus the shader's, whose per-operation
/// errors Vulkan lets be up to 8× the CPU's (module docs).
pub const NOISE_FACTOR: f64 = 9.0;
/// How many one-ulp perturbations of the inputs sample the f32 noise.
pub const PERTURBATIONS: usize = 20;

/// What the CPU says a record's shader result should be.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Expected {
    /// The f32 CPU kernel's value (0 for an invalid record, `f32::MAX` for `+∞`, as the shader
    /// writes them).
    pub value: f32,
    /// The status the shader must report.
    pub status: u32,
    /// The f64 kernel's value by the same method (nodes per panel and control).
    pub f64_value: f64,
    /// The f32 noise plus the expansion error estimate (module docs), absolute.
    pub noise: f64,
    /// The integrand's scale: `L` with `F` replaced by its maximum (≥ |value|).
    pub scale: f64,
}

/// How one shader result compares.
#[derive(Clone, Debug, PartialEq)]
pub struct Judgement {
    /// `|gpu − cpu_f32| / scale` (0 for non-OK statuses).
    pub diff: f64,
    /// `|gpu − cpu_f64| / scale`.
    pub diff_f64: f64,
    /// How far the difference exceeds the tolerance, relative to scale (0 when within).
    pub excess: f64,
    /// What disagrees, if anything: a non-finite value, a status, or a value off tolerance.
    pub problem: Option<String>,
}

/// What the shader computes, on the CPU: the panels with `terms` nodes each and the shaders'
/// control ([`airlight::SHADER_CONTROL`], in `T`).
fn in_scatter<T: airlight::Real>(rec: &SceneRecord<T>, terms: usize) -> Option<T> {
    rec.scene().ok().and_then(|s| s.in_scatter_panels_with_nodes(terms, shader_control()))
}

/// [`airlight::SHADER_CONTROL`] in `T`.
fn shader_control<T: airlight::Real>() -> airlight::panels::Control<T> {
    let c = airlight::SHADER_CONTROL;
    airlight::panels::Control { tolerance: T::lit(c.tolerance as f64), floor: T::lit(c.floor as f64), max_panels: c.max_panels }
}

/// The record with input `k` (of `PERTURBATIONS`) moved by one ulp: `t_min` up/down, `t_max`
/// down, each coordinate of the light and of the origin up/down, direction components up,
/// `σt` up/down, the phase function's first parameter up/down (where it stays valid).
fn perturbed(rec: &SceneRecord<f32>, k: usize) -> SceneRecord<f32> {
    let mut q = *rec;
    let step = |x: f32, up: bool| if up { x.next_up() } else { x.next_down() };
    match k {
        0 | 1 => q.ray.t_min = step(q.ray.t_min, k == 0),
        2 => {
            if q.ray.t_max.is_finite() && q.ray.t_max.next_down() > q.ray.t_min {
                q.ray.t_max = q.ray.t_max.next_down();
            }
        }
        3..=8 => {
            let i = (k - 3) / 2;
            q.light.position[i] = step(q.light.position[i], k % 2 == 1);
        }
        9..=14 => {
            let i = (k - 9) / 2;
            q.ray.origin[i] = step(q.ray.origin[i], k % 2 == 1);
        }
        15 | 16 => q.ray.dir[k - 15] = step(q.ray.dir[k - 15], true),
        17 => q.medium.sigma_t = q.medium.sigma_t.next_up(),
        18 => q.medium.sigma_t = q.medium.sigma_t.next_down().max(0.0),
        _ => match &mut q.phase {
            AnyPhase::HenyeyGreenstein(p) => p.g = p.g.next_down(),
            AnyPhase::Schlick(p) => p.k = p.k.next_down(),
            AnyPhase::CornetteShanks(p) => p.g = p.g.next_down(),
            AnyPhase::TwoLobeHenyeyGreenstein(p) => p.w = p.w.next_down().max(0.0),
            _ => q.ray.dir[2] = q.ray.dir[2].next_up(),
        },
    }
    q
}

/// The CPU's expectation for `rec` from the shader with `terms` (8 or 12) nodes per panel.
pub fn expect(rec: &SceneRecord<f32>, terms: usize) -> Expected {
    let Some(v) = in_scatter(rec, terms) else {
        return Expected { value: 0.0, status: STATUS_INVALID, f64_value: 0.0, noise: 0.0, scale: 0.0 };
    };
    let wide = rec.cast::<f64>();
    let same = in_scatter(&wide, terms).unwrap_or(0.0);
    if v.is_infinite() {
        return Expected { value: f32::MAX, status: STATUS_INFINITE, f64_value: same, noise: 0.0, scale: 0.0 };
    }
    let exact = Scene::new(wide.ray, wide.light, wide.medium, wide.phase).map(|s| s.in_scatter()).unwrap_or(same);
    let e_n = (same - exact).abs();
    let mut worst = (v as f64 - same).abs();
    for k in 0..PERTURBATIONS {
        if let Some(x) = in_scatter(&perturbed(rec, k), terms) {
            if x.is_finite() {
                worst = worst.max((x as f64 - same).abs());
            }
        }
    }
    let noise = if same.is_finite() { worst + e_n } else { 0.0 };
    let mut iso = wide;
    iso.light.distribution = AnyDistribution::Omni;
    iso.phase = AnyPhase::Isotropic;
    let p_max = [-1.0f64, 1.0].iter().map(|&mu| wide.phase.eval(mu)).fold(0.0, f64::max);
    let scale = (in_scatter(&iso, 6).unwrap_or(0.0) * 4.0 * std::f64::consts::PI * p_max).max(v as f64);
    Expected { value: v, status: STATUS_OK, f64_value: same, noise, scale }
}

/// A segment light's scene in the record types.
pub type SegmentRecord<T> = SegmentScene<T, AnyDistribution<T>, AnyPhase<T>>;

/// What the shader computes for a segment light, on the CPU
/// ([`SegmentScene::in_scatter_panels_counted`] with the shaders' control and
/// [`airlight::SHADER_SEGMENT_PANELS`]).
fn segment_in_scatter<T: airlight::Real>(scene: &SegmentRecord<T>, terms: usize) -> T {
    let control = shader_control();
    let panels = airlight::SHADER_SEGMENT_PANELS;
    match terms {
        8 => scene.in_scatter_panels_counted::<8>(control, panels).0,
        12 => scene.in_scatter_panels_counted::<12>(control, panels).0,
        _ => panic!("the shaders are emitted with 8 or 12 nodes per panel, not {terms}"),
    }
}

/// The segment's scene with a point light at its end `a` in its place (same intensity and
/// distribution): the record [`perturbed`] moves.
fn at_first_end(scene: &SegmentRecord<f32>) -> SceneRecord<f32> {
    let l = scene.light();
    SceneRecord { ray: *scene.ray(), light: PointLight { position: l.a, intensity: l.intensity, distribution: l.distribution }, medium: *scene.medium(), phase: *scene.phase() }
}

/// The segment light with input `k` moved by one ulp: the inputs [`perturbed`] moves (the
/// light's position is the end `a`), then (`k ≥ PERTURBATIONS`) each coordinate of `b` up/down.
fn perturbed_segment(scene: &SegmentRecord<f32>, k: usize) -> Option<SegmentRecord<f32>> {
    let l = *scene.light();
    let mut b = l.b.to_array();
    let rec = at_first_end(scene);
    let q = if k < PERTURBATIONS {
        perturbed(&rec, k)
    } else {
        let i = (k - PERTURBATIONS) / 2;
        b[i] = if k % 2 == 0 { b[i].next_up() } else { b[i].next_down() };
        rec
    };
    let light = SegmentLight { a: q.light.position, b: airlight::glam::Vec3::from_array(b), intensity: l.intensity, distribution: l.distribution };
    SegmentScene::new(q.ray, light, q.medium, q.phase).ok()
}

/// The CPU's expectation for a segment light from the shader with `terms` nodes per panel,
/// by the same criterion as [`expect`]: the noise over the record and its one-ulp
/// perturbations (also of `b`) plus the error of the same method in f64 against the default
/// `in_scatter` (error-controlled to 1e-10); the scale is the segment with `F` replaced by its
/// maximum (isotropic light and phase, times `4π·max P`), at least the value.
pub fn expect_segment(scene: &SegmentRecord<f32>, terms: usize) -> Expected {
    let v = segment_in_scatter(scene, terms);
    let l = *scene.light();
    let cast = |x: airlight::glam::Vec3| airlight::glam::DVec3::new(x.x as f64, x.y as f64, x.z as f64);
    let rec = at_first_end(scene).cast::<f64>();
    let light = SegmentLight { a: rec.light.position, b: cast(l.b), intensity: rec.light.intensity, distribution: rec.light.distribution };
    let Ok(wide) = SegmentScene::new(rec.ray, light, rec.medium, rec.phase) else {
        return Expected { value: 0.0, status: STATUS_INVALID, f64_value: 0.0, noise: 0.0, scale: 0.0 };
    };
    let same = segment_in_scatter(&wide, terms);
    if v.is_infinite() {
        return Expected { value: f32::MAX, status: STATUS_INFINITE, f64_value: same, noise: 0.0, scale: 0.0 };
    }
    let e_n = (same - wide.in_scatter()).abs();
    let mut worst = (v as f64 - same).abs();
    for k in 0..PERTURBATIONS + 6 {
        if let Some(x) = perturbed_segment(scene, k).map(|q| segment_in_scatter(&q, terms)) {
            if x.is_finite() {
                worst = worst.max((x as f64 - same).abs());
            }
        }
    }
    let iso_light = SegmentLight { distribution: AnyDistribution::Omni, ..light };
    let iso = SegmentScene::new(rec.ray, iso_light, rec.medium, AnyPhase::Isotropic).map(|s| segment_in_scatter(&s, terms)).unwrap_or(0.0);
    finite_expectation(v, same, worst + e_n, iso, &rec.phase)
}

/// The expectation of a finite f32 value `v` whose f64 value by the same method is `same`, with
/// `noise` (the f32 spread plus the method's error) and `iso`, the same integral in isotropic
/// fog (and without the light's axis, where it has one): the scale is `iso·4π·max P`, at least
/// the value.
fn finite_expectation(v: f32, same: f64, noise: f64, iso: f64, phase: &AnyPhase<f64>) -> Expected {
    let noise = if same.is_finite() { noise } else { 0.0 };
    let p_max = [-1.0f64, 1.0].iter().map(|&mu| phase.eval(mu)).fold(0.0, f64::max);
    let scale = (iso * 4.0 * std::f64::consts::PI * p_max).max(v as f64);
    Expected { value: v, status: STATUS_OK, f64_value: same, noise, scale }
}

/// An area light's scene in the record types.
pub type AreaRecord<T> = airlight::AreaScene<T, AnyPhase<T>>;

/// An area light as a point-light record (the emitter's centre or corner as the light, of
/// intensity its radiance), the inputs [`perturbed`] moves, and its emitter back from such a
/// record (in `T`).
fn area_parts(scene: &AreaRecord<f32>) -> SceneRecord<f32> {
    let l = scene.light();
    let anchor = match l.emitter {
        airlight::Emitter::Disc { center, .. } | airlight::Emitter::Sphere { center, .. } => center,
        airlight::Emitter::Rectangle { corner, .. } => corner,
    };
    SceneRecord { ray: *scene.ray(), light: PointLight { position: anchor, intensity: l.radiance, distribution: AnyDistribution::Omni }, medium: *scene.medium(), phase: *scene.phase() }
}

/// The area light of `scene` with the ray, medium, phase function and anchor of `rec`, in `T`.
fn area_from<T: airlight::Real>(scene: &AreaRecord<f32>, rec: &SceneRecord<T>) -> Option<AreaRecord<T>> {
    use airlight::Emitter;
    let v = |x: airlight::glam::Vec3| T::vec3_from_array([T::lit(x.x as f64), T::lit(x.y as f64), T::lit(x.z as f64)]);
    let r = |x: f32| T::lit(x as f64);
    let l = scene.light();
    let emitter = match l.emitter {
        Emitter::Disc { normal, radius, .. } => Emitter::Disc { center: rec.light.position, normal: v(normal), radius: r(radius) },
        Emitter::Rectangle { edge_u, edge_v, .. } => Emitter::Rectangle { corner: rec.light.position, edge_u: v(edge_u), edge_v: v(edge_v) },
        Emitter::Sphere { radius, .. } => Emitter::Sphere { center: rec.light.position, radius: r(radius) },
    };
    let light = airlight::AreaLight { emitter, radiance: rec.light.intensity, emission: l.emission };
    airlight::AreaScene::new(rec.ray, light, rec.medium, rec.phase).ok()
}

/// The CPU's expectation for an area light from the shader, by the same criterion as
/// [`expect`]: the value of the same method, `AreaScene::in_scatter_bounded`, in f32; the noise
/// over the record and its one-ulp perturbations (of the ray, the emitter's centre or corner, `σt`
/// and the phase function) plus the method's error in f64 against the default `in_scatter`
/// (error-controlled to 1e-10); the scale is the value in isotropic fog with Lambertian emission
/// times `4π·max P`, at least the value.
pub fn expect_area(scene: &AreaRecord<f32>) -> Expected {
    let v = scene.in_scatter_bounded();
    let rec = area_parts(scene);
    let Some(wide) = area_from(scene, &rec.cast::<f64>()) else {
        return Expected { value: 0.0, status: STATUS_INVALID, f64_value: 0.0, noise: 0.0, scale: 0.0 };
    };
    let same = wide.in_scatter_bounded();
    let e_n = (same - wide.in_scatter()).abs();
    let mut worst = (v as f64 - same).abs();
    for k in 0..PERTURBATIONS {
        if let Some(x) = area_from(scene, &perturbed(&rec, k)).map(|q| q.in_scatter_bounded()) {
            if x.is_finite() {
                worst = worst.max((x as f64 - same).abs());
            }
        }
    }
    let plain = airlight::AreaLight { emission: airlight::Emission::Lambertian, ..*wide.light() };
    let iso = airlight::AreaScene::new(*wide.ray(), plain, *wide.medium(), AnyPhase::Isotropic).map(|s| s.in_scatter_bounded()).unwrap_or(0.0);
    finite_expectation(v, same, worst + e_n, iso, wide.phase())
}

/// A surface point's scene in the record types.
pub type SurfaceRecord<T> = SurfaceScene<T, AnyDistribution<T>, AnyPhase<T>>;

/// What the shader computes for a surface point, on the CPU
/// ([`SurfaceScene::air_light_panels_counted`] with the shaders' control and
/// [`airlight::SHADER_SURFACE_PANELS`] panels, [`airlight::SHADER_PHONG_PANELS`] for a Phong lobe).
fn surface_air_light<T: airlight::Real>(scene: &SurfaceRecord<T>, terms: usize) -> T {
    let control = shader_control();
    let panels = match scene.brdf() {
        airlight::Brdf::Lambert { .. } => airlight::SHADER_SURFACE_PANELS,
        airlight::Brdf::Phong { .. } => airlight::SHADER_PHONG_PANELS,
    };
    match terms {
        8 => scene.air_light_panels_counted::<8>(control, panels).0,
        12 => scene.air_light_panels_counted::<12>(control, panels).0,
        _ => panic!("the shaders are emitted with 8 or 12 nodes per panel, not {terms}"),
    }
}

/// The surface point as a ray record (origin: the point, direction: the normal, to infinity):
/// the inputs [`perturbed`] moves.
fn as_ray_record(scene: &SurfaceRecord<f32>) -> SceneRecord<f32> {
    let s = scene.surface();
    SceneRecord { ray: Ray { origin: s.position, dir: s.normal, t_min: 0.0, t_max: f32::INFINITY }, light: *scene.light(), medium: *scene.medium(), phase: *scene.phase() }
}

/// The surface scene of a ray record (as [`as_ray_record`] makes) with `scene`'s BRDF, in `T`.
fn from_ray_record<T: airlight::Real>(rec: &SceneRecord<T>, brdf: airlight::Brdf<T>) -> Option<SurfaceRecord<T>> {
    SurfaceScene::new(Surface { position: rec.ray.origin, normal: rec.ray.dir }, brdf, rec.light, rec.medium, rec.phase).ok()
}

/// The CPU's expectation for a Lambertian or Phong surface point lit by a light without an axis
/// from the shader with `terms` nodes per panel, by the same criterion as [`expect`]: the noise
/// over the record and its one-ulp perturbations of the point, the normal, the light, `σt` and
/// the phase function, plus the error of the same method in f64 against the default `air_light`
/// (error-controlled to 1e-10); the scale is the value with isotropic scattering times
/// `4π·max P`, at least the value.
pub fn expect_surface(scene: &SurfaceRecord<f32>, terms: usize) -> Expected {
    let v = surface_air_light(scene, terms);
    let brdf = match *scene.brdf() {
        airlight::Brdf::Lambert { albedo } => airlight::Brdf::Lambert { albedo: albedo as f64 },
        airlight::Brdf::Phong { k_s, exponent, view } => airlight::Brdf::Phong { k_s: k_s as f64, exponent: exponent as f64, view: view.as_dvec3() },
    };
    let rec = as_ray_record(scene).cast::<f64>();
    let Some(wide) = from_ray_record(&rec, brdf) else {
        return Expected { value: 0.0, status: STATUS_INVALID, f64_value: 0.0, noise: 0.0, scale: 0.0 };
    };
    let same = surface_air_light(&wide, terms);
    if v.is_infinite() {
        return Expected { value: f32::MAX, status: STATUS_INFINITE, f64_value: same, noise: 0.0, scale: 0.0 };
    }
    let e_n = (same - wide.air_light()).abs();
    let mut worst = (v as f64 - same).abs();
    // t_min and t_max (0 and ∞) are not inputs of a surface point
    for k in 3..PERTURBATIONS {
        let q = perturbed(&as_ray_record(scene), k);
        if let Some(x) = from_ray_record(&q, *scene.brdf()).map(|q| surface_air_light(&q, terms)) {
            if x.is_finite() {
                worst = worst.max((x as f64 - same).abs());
            }
        }
    }
    let iso = SceneRecord { phase: AnyPhase::Isotropic, ..rec };
    let iso = from_ray_record(&iso, brdf).map(|s| surface_air_light(&s, terms)).unwrap_or(0.0);
    finite_expectation(v, same, worst + e_n, iso, &rec.phase)
}

/// Smallest and largest magnitude of an input number [`in_domain`] (module docs).
pub const DOMAIN: (f32, f32) = (1.0 / (1u64 << 40) as f32, (1u64 << 40) as f32);

/// Whether every finite input number of `rec` is zero or of magnitude within [`DOMAIN`]:
/// where [`judge`] applies (module docs). Non-finite numbers (an invalid record, or
/// `t_max = +∞`) do not leave the domain.
pub fn in_domain(rec: &SceneRecord<f32>) -> bool {
    let record = crate::layout::Record::new(&rec.ray, &rec.light, &rec.medium, &rec.phase);
    // unused inputs are packed as 0
    record.float_inputs().iter().all(|x| {
        let m = x.abs();
        !m.is_finite() || m == 0.0 || (DOMAIN.0..=DOMAIN.1).contains(&m)
    })
}

/// Judges a result outside the domain of agreement (module docs): statuses agree on
/// validity, the value is finite and non-negative, and 0 for an invalid record.
pub fn judge_defined(e: &Expected, got: f32, status: u32) -> Judgement {
    let problem = if !got.is_finite() {
        Some(format!("non-finite result {got}"))
    } else if (status == STATUS_INVALID) != (e.status == STATUS_INVALID) || status > STATUS_INFINITE {
        Some(format!("status {status}, CPU {}", e.status))
    } else if status == STATUS_INVALID && got != 0.0 {
        Some(format!("value {got} for an invalid record"))
    } else if got < 0.0 {
        Some(format!("negative value {got}"))
    } else {
        None
    };
    Judgement { diff: 0.0, diff_f64: 0.0, excess: 0.0, problem }
}

/// Judges one shader result `(got, status)` against `e`.
pub fn judge(e: &Expected, got: f32, status: u32) -> Judgement {
    let verdict = |diff: f64, diff_f64: f64, excess: f64, problem: Option<String>| Judgement { diff, diff_f64, excess, problem };
    if got.is_nan() || got.is_infinite() {
        return verdict(0.0, 0.0, 0.0, Some(format!("non-finite result {got}")));
    }
    if status != e.status {
        return verdict(0.0, 0.0, 0.0, Some(format!("status {status}, CPU {}", e.status)));
    }
    if status != STATUS_OK || e.scale == 0.0 {
        let same = got == e.value || (status == STATUS_OK && (got as f64).abs() <= DENORMAL_FLOOR);
        return verdict(0.0, 0.0, 0.0, (!same).then(|| format!("value {got} with status {status}, want {}", e.value)));
    }
    let diff = (got as f64 - e.value as f64).abs();
    let excess = ((diff - DENORMAL_FLOOR - NOISE_FACTOR * e.noise) / e.scale - ALLOWANCE).max(0.0);
    let problem = (excess > 0.0).then(|| {
        format!("gpu {got} cpu {} (differ by {:.2e} of scale {:.3e}, noise {:.2e}; excess {excess:.2e})", e.value, diff / e.scale, e.scale, e.noise / e.scale)
    });
    verdict(diff / e.scale, (got as f64 - e.f64_value).abs() / e.scale, excess, problem)
}
