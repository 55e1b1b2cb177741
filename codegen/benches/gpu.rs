//! GPU throughput (rays/s) of the generated compute shader (`shaders-out/wgsl/airlight_4.wgsl`,
//! and `airlight_6.wgsl`) against a ray-marching WGSL baseline (`benches/raymarch.wgsl`,
//! midpoint rule, uniform steps) at equal accuracy, side by side in one run on whatever adapter
//! wgpu finds (Mesa lavapipe on machines without a GPU):
//!
//! ```sh
//! cargo bench -p airlight-codegen --bench gpu
//! ```
//!
//! 1. Accuracy, untimed: per variant (isotropic; two-lobed c^4 light + Henyey–Greenstein
//!    g = 0.5), the relative error of every ray against the f64 CPU kernel with 12 Chebyshev
//!    terms (same f32-rounded inputs) — median and 99th percentile — for the generated shaders
//!    (and, for reference, the f32 CPU kernel) and for the ray-marcher at STEPS = 8, 16, …, 4096.
//!    "Equal accuracy" = the smallest power-of-two STEPS whose **median** relative error is ≤
//!    the generated shader's median (the main figure); the same on the p99 is reported too.
//!    The step counts reaching 1e-3 and 1e-5 median error are also picked when reachable.
//! 2. Speed, timed by criterion (`Throughput::Elements(rays)`, so it reports rays/s): one group
//!    per variant with the generated shaders, the ray-marcher at the picked step counts and a
//!    copy-only shader (upload + dispatch + read-back of the same buffers, no work: the fixed
//!    cost inside every other figure). Each timed call is [`Prepared::run`] (pipeline built
//!    once, outside the timing; buffers created, filled and read back per call, as `Gpu::run`).
//! 3. A summary table (variant, method, steps, median/p99 error, rays/s, ratio) on stdout and in
//!    `target/criterion/gpu_summary.md`, from criterion's median estimates.

use airlight::glam::Vec3;
use airlight::light::{AnyDistribution, TwoLobed};
use airlight::phase::{AnyPhase, HenyeyGreenstein};
use airlight::{Expansion, Medium, PointLight, Ray, Scene};
use airlight_codegen::eval::compute_wgsl;
use airlight_codegen::gpu::{Gpu, Prepared, Shader};
use airlight_codegen::scene_json::SceneRecord;
use airlight_codegen::layout::{pack, unpack_result, RESULT_SIZE, STATUS_OK};
use criterion::{Criterion, SamplingMode, Throughput};
use std::fmt::Write as _;
use std::path::PathBuf;
use std::time::{Duration, Instant};

/// Rays per timed call.
const RAYS: usize = 65_536;
const RAYMARCH: &str = include_str!("raymarch.wgsl");
/// The include library whose structs and phase/light functions the ray-marcher uses.
const LIBRARY: &str = include_str!("../../shaders-out/wgsl/airlight_lib_4.wgsl");
const STEPS_LINE: &str = "const STEPS: u32 = 64u;";
/// Ray-marcher step counts tried for the accuracy table.
const STEP_GRID: [u32; 10] = [8, 16, 32, 64, 128, 256, 512, 1024, 2048, 4096];
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

