// airlight — analytic single-scattered air-light of point and spot lights in a homogeneous
// medium (Pegoraro, Schott & Parker, Graphics Interface 2009), f32, error-controlled panels of
// @TERMS@ Gauss–Legendre nodes.
//
// The single shader source of truth, mirroring the CPU kernel (crate `airlight`, kernel/src)
// module by module: special/ (exponential integrals) → integrals.rs (the isotropic moment) →
// panels.rs (error-controlled panels) → combined.rs (split at the light's foot) → geometry.rs,
// with phase.rs and light.rs. Every placeholder between at-signs is filled at emission from
// the kernel's own tables and constants (codegen/shaders/src/targets.rs `source`). Every public name
// starts with `airlight_`. Every loop has a constant bound (some leave early by `break`).

// Gauss–Legendre nodes per panel, half of them, and the panel control (kernel SHADER_CONTROL).
const AIRLIGHT_TERMS: u32 = @TERMS@u;
const AIRLIGHT_HALF_TERMS: u32 = @HALF_TERMS@u;
const AIRLIGHT_PANEL_TOLERANCE: f32 = @PANEL_TOLERANCE@;
const AIRLIGHT_PANEL_FLOOR: f32 = @PANEL_FLOOR@;
const AIRLIGHT_MAX_PANELS: u32 = @MAX_PANELS@u;
// A piece's panel list: each split adds one panel for two evaluations.
const AIRLIGHT_PANEL_LIST: u32 = @PANEL_LIST@u;
// The largest exponent growth across a y-panel (panels.rs Y_PANEL_EXPONENT).
const AIRLIGHT_Y_PANEL_EXPONENT: f32 = @Y_PANEL_EXPONENT@;
// The margin of the panels' aliasing model (panels.rs ALIASING_MARGIN).
const AIRLIGHT_ALIASING_MARGIN: u32 = @ALIASING_MARGIN@u;
// 1/(3·5⋯(2N+1)) for the light-angle route's predicted coefficient, and for N − 1 and N − 2
// for its predicted estimate (angle.rs `predicted_coefficient`, `predicted_estimate`).
const AIRLIGHT_INV_ODD_FACTORIAL: f32 = @INV_ODD_FACTORIAL@;
const AIRLIGHT_INV_ODD_FACTORIAL_1: f32 = @INV_ODD_FACTORIAL_1@;
const AIRLIGHT_INV_ODD_FACTORIAL_2: f32 = @INV_ODD_FACTORIAL_2@;
// The extinction's cut: the fraction δ·τ of the scale it may drop (combined.rs
// `cut_resolution`) and the largest H·Δv it never cuts (`uncut_span`).
const AIRLIGHT_CUT_RESOLUTION: f32 = @CUT_RESOLUTION@;
const AIRLIGHT_UNCUT_SPAN: f32 = @UNCUT_SPAN@;
// The range of exact products (real.rs, f32).
const AIRLIGHT_EXACT_RANGE: f32 = @EXACT_RANGE@;
const AIRLIGHT_PI: f32 = 3.14159265358979;
const AIRLIGHT_EULER_GAMMA: f32 = 0.5772156649015329;
const AIRLIGHT_FLT_MAX: f32 = 3.40282347e38;
const AIRLIGHT_FLT_EPS: f32 = 1.1920929e-7;
const AIRLIGHT_LN_2: f32 = 0.6931472;
/// Orders of e^x E_n(x) a tail panel uses: n = 1 … N + 2.
const AIRLIGHT_EN_ORDERS: u32 = @EN_ORDERS@u;

/// Explicitly zeroed arrays (some HLSL front ends reject the zero-value cast naga would
/// otherwise write for an uninitialised `var`).
fn airlight_zero_terms() -> array<f32, AIRLIGHT_TERMS> {
    return array<f32, AIRLIGHT_TERMS>(@ZEROS_TERMS@);
}

// Phase-function and light-distribution kinds (record fields `phase_kind`, `light_kind`;
// codegen/shaders/src/layout.rs).
const AIRLIGHT_PHASE_ISOTROPIC: u32 = @PHASE_ISOTROPIC@u;
const AIRLIGHT_PHASE_RAYLEIGH: u32 = @PHASE_RAYLEIGH@u;
const AIRLIGHT_PHASE_HENYEY_GREENSTEIN: u32 = @PHASE_HENYEY_GREENSTEIN@u;
const AIRLIGHT_PHASE_SCHLICK: u32 = @PHASE_SCHLICK@u;
const AIRLIGHT_PHASE_CORNETTE_SHANKS: u32 = @PHASE_CORNETTE_SHANKS@u;
const AIRLIGHT_PHASE_TWO_LOBE_HG: u32 = @PHASE_TWO_LOBE_HG@u;
const AIRLIGHT_LIGHT_OMNI: u32 = @LIGHT_OMNI@u;
const AIRLIGHT_LIGHT_TWO_LOBED: u32 = @LIGHT_TWO_LOBED@u;
const AIRLIGHT_LIGHT_SPOT: u32 = @LIGHT_SPOT@u;
// Emitter shapes (record field `light_shape`).
const AIRLIGHT_SHAPE_POINT: u32 = @SHAPE_POINT@u;
const AIRLIGHT_SHAPE_SEGMENT: u32 = @SHAPE_SEGMENT@u;
const AIRLIGHT_SHAPE_DISC: u32 = @SHAPE_DISC@u;
const AIRLIGHT_SHAPE_RECTANGLE: u32 = @SHAPE_RECTANGLE@u;
const AIRLIGHT_SHAPE_SPHERE: u32 = @SHAPE_SPHERE@u;
const AIRLIGHT_SURFACE_NONE: u32 = @SURFACE_NONE@u;
const AIRLIGHT_SURFACE_LAMBERT: u32 = @SURFACE_LAMBERT@u;
const AIRLIGHT_SURFACE_PHONG: u32 = @SURFACE_PHONG@u;

// Result status codes (codegen/shaders/src/layout.rs).
const AIRLIGHT_STATUS_OK: u32 = @STATUS_OK@u;
const AIRLIGHT_STATUS_INVALID: u32 = @STATUS_INVALID@u;
const AIRLIGHT_STATUS_INFINITE: u32 = @STATUS_INFINITE@u;
const AIRLIGHT_STATUS_DEFERRED: u32 = @STATUS_DEFERRED@u;

// The two-lobed light's largest power and its bit length (light.rs TwoLobed::MAX_POWER).
const AIRLIGHT_MAX_POWER: u32 = @MAX_POWER@u;
const AIRLIGHT_MAX_POWER_BITS: u32 = @MAX_POWER_BITS@u;

// The exponential integrals' f32 tuning (kernel/src/real.rs): series terms inside the ellipse
// (Re z·INV_RE)² + (Im z·INV_IM)² < 1, the divided differences' terms for |a|, |b| ≤ 1, and the
// continued fraction's largest depth.
const AIRLIGHT_E1_SERIES_TERMS: u32 = @E1_SERIES_TERMS@u;
const AIRLIGHT_EIN_DD_TERMS: u32 = @EIN_DD_TERMS@u;
const AIRLIGHT_E1_INV_RE: f32 = @E1_INV_RE@;
const AIRLIGHT_E1_INV_IM: f32 = @E1_INV_IM@;
const AIRLIGHT_E1_CF_MAX_DEPTH: u32 = @E1_CF_MAX_DEPTH@u;
// Fractions this deep divide plainly (continued_fraction.rs `PLAIN_FROM`).
const AIRLIGHT_E1_CF_PLAIN_FROM: u32 = @E1_CF_PLAIN_FROM@u;

/// (−1)^{k+1}/(k·k!), k = 1 … AIRLIGHT_E1_SERIES_TERMS (series.rs `EIN_COEFFS`).
fn airlight_ein_coefficients() -> array<f32, AIRLIGHT_E1_SERIES_TERMS> {
    return array<f32, AIRLIGHT_E1_SERIES_TERMS>(@EIN_COEFFS@);
}

/// A scene: the kernel's Ray, PointLight, Medium and phase function in one struct.
struct AirlightScene {
    origin: vec3<f32>,
    t_min: f32,
    dir: vec3<f32>,
    /// Segment end; ignored when `t_max_infinite` is set.
    t_max: f32,
    /// The light's position; an area light's centre (disc, sphere) or corner (rectangle).
    light_position: vec3<f32>,
    /// The light's intensity; an area light's radiance.
    intensity: f32,
    /// Light axis (two-lobed, spot); a disc's normal, a rectangle's edge u.
    light_axis: vec3<f32>,
    /// two-lobed: power p (even); spot: cos_inner; disc, sphere: radius.
    light_param_a: f32,
    /// spot: cos_outer; area lights: the emission's power (1: Lambertian).
    light_param_b: f32,
    sigma_s: f32,
    sigma_t: f32,
    /// HG/Cornette–Shanks: g; Schlick: k; two-lobe HG: g1.
    phase_param_a: f32,
    /// two-lobe HG: g2.
    phase_param_b: f32,
    /// two-lobe HG: w.
    phase_param_c: f32,
    light_kind: u32,
    phase_kind: u32,
    /// bit 0: t_max is +∞.
    flags: u32,
    /// A surface's albedo ρ (AIRLIGHT_SURFACE_LAMBERT) or k_s (AIRLIGHT_SURFACE_PHONG).
    brdf_scale: f32,
    /// AIRLIGHT_SURFACE_NONE: the in-scattered radiance along the ray; AIRLIGHT_SURFACE_LAMBERT,
    /// AIRLIGHT_SURFACE_PHONG: the air-light reflected by a surface at `origin` with normal `dir`.
    surface_kind: u32,
    /// A Phong lobe's exponent n.
    brdf_exponent: f32,
    /// A segment light's other end (its first is `light_position`); a rectangle's edge v.
    light_end: vec3<f32>,
    /// AIRLIGHT_SHAPE_POINT, or AIRLIGHT_SHAPE_SEGMENT: every point of `light_position →
    /// light_end` emits `intensity` per unit length with the light's distribution; or an area
    /// light (AIRLIGHT_SHAPE_DISC, _RECTANGLE, _SPHERE: airlight_in_scatter_area).
    light_shape: u32,
    /// A Phong lobe's direction from the surface towards the eye (any non-zero length).
    brdf_view: vec3<f32>,
}

/// `in_scatter` (L_m) and a status: OK, INVALID (value 0) or INFINITE (value FLT_MAX).
struct AirlightResult {
    in_scatter: f32,
    status: u32,
}

// ---------------------------------------------------------------- building a scene
// (kernel/src/scene.rs Ray, PointLight, Medium; light.rs; phase.rs): named parts instead of
// AirlightScene's 17 positional fields.

/// The segment `origin + t·dir/|dir|`, `t ∈ [t_min, t_max]`: `dir` any non-zero length (it is
/// normalised inside), `t_min`, `t_max` world distances along it (so `dir = P − eye` needs
/// `t_max = length(P − eye)`, not 1). `flags` bit 0: `t_max` is +∞.
struct AirlightRay {
    origin: vec3<f32>,
    t_min: f32,
    dir: vec3<f32>,
    t_max: f32,
    flags: u32,
}

/// A point light: `intensity · D(c)`, `D` by `kind` (`AIRLIGHT_LIGHT_*`) with `axis` and the
/// parameters as in AirlightScene; or, with `shape` AIRLIGHT_SHAPE_SEGMENT, a segment light
/// `position → end` (airlight_segment_light); or an area light (airlight_disc_light,
/// airlight_rectangle_light, airlight_sphere_light).
struct AirlightLight {
    position: vec3<f32>,
    intensity: f32,
    axis: vec3<f32>,
    param_a: f32,
    param_b: f32,
    kind: u32,
    end: vec3<f32>,
    shape: u32,
}

/// Scattering and extinction coefficients, per world unit.
struct AirlightMedium {
    sigma_s: f32,
    sigma_t: f32,
}

/// A phase function: `kind` (`AIRLIGHT_PHASE_*`) and up to three parameters.
struct AirlightPhase {
    kind: u32,
    param_a: f32,
    param_b: f32,
    param_c: f32,
}

/// The segment `[t_min, t_max]` (world distances) of the ray from `origin` along `dir`.
fn airlight_ray(origin: vec3<f32>, dir: vec3<f32>, t_min: f32, t_max: f32) -> AirlightRay {
    return AirlightRay(origin, t_min, dir, t_max, 0u);
}

/// The ray from `t_min` to infinity.
fn airlight_ray_to_infinity(origin: vec3<f32>, dir: vec3<f32>, t_min: f32) -> AirlightRay {
    return AirlightRay(origin, t_min, dir, 0.0, 1u);
}

/// A light shining equally in all directions.
fn airlight_omni(position: vec3<f32>, intensity: f32) -> AirlightLight {
    return AirlightLight(position, intensity, vec3<f32>(0.0, 0.0, 1.0), 0.0, 0.0, AIRLIGHT_LIGHT_OMNI, position, AIRLIGHT_SHAPE_POINT);
}

/// The paper's two-lobed light `D = c^power` about `axis` (`power` even, at most
/// AIRLIGHT_MAX_POWER).
fn airlight_two_lobed(position: vec3<f32>, intensity: f32, axis: vec3<f32>, power: u32) -> AirlightLight {
    return AirlightLight(position, intensity, axis, f32(power), 0.0, AIRLIGHT_LIGHT_TWO_LOBED, position, AIRLIGHT_SHAPE_POINT);
}

/// A spot cone about `axis`: full intensity inside `cos_inner`, none outside `cos_outer`
/// (`cos_outer < cos_inner`), smoothstep between.
fn airlight_spot(position: vec3<f32>, intensity: f32, axis: vec3<f32>, cos_inner: f32, cos_outer: f32) -> AirlightLight {
    return AirlightLight(position, intensity, axis, cos_inner, cos_outer, AIRLIGHT_LIGHT_SPOT, position, AIRLIGHT_SHAPE_POINT);
}

/// The segment light (a fluorescent tube) from `light.position` to `end`: every point of it
/// emits `light.intensity` per unit length with `light`'s distribution.
fn airlight_segment_light(light: AirlightLight, end: vec3<f32>) -> AirlightLight {
    var segment = light;
    segment.end = end;
    segment.shape = AIRLIGHT_SHAPE_SEGMENT;
    return segment;
}

/// A disc of uniform radiance `radiance` (Lambertian: every element `max(0, n·ω)` about `normal`,
/// any non-zero length), emitting on the side of `normal`; its scene is airlight_in_scatter_area's.
fn airlight_disc_light(center: vec3<f32>, normal: vec3<f32>, radius: f32, radiance: f32) -> AirlightLight {
    return AirlightLight(center, radiance, normal, radius, 1.0, AIRLIGHT_LIGHT_OMNI, center, AIRLIGHT_SHAPE_DISC);
}

/// The parallelogram `corner + u·edge_u + v·edge_v` (u, v ∈ [0, 1]) of uniform radiance
/// `radiance`, emitting on the side of `edge_u × edge_v`; its scene is airlight_in_scatter_area's.
fn airlight_rectangle_light(corner: vec3<f32>, edge_u: vec3<f32>, edge_v: vec3<f32>, radiance: f32) -> AirlightLight {
    return AirlightLight(corner, radiance, edge_u, 0.0, 1.0, AIRLIGHT_LIGHT_OMNI, edge_v, AIRLIGHT_SHAPE_RECTANGLE);
}

/// A sphere of uniform radiance `radiance`, emitting outward; its scene is
/// airlight_in_scatter_area's.
fn airlight_sphere_light(center: vec3<f32>, radius: f32, radiance: f32) -> AirlightLight {
    return AirlightLight(center, radiance, vec3<f32>(0.0, 0.0, 1.0), radius, 1.0, AIRLIGHT_LIGHT_OMNI, center, AIRLIGHT_SHAPE_SPHERE);
}

/// An area light whose every element emits `max(0, n·ω)^power` (radiance `radiance·c^{power−1}`,
/// a focused panel), `power` from 1 (Lambertian) to AIRLIGHT_EMISSION_MAX_POWER.
fn airlight_cosine_lobe(light: AirlightLight, power: u32) -> AirlightLight {
    var lobe = light;
    lobe.param_b = f32(power);
    return lobe;
}

/// Scattering and extinction coefficients (`σs ≤ σt` physically; both ≥ 0), per world unit.
fn airlight_medium(sigma_s: f32, sigma_t: f32) -> AirlightMedium {
    return AirlightMedium(sigma_s, sigma_t);
}

/// Isotropic scattering, `1/(4π)`.
fn airlight_isotropic() -> AirlightPhase {
    return AirlightPhase(AIRLIGHT_PHASE_ISOTROPIC, 0.0, 0.0, 0.0);
}

/// Rayleigh scattering, `3(1 + μ²)/(16π)`.
fn airlight_rayleigh() -> AirlightPhase {
    return AirlightPhase(AIRLIGHT_PHASE_RAYLEIGH, 0.0, 0.0, 0.0);
}

/// Henyey–Greenstein with asymmetry `g ∈ (−1, 1)`.
fn airlight_henyey_greenstein(g: f32) -> AirlightPhase {
    return AirlightPhase(AIRLIGHT_PHASE_HENYEY_GREENSTEIN, g, 0.0, 0.0);
}

/// Schlick's approximation with `k ∈ (−1, 1)`.
fn airlight_schlick(k: f32) -> AirlightPhase {
    return AirlightPhase(AIRLIGHT_PHASE_SCHLICK, k, 0.0, 0.0);
}

/// Cornette–Shanks with asymmetry `g ∈ (−1, 1)`.
fn airlight_cornette_shanks(g: f32) -> AirlightPhase {
    return AirlightPhase(AIRLIGHT_PHASE_CORNETTE_SHANKS, g, 0.0, 0.0);
}

/// `w·HG(g1) + (1 − w)·HG(g2)`, `w ∈ [0, 1]`.
fn airlight_two_lobe_henyey_greenstein(g1: f32, g2: f32, w: f32) -> AirlightPhase {
    return AirlightPhase(AIRLIGHT_PHASE_TWO_LOBE_HG, g1, g2, w);
}

/// The scene of its parts.
fn airlight_scene(ray: AirlightRay, light: AirlightLight, medium: AirlightMedium, phase: AirlightPhase) -> AirlightScene {
    return AirlightScene(ray.origin, ray.t_min, ray.dir, ray.t_max, light.position, light.intensity, light.axis,
        light.param_a, light.param_b, medium.sigma_s, medium.sigma_t, phase.param_a, phase.param_b, phase.param_c,
        light.kind, phase.kind, ray.flags, 0.0, AIRLIGHT_SURFACE_NONE, 0.0, light.end, light.shape, vec3<f32>(0.0));
}

/// A Lambertian surface point (albedo `albedo`) at `position`, lit side towards `normal` (any
/// non-zero length), in the air-light of `light` (a point light without an axis: omni): the
/// scene whose airlight_in_scatter is the surface radiance from air-light
/// `∫_{n·ω>0} L_a(s, ω) (ρ/π) (n·ω) dω` (kernel/src/surface.rs). Lights with an axis are the
/// CPU kernel's only (the record is invalid here).
fn airlight_lambert_surface(position: vec3<f32>, normal: vec3<f32>, albedo: f32, light: AirlightLight, medium: AirlightMedium, phase: AirlightPhase) -> AirlightScene {
    var s = airlight_scene(airlight_ray_to_infinity(position, normal, 0.0), light, medium, phase);
    s.brdf_scale = albedo;
    s.surface_kind = AIRLIGHT_SURFACE_LAMBERT;
    return s;
}

/// A Phong surface point at `position`, lit side towards `normal`, seen from `view` (from the
/// point towards the eye; both any non-zero length), in the air-light of `light` (omni, as
/// airlight_lambert_surface): the scene whose airlight_in_scatter is
/// `∫_{n·ω>0} L_a(s, ω) k_s (n+2)/(2π) max(0, r·ω)ⁿ (n·ω) dω`, `r` the mirror image of `view`
/// about the normal, `k_s ≥ 0`, `n ≥ 0` (kernel/src/surface.rs).
fn airlight_phong_surface(position: vec3<f32>, normal: vec3<f32>, k_s: f32, exponent: f32, view: vec3<f32>, light: AirlightLight, medium: AirlightMedium, phase: AirlightPhase) -> AirlightScene {
    var s = airlight_scene(airlight_ray_to_infinity(position, normal, 0.0), light, medium, phase);
    s.brdf_scale = k_s;
    s.brdf_exponent = exponent;
    s.brdf_view = view;
    s.surface_kind = AIRLIGHT_SURFACE_PHONG;
    return s;
}

// ---------------------------------------------------------------- complex arithmetic
// (kernel/src/special/complex.rs)

fn airlight_cmul(a: vec2<f32>, b: vec2<f32>) -> vec2<f32> {
    return vec2<f32>(a.x * b.x - a.y * b.y, a.x * b.y + a.y * b.x);
}

/// a / b by Smith's algorithm.
fn airlight_cdiv(a: vec2<f32>, b: vec2<f32>) -> vec2<f32> {
    if (abs(b.x) >= abs(b.y)) {
        let r = b.y / b.x;
        let inv = 1.0 / (b.x + b.y * r);
        return vec2<f32>((a.x + a.y * r) * inv, (a.y - a.x * r) * inv);
    }
    let r = b.x / b.y;
    let inv = 1.0 / (b.x * r + b.y);
    return vec2<f32>((a.x * r + a.y) * inv, (a.y * r - a.x) * inv);
}

/// |z|, scaled by the larger part first: `length` may square its argument, and |z|² underflows
/// to 0 below |z| ≈ 1e-19 (num-complex's `norm` is a hypot; found by the shader fuzz target:
/// ln z = −∞ for z = 1.9e-37).
fn airlight_cabs(z: vec2<f32>) -> f32 {
    let m = max(abs(z.x), abs(z.y));
    if (m == 0.0) { return 0.0; }
    return m * length(z / m);
}

/// Principal square root (Kahan).
fn airlight_csqrt(z: vec2<f32>) -> vec2<f32> {
    if (z.x == 0.0 && z.y == 0.0) {
        return vec2<f32>(0.0, z.y);
    }
    let r = airlight_cabs(z);
    if (z.x >= 0.0) {
        let t = sqrt((r + z.x) * 0.5);
        return vec2<f32>(t, z.y / (t + t));
    }
    let t = sqrt((r - z.x) * 0.5);
    return vec2<f32>(abs(z.y) / (t + t), select(-t, t, z.y >= 0.0));
}

/// e^z for |Im z| ≤ 2.2 (the E1 series region).
fn airlight_cexp(z: vec2<f32>) -> vec2<f32> {
    let m = exp(z.x);
    let cs = airlight_cos_sin(z.y);
    return vec2<f32>(m * cs.x, m * cs.y);
}

/// ln z for Re z ≥ 0.
fn airlight_cln(z: vec2<f32>) -> vec2<f32> {
    // arg z for Re z ≥ 0 (all our arguments), from the accurate atan above
    var arg = 1.5707963267948966;
    if (z.x > 0.0) {
        arg = airlight_atan(abs(z.y) / z.x);
    }
    return vec2<f32>(log(airlight_cabs(z)), select(arg, -arg, z.y < 0.0));
}

// Vulkan allows atan 4096 ulp, sin/cos 2^-11 absolute and log 2^-21 absolute near 1 — far too
// loose where the moment recurrence amplifies the error of Q_0 — so these are computed here
// from + − × ÷ (correctly rounded or 2.5 ulp) only.

/// atan(x) for x ≥ 0 (Cephes atanf: reduction by π/2 and π/4, then a degree-9 odd
/// polynomial; ≈ 2 ulp).
fn airlight_atan(x: f32) -> f32 {
    var y = 0.0;
    var t = x;
    if (x > 2.414213562373095) {
        y = 1.5707963267948966;
        t = -1.0 / x;
    } else if (x > 0.4142135623730950) {
        y = 0.7853981633974483;
        t = (x - 1.0) / (x + 1.0);
    }
    let z = t * t;
    return y + ((((8.05374449538e-2 * z - 1.38776856032e-1) * z + 1.99777106478e-1) * z - 3.33329491539e-1) * z * t + t);
}

/// log(1 + x) for x > −1: 2 atanh(x/(2+x)) by its series where −1/2 ≤ x ≤ 1 (ratio s² ≤ 1/9,
/// 9 terms, Horner's scheme written out: no loop iterations, §10 of docs/DESIGN.md), the
/// built-in log elsewhere (where 1 + x is 1/2 or more from 1 and log is 3 ulp).
fn airlight_log1p(x: f32) -> f32 {
    if (x > 1.0 || x < -0.5) {
        return log(1.0 + x);
    }
    let s = x / (2.0 + x);
    let z = s * s;
    let sum = (((((((z / 17.0 + 1.0 / 15.0) * z + 1.0 / 13.0) * z + 1.0 / 11.0) * z + 1.0 / 9.0) * z + 1.0 / 7.0) * z + 1.0 / 5.0) * z
        + 1.0 / 3.0) * z + 1.0;
    return 2.0 * s * sum;
}

/// (cos x, sin x) for |x| ≤ 2.2 by Taylor polynomials (degree 16/17, error < 2^-24 there),
/// Horner's scheme in straight-line code: no loop (lavapipe's loops share one iteration budget,
/// §10 of docs/DESIGN.md).
fn airlight_cos_sin(x: f32) -> vec2<f32> {
    let z = x * x;
    let c = 1.0 + z * (-0.5 + z * (0.041666666666666664 + z * (-0.001388888888888889 + z * (2.48015873015873e-05 + z * (-2.755731922398589e-07 + z * (2.08767569878681e-09 + z * (-1.1470745597729725e-11 + z * (4.779477332387385e-14))))))));
    let s = 1.0 + z * (-0.16666666666666666 + z * (0.008333333333333333 + z * (-0.0001984126984126984 + z * (2.7557319223985893e-06 + z * (-2.505210838544172e-08 + z * (1.6059043836821613e-10 + z * (-7.647163731819816e-13 + z * (2.8114572543455206e-15))))))));
    return vec2<f32>(c, s * x);
}

fn airlight_is_finite(x: f32) -> bool {
    return (bitcast<u32>(x) & 0x7f800000u) != 0x7f800000u;
}

// ---------------------------------------------------------------- exponential integrals
// (kernel/src/special/: series.rs, continued_fraction.rs, e1.rs, en.rs)

/// Ein(z) = Σ_{k≥1} (−1)^{k+1} z^k/(k·k!), AIRLIGHT_E1_SERIES_TERMS terms (A&S 5.1.11), by Horner.
/// The ellipse's count everywhere, where the kernel takes fewer for small |z| (real.rs
/// `E1_SERIES_BANDS`; the same value within the 8-unit-roundoff truncation both counts allow): a
/// loop with constant bounds, and lanes running in step would wait for the longest anyway.
fn airlight_ein(z: vec2<f32>) -> vec2<f32> {
    let c = airlight_ein_coefficients();
    var sum = vec2<f32>(0.0, 0.0);
    for (var k = 0u; k < AIRLIGHT_E1_SERIES_TERMS; k++) {
        sum = airlight_cmul(sum, z) + vec2<f32>(c[AIRLIGHT_E1_SERIES_TERMS - 1u - k], 0.0);
    }
    return airlight_cmul(sum, z);
}

/// (Ein(b) − Ein(a))/(b − a) by divided differences, |a|, |b| ≤ 1: the kernel's count for its
/// widest band (series.rs `ein_divided_difference`, real.rs `E1_DD_BANDS`), a constant bound.
fn airlight_ein_divided_difference(a: vec2<f32>, b: vec2<f32>) -> vec2<f32> {
    let c = airlight_ein_coefficients();
    var h = vec2<f32>(1.0, 0.0);
    var a_pow = vec2<f32>(1.0, 0.0);
    var sum = vec2<f32>(0.0, 0.0);
    for (var k = 0u; k < AIRLIGHT_EIN_DD_TERMS; k++) {
        sum += h * c[k];
        a_pow = airlight_cmul(a_pow, a);
        h = airlight_cmul(h, b) + a_pow;
    }
    return sum;
}

/// Power series inside the ellipse (e1.rs `in_series_region`).
fn airlight_in_series_region(z: vec2<f32>) -> bool {
    let x = z.x * AIRLIGHT_E1_INV_RE;
    let y = z.y * AIRLIGHT_E1_INV_IM;
    return x * x + y * y < 1.0;
}

