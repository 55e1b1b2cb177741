//! CPU/shader agreement on a real Vulkan driver: the artifacts in shaders-out/ are
//! *executed* — the WGSL through wgpu, the committed SPIR-V as it is, the GLSL 450 and HLSL
//! compute shaders after glslang compiled them to SPIR-V — and compared with the f32 CPU
//! kernel computing the same method (the panels with the same nodes per panel and
//! `airlight::SHADER_CONTROL`), and with the f64 kernel, over property-generated scenes
//! (including the extremes of docs/DESIGN.md §3) and invalid records.
//!
//! Judged with the one criterion of `airlight_shaders::agreement` (its module docs derive it
//! from Vulkan's precision rules): `|gpu − cpu_f32| ≤ 9·noise + 2e-4·scale (+ 2^-100)`, `noise`
//! the f32 spread of the same method over one-ulp input perturbations plus its error against
//! the f64 default path; statuses equal; no NaN, no Inf. Asserted for every artifact kind at 8
//! and 12 nodes. The mpmath reference scenes (tests/reference/scenes.jsonl) run through the
//! shaders too: the `f32_exact` ones (isotropic, inputs exact in f32) must be within 1e-4 of
//! the quadrature value, as the CPU kernel is (`tests/reference.rs`). The hard scene classes
//! (tests/reference/classes.jsonl) must be within 1e-3 (`shaders_meet_the_class_targets`).
//!
//! Printed (`--nocapture`) and written to `target/agreement.md`: per artifact and node count,
//! the largest and median difference to the f32 CPU kernel and the largest to the f64 kernel
//! (of scale; values above 2^-80), and the largest error against the `f32_exact` reference
//! values — the closing note's table.

use airlight_shaders::agreement::{expect, judge, Expected};
use airlight_shaders::gpu::{Gpu, Shader};
use airlight_shaders::layout::{pack, unpack_result, RECORD_SIZE, RESULT_SIZE, STATUS_INVALID};
use airlight::record::SceneRecord;
use airlight_codegen::scene_json::parse_value;
use airlight_shaders::targets::{compute_wgsl, default_out_dir, point_compute_wgsl, NODE_COUNTS};
use airlight_tests::scenes::{random, Aniso, Plain};
use airlight_tests::{class_cases, reference_lines, rel_err, repo_root, ClassCase, Rng};
use std::process::Command;

const CASES: usize = 10_000;

fn gpu() -> Option<Gpu> {
    match Gpu::new() {
        Ok(g) => Some(g),
        Err(e) => {
            if std::env::var("CI").as_deref() == Ok("true") {
                panic!("no GPU adapter (CI=true: install mesa-vulkan-drivers and libvulkan1): {e}");
            }
            eprintln!("WARNING: no GPU adapter, agreement tests SKIPPED (CI fails instead): {e}");
            None
        }
    }
}

/// Scenes: random ones over wide ranges, plus the extremes of docs/DESIGN.md §3.
fn scenes() -> Vec<Plain> {
    let mut rng = Rng(42);
    let mut out = Vec::new();
    while out.len() < CASES {
        let mut p = random(&mut rng, if out.len() % 3 == 0 { Aniso::None } else { Aniso::Any });
        match out.len() % 10 {
            // σt up to 1e3/h: thick media
            7 => p.sigma_t = 1e3 * rng.unit() / p.light.iter().zip(&p.origin).map(|(a, b)| (a - b).abs()).fold(1e-3, f64::max),
            // light far behind the camera
            8 => {
                for i in 0..3 {
                    p.light[i] = p.origin[i] - (50.0 + 500.0 * rng.unit()) * p.dir[i] + p.light[i] * 1e-3;
                }
            }
            // light (almost) on the ray line, outside the segment
            9 => {
                for i in 0..3 {
                    p.light[i] = p.origin[i] + (p.t_min - 1.0 - 10.0 * rng.unit()) * p.dir[i];
                }
            }
            _ => {}
        }
        out.push(p.rounded());
    }
    out
}

fn record(p: &Plain) -> SceneRecord<f32> {
    let s = p.f32();
    SceneRecord { ray: *s.ray(), light: *s.light(), medium: *s.medium(), phase: *s.phase() }
}

/// The mpmath reference scenes that are valid in f32, with their quadrature value and
/// whether they are `f32_exact`.
fn reference_scenes() -> Vec<(SceneRecord<f32>, f64, bool)> {
    reference_lines("scenes.jsonl")
        .iter()
        .filter_map(|v| {
            let want = v["in_scatter"].as_f64()?;
            let rec = parse_value::<f32>(v).ok()?;
            Some((rec, want, v["category"].as_str() == Some("f32_exact")))
        })
        .collect()
}

struct Case {
    records: Vec<u8>,
    expected: Vec<Expected>,
    /// The scene of each expected result, for failure messages (`None`: a patched invalid
    /// record).
    scenes: Vec<Option<SceneRecord<f32>>>,
    /// Index of the first reference scene in `expected`, and the scenes' (value, f32_exact).
    reference_start: usize,
    reference: Vec<(f64, bool)>,
}

fn case(terms: usize) -> Case {
    let mut records = Vec::new();
    let mut expected = Vec::new();
    let mut described = Vec::new();
    for p in scenes() {
        let rec = record(&p);
        records.extend_from_slice(&pack(&rec.ray, &rec.light, &rec.medium, &rec.phase));
        expected.push(expect(&rec, terms));
        described.push(Some(rec));
    }
    // two-lobe Henyey–Greenstein with both asymmetries 0 — a constant phase function, which the
    // kernel and the shader take by the isotropic path where the light is omni
    for p in scenes().iter().take(6) {
        let rec = SceneRecord { phase: airlight::phase::AnyPhase::TwoLobeHenyeyGreenstein(airlight::phase::TwoLobeHenyeyGreenstein { g1: 0.0, g2: 0.0, w: 0.3 }), ..record(p) };
        records.extend_from_slice(&pack(&rec.ray, &rec.light, &rec.medium, &rec.phase));
        expected.push(expect(&rec, terms));
        described.push(Some(rec));
    }
    // invalid records: the shader must give status INVALID and value 0
    let good = records[..RECORD_SIZE].to_vec();
    for (field, value) in [(16usize, 0.0f32), (20, f32::MAX), (68, -1.0), (72, f32::NAN), (0, f32::INFINITY), (76, 1.5), (60, 3.0)] {
        let mut r = good.clone();
        r[field..field + 4].copy_from_slice(&value.to_le_bytes());
        match field {
            16 => r[16..28].copy_from_slice(&[0u8; 12]),       // zero direction
            20 => {
                // a direction whose length overflows (found by the shader fuzz target)
                for i in [16, 24] {
                    r[i..i + 4].copy_from_slice(&f32::MAX.to_le_bytes());
                }
            }
            76 => r[92..96].copy_from_slice(&2u32.to_le_bytes()), // |g| ≥ 1 for Henyey–Greenstein
            60 => r[88..92].copy_from_slice(&1u32.to_le_bytes()), // odd two-lobed power
            _ => {}
        }
        records.extend_from_slice(&r);
        expected.push(Expected { value: 0.0, status: STATUS_INVALID, f64_value: 0.0, noise: 0.0, scale: 0.0 });
        described.push(None);
    }
    let reference_start = expected.len();
    let mut reference = Vec::new();
    for (rec, want, exact) in reference_scenes() {
        records.extend_from_slice(&pack(&rec.ray, &rec.light, &rec.medium, &rec.phase));
        expected.push(expect(&rec, terms));
        described.push(Some(rec));
        reference.push((want, exact));
    }
    Case { records, expected, scenes: described, reference_start, reference }
}

