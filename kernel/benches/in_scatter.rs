//! CPU ns per ray, side by side over the same 256 rays, for this kernel (the fixed-cost method
//! and the default path, `Scene::in_scatter`) and every baseline: the seeds' `atan` form
//! (isotropic, no extinction: the cheapest analytic glow, our floor), the paper's algorithm as
//! published (its eq. 27 `Ei`, Taylor expansion), and ray marching ([`airlight::march`]:
//! uniform steps in `t`, and equiangular steps) at the step counts that reach 1e-3 and 1e-5
//! relative error on these scenes.
//!
//! Accuracy is measured first, outside the timed loops, against an independent reference:
//! the f64 equiangular midpoint rule at 2^15 and 2^16 steps, Richardson-extrapolated (its
//! error expansion has even powers only: `(4 M(2n) − M(n))/3` is fourth order; no closed form;
//! the table prints its distance to the same extrapolation from 2^14 and 2^15 steps). Every
//! accuracy figure is the **largest** relative error over the 256 rays. "Equal accuracy" for
//! the paper's algorithm: the first configuration in `PAPER_LADDER` (more Taylor terms, then a
//! 100× tighter `Ei` tolerance) whose largest error is at most ours at 4 (resp. 6) terms.
//! "Ours at 1e-3 / 1e-5": the fewest terms (4, 6, 8, 12) whose largest error reaches it. The figures go to `target/criterion/accuracy.json`;
//! `python3 scripts/bench_table.py` joins them with criterion's timings into BENCHMARKS.md's
//! table.
//!
//! On the isotropic rays it also prints a **paired** line: the default path, the `atan` form and
//! the Sun et al. table that reaches 1e-3, timed in alternating bursts over the same rays
//! ([`paired`]), the ratio the target "f32 isotropic ≤ 2× the atan form" is read from.
//!
//! `cargo bench -p airlight --bench in_scatter && python3 scripts/bench_table.py`

use airlight::glam::{DVec3, Vec3};
use airlight::light::{AnyDistribution, TwoLobed};
use airlight::march::Steps;
use airlight::phase::{AnyPhase, HenyeyGreenstein};
use airlight::{Expansion, Medium, PointLight, Ray, Real, Scene};
use criterion::{black_box, criterion_group, criterion_main, Criterion};
use std::fmt::Write as _;
use std::time::Duration;

type S<T> = Scene<T, AnyDistribution<T>, AnyPhase<T>>;

/// 256 rays through a street-lamp-like scene: origins on a line, directions fanning out,
/// light 1–4 units off the rays, media from thin to moderately thick. Every number passes
/// through `round` (to f32 for the f32 group), so the f64 reference sees the same inputs.
fn scenes<T: Real>(aniso: bool, v: impl Fn([f64; 3]) -> T::Vec3, round: fn(f64) -> f64) -> Vec<S<T>> {
    let mut out = Vec::new();
    let mut seed = 7u64;
    let mut rnd = || {
        seed = seed.wrapping_mul(6364136223846793005).wrapping_add(1442695040888963407);
        round((seed >> 11) as f64 / (1u64 << 53) as f64)
    };
    let v = |a: [f64; 3]| v(a.map(round));
    let lit = |x: f64| T::lit(round(x));
    for _ in 0..256 {
        let ray = Ray {
            origin: v([0.0, 0.0, 0.0]),
            dir: v([1.0, 0.2 * rnd() - 0.1, 0.2 * rnd() - 0.1]),
            t_min: T::lit(0.0),
            t_max: lit(5.0 + 60.0 * rnd()),
        };
        let distribution = if aniso {
            AnyDistribution::TwoLobed(TwoLobed { axis: v([0.0, -1.0, 0.0]), power: 4 })
        } else {
            AnyDistribution::Omni
        };
        let light = PointLight { position: v([40.0 * rnd() - 5.0, 1.0 + 3.0 * rnd(), rnd()]), intensity: lit(100.0), distribution };
        let medium = Medium { sigma_s: lit(0.05), sigma_t: lit(0.01 + 0.3 * rnd()) };
        let phase = if aniso { AnyPhase::HenyeyGreenstein(HenyeyGreenstein { g: lit(0.5) }) } else { AnyPhase::Isotropic };
        out.push(Scene::new(ray, light, medium, phase).unwrap());
    }
    out
}

