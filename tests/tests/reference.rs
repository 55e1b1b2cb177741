//! The kernel against independent references: mpmath quadrature of the integral of docs/DESIGN.md §1
//! (tests/reference/scenes.jsonl, made by tests/reference/gen_reference.py).
//!
//! Asserted:
//! * model-exact scenes (isotropic light and phase): f64, the default path and 6 terms, within 1e-12 relative
//!   (the target; there the expansion is exact and only the closed forms' rounding
//!   remains);
//! * `f32_exact` scenes (isotropic, inputs exact in f32, `|o − p| ≤ 300 h`): f32, 4 terms,
//!   within 1e-4 relative (the target);
//! * a light exactly on the segment gives `+∞`;
//! * anisotropic scenes: every value is finite and ≥ 0, and the expansion converges: in every
//!   (phase, light) class the median error with 12 Chebyshev terms is at most a tenth of the
//!   median 6-term error, or below 1e-7. (Per scene it need not: a narrow `c^16` beam pointing
//!   away from a segment leaves an integral far below the integrand's own scale, where no
//!   few-term polynomial is accurate in relative terms — the paper's §6 caveat.)
//!
//! Printed (`--nocapture`): the error table per phase function, light distribution, term
//! count and expansion (the README's table).

use airlight::light::AnyDistribution;
use airlight::phase::AnyPhase;
use airlight::Expansion;
use airlight_codegen::scene_json::parse_value;
use airlight_tests::{reference_lines, rel_err};
use std::collections::BTreeMap;

fn phase_name(p: &AnyPhase<f64>) -> &'static str {
    match p {
        AnyPhase::Isotropic => "isotropic",
        AnyPhase::Rayleigh => "rayleigh",
        AnyPhase::HenyeyGreenstein(_) => "henyey_greenstein",
        AnyPhase::Schlick(_) => "schlick",
        AnyPhase::CornetteShanks(_) => "cornette_shanks",
        AnyPhase::TwoLobeHenyeyGreenstein(_) => "two_lobe_hg",
    }
}

fn light_name(d: &AnyDistribution<f64>) -> &'static str {
    match d {
        AnyDistribution::Omni => "isotropic",
        AnyDistribution::TwoLobed(_) => "two_lobed",
        AnyDistribution::SpotCone(_) => "spot",
    }
}

#[derive(Default)]
struct Stats {
    errs: Vec<f64>,
}

impl Stats {
    fn add(&mut self, e: f64) {
        self.errs.push(e);
    }
    fn summary(&mut self) -> String {
        self.errs.sort_by(|a, b| a.partial_cmp(b).unwrap());
        let n = self.errs.len();
        if n == 0 {
            return "-".into();
        }
        format!("{:.1e} / {:.1e}", self.errs[n / 2], self.errs[n - 1])
    }
}

#[test]
fn kernel_against_quadrature() {
    let lines = reference_lines("scenes.jsonl");
    assert!(lines.len() >= 100, "reference file too small");
    let mut table: BTreeMap<(String, String), [Stats; 6]> = BTreeMap::new();
    let mut exact_worst = 0.0f64;
    let mut f32_worst = 0.0f64;
    let (mut n_exact, mut n_f32, mut n_inf) = (0, 0, 0);
    let mut failures = Vec::new();
    for v in &lines {
        let category = v["category"].as_str().unwrap_or("?").to_string();
        let rec64 = parse_value::<f64>(v).unwrap_or_else(|e| panic!("reference record invalid: {e}: {v}"));
        let scene = airlight::Scene::new(rec64.ray, rec64.light, rec64.medium, rec64.phase).unwrap();
        let want = match &v["in_scatter"] {
            serde_json::Value::String(s) if s == "inf" => f64::INFINITY,
            x => x.as_f64().unwrap(),
        };
        if want.is_infinite() {
            n_inf += 1;
            let got = scene.in_scatter();
            if got != f64::INFINITY {
                failures.push(format!("{category}: light on the segment gave {got}, want +inf"));
            }
            continue;
        }
        let model_exact = matches!(rec64.phase, AnyPhase::Isotropic) && matches!(rec64.light.distribution, AnyDistribution::Omni);
        let vals = [
            scene.in_scatter(),
            scene.in_scatter_with::<6>(Expansion::Chebyshev),
            scene.in_scatter_with::<6>(Expansion::Taylor),
            scene.in_scatter_with::<4>(Expansion::Chebyshev),
            scene.in_scatter_with::<4>(Expansion::Taylor),
            scene.in_scatter_with::<12>(Expansion::Chebyshev),
        ];
        for x in vals {
            if !(x >= 0.0 && x.is_finite()) {
                failures.push(format!("{category}: non-finite or negative {x} for {v}"));
            }
        }
        let errs = vals.map(|x| rel_err(x, want));
        let key = (phase_name(&rec64.phase).to_string(), light_name(&rec64.light.distribution).to_string());
        let row = table.entry(key).or_default();
        for (s, e) in row.iter_mut().zip(errs) {
            s.add(e);
        }
        if model_exact {
            n_exact += 1;
            exact_worst = exact_worst.max(errs[0]).max(errs[1]);
            for (e, x) in errs.iter().zip(vals).take(2) {
                if *e > 1e-12 {
                    failures.push(format!("{category}: model-exact f64 rel err {e:.2e} > 1e-12: got {x} want {want}: {v}"));
                }
            }
        }
        if category == "f32_exact" {
            n_f32 += 1;
            let rec32 = parse_value::<f32>(v).unwrap();
            let s32 = airlight::Scene::new(rec32.ray, rec32.light, rec32.medium, rec32.phase).unwrap();
            let got = s32.in_scatter_with::<4>(Expansion::Chebyshev) as f64;
            // Judged where the true value is a normal f32 (the generator keeps it there).
            assert!(want >= f32::MIN_POSITIVE as f64, "f32_exact reference outside f32's normal range: {v}");
            let e = rel_err(got, want);
            f32_worst = f32_worst.max(e);
            if e > 1e-4 {
                failures.push(format!("f32_exact: rel err {e:.2e} > 1e-4: got {got} want {want}: {v}"));
            }
        }
    }
    println!("model-exact scenes: {n_exact}, worst f64 rel err (default and 6 terms) {exact_worst:.2e}");
    println!("f32_exact scenes: {n_f32}, worst f32 4-term rel err {f32_worst:.2e}");
    println!("light-on-segment scenes: {n_inf}");
    println!("\nrelative error against quadrature, median / max, f64:");
    println!("| phase | light | n | default | Chebyshev 6 | Taylor 6 | Chebyshev 4 | Taylor 4 | Chebyshev 12 |");
    println!("|---|---|---|---|---|---|---|---|---|");
    for ((p, l), row) in table.iter_mut() {
        let n = row[0].errs.len();
        let cells: Vec<String> = row.iter_mut().map(|s| s.summary()).collect();
        println!("| {p} | {l} | {n} | {} |", cells.join(" | "));
        let (m6, m12) = (row[1].errs[n / 2], row[5].errs[n / 2]);
        if !(p == "isotropic" && l == "isotropic") && !(m12 <= (m6 / 10.0).max(1e-7)) {
            failures.push(format!("{p} × {l}: expansion does not converge: median 6 terms {m6:.2e}, 12 terms {m12:.2e}"));
        }
    }
    assert!(n_exact >= 50 && n_f32 >= 20 && n_inf >= 1, "reference coverage too thin: {n_exact} exact, {n_f32} f32, {n_inf} inf");
    assert!(failures.is_empty(), "{} failures:\n{}", failures.len(), failures.join("\n"));
}