/// The complex fraction's depth at |z|² = r2 (real.rs `E1_CF_DEPTH`).
fn airlight_cf_depth_squared(r2: f32) -> u32 {
@E1_CF_DEPTH_SQUARED@
}

/// The real e^x E_n(x) fraction's depth at x = r (real.rs `EN_CF_DEPTH`).
fn airlight_en_cf_depth(r: f32) -> u32 {
@EN_CF_DEPTH@
}

/// e^z E1(z) by the continued fraction (A&S 5.1.22) with the tail estimate; depth by |z|.
fn airlight_e1_scaled_cf(z: vec2<f32>) -> vec2<f32> {
    let ax = abs(z.x);
    let ay = abs(z.y);
    var r2 = 3.0e38;
    if (max(ax, ay) < 1.0e18) {
        r2 = ax * ax + ay * ay;
    }
    let depth = airlight_cf_depth_squared(r2);
    let nf = f32(depth);
    let b = z + vec2<f32>(2.0 * nf + 1.0, 0.0);
    let q = airlight_cdiv(vec2<f32>(2.0 * (nf + 1.0), 0.0), b);
    var root = airlight_csqrt(vec2<f32>(1.0, 0.0) - airlight_cmul(q, q));
    if (root.x < 0.0) {
        root = -root;
    }
    var t = airlight_cmul(b, vec2<f32>(1.0, 0.0) + root) * 0.5;
    for (var i = 0u; i < AIRLIGHT_E1_CF_MAX_DEPTH; i++) {
        if (i >= depth) { break; }
        let kf = f32(depth - i);
        // deep fractions (small |z|, |t| ≤ |z| + 2·depth + 1): k² t̄/|t|², one division
        var ratio = vec2<f32>(0.0, 0.0);
        if (depth >= AIRLIGHT_E1_CF_PLAIN_FROM) {
            ratio = vec2<f32>(t.x, -t.y) * (kf * kf / (t.x * t.x + t.y * t.y));
        } else {
            ratio = airlight_cdiv(vec2<f32>(kf * kf, 0.0), t);
        }
        t = z + vec2<f32>(2.0 * kf - 1.0, 0.0) - ratio;
    }
    return airlight_cdiv(vec2<f32>(1.0, 0.0), t);
}

/// E1(z) = Ein(z) − ln z − γ, inside the series region (special/e1.rs `e1_by_series`).
fn airlight_e1_series(z: vec2<f32>) -> vec2<f32> {
    return airlight_ein(z) - airlight_cln(z) - vec2<f32>(AIRLIGHT_EULER_GAMMA, 0.0);
}

/// e^z E1(z) for Re z ≥ 0.
fn airlight_e1_scaled(z: vec2<f32>) -> vec2<f32> {
    if (airlight_in_series_region(z)) {
        return airlight_cmul(airlight_e1_series(z), airlight_cexp(z));
    }
    return airlight_e1_scaled_cf(z);
}

/// e^x E_n(x) by its continued fraction, x outside the series region, bottom-up (the kernel
/// takes its deep fractions top-down in f64, one division instead of a chain of them: a CPU's
/// latency, not a GPU's; the same fraction and tail).
fn airlight_en_scaled_cf(x: f32, n: u32) -> f32 {
    let depth = airlight_en_cf_depth(x);
    let nf = f32(n);
    let m = f32(depth);
    let b = x + nf + 2.0 * (m + 1.0);
    let a = (m + 2.0) * (nf + m + 1.0);
    let disc = 1.0 - 4.0 * a / (b * b);
    var t = b;
    if (disc > 0.0) {
        t = b * (1.0 + sqrt(disc)) * 0.5;
    }
    for (var i = 0u; i < AIRLIGHT_E1_CF_MAX_DEPTH; i++) {
        if (i >= depth) { break; }
        let kf = f32(depth - i);
        t = x + nf + 2.0 * kf - (kf + 1.0) * (nf + kf) / t;
    }
    return 1.0 / (x + nf - nf / t);
}

/// out[n − 1] = e^x E_n(x), n = 1 … AIRLIGHT_EN_ORDERS, x ≥ 0 (special/en.rs `en_scaled`):
/// recurrences away from the pivot order n* ≈ x (Miller's rule), written out (unrolled.rs),
/// one order a step (the kernel's two interleaved chains only shorten a CPU's latency).
fn airlight_en_scaled(x: f32) -> array<f32, AIRLIGHT_EN_ORDERS> {
    var out = array<f32, AIRLIGHT_EN_ORDERS>(@ZEROS_EN@);
    if (x == 0.0) {
        // E_1(0) = +∞ (never used at x = 0), E_n(0) = 1/(n − 1)
        @EN_AT_ZERO@
        return out;
    }
    var pivot = 1u;
    var start = 0.0;
    if (airlight_in_series_region(vec2<f32>(x, 0.0))) {
        start = airlight_e1_scaled(vec2<f32>(x, 0.0)).x;
    } else {
        pivot = u32(clamp(ceil(x), 1.0, f32(AIRLIGHT_EN_ORDERS)));
        start = airlight_en_scaled_cf(x, pivot);
    }
    let inv_x = 1.0 / x;
@EN_RECURRENCES@    return out;
}

// ---------------------------------------------------------------- phase functions, lights
// (kernel/src/phase.rs, kernel/src/light.rs)

/// 1 + g² − 2gμ from 1 − μ and 1 + μ as two non-negative terms (phase.rs::hg_kernel): no
/// cancellation at a peak.
fn airlight_hg_base(g: f32, om: f32, op: f32) -> f32 {
    if (g >= 0.0) {
        let a = 1.0 - g;
        return om * (g + g) + a * a;
    }
    let b = 1.0 + g;
    return op * -(g + g) + b * b;
}

fn airlight_hg(g: f32, om: f32, op: f32) -> f32 {
    let base = airlight_hg_base(g, om, op);
    return (1.0 - g) * (1.0 + g) / (4.0 * AIRLIGHT_PI) / (base * sqrt(base));
}

/// P(μ), normalised over the sphere, μ = 1 forward, given with om = 1 − μ and op = 1 + μ
/// exact (phase.rs `eval_sides`).
fn airlight_phase(kind: u32, p0: f32, p1: f32, p2: f32, mu: f32, om: f32, op: f32) -> f32 {
    switch kind {
        case AIRLIGHT_PHASE_RAYLEIGH: { return 3.0 / (16.0 * AIRLIGHT_PI) * (1.0 + mu * mu); }
        case AIRLIGHT_PHASE_HENYEY_GREENSTEIN: { return airlight_hg(p0, om, op); }
        case AIRLIGHT_PHASE_SCHLICK: {
            // 1 − kμ = (1 − k) + k(1 − μ) for k ≥ 0, (1 + k) − k(1 + μ) for k < 0
            var d = (1.0 + p0) - p0 * op;
            if (p0 >= 0.0) { d = (1.0 - p0) + p0 * om; }
            return (1.0 - p0) * (1.0 + p0) / (4.0 * AIRLIGHT_PI) / (d * d);
        }
        case AIRLIGHT_PHASE_CORNETTE_SHANKS: {
            let base = airlight_hg_base(p0, om, op);
            return 3.0 / 8.0 / AIRLIGHT_PI * (1.0 - p0) * (1.0 + p0) / (2.0 + p0 * p0) * ((1.0 + mu * mu) / (base * sqrt(base)));
        }
        case AIRLIGHT_PHASE_TWO_LOBE_HG: { return p2 * airlight_hg(p0, om, op) + (1.0 - p2) * airlight_hg(p1, om, op); }
        default: { return 1.0 / (4.0 * AIRLIGHT_PI); }
    }
}

/// P(μ) with 1 ∓ μ formed from μ (the limits at h = 0, where μ = ±1 exactly).
fn airlight_phase_mu(kind: u32, p0: f32, p1: f32, p2: f32, mu: f32) -> f32 {
    return airlight_phase(kind, p0, p1, p2, mu, 1.0 - mu, 1.0 + mu);
}

/// D(c): omni 1, two-lobed c^p, spot smoothstep between cos_outer and cos_inner.
fn airlight_light(kind: u32, p0: f32, p1: f32, c: f32) -> f32 {
    switch kind {
        case AIRLIGHT_LIGHT_TWO_LOBED: {
            // c^p by repeated squaring, p ≤ AIRLIGHT_MAX_POWER (light.rs TwoLobed::MAX_POWER)
            var base = c;
            var e = u32(p0);
            var acc = 1.0;
            for (var i = 0u; i < AIRLIGHT_MAX_POWER_BITS; i++) {
                if (e == 0u) { break; }
                if ((e & 1u) == 1u) { acc *= base; }
                e = e >> 1u;
                base *= base;
            }
            return acc;
        }
        case AIRLIGHT_LIGHT_SPOT: {
            // an edge narrower than f32's epsilon is a step at its middle (light.rs)
            let width = p0 - p1;
            if (width <= AIRLIGHT_FLT_EPS) {
                return select(0.0, 1.0, c >= p1 + width * 0.5);
            }
            let x = clamp((c - p1) / width, 0.0, 1.0);
            return x * x * (3.0 - 2.0 * x);
        }
        default: { return 1.0; }
    }
}

// ---------------------------------------------------------------- the canonical problem
// (kernel/src/geometry.rs, kernel/src/combined.rs)

struct AirlightCanonical {
    h: f32,
    x_h: f32,
    d_el: f32,
    d_c: f32,
    t_lo: f32,
    t_hi: f32,
    t_hi_infinite: bool,
}

struct AirlightHalf {
    second: bool,
    big_h: f32,
    y_lo: f32,
    y_hi: f32,
    dy: f32,
    dv: f32,
    dv_infinite: bool,
}

/// The height t of y = ±it where μ(y) = −σ(1 − y²)/(1 + y²) reaches the phase's singular cosine
/// `side`·(1 + gap) (combined.rs `singularities`; gap AIRLIGHT_FLT_MAX: none, height 1).
fn airlight_singular_height(side: f32, gap: f32, sigma: f32) -> f32 {
    if (!(gap > 0.0)) { return 0.0; }
    if ((side > 0.0) == (sigma < 0.0)) { return sqrt(gap / (2.0 + gap)); }
    return sqrt((2.0 + gap) / gap);
}

/// Henyey–Greenstein's singular cosine ±(1 + (1 − |g|)²/(2|g|)) as its gap (phase.rs
/// `hg_singular_cosine`).
fn airlight_hg_gap(g: f32) -> f32 {
    let a = abs(g);
    if (!(a > 0.0)) { return AIRLIGHT_FLT_MAX; }
    return (1.0 - a) * (1.0 - a) / (a + a);
}

/// Heights t of the integrand's singularities at y = ±it on the half with this σ (combined.rs
/// `singularities`, phase.rs `singularities`): the poles of c and μ at ±i, and the phase
/// function's (every light kind is a polynomial in c between its kinks).
fn airlight_singular_heights(s: AirlightScene, sigma: f32) -> vec3<f32> {
    let p0 = s.phase_param_a;
    var h = vec3<f32>(1.0);
    switch s.phase_kind {
        case AIRLIGHT_PHASE_HENYEY_GREENSTEIN, AIRLIGHT_PHASE_CORNETTE_SHANKS: {
            h.y = airlight_singular_height(p0, airlight_hg_gap(p0), sigma);
        }
        case AIRLIGHT_PHASE_SCHLICK: {
            // 1 − kμ = 0 at μ = 1/k = ±(1 + (1 − |k|)/|k|)
            let a = abs(p0);
            h.y = airlight_singular_height(p0, select(AIRLIGHT_FLT_MAX, (1.0 - a) / a, a > 0.0), sigma);
        }
        case AIRLIGHT_PHASE_TWO_LOBE_HG: {
            h.y = airlight_singular_height(p0, airlight_hg_gap(p0), sigma);
            h.z = airlight_singular_height(s.phase_param_b, airlight_hg_gap(s.phase_param_b), sigma);
        }
        default: {}
    }
    return h;
}

/// Each singularity's bound on the coefficients' step ratio beyond c_{N−1}, per unit of 1/ρ:
/// (N/(N − 1))^{max(α − 1, 0)} for its order α (panels.rs `Singular`) — at y = ±i
/// α − 1 = deg D + max(growth of P, 0), at the phase's own its order (combined.rs
/// `singularities`; the orders and growths, and the spot's degree, from the kernel).
fn airlight_singular_steps(s: AirlightScene) -> vec3<f32> {
    var degree = 0.0;
    if (s.light_kind == AIRLIGHT_LIGHT_TWO_LOBED) { degree = s.light_param_a; }
    if (s.light_kind == AIRLIGHT_LIGHT_SPOT) { degree = @SPOT_DEGREE@; }
    var order = 0.0;
    var growth = 0.0;
    switch s.phase_kind {
@SINGULAR_PHASES@
    }
    let ratio = f32(AIRLIGHT_TERMS) / f32(AIRLIGHT_TERMS - 1u);
    let phase = pow(ratio, max(order - 1.0, 0.0));
    return vec3<f32>(pow(ratio, degree + growth), phase, phase);
}

/// F(y) = D(c(y))·P(μ(y)) on a half: μ = −σ(1−y²)/(1+y²), c = (σ d_el(1−y²) + 2 d_c y)/(1+y²);
/// 1 − μ and 1 + μ are 2y²/(1+y²) and 2/(1+y²) in the order σ decides (combined.rs).
fn airlight_integrand(s: AirlightScene, g: AirlightCanonical, sigma: f32, y: f32) -> f32 {
    return airlight_integrand_over(s, g, sigma, y).x;
}

/// (F(y), 1/(1 + y²)) (combined.rs `with_over`).
fn airlight_integrand_over(s: AirlightScene, g: AirlightCanonical, sigma: f32, y: f32) -> vec2<f32> {
    let y2 = y * y;
    let inv = 1.0 / (1.0 + y2);
    let om = 1.0 - y2;
    let mu = -sigma * (om * inv);
    let c = (sigma * g.d_el * om + 2.0 * g.d_c * y) * inv;
    let far = y2 * inv * 2.0;
    let near = inv * 2.0;
    var minus = near;
    var plus = far;
    if (sigma < 0.0) {
        minus = far;
        plus = near;
    }
    let f = airlight_light(s.light_kind, s.light_param_a, s.light_param_b, c)
        * airlight_phase(s.phase_kind, s.phase_param_a, s.phase_param_b, s.phase_param_c, mu, minus, plus);
    return vec2<f32>(f, inv);
}

// ---------------------------------------------------------------- the isotropic moment
// (kernel/src/integrals.rs, count = 1)

/// m_0 on a short sub-interval (route 1): Gauss–Legendre with real.rs `GAUSS_NODES`.
fn airlight_moment_gauss(half: AirlightHalf) -> f32 {
    var m = 0.0;
    let hw = half.dy * 0.5;
    let yc = half.y_lo + hw;
    let nodes = array<vec2<f32>, @SHORT_NODES@>(@SHORT_RULE@);
    for (var j = 0u; j < @SHORT_NODES@u; j++) {
        let xi = nodes[j].x;
        let y = yc + hw * xi;
        var dv = hw * (1.0 + xi);
        if (half.second) { dv = hw * (1.0 - xi) / (y * half.y_hi); }
        m += nodes[j].y * hw * exp(-half.big_h * dv) / (1.0 + y * y);
    }
    return m;
}

/// Route 1 applies (integrals.rs `is_short`).
fn airlight_is_short(half: AirlightHalf) -> bool {
    let short_exp = !half.dv_infinite && half.big_h * half.dv <= 1.0;
    let short_len = half.dy <= 0.25 && (!half.second || half.dy <= half.y_lo * 0.5);
    return short_exp && short_len;
}

/// Route 2 applies, for the half's largest v_e (integrals.rs `is_near`).
fn airlight_is_near(big_h: f32, v_e: f32, v_e_infinite: bool) -> bool {
    return big_h == 0.0 || (!v_e_infinite && big_h * airlight_hypot_one(v_e) <= 1.0);
}

/// Im Q_0 = m_0 (integrals.rs `q0`, without its real part): routes near and far.
fn airlight_q_zero(half: AirlightHalf) -> f32 {
    let big_h = half.big_h;
    let v_s = select(half.y_lo, 1.0 / half.y_hi, half.second);
    let v_e_infinite = half.dv_infinite;
    var v_e = half.y_hi;
    if (half.second && !v_e_infinite) { v_e = 1.0 / half.y_lo; }
    if (airlight_is_near(big_h, v_e, v_e_infinite)) {
        var d_im = 0.0;
        var d_re = 0.0;
        if (!v_e_infinite) {
            d_im = airlight_atan(half.dv / (1.0 + v_s * v_e));
            let x = half.dv * (v_s + v_e) / (1.0 + v_s * v_s);
            if (airlight_is_finite(x)) {
                d_re = 0.5 * airlight_log1p(x);
            } else {
                // the product overflows, its logarithm does not (integrals.rs `q0_near`)
                d_re = 0.5 * (log(half.dv) + log(v_s + v_e) - airlight_log1p(v_s * v_s));
            }
        } else {
            d_im = airlight_atan(1.0 / v_s);
        }
        if (big_h == 0.0) { return d_im; }
        let z_s = vec2<f32>(big_h * v_s, -big_h);
        let z_e = vec2<f32>(big_h * v_e, -big_h);
        let ein_dd = airlight_ein_divided_difference(z_s, z_e);
        let cs = airlight_cos_sin(big_h);
        let rot = vec2<f32>(cs.x, -cs.y);
        return airlight_cmul(rot, vec2<f32>(d_re, d_im) - ein_dd * (big_h * half.dv)).y * exp(big_h * v_s);
    }
    let s_s = airlight_e1_scaled(vec2<f32>(big_h * v_s, -big_h));
    // the far end contributes e^{−HΔv}·S(z_e): 0 where H·v_e overflows, left out where its
    // weight is at most ε/4 (integrals.rs `FAR_END_NEGLIGIBLE`)
    if (!v_e_infinite && airlight_is_finite(big_h * v_e)) {
        let decay = exp(-big_h * half.dv);
        if (decay > @FAR_END_NEGLIGIBLE@) {
            let s_e = airlight_e1_scaled(vec2<f32>(big_h * v_e, -big_h));
            return s_s.y - s_e.y * decay;
        }
    }
    return s_s.y;
}

/// The moment m_0 of a half (integrals.rs `moments` with count 1).
fn airlight_moment_zero(half: AirlightHalf) -> f32 {
    if (!(half.dy > 0.0)) { return 0.0; }
    if (airlight_is_short(half)) { return airlight_moment_gauss(half); }
    return airlight_q_zero(half);
}

/// (m, x') with e^{−x'} m = e^{−x} m_0 (integrals.rs `moment_zero`): on route 3 of a first half
/// whose near end is in E1's series region, m = e^{−Hv_s} m_0 and x' = x − Hv_s, since
/// e^{−Hv_s} S(z_s) = e^{−iH} E1(z_s); the far end as e^{−Hv_e} Im S(z_e), left out where
/// HΔv ≥ ln(1/δ), δ = ε/4 (`FAR_END_NEGLIGIBLE`). Elsewhere (m_0, x).
fn airlight_moment_zero_weighted(half: AirlightHalf, x: f32) -> vec2<f32> {
    let big_h = half.big_h;
    let v_s = half.y_lo;
    let z_s = vec2<f32>(big_h * v_s, -big_h);
    let far_route = !half.second && half.dy > 0.0 && !airlight_is_short(half) && !airlight_is_near(big_h, half.y_hi, half.dv_infinite);
    if (!far_route || !airlight_in_series_region(z_s)) {
        return vec2<f32>(airlight_moment_zero(half), x);
    }
    let cs = airlight_cos_sin(big_h);
    let near_end = airlight_cmul(airlight_e1_series(z_s), vec2<f32>(cs.x, -cs.y)).y;
    var far_end = 0.0;
    let v_e = half.y_hi;
    if (!half.dv_infinite && airlight_is_finite(big_h * v_e) && big_h * half.dv < @FAR_END_EXPONENT@) {
        far_end = exp(-big_h * v_e) * airlight_e1_scaled(vec2<f32>(big_h * v_e, -big_h)).y;
    }
    return vec2<f32>(near_end - far_end, x - big_h * v_s);
}

// ---------------------------------------------------------------- panels
// (kernel/src/panels.rs, kernel/src/expansion/gauss_table.rs)

/// (x_j, w_j), x_j > 0, of the AIRLIGHT_TERMS-point Gauss–Legendre rule (gauss_table.rs).
fn airlight_gauss_rule() -> array<vec2<f32>, AIRLIGHT_HALF_TERMS> {
    return array<vec2<f32>, AIRLIGHT_HALF_TERMS>(@GAUSS_RULE@);
}

/// Node i in the order of the samples: −x_0, x_0, −x_1, x_1, …
fn airlight_node(rule: array<vec2<f32>, AIRLIGHT_HALF_TERMS>, i: u32) -> f32 {
    let x = rule[i / 2u].x;
    return select(x, -x, i % 2u == 0u);
}

/// Legendre coefficients of the samples at the nodes (panels.rs `legendre`).
fn airlight_legendre(g: array<f32, AIRLIGHT_TERMS>) -> array<f32, AIRLIGHT_TERMS> {
@LEGENDRE_BODY@
}

/// e^x − 1 without cancellation near 0 (Taylor below |x| = 1/2, 12 terms: < 2^-35; Horner's
/// scheme written out: no loop iterations).
fn airlight_expm1(x: f32) -> f32 {
    if (abs(x) >= 0.5) { return exp(x) - 1.0; }
    var sum = 1.0 + x / 12.0;
    sum = 1.0 + x * sum / 11.0;
    sum = 1.0 + x * sum / 10.0;
    sum = 1.0 + x * sum / 9.0;
    sum = 1.0 + x * sum / 8.0;
    sum = 1.0 + x * sum / 7.0;
    sum = 1.0 + x * sum / 6.0;
    sum = 1.0 + x * sum / 5.0;
    sum = 1.0 + x * sum / 4.0;
    sum = 1.0 + x * sum / 3.0;
    sum = 1.0 + x * sum / 2.0;
    return x * sum;
}

/// M_k(λ) = ∫ e^{−λ(1+ξ)} P_k(ξ) dξ = 2(−1)^k e^{−λ} i_k(λ), k < AIRLIGHT_TERMS (panels.rs
/// `exp_legendre_moments`: Miller's recurrence below λ = 2N, upward above it).
fn airlight_exp_legendre_moments(lambda: f32) -> array<f32, AIRLIGHT_TERMS> {
    var out = airlight_zero_terms();
    if (!(lambda > 0.0)) {
        out[0] = 2.0;
        return out;
    }
    if (!airlight_is_finite(lambda)) { return out; }
    let n = AIRLIGHT_TERMS;
    let i0 = -airlight_expm1(-(lambda + lambda)) / (lambda + lambda);
    if (lambda < AIRLIGHT_FLT_EPS) {
        out[0] = i0;
        out[1] = lambda * (1.0 / 3.0);
    } else if (lambda < f32(2u * n)) {
        let inv = 1.0 / lambda;
        let k0 = max(n, u32(lambda) + 1u);
        // the fewest steps s with (λ/(2k0))^{2s} ≤ ε (at most 28), by products
        let x = lambda / f32(2u * k0);
        let per_step = x * x;
        var share = per_step;
        var steps = 1u;
        for (; steps < 28u; steps++) {
            if (!(share > AIRLIGHT_FLT_EPS)) { break; }
            share *= per_step;
        }
        let top = k0 + steps + 2u;
        var above = 0.0;
        var cur = 1.0e-20;
        var below = 0.0;
        var odd = f32(2u * top + 1u);
        // orders top … N: nothing stored (top − N < N + 30 steps)
        for (var i = 0u; i < 2u * AIRLIGHT_TERMS + 30u; i++) {
            if (i + n > top) { break; }
            below = above + odd * inv * cur;
            odd -= 2.0;
            above = cur;
            cur = below;
            if (cur > 1.0e20) {
                cur *= 1.0e-20;
                above *= 1.0e-20;
            }
        }
        // orders N − 1 … 1, stored (unrolled.rs)
@MILLER_STORED@        out[0] = cur;
        let norm = i0 / cur;
        @EACH_TERM@ out[{k}] *= norm;
    } else {
        let e2 = exp(-(lambda + lambda));
        out[0] = i0;
        out[1] = ((1.0 + e2) * 0.5 - i0) / lambda;
@MOMENTS_UPWARD@    }
    @MOMENTS_SIGNS@
    return out;
}

/// |c_{N−1}| + |c_{N−2}|.
fn airlight_tail_estimate(c: array<f32, AIRLIGHT_TERMS>) -> f32 {
    return abs(c[AIRLIGHT_TERMS - 1u]) + abs(c[AIRLIGHT_TERMS - 2u]);
}

/// The error per unit of the tail and of M_0 (panels.rs `error_factor`): with q at least the
/// singularities' rate `floor`, aliasing Σ_j q^{N+1−j−margin}|M_j| by Horner plus truncation;
/// where that rate reaches 1, the cautious q^{N/4} (q^{N/6} near a peak at the panel's end).
fn airlight_error_factor(c: array<f32, AIRLIGHT_TERMS>, m: array<f32, AIRLIGHT_TERMS>, floor: f32) -> f32 {
    if (!(m[0] > 0.0)) { return 1.0; }
    let last = abs(c[AIRLIGHT_TERMS - 1u]) + abs(c[AIRLIGHT_TERMS - 2u]);
    let before = abs(c[AIRLIGHT_TERMS - 3u]) + abs(c[AIRLIGHT_TERMS - 4u]);
    if (!(before > 0.0) || !(last < before)) { return 1.0; }
    let measured = sqrt(last / before);
    let q = max(measured, select(0.0, floor, floor > 0.0));
    let truncation = max(abs(m[AIRLIGHT_TERMS - 1u]), abs(m[AIRLIGHT_TERMS - 2u]));
    if (q < 1.0) {
        var aliasing = 0.0;
        @EACH_TERM@ aliasing = select(aliasing + abs(m[{k}]), aliasing * q + abs(m[{k}]), {k}u + AIRLIGHT_ALIASING_MARGIN < AIRLIGHT_TERMS + 2u);
        return min((aliasing + q * truncation) / m[0], 1.0);
    }
    var c_max = 0.0;
    @EACH_TERM@ c_max = max(c_max, abs(c[{k}]));
    let power = select(AIRLIGHT_TERMS / 4u, AIRLIGHT_TERMS / 6u, c_max > 1.2 * abs(c[0]));
    var aliasing = 1.0;
    for (var i = 0u; i < power; i++) { aliasing *= measured; }
    return min(aliasing + measured * truncation / m[0], 1.0);
}

/// ρ of the Bernstein ellipse of [−1, 1] through re + i·im (panels.rs `bernstein_rho`).
fn airlight_bernstein_rho(re: f32, im: f32) -> f32 {
    let im2 = im * im;
    let a = (sqrt((re - 1.0) * (re - 1.0) + im2) + sqrt((re + 1.0) * (re + 1.0) + im2)) * 0.5;
    return a + sqrt(max(a * a - 1.0, 0.0));
}

/// The transform's rounding: 4Nε·mass·mean.
fn airlight_transform_noise(mass: f32, mean_abs: f32) -> f32 {
    return f32(4u * AIRLIGHT_TERMS) * AIRLIGHT_FLT_EPS * mass * mean_abs;
}

/// e^{−H(v_s(panel) − v_s(half))} for the panel [a, b] in y.
fn airlight_factor(half: AirlightHalf, a: f32, b: f32) -> f32 {
    var offset = a - half.y_lo;
    if (half.second) { offset = (half.y_hi - b) / (b * half.y_hi); }
    let x = half.big_h * offset;
    return select(1.0, exp(-x), x > 0.0);
}

/// value, error (0 at the noise floor), mass_over, f_max of one panel (panels.rs `Panel`).
struct AirlightPanel {
    value: f32,
    error: f32,
    mass_over: f32,
    f_max: f32,
}

fn airlight_panel_result(value: f32, error: f32, noise: f32, mass_over: f32, f_max: f32) -> AirlightPanel {
    return AirlightPanel(value, select(error, 0.0, error <= noise), mass_over, f_max);
}

