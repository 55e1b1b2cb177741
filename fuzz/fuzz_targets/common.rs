//! Decoding fuzz bytes into scenes, shared by the targets.
#![allow(dead_code, unused_macros)]

use libfuzzer_sys::arbitrary::{Arbitrary, Result, Unstructured};

/// A number in `[lo, hi]` most of the time; raw bits, a special value or a log-uniform
/// magnitude otherwise. It takes a mode byte and 8 payload bytes (little-endian), the layout
/// of the committed seeds in `corpus/`.
pub fn num(u: &mut Unstructured, lo: f64, hi: f64) -> Result<f64> {
    let mode = u8::arbitrary(u)?;
    let bits = u64::arbitrary(u)?;
    let unit = (bits >> 11) as f64 / (1u64 << 53) as f64;
    Ok(match mode % 16 {
        0 => f64::from_bits(bits),
        1 => [0.0, -0.0, 1.0, -1.0, f64::MIN_POSITIVE, 5e-324, f64::MAX, f64::INFINITY, f64::NAN, 1e-300, 1e300, f32::MAX as f64, f32::MIN_POSITIVE as f64, 1e-45][(bits % 14) as usize],
        2 => lo.signum() * (unit * 600.0 - 300.0).exp(),
        _ => lo + (hi - lo) * unit,
    })
}

/// A small integer in `[0, n)`; it takes 9 bytes, as a number does.
pub fn int(u: &mut Unstructured, n: u64) -> Result<u64> {
    let _mode = u8::arbitrary(u)?;
    Ok(u64::arbitrary(u)? % n.max(1))
}

/// A scene as the fuzzer's bytes give it, in f64 (each field may be anything).
#[derive(Clone, Copy, Debug)]
pub struct Raw {
    pub o: [f64; 3],
    pub d: [f64; 3],
    pub t0: f64,
    pub t1: f64,
    pub p: [f64; 3],
    pub i: f64,
    pub ss: f64,
    pub st: f64,
    pub light: u64,
    pub axis: [f64; 3],
    pub power: u64,
    pub ci: f64,
    pub co: f64,
    pub phase: u64,
    pub g1: f64,
    pub g2: f64,
    pub w: f64,
}

/// One scene: 25 or 26 numbers of 9 bytes ([`num`], [`int`]).
impl<'a> Arbitrary<'a> for Raw {
    fn arbitrary(u: &mut Unstructured<'a>) -> Result<Self> {
        let v3 = |u: &mut Unstructured, lo: f64, hi: f64| -> Result<[f64; 3]> { Ok([num(u, lo, hi)?, num(u, lo, hi)?, num(u, lo, hi)?]) };
        let o = v3(u, -100.0, 100.0)?;
        let d = v3(u, -1.0, 1.0)?;
        let t0 = num(u, -10.0, 10.0)?;
        let t1 = if int(u, 5)? == 0 { f64::INFINITY } else { t0 + num(u, 0.0, 200.0)?.abs() };
        let p = v3(u, -100.0, 100.0)?;
        Ok(Raw {
            o,
            d,
            t0,
            t1,
            p,
            i: num(u, 0.0, 1000.0)?,
            ss: num(u, 0.0, 2.0)?,
            st: num(u, 0.0, 50.0)?,
            light: int(u, 3)?,
            axis: v3(u, -1.0, 1.0)?,
            power: int(u, 20)?,
            ci: num(u, -1.0, 1.0)?,
            co: num(u, -1.0, 1.0)?,
            phase: int(u, 6)?,
            g1: num(u, -0.99, 0.99)?,
            g2: num(u, -0.99, 0.99)?,
            w: num(u, 0.0, 1.0)?,
        })
    }
}

/// Up to [`Batch::MAX`] scenes, one after the other until the input ends.
#[derive(Debug)]
pub struct Batch(pub Vec<Raw>);

impl Batch {
    /// The most scenes in one batch.
    pub const MAX: usize = 64;
}

impl<'a> Arbitrary<'a> for Batch {
    fn arbitrary(u: &mut Unstructured<'a>) -> Result<Self> {
        let mut scenes = Vec::new();
        while !u.is_empty() && scenes.len() < Batch::MAX {
            scenes.push(Raw::arbitrary(u)?);
        }
        Ok(Batch(scenes))
    }
}

/// The light's distance from the ray line and its foot, in f64.
pub fn h_and_xh(raw: &Raw) -> (f64, f64) {
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

/// An upper bound of every phase function at the raw parameters.
pub fn p_max(raw: &Raw) -> f64 {
    let g = raw.g1.abs().max(raw.g2.abs()).min(0.999_999);
    3.0 * (1.0 + g) / (4.0 * std::f64::consts::PI * (1.0 - g) * (1.0 - g))
}

/// `(ray, light, medium, phase)` of a [`Raw`] scene in the given precision and glam vector.
macro_rules! scene_types {
    ($t:ty, $v:ident) => {{
        |raw: &common::Raw| {
            let v = |a: [f64; 3]| $v::new(a[0] as $t, a[1] as $t, a[2] as $t);
            let dist = match raw.light {
                0 => airlight::light::AnyDistribution::Omni,
                1 => airlight::light::AnyDistribution::TwoLobed(airlight::light::TwoLobed { axis: v(raw.axis), power: raw.power as u32 }),
                _ => airlight::light::AnyDistribution::SpotCone(airlight::light::SpotCone { axis: v(raw.axis), cos_inner: raw.ci as $t, cos_outer: raw.co as $t }),
            };
            let phase = match raw.phase {
                0 => airlight::phase::AnyPhase::Isotropic,
                1 => airlight::phase::AnyPhase::Rayleigh,
                2 => airlight::phase::AnyPhase::HenyeyGreenstein(airlight::phase::HenyeyGreenstein { g: raw.g1 as $t }),
                3 => airlight::phase::AnyPhase::Schlick(airlight::phase::Schlick { k: raw.g1 as $t }),
                4 => airlight::phase::AnyPhase::CornetteShanks(airlight::phase::CornetteShanks { g: raw.g1 as $t }),
                _ => airlight::phase::AnyPhase::TwoLobeHenyeyGreenstein(airlight::phase::TwoLobeHenyeyGreenstein { g1: raw.g1 as $t, g2: raw.g2 as $t, w: raw.w as $t }),
            };
            (
                airlight::Ray { origin: v(raw.o), dir: v(raw.d), t_min: raw.t0 as $t, t_max: raw.t1 as $t },
                airlight::PointLight { position: v(raw.p), intensity: raw.i as $t, distribution: dist },
                airlight::Medium { sigma_s: raw.ss as $t, sigma_t: raw.st as $t },
                phase,
            )
        }
    }};
}

