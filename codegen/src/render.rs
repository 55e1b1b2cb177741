//! Pictures: the paper's kinds of scenes — a lighthouse with a two-lobed beam in
//! thick brume, a foggy road with headlights and a streetlamp, a stage under three coloured
//! spotlights, a park bench in Rayleigh mist — rendered four ways:
//!
//! * [`render_cpu`]: the CPU kernel in f64, its default error-controlled path;
//! * [`render_gpu`]: the committed compute shader (`shaders-out/wgsl/airlight_4.wgsl`, f32, 4
//!   nodes per panel) through wgpu, every (pixel, light) segment one record of [`crate::layout`];
//! * [`render_reference`]: brute-force quadrature of the contract integral (docs/DESIGN.md §1) that
//!   uses none of the kernel's closed forms (see [`reference_in_scatter`]);
//! * [`relative_errors`] + [`heat_map`]: per-pixel relative error against the reference in a
//!   false-colour scale.
//!
//! The image model is deliberately simple: one primary ray per pixel (through its centre),
//! opaque geometry (a ground plane `y = 0` and axis-aligned boxes), no shadows. Per light, the
//! pixel gets `colour × (L_m(0, t_hit) + e^{−σt t_hit} · L_s)` with `L_m` the in-scattered
//! air-light over the visible segment and `L_s` the paper's eq. 7 surface term of a Lambertian
//! surface (`brdf = albedo/π`); rays that hit nothing see the glow over `[0, ∞)`.

use crate::gpu::Prepared;
use crate::scene_json::{cast_light, cast_phase};
use crate::layout::{self, RESULT_SIZE, STATUS_INFINITE, STATUS_OK};
use airlight::glam::DVec3;
use airlight::light::{AnyDistribution, SpotCone, TwoLobed};
use airlight::phase::{AnyPhase, HenyeyGreenstein, Schlick};
use airlight::{LightDistribution, Medium, PhaseFunction, PointLight, Ray, Scene};
use std::path::Path;
use std::sync::atomic::{AtomicUsize, Ordering};
use std::sync::Mutex;
use std::time::Instant;

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
    fn new(min: [f64; 3], max: [f64; 3], albedo: Rgb) -> Cuboid {
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

/// A light of the scene: a kernel point light and its RGB colour (the light's radiant
/// intensity per channel is `colour × intensity`).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Light {
    /// Position, intensity and angular distribution.
    pub light: PointLight<f64, AnyDistribution<f64>>,
    /// Colour (linear RGB multiplier).
    pub color: Rgb,
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

    fn ray(&self, d: DVec3, hit: &Hit) -> Ray<f64> {
        Ray { origin: self.camera.position, dir: d, t_min: 0.0, t_max: hit.t }
    }

    /// The surface term `e^{−σt t_hit} · L_s` of one light at a hit with brdf `1/π` (multiply
    /// by the albedo), from the kernel's [`Scene::surface_radiance`] (paper eq. 7).
    fn surface_kernel(&self, d: DVec3, hit: &Hit, light: &Light) -> f64 {
        if !hit.t.is_finite() {
            return 0.0;
        }
        match Scene::new(self.ray(d, hit), light.light, self.medium, self.phase) {
            Ok(s) => (-self.medium.sigma_t * hit.t).exp() * s.surface_radiance(hit.normal, std::f64::consts::FRAC_1_PI),
            Err(_) => 0.0,
        }
    }
}

fn sph(x: f64, y: f64, z: f64) -> DVec3 {
    DVec3::new(x, y, z).normalize()
}

fn spot(position: [f64; 3], target: [f64; 3], intensity: f64, inner_deg: f64, outer_deg: f64, color: Rgb) -> Light {
    let p = DVec3::from_array(position);
    Light {
        light: PointLight {
            position: p,
            intensity,
            distribution: AnyDistribution::SpotCone(SpotCone {
                axis: (DVec3::from_array(target) - p).normalize(),
                cos_inner: inner_deg.to_radians().cos(),
                cos_outer: outer_deg.to_radians().cos(),
            }),
        },
        color,
    }
}

fn omni(position: [f64; 3], intensity: f64, color: Rgb) -> Light {
    Light { light: PointLight { position: DVec3::from_array(position), intensity, distribution: AnyDistribution::Omni }, color }
}

