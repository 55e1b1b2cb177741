//! Target (3), differential: the CPU kernel against the committed compute shader
//! (shaders-out/wgsl/airlight_8.wgsl) on this machine's Vulkan adapter (lavapipe here). Each
//! input is a batch of up to 64 scenes (decoded as in the `kernel` target: arbitrary values,
//! special values and raw bits included), run in one dispatch and judged record by record
//! with the agreement criterion of `airlight_shaders::agreement` (the one the agreement tests
//! and `airlight verify` use): statuses equal, no NaN or Inf, values within
//! `9·noise + 2e-4·scale` — for records in its domain of agreement (input magnitudes in
//! `[2^-40, 2^40]`); outside it, where Vulkan's denormal flushing may change the geometry,
//! the result must be defined: same validity, finite, non-negative. Built without a sanitizer (`-s none`: the driver is not
//! instrumented and wgpu under ASan is slow); `scripts/fuzz.sh` does that.
#![no_main]
use airlight::glam::Vec3;
use airlight_shaders::agreement::{expect, in_domain, judge, judge_defined};
use airlight_shaders::gpu::{Gpu, Prepared, Shader};
use airlight_shaders::layout::{pack, unpack_result, RESULT_SIZE};
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
    let before = SCENES.fetch_add(scenes.len(), Ordering::Relaxed);
    if (before + scenes.len()) / 10_000 > before / 10_000 {
        let judged = IN_DOMAIN.load(Ordering::Relaxed);
        eprintln!("shader target: {} scenes executed on the adapter, {judged} in the domain of agreement", before + scenes.len());
    }
});