fn compare(label: &str, c: &Case, out: &[u8]) {
    assert_eq!(out.len(), c.expected.len() * RESULT_SIZE, "{label}: result count");
    let (mut worst, mut worst_f64, mut nan) = (0.0f64, 0.0f64, 0usize);
    let mut worst_exact = 0.0f64;
    let mut diffs = Vec::new();
    let mut failures = Vec::new();
    for (i, e) in c.expected.iter().enumerate() {
        let (got, status) = unpack_result(&out[i * RESULT_SIZE..(i + 1) * RESULT_SIZE]);
        if !got.is_finite() {
            nan += 1;
        }
        let j = judge(e, got, status);
        match j.problem {
            // the statistics leave out values below 2^-80, where f32 underflow and Vulkan's
            // denormal flushing dominate (as `airlight verify` does)
            None if e.scale > 2f64.powi(-80) => {
                diffs.push(j.diff);
                worst = worst.max(j.diff);
                worst_f64 = worst_f64.max(j.diff_f64);
            }
            None => {}
            Some(msg) => failures.push(format!("#{i}: {msg} {}", c.scenes[i].map(|r| format!("{r:?}")).unwrap_or_default())),
        }
        if i >= c.reference_start && status == airlight_shaders::layout::STATUS_OK {
            let (want, exact) = c.reference[i - c.reference_start];
            let err = rel_err(got as f64, want);
            if exact {
                worst_exact = worst_exact.max(err);
                if err > 1e-4 {
                    failures.push(format!("#{i}: f32_exact reference scene off by {err:.2e} (> 1e-4): gpu {got}, quadrature {want}"));
                }
            }
        }
    }
    diffs.sort_by(|a, b| a.partial_cmp(b).unwrap());
    let median = diffs.get(diffs.len() / 2).copied().unwrap_or(0.0);
    report(&format!(
        "| {label} | {} | {nan} | {worst:.2e} | {median:.2e} | {worst_f64:.2e} | {worst_exact:.2e} | {} |",
        c.expected.len(),
        failures.len()
    ));
    assert!(failures.is_empty(), "{label}: {} disagreements, first:\n{}", failures.len(), failures.iter().take(10).cloned().collect::<Vec<_>>().join("\n"));
}

/// Where the error table goes besides stdout (seen with `--nocapture`): `target/agreement.md`.
fn report_path() -> std::path::PathBuf {
    repo_root().join("target/agreement.md")
}

fn report(line: &str) {
    use std::io::Write;
    println!("{line}");
    let file = std::fs::OpenOptions::new().create(true).append(true).open(report_path());
    if let Ok(mut f) = file {
        let _ = writeln!(f, "{line}");
    }
}

fn glslang(args: &[&str], input: &std::path::Path, output: &std::path::Path) -> Vec<u32> {
    let out = Command::new("glslangValidator").args(args).arg("-o").arg(output).arg(input).output();
    let out = match out {
        Ok(o) => o,
        Err(e) => panic!("glslangValidator not available ({e}); install glslang-tools"),
    };
    assert!(out.status.success(), "glslang failed: {}", String::from_utf8_lossy(&out.stdout));
    let bytes = std::fs::read(output).unwrap();
    bytes.chunks(4).map(|c| u32::from_le_bytes(c.try_into().unwrap())).collect()
}

/// Runs `records` through the four compute artifacts of shaders-out/ at `terms` nodes per panel —
/// the WGSL through wgpu, the committed SPIR-V, the GLSL 450 and HLSL after glslang compiled them
/// (in `tmp`) — and gives each artifact's label and results to `each`.
fn each_artifact(gpu: &Gpu, terms: usize, records: &[u8], tmp: &std::path::Path, mut each: impl FnMut(&str, &[u8])) {
    let dir = default_out_dir();
    let wgsl = std::fs::read_to_string(dir.join(format!("wgsl/airlight_{terms}.wgsl"))).unwrap();
    each("wgsl", &gpu.run(Shader::Wgsl(&wgsl), records, false).unwrap());
    let spv: Vec<u32> = std::fs::read(dir.join(format!("spirv/airlight_{terms}.spv"))).unwrap().chunks(4).map(|b| u32::from_le_bytes(b.try_into().unwrap())).collect();
    each("spirv", &gpu.run(Shader::SpirV(&spv, "airlight_main"), records, false).unwrap());
    let glsl = glslang(&["-V", "--target-env", "vulkan1.0"], &dir.join(format!("glsl/airlight_{terms}.comp")), &tmp.join("g.spv"));
    each("glsl", &gpu.run(Shader::SpirV(&glsl, "main"), records, false).unwrap());
    let hlsl = glslang(&["-V", "-D", "-e", "airlight_main", "-S", "comp"], &dir.join(format!("hlsl/airlight_{terms}.hlsl")), &tmp.join("h.spv"));
    // glslang's HLSL front end returns `ByteAddressBuffer::GetDimensions` in 4-byte words,
    // not bytes as HLSL specifies (and as FXC/DXC do), so the shader's `arrayLength` guard
    // sees a quarter of the records. Padding the buffer to 4× makes that quarter the real
    // records; the results past them are dropped.
    let mut padded = records.to_vec();
    padded.resize(records.len() * 4, 0);
    let out = gpu.run(Shader::SpirV(&hlsl, "airlight_main"), &padded, false).unwrap();
    each("hlsl", &out[..records.len() / RECORD_SIZE * RESULT_SIZE]);
}

#[test]
fn every_artifact_agrees_with_the_cpu_kernel() {
    let Some(gpu) = gpu() else { return };
    let _ = std::fs::remove_file(report_path());
    report(&format!("adapter: {}; SPIR-V pass-through: {}\n", gpu.describe(), gpu.spirv_passthrough()));
    let tmp = std::env::temp_dir().join(format!("airlight-agree-{}", std::process::id()));
    std::fs::create_dir_all(&tmp).unwrap();
    report("| artifact | records | NaN/Inf | max diff to f32 CPU (of scale) | median | max diff to f64 CPU | max err f32_exact vs mpmath | failures |");
    report("|---|---|---|---|---|---|---|---|");
    for terms in NODE_COUNTS {
        let c = case(terms);
        each_artifact(&gpu, terms, &c.records, &tmp, |label, out| compare(&format!("{label}/{terms}"), &c, out));
    }
}