/// A lighthouse on a headland at night: a tall tower, the lamp's two-lobed beam (`D = c^12`,
/// axis nearly horizontal, one lobe swept towards the viewer's side) and a dim cottage light
/// at the foot, in thick brume (`σs = 0.08`, `σt = 0.1`), Henyey–Greenstein `g = 0.6`.
pub fn lighthouse(width: u32, height: u32) -> SceneDesc {
    let white = [0.85, 0.85, 0.8];
    SceneDesc {
        name: "lighthouse",
        camera: Camera { position: DVec3::new(-13.0, 2.0, 22.0), look_at: DVec3::new(1.0, 13.0, 0.0), vfov_deg: 60.0, width, height },
        medium: Medium { sigma_s: 0.08, sigma_t: 0.1 },
        phase: AnyPhase::HenyeyGreenstein(HenyeyGreenstein { g: 0.6 }),
        lights: vec![Light {
            light: PointLight {
                position: DVec3::new(0.0, 21.0, 0.0),
                intensity: 20000.0,
                distribution: AnyDistribution::TwoLobed(TwoLobed { axis: sph(1.0, -0.06, 0.45), power: 12 }),
            },
            color: [1.0, 0.93, 0.78],
        },
        // the keeper's cottage window, a dim omni light by the tower's foot
        omni([4.0, 2.2, 5.0], 40.0, [1.0, 0.7, 0.4])],
        ground: Some([0.12, 0.13, 0.14]),
        boxes: vec![
            Cuboid::new([-1.6, 0.0, -1.6], [1.6, 19.0, 1.6], white),
            Cuboid::new([-2.2, 19.0, -2.2], [2.2, 19.6, 2.2], [0.3, 0.1, 0.1]),
            Cuboid::new([-1.0, 22.4, -1.0], [1.0, 23.0, 1.0], [0.3, 0.1, 0.1]),
            Cuboid::new([-9.0, 0.0, -7.0], [7.0, 1.5, 6.0], [0.25, 0.22, 0.2]),
        ],
        exposure: 2.5,
    }
}

/// A foggy road: an oncoming car's two headlights (spot cones, 10°/24°, low above the road,
/// pointing along it towards the camera's side) and a sodium streetlamp on a pole (a spot
/// pointing down, 35°/65°); `σs = 0.05`, `σt = 0.06`, Schlick `k = 0.5`.
pub fn road(width: u32, height: u32) -> SceneDesc {
    let head = [1.0, 0.95, 0.85];
    let sodium = [1.0, 0.55, 0.2];
    let metal = [0.3, 0.3, 0.32];
    SceneDesc {
        name: "road",
        camera: Camera { position: DVec3::new(-1.8, 1.3, 6.0), look_at: DVec3::new(0.5, 1.6, -30.0), vfov_deg: 45.0, width, height },
        medium: Medium { sigma_s: 0.05, sigma_t: 0.06 },
        phase: AnyPhase::Schlick(Schlick { k: 0.5 }),
        lights: vec![
            spot([1.1, 0.7, -21.9], [0.6, 0.0, 8.0], 400.0, 10.0, 24.0, head),
            spot([2.5, 0.7, -21.9], [2.0, 0.0, 8.0], 400.0, 10.0, 24.0, head),
            spot([-3.6, 6.3, -12.0], [-2.6, 0.0, -12.0], 600.0, 35.0, 65.0, sodium),
        ],
        ground: Some([0.12, 0.12, 0.12]),
        boxes: vec![
            // car body and cabin
            Cuboid::new([0.8, 0.3, -26.0], [2.8, 1.1, -22.0], [0.35, 0.05, 0.05]),
            Cuboid::new([1.0, 1.1, -25.5], [2.6, 1.7, -23.5], [0.1, 0.1, 0.12]),
            // lamp post and arm
            Cuboid::new([-5.15, 0.0, -12.15], [-4.85, 6.8, -11.85], metal),
            Cuboid::new([-5.0, 6.6, -12.15], [-3.2, 6.8, -11.85], metal),
            // kerb
            Cuboid::new([-40.0, 0.0, -200.0], [-4.0, 0.15, 10.0], [0.2, 0.2, 0.2]),
        ],
        exposure: 2.0,
    }
}