/// A v-panel (panels.rs `v_panel`).
fn airlight_v_panel(s: AirlightScene, g: AirlightCanonical, sigma: f32, half: AirlightHalf, a: f32, b: f32, heights: vec3<f32>, steps: vec3<f32>) -> AirlightPanel {
    let rule = airlight_gauss_rule();
    var r = (b - a) * 0.5;
    var vc = a + r;
    if (half.second) {
        r = (b - a) / (a * b) * 0.5;
        vc = 1.0 / b + r;
    }
    var samples = airlight_zero_terms();
    var f_max = 0.0;
    var over_max = 0.0;
    var g_avg = 0.0;
    for (var i = 0u; i < AIRLIGHT_TERMS; i++) {
        let v = vc + r * airlight_node(rule, i);
        // v = y before the foot, 1/y after it: F(1/v) is the integrand with σ negated, at v
        // (combined.rs `eval_over_reciprocal`)
        let fo = airlight_integrand_over(s, g, select(sigma, -sigma, half.second), v);
        let fy = fo.x;
        let over = fo.y;
        samples[i] = fy * over;
        f_max = max(f_max, abs(fy));
        over_max = max(over_max, over);
        g_avg += rule[i / 2u].y * 0.5 * abs(samples[i]);
    }
    let c = airlight_legendre(samples);
    let m = airlight_exp_legendre_moments(half.big_h * r);
    var sum = 0.0;
    @EACH_TERM@ sum += c[{k}] * m[{k}];
    let w = airlight_factor(half, a, b) * r;
    let mass = w * m[0];
    let floor = airlight_singular_floor(heights, steps, vc, r, false);
    let error = mass * airlight_tail_estimate(c) * airlight_error_factor(c, m, floor);
    return airlight_panel_result(w * sum, error, airlight_transform_noise(mass, g_avg), mass * over_max, f_max);
}

/// A y-panel (panels.rs `y_panel`): the whole integrand by the rule in y.
fn airlight_y_panel(s: AirlightScene, g: AirlightCanonical, sigma: f32, half: AirlightHalf, a: f32, b: f32, heights: vec3<f32>, steps: vec3<f32>) -> AirlightPanel {
    let rule = airlight_gauss_rule();
    let r = (b - a) * 0.5;
    let yc = a + r;
    var samples = airlight_zero_terms();
    var f_max = 0.0;
    var over_max = 0.0;
    var mass = 0.0;
    var p_avg = 0.0;
    for (var i = 0u; i < AIRLIGHT_TERMS; i++) {
        let xi = airlight_node(rule, i);
        let y = yc + r * xi;
        let weight = exp(-half.big_h * (r * (1.0 - xi)) / (y * b));
        let fy = airlight_integrand(s, g, sigma, y);
        let over = 1.0 / (1.0 + y * y);
        samples[i] = fy * over * weight;
        f_max = max(f_max, abs(fy));
        over_max = max(over_max, over);
        mass += rule[i / 2u].y * weight;
        p_avg += rule[i / 2u].y * 0.5 * abs(samples[i]);
    }
    let c = airlight_legendre(samples);
    let w = airlight_factor(half, a, b) * r;
    var m = airlight_zero_terms();
    m[0] = 2.0;
    // the exponential's essential singularity at y = 0 as well
    let floor = airlight_singular_floor(heights, steps, yc, r, true);
    let error = w * 2.0 * airlight_tail_estimate(c) * airlight_error_factor(c, m, floor);
    return airlight_panel_result(w * 2.0 * c[0], error, airlight_transform_noise(w * 2.0, p_avg), w * mass * over_max, f_max);
}

/// Monomial coefficients in ξ of Σ c_k P_k(ξ) (panels.rs `legendre_to_monomial`, its table).
fn airlight_legendre_to_monomial(c: array<f32, AIRLIGHT_TERMS>) -> array<f32, AIRLIGHT_TERMS> {
@LEGENDRE_TO_MONOMIAL_BODY@
}

/// A tail panel [a, b], a ≤ b/4, after the foot (panels.rs `tail_panel`).
fn airlight_tail_panel(s: AirlightScene, g: AirlightCanonical, sigma: f32, half: AirlightHalf, a: f32, b: f32) -> AirlightPanel {
    let rule = airlight_gauss_rule();
    let r = (b - a) * 0.5;
    let yc = a + r;
    var samples = airlight_zero_terms();
    var f_max = 0.0;
    var g_avg = 0.0;
    for (var i = 0u; i < AIRLIGHT_TERMS; i++) {
        let y = yc + r * airlight_node(rule, i);
        let fy = airlight_integrand(s, g, sigma, y);
        samples[i] = fy / (1.0 + y * y);
        f_max = max(f_max, abs(fy));
        g_avg += rule[i / 2u].y * 0.5 * abs(samples[i]);
    }
    let c = airlight_legendre(samples);
    // Σ c_k P_k(ξ) → Σ q_k u^k, u = y/b, ξ = α u + β
    let alpha = b / r;
    let beta = -yc / r;
    let hat = airlight_legendre_to_monomial(c);
    // Horner's scheme from the highest power, written out (unrolled.rs)
    var q = airlight_zero_terms();
@MONOMIAL_SHIFT@
    // U_k = b s_{k+2}(H/b) − e^{−H(1/a − 1/b)} a (a/b)^k s_{k+2}(H/a)
    let big_h = half.big_h;
    let s_b = airlight_en_scaled(big_h / b);
    var s_a = array<f32, AIRLIGHT_EN_ORDERS>(@ZEROS_EN@);
    // the far end's terms are at most `decay` of the near end's: below ε/4 of them they change
    // nothing and are not computed
    let far = a > 0.0 && airlight_is_finite(big_h / a);
    var decay = 0.0;
    if (far) { decay = exp(-big_h * ((b - a) / (a * b))); }
    if (!(decay > AIRLIGHT_FLT_EPS * 0.25)) { decay = 0.0; }
    if (decay > 0.0) { s_a = airlight_en_scaled(big_h / a); }
    var ab = 0.0;
    if (b > 0.0) { ab = a / b; }
    // k = 0 sets the mass
    let mass_u = b * s_b[1] - select(0.0, decay * a * s_a[1], decay > 0.0);
    var mass = mass_u;
    var sum = q[0] * mass_u;
    var ratio = ab;
    @EACH_TERM_FROM_1@ sum += q[{k}] * (b * s_b[{k1}] - select(0.0, decay * a * ratio * s_a[{k1}], decay > 0.0)); ratio *= ab;
    let w = airlight_factor(half, a, b);
    mass *= w;
    // the conversion's rounding: ε·mass·Σ L_k(|α| + |β|)|c_k|
    let x = abs(alpha) + abs(beta);
    var l_prev = 0.0;
    var l_cur = 1.0;
    var spread = 0.0;
    var next = 0.0;
    @EACH_TERM@ spread += l_cur * abs(c[{k}]); next = (({kf} + {kf} + 1.0) * x * l_cur + {kf} * l_prev) / ({kf} + 1.0); l_prev = l_cur; l_cur = next;
    let error = mass * airlight_tail_estimate(c) + AIRLIGHT_FLT_EPS * mass * spread;
    return airlight_panel_result(w * sum, error, airlight_transform_noise(mass, g_avg), mass, f_max);
}

/// The panel kind for [a, b] (panels.rs `panel`); the singularities' heights in y and in the
/// v-panels' variable and their step factors (`airlight_singular_heights`, `_steps`).
fn airlight_panel(s: AirlightScene, g: AirlightCanonical, sigma: f32, half: AirlightHalf, a: f32, b: f32, heights_y: vec3<f32>, heights_v: vec3<f32>, steps: vec3<f32>) -> AirlightPanel {
    if (half.second && a <= b * 0.25) {
        return airlight_tail_panel(s, g, sigma, half, a, b);
    }
    if (half.second && half.big_h * ((b - a) / (a * b)) <= AIRLIGHT_Y_PANEL_EXPONENT) {
        return airlight_y_panel(s, g, sigma, half, a, b, heights_y, steps);
    }
    return airlight_v_panel(s, g, sigma, half, a, b, heights_v, steps);
}

/// The least rate the coefficients on [c − r, c + r] can fall at beyond c_{N−1}, 1/min(ρ/step),
/// with `origin` also the exponential's singularity at y = 0 (panels.rs `Singular::floor`).
fn airlight_singular_floor(heights: vec3<f32>, steps: vec3<f32>, c: f32, r: f32, origin: bool) -> f32 {
    let inv = 1.0 / r;
    let re = c * inv;
    var rho = select(AIRLIGHT_FLT_MAX, airlight_bernstein_rho(re, 0.0), origin);
    rho = min(rho, airlight_bernstein_rho(re, heights.x * inv) / steps.x);
    rho = min(rho, airlight_bernstein_rho(re, heights.y * inv) / steps.y);
    rho = min(rho, airlight_bernstein_rho(re, heights.z * inv) / steps.z);
    return 1.0 / rho;
}

/// Where the panel [a, b] (in y) is split if not at its midpoint (panels.rs `graded_split`):
/// a + 2d where G's nearest singularity ±it, at the distance d = |a + it|, is closer than a
/// quarter of the width; −1 where it is not.
fn airlight_graded_split(a: f32, b: f32, heights: vec3<f32>) -> f32 {
    let t = min(heights.x, min(heights.y, heights.z));
    let d = sqrt(a * a + t * t);
    return select(-1.0, a + 2.0 * d, d > 0.0 && d < (b - a) * 0.25);
}

/// ∫ e^{−H(v − v_s)} G(v) dv over y ∈ [lo, hi] in the half's scaling, the worst panel split
/// first until the estimates sum below the target (panels.rs `integrate_piece`); f_max: the
/// largest |F| seen on the segment.
fn airlight_integrate_piece(s: AirlightScene, g: AirlightCanonical, sigma: f32, half: AirlightHalf, lo: f32, hi: f32, f_max: ptr<function, f32>) -> f32 {
    if (!(hi > lo)) { return 0.0; }
    // G's singularities once per piece, in y and in the v-panels' variable (1/t after the foot)
    let heights_y = airlight_singular_heights(s, sigma);
    let heights_v = select(heights_y, 1.0 / heights_y, half.second);
    let steps = airlight_singular_steps(s);
    // (a, b, value, error) and mass_over per listed panel
    var list = array<vec4<f32>, AIRLIGHT_PANEL_LIST>(@ZEROS_LIST4@);
    var mass_over = array<f32, AIRLIGHT_PANEL_LIST>(@ZEROS_LIST@);
    // One panel is evaluated per step, at this one call site (a split's halves on consecutive
    // steps): the panel code is inlined once, not three times. [a, b] goes to `slot`; a split's
    // right half [next_a, next_b] is pending for the next step.
    var a = lo;
    var b = hi;
    var slot = 0u;
    var pending = false;
    var next_a = 0.0;
    var next_b = 0.0;
    // a piece that starts next to a known singularity is graded at once
    let graded = airlight_graded_split(lo, hi, heights_y);
    if (graded >= 0.0 && AIRLIGHT_MAX_PANELS >= 2u) {
        b = graded;
        pending = true;
        next_a = graded;
        next_b = hi;
    }
    var count = 0u;
    var budget = AIRLIGHT_MAX_PANELS;
    for (var step = 0u; step < AIRLIGHT_MAX_PANELS; step++) {
        let p = airlight_panel(s, g, sigma, half, a, b, heights_y, heights_v, steps);
        *f_max = max(*f_max, p.f_max);
        list[slot] = vec4<f32>(a, b, p.value, p.error);
        mass_over[slot] = p.mass_over;
        budget -= 1u;
        if (slot == count) { count += 1u; }
        if (pending) {
            a = next_a;
            b = next_b;
            slot = count;
            pending = false;
            continue;
        }
        // the worst panel is split; one too narrow to split is retired (its error set to 0)
        for (var retire = 0u; retire <= AIRLIGHT_PANEL_LIST; retire++) {
            var total = 0.0;
            var errors = 0.0;
            var mass = 0.0;
            var worst = 0u;
            for (var i = 0u; i < AIRLIGHT_PANEL_LIST; i++) {
                if (i >= count) { break; }
                total += list[i].z;
                errors += list[i].w;
                mass += mass_over[i];
                if (list[i].w > list[worst].w) { worst = i; }
            }
            let goal = AIRLIGHT_PANEL_TOLERANCE * max(abs(total), AIRLIGHT_PANEL_FLOOR * *f_max * mass);
            if (errors <= goal || !(list[worst].w > 0.0) || budget < 2u || count == AIRLIGHT_PANEL_LIST) {
                return total;
            }
            let wa = list[worst].x;
            let wb = list[worst].y;
            if (!((wb - wa) > AIRLIGHT_FLT_EPS * wb)) {
                list[worst].w = 0.0;
                continue;
            }
            let at = airlight_graded_split(wa, wb, heights_y);
            let mid = select(wa + (wb - wa) * 0.5, at, at >= 0.0);
            a = wa;
            b = mid;
            slot = worst;
            pending = true;
            next_a = mid;
            next_b = wb;
            break;
        }
    }
    var total = 0.0;
    for (var i = 0u; i < AIRLIGHT_PANEL_LIST; i++) {
        if (i >= count) { break; }
        total += list[i].z;
    }
    return total;
}

// ---------------------------------------------------------------- the light-angle route
// (kernel/src/angle.rs)

/// atan2(y, x) for y ≥ 0 from airlight_atan (x ≥ 0): in [0, π].
fn airlight_atan2_upper(y: f32, x: f32) -> f32 {
    // one atan of a ratio ≤ 1 and the octant by selects, not four branches: a driver that
    // masks branches (lavapipe, §4.1 of docs/DESIGN.md) would run all four atans
    let ax = abs(x);
    let near_axis = y <= ax;
    let positive = x > 0.0;
    let r = airlight_atan(select(ax / y, y / ax, near_axis));
    return select(select(0.5 * AIRLIGHT_PI + r, 0.5 * AIRLIGHT_PI - r, positive), select(AIRLIGHT_PI - r, r, positive), near_axis);
}

/// atan2(y, x) from airlight_atan2_upper: in [−π, π].
fn airlight_atan2(y: f32, x: f32) -> f32 {
    return select(-1.0, 1.0, y >= 0.0) * airlight_atan2_upper(abs(y), x);
}

/// Y = u + √(1 + u²) without cancellation: the halves' bounded y before the foot.
fn airlight_angle_y(u: f32) -> f32 {
    if (u < 0.0) { return airlight_bounded(-u); }
    return u + airlight_hypot_one(u);
}

/// x + √(x(2 + x)) = e^{acosh(1 + x)} − 1 for x ≥ 0, without cancellation near 0: ρ − 1 of the
/// Bernstein ellipse through the real point 1 + x (angle.rs `axis_excess`).
fn airlight_axis_excess(x: f32) -> f32 {
    return x + sqrt(x * (2.0 + x));
}

/// The floor of the coefficients' rate from a phase singularity at the cosine
/// side·(1 + gap): θ = ∓π/2 ± i·acosh(1 + gap), through the Bernstein ellipse of the panel,
/// the pole ψ0 before its start (side > 0) or ψ1 past its end, 1 + ψ/hw from its centre in
/// units of hw (angle.rs `Plan::new`).
fn airlight_angle_floor(side: f32, gap: f32, psi0: f32, psi1: f32, inv_hw: f32, step: f32) -> f32 {
    if (!(gap > 0.0) || gap >= AIRLIGHT_FLT_MAX) { return 0.0; }
    // acosh(1 + gap) = ln(1 + y) from below by 2y/(2 + y)
    let y = airlight_axis_excess(gap);
    let im = (y + y) / (2.0 + y);
    let offset = select(psi1, psi0, side > 0.0);
    return step / airlight_bernstein_rho(1.0 + offset * inv_hw, im * inv_hw);
}

/// The whole segment as one Gauss–Legendre panel in the angle seen from the light, where its
/// estimate meets the panels' target (angle.rs `whole_segment`): (1, L_m) when taken, (0, 0)
/// when declined or failed. Nodes as distances from the poles θ = ∓π/2, the width from the
/// segment's length.
fn airlight_angle_route(s: AirlightScene, g: AirlightCanonical) -> vec2<f32> {
    if (s.light_kind == AIRLIGHT_LIGHT_SPOT) { return vec2<f32>(0.0, 0.0); }
    let h = g.h;
    let u0 = (g.t_lo - g.x_h) / h;
    let u1 = (g.t_hi - g.x_h) / h;
    let u1_finite = !g.t_hi_infinite && airlight_is_finite(u1);
    let big_h = s.sigma_t * h;
    let y0 = airlight_angle_y(u0);
    var y1 = AIRLIGHT_FLT_MAX;
    if (u1_finite) { y1 = airlight_angle_y(u1); }
    var y_cut = AIRLIGHT_FLT_MAX;
    if (big_h > 0.0) { y_cut = y0 + airlight_cut_length(big_h, y0, y1 - y0); }
    let psi0 = airlight_atan2_upper(1.0, -u0);
    // ψ1, and the width as k·atan2(y, x) from the segment's length; a width of at least 1 as
    // π − ψ0 − ψ1, which loses at most πε of it (angle.rs `Plan::new`)
    var psi1 = 0.0;
    var k = 1.0;
    var wy = 1.0;
    var wx = u0;
    if (y_cut < y1) {
        psi1 = 2.0 * airlight_atan(1.0 / y_cut);
        k = 2.0;
        wy = y_cut - y0;
        wx = 1.0 + y0 * y_cut;
    } else if (u1_finite) {
        psi1 = airlight_atan2_upper(1.0, u1);
        wy = (g.t_hi - g.t_lo) / h;
        wx = 1.0 + u0 * u1;
    }
    let difference = AIRLIGHT_PI - psi0 - psi1;
    var width = difference;
    if (!(difference >= 1.0)) { width = k * airlight_atan2_upper(wy, wx); }
    let hw = width * 0.5;
    if (!(hw > 0.0)) { return vec2<f32>(0.0, 0.0); }
    let inv_hw = 1.0 / hw;
    // predicted coefficients: the exponential's and the lobe's rate λ, the phase's ρ, Y's pole
    let y_end = min(y1, y_cut);
    let y_e = min(y0 + 1.0 / big_h, y_end);
    var degree = 0.0;
    if (s.light_kind == AIRLIGHT_LIGHT_TWO_LOBED) { degree = s.light_param_a; }
    var lambda = sqrt(degree) * hw;
    if (big_h > 0.0) { lambda += min(big_h * (y_end - y0), hw * big_h * (1.0 + y_e * y_e)) * 0.5; }
    let step = airlight_singular_steps(s).y;
    let p0 = s.phase_param_a;
    var rate = 0.0;
    switch s.phase_kind {
        case AIRLIGHT_PHASE_HENYEY_GREENSTEIN, AIRLIGHT_PHASE_CORNETTE_SHANKS: {
            rate = airlight_angle_floor(p0, airlight_hg_gap(p0), psi0, psi1, inv_hw, step);
        }
        case AIRLIGHT_PHASE_SCHLICK: {
            let a = abs(p0);
            rate = airlight_angle_floor(p0, select(AIRLIGHT_FLT_MAX, (1.0 - a) / a, a > 0.0), psi0, psi1, inv_hw, step);
        }
        case AIRLIGHT_PHASE_TWO_LOBE_HG: {
            let p1 = s.phase_param_b;
            rate = max(airlight_angle_floor(p0, airlight_hg_gap(p0), psi0, psi1, inv_hw, step), airlight_angle_floor(p1, airlight_hg_gap(p1), psi0, psi1, inv_hw, step));
        }
        default: {}
    }
    // Y's pole ψ1 past the panel's end, on the real axis at 1 + d: ρ = 1 + axis_excess(d)
    var exponential = 0.0;
    if (big_h > 0.0) { exponential = 1.0 / (1.0 + airlight_axis_excess(psi1 * inv_hw)); }
    // λ^N/(3·5⋯(2N+1)), without a loop (lavapipe's loops share one iteration budget), or where
    // that declines, the estimate's own form (angle.rs `predicted_estimate`)
    let n = f32(AIRLIGHT_TERMS);
    let predicted = pow(lambda, n) * AIRLIGHT_INV_ODD_FACTORIAL;
    let decay = max(max(lambda / (2.0 * n - 1.0), rate), exponential);
    let estimated = (pow(lambda, n - 1.0) * AIRLIGHT_INV_ODD_FACTORIAL_1 + pow(lambda, n - 2.0) * AIRLIGHT_INV_ODD_FACTORIAL_2)
        * pow(decay, n + 1.0 - f32(AIRLIGHT_ALIASING_MARGIN));
    if (!(predicted <= AIRLIGHT_PANEL_TOLERANCE) && !(estimated <= AIRLIGHT_PANEL_TOLERANCE)) { return vec2<f32>(0.0, 0.0); }
    if (!(pow(rate, n) <= AIRLIGHT_PANEL_TOLERANCE)) { return vec2<f32>(0.0, 0.0); }
    rate = max(rate, exponential);
    // the samples
    let rule = airlight_gauss_rule();
    var samples = airlight_zero_terms();
    var value = 0.0;
    var mass = 0.0;
    var magnitude = 0.0;
    var f_max = 0.0;
    for (var i = 0u; i < AIRLIGHT_TERMS; i++) {
        let x = airlight_node(rule, i);
        // the node's distance from the nearer pole, one cos_sin for both sides (selects, not a
        // branch: a masking driver would run both): sin θ = ∓cos, cos θ = sin of that distance
        let lower = psi0 + hw * (1.0 + x);
        let below = lower <= 0.5 * AIRLIGHT_PI;
        let t = airlight_cos_sin(select(psi1 + hw * (1.0 - x), lower, below));
        let cs = t.y;
        let sn = select(t.x, -t.x, below);
        // 1 − sin θ below the foot, 1 + sin θ beyond it; the other as cos²θ over it
        let near_pole = 1.0 + t.x;
        let far_pole = cs * cs / near_pole;
        let one_minus = select(far_pole, near_pole, below);
        let one_plus = select(near_pole, far_pole, below);
        let y = select(near_pole / cs, cs / near_pole, below);
        let weight = select(0.0, exp(-max(big_h * (y - y0), 0.0)), cs > 0.0);
        let f = airlight_light(s.light_kind, s.light_param_a, s.light_param_b, g.d_el * sn + g.d_c * cs)
            * airlight_phase(s.phase_kind, s.phase_param_a, s.phase_param_b, s.phase_param_c, -sn, one_plus, one_minus);
        let gw = weight * f;
        samples[i] = gw;
        let w = rule[i / 2u].y;
        value += w * gw;
        mass += w * weight;
        magnitude += w * abs(gw);
        f_max = max(f_max, abs(f));
    }
    let c = airlight_legendre(samples);
    var m = airlight_zero_terms();
    m[0] = 2.0;
    let error = 2.0 * airlight_tail_estimate(c) * airlight_error_factor(c, m, rate);
    let noise = airlight_transform_noise(2.0, 0.5 * magnitude);
    let accepted = AIRLIGHT_PANEL_TOLERANCE * max(abs(value), AIRLIGHT_PANEL_FLOOR * f_max * mass);
    if (!(error <= accepted || error <= noise)) { return vec2<f32>(0.0, 0.0); }
    // without extinction the exponent is 0, not 0·∞ where r0 overflows
    var x = 0.0;
    if (s.sigma_t > 0.0) { x = s.sigma_t * (h * airlight_hypot_one(u0)); }
    return vec2<f32>(1.0, airlight_weighted(s.sigma_s, s.intensity, h, x, value * hw * 0.5));
}

// ---------------------------------------------------------------- combined formulation
// (kernel/src/combined.rs)

fn airlight_bounded(a: f32) -> f32 {
    return 1.0 / (a + airlight_hypot_one(a));
}

fn airlight_hypot_one(a: f32) -> f32 {
    if (abs(a) < 1.0e15) { return sqrt(1.0 + a * a); }
    return abs(a);
}

/// Roots in y of c(y) = k (two at most); NaN-free: −1 marks "none".
/// The coefficients are scaled by the largest (combined.rs `crossings`): b² of a tiny b must not
/// underflow to a zero discriminant.
fn airlight_crossings(sigma: f32, d_el: f32, d_c: f32, k: f32) -> vec2<f32> {
    let a0 = k + sigma * d_el;
    let b0 = -(d_c + d_c);
    let c0 = k - sigma * d_el;
    let scale = max(abs(a0), max(abs(b0), abs(c0)));
    if (!(scale > 0.0) || !airlight_is_finite(scale)) { return vec2<f32>(-1.0, -1.0); }
    let a = a0 / scale;
    let b = b0 / scale;
    let c = c0 / scale;
    let disc = b * b - 4.0 * a * c;
    if (!(disc >= 0.0)) { return vec2<f32>(-1.0, -1.0); }
    var sb = 1.0;
    if (b < 0.0) { sb = -1.0; }
    let q = -0.5 * (b + sb * sqrt(disc));
    var r1 = -1.0;
    var r2 = -1.0;
    if (q != 0.0) { r1 = c / q; }
    if (a != 0.0) { r2 = q / a; }
    return vec2<f32>(r1, r2);
}

/// c(y) = (σ d_el(1−y²) + 2 d_c y)/(1+y²) (combined.rs `cosine`).
fn airlight_cosine(g: AirlightCanonical, sigma: f32, y: f32) -> f32 {
    let y2 = y * y;
    return ((1.0 - y2) * (sigma * g.d_el) + (y + y) * g.d_c) / (1.0 + y2);
}

/// Whether the light is dark (D = 0 for c < bound) on all of the piece [lo, hi] of a half
/// (combined.rs `HalfIntegrand::dark`): c < bound at the piece's middle, at the stationary
/// points of c inside it (d_c y² + 2σd_el y − d_c = 0) and at those of its ends that are the
/// half's ends.
fn airlight_dark(g: AirlightCanonical, sigma: f32, half: AirlightHalf, bound: f32, lo: f32, hi: f32) -> bool {
    if (!(airlight_cosine(g, sigma, 0.5 * (lo + hi)) < bound)) { return false; }
    if (lo == half.y_lo && !(airlight_cosine(g, sigma, lo) < bound)) { return false; }
    if (hi == half.y_hi && !(airlight_cosine(g, sigma, hi) < bound)) { return false; }
    let a = sigma * g.d_el;
    let d = g.d_c;
    if (d == 0.0) { return true; }
    let root = sqrt(a * a + d * d);
    var y1 = (root - a) / d;
    if (a > 0.0) { y1 = d / (a + root); }
    let y2 = -1.0 / y1;
    if (y1 > lo && y1 < hi && !(airlight_cosine(g, sigma, y1) < bound)) { return false; }
    if (y2 > lo && y2 < hi && !(airlight_cosine(g, sigma, y2) < bound)) { return false; }
    return true;
}

/// ∫ e^{−H(v − v_s)} F/(1+v²) dv on one half, in pieces split where c(y) crosses a spot
/// cone's edges (combined.rs `half_integral`), the pieces outside the cone skipped;
/// f_max: the largest |F| seen on the segment.
fn airlight_half(s: AirlightScene, g: AirlightCanonical, sigma: f32, half: AirlightHalf, isotropic: bool, f_max: ptr<function, f32>) -> f32 {
    if (isotropic) {
        return airlight_integrand(s, g, sigma, 0.0) * airlight_moment_zero(half);
    }
    var cuts = array<f32, 4>(2.0, 2.0, 2.0, 2.0);
    // a spot is dark below this cosine (light.rs `dark_below`): its outer cone, or its step
    var dark_below = -1.0;
    if (s.light_kind == AIRLIGHT_LIGHT_SPOT) {
        // a needle-thin edge is a step: one cut at its middle (both crossings coincide; the
        // zero-width piece between them is skipped below)
        var k_in = s.light_param_a;
        var k_out = s.light_param_b;
        let width = k_in - k_out;
        if (width <= AIRLIGHT_FLT_EPS) {
            k_in = k_out + width * 0.5;
            k_out = k_in;
        }
        dark_below = k_out;
        let r_in = airlight_crossings(sigma, g.d_el, g.d_c, k_in);
        let r_out = airlight_crossings(sigma, g.d_el, g.d_c, k_out);
        cuts = array<f32, 4>(r_in.x, r_in.y, r_out.x, r_out.y);
        for (var i = 0u; i < 4u; i++) {
            if (!(cuts[i] > half.y_lo && cuts[i] < half.y_hi)) { cuts[i] = 2.0; }
        }
        // sort ascending (4 elements)
        for (var i = 0u; i < 3u; i++) {
            for (var j = 0u; j < 3u - i; j++) {
                if (cuts[j] > cuts[j + 1u]) {
                    let t = cuts[j];
                    cuts[j] = cuts[j + 1u];
                    cuts[j + 1u] = t;
                }
            }
        }
    }
    var total = 0.0;
    var lo = half.y_lo;
    for (var i = 0u; i < 5u; i++) {
        var hi = half.y_hi;
        if (i < 4u && cuts[i] < 2.0) { hi = cuts[i]; }
        if (hi > lo) {
            if (!(s.light_kind == AIRLIGHT_LIGHT_SPOT && airlight_dark(g, sigma, half, dark_below, lo, hi))) {
                total += airlight_integrate_piece(s, g, sigma, half, lo, hi, f_max);
            }
            lo = hi;
        }
        if (i < 4u && cuts[i] >= 2.0) { break; }
    }
    return total;
}

