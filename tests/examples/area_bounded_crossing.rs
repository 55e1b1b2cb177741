//! The bounded area-light method (`AreaScene::in_scatter_bounded`, docs/DESIGN.md §12) on rays
//! that cross a rectangle's plane just inside or outside its corners and the middles of its
//! edges (and a disc's plane by its rim), in Henyey–Greenstein fog of `g` = 0.95 and 0.99: there the phase lobe's point `q_L`
//! (where the ray's line meets the plane) lies next to the edge, and the emitter is taken about
//! it (`flat_about_lobe`; docs/DESIGN.md §12 gives what this prints and what is not yet met).
//! Relative error against the nested construction at 1e-10
//! (`AreaScene::in_scatter_counted`), by default and with the ray integral to 1e-7 (what is left
//! then is the emitter's rules'); crossing points `offset` inside (> 0) or outside (< 0) along a
//! direction from the corner or edge point.
//!
//! `cargo run --release -p airlight-tests --example area_bounded_crossing`

use airlight::glam::DVec3;
use airlight::phase::{AnyPhase, HenyeyGreenstein};
use airlight::{AreaLight, AreaScene, Emitter, Medium, Ray};

fn main() {
    let medium = Medium { sigma_s: 0.05, sigma_t: 0.08 };
    let (corner, eu, ev) = (DVec3::new(6.0, 1.0, -1.0), DVec3::new(0.1, 0.0, 1.0), DVec3::new(0.0, 1.2, 0.1));
    let rect = Emitter::Rectangle { corner, edge_u: eu, edge_v: ev };
    println!("| g | crossing near (u, v) | offset | towards | default | ray to 1e-7 |");
    println!("|---|---|---|---|---|---|");
    let mut worst = [0.0f64; 2];
    for g in [0.95, 0.99] {
        // the corners (0, 0) and (1, 1), the middles of the edges v = 0 and u = 1; inward directions
        for ((u, v), inward) in [((0.0, 0.0), 1.0), ((1.0, 1.0), -1.0), ((0.5, 0.0), 1.0), ((1.0, 0.5), -1.0)] {
            for offset in [-0.002, -0.0005, -0.0001, -0.00001, 0.00001, 0.0001, 0.0005, 0.002, 0.01] {
                for (label, (a, b)) in [("u", (1.0, 0.0)), ("v", (0.0, 1.0)), ("diagonal", (0.7, 0.7))] {
                    let towards = (eu * a + ev * b).normalize() * inward;
                    let dir = corner + eu * u + ev * v + towards * offset;
                    let ray = Ray { origin: DVec3::ZERO, dir, t_min: 0.0, t_max: f64::INFINITY };
                    let scene = AreaScene::new(ray, AreaLight::new(rect, 2.0), medium, AnyPhase::HenyeyGreenstein(HenyeyGreenstein { g })).unwrap();
                    let exact = scene.in_scatter_counted(1e-10).0;
                    let errors = [scene.in_scatter_bounded(), scene.in_scatter_bounded_counted(1e-7, 1000).0].map(|x| (x - exact).abs() / exact);
                    worst = [worst[0].max(errors[0]), worst[1].max(errors[1])];
                    println!("| {g} | ({u}, {v}) | {offset} | {label} | {:.1e} | {:.1e} |", errors[0], errors[1]);
                }
            }
        }
    }
    // a disc of the rectangle's plane and size, crossed next to its rim across it (radially) and
    // along it (its tangent)
    let (center, normal, radius) = (corner + 0.5 * (eu + ev), eu.cross(ev).normalize(), 0.6);
    let disc = Emitter::Disc { center, normal, radius };
    let (radial, tangent) = (eu.normalize(), normal.cross(eu.normalize()));
    for g in [0.95, 0.99] {
        for offset in [-0.002, -0.0005, -0.00001, 0.00001, 0.0005, 0.002, 0.01] {
            for (label, dir) in [("across the rim", center + radial * (radius - offset)), ("along the rim", center + radial * (radius - offset) + tangent * 0.05)] {
                let ray = Ray { origin: DVec3::ZERO, dir, t_min: 0.0, t_max: f64::INFINITY };
                let scene = AreaScene::new(ray, AreaLight::new(disc, 2.0), medium, AnyPhase::HenyeyGreenstein(HenyeyGreenstein { g })).unwrap();
                let exact = scene.in_scatter_counted(1e-10).0;
                let errors = [scene.in_scatter_bounded(), scene.in_scatter_bounded_counted(1e-7, 1000).0].map(|x| (x - exact).abs() / exact);
                worst = [worst[0].max(errors[0]), worst[1].max(errors[1])];
                println!("| {g} | disc's rim | {offset} | {label} | {:.1e} | {:.1e} |", errors[0], errors[1]);
            }
        }
    }
    println!("\nlargest: {:.1e} by default, {:.1e} with the ray to 1e-7", worst[0], worst[1]);
}
