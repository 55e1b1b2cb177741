//! Properties of the exact integral that the kernel must keep: linearity in `I` and
//! `σs`; splitting a segment; continuity to the `atan` form as `σt → 0`; non-negativity;
//! finite output for finite input; f32 close to f64. Scenes come from a seeded generator
//! (`airlight_tests::scenes::random`), so every run checks the same few thousand cases.

use airlight::light::AnyDistribution;
use airlight::phase::AnyPhase;
use airlight::{Expansion, Scene};
use airlight_tests::scenes::{random, Aniso};
use airlight_tests::{rel_err, Rng};

const CASES: usize = 2000;

/// `L` is linear in `I` and in `σs`: scaling either by 3 scales `L` by 3 up to the rounding of
/// the two products that carry them (≤ 2 ulp each side) — bound 8ε.
#[test]
fn linear_in_intensity_and_scattering() {
    let mut rng = Rng(1);
    for _ in 0..CASES {
        let p = random(&mut rng, Aniso::Any);
        let base = p.f64().in_scatter();
        if !base.is_finite() || base == 0.0 || base < 1e-290 {
            continue;
        }
        let mut q = p;
        q.intensity *= 3.0;
        assert!(rel_err(q.f64().in_scatter(), 3.0 * base) <= 8.0 * f64::EPSILON, "{p:?}");
        let mut q = p;
        q.sigma_s *= 3.0;
        assert!(rel_err(q.f64().in_scatter(), 3.0 * base) <= 8.0 * f64::EPSILON, "{p:?}");
    }
}

/// `L(t0,t1) = L(t0,tm) + e^{−σt(tm−t0)} L(tm,t1)`. Model-exact scenes: each of the three
/// values is within the kernel's 1e-12 target, so the identity holds to 3e-12 relative to the
/// sum of the magnitudes. Anisotropic scenes: the three sub-intervals get different
/// polynomials, so the identity holds only up to the expansion error; with 14 Chebyshev terms
/// on gentle anisotropy that is below 1e-6 (the README's convergence table). The default
/// error-controlled path (`in_scatter_lit`): each value within its 1e-10 target of itself, so
/// the identity holds to 1e-10 of the sum of the magnitudes, anisotropic or not.
#[test]
fn splitting_a_segment() {
    type Lit = fn(&Scene<f64, AnyDistribution<f64>, AnyPhase<f64>>, &[(f64, f64)]) -> f64;
    let default: Lit = |s, lit| s.in_scatter_lit(lit);
    let fixed_14: Lit = |s, lit| s.in_scatter_lit_with::<14>(lit, Expansion::Chebyshev);
    // (method, its name, random stream, [(anisotropy, tolerance)])
    let runs: [(Lit, &str, u64, [(Aniso, f64); 2]); 2] =
        [(default, "default", 12, [(Aniso::None, 1e-10), (Aniso::Mild, 1e-10)]), (fixed_14, "fixed 14 terms", 2, [(Aniso::None, 3e-12), (Aniso::Mild, 1e-6)])];
    for (lit, name, seed, cases) in runs {
        let mut rng = Rng(seed);
        for (aniso, tol) in cases {
            let mut worst = 0.0f64;
            for _ in 0..CASES {
                let p = random(&mut rng, aniso);
                let s = p.f64();
                if !p.t_max.is_finite() {
                    continue;
                }
                let tm = p.t_min + rng.unit() * (p.t_max - p.t_min);
                let (whole, left, right_attenuated) = (lit(&s, &[(p.t_min, p.t_max)]), lit(&s, &[(p.t_min, tm)]), lit(&s, &[(tm, p.t_max)]));
                if !whole.is_finite() {
                    continue;
                }
                if name == "default" {
                    assert_eq!(whole, s.in_scatter(), "the whole segment as one lit part is the default path");
                }
                let e = (whole - (left + right_attenuated)).abs() / (whole.abs() + left.abs() + right_attenuated.abs()).max(1e-300);
                worst = worst.max(e);
                assert!(e <= tol, "{name}, {aniso:?}: split at {tm}: {whole} vs {left} + {right_attenuated} (rel {e:.2e}) in {p:?}");
            }
            println!("{name}, {aniso:?}: worst split defect {worst:.2e}");
        }
    }
}

