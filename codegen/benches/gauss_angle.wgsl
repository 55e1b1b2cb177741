// Gauss–Legendre in the angle seen from the light: the GPU benchmark's (codegen/benches/gpu.rs)
// peer, the strongest simple alternative a renderer engineer writes instead of closed forms
// (docs/DESIGN.md §9; on the CPU `airlight::march::gauss_angle`). Same record buffer (binding
// 0) and results (binding 1) as the generated `airlight_main`, workgroup size 64.
//
// With t − x_h = h·tan θ, dt/r² = dθ/h:
//   L_m = (σs I / h) ∫ e^{−σt (x_h − t0 + h (tan θ + sec θ))} D(d_el sin θ + d_c cos θ) P(−sin θ) dθ
// over [atan u0, atan u1] (π/2 for an infinite ray), split at the foot θ = 0 (SPLIT; without it
// one part, "plain") and cut where the exponent has grown by CUT from its start
// (tan(θ/2 + π/4) − tan(θ0/2 + π/4) = CUT/(σt h)), NODES Gauss–Legendre nodes per part, with the
// shader language's own atan, sin, cos and exp, as a user would write it. The canonical
// reduction is the library's plain one.
//
// The benchmark puts this between the include library (shaders-out/wgsl/airlight_lib_4.wgsl,
// for the record structs, `airlight_canonical`, `airlight_light` and `airlight_phase_mu`) and
// the shared entry point (baseline_entry.wgsl), and replaces the three lines below: NODES, RULE
// with the kernel's own rule of that many nodes (`airlight::expansion::gauss_table`, (x, w) for
// x > 0), and SPLIT.

const NODES: u32 = 8u;
const SPLIT: bool = true;
const RULE = array<vec2<f32>, 4>(vec2<f32>(0.0, 0.0), vec2<f32>(0.0, 0.0), vec2<f32>(0.0, 0.0), vec2<f32>(0.0, 0.0));
const CUT: f32 = 20.0;
const HALF_PI: f32 = 1.5707963267948966;

fn ga_part(s: AirlightScene, g: AirlightCanonical, a: f32, b: f32) -> f32 {
    let mid = (a + b) * 0.5;
    let hw = (b - a) * 0.5;
    var rule = RULE;
    var part = 0.0;
    for (var j = 0u; j < NODES / 2u; j++) {
        for (var k = 0u; k < 2u; k++) {
            let th = mid + hw * rule[j].x * select(1.0, -1.0, k == 0u);
            let sn = sin(th);
            let cs = cos(th);
            let exponent = s.sigma_t * ((g.x_h - g.t_lo) + g.h * (sn + 1.0) / cs);
            let f = airlight_light(s.light_kind, s.light_param_a, s.light_param_b, g.d_el * sn + g.d_c * cs)
                * airlight_phase_mu(s.phase_kind, s.phase_param_a, s.phase_param_b, s.phase_param_c, -sn);
            part += rule[j].y * exp(-exponent) * f;
        }
    }
    return part * hw;
}

fn baseline_in_scatter(s: AirlightScene) -> AirlightResult {
    let g = airlight_canonical(s);
    let th0 = atan((g.t_lo - g.x_h) / g.h);
    var th1 = HALF_PI;
    if (!g.t_hi_infinite) { th1 = atan((g.t_hi - g.x_h) / g.h); }
    let big_h = s.sigma_t * g.h;
    if (big_h > 0.0) {
        let y0 = tan(th0 * 0.5 + HALF_PI * 0.5);
        th1 = min(th1, 2.0 * atan(y0 + CUT / big_h) - HALF_PI);
    }
    var sum = 0.0;
    if (SPLIT && th0 < 0.0 && th1 > 0.0) {
        sum = ga_part(s, g, th0, 0.0) + ga_part(s, g, 0.0, th1);
    } else if (th1 > th0) {
        sum = ga_part(s, g, th0, th1);
    }
    let value = s.sigma_s * s.intensity / g.h * sum;
    return baseline_result(value);
}
