//! The baked-table peer of fog-lit surfaces, side by side with `SurfaceScene` in one process.
//!
//! Hong 2006 (§4.2.2 of the thesis in `../shared/seeds/`, eq. 4.13; Sun et al. 2005's `G_0` in
//! other variables) tabulates the air-light a Lambertian surface receives from an isotropic
//! point light in an isotropic medium as one 2D function: with `d` the distance from the surface
//! point to the light, `θ_s` the light's angle from the normal and `T = σt·d`,
//! `L_{p,a} = σs·I·ρ/d · J(T, θ_s)` (lengths scaled by `d`; `J` holds the `1/π` of the BRDF).
//! As Hong does, `J` is baked on a uniform `n × n` grid over `T ∈ [0, T_MAX]`, `θ_s ∈ [0, π]`
//! (Hong: `[0, 10] × [0, π/2]`; here wide enough for this repository's thick records and for
//! lights below the surface's horizon) and read bilinearly, in f32, as a texture would be. The
//! baking integrates this crate's own `SurfaceScene` (f64, tolerance 1e-9) — the peer's cost
//! is the bake, not its quadrature.
//!
//! Accuracy, untimed: per table size, the largest relative error over `POINTS` random `(T, θ_s)`
//! (`T` log-uniform in `[1e-3, T_MAX]`, `θ_s` uniform) against `SurfaceScene::air_light()` in f64
//! (the default path, itself within 6.8e-14 of the independent references of
//! tests/reference/surface.jsonl, `tests/surface.rs`), and over the 12 Lambertian, omni,
//! isotropic records of surface.jsonl against their references. Then, timed over the same
//! points: the table's lookup (`table_<axis>_<n>`), and `SurfaceScene::air_light_counted(tolerance)`
//! in f32 (`ours_<tolerance>`) at the loosest tolerance whose largest error over the points is at
//! most the table's: ours at the table's accuracy.
//!
//! `cargo bench -p airlight-tests --bench surface_table && python3 scripts/surface_table_peer.py`

use airlight::glam::Vec3;
use airlight::light::Omni;
use airlight::phase::{Isotropic, PhaseFunction};
use airlight::{Brdf, LightDistribution, SurfaceScene};
use airlight_tests::{canonical_surface, reference_lines, rel_err, surface_record, Rng};
use criterion::{black_box, criterion_group, criterion_main, Criterion};
use std::fmt::Write as _;
use std::time::{Duration, Instant};

/// Largest optical distance `σt·d` the tables hold.
const T_MAX: f64 = 20.0;
/// Table sizes `n` (an `n × n` grid of f32).
const SIZES: [usize; 6] = [16, 32, 64, 128, 256, 512];
/// Random `(T, θ_s)` points the accuracy and the timing run over.
const POINTS: usize = 2000;
/// Our tolerances, loosest first.
const TOLERANCES: [f64; 7] = [1e-2, 1e-3, 1e-4, 1e-5, 1e-6, 1e-7, 1e-8];

/// Hong's `J(T, θ_s)` on an `n × n` grid, f32, row-major in `T`: uniform in `T` as Hong's
/// (`Axis::Linear`), or uniform in `√T` (`Axis::Sqrt`, this bench's own variant: `J` has a
/// `T ln T` term at `T → 0` that a uniform `T` axis resolves only to first order).
struct Table {
    n: usize,
    axis: Axis,
    data: Vec<f32>,
}

#[derive(Clone, Copy, PartialEq)]
enum Axis {
    Linear,
    Sqrt,
}

impl Table {
    fn bake(n: usize, axis: Axis) -> (Table, Duration) {
        let start = Instant::now();
        let mut data = Vec::with_capacity(n * n);
        for i in 0..n {
            let x = i as f64 / (n - 1) as f64;
            let t = T_MAX * if axis == Axis::Sqrt { x * x } else { x };
            for j in 0..n {
                let theta = std::f64::consts::PI * j as f64 / (n - 1) as f64;
                data.push(canonical_surface(t, theta).air_light_counted(1e-9).0 as f32);
            }
        }
        (Table { n, axis, data }, start.elapsed())
    }

    /// Bilinear read at `(T, θ_s)`, clamped to the grid.
    #[inline]
    fn lookup(&self, t: f32, theta: f32) -> f32 {
        let last = (self.n - 1) as f32;
        let x = t * (1.0 / T_MAX as f32);
        let x = if self.axis == Axis::Sqrt { x.sqrt() } else { x };
        let u = (x * last).clamp(0.0, last);
        let v = (theta * (last / std::f32::consts::PI)).clamp(0.0, last);
        let (i, j) = ((u as usize).min(self.n - 2), (v as usize).min(self.n - 2));
        let (fu, fv) = (u - i as f32, v - j as f32);
        let at = |a: usize, b: usize| self.data[a * self.n + b];
        let lo = at(i, j) + fv * (at(i, j + 1) - at(i, j));
        let hi = at(i + 1, j) + fv * (at(i + 1, j + 1) - at(i + 1, j));
        lo + fu * (hi - lo)
    }

    /// `L_{p,a}` of a Lambertian point `s` (unit normal `n`) lit by an isotropic point light at
    /// `p`: `σs I ρ/d · J(σt d, θ_s)`.
    #[inline]
    fn air_light(&self, s: Vec3, n: Vec3, p: Vec3, sigma_s: f32, sigma_t: f32, intensity: f32, albedo: f32) -> f32 {
        let to_light = p - s;
        let d = to_light.length();
        let theta = (n.dot(to_light) / d).clamp(-1.0, 1.0).acos();
        sigma_s * intensity * albedo / d * self.lookup(sigma_t * d, theta)
    }
}

