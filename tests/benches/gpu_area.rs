//! Area lights on the GPU against one point light, side by side in one run on whatever adapter
//! wgpu finds (Mesa's lavapipe on machines without a GPU): the bounded method's shader entry
//! `airlight_in_scatter_area` (`targets::area_compute_wgsl`, docs/DESIGN.md §12) over the
//! records of tests/reference/area.jsonl, shape by shape, against the generated compute shader
//! (`shaders-out/wgsl/airlight_8.wgsl`) and its point-light entry on the same rays lit by one
//! omni point light at the emitter's centre (intensity `L_e·area`, a sphere's `π R² L_e`): what an
//! area light costs in point lights on the GPU, as `extended.rs` measures it on the CPU.
//!
//! Accuracy first, untimed: each shader's largest relative error over the shape's records
//! against area.jsonl's references (the point lights: against the f64 CPU kernel's default path
//! on the same f32 inputs). Timed by criterion: every call uploads [`RAYS`] area-light records
//! or [`POINT_RAYS`] point-light ones (the shape's records repeated), dispatches and reads the
//! results back; pipelines are built once, outside the timing, and their build times reported.
//! The table gives the median of criterion's samples per shader, in µs a ray, and the ratios of
//! the area entry's to the point light's.
//!
//! `cargo bench -p airlight-tests --bench gpu_area`

use airlight::light::AnyDistribution;
use airlight::phase::AnyPhase;
use airlight::record::SceneRecord;
use airlight::{AreaScene, Emitter, PointLight, Scene};
use airlight_codegen::scene_json::{parse_any_value, AnyRecord};
use airlight_shaders::gpu::{Gpu, Shader};
use airlight_shaders::layout::{pack, pack_area, unpack_result, RESULT_SIZE};
use airlight_shaders::targets::{area_compute_wgsl, compute_wgsl, point_compute_wgsl};
use airlight_tests::{reference_lines, rel_err};
use criterion::{Criterion, SamplingMode};
use std::fmt::Write as _;
use std::time::{Duration, Instant};

/// Rays per timed call of the area entry: a shape's records repeated (about a second a call on
/// lavapipe).
const RAYS: usize = 1024;
/// Rays per timed call of a point-light shader (as `codegen/benches/gpu.rs`): with as few as the
/// area entry's, the upload, dispatch and read-back would be most of the time.
const POINT_RAYS: usize = 65_536;
/// Criterion's samples per shader (each a whole number of calls; their median is reported).
const SAMPLES: usize = 10;

/// The omni point light at an area light's centre radiating its whole output `L_e·area`, on the
/// same ray, medium and phase function.
fn point_of(area: &AreaScene<f32, AnyPhase<f32>>) -> Scene<f32, AnyDistribution<f32>, AnyPhase<f32>> {
    let l = area.light();
    let (position, size) = match l.emitter {
        Emitter::Disc { center, radius, .. } | Emitter::Sphere { center, radius } => (center, std::f32::consts::PI * radius * radius),
        Emitter::Rectangle { corner, edge_u, edge_v } => (corner + 0.5 * (edge_u + edge_v), edge_u.cross(edge_v).length()),
    };
    let light = PointLight { position, intensity: l.radiance * size, distribution: AnyDistribution::Omni };
    Scene::new(*area.ray(), light, *area.medium(), *area.phase()).expect("a point light at a valid area light's centre is valid")
}

/// Each record's result of a run.
fn results(out: &[u8]) -> impl Iterator<Item = f64> + '_ {
    out.chunks_exact(RESULT_SIZE).map(|c| unpack_result(c).0 as f64)
}

