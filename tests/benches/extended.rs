//! Extended lights against one point light, side by side in one process: segment lights on the
//! records of tests/reference/extended.jsonl (nested mpmath references;
//! tests/reference/gen_extended.py), discs, rectangles and spheres on those of
//! tests/reference/area.jsonl (tests/reference/gen_area.py).
//!
//! Accuracy first, outside the timed loops: per class and precision, the largest relative error
//! of the default (`in_scatter()`, the outer tolerance `extended::outer_tolerance`) and of
//! `in_scatter_counted(1e-3)` against the references, and what each evaluates (a segment:
//! Gauss–Kronrod panels; an area light: point lights); for segments also *at 1e-3* (the speed
//! target's level): the loosest tolerance of 1e-1, 3e-2, 1e-2, 3e-3, 1e-3 whose largest error over the class
//! is at most 1e-3, picked knowing the class's errors as the classes bench picks the kernel's.
//! Timed, per class, over all its records per iteration: `emitter_default`, `emitter_1e-3`, for
//! segments `emitter_at_1e-3`, for area lights `emitter_bounded` (`AreaScene::in_scatter_bounded`,
//! its largest error reported as `bounded`), and `point`: the default point light of
//! the emitter's whole output at its middle (a segment: intensity `I·ℓ` at its midpoint; a disc
//! or rectangle: the Lambertian point light of intensity `L_e·area` at its centre; a sphere: the
//! isotropic one of intensity `π R² L_e` at its centre), the cost an emitter is compared with.
//!
//! `cargo bench -p airlight-tests --bench extended && python3 scripts/extended_table.py`

use airlight::light::{Lambertian, Omni};
use airlight::{Emitter, PointLight, Real, Scene};
use airlight_codegen::scene_json::{parse_any_value, AnyRecord};
use airlight_tests::reference_lines;
use criterion::{black_box, criterion_group, criterion_main, Criterion};
use std::collections::BTreeMap;
use std::fmt::Write as _;
use std::time::Duration;

/// One emitter of a class: its counted evaluation at a tolerance, and the point light it is
/// compared with.
struct Record<T> {
    counted: Box<dyn Fn(T) -> (T, usize)>,
    point: Box<dyn Fn() -> T>,
    /// An area light's bounded method (`AreaScene::in_scatter_bounded`).
    bounded: Option<Box<dyn Fn() -> T>>,
}

struct Class<T: Real> {
    records: Vec<Record<T>>,
    exact: Vec<f64>,
}

fn load<T: Real>() -> BTreeMap<String, Class<T>> {
    let mut out: BTreeMap<String, Class<T>> = BTreeMap::new();
    for v in reference_lines("extended.jsonl").into_iter().chain(reference_lines("area.jsonl")) {
        let record = match parse_any_value::<T>(&v).unwrap() {
            AnyRecord::Segment(seg) => {
                let (a, b) = (T::vec3_to_array(seg.light().a), T::vec3_to_array(seg.light().b));
                let mid = T::vec3_from_array([0, 1, 2].map(|i| (a[i] + b[i]) * T::lit(0.5)));
                let len = [0, 1, 2].map(|i| b[i] - a[i]).iter().fold(T::zero(), |s, x| s + *x * *x).sqrt();
                let light = PointLight { position: mid, intensity: seg.light().intensity * len, distribution: seg.light().distribution };
                let point = Scene::new(*seg.ray(), light, *seg.medium(), *seg.phase()).unwrap();
                Record { counted: Box::new(move |tol| seg.in_scatter_counted(tol)), point: Box::new(move || point.in_scatter()), bounded: None }
            }
            AnyRecord::Area(area) => {
                let l = *area.light();
                let (ray, medium, phase) = (*area.ray(), *area.medium(), *area.phase());
                let point: Box<dyn Fn() -> T> = match l.emitter {
                    Emitter::Disc { center, normal, radius } => {
                        let light = PointLight { position: center, intensity: l.radiance * T::PI() * radius * radius, distribution: Lambertian { axis: normal } };
                        let s = Scene::new(ray, light, medium, phase).unwrap();
                        Box::new(move || s.in_scatter())
                    }
                    Emitter::Rectangle { corner, edge_u, edge_v } => {
                        let (c, u, w) = (T::vec3_to_array(corner), T::vec3_to_array(edge_u), T::vec3_to_array(edge_v));
                        let n = [u[1] * w[2] - u[2] * w[1], u[2] * w[0] - u[0] * w[2], u[0] * w[1] - u[1] * w[0]];
                        let area_size = n.iter().fold(T::zero(), |s, x| s + *x * *x).sqrt();
                        let centre = T::vec3_from_array([0, 1, 2].map(|i| c[i] + (u[i] + w[i]) * T::lit(0.5)));
                        let light = PointLight { position: centre, intensity: l.radiance * area_size, distribution: Lambertian { axis: T::vec3_from_array(n) } };
                        let s = Scene::new(ray, light, medium, phase).unwrap();
                        Box::new(move || s.in_scatter())
                    }
                    Emitter::Sphere { center, radius } => {
                        let light = PointLight { position: center, intensity: l.radiance * T::PI() * radius * radius, distribution: Omni };
                        let s = Scene::new(ray, light, medium, phase).unwrap();
                        Box::new(move || s.in_scatter())
                    }
                };
                Record { counted: Box::new(move |tol| area.in_scatter_counted(tol)), point, bounded: Some(Box::new(move || area.in_scatter_bounded())) }
            }
            _ => panic!("not an extended light: {v}"),
        };
        let shape = v["light"]["shape"].as_str().unwrap();
        let class = out.entry(format!("{shape}_{}", v["category"].as_str().unwrap())).or_insert(Class { records: vec![], exact: vec![] });
        class.records.push(record);
        class.exact.push(v["in_scatter"].as_f64().unwrap());
    }
    out
}

