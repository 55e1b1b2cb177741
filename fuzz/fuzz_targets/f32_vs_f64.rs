//! Target (2), differential: model-exact scenes (isotropic light and phase) with inputs exact
//! in f32, `|o − p| ≤ 300 h`, `σt h ∈ [1e-3, 100]` and `σt·|t| ≤ 1e3` for the segment's ends and
//! the light's foot (the f32 conditioning, see below): the f32 kernel with 4 terms within 1e-4
//! of the f64 kernel with 6 terms (the target; the f64 value is within 1e-12 of the
//! integral) wherever the value is a normal f32. (Anisotropic f32 against f64 depends on the
//! expansion's conditioning: bounded in tests/tests/properties.rs, and against the shader by
//! the `shader` target.)
#![no_main]
use airlight::glam::{DVec3, Vec3};
use airlight::light::Omni;
use airlight::phase::Isotropic;
use airlight::{Expansion, Medium, PointLight, Ray, Scene};
use libfuzzer_sys::fuzz_target;

#[allow(dead_code)]
mod common;
use common::{int, num};
use libfuzzer_sys::arbitrary::{Arbitrary, Result, Unstructured};

/// A model-exact scene's inputs, each rounded to f32 (numbers as in the `kernel` target).
#[derive(Debug)]
struct Input {
    o: [f64; 3],
    d: [f64; 3],
    p: [f64; 3],
    t0: f64,
    t1: f64,
    st: f64,
    ss: f64,
}

impl<'a> Arbitrary<'a> for Input {
    fn arbitrary(u: &mut Unstructured<'a>) -> Result<Self> {
        let f = |u: &mut Unstructured, lo: f64, hi: f64| num(u, lo, hi).map(|x| x as f32 as f64);
        let o = [f(u, -50.0, 50.0)?, f(u, -50.0, 50.0)?, f(u, -50.0, 50.0)?];
        let d = [f(u, -1.0, 1.0)?, f(u, -1.0, 1.0)?, f(u, -1.0, 1.0)?];
        let p = [f(u, -50.0, 50.0)?, f(u, -50.0, 50.0)?, f(u, -50.0, 50.0)?];
        let t0 = f(u, -5.0, 5.0)?;
        let t1 = if int(u, 4)? == 0 { f64::INFINITY } else { (t0 + num(u, 0.01, 100.0)?.abs()) as f32 as f64 };
        Ok(Input { o, d, p, t0, t1, st: f(u, 0.0, 10.0)?.abs(), ss: f(u, 0.01, 1.0)?.abs() })
    }
}

fuzz_target!(|input: Input| {
    let Input { o, d, p, t0, t1, st, ss } = input;
    if !(o.iter().chain(&d).chain(&p).all(|x| x.is_finite()) && t0.is_finite() && st.is_finite() && ss.is_finite()) {
        return;
    }
    let ray64 = Ray { origin: DVec3::from_array(o), dir: DVec3::from_array(d), t_min: t0, t_max: t1 };
    let light64 = PointLight { position: DVec3::from_array(p), intensity: 10.0, distribution: Omni };
    let Ok(s64) = Scene::new(ray64, light64, Medium { sigma_s: ss, sigma_t: st }, Isotropic) else { return };
    let g = *s64.canonical();
    let dist = ((p[0] - o[0]).powi(2) + (p[1] - o[1]).powi(2) + (p[2] - o[2]).powi(2)).sqrt();
    // the domain, in a moderate physical range: segments of at least 1e-3 and
    // coefficients below 1e3 (so that no intermediate leaves f32's normal range); and where f32
    // can state the value to 1e-4 at all: one ulp (2^-24 relative) of a segment end or of the
    // foot's x_h moves the exponent σt(t − t0 + r) by up to σt·|t|·2^-24, 6e-5 at σt·|t| = 1e3
    // (a fuzz finding: σt·|t0| = 5.2e3, 8.6 km from the origin, 1.26e-4 off in f32 through the
    // rounding of p − o alone; seed seed-regression-f32-far-from-origin)
    let far = [t0.abs(), if t1.is_finite() { t1.abs() } else { 0.0 }, g.x_h.abs()].into_iter().fold(0.0, f64::max);
    if !(g.h > 0.0 && dist <= 300.0 * g.h && (1e-3..=100.0).contains(&(st * g.h)) && t1 - t0 >= 1e-3 && ss <= 1e3 && st * far <= 1e3) {
        return;
    }
    let v = |a: [f64; 3]| Vec3::new(a[0] as f32, a[1] as f32, a[2] as f32);
    let ray32 = Ray { origin: v(o), dir: v(d), t_min: t0 as f32, t_max: t1 as f32 };
    let light32 = PointLight { position: v(p), intensity: 10.0f32, distribution: Omni };
    // (inputs whose f32 rounding is not a valid scene are not this target's concern)
    let Ok(s32) = Scene::new(ray32, light32, Medium { sigma_s: ss as f32, sigma_t: st as f32 }, Isotropic) else { return };
    let want = s64.in_scatter();
    let got = s32.in_scatter_with::<4>(Expansion::Chebyshev) as f64;
    assert!(!got.is_nan() && got >= 0.0);
    if want >= f32::MIN_POSITIVE as f64 * 1e3 && want <= f32::MAX as f64 / 1e3 {
        let e = (got - want).abs() / want;
        assert!(e <= 1e-4, "f32 {got} vs f64 {want} (rel {e:e}) o {o:?} d {d:?} p {p:?} t [{t0}, {t1}] st {st} ss {ss}");
    }
});
