//! One scene class of `tests/reference/classes.jsonl` evaluated `repetitions` times by the
//! default path at a tolerance, or by the Gauss–Legendre-in-angle peer: the workload that
//! `scripts/class_instructions.py` counts instructions of under callgrind (deterministic, where
//! the benches' times move by ±30 % on shared machines). Prints the scene count and the largest
//! error over the class (`|x − exact| / max(|exact|, τ·scale)`, τ = 1e-10 / 1e-4).
//!
//! `cargo run --release -p airlight-tests --example class_cost -- f32 hg_0.9 1e-1 10`
//! (`p32` / `s10` in place of the tolerance: the peer, plain or split, at that many nodes).

use airlight::march::GaussAngle;
use airlight::{default_control, Real};
use airlight_tests::{class_cases, ClassCase};
use std::hint::black_box;

fn run<T: Real>(cases: &[ClassCase], method: &str, repetitions: usize, tau: f64, cut: f64) -> (usize, f64) {
    let scenes: Vec<_> = cases.iter().filter(|c| c.judged(tau)).map(|c| (c.rec.cast::<T>().scene().expect("a valid scene"), c)).collect();
    let peer = |split: bool, n: &str| GaussAngle { nodes: n.parse().expect("a node count"), panels: 1, split, cut: Some(T::lit(cut)) };
    let peer = method.strip_prefix('p').map(|n| peer(false, n)).or(method.strip_prefix('s').map(|n| peer(true, n)));
    let control = airlight::panels::Control { tolerance: T::lit(method.parse().unwrap_or(1.0)), ..default_control::<T>() };
    let mut worst = 0.0f64;
    for _ in 0..repetitions {
        for (scene, case) in &scenes {
            let value = match peer {
                Some(rule) => black_box(scene).gauss_angle(rule).0,
                None => black_box(scene).in_scatter_controlled(control).0,
            };
            worst = worst.max(case.err(value.to_f64_exact(), tau));
        }
    }
    (scenes.len(), worst)
}

fn main() {
    let args: Vec<String> = std::env::args().collect();
    let [_, precision, class, method, repetitions] = &args[..] else {
        panic!("usage: class_cost f32|f64 CLASS TOLERANCE|pN|sN REPETITIONS");
    };
    let repetitions: usize = repetitions.parse().expect("a repetition count");
    let cases: Vec<_> = class_cases().into_iter().filter(|c| &c.category == class).collect();
    assert!(!cases.is_empty(), "no class {class}");
    // the peer's cut as in the classes bench: the extinction exponent grown by 20 (f32) / 40 (f64)
    let (scenes, worst) = match precision.as_str() {
        "f32" => run::<f32>(&cases, method, repetitions, 1e-4, 20.0),
        "f64" => run::<f64>(&cases, method, repetitions, 1e-10, 40.0),
        _ => panic!("precision f32 or f64"),
    };
    println!("scenes {scenes} worst {worst:e}");
}
