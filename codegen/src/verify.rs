//! `airlight verify`: the CPU/shader agreement check on the user's own GPU.
//!
//! Generates `cases` scenes (deterministic, wide ranges, every phase function and light
//! distribution), runs the committed compute shader on the first adapter wgpu finds, and
//! compares with the f32 CPU kernel at the same term count, with the tolerance of
//! `tests/tests/gpu_agreement.rs`: `|gpu − cpu_f32| ≤ 2·|cpu_f32 − cpu_f64| + 2e-4·scale`
//! (+ 2^-100), `scale` the integral with `F` replaced by its maximum.

use crate::gpu::{Gpu, Shader};
use crate::layout::{pack, unpack_result, RESULT_SIZE, STATUS_INFINITE, STATUS_OK};
use airlight::glam::{DVec3, Vec3};
use airlight::light::{AnyDistribution, SpotCone, TwoLobed};
use airlight::phase::{AnyPhase, CornetteShanks, HenyeyGreenstein, Schlick, TwoLobeHenyeyGreenstein};
use airlight::{Expansion, Medium, PhaseFunction, PointLight, Ray, Scene};

/// What `verify` found.
#[derive(Clone, Debug)]
pub struct Report {
    /// Adapter name and backend.
    pub adapter: String,
    /// Number of scenes.
    pub cases: usize,
    /// Largest excess over the allowance, relative to the scale.
    pub max_excess: f64,
    /// Median relative difference to the f32 CPU kernel (of scale).
    pub median_diff: f64,
    /// Largest relative difference to the f32 CPU kernel (of scale).
    pub max_diff: f64,
    /// Non-finite results.
    pub non_finite: usize,
    /// Status mismatches.
    pub status_mismatches: usize,
}

impl Report {
    /// `true` when everything agreed.
    pub fn pass(&self) -> bool {
        self.max_excess == 0.0 && self.non_finite == 0 && self.status_mismatches == 0
    }
}

struct Lcg(u64);
impl Lcg {
    fn unit(&mut self) -> f64 {
        self.0 = self.0.wrapping_mul(6364136223846793005).wrapping_add(1442695040888963407);
        (self.0 >> 11) as f64 / (1u64 << 53) as f64
    }
    fn range(&mut self, a: f64, b: f64) -> f64 {
        a + (b - a) * self.unit()
    }
}

fn f32r(x: f64) -> f64 {
    x as f32 as f64
}

