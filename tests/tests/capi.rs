//! The C ABI (capi/): its header is what cbindgen generates from capi/src/lib.rs, its codes are
//! the shader record's, and a C program compiled with the system `cc` against the header and
//! the static library evaluates the mpmath reference scenes to the f64/f32 targets
//! (capi/c/reference_test.c) — with std, and built `#![no_std]` with `panic = "abort"` (the
//! firmware build: if anything in the kernel's dependency graph pulled in `std`, rustc would
//! reject the crate's own `#[panic_handler]` as a duplicate `panic_impl` lang item).

use airlight::light::AnyDistribution;
use airlight::phase::AnyPhase;
use airlight_shaders::layout;
use airlight_tests::{class_cases, repo_root};
use std::fmt::Write as _;
use std::path::PathBuf;
use std::process::Command;

/// The committed header is cbindgen's output for the committed source and configuration;
/// `AIRLIGHT_UPDATE_HEADER=1` rewrites it instead.
#[test]
fn header_is_current() {
    let capi = repo_root().join("capi");
    let config = cbindgen::Config::from_file(capi.join("cbindgen.toml")).unwrap();
    let bindings = cbindgen::Builder::new().with_config(config).with_src(capi.join("src/lib.rs")).generate().expect("cbindgen");
    let mut generated = Vec::new();
    bindings.write(&mut generated);
    let path = capi.join("include/airlight.h");
    if std::env::var_os("AIRLIGHT_UPDATE_HEADER").is_some() {
        std::fs::write(&path, &generated).unwrap();
    }
    let committed = std::fs::read(&path).unwrap_or_default();
    assert!(
        committed == generated,
        "capi/include/airlight.h is not what cbindgen generates from capi/src/lib.rs: run `AIRLIGHT_UPDATE_HEADER=1 cargo test --release -p airlight-tests --test capi`"
    );
}

/// The C ABI's kind and status codes are the GPU record's (codegen's layout), which the
/// shader libraries' `AIRLIGHT_*` constants also are.
#[test]
fn codes_are_the_shader_records() {
    use airlight_c as c;
    assert_eq!(
        [c::AIRLIGHT_LIGHT_OMNI, c::AIRLIGHT_LIGHT_TWO_LOBED, c::AIRLIGHT_LIGHT_SPOT],
        [layout::LIGHT_OMNI, layout::LIGHT_TWO_LOBED, layout::LIGHT_SPOT]
    );
    assert_eq!(
        [
            c::AIRLIGHT_PHASE_ISOTROPIC,
            c::AIRLIGHT_PHASE_RAYLEIGH,
            c::AIRLIGHT_PHASE_HENYEY_GREENSTEIN,
            c::AIRLIGHT_PHASE_SCHLICK,
            c::AIRLIGHT_PHASE_CORNETTE_SHANKS,
            c::AIRLIGHT_PHASE_TWO_LOBE_HENYEY_GREENSTEIN
        ],
        [
            layout::PHASE_ISOTROPIC,
            layout::PHASE_RAYLEIGH,
            layout::PHASE_HENYEY_GREENSTEIN,
            layout::PHASE_SCHLICK,
            layout::PHASE_CORNETTE_SHANKS,
            layout::PHASE_TWO_LOBE_HG
        ]
    );
    assert_eq!([c::AIRLIGHT_STATUS_OK, c::AIRLIGHT_STATUS_INVALID, c::AIRLIGHT_STATUS_INFINITE], [layout::STATUS_OK, layout::STATUS_INVALID, layout::STATUS_INFINITE]);
}

