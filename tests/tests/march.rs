//! The ray-marching baselines ([`airlight::march`]) against the independent mpmath
//! references (tests/reference/scenes.jsonl): the benchmarks compare the kernel with them at
//! the step counts that reach a given accuracy, so they must be correct quadratures of the
//! same integral.
//!
//! Both are midpoint rules, second order for integrands with a bounded second derivative
//! (every phase function and light distribution here; a spot cone's smoothstep edge has a
//! jump in the second derivative only): quadrupling the step count divides the error by 16
//! up to rounding. Asserted, per rule, on the scenes whose error at `n` steps is well above
//! rounding (> 1e-9): the median of `err(n)/err(4n)` lies in [8, 32] (16 within a factor 2 —
//! the leading error term dominates for most scenes, not all: kinks and the truncation of
//! unbounded segments perturb some), and at the larger step count the median error is below
//! 1e-4 (uniform, 2^16 steps) and 1e-6 (equiangular, 2^12 steps).

use airlight::march::Steps;
use airlight_codegen::scene_json::parse_value;
use airlight_tests::{reference_lines, rel_err};

fn median(mut v: Vec<f64>) -> f64 {
    v.sort_by(|a, b| a.partial_cmp(b).unwrap());
    v[v.len() / 2]
}

#[test]
fn ray_marchers_converge_to_the_reference() {
    for (rule, n, floor) in [(Steps::Uniform, 1 << 14, 1e-4), (Steps::Equiangular, 1 << 10, 1e-6)] {
        let (mut ratios, mut errs) = (Vec::new(), Vec::new());
        for v in reference_lines("scenes.jsonl") {
            let Some(want) = v["in_scatter"].as_f64() else { continue };
            let rec = parse_value::<f64>(&v).unwrap();
            let scene = rec.scene().unwrap();
            if scene.canonical().h == 0.0 || want == 0.0 {
                continue; // light on the ray line: the equiangular variable degenerates
            }
            let (coarse, fine) = (rel_err(scene.ray_march(rule, n), want), rel_err(scene.ray_march(rule, 4 * n), want));
            errs.push(fine);
            if coarse > 1e-9 {
                ratios.push(coarse / fine.max(1e-300));
            }
        }
        let (m_ratio, m_err) = (median(ratios.clone()), median(errs.clone()));
        println!("{rule:?}: {} scenes, median err(n)/err(4n) = {m_ratio:.1} over {} scenes, median err at {} steps {m_err:.1e}, max {:.1e}",
            errs.len(), ratios.len(), 4 * n, errs.iter().cloned().fold(0.0, f64::max));
        assert!((8.0..=32.0).contains(&m_ratio), "{rule:?}: not second order: median ratio {m_ratio}");
        assert!(m_err < floor, "{rule:?}: median error {m_err:e} at {} steps", 4 * n);
    }
}