fn run<T: Real>(crit: &mut Criterion, label: &str, report: &mut String) {
    for (name, class) in load::<T>() {
        let worst = |tol: T| {
            let mut e = 0.0f64;
            let mut counts = vec![];
            for (r, exact) in class.records.iter().zip(&class.exact) {
                let (x, p) = (r.counted)(tol);
                e = e.max((x.to_f64_exact() - exact).abs() / exact);
                counts.push(p);
            }
            counts.sort();
            (e, counts[counts.len() / 2], counts[counts.len() - 1])
        };
        let (e_default, med_default, max_default) = worst(airlight::extended::outer_tolerance());
        let (e_loose, med_loose, max_loose) = worst(T::lit(1e-3));
        // segments, at error 1e-3 (the target's level): the loosest tolerance whose largest error
        // over the class is at most 1e-3 (as the classes bench picks the kernel's)
        let level = name.starts_with("segment_").then(|| LEVEL_TOLERANCES.iter().copied().find(|&t| worst(T::lit(t)).0 <= LEVEL).unwrap_or(1e-3));
        // an area light's bounded method: its largest error
        let bounded_json = match class.records.iter().map(|r| r.bounded.as_ref()).collect::<Option<Vec<_>>>() {
            Some(b) => format!(",\"bounded\":{:e}", b.iter().zip(&class.exact).map(|(f, exact)| (f().to_f64_exact() - exact).abs() / exact).fold(0.0, f64::max)),
            None => String::new(),
        };
        let level_json = match level {
            Some(t) => {
                let (e, med, max) = worst(T::lit(t));
                format!(",\"level_tolerance\":{t:e},\"level\":{e:e},\"level_panels\":[{med},{max}]")
            }
            None => String::new(),
        };
        writeln!(
            report,
            "{{\"precision\":\"{label}\",\"class\":\"{name}\",\"records\":{},\"default\":{e_default:e},\"default_panels\":[{med_default},{max_default}],\"loose\":{e_loose:e},\"loose_panels\":[{med_loose},{max_loose}]{level_json}{bounded_json}}}",
            class.records.len()
        )
        .unwrap();
        let mut g = crit.benchmark_group(format!("extended_{label}_{name}"));
        let default = airlight::extended::outer_tolerance::<T>();
        g.bench_function("emitter_default", |b| b.iter(|| class.records.iter().map(|r| (r.counted)(black_box(default)).0).fold(T::zero(), |a, x| a + x)));
        g.bench_function("emitter_1e-3", |b| b.iter(|| class.records.iter().map(|r| (r.counted)(black_box(T::lit(1e-3))).0).fold(T::zero(), |a, x| a + x)));
        if let Some(t) = level {
            g.bench_function("emitter_at_1e-3", |b| b.iter(|| class.records.iter().map(|r| (r.counted)(black_box(T::lit(t))).0).fold(T::zero(), |a, x| a + x)));
        }
        if class.records.iter().all(|r| r.bounded.is_some()) {
            g.bench_function("emitter_bounded", |b| b.iter(|| class.records.iter().map(|r| (r.bounded.as_ref().unwrap())()).fold(T::zero(), |a, x| a + black_box(x))));
        }
        g.bench_function("point", |b| b.iter(|| class.records.iter().map(|r| black_box((r.point)())).fold(T::zero(), |a, x| a + x)));
        g.finish();
    }
}

/// The error level of the segment light's speed target, and the tolerances tried for it,
/// loosest first.
const LEVEL: f64 = 1e-3;
const LEVEL_TOLERANCES: [f64; 5] = [1e-1, 3e-2, 1e-2, 3e-3, 1e-3];

fn benches(crit: &mut Criterion) {
    let mut report = String::new();
    run::<f64>(crit, "f64", &mut report);
    run::<f32>(crit, "f32", &mut report);
    let dir = airlight_tests::repo_root().join("target/criterion");
    std::fs::create_dir_all(&dir).unwrap();
    std::fs::write(dir.join("extended_accuracy.jsonl"), report).unwrap();
}

criterion_group! {
    name = group;
    config = Criterion::default().sample_size(10).warm_up_time(Duration::from_millis(300)).measurement_time(Duration::from_millis(1500));
    targets = benches
}
criterion_main!(group);