fn main() {
    let gpu = match Gpu::new() {
        Ok(g) => g,
        Err(e) => {
            eprintln!("gpu_area bench skipped: {e}");
            return;
        }
    };
    println!("adapter: {}", gpu.describe());
    let mut c = Criterion::default().configure_from_args();
    let mut build_md = String::new();
    let mut prepare = |id: &str, src: &str| {
        let t = Instant::now();
        let p = gpu.prepare(Shader::Wgsl(src));
        let _ = writeln!(build_md, "| {id} | {:.0} |", t.elapsed().as_secs_f64() * 1e3);
        p
    };
    let area_shader = prepare("area entry (8 nodes)", &area_compute_wgsl(8));
    let full_shader = prepare("compute shader (8 nodes)", compute_wgsl(8));
    let point_shader = prepare("point entry (8 nodes)", &point_compute_wgsl(8));
    let mut table = String::new();
    for shape in ["disc", "rectangle", "sphere"] {
        let lines: Vec<_> = reference_lines("area.jsonl").into_iter().filter(|v| v["light"]["shape"] == shape).collect();
        let (areas, exact): (Vec<_>, Vec<f64>) = lines
            .iter()
            .map(|v| match parse_any_value::<f32>(v) {
                Ok(AnyRecord::Area(s)) => (s, v["in_scatter"].as_f64().expect("a reference value")),
                other => panic!("area.jsonl holds area lights valid in f32, not {other:?}"),
            })
            .unzip();
        let points: Vec<_> = areas.iter().map(point_of).collect();
        let point_exact: Vec<f64> = points
            .iter()
            .map(|p| {
                let wide = SceneRecord { ray: *p.ray(), light: *p.light(), medium: *p.medium(), phase: *p.phase() }.cast::<f64>();
                Scene::new(wide.ray, wide.light, wide.medium, wide.phase).expect("the same scene in f64").in_scatter()
            })
            .collect();
        let repeat = |bytes: Vec<[u8; airlight_shaders::layout::RECORD_SIZE]>, rays: usize| -> Vec<u8> { (0..rays).flat_map(|i| bytes[i % bytes.len()]).collect() };
        let area_records = repeat(areas.iter().map(pack_area).collect(), RAYS);
        let point_records = repeat(points.iter().map(|s| pack(s.ray(), s.light(), s.medium(), s.phase())).collect(), POINT_RAYS);
        let n = areas.len();
        let worst = |out: &[u8], exact: &[f64]| results(out).take(n).zip(exact).map(|(x, e)| rel_err(x, *e)).fold(0.0f64, f64::max);
        let errs = [
            worst(&area_shader.run(&area_records, false).expect("GPU run"), &exact),
            worst(&full_shader.run(&point_records, false).expect("GPU run"), &point_exact),
            worst(&point_shader.run(&point_records, false).expect("GPU run"), &point_exact),
        ];
        let group = format!("gpu_area_{shape}");
        let mut g = c.benchmark_group(&group);
        g.sample_size(SAMPLES).sampling_mode(SamplingMode::Flat).warm_up_time(Duration::from_millis(500)).measurement_time(Duration::from_secs(3));
        let mut median = |id: &str, p: &airlight_shaders::gpu::Prepared<'_>, records: &[u8]| {
            let mut times = Vec::new();
            g.bench_function(id, |b| {
                b.iter_custom(|iters| {
                    let t = Instant::now();
                    for _ in 0..iters {
                        p.run(records, false).expect("GPU run");
                    }
                    let e = t.elapsed();
                    times.push(e.as_secs_f64() / iters as f64);
                    e
                })
            });
            // the last SAMPLES calls are criterion's samples (the ones before, its warm-up)
            let mut samples = times.split_off(times.len() - SAMPLES);
            samples.sort_by(f64::total_cmp);
            samples[SAMPLES / 2]
        };
        let t_area = median("area_entry", &area_shader, &area_records) / RAYS as f64;
        let t_full = median("point_light_compute_shader", &full_shader, &point_records) / POINT_RAYS as f64;
        let t_point = median("point_light_point_entry", &point_shader, &point_records) / POINT_RAYS as f64;
        g.finish();
        let _ = writeln!(
            table,
            "| {shape} | {n} | {:.1} ({:.1e}) | {:.2} ({:.1e}) | {:.2} ({:.1e}) | {:.0} | {:.0} |",
            t_area * 1e6,
            errs[0],
            t_full * 1e6,
            errs[1],
            t_point * 1e6,
            errs[2],
            t_area / t_full,
            t_area / t_point
        );
    }
    c.final_summary();
    println!("\n{RAYS} area lights or {POINT_RAYS} point lights a call; µs a ray (largest relative error over the shape's records):\n");
    println!("| shape | records | area entry | point light, compute shader | point light, point entry | area / compute shader | area / point entry |");
    println!("|---|---|---|---|---|---|---|");
    print!("{table}");
    println!("\nPipeline build, once per shader, outside the timing:\n\n| shader | ms |\n|---|---|");
    print!("{build_md}");
}