/// The committed compute shaders (WGSL, 8 and 12 nodes per panel) on the hard scene classes
/// against the mpmath references (tests/reference/classes.jsonl, as `tests/classes.rs` uses
/// them): error `|x − exact| / max(|exact|, 1e-4·scale)` at most 1e-3 on every record whose
/// value is at least 1e-30 (far inside f32's normal range), every class — the shaders' target
/// (docs/DESIGN.md §8). Printed (`--nocapture`): the per-class maximum and median.
#[test]
fn shaders_meet_the_class_targets() {
    let Some(gpu) = gpu() else { return };
    let cases: Vec<ClassCase> = class_cases().into_iter().filter(|c| c.f32_ok).collect();
    let records: Vec<u8> = cases
        .iter()
        .flat_map(|c| {
            let r = c.rec.cast::<f32>();
            pack(&r.ray, &r.light, &r.medium, &r.phase)
        })
        .collect();
    let dir = default_out_dir();
    let mut failures = Vec::new();
    for terms in NODE_COUNTS {
        let wgsl = std::fs::read_to_string(dir.join(format!("wgsl/airlight_{terms}.wgsl"))).unwrap();
        let out = gpu.run(Shader::Wgsl(&wgsl), &records, false).unwrap();
        let mut classes: std::collections::BTreeMap<&str, Vec<f64>> = std::collections::BTreeMap::new();
        for (i, c) in cases.iter().enumerate() {
            let (got, _) = unpack_result(&out[i * RESULT_SIZE..(i + 1) * RESULT_SIZE]);
            let err = c.err(got as f64, 1e-4);
            if !(err <= 1e-3) {
                failures.push(format!("{terms} nodes, {} #{i}: err {err:.2e} (gpu {got}, exact {})", c.category, c.exact));
            }
            classes.entry(&c.category).or_default().push(err);
        }
        println!("\nshader, {terms} nodes per panel: | class | n | max | median |");
        for (class, errs) in &mut classes {
            errs.sort_by(|a, b| a.partial_cmp(b).unwrap());
            println!("| {class} | {} | {:.1e} | {:.1e} |", errs.len(), errs[errs.len() - 1], errs[errs.len() / 2]);
        }
    }
    assert!(failures.is_empty(), "{} records off target:\n{}", failures.len(), failures.join("\n"));
}

/// Segment lights (tests/reference/extended.jsonl: near, far, behind, end-on, thick and short
/// tubes; isotropic, HG g = 0.8 and Rayleigh; omni, c^4 and spot distributions): the WGSL,
/// SPIR-V, GLSL and HLSL compute shaders at 8 and 12 nodes agree with the f32 CPU kernel computing the same
/// method (`SegmentScene::in_scatter_panels_counted` with the shaders' control and
/// `SHADER_SEGMENT_PANELS`) by the criterion of the point light, and are within 1e-3 of the
/// mpmath value (the shaders' target, docs/DESIGN.md §8). Invalid segment records (an unknown
/// shape, a non-finite end) give INVALID.
#[test]
fn segment_lights_agree_with_the_cpu_kernel() {
    use airlight_codegen::scene_json::{parse_any_value, AnyRecord};
    use airlight_shaders::agreement::expect_segment;
    use airlight_shaders::layout::pack_segment;
    let Some(gpu) = gpu() else { return };
    let cases: Vec<_> = reference_lines("extended.jsonl")
        .iter()
        .map(|v| match parse_any_value::<f32>(v) {
            Ok(AnyRecord::Segment(s)) => (s, v["in_scatter"].as_f64().unwrap(), v["category"].as_str().unwrap().to_string()),
            other => panic!("extended.jsonl holds segment lights valid in f32, not {other:?}"),
        })
        .collect();
    let mut records: Vec<u8> = cases.iter().flat_map(|c| pack_segment(&c.0)).collect();
    let good = records[..RECORD_SIZE].to_vec();
    for patch in 0..2 {
        let mut r = good.clone();
        match patch {
            0 => r[124..128].copy_from_slice(&7u32.to_le_bytes()),      // no such shape
            _ => r[112..116].copy_from_slice(&f32::NAN.to_le_bytes()), // end not finite
        }
        records.extend_from_slice(&r);
    }
    let tmp = std::env::temp_dir().join(format!("airlight-segment-{}", std::process::id()));
    std::fs::create_dir_all(&tmp).unwrap();
    let mut failures = Vec::new();
    println!("| artifact | records | max diff to f32 CPU (of scale) | max err vs mpmath | worst class |");
    println!("|---|---|---|---|---|");
    for terms in NODE_COUNTS {
        let expected: Vec<Expected> = cases.iter().map(|c| expect_segment(&c.0, terms)).collect();
        each_artifact(&gpu, terms, &records, &tmp, |label, out| {
            let (mut worst, mut worst_ref, mut worst_class) = (0.0f64, 0.0f64, String::new());
            for (i, (c, e)) in cases.iter().zip(&expected).enumerate() {
                let (got, status) = unpack_result(&out[i * RESULT_SIZE..(i + 1) * RESULT_SIZE]);
                let j = judge(e, got, status);
                worst = worst.max(j.diff);
                if let Some(msg) = j.problem {
                    failures.push(format!("{label}/{terms} {} #{i}: {msg}", c.2));
                }
                let err = rel_err(got as f64, c.1);
                if err > worst_ref {
                    (worst_ref, worst_class) = (err, c.2.clone());
                }
                if !(err <= 1e-3) {
                    failures.push(format!("{label}/{terms} {} #{i}: {err:.2e} off the mpmath value (gpu {got}, exact {})", c.2, c.1));
                }
            }
            for k in 0..2 {
                let (got, status) = unpack_result(&out[(cases.len() + k) * RESULT_SIZE..(cases.len() + k + 1) * RESULT_SIZE]);
                if (got, status) != (0.0, STATUS_INVALID) {
                    failures.push(format!("{label}/{terms}: invalid segment record {k} gave ({got}, {status})"));
                }
            }
            println!("| {label}/{terms} | {} | {worst:.2e} | {worst_ref:.2e} | {worst_class} |", cases.len());
        });
    }
    assert!(failures.is_empty(), "{} failures:\n{}", failures.len(), failures.join("\n"));
}

