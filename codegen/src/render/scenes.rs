//! The five scenes, after the source papers' kinds of pictures.

use super::world::{Camera, Cuboid, Light, Rgb, SceneDesc};
use airlight::glam::DVec3;
use airlight::light::{AnyDistribution, SpotCone, TwoLobed};
use airlight::phase::{AnyPhase, HenyeyGreenstein, Schlick};
use airlight::{Medium, PointLight};

fn sph(x: f64, y: f64, z: f64) -> DVec3 {
    DVec3::new(x, y, z).normalize()
}

fn spot(position: [f64; 3], target: [f64; 3], intensity: f64, inner_deg: f64, outer_deg: f64, color: Rgb) -> Light {
    let p = DVec3::from_array(position);
    Light {
        light: PointLight {
            position: p,
            intensity,
            distribution: AnyDistribution::SpotCone(SpotCone {
                axis: (DVec3::from_array(target) - p).normalize(),
                cos_inner: inner_deg.to_radians().cos(),
                cos_outer: outer_deg.to_radians().cos(),
            }),
        },
        tube_end: None,
        color,
    }
}

fn omni(position: [f64; 3], intensity: f64, color: Rgb) -> Light {
    Light { light: PointLight { position: DVec3::from_array(position), intensity, distribution: AnyDistribution::Omni }, tube_end: None, color }
}

/// A lighthouse on a headland at night: a tall tower, the lamp's two-lobed beam (`D = c^12`,
/// axis nearly horizontal, one lobe swept towards the viewer's side) and a dim cottage light
/// at the foot, in thick brume (`σs = 0.08`, `σt = 0.1`), Henyey–Greenstein `g = 0.6`.
pub fn lighthouse(width: u32, height: u32) -> SceneDesc {
    let white = [0.85, 0.85, 0.8];
    SceneDesc {
        name: "lighthouse",
        camera: Camera { position: DVec3::new(-13.0, 2.0, 22.0), look_at: DVec3::new(1.0, 13.0, 0.0), vfov_deg: 60.0, width, height },
        medium: Medium { sigma_s: 0.08, sigma_t: 0.1 },
        phase: AnyPhase::HenyeyGreenstein(HenyeyGreenstein { g: 0.6 }),
        lights: vec![Light {
            light: PointLight {
                position: DVec3::new(0.0, 21.0, 0.0),
                intensity: 20000.0,
                distribution: AnyDistribution::TwoLobed(TwoLobed { axis: sph(1.0, -0.06, 0.45), power: 12 }),
            },
            tube_end: None,
            color: [1.0, 0.93, 0.78],
        },
        // the keeper's cottage window, a dim omni light by the tower's foot
        omni([4.0, 2.2, 5.0], 40.0, [1.0, 0.7, 0.4])],
        ground: Some([0.12, 0.13, 0.14]),
        boxes: vec![
            Cuboid::new([-1.6, 0.0, -1.6], [1.6, 19.0, 1.6], white),
            Cuboid::new([-2.2, 19.0, -2.2], [2.2, 19.6, 2.2], [0.3, 0.1, 0.1]),
            Cuboid::new([-1.0, 22.4, -1.0], [1.0, 23.0, 1.0], [0.3, 0.1, 0.1]),
            Cuboid::new([-9.0, 0.0, -7.0], [7.0, 1.5, 6.0], [0.25, 0.22, 0.2]),
        ],
        exposure: 2.5,
        fog_lit_surfaces: false,
    }
}