/// E_2-based exact limit for a light on the ray line outside the segment (h = 0).
fn airlight_on_line(s: AirlightScene, g: AirlightCanonical) -> f32 {
    if (!g.t_hi_infinite && g.x_h > g.t_hi) {
        let f = airlight_light(s.light_kind, s.light_param_a, s.light_param_b, -g.d_el) * airlight_phase_mu(s.phase_kind, s.phase_param_a, s.phase_param_b, s.phase_param_c, 1.0);
        let r0 = g.x_h - g.t_lo;
        let r1 = g.x_h - g.t_hi;
        return airlight_weighted(s.sigma_s, s.intensity, 2.0, s.sigma_t * r0, f * ((g.t_hi - g.t_lo) / r0 / r1));
    }
    let f = airlight_light(s.light_kind, s.light_param_a, s.light_param_b, g.d_el) * airlight_phase_mu(s.phase_kind, s.phase_param_a, s.phase_param_b, s.phase_param_c, -1.0);
    let s0 = g.t_lo - g.x_h;
    let s1 = g.t_hi - g.x_h;
    if (s.sigma_t == 0.0) {
        var span = 1.0 / s0;
        if (!g.t_hi_infinite) { span = (s1 - s0) / s1 / s0; }
        return airlight_weighted(s.sigma_s, s.intensity, 2.0, 0.0, f * span);
    }
    let two_st = s.sigma_t + s.sigma_t;
    let span = g.t_hi - g.t_lo;
    if (!g.t_hi_infinite && span <= s0 * 0.125 && two_st * span <= 1.0) {
        // a span short against s0, where head − tail below cancels to rounding (combined.rs
        // `on_line`): Gauss–Legendre in s, the panels' rule
        let rule = airlight_gauss_rule();
        let half = span * 0.5;
        var j = 0.0;
        for (var i = 0u; i < AIRLIGHT_HALF_TERMS; i++) {
            let s_lo = s0 + half * (1.0 - rule[i].x);
            let s_hi = s0 + half * (1.0 + rule[i].x);
            j += rule[i].y * ((half / s_lo) * (s0 / s_lo) * exp(-two_st * (s_lo - s0)) + (half / s_hi) * (s0 / s_hi) * exp(-two_st * (s_hi - s0)));
        }
        return airlight_weighted(s.sigma_s, s.intensity, 2.0, s.sigma_t * s0, f * j / s0);
    }
    var e2 = airlight_en_scaled(two_st * s0);
    // σs I e^{−x} as weighted(σs, I, 2, x), whose h = 2 cancels its 2
    let head = airlight_weighted(s.sigma_s, s.intensity, 2.0, s.sigma_t * s0, f * e2[1] / s0);
    var tail = 0.0;
    if (!g.t_hi_infinite) {
        e2 = airlight_en_scaled(two_st * s1);
        tail = airlight_weighted(s.sigma_s, s.intensity, 2.0, s.sigma_t * (s1 - s0) + s.sigma_t * s1, f * e2[1] / s1);
    }
    // head ≥ tail exactly; ∞ − ∞ (both overflowing) means the value overflows
    if (!airlight_is_finite(head)) {
        return head;
    }
    return head - tail;
}

/// H on one half: 0 where e^{−H(v − v_s)} is 1 to working precision (H·Δv < ε; unbounded:
/// H < ε²), so no H-sized intermediate can be flushed as a denormal (combined.rs `optical`).
fn airlight_optical(big_h: f32, dv: f32, infinite: bool) -> f32 {
    var negligible = big_h * dv < AIRLIGHT_FLT_EPS;
    if (infinite) { negligible = big_h < AIRLIGHT_FLT_EPS * AIRLIGHT_FLT_EPS; }
    return select(big_h, 0.0, negligible);
}

/// (2 σs I / h)·e^{−x}·j, a half's prefactor, folded exponent and sum (combined.rs
/// `weighted`): where the plain product is not finite (σs·I/h overflowing while e^{−x} or j
/// underflows) it is formed through logarithms, so a representable value stays finite.
fn airlight_weighted(sigma_s: f32, intensity: f32, h: f32, x: f32, j: f32) -> f32 {
    let plain = 2.0 * sigma_s * intensity / h * exp(-x) * j;
    if (airlight_is_finite(plain)) {
        return plain;
    }
    if (!(abs(j) > 0.0)) {
        return 0.0;
    }
    return sign(j) * exp(AIRLIGHT_LN_2 + log(sigma_s) + log(intensity) - log(h) - x + log(abs(j)));
}

/// An isotropic segment across the foot in one piece (combined.rs `whole_line`): the first
/// reformulation's v = u + √(1+u²) over the whole line, two e^z E1(z) values instead of three.
fn airlight_whole_line(s: AirlightScene, g: AirlightCanonical, big_h: f32) -> f32 {
    let h = g.h;
    let a_s = (g.x_h - g.t_lo) / h;
    let r_s = airlight_hypot_one(a_s);
    let v_s = airlight_bounded(a_s);
    var v_e = AIRLIGHT_FLT_MAX;
    var dv = AIRLIGHT_FLT_MAX;
    var infinite = true;
    // Δv = Δu (v_s + v_e)/(r_s + r_e); an end beyond the float range is the end at t = ∞
    let u_e = (g.t_hi - g.x_h) / h;
    if (!g.t_hi_infinite && airlight_is_finite(u_e)) {
        let r_e = airlight_hypot_one(u_e);
        let v_end = u_e + r_e;
        let dv_end = (g.t_hi - g.t_lo) / h * ((v_s + v_end) / (r_s + r_e));
        if (airlight_is_finite(v_end) && airlight_is_finite(dv_end)) {
            v_e = v_end;
            dv = dv_end;
            infinite = false;
        }
    }
    let half = AirlightHalf(false, airlight_optical(big_h, dv, infinite), v_s, v_e, dv, dv, infinite);
    // H·r_s = σt·|p − x(t0)|; where r_s overflows (a tiny h) the distance is |x_h − t0|, and
    // without extinction the exponent is 0, not 0·∞ (combined.rs `whole_line`)
    var x = 0.0;
    if (airlight_is_finite(r_s)) {
        x = big_h * r_s;
    } else if (s.sigma_t > 0.0) {
        x = s.sigma_t * abs(g.x_h - g.t_lo);
    }
    // F is constant: its value at y = 0
    let m = airlight_moment_zero_weighted(half, x);
    return airlight_weighted(s.sigma_s, s.intensity, h, m.y, airlight_integrand(s, g, -1.0, 0.0) * m.x);
}

/// The length Δv of a half beyond which the panels cut it, E = 1 + ln(8R/(δ·τ)) over H > 0,
/// δ·τ = AIRLIGHT_CUT_RESOLUTION (combined.rs::cut_length, where the bound is derived); FLT_MAX
/// without the logarithm where H·span is at most AIRLIGHT_UNCUT_SPAN, below E.
fn airlight_cut_length(big_h: f32, v_s: f32, span: f32) -> f32 {
    if (big_h * span <= AIRLIGHT_UNCUT_SPAN) { return AIRLIGHT_FLT_MAX; }
    let inv_h = 1.0 / big_h;
    let w = v_s + inv_h;
    let r = (1.0 + w * w) / (1.0 + v_s * v_s);
    let e = 1.0 + log(8.0 * r / AIRLIGHT_CUT_RESOLUTION);
    return e * inv_h;
}

/// The combined formulation on the canonical problem (combined.rs::in_scatter_canonical).
/// Returns +∞ as FLT_MAX with status INFINITE.
/// The canonical problem's limits, which need no integral (combined.rs `in_scatter_counted`'s
/// first cases): an empty segment or no scattering (0), the light on the ray's line beyond the
/// segment (the on-line limit), on the segment itself (+∞); (0, DEFERRED) where none holds.
fn airlight_limits(s: AirlightScene, g: AirlightCanonical) -> AirlightResult {
    let t0 = g.t_lo;
    let t1 = g.t_hi;
    if (!(g.t_hi_infinite || t1 > t0) || s.sigma_s * s.intensity == 0.0) {
        return AirlightResult(0.0, AIRLIGHT_STATUS_OK);
    }
    let h = g.h;
    let x_h = g.x_h;
    let inside = t0 <= x_h && (g.t_hi_infinite || x_h <= t1);
    var gap = 0.0;
    if (x_h < t0) { gap = t0 - x_h; } else if (!inside) { gap = x_h - t1; }
    if (!inside && h <= gap * AIRLIGHT_FLT_EPS * AIRLIGHT_FLT_EPS) {
        return AirlightResult(max(airlight_on_line(s, g), 0.0), AIRLIGHT_STATUS_OK);
    }
    if (h == 0.0) {
        return AirlightResult(AIRLIGHT_FLT_MAX, AIRLIGHT_STATUS_INFINITE);
    }
    return AirlightResult(0.0, AIRLIGHT_STATUS_DEFERRED);
}

/// Whether F = D·P is constant: an omni light (or c^0) in a constant phase function
/// (airlight_isotropic_phase), where the kernel takes the closed forms of the isotropic path
/// (combined.rs: `light.is_isotropic() && phase.is_isotropic()`).
fn airlight_isotropic_scene(s: AirlightScene) -> bool {
    return (s.light_kind == AIRLIGHT_LIGHT_OMNI || (s.light_kind == AIRLIGHT_LIGHT_TWO_LOBED && s.light_param_a == 0.0))
        && airlight_isotropic_phase(s);
}

/// Whether the phase function is a constant (phase.rs `AnyPhase::is_isotropic`): isotropic, or
/// Henyey–Greenstein, Schlick or two-lobe Henyey–Greenstein with every asymmetry 0.
fn airlight_isotropic_phase(s: AirlightScene) -> bool {
    return s.phase_kind == AIRLIGHT_PHASE_ISOTROPIC
        || ((s.phase_kind == AIRLIGHT_PHASE_HENYEY_GREENSTEIN || s.phase_kind == AIRLIGHT_PHASE_SCHLICK) && s.phase_param_a == 0.0)
        || (s.phase_kind == AIRLIGHT_PHASE_TWO_LOBE_HG && s.phase_param_a == 0.0 && s.phase_param_b == 0.0);
}

fn airlight_in_scatter_canonical(s: AirlightScene, g: AirlightCanonical) -> AirlightResult {
    let limit = airlight_limits(s, g);
    if (limit.status != AIRLIGHT_STATUS_DEFERRED) {
        return limit;
    }
    let t0 = g.t_lo;
    let t1 = g.t_hi;
    let h = g.h;
    let x_h = g.x_h;
    let big_h = s.sigma_t * h;
    let isotropic = airlight_isotropic_scene(s);
    if (isotropic && t0 < x_h && (g.t_hi_infinite || x_h < t1)) {
        return AirlightResult(max(airlight_whole_line(s, g, big_h), 0.0), AIRLIGHT_STATUS_OK);
    }
    // a route by cost first: the whole segment in the light angle (angle.rs)
    if (!isotropic) {
        let route = airlight_angle_route(s, g);
        if (route.x > 0.5) { return AirlightResult(max(route.y, 0.0), AIRLIGHT_STATUS_OK); }
    }
    var total = 0.0;
    var f_max = 0.0;
    // the exponent's boundary layer is cut where the rest is below rounding (isotropic: exact)
    let cut = !isotropic;
    var behind_cut = false;
    if (t0 < x_h) {
        let a_s = (x_h - t0) / h;
        var t_end = x_h;
        if (!g.t_hi_infinite && t1 < x_h) { t_end = t1; }
        let a_e = (x_h - t_end) / h;
        let r_s = airlight_hypot_one(a_s);
        let r_e = airlight_hypot_one(a_e);
        let y_lo = airlight_bounded(a_s);
        let y_hi = airlight_bounded(a_e);
        let dy = (t_end - t0) / h * (1.0 + (a_s + a_e) / (r_s + r_e)) * y_lo * y_hi;
        var half = AirlightHalf(false, airlight_optical(big_h, dy, false), y_lo, y_hi, dy, dy, false);
        if (cut && half.big_h > 0.0) {
            let cut_dv = airlight_cut_length(half.big_h, y_lo, dy);
            if (cut_dv < dy) {
                // the rest of this half and all of the second lie beyond the cut
                half = AirlightHalf(false, half.big_h, y_lo, y_lo + cut_dv, cut_dv, cut_dv, false);
                behind_cut = true;
            }
        }
        let j = airlight_half(s, g, -1.0, half, isotropic, &f_max);
        total += airlight_weighted(s.sigma_s, s.intensity, h, big_h * r_s, j);
    }
    if ((g.t_hi_infinite || t1 > x_h) && !behind_cut) {
        let t_start = max(t0, x_h);
        let a_s = (t_start - x_h) / h;
        let r_s = airlight_hypot_one(a_s);
        let y_hi = airlight_bounded(a_s);
        var y_lo = 0.0;
        var dv = 0.0;
        var dy = y_hi;
        var infinite = true;
        // An end so far out that y_lo or Δv leaves the float range is the end at t = ∞.
        let a_e = (t1 - x_h) / h;
        if (!g.t_hi_infinite && airlight_is_finite(a_e)) {
            let y_end = airlight_bounded(a_e);
            let dv_end = (t1 - t_start) / h * (1.0 + (a_s + a_e) / (r_s + airlight_hypot_one(a_e)));
            if (y_end > 0.0 && airlight_is_finite(dv_end)) {
                y_lo = y_end;
                dv = dv_end;
                dy = dv * y_lo * y_hi;
                infinite = false;
            }
        }
        var half = AirlightHalf(true, airlight_optical(big_h, dv, infinite), y_lo, y_hi, dy, dv, infinite);
        if (cut && half.big_h > 0.0) {
            let cut_dv = airlight_cut_length(half.big_h, 1.0 / y_hi, select(dv, AIRLIGHT_FLT_MAX, infinite));
            if (infinite || cut_dv < dv) {
                // v_e = v_s + Δv: y_lo = 1/v_e, Δy = Δv·y_lo·y_hi
                let cut_y_lo = y_hi / (1.0 + y_hi * cut_dv);
                if (cut_y_lo > 0.0 && airlight_is_finite(cut_dv)) {
                    half = AirlightHalf(true, half.big_h, cut_y_lo, y_hi, cut_dv * cut_y_lo * y_hi, cut_dv, false);
                }
            }
        }
        let j = airlight_half(s, g, 1.0, half, isotropic, &f_max);
        total += airlight_weighted(s.sigma_s, s.intensity, h, s.sigma_t * (t_start - t0) + big_h * r_s, j);
    }
    return AirlightResult(max(total, 0.0), AIRLIGHT_STATUS_OK);
}

// ---------------------------------------------------------------- geometry and checks
// (kernel/src/geometry.rs, kernel/src/scene.rs::validate)

fn airlight_vec_finite(v: vec3<f32>) -> bool {
    return airlight_is_finite(v.x) && airlight_is_finite(v.y) && airlight_is_finite(v.z);
}

fn airlight_safe_length(v: vec3<f32>) -> f32 {
    let m = max(abs(v.x), max(abs(v.y), abs(v.z)));
    if (m == 0.0) { return 0.0; }
    return m * length(v / m);
}

/// |v| is non-zero and finite: v can be normalised (error.rs::check_vector).
fn airlight_normalisable(v: vec3<f32>) -> bool {
    let l = airlight_safe_length(v);
    return l > 0.0 && airlight_is_finite(l);
}

/// v/|v|, scaled by the largest component first (geometry.rs::normalize).
fn airlight_normalize(v: vec3<f32>) -> vec3<f32> {
    let m = max(abs(v.x), max(abs(v.y), abs(v.z)));
    let u = v / m;
    return u / length(u);
}

/// The checks of the kernel's checked API; false → the record is invalid.
fn airlight_valid(s: AirlightScene) -> bool {
    var ok = airlight_vec_finite(s.origin) && airlight_vec_finite(s.dir) && airlight_normalisable(s.dir)
        && airlight_is_finite(s.t_min) && airlight_vec_finite(s.light_position)
        && airlight_is_finite(s.intensity) && s.intensity >= 0.0
        && airlight_is_finite(s.sigma_s) && s.sigma_s >= 0.0 && airlight_is_finite(s.sigma_t) && s.sigma_t >= 0.0;
    if ((s.flags & 1u) == 0u) {
        ok = ok && airlight_is_finite(s.t_max) && s.t_min <= s.t_max;
    }
    if (s.light_shape == AIRLIGHT_SHAPE_SEGMENT) {
        ok = ok && airlight_vec_finite(s.light_end);
    } else if (s.light_shape >= AIRLIGHT_SHAPE_DISC && s.light_shape <= AIRLIGHT_SHAPE_SPHERE) {
        // area.rs AreaScene::new: the emitter, its radiance (`intensity`) and emission power
        // (`light_param_b`); an omni light's fields otherwise
        ok = ok && s.light_kind == AIRLIGHT_LIGHT_OMNI && s.light_param_b >= 1.0
            && s.light_param_b <= f32(AIRLIGHT_EMISSION_MAX_POWER) && fract(s.light_param_b) == 0.0;
        if (s.light_shape == AIRLIGHT_SHAPE_RECTANGLE) {
            ok = ok && airlight_vec_finite(s.light_axis) && airlight_normalisable(s.light_axis) && airlight_vec_finite(s.light_end)
                && airlight_normalisable(s.light_end)
                && airlight_safe_length(cross(airlight_normalize(s.light_axis), airlight_normalize(s.light_end))) > AIRLIGHT_FLT_EPS;
        } else {
            ok = ok && airlight_is_finite(s.light_param_a) && s.light_param_a >= 0.0;
            if (s.light_shape == AIRLIGHT_SHAPE_DISC) {
                ok = ok && airlight_vec_finite(s.light_axis) && airlight_normalisable(s.light_axis);
            }
        }
    } else if (s.light_shape != AIRLIGHT_SHAPE_POINT) {
        ok = false;
    }
    if (s.surface_kind == AIRLIGHT_SURFACE_LAMBERT || s.surface_kind == AIRLIGHT_SURFACE_PHONG) {
        // surface.rs SurfaceScene::new; lights with an axis: the CPU kernel's only
        ok = ok && airlight_is_finite(s.brdf_scale) && s.brdf_scale >= 0.0 && s.light_kind == AIRLIGHT_LIGHT_OMNI
            && s.light_shape == AIRLIGHT_SHAPE_POINT && airlight_is_finite(airlight_safe_length(s.light_position - s.origin));
        if (s.surface_kind == AIRLIGHT_SURFACE_PHONG) {
            ok = ok && airlight_is_finite(s.brdf_exponent) && s.brdf_exponent >= 0.0 && airlight_vec_finite(s.brdf_view)
                && airlight_normalisable(s.brdf_view);
        }
    } else if (s.surface_kind != AIRLIGHT_SURFACE_NONE) {
        ok = false;
    }
    if (s.light_kind == AIRLIGHT_LIGHT_TWO_LOBED) {
        ok = ok && airlight_vec_finite(s.light_axis) && airlight_normalisable(s.light_axis)
            && s.light_param_a >= 0.0 && s.light_param_a <= f32(AIRLIGHT_MAX_POWER) && fract(s.light_param_a * 0.5) == 0.0;
    } else if (s.light_kind == AIRLIGHT_LIGHT_SPOT) {
        ok = ok && airlight_vec_finite(s.light_axis) && airlight_normalisable(s.light_axis)
            && s.light_param_b < s.light_param_a && s.light_param_b >= -1.0 && s.light_param_a <= 1.0;
    } else if (s.light_kind != AIRLIGHT_LIGHT_OMNI) {
        ok = false;
    }
    let g_ok = abs(s.phase_param_a) < 1.0;
    switch s.phase_kind {
        case AIRLIGHT_PHASE_ISOTROPIC, AIRLIGHT_PHASE_RAYLEIGH: {}
        case AIRLIGHT_PHASE_HENYEY_GREENSTEIN, AIRLIGHT_PHASE_SCHLICK, AIRLIGHT_PHASE_CORNETTE_SHANKS: { ok = ok && g_ok; }
        case AIRLIGHT_PHASE_TWO_LOBE_HG: { ok = ok && g_ok && abs(s.phase_param_b) < 1.0 && s.phase_param_c >= 0.0 && s.phase_param_c <= 1.0; }
        default: { ok = false; }
    }
    return ok;
}

/// World space → canonical (geometry.rs::Canonical::new).
fn airlight_canonical(s: AirlightScene) -> AirlightCanonical {
    let d = airlight_normalize(s.dir);
    var a = vec3<f32>(0.0, 0.0, 1.0);
    if (s.light_kind != AIRLIGHT_LIGHT_OMNI) { a = airlight_normalize(s.light_axis); }
    let to_light = s.light_position - s.origin;
    let x_h = dot(to_light, d);
    let perp = x_h * d - to_light;
    let h = airlight_safe_length(perp);
    var d_c = 0.0;
    if (h > 0.0) { d_c = dot(perp, a) / h; }
    let infinite = (s.flags & 1u) != 0u;
    return AirlightCanonical(h, x_h, dot(d, a), d_c, s.t_min, select(s.t_max, 0.0, infinite), infinite);
}

/// `x` itself (`key` is 0 at run time), in a form no compiler can see through: a driver may
/// otherwise fold `(a + b) − a` to `b` or contract `a·b − c` into `fma(a, b, −c)`, either of
/// which destroys an error-free transformation (SPIR-V has `NoContraction` for this, which
/// naga does not emit).
fn airlight_opaque(x: f32, key: u32) -> f32 {
    return bitcast<f32>(bitcast<u32>(x) ^ key);
}

/// (s, e) with s = a + b rounded and s + e = a + b exactly (Knuth's two-sum; geometry.rs).
fn airlight_two_sum(a: f32, b: f32, key: u32) -> vec2<f32> {
    let s = airlight_opaque(a + b, key);
    let bb = airlight_opaque(s - a, key);
    let av = airlight_opaque(s - bb, key);
    let e = (a - av) + (b - bb);
    return vec2<f32>(s, select(0.0, e, airlight_is_finite(e)));
}

/// The 12 leading bits of `x` rounded to nearest, by integer operations (Veltkamp's
/// `c − (c − x)` could be folded to `x`): `x − hi` then has 11 bits and a sign, the split
/// Dekker's product needs (a truncated split leaves 12-bit tails, and its partial sums are
/// not exact).
fn airlight_split_high(x: f32) -> f32 {
    return bitcast<f32>((bitcast<u32>(x) + 0x800u) & 0xfffff000u);
}

/// (p, e) with p = a·b rounded and p + e = a·b exactly (Dekker's product); |a|, |b| within
/// AIRLIGHT_EXACT_RANGE.
fn airlight_two_product(a: f32, b: f32, key: u32) -> vec2<f32> {
    let p = airlight_opaque(a * b, key);
    let ah = airlight_split_high(a);
    let al = a - ah;
    let bh = airlight_split_high(b);
    let bl = b - bh;
    let e = ((ah * bh - p) + ah * bl + al * bh) + al * bl;
    return vec2<f32>(p, select(0.0, e, airlight_is_finite(e)));
}

/// a·b − c·d with the products' rounding errors carried.
fn airlight_diff_of_products(a: f32, b: f32, c: f32, d: f32, key: u32) -> f32 {
    let p = airlight_two_product(a, b, key);
    let q = airlight_two_product(c, d, key);
    return airlight_opaque(p.x - q.x, key) + airlight_opaque(p.y - q.y, key);
}

/// A float pair (hi, lo) plus another, to about ε² of the larger (geometry.rs `pair_add`).
fn airlight_pair_add(a: vec2<f32>, b: vec2<f32>, key: u32) -> vec2<f32> {
    let s = airlight_two_sum(a.x, b.x, key);
    return airlight_two_sum(s.x, s.y + (a.y + b.y), key);
}

/// A float pair times another, to about ε² (geometry.rs `pair_mul`).
fn airlight_pair_mul(a: vec2<f32>, b: vec2<f32>, key: u32) -> vec2<f32> {
    let p = airlight_two_product(a.x, b.x, key);
    return airlight_two_sum(p.x, p.y + (a.x * b.y + a.y * b.x), key);
}

/// hi_i·dir_j − hi_j·dir_i + lo_i·dir_j − lo_j·dir_i as a float pair (geometry.rs
/// `sphere_miss`'s cross product): the hi products exact, their difference a two-sum.
fn airlight_cross_pair(hi_i: f32, hi_j: f32, lo_i: f32, lo_j: f32, dir_i: f32, dir_j: f32, key: u32) -> vec2<f32> {
    let p = airlight_two_product(hi_i, dir_j, key);
    let q = airlight_two_product(hi_j, dir_i, key);
    let s = airlight_two_sum(p.x, -q.x, key);
    return airlight_two_sum(s.x, s.y + (p.y - q.y) + (lo_i * dir_j - lo_j * dir_i), key);
}

fn airlight_in_exact_range(v: vec3<f32>) -> bool {
    let m = max(abs(v.x), max(abs(v.y), abs(v.z)));
    return m == 0.0 || (m >= 1.0 / AIRLIGHT_EXACT_RANGE && m <= AIRLIGHT_EXACT_RANGE);
}

/// point − origin exactly, as a two-sum (hi, lo) per component, and whether it and dir lie
/// within AIRLIGHT_EXACT_RANGE for exact products (geometry.rs `exact_difference`).
struct AirlightExactDifference {
    hi: vec3<f32>,
    lo: vec3<f32>,
    in_range: bool,
}

fn airlight_exact_difference(point: vec3<f32>, origin: vec3<f32>, dir: vec3<f32>, key: u32) -> AirlightExactDifference {
    let sx = airlight_two_sum(point.x, -origin.x, key);
    let sy = airlight_two_sum(point.y, -origin.y, key);
    let sz = airlight_two_sum(point.z, -origin.z, key);
    let hi = vec3<f32>(sx.x, sy.x, sz.x);
    return AirlightExactDifference(hi, vec3<f32>(sx.y, sy.y, sz.y), airlight_in_exact_range(hi) && airlight_in_exact_range(dir));
}

/// The plain reduction with h and d_c from exact products (geometry.rs `Canonical::refined`):
/// p − o kept as a two-sum, w = (p − o) × dir from Dekker's products, h = |w|/|dir|, the unit
/// vector from the light to the foot −(dir × w)/(|dir||w|).
fn airlight_refined(s: AirlightScene, plain: AirlightCanonical) -> AirlightCanonical {
    // 0 for every record the kernel writes (flags has one defined bit), from an integer
    // test the compiler cannot decide (a float test such as t_min != t_min it may fold under
    // its no-NaN assumptions); were it 1, each opaque value would move by one ulp only
    let key = u32(s.flags > 1u);
    let dir = s.dir;
    let exact = airlight_exact_difference(s.light_position, s.origin, dir, key);
    if (!exact.in_range) { return plain; }
    let hi = exact.hi;
    let lo = exact.lo;
    let w = vec3<f32>(
        airlight_diff_of_products(hi.y, dir.z, hi.z, dir.y, key) + (lo.y * dir.z - lo.z * dir.y),
        airlight_diff_of_products(hi.z, dir.x, hi.x, dir.z, key) + (lo.z * dir.x - lo.x * dir.z),
        airlight_diff_of_products(hi.x, dir.y, hi.y, dir.x, key) + (lo.x * dir.y - lo.y * dir.x));
    if (!airlight_vec_finite(w)) { return plain; }
    var out = plain;
    let w_len = airlight_safe_length(w);
    if (w_len == 0.0) {
        out.h = 0.0;
        out.d_c = 0.0;
        return out;
    }
    let h = w_len / airlight_safe_length(dir);
    if (!(airlight_is_finite(h) && h > 0.0)) { return plain; }
    var a = vec3<f32>(0.0, 0.0, 1.0);
    if (s.light_kind != AIRLIGHT_LIGHT_OMNI) { a = airlight_normalize(s.light_axis); }
    let n = -cross(airlight_normalize(dir), airlight_normalize(w));
    out.h = h;
    out.d_c = dot(n, a);
    return out;
}

