//! GPU throughput (rays/s) of the generated compute shader (`shaders-out/wgsl/airlight_8.wgsl`
//! and `airlight_12.wgsl`: error-controlled panels of 8 or 12 nodes) against two WGSL baselines
//! at equal accuracy, side by side in one run on whatever adapter wgpu finds (Mesa lavapipe on
//! machines without a GPU):
//!
//! * **Gauss–Legendre in the light angle** (`benches/gauss_angle.wgsl`, docs/DESIGN.md §9): the
//!   peer to beat, cut where the extinction exponent grew by 20, with the kernel's own rules of
//!   4 to 64 nodes per part, split at the foot, and *plain* (one part over the whole segment);
//! * a **ray marcher** (`benches/raymarch.wgsl`, midpoint rule, uniform steps, 8 to 4096).
//!
//! ```sh
//! cargo bench -p airlight-codegen --bench gpu
//! ```
//!
//! 1. Accuracy, untimed: per variant (isotropic; two-lobed c^4 light + Henyey–Greenstein
//!    g = 0.5), the relative error of every ray against the f64 CPU kernel's default path
//!    (same f32-rounded inputs; within 1e-10, tests/classes.rs) — median, 99th percentile and
//!    maximum — for the generated shaders (and, for reference, the f32 CPU kernel) and for each
//!    baseline over its grid. "Equal accuracy" = the smallest grid point whose statistic is ≤
//!    the generated shader's, for each of the three statistics (the **maximum** is the main
//!    figure); the grid points reaching 1e-3 and 1e-5 median error are timed too.
//! 2. Speed, timed by criterion (`Throughput::Elements(rays)`, so it reports rays/s): one group
//!    per variant with the generated shaders, the baselines at the picked grid points and a
//!    copy-only shader (upload + dispatch + read-back of the same buffers, no work: the fixed
//!    cost inside every other figure). Each timed call is [`Prepared::run`] (pipeline built
//!    once, outside the timing; buffers created, filled and read back per call, as `Gpu::run`).
//!    The 8-node shader is also emitted at the looser tolerances [`LOOSER_TOLERANCES`] (`airlight
//!    emit --tolerance`) and timed beside the committed ones, as the CPU bench takes the loosest
//!    tolerance that meets an accuracy level; at each tolerance also through the include
//!    library's point-light entry `airlight_in_scatter_point` (`point_compute_entry`: the ray
//!    integral without the emitter and surface loop, for shaders whose lights are all points),
//!    and in two passes (`gpu::run_deferred`: the route entry `airlight_in_scatter_route` over
//!    every ray, the point entry over the rays it defers, both timed with the gathering between);
//!    and, on the aniso rays, with its ray integral cut short ([`parts`]) to show where the time
//!    goes on the adapter.
//! 3. A summary table (variant, method, grid point, errors, rays/s, ratio), the pipeline build
//!    times and the SPIR-V instruction counts of the generated shaders, on stdout and in
//!    `target/criterion/gpu_summary.md`, from criterion's median estimates.

use airlight::glam::Vec3;
use airlight::light::{AnyDistribution, TwoLobed};
use airlight::phase::{AnyPhase, HenyeyGreenstein};
use airlight::{Medium, PointLight, Ray, Scene};
use airlight_shaders::targets::{compute_wgsl, point_compute_entry, point_compute_wgsl, render, route_compute_entry, route_compute_wgsl, Constants, EmitOptions, Target, NODE_COUNTS};
use airlight_shaders::gpu::{Gpu, Prepared, Shader};
use airlight_shaders::layout::{pack, unpack_result, RESULT_SIZE, STATUS_OK};
use airlight::record::SceneRecord;
use criterion::{Criterion, SamplingMode, Throughput};
use std::fmt::Write as _;
use std::path::PathBuf;
use std::time::{Duration, Instant};