/// A concert stage lit by three coloured spot lights (red, green, blue; 7°/13°) hanging
/// above it and crossing on the stage floor, in a thin haze (`σs = 0.025`, `σt = 0.03`),
/// Henyey–Greenstein `g = 0.3`.
pub fn stage(width: u32, height: u32) -> SceneDesc {
    SceneDesc {
        name: "stage",
        camera: Camera { position: DVec3::new(0.0, 5.5, 15.0), look_at: DVec3::new(0.0, 3.5, -4.0), vfov_deg: 55.0, width, height },
        medium: Medium { sigma_s: 0.025, sigma_t: 0.03 },
        phase: AnyPhase::HenyeyGreenstein(HenyeyGreenstein { g: 0.3 }),
        lights: vec![
            spot([-5.0, 9.0, -3.0], [0.0, 1.0, -5.0], 2500.0, 9.0, 15.0, [1.0, 0.08, 0.05]),
            spot([0.0, 9.5, -1.5], [0.0, 1.0, -5.0], 2500.0, 9.0, 15.0, [0.08, 1.0, 0.12]),
            spot([5.0, 9.0, -3.0], [0.0, 1.0, -5.0], 2500.0, 9.0, 15.0, [0.1, 0.25, 1.0]),
        ],
        ground: Some([0.05, 0.05, 0.05]),
        boxes: vec![
            Cuboid::new([-7.0, 0.0, -9.0], [7.0, 1.0, -1.0], [0.35, 0.3, 0.28]),
            Cuboid::new([-12.0, 0.0, -11.0], [12.0, 14.0, -10.0], [0.12, 0.12, 0.14]),
            Cuboid::new([-8.0, 10.0, -4.0], [8.0, 10.4, -1.0], [0.15, 0.15, 0.15]),
        ],
        exposure: 3.0,
    }
}

/// A park bench beside an omni lamp on a post, a second lamp further back, in a mist of
/// small droplets with Rayleigh scattering (`σs = 0.07`, `σt = 0.08`).
pub fn bench(width: u32, height: u32) -> SceneDesc {
    let wood = [0.45, 0.28, 0.15];
    let iron = [0.08, 0.08, 0.09];
    let mut boxes = vec![
        // lamp posts (the lamps sit just above their tops)
        Cuboid::new([-1.06, 0.0, -0.06], [-0.94, 3.0, 0.06], iron),
        Cuboid::new([-9.06, 0.0, -12.06], [-8.94, 3.0, -11.94], iron),
        // bench legs
        Cuboid::new([0.1, 0.0, -0.3], [0.18, 0.45, 0.3], iron),
        Cuboid::new([1.82, 0.0, -0.3], [1.9, 0.45, 0.3], iron),
    ];
    for z in [-0.28, -0.12, 0.04] {
        boxes.push(Cuboid::new([0.0, 0.45, z], [2.0, 0.5, z + 0.13], wood));
    }
    for y in [0.62, 0.8] {
        boxes.push(Cuboid::new([0.0, y, 0.24], [2.0, y + 0.12, 0.3], wood));
    }
    SceneDesc {
        name: "bench",
        camera: Camera { position: DVec3::new(4.5, 1.5, 5.5), look_at: DVec3::new(-0.5, 1.2, -1.0), vfov_deg: 50.0, width, height },
        medium: Medium { sigma_s: 0.07, sigma_t: 0.08 },
        phase: AnyPhase::Rayleigh,
        lights: vec![omni([-1.0, 3.15, 0.0], 30.0, [1.0, 0.82, 0.55]), omni([-9.0, 3.15, -12.0], 30.0, [0.85, 0.9, 1.0])],
        ground: Some([0.1, 0.14, 0.08]),
        boxes,
        exposure: 1.0,
    }
}

/// The scene names, in order.
pub const SCENES: [&str; 4] = ["lighthouse", "road", "stage", "bench"];

/// The scene called `name` (one of [`SCENES`]) at `width × height`.
pub fn scene_by_name(name: &str, width: u32, height: u32) -> Option<SceneDesc> {
    match name {
        "lighthouse" => Some(lighthouse(width, height)),
        "road" => Some(road(width, height)),
        "stage" => Some(stage(width, height)),
        "bench" => Some(bench(width, height)),
        _ => None,
    }
}

/// A linear-RGB image, row-major, row 0 at the top.
#[derive(Clone, Debug, PartialEq)]
pub struct Image {
    /// Width in pixels.
    pub width: u32,
    /// Height in pixels.
    pub height: u32,
    /// `width × height` pixels.
    pub pixels: Vec<Rgb>,
}

impl Image {
    /// The largest finite channel value.
    pub fn max_value(&self) -> f64 {
        self.pixels.iter().flatten().copied().filter(|v| v.is_finite()).fold(0.0, f64::max)
    }
}