/// Area lights (tests/reference/area.jsonl: discs, rectangles and spheres near, far, pierced,
/// behind the camera, thick, inside a sphere, with cosine lobes of emission; isotropic, HG and
/// Rayleigh fog; a disc and a rectangle in `g = 0.95` and `0.99` fog looked at; and more of
/// those in Henyey–Greenstein fog, `g = 0.9`–`0.99`, or
/// emitting the cosine lobe `p = 1024`, on rays that look at them, at their limb, past it and
/// beside them, where the flat emitters are taken about the phase lobe's direction or graded
/// towards the emission lobe, their values the nested construction's at tolerance 1e-9,
/// tests/area.rs `bounded_flat_emitters_in_forward_fog`,
/// `bounded_flat_emitters_with_a_narrow_emission_lobe`): the area entry `airlight_in_scatter_area` as a compute shader over the
/// committed WGSL library at 8 and 12 nodes, run as WGSL and as naga's SPIR-V, agrees with the
/// f32 CPU kernel computing the same method (`AreaScene::in_scatter_bounded`) by the criterion of
/// the point light, and is within 1e-4 of the nested-quadrature value, relative to the value
/// (the f32 target of area lights, docs/DESIGN.md §12). Invalid area records (a NaN radius, a
/// zero normal, parallel edges, an emission power of 0, a light with an axis) give INVALID, and
/// the full entry `airlight_in_scatter` answers an area light INVALID. (Not run: the GLSL and HLSL
/// back ends' texts through glslang — glslang's SPIR-V of a compute shader holding the area code
/// took lavapipe 766 s to compile, naga's 12 s, and the area entry's alone more than 300 s after
/// `spirv-opt`'s local passes (docs/DESIGN.md §12); tests/shaders.rs compiles both libraries'
/// area entry with glslang.)
#[test]
fn area_lights_agree_with_the_cpu_kernel() {
    use airlight_codegen::scene_json::{parse_any_value, AnyRecord};
    use airlight_shaders::agreement::expect_area;
    use airlight_shaders::layout::{pack_area, Record, SHAPE_DISC, SHAPE_RECTANGLE};
    use airlight_shaders::targets::{area_compute_wgsl, spirv_of_compute};
    let Some(gpu) = gpu() else { return };
    let cases: Vec<_> = reference_lines("area.jsonl")
        .iter()
        .map(|v| match parse_any_value::<f32>(v) {
            Ok(AnyRecord::Area(s)) => (s, v["in_scatter"].as_f64().unwrap(), format!("{} {}", v["category"].as_str().unwrap(), v["light"]["shape"].as_str().unwrap())),
            other => panic!("area.jsonl holds area lights valid in f32, not {other:?}"),
        })
        .chain(focused_flat_emitters())
        .chain(sphere_limb_rays())
        .collect();
    let mut records: Vec<u8> = cases.iter().flat_map(|c| pack_area(&c.0)).collect();
    let first = |shape: u32| Record::area(&cases.iter().find(|c| Record::area(&c.0).light_shape == shape).expect("each shape in area.jsonl").0);
    let invalid: Vec<Record> = vec![
        Record { light_param_a: f32::NAN, ..first(SHAPE_DISC) },
        Record { light_axis: [0.0; 3], ..first(SHAPE_DISC) },
        Record { light_end: first(SHAPE_RECTANGLE).light_axis, ..first(SHAPE_RECTANGLE) },
        Record { light_param_b: 0.0, ..first(SHAPE_RECTANGLE) },
        Record { light_kind: airlight_shaders::layout::LIGHT_TWO_LOBED, ..first(SHAPE_DISC) },
    ];
    records.extend(invalid.iter().flat_map(|r| r.bytes()));
    let mut failures = Vec::new();
    let expected: Vec<Expected> = cases.iter().map(|c| expect_area(&c.0)).collect();
    println!("| artifact | records | max diff to f32 CPU (of scale) | max err vs nested quadrature | worst class |");
    println!("|---|---|---|---|---|");
    for terms in NODE_COUNTS {
        let wgsl = area_compute_wgsl(terms);
        let spirv = spirv_of_compute(&wgsl).unwrap();
        let full = gpu.run(Shader::Wgsl(compute_wgsl(terms)), &records[..RECORD_SIZE], false).unwrap();
        if unpack_result(&full) != (0.0, STATUS_INVALID) {
            failures.push(format!("airlight_in_scatter/{terms} answered an area light {:?}", unpack_result(&full)));
        }
        for (label, shader) in [("wgsl", Shader::Wgsl(&wgsl)), ("spirv", Shader::SpirV(&spirv, "airlight_main"))] {
            let out = gpu.run(shader, &records, false).unwrap();
            let (mut worst, mut worst_ref, mut worst_class) = (0.0f64, 0.0f64, String::new());
            for (i, (c, e)) in cases.iter().zip(&expected).enumerate() {
                let (got, status) = unpack_result(&out[i * RESULT_SIZE..(i + 1) * RESULT_SIZE]);
                let j = judge(e, got, status);
                worst = worst.max(j.diff);
                if let Some(msg) = j.problem {
                    failures.push(format!("{label}/{terms} {} #{i}: {msg}", c.2));
                }
                let err = rel_err(got as f64, c.1);
                if err > worst_ref {
                    (worst_ref, worst_class) = (err, c.2.clone());
                }
                if !(err <= 1e-4) {
                    failures.push(format!("{label}/{terms} {} #{i}: {err:.2e} off the reference (gpu {got}, exact {})", c.2, c.1));
                }
            }
            for k in 0..invalid.len() {
                let (got, status) = unpack_result(&out[(cases.len() + k) * RESULT_SIZE..(cases.len() + k + 1) * RESULT_SIZE]);
                if (got, status) != (0.0, STATUS_INVALID) {
                    failures.push(format!("{label}/{terms}: invalid area record {k} gave ({got}, {status})"));
                }
            }
            println!("| {label}/{terms} | {} | {worst:.2e} | {worst_ref:.2e} | {worst_class} |", cases.len());
        }
    }
    assert!(failures.is_empty(), "{} failures:\n{}", failures.len(), failures.join("\n"));
}