/// A foggy road: an oncoming car's two headlights (spot cones, 10°/24°, low above the road,
/// pointing along it towards the camera's side) and a sodium streetlamp on a pole (a spot
/// pointing down, 35°/65°); `σs = 0.05`, `σt = 0.06`, Schlick `k = 0.5`.
pub fn road(width: u32, height: u32) -> SceneDesc {
    let head = [1.0, 0.95, 0.85];
    let sodium = [1.0, 0.55, 0.2];
    let metal = [0.3, 0.3, 0.32];
    SceneDesc {
        name: "road",
        camera: Camera { position: DVec3::new(-1.8, 1.3, 6.0), look_at: DVec3::new(0.5, 1.6, -30.0), vfov_deg: 45.0, width, height },
        medium: Medium { sigma_s: 0.05, sigma_t: 0.06 },
        phase: AnyPhase::Schlick(Schlick { k: 0.5 }),
        lights: vec![
            spot([1.1, 0.7, -21.9], [0.6, 0.0, 8.0], 400.0, 10.0, 24.0, head),
            spot([2.5, 0.7, -21.9], [2.0, 0.0, 8.0], 400.0, 10.0, 24.0, head),
            spot([-3.6, 6.3, -12.0], [-2.6, 0.0, -12.0], 600.0, 35.0, 65.0, sodium),
        ],
        ground: Some([0.12, 0.12, 0.12]),
        boxes: vec![
            // car body and cabin
            Cuboid::new([0.8, 0.3, -26.0], [2.8, 1.1, -22.0], [0.35, 0.05, 0.05]),
            Cuboid::new([1.0, 1.1, -25.5], [2.6, 1.7, -23.5], [0.1, 0.1, 0.12]),
            // lamp post and arm
            Cuboid::new([-5.15, 0.0, -12.15], [-4.85, 6.8, -11.85], metal),
            Cuboid::new([-5.0, 6.6, -12.15], [-3.2, 6.8, -11.85], metal),
            // kerb
            Cuboid::new([-40.0, 0.0, -200.0], [-4.0, 0.15, 10.0], [0.2, 0.2, 0.2]),
        ],
        exposure: 2.0,
        fog_lit_surfaces: false,
    }
}

/// A concert stage lit by three coloured spot lights (red, green, blue; 7°/13°) hanging
/// above it and crossing on the stage floor, in a thin haze (`σs = 0.025`, `σt = 0.03`),
/// Henyey–Greenstein `g = 0.3`.
pub fn stage(width: u32, height: u32) -> SceneDesc {
    SceneDesc {
        name: "stage",
        camera: Camera { position: DVec3::new(0.0, 5.5, 15.0), look_at: DVec3::new(0.0, 3.5, -4.0), vfov_deg: 55.0, width, height },
        medium: Medium { sigma_s: 0.025, sigma_t: 0.03 },
        phase: AnyPhase::HenyeyGreenstein(HenyeyGreenstein { g: 0.3 }),
        lights: vec![
            spot([-5.0, 9.0, -3.0], [0.0, 1.0, -5.0], 2500.0, 9.0, 15.0, [1.0, 0.08, 0.05]),
            spot([0.0, 9.5, -1.5], [0.0, 1.0, -5.0], 2500.0, 9.0, 15.0, [0.08, 1.0, 0.12]),
            spot([5.0, 9.0, -3.0], [0.0, 1.0, -5.0], 2500.0, 9.0, 15.0, [0.1, 0.25, 1.0]),
        ],
        ground: Some([0.05, 0.05, 0.05]),
        boxes: vec![
            Cuboid::new([-7.0, 0.0, -9.0], [7.0, 1.0, -1.0], [0.35, 0.3, 0.28]),
            Cuboid::new([-12.0, 0.0, -11.0], [12.0, 14.0, -10.0], [0.12, 0.12, 0.14]),
            Cuboid::new([-8.0, 10.0, -4.0], [8.0, 10.4, -1.0], [0.15, 0.15, 0.15]),
        ],
        exposure: 3.0,
        fog_lit_surfaces: false,
    }
}

