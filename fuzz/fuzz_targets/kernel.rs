//! Target (1): the kernel on arbitrary inputs, f32 and f64, checked and unchecked API, the
//! default error-controlled path, both expansions at 4 and 6 terms, lit sub-segments, a segment
//! light along the light's axis, a disc and a sphere light and fog-lit surface points (f64; in isotropic and the input's fog, lit by an omni light, the input's or a beam). Oracle: no panic; never NaN; never negative;
//! `+∞` only where documented — the light on the segment (`h = 0`, `t_min ≤ x_h ≤ t_max`;
//! here `h` is recomputed in f64 from the same inputs, so "0" means within 8 ulps of
//! `|p − o|` in the evaluation precision), or a true value beyond the float range, which is
//! excluded when the bound `σs·I·P_max·π/h` (since `∫ dt/r² ≤ π/h` and `D ≤ 1`) is finite and
//! below `1e-20·max`: within 20 decades of the range's end, intermediate products (the
//! prefactor times expansion coefficients that grow like `r^{−k}` on a needle-thin cone edge)
//! may overflow before the result would, which is documented rather than hidden.
#![no_main]
use airlight::glam::{DVec3, Vec3};
use airlight::{in_scatter_unchecked, AreaLight, AreaScene, Brdf, Emission, Emitter, Expansion, Scene, SegmentLight, SegmentScene, Surface, SurfaceScene};
use libfuzzer_sys::fuzz_target;

#[macro_use]
mod common;
use common::{h_and_xh, p_max, Raw};

/// `eps`: the evaluation precision's epsilon; a light within a few ulps of `|p − o|` of the
/// line counts as on it (its computed distance is rounding noise, possibly exactly 0), and so
/// does one whose distance, computed by the kernel's own reduction
/// (`airlight::geometry::Canonical`) in the evaluation precision, is 0 — the documented
/// condition (subnormal distances can round to 0 there).
fn check(raw: &Raw, x: f64, max: f64, label: &str) {
    let eps = if max < 1e39 { f32::EPSILON as f64 } else { f64::EPSILON };
    assert!(!x.is_nan(), "{label}: NaN for {raw:?}");
    assert!(x >= 0.0, "{label}: negative {x} for {raw:?}");
    if x.is_infinite() {
        let (h, xh) = h_and_xh(raw);
        let dist = ((raw.p[0] - raw.o[0]).powi(2) + (raw.p[1] - raw.o[1]).powi(2) + (raw.p[2] - raw.o[2]).powi(2)).sqrt();
        let mut on_segment = h <= 8.0 * eps * dist && raw.t0 <= xh + 8.0 * eps * dist && xh <= raw.t1 + 8.0 * eps * dist;
        if max < 1e39 {
            let f = |a: [f64; 3]| a.map(|x| x as f32);
            let c = airlight::geometry::Canonical::new(f(raw.o), f(raw.d), raw.t0 as f32, raw.t1 as f32, f(raw.p), [0.0, 0.0, 1.0]);
            on_segment |= c.h == 0.0 && c.t0 <= c.x_h && c.x_h <= c.t1;
        } else {
            let c = airlight::geometry::Canonical::new(raw.o, raw.d, raw.t0, raw.t1, raw.p, [0.0, 0.0, 1.0]);
            on_segment |= c.h == 0.0 && c.t0 <= c.x_h && c.x_h <= c.t1;
        }
        let bound = raw.ss * raw.i * p_max(raw) * std::f64::consts::PI / h;
        assert!(on_segment || !(bound.is_finite() && bound < max * 1e-20), "{label}: +inf outside the documented cases (bound {bound:e}) for {raw:?}");
    }
}