/// A disc and a rectangle in Henyey–Greenstein fog (`g` = 0.9, 0.95, 0.99) and, in isotropic
/// fog, emitting the cosine lobe `p = 1024`, on rays that look at them, towards their limb, past
/// it and beside them (tests/examples/area_bounded_phase.rs), but those of area.jsonl's
/// `focused` records (`g` = 0.95, 0.99, not beside): the f32 scene, the nested construction's
/// value at tolerance 1e-9 in f64, a label.
fn focused_flat_emitters() -> Vec<(airlight::AreaScene<f32, airlight::phase::AnyPhase<f32>>, f64, String)> {
    use airlight::glam::{DVec3, Vec3};
    use airlight::phase::{AnyPhase, HenyeyGreenstein};
    use airlight::{AreaLight, AreaScene, Emission, Emitter, Medium, Ray};
    let (center, normal) = (Vec3::new(6.0, 1.5, -0.5), Vec3::new(-1.0, -0.4, 0.1));
    let (corner, edge_u, edge_v) = (Vec3::new(6.0, 1.0, -1.0), Vec3::new(0.1, 0.0, 1.0), Vec3::new(0.0, 1.2, 0.1));
    let emitters = [("disc", Emitter::Disc { center, normal, radius: 0.8 }), ("rectangle", Emitter::Rectangle { corner, edge_u, edge_v })];
    let rays = [("at", Vec3::new(6.0, 1.5, -0.5)), ("limb", Vec3::new(6.0, 2.25, -0.3)), ("past the limb", Vec3::new(6.0, 2.4, -0.5)), ("beside", Vec3::new(1.0, 0.0, 0.3))];
    let lights = [(0.9f32, 1u32), (0.95, 1), (0.99, 1), (0.0, 1024)];
    // the f32 scene of the ray from the origin towards `dir` (σs 0.05, σt 0.08, radiance 2) and
    // the nested construction's value on its f32 inputs at tolerance 1e-9
    let case = |emitter: Emitter<f32>, emission: Emission, dir: Vec3, g: f32, label: String| {
        let medium = Medium { sigma_s: 0.05, sigma_t: 0.08 };
        let light = AreaLight { emission, ..AreaLight::new(emitter, 2.0) };
        let single = AreaScene::new(Ray { origin: Vec3::ZERO, dir, t_min: 0.0, t_max: f32::INFINITY }, light, medium, AnyPhase::HenyeyGreenstein(HenyeyGreenstein { g })).unwrap();
        let ray = Ray { origin: DVec3::ZERO, dir: dir.as_dvec3(), t_min: 0.0, t_max: f64::INFINITY };
        let medium = Medium { sigma_s: 0.05f32 as f64, sigma_t: 0.08f32 as f64 };
        let light = AreaLight { emission, ..AreaLight::new(airlight::record::cast_emitter::<f32, f64>(&emitter), 2.0) };
        let double = AreaScene::new(ray, light, medium, AnyPhase::HenyeyGreenstein(HenyeyGreenstein { g: g as f64 })).unwrap();
        (single, double.in_scatter_counted(1e-9).0, label)
    };
    let mut cases = Vec::new();
    for (g, power) in lights {
        let emission = if power == 1 { Emission::Lambertian } else { Emission::CosineLobe { power } };
        for (name, emitter) in emitters {
            for (label, dir) in rays {
                if g >= 0.95 && label != "beside" {
                    continue;
                }
                cases.push(case(emitter, emission, dir, g, format!("g = {g} p = {power} {name} {label}")));
            }
        }
    }
    // the rectangle in g = 0.99 and 0.95 fog on rays crossing its plane just inside and outside an
    // edge's middle, inside a corner and on an edge by a corner (tests/area.rs
    // bounded_rectangle_with_the_lobe_next_to_an_edge)
    let rectangle = Emitter::Rectangle { corner, edge_u, edge_v };
    let crossings = [
        ("inside an edge", corner + 0.5 * edge_u, edge_v),
        ("outside an edge", corner + 0.5 * edge_u, -edge_v),
        ("inside a corner", corner, edge_u + edge_v),
        ("on an edge from a corner", corner, edge_u),
        ("outside an edge by a corner", corner + 0.001 * edge_u, -edge_v),
    ];
    for (label, inside, inward) in crossings {
        for (g, offset) in [(0.99, 0.0005f32), (0.99, 0.002), (0.95, 0.0001)] {
            cases.push(case(rectangle, Emission::Lambertian, inside + inward.normalize() * offset, g, format!("g = {g} rectangle, crossing {offset} {label}")));
        }
    }
    // a disc of the rectangle's plane in g = 0.95 fog on rays crossing it on and just inside its rim
    // (tests/area.rs bounded_disc_with_the_lobe_next_to_its_rim)
    let centre = corner + 0.5 * (edge_u + edge_v);
    let disc = Emitter::Disc { center: centre, normal: edge_u.cross(edge_v), radius: 0.6 };
    for offset in [0.0f32, 0.0005, 0.002] {
        cases.push(case(disc, Emission::Lambertian, centre + edge_u.normalize() * (0.6 - offset), 0.95, format!("g = 0.95 disc, crossing {offset} inside its rim")));
    }
    cases
}

/// A sphere in `g = 0.95` and `0.99` fog on rays entering it 0.001 and 0.00001 of its radius
/// inside its limb, up to the middle of their chord and (0.00001) whole (tests/area.rs
/// `bounded_sphere_with_the_lobe_next_to_its_limb`), and in `g = 0.99` fog behind it on rays
/// that miss it by 0.001, 0.0001 and 0.00001 of its radius (`bounded_sphere_behind_a_grazing_ray`): the
/// f32 scene, the nested construction's value on its f32 inputs at tolerance 1e-9 in f64, a label.
fn sphere_limb_rays() -> Vec<(airlight::AreaScene<f32, airlight::phase::AnyPhase<f32>>, f64, String)> {
    use airlight::glam::{DVec3, Vec3};
    use airlight::phase::{AnyPhase, HenyeyGreenstein};
    use airlight::{AreaLight, AreaScene, Emitter, Medium, Ray};
    let (center, radius) = (Vec3::new(6.0, 1.5, -0.5), 0.6f32);
    let (towards, side) = (center.normalize(), center.normalize().cross(Vec3::Z).normalize());
    // the f32 scene of the ray along `dir` over `[t_min, t_max]` in HG fog of `g`, and the nested
    // construction's value on its f32 inputs
    let case = |dir: Vec3, (t_min, t_max): (f32, f32), g: f32, label: String| {
        let (medium, light) = (Medium { sigma_s: 0.05f32, sigma_t: 0.08 }, AreaLight::new(Emitter::Sphere { center, radius }, 2.0f32));
        let single = AreaScene::new(Ray { origin: Vec3::ZERO, dir, t_min, t_max }, light, medium, AnyPhase::HenyeyGreenstein(HenyeyGreenstein { g })).unwrap();
        let double = AreaScene::new(
            Ray { origin: DVec3::ZERO, dir: dir.as_dvec3(), t_min: t_min as f64, t_max: t_max as f64 },
            AreaLight::new(airlight::record::cast_emitter::<f32, f64>(&light.emitter), 2.0),
            Medium { sigma_s: 0.05f32 as f64, sigma_t: 0.08f32 as f64 },
            AnyPhase::HenyeyGreenstein(HenyeyGreenstein { g: g as f64 }),
        )
        .unwrap();
        (single, double.in_scatter_counted(1e-9).0, label)
    };
    let mut cases = Vec::new();
    for g in [0.95f32, 0.99] {
        for depth in [0.001f32, 0.00001] {
            let angle = (radius * (1.0 - depth) / center.length()).asin();
            let dir = towards * angle.cos() + side * angle.sin();
            let ends: &[(f32, &str)] = if depth < 0.0001 { &[(dir.dot(center), "to its chord's middle"), (f32::INFINITY, "whole")] } else { &[(dir.dot(center), "to its chord's middle")] };
            for &(t_max, part) in ends {
                cases.push(case(dir, (0.0, t_max), g, format!("g = {g} sphere, entering {depth} of its radius inside its limb, {part}")));
            }
        }
    }
    // behind a sphere the ray misses (its lobe just outside a cap nearly a hemisphere wide, the
    // θ rule cut at LOBE_TAIL), from the closest approach on
    for miss in [0.001f32, 0.0001, 0.00001] {
        let angle = (radius * (1.0 + miss) / center.length()).asin();
        let dir = towards * angle.cos() + side * angle.sin();
        cases.push(case(dir, (dir.dot(center), f32::INFINITY), 0.99, format!("g = 0.99 sphere, behind it, missing it by {miss} of its radius")));
    }
    cases
}

