//! Target (1): the kernel on arbitrary inputs, f32 and f64, checked and unchecked API, both
//! expansions, 4 and 6 terms, lit sub-segments. Oracle: no panic; never NaN; never negative;
//! `+∞` only where documented — the light on the segment (`h = 0`, `t_min ≤ x_h ≤ t_max`;
//! here `h` is recomputed in f64 from the same inputs, so "0" means within 8 ulps of
//! `|p − o|` in the evaluation precision), or a true value beyond the float range, which is
//! excluded when the bound `σs·I·P_max·π/h` (since `∫ dt/r² ≤ π/h` and `D ≤ 1`) is finite and
//! below `1e-20·max`: within 20 decades of the range's end, intermediate products (the
//! prefactor times expansion coefficients that grow like `r^{−k}` on a needle-thin cone edge)
//! may overflow before the result would, which is documented rather than hidden.
#![no_main]
use airlight::glam::{DVec3, Vec3};
use airlight::light::{AnyDistribution, SpotCone, TwoLobed};
use airlight::phase::{AnyPhase, CornetteShanks, HenyeyGreenstein, Schlick, TwoLobeHenyeyGreenstein};
use airlight::{in_scatter_unchecked, Expansion, Medium, PointLight, Ray, Scene};
use libfuzzer_sys::fuzz_target;

mod common;
use common::Reader;

#[derive(Clone, Copy, Debug)]
struct Raw {
    o: [f64; 3],
    d: [f64; 3],
    t0: f64,
    t1: f64,
    p: [f64; 3],
    i: f64,
    ss: f64,
    st: f64,
    light: u64,
    axis: [f64; 3],
    power: u64,
    ci: f64,
    co: f64,
    phase: u64,
    g1: f64,
    g2: f64,
    w: f64,
}

fn decode(data: &[u8]) -> Raw {
    let mut r = Reader(data);
    let mut v3 = |r: &mut Reader, lo: f64, hi: f64| [r.num(lo, hi), r.num(lo, hi), r.num(lo, hi)];
    let o = v3(&mut r, -100.0, 100.0);
    let d = v3(&mut r, -1.0, 1.0);
    let t0 = r.num(-10.0, 10.0);
    let t1 = if r.int(5) == 0 { f64::INFINITY } else { t0 + r.num(0.0, 200.0).abs() };
    let p = v3(&mut r, -100.0, 100.0);
    Raw {
        o,
        d,
        t0,
        t1,
        p,
        i: r.num(0.0, 1000.0),
        ss: r.num(0.0, 2.0),
        st: r.num(0.0, 50.0),
        light: r.int(3),
        axis: v3(&mut r, -1.0, 1.0),
        power: r.int(20),
        ci: r.num(-1.0, 1.0),
        co: r.num(-1.0, 1.0),
        phase: r.int(6),
        g1: r.num(-0.99, 0.99),
        g2: r.num(-0.99, 0.99),
        w: r.num(0.0, 1.0),
    }
}

fn h_and_xh(raw: &Raw) -> (f64, f64) {
    // normalise as the kernel does: scaled by the largest component first
    let m = raw.d.iter().fold(0.0f64, |a, x| a.max(x.abs()));
    let s = raw.d.map(|x| x / m);
    let n = (s.iter().map(|x| x * x).sum::<f64>()).sqrt();
    let d = s.map(|x| x / n);
    let op = [raw.p[0] - raw.o[0], raw.p[1] - raw.o[1], raw.p[2] - raw.o[2]];
    let xh = op[0] * d[0] + op[1] * d[1] + op[2] * d[2];
    let perp = [xh * d[0] - op[0], xh * d[1] - op[1], xh * d[2] - op[2]];
    let pm = perp.iter().fold(0.0f64, |a, x| a.max(x.abs()));
    let h = if pm == 0.0 { 0.0 } else { pm * (perp.iter().map(|x| (x / pm) * (x / pm)).sum::<f64>()).sqrt() };
    (h, xh)
}

fn p_max(raw: &Raw) -> f64 {
    let g = raw.g1.abs().max(raw.g2.abs()).min(0.999_999);
    3.0 * (1.0 + g) / (4.0 * std::f64::consts::PI * (1.0 - g) * (1.0 - g))
}

macro_rules! scene_types {
    ($t:ty, $v:ident) => {{
        |raw: &Raw| {
            let v = |a: [f64; 3]| $v::new(a[0] as $t, a[1] as $t, a[2] as $t);
            let dist = match raw.light {
                0 => AnyDistribution::Omni,
                1 => AnyDistribution::TwoLobed(TwoLobed { axis: v(raw.axis), power: raw.power as u32 }),
                _ => AnyDistribution::SpotCone(SpotCone { axis: v(raw.axis), cos_inner: raw.ci as $t, cos_outer: raw.co as $t }),
            };
            let phase = match raw.phase {
                0 => AnyPhase::Isotropic,
                1 => AnyPhase::Rayleigh,
                2 => AnyPhase::HenyeyGreenstein(HenyeyGreenstein { g: raw.g1 as $t }),
                3 => AnyPhase::Schlick(Schlick { k: raw.g1 as $t }),
                4 => AnyPhase::CornetteShanks(CornetteShanks { g: raw.g1 as $t }),
                _ => AnyPhase::TwoLobeHenyeyGreenstein(TwoLobeHenyeyGreenstein { g1: raw.g1 as $t, g2: raw.g2 as $t, w: raw.w as $t }),
            };
            (
                Ray { origin: v(raw.o), dir: v(raw.d), t_min: raw.t0 as $t, t_max: raw.t1 as $t },
                PointLight { position: v(raw.p), intensity: raw.i as $t, distribution: dist },
                Medium { sigma_s: raw.ss as $t, sigma_t: raw.st as $t },
                phase,
            )
        }
    }};
}

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

fuzz_target!(|data: &[u8]| {
    let raw = decode(data);
    // f64, checked
    let (r, l, m, p) = scene_types!(f64, DVec3)(&raw);
    if let Ok(s) = Scene::new(r, l, m, p) {
        for e in [Expansion::Chebyshev, Expansion::Taylor] {
            check(&raw, s.in_scatter_with::<4>(e), f64::MAX, "f64/4");
            check(&raw, s.in_scatter_with::<6>(e), f64::MAX, "f64/6");
        }
        let mid = if raw.t1.is_finite() { 0.5 * (raw.t0 + raw.t1) } else { raw.t0 + 1.0 };
        check(&raw, s.in_scatter_lit::<6>(&[(raw.t0, mid), (mid, raw.t1)], Expansion::Chebyshev), f64::MAX, "f64/lit");
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
        for e in [Expansion::Chebyshev, Expansion::Taylor] {
            check(&raw32, s.in_scatter_with::<4>(e) as f64, f32::MAX as f64, "f32/4");
            check(&raw32, s.in_scatter_with::<6>(e) as f64, f32::MAX as f64, "f32/6");
        }
    }
    check(&raw32, in_scatter_unchecked::<f32, _, _, 4>(r, l, m, p, Expansion::Chebyshev) as f64, f32::MAX as f64, "f32/unchecked");
});