/// A park bench beside an omni lamp on a post, a second lamp further back, in a mist of
/// small droplets with Rayleigh scattering (`σs = 0.07`, `σt = 0.08`).
pub fn bench(width: u32, height: u32) -> SceneDesc {
    let wood = [0.45, 0.28, 0.15];
    let iron = [0.08, 0.08, 0.09];
    let mut boxes = vec![
        // lamp posts (the lamps sit just above their tops)
        Cuboid::new([-1.06, 0.0, -0.06], [-0.94, 3.0, 0.06], iron),
        Cuboid::new([-9.06, 0.0, -12.06], [-8.94, 3.0, -11.94], iron),
        // bench legs
        Cuboid::new([0.1, 0.0, -0.3], [0.18, 0.45, 0.3], iron),
        Cuboid::new([1.82, 0.0, -0.3], [1.9, 0.45, 0.3], iron),
    ];
    for z in [-0.28, -0.12, 0.04] {
        boxes.push(Cuboid::new([0.0, 0.45, z], [2.0, 0.5, z + 0.13], wood));
    }
    for y in [0.62, 0.8] {
        boxes.push(Cuboid::new([0.0, y, 0.24], [2.0, y + 0.12, 0.3], wood));
    }
    SceneDesc {
        name: "bench",
        camera: Camera { position: DVec3::new(4.5, 1.5, 5.5), look_at: DVec3::new(-0.5, 1.2, -1.0), vfov_deg: 50.0, width, height },
        medium: Medium { sigma_s: 0.07, sigma_t: 0.08 },
        phase: AnyPhase::Rayleigh,
        lights: vec![omni([-1.0, 3.15, 0.0], 30.0, [1.0, 0.82, 0.55]), omni([-9.0, 3.15, -12.0], 30.0, [0.85, 0.9, 1.0])],
        ground: Some([0.1, 0.14, 0.08]),
        boxes,
        exposure: 1.0,
        fog_lit_surfaces: false,
    }
}

/// A street at night in fog (`σs = 0.04`, `σt = 0.05`, Henyey–Greenstein `g = 0.5`): a
/// fluorescent tube (a segment light, 3 units long) on a building's wall and a streetlamp (an
/// omni light on a post) across the street, a kiosk on the pavement. Every surface also
/// receives the lamp's air-light ([`SceneDesc::fog_lit_surfaces`]): the kiosk's faces turned away
/// from the lamp, black under direct light alone, glow with the fog's light.
pub fn street(width: u32, height: u32) -> SceneDesc {
    let brick = [0.35, 0.22, 0.18];
    let tube = PointLight { position: DVec3::new(-4.75, 3.2, -9.0), intensity: 25.0, distribution: AnyDistribution::Omni };
    SceneDesc {
        name: "street",
        camera: Camera { position: DVec3::new(1.5, 1.7, 6.0), look_at: DVec3::new(-2.0, 2.2, -14.0), vfov_deg: 55.0, width, height },
        medium: Medium { sigma_s: 0.04, sigma_t: 0.05 },
        phase: AnyPhase::HenyeyGreenstein(HenyeyGreenstein { g: 0.5 }),
        lights: vec![
            Light { light: tube, tube_end: Some(DVec3::new(-4.75, 3.2, -6.0)), color: [0.8, 0.9, 1.0] },
            omni([3.5, 5.05, -16.0], 150.0, [1.0, 0.7, 0.35]),
        ],
        ground: Some([0.1, 0.1, 0.11]),
        boxes: vec![
            // the building's wall along the street, its face at x = −5
            Cuboid::new([-9.0, 0.0, -60.0], [-5.0, 9.0, 8.0], brick),
            // the lamp's post (the lamp sits just above its top)
            Cuboid::new([3.44, 0.0, -16.06], [3.56, 4.9, -15.94], [0.08, 0.08, 0.09]),
            // a kiosk on the pavement between the tube and the lamp
            Cuboid::new([-4.5, 0.0, -14.0], [-2.5, 2.2, -12.0], [0.5, 0.5, 0.45]),
            // the kerb
            Cuboid::new([-5.0, 0.0, -60.0], [-4.0, 0.15, 8.0], [0.2, 0.2, 0.2]),
        ],
        exposure: 1.0,
        fog_lit_surfaces: true,
    }
}

/// The scene names, in order.
pub const SCENES: [&str; 5] = ["lighthouse", "road", "stage", "bench", "street"];

/// The scene called `name` (one of [`SCENES`]) at `width × height`.
pub fn scene_by_name(name: &str, width: u32, height: u32) -> Option<SceneDesc> {
    match name {
        "lighthouse" => Some(lighthouse(width, height)),
        "road" => Some(road(width, height)),
        "stage" => Some(stage(width, height)),
        "bench" => Some(bench(width, height)),
        "street" => Some(street(width, height)),
        _ => None,
    }
}