/// A way of computing `L_m`.
#[derive(Clone, Copy, Debug)]
enum Method {
    /// This kernel, Chebyshev, `n` terms.
    Ours(usize),
    /// This kernel, the paper's Taylor expansion, 6 terms.
    Taylor6,
    /// The paper's algorithm with `n` Taylor terms and its `Ei` tolerance scaled by the factor.
    Paper(usize, f64),
    /// The seeds' `atan` form.
    Atan,
    /// This kernel's default path, `Scene::in_scatter` (error-controlled panels).
    Default,
    /// Sun et al. 2005's tabulated `F(u, v)`, an `n × n` table (isotropic only).
    SunTable(usize),
    /// Ray marching.
    March(Steps, usize),
}

/// Sun, Ramamoorthi, Narasimhan & Nayar 2005 ("A practical analytic single scattering model
/// for real time rendering"), the table method the issue names as the speed floor: for an
/// isotropic point light and phase function, with `t − x_h = h tan θ` and `ξ = θ/2 + π/4`,
/// `L_m = σs I/(2π h) e^{−σt (x_h − t0)} [F(σt h, ξ1) − F(σt h, ξ0)]`,
/// `F(u, v) = ∫_0^v e^{−u tan ξ} dξ`, baked once as an `n × n` table over `u ∈ [0, SUN_U_MAX]`,
/// `v ∈ [0, π/2]` and read by bilinear interpolation. A peer in this benchmark, not the
/// product: it knows no anisotropy.
struct SunTable {
    n: usize,
    data: Vec<f64>,
    bake_ms: f64,
}

/// The table's `u = σt h` range (the street-lamp rays reach 1.3).
const SUN_U_MAX: f64 = 2.0;
/// Table sizes baked.
const SUN_SIZES: [usize; 8] = [16, 32, 64, 128, 256, 512, 1024, 2048];

impl SunTable {
    fn bake(n: usize) -> SunTable {
        let t = std::time::Instant::now();
        let rule = airlight::expansion::gauss_table::rule(16).expect("16-point rule");
        let mut data = vec![0.0; n * n];
        let dv = std::f64::consts::FRAC_PI_2 / (n - 1) as f64;
        for i in 0..n {
            let u = SUN_U_MAX * i as f64 / (n - 1) as f64;
            let mut acc = 0.0;
            for j in 1..n {
                let (a, b) = (dv * (j - 1) as f64, dv * j as f64);
                let (m, r) = ((a + b) / 2.0, (b - a) / 2.0);
                let mut cell = 0.0;
                for &(x, w) in rule {
                    for xi in [m - r * x, m + r * x] {
                        cell += w * (-u * xi.tan()).exp();
                    }
                }
                acc += cell * r;
                data[i * n + j] = acc;
            }
        }
        SunTable { n, data, bake_ms: t.elapsed().as_secs_f64() * 1e3 }
    }

    /// `F(u, v)`, bilinear; `u` clamped to the table.
    #[inline]
    fn lookup<T: Real>(&self, u: T, v: T) -> T {
        let last = T::from(self.n - 1).unwrap();
        let x = (u * (last / T::lit(SUN_U_MAX))).max(T::zero()).min(last);
        let y = (v * (last / T::FRAC_PI_2())).max(T::zero()).min(last);
        let (i, j) = (x.floor().to_usize().unwrap().min(self.n - 2), y.floor().to_usize().unwrap().min(self.n - 2));
        let (fx, fy) = (x - T::from(i).unwrap(), y - T::from(j).unwrap());
        let at = |a: usize, b: usize| T::lit(self.data[a * self.n + b]);
        let low = at(i, j) + (at(i, j + 1) - at(i, j)) * fy;
        let high = at(i + 1, j) + (at(i + 1, j + 1) - at(i + 1, j)) * fy;
        low + (high - low) * fx
    }
}

fn sun_tables() -> &'static [SunTable] {
    static TABLES: std::sync::OnceLock<Vec<SunTable>> = std::sync::OnceLock::new();
    TABLES.get_or_init(|| SUN_SIZES.iter().map(|&n| SunTable::bake(n)).collect())
}