/// A surface record in the table's inputs.
struct Record {
    s: Vec3,
    n: Vec3,
    p: Vec3,
    sigma_s: f32,
    sigma_t: f32,
    intensity: f32,
    albedo: f32,
    exact: f64,
}

/// The Lambertian, omni, isotropic records of surface.jsonl: the table's domain.
fn records() -> Vec<Record> {
    let mut out = vec![];
    for v in reference_lines("surface.jsonl") {
        let sc = surface_record::<f32>(&v);
        let Brdf::Lambert { albedo } = *sc.brdf() else { continue };
        if !(sc.light().distribution.is_isotropic() && sc.phase().is_isotropic()) {
            continue;
        }
        let s = sc.surface();
        out.push(Record {
            s: s.position,
            n: s.normal.normalize(),
            p: sc.light().position,
            sigma_s: sc.medium().sigma_s,
            sigma_t: sc.medium().sigma_t,
            intensity: sc.light().intensity,
            albedo,
            exact: v["surface_air_light"].as_f64().unwrap(),
        });
    }
    out
}

fn benches(crit: &mut Criterion) {
    let mut rng = Rng(2005);
    let points: Vec<(f64, f64)> = (0..POINTS).map(|_| (rng.log_range(1e-3, T_MAX), rng.range(0.0, std::f64::consts::PI))).collect();
    let exact: Vec<f64> = points.iter().map(|&(t, th)| canonical_surface(t as f32 as f64, th as f32 as f64).air_light()).collect();
    let ours32: Vec<SurfaceScene<f32, Omni, Isotropic>> = points.iter().map(|&(t, th)| canonical_surface(t as f32, th as f32)).collect();
    let recs = records();
    let rel = rel_err;
    // ours: largest error over the points at each tolerance
    let ours_err: Vec<f64> = TOLERANCES.iter().map(|&tol| ours32.iter().zip(&exact).map(|(s, &e)| rel(s.air_light_counted(tol as f32).0 as f64, e)).fold(0.0, f64::max)).collect();
    let mut report = String::new();
    for (k, &tol) in TOLERANCES.iter().enumerate() {
        writeln!(report, "{{\"ours\":{tol:e},\"error\":{:e}}}", ours_err[k]).unwrap();
    }
    let mut g = crit.benchmark_group("surface_table");
    let mut timed: Vec<usize> = vec![];
    for (axis, label) in [(Axis::Linear, "linear"), (Axis::Sqrt, "sqrt")] {
    for n in SIZES {
        let (table, bake) = Table::bake(n, axis);
        let (err, worst_t, worst_theta) = points
            .iter()
            .zip(&exact)
            .map(|(&(t, th), &e)| (rel(table.lookup(t as f32, th as f32) as f64, e), t, th))
            .fold((0.0, 0.0, 0.0), |w, x| if x.0 > w.0 { x } else { w });
        let err_records = recs
            .iter()
            .map(|r| rel(table.air_light(r.s, r.n, r.p, r.sigma_s, r.sigma_t, r.intensity, r.albedo) as f64, r.exact))
            .fold(0.0, f64::max);
        let at = ours_err.iter().position(|&e| e <= err);
        writeln!(
            report,
            "{{\"axis\":\"{label}\",\"n\":{n},\"bytes\":{},\"bake_s\":{},\"error\":{err:e},\"worst_at\":[{worst_t},{worst_theta}],\"error_records\":{err_records:e},\"ours_tolerance\":{},\"ours_error\":{}}}",
            n * n * 4,
            bake.as_secs_f64(),
            at.map_or("null".into(), |i| format!("{:e}", TOLERANCES[i])),
            at.map_or("null".into(), |i| format!("{:e}", ours_err[i]))
        )
        .unwrap();
        // the lookup in a surface's own inputs (distance, angle, then the read), over the points
        let inputs: Vec<(Vec3, Vec3, Vec3, f32)> = ours32.iter().map(|s| (s.surface().position, s.surface().normal, s.light().position, s.medium().sigma_t)).collect();
        g.bench_function(format!("table_{label}_{n}"), |b| {
            b.iter(|| inputs.iter().map(|&(s, nn, p, st)| table.air_light(black_box(s), nn, p, 1.0, st, 1.0, 1.0)).fold(0.0f32, |a, x| a + x))
        });
        if let Some(i) = at {
            if !timed.contains(&i) {
                timed.push(i);
            }
        }
    }
    }
    // ours, once per tolerance some table's accuracy asks for
    for i in timed {
        let tol = TOLERANCES[i] as f32;
        g.bench_function(format!("ours_{:e}", TOLERANCES[i]), |b| b.iter(|| ours32.iter().map(|s| black_box(s).air_light_counted(tol).0).fold(0.0f32, |a, x| a + x)));
    }
    g.finish();
    let dir = airlight_tests::repo_root().join("target/criterion");
    std::fs::create_dir_all(&dir).unwrap();
    std::fs::write(dir.join("surface_table.jsonl"), report).unwrap();
}

criterion_group! {
    name = group;
    config = Criterion::default().sample_size(10).warm_up_time(Duration::from_millis(300)).measurement_time(Duration::from_millis(1500));
    targets = benches
}
criterion_main!(group);
