//! # airlight
//!
//! Analytic single-scattered light ("air-light") of point and spot lights in a homogeneous
//! participating medium, by the combined formulation of Pegoraro, Schott & Parker, *An
//! Analytical Approach to Single Scattering for Anisotropic Media and Light Distributions*
//! (Graphics Interface 2009): no ray marching, no tables.
//!
//! `#![no_std]`, no allocation, one generic implementation for `f32` and `f64`. The example is
//! the README's (a test keeps the two the same):
//!
//! ```
//! use airlight::glam::Vec3;
//! use airlight::light::TwoLobed;
//! use airlight::phase::HenyeyGreenstein;
//! use airlight::{Expansion, InputError, Medium, PointLight, Ray, Scene};
//!
//! fn main() -> Result<(), InputError> {
//!     let ray = Ray { origin: Vec3::ZERO, dir: Vec3::X, t_min: 0.0, t_max: f32::INFINITY };
//!     let light = PointLight {
//!         position: Vec3::new(5.0, 1.0, 0.0),
//!         intensity: 100.0,
//!         distribution: TwoLobed { axis: Vec3::NEG_Y, power: 4 },
//!     };
//!     let medium = Medium { sigma_s: 0.08, sigma_t: 0.1 };
//!     let scene = Scene::new(ray, light, medium, HenyeyGreenstein { g: 0.5 })?;
//!     let glow = scene.in_scatter(); // error-controlled: within 1e-4 in f32 (the default)
//!     let glow4 = scene.in_scatter_with::<4>(Expansion::Chebyshev); // the paper's fixed cost
//!     assert!(glow > 0.0 && glow4 > 0.0);
//!     Ok(())
//! }
//! ```
//!
//! ## The data path, one module per step
//! 1. [`geometry`]: world space → canonical integral (`h`, `x_h`, `d_el`, `d_c`; paper eq. 4–6).
//! 2. [`combined`]: split at the light's foot (combined formulation, eq. 20), and at a cone's
//!    kinks.
//! 3. The default, error-controlled path: first [`angle`] — the whole segment as one
//!    Gauss–Legendre panel in the light angle, taken where its estimate meets the target
//!    (docs/DESIGN.md §4.2) — else [`panels`] — panels refined until `F/(1+v²)` is
//!    resolved, the exponential integrated exactly by its Legendre moments (docs/DESIGN.md §4.1).
//!    The paper's fixed-cost path instead: [`expansion`] (phase × light as one
//!    polynomial per piece, Chebyshev or Taylor by jets) and [`integrals`] (closed forms of
//!    both reformulations, eq. 8–19, as moments).
//! 4. [`special`]: the exponential integrals (complex `E1` with fixed-bound region selection,
//!    real `E_n`).
//!
//! [`scene`] is the public front: [`Scene`], [`in_scatter`], the surface term and total
//! radiance, and the seeds' [`atan_form`] (with [`lambert_vacuum_form`], its analogue for a
//! Lambertian surface). [`march`] is the ray-marching baseline
//! ([`Scene::ray_march`]) the benchmarks compare against.
#![no_std]
#![warn(missing_docs)]

pub mod angle;
pub mod area;
pub mod combined;
pub mod depth;
pub mod error;
pub mod expansion;
pub mod extended;
pub mod geometry;
pub mod integrals;
pub mod light;
pub mod march;
pub mod panels;
pub mod phase;
pub mod precision;
pub mod record;
mod real;
mod scalar;
pub mod scene;
pub mod special;
pub mod surface;

pub use glam;
pub use area::{AreaLight, AreaScene, Emission, Emitter};
pub use error::{ErrorKind, InputError};
pub use expansion::Expansion;
pub use extended::{SegmentLight, SegmentScene, SHADER_SEGMENT_PANELS};
pub use light::LightDistribution;
pub use phase::PhaseFunction;
pub use precision::{f32, f64};
pub use real::Real;
pub use scalar::Scalar;
pub use surface::{lambert_vacuum_form, Brdf, Surface, SurfaceScene, SHADER_PHONG_PANELS, SHADER_SURFACE_PANELS};
pub use scene::{atan_form, default_control, in_scatter, in_scatter_unchecked, Medium, PointLight, Ray, Scene, CPU_TERMS, FEWER_NODES_FROM, SHADER_CONTROL, SHADER_NODES};
