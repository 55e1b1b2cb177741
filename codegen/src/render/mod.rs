//! Pictures: the source papers' kinds of scenes — a lighthouse with a two-lobed beam in
//! thick brume, a foggy road with headlights and a streetlamp, a stage under three coloured
//! spotlights, a park bench in Rayleigh mist, a street with a fluorescent tube and fog-lit
//! walls — rendered four ways:
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
//! pixel gets `colour × (L_m(0, t_hit) + e^{−σt t_hit} · (L_s + L_{p,a}))` with `L_m` the
//! in-scattered air-light over the visible segment, `L_s` the paper's eq. 7 surface term of a
//! Lambertian surface (`brdf = albedo/π`; a tube's integrated over it) and, in a scene with
//! [`SceneDesc::fog_lit_surfaces`], `L_{p,a}` the air-light the surface receives from an omni
//! light through the fog (docs/DESIGN.md §11); rays that hit nothing see the glow over `[0, ∞)`.
//!
//! One file per part: [`world`] (camera, geometry, ray casts), [`scenes`] (the five scenes),
//! this module (the three renderers), [`mod@reference`] (the quadrature), [`picture`] (errors,
//! heat maps, PNG).

pub mod picture;
pub mod reference;
pub mod scenes;
pub mod world;

pub use picture::{error_floor, error_stats, heat_color, heat_map, relative_errors, tone_map, write_png, ErrorStats, HEAT_LOG10_MAX, HEAT_LOG10_MIN};
pub use reference::{reference_air_light, reference_in_scatter, REFERENCE_TOL};
pub use scenes::{bench, lighthouse, road, scene_by_name, stage, street, SCENES};
pub use world::{Camera, Cuboid, Hit, Light, Rgb, SceneDesc};

use airlight_shaders::gpu::Prepared;
use airlight_shaders::layout::{self, RESULT_SIZE, STATUS_INFINITE, STATUS_OK};
use airlight::glam::DVec3;
use airlight::record::{cast_light, cast_phase};
use airlight::{Brdf, Medium, Ray, SegmentLight, SegmentScene, Surface, SurfaceScene};
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

/// The image on the CPU kernel: f64, the default, error-controlled paths per (pixel, light)
/// segment ([`airlight::Scene::in_scatter`], [`airlight::SegmentScene::in_scatter`]) and surface point
/// ([`airlight::SurfaceScene::air_light`]). A light exactly on a segment (an infinite value) is
/// kept as `+∞`.
pub fn render_cpu(scene: &SceneDesc, progress: bool) -> Image {
    render_per_light(scene, "cpu", progress, |d, hit, l| {
        (scene.in_scatter_kernel(d, hit, l), scene.surface_kernel(d, hit, l) + scene.air_light_kernel(d, hit, l))
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
/// record ([`layout::pack`], [`layout::pack_segment`] for a tube), and so is every surface
/// point a light's air-light reaches ([`layout::pack_surface`]); all of them run in one call of
/// `shader`, the compute entry
/// point ([`airlight_shaders::targets::compute_wgsl`] at [`airlight::SHADER_NODES`]) prepared once with
/// [`Gpu::prepare`](airlight_shaders::gpu::Gpu::prepare) — [`Prepared::run`] is what
/// [`Gpu::run`](airlight_shaders::gpu::Gpu::run) does after compiling, which on a CPU Vulkan driver takes
/// longer than the dispatch. The direct surface term, which the
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
    // per pixel: its direction and hit, and per light whether its glow's record is followed by
    // one of its air-light on the surface
    let mut hits = Vec::with_capacity(w as usize * h as usize);
    for y in 0..h {
        for x in 0..w {
            let (d, hit) = scene.primary(x, y);
            let ray = Ray { origin: scene.camera.position.as_vec3(), dir: d.as_vec3(), t_min: 0.0f32, t_max: hit.t as f32 };
            let mut surfaces = Vec::new();
            for (l, light) in lights.iter().zip(&scene.lights) {
                match light.tube() {
                    Some(tube) => {
                        let tube = SegmentLight { a: tube.a.as_vec3(), b: tube.b.as_vec3(), intensity: tube.intensity as f32, distribution: l.distribution };
                        let s = SegmentScene::new(ray, tube, medium, phase).map_err(|e| format!("{}: tube: {e}", scene.name))?;
                        records.extend_from_slice(&layout::pack_segment(&s));
                    }
                    None => records.extend_from_slice(&layout::pack(&ray, l, &medium, &phase)),
                }
                let lit = scene.air_lit(&hit, light);
                if lit {
                    let surface = Surface { position: scene.surface_point(d, &hit).as_vec3(), normal: hit.normal.as_vec3() };
                    let s = SurfaceScene::new(surface, Brdf::Lambert { albedo: 1.0f32 }, *l, medium, phase).map_err(|e| format!("{}: surface point: {e}", scene.name))?;
                    records.extend_from_slice(&layout::pack_surface(&s).ok_or_else(|| format!("{}: a surface the shader has not", scene.name))?);
                }
                surfaces.push(lit);
            }
            hits.push((d, hit, surfaces));
        }
    }
    let start = Instant::now();
    if progress {
        eprintln!("airlight: {} gpu: {} records", scene.name, records.len() / layout::RECORD_SIZE);
    }
    let out = shader.run(&records, progress)?;
    if progress && start.elapsed().as_secs_f64() > 1.0 {
        eprintln!("airlight: {} gpu: done ({:.1} s)", scene.name, start.elapsed().as_secs_f64());
    }
    let result = |k: usize| -> Result<f64, String> {
        let (v, status) = layout::unpack_result(&out[k * RESULT_SIZE..(k + 1) * RESULT_SIZE]);
        match status {
            STATUS_OK => Ok(v as f64),
            STATUS_INFINITE => Ok(f64::INFINITY),
            _ => Err(format!("{}: the shader rejected record {k} as invalid", scene.name)),
        }
    };
    let mut pixels = Vec::with_capacity(hits.len());
    let mut k = 0;
    for (d, hit, surfaces) in &hits {
        let mut px = [0.0; 3];
        for (l, &lit) in scene.lights.iter().zip(surfaces) {
            let lm = result(k)?;
            k += 1;
            let air = if lit {
                k += 1;
                (-scene.medium.sigma_t * hit.t).exp() * result(k - 1)?
            } else {
                0.0
            };
            accumulate(&mut px, l.color, hit.albedo, lm, scene.surface_kernel(*d, hit, l) + air);
        }
        pixels.push(px);
    }
    Ok(Image { width: w, height: h, pixels })
}

/// The brute-force reference image: [`reference_in_scatter`] with [`REFERENCE_TOL`] per
/// (pixel, light) segment (a tube's integrated over it), the surface term written out from
/// eq. 7 and the surface's air-light by [`reference_air_light`].
pub fn render_reference(scene: &SceneDesc, progress: bool) -> Image {
    render_per_light(scene, "reference", progress, |d, hit, l| {
        let lm = l.over_emitter(REFERENCE_TOL, |point| reference_in_scatter(scene.camera.position, d, 0.0, hit.t, point, &scene.medium, &scene.phase, REFERENCE_TOL));
        let direct = l.over_emitter(REFERENCE_TOL, |point| surface_reference(scene, d, hit, point));
        let air = if scene.air_lit(hit, l) {
            (-scene.medium.sigma_t * hit.t).exp() * reference_air_light(scene.surface_point(d, hit), hit.normal, &l.light, &scene.medium, &scene.phase, REFERENCE_TOL)
        } else {
            0.0
        };
        (lm, direct + air)
    })
}
