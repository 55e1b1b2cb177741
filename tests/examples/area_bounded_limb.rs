//! The bounded area-light method (`AreaScene::in_scatter_bounded`, docs/DESIGN.md §12) on rays
//! that pass a sphere just outside its limb or enter it just inside, in Henyey–Greenstein fog of
//! `g` = 0.9, 0.95 and 0.99: in front of the sphere the phase lobe's direction lies in the cap it
//! subtends next to its rim (or just outside it), behind it (past the ray's closest approach to
//! the centre, leaving the sphere at a grazing angle) the lobe points away from it, just outside
//! the cap of a sphere seen from next to its surface. Relative error against the nested
//! construction at 1e-10 (`AreaScene::in_scatter_counted`) of the whole ray, of its part up to
//! the closest approach (in front) and of the part after it (behind); `offset` the distance of
//! the ray's line from the centre less the radius (< 0: the ray enters the sphere).
//!
//! `cargo run --release -p airlight-tests --example area_bounded_limb`

use airlight::glam::DVec3;
use airlight::phase::{AnyPhase, HenyeyGreenstein};
use airlight::{AreaLight, AreaScene, Emitter, Medium, Ray};

fn main() {
    let medium = Medium { sigma_s: 0.05, sigma_t: 0.08 };
    let (center, radius) = (DVec3::new(6.0, 1.5, -0.5), 0.6);
    let sphere = Emitter::Sphere { center, radius };
    let (towards, side) = (center.normalize(), center.normalize().cross(DVec3::Z).normalize());
    println!("| g | offset | whole ray | in front | behind (its share of the whole) |");
    println!("|---|---|---|---|---|");
    let mut worst = [0.0f64; 3];
    for g in [0.9, 0.95, 0.99] {
        for offset in [-0.001, -0.0001, -0.00001, 0.00001, 0.0001, 0.001] {
            let angle = ((radius + offset) / center.length()).asin();
            let dir = towards * angle.cos() + side * angle.sin();
            let closest = dir.dot(center);
            let mut errors = [0.0; 3];
            let mut values = [0.0; 3];
            for (i, (t_min, t_max)) in [(0.0, f64::INFINITY), (0.0, closest), (closest, f64::INFINITY)].into_iter().enumerate() {
                let ray = Ray { origin: DVec3::ZERO, dir, t_min, t_max };
                let scene = AreaScene::new(ray, AreaLight::new(sphere, 2.0), medium, AnyPhase::HenyeyGreenstein(HenyeyGreenstein { g })).unwrap();
                values[i] = scene.in_scatter_counted(1e-10).0;
                errors[i] = (scene.in_scatter_bounded() - values[i]).abs() / values[i];
                worst[i] = worst[i].max(errors[i]);
            }
            println!("| {g} | {offset} | {:.1e} | {:.1e} | {:.1e} ({:.1e}) |", errors[0], errors[1], errors[2], values[2] / values[0]);
        }
    }
    println!("\nlargest: whole ray {:.1e}, in front {:.1e}, behind {:.1e}", worst[0], worst[1], worst[2]);
}
