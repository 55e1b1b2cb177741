//! Stable moments: no step of the moment computation amplifies rounding with the term index.
//!
//! References: tests/reference/moments.jsonl (tests/reference/gen_moments.py, mpmath at 40
//! digits). Criterion, for every `k < 16` and every `λ` from 0 to 1e8, in f64 and f32: the
//! error of `M_k(λ) = ∫_{−1}^{1} e^{−λ(1+ξ)} P_k(ξ) dξ` is at most `C·ε` times its size
//! bound `M_0(λ)` (`|P_k| ≤ 1` and the weight is positive, so `|M_k| ≤ M_0`). `C = 8`: the
//! series sums ≤ 11 positive terms with ≤ 3 roundings each; Miller's recurrence is stable
//! downward above `k ≈ λ` (each step adds ≤ 2 roundings relative to the larger of the two
//! terms, which shrink) and its normalisation adds 2; the upward recurrence below `k ≈ λ`
//! likewise; the final scaling 1. Measured: 1.8 (f64) and 1.4 (f32).
//!
//! The same criterion applied to the fixed-term path's monomial moments (`Q_k = R_{k−1} −
//! b Q_{k−1}`, module docs of `airlight::integrals`), with the size bound `r^k m_0` of
//! `m_k = ∫ e^{−H(y − y_lo)} (y − y_c)^k/(1 + y²) dy` on a sub-interval of half-width `r`,
//! fails by many orders: the recurrence multiplies the error of `Q_0` by `(|b|/r)^k`. That
//! path is kept only because the shaders implement it.

use airlight::integrals::{moment_zero, moments, Half, Production};
use airlight::Real;
use airlight::panels::exp_legendre_moments;
use airlight_tests::reference_lines;

#[test]
fn legendre_moments_of_the_exponential_are_stable() {
    let lines = reference_lines("moments.jsonl");
    let mut worst64 = 0.0f64;
    let mut worst32 = 0.0f64;
    let mut checked = 0;
    let lambdas: Vec<f64> = {
        let mut v: Vec<f64> = lines.iter().filter(|l| l["kind"] == "legendre").map(|l| l["lambda"].as_f64().unwrap()).collect();
        v.dedup();
        v
    };
    for &lambda in &lambdas {
        let refs: Vec<f64> =
            lines.iter().filter(|l| l["kind"] == "legendre" && l["lambda"].as_f64() == Some(lambda)).map(|l| l["value"].as_f64().unwrap()).collect();
        assert_eq!(refs.len(), 16);
        let bound = refs[0];
        let mut m64 = [0.0f64; 16];
        exp_legendre_moments(lambda, &mut m64);
        let mut m32 = [0.0f32; 16];
        exp_legendre_moments(lambda as f32, &mut m32);
        for k in 0..16 {
            let e64 = (m64[k] - refs[k]).abs() / bound / f64::EPSILON;
            let e32 = (m32[k] as f64 - refs[k]).abs() / bound / f32::EPSILON as f64;
            worst64 = worst64.max(e64);
            worst32 = worst32.max(e32);
            assert!(e64 <= 8.0, "f64 λ = {lambda}, k = {k}: {} vs {} ({e64:.1} ε of M_0)", m64[k], refs[k]);
            assert!(e32 <= 8.0, "f32 λ = {lambda}, k = {k}: {} vs {} ({e32:.1} ε of M_0)", m32[k], refs[k]);
            checked += 1;
        }
    }
    println!("Legendre moments: {checked} checked; worst error / (ε·M_0): f64 {worst64:.2}, f32 {worst32:.2}");
}

