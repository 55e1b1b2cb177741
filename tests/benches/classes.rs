//! The default (error-controlled) kernel against Gauss–Legendre in the light angle — the peer a
//! renderer engineer would write instead — per scene class, side by side in one process, on
//! the scenes of tests/reference/classes.jsonl (mpmath references; tests/reference/gen_classes.py).
//!
//! Accuracy first, outside the timed loops, against the references: the error of a method on a
//! class is the **largest** over its scenes of `|x − exact| / max(|exact|, τ·scale)` (`τ` =
//! 1e-10 in f64, 1e-4 in f32). The peer (cut where the extinction exponent has grown by 40 in
//! f64, 20 in f32) climbs a ladder of rules: one panel of 4 … 64 nodes over the whole segment
//! ("plain"), the same split at the foot, then composite rules of 16- or 64-node panels up to
//! 4096 nodes per part, split (`PEER_LADDER`); a comparison "at error e" takes, of the rungs
//! whose largest error is at most `e`, the one with the fewest integrand evaluations over the
//! class (where none is, the last rung, flagged: the peer's true cost there is higher). Then,
//! per class and precision, timed over all the class's scenes per iteration:
//! * `airlight`: `Scene::in_scatter()` (the default), and `peer_default`: the peer at the
//!   default's largest error;
//! * at each error level of the targets (`LEVELS`: 1e-8 and 1e-10 in f64, 1e-3 and 1e-4 in
//!   f32), `airlight_<level>`: the kernel with the loosest tolerance (1e-1, 3e-2, 1e-2, … 1e-12:
//!   half decades, as the peer's ladder steps by 1.2–1.6× in nodes) whose largest error is at
//!   most the level (where none is, the default, flagged), and `peer_<level>`. Both
//!   sides are chosen knowing the class's errors: the peer's cheapest rung is one plain 4-node
//!   panel, the kernel's cheapest setting tolerance 1e-1 (one panel a piece where the first estimate
//!   passes).
//! Also `node_count_<precision>`: every scene of every class at the default tolerance with 6 … 16
//! Gauss–Legendre nodes per panel (the choice of `Real::PANEL_NODES`), and `special`: complex
//! `e^z E1(z)` over 256 points against one libm `exp` per point, in each precision.
//!
//! `cargo bench -p airlight-tests --bench classes && python3 scripts/classes_table.py`

use airlight::light::AnyDistribution;
use airlight::march::GaussAngle;
use airlight::panels::Control;
use airlight::phase::AnyPhase;
use airlight::special::{e1_scaled, C};
use airlight::{default_control, Real, Scene};
use airlight_codegen::scene_json::parse_value;
use airlight_tests::reference_lines;
use criterion::{black_box, criterion_group, criterion_main, Criterion};
use std::collections::BTreeMap;
use std::fmt::Write as _;
use std::time::Duration;

type S<T> = Scene<T, AnyDistribution<T>, AnyPhase<T>>;

struct Class<T: Real> {
    scenes: Vec<S<T>>,
    exact: Vec<f64>,
    scale: Vec<f64>,
}

/// The peer's rungs as (nodes per panel, panels per part, split at the foot): one panel of 4 …
/// 64 nodes over the whole segment ("plain"), the same split at the foot, then composite rules
/// of the split form. A comparison takes the rung with the fewest integrand evaluations over
/// the class among those reaching the error ([`peer_at`]).
const PEER_LADDER: [(usize, usize, bool); 34] = [
    (4, 1, false),
    (6, 1, false),
    (8, 1, false),
    (10, 1, false),
    (12, 1, false),
    (16, 1, false),
    (20, 1, false),
    (24, 1, false),
    (32, 1, false),
    (48, 1, false),
    (64, 1, false),
    (4, 1, true),
    (6, 1, true),
    (8, 1, true),
    (10, 1, true),
    (12, 1, true),
    (16, 1, true),
    (20, 1, true),
    (24, 1, true),
    (32, 1, true),
    (48, 1, true),
    (64, 1, true),
    (16, 8, true),
    (64, 2, true),
    (16, 16, true),
    (64, 4, true),
    (16, 32, true),
    (64, 8, true),
    (16, 64, true),
    (64, 16, true),
    (16, 128, true),
    (64, 32, true),
    (16, 256, true),
    (64, 64, true),
];
const TOLERANCES: [f64; 23] = [
    1e-1, 3e-2, 1e-2, 3e-3, 1e-3, 3e-4, 1e-4, 3e-5, 1e-5, 3e-6, 1e-6, 3e-7, 1e-7, 3e-8, 1e-8, 3e-9, 1e-9, 3e-10, 1e-10, 3e-11, 1e-11, 3e-12, 1e-12,
];

fn levels<T: Real>() -> [f64; 2] {
    if T::epsilon() > T::lit(1e-10) {
        [1e-3, 1e-4]
    } else {
        [1e-8, 1e-10]
    }
}