/// Every reference scene as one line of plain numbers, in the order reference_test.c reads.
fn scenes_as_text() -> String {
    let mut out = String::new();
    use airlight_c as c;
    for case in class_cases() {
        let (r, l, m) = (&case.rec.ray, &case.rec.light, &case.rec.medium);
        let (kind, power, axis, cos_inner, cos_outer) = match l.distribution {
            AnyDistribution::Omni => (c::AIRLIGHT_LIGHT_OMNI, 0, [0.0, 0.0, 1.0], 0.0, 0.0),
            AnyDistribution::TwoLobed(d) => (c::AIRLIGHT_LIGHT_TWO_LOBED, d.power, d.axis.to_array(), 0.0, 0.0),
            AnyDistribution::SpotCone(d) => (c::AIRLIGHT_LIGHT_SPOT, 0, d.axis.to_array(), d.cos_inner, d.cos_outer),
        };
        let (pk, g, k, g1, g2, w) = match case.rec.phase {
            AnyPhase::Isotropic => (c::AIRLIGHT_PHASE_ISOTROPIC, 0.0, 0.0, 0.0, 0.0, 0.0),
            AnyPhase::Rayleigh => (c::AIRLIGHT_PHASE_RAYLEIGH, 0.0, 0.0, 0.0, 0.0, 0.0),
            AnyPhase::HenyeyGreenstein(p) => (c::AIRLIGHT_PHASE_HENYEY_GREENSTEIN, p.g, 0.0, 0.0, 0.0, 0.0),
            AnyPhase::Schlick(p) => (c::AIRLIGHT_PHASE_SCHLICK, 0.0, p.k, 0.0, 0.0, 0.0),
            AnyPhase::CornetteShanks(p) => (c::AIRLIGHT_PHASE_CORNETTE_SHANKS, p.g, 0.0, 0.0, 0.0, 0.0),
            AnyPhase::TwoLobeHenyeyGreenstein(p) => (c::AIRLIGHT_PHASE_TWO_LOBE_HENYEY_GREENSTEIN, 0.0, 0.0, p.g1, p.g2, p.w),
        };
        let v = |x: f64| format!("{x:e}");
        let v3 = |a: [f64; 3]| a.map(v).join(" ");
        writeln!(
            out,
            "{} {} {} {} {} {} {} {} {} {kind} {power} {} {} {} {} {} {pk} {} {} {} {} {}",
            case.category,
            v(case.exact),
            v(case.scale),
            v3(r.origin.to_array()),
            v3(r.dir.to_array()),
            v(r.t_min),
            v(r.t_max),
            v3(l.position.to_array()),
            v(l.intensity),
            v3(axis),
            v(cos_inner),
            v(cos_outer),
            v(m.sigma_s),
            v(m.sigma_t),
            v(g),
            v(k),
            v(g1),
            v(g2),
            v(w)
        )
        .unwrap();
    }
    out
}

/// The static library this test run built: the capi crate is a dependency of this test, and
/// cargo builds every crate type of a dependency into `<target>/<profile>/deps/`, beside this
/// test's executable.
fn static_library() -> PathBuf {
    let exe = std::env::current_exe().unwrap();
    let lib = exe.parent().unwrap().join("libairlight_c.a");
    assert!(lib.exists(), "{} missing: the capi crate's staticlib was not built", lib.display());
    lib
}

/// The firmware build of the static library: `--no-default-features` (`#![no_std]`, its own
/// panic handler), `-C panic=abort`, built here with the cargo that runs the tests, in a target
/// directory of its own.
fn no_std_static_library() -> PathBuf {
    let target = repo_root().join("target/capi-no-std");
    let out = Command::new(env!("CARGO"))
        .args(["build", "--release", "-p", "airlight-capi", "--no-default-features", "--target-dir"])
        .arg(&target)
        .env("RUSTFLAGS", "-C panic=abort")
        .output()
        .expect("run cargo");
    assert!(out.status.success(), "the no_std build failed:\n{}", String::from_utf8_lossy(&out.stderr));
    target.join("release/libairlight_c.a")
}

