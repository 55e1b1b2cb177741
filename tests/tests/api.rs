//! The world-space API: typed input errors, the surface term (paper eq. 7), total radiance,
//! the unchecked API's defined value, the on-line limits, and `airlight eval`'s line protocol.

use airlight::glam::DVec3;
use airlight::light::{AnyDistribution, Omni, SpotCone, TwoLobed};
use airlight::phase::{AnyPhase, HenyeyGreenstein, Isotropic, TwoLobeHenyeyGreenstein};
use airlight::{in_scatter, in_scatter_unchecked, ErrorKind, Expansion, Medium, PointLight, Ray, Scene};
use airlight_codegen::eval::{run, EvalOptions, Precision};

fn ray() -> Ray<f64> {
    Ray { origin: DVec3::ZERO, dir: DVec3::X, t_min: 0.0, t_max: 10.0 }
}
fn light() -> PointLight<f64, AnyDistribution<f64>> {
    PointLight { position: DVec3::new(5.0, 1.0, 0.0), intensity: 10.0, distribution: AnyDistribution::Omni }
}
fn medium() -> Medium<f64> {
    Medium { sigma_s: 0.1, sigma_t: 0.2 }
}

fn error_of(r: Ray<f64>, l: PointLight<f64, AnyDistribution<f64>>, m: Medium<f64>, p: AnyPhase<f64>) -> (&'static str, ErrorKind) {
    let e = in_scatter(r, l, m, p).expect_err("invalid input must be rejected");
    (e.field, e.kind)
}

#[test]
fn bad_input_gets_a_typed_error_naming_the_field() {
    let iso = AnyPhase::Isotropic;
    let mut r = ray();
    r.dir = DVec3::ZERO;
    assert_eq!(error_of(r, light(), medium(), iso), ("ray.dir", ErrorKind::ZeroVector));
    let mut r = ray();
    r.origin.x = f64::NAN;
    assert_eq!(error_of(r, light(), medium(), iso), ("ray.origin", ErrorKind::NonFinite));
    let mut r = ray();
    r.t_min = 11.0;
    assert_eq!(error_of(r, light(), medium(), iso), ("ray.t_max", ErrorKind::EmptyRange));
    let mut r = ray();
    r.t_max = f64::NAN;
    assert_eq!(error_of(r, light(), medium(), iso), ("ray.t_max", ErrorKind::NonFinite));
    let mut r = ray();
    r.t_min = f64::NEG_INFINITY;
    assert_eq!(error_of(r, light(), medium(), iso), ("ray.t_min", ErrorKind::NonFinite));
    let mut m = medium();
    m.sigma_s = -1.0;
    assert_eq!(error_of(ray(), light(), m, iso), ("medium.sigma_s", ErrorKind::Negative));
    let mut m = medium();
    m.sigma_t = f64::INFINITY;
    assert_eq!(error_of(ray(), light(), m, iso), ("medium.sigma_t", ErrorKind::NonFinite));
    let mut l = light();
    l.intensity = -2.0;
    assert_eq!(error_of(ray(), l, medium(), iso), ("light.intensity", ErrorKind::Negative));
    let mut l = light();
    l.distribution = AnyDistribution::TwoLobed(TwoLobed { axis: DVec3::Y, power: 3 });
    assert_eq!(error_of(ray(), l, medium(), iso), ("light.distribution.power", ErrorKind::OddPower));
    let mut l = light();
    l.distribution = AnyDistribution::TwoLobed(TwoLobed { axis: DVec3::ZERO, power: 2 });
    assert_eq!(error_of(ray(), l, medium(), iso), ("light.distribution.axis", ErrorKind::ZeroVector));
    let mut l = light();
    l.distribution = AnyDistribution::SpotCone(SpotCone { axis: DVec3::Y, cos_inner: 0.5, cos_outer: 0.9 });
    assert_eq!(error_of(ray(), l, medium(), iso), ("light.distribution.cos_outer", ErrorKind::InvertedCone));
    // a cosine beyond 1 is named where it is, not as an inverted cone
    l.distribution = AnyDistribution::SpotCone(SpotCone { axis: DVec3::Y, cos_inner: 2.0, cos_outer: 0.9 });
    assert_eq!(error_of(ray(), l, medium(), iso), ("light.distribution.cos_inner", ErrorKind::NotACosine));
    let hg = AnyPhase::HenyeyGreenstein(HenyeyGreenstein { g: 1.0 });
    assert_eq!(error_of(ray(), light(), medium(), hg), ("phase.g", ErrorKind::OutOfRange));
    let two = AnyPhase::TwoLobeHenyeyGreenstein(TwoLobeHenyeyGreenstein { g1: 0.5, g2: -0.2, w: 1.5 });
    assert_eq!(error_of(ray(), light(), medium(), two), ("phase.w", ErrorKind::NotAFraction));
    // The unchecked API gives the documented defined value instead of failing.
    let mut r = ray();
    r.dir = DVec3::ZERO;
    assert_eq!(in_scatter_unchecked::<f64, _, _, 6>(r, light(), medium(), iso, Expansion::Chebyshev), 0.0);
}

