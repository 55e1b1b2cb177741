//! The world of the pictures: a pinhole camera, opaque geometry (a ground plane `y = 0` and
//! axis-aligned boxes), lights with colours, a medium and a phase function, and the ray casts.

use super::reference::adapt;
use airlight::glam::DVec3;
use airlight::light::AnyDistribution;
use airlight::phase::AnyPhase;
use airlight::{Brdf, Medium, PointLight, Ray, Scene, SegmentLight, SegmentScene, Surface, SurfaceScene};

/// Linear RGB radiance.
pub type Rgb = [f64; 3];

/// A pinhole camera; `y` is up.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Camera {
    /// Eye position.
    pub position: DVec3,
    /// The point the camera looks at (the image centre).
    pub look_at: DVec3,
    /// Vertical field of view, degrees.
    pub vfov_deg: f64,
    /// Image width in pixels.
    pub width: u32,
    /// Image height in pixels.
    pub height: u32,
}

impl Camera {
    /// The unit direction of the primary ray through the centre of pixel `(x, y)` (row 0 at
    /// the top).
    pub fn ray_dir(&self, x: u32, y: u32) -> DVec3 {
        let forward = (self.look_at - self.position).normalize();
        let right = forward.cross(DVec3::Y).normalize();
        let up = right.cross(forward);
        let half_h = (self.vfov_deg.to_radians() * 0.5).tan();
        let half_w = half_h * self.width as f64 / self.height as f64;
        let sx = ((x as f64 + 0.5) / self.width as f64 * 2.0 - 1.0) * half_w;
        let sy = (1.0 - (y as f64 + 0.5) / self.height as f64 * 2.0) * half_h;
        (forward + right * sx + up * sy).normalize()
    }
}

/// An opaque axis-aligned box with a Lambertian albedo.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Cuboid {
    /// Minimum corner.
    pub min: DVec3,
    /// Maximum corner.
    pub max: DVec3,
    /// Diffuse albedo per channel.
    pub albedo: Rgb,
}

impl Cuboid {
    pub(crate) fn new(min: [f64; 3], max: [f64; 3], albedo: Rgb) -> Cuboid {
        Cuboid { min: DVec3::from_array(min), max: DVec3::from_array(max), albedo }
    }

    /// Entry distance and outward normal of the ray `o + t·d` (`t > 0`), by slabs.
    fn hit(&self, o: DVec3, d: DVec3) -> Option<(f64, DVec3)> {
        let (mut t_near, mut t_far, mut axis) = (f64::NEG_INFINITY, f64::INFINITY, 0usize);
        for k in 0..3 {
            let (ok, dk, lo, hi) = (o[k], d[k], self.min[k], self.max[k]);
            if dk == 0.0 {
                if ok < lo || ok > hi {
                    return None;
                }
                continue;
            }
            let (mut a, mut b) = ((lo - ok) / dk, (hi - ok) / dk);
            if a > b {
                std::mem::swap(&mut a, &mut b);
            }
            if a > t_near {
                t_near = a;
                axis = k;
            }
            t_far = t_far.min(b);
        }
        if t_near > t_far || t_near <= 0.0 {
            return None;
        }
        let mut n = DVec3::ZERO;
        n[axis] = -d[axis].signum();
        Some((t_near, n))
    }
}

/// A light of the scene: a kernel point light — or, with `tube_end`, a segment light (a
/// fluorescent tube) from the point light's position to `tube_end`, every point of it emitting
/// the point light's intensity per unit length with its distribution — and its RGB colour (the
/// radiant intensity per channel is `colour × intensity`).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Light {
    /// Position, intensity and angular distribution.
    pub light: PointLight<f64, AnyDistribution<f64>>,
    /// A tube's other end.
    pub tube_end: Option<DVec3>,
    /// Colour (linear RGB multiplier).
    pub color: Rgb,
}

impl Light {
    /// The tube as the kernel's segment light, `None` for a point light.
    pub fn tube(&self) -> Option<SegmentLight<f64, AnyDistribution<f64>>> {
        self.tube_end.map(|b| SegmentLight { a: self.light.position, b, intensity: self.light.intensity, distribution: self.light.distribution })
    }

    /// `∫ f(point light at a + s·e) ds` over a tube (`f` of the point light itself for a point
    /// light): adaptive Gauss–Kronrod 7/15 to `rel_tol` from 16 equal panels.
    pub fn over_emitter(&self, rel_tol: f64, f: impl Fn(&PointLight<f64, AnyDistribution<f64>>) -> f64) -> f64 {
        let Some(b) = self.tube_end else { return f(&self.light) };
        let a = self.light.position;
        let len = (b - a).length();
        if !(len > 0.0) {
            return 0.0;
        }
        let e = (b - a) / len;
        let at = |s: f64| f(&PointLight { position: a + e * s, ..self.light });
        let edges: Vec<f64> = (0..=16).map(|i| len * i as f64 / 16.0).collect();
        adapt(&at, &edges, rel_tol, 4000)
    }
}