/// Rays per timed call.
const RAYS: usize = 65_536;
/// The looser panel tolerances the 8-node shader is also emitted with (`airlight emit
/// --tolerance`) and timed at, beside the committed shaders' 1e-3: as the CPU bench picks the
/// loosest tolerance that meets an accuracy level.
const LOOSER_TOLERANCES: [f32; 2] = [1e-2, 1e-1];
const RAYMARCH: &str = include_str!("raymarch.wgsl");
const GAUSS_ANGLE: &str = include_str!("gauss_angle.wgsl");
const BASELINE_ENTRY: &str = include_str!("baseline_entry.wgsl");
/// The include library whose structs and phase/light functions the baselines use.
const LIBRARY: &str = include_str!("../../shaders-out/wgsl/airlight_lib_8.wgsl");
const STEPS_LINE: &str = "const STEPS: u32 = 64u;";
const NODES_LINE: &str = "const NODES: u32 = 8u;";
const RULE_LINE: &str = "const RULE = array<vec2<f32>, 4>(vec2<f32>(0.0, 0.0), vec2<f32>(0.0, 0.0), vec2<f32>(0.0, 0.0), vec2<f32>(0.0, 0.0));";
/// Ray-marcher step counts tried.
const STEP_GRID: [u32; 10] = [8, 16, 32, 64, 128, 256, 512, 1024, 2048, 4096];
/// The line of gauss_angle.wgsl that says whether the rule splits at the foot (false: plain).
const SPLIT_LINE: &str = "const SPLIT: bool = true;";
/// Gauss–Legendre nodes per part tried (every tabulated rule).
const NODE_GRID: [u32; 11] = [4, 6, 8, 10, 12, 16, 20, 24, 32, 48, 64];
/// The first lines of the ray integral's body in the generated shader (airlight.wgsl
/// `airlight_in_scatter_canonical`), before which [`parts`] cuts it short.
const RAY_INTEGRAL_BODY: &str = "    let t0 = g.t_lo;\n    let t1 = g.t_hi;\n";

/// Where the anisotropic time goes on this adapter: the 8-node shader at the loosest emitted
/// tolerance with its ray integral cut short — (id, what is left). Not usable shaders (the
/// route-only one returns 0 where the route declines or fails), only timings: Mesa's lavapipe
/// runs an `if` by masking its lanes, not by branching around it, so every ray pays for every
/// path the shader has; these say what the same rays cost with fewer paths.
fn parts() -> Vec<(String, &'static str, String)> {
    let tolerance = LOOSER_TOLERANCES[LOOSER_TOLERANCES.len() - 1];
    let full = Constants::from_kernel_with(8, tolerance).source(true);
    assert!(full.contains(RAY_INTEGRAL_BODY), "airlight.wgsl's ray integral lost its first lines");
    let cut = |body: &str| full.replacen(RAY_INTEGRAL_BODY, &format!("    {body}\n{RAY_INTEGRAL_BODY}"), 1);
    vec![
        (format!("part_machinery_tol{tolerance:e}"), "validation, record, reduction and outer loop only (the ray integral returns at once)", cut("return AirlightResult(g.h + g.x_h, AIRLIGHT_STATUS_OK);")),
        (
            format!("part_route_tol{tolerance:e}"),
            "the light-angle route only (no closed forms, no panels)",
            cut("{ let route = airlight_angle_route(s, g); return AirlightResult(route.x * route.y, select(AIRLIGHT_STATUS_INVALID, AIRLIGHT_STATUS_OK, route.x > 0.5)); }"),
        ),
    ]
}

/// The upload/dispatch/read-back cost alone: same bindings, writes (0, OK).
const COPY_ONLY: &str = r#"
struct AirlightScene { origin: vec3<f32>, t_min: f32, dir: vec3<f32>, t_max: f32, light_position: vec3<f32>, intensity: f32,
    light_axis: vec3<f32>, light_param_a: f32, light_param_b: f32, sigma_s: f32, sigma_t: f32, phase_param_a: f32,
    phase_param_b: f32, phase_param_c: f32, light_kind: u32, phase_kind: u32, flags: u32 }
struct AirlightResult { in_scatter: f32, status: u32 }
@group(0) @binding(0) var<storage, read> airlight_records: array<AirlightScene>;
@group(0) @binding(1) var<storage, read_write> airlight_results: array<AirlightResult>;
@compute @workgroup_size(64)
fn airlight_main(@builtin(global_invocation_id) id: vec3<u32>) {
    if (id.x >= arrayLength(&airlight_records)) { return; }
    airlight_results[id.x] = AirlightResult(airlight_records[id.x].intensity * 0.0, 0u);
}
"#;