/// Compiles `sources` with the system `cc` against the header and the static library `lib`.
fn compile_c(sources: &[PathBuf], lib: &std::path::Path, exe: &std::path::Path) {
    let cc = Command::new("cc")
        .args(["-std=c99", "-O2", "-Wall", "-Wextra", "-Werror", "-pedantic", "-I"])
        .arg(repo_root().join("capi/include"))
        .args(sources)
        .arg(lib)
        // as a firmware link does: unreferenced sections dropped (the no_std build's prebuilt
        // `core` keeps unwind tables that name a personality routine nothing calls)
        .arg("-Wl,--gc-sections")
        // what a std staticlib needs from the system (`rustc --print native-static-libs`)
        .args(["-lgcc_s", "-lutil", "-lrt", "-lpthread", "-lm", "-ldl", "-lc", "-o"])
        .arg(exe)
        .output()
        .expect("the system C compiler `cc`");
    assert!(cc.status.success(), "cc failed:\n{}", String::from_utf8_lossy(&cc.stderr));
}

fn scratch() -> PathBuf {
    let dir = PathBuf::from(env!("CARGO_TARGET_TMPDIR")).join("capi");
    std::fs::create_dir_all(&dir).unwrap();
    dir
}

fn reference_test(lib: &std::path::Path, name: &str) {
    let dir = scratch();
    let scenes = dir.join("scenes.txt");
    std::fs::write(&scenes, scenes_as_text()).unwrap();
    let exe = dir.join(name);
    compile_c(&[repo_root().join("capi/c/reference_test.c")], lib, &exe);
    let run = Command::new(&exe).arg(&scenes).output().unwrap();
    let stdout = String::from_utf8_lossy(&run.stdout);
    println!("{name}: {stdout}");
    assert!(run.status.success(), "the C reference test ({name}) failed:\n{stdout}{}", String::from_utf8_lossy(&run.stderr));
    assert!(stdout.contains("0 failures"), "{stdout}");
}

#[test]
fn c_program_meets_the_targets_on_the_references() {
    reference_test(&static_library(), "reference_test");
}

#[test]
fn no_std_build_meets_the_targets_on_the_references() {
    reference_test(&no_std_static_library(), "reference_test_no_std");
}

/// capi/README.md's C example compiles as shown and prints a positive value.
#[test]
fn readme_c_example_runs() {
    let readme = std::fs::read_to_string(repo_root().join("capi/README.md")).unwrap();
    let start = readme.find("```c\n").expect("a C block in capi/README.md") + "```c\n".len();
    let source = &readme[start..start + readme[start..].find("```").unwrap()];
    let dir = scratch();
    let path = dir.join("readme_example.c");
    std::fs::write(&path, source).unwrap();
    let exe = dir.join("readme_example");
    compile_c(&[path], &static_library(), &exe);
    let run = Command::new(&exe).output().unwrap();
    let printed = String::from_utf8_lossy(&run.stdout);
    let value: f64 = printed.trim().parse().unwrap_or_else(|_| panic!("the example printed {printed:?}"));
    assert!(run.status.success() && value > 0.0, "{printed}");
}

/// The C structs of a kernel point light and phase function (the inverse of the ABI's own
/// conversion).
fn c_light<T: airlight::Real>(l: &airlight::PointLight<T, AnyDistribution<T>>) -> airlight_c::AirlightLight<T> {
    let zero = T::zero();
    let distribution = match l.distribution {
        AnyDistribution::Omni => airlight_c::AirlightDistribution { kind: airlight_c::AIRLIGHT_LIGHT_OMNI, power: 0, axis: [zero; 3], cos_inner: zero, cos_outer: zero },
        AnyDistribution::TwoLobed(d) => airlight_c::AirlightDistribution { kind: airlight_c::AIRLIGHT_LIGHT_TWO_LOBED, power: d.power, axis: T::vec3_to_array(d.axis), cos_inner: zero, cos_outer: zero },
        AnyDistribution::SpotCone(d) => airlight_c::AirlightDistribution { kind: airlight_c::AIRLIGHT_LIGHT_SPOT, power: 0, axis: T::vec3_to_array(d.axis), cos_inner: d.cos_inner, cos_outer: d.cos_outer },
    };
    airlight_c::AirlightLight { position: T::vec3_to_array(l.position), intensity: l.intensity, distribution }
}

