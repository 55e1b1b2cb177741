//! Disc and rectangle lights (docs/DESIGN.md §12) against nested quadrature
//! (tests/reference/area.jsonl, tests/reference/gen_area.py; the Lambertian emission and cosine
//! lobes), against their exact limits (an emitter shrinking to a point is the Lambertian, or
//! two-lobed, point light; areas add), and their edges.

use airlight::glam::{DVec3, Vec3};
use airlight::light::Lambertian;
use airlight::phase::{AnyPhase, HenyeyGreenstein};
use airlight::{AreaLight, AreaScene, Emitter, Medium, PointLight, Ray, Scene};
use airlight_codegen::scene_json::{parse_any_value, parse_line_with_id, AnyRecord};
use airlight_tests::reference_lines;
use std::collections::BTreeMap;

fn area<T: airlight::Real>(v: &serde_json::Value) -> AreaScene<T, AnyPhase<T>> {
    match parse_any_value::<T>(v).unwrap_or_else(|e| panic!("reference record invalid: {e}: {v}")) {
        AnyRecord::Area(s) => s,
        _ => panic!("not an area light in area.jsonl: {v}"),
    }
}

/// Targets (docs/DESIGN.md §8): f64 within 1e-9 of the reference, f32 within 1e-4 (the inputs
/// are f32-exact), relative to the value (the integrand is positive), on every record of every
/// class; the references agree between two resolutions to 1e-11.
#[test]
fn area_lights_against_nested_quadrature() {
    let lines = reference_lines("area.jsonl");
    assert!(lines.len() >= 12, "area.jsonl has {} records", lines.len());
    let mut worst: BTreeMap<String, (f64, f64, usize)> = BTreeMap::new();
    let mut failures = vec![];
    for v in &lines {
        let exact = v["in_scatter"].as_f64().unwrap();
        let category = format!("{} {}", v["category"].as_str().unwrap(), v["light"]["shape"].as_str().unwrap());
        let got64 = area::<f64>(v).in_scatter();
        let got32 = area::<f32>(v).in_scatter() as f64;
        let (e64, e32) = ((got64 - exact).abs() / exact, (got32 - exact).abs() / exact);
        let w = worst.entry(category.clone()).or_insert((0.0, 0.0, 0));
        *w = (w.0.max(e64), w.1.max(e32), w.2 + 1);
        if !(e64 <= 1e-9) || !(e32 <= 1e-4) {
            failures.push(format!("{category}: f64 {got64} ({e64:.1e}), f32 {got32} ({e32:.1e}), exact {exact}"));
        }
    }
    for (c, (e64, e32, n)) in &worst {
        println!("{c:>18}: {n} records, largest error f64 {e64:.2e}, f32 {e32:.2e}");
    }
    assert!(failures.is_empty(), "{}", failures.join("\n"));
}

fn ray() -> Ray<f64> {
    Ray { origin: DVec3::new(0.2, -0.1, 0.3), dir: DVec3::new(1.0, 0.15, -0.05), t_min: 0.0, t_max: 30.0 }
}

fn medium() -> Medium<f64> {
    Medium { sigma_s: 0.05, sigma_t: 0.08 }
}

fn phase() -> AnyPhase<f64> {
    AnyPhase::HenyeyGreenstein(HenyeyGreenstein { g: 0.6 })
}

/// A disc of radius `r` is, to `O(r²/d²)`, the point light of intensity `L_e π r²` at its
/// centre with the Lambertian distribution about its normal.
#[test]
fn small_disc_is_the_lambertian_point_light() {
    let (center, normal, radiance) = (DVec3::new(6.0, 2.5, -1.0), DVec3::new(-0.3, -1.0, 0.2), 3.0);
    for r in [1e-2f64, 1e-3] {
        let disc = AreaScene::new(ray(), AreaLight::new(Emitter::Disc { center, normal, radius: r }, radiance), medium(), phase()).unwrap().in_scatter();
        let light = PointLight { position: center, intensity: radiance * std::f64::consts::PI * r * r, distribution: Lambertian { axis: normal } };
        let point = Scene::new(ray(), light, medium(), phase()).unwrap().in_scatter();
        // the distance to the ray is ~2.6: the relative difference is ~(r/2.6)²
        assert!((disc - point).abs() <= 0.2 * r * r * point, "radius {r}: disc {disc} vs point light {point}");
    }
}