/// Where a sphere lies from the ray's line (outer.rs `SphereFoot`): the vector from the centre's
/// foot on the line to the centre, its length h, and the miss h − R to a few ulps of itself.
struct AirlightSphereFoot {
    to_centre: vec3<f32>,
    h: f32,
    miss: f32,
}

/// geometry.rs `sphere_miss`: c − o a two-sum, w = (c − o) × dir as float pairs from Dekker's
/// products, h = |w|/|dir|, the foot's vector (dir × w)/(|dir||w|)·h, and h − R = (|w|² −
/// R²|dir|²)/((|w| + R|dir|)|dir|) from the pairs' squares; the plain reduction where the
/// products could overflow or underflow or the centre is on the line (outer.rs).
fn airlight_sphere_foot(o: vec3<f32>, dir: vec3<f32>, c: vec3<f32>, radius: f32, key: u32) -> AirlightSphereFoot {
    let d = airlight_normalize(dir);
    let oc = o - c;
    let to_centre = -(oc - dot(oc, d) * d);
    let plain_h = airlight_safe_length(to_centre);
    let plain = AirlightSphereFoot(to_centre, plain_h, plain_h - radius);
    let exact = airlight_exact_difference(c, o, dir, key);
    if (!exact.in_range) { return plain; }
    let hi = exact.hi;
    let lo = exact.lo;
    let wx = airlight_cross_pair(hi.y, hi.z, lo.y, lo.z, dir.y, dir.z, key);
    let wy = airlight_cross_pair(hi.z, hi.x, lo.z, lo.x, dir.z, dir.x, key);
    let wz = airlight_cross_pair(hi.x, hi.y, lo.x, lo.y, dir.x, dir.y, key);
    let w2 = airlight_pair_add(airlight_pair_add(airlight_pair_mul(wx, wx, key), airlight_pair_mul(wy, wy, key), key), airlight_pair_mul(wz, wz, key), key);
    let dx = vec2<f32>(dir.x, 0.0);
    let dy = vec2<f32>(dir.y, 0.0);
    let dz = vec2<f32>(dir.z, 0.0);
    let dir2 = airlight_pair_add(airlight_pair_add(airlight_pair_mul(dx, dx, key), airlight_pair_mul(dy, dy, key), key), airlight_pair_mul(dz, dz, key), key);
    let w_len = sqrt(w2.x);
    let scale = sqrt(dir2.x);
    let h = w_len / scale;
    let k = airlight_pair_mul(airlight_two_product(radius, radius, key), dir2, key);
    let miss = airlight_pair_add(w2, -k, key).x / ((w_len + radius * scale) * scale);
    if (!(h > 0.0 && airlight_is_finite(h) && airlight_is_finite(miss))) { return plain; }
    let m = cross(d, airlight_normalize(vec3<f32>(wx.x, wy.x, wz.x)));
    return AirlightSphereFoot(h * m, h, miss);
}

// ---------------------------------------------------------------- outer integrals
// Every result is one loop of point-light ray integrals, by globally adaptive Gauss–Kronrod 3/7
// to the panels' tolerance over an outer variable (kernel/src/extended.rs `adaptive`): a point
// light is the first node of the loop, so the ray integral has one call site in
// `airlight_in_scatter` (`airlight_in_scatter_point` calls it alone).
// * A segment light (extended.rs, SegmentScene::in_scatter_panels_counted with SHADER_CONTROL)
//   `a → b` of intensity I per unit length sheds L = ∫_0^ℓ L_point(a + s·e) ds, taken in w with
//   s = s* + (ρ*/sin α) sinh w about the emitter's closest approach to the ray's line
//   (ds/ρ = dw/sin α: the 1/ρ peak is smooth in w), split where the light's foot passes the ray's
//   ends, at most AIRLIGHT_SEGMENT_PANELS panels.
// * A Lambertian surface point (surface.rs, SurfaceScene::air_light_panels_counted with
//   SHADER_CONTROL) lit by a light without an axis: the rays leave it at the angle γ from the
//   light's direction ℓ, where L_a depends on γ alone, so the integral over the hemisphere is
//   ∫_0^π L_a(γ) (ρ/π) 2(Aψ + B sin ψ) sin γ dγ (A = cos α cos γ, B = sin α sin γ, α the normal's
//   angle from ℓ, ψ the half-arc of the hemisphere at γ), split where the arc changes kind
//   (γ = |π/2 − α|, π − |π/2 − α|) and taken in the smoothstep of each piece, at most
//   AIRLIGHT_SURFACE_PANELS panels.

// At most this many panels (kernel SHADER_SEGMENT_PANELS, SHADER_SURFACE_PANELS), so at most
// 7·(2·6 − 1) = 77 ray integrals. Mesa's lavapipe (llvmpipe) ends every loop once all loops
// together have run 65 535 iterations (gallivm LP_MAX_TGSI_LOOP_ITERATIONS, shared by every
// loop; as observed, over the 8 lanes it runs together): at 8 panels, tubes of 98 point lights
// of 12 nodes reached it and came out 10–43 % low there. A tube whose every point light takes
// many panels still can.
const AIRLIGHT_SEGMENT_PANELS: u32 = @SEGMENT_PANELS@u;
const AIRLIGHT_SURFACE_PANELS: u32 = @SURFACE_PANELS@u;
const AIRLIGHT_PHONG_PANELS: u32 = @PHONG_PANELS@u;
// An outer integral's first panels' edges: a segment's ≤ 5, a surface's ≤ 13 (11 cuts).
const AIRLIGHT_OUTER_EDGES: u32 = 13u;
// The pairs of nodes of a Phong lobe's rule (surface.rs LOBE_RULE).
const AIRLIGHT_LOBE_PAIRS: u32 = @LOBE_PAIRS@u;
// ln of where a Phong lobe is ended, relative to its peak (surface.rs LOBE_FLOOR).
const AIRLIGHT_LN_LOBE_FLOOR: f32 = @LN_LOBE_FLOOR@;

/// Gauss–Kronrod 3/7 (extended.rs GAUSS_KRONROD_7): (x ≥ 0 descending, Kronrod weight, Gauss
/// weight or 0); the rule takes ±x.
fn airlight_kronrod_rule() -> array<vec3<f32>, 4> {
    return array<vec3<f32>, 4>(@KRONROD_RULE@);
}

/// A segment's panel list: (a, b, Kronrod value, |Kronrod − Gauss|) per panel, one field
/// each, read and written through a switch and scanned in straight-line code, so that every
/// index is a literal and the list stays in registers (as codegen/shaders/src/unrolled.rs
/// explains for the panels' arrays), and the scans add no loop iterations (see
/// AIRLIGHT_SEGMENT_PANELS).
struct AirlightPanelList {
@SEGMENT_LIST_FIELDS@}

fn airlight_list_get(l: AirlightPanelList, i: u32) -> vec4<f32> {
    switch i {
@SEGMENT_LIST_GET@    }
}

fn airlight_list_set(l: ptr<function, AirlightPanelList>, i: u32, v: vec4<f32>) {
    switch i {
@SEGMENT_LIST_SET@    }
}

/// The sums of the first `count` panels' values and errors, in order, and the first panel
/// with the largest error.
struct AirlightListScan {
    total: f32,
    errors: f32,
    worst: u32,
}

fn airlight_list_scan(l: AirlightPanelList, count: u32) -> AirlightListScan {
    var r = AirlightListScan(0.0, 0.0, 0u);
    var worst_error = -1.0;
@SEGMENT_LIST_SCAN@    return r;
}

/// The first panels' edges of an outer integral over [lo, hi] (extended.rs `edges_between`): lo,
/// the cuts strictly inside in increasing order (five compare-and-swaps; repeats dropped), hi;
/// `panels` of them between.
struct AirlightEdges {
    at: array<f32, AIRLIGHT_OUTER_EDGES>,
    panels: u32,
}

fn airlight_edges_between(lo: f32, hi: f32, unsorted: array<f32, 4>) -> AirlightEdges {
    var cuts = unsorted;
    if (cuts[1] < cuts[0]) { let c = cuts[0]; cuts[0] = cuts[1]; cuts[1] = c; }
    if (cuts[3] < cuts[2]) { let c = cuts[2]; cuts[2] = cuts[3]; cuts[3] = c; }
    if (cuts[2] < cuts[0]) { let c = cuts[0]; cuts[0] = cuts[2]; cuts[2] = c; }
    if (cuts[3] < cuts[1]) { let c = cuts[1]; cuts[1] = cuts[3]; cuts[3] = c; }
    if (cuts[2] < cuts[1]) { let c = cuts[1]; cuts[1] = cuts[2]; cuts[2] = c; }
    var e = AirlightEdges(array<f32, AIRLIGHT_OUTER_EDGES>(lo, lo, lo, lo, lo, lo, lo, lo, lo, lo, lo, lo, lo), 0u);
    var n = 0u;
    for (var i = 0u; i < 4u; i++) {
        if (cuts[i] > e.at[n] && cuts[i] < hi) {
            n += 1u;
            e.at[n] = cuts[i];
        }
    }
    e.at[n + 1u] = hi;
    e.panels = n + 1u;
    return e;
}

/// The adaptive scheme's next step (extended.rs `adaptive`): whether the listed panels' summed
/// error is still above `tolerance` of their sum with room for another panel, and then the first
/// panel of the largest error, [lo, hi], to be split at `mid` and its halves written at `slot`
/// and the list's end (a panel too narrow to split has its error cleared instead).
struct AirlightSplit {
    split: bool,
    lo: f32,
    mid: f32,
    hi: f32,
    slot: u32,
}

fn airlight_split_worst(list: ptr<function, AirlightPanelList>, count: u32, max_panels: u32, tolerance: f32) -> AirlightSplit {
    for (var tries = 0u; tries < max_panels; tries++) {
        let scan = airlight_list_scan(*list, count);
        if (!(scan.errors > tolerance * abs(scan.total)) || count == max_panels || !airlight_is_finite(scan.total)) {
            break;
        }
        let w = airlight_list_get(*list, scan.worst);
        let mid = 0.5 * (w.x + w.y);
        if (!(mid > w.x && mid < w.y)) {
            airlight_list_set(list, scan.worst, vec4<f32>(w.xyz, 0.0));
            continue;
        }
        return AirlightSplit(true, w.x, mid, w.y, scan.worst);
    }
    return AirlightSplit(false, 0.0, 0.0, 0.0, 0u);
}

/// An adaptive outer integral's state (extended.rs `adaptive`): the panel list, `count` panels
/// long, and the panel to evaluate next, [lo, hi], with the slot it goes to (none: `more` false);
/// a split's second half waits in `queued_lo`, `queued_hi` (`queued`).
struct AirlightAdaptive {
    list: AirlightPanelList,
    count: u32,
    lo: f32,
    hi: f32,
    slot: u32,
    more: bool,
    queued: bool,
    queued_lo: f32,
    queued_hi: f32,
}

/// The state before the first panel, [lo, hi].
fn airlight_adaptive(lo: f32, hi: f32) -> AirlightAdaptive {
    return AirlightAdaptive(AirlightPanelList(@ZEROS_SEGMENT_LIST@), 0u, lo, hi, 0u, true, false, 0.0, 0.0);
}

/// The state after the panel just evaluated (its Kronrod and Gauss sums) is listed, with the
/// next: the rest of the first `panels` panels between `edges`, a split's second half, or the
/// first half of the panel of the largest error (airlight_split_worst).
fn airlight_adaptive_step(state: AirlightAdaptive, kronrod: f32, gauss: f32, edges: array<f32, AIRLIGHT_OUTER_EDGES>, panels: u32, max_panels: u32, tolerance: f32) -> AirlightAdaptive {
    var st = state;
    var list = st.list;
    airlight_list_set(&list, st.slot, vec4<f32>(st.lo, st.hi, kronrod, abs(kronrod - gauss)));
    if (st.slot == st.count) { st.count += 1u; }
    let count = st.count;
    if (count < panels) {
        st.lo = edges[count];
        st.hi = edges[count + 1u];
        st.slot = count;
    } else if (st.queued) {
        st.lo = st.queued_lo;
        st.hi = st.queued_hi;
        st.slot = count;
        st.queued = false;
    } else {
        let next = airlight_split_worst(&list, count, max_panels, tolerance);
        st.lo = next.lo;
        st.hi = next.mid;
        st.slot = next.slot;
        st.more = next.split;
        st.queued = true;
        st.queued_lo = next.mid;
        st.queued_hi = next.hi;
    }
    st.list = list;
    return st;
}

/// asinh x: log1p(|x| + x²/(1 + √(1 + x²))) (no cancellation for x < 0, where Vulkan's asinh
/// may take log(x + √(x² + 1))); ln 2 + ln|x| beyond 2^12, where the omitted 1/(4x²) < 2^-26.
fn airlight_asinh(x: f32) -> f32 {
    let a = abs(x);
    var r = AIRLIGHT_LN_2 + log(a);
    if (a <= 4096.0) {
        r = airlight_log1p(a + a * a / (1.0 + sqrt(1.0 + a * a)));
    }
    return select(r, -r, x < 0.0);
}

/// An outer integral: a point light (one node), a segment light — s(w) = s* + scale·sinh w
/// (scale > 0) or w, the emitter point a + s·e, the panel edges in w — or a Lambertian surface
/// point — the frame (ℓ, u: the normal's direction across ℓ), the normal's cos α, sin α, the
/// pieces' edges in γ; the panels' edges in x are the integers, x ∈ [i, i + 1] ↦ γ by the
/// smoothstep of piece i.
struct AirlightOuter {
    a: vec3<f32>,
    e: vec3<f32>,
    s_star: f32,
    scale: f32,
    edges: array<f32, AIRLIGHT_OUTER_EDGES>,
    /// Panels between the edges (a point light: one, [0, 0]).
    panels: u32,
    /// 0: integrate; 1: the result is 0; 2: the emitter meets the ray segment, or the light the
    /// surface point (+∞).
    outcome: u32,
    /// The most panels.
    max_panels: u32,
    l: vec3<f32>,
    u: vec3<f32>,
    cos_a: f32,
    sin_a: f32,
    gamma: array<f32, AIRLIGHT_OUTER_EDGES>,
    /// A Phong lobe: the mirror direction's cos α_r, sin α_r and α_r, and Δ = φ_n − φ_r, its
    /// cosine and sine (the normal at φ_n = 0).
    cos_r: f32,
    sin_r: f32,
    alpha_r: f32,
    delta: vec3<f32>,
    /// A surface point's distance to the light, and the light's axis along ℓ and u.
    d: f32,
    axis_l: f32,
    axis_u: f32,
    /// Bit i: the edge gamma[i] is a smooth cut (a Phong lobe's peak or extent), no arc's end.
    smooth_edges: u32,
}

fn airlight_to_w(g: AirlightOuter, s: f32) -> f32 {
    if (g.scale > 0.0) { return airlight_asinh((s - g.s_star) / g.scale); }
    return s;
}

/// (cos x, sin x) for x ∈ [0, π], sin x to its own relative precision next to 0 and π (the
/// polar angles' sin is a solid angle's measure): `airlight_cos_sin` of x, or of π − x reflected
/// (from cos and sin of x − π/2, sin x was ~2e-7 off absolute next to 0: a sphere's θ rule cut at
/// LOBE_TAIL was 1.6e-4 off with it, docs/DESIGN.md §12).
fn airlight_cos_sin_half_turn(x: f32) -> vec2<f32> {
    if (x <= 0.5 * AIRLIGHT_PI) {
        return airlight_cos_sin(x);
    }
    let r = airlight_cos_sin(AIRLIGHT_PI - x);
    return vec2<f32>(-r.x, r.y);
}

/// acos x for |x| ≤ 1: 2 atan √((1 − |x|)/(1 + |x|)), reflected for x < 0 (Vulkan's acos
/// inherits atan's 4096 ulp).
fn airlight_acos(x: f32) -> f32 {
    let a = abs(x);
    let half = airlight_atan(sqrt((1.0 - a) / (1.0 + a)));
    return select(half + half, AIRLIGHT_PI - half - half, x < 0.0);
}

/// The angle α ∈ [0, π] with (cos α, sin α) ∝ (c, s), s ≥ 0: one atan (airlight_atan2_upper),
/// not four branches — every ray of the compute shader runs the surface's setup on a driver that
/// masks branches (lavapipe), so a branch per octant cost them all four.
fn airlight_angle(c: f32, s: f32) -> f32 {
    return airlight_atan2_upper(s, c);
}

/// The half-arc ψ ∈ [0, π] of the hemisphere about a direction at α from ℓ, at γ: where
/// cos α cos γ + sin α sin γ cos(φ − φ_α) > 0 (surface.rs half_arc).
fn airlight_half_arc(cos_a: f32, sin_a: f32, cos_g: f32, sin_g: f32) -> f32 {
    let a = cos_a * cos_g;
    let b = sin_a * sin_g;
    if (b <= abs(a)) { return select(0.0, AIRLIGHT_PI, a > 0.0); }
    return airlight_acos(clamp(-a / b, -1.0, 1.0));
}

/// The outer integral of a point light (one panel, [0, 0]), bounded at `max_panels`: where the
/// others start.
fn airlight_outer_point(s: AirlightScene, max_panels: u32) -> AirlightOuter {
    // zeros written out (naga's HLSL back end emits an array's zero value as invalid HLSL)
    let zeros = array<f32, AIRLIGHT_OUTER_EDGES>(0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0);
    return AirlightOuter(s.light_position, vec3<f32>(0.0), 0.0, 0.0, zeros, 1u, 0u, max_panels, vec3<f32>(0.0),
        vec3<f32>(0.0), 0.0, 0.0, zeros, 0.0, 0.0, 0.0, vec3<f32>(0.0, 1.0, 0.0), 0.0, 0.0, 0.0, 0u);
}

/// A surface point's outer integral (surface.rs SurfaceScene::integrate).
fn airlight_surface(s: AirlightScene) -> AirlightOuter {
    var g = airlight_outer_point(s, AIRLIGHT_SURFACE_PANELS);
    let to_light = s.light_position - s.origin;
    let d = airlight_safe_length(to_light);
    if (s.intensity == 0.0 || s.sigma_s == 0.0) {
        g.outcome = 1u;
        return g;
    }
    if (!(d > 0.0)) {
        g.outcome = 2u;
        return g;
    }
    if (s.brdf_scale == 0.0) {
        g.outcome = 1u;
        return g;
    }
    let l = to_light / d;
    let n = airlight_normalize(s.dir);
    let cos_a = dot(n, l);
    let across = n - cos_a * l;
    let sin_a = airlight_safe_length(across);
    // the normal's direction across ℓ; any where the normal is ℓ (L_a depends on γ alone)
    var u = across / sin_a;
    if (!(sin_a > 0.0)) {
        let pick = select(vec3<f32>(1.0, 0.0, 0.0), vec3<f32>(0.0, 1.0, 0.0), abs(l.x) > 0.7);
        u = airlight_normalize(pick - dot(pick, l) * l);
    }
    g.l = l;
    g.u = u;
    g.d = d;
    let axis = airlight_normalize(s.light_axis);
    g.axis_l = dot(axis, l);
    g.axis_u = dot(axis, u);
    g.cos_a = cos_a;
    g.sin_a = sin_a;
    // the pieces: where the normal's arc changes kind, |π/2 − α| and π − |π/2 − α|; for a Phong
    // lobe also where its arc does, its peak α_r, its extent α_r ± 1.5/√n, ± 4/√n, and where the
    // arcs' ends meet (the great circles n·ω = 0 and r·ω = 0 cross at ±n × r)
    var cuts = array<f32, 11>(AIRLIGHT_FLT_MAX, AIRLIGHT_FLT_MAX, AIRLIGHT_FLT_MAX, AIRLIGHT_FLT_MAX, AIRLIGHT_FLT_MAX,
        AIRLIGHT_FLT_MAX, AIRLIGHT_FLT_MAX, AIRLIGHT_FLT_MAX, AIRLIGHT_FLT_MAX, AIRLIGHT_FLT_MAX, AIRLIGHT_FLT_MAX);
    let first = abs(0.5 * AIRLIGHT_PI - airlight_angle(cos_a, sin_a));
    cuts[0] = first;
    cuts[1] = AIRLIGHT_PI - first;
    if (s.surface_kind == AIRLIGHT_SURFACE_PHONG) {
        g.max_panels = AIRLIGHT_PHONG_PANELS;
        let v = airlight_normalize(s.brdf_view);
        let r = airlight_normalize(2.0 * dot(n, v) * n - v);
        let x = dot(r, u);
        let y = dot(r, cross(l, u));
        g.cos_r = dot(r, l);
        g.sin_r = sqrt(x * x + y * y);
        g.alpha_r = airlight_angle(g.cos_r, g.sin_r);
        if (g.sin_r > 0.0) {
            // Δ = φ_n − φ_r = −atan2(y, x)
            let phi_r = select(1.0, -1.0, y < 0.0) * airlight_angle(x, abs(y));
            g.delta = vec3<f32>(-phi_r, x / g.sin_r, -y / g.sin_r);
        }
        let first_r = abs(0.5 * AIRLIGHT_PI - g.alpha_r);
        cuts[2] = first_r;
        cuts[3] = AIRLIGHT_PI - first_r;
        cuts[4] = g.alpha_r;
        if (s.brdf_exponent > 1.0) {
            let width = 1.0 / sqrt(s.brdf_exponent);
            cuts[5] = g.alpha_r - 1.5 * width;
            cuts[6] = g.alpha_r + 1.5 * width;
            cuts[7] = g.alpha_r - 4.0 * width;
            cuts[8] = g.alpha_r + 4.0 * width;
        }
        let meet = cross(n, r);
        let norm = airlight_safe_length(meet);
        if (norm > AIRLIGHT_FLT_EPS) {
            let at = airlight_acos(clamp(dot(meet, l) / norm, -1.0, 1.0));
            cuts[9] = at;
            cuts[10] = AIRLIGHT_PI - at;
        }
    }
    // the cuts where an arc opens or closes (the rest are smooth: surface.rs piece_map)
    let kinks = array<f32, 6>(cuts[0], cuts[1], cuts[2], cuts[3], cuts[9], cuts[10]);
    // sorted (insertion), then those strictly inside and increasing kept (extended.rs edges_between)
    for (var i = 1u; i < 11u; i++) {
        let c = cuts[i];
        var j = i;
        while (j > 0u && cuts[j - 1u] > c) {
            cuts[j] = cuts[j - 1u];
            j -= 1u;
        }
        cuts[j] = c;
    }
    // only γ ∈ (α − π/2, α + π/2) sees the hemisphere, its end the normal's turning point
    // (surface.rs integrate): no panel is spent where every arc is empty
    let hi = select(AIRLIGHT_PI - first, AIRLIGHT_PI, cos_a < 0.0);
    g.gamma[0] = select(0.0, first, cos_a < 0.0);
    var k = 0u;
    for (var i = 0u; i < 11u; i++) {
        if (cuts[i] > g.gamma[k] && cuts[i] < hi) {
            k += 1u;
            g.gamma[k] = cuts[i];
        }
    }
    g.gamma[k + 1u] = hi;
    g.panels = k + 1u;
    for (var i = 0u; i <= g.panels; i++) { g.edges[i] = f32(i); }
    if (s.surface_kind == AIRLIGHT_SURFACE_PHONG) {
        for (var i = 1u; i <= k; i++) {
            let e = g.gamma[i];
            let kink = e == kinks[0] || e == kinks[1] || e == kinks[2] || e == kinks[3] || e == kinks[4] || e == kinks[5];
            g.smooth_edges |= select(1u << i, 0u, kink);
        }
    }
    return g;
}

/// A Phong lobe at one angle γ (surface.rs lobe_arcs): the normal's A, B, the lobe's
/// k = 2D/(C + D) and ln(C + D), Δ's cosine and sine, the exponent.
struct AirlightLobe {
    a: f32,
    b: f32,
    k: f32,
    log_peak: f32,
    cos_delta: f32,
    sin_delta: f32,
    exponent: f32,
}

/// (A + B cos(x − Δ))⁺ (C + D cos x)⁺ⁿ at x and at −x, x ∈ [0, π], summed, with s = sin(x/2):
/// the lobe is (C + D)(1 − k s²), even in x (surface.rs lobe_arcs).
fn airlight_lobe_at(q: AirlightLobe, x: f32) -> f32 {
    let half = airlight_cos_sin(0.5 * x);
    let s2 = half.y * half.y;
    let cos_x = 1.0 - 2.0 * s2;
    let sin_x = 2.0 * half.y * half.x;
    let even = q.a + q.b * cos_x * q.cos_delta;
    let odd = q.b * sin_x * q.sin_delta;
    let clip = max(even + odd, 0.0) + max(even - odd, 0.0);
    let fall = q.k * s2;
    if (fall < 1.0 && clip > 0.0) {
        return clip * exp(q.exponent * (q.log_peak + airlight_log1p(-fall)));
    }
    return 0.0;
}

/// The rule's node at u ∈ (0, 1) of the piece [lo, lo + w], times its Jacobian: in x itself,
/// or in the smoothstep of the piece.
fn airlight_lobe_node(q: AirlightLobe, lo: f32, w: f32, u: f32, smoothstep: bool) -> f32 {
    if (smoothstep) {
        return w * 6.0 * u * (1.0 - u) * airlight_lobe_at(q, lo + w * u * u * (3.0 - u - u));
    }
    return w * airlight_lobe_at(q, lo + w * u);
}

/// ∫ (A + B cos(x − Δ))⁺ (C + D cos x)⁺ⁿ dx over the circle at the angle γ (cos γ, sin γ = cs)
/// of a Phong surface's outer integral, ψ_n the normal's half-arc there (surface.rs lobe_arcs:
/// the lobe ended at AIRLIGHT_LN_LOBE_FLOOR of its peak, each node of [0, cut] serving x and −x,
/// the half-range cut at the normal's arc ends' distances from the peak, the kernel's
/// LOBE_RULE's 10 points on every piece).
fn airlight_lobe_arcs(g: AirlightOuter, cs: vec2<f32>, gamma: f32, psi_n: f32, exponent: f32) -> f32 {
    let c = g.cos_r * cs.x;
    let d = g.sin_r * cs.y;
    let peak = c + d;
    if (!(peak > 0.0)) { return 0.0; }
    let sin_gap = airlight_cos_sin(0.5 * (gamma - g.alpha_r)).y;
    let q = AirlightLobe(g.cos_a * cs.x, g.sin_a * cs.y, 2.0 * d / peak, airlight_log1p(-2.0 * sin_gap * sin_gap),
        g.delta.y, g.delta.z, exponent);
    // where the lobe ends: s² = (1 − floor^{1/n})/k (n = 0: 1/k, its arc), at most 1
    var reach = 1.0;
    if (exponent > 0.0) { reach = -airlight_expm1(AIRLIGHT_LN_LOBE_FLOOR / exponent); }
    let s2 = select(1.0, reach / q.k, reach < q.k);
    let cut = 2.0 * airlight_angle(sqrt(1.0 - s2), sqrt(s2));
    // the pieces' edges: the peak 0, the normal's arc ends' distances from it within cut, cut
    var inner = vec2<f32>(0.0);
    if (psi_n < AIRLIGHT_PI) {
        inner.x = abs(airlight_arc_end(g.delta.x - psi_n, cut));
        inner.y = abs(airlight_arc_end(g.delta.x + psi_n, cut));
    }
    if (inner.y < inner.x) { inner = inner.yx; }
    // a loop over the pieces, not three calls: a driver that runs a branch's straight-line code
    // for every lane (lavapipe) runs this for every ray of a dispatch, but a loop none of whose
    // lanes needs it only once
    let edges = array<f32, 4>(0.0, inner.x, inner.y, cut);
    let smoothstep = exponent < 1.0;
    var sum = 0.0;
    for (var i = 0u; i < 3u; i++) {
        sum += airlight_lobe_piece(q, edges[i], edges[i + 1u], smoothstep);
    }
    return sum;
}