/// A generated variant's pipelines: one, or two passes (`gpu::run_deferred`).
struct Pipelines<'g> {
    first: Prepared<'g>,
    rest: Option<Prepared<'g>>,
}

impl Pipelines<'_> {
    fn run(&self, records: &[u8]) -> Vec<u8> {
        match &self.rest {
            Some(rest) => airlight_shaders::gpu::run_deferred(&self.first, rest, records, false),
            None => self.first.run(records, false),
        }
        .expect("GPU run")
    }
}

/// A baseline shader family, parameterised by its grid point.
#[derive(Clone, Copy, PartialEq)]
enum Baseline {
    GaussAngle,
    GaussAnglePlain,
    RayMarch,
}

impl Baseline {
    const ALL: [Baseline; 3] = [Baseline::GaussAngle, Baseline::GaussAnglePlain, Baseline::RayMarch];

    fn name(self) -> &'static str {
        match self {
            Baseline::GaussAngle => "Gauss–Legendre in θ",
            Baseline::GaussAnglePlain => "Gauss–Legendre in θ, plain",
            Baseline::RayMarch => "ray-marcher",
        }
    }
    fn id(self) -> &'static str {
        match self {
            Baseline::GaussAngle => "gauss_angle",
            Baseline::GaussAnglePlain => "gauss_angle_plain",
            Baseline::RayMarch => "raymarch",
        }
    }
    fn unit(self) -> &'static str {
        match self {
            Baseline::GaussAngle => "nodes per part",
            Baseline::GaussAnglePlain => "nodes",
            Baseline::RayMarch => "steps",
        }
    }
    fn grid(self) -> &'static [u32] {
        match self {
            Baseline::GaussAngle | Baseline::GaussAnglePlain => &NODE_GRID,
            Baseline::RayMarch => &STEP_GRID,
        }
    }
    /// The WGSL source at grid point `n`: the include library, the baseline with its constants
    /// filled in (the Gauss–Legendre rule from the kernel's table), the shared entry point.
    fn source(self, n: u32) -> String {
        match self {
            Baseline::RayMarch => {
                assert!(RAYMARCH.contains(STEPS_LINE), "raymarch.wgsl lost its `{STEPS_LINE}` line");
                format!("{LIBRARY}\n{}\n{BASELINE_ENTRY}", RAYMARCH.replace(STEPS_LINE, &format!("const STEPS: u32 = {n}u;")))
            }
            Baseline::GaussAngle | Baseline::GaussAnglePlain => {
                assert!(GAUSS_ANGLE.contains(NODES_LINE) && GAUSS_ANGLE.contains(RULE_LINE) && GAUSS_ANGLE.contains(SPLIT_LINE), "gauss_angle.wgsl lost its NODES, RULE or SPLIT line");
                let split = format!("const SPLIT: bool = {};", self == Baseline::GaussAngle);
                let rule = airlight::expansion::gauss_table::rule(n as usize).expect("a tabulated rule");
                let pairs: Vec<String> = rule.iter().map(|&(x, w)| format!("vec2<f32>({:?}, {:?})", x as f32, w as f32)).collect();
                let rule_line = format!("const RULE = array<vec2<f32>, {}>({});", rule.len(), pairs.join(", "));
                format!("{LIBRARY}\n{}\n{BASELINE_ENTRY}", GAUSS_ANGLE.replace(NODES_LINE, &format!("const NODES: u32 = {n}u;")).replace(RULE_LINE, &rule_line).replace(SPLIT_LINE, &split))
            }
        }
    }
}

type S64 = Scene<f64, AnyDistribution<f64>, AnyPhase<f64>>;
type S32 = Scene<f32, AnyDistribution<f32>, AnyPhase<f32>>;

