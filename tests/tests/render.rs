//! `airlight render`: the five scenes at 48×27 on the CPU kernel (f64, its default
//! error-controlled paths) against the brute-force reference (adaptive Gauss–Kronrod quadrature
//! of the contract integral in `u = atan((t − x_h)/h)`, no closed forms; a tube's integrated
//! over it, a fog-lit surface's over its hemisphere).
//!
//! ## The bounds
//! The reference stops at a summed `|K15 − G7|` estimate of 1e-9 of the integral; a 1e-11 run
//! differs from it by at most 7e-9 relatively on these scenes ([`reference_is_converged`]).
//! The kernel's default path is within 1e-10 of `max(|exact|, 1e-10·scale)` (tests/classes.rs).
//! So a pixel's difference is at most ≈ 1e-8 of its scale, and both bounds below are `1e-6`:
//!
//! 1. Per pixel and channel, relative to that pixel's *integrand scale* `S` (`L_m` with
//!    `D·P` replaced by its maximum, summed over the lights with their colours — computed
//!    here by the kernel's model-exact isotropic path): `|kernel − ref| ≤ ε·S`, `ε = 1e-6`.
//! 2. Per pixel, relative to the image's brightest reference value `B` (largest channel of
//!    any pixel): `max_c |kernel − ref| ≤ ε·B`, the same `ε` — the image-level claim.
//!
//! Measured (48×27): of the pixel scale, max 1.3e-9 (road), 7.5e-10 (stage), 4.0e-11 (bench),
//! 3.0e-12 (street), 5.9e-14 (lighthouse) — the reference's own convergence, not the kernel's
//! error. The f32
//! shader is not tested here (no GPU test in this file; `tests/gpu_agreement.rs` covers it).

use airlight::light::AnyDistribution;
use airlight::phase::AnyPhase;
use airlight::{Brdf, PhaseFunction, PointLight, Ray, Scene, SegmentLight, SegmentScene, Surface, SurfaceScene};
use airlight_codegen::render::{self, Image, SceneDesc};

/// Per pixel: `Σ_lights colour · S`, `S` the integrand's scale of the pixel's segment —
/// `L_m` with `D·P` replaced by its maximum `max P` (`D ≤ 1`), i.e. the isotropic integral
/// (computed by the kernel's model-exact isotropic path, 1e-13 accurate; a tube's by its
/// default path, 1e-10) × `4π·max P` — plus, on a fog-lit surface, its air-light in isotropic
/// fog × `4π·max P` × the albedo.
fn scales(scene: &SceneDesc) -> Vec<[f64; 3]> {
    let p_max = PhaseFunction::<f64>::eval(&scene.phase, 1.0).max(PhaseFunction::<f64>::eval(&scene.phase, -1.0));
    let mut out = Vec::new();
    for y in 0..scene.camera.height {
        for x in 0..scene.camera.width {
            let (d, hit) = scene.primary(x, y);
            let mut px = [0.0; 3];
            for l in &scene.lights {
                let ray = Ray { origin: scene.camera.position, dir: d, t_min: 0.0, t_max: hit.t };
                let iso = PointLight { position: l.light.position, intensity: l.light.intensity, distribution: AnyDistribution::Omni };
                let glow = match l.tube() {
                    Some(tube) => SegmentScene::new(ray, SegmentLight { distribution: AnyDistribution::Omni, ..tube }, scene.medium, AnyPhase::Isotropic).unwrap().in_scatter(),
                    None => Scene::new(ray, iso, scene.medium, AnyPhase::Isotropic).unwrap().in_scatter(),
                };
                // a fog-lit surface: its air-light in isotropic fog
                let air = if scene.air_lit(&hit, l) {
                    let surface = Surface { position: scene.surface_point(d, &hit), normal: hit.normal };
                    let s = SurfaceScene::new(surface, Brdf::Lambert { albedo: 1.0 }, iso, scene.medium, AnyPhase::Isotropic).unwrap();
                    (-scene.medium.sigma_t * hit.t).exp() * s.air_light()
                } else {
                    0.0
                };
                for c in 0..3 {
                    px[c] += l.color[c] * (glow + hit.albedo[c] * air) * 4.0 * std::f64::consts::PI * p_max;
                }
            }
            out.push(px);
        }
    }
    out
}

fn worst_of_scale(kernel: &Image, reference: &Image) -> (f64, f64) {
    let scale = reference.max_value();
    let mut worst: f64 = 0.0;
    let mut diffs = Vec::new();
    for (a, b) in kernel.pixels.iter().zip(&reference.pixels) {
        let d = (0..3).map(|c| (a[c] - b[c]).abs()).fold(0.0, f64::max);
        worst = worst.max(d / scale);
        diffs.push(d / scale);
    }
    diffs.sort_by(f64::total_cmp);
    (worst, diffs[diffs.len() / 2])
}