fn load<T: Real>() -> BTreeMap<String, Class<T>> {
    let mut out: BTreeMap<String, Class<T>> = BTreeMap::new();
    let f32_run = T::epsilon() > T::lit(1e-10);
    for v in reference_lines("classes.jsonl") {
        let exact = v["in_scatter"].as_f64().unwrap();
        // values below the precision's range (deep in thick media) have nothing to measure
        if exact < if f32_run { 1e-30 } else { 1e-290 } {
            continue;
        }
        let rec = parse_value::<T>(&v).unwrap();
        let class = out.entry(v["category"].as_str().unwrap().to_string()).or_insert(Class { scenes: vec![], exact: vec![], scale: vec![] });
        class.scenes.push(rec.scene().unwrap());
        class.exact.push(exact);
        class.scale.push(v["scale"].as_f64().unwrap());
    }
    out
}

fn tau<T: Real>() -> f64 {
    if T::epsilon() > T::lit(1e-10) {
        1e-4
    } else {
        1e-10
    }
}

fn largest_error<T: Real>(c: &Class<T>, f: impl Fn(&S<T>) -> T) -> f64 {
    largest_error_of(c, c.scenes.iter().map(f))
}

/// [`largest_error`] of values already computed, one per scene in order.
fn largest_error_of<T: Real>(c: &Class<T>, values: impl Iterator<Item = T>) -> f64 {
    let t = tau::<T>();
    values.enumerate().map(|(i, x)| (x.to_f64_exact() - c.exact[i]).abs() / c.exact[i].abs().max(t * c.scale[i])).fold(0.0, f64::max)
}

fn peer<T: Real>((nodes, panels, split): (usize, usize, bool)) -> GaussAngle<T> {
    let cut = if T::epsilon() > T::lit(1e-10) { 20.0 } else { 40.0 };
    GaussAngle { nodes, panels, split, cut: Some(T::lit(cut)) }
}

fn ours<T: Real>(s: &S<T>, control: Control<T>) -> T {
    s.in_scatter_controlled(control).0
}

/// The peer rung at most `e` off over the class with the fewest integrand evaluations (or, where
/// none is, the last rung), its error, and whether it reached `e`.
fn peer_at(errors: &[f64], evaluations: &[usize], e: f64) -> (usize, f64, bool) {
    match (0..errors.len()).filter(|&i| errors[i] <= e).min_by_key(|&i| evaluations[i]) {
        Some(i) => (i, errors[i], true),
        None => (errors.len() - 1, errors[errors.len() - 1], false),
    }
}

fn json_rung(i: usize, e: f64, reached: bool) -> String {
    let (n, p, split) = PEER_LADDER[i];
    format!("{{\"nodes\":{n},\"panels\":{p},\"split\":{split},\"error\":{e:e},\"reached\":{reached}}}")
}

fn run<T: Real>(crit: &mut Criterion, label: &str, report: &mut String) {
    for (name, class) in load::<T>() {
        let ours_err = largest_error(&class, |s| s.in_scatter());
        let mut panels: Vec<usize> = class.scenes.iter().map(|s| s.in_scatter_controlled(default_control()).1).collect();
        panels.sort();
        // each rung once over the class: its largest error and its integrand evaluations
        let (peer_errs, peer_evals): (Vec<f64>, Vec<usize>) = PEER_LADDER
            .iter()
            .map(|&r| {
                let runs: Vec<(T, usize)> = class.scenes.iter().map(|s| s.gauss_angle(peer(r))).collect();
                (largest_error_of(&class, runs.iter().map(|x| x.0)), runs.iter().map(|x| x.1).sum::<usize>())
            })
            .unzip();
        let (peer_default, e, reached) = peer_at(&peer_errs, &peer_evals, ours_err);
        let mut line = format!(
            "{{\"precision\":\"{label}\",\"class\":\"{name}\",\"scenes\":{},\"airlight\":{ours_err:e},\"panels_median\":{},\"panels_max\":{},\"peer_default\":{},\"levels\":[",
            class.scenes.len(),
            panels[panels.len() / 2],
            panels[panels.len() - 1],
            json_rung(peer_default, e, reached)
        );
        let mut timed: Vec<(String, Control<T>, usize)> = vec![];
        for (k, level) in levels::<T>().into_iter().enumerate() {
            let at = |t: f64| Control { tolerance: T::lit(t), ..default_control() };
            let tol = TOLERANCES.iter().copied().find(|&t| largest_error(&class, |s| ours(s, at(t))) <= level);
            let control = tol.map_or(default_control(), at);
            let err = largest_error(&class, |s| ours(s, control));
            let (rung, e, reached) = peer_at(&peer_errs, &peer_evals, level);
            write!(
                line,
                "{}{{\"level\":{level:e},\"tolerance\":{},\"airlight\":{err:e},\"peer\":{}}}",
                if k > 0 { "," } else { "" },
                tol.map_or("null".to_string(), |t| format!("{t:e}")),
                json_rung(rung, e, reached)
            )
            .unwrap();
            timed.push((format!("{level:e}"), control, rung));
        }
        writeln!(report, "{line}]}}").unwrap();
        let mut g = crit.benchmark_group(format!("classes_{label}_{name}"));
        let sc = &class.scenes;
        let sum = |f: &dyn Fn(&S<T>) -> T| sc.iter().map(|s| f(black_box(s))).fold(T::zero(), |a, x| a + x);
        g.bench_function("airlight", |b| b.iter(|| sum(&|s| s.in_scatter())));
        g.bench_function("peer_default", |b| b.iter(|| sum(&|s| s.gauss_angle(peer(PEER_LADDER[peer_default])).0)));
        for (level, control, rung) in timed {
            g.bench_function(format!("airlight_{level}"), |b| b.iter(|| sum(&|s| ours(s, control))));
            g.bench_function(format!("peer_{level}"), |b| b.iter(|| sum(&|s| s.gauss_angle(peer(PEER_LADDER[rung])).0)));
        }
        g.finish();
    }
}