/// `L_m` of an isotropic scene through Sun et al.'s table.
#[inline]
fn sun_table<T: Real>(s: &S<T>, table: &SunTable) -> T {
    let (ray, light, medium) = (s.ray(), s.light(), s.medium());
    // the plain reduction written out rather than `Canonical::new`, which also normalises a
    // light axis and forms `d_c`, neither of which the table needs: the peer is timed lean
    let (o, p) = (T::vec3_to_array(ray.origin), T::vec3_to_array(light.position));
    let dir = T::vec3_to_array(ray.dir);
    let len = (dir[0] * dir[0] + dir[1] * dir[1] + dir[2] * dir[2]).sqrt();
    let d = [dir[0] / len, dir[1] / len, dir[2] / len];
    let q = [p[0] - o[0], p[1] - o[1], p[2] - o[2]];
    let x_h = q[0] * d[0] + q[1] * d[1] + q[2] * d[2];
    let w = [q[0] - x_h * d[0], q[1] - x_h * d[1], q[2] - x_h * d[2]];
    let h = (w[0] * w[0] + w[1] * w[1] + w[2] * w[2]).sqrt();
    let xi = |t: T| if t.is_finite() { ((t - x_h) / h).atan() * T::lit(0.5) + T::FRAC_PI_4() } else { T::FRAC_PI_2() };
    let u = medium.sigma_t * h;
    let a0 = medium.sigma_s * light.intensity / (T::lit(2.0) * T::PI() * h) * (-medium.sigma_t * (x_h - ray.t_min)).exp();
    a0 * (table.lookup(u, xi(ray.t_max)) - table.lookup(u, xi(ray.t_min)))
}

/// The paper's algorithm, configurations in the order tried for "equal accuracy".
const PAPER_LADDER: &[(usize, f64)] = &[(4, 1.0), (6, 1.0), (8, 1.0), (12, 1.0), (16, 1.0), (8, 1e-2), (12, 1e-2), (16, 1e-2)];

fn paper<T: Real>(s: &S<T>, n: usize, eps: T) -> T {
    match n {
        4 => s.in_scatter_paper::<4>(eps, 100),
        6 => s.in_scatter_paper::<6>(eps, 100),
        8 => s.in_scatter_paper::<8>(eps, 100),
        12 => s.in_scatter_paper::<12>(eps, 100),
        _ => s.in_scatter_paper::<16>(eps, 100),
    }
}

/// The paper's `Ei` tolerance (absolute) in this precision: 1e-6 in f32, 1e-12 in f64.
fn paper_eps<T: Real>() -> T {
    if T::epsilon() < T::lit(1e-10) {
        T::lit(1e-12)
    } else {
        T::lit(1e-6)
    }
}

/// The seeds' `atan` form for a scene's ray, light and medium.
#[inline]
fn atan_form<T: Real>(s: &S<T>) -> T {
    airlight::atan_form(s.ray(), s.light().position, s.light().intensity, s.medium().sigma_s)
}

#[inline]
fn eval<T: Real>(m: Method, s: &S<T>) -> T {
    match m {
        Method::Ours(4) => s.in_scatter_with::<4>(Expansion::Chebyshev),
        Method::Ours(6) => s.in_scatter_with::<6>(Expansion::Chebyshev),
        Method::Ours(8) => s.in_scatter_with::<8>(Expansion::Chebyshev),
        Method::Ours(_) => s.in_scatter_with::<12>(Expansion::Chebyshev),
        Method::Taylor6 => s.in_scatter_with::<6>(Expansion::Taylor),
        Method::Paper(n, scale) => paper(s, n, paper_eps::<T>() * T::lit(scale)),
        Method::Default => s.in_scatter(),
        Method::SunTable(n) => sun_table(s, sun_tables().iter().find(|t| t.n == n).expect("a baked size")),
        Method::Atan => atan_form(s),
        Method::March(rule, steps) => s.ray_march(rule, steps),
    }
}

/// Largest and median relative error of `m` over the scenes.
fn accuracy<T: Real>(m: Method, sc: &[S<T>], reference: &[f64]) -> (f64, f64) {
    let mut e: Vec<f64> = sc.iter().zip(reference).map(|(s, &r)| ((eval(m, s).to_f64_exact() - r) / r).abs()).collect();
    e.sort_by(|a, b| a.partial_cmp(b).unwrap());
    (e[e.len() - 1], e[e.len() / 2])
}

/// The smallest step count of the ladder 8·√2^k whose largest error is at most `target`.
fn steps_for<T: Real>(rule: Steps, target: f64, sc: &[S<T>], reference: &[f64]) -> Option<usize> {
    (0..40).map(|k| (8.0 * 2f64.sqrt().powi(k)).round() as usize).find(|&n| accuracy(Method::March(rule, n), sc, reference).0 <= target)
}