/// An end of the normal's arc brought into (−π, π], or 0 (the peak, an edge already) where it
/// lies outside (−cut, cut).
fn airlight_arc_end(x: f32, cut: f32) -> f32 {
    var end = x;
    if (end > AIRLIGHT_PI) { end -= 2.0 * AIRLIGHT_PI; }
    if (end < -AIRLIGHT_PI) { end += 2.0 * AIRLIGHT_PI; }
    return select(0.0, end, end > -cut && end < cut);
}

/// The kernel's LOBE_RULE (surface.rs GL10): (u, weight/2) for the pairs of nodes u and 1 − u
/// on [0, 1].
fn airlight_lobe_rule() -> array<vec2<f32>, AIRLIGHT_LOBE_PAIRS> {
    return array<vec2<f32>, AIRLIGHT_LOBE_PAIRS>(@LOBE_RULE@);
}

/// The kernel's LOBE_RULE on the piece [lo, hi] of a lobe's arcs; 0 where it is empty or the
/// integrand vanishes at its middle (its sign is constant between the edges). The pairs of nodes
/// in a loop, as the pieces: lavapipe runs a loop whose lanes are all off once, where it would
/// run written-out code whole, and every ray of the compute shader reaches this code.
fn airlight_lobe_piece(q: AirlightLobe, lo: f32, hi: f32, smoothstep: bool) -> f32 {
    let w = hi - lo;
    if (!(w > 0.0) || !(airlight_lobe_at(q, lo + 0.5 * w) > 0.0)) { return 0.0; }
    let rule = airlight_lobe_rule();
    var sum = 0.0;
    for (var k = 0u; k < AIRLIGHT_LOBE_PAIRS; k++) {
        let node = rule[k];
        sum += node.y * (airlight_lobe_node(q, lo, w, node.x, smoothstep) + airlight_lobe_node(q, lo, w, 1.0 - node.x, smoothstep));
    }
    return sum;
}

/// The outer integral of a scene: a surface point's, a segment light's (extended.rs
/// SegmentScene::integrate) or a point light's.
fn airlight_outer(s: AirlightScene) -> AirlightOuter {
    if (s.surface_kind != AIRLIGHT_SURFACE_NONE) {
        return airlight_surface(s);
    }
    var g = airlight_outer_point(s, AIRLIGHT_SEGMENT_PANELS);
    if (s.light_shape != AIRLIGHT_SHAPE_SEGMENT) {
        return g;
    }
    let ab = s.light_end - s.light_position;
    let len = airlight_safe_length(ab);
    if (!(len > 0.0) || s.intensity == 0.0 || s.sigma_s == 0.0) {
        g.outcome = 1u;
        return g;
    }
    let e = ab / len;
    let d = airlight_normalize(s.dir);
    let w0 = s.light_position - s.origin;
    let cos_a = dot(e, d);
    let along_e = dot(e, w0);
    let along_d = dot(d, w0);
    let sin2 = 1.0 - cos_a * cos_a;
    let infinite = (s.flags & 1u) != 0u;
    // the emitter's closest approach to the ray's line: s*, the ray's t*, the distance ρ*
    var s_star = 0.0;
    var t_star = along_d;
    if (sin2 > AIRLIGHT_FLT_EPS) {
        s_star = (cos_a * along_d - along_e) / sin2;
        t_star = (along_d - cos_a * along_e) / sin2;
    }
    let rho = airlight_safe_length(w0 - d * t_star + e * s_star);
    let sin_a = sqrt(max(sin2, 0.0));
    if (rho == 0.0 && sin_a > 0.0 && s_star >= 0.0 && s_star <= len && s.t_min <= t_star && (infinite || t_star <= s.t_max)) {
        g.outcome = 2u;
        return g;
    }
    // sinh about s* where the lines are skew and the peak is narrower than the segment and
    // within a length of it; else s itself
    var scale = 0.0;
    if (sin_a > 0.0 && rho > 0.0) { scale = rho / sin_a; }
    let near = s_star > -len && s_star < len + len && scale < len;
    if (!(near && airlight_is_finite(airlight_asinh((len - s_star) / scale)) && airlight_is_finite(airlight_asinh(s_star / scale)))) {
        scale = 0.0;
    }
    g.e = e;
    g.s_star = s_star;
    g.scale = scale;
    // panels: split at the closest approach and where the light's foot passes a ray end; not at
    // the closest approach within half a unit of w of an end where the map is taken (extended.rs)
    var cuts = array<f32, 4>(AIRLIGHT_FLT_MAX, AIRLIGHT_FLT_MAX, AIRLIGHT_FLT_MAX, AIRLIGHT_FLT_MAX);
    var at = array<f32, 3>(s_star, (s.t_min - along_d) / cos_a, (s.t_max - along_d) / cos_a);
    let sliver = scale > 0.0 && min(-airlight_to_w(g, 0.0), airlight_to_w(g, len)) < 0.5;
    for (var i = 0u; i < 3u; i++) {
        if (i == 0u && sliver) { continue; }
        if (cos_a == 0.0 && i > 0u) { continue; }
        if (i == 2u && infinite) { continue; }
        if (at[i] > 0.0 && at[i] < len) { cuts[i] = airlight_to_w(g, at[i]); }
    }
    let edges = airlight_edges_between(airlight_to_w(g, 0.0), airlight_to_w(g, len), cuts);
    g.edges = edges.at;
    g.panels = edges.panels;
    return g;
}

/// One node of an outer integral: the point-light ray it evaluates and the weight of its
/// value; at weight 0 the node adds nothing and its ray is not evaluated (as the kernel's). A
/// surface point's ray comes with its canonical form (`exact`), known without a reduction.
struct AirlightNode {
    scene: AirlightScene,
    weight: f32,
    canonical: AirlightCanonical,
    exact: bool,
}

/// The node at `x` of the outer integral `g` of `s`.
fn airlight_outer_node(s: AirlightScene, g: AirlightOuter, x: f32) -> AirlightNode {
    var p = s;
    let none = airlight_no_canonical();
    p.light_shape = AIRLIGHT_SHAPE_POINT;
    p.surface_kind = AIRLIGHT_SURFACE_NONE;
    if (s.surface_kind != AIRLIGHT_SURFACE_NONE) {
        // piece i: γ = a + (b − a)(3t² − 2t³), t = x − i, or a + (b − a)t², b − (b − a)(1 − t)²,
        // a + (b − a)t where an end or both are smooth cuts (surface.rs piece_map)
        let i = min(u32(max(floor(x), 0.0)), g.panels - 1u);
        let t = x - f32(i);
        let a = g.gamma[i];
        let b = g.gamma[i + 1u];
        let w = b - a;
        let u = 1.0 - t;
        let smooth_a = ((g.smooth_edges >> i) & 1u) != 0u;
        let smooth_b = ((g.smooth_edges >> (i + 1u)) & 1u) != 0u;
        var gamma = a + w * t * t * (3.0 - t - t);
        var jacobian = w * 6.0 * t * u;
        gamma = select(gamma, a + w * t * t, smooth_b && !smooth_a);
        jacobian = select(jacobian, w * (t + t), smooth_b && !smooth_a);
        gamma = select(gamma, b - w * u * u, smooth_a && !smooth_b);
        jacobian = select(jacobian, w * (u + u), smooth_a && !smooth_b);
        gamma = select(gamma, a + w * t, smooth_a && smooth_b);
        jacobian = select(jacobian, w, smooth_a && smooth_b);
        if (!(jacobian > 0.0)) { return AirlightNode(p, 0.0, none, false); }
        let cs = airlight_cos_sin_half_turn(gamma);
        let psi = airlight_half_arc(g.cos_a, g.sin_a, cs.x, cs.y);
        if (!(psi > 0.0)) { return AirlightNode(p, 0.0, none, false); }
        var weight = 0.0;
        if (s.surface_kind == AIRLIGHT_SURFACE_LAMBERT) {
            // (ρ/π) ∫ (A + B cos x)⁺ over the arc = (ρ/π) 2(Aψ + B sin ψ)
            let arc = 2.0 * (g.cos_a * cs.x * psi + g.sin_a * cs.y * airlight_cos_sin_half_turn(psi).y);
            weight = s.brdf_scale * (1.0 / AIRLIGHT_PI) * arc;
        } else {
            let n = s.brdf_exponent;
            weight = s.brdf_scale * (n + 2.0) * (0.5 / AIRLIGHT_PI) * airlight_lobe_arcs(g, cs, gamma, psi, n);
        }
        p.dir = cs.x * g.l + cs.y * g.u;
        p.t_min = 0.0;
        p.t_max = 0.0;
        p.flags = 1u;
        // its canonical form (surface.rs `integrate`): the light at x_h = d cos γ, h = d sin γ
        // from the ray, the axis's cosines cos γ (ℓ·a) + sin γ (u·a) and cos γ (u·a) − sin γ (ℓ·a)
        let sin_g = max(cs.y, 0.0);
        let h = g.d * sin_g;
        let d_c = select(0.0, cs.x * g.axis_u - sin_g * g.axis_l, h > 0.0);
        let exact = AirlightCanonical(h, g.d * cs.x, cs.x * g.axis_l + sin_g * g.axis_u, d_c, 0.0, 0.0, true);
        return AirlightNode(p, weight * cs.y * jacobian, exact, true);
    }
    if (s.light_shape == AIRLIGHT_SHAPE_SEGMENT) {
        var at = x;
        var ds = 1.0;
        if (g.scale > 0.0) {
            at = g.s_star + g.scale * sinh(x);
            ds = g.scale * cosh(x);
        }
        p.light_position = g.a + at * g.e;
        return AirlightNode(p, ds, none, false);
    }
    return AirlightNode(p, 1.0, none, false);
}

// ---------------------------------------------------------------- area lights
// (kernel/src/area/outer.rs: the ray outside, the directions to the emitter inside)

// The ray's panels and tolerance (outer.rs BOUNDED_RAY_PANELS, BOUNDED_RAY_TOLERANCE).
const AIRLIGHT_AREA_RAY_PANELS: u32 = @AREA_RAY_PANELS@u;
const AIRLIGHT_AREA_RAY_TOLERANCE: f32 = @AREA_RAY_TOLERANCE@;
// How far outside a sphere's cap or a flat emitter, in radial scales, a phase lobe is taken about
// (outer.rs LOBE_REACH).
const AIRLIGHT_LOBE_REACH: f32 = @LOBE_REACH@;
// Where a sphere's θ range about a lobe is cut in two, radians past its start (outer.rs LOBE_TAIL).
const AIRLIGHT_LOBE_TAIL: f32 = @LOBE_TAIL@;
// The widest lobe a sphere is taken about from beside it (outer.rs BESIDE_SCALE).
const AIRLIGHT_BESIDE_SCALE: f32 = @BESIDE_SCALE@;
// How far inside a flat emitter's edge, in heights above its plane, its foot is taken about
// (outer.rs EDGE_REACH).
const AIRLIGHT_EDGE_REACH: f32 = @EDGE_REACH@;
// Where a ray crosses a flat emitter's plane near an edge, in a narrow phase lobe, how far from
// the crossing, in lobe scales of the edge's distance, a ray panel ends (outer.rs CROSSING_REACH).
const AIRLIGHT_CROSSING_REACH: f32 = @CROSSING_REACH@;
// The largest power of an emission lobe (area.rs Emission::MAX_POWER).
const AIRLIGHT_EMISSION_MAX_POWER: u32 = @EMISSION_MAX_POWER@u;

/// Gauss–Kronrod 7/15 (extended.rs GAUSS_KRONROD_15): (x ≥ 0 descending, Kronrod weight, Gauss
/// weight or 0); the rule takes ±x.
fn airlight_kronrod15_rule() -> array<vec3<f32>, 8> {
    return array<vec3<f32>, 8>(@KRONROD15_RULE@);
}

/// The azimuths of outer.rs AZIMUTHAL (Gauss–Legendre, 32 points) as (cos ψ, sin ψ, weight): over
/// the circle ψ ∈ [0, 2π] (`circle`) or the half ψ ∈ [−π/2, π/2].
fn airlight_azimuths(circle: bool, i: u32) -> vec3<f32> {
    let full = array<vec3<f32>, 32>(@AZIMUTHS_CIRCLE@);
    let half = array<vec3<f32>, 32>(@AZIMUTHS_HALF@);
    return select(half[i], full[i], circle);
}

/// The half's node j with ψ > 0, its weight doubled: its sum of an integrand even in ψ (outer.rs
/// `Azimuths::even`).
fn airlight_azimuths_even(j: u32) -> vec3<f32> {
    let az = airlight_azimuths(false, 2u * j + 1u);
    return vec3<f32>(az.xy, 2.0 * az.z);
}

/// outer.rs TRIANGLE_AZIMUTHAL (Gauss–Legendre, 12 points) on [−1, 1]: (x, weight).
fn airlight_triangle_rule(i: u32) -> vec2<f32> {
    let rule = array<vec2<f32>, 12>(@TRIANGLE_RULE@);
    return rule[i];
}

/// An area light as its ray integral takes it (outer.rs `in_scatter_bounded`): the ray's unit
/// direction; the emitter — a disc's or a sphere's centre `c` and radius, a parallelogram's
/// corner `c` and edges `eu`, `ev` — with a flat one's unit normal `n` and plane vectors `a1`,
/// `a2`, and their dot products with the ray's direction (`dirs`); the ray's map `t − x_h =
/// h' tan θ` and its first panels' edges in θ; the phase function's lobes.
struct AirlightArea {
    d: vec3<f32>,
    c: vec3<f32>,
    n: vec3<f32>,
    a1: vec3<f32>,
    a2: vec3<f32>,
    eu: vec3<f32>,
    ev: vec3<f32>,
    dirs: vec3<f32>,
    radius: f32,
    x_h: f32,
    h_eff: f32,
    edges: array<f32, AIRLIGHT_OUTER_EDGES>,
    panels: u32,
    /// 0: integrate; 1: the result is 0.
    outcome: u32,
    /// The lobes at μ = ±1 (outer.rs `lobes`): (sign, radial scale s) each, s = 0 for none.
    lobes: vec4<f32>,
    /// A constant phase function (outer.rs `constant_phase`).
    isotropic: bool,
    /// A sphere's place from the ray's line (outer.rs `SphereFoot`).
    foot: AirlightSphereFoot,
}

/// P(μ) of the scene's phase function.
fn airlight_area_phase(s: AirlightScene, mu: f32) -> f32 {
    return airlight_phase_mu(s.phase_kind, s.phase_param_a, s.phase_param_b, s.phase_param_c, mu);
}

/// P(sign·cos θ) at the angle θ from a lobe's direction sign·d, given (cos θ, sin θ), with
/// 1 ∓ cos θ to their relative precision as sin²θ/(1 ± cos θ) (outer.rs `Light::phase_about`).
fn airlight_area_phase_about(s: AirlightScene, sign: f32, cs: vec2<f32>) -> f32 {
    let ss = cs.y * cs.y;
    var near = ss / (1.0 + cs.x);
    var far = 1.0 + cs.x;
    if (cs.x < 0.0) {
        near = 1.0 - cs.x;
        far = ss / (1.0 - cs.x);
    }
    let om = select(far, near, sign > 0.0);
    let op = select(near, far, sign > 0.0);
    return airlight_phase(s.phase_kind, s.phase_param_a, s.phase_param_b, s.phase_param_c, sign * cs.x, om, op);
}

/// L_e c^{p−1} (outer.rs `emitted`): the power p in `light_param_b`, c^{p−1} by repeated squaring
/// in the order of Rust's `powi` (compiler-rt `__powisf2`), written out: no loop iterations.
fn airlight_emitted(s: AirlightScene, c: f32) -> f32 {
    let p = u32(s.light_param_b);
    if (p <= 1u) { return s.intensity; }
    var e = p - 1u;
    var base = c;
    var acc = 1.0;
@EMISSION_POWER_STEPS@    return s.intensity * acc;
}

/// The width scale s = 2/√(p − 1) of the emission's lobe c^{p−1} (outer.rs `Light::emission_scale`);
/// 0 for p = 1.
fn airlight_emission_scale(s: AirlightScene) -> f32 {
    let p = u32(s.light_param_b);
    if (p <= 1u) { return 0.0; }
    return 2.0 / sqrt(f32(p - 1u));
}

/// outer.rs `graded_radial`'s rule on [0, top]: (the range of ϑ, the scale s) where the emission
/// lobe's scale s is below `top`, (top, 0) where the nodes are not graded.
fn airlight_graded_range(s: AirlightScene, top: f32) -> vec2<f32> {
    let scale = airlight_emission_scale(s);
    if (scale > 0.0 && scale < top) { return vec2<f32>(airlight_atan(top / scale), scale); }
    return vec2<f32>(top, 0.0);
}

/// A node ϑ of that rule as (x, dx/dϑ): (s tan ϑ, s/cos²ϑ) for s = `graded` > 0, else (ϑ, 1).
fn airlight_graded_node(graded: f32, node: f32) -> vec2<f32> {
    if (graded > 0.0) {
        let t = airlight_cos_sin_half_turn(node);
        return vec2<f32>(graded * t.y / t.x, graded / (t.x * t.x));
    }
    return vec2<f32>(node, 1.0);
}

/// Whether a flat emitter is taken about the foot `depth` inside its edge at the height z
/// (outer.rs `Light::far_from_edge`): depth ≥ EDGE_REACH·z·min(1, s).
fn airlight_far_from_edge(s: AirlightScene, depth: f32, z: f32) -> bool {
    return depth >= AIRLIGHT_EDGE_REACH * airlight_narrowed(s, z);
}

/// length·min(1, s), s the emission lobe's scale (outer.rs `Light::narrowed`).
fn airlight_narrowed(s: AirlightScene, length: f32) -> f32 {
    let scale = airlight_emission_scale(s);
    return length * select(1.0, min(scale, 1.0), scale > 0.0);
}

/// A lobe of Henyey–Greenstein form at its singular cosine's gap `gap` (|μ*| − 1) on the side of
/// `sign`: (sign, 2√(2 gap)), or none (outer.rs `lobes`).
fn airlight_lobe(sign: f32, gap: f32) -> vec2<f32> {
    if (!(gap > 0.0) || !(gap < AIRLIGHT_FLT_MAX)) { return vec2<f32>(1.0, 0.0); }
    return vec2<f32>(select(1.0, -1.0, sign < 0.0), 2.0 * sqrt(gap + gap));
}

/// The phase function's lobes (phase.rs `singularities`, outer.rs `lobes`).
fn airlight_phase_lobes(s: AirlightScene) -> vec4<f32> {
    let p0 = s.phase_param_a;
    var first = vec2<f32>(1.0, 0.0);
    var second = vec2<f32>(1.0, 0.0);
    switch s.phase_kind {
        case AIRLIGHT_PHASE_HENYEY_GREENSTEIN, AIRLIGHT_PHASE_CORNETTE_SHANKS: { first = airlight_lobe(p0, airlight_hg_gap(p0)); }
        case AIRLIGHT_PHASE_SCHLICK: {
            let a = abs(p0);
            first = airlight_lobe(p0, select(AIRLIGHT_FLT_MAX, (1.0 - a) / a, a > 0.0));
        }
        case AIRLIGHT_PHASE_TWO_LOBE_HG: {
            first = airlight_lobe(p0, airlight_hg_gap(p0));
            second = airlight_lobe(s.phase_param_b, airlight_hg_gap(s.phase_param_b));
        }
        default: {}
    }
    return vec4<f32>(first, second);
}

/// Two unit vectors completing the unit `n` to a right-handed frame (geometry.rs `basis`).
fn airlight_basis_e1(n: vec3<f32>) -> vec3<f32> {
    let m = abs(n);
    var u = vec3<f32>(0.0, 0.0, 1.0);
    if (m.x <= m.y && m.x <= m.z) {
        u = vec3<f32>(1.0, 0.0, 0.0);
    } else if (m.y <= m.z) {
        u = vec3<f32>(0.0, 1.0, 0.0);
    }
    return airlight_normalize(cross(u, n));
}

/// The angle θ of the ray's point `t` seen from the emitter's centre: atan((t − x_h)/h'), π/2 at
/// +∞ (outer.rs `theta`).
fn airlight_area_theta(a: AirlightArea, t: f32, infinite: bool) -> f32 {
    if (infinite) { return 0.5 * AIRLIGHT_PI; }
    return airlight_atan2(t - a.x_h, a.h_eff);
}

/// The ray integral's setup (outer.rs `in_scatter_bounded`): the emitter's frame, its centre and
/// size, and the first panels' edges — at the centre's foot, where the ray crosses a flat
/// emitter's plane (and, in a narrow phase lobe, CROSSING_REACH lobe scales of an edge's distance
/// from it) and where it enters and leaves a sphere — cut where the extinction has grown by
/// −ln ε past the emitter's far side.
fn airlight_area(s: AirlightScene) -> AirlightArea {
    let zero = vec3<f32>(0.0);
    var a = AirlightArea(zero, s.light_position, zero, zero, zero, zero, zero, zero, s.light_param_a, 0.0, 0.0,
        array<f32, AIRLIGHT_OUTER_EDGES>(0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0), 0u, 0u, airlight_phase_lobes(s),
        false, AirlightSphereFoot(zero, 0.0, 0.0));
    a.isotropic = airlight_isotropic_phase(s);
    if (s.intensity == 0.0 || s.sigma_s == 0.0) {
        a.outcome = 1u;
        return a;
    }
    let o = s.origin;
    let d = airlight_normalize(s.dir);
    a.d = d;
    let infinite = (s.flags & 1u) != 0u;
    let t0 = s.t_min;
    // where the ray's integrand changes its form besides the centre's foot (`cuts`: none set
    // stand for the foot again, which the edges drop as a repeat): `cut_count` of them
    var cut_count = 0u;
    var cut0 = 0.0;
    var cut1 = 0.0;
    // a flat emitter's: its plane's crossing's distances from the nearest edge and the next, and
    // the emitting side along the ray
    var distances = vec2<f32>(AIRLIGHT_FLT_MAX);
    var front = 1.0;
    var centre = s.light_position;
    var size = s.light_param_a;
    if (s.light_shape == AIRLIGHT_SHAPE_SPHERE) {
        // entry and exit: t² + 2bt + k = 0, its discriminant b² − k = −(ρ − R)(ρ + R) from the
        // centre's distance ρ to the ray's line and its miss (b² − k itself cancels for a
        // grazing ray)
        let oc = o - a.c;
        let b = dot(oc, d);
        let k = dot(oc, oc) - a.radius * a.radius;
        // 0 for every record (flags has one defined bit), undecidable by the compiler
        let key = u32(s.flags > 1u);
        a.foot = airlight_sphere_foot(o, s.dir, a.c, a.radius, key);
        let disc = -a.foot.miss * (a.foot.h + a.radius);
        if (disc > 0.0) {
            let root = sqrt(disc);
            let q = -b - select(root, -root, (bitcast<u32>(b) & 0x80000000u) != 0u);
            cut0 = q;
            cut1 = k / q;
            cut_count = 2u;
        }
    } else {
        if (s.light_shape == AIRLIGHT_SHAPE_DISC) {
            a.n = airlight_normalize(s.light_axis);
            a.a1 = airlight_basis_e1(a.n);
        } else {
            a.eu = s.light_axis;
            a.ev = s.light_end;
            a.n = airlight_normalize(cross(a.eu, a.ev));
            a.a1 = airlight_normalize(a.eu);
            let diagonal = a.eu + a.ev;
            centre = a.c + 0.5 * diagonal;
            size = 0.5 * max(airlight_safe_length(diagonal), airlight_safe_length(a.eu - a.ev));
        }
        a.a2 = cross(a.n, a.a1);
        a.dirs = vec3<f32>(dot(a.a1, d), dot(a.a2, d), dot(a.n, d));
        cut0 = dot(a.c - o, a.n) / dot(d, a.n);
        cut_count = 1u;
        distances = airlight_outline_distances(airlight_outline_at(s, a, o + cut0 * d));
        front = select(1.0, -1.0, dot(d, a.n) < 0.0);
    }
    if (!(size > 0.0)) {
        a.outcome = 1u;
        return a;
    }
    let to_centre = centre - o;
    a.x_h = dot(to_centre, d);
    let h = airlight_safe_length(to_centre - a.x_h * d);
    a.h_eff = sqrt(h * h + size * size);
    var t_end = s.t_max;
    var end_infinite = infinite;
    if (s.sigma_t > 0.0) {
        let reach = t0 + airlight_safe_length(centre - (o + t0 * d)) + size - log(AIRLIGHT_FLT_EPS) / s.sigma_t;
        if (infinite || reach < t_end) {
            t_end = reach;
            end_infinite = false;
        }
    }
    let lo = airlight_area_theta(a, t0, false);
    let hi = airlight_area_theta(a, t_end, end_infinite);
    // the cuts within [t0, t_end] (outside it: its start, which the edges skip)
    var cuts = array<f32, 4>(a.x_h, select(a.x_h, cut0, cut_count > 0u), select(a.x_h, cut1, cut_count > 1u), a.x_h);
    // a flat emitter's plane crossed δ from an edge in a phase lobe of scale s < 1: a panel ends
    // CROSSING_REACH·δ/s from the crossing on the emitting side, for the nearest edge and the
    // next, unless the θ map's own scale h' is shorter
    var scale = 1.0;
    if (a.lobes.y > 0.0) { scale = min(scale, a.lobes.y); }
    if (a.lobes.w > 0.0) { scale = min(scale, a.lobes.w); }
    if (cut_count == 1u && scale < 1.0 && cut0 >= t0 && (end_infinite || cut0 <= t_end)) {
        for (var i = 0u; i < 2u; i++) {
            let reach = AIRLIGHT_CROSSING_REACH * distances[i] / scale;
            if (reach < a.h_eff) { cuts[i + 2u] = cut0 + front * reach; }
        }
    }
    for (var i = 0u; i < 4u; i++) {
        let t = cuts[i];
        cuts[i] = lo;
        if (airlight_is_finite(t) && t >= t0 && (end_infinite || t <= t_end)) { cuts[i] = airlight_area_theta(a, t, false); }
    }
    let edges = airlight_edges_between(lo, hi, cuts);
    a.edges = edges.at;
    a.panels = edges.panels;
    return a;
}

/// A point above a flat emitter's plane (outer.rs `Above`): its height z > 0, q* − foot in the
/// plane's coordinates, ρ₀ = |x − q*|.
struct AirlightAbove {
    z: f32,
    off: vec2<f32>,
    rho0: f32,
}

fn airlight_above(z: f32, off: vec2<f32>) -> AirlightAbove {
    return AirlightAbove(z, off, sqrt(z * z + off.x * off.x + off.y * off.y));
}

/// One node of `airlight_flat_radial`: L_e c^{p−1} P e^{−σt d} z/d³ r dr/dγ at r = ρ₀ tan γ along
/// `e`, γ the node, or s tan of it where the rule is graded by s = `graded` > 0 (times s/cos²).
fn airlight_flat_node(s: AirlightScene, a: AirlightArea, above: AirlightAbove, e: vec2<f32>, graded: f32, node: f32) -> f32 {
    let at = airlight_graded_node(graded, node);
    let cs = airlight_cos_sin_half_turn(at.x);
    let r = above.rho0 * cs.y / cs.x;
    let dr = above.rho0 / (cs.x * cs.x);
    let p = above.off + r * e;
    let z = above.z;
    let dist = sqrt(z * z + p.x * p.x + p.y * p.y);
    let inv = 1.0 / dist;
    let cos = z * inv;
    let phase = airlight_area_phase(s, (p.x * a.dirs.x + p.y * a.dirs.y - z * a.dirs.z) * inv);
    return at.y * airlight_emitted(s, cos) * exp(min(-s.sigma_t * dist, 0.0)) * phase * cos * inv * inv * r * dr;
}