/// `airlight eval` input lines of reference records: each without the fields named in `drop`
/// (its answer and bookkeeping), with its index as `"id"`.
fn eval_input<'a>(records: impl IntoIterator<Item = &'a serde_json::Value>, drop: &[&str]) -> String {
    let mut input = String::new();
    for (i, v) in records.into_iter().enumerate() {
        let mut r = v.clone();
        let o = r.as_object_mut().unwrap();
        for key in drop {
            o.remove(*key);
        }
        o.insert("id".into(), i.into());
        input.push_str(&format!("{r}\n"));
    }
    input
}

/// `airlight eval --backend gpu` over the scenes of tests/reference/`file` (ids echoed): every
/// answer line within `tolerance` of the reference's `in_scatter`, relative.
fn eval_on_the_gpu_within(file: &str, tolerance: f64) {
    use airlight_codegen::eval::{run_gpu, Backend, EvalOptions};
    if gpu().is_none() {
        return;
    }
    let lines = reference_lines(file);
    let input = eval_input(&lines, &["in_scatter", "category"]);
    let mut out = Vec::new();
    run_gpu(input.as_bytes(), &mut out, &EvalOptions { backend: Backend::Gpu, ..Default::default() }).unwrap();
    let answers: Vec<serde_json::Value> = String::from_utf8(out).unwrap().lines().map(|l| serde_json::from_str(l).unwrap()).collect();
    assert_eq!(answers.len(), lines.len());
    for (i, (a, v)) in answers.iter().zip(&lines).enumerate() {
        assert_eq!(a["id"], i, "answer {i}: {a}");
        let got = a["in_scatter"].as_f64().unwrap_or_else(|| panic!("answer {i}: {a}"));
        let want = v["in_scatter"].as_f64().unwrap();
        assert!(rel_err(got, want) <= tolerance, "{file} record {i}: eval --backend gpu {got}, reference {want}");
    }
}

/// `airlight eval --backend gpu` evaluates segment-light records through the shader: every
/// answer line of tests/reference/extended.jsonl's scenes within 1e-3 of the mpmath value, as
/// the shaders' target asks.
#[test]
fn eval_runs_segment_lights_on_the_gpu() {
    eval_on_the_gpu_within("extended.jsonl", 1e-3);
}

/// `airlight eval --backend gpu` evaluates area-light records through the shader (a batch of
/// their own, through `airlight_in_scatter_area`): every answer line of
/// tests/reference/area.jsonl's scenes within 1e-4 of the reference value, the f32 target of
/// area lights (docs/DESIGN.md §12).
#[test]
fn eval_runs_area_lights_on_the_gpu() {
    eval_on_the_gpu_within("area.jsonl", 1e-4);
}

/// The surface points of tests/reference/surface.jsonl lit by omni lights — Lambertian (thin and
/// thick media, grazing normals, lights close to the surface, HG g from −0.7 to 0.95) and Phong
/// (exponents 1 to 1000, one in a thick medium): the WGSL, SPIR-V, GLSL and HLSL compute
/// shaders at 8 and 12 nodes agree with the f32 CPU kernel computing the same method
/// (`SurfaceScene::air_light_panels_counted` with the shaders' control, `SHADER_SURFACE_PANELS`
/// or `SHADER_PHONG_PANELS`) by the criterion
/// of the point light, and are within 1e-4 of the nested-quadrature reference, relative to
/// `max(|exact|, 1e-4·scale)` (the f32 target of surface radiance, docs/DESIGN.md §11). Invalid
/// surface records (a light with an axis, a NaN albedo, an unknown surface kind, a negative Phong
/// exponent, a zero view) give INVALID.
#[test]
fn surfaces_agree_with_the_cpu_kernel() {
    use airlight_codegen::scene_json::{parse_any_value, AnyRecord};
    use airlight_shaders::agreement::expect_surface;
    use airlight_shaders::layout::pack_surface;
    let Some(gpu) = gpu() else { return };
    let cases: Vec<_> = reference_lines("surface.jsonl")
        .iter()
        .filter_map(|v| match parse_any_value::<f32>(v) {
            Ok(AnyRecord::Surface(s)) => pack_surface(&s).map(|r| (s, r, v["surface_air_light"].as_f64().unwrap(), v["scale"].as_f64().unwrap(), v["category"].as_str().unwrap().to_string())),
            other => panic!("surface.jsonl holds surface points valid in f32, not {other:?}"),
        })
        .collect();
    let phong = cases.iter().filter(|c| matches!(c.0.brdf(), airlight::Brdf::Phong { .. })).count();
    assert!(cases.len() - phong >= 30 && phong >= 6, "{} Lambertian and {phong} Phong records lit by omni lights", cases.len() - phong);
    let mut cases = cases;
    cases.extend(random_phong_surfaces());
    let mut records: Vec<u8> = cases.iter().flat_map(|c| c.1).collect();
    let good = records[..RECORD_SIZE].to_vec();
    let good_phong = cases.iter().find(|c| matches!(c.0.brdf(), airlight::Brdf::Phong { .. })).unwrap().1.to_vec();
    const PATCHES: usize = 5;
    for patch in 0..PATCHES {
        let mut r = if patch < 3 { good.clone() } else { good_phong.clone() };
        match patch {
            0 => r[88..92].copy_from_slice(&1u32.to_le_bytes()),        // a two-lobed light
            1 => r[100..104].copy_from_slice(&f32::NAN.to_le_bytes()), // albedo not finite
            2 => r[104..108].copy_from_slice(&7u32.to_le_bytes()),     // no such surface kind
            3 => r[108..112].copy_from_slice(&(-1.0f32).to_le_bytes()), // a negative exponent
            _ => r[128..140].fill(0),                                   // a zero view
        }
        records.extend_from_slice(&r);
    }
    let tmp = std::env::temp_dir().join(format!("airlight-surface-{}", std::process::id()));
    std::fs::create_dir_all(&tmp).unwrap();
    let mut failures = Vec::new();
    println!("| artifact | records | max diff to f32 CPU (of scale) | max err vs reference | worst class |");
    println!("|---|---|---|---|---|");
    for terms in NODE_COUNTS {
        let expected: Vec<Expected> = cases.iter().map(|c| expect_surface(&c.0, terms)).collect();
        each_artifact(&gpu, terms, &records, &tmp, |label, out| {
            let (mut worst, mut worst_ref, mut worst_class) = (0.0f64, 0.0f64, String::new());
            for (i, (c, e)) in cases.iter().zip(&expected).enumerate() {
                let (got, status) = unpack_result(&out[i * RESULT_SIZE..(i + 1) * RESULT_SIZE]);
                let j = judge(e, got, status);
                worst = worst.max(j.diff);
                if let Some(msg) = j.problem {
                    failures.push(format!("{label}/{terms} {} #{i}: {msg}", c.4));
                }
                let err = (got as f64 - c.2).abs() / c.2.max(1e-4 * c.3);
                if err > worst_ref {
                    (worst_ref, worst_class) = (err, c.4.clone());
                }
                if !(err <= 1e-4) {
                    failures.push(format!("{label}/{terms} {} #{i}: {err:.2e} off the reference (gpu {got}, exact {})", c.4, c.2));
                }
            }
            for k in 0..PATCHES {
                let (got, status) = unpack_result(&out[(cases.len() + k) * RESULT_SIZE..(cases.len() + k + 1) * RESULT_SIZE]);
                if (got, status) != (0.0, STATUS_INVALID) {
                    failures.push(format!("{label}/{terms}: invalid surface record {k} gave ({got}, {status})"));
                }
            }
            println!("| {label}/{terms} | {} | {worst:.2e} | {worst_ref:.2e} | {worst_class} |", cases.len());
        });
    }
    assert!(failures.is_empty(), "{} failures:\n{}", failures.len(), failures.join("\n"));
}