/// Runs `row(y)` for every row on all cores; progress lines on stderr (`label: rows done /
/// total`) once the work has taken more than a second, when `progress` is set.
fn par_rows<F>(height: u32, label: &str, progress: bool, row: F) -> Vec<Vec<Rgb>>
where
    F: Fn(u32) -> Vec<Rgb> + Sync,
{
    let start = Instant::now();
    let next = AtomicUsize::new(0);
    let done = AtomicUsize::new(0);
    let reported = AtomicUsize::new(0);
    let rows: Mutex<Vec<Option<Vec<Rgb>>>> = Mutex::new(vec![None; height as usize]);
    let threads = std::thread::available_parallelism().map_or(1, |n| n.get()).min(height.max(1) as usize);
    std::thread::scope(|s| {
        for _ in 0..threads {
            s.spawn(|| loop {
                let y = next.fetch_add(1, Ordering::Relaxed);
                if y >= height as usize {
                    break;
                }
                let r = row(y as u32);
                rows.lock().unwrap()[y] = Some(r);
                let n = done.fetch_add(1, Ordering::Relaxed) + 1;
                if progress && start.elapsed().as_secs_f64() > 1.0 {
                    let decile = n * 10 / height as usize;
                    let prev = reported.load(Ordering::Relaxed);
                    if decile > prev && reported.compare_exchange(prev, decile, Ordering::Relaxed, Ordering::Relaxed).is_ok() {
                        eprintln!("airlight: {label}: rows {n}/{height} ({:.1} s)", start.elapsed().as_secs_f64());
                    }
                }
            });
        }
    });
    rows.into_inner().unwrap().into_iter().map(|r| r.expect("every row rendered")).collect()
}

fn assemble(scene: &SceneDesc, rows: Vec<Vec<Rgb>>) -> Image {
    Image { width: scene.camera.width, height: scene.camera.height, pixels: rows.into_iter().flatten().collect() }
}

fn accumulate(px: &mut Rgb, color: Rgb, albedo: Rgb, in_scatter: f64, surface: f64) {
    for c in 0..3 {
        px[c] += color[c] * (in_scatter + albedo[c] * surface);
    }
}

/// The image on the CPU kernel: f64, [`Scene::in_scatter`] (the default, error-controlled
/// path) per (pixel, light) segment. A light exactly on a segment (an infinite value) is kept as `+∞`.
pub fn render_cpu(scene: &SceneDesc, progress: bool) -> Image {
    render_per_light(scene, "cpu", progress, |d, hit, l| {
        let lm = match Scene::new(scene.ray(d, hit), l.light, scene.medium, scene.phase) {
            Ok(s) => s.in_scatter(),
            Err(_) => 0.0,
        };
        (lm, scene.surface_kernel(d, hit, l))
    })
}

/// The image with `(in_scatter, surface)` of each (pixel, light) from `per_light`, in
/// parallel rows with progress labelled `<scene> <what>`.
fn render_per_light<F>(scene: &SceneDesc, what: &str, progress: bool, per_light: F) -> Image
where
    F: Fn(DVec3, &Hit, &Light) -> (f64, f64) + Sync,
{
    let label = format!("{} {what}", scene.name);
    let rows = par_rows(scene.camera.height, &label, progress, |y| {
        (0..scene.camera.width)
            .map(|x| {
                let (d, hit) = scene.primary(x, y);
                let mut px = [0.0; 3];
                for l in &scene.lights {
                    let (lm, surface) = per_light(d, &hit, l);
                    accumulate(&mut px, l.color, hit.albedo, lm, surface);
                }
                px
            })
            .collect()
    });
    assemble(scene, rows)
}