/// `RAYS` rays through a street-lamp-like scene (as kernel/benches/in_scatter.rs): origins at
/// 0, directions fanning out along +x, segments 5–65 long, the light 1–4 units off the rays,
/// σt from 0.01 to 0.31. Returns the packed f32 records, the same scenes for the f32 CPU
/// kernel, and the f64 scenes of the same (f32-rounded) inputs.
fn scenes(aniso: bool) -> (Vec<u8>, Vec<S32>, Vec<S64>) {
    let mut seed = 7u64;
    let mut rnd = || {
        seed = seed.wrapping_mul(6364136223846793005).wrapping_add(1442695040888963407);
        (seed >> 11) as f64 / (1u64 << 53) as f64
    };
    let r32 = |x: f64| x as f32;
    let v32 = |a: [f64; 3]| Vec3::new(a[0] as f32, a[1] as f32, a[2] as f32);
    let mut records = Vec::with_capacity(RAYS * airlight_shaders::layout::RECORD_SIZE);
    let mut cpu32 = Vec::with_capacity(RAYS);
    let mut reference = Vec::with_capacity(RAYS);
    for _ in 0..RAYS {
        let dir = v32([1.0, 0.2 * rnd() - 0.1, 0.2 * rnd() - 0.1]);
        let t_max = r32(5.0 + 60.0 * rnd());
        let position = v32([40.0 * rnd() - 5.0, 1.0 + 3.0 * rnd(), rnd()]);
        let sigma_t = r32(0.01 + 0.3 * rnd());
        let axis = Vec3::NEG_Y;
        let ray = Ray { origin: Vec3::ZERO, dir, t_min: 0.0, t_max };
        let (dist, phase) = if aniso {
            (AnyDistribution::TwoLobed(TwoLobed { axis, power: 4 }), AnyPhase::HenyeyGreenstein(HenyeyGreenstein { g: 0.5f32 }))
        } else {
            (AnyDistribution::Omni, AnyPhase::Isotropic)
        };
        let light = PointLight { position, intensity: 100.0f32, distribution: dist };
        let medium = Medium { sigma_s: 0.05f32, sigma_t };
        records.extend_from_slice(&pack(&ray, &light, &medium, &phase));
        cpu32.push(Scene::new(ray, light, medium, phase).expect("benchmark scene is valid"));
        let wide = SceneRecord { ray, light, medium, phase }.cast::<f64>();
        reference.push(Scene::new(wide.ray, wide.light, wide.medium, wide.phase).expect("benchmark scene is valid"));
    }
    (records, cpu32, reference)
}

/// Median, 99th percentile and maximum of the relative errors of the GPU `results` against
/// `reference`.
fn errors(results: &[u8], reference: &[f64]) -> [f64; 3] {
    assert_eq!(results.len(), reference.len() * RESULT_SIZE);
    let got = results.chunks(RESULT_SIZE).map(|r| {
        let (v, status) = unpack_result(r);
        if status == STATUS_OK { v as f64 } else { f64::NAN }
    });
    quantiles(got, reference)
}

/// Median, 99th percentile and maximum of the relative errors of `got` against `reference`
/// (NaN, or a non-zero value for a zero reference, counts as infinite).
fn quantiles(got: impl Iterator<Item = f64>, reference: &[f64]) -> [f64; 3] {
    let mut e: Vec<f64> = got
        .zip(reference)
        .map(|(v, &want)| {
            if v.is_nan() {
                f64::INFINITY
            } else if want == 0.0 {
                if v == 0.0 { 0.0 } else { f64::INFINITY }
            } else {
                ((v - want) / want).abs()
            }
        })
        .collect();
    assert_eq!(e.len(), reference.len());
    e.sort_by(|a, b| a.total_cmp(b));
    let q = |p: f64| e[((e.len() - 1) as f64 * p).round() as usize];
    [q(0.5), q(0.99), q(1.0)]
}

fn target_dir() -> PathBuf {
    std::env::var_os("CARGO_TARGET_DIR").map(PathBuf::from).unwrap_or_else(|| PathBuf::from(concat!(env!("CARGO_MANIFEST_DIR"), "/../target")))
}