/// Light exactly on the segment: `+∞`. On the ray line but outside the segment: the closed
/// forms of the `h = 0` limit, checked here against elementary integrals done by hand.
#[test]
fn light_on_the_ray_line() {
    let phase = Isotropic;
    let m = Medium { sigma_s: 0.5, sigma_t: 0.0 };
    let on = PointLight { position: DVec3::new(3.0, 0.0, 0.0), intensity: 2.0, distribution: Omni };
    assert_eq!(in_scatter(ray(), on, m, phase).unwrap(), f64::INFINITY);
    // Ahead of the segment [0, 10] at x = 12, σt = 0: σs I/(4π) ∫ dt/(12 − t)² = σs I/(4π)(1/2 − 1/12).
    let ahead = PointLight { position: DVec3::new(12.0, 0.0, 0.0), intensity: 2.0, distribution: Omni };
    let want = 0.5 * 2.0 / (4.0 * std::f64::consts::PI) * (0.5 - 1.0 / 12.0);
    let got = in_scatter(ray(), ahead, m, phase).unwrap();
    assert!((got - want).abs() <= 4.0 * f64::EPSILON * want, "{got} vs {want}");
    // Behind, σt > 0: ∫_0^10 e^{−σt t} e^{−σt (t+2)}/(t+2)² dt for the light at x = −2, by
    // composite Simpson with 200 000 panels (error ≲ 1e-14 here).
    let mb = Medium { sigma_s: 0.5, sigma_t: 0.3 };
    let behind = PointLight { position: DVec3::new(-2.0, 0.0, 0.0), intensity: 2.0, distribution: Omni };
    let f = |t: f64| (-0.3 * t).exp() * (-0.3 * (t + 2.0)).exp() / ((t + 2.0) * (t + 2.0));
    let n = 200_000;
    let hstep = 10.0 / n as f64;
    let mut s = f(0.0) + f(10.0);
    for i in 1..n {
        s += f(i as f64 * hstep) * if i % 2 == 1 { 4.0 } else { 2.0 };
    }
    let want = 0.5 * 2.0 / (4.0 * std::f64::consts::PI) * s * hstep / 3.0;
    let got = in_scatter(ray(), behind, mb, phase).unwrap();
    assert!((got - want).abs() <= 1e-12 * want, "{got} vs {want}");
}

/// Paper eq. 7 at a point straight below the light: `r_b = 2`, `ω_i·n = 1`, `c_b = −ω_i·a`.
#[test]
fn surface_term_and_total_radiance() {
    let r = Ray { origin: DVec3::ZERO, dir: DVec3::X, t_min: 0.0, t_max: 4.0 };
    let l = PointLight {
        position: DVec3::new(4.0, 2.0, 0.0),
        intensity: 3.0,
        distribution: AnyDistribution::TwoLobed(TwoLobed { axis: DVec3::Y, power: 2 }),
    };
    let m = Medium { sigma_s: 0.1, sigma_t: 0.25 };
    let s = Scene::new(r, l, m, AnyPhase::Isotropic).unwrap();
    let brdf = 1.0 / std::f64::consts::PI;
    let lb = s.surface_radiance(DVec3::Y, brdf);
    let want = (-0.25f64 * 2.0).exp() / 4.0 * 3.0 * 1.0 * brdf * 1.0;
    assert!((lb - want).abs() <= 4.0 * f64::EPSILON * want, "{lb} vs {want}");
    // facing away: no light
    assert_eq!(s.surface_radiance(-DVec3::Y, brdf), 0.0);
    let total = s.radiance(DVec3::Y, brdf);
    let want_total = (-0.25f64 * 4.0).exp() * want + s.in_scatter();
    assert!((total - want_total).abs() <= 4.0 * f64::EPSILON * want_total);
}

