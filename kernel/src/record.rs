//! A scene as plain parts with its kinds chosen at run time ([`AnyDistribution`],
//! [`AnyPhase`]): what a JSON line, a GPU record and a fuzz input each describe, before the
//! checks of [`Scene::new`]; and its conversion between precisions.

use crate::light::{AnyDistribution, SpotCone, TwoLobed};
use crate::phase::{AnyPhase, CornetteShanks, HenyeyGreenstein, Schlick, TwoLobeHenyeyGreenstein};
use crate::{Emitter, InputError, Medium, PointLight, Ray, Real, Scene};

/// A scene record: the four parts of a [`Scene`], unchecked.
#[derive(Clone, Copy, Debug)]
pub struct SceneRecord<T: Real> {
    /// The ray segment.
    pub ray: Ray<T>,
    /// The light.
    pub light: PointLight<T, AnyDistribution<T>>,
    /// The medium.
    pub medium: Medium<T>,
    /// The phase function.
    pub phase: AnyPhase<T>,
}

/// `x` in precision `U` (exact when widening, rounded to nearest when narrowing).
fn cast<T: Real, U: Real>(x: T) -> U {
    U::lit(x.to_f64_exact())
}

fn cast3<T: Real, U: Real>(v: T::Vec3) -> U::Vec3 {
    U::vec3_from_array(T::vec3_to_array(v).map(cast::<T, U>))
}

/// A light in precision `U`.
pub fn cast_light<T: Real, U: Real>(l: &PointLight<T, AnyDistribution<T>>) -> PointLight<U, AnyDistribution<U>> {
    let distribution = match l.distribution {
        AnyDistribution::Omni => AnyDistribution::Omni,
        AnyDistribution::TwoLobed(d) => AnyDistribution::TwoLobed(TwoLobed { axis: cast3::<T, U>(d.axis), power: d.power }),
        AnyDistribution::SpotCone(d) => {
            AnyDistribution::SpotCone(SpotCone { axis: cast3::<T, U>(d.axis), cos_inner: cast(d.cos_inner), cos_outer: cast(d.cos_outer) })
        }
    };
    PointLight { position: cast3::<T, U>(l.position), intensity: cast(l.intensity), distribution }
}

/// An area light's emitter in precision `U`.
pub fn cast_emitter<T: Real, U: Real>(e: &Emitter<T>) -> Emitter<U> {
    match *e {
        Emitter::Disc { center, normal, radius } => Emitter::Disc { center: cast3::<T, U>(center), normal: cast3::<T, U>(normal), radius: cast(radius) },
        Emitter::Rectangle { corner, edge_u, edge_v } => Emitter::Rectangle { corner: cast3::<T, U>(corner), edge_u: cast3::<T, U>(edge_u), edge_v: cast3::<T, U>(edge_v) },
        Emitter::Sphere { center, radius } => Emitter::Sphere { center: cast3::<T, U>(center), radius: cast(radius) },
    }
}

/// A phase function in precision `U`.
pub fn cast_phase<T: Real, U: Real>(p: &AnyPhase<T>) -> AnyPhase<U> {
    match *p {
        AnyPhase::Isotropic => AnyPhase::Isotropic,
        AnyPhase::Rayleigh => AnyPhase::Rayleigh,
        AnyPhase::HenyeyGreenstein(p) => AnyPhase::HenyeyGreenstein(HenyeyGreenstein { g: cast(p.g) }),
        AnyPhase::Schlick(p) => AnyPhase::Schlick(Schlick { k: cast(p.k) }),
        AnyPhase::CornetteShanks(p) => AnyPhase::CornetteShanks(CornetteShanks { g: cast(p.g) }),
        AnyPhase::TwoLobeHenyeyGreenstein(p) => {
            AnyPhase::TwoLobeHenyeyGreenstein(TwoLobeHenyeyGreenstein { g1: cast(p.g1), g2: cast(p.g2), w: cast(p.w) })
        }
    }
}

impl<T: Real> SceneRecord<T> {
    /// The record in precision `U`: every number exact when widening (f32 → f64), rounded to
    /// nearest when narrowing.
    pub fn cast<U: Real>(&self) -> SceneRecord<U> {
        let r = &self.ray;
        SceneRecord {
            ray: Ray { origin: cast3::<T, U>(r.origin), dir: cast3::<T, U>(r.dir), t_min: cast(r.t_min), t_max: cast(r.t_max) },
            light: cast_light(&self.light),
            medium: Medium { sigma_s: cast(self.medium.sigma_s), sigma_t: cast(self.medium.sigma_t) },
            phase: cast_phase(&self.phase),
        }
    }

    /// The checked scene ([`Scene::new`]).
    ///
    /// # Errors
    /// [`InputError`] naming the first invalid field.
    pub fn scene(&self) -> Result<Scene<T, AnyDistribution<T>, AnyPhase<T>>, InputError> {
        Scene::new(self.ray, self.light, self.medium, self.phase)
    }
}