/// With a cosine lobe `cᵖ` (p even) a small disc is, to `O(r²/d²)`, the two-lobed point light
/// `cᵖ` of intensity `L_e π r²` at its centre, on a ray segment wholly in front of it (where
/// `max(0, c)ᵖ = cᵖ`: the plane is crossed at t ≈ 10.1, the segment ends at 8); power 1 is the
/// Lambertian emitter, to the last bit.
#[test]
fn small_disc_with_a_cosine_lobe_is_the_two_lobed_point_light() {
    use airlight::light::TwoLobed;
    use airlight::Emission;
    let (center, normal, radiance) = (DVec3::new(6.0, 2.5, -1.0), DVec3::new(-0.3, -1.0, 0.2), 3.0);
    let front = Ray { t_max: 8.0, ..ray() };
    for r in [1e-2f64, 1e-3] {
        let emitter = Emitter::Disc { center, normal, radius: r };
        let disc = AreaScene::new(front, AreaLight { emission: Emission::CosineLobe { power: 8 }, ..AreaLight::new(emitter, radiance) }, medium(), phase()).unwrap().in_scatter();
        let light = PointLight { position: center, intensity: radiance * std::f64::consts::PI * r * r, distribution: TwoLobed { axis: normal, power: 8 } };
        let point = Scene::new(front, light, medium(), phase()).unwrap().in_scatter();
        assert!((disc - point).abs() <= 0.2 * r * r * point, "radius {r}: disc {disc} vs point light {point}");
        let lambertian = AreaScene::new(ray(), AreaLight::new(emitter, radiance), medium(), phase()).unwrap().in_scatter();
        let power_one = AreaScene::new(ray(), AreaLight { emission: Emission::CosineLobe { power: 1 }, ..AreaLight::new(emitter, radiance) }, medium(), phase()).unwrap().in_scatter();
        assert_eq!(power_one, lambertian, "radius {r}");
    }
}

/// A sphere of radius `r` and radiance `L_e` sheds `π r² L_e` in every direction: the isotropic
/// point light of that intensity at its centre, but the half it shows is nearer the ray, on
/// average by `(2/3) r` (`∫ cos² dΩ / ∫ cos dΩ` over a hemisphere), so attenuation gives the
/// first-order excess `(2/3) σt r`; the other first-order terms (the nearer half's larger
/// `1/d²`, the spread of directions) cancel by the sphere's symmetry, leaving `O(r²/d²)`
/// (`d ≥ 2.6` here) and `O((σt r)²)`.
#[test]
fn small_sphere_is_the_isotropic_point_light() {
    let (center, radiance) = (DVec3::new(6.0, 2.5, -1.0), 3.0);
    for r in [1e-2f64, 1e-3] {
        let sphere = AreaScene::new(ray(), AreaLight::new(Emitter::Sphere { center, radius: r }, radiance), medium(), phase()).unwrap().in_scatter();
        let light = PointLight { position: center, intensity: radiance * std::f64::consts::PI * r * r, distribution: airlight::light::Omni };
        let point = Scene::new(ray(), light, medium(), phase()).unwrap().in_scatter();
        let first_order = point * (1.0 + 2.0 / 3.0 * medium().sigma_t * r);
        assert!((sphere - first_order).abs() <= 0.2 * r * r * point, "radius {r}: sphere {sphere} vs point light {point} (to first order {first_order})");
        // and the excess is there: without it the difference is the first-order term itself
        assert!((sphere - point).abs() > 0.5 * (2.0 / 3.0 * medium().sigma_t * r) * point, "radius {r}: no attenuation excess");
    }
}

/// No element of a sphere faces a point inside it: a segment inside sees nothing, and one that
/// starts inside sees what the part after the exit sees, attenuated by the path to the exit
/// (computed about another pole: the exit point is inside the segment in one case, its start in
/// the other).
#[test]
fn sphere_interior_is_dark() {
    let (center, radius) = (DVec3::new(5.0, 0.6, 0.2), 1.5);
    let light = AreaLight::new(Emitter::Sphere { center, radius }, 2.0);
    let dir = DVec3::new(1.0, 0.1, -0.05).normalize();
    let origin = center - dir * 0.4 + DVec3::new(0.0, 0.3, 0.1);
    // the exit: |origin + t dir − center| = radius
    let w = origin - center;
    let (b, c) = (w.dot(dir), w.length_squared() - radius * radius);
    let t_out = -b + (b * b - c).sqrt();
    let scene = |t_min, t_max| AreaScene::new(Ray { origin, dir, t_min, t_max }, light, medium(), phase()).unwrap().in_scatter();
    assert_eq!(scene(0.0, 0.9 * t_out), 0.0, "a segment inside the sphere");
    for t_max in [t_out + 4.0, f64::INFINITY] {
        let (from_inside, from_exit) = (scene(0.0, t_max), scene(t_out, t_max) * (-medium().sigma_t * t_out).exp());
        assert!(from_exit > 0.0);
        assert!((from_inside - from_exit).abs() <= 1e-9 * from_exit, "t_max {t_max}: from inside {from_inside} vs from the exit {from_exit}");
    }
}