fn eval_lines(input: impl AsRef<[u8]>, precision: Precision) -> Vec<String> {
    let mut out = Vec::new();
    let opts = EvalOptions { precision, ..EvalOptions::default() };
    run(input.as_ref(), &mut out, &opts).unwrap();
    String::from_utf8(out).unwrap().lines().map(str::to_string).collect()
}

#[test]
fn eval_lines_in_order_with_errors_naming_line_and_field() {
    let good = r#"{"ray": {"origin": [0,0,0], "dir": [1,0,0], "t_min": 0.0, "t_max": 25.0}, "medium": {"sigma_s": 0.08, "sigma_t": 0.1}, "light": {"position": [5,1,0], "intensity": 100.0, "distribution": {"kind": "two_lobed", "axis": [0,-1,0], "power": 4}}, "phase": {"kind": "henyey_greenstein", "g": 0.5}, "comment": "an annotation, ignored"}"#;
    let bad_power = good.replace("\"power\": 4", "\"power\": 3");
    let bad_dir = good.replace("\"dir\": [1,0,0]", "\"dir\": [1,0]");
    let on_segment = r#"{"ray": {"origin": [0,0,0], "dir": [1,0,0], "t_min": 0, "t_max": null}, "medium": {"sigma_s": 1, "sigma_t": 0}, "light": {"position": [2,0,0], "intensity": 1}, "phase": {"kind": "isotropic"}}"#;
    let input = format!("{good}\n{bad_power}\nnot json\n\n{bad_dir}\n{on_segment}\r\n{good}");
    let out = eval_lines(&input, Precision::F64);
    // one output line per input line, the blank one included, the last one without its newline
    assert_eq!(out.len(), 7, "{out:?}");
    let first: serde_json::Value = serde_json::from_str(&out[0]).unwrap();
    let x = first["in_scatter"].as_f64().unwrap();
    assert!(x > 0.0);
    // shortest round-trip printing: the text parses back to the identical double
    assert_eq!(out[0], format!("{{\"in_scatter\":{x:?}}}"));
    assert!(out[1].contains("line 2") && out[1].contains("light.distribution.power"), "{}", out[1]);
    assert!(out[2].contains("line 3") && out[2].contains("invalid JSON"), "{}", out[2]);
    assert!(out[3].contains("line 4") && out[3].contains("empty line"), "{}", out[3]);
    assert!(out[4].contains("line 5") && out[4].contains("ray.dir"), "{}", out[4]);
    assert_eq!(out[5], "{\"in_scatter\":\"inf\"}");
    assert_eq!(out[6], out[0]);
    let out32 = eval_lines(good, Precision::F32);
    let y: f32 = serde_json::from_str::<serde_json::Value>(&out32[0]).unwrap()["in_scatter"].as_f64().unwrap() as f32;
    assert_eq!(out32[0], format!("{{\"in_scatter\":{y:?}}}"));
    assert!(((y as f64) - x).abs() < 1e-2 * x);
}