/// A scene to render: camera, medium, phase function, lights and opaque geometry.
#[derive(Clone, Debug, PartialEq)]
pub struct SceneDesc {
    /// Short name, used for file names (`lighthouse`, `road`, `stage`, `bench`).
    pub name: &'static str,
    /// The camera (and image size).
    pub camera: Camera,
    /// The participating medium.
    pub medium: Medium<f64>,
    /// Its phase function.
    pub phase: AnyPhase<f64>,
    /// The lights.
    pub lights: Vec<Light>,
    /// Albedo of the ground plane `y = 0`, or `None` for no ground.
    pub ground: Option<Rgb>,
    /// Opaque boxes.
    pub boxes: Vec<Cuboid>,
    /// Tone-mapping exposure: display value `1 − e^{−x·exposure}` before sRGB encoding.
    pub exposure: f64,
    /// Surfaces lit by the fog: every surface receives the air-light of every omni point light
    /// ([`SurfaceScene::air_light`], Lambertian), which brightens the faces the light does not
    /// reach directly.
    pub fog_lit_surfaces: bool,
}

/// What a primary ray sees first.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Hit {
    /// Distance to the surface (`+∞`: sky).
    pub t: f64,
    /// Outward unit normal (zero for sky).
    pub normal: DVec3,
    /// Albedo (zero for sky).
    pub albedo: Rgb,
}

impl SceneDesc {
    /// Nearest surface along `o + t·d`, `t > 0`.
    pub fn trace(&self, o: DVec3, d: DVec3) -> Hit {
        let mut best = Hit { t: f64::INFINITY, normal: DVec3::ZERO, albedo: [0.0; 3] };
        if let Some(albedo) = self.ground {
            if d.y < 0.0 && o.y > 0.0 {
                let t = -o.y / d.y;
                if t.is_finite() {
                    best = Hit { t, normal: DVec3::Y, albedo };
                }
            }
        }
        for b in &self.boxes {
            if let Some((t, normal)) = b.hit(o, d) {
                if t < best.t {
                    best = Hit { t, normal, albedo: b.albedo };
                }
            }
        }
        best
    }

    /// The primary ray's direction and hit for pixel `(x, y)`.
    pub fn primary(&self, x: u32, y: u32) -> (DVec3, Hit) {
        let d = self.camera.ray_dir(x, y);
        (d, self.trace(self.camera.position, d))
    }

    /// The same scene at another image size.
    pub fn with_size(mut self, width: u32, height: u32) -> SceneDesc {
        self.camera.width = width;
        self.camera.height = height;
        self
    }

    pub(crate) fn ray(&self, d: DVec3, hit: &Hit) -> Ray<f64> {
        Ray { origin: self.camera.position, dir: d, t_min: 0.0, t_max: hit.t }
    }

    /// The surface term `e^{−σt t_hit} · L_s` of one light at a hit with brdf `1/π` (multiply
    /// by the albedo), from the kernel's [`Scene::surface_radiance`] (paper eq. 7); a tube's,
    /// its point lights' integrated over it ([`Light::over_emitter`], to 1e-10).
    pub(crate) fn surface_kernel(&self, d: DVec3, hit: &Hit, light: &Light) -> f64 {
        if !hit.t.is_finite() {
            return 0.0;
        }
        light.over_emitter(1e-10, |point| match Scene::new(self.ray(d, hit), *point, self.medium, self.phase) {
            Ok(s) => (-self.medium.sigma_t * hit.t).exp() * s.surface_radiance(hit.normal, std::f64::consts::FRAC_1_PI),
            Err(_) => 0.0,
        })
    }

    /// `L_m` of one light over the pixel's segment: the kernel's default path
    /// ([`Scene::in_scatter`], [`SegmentScene::in_scatter`]).
    pub(crate) fn in_scatter_kernel(&self, d: DVec3, hit: &Hit, light: &Light) -> f64 {
        match light.tube() {
            Some(tube) => SegmentScene::new(self.ray(d, hit), tube, self.medium, self.phase).map(|s| s.in_scatter()).unwrap_or(0.0),
            None => Scene::new(self.ray(d, hit), light.light, self.medium, self.phase).map(|s| s.in_scatter()).unwrap_or(0.0),
        }
    }

    /// Whether `light`'s air-light reaches the surface of a hit ([`SceneDesc::fog_lit_surfaces`]:
    /// omni point lights, on every surface the primary ray meets).
    pub fn air_lit(&self, hit: &Hit, light: &Light) -> bool {
        hit.t.is_finite() && self.fog_lit_surfaces && light.tube_end.is_none() && matches!(light.light.distribution, AnyDistribution::Omni)
    }

    /// The point where the primary ray along `d` meets its hit.
    pub fn surface_point(&self, d: DVec3, hit: &Hit) -> DVec3 {
        self.camera.position + d * hit.t
    }

    /// The surface point and the kernel's Lambertian surface scene (albedo 1: multiply by the
    /// albedo) of a hit, where [`SceneDesc::air_lit`].
    pub(crate) fn surface_scene(&self, d: DVec3, hit: &Hit, light: &Light) -> Option<SurfaceScene<f64, AnyDistribution<f64>, AnyPhase<f64>>> {
        if !self.air_lit(hit, light) {
            return None;
        }
        let surface = Surface { position: self.surface_point(d, hit), normal: hit.normal };
        SurfaceScene::new(surface, Brdf::Lambert { albedo: 1.0 }, light.light, self.medium, self.phase).ok()
    }

    /// The air-light term `e^{−σt t_hit} · L_{p,a}` of one light at a hit (albedo 1), by the
    /// kernel's [`SurfaceScene::air_light`]; 0 where the light does not light the surfaces.
    pub(crate) fn air_light_kernel(&self, d: DVec3, hit: &Hit, light: &Light) -> f64 {
        self.surface_scene(d, hit, light).map_or(0.0, |s| (-self.medium.sigma_t * hit.t).exp() * s.air_light())
    }
}
