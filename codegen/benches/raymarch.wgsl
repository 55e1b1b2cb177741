// Ray-marching baseline for the GPU benchmark (codegen/benches/gpu.rs): the same record buffer
// (binding 0, the 112-byte `AirlightScene` of codegen/src/layout.rs) and the same 8-byte results
// (binding 1: value + status) as the generated `airlight_main`, workgroup size 64.
//
// It integrates the contract integral (README, DESIGN §1)
//   L_m = σs·I·∫_{t0}^{t1} e^{−σt(t−t0)}·e^{−σt r}/r²·D(c)·P(μ) dt,
//   r = |x(t)−p|, c = (x−p)·a/r, μ = −(x−p)·d/r, d normalised,
// the way an engine's ray marcher does: STEPS uniform steps in t over the segment, the
// integrand at each step's midpoint (midpoint rule), one exp per step for both attenuations.
// Infinite segments are clamped where the transmittance e^{−σt(t−t0)} falls below 1e-6
// (t1 = t0 + 14/σt), or at t0 + AIRLIGHT_RM_FAR when σt = 0. No input validation: every record
// gets status 0 (2 if the sum is not finite).
//
// The benchmark replaces the `const STEPS` line below before compiling.

const STEPS: u32 = 64u;
const AIRLIGHT_RM_FAR: f32 = 1000.0;
const AIRLIGHT_RM_PI: f32 = 3.14159265358979;

struct AirlightScene {
    origin: vec3<f32>,
    t_min: f32,
    dir: vec3<f32>,
    t_max: f32,
    light_position: vec3<f32>,
    intensity: f32,
    light_axis: vec3<f32>,
    light_param_a: f32,
    light_param_b: f32,
    sigma_s: f32,
    sigma_t: f32,
    phase_param_a: f32,
    phase_param_b: f32,
    phase_param_c: f32,
    light_kind: u32,
    phase_kind: u32,
    flags: u32,
}

struct AirlightResult {
    in_scatter: f32,
    status: u32,
}

@group(0) @binding(0) var<storage, read> airlight_records: array<AirlightScene>;
@group(0) @binding(1) var<storage, read_write> airlight_results: array<AirlightResult>;

fn rm_hg(g: f32, mu: f32) -> f32 {
    let base = 1.0 + g * g - 2.0 * g * mu;
    return (1.0 - g * g) / (4.0 * AIRLIGHT_RM_PI * base * sqrt(base));
}

/// P(μ), as kernel/src/phase.rs: 0 isotropic, 1 Rayleigh, 2 HG, 3 Schlick, 4 Cornette–Shanks,
/// 5 two-lobe HG.
fn rm_phase(kind: u32, p0: f32, p1: f32, p2: f32, mu: f32) -> f32 {
    switch kind {
        case 1u: { return 3.0 / (16.0 * AIRLIGHT_RM_PI) * (1.0 + mu * mu); }
        case 2u: { return rm_hg(p0, mu); }
        case 3u: {
            let d = 1.0 - p0 * mu;
            return (1.0 - p0 * p0) / (4.0 * AIRLIGHT_RM_PI * d * d);
        }
        case 4u: {
            let base = 1.0 + p0 * p0 - 2.0 * p0 * mu;
            return 3.0 * (1.0 - p0 * p0) * (1.0 + mu * mu) / (8.0 * AIRLIGHT_RM_PI * (2.0 + p0 * p0) * base * sqrt(base));
        }
        case 5u: { return p2 * rm_hg(p0, mu) + (1.0 - p2) * rm_hg(p1, mu); }
        default: { return 1.0 / (4.0 * AIRLIGHT_RM_PI); }
    }
}

/// D(c), as kernel/src/light.rs: 0 omni, 1 two-lobed c^p (p even, so (c²)^(p/2)), 2 spot
/// smoothstep x²(3−2x), x = (c − cos_outer)/(cos_inner − cos_outer).
fn rm_light(kind: u32, p0: f32, p1: f32, c: f32) -> f32 {
    switch kind {
        case 1u: {
            if (p0 == 0.0) { return 1.0; }
            return pow(c * c, 0.5 * p0);
        }
        case 2u: {
            let width = p0 - p1;
            if (width <= 1.1920929e-7) {
                return select(0.0, 1.0, c >= p1 + width * 0.5);
            }
            let x = clamp((c - p1) / width, 0.0, 1.0);
            return x * x * (3.0 - 2.0 * x);
        }
        default: { return 1.0; }
    }
}

fn rm_in_scatter(s: AirlightScene) -> AirlightResult {
    let d = normalize(s.dir);
    var a = vec3<f32>(0.0, 0.0, 1.0);
    if (s.light_kind != 0u) { a = normalize(s.light_axis); }
    let t0 = s.t_min;
    var t1 = s.t_max;
    if ((s.flags & 1u) != 0u) {
        t1 = select(t0 + AIRLIGHT_RM_FAR, t0 + 14.0 / s.sigma_t, s.sigma_t > 0.0);
    }
    let dt = (t1 - t0) / f32(STEPS);
    // x − p at the first midpoint, advanced by d·dt per step
    let start = s.origin + (t0 + 0.5 * dt) * d - s.light_position;
    let step = d * dt;
    var sum = 0.0;
    for (var i = 0u; i < STEPS; i++) {
        let u = start + f32(i) * step;
        let r2 = dot(u, u);
        let inv_r = inverseSqrt(r2);
        let r = r2 * inv_r;
        let c = dot(u, a) * inv_r;
        let mu = -dot(u, d) * inv_r;
        let along = (f32(i) + 0.5) * dt;
        let f = exp(-s.sigma_t * (along + r)) / r2;
        sum += f * rm_light(s.light_kind, s.light_param_a, s.light_param_b, c)
            * rm_phase(s.phase_kind, s.phase_param_a, s.phase_param_b, s.phase_param_c, mu);
    }
    let value = s.sigma_s * s.intensity * sum * dt;
    if ((bitcast<u32>(value) & 0x7f800000u) == 0x7f800000u) {
        return AirlightResult(3.40282347e38, 2u);
    }
    return AirlightResult(value, 0u);
}

@compute @workgroup_size(64)
fn airlight_main(@builtin(global_invocation_id) id: vec3<u32>) {
    let i = id.x;
    if (i >= arrayLength(&airlight_records)) {
        return;
    }
    airlight_results[i] = rm_in_scatter(airlight_records[i]);
}