/// The image through the generated shader: every (pixel, light) segment is packed as an f32
/// record ([`layout::pack`]) and all of them run in one call of `shader`, the compute entry
/// point ([`crate::eval::compute_wgsl`] at [`airlight::SHADER_TERMS`]) prepared once with
/// [`Gpu::prepare`](crate::gpu::Gpu::prepare) — [`Prepared::run`] is what
/// [`Gpu::run`](crate::gpu::Gpu::run) does after compiling, which on a CPU Vulkan driver takes
/// longer than the dispatch. The surface term, which the
/// shader does not compute, comes from the f64 CPU kernel as in [`render_cpu`]. A record with
/// status "infinite" (the light on the segment) gives `+∞`.
///
/// # Errors
/// The GPU's error message, or a record the shader reports as invalid.
pub fn render_gpu(scene: &SceneDesc, shader: &Prepared<'_>, progress: bool) -> Result<Image, String> {
    let (w, h) = (scene.camera.width, scene.camera.height);
    let medium = Medium { sigma_s: scene.medium.sigma_s as f32, sigma_t: scene.medium.sigma_t as f32 };
    let phase = cast_phase::<f64, f32>(&scene.phase);
    let lights: Vec<_> = scene.lights.iter().map(|l| cast_light::<f64, f32>(&l.light)).collect();
    let n = scene.lights.len();
    let mut records = Vec::with_capacity(w as usize * h as usize * n * layout::RECORD_SIZE);
    let mut hits = Vec::with_capacity(w as usize * h as usize);
    for y in 0..h {
        for x in 0..w {
            let (d, hit) = scene.primary(x, y);
            let ray = Ray { origin: scene.camera.position.as_vec3(), dir: d.as_vec3(), t_min: 0.0f32, t_max: hit.t as f32 };
            for l in &lights {
                records.extend_from_slice(&layout::pack(&ray, l, &medium, &phase));
            }
            hits.push((d, hit));
        }
    }
    let start = Instant::now();
    if progress {
        eprintln!("airlight: {} gpu: {} records", scene.name, w as usize * h as usize * n);
    }
    let out = shader.run(&records, progress)?;
    if progress && start.elapsed().as_secs_f64() > 1.0 {
        eprintln!("airlight: {} gpu: done ({:.1} s)", scene.name, start.elapsed().as_secs_f64());
    }
    let mut pixels = Vec::with_capacity(hits.len());
    for (i, (d, hit)) in hits.iter().enumerate() {
        let mut px = [0.0; 3];
        for (j, l) in scene.lights.iter().enumerate() {
            let k = (i * n + j) * RESULT_SIZE;
            let (v, status) = layout::unpack_result(&out[k..k + RESULT_SIZE]);
            let lm = match status {
                STATUS_OK => v as f64,
                STATUS_INFINITE => f64::INFINITY,
                _ => return Err(format!("{}: the shader rejected record {} as invalid", scene.name, i * n + j)),
            };
            accumulate(&mut px, l.color, hit.albedo, lm, scene.surface_kernel(*d, hit, l));
        }
        pixels.push(px);
    }
    Ok(Image { width: w, height: h, pixels })
}

// Gauss–Kronrod 7/15 nodes and weights (QUADPACK qk15): abscissae in [0, 1) on one half.
const XGK: [f64; 8] = [
    0.991455371120812639206854697526329,
    0.949107912342758524526189684047851,
    0.864864423359769072789712788640926,
    0.741531185599394439863864773280788,
    0.586087235467691130294144845693013,
    0.405845151377397166906606412076961,
    0.207784955007898467600689403773245,
    0.0,
];
const WGK: [f64; 8] = [
    0.022935322010529224963732008058970,
    0.063092092629978553290700663189204,
    0.104790010322250183839876322541518,
    0.140653259715525918745189590510238,
    0.169004726639267902826583426598550,
    0.190350578064785409913256402421014,
    0.204432940075298892414161999234649,
    0.209482141084727828012999174891714,
];
/// Gauss 7-point weights at `XGK[1], XGK[3], XGK[5], XGK[7]`.
const WG: [f64; 4] = [0.129484966168869693270611432679082, 0.279705391489276667901467771423780, 0.381830050505118944950369775488975, 0.417959183673469387755102040816327];

/// `(Kronrod 15, Gauss 7)` estimates of `∫_a^b f`.
fn gk15(f: &impl Fn(f64) -> f64, a: f64, b: f64) -> (f64, f64) {
    let (c, hw) = (0.5 * (a + b), 0.5 * (b - a));
    let fc = f(c);
    let (mut k, mut g) = (WGK[7] * fc, WG[3] * fc);
    for i in 0..7 {
        let s = f(c - hw * XGK[i]) + f(c + hw * XGK[i]);
        k += WGK[i] * s;
        if i % 2 == 1 {
            g += WG[i / 2] * s;
        }
    }
    (k * hw, g * hw)
}

