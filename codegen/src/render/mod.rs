//! Pictures: the paper's kinds of scenes — a lighthouse with a two-lobed beam in
//! thick brume, a foggy road with headlights and a streetlamp, a stage under three coloured
//! spotlights, a park bench in Rayleigh mist — rendered four ways:
//!
//! * [`render_cpu`]: the CPU kernel in f64, its default error-controlled path;
//! * [`render_gpu`]: the committed compute shader (`shaders-out/wgsl/airlight_8.wgsl`, f32, 8
//!   nodes per panel) through wgpu, every (pixel, light) segment one record of [`airlight_shaders::layout`];
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
//!
//! One file per part: [`world`] (camera, geometry, ray casts), [`scenes`] (the four scenes),
//! this module (the three renderers), [`reference`] (the quadrature), [`picture`] (errors,
//! heat maps, PNG).

pub mod picture;
pub mod reference;
pub mod scenes;
pub mod world;

pub use picture::{error_floor, error_stats, heat_color, heat_map, relative_errors, tone_map, write_png, ErrorStats, HEAT_LOG10_MAX, HEAT_LOG10_MIN};
pub use reference::{reference_in_scatter, REFERENCE_TOL};
pub use scenes::{bench, lighthouse, road, scene_by_name, stage, SCENES};
pub use world::{Camera, Cuboid, Hit, Light, Rgb, SceneDesc};

use airlight_shaders::gpu::Prepared;
use airlight_shaders::layout::{self, RESULT_SIZE, STATUS_INFINITE, STATUS_OK};
use airlight::glam::DVec3;
use airlight::record::{cast_light, cast_phase};
use airlight::{Medium, Ray, Scene};
use rayon::prelude::*;
use reference::surface_reference;
use std::sync::atomic::{AtomicUsize, Ordering};
use std::time::Instant;

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

/// Runs `row(y)` for every row on all cores (rayon); progress lines on stderr (`label: rows
/// done / total`) once the work has taken more than a second, when `progress` is set.
fn par_rows<F>(height: u32, label: &str, progress: bool, row: F) -> Vec<Vec<Rgb>>
where
    F: Fn(u32) -> Vec<Rgb> + Sync,
{
    let start = Instant::now();
    let (done, reported) = (AtomicUsize::new(0), AtomicUsize::new(0));
    (0..height)
        .into_par_iter()
        .map(|y| {
            let r = row(y);
            let n = done.fetch_add(1, Ordering::Relaxed) + 1;
            if progress && start.elapsed().as_secs_f64() > 1.0 {
                let decile = n * 10 / height as usize;
                let prev = reported.load(Ordering::Relaxed);
                if decile > prev && reported.compare_exchange(prev, decile, Ordering::Relaxed, Ordering::Relaxed).is_ok() {
                    eprintln!("airlight: {label}: rows {n}/{height} ({:.1} s)", start.elapsed().as_secs_f64());
                }
            }
            r
        })
        .collect()
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
/// point ([`airlight_shaders::targets::compute_wgsl`] at [`airlight::SHADER_NODES`]) prepared once with
/// [`Gpu::prepare`](airlight_shaders::gpu::Gpu::prepare) — [`Prepared::run`] is what
/// [`Gpu::run`](airlight_shaders::gpu::Gpu::run) does after compiling, which on a CPU Vulkan driver takes
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

/// The brute-force reference image: [`reference_in_scatter`] with [`REFERENCE_TOL`] per
/// (pixel, light) segment and the surface term written out from eq. 7.
pub fn render_reference(scene: &SceneDesc, progress: bool) -> Image {
    render_per_light(scene, "reference", progress, |d, hit, l| {
        let lm = reference_in_scatter(scene.camera.position, d, 0.0, hit.t, &l.light, &scene.medium, &scene.phase, REFERENCE_TOL);
        (lm, surface_reference(scene, d, hit, l))
    })
}
