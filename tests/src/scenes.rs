//! Random scene generators for property tests.

use crate::Rng;
use airlight::glam::{DVec3, Vec3};
use airlight::light::{AnyDistribution, SpotCone, TwoLobed};
use airlight::phase::{AnyPhase, CornetteShanks, HenyeyGreenstein, Schlick, TwoLobeHenyeyGreenstein};
use airlight::{LightDistribution, Medium, PointLight, Ray, Scene};
use airlight::record::{cast_light, cast_phase};

/// A scene in plain f64 numbers, convertible to either precision.
#[derive(Clone, Copy, Debug)]
pub struct Plain {
    /// Ray origin.
    pub origin: [f64; 3],
    /// Unit ray direction.
    pub dir: [f64; 3],
    /// Segment start.
    pub t_min: f64,
    /// Segment end (may be +∞).
    pub t_max: f64,
    /// Light position.
    pub light: [f64; 3],
    /// Intensity.
    pub intensity: f64,
    /// σs.
    pub sigma_s: f64,
    /// σt.
    pub sigma_t: f64,
    /// Light distribution.
    pub dist: AnyDistribution<f64>,
    /// Phase function.
    pub phase: AnyPhase<f64>,
}

/// How far from isotropic the generated scenes may be.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Aniso {
    /// Isotropic light and phase (the model-exact case).
    None,
    /// Gentle: |g| ≤ 0.5, powers ≤ 4, wide cones.
    Mild,
    /// Anything the contract allows.
    Any,
}

fn pick_phase(rng: &mut Rng, a: Aniso) -> AnyPhase<f64> {
    let gmax = if a == Aniso::Mild { 0.5 } else { 0.9 };
    match rng.next_u64() % 6 {
        0 => AnyPhase::Isotropic,
        1 => AnyPhase::Rayleigh,
        2 => AnyPhase::HenyeyGreenstein(HenyeyGreenstein { g: rng.range(-gmax, gmax) }),
        3 => AnyPhase::Schlick(Schlick { k: rng.range(-gmax, gmax) }),
        4 => AnyPhase::CornetteShanks(CornetteShanks { g: rng.range(-gmax, gmax) }),
        _ => AnyPhase::TwoLobeHenyeyGreenstein(TwoLobeHenyeyGreenstein {
            g1: rng.range(0.0, gmax),
            g2: rng.range(-gmax, 0.0),
            w: rng.unit(),
        }),
    }
}

fn pick_dist(rng: &mut Rng, a: Aniso) -> AnyDistribution<f64> {
    let axis = DVec3::from_array(rng.unit_vector());
    match rng.next_u64() % 3 {
        0 => AnyDistribution::Omni,
        1 => {
            let pmax = if a == Aniso::Mild { 2 } else { 8 };
            AnyDistribution::TwoLobed(TwoLobed { axis, power: 2 * (1 + (rng.next_u64() % pmax) as u32) })
        }
        _ => {
            let (lo, hi) = if a == Aniso::Mild { (-0.5, 0.3) } else { (0.3, 0.95) };
            let co = rng.range(lo, hi);
            AnyDistribution::SpotCone(SpotCone { axis, cos_inner: co + rng.range(0.02, 1.0 - co), cos_outer: co })
        }
    }
}

/// A random valid scene: light at distance `h` (log-uniform 1e-4..30) from the ray line, its
/// foot anywhere from well before to well after the segment; σt log-uniform 1e-6..10 (or 0).
pub fn random(rng: &mut Rng, a: Aniso) -> Plain {
    let origin = [rng.range(-50.0, 50.0), rng.range(-50.0, 50.0), rng.range(-50.0, 50.0)];
    let dir = rng.unit_vector();
    let t_min = rng.range(-5.0, 5.0);
    let t_max = if rng.unit() < 0.2 { f64::INFINITY } else { t_min + rng.log_range(1e-3, 1e3) };
    let span = if t_max.is_finite() { t_max - t_min } else { 100.0 };
    let foot = rng.range(t_min - 0.5 * span - 20.0, t_min + 1.5 * span + 20.0);
    let h = rng.log_range(1e-4, 30.0);
    // a unit vector perpendicular to dir
    let mut p = rng.unit_vector();
    let dp = p[0] * dir[0] + p[1] * dir[1] + p[2] * dir[2];
    for i in 0..3 {
        p[i] -= dp * dir[i];
    }
    let pn = (p[0] * p[0] + p[1] * p[1] + p[2] * p[2]).sqrt();
    let light = [0, 1, 2].map(|i| origin[i] + foot * dir[i] + h * p[i] / pn);
    let sigma_t = if rng.unit() < 0.1 { 0.0 } else { rng.log_range(1e-6, 10.0) };
    let (dist, phase) = if a == Aniso::None {
        (AnyDistribution::Omni, AnyPhase::Isotropic)
    } else {
        (pick_dist(rng, a), pick_phase(rng, a))
    };
    Plain {
        origin,
        dir,
        t_min,
        t_max,
        light,
        intensity: rng.log_range(0.1, 1000.0),
        sigma_s: rng.range(0.01, 1.0),
        sigma_t,
        dist,
        phase,
    }
}

