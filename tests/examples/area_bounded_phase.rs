//! The bounded area-light method (`AreaScene::in_scatter_bounded`, docs/DESIGN.md §12) in
//! forward-scattering fog: its relative error against the nested construction at tolerance
//! 1e-9 (`AreaScene::in_scatter_counted`) for each emitter shape, on rays that look at the
//! emitter (the phase function's forward peak inside the emitter's solid angle), towards and
//! just past its limb (the peak at the solid angle's rim), pass beside it and look away,
//! Henyey–Greenstein `g` from 0 to 0.99; then in isotropic fog with the emitters
//! focused by cosine lobes `cᵖ`, `p` from 2 to 1024.
//!
//! `cargo run --release -p airlight-tests --example area_bounded_phase`

use airlight::glam::DVec3;
use airlight::phase::{AnyPhase, HenyeyGreenstein};
use airlight::{AreaLight, AreaScene, Emission, Emitter, Medium, Ray};

fn main() {
    let medium = Medium { sigma_s: 0.05, sigma_t: 0.08 };
    let emitters = [
        ("sphere", Emitter::Sphere { center: DVec3::new(6.0, 1.5, -0.5), radius: 0.8 }),
        ("disc", Emitter::Disc { center: DVec3::new(6.0, 1.5, -0.5), normal: DVec3::new(-1.0, -0.4, 0.1), radius: 0.8 }),
        ("rectangle", Emitter::Rectangle { corner: DVec3::new(6.0, 1.0, -1.0), edge_u: DVec3::new(0.1, 0.0, 1.0), edge_v: DVec3::new(0.0, 1.2, 0.1) }),
    ];
    // from the origin (which every emitter faces): towards the emitters' centre, towards the
    // sphere's limb (its rim seen from the origin is 0.8 off the centre's direction at the centre's
    // distance), just past it, beside them, away from them
    let rays = [
        ("at", DVec3::new(6.0, 1.5, -0.5)),
        ("limb", DVec3::new(6.0, 2.25, -0.3)),
        ("past the limb", DVec3::new(6.0, 2.4, -0.5)),
        ("beside", DVec3::new(1.0, 0.0, 0.3)),
        ("away", DVec3::new(-1.0, 0.2, 0.1)),
    ];
    println!("| fog or emission | emitter | ray | value (nested, 1e-9) | bounded: relative error |");
    println!("|---|---|---|---|---|");
    let row = |what: String, name: &str, label: &str, light: AreaLight<f64>, g: f64, dir: DVec3| {
        let ray = Ray { origin: DVec3::ZERO, dir, t_min: 0.0, t_max: f64::INFINITY };
        let scene = AreaScene::new(ray, light, medium, AnyPhase::HenyeyGreenstein(HenyeyGreenstein { g })).unwrap();
        let reference = scene.in_scatter_counted(1e-9).0;
        if reference > 0.0 {
            println!("| {what} | {name} | {label} | {reference:.6e} | {:.1e} |", (scene.in_scatter_bounded() - reference).abs() / reference);
        }
    };
    for g in [0.0, 0.5, 0.8, 0.9, 0.95, 0.99] {
        for (name, emitter) in emitters {
            for (label, dir) in rays {
                row(format!("g = {g}"), name, label, AreaLight::new(emitter, 2.0), g, dir);
            }
        }
    }
    for power in [2, 8, 32, 128, 1024] {
        for (name, emitter) in emitters {
            for (label, dir) in rays {
                row(format!("p = {power}"), name, label, AreaLight { emission: Emission::CosineLobe { power }, ..AreaLight::new(emitter, 2.0) }, 0.0, dir);
            }
        }
    }
}
