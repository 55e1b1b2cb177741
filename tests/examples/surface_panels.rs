//! The shaders' surface methods on the CPU (`SurfaceScene::air_light_panels_counted` with
//! `SHADER_CONTROL`, 8 and 12 nodes, f32) against the references of tests/reference/surface.jsonl
//! (the Lambertian or, with `phong`, the Phong points lit by omni lights), at a ladder of outer
//! panel bounds: the largest error (`|x − exact| / max(|exact|, 1e-4·scale)`) and the rays per
//! point — what bounds `SHADER_SURFACE_PANELS` and `SHADER_PHONG_PANELS` (docs/DESIGN.md §11).
//!
//! `cargo run --release -p airlight-tests --example surface_panels [phong]`

use airlight::LightDistribution;
use airlight_tests::{reference_lines, surface_record};

fn run<const N: usize>(lines: &[serde_json::Value], phong: bool, bounds: &[usize]) {
    for &panels in bounds {
        let (mut worst, mut rays_max, mut rays_sum, mut n) = (0.0f64, 0, 0, 0);
        for v in lines {
            let s = surface_record::<f32>(v);
            if matches!(s.brdf(), airlight::Brdf::Phong { .. }) != phong || !s.light().distribution.is_isotropic() {
                continue;
            }
            let (x, r) = s.air_light_panels_counted::<N>(airlight::SHADER_CONTROL, panels);
            let (exact, scale) = (
                v["surface_air_light"].as_f64().unwrap(),
                v["scale"].as_f64().unwrap(),
            );
            worst = worst.max((x as f64 - exact).abs() / exact.max(1e-4 * scale));
            rays_max = rays_max.max(r);
            rays_sum += r;
            n += 1;
        }
        println!("{N} nodes, panels {panels}: {n} records, largest error {worst:.2e}, rays mean {:.1} max {rays_max}", rays_sum as f64 / n as f64);
    }
}
fn main() {
    let lines = reference_lines("surface.jsonl");
    let phong = std::env::args().nth(1).as_deref() == Some("phong");
    let bounds: &[usize] = if phong { &[10, 12, 14, 16, 20, 24] } else { &[3, 4, 5, 6, 8] };
    run::<8>(&lines, phong, bounds);
    run::<12>(&lines, phong, bounds);
}