/// criterion's median time per iteration (ns) of `group/id` from its last run.
fn criterion_median_ns(group: &str, id: &str) -> Option<f64> {
    let path = target_dir().join("criterion").join(group).join(id).join("new").join("estimates.json");
    let v: serde_json::Value = serde_json::from_str(&std::fs::read_to_string(path).ok()?).ok()?;
    v["median"]["point_estimate"].as_f64()
}

fn fmt_e(x: f64) -> String {
    if x == 0.0 { "0".into() } else if x.is_finite() { format!("{x:.1e}") } else { "inf".into() }
}

/// The error statistics, in the order [`quantiles`] returns them.
const STATS: [&str; 3] = ["median", "p99", "max"];

/// SPIR-V instruction count (lines of `spirv-dis` naming an `Op`) of a committed shader, if
/// `spirv-dis` is installed.
fn spirv_instructions(terms: u32) -> Option<usize> {
    let path = PathBuf::from(concat!(env!("CARGO_MANIFEST_DIR"), "/../shaders-out/spirv")).join(format!("airlight_{terms}.spv"));
    let out = std::process::Command::new("spirv-dis").arg(path).output().ok()?;
    out.status.success().then(|| String::from_utf8_lossy(&out.stdout).lines().filter(|l| l.contains("Op")).count())
}