fn check(scene: SceneDesc) {
    let name = scene.name;
    let cpu = render::render_cpu(&scene, false);
    let reference = render::render_reference(&scene, false);
    assert!(cpu.pixels.iter().flatten().all(|v| v.is_finite() && *v >= 0.0), "{name}: non-finite or negative kernel pixel");
    assert!(reference.pixels.iter().flatten().all(|v| v.is_finite() && *v >= 0.0), "{name}: non-finite or negative reference pixel");
    let (worst, median) = worst_of_scale(&cpu, &reference);
    let rel = render::error_stats(&render::relative_errors(&cpu, &reference, render::error_floor(&scene)));
    println!(
        "{name}: brightest {:.3e}; |kernel − ref| / brightest: max {worst:.2e}, median {median:.2e}; per-pixel relative (floor {:.1e}): max {:.2e}, median {:.2e}",
        reference.max_value(),
        render::error_floor(&scene),
        rel.max,
        rel.median
    );
    assert!(reference.max_value() > 0.0, "{name}: black image");
    // the per-segment premise of the bound: error ≤ EPS_SCALE of the pixel's scale
    let sc = scales(&scene);
    let mut worst_of_pixel_scale: f64 = 0.0;
    for (i, ((a, b), s)) in cpu.pixels.iter().zip(&reference.pixels).zip(&sc).enumerate() {
        for c in 0..3 {
            if s[c] > 0.0 {
                let e = (a[c] - b[c]).abs() / s[c];
                worst_of_pixel_scale = worst_of_pixel_scale.max(e);
                assert!(e <= EPS_SCALE, "{name}: pixel {i} channel {c}: error {e:.3e} of its scale exceeds {EPS_SCALE:.0e}");
            }
        }
    }
    let max_scale = sc.iter().flatten().copied().fold(0.0, f64::max);
    println!(
        "{name}: |kernel − ref| / pixel scale: max {worst_of_pixel_scale:.2e}; largest pixel scale / brightest pixel {:.2}",
        max_scale / reference.max_value()
    );
    assert!(worst <= BOUND, "{name}: error {worst:.3e} of the brightest pixel exceeds {BOUND:.0e}");
}

/// Bound 2: error of the brightest reference value (see the module docs).
const BOUND: f64 = 1e-6;
/// Bound 1: error of the pixel's integrand scale (see the module docs).
const EPS_SCALE: f64 = 1e-6;

#[test]
fn lighthouse() {
    check(render::lighthouse(48, 27));
}

#[test]
fn road() {
    check(render::road(48, 27));
}

#[test]
fn stage() {
    check(render::stage(48, 27));
}

#[test]
fn street() {
    check(render::street(48, 27));
}

#[test]
fn bench() {
    check(render::bench(48, 27));
}

/// The premise that the reference is converged: on every 5th pixel of each scene, the
/// quadrature at `REFERENCE_TOL` and at 1e-11 — of the glow and of a fog-lit surface's
/// air-light — agree to 1e-7 relatively (of the larger value;
/// segments where both are 0 — a spot that the ray never crosses — count as equal).
#[test]
fn reference_is_converged() {
    for name in render::SCENES {
        let scene = render::scene_by_name(name, 48, 27).unwrap();
        let mut worst: f64 = 0.0;
        for i in (0..48 * 27).step_by(5) {
            let (d, hit) = scene.primary(i % 48, i / 48);
            for l in &scene.lights {
                let q = |tol| l.over_emitter(tol, |point| render::reference_in_scatter(scene.camera.position, d, 0.0, hit.t, point, &scene.medium, &scene.phase, tol));
                let (a, b) = (q(render::REFERENCE_TOL), q(1e-11));
                assert!(a.is_finite() && b.is_finite(), "{name}: pixel {i}: non-finite reference");
                if a != b {
                    worst = worst.max((a - b).abs() / a.abs().max(b.abs()));
                }
                if scene.air_lit(&hit, l) {
                    let x = scene.surface_point(d, &hit);
                    let q = |tol| render::reference_air_light(x, hit.normal, &l.light, &scene.medium, &scene.phase, tol);
                    let (a, b) = (q(render::REFERENCE_TOL), q(1e-11));
                    assert!(a.is_finite() && b.is_finite() && a > 0.0, "{name}: pixel {i}: reference air-light {a}, {b}");
                    worst = worst.max((a - b).abs() / a.max(b));
                }
            }
        }
        println!("{name}: reference at {:.0e} vs 1e-11: max relative difference {worst:.2e}", render::REFERENCE_TOL);
        assert!(worst <= 1e-7, "{name}: reference not converged: {worst:.3e}");
    }
}