fn raymarch_source(steps: u32) -> String {
    assert!(RAYMARCH.contains(STEPS_LINE), "raymarch.wgsl lost its `{STEPS_LINE}` line");
    format!("{LIBRARY}\n{}", RAYMARCH.replace(STEPS_LINE, &format!("const STEPS: u32 = {steps}u;")))
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
    let mut records = Vec::with_capacity(RAYS * airlight_codegen::layout::RECORD_SIZE);
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

/// Median and 99th percentile of the relative errors of the GPU `results` against `reference`.
fn errors(results: &[u8], reference: &[f64]) -> (f64, f64) {
    assert_eq!(results.len(), reference.len() * RESULT_SIZE);
    let got = results.chunks(RESULT_SIZE).map(|r| {
        let (v, status) = unpack_result(r);
        if status == STATUS_OK { v as f64 } else { f64::NAN }
    });
    quantiles(got, reference)
}

/// Median and 99th percentile of the relative errors of `got` against `reference` (NaN or a
/// non-zero value for a zero reference count as infinite).
fn quantiles(got: impl Iterator<Item = f64>, reference: &[f64]) -> (f64, f64) {
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
    (q(0.5), q(0.99))
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

/// Which error statistic the ray-marcher is matched on.
#[derive(Clone, Copy)]
enum Stat {
    Median,
    P99,
}

impl Stat {
    fn name(self) -> &'static str {
        match self {
            Stat::Median => "median",
            Stat::P99 => "p99",
        }
    }
    fn of(self, e: (f64, f64)) -> f64 {
        match self {
            Stat::Median => e.0,
            Stat::P99 => e.1,
        }
    }
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
    let largest = *STEP_GRID.last().unwrap();
    let mut build_md = String::new();
    let mut prepare = |id: &str, src: &str| {
        let t = Instant::now();
        let p = gpu.prepare(Shader::Wgsl(src));
        let _ = writeln!(build_md, "| {id} | {:.0} |", t.elapsed().as_secs_f64() * 1e3);
        p
    };
    // the generated shaders take seconds to compile on lavapipe: once for both variants
    let generated = [4u32, 6].map(|terms| (terms, prepare(&format!("generated_{terms}"), compute_wgsl(terms as usize))));
    let copy_only = prepare("copy_only", COPY_ONLY);
    let mut accuracy_md = String::new();
    let mut speed_md = String::new();
    let mut ratio_md = String::new();

    for (variant, aniso) in [("iso", false), ("aniso", true)] {
        let label = if aniso { "aniso (two-lobed c^4 light, HG g = 0.5)" } else { "iso (omni light, isotropic phase)" };
        let (records, cpu32, scenes) = scenes(aniso);
        let t = Instant::now();
        let reference: Vec<f64> = scenes.iter().map(|s| s.in_scatter_with::<12>(Expansion::Chebyshev)).collect();
        eprintln!("{variant}: f64 12-term reference for {RAYS} rays in {:.2?}", t.elapsed());

        // ---- accuracy, untimed
        let gen_err: Vec<(u32, (f64, f64))> =
            generated.iter().map(|(terms, p)| (*terms, errors(&p.run(&records, false).expect("generated shader runs"), &reference))).collect();
        let cpu_err = [
            (4, quantiles(cpu32.iter().map(|s| s.in_scatter_with::<4>(Expansion::Chebyshev) as f64), &reference)),
            (6, quantiles(cpu32.iter().map(|s| s.in_scatter_with::<6>(Expansion::Chebyshev) as f64), &reference)),
        ];
        let mut rm_err: Vec<(u32, (f64, f64))> = Vec::new();
        for &steps in &STEP_GRID {
            let t = Instant::now();
            let out = gpu.run(Shader::Wgsl(&raymarch_source(steps)), &records, false).expect("ray-marcher runs");
            let e = errors(&out, &reference);
            eprintln!("{variant}: raymarch {steps:>4} steps: median {:.2e}, p99 {:.2e} ({:.2?})", e.0, e.1, t.elapsed());
            rm_err.push((steps, e));
        }
        let pick = |stat: Stat, target: f64| rm_err.iter().find(|e| stat.of(e.1) <= target).map(|e| e.0);
        // step counts to time, with why
        let mut picks: Vec<(u32, Vec<String>)> = Vec::new();
        let mut note = |steps: u32, why: String| match picks.iter_mut().find(|p| p.0 == steps) {
            Some(p) if !p.1.contains(&why) => p.1.push(why),
            Some(_) => {}
            None => picks.push((steps, vec![why])),
        };
        // (terms, stat, matched steps or None, steps timed against)
        let mut matches = Vec::new();
        for &(terms, e) in &gen_err {
            for stat in [Stat::Median, Stat::P99] {
                let m = pick(stat, stat.of(e));
                match m {
                    Some(s) => note(s, format!("{} = generated {terms}", stat.name())),
                    None => note(largest, "largest tried: the generated shader is not reached".into()),
                }
                matches.push((terms, stat, m, m.unwrap_or(largest)));
            }
        }
        for target in [1e-3, 1e-5] {
            if let Some(s) = pick(Stat::Median, target) {
                note(s, format!("median ≤ {target:.0e}"));
            }
        }
        picks.sort();

        let _ = writeln!(accuracy_md, "\n**{label}**, {RAYS} rays; relative error against the f64 CPU kernel with 12 Chebyshev terms:\n");
        let _ = writeln!(accuracy_md, "| method | steps | median rel. error | p99 rel. error | timed as |");
        let _ = writeln!(accuracy_md, "|---|---|---|---|---|");
        for &(terms, e) in &gen_err {
            let _ = writeln!(accuracy_md, "| generated shader, {terms} terms | — | {} | {} | |", fmt_e(e.0), fmt_e(e.1));
        }
        for &(terms, e) in &cpu_err {
            let _ = writeln!(accuracy_md, "| (CPU kernel f32, {terms} terms, for reference) | — | {} | {} | not timed |", fmt_e(e.0), fmt_e(e.1));
        }
        for &(steps, e) in &rm_err {
            let why = picks.iter().find(|p| p.0 == steps).map(|p| p.1.join("; ")).unwrap_or_default();
            let _ = writeln!(accuracy_md, "| ray-marcher | {steps} | {} | {} | {why} |", fmt_e(e.0), fmt_e(e.1));
        }
        for target in [1e-3, 1e-5] {
            if pick(Stat::Median, target).is_none() {
                let _ = writeln!(accuracy_md, "\nMedian {target:.0e} is not reached by the ray-marcher up to {largest} steps (f32).");
            }
        }

        // ---- speed, timed
        let marchers: Vec<(u32, Prepared<'_>)> = picks.iter().map(|(s, _)| (*s, gpu.prepare(Shader::Wgsl(&raymarch_source(*s))))).collect();
        let group = format!("gpu_{variant}");
        let mut g = c.benchmark_group(&group);
        g.sample_size(10)
            .sampling_mode(SamplingMode::Flat)
            .warm_up_time(Duration::from_millis(500))
            .measurement_time(Duration::from_secs(3))
            .throughput(Throughput::Elements(RAYS as u64));
        for (terms, p) in &generated {
            g.bench_function(format!("generated_{terms}"), |b| b.iter(|| p.run(&records, false).expect("GPU run")));
        }
        for (steps, p) in &marchers {
            g.bench_function(format!("raymarch_{steps}"), |b| b.iter(|| p.run(&records, false).expect("GPU run")));
        }
        g.bench_function("copy_only", |b| b.iter(|| copy_only.run(&records, false).expect("GPU run")));
        g.finish();

        // ---- summary rows, from criterion's median estimates
        let rays_per_s = |id: &str| criterion_median_ns(&group, id).map(|ns| RAYS as f64 / (ns * 1e-9));
        let mr = |x: Option<f64>| x.map(|r| format!("{:.3}", r * 1e-6)).unwrap_or_else(|| "—".into());
        let ms = |x: Option<f64>| x.map(|r| format!("{:.1}", RAYS as f64 / r * 1e3)).unwrap_or_else(|| "—".into());
        for &(terms, e) in &gen_err {
            let r = rays_per_s(&format!("generated_{terms}"));
            let _ = writeln!(speed_md, "| {variant} | generated shader, {terms} terms | — | {} | {} | {} | {} |", fmt_e(e.0), fmt_e(e.1), ms(r), mr(r));
        }
        for (steps, why) in &picks {
            let e = rm_err.iter().find(|e| e.0 == *steps).unwrap().1;
            let r = rays_per_s(&format!("raymarch_{steps}"));
            let _ = writeln!(speed_md, "| {variant} | ray-marcher ({}) | {steps} | {} | {} | {} | {} |", why.join("; "), fmt_e(e.0), fmt_e(e.1), ms(r), mr(r));
        }
        let r = rays_per_s("copy_only");
        let _ = writeln!(speed_md, "| {variant} | copy only (upload + read-back, no work) | — | — | — | {} | {} |", ms(r), mr(r));
        for (terms, stat, matched, timed) in matches {
            let ratio = match (rays_per_s(&format!("generated_{terms}")), rays_per_s(&format!("raymarch_{timed}"))) {
                (Some(a), Some(b)) => format!("{:.2}×", a / b),
                _ => "—".into(),
            };
            let steps = match matched {
                Some(s) => s.to_string(),
                None => format!("not reached by {largest} (timed {largest}: ratio is a lower bound)"),
            };
            let _ = writeln!(ratio_md, "| {variant} | {terms} | {} | {steps} | {ratio} |", stat.name());
        }
    }
    c.final_summary();

    let mut md = String::new();
    let _ = writeln!(md, "## GPU: generated shader vs ray marching\n");
    let _ = writeln!(md, "`cargo bench -p airlight-codegen --bench gpu` — adapter: {adapter}; {RAYS} rays per call.\n");
    let _ = writeln!(md, "### Accuracy (untimed)");
    md.push_str(&accuracy_md);
    let _ = writeln!(md, "\n### Speed (criterion medians; every call uploads {RAYS} records, dispatches and reads the results back)\n");
    let _ = writeln!(md, "| variant | method | steps | median rel. err | p99 rel. err | ms / call | Mrays/s |");
    let _ = writeln!(md, "|---|---|---|---|---|---|---|");
    md.push_str(&speed_md);
    let _ = writeln!(md, "\n### Ratio at equal accuracy: generated rays/s ÷ ray-marcher rays/s (> 1: the generated shader is faster)\n");
    let _ = writeln!(md, "The ray-marcher's step count is the smallest power of two whose error statistic is ≤ the generated shader's.\n");
    let _ = writeln!(md, "| variant | terms | matched on | ray-marcher steps | ratio |");
    let _ = writeln!(md, "|---|---|---|---|---|");
    md.push_str(&ratio_md);
    let _ = writeln!(md, "\nPipeline build (shader compilation by the driver), once per shader, outside the timing:\n\n| shader | ms |\n|---|---|");
    md.push_str(&build_md);
    println!("\n{md}");
    let path = target_dir().join("criterion").join("gpu_summary.md");
    if std::fs::create_dir_all(path.parent().unwrap()).and_then(|_| std::fs::write(&path, &md)).is_ok() {
        println!("(written to {})", path.display());
    }
}