/// The default's node count: every class's scenes at the default tolerance with 6 … 16 nodes
/// per panel, largest error over all classes (relative to `max(|exact|, τ·scale)`) and time;
/// also the largest error at tolerance 1e-3 (where the estimate must still hold).
fn node_count<T: Real>(crit: &mut Criterion, label: &str, report: &mut String) {
    let classes = load::<T>();
    let all: Vec<&S<T>> = classes.values().flat_map(|c| c.scenes.iter()).collect();
    let mut g = crit.benchmark_group(format!("node_count_{label}"));
    for nodes in [6usize, 8, 10, 12, 16] {
        let at = |s: &S<T>| s.in_scatter_panels_with_nodes(nodes, default_control()).unwrap();
        let err = classes.values().map(|c| largest_error(c, at)).fold(0.0, f64::max);
        // and how far the estimate holds at a loose tolerance (1e-3), untimed
        let loose = Control { tolerance: T::lit(1e-3), ..default_control() };
        let err_loose = classes.values().map(|c| largest_error(c, |s| s.in_scatter_panels_with_nodes(nodes, loose).unwrap())).fold(0.0, f64::max);
        writeln!(report, "{{\"precision\":\"{label}\",\"node_count\":{nodes},\"scenes\":{},\"error\":{err:e},\"error_at_1e-3\":{err_loose:e}}}", all.len()).unwrap();
        g.bench_function(format!("{nodes}"), |b| b.iter(|| all.iter().map(|s| at(black_box(s))).fold(T::zero(), |a, x| a + x)));
    }
    g.finish();
}

fn special(crit: &mut Criterion) {
    // 256 points over the domain the kernel uses: |z| from 1e-3 to 1e3, arguments in [−π/2, π/2]
    let mut z64 = Vec::new();
    let mut seed = 11u64;
    for _ in 0..256 {
        seed = seed.wrapping_mul(6364136223846793005).wrapping_add(1442695040888963407);
        let u = (seed >> 11) as f64 / (1u64 << 53) as f64;
        seed = seed.wrapping_mul(6364136223846793005).wrapping_add(1442695040888963407);
        let w = (seed >> 11) as f64 / (1u64 << 53) as f64;
        let r = 10f64.powf(-3.0 + 6.0 * u);
        let a = (w - 0.5) * std::f64::consts::PI;
        z64.push(C::new(r * a.cos(), r * a.sin()));
    }
    let z32: Vec<C<f32>> = z64.iter().map(|z| C::new(z.re as f32, z.im as f32)).collect();
    let x64: Vec<f64> = z64.iter().map(|z| -z.re.min(80.0)).collect();
    let x32: Vec<f32> = x64.iter().map(|&x| x as f32).collect();
    let mut g = crit.benchmark_group("special");
    g.bench_function("e1_scaled_f64", |b| b.iter(|| z64.iter().map(|&z| e1_scaled(black_box(z)).re).sum::<f64>()));
    g.bench_function("exp_f64", |b| b.iter(|| x64.iter().map(|&x| libm::exp(black_box(x))).sum::<f64>()));
    g.bench_function("e1_scaled_f32", |b| b.iter(|| z32.iter().map(|&z| e1_scaled(black_box(z)).re).sum::<f32>()));
    g.bench_function("exp_f32", |b| b.iter(|| x32.iter().map(|&x| libm::expf(black_box(x))).sum::<f32>()));
    g.finish();
}

fn benches(crit: &mut Criterion) {
    let mut report = String::new();
    run::<f64>(crit, "f64", &mut report);
    run::<f32>(crit, "f32", &mut report);
    let mut nodes = String::new();
    node_count::<f64>(crit, "f64", &mut nodes);
    node_count::<f32>(crit, "f32", &mut nodes);
    special(crit);
    let dir = airlight_tests::repo_root().join("target/criterion");
    std::fs::create_dir_all(&dir).unwrap();
    std::fs::write(dir.join("classes_accuracy.jsonl"), report).unwrap();
    std::fs::write(dir.join("node_count.jsonl"), nodes).unwrap();
}

criterion_group! {
    name = group;
    config = Criterion::default().sample_size(20).warm_up_time(Duration::from_millis(300)).measurement_time(Duration::from_millis(1200));
    targets = benches
}
criterion_main!(group);
