//! How many rays the default path's interpolant of `L_a(γ)` spends on a Lambertian point in
//! isotropic fog (`SurfaceScene::air_light_counted`, docs/DESIGN.md §11), by the optical
//! distance `σt·d` to the light: 40 points per depth, the light at distance 1 and 0.04 to 3.06
//! from the normal (`airlight_tests::canonical_surface`). Prints, per depth, how many points
//! took each ray count — 4, 6 or 12 where the interpolant passed at that count (plus the
//! counts tried before it: 10 = 4 + 6, 18 = 6 + 12, 22 = 4 + 6 + 12), more where a ray was
//! taken at every outer node.
//!
//! Since the open ray's closed form (`open_ray_isotropic`, docs/DESIGN.md §11) such a point takes
//! no interpolant: the counts printed are its closed forms, one an outer node (14 where one
//! Gauss–Kronrod 3/7 panel on each of its two pieces passes, 28 where the outer estimate splits
//! one of them into two). The interpolant's counts that docs/DESIGN.md §11 quotes are from
//! before it (8edf611 reproduces them).
//!
//! `cargo run --release -p airlight-tests --example surface_rays -- 1e-1`

use airlight_tests::canonical_surface;
use std::collections::BTreeMap;

fn main() {
    let tolerance: f64 = std::env::args().nth(1).map(|t| t.parse().expect("a tolerance")).unwrap_or(0.1);
    for depth in [0.001, 0.01, 0.03, 0.1, 0.3, 0.6, 1.0, 2.0, 3.0, 5.0, 10.0] {
        let mut rays = BTreeMap::new();
        for k in 0..40 {
            let theta = (k as f64 + 0.5) / 40.0 * 3.1;
            *rays.entry(canonical_surface(depth, theta).air_light_counted(tolerance).1).or_insert(0) += 1;
        }
        let counts: Vec<String> = rays.iter().map(|(r, n)| format!("{n} × {r}")).collect();
        println!("σt·d {depth}: {}", counts.join(", "));
    }
}
