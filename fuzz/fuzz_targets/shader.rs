//! Target (3), differential: the CPU kernel against the committed compute shader
//! (shaders-out/wgsl/airlight_8.wgsl) on this machine's Vulkan adapter (lavapipe here). Each
//! input is a batch of up to 64 scenes (decoded as in the `kernel` target: arbitrary values,
//! special values and raw bits included), run in one dispatch and judged record by record
//! with the agreement criterion of `airlight_shaders::agreement` (the one the agreement tests
//! and `airlight verify` use): statuses equal, no NaN or Inf, values within
//! `9·noise + 2e-4·scale` — for records in its domain of agreement (input magnitudes in
//! `[2^-40, 2^40]`); outside it, where Vulkan's denormal flushing may change the geometry,
//! the result must be defined: same validity, finite, non-negative. Each scene also gives a
//! segment light (from the light to the light plus the raw axis vector) and, with an omni light,
//! a Lambertian surface point (at the ray's origin, facing its direction): run in a dispatch of
//! their own and judged as defined only — their outer loops of up to 77 ray integrals can reach
//! lavapipe's limit on loop iterations (codegen/shaders/shader/airlight.wgsl), which ends loops
//! early, so their values are the agreement tests' to judge. Built without a sanitizer (`-s none`: the driver is not
//! instrumented and wgpu under ASan is slow); `scripts/fuzz.sh` does that.
#![no_main]
use airlight::glam::Vec3;
use airlight_shaders::agreement::{expect, in_domain, judge, judge_defined, Expected};
use airlight_shaders::gpu::{Gpu, Prepared, Shader};
use airlight::{Brdf, SegmentLight, SegmentScene, Surface, SurfaceScene};
use airlight_shaders::layout::{pack, pack_segment, pack_surface, unpack_result, Record, RECORD_SIZE, RESULT_SIZE, STATUS_INVALID, STATUS_OK, SURFACE_LAMBERT, SURFACE_PHONG};
use airlight::record::SceneRecord;
use libfuzzer_sys::fuzz_target;
use std::sync::atomic::{AtomicUsize, Ordering};
use std::sync::OnceLock;

#[macro_use]
mod common;
use common::Batch;

const TERMS: usize = airlight::SHADER_NODES;

/// The adapter and the compiled pipeline, built once per process (leaked: they live as long
/// as the fuzzer).
fn pipeline() -> &'static Prepared<'static> {
    static PIPELINE: OnceLock<Prepared<'static>> = OnceLock::new();
    PIPELINE.get_or_init(|| {
        let gpu: &'static Gpu = Box::leak(Box::new(Gpu::new().expect("the shader target needs a Vulkan adapter (mesa-vulkan-drivers)")));
        eprintln!("shader target: {}", gpu.describe());
        gpu.prepare(Shader::Wgsl(airlight_shaders::targets::compute_wgsl(TERMS)))
    })
}

/// Scenes executed on the adapter so far, and how many of them in the domain of agreement
/// (printed every 10 000).
static SCENES: AtomicUsize = AtomicUsize::new(0);
static IN_DOMAIN: AtomicUsize = AtomicUsize::new(0);
/// Segment lights and surface points executed so far.
static OUTER: AtomicUsize = AtomicUsize::new(0);