impl Plain {
    /// The f64 scene.
    pub fn f64(&self) -> Scene<f64, AnyDistribution<f64>, AnyPhase<f64>> {
        self.f64_with(self.dist)
    }

    /// The f64 scene with `distribution` in place of [`Plain::dist`] (any type, a user's own
    /// included).
    pub fn f64_with<D: LightDistribution<f64>>(&self, distribution: D) -> Scene<f64, D, AnyPhase<f64>> {
        Scene::new(
            Ray { origin: DVec3::from_array(self.origin), dir: DVec3::from_array(self.dir), t_min: self.t_min, t_max: self.t_max },
            PointLight { position: DVec3::from_array(self.light), intensity: self.intensity, distribution },
            Medium { sigma_s: self.sigma_s, sigma_t: self.sigma_t },
            self.phase,
        )
        .expect("generated scene is valid")
    }

    /// The same scene with every number rounded to f32 (use [`Plain::rounded`] first so that
    /// both precisions see identical inputs).
    pub fn f32(&self) -> Scene<f32, AnyDistribution<f32>, AnyPhase<f32>> {
        let v = |a: [f64; 3]| Vec3::new(a[0] as f32, a[1] as f32, a[2] as f32);
        let light = PointLight { position: self.light.into(), intensity: self.intensity, distribution: self.dist };
        let light = cast_light::<f64, f32>(&light);
        Scene::new(
            Ray { origin: v(self.origin), dir: v(self.dir), t_min: self.t_min as f32, t_max: self.t_max as f32 },
            light,
            Medium { sigma_s: self.sigma_s as f32, sigma_t: self.sigma_t as f32 },
            cast_phase::<f64, f32>(&self.phase),
        )
        .expect("generated scene is valid")
    }

    /// Every number rounded to the nearest f32 (kept in f64), so that the f32 and f64 kernels
    /// evaluate exactly the same scene.
    pub fn rounded(&self) -> Plain {
        let r = |x: f64| x as f32 as f64;
        let v = |a: [f64; 3]| a.map(r);
        let mut out = *self;
        out.origin = v(self.origin);
        out.dir = v(self.dir);
        out.t_min = r(self.t_min);
        out.t_max = r(self.t_max);
        out.light = v(self.light);
        out.intensity = r(self.intensity);
        out.sigma_s = r(self.sigma_s);
        out.sigma_t = r(self.sigma_t);
        out.dist = match self.dist {
            AnyDistribution::TwoLobed(d) => AnyDistribution::TwoLobed(TwoLobed { axis: d.axis.as_vec3().as_dvec3(), power: d.power }),
            AnyDistribution::SpotCone(d) => AnyDistribution::SpotCone(SpotCone {
                axis: d.axis.as_vec3().as_dvec3(),
                cos_inner: r(d.cos_inner),
                cos_outer: r(d.cos_outer),
            }),
            o => o,
        };
        out.phase = match self.phase {
            AnyPhase::HenyeyGreenstein(p) => AnyPhase::HenyeyGreenstein(HenyeyGreenstein { g: r(p.g) }),
            AnyPhase::Schlick(p) => AnyPhase::Schlick(Schlick { k: r(p.k) }),
            AnyPhase::CornetteShanks(p) => AnyPhase::CornetteShanks(CornetteShanks { g: r(p.g) }),
            AnyPhase::TwoLobeHenyeyGreenstein(p) => {
                AnyPhase::TwoLobeHenyeyGreenstein(TwoLobeHenyeyGreenstein { g1: r(p.g1), g2: r(p.g2), w: r(p.w) })
            }
            o => o,
        };
        out
    }
}
