// Ray-marching baseline for the GPU benchmark (codegen/benches/gpu.rs): the same record buffer
// (binding 0, the 144-byte `AirlightScene` of codegen/shaders/src/layout.rs) and the same 8-byte results
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
// The benchmark puts this between the include library (shaders-out/wgsl/airlight_lib_4.wgsl:
// the record structs, and the phase function and light distribution the generated kernel uses,
// `airlight_phase_mu` and `airlight_light`) and the shared entry point (baseline_entry.wgsl),
// and replaces the `const STEPS` line below.

const STEPS: u32 = 64u;
const AIRLIGHT_RM_FAR: f32 = 1000.0;

fn baseline_in_scatter(s: AirlightScene) -> AirlightResult {
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
        sum += f * airlight_light(s.light_kind, s.light_param_a, s.light_param_b, c)
            * airlight_phase_mu(s.phase_kind, s.phase_param_a, s.phase_param_b, s.phase_param_c, mu);
    }
    let value = s.sigma_s * s.intensity * sum * dt;
    return baseline_result(value);
}