/// ∫ L_e c^{p−1} P e^{−σt d} z/d³ r dr along the direction `e` from q* out to `r_max`, in γ
/// (outer.rs `radial`): Gauss–Legendre RADIAL, written out, graded towards γ = 0 by an emission
/// lobe narrower than the range (outer.rs `graded_radial`).
fn airlight_flat_radial(s: AirlightScene, a: AirlightArea, above: AirlightAbove, e: vec2<f32>, r_max: f32) -> f32 {
    let range = airlight_graded_range(s, airlight_atan(r_max / above.rho0));
    let graded = range.y;
    let c = 0.5 * range.x;
    let hw = 0.5 * range.x;
    var sum = 0.0;
@RADIAL_FLAT@    return sum;
}

/// S(x) of a disc (outer.rs `disc`): about the foot over the circle, or with the foot outside,
/// about the rim's point nearest it over the half towards the centre.
fn airlight_disc(s: AirlightScene, a: AirlightArea, x: vec3<f32>) -> f32 {
    let rel = x - a.c;
    let z = dot(rel, a.n);
    if (!(z > 0.0)) { return 0.0; }
    let fx = dot(rel, a.a1);
    let fy = dot(rel, a.a2);
    let rf = sqrt(fx * fx + fy * fy);
    let radius = a.radius;
    let zero = vec2<f32>(0.0);
    let outline = AirlightOutline(array<vec2<f32>, 4>(vec2<f32>(-fx, -fy), zero, zero, zero), radius);
    let lobe = airlight_flat_lobe(a, z, outline, vec2<f32>(-fx, -fy), radius);
    if (lobe.scale > 0.0) {
        return airlight_flat_about_lobe(s, z, outline, lobe);
    }
    // about the foot where it is on the disc and not near its rim (outer.rs `disc`)
    let inside = rf <= radius && (rf == 0.0 || airlight_far_from_edge(s, radius - rf, z));
    // else u towards the centre, q* on the rim
    var u = vec2<f32>(0.0);
    var above = airlight_above(z, vec2<f32>(0.0));
    if (!inside) {
        u = vec2<f32>(-fx / rf, -fy / rf);
        above = airlight_above(z, (rf - radius) * u);
    }
    let k = (rf - radius) * (rf + radius);
    var sum = 0.0;
    for (var i = 0u; i < 32u; i++) {
        let az = airlight_azimuths(inside, i);
        var e = vec2<f32>(az.x * u.x - az.y * u.y, az.x * u.y + az.y * u.x);
        var r_max = (radius + radius) * az.x;
        if (inside) {
            // the chord to the rim along e, the positive root of r² + 2br + k = 0
            e = az.xy;
            let b = fx * az.x + fy * az.y;
            let root = sqrt(b * b - k);
            r_max = select(root - b, -k / (b + root), b > 0.0);
        }
        sum += az.z * airlight_flat_radial(s, a, above, e, r_max);
    }
    return sum;
}

/// S(x) of the parallelogram c + u·eu + v·ev (outer.rs `parallelogram`): the triangles from q*
/// (the foot, or the nearest point of the edges) to its edges.
fn airlight_parallelogram(s: AirlightScene, a: AirlightArea, x: vec3<f32>) -> f32 {
    let rel = x - a.c;
    let z = dot(rel, a.n);
    if (!(z > 0.0)) { return 0.0; }
    let foot = vec2<f32>(dot(rel, a.a1), dot(rel, a.a2));
    let u2 = vec2<f32>(dot(a.eu, a.a1), dot(a.eu, a.a2));
    let v2 = vec2<f32>(dot(a.ev, a.a1), dot(a.ev, a.a2));
    // counter-clockwise about n
    let corners = array<vec2<f32>, 5>(vec2<f32>(0.0), u2, u2 + v2, v2, vec2<f32>(0.0));
    let det = u2.x * v2.y - u2.y * v2.x;
    let about_foot = AirlightOutline(array<vec2<f32>, 4>(corners[0] - foot, corners[1] - foot, corners[2] - foot, corners[3] - foot), 0.0);
    let size = 0.5 * max(sqrt(dot(u2 + v2, u2 + v2)), sqrt(dot(u2 - v2, u2 - v2)));
    let lobe = airlight_flat_lobe(a, z, about_foot, 0.5 * corners[2] - foot, size);
    if (lobe.scale > 0.0) {
        return airlight_flat_about_lobe(s, z, about_foot, lobe);
    }
    // about the foot where it is on the emitter and not near its edge, else the edge's nearest point
    let edge = airlight_outline_boundary(about_foot, vec2<f32>(0.0));
    var q = edge.xy + foot;
    if (edge.z > 0.0 && airlight_far_from_edge(s, sqrt(dot(edge.xy, edge.xy)), z)) { q = foot; }
    let above = airlight_above(z, q - foot);
    // a triangle (q*, C_i, C_{i+1}) without area (q* on its edge) is left out
    let thin = AIRLIGHT_FLT_EPS * abs(det);
    let width = airlight_narrowed(s, above.rho0);
    var sum = 0.0;
    for (var i = 0u; i < 4u; i++) {
        let ca = corners[i] - q;
        let cb = corners[i + 1u] - q;
        if (!(ca.x * cb.y - ca.y * cb.x > thin)) { continue; }
        let rule = airlight_edge_rule(ca, cb, width);
        for (var j = 0u; j < 12u; j++) {
            let node = airlight_edge_node(rule, j);
            sum += node.w * airlight_flat_radial(s, a, above, node.xy, node.z);
        }
    }
    return sum;
}

/// An edge a → b seen from the origin on its left (outer.rs `edge_rule`): its points h m + σ t
/// (distance h, outward normal m = (t.y, −t.x), direction t), σ = D tan β, D = hypot(h, width),
/// β from `first` to `last`.
struct AirlightEdgeRule {
    h: f32,
    t: vec2<f32>,
    reach: f32,
    first: f32,
    last: f32,
}

/// outer.rs `edge_rule`'s rule on the edge a → b (a × b > 0) with the width `width`.
fn airlight_edge_rule(a: vec2<f32>, b: vec2<f32>, width: f32) -> AirlightEdgeRule {
    let e = b - a;
    let el = sqrt(e.x * e.x + e.y * e.y);
    let t = e / el;
    let h = (a.x * b.y - a.y * b.x) / el;
    let reach = sqrt(h * h + width * width);
    return AirlightEdgeRule(h, t, reach, airlight_atan2(dot(a, t), reach), airlight_atan2(dot(b, t), reach));
}

/// Node j of TRIANGLE_AZIMUTHAL on that rule: (the point's direction, its distance r, the weight
/// in the angle ψ at the origin, dψ = h dσ/(h² + σ²)).
fn airlight_edge_node(rule: AirlightEdgeRule, j: u32) -> vec4<f32> {
    let node = airlight_triangle_rule(j);
    let hw = 0.5 * (rule.last - rule.first);
    let at = airlight_edge_at(rule, 0.5 * (rule.first + rule.last) + hw * node.x);
    return vec4<f32>(at.xyz, node.y * hw * at.w);
}

/// The point of that rule's line at β: (its direction, its distance r, dψ/dβ) (outer.rs
/// `line_rule`).
fn airlight_edge_at(rule: AirlightEdgeRule, beta: f32) -> vec4<f32> {
    // (cos β, sin β) from the half turn's (−sin, cos) at β + π/2 ∈ (0, π)
    let turn = airlight_cos_sin_half_turn(beta + 0.5 * AIRLIGHT_PI);
    let sigma = rule.reach * -turn.x / turn.y;
    let r2 = rule.h * rule.h + sigma * sigma;
    let r = sqrt(r2);
    let m = vec2<f32>(rule.t.y, -rule.t.x);
    return vec4<f32>((rule.h * m + sigma * rule.t) / r, r, rule.h * rule.reach / (turn.y * turn.y * r2));
}

/// A flat emitter's outline in its plane's coordinates about x's foot (outer.rs `Outline`): a
/// disc's centre `corners[0]` and radius, or (radius 0) a parallelogram's corners,
/// counter-clockwise about the normal.
struct AirlightOutline {
    corners: array<vec2<f32>, 4>,
    radius: f32,
}

/// The chord `[lo, hi]` of q + r e clipped by the half-plane inside the edge a → b (outer.rs
/// `Outline::chord`, Cyrus–Beck); an empty chord (lo ≥ hi) stays empty.
fn airlight_clip(chord: vec2<f32>, a: vec2<f32>, b: vec2<f32>, q: vec2<f32>, e: vec2<f32>) -> vec2<f32> {
    let m = vec2<f32>(b.y - a.y, a.x - b.x);
    let num = (q.x - a.x) * m.x + (q.y - a.y) * m.y;
    let den = e.x * m.x + e.y * m.y;
    if (den > 0.0) { return vec2<f32>(chord.x, min(chord.y, -num / den)); }
    if (den < 0.0) { return vec2<f32>(max(chord.x, -num / den), chord.y); }
    if (num > 0.0) { return vec2<f32>(1.0, 0.0); }
    return chord;
}

/// The interval `[lo, hi]` of r ≥ 0 for which q + r e lies on the emitter, empty (lo ≥ hi) if the
/// half-line misses it (outer.rs `Outline::chord`); the edges written out, not a loop.
fn airlight_outline_chord(o: AirlightOutline, q: vec2<f32>, e: vec2<f32>) -> vec2<f32> {
    if (o.radius > 0.0) {
        // r² a + 2 r b + k = 0
        let qc = q - o.corners[0];
        let a = e.x * e.x + e.y * e.y;
        let b = qc.x * e.x + qc.y * e.y;
        let dq = sqrt(qc.x * qc.x + qc.y * qc.y);
        let k = (dq - o.radius) * (dq + o.radius);
        let disc = b * b - a * k;
        if (!(disc > 0.0)) { return vec2<f32>(0.0); }
        let root = sqrt(disc);
        let t = -b - select(root, -root, (bitcast<u32>(b) & 0x80000000u) != 0u);
        let r1 = t / a;
        let r2 = k / t;
        let hi = max(r1, r2);
        if (!(hi > 0.0)) { return vec2<f32>(0.0); }
        return vec2<f32>(max(min(r1, r2), 0.0), hi);
    }
    var chord = vec2<f32>(0.0, AIRLIGHT_FLT_MAX);
    chord = airlight_clip(chord, o.corners[0], o.corners[1], q, e);
    chord = airlight_clip(chord, o.corners[1], o.corners[2], q, e);
    chord = airlight_clip(chord, o.corners[2], o.corners[3], q, e);
    return airlight_clip(chord, o.corners[3], o.corners[0], q, e);
}

/// The emitter's point nearest q, q itself on the emitter (outer.rs `Outline::nearest`).
fn airlight_outline_nearest(o: AirlightOutline, q: vec2<f32>) -> vec2<f32> {
    let edge = airlight_outline_boundary(o, q);
    return select(edge.xy, q, edge.z > 0.0);
}

/// The point of the emitter's edge nearest q, and 1 if q is on the emitter, else 0 (outer.rs
/// `Outline::boundary`).
fn airlight_outline_boundary(o: AirlightOutline, q: vec2<f32>) -> vec3<f32> {
    if (o.radius > 0.0) {
        let qc = q - o.corners[0];
        let dq = sqrt(qc.x * qc.x + qc.y * qc.y);
        return vec3<f32>(o.corners[0] + qc * o.radius / dq, select(0.0, 1.0, dq <= o.radius));
    }
    var best = AIRLIGHT_FLT_MAX;
    var nearest = q;
    var inside = true;
    for (var i = 0u; i < 4u; i++) {
        let a = o.corners[i];
        let b = o.corners[(i + 1u) % 4u];
        inside = inside && (q.x - a.x) * (b.y - a.y) - (q.y - a.y) * (b.x - a.x) <= 0.0;
        let p = airlight_edge_nearest(a, b, q);
        let dd = (p.x - q.x) * (p.x - q.x) + (p.y - q.y) * (p.y - q.y);
        if (dd < best) {
            best = dd;
            nearest = p;
        }
    }
    return vec3<f32>(nearest, select(0.0, 1.0, inside));
}

/// The point of the edge a → b nearest q (outer.rs `edge_nearest`).
fn airlight_edge_nearest(a: vec2<f32>, b: vec2<f32>, q: vec2<f32>) -> vec2<f32> {
    let e = b - a;
    return a + clamp(((q.x - a.x) * e.x + (q.y - a.y) * e.y) / (e.x * e.x + e.y * e.y), 0.0, 1.0) * e;
}

/// The distances of the foot (the origin) from the outline's nearest edge and from the next, a
/// circle's next FLT_MAX (outer.rs `Outline::distances`).
fn airlight_outline_distances(o: AirlightOutline) -> vec2<f32> {
    if (o.radius > 0.0) {
        let c = o.corners[0];
        return vec2<f32>(abs(sqrt(c.x * c.x + c.y * c.y) - o.radius), AIRLIGHT_FLT_MAX);
    }
    var nearest = vec2<f32>(AIRLIGHT_FLT_MAX);
    for (var i = 0u; i < 4u; i++) {
        let p = airlight_edge_nearest(o.corners[i], o.corners[(i + 1u) % 4u], vec2<f32>(0.0));
        let distance = sqrt(p.x * p.x + p.y * p.y);
        if (distance < nearest.x) {
            nearest = vec2<f32>(distance, nearest.x);
        } else if (distance < nearest.y) {
            nearest.y = distance;
        }
    }
    return nearest;
}

/// A flat emitter's outline about the foot of x, a point of its plane (outer.rs
/// `Shape::outline_distances`).
fn airlight_outline_at(s: AirlightScene, a: AirlightArea, x: vec3<f32>) -> AirlightOutline {
    let rel = x - a.c;
    let foot = vec2<f32>(dot(rel, a.a1), dot(rel, a.a2));
    let zero = vec2<f32>(0.0);
    if (s.light_shape == AIRLIGHT_SHAPE_DISC) {
        return AirlightOutline(array<vec2<f32>, 4>(-foot, zero, zero, zero), a.radius);
    }
    let u2 = vec2<f32>(dot(a.eu, a.a1), dot(a.eu, a.a2));
    let v2 = vec2<f32>(dot(a.ev, a.a1), dot(a.ev, a.a2));
    return AirlightOutline(array<vec2<f32>, 4>(-foot, u2 - foot, u2 + v2 - foot, v2 - foot), 0.0);
}

/// A phase lobe pointing at a flat emitter (outer.rs `FlatLobe`): its direction p = sign·d in
/// the plane's coordinates (p·n < 0), its radial scale (0: none), x's distance L from the point
/// q_L where p meets the plane, q_L about the foot, and whether it is on the emitter.
struct AirlightFlatLobe {
    p: vec3<f32>,
    sign: f32,
    scale: f32,
    l: f32,
    q: vec2<f32>,
    on_emitter: bool,
}

/// The phase lobe to take a flat emitter about (outer.rs `flat_lobe`): one narrower than the
/// emitter seen from x = (0, 0, z) whose direction meets the plane on it or within
/// LOBE_REACH scales of it; scale 0 for none.
fn airlight_flat_lobe(a: AirlightArea, z: f32, o: AirlightOutline, centre: vec2<f32>, size: f32) -> AirlightFlatLobe {
    let reach = airlight_atan(size / sqrt(dot(centre, centre) + z * z));
    for (var j = 0u; j < 2u; j++) {
        let lobe = select(a.lobes.xy, a.lobes.zw, j == 1u);
        let p = lobe.x * a.dirs;
        if (lobe.y > 0.0 && p.z < 0.0 && lobe.y < reach + reach) {
            let l = z / -p.z;
            let q = l * p.xy;
            let near = airlight_outline_nearest(o, q);
            let to_near = vec3<f32>(near, -z);
            let cos = min(dot(p, to_near) / sqrt(dot(to_near, to_near)), 1.0);
            // on it, or outside by no more than the rounding of q_L and the corners about the foot
            let on_emitter = length(near - q) <= 16.0 * AIRLIGHT_FLT_EPS * (length(q) + size + z);
            if (on_emitter || airlight_acos(cos) < AIRLIGHT_LOBE_REACH * lobe.y) {
                return AirlightFlatLobe(p, lobe.x, lobe.y, l, q, on_emitter);
            }
        }
    }
    return AirlightFlatLobe(vec3<f32>(0.0), 1.0, 0.0, 0.0, vec2<f32>(0.0), false);
}

/// (cos x, sin x) for any x: reduced to [−π, π] by 2π (an absolute error of about ε|x|), then
/// airlight_cos_sin_half_turn.
fn airlight_cos_sin_turns(x: f32) -> vec2<f32> {
    let r = airlight_wrap_turn(x);
    let cs = airlight_cos_sin_half_turn(abs(r));
    return vec2<f32>(cs.x, select(cs.y, -cs.y, r < 0.0));
}

/// x − 2π·round(x/2π): an angle difference in [−π, π].
fn airlight_wrap_turn(x: f32) -> f32 {
    return x - 2.0 * AIRLIGHT_PI * round(x / (2.0 * AIRLIGHT_PI));
}

/// The azimuth ψ about p (basis u, v) of the half-plane holding the plane's direction e:
/// atan2(e·v, e·u) (outer.rs `flat_about_lobe`'s `azimuth`).
fn airlight_lobe_azimuth(u: vec3<f32>, v: vec3<f32>, e: vec2<f32>) -> f32 {
    let y = e.x * v.x + e.y * v.y;
    return airlight_atan2(y, e.x * u.x + e.y * u.y);
}

/// Four values in ascending order (a sorting network: no loop iterations).
fn airlight_sort4(x: vec4<f32>) -> vec4<f32> {
    let a = vec4<f32>(min(x.x, x.y), max(x.x, x.y), min(x.z, x.w), max(x.z, x.w));
    let b = vec4<f32>(min(a.x, a.z), min(a.y, a.w), max(a.x, a.z), max(a.y, a.w));
    return vec4<f32>(b.x, min(b.y, b.z), max(b.y, b.z), b.w);
}

/// outer.rs `graded_from`'s rule on θ ∈ [start, to] (a phase lobe of scale `scale`): (the scale
/// g = max(scale, start), the range of γ).
fn airlight_graded_from(scale: f32, start: f32, to: f32) -> vec2<f32> {
    let graded = max(scale, start);
    return vec2<f32>(graded, airlight_atan((to - start) / graded));
}

/// A node γ of that rule as (cos θ, sin θ, dθ/dγ), θ = start + g tan γ.
fn airlight_graded_from_node(start: f32, graded: f32, g: f32) -> vec3<f32> {
    let tg = airlight_cos_sin_half_turn(g);
    return vec3<f32>(airlight_cos_sin_half_turn(start + graded * tg.y / tg.x), graded / (tg.x * tg.x));
}

/// One node γ of `airlight_flat_lobe_along`: L_e c^{p−1} e^{−σt z/c} P sin θ dθ/dγ,
/// c = −(p·n)(cos θ − k sin θ).
fn airlight_flat_lobe_node(s: AirlightScene, z: f32, lobe: AirlightFlatLobe, k: f32, start: f32, graded: f32, g: f32) -> f32 {
    let at = airlight_graded_from_node(start, graded, g);
    let c = -lobe.p.z * (at.x - k * at.y);
    if (!(c > 0.0)) { return 0.0; }
    return airlight_emitted(s, c) * exp(min(-s.sigma_t * z / c, 0.0)) * airlight_area_phase_about(s, lobe.sign, at.xy) * at.y * at.z;
}

/// The θ integral of `airlight_flat_about_lobe` in the half-plane of azimuth ψ (`cs` = (cos ψ,
/// sin ψ)) over the emitter's chord of its half-line q_L + r (w_ψ + k p), tan θ = r/(L + k r),
/// graded from its start (outer.rs `flat_about_lobe`'s `along`): RADIAL written out.
fn airlight_flat_lobe_along(s: AirlightScene, z: f32, o: AirlightOutline, lobe: AirlightFlatLobe, u: vec3<f32>, v: vec3<f32>, cs: vec2<f32>) -> f32 {
    let w = cs.x * u + cs.y * v;
    let k = w.z / -lobe.p.z;
    let chord = airlight_outline_chord(o, lobe.q, w.xy + k * lobe.p.xy);
    if (!(chord.x < chord.y)) { return 0.0; }
    let start = airlight_atan2_upper(chord.x, lobe.l + k * chord.x);
    let range = airlight_graded_from(lobe.scale, start, airlight_atan2_upper(chord.y, lobe.l + k * chord.y));
    let graded = range.x;
    let c = 0.5 * range.y;
    let hw = 0.5 * range.y;
    var sum = 0.0;
@RADIAL_FLAT_LOBE@    return sum;
}

/// S(x) of a flat emitter about a phase lobe's direction p (outer.rs `flat_about_lobe`): ψ over
/// the circle (AZIMUTHAL) on a disc holding q_L, over the wedge of its tangents from q_L
/// (ψ = ψ_m + Ψ sin φ) off it; on a parallelogram holding q_L edge by edge (`airlight_edge_rule`),
/// off it over the wedges between its corners seen from q_L (TRIANGLE_AZIMUTHAL each).
fn airlight_flat_about_lobe(s: AirlightScene, z: f32, o: AirlightOutline, lobe: AirlightFlatLobe) -> f32 {
    let u = airlight_basis_e1(lobe.p);
    let v = cross(lobe.p, u);
    let q = lobe.q;
    var sum = 0.0;
    if (o.radius > 0.0) {
        if (lobe.on_emitter) {
            // the half of the directions towards the rim's nearest point in the angle β of its
            // tangent there (in the lobe's plane the line h n + σ t, σ = D tan β,
            // D = hypot(h, min(L s, the half chord of the rim along the tangent through q_L))),
            // the far half in ψ
            let dq = q - o.corners[0];
            let d = sqrt(dot(dq, dq));
            var m = vec2<f32>(1.0, 0.0);
            if (d > 0.0) { m = dq / d; }
            let rim_e = o.corners[0] + o.radius * m - q;
            let rim = vec2<f32>(dot(rim_e, u.xy), dot(rim_e, v.xy));
            let along_rim = vec2<f32>(-m.y * u.x + m.x * u.y, -m.y * v.x + m.x * v.y);
            let tl = sqrt(dot(along_rim, along_rim));
            // t turned by −π/2 the tangent's normal out of the disc, h q_L's distance inside it
            // (≤ 0 on the rim or outside by rounding: no near half)
            var t = along_rim / tl;
            let outward = vec2<f32>(dot(m, u.xy), dot(m, v.xy));
            if (t.y * outward.x - t.x * outward.y < 0.0) { t = -t; }
            let h = t.y * rim.x - t.x * rim.y;
            let half_chord = tl * sqrt(max((o.radius - d) * (o.radius + d), 0.0));
            let width = min(lobe.l * lobe.scale, half_chord);
            let rule = AirlightEdgeRule(h, t, sqrt(h * h + width * width), -0.5 * AIRLIGHT_PI, 0.5 * AIRLIGHT_PI);
            for (var j = 0u; j < 16u; j++) {
                if (!(h > 0.0)) { break; }
                let node = airlight_radial_rule(j);
                let at = airlight_edge_at(rule, 0.5 * AIRLIGHT_PI * node.x);
                sum += node.y * 0.5 * AIRLIGHT_PI * at.w * airlight_flat_lobe_along(s, z, o, lobe, u, v, at.xy);
            }
            let n = vec2<f32>(t.y, -t.x);
            for (var i = 0u; i < 32u; i++) {
                let az = airlight_azimuths(false, i);
                sum += az.z * airlight_flat_lobe_along(s, z, o, lobe, u, v, -(n * az.x + t * az.y));
            }
            return sum;
        }
        // the tangents from q_L, at ±β from the centre's direction
        let d = o.corners[0] - q;
        let dq = sqrt(d.x * d.x + d.y * d.y);
        let sb = o.radius / dq;
        let cb = sqrt((dq - o.radius) * (dq + o.radius)) / dq;
        let mid = airlight_lobe_azimuth(u, v, d);
        let end0 = airlight_wrap_turn(airlight_lobe_azimuth(u, v, vec2<f32>(d.x * cb - d.y * sb, d.y * cb + d.x * sb)) - mid);
        let end1 = airlight_wrap_turn(airlight_lobe_azimuth(u, v, vec2<f32>(d.x * cb + d.y * sb, d.y * cb - d.x * sb)) - mid);
        let centre = mid + (end0 + end1) * 0.5;
        let half = abs(end0 - end1) * 0.5;
        for (var i = 0u; i < 32u; i++) {
            let az = airlight_azimuths(false, i);
            sum += az.z * half * az.x * airlight_flat_lobe_along(s, z, o, lobe, u, v, airlight_cos_sin_turns(centre + half * az.y));
        }
        return sum;
    }
    // the corners about q_L in the lobe's plane, e ↦ (e·u, e·v): its angle is ψ
    let y = array<vec2<f32>, 4>(
        vec2<f32>(dot(o.corners[0] - q, u.xy), dot(o.corners[0] - q, v.xy)),
        vec2<f32>(dot(o.corners[1] - q, u.xy), dot(o.corners[1] - q, v.xy)),
        vec2<f32>(dot(o.corners[2] - q, u.xy), dot(o.corners[2] - q, v.xy)),
        vec2<f32>(dot(o.corners[3] - q, u.xy), dot(o.corners[3] - q, v.xy)));
    if (lobe.on_emitter) {
        // the chords of the wedge between two corners end on the edge between them; the image
        // keeps or reverses the corners' turn; an edge q_L is on (or outside by rounding) has no
        // chords of its own
        var area = vec4<f32>(0.0);
        for (var i = 0u; i < 4u; i++) {
            let b = y[(i + 1u) % 4u];
            area[i] = y[i].x * b.y - y[i].y * b.x;
        }
        let turn = area.x + area.y + area.z + area.w;
        for (var i = 0u; i < 4u; i++) {
            if (!(area[i] * turn > 0.0)) { continue; }
            var ya = y[i];
            var yb = y[(i + 1u) % 4u];
            if (turn < 0.0) {
                ya = y[(i + 1u) % 4u];
                yb = y[i];
            }
            let rule = airlight_edge_rule(ya, yb, lobe.l * lobe.scale);
            for (var j = 0u; j < 12u; j++) {
                let node = airlight_edge_node(rule, j);
                sum += node.w * airlight_flat_lobe_along(s, z, o, lobe, u, v, node.xy);
            }
        }
        return sum;
    }
    // the wedges between the corners' azimuths about the centre's, in order, each in the
    // Mercator angle of the edge its chords enter by
    let mid = airlight_lobe_azimuth(u, v, 0.5 * (o.corners[0] + o.corners[2]) - q);
    let psi = airlight_sort4(vec4<f32>(
        airlight_wrap_turn(airlight_lobe_azimuth(u, v, o.corners[0] - q) - mid),
        airlight_wrap_turn(airlight_lobe_azimuth(u, v, o.corners[1] - q) - mid),
        airlight_wrap_turn(airlight_lobe_azimuth(u, v, o.corners[2] - q) - mid),
        airlight_wrap_turn(airlight_lobe_azimuth(u, v, o.corners[3] - q) - mid)));
    for (var i = 0u; i < 3u; i++) {
        let first = mid + psi[i];
        let last = mid + psi[i + 1u];
        let towards_half = airlight_cos_sin_turns(0.5 * (first + last));
        let edges = airlight_chord_edges(y, towards_half);
        let n = edges.entry;
        if (all(n == vec2<f32>(0.0))) {
            let c = (first + last) * 0.5;
            let hw = (last - first) * 0.5;
            for (var j = 0u; j < 12u; j++) {
                let node = airlight_triangle_rule(j);
                sum += node.y * hw * airlight_flat_lobe_along(s, z, o, lobe, u, v, airlight_cos_sin_turns(c + hw * node.x));
            }
            continue;
        }
        // an exit edge nearer than the lobe's footprint: the half of the wedge at the end more
        // nearly parallel to it in the angle β of that edge (D = hypot(h, L s)), the other half
        // in the Mercator angle of the entry edge
        var merc_first = airlight_cos_sin_turns(first);
        var merc_last = airlight_cos_sin_turns(last);
        let exit_h = edges.exit_h;
        let width = lobe.l * lobe.scale;
        if (exit_h > 0.0 && exit_h < width) {
            var rule = AirlightEdgeRule(exit_h, vec2<f32>(-edges.exit.y, edges.exit.x), sqrt(exit_h * exit_h + width * width), 0.0, 0.0);
            if (dot(merc_first, edges.exit) < dot(merc_last, edges.exit)) {
                rule.first = airlight_line_beta(rule, merc_first);
                rule.last = airlight_line_beta(rule, towards_half);
                merc_first = towards_half;
            } else {
                rule.first = airlight_line_beta(rule, towards_half);
                rule.last = airlight_line_beta(rule, merc_last);
                merc_last = towards_half;
            }
            for (var j = 0u; j < 12u; j++) {
                let node = airlight_edge_node(rule, j);
                sum += node.w * airlight_flat_lobe_along(s, z, o, lobe, u, v, node.xy);
            }
        }
        sum += airlight_mercator_wedge(s, z, o, lobe, u, v, n, merc_first, merc_last);
    }
    return sum;
}