/// What a new user mistypes gets an error naming the field, not a silently different scene:
/// unknown keys and kinds (with the closest known one), a field a kind does not have, a field
/// of a kind that is not what it should be (named by its own path), a number beyond the
/// precision's range, a line
/// that is not UTF-8 (the lines after it are still evaluated).
#[test]
fn eval_rejects_unknown_keys_and_bad_bytes_per_line() {
    let good = r#"{"ray": {"origin": [0,0,0], "dir": [1,0,0], "t_max": 25}, "medium": {"sigma_s": 0.08, "sigma_t": 0.1}, "light": {"position": [5,1,0], "intensity": 100}, "phase": {"kind": "henyey_greenstein", "g": 0.5}}"#;
    let cases = [
        (good.replace("\"t_max\"", "\"tmax\""), "ray.tmax", "did you mean `t_max`?"),
        (good.replace("\"phase\"", "\"phase_function\""), "phase_function", "did you mean `phase`?"),
        (good.replace("\"g\": 0.5", "\"g\": 0.5, \"k\": 0.2"), "phase.k", "unknown field"),
        (good.replace("\"intensity\": 100", "\"intensity\": 1e39"), "light.intensity", "beyond the range of f32"),
        (good.replace("\"henyey_greenstein\"", "\"henyey_green\""), "phase.kind", "did you mean `henyey_greenstein`?"),
        (good.replace("\"intensity\": 100", "\"intensity\": 100, \"distribution\": {\"kind\": \"omni\", \"axis\": [1,0,0]}"), "light.distribution.axis", "no fields"),
        (good.replace("\"intensity\": 100", "\"intensity\": 100, \"distribution\": {\"kind\": \"spot\", \"axis\": [1,0], \"cos_inner\": 0.9, \"cos_outer\": 0.8}"), "light.distribution.axis", "length 3"),
    ];
    for (line, field, message) in &cases {
        let out = eval_lines(line, Precision::F32);
        assert!(out.len() == 1 && out[0].contains(&format!("line 1: {field}: ")) && out[0].contains(message), "{line} -> {out:?}");
    }
    let mut input = b"{\"ray\": \xff}\n".to_vec();
    input.extend_from_slice(good.as_bytes());
    let out = eval_lines(&input, Precision::F64);
    assert_eq!(out.len(), 2, "{out:?}");
    assert!(out[0].contains("line 1") && out[0].contains("not UTF-8"), "{}", out[0]);
    assert!(out[1].starts_with("{\"in_scatter\":"), "{}", out[1]);
}

/// Subnormal inputs (a kernel fuzz finding): the exact-product reduction would underflow to
/// `h = 0` and put the light on the line, where `1/s0` then overflowed; the default path falls
/// back to the plain reduction outside `Real::EXACT_RANGE`, and the on-line limit divides
/// through logarithms. The value here is finite: `σs I ∫ e^{−2σt s}/s² ds ≈ σs I D(c)/(4π s0)`.
#[test]
fn subnormal_geometry_is_finite() {
    use airlight::glam::DVec3;
    use airlight::light::TwoLobed;
    let ray = airlight::Ray { origin: DVec3::new(4e-323, 0.0, 1.6316e-319), dir: DVec3::new(0.0, 0.0, 1.59366e-319), t_min: 0.0, t_max: f64::INFINITY };
    let light = airlight::PointLight {
        position: DVec3::ZERO,
        intensity: 5.686073565698723e-270,
        distribution: TwoLobed { axis: DVec3::new(-0.9327512254901962, 0.6782531733770727, -0.7672402119390289), power: 4 },
    };
    let medium = airlight::Medium { sigma_s: 0.06274509803921569, sigma_t: 1.5686274509803921 };
    let s = airlight::Scene::new(ray, light, medium, airlight::phase::Isotropic).unwrap();
    let l = s.in_scatter();
    assert!(l.is_finite() && l > 0.0, "{l}");
    assert!(s.in_scatter_with::<6>(airlight::Expansion::Chebyshev).is_finite());
}