#[test]
fn monomial_recurrence_of_the_fixed_path_is_not() {
    let lines = reference_lines("moments.jsonl");
    let mut configs: Vec<(f64, f64, f64)> = lines
        .iter()
        .filter(|l| l["kind"] == "monomial")
        .map(|l| (l["big_h"].as_f64().unwrap(), l["y_lo"].as_f64().unwrap(), l["y_hi"].as_f64().unwrap()))
        .collect();
    configs.dedup();
    assert!(!configs.is_empty());
    for (big_h, y_lo, y_hi) in configs {
        let refs: Vec<f64> = lines
            .iter()
            .filter(|l| l["kind"] == "monomial" && l["big_h"].as_f64() == Some(big_h) && l["y_lo"].as_f64() == Some(y_lo))
            .map(|l| l["value"].as_f64().unwrap())
            .collect();
        let dy = y_hi - y_lo;
        // H·Δv > 1: not the short (Gauss) route, so the closed form and the recurrence apply
        assert!(big_h * dy > 1.0);
        let half = Half { second: false, big_h, y_lo, y_hi, dy, dv: dy };
        let m: [f64; 16] = moments(&half, &Production, 16);
        let r = dy / 2.0;
        let mut worst = 0.0f64;
        for k in 0..16 {
            let size = r.powi(k as i32) * refs[0];
            worst = worst.max((m[k] - refs[k]).abs() / size / f64::EPSILON);
        }
        println!("monomial recurrence, H = {big_h}, y ∈ [{y_lo}, {y_hi}]: worst error / (ε·r^k m_0) = {worst:.2e}");
        assert!(worst > 1e6, "the recurrence was expected to amplify rounding (worst {worst:.2e} ε)");
    }
}

/// The isotropic moment `m_0` on halves whose far end's weight `e^{−HΔv}` lies either side of
/// where route 3 leaves that end out (`airlight::integrals::FAR_END_NEGLIGIBLE`, derived there to
/// cost under half a rounding of `m_0`). Criterion: the error is at most the exponential
/// integral's tolerance (tests/tests/expint.rs: 1e-13 in f64, 2e-6 in f32, relative to `|S|`)
/// times `|S(z_s)| + e^{−HΔv}|S(z_e)|`, plus half a rounding of `m_0` for the end left out and 4
/// for the difference. Leaving the end out at a weight of 64ε (the largest record's) exceeds
/// it in f32 by a factor 2.7. `moment_zero`, which folds the near end's `e^{Hv_s}` into the
/// caller's weight where that end is in `E1`'s series region (the H = 1 records), is held to
/// the same bound after `e^{−x'}`, plus that factor's roundings.
fn far_end_left_out<T: Real>(label: &str, e1_tol: f64) {
    let lines = reference_lines("moments.jsonl");
    let eps = T::epsilon().to_f64_exact();
    let delta = airlight::integrals::FAR_END_NEGLIGIBLE * eps;
    let (mut checked, mut left_out, mut folded_in, mut worst) = (0, 0, 0, 0.0f64);
    for l in lines.iter().filter(|l| l["kind"] == "far_end" && l["precision"] == label) {
        let get = |k: &str| l[k].as_f64().unwrap();
        let (big_h, y_lo, y_hi) = (T::lit(get("big_h")), T::lit(get("y_lo")), T::lit(get("y_hi")));
        let second = l["second"].as_bool().unwrap();
        let dy = y_hi - y_lo;
        let dv = if second { dy / (y_lo * y_hi) } else { dy };
        let half = Half { second, big_h, y_lo, y_hi, dy, dv };
        let m: [T; 1] = moments(&half, &Production, 1);
        // the same with the weight's exponent folded in: e^{−x'}·m' = m_0 at x = 0
        let (folded, x) = moment_zero(&half, &Production, T::zero());
        folded_in += usize::from(x != T::zero());
        let (want, scale) = (get("value"), get("scale"));
        let decay = (-big_h * dv).exp().to_f64_exact();
        left_out += usize::from(decay <= delta);
        // e^{−x'} adds |x'| ε (the rounding of x' = −Hv_s, amplified) and one rounding
        let bound = e1_tol * scale + (4.5 + 1.0 + x.to_f64_exact().abs()) * eps * want;
        for (route, got) in [("moments", m[0].to_f64_exact()), ("moment_zero", (folded * (-x).exp()).to_f64_exact())] {
            let err = (got - want).abs();
            worst = worst.max(err / bound);
            assert!(err <= bound, "{label} {route}, second = {second}, H = {big_h:?}, y ∈ [{y_lo:?}, {y_hi:?}], e^(−HΔv) = {decay:.2e}: {got} vs {want} (error {err:.2e}, bound {bound:.2e})");
        }
        checked += 1;
    }
    assert!(checked >= 18 && left_out >= 6 && left_out < checked && folded_in >= 6, "{label}: {checked} records, {left_out} with the far end left out, {folded_in} folded");
    println!("{label}: far end left out on {left_out} of {checked} halves, weight folded in on {folded_in}; worst error / bound {worst:.3}");
}

#[test]
fn far_end_left_out_within_half_a_rounding() {
    far_end_left_out::<f64>("f64", 1e-13);
    far_end_left_out::<f32>("f32", 2e-6);
}