/// A rectangle is the sum of its two halves (cut across `edge_u`), here pierced by the ray: each
/// half has its own focus and triangles.
#[test]
fn rectangle_halves_add_up() {
    let (corner, eu, ev) = (DVec3::new(8.0, -1.0, -1.0), DVec3::new(0.3, 2.0, 0.1), DVec3::new(0.2, -0.1, 2.0));
    let scene = |corner, edge_u| {
        AreaScene::new(ray(), AreaLight::new(Emitter::Rectangle { corner, edge_u, edge_v: ev }, 2.0), medium(), phase()).unwrap().in_scatter()
    };
    let whole = scene(corner, eu);
    let halves = scene(corner, eu * 0.5) + scene(corner + eu * 0.5, eu * 0.5);
    assert!((whole - halves).abs() <= 1e-9 * whole, "whole {whole} vs halves {halves}");
}

/// An emitter whose plane the ray never meets, turned away from it, lights nothing; zero
/// radiance or no scattering give 0.
#[test]
fn edges() {
    // the ray stays at y ≤ 4.5 (from y = −0.1 with slope 0.15 over 30 units); the disc at y = 6
    // faces +y
    let away = Emitter::Disc { center: DVec3::new(5.0, 6.0, 0.0), normal: DVec3::Y, radius: 1.0 };
    assert_eq!(AreaScene::new(ray(), AreaLight::new(away, 1.0), medium(), phase()).unwrap().in_scatter(), 0.0);
    let facing = Emitter::Disc { center: DVec3::new(5.0, 6.0, 0.0), normal: DVec3::NEG_Y, radius: 1.0 };
    assert!(AreaScene::new(ray(), AreaLight::new(facing, 1.0), medium(), phase()).unwrap().in_scatter() > 0.0);
    assert_eq!(AreaScene::new(ray(), AreaLight::new(facing, 0.0), medium(), phase()).unwrap().in_scatter(), 0.0);
    let clear = Medium { sigma_s: 0.0, sigma_t: 0.1 };
    assert_eq!(AreaScene::new(ray(), AreaLight::new(facing, 1.0), clear, phase()).unwrap().in_scatter(), 0.0);
}

