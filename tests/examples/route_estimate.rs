//! How far the light-angle route's error estimate (docs/DESIGN.md §4.2) stands above the error
//! it guards, ray by ray: for each scene of one class of `tests/reference/classes.jsonl`, the
//! smallest tolerance at which the route's first try of `N` nodes is taken (found by bisection
//! in `log10` of the tolerance: about the estimate over the value, or the prediction that
//! declines it, marked `D`; `F` where the estimate fails), the true error of the value taken
//! at tolerance 1 (`|x − exact| / max(|exact|, τ·scale)`, τ = 1e-10 / 1e-4), and their ratio.
//! A try taken down to tolerances far below its error (its estimate within the samples' own
//! rounding, which the route accepts at any tolerance) shows a ratio below 1: no estimate
//! decided there.
//!
//! `cargo run --release -p airlight-tests --example route_estimate -- f64 street_aniso`
//! (f64 with 16 nodes, f32 with 8: the default path's first tries).

use airlight::angle::{Plan, Route};
use airlight::combined::Physics;
use airlight::{default_control, Real};
use airlight_tests::{class_cases, ClassCase};

fn run<T: Real, const N: usize>(cases: &[ClassCase], tau: f64) {
    for case in cases {
        if !case.judged(tau) {
            continue;
        }
        let scene = case.rec.cast::<T>().scene().expect("a valid scene");
        let phys = Physics::new(scene.light(), scene.medium(), scene.phase());
        let g = scene.canonical();
        let route = |tolerance: f64| {
            let control = airlight::panels::Control { tolerance: T::lit(tolerance), ..default_control::<T>() };
            Plan::new(g, &phys, &control).map_or(Route::Declined, |plan| plan.rule::<_, _, N>(g, &phys, &control, false))
        };
        let Route::Taken(value) = route(1.0) else {
            println!("not taken at tolerance 1");
            continue;
        };
        let error = case.err(value.to_f64_exact(), tau);
        let (mut lo, mut hi, mut why) = (-17.0f64, 0.0f64, "-");
        for _ in 0..40 {
            let mid = 0.5 * (lo + hi);
            match route(10f64.powf(mid)) {
                Route::Taken(_) => hi = mid,
                Route::Failed => (lo, why) = (mid, "F"),
                Route::Declined => (lo, why) = (mid, "D"),
            }
        }
        let smallest = 10f64.powf(hi);
        println!("taken from tolerance {smallest:.1e} ({why}), error {error:.1e}, ratio {:.1e}", smallest / error);
    }
}

fn main() {
    let args: Vec<String> = std::env::args().collect();
    let [_, precision, class] = &args[..] else {
        panic!("usage: route_estimate f32|f64 CLASS");
    };
    let cases: Vec<_> = class_cases().into_iter().filter(|c| &c.category == class).collect();
    assert!(!cases.is_empty(), "no class {class}");
    match precision.as_str() {
        "f32" => run::<f32, 8>(&cases, 1e-4),
        "f64" => run::<f64, 16>(&cases, 1e-10),
        _ => panic!("precision f32 or f64"),
    }
}
