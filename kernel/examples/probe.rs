use ::airlight::glam::DVec3;
use ::airlight::light::*;
use ::airlight::phase::*;
use ::airlight::{Expansion, Medium, PointLight, Ray, Scene};
fn main() {
    let ray = Ray { origin: DVec3::new(22.32563554375797, -5.593461576947881, -37.06787777782667), dir: DVec3::new(0.14683259423143202, 0.196108473463103, -0.9695265111936028), t_min: 3.846437466782799, t_max: 3.888378113085576 };
    let light = PointLight { position: DVec3::new(22.297738036446876, 0.5964211790557652, -28.118790614938835), intensity: 177.64955326301094, distribution: AnyDistribution::SpotCone(SpotCone { axis: DVec3::new(0.03492419741582102, 0.43351696896371006, -0.9004683992541762), cos_inner: 0.12544632306803094, cos_outer: -0.3277838259092565 }) };
    let s = Scene::new(ray, light, Medium { sigma_s: 0.19572039818455628, sigma_t: 5.69854647906275 }, Isotropic).unwrap();
    println!("{:?}", s.canonical());
    for e in [Expansion::Chebyshev, Expansion::Taylor] {
    println!("{:e} {:e} {:e} {:e} {:e} {:e}", s.in_scatter_with::<6>(e), s.in_scatter_with::<8>(e), s.in_scatter_with::<9>(e), s.in_scatter_with::<10>(e), s.in_scatter_with::<12>(e), s.in_scatter_with::<14>(e));
    }
}
