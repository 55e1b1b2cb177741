//! One class of tests/reference/surface.jsonl evaluated `passes` times by
//! `SurfaceScene::air_light_counted` (f64) at a tolerance: the workload whose instructions per
//! surface point callgrind counts (deterministic, where the surface bench's times move by up to
//! 2× between runs on shared machines). Per point: the count at `passes` minus the count at 0
//! (the reference file's parsing), divided by passes × the class's points (6 each):
//!
//! `valgrind --tool=callgrind --callgrind-out-file=/dev/null target/release/examples/surface_cost lambert_thin 1e-1 20`
//! (and the same with 0), after `cargo build --release -p airlight-tests --example surface_cost`.

use airlight_codegen::scene_json::{parse_any_value, AnyRecord};
use airlight_tests::reference_lines;
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
        .map(|v| match parse_any_value::<f64>(v) {
            Ok(AnyRecord::Surface(s)) => s,
            other => panic!("a surface point, not {other:?}"),
        })
        .collect();
    assert!(!points.is_empty(), "no class {class}");
    let (mut sum, mut rays) = (0.0, 0);
    for _ in 0..passes {
        for point in &points {
            let (value, r) = black_box(point).air_light_counted(tolerance);
            sum += value;
            rays += r;
        }
    }
    println!("points {} rays {rays} sum {sum:e}", points.len());
}
