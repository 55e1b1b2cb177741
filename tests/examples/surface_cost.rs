//! One class of tests/reference/surface.jsonl evaluated `passes` times by
//! `SurfaceScene::air_light_counted` at a tolerance, in f64 or f32: the workload whose
//! instructions per surface point `python3 scripts/class_instructions.py --surface [f32] CLASS
//! TOLERANCE` counts under callgrind (deterministic, where the surface bench's times move by up
//! to 2× between runs on shared machines). Prints the point count and the largest error over
//! the class (`|x − exact| / max(|exact|, τ·scale)`, τ = 1e-10 in f64, 1e-4 in f32, as the
//! surface bench states them).
//!
//! `cargo run --release -p airlight-tests --example surface_cost -- lambert_thin 1e-1 10`
//! (`-- f32 lambert_thin 1e-1 10` in single precision)

use airlight::Real;
use airlight_tests::{reference_lines, surface_record};
use std::hint::black_box;

fn run<T: Real>(class: &str, tolerance: f64, passes: usize, tau: f64) -> (usize, f64) {
    let points: Vec<_> = reference_lines("surface.jsonl")
        .iter()
        .filter(|v| v["category"].as_str() == Some(class))
        .map(|v| (surface_record::<T>(v), v["surface_air_light"].as_f64().unwrap(), v["scale"].as_f64().unwrap()))
        .collect();
    assert!(!points.is_empty(), "no class {class}");
    let mut worst = 0.0f64;
    for _ in 0..passes {
        for (point, exact, scale) in &points {
            let value = black_box(point).air_light_counted(T::lit(tolerance)).0.to_f64_exact();
            worst = worst.max((value - exact).abs() / exact.abs().max(tau * scale));
        }
    }
    (points.len(), worst)
}

fn main() {
    let args: Vec<String> = std::env::args().collect();
    let (single, rest) = match args.get(1).map(String::as_str) {
        Some("f32") => (true, &args[2..]),
        Some("f64") => (false, &args[2..]),
        _ => (false, &args[1..]),
    };
    let [class, tolerance, passes] = rest else {
        panic!("usage: surface_cost [f32|f64] CLASS TOLERANCE PASSES");
    };
    let (tolerance, passes): (f64, usize) = (tolerance.parse().expect("a tolerance"), passes.parse().expect("a pass count"));
    let (points, worst) = if single { run::<f32>(class, tolerance, passes, 1e-4) } else { run::<f64>(class, tolerance, passes, 1e-10) };
    println!("scenes {points} worst {worst:e}");
}