/// Phong surface points lit by omni lights, random over exponents 0.5–200, thin to thick media,
/// isotropic to HG g = 0.95, any normal, view and light position: as the cases of
/// `surfaces_agree_with_the_cpu_kernel`, their exact value the f64 default `air_light`
/// (error-controlled to 1e-10; tests/surface.rs holds it to the nested-quadrature references) and
/// their scale that of the same point with a Lambertian BRDF at the lobe's peak (as
/// tests/reference/gen_surface.py defines it).
fn random_phong_surfaces() -> Vec<(airlight_shaders::agreement::SurfaceRecord<f32>, [u8; RECORD_SIZE], f64, f64, String)> {
    use airlight::glam::Vec3;
    use airlight::light::AnyDistribution;
    use airlight::phase::{AnyPhase, HenyeyGreenstein};
    use airlight::record::{cast_light, cast_phase};
    use airlight::{Brdf, Medium, PointLight, Surface, SurfaceScene};
    let mut rng = Rng(2026);
    let mut out = Vec::new();
    for i in 0..28 {
        let mut v = |r: f64| Vec3::from_array(rng.unit_vector().map(|x| x as f32)) * r as f32;
        let (position, normal, view) = (v(3.0), v(1.0), v(1.0));
        let light_position = v(0.5 + 6.0 * (i % 5) as f64 / 4.0);
        let exponent = [0.5f32, 1.0, 3.0, 10.0, 50.0, 100.0, 200.0][i % 7];
        let sigma_t = [0.01f32, 0.1, 0.5, 2.0][(i / 7) % 4];
        let g = [0.0f32, 0.5, 0.8, 0.95][i % 4];
        let medium = Medium { sigma_s: 0.7 * sigma_t, sigma_t };
        let phase = if g == 0.0 { AnyPhase::Isotropic } else { AnyPhase::HenyeyGreenstein(HenyeyGreenstein { g }) };
        let light = PointLight { position: light_position + position, intensity: 10.0, distribution: AnyDistribution::Omni };
        let scene = SurfaceScene::new(Surface { position, normal }, Brdf::Phong { k_s: 0.5, exponent, view }, light, medium, phase).unwrap();
        // the same point in f64 (every number exact), with `brdf`
        let wide = |brdf: Brdf<f64>| {
            let surface = Surface { position: position.as_dvec3(), normal: normal.as_dvec3() };
            let medium = Medium { sigma_s: medium.sigma_s as f64, sigma_t: sigma_t as f64 };
            SurfaceScene::new(surface, brdf, cast_light::<f32, f64>(&light), medium, cast_phase::<f32, f64>(&phase)).unwrap().air_light()
        };
        let exact = wide(Brdf::Phong { k_s: 0.5, exponent: exponent as f64, view: view.as_dvec3() });
        let scale = wide(Brdf::Lambert { albedo: 0.5 * (exponent as f64 + 2.0) / 2.0 });
        let record = airlight_shaders::layout::pack_surface(&scene).unwrap();
        out.push((scene, record, exact, scale, format!("random phong n={exponent}")));
    }
    out
}

/// `airlight eval --backend gpu` evaluates surface points lit by omni lights (Lambertian and
/// Phong) through the shader (`surface_air_light`, within 1e-4 of the reference as above) and
/// answers a record lit by a light with an axis with an error line naming the CPU backend.
#[test]
fn eval_runs_surfaces_on_the_gpu() {
    use airlight_codegen::eval::{run_gpu, Backend, EvalOptions};
    if gpu().is_none() {
        return;
    }
    let lines = reference_lines("surface.jsonl");
    let input = eval_input(&lines, &["surface_air_light", "scale", "category"]);
    let mut out = Vec::new();
    run_gpu(input.as_bytes(), &mut out, &EvalOptions { backend: Backend::Gpu, ..Default::default() }).unwrap();
    let answers: Vec<serde_json::Value> = String::from_utf8(out).unwrap().lines().map(|l| serde_json::from_str(l).unwrap()).collect();
    assert_eq!(answers.len(), lines.len());
    let (mut on_gpu, mut refused) = (0, 0);
    for (i, (a, v)) in answers.iter().zip(&lines).enumerate() {
        assert_eq!(a["id"], i, "answer {i}: {a}");
        if v["light"]["distribution"]["kind"] == "isotropic" {
            let got = a["surface_air_light"].as_f64().unwrap_or_else(|| panic!("answer {i}: {a}"));
            let (want, scale) = (v["surface_air_light"].as_f64().unwrap(), v["scale"].as_f64().unwrap());
            assert!((got - want).abs() <= 1e-4 * want.max(1e-4 * scale), "record {i}: eval --backend gpu {got}, reference {want}");
            on_gpu += 1;
        } else {
            let e = a["error"].as_str().unwrap_or_else(|| panic!("answer {i}: {a}"));
            assert!(e.contains("CPU backend"), "record {i}: {e}");
            refused += 1;
        }
    }
    assert!(on_gpu >= 36 && refused >= 1, "{on_gpu} on the GPU, {refused} refused");
}

/// `airlight render`'s street (a fluorescent tube, an omni lamp whose air-light reaches every
/// surface) through the shader at 48×27: every pixel within 1e-3 — the shaders' accuracy
/// target — of the brute-force reference, relative to `max(reference, error floor)` (the
/// render's per-pixel measure, `render::relative_errors`).
#[test]
fn street_renders_through_the_shader() {
    use airlight_codegen::render;
    let Some(gpu) = gpu() else { return };
    let scene = render::street(48, 27);
    let shader = gpu.prepare(Shader::Wgsl(airlight_shaders::targets::compute_wgsl(airlight::SHADER_NODES)));
    let image = render::render_gpu(&scene, &shader, false).unwrap();
    let reference = render::render_reference(&scene, false);
    let errors = render::relative_errors(&image, &reference, render::error_floor(&scene));
    let stats = render::error_stats(&errors);
    println!("street through the shader: relative error max {:.2e}, median {:.2e}", stats.max, stats.median);
    assert!(stats.max <= 1e-3, "street: shader pixel {:.3e} off the reference", stats.max);
}