fn main() {
    let gpu = match Gpu::new() {
        Ok(g) => g,
        Err(e) => {
            eprintln!("gpu bench skipped: {e}");
            return;
        }
    };
    let adapter = gpu.describe();
    println!("adapter: {adapter}");
    let mut c = Criterion::default().configure_from_args();
    let mut build_md = String::new();
    let mut prepare = |id: &str, src: &str| {
        let t = Instant::now();
        let p = gpu.prepare(Shader::Wgsl(src));
        let _ = writeln!(build_md, "| {id} | {:.0} |", t.elapsed().as_secs_f64() * 1e3);
        p
    };
    // the generated shaders take seconds to compile on lavapipe: once for both variants. The
    // committed ones, then the 8-node one emitted at the looser tolerances: (id, name, nodes,
    // tolerance, pipeline, and for two passes the second's)
    let mut sources: Vec<(String, String, usize, f32, String, Option<String>)> = NODE_COUNTS
        .iter()
        .map(|&n| (format!("generated_{n}"), format!("{n} nodes"), n, airlight::SHADER_CONTROL.tolerance, compute_wgsl(n).to_string(), None))
        .collect();
    // the point-light entry: the include library with `point_compute_entry`; the two passes:
    // with `route_compute_entry`, then with `point_compute_entry`
    let (point_entry, route_entry) = (point_compute_entry(), route_compute_entry());
    let default_tolerance = airlight::SHADER_CONTROL.tolerance;
    sources.push(("generated_8_point".into(), "8 nodes, point entry".into(), 8, default_tolerance, point_compute_wgsl(8), None));
    sources.push(("generated_8_two_pass".into(), "8 nodes, two passes".into(), 8, default_tolerance, route_compute_wgsl(8), Some(point_compute_wgsl(8))));
    for tolerance in LOOSER_TOLERANCES {
        let opts = EmitOptions { terms: vec![8], targets: vec![Target::Wgsl], tolerance };
        let mut files = render(&opts).expect("the shader emits at a tolerance in range");
        let mut take = |name: &str| String::from_utf8(files.remove(name).expect("an emitted 8-node WGSL file")).expect("WGSL is UTF-8");
        let (src, library) = (take("wgsl/airlight_8.wgsl"), take("wgsl/airlight_lib_8.wgsl"));
        sources.push((format!("generated_8_tol{tolerance:e}"), format!("8 nodes, tolerance {tolerance:e}"), 8, tolerance, src, None));
        sources.push((format!("generated_8_point_tol{tolerance:e}"), format!("8 nodes, point entry, tolerance {tolerance:e}"), 8, tolerance, format!("{library}\n{point_entry}"), None));
        sources.push((
            format!("generated_8_two_pass_tol{tolerance:e}"),
            format!("8 nodes, two passes, tolerance {tolerance:e}"),
            8,
            tolerance,
            format!("{library}\n{route_entry}"),
            Some(format!("{library}\n{point_entry}")),
        ));
    }
    let generated: Vec<(String, String, usize, f32, Pipelines<'_>)> = sources
        .into_iter()
        .map(|(id, name, n, tol, src, rest)| {
            let first = prepare(&id, &src);
            let rest = rest.map(|r| prepare(&format!("{id} (second pass)"), &r));
            (id, name, n, tol, Pipelines { first, rest })
        })
        .collect();
    let copy_only = prepare("copy_only", COPY_ONLY);
    let parts: Vec<(String, &str, Prepared<'_>)> = parts().into_iter().map(|(id, what, src)| { let p = prepare(&id, &src); (id, what, p) }).collect();
    let mut parts_md = String::new();
    let mut accuracy_md = String::new();
    let mut speed_md = String::new();
    let mut ratio_md = String::new();

    for (variant, aniso) in [("iso", false), ("aniso", true)] {
        let label = if aniso { "aniso (two-lobed c^4 light, HG g = 0.5)" } else { "iso (omni light, isotropic phase)" };
        let (records, cpu32, scenes) = scenes(aniso);
        let t = Instant::now();
        let reference: Vec<f64> = scenes.iter().map(|s| s.in_scatter()).collect();
        eprintln!("{variant}: f64 default-path reference for {RAYS} rays in {:.2?}", t.elapsed());

        // ---- accuracy, untimed
        let gen_err: Vec<(&str, [f64; 3])> =
            generated.iter().map(|(_, name, _, _, p)| (name.as_str(), errors(&p.run(&records), &reference))).collect();
        let cpu_err: Vec<(&str, [f64; 3])> = generated
            .iter()
            .map(|(_, name, n, tolerance, _)| {
                let control = airlight::panels::Control { tolerance: *tolerance, ..airlight::SHADER_CONTROL };
                (name.as_str(), quantiles(cpu32.iter().map(|s| s.in_scatter_panels_with_nodes(*n, control).unwrap() as f64), &reference))
            })
            .collect();
        let _ = writeln!(accuracy_md, "\n**{label}**, {RAYS} rays; relative error against the f64 CPU kernel's default path:\n");
        let _ = writeln!(accuracy_md, "| method | grid point | median | p99 | max | timed as |");
        let _ = writeln!(accuracy_md, "|---|---|---|---|---|---|");
        for &(name, e) in &gen_err {
            let _ = writeln!(accuracy_md, "| generated shader, {name} | — | {} | {} | {} | |", fmt_e(e[0]), fmt_e(e[1]), fmt_e(e[2]));
        }
        for &(name, e) in &cpu_err {
            let _ = writeln!(accuracy_md, "| (CPU kernel f32, the same method, {name}) | — | {} | {} | {} | not timed |", fmt_e(e[0]), fmt_e(e[1]), fmt_e(e[2]));
        }

        let group = format!("gpu_{variant}");
        // (baseline, grid point) → why it is timed
        let mut timed: Vec<(Baseline, u32, Vec<String>)> = Vec::new();
        // (baseline, generated shader's index, stat index, matched grid point)
        let mut matches: Vec<(Baseline, usize, usize, Option<u32>)> = Vec::new();
        let mut baseline_err: Vec<(Baseline, u32, [f64; 3])> = Vec::new();
        for baseline in Baseline::ALL {
            let grid = baseline.grid();
            let mut errs: Vec<(u32, [f64; 3])> = Vec::new();
            for &n in grid {
                let t = Instant::now();
                let out = gpu.run(Shader::Wgsl(&baseline.source(n)), &records, false).expect("baseline runs");
                let e = errors(&out, &reference);
                eprintln!("{variant}: {} {n:>4}: median {:.2e}, p99 {:.2e}, max {:.2e} ({:.2?})", baseline.id(), e[0], e[1], e[2], t.elapsed());
                errs.push((n, e));
            }
            let mut note = |n: u32, why: String| match timed.iter_mut().find(|p| p.0 == baseline && p.1 == n) {
                Some(p) if !p.2.contains(&why) => p.2.push(why),
                Some(_) => {}
                None => timed.push((baseline, n, vec![why])),
            };
            let pick = |stat: usize, target: f64| errs.iter().find(|e| e.1[stat] <= target).map(|e| e.0);
            for (i, &(name, e)) in gen_err.iter().enumerate() {
                for (k, stat) in STATS.iter().enumerate() {
                    let m = pick(k, e[k]);
                    note(m.unwrap_or(*grid.last().unwrap()), match m {
                        Some(_) => format!("{stat} = generated, {name}"),
                        None => "largest tried: a generated shader is not reached".into(),
                    });
                    matches.push((baseline, i, k, m));
                }
            }
            for target in [1e-3, 1e-5] {
                if let Some(n) = pick(0, target) {
                    note(n, format!("median ≤ {target:.0e}"));
                }
            }
            for &(n, e) in &errs {
                let why = timed.iter().find(|p| p.0 == baseline && p.1 == n).map(|p| p.2.join("; ")).unwrap_or_default();
                let _ = writeln!(accuracy_md, "| {} | {n} {} | {} | {} | {} | {why} |", baseline.name(), baseline.unit(), fmt_e(e[0]), fmt_e(e[1]), fmt_e(e[2]));
                baseline_err.push((baseline, n, e));
            }
        }
        timed.sort_by_key(|t| (Baseline::ALL.iter().position(|b| *b == t.0), t.1));

        // ---- speed, timed
        let prepared: Vec<(Baseline, u32, Prepared<'_>)> = timed.iter().map(|(b, n, _)| (*b, *n, gpu.prepare(Shader::Wgsl(&b.source(*n))))).collect();
        let mut g = c.benchmark_group(&group);
        g.sample_size(10)
            .sampling_mode(SamplingMode::Flat)
            .warm_up_time(Duration::from_millis(500))
            .measurement_time(Duration::from_secs(3))
            .throughput(Throughput::Elements(RAYS as u64));
        for (id, _, _, _, p) in &generated {
            g.bench_function(id.as_str(), |b| b.iter(|| p.run(&records)));
        }
        for (baseline, n, p) in &prepared {
            g.bench_function(format!("{}_{n}", baseline.id()), |b| b.iter(|| p.run(&records, false).expect("GPU run")));
        }
        g.bench_function("copy_only", |b| b.iter(|| copy_only.run(&records, false).expect("GPU run")));
        if aniso {
            for (id, _, p) in &parts {
                g.bench_function(id.as_str(), |b| b.iter(|| p.run(&records, false).expect("GPU run")));
            }
        }
        g.finish();

        // ---- summary rows, from criterion's median estimates
        let rays_per_s = |id: &str| criterion_median_ns(&group, id).map(|ns| RAYS as f64 / (ns * 1e-9));
        let mr = |x: Option<f64>| x.map(|r| format!("{:.3}", r * 1e-6)).unwrap_or_else(|| "—".into());
        let ms = |x: Option<f64>| x.map(|r| format!("{:.1}", RAYS as f64 / r * 1e3)).unwrap_or_else(|| "—".into());
        for (&(name, e), (id, ..)) in gen_err.iter().zip(&generated) {
            let r = rays_per_s(id);
            let _ = writeln!(speed_md, "| {variant} | generated shader, {name} | — | {} | {} | {} | {} | {} |", fmt_e(e[0]), fmt_e(e[1]), fmt_e(e[2]), ms(r), mr(r));
        }
        for (baseline, n, why) in &timed {
            let e = baseline_err.iter().find(|x| x.0 == *baseline && x.1 == *n).unwrap().2;
            let r = rays_per_s(&format!("{}_{n}", baseline.id()));
            let _ = writeln!(speed_md, "| {variant} | {} ({}) | {n} | {} | {} | {} | {} | {} |", baseline.name(), why.join("; "), fmt_e(e[0]), fmt_e(e[1]), fmt_e(e[2]), ms(r), mr(r));
        }
        let r = rays_per_s("copy_only");
        let _ = writeln!(speed_md, "| {variant} | copy only (upload + read-back, no work) | — | — | — | — | {} | {} |", ms(r), mr(r));
        if aniso {
            let loosest = format!("generated_8_tol{:e}", LOOSER_TOLERANCES[LOOSER_TOLERANCES.len() - 1]);
            let full = generated.iter().find(|g| g.0 == loosest).expect("the loosest-tolerance shader");
            let r = rays_per_s(&full.0);
            let _ = writeln!(parts_md, "| the whole shader ({}) | {} | {} | — |", full.1, ms(r), mr(r));
            for (id, what, p) in &parts {
                // statuses: the route-only shader marks the rays it does not take
                let out = p.run(&records, false).expect("GPU run");
                let taken = out.chunks(RESULT_SIZE).filter(|c| unpack_result(c).1 == STATUS_OK).count();
                let r = rays_per_s(id);
                let share = if id.starts_with("part_route") { format!("{:.1} %", 100.0 * taken as f64 / RAYS as f64) } else { "—".into() };
                let _ = writeln!(parts_md, "| {what} | {} | {} | {share} |", ms(r), mr(r));
            }
        }
        for (baseline, i, k, matched) in matches {
            let largest = *baseline.grid().last().unwrap();
            let (id, name, ..) = &generated[i];
            let ratio = match (rays_per_s(id), rays_per_s(&format!("{}_{}", baseline.id(), matched.unwrap_or(largest)))) {
                (Some(a), Some(b)) => format!("{:.2}×", a / b),
                _ => "—".into(),
            };
            let point = match matched {
                Some(n) => n.to_string(),
                None => format!("not reached by {largest} (timed {largest}: ratio is a lower bound)"),
            };
            let _ = writeln!(ratio_md, "| {variant} | {name} | {} | {} | {point} | {ratio} |", STATS[k], baseline.name());
        }
    }
    c.final_summary();

    let mut md = String::new();
    let _ = writeln!(md, "## GPU: generated shader vs Gauss–Legendre in the light angle and ray marching\n");
    let _ = writeln!(md, "`cargo bench -p airlight-codegen --bench gpu` — adapter: {adapter}; {RAYS} rays per call.\n");
    let _ = writeln!(md, "### Accuracy (untimed)");
    md.push_str(&accuracy_md);
    let _ = writeln!(md, "\n### Speed (criterion medians; every call uploads {RAYS} records, dispatches and reads the results back)\n");
    let _ = writeln!(md, "| variant | method | grid point | median rel. err | p99 rel. err | max rel. err | ms / call | Mrays/s |");
    let _ = writeln!(md, "|---|---|---|---|---|---|---|---|");
    md.push_str(&speed_md);
    let _ = writeln!(md, "\n### Ratio at equal accuracy: generated rays/s ÷ baseline rays/s (> 1: the generated shader is faster)\n");
    let _ = writeln!(md, "The baseline's grid point is the smallest whose error statistic is ≤ the generated shader's.\n");
    let _ = writeln!(md, "| variant | generated shader | matched on | baseline | grid point | ratio |");
    let _ = writeln!(md, "|---|---|---|---|---|---|");
    md.push_str(&ratio_md);
    let _ = writeln!(md, "\n### Where the time goes (aniso, the 8-node shader at tolerance {:e}, parts cut out; not usable shaders)\n", LOOSER_TOLERANCES[LOOSER_TOLERANCES.len() - 1]);
    let _ = writeln!(md, "| shader | ms / call | Mrays/s | rays the route takes |\n|---|---|---|---|");
    md.push_str(&parts_md);
    let _ = writeln!(md, "\nPipeline build (shader compilation by the driver), once per shader, outside the timing:\n\n| shader | ms |\n|---|---|");
    md.push_str(&build_md);
    let counts: Vec<String> = NODE_COUNTS.iter().map(|&t| spirv_instructions(t as u32).map(|n| format!("{t} nodes: {n}")).unwrap_or_else(|| format!("{t} nodes: spirv-dis not found"))).collect();
    let _ = writeln!(md, "\nSPIR-V instructions of the committed compute shaders: {}.", counts.join(", "));
    println!("\n{md}");
    let path = target_dir().join("criterion").join("gpu_summary.md");
    if std::fs::create_dir_all(path.parent().unwrap()).and_then(|_| std::fs::write(&path, &md)).is_ok() {
        println!("(written to {})", path.display());
    }
}