/// As `σt → 0` (isotropic light and phase), `L` tends to its `σt = 0` value `L_0` from below:
/// `0 ≤ L_0 − L ≤ σt·(t1 − t0 + r_max)·L_0`, since `1 − e^{−x} ≤ x`; and `L_0` is the `atan`
/// form `A` up to the rounding of `atan u1 − atan u0` in `A`:
/// `64ε (|atan u1| + |atan u0|)/|atan u1 − atan u0|` (plus the kernel's own 1e-13).
#[test]
fn continuous_to_the_atan_form() {
    let mut rng = Rng(3);
    for _ in 0..CASES {
        let mut p = random(&mut rng, Aniso::None);
        if !p.t_max.is_finite() {
            continue;
        }
        p.sigma_t = 0.0;
        let s = p.f64();
        let g = s.canonical();
        let (u0, u1) = (g.u(g.t0), g.u(g.t1));
        // the atan form on the scene's own reduction (`atan_form` reduces plainly, which is
        // less accurate in h than the default path's reduction)
        let a = p.sigma_s * p.intensity / (4.0 * std::f64::consts::PI * g.h) * (u1.atan() - u0.atan());
        let cond = (u1.atan().abs() + u0.atan().abs()) / (u1.atan() - u0.atan()).abs();
        let l0 = s.in_scatter();
        assert!(rel_err(l0, a) <= 64.0 * f64::EPSILON * cond + 1e-13, "σt = 0: {l0} vs atan form {a} in {p:?}");
        let r_max = [p.t_min, p.t_max].iter().map(|t| (g.h * g.h + (t - g.x_h).powi(2)).sqrt()).fold(0.0, f64::max);
        for sigma_t in [1e-9, 1e-6, 1e-3] {
            p.sigma_t = sigma_t;
            let l = p.f64().in_scatter();
            let bound = sigma_t * (p.t_max - p.t_min + r_max) * l0;
            let slack = 1e-13 * l0;
            assert!(l <= l0 + slack && l0 - l <= bound + slack, "σt = {sigma_t}: L = {l}, L_0 = {l0}, bound {bound} in {p:?}");
        }
    }
}

/// `L ≥ 0`, and finite unless the light lies on the segment, for every valid scene over wide
/// ranges, in both precisions, both term counts, both expansions.
#[test]
fn non_negative_and_finite() {
    let mut rng = Rng(4);
    for _ in 0..CASES {
        let p = random(&mut rng, Aniso::Any).rounded();
        for e in [Expansion::Chebyshev, Expansion::Taylor] {
            let s64 = p.f64();
            let s32 = p.f32();
            let vals = [
                s64.in_scatter_with::<4>(e),
                s64.in_scatter_with::<6>(e),
                s32.in_scatter_with::<4>(e) as f64,
                s32.in_scatter_with::<6>(e) as f64,
            ];
            for v in vals {
                assert!(v >= 0.0 && !v.is_nan(), "{v} for {p:?}");
                assert!(v.is_finite(), "{v} for {p:?}");
            }
        }
    }
}

/// f32 against f64 on identical (f32-rounded) inputs. Model-exact scenes with
/// `|origin − light| ≤ 300 h` (the domain): 4-term f32 within 1e-4 of the f64 value.
/// That budget: inputs are exact, `x_h`, `h`, `u` carry a few ulps each, amplified by at most
/// `|o − p|/h ≤ 300` in `u` (≈ 2e-5 relative in the worst case), plus the f32 `E1` (2e-6) times
/// the cancellation of the short-interval guard (≤ 4).
#[test]
fn f32_close_to_f64_model_exact() {
    let mut rng = Rng(5);
    let mut worst = 0.0f64;
    let mut n = 0;
    while n < CASES {
        let p = random(&mut rng, Aniso::None).rounded();
        let d = [0, 1, 2].map(|i| p.light[i] - p.origin[i]);
        let dist = (d[0] * d[0] + d[1] * d[1] + d[2] * d[2]).sqrt();
        let s = p.f64();
        if dist > 300.0 * s.canonical().h {
            continue;
        }
        let want = s.in_scatter();
        if !(want > f32::MIN_POSITIVE as f64 * 1e6 && want < f32::MAX as f64 / 1e6) {
            continue;
        }
        let got = p.f32().in_scatter_with::<4>(Expansion::Chebyshev) as f64;
        let e = rel_err(got, want);
        worst = worst.max(e);
        assert!(e <= 1e-4, "f32 {got} vs f64 {want} (rel {e:.2e}) in {p:?}");
        n += 1;
    }
    println!("worst f32/f64 model-exact: {worst:.2e}");
}

