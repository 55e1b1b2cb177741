//! The surface points of `tests/reference/surface.jsonl` lit by lights with an axis (class
//! `distribution`), one line each: `SurfaceScene::air_light_counted` at the default tolerance,
//! 1e-3 and 1e-1 in f64 (error against the reference, relative to `max(|exact|, 1e-10·scale)`,
//! ray integrals, time of one evaluation) and at 1e-5 and 1e-1 in f32 (τ = 1e-4): the per-record
//! figures of BENCHMARKS.md's fog-lit surfaces and docs/DESIGN.md §11. Times are single
//! evaluations on a shared machine, for orders of magnitude only; the bench has the ratios.
//!
//! `cargo run --release -p airlight-tests --example surface_beams`

use airlight_tests::reference_lines;
use std::time::Instant;

use airlight_tests::surface_record as surface;

fn main() {
    for v in reference_lines("surface.jsonl").iter().filter(|v| v["category"] == "distribution") {
        let (exact, scale) = (v["surface_air_light"].as_f64().unwrap(), v["scale"].as_f64().unwrap());
        let d = &v["light"]["distribution"];
        let (s64, s32) = (surface::<f64>(v), surface::<f32>(v));
        let mut line = format!("{} p={} {}:", d["kind"], d["power"], v["surface"]["brdf"]["kind"]);
        for tolerance in [1e-10, 1e-3, 1e-1] {
            let start = Instant::now();
            let (x, rays) = s64.air_light_counted(tolerance);
            let us = start.elapsed().as_secs_f64() * 1e6;
            line += &format!(" f64 at {tolerance:e}: {:.1e}, {rays} rays, {us:.0} µs;", (x - exact).abs() / exact.max(1e-10 * scale));
        }
        for tolerance in [1e-5f32, 1e-1] {
            let (x, rays) = s32.air_light_counted(tolerance);
            line += &format!(" f32 at {tolerance:e}: {:.1e}, {rays} rays;", (x as f64 - exact).abs() / exact.max(1e-4 * scale));
        }
        println!("{line}");
    }
}