fn c_phase<T: airlight::Real>(p: &AnyPhase<T>) -> airlight_c::AirlightPhase<T> {
    let z = T::zero();
    let (kind, g, k, g1, g2, w) = match *p {
        AnyPhase::Isotropic => (airlight_c::AIRLIGHT_PHASE_ISOTROPIC, z, z, z, z, z),
        AnyPhase::Rayleigh => (airlight_c::AIRLIGHT_PHASE_RAYLEIGH, z, z, z, z, z),
        AnyPhase::HenyeyGreenstein(h) => (airlight_c::AIRLIGHT_PHASE_HENYEY_GREENSTEIN, h.g, z, z, z, z),
        AnyPhase::Schlick(s) => (airlight_c::AIRLIGHT_PHASE_SCHLICK, z, s.k, z, z, z),
        AnyPhase::CornetteShanks(c) => (airlight_c::AIRLIGHT_PHASE_CORNETTE_SHANKS, c.g, z, z, z, z),
        AnyPhase::TwoLobeHenyeyGreenstein(t) => (airlight_c::AIRLIGHT_PHASE_TWO_LOBE_HENYEY_GREENSTEIN, z, z, t.g1, t.g2, t.w),
    };
    airlight_c::AirlightPhase { kind, g, k, g1, g2, w }
}

fn c_segment<T: airlight::Real>(s: &airlight::SegmentScene<T, AnyDistribution<T>, AnyPhase<T>>) -> airlight_c::AirlightSegmentScene<T> {
    let (r, l, m) = (s.ray(), s.light(), s.medium());
    airlight_c::AirlightSegmentScene {
        ray: airlight_c::AirlightRay { origin: T::vec3_to_array(r.origin), dir: T::vec3_to_array(r.dir), t_min: r.t_min, t_max: r.t_max },
        light: c_light(&airlight::PointLight { position: l.a, intensity: l.intensity, distribution: l.distribution }),
        end: T::vec3_to_array(l.b),
        medium: airlight_c::AirlightMedium { sigma_s: m.sigma_s, sigma_t: m.sigma_t },
        phase: c_phase(s.phase()),
    }
}

fn c_surface<T: airlight::Real>(s: &airlight::SurfaceScene<T, AnyDistribution<T>, AnyPhase<T>>) -> airlight_c::AirlightSurfaceScene<T> {
    let z = T::zero();
    let brdf = match *s.brdf() {
        airlight::Brdf::Lambert { albedo } => airlight_c::AirlightBrdf { kind: airlight_c::AIRLIGHT_BRDF_LAMBERT, albedo, k_s: z, exponent: z, view: [z; 3] },
        airlight::Brdf::Phong { k_s, exponent, view } => airlight_c::AirlightBrdf { kind: airlight_c::AIRLIGHT_BRDF_PHONG, albedo: z, k_s, exponent, view: T::vec3_to_array(view) },
    };
    let m = s.medium();
    airlight_c::AirlightSurfaceScene {
        position: T::vec3_to_array(s.surface().position),
        normal: T::vec3_to_array(s.surface().normal),
        brdf,
        light: c_light(s.light()),
        medium: airlight_c::AirlightMedium { sigma_s: m.sigma_s, sigma_t: m.sigma_t },
        phase: c_phase(s.phase()),
    }
}