/// The angle β of the direction `cs` = (cos ψ, sin ψ) on the line h m + σ t of `rule`, σ = D tan β
/// (m = (t.y, −t.x) its unit normal from the origin; a direction parallel to it or past it at
/// ±π/2; outer.rs `flat_about_lobe`, the exit edge's half).
fn airlight_line_beta(rule: AirlightEdgeRule, cs: vec2<f32>) -> f32 {
    let m = vec2<f32>(rule.t.y, -rule.t.x);
    return airlight_atan2(dot(cs, rule.t) * rule.h, max(dot(cs, m), 0.0) * rule.reach);
}

/// The lobe's chords from q_L over the wedge of directions from `first` to `last` ((cos ψ, sin ψ)
/// each) that enter the emitter by the line of unit normal `n` from q_L, in its Mercator angle
/// asinh(tan δ) (dψ = sech u du), panels at MERCATOR_CUTS, 12 nodes each (outer.rs
/// `mercator_rule`).
fn airlight_mercator_wedge(s: AirlightScene, z: f32, o: AirlightOutline, lobe: AirlightFlatLobe, u: vec3<f32>, v: vec3<f32>, n: vec2<f32>, first: vec2<f32>, last: vec2<f32>) -> f32 {
    let t = vec2<f32>(-n.y, n.x);
    let ua = airlight_mercator(n, first);
    let ub = airlight_mercator(n, last);
    var sum = 0.0;
    for (var i = 0u; i < 7u * 12u; i++) {
        let node = airlight_mercator_node(ua, ub, i);
        if (node.z == 0.0) { continue; }
        sum += node.z * airlight_flat_lobe_along(s, z, o, lobe, u, v, n * node.x + t * node.y);
    }
    return sum;
}

/// Slot i = 12 k + j of the Mercator rule on [ua, ub] (outer.rs `mercator_rule`): node j of panel
/// k between MERCATOR_CUTS as (sech u, tanh u, its weight in ψ: the node's weight in u times
/// sech u), the weight 0 where the panel lies outside [ua, ub].
fn airlight_mercator_node(ua: f32, ub: f32, i: u32) -> vec3<f32> {
    let lo = max(ua, airlight_mercator_cut(i / 12u));
    let hi = min(ub, airlight_mercator_cut(i / 12u + 1u));
    if (!(lo < hi)) { return vec3<f32>(0.0); }
    let node = airlight_triangle_rule(i % 12u);
    let hw = 0.5 * (hi - lo);
    let x = 0.5 * (lo + hi) + hw * node.x;
    // sech x and tanh x from e^{−|x|}
    let e = exp(-abs(x));
    let sech = 2.0 * e / (1.0 + e * e);
    return vec3<f32>(sech, sign(x) * (1.0 - e * e) / (1.0 + e * e), node.y * hw * sech);
}

/// outer.rs RADIAL (Gauss–Legendre, 16 points) on [−1, 1]: (x, weight).
fn airlight_radial_rule(i: u32) -> vec2<f32> {
    let rule = array<vec2<f32>, 16>(@RADIAL_RULE@);
    return rule[i];
}

/// outer.rs `MERCATOR_CUTS[k]`.
fn airlight_mercator_cut(k: u32) -> f32 {
    let cuts = array<f32, 8>(@MERCATOR_CUTS@);
    return cuts[k];
}

/// The Mercator angle asinh(tan δ) of the direction `cs` = (cos ψ, sin ψ) about the unit normal
/// `n` of a line (outer.rs `mercator_rule`), clamped to the outermost cut.
fn airlight_mercator(n: vec2<f32>, cs: vec2<f32>) -> f32 {
    let cap = airlight_mercator_cut(7u);
    let tangent = (cs.y * n.x - cs.x * n.y) / max(cs.x * n.x + cs.y * n.y, 1e-30);
    return clamp(airlight_asinh(tangent), -cap, cap);
}

/// The edges by which the half-line r e (r > 0) enters and leaves a convex polygon (outer.rs
/// `chord_edges`): their lines' unit normals from the origin, the exit line's distance; the
/// entry normal (0, 0) if the half-line misses it.
struct AirlightChordEdges {
    entry: vec2<f32>,
    exit: vec2<f32>,
    exit_h: f32,
}

/// `AirlightChordEdges` of the half-line r e and the polygon `y`.
fn airlight_chord_edges(y: array<vec2<f32>, 4>, e: vec2<f32>) -> AirlightChordEdges {
    var nearest = AIRLIGHT_FLT_MAX;
    var farthest = 0.0;
    var edges = AirlightChordEdges(vec2<f32>(0.0), vec2<f32>(0.0), 0.0);
    for (var i = 0u; i < 4u; i++) {
        let a = y[i];
        let d = y[(i + 1u) % 4u] - a;
        let den = e.x * d.y - e.y * d.x;
        if (den == 0.0) { continue; }
        let r = (a.x * d.y - a.y * d.x) / den;
        let along = (a.x * e.y - a.y * e.x) / den;
        if (r > 0.0 && along >= 0.0 && along <= 1.0) {
            let n = vec2<f32>(d.y, -d.x) / sqrt(dot(d, d));
            let h = dot(n, a);
            let outward = select(n, -n, h < 0.0);
            if (r < nearest) {
                nearest = r;
                edges.entry = outward;
            }
            if (r > farthest) {
                farthest = r;
                edges.exit = outward;
                edges.exit_h = abs(h);
            }
        }
    }
    return edges;
}

/// The cap a sphere subtends from x (outer.rs `Cap`): its centre's unit direction `a` at
/// distance `dc`, the radius, sin α and cos α.
struct AirlightCap {
    a: vec3<f32>,
    dc: f32,
    radius: f32,
    sin_a: f32,
    cos_a: f32,
    // its angular radius α
    alpha: f32,
}

/// One node φ of the cap rule (outer.rs `sphere`): (the φ-weight's factor w L_e cos^{p−1} φ
/// sin²α sin φ cos φ / cos β e^{−σt d}, cos β, sin β).
fn airlight_cap_row(s: AirlightScene, cap: AirlightCap, graded: f32, node: f32, weight: f32) -> vec3<f32> {
    let at = airlight_graded_node(graded, node);
    let w = weight * at.y;
    let cs = airlight_cos_sin_half_turn(at.x);
    let sb = cap.sin_a * cs.y;
    let cb = sqrt((1.0 - sb) * (1.0 + sb));
    let dist = max(cap.dc * cb - cap.radius * cs.x, 0.0);
    let factor = w * airlight_emitted(s, cs.x) * cap.sin_a * cap.sin_a * cs.y * cs.x / cb * exp(min(-s.sigma_t * dist, 0.0));
    return vec3<f32>(factor, cb, sb);
}

/// S(x) of a sphere by its cap about the centre's direction (outer.rs `sphere`): φ by RADIAL
/// (graded towards the centre, φ = s tan ϑ, s = 2/√(p − 1), under a narrow emission lobe) written
/// out, the ψ loop outside it (32 loop iterations, not 16 × 32).
fn airlight_sphere_cap(s: AirlightScene, a: AirlightArea, cap: AirlightCap) -> f32 {
    let e1 = airlight_basis_e1(cap.a);
    let e2 = cross(cap.a, e1);
    let ad = dot(cap.a, a.d);
    let e1d = dot(e1, a.d);
    let e2d = dot(e2, a.d);
    let range = airlight_graded_range(s, 0.5 * AIRLIGHT_PI);
    let graded = range.y;
    let c = 0.5 * range.x;
    let hw = 0.5 * range.x;
    // zeros written out (naga's HLSL back end emits an array's zero value as invalid HLSL)
    var rows = array<vec3<f32>, @RADIAL_NODES@>(@ZEROS_RADIAL_ROWS@);
@RADIAL_CAP_ROWS@    var sum = 0.0;
    if (a.isotropic) {
        // a constant phase function's integral round the circle, 2π·P
        let around = 2.0 * AIRLIGHT_PI * airlight_area_phase(s, 0.0);
@RADIAL_CAP_CONSTANT@        return sum;
    }
    for (var i = 0u; i < 32u; i++) {
        let az = airlight_azimuths(true, i);
        let across = az.x * e1d + az.y * e2d;
        var at = 0.0;
@RADIAL_CAP_AROUND@        sum += az.z * at;
    }
    return sum;
}

/// One node γ of `airlight_sphere_about_lobe`'s θ integral along ψ: L_e c^{p−1} e^{−σt d} P sin θ dθ/dγ.
fn airlight_sphere_lobe_node(s: AirlightScene, cap: AirlightCap, sign: f32, cos_p: f32, big_b: f32, start: f32, graded: f32, g: f32) -> f32 {
    let at = airlight_graded_from_node(start, graded, g);
    let toward_a = at.x * cos_p + at.y * big_b;
    let root = sqrt(max(cap.radius * cap.radius - cap.dc * cap.dc * (1.0 - toward_a) * (1.0 + toward_a), 0.0));
    let dist = max(cap.dc * toward_a - root, 0.0);
    return airlight_emitted(s, root / cap.radius) * exp(min(-s.sigma_t * dist, 0.0)) * airlight_area_phase_about(s, sign, at.xy) * at.y * at.z;
}

/// S(x) of a sphere whose cap holds (or nearly) the direction p = sign·d of a phase lobe of
/// radial scale `scale` (outer.rs `sphere_about_lobe`): polar about p, θ = s tan γ from it (from
/// the near rim outside) to the cap's rim in each ψ (a long range in two, LOBE_TAIL), RADIAL in
/// γ written out, AZIMUTHAL in ψ.
fn airlight_sphere_about_lobe(s: AirlightScene, a: AirlightArea, cap: AirlightCap, sign: f32, cos_p: f32, scale: f32) -> f32 {
    let p = sign * a.d;
    let u = airlight_basis_e1(p);
    let v = cross(p, u);
    let au = dot(cap.a, u);
    let av = dot(cap.a, v);
    let inside = cos_p > cap.cos_a;
    // outside: the wedge |ψ − ψ_a| ≤ Ψ that meets the cap, ψ = ψ_a + Ψ sin φ
    let sin_p = sqrt(au * au + av * av);
    var axis = vec2<f32>(1.0, 0.0);
    var half = 0.0;
    if (sin_p > 0.0) {
        axis = vec2<f32>(au / sin_p, av / sin_p);
        half = airlight_acos(min(sqrt(max((cap.cos_a - cos_p) * (cap.cos_a + cos_p), 0.0)) / sin_p, 1.0));
    }
    // inside: the half of the directions towards the rim's nearest point (−axis, the angle
    // ε = α − β_p away) in the angle β of the rim's tangent there (σ = D tan β, D = hypot(ε,
    // min(s, the rim's half chord through p))), 16 nodes, then the far half in ψ about axis, 32
    let beta_p = airlight_atan2(sin_p, cos_p);
    let eps = cap.alpha - beta_p;
    let width = min(scale, sqrt(max(eps * (cap.alpha + beta_p), 0.0)));
    // (both halves even about axis, as the wedge outside is in φ: the rules' nodes on one side,
    // weights doubled)
    let rim = AirlightEdgeRule(eps, vec2<f32>(axis.y, -axis.x), sqrt(eps * eps + width * width), -0.5 * AIRLIGHT_PI, 0.5 * AIRLIGHT_PI);
    // −p inside the cap as well (x beside the sphere, the lobe along its surface): every half
    // great circle from p meets the cap, up to θ = π; the half towards the rim's nearest point
    // (axis) in the Mercator angle of the rim's tangent there (MERCATOR_CUTS from 0, 12 nodes
    // each, 7 × 12 slots), the far half in ψ, 16
    let beside = cos_p < -cap.cos_a;
    var count = select(16u, 24u, inside);
    if (beside) { count = 7u * 12u + 16u; }
    var sum = 0.0;
    for (var i = 0u; i < count; i++) {
        // a·e_ψ = sin β_p cos(ψ − ψ_a) and the weight in ψ (outside: ψ − ψ_a = Ψ sin φ,
        // dψ = Ψ cos φ dφ)
        var big_b = 0.0;
        var wpsi = 0.0;
        if (beside && i < 84u) {
            let node = airlight_mercator_node(0.0, airlight_mercator_cut(7u), i);
            if (node.z == 0.0) { continue; }
            big_b = sin_p * node.x;
            wpsi = 2.0 * node.z;
        } else if (beside) {
            let az = airlight_azimuths_even(i - 84u);
            big_b = -sin_p * az.x;
            wpsi = az.z;
        } else if (inside && i < 8u) {
            if (!(eps > 0.0)) { continue; }
            let node = airlight_radial_rule(2u * i + 1u);
            let at = airlight_edge_at(rim, 0.5 * AIRLIGHT_PI * node.x);
            big_b = sin_p * dot(at.xy, axis);
            wpsi = 2.0 * node.y * 0.5 * AIRLIGHT_PI * at.w;
        } else if (inside) {
            let az = airlight_azimuths_even(i - 8u);
            big_b = sin_p * az.x;
            wpsi = az.z;
        } else {
            let az = airlight_azimuths_even(i);
            big_b = sin_p * airlight_cos_sin(half * az.y).x;
            wpsi = az.z * half * az.x;
        }
        var mid = airlight_atan2(big_b, cos_p);
        if (beside && mid < 0.0) { mid += 2.0 * AIRLIGHT_PI; }
        let spread = airlight_acos(min(cap.cos_a / sqrt(cos_p * cos_p + big_b * big_b), 1.0));
        var lo = 0.0;
        if (!inside) { lo = max(mid - spread, 0.0); }
        var hi = mid + spread;
        if (beside) { hi = min(hi, AIRLIGHT_PI); }
        // a range longer than LOBE_REACH of its grading scales: the lobe's tail past LOBE_TAIL
        // graded from there by its own distance
        let tail = lo + AIRLIGHT_LOBE_TAIL;
        let cut = hi > tail && hi - lo > AIRLIGHT_LOBE_REACH * max(scale, lo);
        var around = 0.0;
        // (the two parts in one loop: a second copy of the written-out rule would grow
        // lavapipe's build)
        for (var k = 0u; k < select(1u, 2u, cut); k++) {
            let start = select(lo, tail, k == 1u);
            let to = select(hi, tail, cut && k == 0u);
            let range = airlight_graded_from(scale, start, to);
            let graded = range.x;
            let c = 0.5 * range.y;
            let hw = 0.5 * range.y;
@RADIAL_LOBE@        }
        sum += wpsi * around;
    }
    return sum;
}

/// S(x) of a sphere (outer.rs `sphere`) at `along` past the centre's foot, c − x and |c − x| − R
/// from its foot and miss (outer.rs `SphereFoot::at`); 0 inside it.
fn airlight_sphere(s: AirlightScene, a: AirlightArea, along: f32) -> f32 {
    let v = a.foot.to_centre - along * a.d;
    let length = airlight_safe_length(v);
    var gap = (a.foot.miss * (a.foot.h + a.radius) + along * along) / (length + a.radius);
    if (!airlight_is_finite(gap)) { gap = length - a.radius; }
    // inside, or beyond the float range (a cap of no size)
    if (!(gap > 0.0 && airlight_is_finite(gap))) { return 0.0; }
    let dc = a.radius + gap;
    let sin_a = a.radius / dc;
    let cos_a = sqrt((gap / dc) * (1.0 + sin_a));
    let alpha = airlight_atan2_upper(sin_a, cos_a);
    let cap = AirlightCap(v / length, dc, a.radius, sin_a, cos_a, alpha);
    // a lobe narrower than the cap (κ < α) whose direction lies inside it, or outside within
    // LOBE_REACH scales of its rim or the cap's radius α (beyond the great circle opposite the
    // centre, beside the sphere, only one narrower than BESIDE_SCALE)
    var chosen = 0.0;
    var sign = 1.0;
    var cos_p = 0.0;
    for (var j = 0u; j < 2u; j++) {
        let lobe = select(a.lobes.xy, a.lobes.zw, j == 1u);
        let c = dot(cap.a, lobe.x * a.d);
        if (chosen == 0.0 && lobe.y > 0.0 && lobe.y < alpha + alpha
            && (!(c < -cap.cos_a) || lobe.y < AIRLIGHT_BESIDE_SCALE)
            && (c > cap.cos_a || airlight_acos(c) - alpha < max(AIRLIGHT_LOBE_REACH * lobe.y, alpha))) {
            chosen = lobe.y;
            sign = lobe.x;
            cos_p = c;
        }
    }
    if (chosen > 0.0) {
        return airlight_sphere_about_lobe(s, a, cap, sign, cos_p, chosen);
    }
    return airlight_sphere_cap(s, a, cap);
}

/// S(x): the radiance the emitter's directions send along the ray at x, weighted by the phase
/// function (outer.rs `Shape::radiance`), `along` past the centre's foot.
fn airlight_emitter_radiance(s: AirlightScene, a: AirlightArea, x: vec3<f32>, along: f32) -> f32 {
    switch s.light_shape {
        case AIRLIGHT_SHAPE_DISC: { return airlight_disc(s, a, x); }
        case AIRLIGHT_SHAPE_RECTANGLE: { return airlight_parallelogram(s, a, x); }
        default: { return airlight_sphere(s, a, along); }
    }
}

/// The ray's integrand at θ (outer.rs `in_scatter_bounded`): h'/cos²θ e^{−σt(t − t0)} S(x(t)).
fn airlight_area_node(s: AirlightScene, a: AirlightArea, theta: f32) -> f32 {
    let cs = airlight_cos_sin(theta);
    let along = a.h_eff * cs.y / cs.x;
    let t = a.x_h + along;
    let fade = exp(min(-s.sigma_t * max((a.x_h - s.t_min) + along, 0.0), 0.0));
    return a.h_eff / (cs.x * cs.x) * fade * airlight_emitter_radiance(s, a, s.origin + t * a.d, along);
}

/// In-scattered radiance L_m of an area light (AIRLIGHT_SHAPE_DISC, _RECTANGLE, _SPHERE; without a
/// surface) by the bounded method of docs/DESIGN.md §12; any other scene gives (0, INVALID). Its
/// own entry, not reached from airlight_in_scatter: its fixed rules, written out, more than double
/// the code a driver compiles (a full entry with it took lavapipe 2.5 times as long to compile
/// from naga's SPIR-V, over 100 times from glslang's), and a driver that masks branches
/// (lavapipe) would run them for every record of a shader that holds them.
fn airlight_in_scatter_area(s: AirlightScene) -> AirlightResult {
    if (!airlight_valid(s) || s.light_shape < AIRLIGHT_SHAPE_DISC || s.surface_kind != AIRLIGHT_SURFACE_NONE) {
        return AirlightResult(0.0, AIRLIGHT_STATUS_INVALID);
    }
    return airlight_area_light(s);
}

/// In-scattered radiance of a valid area light (outer.rs `AreaScene::in_scatter_bounded`): the ray by
/// adaptive Gauss–Kronrod 7/15 in θ to AIRLIGHT_AREA_RAY_TOLERANCE in at most
/// AIRLIGHT_AREA_RAY_PANELS panels (extended.rs `adaptive`), the emitter by fixed rules.
fn airlight_area_light(s: AirlightScene) -> AirlightResult {
    let a = airlight_area(s);
    if (a.outcome == 1u) {
        return AirlightResult(0.0, AIRLIGHT_STATUS_OK);
    }
    let rule = airlight_kronrod15_rule();
    var st = airlight_adaptive(a.edges[0], a.edges[1]);
    let max_panels = max(AIRLIGHT_AREA_RAY_PANELS, a.panels);
    let evaluations = 2u * max_panels - 1u;
    for (var step = 0u; step < evaluations; step++) {
        let c = 0.5 * (st.lo + st.hi);
        let hw = 0.5 * (st.hi - st.lo);
        var k = 0.0;
        var gauss = 0.0;
        for (var j = 0u; j < 15u; j++) {
            let node = rule[j / 2u];
            let x = select(c + hw * node.x, c - hw * node.x, (j & 1u) == 0u && j < 14u);
            let f = airlight_area_node(s, a, x);
            k += node.y * f;
            gauss += node.z * f;
        }
        st = airlight_adaptive_step(st, k * hw, gauss * hw, a.edges, a.panels, max_panels, AIRLIGHT_AREA_RAY_TOLERANCE);
        if (!st.more) { break; }
    }
    let total = airlight_list_scan(st.list, st.count).total;
    if (!airlight_is_finite(total)) {
        return AirlightResult(AIRLIGHT_FLT_MAX, AIRLIGHT_STATUS_INFINITE);
    }
    return AirlightResult(s.sigma_s * max(total, 0.0), AIRLIGHT_STATUS_OK);
}

/// In-scattered radiance L_m of a point light without a surface (scene.rs `Scene::in_scatter`):
/// the ray integral alone, without the emitter and hemisphere loop `airlight_in_scatter` wraps
/// round every scene. The same value and status as `airlight_in_scatter` on such a scene; any
/// other scene (a segment light, a surface point) gives (0, INVALID). For shaders whose lights
/// are all points: a driver that masks branches instead of taking them (Mesa's lavapipe) runs
/// the loop's code for every ray (docs/DESIGN.md §4.1).
fn airlight_in_scatter_point(s: AirlightScene) -> AirlightResult {
    if (!airlight_valid(s) || s.light_shape != AIRLIGHT_SHAPE_POINT || s.surface_kind != AIRLIGHT_SURFACE_NONE) {
        return AirlightResult(0.0, AIRLIGHT_STATUS_INVALID);
    }
    return airlight_point_integral(s);
}

/// The first of two passes over point lights without a surface (docs/DESIGN.md §4.1): the
/// light-angle route alone (angle.rs), where it meets the tolerance, and the limits that need no
/// integral — the same value and status `airlight_in_scatter_point` gives — else (0, DEFERRED):
/// an isotropic scene (whose closed form is the full entry's), a route declined or failed. Run
/// the deferred records through `airlight_in_scatter_point` in a second pass: a driver that
/// masks branches (lavapipe) charges every ray of a dispatch for the closed forms that a few
/// need, and a GPU that branches per group of lanes charges every group with one such ray.
/// Other scenes give (0, INVALID).
fn airlight_in_scatter_route(s: AirlightScene) -> AirlightResult {
    if (!airlight_valid(s) || s.light_shape != AIRLIGHT_SHAPE_POINT || s.surface_kind != AIRLIGHT_SURFACE_NONE) {
        return AirlightResult(0.0, AIRLIGHT_STATUS_INVALID);
    }
    let g = airlight_refined(s, airlight_canonical(s));
    let limit = airlight_limits(s, g);
    if (limit.status != AIRLIGHT_STATUS_DEFERRED) {
        return airlight_overflowed(limit);
    }
    if (!airlight_isotropic_scene(s)) {
        let route = airlight_angle_route(s, g);
        if (route.x > 0.5) {
            return airlight_overflowed(AirlightResult(max(route.y, 0.0), AIRLIGHT_STATUS_OK));
        }
    }
    return AirlightResult(0.0, AIRLIGHT_STATUS_DEFERRED);
}

/// (FLT_MAX, INFINITE) where a ray integral's value is not finite or the light is on the
/// segment; else the result itself.
fn airlight_overflowed(r: AirlightResult) -> AirlightResult {
    if (!airlight_is_finite(r.in_scatter) || r.status == AIRLIGHT_STATUS_INFINITE) {
        return AirlightResult(AIRLIGHT_FLT_MAX, AIRLIGHT_STATUS_INFINITE);
    }
    return r;
}

/// The ray integral of the point light of a validated point scene `p`: airlight_node_integral
/// of its one node.
fn airlight_point_integral(p: AirlightScene) -> AirlightResult {
    return airlight_node_integral(AirlightNode(p, 1.0, airlight_no_canonical(), false));
}

/// The canonical form of a node that brings none (its ray is reduced).
fn airlight_no_canonical() -> AirlightCanonical {
    return AirlightCanonical(0.0, 0.0, 0.0, 0.0, 0.0, 0.0, false);
}

/// The ray integral of a node's point light (a node of an outer integral, or a point scene's),
/// from the canonical form the node brings (`exact`: a surface point's ray) or else by the
/// reduction: 0 where the node's light or direction is not finite, (FLT_MAX, INFINITE) where
/// the integral is not finite or the light is on the segment. The one place every public entry
/// reaches the canonical problem from.
fn airlight_node_integral(n: AirlightNode) -> AirlightResult {
    let p = n.scene;
    var r = AirlightResult(0.0, AIRLIGHT_STATUS_OK);
    if (airlight_vec_finite(p.light_position) && airlight_vec_finite(p.dir)) {
        var g = n.canonical;
        if (!n.exact) { g = airlight_refined(p, airlight_canonical(p)); }
        r = airlight_in_scatter_canonical(p, g);
    }
    return airlight_overflowed(r);
}

/// In-scattered radiance L_m of a scene (docs/DESIGN.md §1): the public entry of the library;
/// for a surface scene (airlight_lambert_surface), the surface radiance from air-light.
/// Invalid scenes give (0, INVALID); a light on the segment gives (FLT_MAX, INFINITE). An area
/// light is airlight_in_scatter_area's, and INVALID here.
fn airlight_in_scatter(s: AirlightScene) -> AirlightResult {
    if (!airlight_valid(s)) {
        return AirlightResult(0.0, AIRLIGHT_STATUS_INVALID);
    }
    if (s.light_shape >= AIRLIGHT_SHAPE_DISC) {
        // area lights: airlight_in_scatter_area
        return AirlightResult(0.0, AIRLIGHT_STATUS_INVALID);
    }
    let g = airlight_outer(s);
    if (g.outcome == 1u) {
        return AirlightResult(0.0, AIRLIGHT_STATUS_OK);
    }
    if (g.outcome == 2u) {
        return AirlightResult(AIRLIGHT_FLT_MAX, AIRLIGHT_STATUS_INFINITE);
    }
    let rule = airlight_kronrod_rule();
    var st = airlight_adaptive(g.edges[0], g.edges[1]);
    // the first panels (≤ 4) and two per split, until the list is full
    let evaluations = 2u * g.max_panels - 1u;
    for (var step = 0u; step < evaluations; step++) {
        let c = 0.5 * (st.lo + st.hi);
        let hw = 0.5 * (st.hi - st.lo);
        var k = 0.0;
        var gauss = 0.0;
        for (var j = 0u; j < 7u; j++) {
            let node = rule[j / 2u];
            let w = select(c + hw * node.x, c - hw * node.x, (j & 1u) == 0u && j < 6u);
            let at = airlight_outer_node(s, g, w);
            var f = 0.0;
            if (at.weight != 0.0) {
                let r = airlight_node_integral(at);
                // a point light, or a node on the ray (the kernel's sum is then +∞ at once)
                if (r.status == AIRLIGHT_STATUS_INFINITE) {
                    return r;
                }
                if (s.light_shape == AIRLIGHT_SHAPE_POINT && s.surface_kind == AIRLIGHT_SURFACE_NONE) {
                    return r;
                }
                f = r.in_scatter * at.weight;
            }
            k += node.y * f;
            gauss += node.z * f;
        }
        st = airlight_adaptive_step(st, k * hw, gauss * hw, g.edges, g.panels, g.max_panels, AIRLIGHT_PANEL_TOLERANCE);
        if (!st.more) { break; }
    }
    let total = airlight_list_scan(st.list, st.count).total;
    if (!airlight_is_finite(total)) {
        return AirlightResult(AIRLIGHT_FLT_MAX, AIRLIGHT_STATUS_INFINITE);
    }
    return AirlightResult(max(total, 0.0), AIRLIGHT_STATUS_OK);
}
