//! Links the kernel into a `#![no_std]` artifact with its own panic handler.
#![no_std]

use airlight::glam::{DVec3, Vec3};
use airlight::light::Omni;
use airlight::phase::HenyeyGreenstein;
use airlight::{Medium, PointLight, Ray, Scene};

#[panic_handler]
fn panic(_: &core::panic::PanicInfo) -> ! {
    loop {}
}

/// `L_m` in f32 for a ray along +x and a light at (x, y, 0); 0 for invalid input.
#[no_mangle]
pub extern "C" fn airlight_nostd_in_scatter_f32(x: f32, y: f32, sigma_s: f32, sigma_t: f32, g: f32) -> f32 {
    let ray = Ray { origin: Vec3::ZERO, dir: Vec3::X, t_min: 0.0, t_max: 100.0 };
    let light = PointLight { position: Vec3::new(x, y, 0.0), intensity: 1.0, distribution: Omni };
    match Scene::new(ray, light, Medium { sigma_s, sigma_t }, HenyeyGreenstein { g }) {
        Ok(s) => s.in_scatter_with::<4>(airlight::Expansion::Chebyshev),
        Err(_) => 0.0,
    }
}

/// The same in f64 with 6 terms.
#[no_mangle]
pub extern "C" fn airlight_nostd_in_scatter_f64(x: f64, y: f64, sigma_s: f64, sigma_t: f64, g: f64) -> f64 {
    let ray = Ray { origin: DVec3::ZERO, dir: DVec3::X, t_min: 0.0, t_max: 100.0 };
    let light = PointLight { position: DVec3::new(x, y, 0.0), intensity: 1.0, distribution: Omni };
    match Scene::new(ray, light, Medium { sigma_s, sigma_t }, HenyeyGreenstein { g }) {
        Ok(s) => s.in_scatter(),
        Err(_) => 0.0,
    }
}