/// The README's kernel example is the crate's first doctest, character for character, so the
/// example a user copies from the README is one that `cargo test` compiles and runs.
#[test]
fn readme_example_is_the_kernel_doctest() {
    let root = airlight_tests::repo_root();
    let lib = std::fs::read_to_string(root.join("kernel/src/lib.rs")).unwrap();
    let docs: String = lib.lines().take_while(|l| l.starts_with("//!")).map(|l| format!("{}\n", l.trim_start_matches("//!").strip_prefix(' ').unwrap_or(""))).collect();
    let start = docs.find("```\n").expect("a doctest in the crate docs") + "```\n".len();
    let from_docs = &docs[start..start + docs[start..].find("```").unwrap()];
    // the workspace's README and the crate's (its crates.io page)
    for readme in ["README.md", "kernel/README.md"] {
        let text = std::fs::read_to_string(root.join(readme)).unwrap();
        let start = text.find("```rust\n").expect("a Rust block in the README") + "```rust\n".len();
        let from_readme = &text[start..start + text[start..].find("```").unwrap()];
        assert_eq!(from_readme, from_docs, "{readme}'s example and kernel/src/lib.rs's first doctest differ");
    }
}

/// With the `mint` feature, an engine on another math crate (or another glam version) hands
/// its vectors over as `mint` types: `Vec3::from(mint::Vector3)` and back, nothing else.
#[test]
fn mint_vectors_convert_in_and_out() {
    use airlight::glam::Vec3;
    let origin = mint::Vector3 { x: 0.0f32, y: 0.0, z: 0.0 };
    let dir = mint::Vector3 { x: 1.0f32, y: 0.0, z: 0.0 };
    let position = mint::Vector3 { x: 5.0f32, y: 1.0, z: 0.0 };
    let ray = Ray::<f32> { origin: Vec3::from(origin), dir: dir.into(), t_min: 0.0, t_max: 25.0 };
    let light = PointLight { position: position.into(), intensity: 100.0, distribution: airlight::light::Omni };
    let s = Scene::new(ray, light, Medium { sigma_s: 0.08, sigma_t: 0.1 }, airlight::phase::Isotropic).unwrap();
    assert!(s.in_scatter() > 0.0);
    let back = mint::Vector3::<f32>::from(ray.dir);
    assert_eq!((back.x, back.y, back.z), (1.0, 0.0, 0.0));
}

/// A kernel fuzz finding: an isotropic ray across the foot to `t ≈ 8e298` in a medium with a
/// subnormal `σt`. `Re ln((v_e − i)/(v_s − i))` overflowed as a product (`Δv·v_e ≈ 6e593`) and
/// reached `Im C` through `e^{−iH}`'s `sin H ≠ 0`: `−∞`. With `σt·t ≈ 2e-14` the extinction is
/// negligible, so the value is the `atan` form's (Macklin 2010), to that order.
#[test]
fn ray_to_the_range_end_in_a_vanishing_medium_is_the_atan_form() {
    let ray = Ray::<f64> {
        origin: DVec3::new(-36.6809172241934, -61.23279014808105, -1.7215010289859124e27),
        dir: DVec3::new(0.3818469657803454, 0.2752413066208408, 3.4028234663852886e38),
        t_min: 9.843137254900721,
        t_max: 7.845911676394542e298,
    };
    let position = DVec3::new(98.43137254901958, 98.43137254901958, -46.88112745098041);
    let light = PointLight { position, intensity: 992.149233350564, distribution: Omni };
    let medium = Medium { sigma_s: 0.3792906275639931, sigma_t: 3.05137131765e-313 };
    let s = Scene::new(ray, light, medium, Isotropic).unwrap();
    let want = airlight::atan_form(&ray, position, 992.149233350564, 0.3792906275639931);
    for got in [s.in_scatter(), s.in_scatter_with::<6>(Expansion::Chebyshev)] {
        assert!((got - want).abs() <= 1e-12 * want, "{got} vs the atan form {want}");
    }
}

/// A kernel fuzz finding: the light `1.3e-321` off the line, inside an infinite segment, no
/// extinction. `H·r_s` was `0·∞` (the distance in units of a subnormal `h` overflows): NaN.
/// The value, `σs·I/(4h) ≈ 3e313`, is beyond the f64 range: `+∞`, as documented.
#[test]
fn light_a_subnormal_distance_off_an_infinite_ray_is_infinite_not_nan() {
    let ray = Ray::<f64> { origin: DVec3::new(1.18e-321, 4.5e-322, 0.0), dir: DVec3::new(0.0, 0.0, -0.9372549019607843), t_min: -9.997549019607844, t_max: f64::INFINITY };
    let light = PointLight { position: DVec3::new(0.0, 0.0, 1.224167783418391e-250), intensity: 572.5420479675877, distribution: Omni };
    let s = Scene::new(ray, light, Medium { sigma_s: 2.666780130056168e-10, sigma_t: 0.0 }, Isotropic).unwrap();
    assert_eq!(s.in_scatter(), f64::INFINITY);
    assert_eq!(s.in_scatter_with::<6>(Expansion::Chebyshev), f64::INFINITY);
}