/// f32 against f64 at the same term count and expansion, anisotropic scenes, identical
/// (f32-rounded) inputs. The expansion itself is the same polynomial up to rounding; what
/// differs is rounding, amplified (a) in the closed forms like the model-exact case (≤ 1e-4
/// above) and (b) in the expansion coefficients: node values carry ≈ 8 ulp of `F` (a handful
/// of operations), which the Chebyshev-to-monomial conversion amplifies by at most
/// `(1+√2)^N ≈ 34` for `N = 4` — ≈ 3e-5. The sum, 1.3e-4, is judged against the scale of the
/// integrand (`L` with `F` replaced by its maximum on the segment, bounded here by `L_iso·F_max`
/// where `L_iso` is the isotropic value) rather than against `L` itself, which can be far
/// smaller when the beam points away from the ray.
#[test]
fn f32_close_to_f64_anisotropic() {
    use airlight::light::AnyDistribution;
    use airlight::phase::AnyPhase;
    let mut rng = Rng(6);
    let mut worst = 0.0f64;
    let mut n = 0;
    while n < CASES {
        let p = random(&mut rng, Aniso::Any).rounded();
        let d = [0, 1, 2].map(|i| p.light[i] - p.origin[i]);
        let dist = (d[0] * d[0] + d[1] * d[1] + d[2] * d[2]).sqrt();
        let s = p.f64();
        if dist > 300.0 * s.canonical().h {
            continue;
        }
        let mut iso = p;
        iso.dist = AnyDistribution::Omni;
        iso.phase = AnyPhase::Isotropic;
        // F_max ≤ max D · max P; with D ≤ 1 and P ≤ P(μ = ±1) for these phase functions.
        let p_max = [-1.0f64, 1.0].iter().map(|&mu| airlight::PhaseFunction::<f64>::eval(&p.phase, mu)).fold(0.0, f64::max);
        let scale = iso.f64().in_scatter() * 4.0 * std::f64::consts::PI * p_max;
        if !(scale > f32::MIN_POSITIVE as f64 * 1e6 && scale < f32::MAX as f64 / 1e6) {
            continue;
        }
        let want = s.in_scatter_with::<4>(Expansion::Chebyshev);
        let got = p.f32().in_scatter_with::<4>(Expansion::Chebyshev) as f64;
        let e = (got - want).abs() / scale;
        worst = worst.max(e);
        assert!(e <= 1.3e-4, "f32 {got} vs f64 {want}, scale {scale} (err {e:.2e}) in {p:?}");
        n += 1;
    }
    println!("worst f32/f64 anisotropic (relative to the integrand's scale): {worst:.2e}");
}

/// Henyey–Greenstein (alone, in Cornette–Shanks, in two lobes) at its peak with `|g| → 1`:
/// `1 + g² − 2gμ` must not cancel (it rounded to 0 and made a far segment `+∞`; kernel fuzz
/// finding). At `μ = sign(g)` the exact value is `(1 + |g|) / (4π (1 − |g|)²)`, computed here
/// from `1 − |g|`, which is exact.
#[test]
fn henyey_greenstein_peak_does_not_cancel() {
    use airlight::phase::{CornetteShanks, HenyeyGreenstein, PhaseFunction};
    for k in [20, 30, 40, 45, 50] {
        let one_minus = 2f64.powi(-k);
        for sign in [1.0, -1.0] {
            let g = sign * (1.0 - one_minus);
            let want = (2.0 - one_minus) / (4.0 * std::f64::consts::PI * one_minus * one_minus);
            let hg = HenyeyGreenstein { g }.eval(sign);
            assert!(rel_err(hg, want) < 1e-14, "HG g = {g}: {hg:e}, want {want:e}");
            // Cornette–Shanks at μ = ±1: HG · 3(1 + μ²)/(2(2 + g²)) = HG · 3/(2 + g²)
            let cs = CornetteShanks { g }.eval(sign);
            let want_cs = want * 3.0 / (2.0 + g * g);
            assert!(rel_err(cs, want_cs) < 1e-14, "Cornette–Shanks g = {g}: {cs:e}, want {want_cs:e}");
            // f32 with the nearest g (1 − 2^-k is exact in f32 only for k ≤ 24)
            if k <= 24 {
                let hg32 = HenyeyGreenstein { g: g as f32 }.eval(sign as f32) as f64;
                assert!(rel_err(hg32, want) < 1e-6, "HG f32 g = {g}: {hg32:e}, want {want:e}");
            }
        }
    }
}

