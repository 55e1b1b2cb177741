//! `airlight verify`: the CPU/shader agreement check on the user's own GPU.
//!
//! Generates `cases` scenes (deterministic, wide ranges, every phase function and light
//! distribution), runs the committed compute shader on the first adapter wgpu finds, and
//! judges every result with the criterion of [`airlight_shaders::agreement`] (the one the agreement
//! tests use): `|gpu − cpu_f32| ≤ 9·noise + 2e-4·scale (+ 2^-100)`.

use airlight_shaders::agreement::{expect, judge};
use airlight_shaders::gpu::{Gpu, Shader};
use airlight_shaders::layout::{pack, unpack_result, RESULT_SIZE};
use airlight::record::SceneRecord;
use airlight::glam::Vec3;
use airlight::light::{AnyDistribution, SpotCone, TwoLobed};
use airlight::phase::{AnyPhase, CornetteShanks, HenyeyGreenstein, Schlick, TwoLobeHenyeyGreenstein};
use airlight::{Medium, PointLight, Ray};
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

/// Runs the check with `cases` scenes through the shader with `terms` (8 or 12) nodes per panel.
pub fn verify(cases: usize, terms: usize) -> Result<Report, String> {
    let gpu = Gpu::new()?;
    let mut rng = Lcg(2009);
    let mut records = Vec::new();
    let mut expected = Vec::new();
    for i in 0..cases {
        let mut v3 = |lo: [f64; 3], hi: [f64; 3]| Vec3::new(rng.range(lo[0], hi[0]) as f32, rng.range(lo[1], hi[1]) as f32, rng.range(lo[2], hi[2]) as f32);
        let origin = v3([-50.0; 3], [50.0; 3]);
        let dir = v3([-1.0, -1.0, 0.1], [1.0; 3]);
        let position = origin + v3([-40.0; 3], [40.0; 3]);
        let axis = v3([-1.0, -1.0, 0.2], [1.0; 3]);
        let t_min = rng.range(-2.0, 5.0) as f32;
        let t_max = if i % 5 == 0 { f32::INFINITY } else { t_min + rng.range(0.1, 200.0) as f32 };
        let sigma_t = (rng.range(0.0, 1.0).powi(3) * 5.0) as f32;
        let sigma_s = rng.range(0.01, 1.0) as f32;
        let g = rng.range(-0.7, 0.7) as f32;
        let distribution = match i % 3 {
            0 => AnyDistribution::Omni,
            1 => AnyDistribution::TwoLobed(TwoLobed { axis, power: 2 * (1 + (i / 3 % 4) as u32) }),
            _ => AnyDistribution::SpotCone(SpotCone { axis, cos_inner: 0.9, cos_outer: 0.6 }),
        };
        let phase = match i % 6 {
            0 => AnyPhase::Isotropic,
            1 => AnyPhase::Rayleigh,
            2 => AnyPhase::HenyeyGreenstein(HenyeyGreenstein { g }),
            3 => AnyPhase::Schlick(Schlick { k: g }),
            4 => AnyPhase::CornetteShanks(CornetteShanks { g }),
            _ => AnyPhase::TwoLobeHenyeyGreenstein(TwoLobeHenyeyGreenstein { g1: g.abs(), g2: -0.3, w: 0.75 }),
        };
        let rec = SceneRecord {
            ray: Ray { origin, dir, t_min, t_max },
            light: PointLight { position, intensity: 100.0, distribution },
            medium: Medium { sigma_s, sigma_t },
            phase,
        };
        records.extend_from_slice(&pack(&rec.ray, &rec.light, &rec.medium, &rec.phase));
        expected.push(expect(&rec, terms));
    }
    let wgsl = airlight_shaders::targets::compute_wgsl(terms);
    let out = gpu.run(Shader::Wgsl(wgsl), &records, true)?;
    let mut diffs = Vec::new();
    let (mut max_excess, mut non_finite, mut status_mismatches) = (0.0f64, 0, 0);
    for (i, e) in expected.iter().enumerate() {
        let (got, status) = unpack_result(&out[i * RESULT_SIZE..(i + 1) * RESULT_SIZE]);
        if !got.is_finite() {
            non_finite += 1;
        } else if status != e.status {
            status_mismatches += 1;
        }
        let j = judge(e, got, status);
        max_excess = max_excess.max(j.excess);
        // the statistics leave out values where Vulkan's denormal flushing dominates
        if e.status == airlight_shaders::layout::STATUS_OK && status == e.status && got.is_finite() && e.scale > 2f64.powi(-80) {
            diffs.push(j.diff);
        }
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