/// An area light's record errors name the field.
#[test]
fn area_record_errors() {
    let base = r#"{"ray": {"origin": [0,0,0], "dir": [1,0,0]}, "medium": {"sigma_s": 0.1, "sigma_t": 0.1}, "light": LIGHT}"#;
    for (light, field) in [
        (r#"{"shape": "disc", "center": [1,1,0], "normal": [0,-1,0], "radius": -1, "radiance": 1}"#, "light.radius"),
        (r#"{"shape": "disc", "center": [1,1,0], "normal": [0,0,0], "radius": 1, "radiance": 1}"#, "light.normal"),
        (r#"{"shape": "rectangle", "corner": [1,1,0], "edge_u": [1,0,0], "edge_v": [2,0,0], "radiance": 1}"#, "light.edge_v"),
        (r#"{"shape": "rectangle", "corner": [1,1,0], "edge_u": [1,0,0], "edge_v": [0,0,1], "radiance": -2}"#, "light.radiance"),
        (r#"{"shape": "disc", "center": [1,1,0], "normal": [0,1,0], "radius": 1, "radiance": 1, "intensity": 3}"#, "light.intensity"),
        (r#"{"shape": "sphere", "center": [1,1,0], "radius": -1, "radiance": 1}"#, "light.radius"),
        (r#"{"shape": "sphere", "center": [1,1,0], "normal": [0,1,0], "radius": 1, "radiance": 1}"#, "light.normal"),
        (r#"{"shape": "sphere", "center": [1,1,0], "radius": 1, "radiance": -1}"#, "light.radiance"),
        (r#"{"shape": "cylinder", "center": [1,1,0], "radius": 1, "radiance": 1}"#, "light.shape"),
        (r#"{"shape": "sphere", "center": [1,1,0], "radius": 1, "radiance": 1, "emission": {"kind": "cosine_lobe", "power": 0}}"#, "light.emission.power"),
        (r#"{"shape": "disc", "center": [1,1,0], "normal": [0,1,0], "radius": 1, "radiance": 1, "emission": {"kind": "cosine_lobe", "power": 2.5}}"#, "light.emission.power"),
        (r#"{"shape": "disc", "center": [1,1,0], "normal": [0,1,0], "radius": 1, "radiance": 1, "emission": {"kind": "cosine_lobe", "power": 1025}}"#, "light.emission.power"),
        (r#"{"shape": "disc", "center": [1,1,0], "normal": [0,1,0], "radius": 1, "radiance": 1, "emission": {"kind": "cone"}}"#, "light.emission"),
        (r#"{"shape": "disc", "center": [1,1,0], "normal": [0,1,0], "radius": 1, "radiance": 1, "emission": {"kind": "lambertian", "power": 2}}"#, "light.emission.power"),
    ] {
        let (_, r) = parse_line_with_id::<f64>(&base.replace("LIGHT", light));
        let e = r.err().unwrap_or_else(|| panic!("{light} accepted"));
        assert_eq!(e.field, field, "{light}: {e}");
    }
}

/// The bounded method (`airlight::area::outer`: the ray outside, the emitter's solid angle
/// inside, fixed rules there) against the same references: within the f32 target, 1e-4 of the
/// value, in both precisions, on every record (docs/DESIGN.md §12 has the figures by rule size,
/// `scripts/area_ray_outer.py`).
#[test]
fn bounded_area_lights_against_nested_quadrature() {
    let mut worst: BTreeMap<String, (f64, f64, usize)> = BTreeMap::new();
    let mut failures = vec![];
    for v in &reference_lines("area.jsonl") {
        let exact = v["in_scatter"].as_f64().unwrap();
        let category = format!("{} {}", v["category"].as_str().unwrap(), v["light"]["shape"].as_str().unwrap());
        let (got64, p64) = area::<f64>(v).in_scatter_bounded_counted(1e-3, airlight::area::outer::BOUNDED_RAY_PANELS);
        let got32 = area::<f32>(v).in_scatter_bounded() as f64;
        let (e64, e32) = ((got64 - exact).abs() / exact, (got32 - exact).abs() / exact);
        let w = worst.entry(category.clone()).or_insert((0.0, 0.0, 0));
        *w = (w.0.max(e64), w.1.max(e32), w.2.max(p64));
        if !(e64 <= 1e-4) || !(e32 <= 1e-4) {
            failures.push(format!("{category}: f64 {got64} ({e64:.1e}), f32 {got32} ({e32:.1e}), exact {exact}"));
        }
    }
    for (c, (e64, e32, p)) in &worst {
        println!("{c:>18}: largest error f64 {e64:.2e}, f32 {e32:.2e}, ray panels at most {p}");
    }
    assert!(failures.is_empty(), "{}", failures.join("\n"));
}

/// The bounded method's exact limits: a small disc is the Lambertian point light of intensity
/// `L_e π r²` and a small sphere the isotropic one of `π R² L_e`, to first order `(1 + (2/3)σt R)`
/// times it (as the nested construction, above), each within the method's target 1e-4 on top of
/// the limit's `O(r²/d²)`; a segment inside a sphere sees nothing.
#[test]
fn bounded_limits() {
    let (center, normal, radiance) = (DVec3::new(6.0, 2.5, -1.0), DVec3::new(-0.3, -1.0, 0.2), 3.0);
    let pi = std::f64::consts::PI;
    for r in [1e-2f64, 1e-3] {
        let disc = AreaScene::new(ray(), AreaLight::new(Emitter::Disc { center, normal, radius: r }, radiance), medium(), phase()).unwrap().in_scatter_bounded();
        let light = PointLight { position: center, intensity: radiance * pi * r * r, distribution: Lambertian { axis: normal } };
        let point = Scene::new(ray(), light, medium(), phase()).unwrap().in_scatter();
        assert!((disc - point).abs() <= (1e-4 + 0.2 * r * r) * point, "radius {r}: disc {disc} vs point light {point}");
        let sphere = AreaScene::new(ray(), AreaLight::new(Emitter::Sphere { center, radius: r }, radiance), medium(), phase()).unwrap().in_scatter_bounded();
        let light = PointLight { position: center, intensity: radiance * pi * r * r, distribution: airlight::light::Omni };
        let first_order = Scene::new(ray(), light, medium(), phase()).unwrap().in_scatter() * (1.0 + 2.0 / 3.0 * medium().sigma_t * r);
        assert!((sphere - first_order).abs() <= (1e-4 + 0.2 * r * r) * first_order, "radius {r}: sphere {sphere} vs point light {first_order}");
    }
    let (center, radius) = (DVec3::new(5.0, 0.6, 0.2), 1.5);
    let dir = DVec3::new(1.0, 0.1, -0.05).normalize();
    let inside = Ray { origin: center - dir * 0.4, dir, t_min: 0.0, t_max: 0.8 };
    let scene = AreaScene::new(inside, AreaLight::new(Emitter::Sphere { center, radius }, 2.0), medium(), phase()).unwrap();
    assert_eq!(scene.in_scatter_bounded(), 0.0, "a segment inside the sphere");
}

/// A ray through a rectangle at a point its focus lands on exactly (the nested construction's
/// nodes then lie on the ray within rounding, where the point light is `+∞`): a finite value,
/// which is the mean of the two rays `δ = 1e-6` to either side of it (the glow is smooth in the
/// ray's direction: the first-order change cancels in the mean, the second is `O(δ²)`), to three
/// times the f64 target 1e-9 (each of the three values within it).
#[test]
fn a_ray_through_the_focus_is_finite() {
    let emitter = Emitter::Rectangle { corner: DVec3::new(6.0, 1.0, -1.0), edge_u: DVec3::new(0.0, 1.2, 0.1), edge_v: DVec3::new(0.1, 0.0, 1.0) };
    let value = |dir: DVec3| {
        let ray = Ray { origin: DVec3::ZERO, dir, t_min: 0.0, t_max: f64::INFINITY };
        AreaScene::new(ray, AreaLight::new(emitter, 2.0), Medium { sigma_s: 0.05, sigma_t: 0.08 }, phase()).unwrap().in_scatter()
    };
    let through = value(DVec3::new(6.0, 1.5, -0.5));
    let delta = DVec3::new(0.0, 1e-6, 0.0);
    let mean = 0.5 * (value(DVec3::new(6.0, 1.5, -0.5) + delta) + value(DVec3::new(6.0, 1.5, -0.5) - delta));
    assert!(through.is_finite() && (through - mean).abs() <= 3e-9 * mean, "through the focus {through}, beside it {mean}");
}

/// The bounded method on a sphere in forward-scattering fog, on rays that look at its centre, at
/// its limb and just past it, where the phase lobe (as narrow as `1 − g`) falls on or next to the
/// sphere's cap and the method takes the cap about the lobe's direction: within the f32 target
/// 1e-4 of the nested construction at tolerance 1e-9 (itself within 1e-9 of the mpmath
/// references of `area.jsonl`; a numpy quadrature about the lobe, `scripts/area_lobe_study.py`,
/// agrees with it on these rays).
#[test]
fn bounded_sphere_in_forward_fog() {
    use airlight::phase::HenyeyGreenstein as Hg;
    let (center, radius) = (DVec3::new(6.0, 1.5, -0.5), 0.8);
    let medium = Medium { sigma_s: 0.05, sigma_t: 0.08 };
    for towards in [center, DVec3::new(6.0, 2.25, -0.3), DVec3::new(6.0, 2.4, -0.5)] {
        for g in [0.9, 0.95, 0.99] {
            let ray = Ray { origin: DVec3::ZERO, dir: towards, t_min: 0.0, t_max: f64::INFINITY };
            let scene = AreaScene::new(ray, AreaLight::new(Emitter::Sphere { center, radius }, 2.0), medium, AnyPhase::HenyeyGreenstein(Hg { g })).unwrap();
            let (bounded, nested) = (scene.in_scatter_bounded(), scene.in_scatter_counted(1e-9).0);
            assert!((bounded - nested).abs() <= 1e-4 * nested, "towards {towards}, g {g}: bounded {bounded} vs nested {nested}");
        }
    }
}

/// The bounded method in f64 and in f32 (f32-rounded inputs) and the nested construction at
/// `tolerance` in f64, on the ray from the origin towards `dir` and `emitter` (radiance 2) in
/// Henyey–Greenstein fog `g` (σs 0.05, σt 0.08): (bounded, f32 bounded, nested).
fn bounded_in_both_precisions(dir: DVec3, emitter: Emitter<f64>, g: f64, tolerance: f64) -> (f64, f64, f64) {
    bounded_in_both_precisions_to(dir, f64::INFINITY, emitter, g, tolerance)
}

/// [`bounded_in_both_precisions`] on the segment `t ∈ [0, t_max]` of the ray.
fn bounded_in_both_precisions_to(dir: DVec3, t_max: f64, emitter: Emitter<f64>, g: f64, tolerance: f64) -> (f64, f64, f64) {
    bounded_in_both_precisions_over(dir, (0.0, t_max), emitter, g, tolerance)
}

/// [`bounded_in_both_precisions_to`] on the part of the ray from `t_min` to `t_max`.
fn bounded_in_both_precisions_over(dir: DVec3, range: (f64, f64), emitter: Emitter<f64>, g: f64, tolerance: f64) -> (f64, f64, f64) {
    let (scene, single) = scenes_in_both_precisions(dir, range, emitter, g);
    (scene.in_scatter_bounded(), single.in_scatter_bounded() as f64, scene.in_scatter_counted(tolerance).0)
}

/// The scene of the ray from the origin along `dir` over `[t_min, t_max]` to `emitter` (radiance
/// 2) in Henyey–Greenstein fog of `g` (`σs` 0.05, `σt` 0.08), in f64 and rounded to f32.
fn scenes_in_both_precisions(dir: DVec3, (t_min, t_max): (f64, f64), emitter: Emitter<f64>, g: f64) -> (AreaScene<f64, AnyPhase<f64>>, AreaScene<f32, AnyPhase<f32>>) {
    let medium = Medium { sigma_s: 0.05, sigma_t: 0.08 };
    let ray = Ray { origin: DVec3::ZERO, dir, t_min, t_max };
    let scene = AreaScene::new(ray, AreaLight::new(emitter, 2.0), medium, AnyPhase::HenyeyGreenstein(HenyeyGreenstein { g })).unwrap();
    let single = AreaScene::<f32, _>::new(
        Ray { origin: Vec3::ZERO, dir: dir.as_vec3(), t_min: t_min as f32, t_max: t_max as f32 },
        AreaLight::new(airlight::record::cast_emitter::<f64, f32>(&emitter), 2.0),
        Medium { sigma_s: 0.05, sigma_t: 0.08 },
        AnyPhase::HenyeyGreenstein(HenyeyGreenstein { g: g as f32 }),
    )
    .unwrap();
    (scene, single)
}

/// A sphere of radius 0.625 at (6, 1.5, −0.5) and the part behind it of a ray from the origin
/// that misses it by `miss` of its radius, from the closest approach to its centre on: the
/// emitter, the ray's direction and its range, exact in f32 (the miss, 6e-6 at 1e-5, is then the
/// same ray's in both precisions).
fn behind_a_grazing_ray(miss: f64) -> (Emitter<f64>, DVec3, (f64, f64)) {
    let (center, radius) = (DVec3::new(6.0, 1.5, -0.5), 0.625);
    let (towards, side) = (center.normalize(), center.normalize().cross(DVec3::Z).normalize());
    let angle = (radius * (1.0 + miss) / center.length()).asin();
    let dir = (towards * angle.cos() + side * angle.sin()).as_vec3().as_dvec3();
    let closest = dir.dot(center) / dir.length_squared();
    (Emitter::Sphere { center, radius }, dir, (closest as f32 as f64, f64::INFINITY))
}

/// The bounded method on a disc and a rectangle in forward-scattering fog, on rays that look at
/// their centre, towards their limb and just past it, where the phase lobe's direction meets the
/// emitter's plane on it or next to it and the method takes the emitter in polar coordinates about
/// that direction (`airlight::area::outer`): within the f32 target 1e-4 of the nested construction
/// at tolerance 1e-9, in f64 and in f32 (about the foot, at `g = 0.99` 2.2e-2 and 9.5e-2 off
/// looking at them).
#[test]
fn bounded_flat_emitters_in_forward_fog() {
    let emitters = [
        Emitter::Disc { center: DVec3::new(6.0, 1.5, -0.5), normal: DVec3::new(-1.0, -0.4, 0.1), radius: 0.8 },
        Emitter::Rectangle { corner: DVec3::new(6.0, 1.0, -1.0), edge_u: DVec3::new(0.1, 0.0, 1.0), edge_v: DVec3::new(0.0, 1.2, 0.1) },
    ];
    for emitter in emitters {
        for towards in [DVec3::new(6.0, 1.5, -0.5), DVec3::new(6.0, 2.25, -0.3), DVec3::new(6.0, 2.4, -0.5)] {
            for g in [0.95, 0.99] {
                let (bounded, single, nested) = bounded_in_both_precisions(towards, emitter, g, 1e-9);
                assert!((bounded - nested).abs() <= 1e-4 * nested && (single - nested).abs() <= 1e-4 * nested, "{emitter:?} towards {towards}, g {g}: bounded {bounded} (f32 {single}) vs nested {nested}");
            }
        }
    }
}

/// The bounded method on a rectangle in `g = 0.95` and `0.99` fog, on rays that cross its plane
/// 0.00001 to 0.01 inside and 0.00001 to 0.002 outside the middles of two edges, two corners
/// (along the diagonal and along an edge, where inside is on the edge) and two points of edges
/// 0.001 from a corner: the phase lobe's point `q_L` next to an edge. Inside, a wedge of chords
/// ending on the edge is taken in the angle `β` it subtends (in the azimuth, 2.4e-3 off); outside,
/// one starting on it in its Mercator angle (in the azimuth 1.2e-3 off), but for the half nearer
/// a near edge they end on, in that edge's `β` (Mercator alone 1.3e-4); on an edge, the emitter
/// is taken as holding `q_L` also where rounding puts it outside (9.7e-4 off without); the ray
/// has a panel ending where the lobe's footprint reaches past the nearest edge and the next
/// (`CROSSING_REACH`; without, crossings 1e-4 from an edge were 1.5e-4 off);
/// `airlight::area::outer`. Within the f32 target 1e-4 of the nested construction at tolerance
/// 1e-10, in f64 and in f32.
#[test]
fn bounded_rectangle_with_the_lobe_next_to_an_edge() {
    let (corner, eu, ev) = (DVec3::new(6.0, 1.0, -1.0), DVec3::new(0.1, 0.0, 1.0), DVec3::new(0.0, 1.2, 0.1));
    let rect = Emitter::Rectangle { corner, edge_u: eu, edge_v: ev };
    let crossings = [(0.5, 0.0, ev), (1.0, 0.5, -eu), (0.0, 0.0, eu + ev), (1.0, 1.0, -(eu + ev)), (0.0, 0.0, eu), (1.0, 1.0, -ev), (0.001, 0.0, ev), (1.0, 0.999, -eu)];
    for g in [0.95, 0.99] {
        for (u, v, inward) in crossings {
            for offset in [-0.002, -0.0005, -0.0001, -0.00001, 0.00001, 0.0001, 0.0005, 0.002, 0.01] {
                let dir = corner + eu * u + ev * v + inward.normalize() * offset;
                let (bounded, single, nested) = bounded_in_both_precisions(dir, rect, g, 1e-10);
                assert!((bounded - nested).abs() <= 1e-4 * nested && (single - nested).abs() <= 1e-4 * nested, "({u}, {v}) + {offset} inward, g {g}: bounded {bounded} (f32 {single}) vs nested {nested}");
            }
        }
    }
}

/// The bounded method on a disc in `g = 0.95` and `0.99` fog, on rays that cross its plane on,
/// 0.00001 to 0.01 inside and 0.00001 to 0.002 outside two points of its rim: the phase lobe's point
/// `q_L` next to the rim. Inside, the half of the chords towards the rim's nearest point is taken
/// in the angle `β` of its tangent there (over the whole circle in the azimuth, 3.0e-3 off; on
/// the rim, that half must be the one outside: f32 gave 0 when it followed the rounding);
/// `airlight::area::outer`. Within the f32 target 1e-4 of the nested construction at tolerance
/// 1e-10, in f64 and in f32 (within 6.0e-6 and 1.4e-5, the rim itself and 0.0005 inside at `g =
/// 0.99`).
#[test]
fn bounded_disc_with_the_lobe_next_to_its_rim() {
    let (corner, eu, ev) = (DVec3::new(6.0, 1.0, -1.0), DVec3::new(0.1, 0.0, 1.0), DVec3::new(0.0, 1.2, 0.1));
    let (center, normal, radius) = (corner + 0.5 * (eu + ev), eu.cross(ev).normalize(), 0.6);
    let disc = Emitter::Disc { center, normal, radius };
    let (across, along) = (eu.normalize(), normal.cross(eu.normalize()));
    for g in [0.95, 0.99] {
        for offset in [-0.002, -0.0005, -0.0001, -0.00001, 0.0, 0.00001, 0.0001, 0.0005, 0.002, 0.01] {
            for dir in [center + across * (radius - offset), center + (across * 0.6 + along * 0.8) * (radius - offset)] {
                let (bounded, single, nested) = bounded_in_both_precisions(dir, disc, g, 1e-10);
                assert!((bounded - nested).abs() <= 1e-4 * nested && (single - nested).abs() <= 1e-4 * nested, "{dir} ({offset} inside), g {g}: bounded {bounded} (f32 {single}) vs nested {nested}");
            }
        }
    }
}

/// The bounded method on a sphere in `g = 0.9`, `0.95` and `0.99` fog, on rays that enter it
/// 0.001, 0.0001 and 0.00001 of its radius inside its limb, up to the middle of their chord (the
/// part in front of it) and whole: in front the phase lobe's direction is inside the cap next to
/// its rim, taken in the angle `β` of the rim's tangent towards the rim (over the whole circle in
/// `ψ`, 8.7e-3 off at `g = 0.95`); behind, beside the sphere, just outside the rim with the
/// opposite direction inside the cap, taken about the lobe too, the half towards the rim in its
/// Mercator angle (about the centre, the whole ray 1.9e-4 off); `sphere_about_lobe`. Within the
/// f32 target 1e-4 of the nested construction at tolerance 1e-10, in f64 and in f32.
#[test]
fn bounded_sphere_with_the_lobe_next_to_its_limb() {
    let (center, radius) = (DVec3::new(6.0, 1.5, -0.5), 0.6);
    let sphere = Emitter::Sphere { center, radius };
    let (towards, side) = (center.normalize(), center.normalize().cross(DVec3::Z).normalize());
    for g in [0.9, 0.95, 0.99] {
        for depth in [0.001, 0.0001, 0.00001] {
            // the ray's closest approach to the centre at radius − depth·radius
            let angle = (radius * (1.0 - depth) / center.length()).asin();
            let dir = towards * angle.cos() + side * angle.sin();
            for t_max in [dir.dot(center), f64::INFINITY] {
                let (bounded, single, nested) = bounded_in_both_precisions_to(dir, t_max, sphere, g, 1e-10);
                assert!((bounded - nested).abs() <= 1e-4 * nested && (single - nested).abs() <= 1e-4 * nested, "depth {depth}, g {g}, to {t_max}: bounded {bounded} (f32 {single}) vs nested {nested}");
            }
        }
    }
}

/// The bounded method on the part of a ray behind a sphere it misses by 0.00001, 0.0001 and
/// 0.001 of its radius (from the closest approach to the centre on), in `g = 0.95` and `0.99`
/// fog: the lobe's direction just outside a cap nearly a hemisphere wide, taken about the lobe
/// with `θ` cut at `LOBE_TAIL` (in one rule 6.0e-4 off at `g = 0.99`), and where it is farther
/// than its reach within the cap's own radius of the rim (the cap rule 3.0e-4 off there):
/// within the f32 target 1e-4 of the nested construction at tolerance 1e-10, in f64 and in f32
/// (whose `|c − x|` rounded holds a miss of 6e-6 only to 1 %, 2.5e-4 off at `g = 0.99`: the gap
/// `|c − x| − R` is formed from the line's miss by exact products, docs/DESIGN.md §12).
#[test]
fn bounded_sphere_behind_a_grazing_ray() {
    for g in [0.95, 0.99] {
        for miss in [0.00001, 0.0001, 0.001] {
            let (sphere, dir, range) = behind_a_grazing_ray(miss);
            let (bounded, single, nested) = bounded_in_both_precisions_over(dir, range, sphere, g, 1e-10);
            assert!((bounded - nested).abs() <= 1e-4 * nested && (single - nested).abs() <= 1e-4 * nested, "miss {miss}, g {g}: bounded {bounded} (f32 {single}) vs nested {nested}");
        }
    }
}

/// The default path (the nested construction) in f32 on the part of a ray behind a sphere it
/// misses by 0.00001, 0.0001 and 0.001 of its radius, in `g = 0.99` fog: within the f32 target
/// 1e-4 of the f64 nested construction at tolerance 1e-10, its elements' canonical forms taken
/// from the sphere's miss (from their positions `c + R n` rounded to f32, 2.2e-4 off at 1e-5;
/// docs/DESIGN.md §12).
#[test]
fn default_sphere_behind_a_grazing_ray_in_f32() {
    for miss in [0.00001, 0.0001, 0.001] {
        let (sphere, dir, range) = behind_a_grazing_ray(miss);
        let (double, single) = scenes_in_both_precisions(dir, range, sphere, 0.99);
        let (got, exact) = (single.in_scatter() as f64, double.in_scatter_counted(1e-10).0);
        assert!((got - exact).abs() <= 1e-4 * exact, "miss {miss}: f32 default {got} vs nested {exact}");
    }
}

/// The bounded method on a sphere whose elements emit the cosine lobe `c¹⁰²³` (`p = 1024`, 0.03
/// wide about each element's normal, seen from `x` at the cap's centre, where the `φ` rule is
/// graded towards it): within the f32 target 1e-4 of the nested construction at tolerance 1e-9
/// on rays at the centre, the limb, beside and away (without the grading 2.9e-2 off).
#[test]
fn bounded_sphere_with_a_narrow_emission_lobe() {
    let (center, radius) = (DVec3::new(6.0, 1.5, -0.5), 0.8);
    let light = AreaLight { emission: airlight::Emission::CosineLobe { power: 1024 }, ..AreaLight::new(Emitter::Sphere { center, radius }, 2.0) };
    for towards in [center, DVec3::new(6.0, 2.25, -0.3), DVec3::new(1.0, 0.0, 0.3), DVec3::new(-1.0, 0.2, 0.1)] {
        let ray = Ray { origin: DVec3::ZERO, dir: towards, t_min: 0.0, t_max: f64::INFINITY };
        let scene = AreaScene::new(ray, light, Medium { sigma_s: 0.05, sigma_t: 0.08 }, AnyPhase::Isotropic).unwrap();
        let (bounded, nested) = (scene.in_scatter_bounded(), scene.in_scatter_counted(1e-9).0);
        assert!((bounded - nested).abs() <= 1e-4 * nested, "towards {towards}: bounded {bounded} vs nested {nested}");
    }
}

/// The bounded method on a disc and a rectangle whose elements emit the cosine lobe `c¹⁰²³`
/// (`p = 1024`, 0.06 wide about each element's normal: on the plane a spot `z/16` wide about the
/// foot), where the radial rule is graded towards the foot and a foot nearer the edge than
/// `EDGE_REACH` heights is taken about the edge's nearest point: within the f32 target 1e-4 of the
/// nested construction at tolerance 1e-9 on rays at the centre, the limb, past it, beside and
/// away (before: 3.8e-4 and 7.0e-4 looking at them).
#[test]
fn bounded_flat_emitters_with_a_narrow_emission_lobe() {
    let emitters = [
        Emitter::Disc { center: DVec3::new(6.0, 1.5, -0.5), normal: DVec3::new(-1.0, -0.4, 0.1), radius: 0.8 },
        Emitter::Rectangle { corner: DVec3::new(6.0, 1.0, -1.0), edge_u: DVec3::new(0.1, 0.0, 1.0), edge_v: DVec3::new(0.0, 1.2, 0.1) },
    ];
    for emitter in emitters {
        let light = AreaLight { emission: airlight::Emission::CosineLobe { power: 1024 }, ..AreaLight::new(emitter, 2.0) };
        for towards in [DVec3::new(6.0, 1.5, -0.5), DVec3::new(6.0, 2.25, -0.3), DVec3::new(6.0, 2.4, -0.5), DVec3::new(1.0, 0.0, 0.3), DVec3::new(-1.0, 0.2, 0.1)] {
            let ray = Ray { origin: DVec3::ZERO, dir: towards, t_min: 0.0, t_max: f64::INFINITY };
            let scene = AreaScene::new(ray, light, Medium { sigma_s: 0.05, sigma_t: 0.08 }, AnyPhase::Isotropic).unwrap();
            let (bounded, nested) = (scene.in_scatter_bounded(), scene.in_scatter_counted(1e-9).0);
            assert!((bounded - nested).abs() <= 1e-4 * nested, "{emitter:?} towards {towards}: bounded {bounded} vs nested {nested}");
        }
    }
}