/// Runs the check with `cases` scenes at `terms` (4 or 6) expansion terms.
pub fn verify(cases: usize, terms: usize) -> Result<Report, String> {
    let gpu = Gpu::new()?;
    let mut rng = Lcg(2009);
    let mut records = Vec::new();
    let mut expected = Vec::new();
    for i in 0..cases {
        let o = [f32r(rng.range(-50.0, 50.0)), f32r(rng.range(-50.0, 50.0)), f32r(rng.range(-50.0, 50.0))];
        let d = [f32r(rng.range(-1.0, 1.0)), f32r(rng.range(-1.0, 1.0)), f32r(rng.range(0.1, 1.0))];
        let p = [f32r(o[0] + rng.range(-40.0, 40.0)), f32r(o[1] + rng.range(-40.0, 40.0)), f32r(o[2] + rng.range(-40.0, 40.0))];
        let t0 = f32r(rng.range(-2.0, 5.0));
        let t1 = if i % 5 == 0 { f64::INFINITY } else { f32r(t0 + rng.range(0.1, 200.0)) };
        let st = f32r(rng.range(0.0, 1.0).powi(3) * 5.0);
        let ss = f32r(rng.range(0.01, 1.0));
        let axis = [f32r(rng.range(-1.0, 1.0)), f32r(rng.range(-1.0, 1.0)), f32r(rng.range(0.2, 1.0))];
        let g = f32r(rng.range(-0.7, 0.7));
        let dist64 = match i % 3 {
            0 => AnyDistribution::Omni,
            1 => AnyDistribution::TwoLobed(TwoLobed { axis: DVec3::from_array(axis), power: 2 * (1 + (i / 3 % 4) as u32) }),
            _ => AnyDistribution::SpotCone(SpotCone { axis: DVec3::from_array(axis), cos_inner: 0.9, cos_outer: 0.6 }),
        };
        let phase64 = match i % 6 {
            0 => AnyPhase::Isotropic,
            1 => AnyPhase::Rayleigh,
            2 => AnyPhase::HenyeyGreenstein(HenyeyGreenstein { g }),
            3 => AnyPhase::Schlick(Schlick { k: g }),
            4 => AnyPhase::CornetteShanks(CornetteShanks { g }),
            _ => AnyPhase::TwoLobeHenyeyGreenstein(TwoLobeHenyeyGreenstein { g1: g.abs(), g2: -0.3, w: 0.75 }),
        };
        let s64 = Scene::new(
            Ray { origin: DVec3::from_array(o), dir: DVec3::from_array(d), t_min: t0, t_max: t1 },
            PointLight { position: DVec3::from_array(p), intensity: 100.0, distribution: dist64 },
            Medium { sigma_s: ss, sigma_t: st },
            phase64,
        )
        .map_err(|e| e.to_string())?;
        let v = |a: [f64; 3]| Vec3::new(a[0] as f32, a[1] as f32, a[2] as f32);
        let dist32 = match dist64 {
            AnyDistribution::Omni => AnyDistribution::Omni,
            AnyDistribution::TwoLobed(t) => AnyDistribution::TwoLobed(TwoLobed { axis: v(axis), power: t.power }),
            AnyDistribution::SpotCone(_) => AnyDistribution::SpotCone(SpotCone { axis: v(axis), cos_inner: 0.9, cos_outer: 0.6 }),
        };
        let phase32 = match phase64 {
            AnyPhase::Isotropic => AnyPhase::Isotropic,
            AnyPhase::Rayleigh => AnyPhase::Rayleigh,
            AnyPhase::HenyeyGreenstein(_) => AnyPhase::HenyeyGreenstein(HenyeyGreenstein { g: g as f32 }),
            AnyPhase::Schlick(_) => AnyPhase::Schlick(Schlick { k: g as f32 }),
            AnyPhase::CornetteShanks(_) => AnyPhase::CornetteShanks(CornetteShanks { g: g as f32 }),
            AnyPhase::TwoLobeHenyeyGreenstein(_) => AnyPhase::TwoLobeHenyeyGreenstein(TwoLobeHenyeyGreenstein { g1: g.abs() as f32, g2: -0.3, w: 0.75 }),
        };
        let ray32 = Ray { origin: v(o), dir: v(d), t_min: t0 as f32, t_max: t1 as f32 };
        let light32 = PointLight { position: v(p), intensity: 100.0f32, distribution: dist32 };
        let medium32 = Medium { sigma_s: ss as f32, sigma_t: st as f32 };
        let s32 = Scene::new(ray32, light32, medium32, phase32).map_err(|e| e.to_string())?;
        records.extend_from_slice(&pack(&ray32, &light32, &medium32, &phase32));
        let (c32, c64) = if terms == 4 {
            (s32.in_scatter_with::<4>(Expansion::Chebyshev), s64.in_scatter_with::<4>(Expansion::Chebyshev))
        } else {
            (s32.in_scatter_with::<6>(Expansion::Chebyshev), s64.in_scatter_with::<6>(Expansion::Chebyshev))
        };
        let iso = Scene::new(
            Ray { origin: DVec3::from_array(o), dir: DVec3::from_array(d), t_min: t0, t_max: t1 },
            PointLight { position: DVec3::from_array(p), intensity: 100.0, distribution: AnyDistribution::Omni },
            Medium { sigma_s: ss, sigma_t: st },
            AnyPhase::Isotropic,
        )
        .map_err(|e| e.to_string())?
        .in_scatter();
        let p_max = [-1.0f64, 1.0].iter().map(|&mu| phase64.eval(mu)).fold(0.0, f64::max);
        let scale = (iso * 4.0 * std::f64::consts::PI * p_max).max(c32 as f64);
        expected.push((c32, (c32 as f64 - c64).abs(), scale));
    }
    let wgsl = crate::eval::compute_wgsl(terms);
    let out = gpu.run(Shader::Wgsl(wgsl), &records, true)?;
    let mut diffs = Vec::new();
    let (mut max_excess, mut non_finite, mut status_mismatches) = (0.0f64, 0, 0);
    for (i, &(want, noise, scale)) in expected.iter().enumerate() {
        let (got, status) = unpack_result(&out[i * RESULT_SIZE..(i + 1) * RESULT_SIZE]);
        if !got.is_finite() {
            non_finite += 1;
            continue;
        }
        let want_status = if want.is_infinite() { STATUS_INFINITE } else { STATUS_OK };
        if status != want_status {
            status_mismatches += 1;
            continue;
        }
        if status != STATUS_OK || scale == 0.0 {
            continue;
        }
        let diff = (got as f64 - want as f64).abs();
        // the statistics leave out values where Vulkan's denormal flushing dominates
        if scale > 2f64.powi(-80) {
            diffs.push(diff / scale);
        }
        let excess = ((diff - 2f64.powi(-100) - 2.0 * noise) / scale - 2e-4).max(0.0);
        max_excess = max_excess.max(excess);
    }
    diffs.sort_by(|a, b| a.partial_cmp(b).unwrap());
    Ok(Report {
        adapter: gpu.describe(),
        cases,
        max_excess,
        median_diff: diffs.get(diffs.len() / 2).copied().unwrap_or(0.0),
        max_diff: diffs.last().copied().unwrap_or(0.0),
        non_finite,
        status_mismatches,
    })
}