/// Globally adaptive Gauss–Kronrod over `edges` (QUADPACK's QAG strategy): keeps bisecting
/// the panel with the largest error estimate `|K15 − G7|` until the sum of the estimates is
/// at most `rel_tol` of the sum of the values (the integrand is positive, so that bounds the
/// relative error of every part too), or `max_panels` panels.
fn adapt(f: &impl Fn(f64) -> f64, edges: &[f64], rel_tol: f64, max_panels: usize) -> f64 {
    struct Panel {
        a: f64,
        b: f64,
        k: f64,
        err: f64,
    }
    impl PartialEq for Panel {
        fn eq(&self, o: &Self) -> bool {
            self.err == o.err
        }
    }
    impl Eq for Panel {}
    impl PartialOrd for Panel {
        fn partial_cmp(&self, o: &Self) -> Option<std::cmp::Ordering> {
            Some(self.cmp(o))
        }
    }
    impl Ord for Panel {
        fn cmp(&self, o: &Self) -> std::cmp::Ordering {
            self.err.total_cmp(&o.err)
        }
    }
    let panel = |a: f64, b: f64| {
        let (k, g) = gk15(f, a, b);
        Panel { a, b, k, err: (k - g).abs() }
    };
    let mut heap: std::collections::BinaryHeap<Panel> = edges.windows(2).map(|e| panel(e[0], e[1])).collect();
    let (mut total, mut err): (f64, f64) = heap.iter().fold((0.0, 0.0), |(t, e), p| (t + p.k, e + p.err));
    while heap.len() < max_panels && err > rel_tol * total.abs() && total.is_finite() {
        let Some(worst) = heap.pop() else { break };
        let m = 0.5 * (worst.a + worst.b);
        if !(m > worst.a && m < worst.b) {
            heap.push(worst);
            break;
        }
        let (l, r) = (panel(worst.a, m), panel(m, worst.b));
        total += l.k + r.k - worst.k;
        err += l.err + r.err - worst.err;
        heap.push(l);
        heap.push(r);
    }
    // re-sum: the running sums drift by rounding
    heap.iter().map(|p| p.k).sum()
}

/// Relative tolerance of the reference quadrature (per segment, on the `|K15 − G7|` error
/// estimate, which overstates the error of the returned K15 value by orders of magnitude on
/// smooth panels).
pub const REFERENCE_TOL: f64 = 1e-9;

/// Panel budget of the reference quadrature per segment (never reached in the four scenes).
const MAX_PANELS: usize = 4000;

/// `L_m` of one segment by brute-force quadrature of the contract integral (docs/DESIGN.md §1),
///
/// ```text
/// L_m = σs·I·∫_{t0}^{t1} e^{−σt(t−t0)} · e^{−σt r}/r² · D(c) · P(μ) dt,
/// r = |x(t) − p|, c = (x − p)·a/r, μ = −(x − p)·d/r,
/// ```
///
/// with none of the kernel's closed forms: `D` and `P` are evaluated pointwise through
/// [`LightDistribution::eval`] and [`PhaseFunction::eval`] (their definitions). The variable
/// is `u = atan((t − x_h)/h)` (`x_h` the foot of the perpendicular from the light to the ray,
/// `h` its length): `dt/r² = du/h`, so the `1/r²` peak becomes a bounded integrand on a finite
/// interval, `t1 = ∞` included (`u1 = π/2`). It is integrated by adaptive Gauss–Kronrod 7/15
/// from 16 equal starting panels, globally adaptive, until the summed error estimates are at
/// most `rel_tol` of the integral. `+∞` when the light
/// lies on the segment.
pub fn reference_in_scatter(
    origin: DVec3,
    dir: DVec3,
    t0: f64,
    t1: f64,
    light: &PointLight<f64, AnyDistribution<f64>>,
    medium: &Medium<f64>,
    phase: &AnyPhase<f64>,
    rel_tol: f64,
) -> f64 {
    let d = dir.normalize();
    let p = light.position;
    let ax = DVec3::from_array(light.distribution.axis()).normalize();
    let v = p - origin;
    let x_h = v.dot(d);
    let h = (v - d * x_h).length();
    let scale = medium.sigma_s * light.intensity;
    if scale == 0.0 || !(t1 > t0) {
        return 0.0;
    }
    let st = medium.sigma_t;
    if h <= 1e-12 * v.length().max(1.0) {
        if x_h >= t0 && x_h <= t1 {
            return f64::INFINITY;
        }
        // The light on the ray's line outside the segment: `r = |t − x_h|`, no peak inside;
        // integrate in `s ∈ [0, 1)`, `t = t0 + s/(1 − s)`, clipped to `t1`.
        let s1 = if t1.is_finite() { (t1 - t0) / (1.0 + t1 - t0) } else { 1.0 };
        let f = |s: f64| -> f64 {
            let t = t0 + s / (1.0 - s);
            let w = origin + d * t - p;
            let r = w.length();
            let c = w.dot(ax) / r;
            let mu = -w.dot(d) / r;
            let jac = 1.0 / ((1.0 - s) * (1.0 - s));
            let val = (-st * ((t - t0) + r)).exp() / (r * r) * jac;
            if val == 0.0 || !val.is_finite() {
                return 0.0;
            }
            val * LightDistribution::<f64>::eval(&light.distribution, c) * PhaseFunction::<f64>::eval(phase, mu)
        };
        let edges: Vec<f64> = (0..=16).map(|i| s1 * i as f64 / 16.0).collect();
        return scale * adapt(&f, &edges, rel_tol, MAX_PANELS);
    }
    let g = |u: f64| -> f64 {
        let t = x_h + h * u.tan();
        if !t.is_finite() {
            return 0.0;
        }
        let w = origin + d * t - p;
        let r = w.length();
        let att = (-st * ((t - t0) + r)).exp();
        if att == 0.0 {
            return 0.0;
        }
        let c = w.dot(ax) / r;
        let mu = -w.dot(d) / r;
        att * LightDistribution::<f64>::eval(&light.distribution, c) * PhaseFunction::<f64>::eval(phase, mu)
    };
    let u0 = ((t0 - x_h) / h).atan();
    let u1 = if t1.is_finite() { ((t1 - x_h) / h).atan() } else { std::f64::consts::FRAC_PI_2 };
    const PANELS: usize = 16;
    let du = (u1 - u0) / PANELS as f64;
    let edges: Vec<f64> = (0..=PANELS).map(|i| if i == PANELS { u1 } else { u0 + du * i as f64 }).collect();
    scale / h * adapt(&g, &edges, rel_tol, MAX_PANELS)
}

