//! The scene types with the precision fixed: `airlight::f32::Ray` is `Ray<f32>` and so on, so a
//! scene needs no type annotation. Without them, float literals default to `f64` while
//! `glam::Vec3` is `f32`, and the precision is only reachable through the vector type's
//! associated type, which Rust does not infer backwards.
//!
//! ```
//! use airlight::f64::{Medium, PointLight, Ray, Scene, Vec3};
//! use airlight::{light::Omni, phase::HenyeyGreenstein};
//! let ray = Ray { origin: Vec3::ZERO, dir: Vec3::X, t_min: 0.0, t_max: 25.0 };
//! let light = PointLight { position: Vec3::new(5.0, 1.0, 0.0), intensity: 100.0, distribution: Omni };
//! let scene = Scene::new(ray, light, Medium { sigma_s: 0.08, sigma_t: 0.1 }, HenyeyGreenstein { g: 0.5 }).unwrap();
//! assert!(scene.in_scatter() > 0.0);
//! ```
//!
//! ```
//! use airlight::f32::{Medium, PointLight, Ray, Scene, Vec3};
//! use airlight::{light::TwoLobed, phase::Rayleigh};
//! let ray = Ray { origin: Vec3::ZERO, dir: Vec3::X, t_min: 0.0, t_max: 25.0 };
//! let light = PointLight { position: Vec3::new(5.0, 1.0, 0.0), intensity: 100.0, distribution: TwoLobed { axis: Vec3::NEG_Y, power: 4 } };
//! let scene = Scene::new(ray, light, Medium { sigma_s: 0.08, sigma_t: 0.1 }, Rayleigh).unwrap();
//! assert!(scene.in_scatter() > 0.0);
//! ```

/// The aliases of one precision (one macro, so the two modules cannot drift apart).
macro_rules! precision {
    ($name:ident, $t:ty, $vec:ty, $what:literal) => {
        #[doc = concat!("The scene types in ", $what, " (see [`crate::precision`]).")]
        pub mod $name {
            /// The vector type of this precision.
            pub type Vec3 = $vec;
            /// [`crate::Ray`] in this precision.
            pub type Ray = crate::Ray<$t>;
            /// [`crate::Medium`] in this precision.
            pub type Medium = crate::Medium<$t>;
            /// [`crate::PointLight`] in this precision.
            pub type PointLight<D> = crate::PointLight<$t, D>;
            /// [`crate::Scene`] in this precision.
            pub type Scene<D, P> = crate::Scene<$t, D, P>;
            /// [`crate::panels::Control`] in this precision.
            pub type Control = crate::panels::Control<$t>;
        }
    };
}

precision!(f32, ::core::primitive::f32, glam::Vec3, "`f32`");
precision!(f64, ::core::primitive::f64, glam::DVec3, "`f64`");
