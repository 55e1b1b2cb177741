//! One class of tests/reference/surface.jsonl evaluated `passes` times by
//! `SurfaceScene::air_light_counted` (f64) at a tolerance: the workload whose instructions per
//! surface point `python3 scripts/class_instructions.py --surface CLASS TOLERANCE` counts under
//! callgrind (deterministic, where the surface bench's times move by up to 2× between runs on
//! shared machines). Prints the point count and the largest error over the class
//! (`|x − exact| / max(|exact|, 1e-10·scale)`).
//!
//! `cargo run --release -p airlight-tests --example surface_cost -- lambert_thin 1e-1 10`

use airlight_tests::{reference_lines, surface_record};
use std::hint::black_box;

fn main() {
    let args: Vec<String> = std::env::args().collect();
    let [_, class, tolerance, passes] = &args[..] else {
        panic!("usage: surface_cost CLASS TOLERANCE PASSES");
    };
    let (tolerance, passes): (f64, usize) = (tolerance.parse().expect("a tolerance"), passes.parse().expect("a pass count"));
    let points: Vec<_> = reference_lines("surface.jsonl")
        .iter()
        .filter(|v| v["category"].as_str() == Some(class.as_str()))
        .map(|v| (surface_record::<f64>(v), v["surface_air_light"].as_f64().unwrap(), v["scale"].as_f64().unwrap()))
        .collect();
    assert!(!points.is_empty(), "no class {class}");
    let mut worst = 0.0f64;
    for _ in 0..passes {
        for (point, exact, scale) in &points {
            let value = black_box(point).air_light_counted(tolerance).0;
            worst = worst.max((value - exact).abs() / exact.abs().max(1e-10 * scale));
        }
    }
    println!("scenes {} worst {worst:e}", points.len());
}