/// Surface term for the reference, written out from paper eq. 7 (no kernel code):
/// `e^{−σt t_hit} · e^{−σt r_b}/r_b² · I·D(c_b) · max(0, ω_i·n)/π`.
fn surface_reference(scene: &SceneDesc, d: DVec3, hit: &Hit, light: &Light) -> f64 {
    if !hit.t.is_finite() {
        return 0.0;
    }
    let x = scene.camera.position + d * hit.t;
    let to_light = light.light.position - x;
    let r = to_light.length();
    if !(r > 0.0) {
        return 0.0;
    }
    let wi = to_light / r;
    let cos = wi.dot(hit.normal).max(0.0);
    let ax = DVec3::from_array(light.light.distribution.axis()).normalize();
    let dist = LightDistribution::<f64>::eval(&light.light.distribution, -wi.dot(ax));
    let st = scene.medium.sigma_t;
    (-st * (hit.t + r)).exp() / (r * r) * light.light.intensity * dist * cos * std::f64::consts::FRAC_1_PI
}

/// The brute-force reference image: [`reference_in_scatter`] with [`REFERENCE_TOL`] per
/// (pixel, light) segment and the surface term written out from eq. 7.
pub fn render_reference(scene: &SceneDesc, progress: bool) -> Image {
    render_per_light(scene, "reference", progress, |d, hit, l| {
        let lm = reference_in_scatter(scene.camera.position, d, 0.0, hit.t, &l.light, &scene.medium, &scene.phase, REFERENCE_TOL);
        (lm, surface_reference(scene, d, hit, l))
    })
}

/// Per-pixel relative error of `test` against `reference`: the largest over the channels of
/// `|test − ref| / max(ref, floor)`. Two equal infinities count as 0.
pub fn relative_errors(test: &Image, reference: &Image, floor: f64) -> Vec<f64> {
    test.pixels
        .iter()
        .zip(&reference.pixels)
        .map(|(a, b)| {
            (0..3)
                .map(|c| {
                    if a[c] == b[c] {
                        0.0
                    } else {
                        let e = (a[c] - b[c]).abs() / b[c].max(floor);
                        if e.is_nan() { f64::INFINITY } else { e }
                    }
                })
                .fold(0.0, f64::max)
        })
        .collect()
}

/// The error floor for a scene: `1e-4 / exposure`, i.e. a ten-thousandth of the radiance the
/// tone map shows at 63 % of white (1/40 of one 8-bit display step near black); smaller
/// absolute differences are invisible.
pub fn error_floor(scene: &SceneDesc) -> f64 {
    1e-4 / scene.exposure
}

