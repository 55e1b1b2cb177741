//! ns per evaluation of `L_m`, side by side over the same 256 rays: this kernel (Chebyshev,
//! and Taylor), the paper's algorithm as published (its eq. 27 `Ei`, Taylor expansion), and the
//! seeds' `atan` form (isotropic, no extinction: the cheapest analytic glow). Scene
//! construction and validation are outside the timed loop.
//!
//! `cargo bench -p airlight --bench in_scatter`; `python3 scripts/bench_table.py` prints the
//! ratio table from criterion's estimates.

use airlight::glam::{DVec3, Vec3};
use airlight::light::{AnyDistribution, TwoLobed};
use airlight::phase::{AnyPhase, HenyeyGreenstein};
use airlight::{Expansion, Medium, PointLight, Ray, Real, Scene};
use criterion::{black_box, criterion_group, criterion_main, Criterion};
use std::time::Duration;

type S<T> = Scene<T, AnyDistribution<T>, AnyPhase<T>>;

/// 256 rays through a street-lamp-like scene: origins on a line, directions fanning out,
/// light 1–4 units off the rays, media from thin to moderately thick.
fn scenes<T: Real>(aniso: bool, v: impl Fn([f64; 3]) -> T::Vec3) -> Vec<S<T>> {
    let mut out = Vec::new();
    let mut seed = 7u64;
    let mut rnd = || {
        seed = seed.wrapping_mul(6364136223846793005).wrapping_add(1442695040888963407);
        (seed >> 11) as f64 / (1u64 << 53) as f64
    };
    for _ in 0..256 {
        let ray = Ray {
            origin: v([0.0, 0.0, 0.0]),
            dir: v([1.0, 0.2 * rnd() - 0.1, 0.2 * rnd() - 0.1]),
            t_min: T::lit(0.0),
            t_max: T::lit(5.0 + 60.0 * rnd()),
        };
        let distribution = if aniso {
            AnyDistribution::TwoLobed(TwoLobed { axis: v([0.0, -1.0, 0.0]), power: 4 })
        } else {
            AnyDistribution::Omni
        };
        let light = PointLight { position: v([40.0 * rnd() - 5.0, 1.0 + 3.0 * rnd(), rnd()]), intensity: T::lit(100.0), distribution };
        let medium = Medium { sigma_s: T::lit(0.05), sigma_t: T::lit(0.01 + 0.3 * rnd()) };
        let phase = if aniso { AnyPhase::HenyeyGreenstein(HenyeyGreenstein { g: T::lit(0.5) }) } else { AnyPhase::Isotropic };
        out.push(Scene::new(ray, light, medium, phase).unwrap());
    }
    out
}

fn group<T: Real>(c: &mut Criterion, name: &str, v: impl Fn([f64; 3]) -> T::Vec3 + Copy, eps: T) {
    for aniso in [false, true] {
        let sc = scenes::<T>(aniso, v);
        let kind = if aniso { "aniso" } else { "iso" };
        let mut g = c.benchmark_group(format!("{name}/{kind}"));
        g.measurement_time(Duration::from_secs(2)).warm_up_time(Duration::from_millis(500)).sample_size(20);
        let n = sc.len() as u64;
        g.throughput(criterion::Throughput::Elements(n));
        g.bench_function("ours_4", |b| b.iter(|| sc.iter().map(|s| black_box(s).in_scatter_with::<4>(Expansion::Chebyshev)).fold(T::zero(), |a, x| a + x)));
        g.bench_function("ours_6", |b| b.iter(|| sc.iter().map(|s| black_box(s).in_scatter_with::<6>(Expansion::Chebyshev)).fold(T::zero(), |a, x| a + x)));
        g.bench_function("taylor_6", |b| b.iter(|| sc.iter().map(|s| black_box(s).in_scatter_with::<6>(Expansion::Taylor)).fold(T::zero(), |a, x| a + x)));
        g.bench_function("paper_4", |b| b.iter(|| sc.iter().map(|s| black_box(s).in_scatter_paper::<4>(eps, 100)).fold(T::zero(), |a, x| a + x)));
        g.bench_function("paper_6", |b| b.iter(|| sc.iter().map(|s| black_box(s).in_scatter_paper::<6>(eps, 100)).fold(T::zero(), |a, x| a + x)));
        g.bench_function("atan_form", |b| {
            b.iter(|| sc.iter().map(|s| { let s = black_box(s); airlight::atan_form(s.ray(), s.light().position, s.light().intensity, s.medium().sigma_s) }).fold(T::zero(), |a, x| a + x))
        });
        g.finish();
    }
}

fn benches(c: &mut Criterion) {
    group::<f32>(c, "f32", |a| Vec3::new(a[0] as f32, a[1] as f32, a[2] as f32), 1e-6);
    group::<f64>(c, "f64", DVec3::from_array, 1e-12);
}

criterion_group!(all, benches);
criterion_main!(all);
