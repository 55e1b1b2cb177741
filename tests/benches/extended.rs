//! Segment lights against one point light, side by side in one process, on the records of
//! tests/reference/extended.jsonl (nested mpmath references; tests/reference/gen_extended.py).
//!
//! Accuracy first, outside the timed loops: per class and precision, the largest relative error
//! of `SegmentScene::in_scatter()` (the default) and of `in_scatter_counted(1e-3)` against the
//! references, and the panels each takes. Timed, per class, over all its records per iteration:
//! `segment_default`, `segment_1e-3`, and `point`: the default point light of intensity `I·ℓ`
//! at each segment's midpoint (the cost a segment is compared with).
//!
//! `cargo bench -p airlight-tests --bench extended && python3 scripts/extended_table.py`

use airlight::light::AnyDistribution;
use airlight::phase::AnyPhase;
use airlight::{PointLight, Real, Scene, SegmentScene};
use airlight_codegen::scene_json::{parse_any_value, AnyRecord};
use airlight_tests::reference_lines;
use criterion::{black_box, criterion_group, criterion_main, Criterion};
use std::collections::BTreeMap;
use std::fmt::Write as _;
use std::time::Duration;

type Seg<T> = SegmentScene<T, AnyDistribution<T>, AnyPhase<T>>;
type Point<T> = Scene<T, AnyDistribution<T>, AnyPhase<T>>;

struct Class<T: Real> {
    segments: Vec<Seg<T>>,
    points: Vec<Point<T>>,
    exact: Vec<f64>,
}

fn load<T: Real>() -> BTreeMap<String, Class<T>> {
    let mut out: BTreeMap<String, Class<T>> = BTreeMap::new();
    for v in reference_lines("extended.jsonl") {
        let AnyRecord::Segment(seg) = parse_any_value::<T>(&v).unwrap() else { panic!("not a segment light: {v}") };
        let (a, b) = (T::vec3_to_array(seg.light().a), T::vec3_to_array(seg.light().b));
        let mid = T::vec3_from_array([0, 1, 2].map(|i| (a[i] + b[i]) * T::lit(0.5)));
        let len = [0, 1, 2].map(|i| b[i] - a[i]).iter().fold(T::zero(), |s, x| s + *x * *x).sqrt();
        let light = PointLight { position: mid, intensity: seg.light().intensity * len, distribution: seg.light().distribution };
        let point = Scene::new(*seg.ray(), light, *seg.medium(), *seg.phase()).unwrap();
        let class = out.entry(v["category"].as_str().unwrap().to_string()).or_insert(Class { segments: vec![], points: vec![], exact: vec![] });
        class.segments.push(seg);
        class.points.push(point);
        class.exact.push(v["in_scatter"].as_f64().unwrap());
    }
    out
}

fn run<T: Real>(crit: &mut Criterion, label: &str, report: &mut String) {
    for (name, class) in load::<T>() {
        let worst = |f: &dyn Fn(&Seg<T>) -> (T, usize)| {
            let mut e = 0.0f64;
            let mut panels = vec![];
            for (s, exact) in class.segments.iter().zip(&class.exact) {
                let (x, p) = f(s);
                e = e.max((x.to_f64_exact() - exact).abs() / exact);
                panels.push(p);
            }
            panels.sort();
            (e, panels[panels.len() / 2], panels[panels.len() - 1])
        };
        let (e_default, med_default, max_default) = worst(&|s| s.in_scatter_counted(airlight::extended::outer_tolerance()));
        let (e_loose, med_loose, max_loose) = worst(&|s| s.in_scatter_counted(T::lit(1e-3)));
        writeln!(
            report,
            "{{\"precision\":\"{label}\",\"class\":\"{name}\",\"records\":{},\"default\":{e_default:e},\"default_panels\":[{med_default},{max_default}],\"loose\":{e_loose:e},\"loose_panels\":[{med_loose},{max_loose}]}}",
            class.segments.len()
        )
        .unwrap();
        let mut g = crit.benchmark_group(format!("extended_{label}_{name}"));
        g.bench_function("segment_default", |b| b.iter(|| class.segments.iter().map(|s| black_box(s).in_scatter()).fold(T::zero(), |a, x| a + x)));
        g.bench_function("segment_1e-3", |b| b.iter(|| class.segments.iter().map(|s| black_box(s).in_scatter_counted(T::lit(1e-3)).0).fold(T::zero(), |a, x| a + x)));
        g.bench_function("point", |b| b.iter(|| class.points.iter().map(|s| black_box(s).in_scatter()).fold(T::zero(), |a, x| a + x)));
        g.finish();
    }
}

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