/// Maximum and median of a list of errors.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ErrorStats {
    /// Largest error.
    pub max: f64,
    /// Median error.
    pub median: f64,
}

/// Max and median of `errors` (`NaN` counts as `+∞`).
pub fn error_stats(errors: &[f64]) -> ErrorStats {
    let mut v: Vec<f64> = errors.iter().map(|e| if e.is_nan() { f64::INFINITY } else { *e }).collect();
    v.sort_by(f64::total_cmp);
    let median = if v.is_empty() { 0.0 } else { v[v.len() / 2] };
    ErrorStats { max: v.last().copied().unwrap_or(0.0), median }
}

/// The heat map's scale: `log10` of the relative error from this …
pub const HEAT_LOG10_MIN: f64 = -7.0;
/// … to this (errors outside are clamped).
pub const HEAT_LOG10_MAX: f64 = -1.0;

/// False colour of a relative error on the log scale [`HEAT_LOG10_MIN`]..[`HEAT_LOG10_MAX`]:
/// black → blue → green → yellow → red (an error of exactly 0 is black).
pub fn heat_color(err: f64) -> [u8; 3] {
    let x = if err > 0.0 { ((err.log10() - HEAT_LOG10_MIN) / (HEAT_LOG10_MAX - HEAT_LOG10_MIN)).clamp(0.0, 1.0) } else { 0.0 };
    const STOPS: [[f64; 3]; 5] = [[0.0, 0.0, 0.0], [0.0, 0.2, 1.0], [0.0, 0.85, 0.2], [1.0, 0.95, 0.0], [1.0, 0.0, 0.0]];
    let s = x * 4.0;
    let i = (s.floor() as usize).min(3);
    let f = s - i as f64;
    let mut out = [0u8; 3];
    for c in 0..3 {
        out[c] = ((STOPS[i][c] * (1.0 - f) + STOPS[i + 1][c] * f) * 255.0).round() as u8;
    }
    out
}

/// 8-bit RGB of the error heat map (with a colour bar of the scale along the bottom 4 % of
/// rows, left = `10^HEAT_LOG10_MIN`, right = `10^HEAT_LOG10_MAX`).
pub fn heat_map(errors: &[f64], width: u32, height: u32) -> Vec<u8> {
    let bar = (height / 25).max(2).min(height);
    let mut out = Vec::with_capacity(width as usize * height as usize * 3);
    for y in 0..height {
        for x in 0..width {
            let rgb = if y >= height - bar {
                let l = HEAT_LOG10_MIN + (HEAT_LOG10_MAX - HEAT_LOG10_MIN) * (x as f64 + 0.5) / width as f64;
                heat_color(10f64.powf(l))
            } else {
                heat_color(errors[(y * width + x) as usize])
            };
            out.extend_from_slice(&rgb);
        }
    }
    out
}

fn srgb(v: f64) -> u8 {
    let v = v.clamp(0.0, 1.0);
    let e = if v <= 0.0031308 { 12.92 * v } else { 1.055 * v.powf(1.0 / 2.4) - 0.055 };
    (e * 255.0).round() as u8
}

/// 8-bit sRGB of an image: `1 − e^{−x·exposure}` per channel, then the sRGB curve.
pub fn tone_map(image: &Image, exposure: f64) -> Vec<u8> {
    image
        .pixels
        .iter()
        .flat_map(|p| p.map(|v| srgb(if v.is_nan() { 1.0 } else { 1.0 - (-v.max(0.0) * exposure).exp() })))
        .collect()
}

/// Writes 8-bit RGB data as a PNG file.
///
/// # Errors
/// The I/O or encoder error as text.
pub fn write_png(path: &Path, width: u32, height: u32, rgb: &[u8]) -> Result<(), String> {
    let file = std::fs::File::create(path).map_err(|e| format!("{}: {e}", path.display()))?;
    let mut enc = png::Encoder::new(std::io::BufWriter::new(file), width, height);
    enc.set_color(png::ColorType::Rgb);
    enc.set_depth(png::BitDepth::Eight);
    let mut w = enc.write_header().map_err(|e| format!("{}: {e}", path.display()))?;
    w.write_image_data(rgb).map_err(|e| format!("{}: {e}", path.display()))?;
    w.finish().map_err(|e| format!("{}: {e}", path.display()))
}
