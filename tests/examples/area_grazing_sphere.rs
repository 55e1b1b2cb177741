//! A sphere of radius 0.625 at (6, 1.5, −0.5), `g = 0.99` fog, on the part behind it of rays
//! from the origin that miss it by 0.00001, 0.0001 and 0.001 of its radius (inputs exact in f32):
//! the f32 default path (the nested construction, `AreaScene::in_scatter`) and the f32 bounded
//! method (`in_scatter_bounded`), each against the f64 nested construction at tolerance 1e-10,
//! and that one at the f32 default's tolerance 1e-5 (docs/DESIGN.md §12: the bounded method
//! carries the sphere's gap `|c − x| − R` apart from `|c − x|`, the nested construction takes
//! its elements' canonical forms from the sphere's miss).
//!
//! `cargo run --release -p airlight-tests --example area_grazing_sphere`

use airlight::glam::{DVec3, Vec3};
use airlight::phase::{AnyPhase, HenyeyGreenstein};
use airlight::{AreaLight, AreaScene, Emitter, Medium, Ray};

fn main() {
    let (center, radius) = (DVec3::new(6.0, 1.5, -0.5), 0.625);
    let (towards, side) = (center.normalize(), center.normalize().cross(DVec3::Z).normalize());
    let medium = Medium { sigma_s: 0.05, sigma_t: 0.08 };
    println!("| miss (of the radius) | f32 default | point lights | f32 bounded | f64 default at 1e-5 |");
    println!("|---|---|---|---|---|");
    for miss in [0.00001, 0.0001, 0.001] {
        let angle = (radius * (1.0 + miss) / center.length()).asin();
        let dir = (towards * angle.cos() + side * angle.sin()).as_vec3();
        let closest = dir.dot(center.as_vec3()) / dir.length_squared();
        let double = AreaScene::new(Ray { origin: DVec3::ZERO, dir: dir.as_dvec3(), t_min: closest as f64, t_max: f64::INFINITY }, AreaLight::new(Emitter::Sphere { center, radius }, 2.0), medium, AnyPhase::HenyeyGreenstein(HenyeyGreenstein { g: 0.99 })).unwrap();
        let single = AreaScene::new(
            Ray { origin: Vec3::ZERO, dir, t_min: closest, t_max: f32::INFINITY },
            AreaLight::new(Emitter::Sphere { center: center.as_vec3(), radius: radius as f32 }, 2.0),
            Medium { sigma_s: 0.05, sigma_t: 0.08 },
            AnyPhase::HenyeyGreenstein(HenyeyGreenstein { g: 0.99f32 }),
        )
        .unwrap();
        let exact = double.in_scatter_counted(1e-10).0;
        let err = |x: f64| (x - exact).abs() / exact;
        let (nested, lights) = (single.in_scatter(), single.in_scatter_counted(1e-5).1);
        println!("| {miss} | {:.2e} | {lights} | {:.2e} | {:.2e} |", err(nested as f64), err(single.in_scatter_bounded() as f64), err(double.in_scatter_counted(1e-5).0));
    }
}