fuzz_target!(|raw: Raw| {
    // f64, checked
    let (r, l, m, p) = scene_types!(f64, DVec3)(&raw);
    if let Ok(s) = Scene::new(r, l, m, p) {
        check(&raw, s.in_scatter(), f64::MAX, "f64/default");
        for e in [Expansion::Chebyshev, Expansion::Taylor] {
            check(&raw, s.in_scatter_with::<4>(e), f64::MAX, "f64/4");
            check(&raw, s.in_scatter_with::<6>(e), f64::MAX, "f64/6");
        }
        let mid = if raw.t1.is_finite() { 0.5 * (raw.t0 + raw.t1) } else { raw.t0 + 1.0 };
        check(&raw, s.in_scatter_lit_with::<6>(&[(raw.t0, mid), (mid, raw.t1)], Expansion::Chebyshev), f64::MAX, "f64/lit");
        check(&raw, s.in_scatter_lit(&[(raw.t0, mid), (mid, raw.t1)]), f64::MAX, "f64/lit default");
    }
    check(&raw, in_scatter_unchecked::<f64, _, _, 6>(r, l, m, p, Expansion::Chebyshev), f64::MAX, "f64/unchecked");
    // f32 on the same inputs rounded to f32 (the oracle judges the rounded scene)
    let raw32 = Raw {
        o: raw.o.map(|x| x as f32 as f64),
        d: raw.d.map(|x| x as f32 as f64),
        t0: raw.t0 as f32 as f64,
        t1: raw.t1 as f32 as f64,
        p: raw.p.map(|x| x as f32 as f64),
        i: raw.i as f32 as f64,
        ss: raw.ss as f32 as f64,
        ..raw
    };
    let (r, l, m, p) = scene_types!(f32, Vec3)(&raw);
    if let Ok(s) = Scene::new(r, l, m, p) {
        check(&raw32, s.in_scatter() as f64, f32::MAX as f64, "f32/default");
        for e in [Expansion::Chebyshev, Expansion::Taylor] {
            check(&raw32, s.in_scatter_with::<4>(e) as f64, f32::MAX as f64, "f32/4");
            check(&raw32, s.in_scatter_with::<6>(e) as f64, f32::MAX as f64, "f32/6");
        }
    }
    check(&raw32, in_scatter_unchecked::<f32, _, _, 4>(r, l, m, p, Expansion::Chebyshev) as f64, f32::MAX as f64, "f32/unchecked");
    // a segment light from the light's position along its axis (length 10·w), on one input in
    // 8 (it costs 15 point lights or more): never NaN, never negative (+∞ where the emitter
    // meets the segment)
    let (r, l, m, p) = scene_types!(f64, DVec3)(&raw);
    if raw.power % 8 == 0 {
        let b = DVec3::from_array(raw.p) + DVec3::from_array(raw.axis) * (10.0 * raw.w);
        let segment = SegmentLight { a: l.position, b, intensity: l.intensity, distribution: l.distribution };
        if let Ok(s) = SegmentScene::new(r, segment, m, p) {
            let x = s.in_scatter();
            assert!(!x.is_nan() && x >= 0.0, "f64/segment: {x} for {raw:?}");
        }
    }
    // on one input in 4, the ray's origin as a Lambertian surface facing along the ray, lit by
    // an omni light in isotropic fog thinned to `σt·d < 1` over the light's distance `d`, at
    // tolerance 1e-1 (6–30 rays): where the point reads its rays from an interpolant
    // (docs/DESIGN.md §11); never NaN, never negative
    if raw.power % 4 == 1 {
        let d = (DVec3::from_array(raw.p) - r.origin).length();
        let thin = m.sigma_t * d + 1.0;
        let thin = airlight::Medium { sigma_s: m.sigma_s / thin, sigma_t: m.sigma_t / thin };
        let omni = airlight::PointLight { distribution: airlight::light::AnyDistribution::Omni, ..l };
        let surface = Surface { position: r.origin, normal: r.dir };
        if let Ok(s) = SurfaceScene::new(surface, Brdf::Lambert { albedo: 1.0 }, omni, thin, airlight::phase::AnyPhase::Isotropic) {
            let x = s.air_light_counted(1e-1).0;
            assert!(!x.is_nan() && x >= 0.0, "f64/thin surface at 1e-1: {x} for {raw:?}");
        }
    }
    // on one input in 8 more, that surface, Lambertian and Phong, lit by the light made omni in
    // the input's fog and phase function, at tolerance 1e-1: where a narrow lobe cuts the outer
    // integral (`airlight::surface::PHASE_LOBE_GAP`) and where the rays come from an
    // interpolant of their logarithm (docs/DESIGN.md §11); never NaN, never negative
    if raw.power % 8 == 2 {
        let omni = airlight::PointLight { distribution: airlight::light::AnyDistribution::Omni, ..l };
        let surface = Surface { position: r.origin, normal: r.dir };
        let view = r.dir + DVec3::from_array(raw.axis) * 0.5;
        for brdf in [Brdf::Lambert { albedo: 1.0 }, Brdf::Phong { k_s: 1.0, exponent: 20.0, view }] {
            if let Ok(s) = SurfaceScene::new(surface, brdf, omni, m, p) {
                let x = s.air_light_counted(1e-1).0;
                assert!(!x.is_nan() && x >= 0.0, "f64/surface in the input's phase at 1e-1: {x} for {raw:?}");
            }
        }
    }
    // on one input in 8 more, that surface, Lambertian and Phong, lit by a beam c^p (p even, at
    // most 32) along the input's axis in the input's fog and phase function, at tolerance 1e-1:
    // where the rays at each outer node share their panel in the light angle (as one sum, or each
    // on shared samples; docs/DESIGN.md §11); never NaN, never negative
    if raw.power % 8 == 4 {
        let beam = airlight::light::TwoLobed { axis: DVec3::from_array(raw.axis), power: 2 * ((raw.power / 8) % 17) as u32 };
        let lit = airlight::PointLight { position: l.position, intensity: l.intensity, distribution: beam };
        let surface = Surface { position: r.origin, normal: r.dir };
        let view = r.dir + DVec3::from_array(raw.axis) * 0.5;
        for brdf in [Brdf::Lambert { albedo: 1.0 }, Brdf::Phong { k_s: 1.0, exponent: 20.0, view }] {
            if let Ok(s) = SurfaceScene::new(surface, brdf, lit, m, p) {
                let x = s.air_light_counted(1e-1).0;
                assert!(!x.is_nan() && x >= 0.0, "f64/surface lit by a beam at 1e-1: {x} for {raw:?}");
            }
        }
    }
    // on inputs with power 18 and phase kind 5 (about one in 120 of uniform inputs, never the
    // zeros most inputs decode to), at tolerance 1e-3 (hundreds of point lights or rays
    // each): a disc of
    // radius |w| at the light facing along its axis, a sphere of that radius there (a cosine lobe),
    // both and a parallelogram by the bounded method, and the ray's origin as a Lambertian
    // surface facing along the ray: never NaN, never negative (+∞ only for the light on the
    // surface point, or a true value beyond the range)
    if !(raw.power == 18 && raw.phase == 5) {
        return;
    }
    let disc = Emitter::Disc { center: l.position, normal: DVec3::from_array(raw.axis), radius: raw.w.abs() };
    if let Ok(s) = AreaScene::new(r, AreaLight::new(disc, l.intensity), m, p) {
        let x = s.in_scatter_counted(1e-3).0;
        assert!(!x.is_nan() && x >= 0.0, "f64/disc: {x} for {raw:?}");
    }
    let sphere = Emitter::Sphere { center: l.position, radius: raw.w.abs() };
    // a cosine lobe of the spot's inner cosine scaled (invalid outside 1..=1024)
    let lobe = Emission::CosineLobe { power: (raw.ci.abs() * 1024.0) as u32 };
    if let Ok(s) = AreaScene::new(r, AreaLight { emission: lobe, ..AreaLight::new(sphere, l.intensity) }, m, p) {
        let x = s.in_scatter_counted(1e-3).0;
        assert!(!x.is_nan() && x >= 0.0, "f64/sphere: {x} for {raw:?}");
    }
    // the bounded method (the shaders'): the disc, the sphere and a parallelogram with edges
    // across the axis, each with and without the cosine lobe — its routes about a phase lobe, an
    // emission lobe and the edge all reachable
    let axis = DVec3::from_array(raw.axis);
    let edge_u = axis.cross(DVec3::new(0.3, 1.0, 0.2)) * raw.w;
    let parallelogram = Emitter::Rectangle { corner: l.position, edge_u, edge_v: axis.cross(edge_u) };
    for emitter in [disc, sphere, parallelogram] {
        for emission in [Emission::Lambertian, lobe] {
            if let Ok(s) = AreaScene::new(r, AreaLight { emission, ..AreaLight::new(emitter, l.intensity) }, m, p) {
                let x = s.in_scatter_bounded();
                assert!(!x.is_nan() && x >= 0.0, "f64/{emitter:?} {emission:?} bounded: {x} for {raw:?}");
            }
        }
    }
    let surface = Surface { position: r.origin, normal: r.dir };
    if let Ok(s) = SurfaceScene::new(surface, Brdf::Lambert { albedo: 1.0 }, l, m, p) {
        let x = s.air_light_counted(1e-3).0;
        assert!(!x.is_nan() && x >= 0.0, "f64/surface: {x} for {raw:?}");
    }
});