/// The packed record of the first segment light in tests/reference/extended.jsonl.
fn segment_record() -> Vec<u8> {
    use airlight_codegen::scene_json::{parse_any_value, AnyRecord};
    reference_lines("extended.jsonl")
        .iter()
        .find_map(|v| match parse_any_value::<f32>(v) {
            Ok(AnyRecord::Segment(s)) => Some(airlight_shaders::layout::pack_segment(&s).to_vec()),
            _ => None,
        })
        .expect("a segment light in extended.jsonl")
}

/// The include library's `airlight_in_scatter_point` (WGSL, 8 and 12 nodes) meets the point
/// light's criterion on the records of `every_artifact_agrees_with_the_cpu_kernel` (random
/// scenes, extremes, invalid records, the mpmath references), and answers a valid segment light
/// or surface point with INVALID: it is the ray integral alone, not `airlight_in_scatter`.
#[test]
fn the_point_entry_agrees_with_the_cpu_kernel() {
    use airlight_codegen::scene_json::{parse_any_value, AnyRecord};
    use airlight_shaders::layout::pack_surface;
    let Some(gpu) = gpu() else { return };
    let surface = reference_lines("surface.jsonl")
        .iter()
        .find_map(|v| match parse_any_value::<f32>(v) {
            Ok(AnyRecord::Surface(s)) => pack_surface(&s),
            _ => None,
        })
        .expect("a Lambertian surface point in surface.jsonl");
    let mut others = segment_record();
    others.extend_from_slice(&surface);
    for terms in NODE_COUNTS {
        let shader = gpu.prepare(Shader::Wgsl(&point_compute_wgsl(terms)));
        let c = case(terms);
        compare(&format!("wgsl airlight_in_scatter_point/{terms}"), &c, &shader.run(&c.records, false).unwrap());
        let general = gpu.run(Shader::Wgsl(compute_wgsl(terms)), &others, false).unwrap();
        let point = shader.run(&others, false).unwrap();
        for (k, what) in ["segment light", "surface point"].iter().enumerate() {
            let (v, status) = unpack_result(&general[k * RESULT_SIZE..(k + 1) * RESULT_SIZE]);
            assert!(status == airlight_shaders::layout::STATUS_OK && v > 0.0, "{terms} nodes: airlight_in_scatter on the {what}: ({v}, {status})");
            assert_eq!(unpack_result(&point[k * RESULT_SIZE..(k + 1) * RESULT_SIZE]), (0.0, STATUS_INVALID), "{terms} nodes: airlight_in_scatter_point on the {what}");
        }
    }
}

/// The two passes (`airlight_in_scatter_route`, then `airlight_in_scatter_point` on the records
/// it defers; `gpu::run_deferred`) meet the point light's criterion on the records of
/// `every_artifact_agrees_with_the_cpu_kernel` and give the point entry's own results (the same
/// code path for each record: the route where it is taken, the whole ray integral for the rest;
/// within 4 ulp, as the two modules may be compiled apart). Both passes run: some records are
/// deferred, some are not. A segment light or surface point is INVALID to the route entry.
#[test]
fn two_passes_give_the_point_entrys_results() {
    use airlight_shaders::gpu::run_deferred;
    use airlight_shaders::layout::STATUS_DEFERRED;
    use airlight_shaders::targets::route_compute_wgsl;
    let Some(gpu) = gpu() else { return };
    for terms in NODE_COUNTS {
        let (route, point) = (gpu.prepare(Shader::Wgsl(&route_compute_wgsl(terms))), gpu.prepare(Shader::Wgsl(&point_compute_wgsl(terms))));
        let c = case(terms);
        let first = route.run(&c.records, false).unwrap();
        let deferred = first.chunks_exact(RESULT_SIZE).filter(|r| unpack_result(r).1 == STATUS_DEFERRED).count();
        let n = c.records.len() / RECORD_SIZE;
        println!("{terms} nodes: the route entry defers {deferred} of {n} records");
        assert!(deferred > 0 && deferred < n, "{terms} nodes: {deferred} of {n} deferred");
        let two = run_deferred(&route, &point, &c.records, false).unwrap();
        compare(&format!("wgsl route + point entries/{terms}"), &c, &two);
        let one = point.run(&c.records, false).unwrap();
        for (i, (a, b)) in two.chunks_exact(RESULT_SIZE).zip(one.chunks_exact(RESULT_SIZE)).enumerate() {
            let ((va, sa), (vb, sb)) = (unpack_result(a), unpack_result(b));
            assert_eq!(sa, sb, "{terms} nodes, record {i}: status two passes {sa}, point entry {sb}");
            assert!((va - vb).abs() <= 4.0 * f32::EPSILON * va.abs().max(vb.abs()) || va == vb, "{terms} nodes, record {i}: two passes {va}, point entry {vb}");
        }
    }
    let segment = segment_record();
    let route = gpu.prepare(Shader::Wgsl(&route_compute_wgsl(NODE_COUNTS[0])));
    assert_eq!(unpack_result(&route.run(&segment, false).unwrap()), (0.0, STATUS_INVALID), "the route entry on a segment light");
}

/// `airlight eval --backend gpu` on point lights (the hard classes of
/// tests/reference/classes.jsonl, ids echoed): every answer within the shaders' 1e-3 of the
/// mpmath value (`|x − exact| / max(|exact|, 1e-4·scale)`, as `shaders_meet_the_class_targets`),
/// both through the point entry it runs when every record is a point light and through the
/// general compute shader it runs when a segment light is among them.
#[test]
fn eval_runs_point_lights_on_the_gpu() {
    use airlight_codegen::eval::{run_gpu, Backend, EvalOptions};
    if gpu().is_none() {
        return;
    }
    let cases: Vec<(serde_json::Value, ClassCase)> = reference_lines("classes.jsonl").into_iter().zip(class_cases()).filter(|(_, c)| c.f32_ok).collect();
    let input = eval_input(cases.iter().map(|(v, _)| v), &["in_scatter", "scale", "category"]);
    let segment = eval_input(&reference_lines("extended.jsonl")[..1], &["in_scatter", "category"]);
    for (label, text) in [("point lights only", input.clone()), ("with a segment light", format!("{input}{segment}"))] {
        let mut out = Vec::new();
        run_gpu(text.as_bytes(), &mut out, &EvalOptions { backend: Backend::Gpu, ..Default::default() }).unwrap();
        let answers: Vec<serde_json::Value> = String::from_utf8(out).unwrap().lines().map(|l| serde_json::from_str(l).unwrap()).collect();
        assert_eq!(answers.len(), text.lines().count(), "{label}");
        let mut worst = 0.0f64;
        for (i, (a, (_, c))) in answers.iter().zip(&cases).enumerate() {
            assert_eq!(a["id"], i, "{label}, answer {i}: {a}");
            let got = a["in_scatter"].as_f64().unwrap_or_else(|| panic!("{label}, answer {i}: {a}"));
            let err = c.err(got, 1e-4);
            assert!(err <= 1e-3, "{label}, {} record {i}: eval --backend gpu {got}, mpmath {} (err {err:.2e})", c.category, c.exact);
            worst = worst.max(err);
        }
        println!("eval --backend gpu, {label}: {} class records, largest error {worst:.2e}", cases.len());
    }
}