/// Rounds and passes over the rays of [`paired`].
const PAIRED_ROUNDS: usize = 60;
const PAIRED_PASSES: usize = 40;

/// ns per ray of the default path, the `atan` form and (given) a Sun et al. table, timed in
/// alternating bursts over the same rays (each burst `PAIRED_PASSES` passes, `PAIRED_ROUNDS`
/// rounds), the fastest burst of each kept: the methods see the same machine state, which
/// criterion's benches, run one after the other, do not (on this shared machine the `atan`
/// form's own median moved by ±30 % between runs). Each method is its own loop, with the call
/// inlined as a caller's would be, not behind [`eval`]'s dispatch.
fn paired<T: Real>(sc: &[S<T>], table: Option<&SunTable>) -> [f64; 3] {
    fn burst<T: Real>(sc: &[S<T>], f: impl Fn(&S<T>) -> T) -> f64 {
        let start = std::time::Instant::now();
        let mut acc = T::zero();
        for _ in 0..PAIRED_PASSES {
            for s in sc {
                acc = acc + f(black_box(s));
            }
        }
        black_box(acc);
        start.elapsed().as_secs_f64() * 1e9 / (PAIRED_PASSES * sc.len()) as f64
    }
    let mut best = [f64::INFINITY; 3];
    for _ in 0..PAIRED_ROUNDS {
        best[0] = best[0].min(burst(sc, |s| s.in_scatter()));
        best[1] = best[1].min(burst(sc, atan_form));
        if let Some(t) = table {
            best[2] = best[2].min(burst(sc, |s| sun_table(s, t)));
        }
    }
    best
}

/// One accuracy record for the JSON file.
fn record(json: &mut String, group: &str, name: &str, m: Method, acc: (f64, f64)) {
    let steps = match m {
        Method::March(_, n) => n.to_string(),
        Method::Paper(n, scale) => format!("\"{n} terms, tolerance x{scale}\""),
        Method::Ours(n) => format!("\"{n} terms\""),
        Method::SunTable(n) => format!("\"{n}x{n} table, {} KiB in f32\"", n * n * 4 / 1024),
        _ => "null".into(),
    };
    let _ = writeln!(json, "{{\"group\": \"{group}\", \"bench\": \"{name}\", \"max_err\": {:e}, \"median_err\": {:e}, \"config\": {steps}}},", acc.0, acc.1);
}

