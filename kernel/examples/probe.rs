use ::airlight::glam::Vec3;
use ::airlight::light::*;
use ::airlight::phase::*;
use ::airlight::{Expansion, Medium, PointLight, Ray, Scene};
use std::hint::black_box;
fn main() {
    let mut scenes = Vec::new();
    let mut seed = 1u64;
    let mut rnd = || { seed = seed.wrapping_mul(6364136223846793005).wrapping_add(1442695040888963407); ((seed >> 33) as f32) / (1u64 << 31) as f32 };
    for _ in 0..1024 {
        let ray = Ray { origin: Vec3::ZERO, dir: Vec3::new(1.0, 0.1 * rnd(), 0.1 * rnd()), t_min: 0.0, t_max: 5.0 + 50.0 * rnd() };
        let light = PointLight { position: Vec3::new(30.0 * rnd() - 5.0, 0.1 + 3.0 * rnd(), 2.0 * rnd()), intensity: 100.0, distribution: Omni };
        let m = Medium { sigma_s: 0.05, sigma_t: 0.01 + 0.5 * rnd() };
        scenes.push(Scene::new(ray, light, m, Isotropic).unwrap());
    }
    let t = std::time::Instant::now();
    let mut acc = 0.0f32;
    let reps = 2000;
    for _ in 0..reps { for s in &scenes { acc += black_box(s).in_scatter_with::<4>(Expansion::Chebyshev); } }
    let ours = t.elapsed().as_nanos() as f64 / (reps * 1024) as f64;
    let t = std::time::Instant::now();
    for _ in 0..reps { for s in &scenes { let s = black_box(s); acc += ::airlight::atan_form(s.ray(), s.light().position, 100.0, 0.05); } }
    let atan = t.elapsed().as_nanos() as f64 / (reps * 1024) as f64;
    println!("ours {ours:.1} ns, atan {atan:.1} ns, ratio {:.2} ({acc})", ours / atan);
}