/// A kernel fuzz finding (and the one the fuzz README had left open): a spot cone whose edge
/// is narrower than any f64 step, seen from a ray `7.7e-121` from the light. The edge's
/// crossing is a root of `a y² + b y + c` with `b ≈ 1e-190`: `b²` underflowed, the
/// discriminant became 0 and the cut landed at twice the root, so the fixed method expanded
/// a step (coefficients to 1e238, `+∞` on a lit part; the Taylor expansion 2× off). With the
/// coefficients scaled first, every method agrees with the default path.
#[test]
fn needle_cone_edge_is_cut_where_it_is() {
    use airlight::light::SpotCone;
    let ray = Ray::<f64> { origin: DVec3::new(0.0, 8.487983164e-314, 7.747074743719559e-121), dir: DVec3::new(-1.0, 1.379679969383946e-309, 0.0), t_min: 3.337610787760802e-308, t_max: f64::INFINITY };
    let cone = SpotCone { axis: DVec3::new(0.0, 1.7976931348623157e308, 0.9999999999985232), cos_inner: 1.17654883e-315, cos_outer: 0.0 };
    let light = PointLight { position: DVec3::new(0.0, 4.889078302384e-311, 0.0), intensity: 6.00746353852756e95, distribution: cone };
    let s = Scene::new(ray, light, Medium { sigma_s: 0.6851587594819881, sigma_t: 49.99999758062074 }, Isotropic).unwrap();
    let want = s.in_scatter();
    for got in [s.in_scatter_with::<6>(Expansion::Chebyshev), s.in_scatter_with::<4>(Expansion::Chebyshev), s.in_scatter_with::<6>(Expansion::Taylor)] {
        assert!((got - want).abs() <= 1e-10 * want, "{got} vs the default {want}");
    }
    let lit = s.in_scatter_lit_with::<6>(&[(3.337610787760802e-308, 1.0)], Expansion::Chebyshev);
    assert!(lit.is_finite() && lit > 0.0 && lit <= want, "{lit}");
}

/// A kernel fuzz finding in f32: the light at `y = f32::MAX`, an infinite ray across its foot,
/// `σt` that rounds to 0 in f32. The start's distance `hypot(h, x_h − t0)` overflowed f32 and
/// met `σt = 0`: NaN. The value is the f64 evaluation of the same (f32-rounded) scene.
#[test]
fn light_at_the_f32_range_end_without_extinction_is_finite() {
    use airlight::glam::Vec3;
    let o = [-39.87963104248047f32, 12.193191528320313, 35.090694427490234];
    let d = [1.0f32, 0.5452190041542053, 0.0];
    let p = [13.72549057006836f32, f32::MAX, -0.0];
    let ray = Ray::<f32> { origin: Vec3::from_array(o), dir: Vec3::from_array(d), t_min: -0.0, t_max: f32::INFINITY };
    let light = PointLight { position: Vec3::from_array(p), intensity: f32::MAX, distribution: Omni };
    let s = Scene::new(ray, light, Medium { sigma_s: f32::MAX, sigma_t: 0.0 }, Isotropic).unwrap();
    let wide = |a: [f32; 3]| DVec3::from_array(a.map(f64::from));
    let ray64 = Ray::<f64> { origin: wide(o), dir: wide(d), t_min: 0.0, t_max: f64::INFINITY };
    let light64 = PointLight { position: wide(p), intensity: f32::MAX as f64, distribution: Omni };
    let want = Scene::new(ray64, light64, Medium { sigma_s: f32::MAX as f64, sigma_t: 0.0 }, Isotropic).unwrap().in_scatter();
    for got in [s.in_scatter(), s.in_scatter_with::<6>(Expansion::Chebyshev)] {
        assert!(((got as f64) - want).abs() <= 1e-5 * want, "{got} vs f64 {want}");
    }
}

