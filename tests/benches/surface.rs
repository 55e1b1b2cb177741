//! Surface radiance from air-light against one ray integral, side by side in one process, on the
//! records of tests/reference/surface.jsonl (nested-quadrature references;
//! tests/reference/gen_surface.py).
//!
//! Accuracy first, outside the timed loops: per class and precision, the largest error
//! `|x − exact| / max(|exact|, τ·scale)` (`τ` = 1e-10 in f64, 1e-4 in f32; `scale`: the value
//! with the BRDF at its maximum, from the references) of `SurfaceScene::air_light()` (the
//! default), of `air_light_counted(1e-3)` and of `air_light_counted` at the loosest tolerance of
//! 1e-1, 3e-2, … 1e-5 (half decades) whose largest error over the class is at most 1e-3 (*at 1e-3*, the targets'
//! level; picked knowing the class's errors, as the classes bench picks the kernel's), and the
//! ray integrals each evaluates. Timed, per class, over all its records per iteration:
//! `surface_default`, `surface_1e-3`, `surface_at_1e-3`, and `ray_default` / `ray_1e-3`: the
//! air-light along one ray, from the surface point along its normal to infinity, by the default
//! path and at tolerance 1e-3 (the cost a surface point is compared with).
//!
//! `cargo bench -p airlight-tests --bench surface && python3 scripts/surface_table.py`

use airlight::light::AnyDistribution;
use airlight::panels::Control;
use airlight::phase::AnyPhase;
use airlight::{default_control, Ray, Real, Scene, SurfaceScene};
use airlight_tests::{reference_lines, surface_record};
use criterion::{black_box, criterion_group, criterion_main, Criterion};
use std::collections::BTreeMap;
use std::fmt::Write as _;
use std::time::Duration;

type Surf<T> = SurfaceScene<T, AnyDistribution<T>, AnyPhase<T>>;
type Point<T> = Scene<T, AnyDistribution<T>, AnyPhase<T>>;

struct Class<T: Real> {
    surfaces: Vec<Surf<T>>,
    rays: Vec<Point<T>>,
    exact: Vec<f64>,
    floor: Vec<f64>,
}

fn load<T: Real>() -> BTreeMap<String, Class<T>> {
    let mut out: BTreeMap<String, Class<T>> = BTreeMap::new();
    for v in reference_lines("surface.jsonl") {
        let s = surface_record::<T>(&v);
        let ray = Ray { origin: s.surface().position, dir: s.surface().normal, t_min: T::zero(), t_max: T::infinity() };
        let point = Scene::new(ray, *s.light(), *s.medium(), *s.phase()).unwrap();
        let class = out.entry(v["category"].as_str().unwrap().to_string()).or_insert(Class { surfaces: vec![], rays: vec![], exact: vec![], floor: vec![] });
        let tau = if T::epsilon() > T::lit(1e-10) { 1e-4 } else { 1e-10 };
        class.surfaces.push(s);
        class.rays.push(point);
        class.exact.push(v["surface_air_light"].as_f64().unwrap());
        class.floor.push(tau * v["scale"].as_f64().unwrap());
    }
    out
}

fn run<T: Real>(crit: &mut Criterion, label: &str, report: &mut String) {
    let loose = Control { tolerance: T::lit(1e-3), ..default_control() };
    for (name, class) in load::<T>() {
        let worst = |f: &dyn Fn(&Surf<T>) -> (T, usize)| {
            let mut e = 0.0f64;
            let mut rays = vec![];
            for ((s, exact), floor) in class.surfaces.iter().zip(&class.exact).zip(&class.floor) {
                let (x, n) = f(s);
                e = e.max((x.to_f64_exact() - exact).abs() / exact.max(*floor));
                rays.push(n);
            }
            rays.sort();
            (e, rays[rays.len() / 2], rays[rays.len() - 1])
        };
        let (e_default, med_default, max_default) = worst(&|s| s.air_light_counted(airlight::extended::outer_tolerance()));
        let (e_loose, med_loose, max_loose) = worst(&|s| s.air_light_counted(T::lit(1e-3)));
        // at error 1e-3: the loosest tolerance whose largest error over the class is at most 1e-3
        // (as the classes bench picks the kernel's), or the finest tried
        let level = LEVEL_TOLERANCES.iter().copied().find(|&t| worst(&|s| s.air_light_counted(T::lit(t))).0 <= LEVEL).unwrap_or(LEVEL_TOLERANCES[LEVEL_TOLERANCES.len() - 1]);
        let (e_level, med_level, max_level) = worst(&|s| s.air_light_counted(T::lit(level)));
        writeln!(
            report,
            "{{\"precision\":\"{label}\",\"class\":\"{name}\",\"records\":{},\"default\":{e_default:e},\"default_rays\":[{med_default},{max_default}],\"loose\":{e_loose:e},\"loose_rays\":[{med_loose},{max_loose}],\"level_tolerance\":{level:e},\"level\":{e_level:e},\"level_rays\":[{med_level},{max_level}]}}",
            class.surfaces.len()
        )
        .unwrap();
        let mut g = crit.benchmark_group(format!("surface_{label}_{name}"));
        g.bench_function("surface_default", |b| b.iter(|| class.surfaces.iter().map(|s| black_box(s).air_light()).fold(T::zero(), |a, x| a + x)));
        g.bench_function("surface_1e-3", |b| b.iter(|| class.surfaces.iter().map(|s| black_box(s).air_light_counted(T::lit(1e-3)).0).fold(T::zero(), |a, x| a + x)));
        g.bench_function("surface_at_1e-3", |b| b.iter(|| class.surfaces.iter().map(|s| black_box(s).air_light_counted(T::lit(level)).0).fold(T::zero(), |a, x| a + x)));
        g.bench_function("ray_default", |b| b.iter(|| class.rays.iter().map(|s| black_box(s).in_scatter()).fold(T::zero(), |a, x| a + x)));
        g.bench_function("ray_1e-3", |b| b.iter(|| class.rays.iter().map(|s| black_box(s).in_scatter_controlled(loose).0).fold(T::zero(), |a, x| a + x)));
        g.finish();
    }
}

/// The error level of the targets ("surface radiance at 1e-3"), and the tolerances tried for it,
/// loosest first.
const LEVEL: f64 = 1e-3;
const LEVEL_TOLERANCES: [f64; 9] = [1e-1, 3e-2, 1e-2, 3e-3, 1e-3, 3e-4, 1e-4, 3e-5, 1e-5];

fn benches(crit: &mut Criterion) {
    let mut report = String::new();
    run::<f64>(crit, "f64", &mut report);
    run::<f32>(crit, "f32", &mut report);
    let dir = airlight_tests::repo_root().join("target/criterion");
    std::fs::create_dir_all(&dir).unwrap();
    std::fs::write(dir.join("surface_accuracy.jsonl"), report).unwrap();
}

criterion_group! {
    name = group;
    config = Criterion::default().sample_size(10).warm_up_time(Duration::from_millis(300)).measurement_time(Duration::from_millis(1500));
    targets = benches
}
criterion_main!(group);