fuzz_target!(|batch: Batch| {
    let mut records = Vec::new();
    let mut scenes = Vec::new();
    for raw in &batch.0 {
        let (ray, light, medium, phase) = scene_types!(f32, Vec3)(raw);
        let rec = SceneRecord { ray, light, medium, phase };
        records.extend_from_slice(&pack(&rec.ray, &rec.light, &rec.medium, &rec.phase));
        scenes.push(rec);
    }
    if scenes.is_empty() {
        return;
    }
    let out = pipeline().run(&records, false).expect("dispatch failed");
    for (i, rec) in scenes.iter().enumerate() {
        let (got, status) = unpack_result(&out[i * RESULT_SIZE..(i + 1) * RESULT_SIZE]);
        let e = expect(rec, TERMS);
        let j = if in_domain(rec) {
            IN_DOMAIN.fetch_add(1, Ordering::Relaxed);
            judge(&e, got, status)
        } else {
            judge_defined(&e, got, status)
        };
        if let Some(problem) = j.problem {
            panic!("CPU and shader disagree: {problem} for {rec:?}");
        }
    }
    // the outer integrals: (record, the CPU accepts it, what it is)
    let mut outer: Vec<([u8; RECORD_SIZE], bool, String)> = Vec::new();
    for (raw, rec) in batch.0.iter().zip(&scenes) {
        let l = rec.light;
        let tube = SegmentLight { a: l.position, b: l.position + Vec3::new(raw.axis[0] as f32, raw.axis[1] as f32, raw.axis[2] as f32), intensity: l.intensity, distribution: l.distribution };
        match SegmentScene::new(rec.ray, tube, rec.medium, rec.phase) {
            Ok(s) => outer.push((pack_segment(&s), true, format!("{s:?}"))),
            Err(_) => {
                let mut r = Record::new(&rec.ray, &l, &rec.medium, &rec.phase);
                r.light_end = tube.b.to_array();
                r.light_shape = airlight_shaders::layout::SHAPE_SEGMENT;
                outer.push((r.bytes(), false, format!("invalid segment light {tube:?} for {rec:?}")));
            }
        }
        if matches!(l.distribution, airlight::light::AnyDistribution::Omni) {
            let surface = Surface { position: rec.ray.origin, normal: rec.ray.dir };
            let view = Vec3::new(raw.axis[0] as f32, raw.axis[1] as f32, raw.axis[2] as f32);
            let (albedo, exponent) = (raw.w as f32, raw.w as f32 * 100.0);
            for brdf in [Brdf::Lambert { albedo }, Brdf::Phong { k_s: albedo, exponent, view }] {
                match SurfaceScene::new(surface, brdf, l, rec.medium, rec.phase) {
                    Ok(s) => outer.push((pack_surface(&s).expect("a surface lit by an omni light packs"), true, format!("{s:?}"))),
                    Err(_) => {
                        let ray = airlight::Ray { origin: surface.position, dir: surface.normal, t_min: 0.0, t_max: f32::INFINITY };
                        let mut r = Record::new(&ray, &l, &rec.medium, &rec.phase);
                        r.brdf_scale = albedo;
                        r.surface_kind = SURFACE_LAMBERT;
                        if let Brdf::Phong { exponent, view, .. } = brdf {
                            r.brdf_exponent = exponent;
                            r.brdf_view = view.to_array();
                            r.surface_kind = SURFACE_PHONG;
                        }
                        outer.push((r.bytes(), false, format!("invalid surface {surface:?} {brdf:?} for {rec:?}")));
                    }
                }
            }
        }
    }
    let bytes: Vec<u8> = outer.iter().flat_map(|o| o.0).collect();
    let out = pipeline().run(&bytes, false).expect("dispatch failed");
    for (i, (_, valid, what)) in outer.iter().enumerate() {
        let (got, status) = unpack_result(&out[i * RESULT_SIZE..(i + 1) * RESULT_SIZE]);
        let e = Expected { value: 0.0, status: if *valid { STATUS_OK } else { STATUS_INVALID }, f64_value: 0.0, noise: 0.0, scale: 0.0 };
        if let Some(problem) = judge_defined(&e, got, status).problem {
            panic!("shader result not defined: {problem} for {what}");
        }
    }
    OUTER.fetch_add(outer.len(), Ordering::Relaxed);
    let before = SCENES.fetch_add(scenes.len(), Ordering::Relaxed);
    if (before + scenes.len()) / 10_000 > before / 10_000 {
        let judged = IN_DOMAIN.load(Ordering::Relaxed);
        let outer = OUTER.load(Ordering::Relaxed);
        eprintln!("shader target: {} scenes executed on the adapter, {judged} in the domain of agreement; {outer} segment lights and surface points", before + scenes.len());
    }
});