fn group<T: Real>(c: &mut Criterion, json: &mut String, name: &str, v: impl Fn([f64; 3]) -> T::Vec3 + Copy, round: fn(f64) -> f64) {
    for aniso in [false, true] {
        let sc = scenes::<T>(aniso, v, round);
        let sc64 = scenes::<f64>(aniso, DVec3::from_array, round);
        let richardson = |s: &S<f64>, n: usize| (4.0 * s.ray_march(Steps::Equiangular, 2 * n) - s.ray_march(Steps::Equiangular, n)) / 3.0;
        let reference: Vec<f64> = sc64.iter().map(|s| richardson(s, 1 << 15)).collect();
        let converged = sc64.iter().zip(&reference).map(|(s, r)| ((richardson(s, 1 << 14) - r) / r).abs()).fold(0.0, f64::max);
        let kind = if aniso { "aniso" } else { "iso" };
        let gname = format!("{name}/{kind}");
        eprintln!("{gname}: reference = f64 equiangular 2^15/2^16 steps extrapolated, max distance to 2^14/2^15 {converged:.1e}");

        let mut methods: Vec<(String, Method)> = vec![
            ("ours_4".into(), Method::Ours(4)),
            ("ours_6".into(), Method::Ours(6)),
            ("taylor_6".into(), Method::Taylor6),
            ("paper_4".into(), Method::Paper(4, 1.0)),
            ("paper_6".into(), Method::Paper(6, 1.0)),
            ("atan_form".into(), Method::Atan),
            ("default".into(), Method::Default),
        ];
        for (terms, ours) in [(4, Method::Ours(4)), (6, Method::Ours(6))] {
            let target = accuracy(ours, &sc, &reference).0;
            let found = PAPER_LADDER.iter().map(|&(n, k)| Method::Paper(n, k)).find(|&m| accuracy(m, &sc, &reference).0 <= target);
            match found {
                Some(m) => methods.push((format!("paper_eq{terms}"), m)),
                None => eprintln!("{gname}: no paper configuration reaches ours_{terms}'s largest error {target:.1e}"),
            }
        }
        for (target, tag) in [(1e-3, "1e-3"), (1e-5, "1e-5")] {
            match [4, 6, 8, 12].iter().map(|&n| Method::Ours(n)).find(|&m| accuracy(m, &sc, &reference).0 <= target) {
                Some(m) => methods.push((format!("ours_{tag}"), m)),
                None => eprintln!("{gname}: ours does not reach {target:e} with 12 terms in this precision"),
            }
        }
        if !aniso {
            for table in sun_tables() {
                let acc = accuracy(Method::SunTable(table.n), &sc, &reference);
                eprintln!("{gname}: Sun et al. table {0}x{0} ({1} KiB in f32, baked in {2:.1} ms): largest error {3:.1e}, median {4:.1e}", table.n, table.n * table.n * 4 / 1024, table.bake_ms, acc.0, acc.1);
            }
            for (target, tag) in [(1e-3, "1e-3"), (1e-5, "1e-5")] {
                match sun_tables().iter().find(|t| accuracy(Method::SunTable(t.n), &sc, &reference).0 <= target) {
                    Some(t) => methods.push((format!("sun_table_{tag}"), Method::SunTable(t.n))),
                    None => eprintln!("{gname}: no Sun et al. table up to {0}x{0} reaches {target:e}", SUN_SIZES[SUN_SIZES.len() - 1]),
                }
            }
        }
        for (rule, label) in [(Steps::Uniform, "march_uniform"), (Steps::Equiangular, "march_equiangular")] {
            for (target, tag) in [(1e-3, "1e-3"), (1e-5, "1e-5")] {
                match steps_for(rule, target, &sc, &reference) {
                    Some(n) => methods.push((format!("{label}_{tag}"), Method::March(rule, n))),
                    None => eprintln!("{gname}: {label} does not reach {target:e} in this precision"),
                }
            }
        }
        if !aniso {
            let table = methods.iter().find_map(|(l, m)| match m {
                Method::SunTable(n) if l == "sun_table_1e-3" => sun_tables().iter().find(|t| t.n == *n),
                _ => None,
            });
            let [default, atan, sun] = paired(&sc, table);
            let mut line = format!("{gname}: paired (fastest of {PAIRED_ROUNDS} alternating bursts of {PAIRED_PASSES} passes, each method inlined in its own loop): atan_form {atan:.1} ns, default {default:.1} ns ({:.2}× the atan form)", default / atan);
            if let Some(t) = table {
                line += &format!(", sun_table {0}x{0} {sun:.1} ns ({1:.2}×)", t.n, sun / atan);
            }
            eprintln!("{line}");
        }
        let _ = writeln!(json, "{{\"group\": \"{gname}\", \"bench\": \"reference\", \"max_err\": {converged:e}, \"median_err\": null, \"config\": \"f64 equiangular 2^15/2^16 Richardson, vs 2^14/2^15\"}},");
        for (label, m) in &methods {
            record(json, &gname, label, *m, accuracy(*m, &sc, &reference));
        }

        let mut g = c.benchmark_group(&gname);
        g.measurement_time(Duration::from_secs(2)).warm_up_time(Duration::from_millis(500)).sample_size(20);
        g.throughput(criterion::Throughput::Elements(sc.len() as u64));
        for (label, m) in methods {
            g.bench_function(label, |b| b.iter(|| sc.iter().map(|s| eval(black_box(m), black_box(s))).fold(T::zero(), |a, x| a + x)));
        }
        g.finish();
    }
}

fn benches(c: &mut Criterion) {
    let mut json = String::from("[\n");
    group::<f32>(c, &mut json, "f32", |a| Vec3::new(a[0] as f32, a[1] as f32, a[2] as f32), |x| x as f32 as f64);
    group::<f64>(c, &mut json, "f64", DVec3::from_array, |x| x);
    let json = json.trim_end().trim_end_matches(',').to_string() + "\n]\n";
    let dir = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("../target/criterion");
    let _ = std::fs::create_dir_all(&dir);
    std::fs::write(dir.join("accuracy.json"), json).expect("write accuracy.json");
}

criterion_group!(all, benches);
criterion_main!(all);