/// A kernel fuzz finding in f64: the light `7.9e-317` off the ray's line, `5.3e-169` ahead of a
/// segment `[−4.6e158, 0]` without extinction. The on-line limit's `Δt/r₁` overflowed before
/// its `1/r₀` was applied (`+∞`); the value is `σs I/(4π)·(1/r₁ − 1/r₀)`, `r₀`, `r₁` the
/// ends' distances, here `1/r₁` to 15 digits. The same geometry with the fuzzer's spot cone and
/// two-lobed phase function is finite too.
#[test]
fn light_just_ahead_of_a_long_segment_is_finite() {
    let ray = Ray::<f64> { origin: DVec3::new(1.18e-321, 4.5e-322, 5.299469827377981e-169), dir: DVec3::new(-0.9212940924815196, 0.7568626441061497, -4.634680647717983e158), t_min: -4.634680647717983e158, t_max: 0.0 };
    let position = DVec3::new(7.2813577e-317, 3.1083923e-317, 0.0);
    let (sigma_s, intensity) = (0.14901960784313717, 8.645627431730427e-217);
    let m = Medium { sigma_s, sigma_t: 0.0 };
    let omni = Scene::new(ray, PointLight { position, intensity, distribution: Omni }, m, Isotropic).unwrap();
    // the foot is at t = 5.299469827377981e-169 (the origin's z; the direction is −z to 1e-159)
    let want = sigma_s * intensity / (4.0 * std::f64::consts::PI) / 5.299469827377981e-169;
    for got in [omni.in_scatter(), omni.in_scatter_with::<6>(Expansion::Chebyshev)] {
        assert!((got - want).abs() <= 1e-14 * want, "{got} vs {want}");
    }
    let spot = SpotCone { axis: DVec3::new(0.7568627450980392, -4.634680647717983e158, 0.0), cos_inner: 3.6260443998244473e-217, cos_outer: -0.8509803921568628 };
    let phase = TwoLobeHenyeyGreenstein { g1: -0.8424705882352942, g2: -0.8424705882352942, w: 0.07450980392156858 };
    let s = Scene::new(ray, PointLight { position, intensity, distribution: spot }, m, phase).unwrap();
    for got in [s.in_scatter(), s.in_scatter_with::<4>(Expansion::Taylor), s.in_scatter_with::<6>(Expansion::Chebyshev)] {
        assert!(got.is_finite() && got > 0.0, "{got}");
    }
}

