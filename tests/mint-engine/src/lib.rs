//! An engine whose math is glam 0.29 (`engine_glam`), calling the airlight kernel (glam 0.30)
//! through mint, the interop types both glam versions convert to and from. Passing an
//! `engine_glam::Vec3` where airlight wants its own `Vec3` would not compile ("two different
//! versions of crate glam"); `to_airlight` is the whole bridge.

use airlight::f32::{Medium, PointLight, Ray, Scene, Vec3};
use airlight::light::Omni;
use airlight::phase::HenyeyGreenstein;
use airlight::InputError;

/// An engine vector as airlight's, through `mint::Vector3`.
pub fn to_airlight(v: engine_glam::Vec3) -> Vec3 {
    let m: mint::Vector3<f32> = v.into();
    Vec3::from(m)
}

/// The fog glow along the engine's view ray from `eye` to the surface point `p`, of an omni
/// light at `lamp`, in Henyey–Greenstein fog with asymmetry `g`.
pub fn glow(eye: engine_glam::Vec3, p: engine_glam::Vec3, lamp: engine_glam::Vec3, g: f32) -> Result<f32, InputError> {
    let to_p = p - eye;
    let ray = Ray { origin: to_airlight(eye), dir: to_airlight(to_p), t_min: 0.0, t_max: to_p.length() };
    let light = PointLight { position: to_airlight(lamp), intensity: 100.0, distribution: Omni };
    Ok(Scene::new(ray, light, Medium { sigma_s: 0.05, sigma_t: 0.1 }, HenyeyGreenstein { g })?.in_scatter())
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The engine's call gives what the same scene built from airlight's own vectors gives,
    /// bit for bit, and vectors survive the round trip.
    #[test]
    fn engine_vectors_cross_over_through_mint() {
        let (eye, p, lamp) = (engine_glam::Vec3::new(0.0, 1.7, 0.0), engine_glam::Vec3::new(30.0, 0.0, 2.0), engine_glam::Vec3::new(5.0, 4.0, 0.0));
        let from_engine = glow(eye, p, lamp, 0.9).unwrap();
        let ray = Ray { origin: Vec3::new(0.0, 1.7, 0.0), dir: Vec3::new(30.0, -1.7, 2.0), t_min: 0.0, t_max: Vec3::new(30.0, -1.7, 2.0).length() };
        let light = PointLight { position: Vec3::new(5.0, 4.0, 0.0), intensity: 100.0, distribution: Omni };
        let direct = Scene::new(ray, light, Medium { sigma_s: 0.05, sigma_t: 0.1 }, HenyeyGreenstein { g: 0.9 }).unwrap().in_scatter();
        assert!(from_engine > 0.0);
        assert_eq!(from_engine.to_bits(), direct.to_bits());
        let back: engine_glam::Vec3 = mint::Vector3::from(to_airlight(lamp)).into();
        assert_eq!(back, lamp);
        assert!(glow(eye, p, lamp, 1.5).is_err(), "a bad g is still a typed error");
    }
}