/// A light that declares where it is dark (`LightDistribution::dark_below`: a spot cone outside
/// its outer cone, a flat emitter behind its plane) makes the default path skip those pieces of
/// the ray. Skipping must change nothing but the work: the same light wrapped in a distribution
/// that does not declare it (a user's own type, delegating `eval`, `axis`, `kinks` and
/// `polynomial_degree`) evaluates
/// every piece, and the two values are bit-identical (a lit piece skipped would lose its light;
/// a dark one integrates to exactly 0), with at least as many panels — and fewer on some scenes.
/// A ray the cone never reaches is 0 with no panel.
#[test]
fn dark_pieces_are_skipped_exactly() {
    use airlight::light::{Lambertian, SpotCone};
    use airlight::{default_control, LightDistribution, Medium, PointLight, Ray, Scalar};
    use airlight::glam::DVec3;

    #[derive(Clone, Copy, Debug)]
    struct Undeclared<D>(D);
    impl<D: LightDistribution<f64>> LightDistribution<f64> for Undeclared<D> {
        fn axis(&self) -> [f64; 3] {
            self.0.axis()
        }
        fn eval<S: Scalar<f64>>(&self, c: S) -> S {
            self.0.eval(c)
        }
        fn kinks(&self) -> [Option<f64>; 2] {
            self.0.kinks()
        }
        // the same error estimate on both sides: only `dark_below` is left undeclared
        fn polynomial_degree(&self) -> Option<u32> {
            self.0.polynomial_degree()
        }
    }
    fn both<D: LightDistribution<f64> + Copy>(p: &airlight_tests::scenes::Plain, dist: D) -> ((f64, usize), (f64, usize)) {
        let control = default_control();
        (p.f64_with(dist).in_scatter_panels_counted::<16>(control), p.f64_with(Undeclared(dist)).in_scatter_panels_counted::<16>(control))
    }
    let mut rng = Rng(23);
    let (mut compared, mut fewer) = (0, 0);
    for i in 0..CASES {
        let p = random(&mut rng, Aniso::Any);
        let axis = DVec3::from_array(rng.unit_vector());
        let co = rng.range(-0.9, 0.99);
        let spot = SpotCone { axis, cos_inner: co + rng.range(0.0, 1.0 - co), cos_outer: co };
        let ((v, n), (w, m)) = if i % 3 == 0 { both(&p, Lambertian { axis }) } else { both(&p, spot) };
        assert!(v.to_bits() == w.to_bits() || (v.is_nan() && w.is_nan()), "case {i}: {v} declared vs {w} undeclared in {p:?}");
        assert!(n <= m, "case {i}: {n} panels declared vs {m} undeclared");
        compared += 1;
        fewer += usize::from(n < m);
    }
    println!("{compared} scenes, {fewer} with fewer panels");
    assert!(fewer > compared / 10, "the dark pieces were skipped on only {fewer} of {compared} scenes");
    // a spot pointing away from the ray: dark everywhere
    let ray = Ray { origin: DVec3::ZERO, dir: DVec3::X, t_min: 0.0, t_max: 50.0 };
    let away = PointLight { position: DVec3::new(10.0, 2.0, 0.0), intensity: 100.0, distribution: SpotCone { axis: DVec3::Y, cos_inner: 0.9, cos_outer: 0.8 } };
    let scene = Scene::new(ray, away, Medium { sigma_s: 0.1, sigma_t: 0.2 }, AnyPhase::Isotropic).unwrap();
    assert_eq!(scene.in_scatter_panels_counted::<16>(default_control()), (0.0, 0), "a ray outside the cone");
}