/// The segment-light and surface entry points through their C structs on the references of
/// tests/reference/extended.jsonl and surface.jsonl: status OK and within the targets the
/// kernel's own tests hold (tests/extended.rs, tests/surface.rs) — f64 1e-9, f32 1e-4 of the
/// exact value (surfaces: of `max(|exact|, τ·scale)`, τ = 1e-10 / 1e-4); `radiance` adds the
/// direct term to the air-light; null pointers, an unknown BRDF kind and a zero normal give their
/// statuses and name the field.
#[test]
fn segment_and_surface_entry_points_meet_the_targets() {
    use airlight_c::*;
    use airlight_codegen::scene_json::{parse_any_value, AnyRecord};
    let mut failures = Vec::new();
    for v in airlight_tests::reference_lines("extended.jsonl") {
        let exact = v["in_scatter"].as_f64().unwrap();
        let (Ok(AnyRecord::Segment(s64)), Ok(AnyRecord::Segment(s32))) = (parse_any_value::<f64>(&v), parse_any_value::<f32>(&v)) else { panic!("{v}") };
        let (r64, r32) = unsafe { (airlight_segment_in_scatter_f64(&c_segment(&s64)), airlight_segment_in_scatter_f32(&c_segment(&s32))) };
        let (e64, e32) = ((r64.value - exact).abs() / exact, (r32.value as f64 - exact).abs() / exact);
        if r64.status != AIRLIGHT_STATUS_OK || r32.status != AIRLIGHT_STATUS_OK || !(e64 <= 1e-9) || !(e32 <= 1e-4) {
            failures.push(format!("segment {}: f64 {e64:.1e}, f32 {e32:.1e}, statuses {} {}", v["category"], r64.status, r32.status));
        }
    }
    for v in airlight_tests::reference_lines("surface.jsonl") {
        let (exact, scale) = (v["surface_air_light"].as_f64().unwrap(), v["scale"].as_f64().unwrap());
        let (Ok(AnyRecord::Surface(s64)), Ok(AnyRecord::Surface(s32))) = (parse_any_value::<f64>(&v), parse_any_value::<f32>(&v)) else { panic!("{v}") };
        let (c64, c32) = (c_surface(&s64), c_surface(&s32));
        let (r64, r32) = unsafe { (airlight_surface_air_light_f64(&c64), airlight_surface_air_light_f32(&c32)) };
        let (e64, e32) = ((r64.value - exact).abs() / exact.max(1e-10 * scale), (r32.value as f64 - exact).abs() / exact.max(1e-4 * scale));
        if r64.status != AIRLIGHT_STATUS_OK || r32.status != AIRLIGHT_STATUS_OK || !(e64 <= 1e-9) || !(e32 <= 1e-4) {
            failures.push(format!("surface {}: f64 {e64:.1e}, f32 {e32:.1e}, statuses {} {}", v["category"], r64.status, r32.status));
        }
        let radiance = unsafe { airlight_surface_radiance_f64(&c64) };
        if radiance.status != AIRLIGHT_STATUS_OK || radiance.value != s64.direct() + r64.value {
            failures.push(format!("surface {}: radiance {} is not direct {} + air-light {}", v["category"], radiance.value, s64.direct(), r64.value));
        }
    }
    assert!(failures.is_empty(), "{}", failures.join("\n"));
    let message = |r: &AirlightResultF64| unsafe { std::ffi::CStr::from_ptr(r.message.as_ptr()) }.to_string_lossy().into_owned();
    let null = unsafe { airlight_surface_air_light_f64(std::ptr::null()) };
    assert_eq!((null.status, null.value, message(&null).as_str()), (AIRLIGHT_STATUS_NULL_POINTER, 0.0, "scene: null pointer"));
    let null = unsafe { airlight_segment_in_scatter_f64(std::ptr::null()) };
    assert_eq!(null.status, AIRLIGHT_STATUS_NULL_POINTER);
    let v = &airlight_tests::reference_lines("surface.jsonl")[0];
    let Ok(AnyRecord::Surface(s)) = parse_any_value::<f64>(v) else { panic!("{v}") };
    let mut bad = c_surface(&s);
    bad.brdf.kind = 9;
    let r = unsafe { airlight_surface_air_light_f64(&bad) };
    assert_eq!((r.status, r.value), (AIRLIGHT_STATUS_INVALID, 0.0));
    assert!(message(&r).starts_with("brdf.kind"), "{}", message(&r));
    let mut bad = c_surface(&s);
    bad.normal = [0.0; 3];
    let r = unsafe { airlight_surface_air_light_f64(&bad) };
    assert_eq!(r.status, AIRLIGHT_STATUS_INVALID);
    assert!(message(&r).starts_with("surface.normal"), "{}", message(&r));
}