/// Found by the `kernel` fuzz target (a CI run of 2026-12-05): a light `6e-249` off the ray's
/// line, `179.5` behind a segment `[0, 1.4e-13]`, in fog — the on-line limit's `head − tail`
/// (`e^{σt s0}(E₂(2σt s0)/s0 − E₂(2σt s1)/s1)`) cancelled to rounding and gave `−4.2e189`
/// (`−2·10⁹` ulps of nothing). Against `σs I/(4π) ∫_{s0}^{s1} e^{−σt(2s − s0)}/s² ds`, which over a
/// span `1e-13` of `s0 = 179.5` is `σs I/(4π)·e^{−σt s0}·span/s0²` to 15 digits (the
/// integrand's relative change over the span, `2σt·span + 2 span/s0`, is below 1e-14): within
/// 1e-13, for the isotropic and the fuzzer's Schlick scenes, in f64 and (finite, non-negative,
/// within 1e-5) f32.
#[test]
fn light_just_behind_a_short_segment_is_not_cancelled() {
    use airlight::glam::Vec3;
    let ray = Ray::<f64> { origin: DVec3::new(99.99713022261858, 0.0, 1.981082008e-314), dir: DVec3::new(7.543031923e-315, 0.0, 0.0), t_min: 0.0, t_max: 1.4210854715202004e-13 };
    let light = PointLight { position: DVec3::new(-79.47124509127082, 6.045834155587397e-249, -0.0), intensity: 8.436253180429202e207, distribution: airlight::light::TwoLobed { axis: DVec3::new(-0.28042633306383813, -0.9988710889629291, 5.686073566141166e-270), power: 0 } };
    let (sigma_s, sigma_t) = (1.9843137254901955, 0.006127461892896369);
    let m = Medium { sigma_s, sigma_t };
    let s0 = 99.99713022261858 + 79.47124509127082;
    let span = 1.4210854715202004e-13;
    let want = sigma_s * light.intensity / (4.0 * std::f64::consts::PI) * (-sigma_t * s0).exp() * (span / s0) / s0;
    let iso = Scene::new(ray, light, m, Isotropic).unwrap();
    let schlick = Scene::new(ray, light, m, airlight::phase::Schlick { k: 1.3730560997e-314 }).unwrap();
    for got in [iso.in_scatter(), schlick.in_scatter(), iso.in_scatter_with::<6>(Expansion::Chebyshev)] {
        assert!((got - want).abs() <= 1e-13 * want, "{got:e} vs {want:e}");
    }
    // f32: the same geometry scaled into f32's range (the intensity 1e30)
    let ray32 = Ray::<f32> { origin: Vec3::new(100.0, 0.0, 0.0), dir: Vec3::X, t_min: 0.0, t_max: 1.0e-5 };
    let light32 = PointLight { position: Vec3::new(-79.5, 1.0e-30, 0.0), intensity: 1.0e30f32, distribution: airlight::light::Omni };
    let m32 = Medium { sigma_s: 2.0f32, sigma_t: 0.006 };
    let got = Scene::new(ray32, light32, m32, Isotropic).unwrap().in_scatter() as f64;
    let (s0, span) = (179.5f64, 1.0e-5f32 as f64);
    let want = 2.0 * 1.0e30 / (4.0 * std::f64::consts::PI) * (-(0.006f32 as f64) * s0).exp() * (span / s0) / s0 * (1.0 - (0.006f32 as f64 + 1.0 / s0) * span);
    assert!(got.is_finite() && (got - want).abs() <= 1e-5 * want, "f32: {got:e} vs {want:e}");
}

/// A segment light's record (docs/DESIGN.md §6, §10) evaluates on the CPU; its errors name
/// `light.a`/`light.b`/`light.shape`; the fixed-term method and the GPU backend are point
/// lights only and say so per line.
#[test]
fn eval_segment_light_records() {
    let seg = r#"{"ray": {"origin": [0,0,0], "dir": [1,0,0], "t_max": 30}, "medium": {"sigma_s": 0.05, "sigma_t": 0.1}, "light": {"shape": "segment", "a": [10, 1, -2], "b": [10, 1, 2], "intensity": 10}, "phase": {"kind": "henyey_greenstein", "g": 0.8}}"#;
    let input = [
        seg.to_string(),
        seg.replace("\"shape\": \"segment\"", "\"shape\": \"segmnet\""),
        seg.replace("\"a\": [10, 1, -2]", "\"position\": [10, 1, -2]"),
        seg.replace("\"b\": [10, 1, 2]", "\"b\": [10, 1, 1e400]"),
    ]
    .join("\n");
    let out = eval_lines(&input, Precision::F64);
    assert_eq!(out.len(), 4, "{out:?}");
    let x: f64 = serde_json::from_str::<serde_json::Value>(&out[0]).unwrap()["in_scatter"].as_f64().unwrap();
    assert!(x > 0.0 && x.is_finite(), "{}", out[0]);
    assert!(out[1].contains("light.shape") && out[1].contains("did you mean `segment`?"), "{}", out[1]);
    assert!(out[2].contains("light.position") && out[2].contains("unknown field"), "{}", out[2]);
    assert!(out[3].contains("line 4"), "{}", out[3]);
    let mut fixed = Vec::new();
    run(seg.as_bytes(), &mut fixed, &EvalOptions { terms: Some(4), ..EvalOptions::default() }).unwrap();
    assert!(String::from_utf8(fixed).unwrap().contains("--terms is for point lights"));
}
