//! Scene records as JSON lines (docs/DESIGN.md §6) → kernel types, with errors that name the field.
//!
//! ```json
//! {"ray": {"origin": [0,0,0], "dir": [1,0,0], "t_min": 0.0, "t_max": 25.0},
//!  "medium": {"sigma_s": 0.08, "sigma_t": 0.1},
//!  "light": {"position": [5,1,0], "intensity": 100.0,
//!            "distribution": {"kind": "two_lobed", "axis": [0,-1,0], "power": 4}},
//!  "phase": {"kind": "henyey_greenstein", "g": 0.5}}
//! ```
//! A surface record (docs/DESIGN.md §11) has `"surface": {"position": [..], "normal": [..],
//! "brdf": {"kind": "lambert", "albedo": ρ}}` (or `{"kind": "phong", "k_s": k, "exponent": n,
//! "view": [..]}`) in place of the ray, and a point light.
//!
//! `t_max: null` (or absent, or `"inf"`) means `+∞`, an absent `t_min` 0, an absent
//! `distribution` or `phase` isotropic. Any other key is an error naming it (with the closest
//! known key when one is close), except the annotations [`ANNOTATIONS`], which never change the
//! evaluation. Numbers are read as f64 and rounded to the evaluation precision; one that
//! overflows it is an error.
//!
//! The format is the serde types below (`deny_unknown_fields`); serde_path_to_error names the
//! field of a decoding error, and [`SceneJson::to_record`] converts to the kernel's
//! [`SceneRecord`] and validates it.

use airlight::light::{AnyDistribution, SpotCone, TwoLobed};
use airlight::phase::{AnyPhase, CornetteShanks, HenyeyGreenstein, Schlick, TwoLobeHenyeyGreenstein};
use airlight::record::SceneRecord;
use airlight::{AreaLight, AreaScene, Brdf, Emission, Emitter, Medium, PointLight, Ray, Real, SegmentLight, SegmentScene, Surface, SurfaceScene};
use serde::de::IgnoredAny;
use serde::{de, Deserialize, Deserializer};
use serde_json::Value;

/// A record that could not be read: the field path and what was expected.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct FieldError {
    /// Dotted path of the field, e.g. `light.distribution.power`.
    pub field: String,
    /// What is wrong.
    pub message: String,
}

impl std::fmt::Display for FieldError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(f, "{}: {}", self.field, self.message)
    }
}

/// Top-level keys a record may carry besides `ray` (or `surface`), `medium`, `light` and
/// `phase`, ignored by the evaluation: `id`, `comment` and `category` (free text),
/// `in_scatter`, `scale` and `surface_air_light` (reference values, as the committed references
/// carry them).
pub const ANNOTATIONS: [&str; 6] = ["id", "comment", "category", "in_scatter", "scale", "surface_air_light"];

/// One JSON-lines record, as written.
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct SceneJson {
    /// The ray (a record has a ray or a surface).
    #[serde(default)]
    pub ray: Option<RayJson>,
    /// The surface point whose air-light is wanted, in place of a ray.
    #[serde(default)]
    pub surface: Option<SurfaceJson>,
    /// The medium.
    pub medium: MediumJson,
    /// The point light.
    pub light: LightJson,
    /// The phase function; absent or `null`: isotropic.
    #[serde(default)]
    pub phase: Option<PhaseJson>,
    #[serde(default, rename = "id")]
    _id: Option<IgnoredAny>,
    #[serde(default, rename = "comment")]
    _comment: Option<IgnoredAny>,
    #[serde(default, rename = "category")]
    _category: Option<IgnoredAny>,
    #[serde(default, rename = "in_scatter")]
    _in_scatter: Option<IgnoredAny>,
    #[serde(default, rename = "scale")]
    _scale: Option<IgnoredAny>,
    #[serde(default, rename = "surface_air_light")]
    _surface_air_light: Option<IgnoredAny>,
}

/// `surface`: a point, its normal and its BRDF.
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct SurfaceJson {
    /// The point.
    pub position: [f64; 3],
    /// Its normal (any length but zero).
    pub normal: [f64; 3],
    /// Its reflectance.
    pub brdf: BrdfJson,
}

/// `surface.brdf`, by `kind`.
#[derive(Debug)]
pub enum BrdfJson {
    /// `"lambert"`: `albedo/π`.
    Lambert(LambertJson),
    /// `"phong"`: `k_s (n+2)/(2π) max(0, r·ω)^n` about the mirror image `r` of `view`.
    Phong(PhongJson),
}

/// The field of a Lambertian BRDF.
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct LambertJson {
    /// Albedo.
    pub albedo: f64,
}

/// The fields of a Phong lobe.
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct PhongJson {
    /// Specular coefficient.
    pub k_s: f64,
    /// Exponent.
    pub exponent: f64,
    /// From the surface towards the eye.
    pub view: [f64; 3],
}

impl<'de> Deserialize<'de> for BrdfJson {
    fn deserialize<D: Deserializer<'de>>(d: D) -> Result<Self, D::Error> {
        let (kind, object) = kind_and_fields(d)?;
        Ok(match kind.as_str() {
            "lambert" => Self::Lambert(fields(object)?),
            "phong" => Self::Phong(fields(object)?),
            _ => return Err(de::Error::unknown_variant(&kind, &["lambert", "phong"])),
        })
    }
}

/// `ray`: `origin + t·dir`, `t ∈ [t_min, t_max]`.
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct RayJson {
    /// Origin.
    pub origin: [f64; 3],
    /// Direction (any length but zero).
    pub dir: [f64; 3],
    /// Start; absent: 0.
    #[serde(default)]
    pub t_min: f64,
    /// End; absent, `null` or `"inf"`: `+∞`.
    #[serde(default = "infinity", deserialize_with = "t_max")]
    pub t_max: f64,
}

fn infinity() -> f64 {
    f64::INFINITY
}

/// A number, `null` or the string `"inf"` (both `+∞`).
fn t_max<'de, D: Deserializer<'de>>(d: D) -> Result<f64, D::Error> {
    #[derive(Deserialize)]
    #[serde(untagged)]
    enum Bound {
        Number(f64),
        Text(String),
        Null(()),
    }
    match Bound::deserialize(d)? {
        Bound::Number(x) => Ok(x),
        Bound::Null(()) => Ok(f64::INFINITY),
        Bound::Text(s) if s == "inf" => Ok(f64::INFINITY),
        Bound::Text(s) => Err(serde::de::Error::custom(format!("expected a number, null or \"inf\", found \"{s}\""))),
    }
}

/// `medium`: scattering and extinction coefficients.
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct MediumJson {
    /// σs.
    pub sigma_s: f64,
    /// σt.
    pub sigma_t: f64,
}

/// `light`, by `shape`: a point light (`shape` absent or `"point"`), a segment light
/// (`"segment"`, docs/DESIGN.md §10), or an area light (`"disc"`, `"rectangle"`, `"sphere"`, §12).
#[derive(Debug)]
pub enum LightJson {
    /// A point light.
    Point(PointLightJson),
    /// A segment light: every point of `a → b` emits `intensity` per unit length.
    Segment(SegmentLightJson),
    /// A disc of uniform radiance (docs/DESIGN.md §12).
    Disc(DiscJson),
    /// A parallelogram of uniform radiance.
    Rectangle(RectangleJson),
    /// A sphere of uniform radiance.
    Sphere(SphereJson),
}

/// The fields of a disc light.
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct DiscJson {
    /// Centre.
    pub center: [f64; 3],
    /// Normal of the emitting side.
    pub normal: [f64; 3],
    /// Radius.
    pub radius: f64,
    /// Radiance of every point along its normal.
    pub radiance: f64,
    /// How every point emits about its normal; absent or `null`: Lambertian.
    #[serde(default)]
    pub emission: Option<EmissionJson>,
}

/// The fields of a rectangle (parallelogram) light.
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct RectangleJson {
    /// One corner.
    pub corner: [f64; 3],
    /// The first edge from it.
    pub edge_u: [f64; 3],
    /// The second edge from it; the emitting side is that of `edge_u × edge_v`.
    pub edge_v: [f64; 3],
    /// Radiance of every point along its normal.
    pub radiance: f64,
    /// How every point emits about its normal; absent or `null`: Lambertian.
    #[serde(default)]
    pub emission: Option<EmissionJson>,
}

/// The fields of a sphere light.
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct SphereJson {
    /// Centre.
    pub center: [f64; 3],
    /// Radius.
    pub radius: f64,
    /// Radiance of every point along its outward normal.
    pub radiance: f64,
    /// How every point emits about its normal; absent or `null`: Lambertian.
    #[serde(default)]
    pub emission: Option<EmissionJson>,
}

/// `light.emission` of an area light, by `kind` ([`airlight::Emission`]).
#[derive(Debug)]
pub enum EmissionJson {
    /// `"lambertian"`: `D = c`, uniform radiance.
    Lambertian,
    /// `"cosine_lobe"`: `D = c^power`, `power` an integer from 1 to 1024.
    CosineLobe(CosineLobeJson),
}

/// The field of a `"cosine_lobe"` emission.
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct CosineLobeJson {
    /// Power (an integer, read as a number).
    pub power: f64,
}

impl<'de> Deserialize<'de> for EmissionJson {
    fn deserialize<D: Deserializer<'de>>(d: D) -> Result<Self, D::Error> {
        let (kind, object) = kind_and_fields(d)?;
        Ok(match kind.as_str() {
            "lambertian" => {
                let NoFields {} = fields(object)?;
                Self::Lambertian
            }
            "cosine_lobe" => Self::CosineLobe(fields(object)?),
            _ => return Err(de::Error::unknown_variant(&kind, &["lambertian", "cosine_lobe"])),
        })
    }
}

/// The fields of a point light.
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct PointLightJson {
    /// Position.
    pub position: [f64; 3],
    /// Intensity.
    pub intensity: f64,
    /// Emission distribution; absent or `null`: isotropic.
    #[serde(default)]
    pub distribution: Option<DistributionJson>,
}

/// The fields of a segment light.
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct SegmentLightJson {
    /// One end.
    pub a: [f64; 3],
    /// The other end.
    pub b: [f64; 3],
    /// Intensity per unit length.
    pub intensity: f64,
    /// Emission distribution of every point; absent or `null`: isotropic.
    #[serde(default)]
    pub distribution: Option<DistributionJson>,
}

impl<'de> Deserialize<'de> for LightJson {
    fn deserialize<D: Deserializer<'de>>(d: D) -> Result<Self, D::Error> {
        let (shape, object) = tag_and_fields(d, "shape", Some("point"))?;
        Ok(match shape.as_str() {
            "point" => Self::Point(fields(object)?),
            "segment" => Self::Segment(fields(object)?),
            "disc" => Self::Disc(fields(object)?),
            "rectangle" => Self::Rectangle(fields(object)?),
            "sphere" => Self::Sphere(fields(object)?),
            _ => return Err(de::Error::unknown_variant(&shape, &["point", "segment", "disc", "rectangle", "sphere"])),
        })
    }
}

/// `light.distribution`, by `kind`.
#[derive(Debug)]
pub enum DistributionJson {
    /// `"isotropic"` or `"omni"`: the same in every direction.
    Isotropic,
    /// `"two_lobed"`: `c^p` about `axis`.
    TwoLobed(TwoLobedJson),
    /// `"spot"`: a cone with a smoothstep edge.
    Spot(SpotJson),
}

/// The fields of a `"two_lobed"` distribution.
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct TwoLobedJson {
    /// Axis.
    pub axis: [f64; 3],
    /// Power (an even integer, read as a number).
    pub power: f64,
}

/// The fields of a `"spot"` distribution.
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct SpotJson {
    /// Axis.
    pub axis: [f64; 3],
    /// Cosine of the fully lit half angle.
    pub cos_inner: f64,
    /// Cosine of the dark half angle.
    pub cos_outer: f64,
}

/// `phase`, by `kind`.
#[derive(Debug)]
pub enum PhaseJson {
    /// `"isotropic"`: `1/4π`.
    Isotropic,
    /// `"rayleigh"`.
    Rayleigh,
    /// `"henyey_greenstein"` with `g`.
    HenyeyGreenstein(AsymmetryJson),
    /// `"schlick"` with `k`.
    Schlick(SchlickJson),
    /// `"cornette_shanks"` with `g`.
    CornetteShanks(AsymmetryJson),
    /// `"two_lobe_henyey_greenstein"`: `w·HG(g1) + (1−w)·HG(g2)`.
    TwoLobeHenyeyGreenstein(TwoLobeJson),
}

/// A kind without fields of its own.
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
struct NoFields {}

/// The field of a one-parameter phase function.
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct AsymmetryJson {
    /// Asymmetry.
    pub g: f64,
}

/// The field of Schlick's phase function.
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct SchlickJson {
    /// Asymmetry.
    pub k: f64,
}

/// The fields of the two-lobed Henyey–Greenstein phase function.
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct TwoLobeJson {
    /// First lobe's asymmetry.
    pub g1: f64,
    /// Second lobe's asymmetry.
    pub g2: f64,
    /// First lobe's weight.
    pub w: f64,
}

/// Separates the path inside a kind's fields from the message in errors raised by [`fields`],
/// so that [`parse_value`] names the whole path (serde's own internally tagged enums buffer the
/// object and lose the path inside it).
const INNER_PATH: char = '\u{1f}';

/// An object with a `tag` (`"kind"`, `"shape"`): its value (`default` where absent, if any)
/// and the object without it.
fn tag_and_fields<'de, D: Deserializer<'de>>(d: D, tag: &'static str, default: Option<&str>) -> Result<(String, Value), D::Error> {
    let mut object = serde_json::Map::deserialize(d)?;
    match (object.remove(tag), default) {
        (Some(Value::String(value)), _) => Ok((value, Value::Object(object))),
        (Some(_), _) => Err(de::Error::custom(format_args!("{INNER_PATH}{tag}{INNER_PATH}expected a string"))),
        (None, Some(value)) => Ok((value.to_string(), Value::Object(object))),
        (None, None) => Err(de::Error::missing_field(tag)),
    }
}

/// An object with a `"kind"`: the kind and the object without it.
fn kind_and_fields<'de, D: Deserializer<'de>>(d: D) -> Result<(String, Value), D::Error> {
    tag_and_fields(d, "kind", None)
}

/// A kind's fields, with the path of an error inside them kept.
fn fields<T: de::DeserializeOwned, E: de::Error>(object: Value) -> Result<T, E> {
    serde_path_to_error::deserialize(object).map_err(|e| {
        let (path, message) = (e.path().to_string(), e.inner().to_string());
        // an error of a kind nested in these fields (a light's distribution) carries its own
        match message.split(INNER_PATH).collect::<Vec<_>>()[..] {
            [_, inner, message] => E::custom(format_args!("{INNER_PATH}{path}.{inner}{INNER_PATH}{message}")),
            _ => E::custom(format_args!("{INNER_PATH}{path}{INNER_PATH}{message}")),
        }
    })
}

impl<'de> Deserialize<'de> for DistributionJson {
    fn deserialize<D: Deserializer<'de>>(d: D) -> Result<Self, D::Error> {
        let (kind, object) = kind_and_fields(d)?;
        Ok(match kind.as_str() {
            "isotropic" | "omni" => fields::<NoFields, _>(object).map(|_| Self::Isotropic)?,
            "two_lobed" => Self::TwoLobed(fields(object)?),
            "spot" => Self::Spot(fields(object)?),
            _ => return Err(de::Error::unknown_variant(&kind, &["isotropic", "omni", "two_lobed", "spot"])),
        })
    }
}

impl<'de> Deserialize<'de> for PhaseJson {
    fn deserialize<D: Deserializer<'de>>(d: D) -> Result<Self, D::Error> {
        let (kind, object) = kind_and_fields(d)?;
        Ok(match kind.as_str() {
            "isotropic" => fields::<NoFields, _>(object).map(|_| Self::Isotropic)?,
            "rayleigh" => fields::<NoFields, _>(object).map(|_| Self::Rayleigh)?,
            "henyey_greenstein" => Self::HenyeyGreenstein(fields(object)?),
            "schlick" => Self::Schlick(fields(object)?),
            "cornette_shanks" => Self::CornetteShanks(fields(object)?),
            "two_lobe_henyey_greenstein" => Self::TwoLobeHenyeyGreenstein(fields(object)?),
            _ => {
                const KINDS: &[&str] = &["isotropic", "rayleigh", "henyey_greenstein", "schlick", "cornette_shanks", "two_lobe_henyey_greenstein"];
                return Err(de::Error::unknown_variant(&kind, KINDS));
            }
        })
    }
}

/// `x` in precision `T`, or an error naming `field` when it overflows.
fn number<T: Real>(field: &str, x: f64) -> Result<T, FieldError> {
    let y = T::lit(x);
    if x.is_finite() && !y.is_finite() {
        let name = if T::epsilon() > T::lit(1e-10) { "f32" } else { "f64" };
        return Err(FieldError { field: field.into(), message: format!("{x:e} is beyond the range of {name}") });
    }
    Ok(y)
}

fn vec3<T: Real>(field: &str, a: [f64; 3]) -> Result<T::Vec3, FieldError> {
    let mut out = [T::zero(); 3];
    for (o, x) in out.iter_mut().zip(a) {
        *o = number(field, x)?;
    }
    Ok(T::vec3_from_array(out))
}

/// A record's scene in precision `T`, validated: a point light's (the kernel's flat record, as
/// the GPU takes it) or a segment light's.
#[derive(Clone, Debug)]
pub enum AnyRecord<T: Real> {
    /// A point light.
    Point(SceneRecord<T>),
    /// A segment light.
    Segment(SegmentScene<T, AnyDistribution<T>, AnyPhase<T>>),
    /// A surface point lit by a point light's air-light.
    Surface(SurfaceScene<T, AnyDistribution<T>, AnyPhase<T>>),
    /// An area light (disc, rectangle).
    Area(AreaScene<T, AnyPhase<T>>),
}

impl<T: Real> AnyRecord<T> {
    /// The point light's record; a segment light is an error naming `light.shape`.
    pub fn into_point(self) -> Result<SceneRecord<T>, FieldError> {
        match self {
            AnyRecord::Point(r) => Ok(r),
            AnyRecord::Segment(_) => Err(FieldError { field: "light.shape".into(), message: "a segment light, where a point light's record is needed".into() }),
            AnyRecord::Surface(_) => Err(FieldError { field: "surface".into(), message: "a surface record, where a ray's is needed".into() }),
            AnyRecord::Area(_) => Err(FieldError { field: "light.shape".into(), message: "an area light, where a point light's record is needed".into() }),
        }
    }
}

fn distribution<T: Real>(json: &Option<DistributionJson>) -> Result<AnyDistribution<T>, FieldError> {
    Ok(match json {
        None | Some(DistributionJson::Isotropic) => AnyDistribution::Omni,
        Some(DistributionJson::TwoLobed(TwoLobedJson { axis, power: p })) => {
            let p = *p;
            if !(p >= 0.0 && p.fract() == 0.0 && p <= 1024.0 && (p as u32) % 2 == 0) {
                return Err(FieldError { field: "light.distribution.power".into(), message: "must be an even non-negative integer".into() });
            }
            AnyDistribution::TwoLobed(TwoLobed { axis: vec3::<T>("light.distribution.axis", *axis)?, power: p as u32 })
        }
        Some(DistributionJson::Spot(SpotJson { axis, cos_inner, cos_outer })) => AnyDistribution::SpotCone(SpotCone {
            axis: vec3::<T>("light.distribution.axis", *axis)?,
            cos_inner: number("light.distribution.cos_inner", *cos_inner)?,
            cos_outer: number("light.distribution.cos_outer", *cos_outer)?,
        }),
    })
}

/// An area light's scene.
fn area<T: Real>(ray: Ray<T>, emitter: Emitter<T>, radiance: f64, emission: &Option<EmissionJson>, medium: Medium<T>, phase: AnyPhase<T>) -> Result<AnyRecord<T>, FieldError> {
    let emission = match emission {
        None | Some(EmissionJson::Lambertian) => Emission::Lambertian,
        // a whole number, else the kernel's error; out of range the saturating cast gives 0 or
        // u32::MAX, which `Emission::validate` (in `AreaScene::new`) rejects with the same error
        Some(EmissionJson::CosineLobe(CosineLobeJson { power: p })) => {
            if p.fract() != 0.0 {
                return Err(field_error(airlight::InputError::new("light.emission.power", airlight::ErrorKind::LobePower)));
            }
            Emission::CosineLobe { power: *p as u32 }
        }
    };
    let light = AreaLight { emitter, radiance: number("light.radiance", radiance)?, emission };
    Ok(AnyRecord::Area(AreaScene::new(ray, light, medium, phase).map_err(field_error)?))
}

/// A point light's fields.
fn point_light<T: Real>(l: &PointLightJson) -> Result<PointLight<T, AnyDistribution<T>>, FieldError> {
    Ok(PointLight { position: vec3::<T>("light.position", l.position)?, intensity: number("light.intensity", l.intensity)?, distribution: distribution(&l.distribution)? })
}

/// The kernel's error as a [`FieldError`].
fn field_error(e: airlight::InputError) -> FieldError {
    FieldError { field: e.field.to_string(), message: e.to_string()[e.field.len() + 2..].to_string() }
}

impl SceneJson {
    /// The record's scene in precision `T`, validated as the kernel's constructors do.
    pub fn to_any<T: Real>(&self) -> Result<AnyRecord<T>, FieldError> {
        let ray = match (&self.ray, &self.surface) {
            (Some(RayJson { origin, dir, t_min, t_max }), None) => {
                Ray { origin: vec3::<T>("ray.origin", *origin)?, dir: vec3::<T>("ray.dir", *dir)?, t_min: number("ray.t_min", *t_min)?, t_max: number("ray.t_max", *t_max)? }
            }
            (None, Some(surface)) => return self.to_surface(surface),
            (Some(_), Some(_)) => return Err(FieldError { field: "surface".into(), message: "a record has a ray or a surface, not both".into() }),
            (None, None) => return Err(FieldError { field: "ray".into(), message: "missing field `ray` (or `surface`)".into() }),
        };
        let (medium, phase) = self.medium_and_phase()?;
        match &self.light {
            LightJson::Point(l) => {
                let light = point_light(l)?;
                airlight::scene::validate(&ray, &light, &medium, &phase).map_err(field_error)?;
                Ok(AnyRecord::Point(SceneRecord { ray, light, medium, phase }))
            }
            LightJson::Segment(l) => {
                let light = SegmentLight { a: vec3::<T>("light.a", l.a)?, b: vec3::<T>("light.b", l.b)?, intensity: number("light.intensity", l.intensity)?, distribution: distribution(&l.distribution)? };
                Ok(AnyRecord::Segment(SegmentScene::new(ray, light, medium, phase).map_err(field_error)?))
            }
            LightJson::Disc(l) => {
                let emitter = Emitter::Disc { center: vec3::<T>("light.center", l.center)?, normal: vec3::<T>("light.normal", l.normal)?, radius: number("light.radius", l.radius)? };
                area(ray, emitter, l.radiance, &l.emission, medium, phase)
            }
            LightJson::Rectangle(l) => {
                let emitter = Emitter::Rectangle { corner: vec3::<T>("light.corner", l.corner)?, edge_u: vec3::<T>("light.edge_u", l.edge_u)?, edge_v: vec3::<T>("light.edge_v", l.edge_v)? };
                area(ray, emitter, l.radiance, &l.emission, medium, phase)
            }
            LightJson::Sphere(l) => {
                let emitter = Emitter::Sphere { center: vec3::<T>("light.center", l.center)?, radius: number("light.radius", l.radius)? };
                area(ray, emitter, l.radiance, &l.emission, medium, phase)
            }
        }
    }

    /// A surface record's scene.
    fn to_surface<T: Real>(&self, surface: &SurfaceJson) -> Result<AnyRecord<T>, FieldError> {
        let (medium, phase) = self.medium_and_phase()?;
        let light = match &self.light {
            LightJson::Point(l) => point_light(l)?,
            _ => return Err(FieldError { field: "light.shape".into(), message: "a surface record takes a point light".into() }),
        };
        let brdf = match &surface.brdf {
            BrdfJson::Lambert(LambertJson { albedo }) => Brdf::Lambert { albedo: number("surface.brdf.albedo", *albedo)? },
            BrdfJson::Phong(PhongJson { k_s, exponent, view }) => {
                Brdf::Phong { k_s: number("surface.brdf.k_s", *k_s)?, exponent: number("surface.brdf.exponent", *exponent)?, view: vec3::<T>("surface.brdf.view", *view)? }
            }
        };
        let point = Surface { position: vec3::<T>("surface.position", surface.position)?, normal: vec3::<T>("surface.normal", surface.normal)? };
        // the kernel names the BRDF's fields `brdf.…`; here they sit under `surface`
        let scene = SurfaceScene::new(point, brdf, light, medium, phase).map_err(|e| {
            let e = field_error(e);
            if e.field.starts_with("brdf.") {
                FieldError { field: format!("surface.{}", e.field), ..e }
            } else {
                e
            }
        })?;
        Ok(AnyRecord::Surface(scene))
    }

    /// The medium and the phase function.
    fn medium_and_phase<T: Real>(&self) -> Result<(Medium<T>, AnyPhase<T>), FieldError> {
        let medium = Medium { sigma_s: number("medium.sigma_s", self.medium.sigma_s)?, sigma_t: number("medium.sigma_t", self.medium.sigma_t)? };
        let phase = match self.phase {
            None | Some(PhaseJson::Isotropic) => AnyPhase::Isotropic,
            Some(PhaseJson::Rayleigh) => AnyPhase::Rayleigh,
            Some(PhaseJson::HenyeyGreenstein(AsymmetryJson { g })) => AnyPhase::HenyeyGreenstein(HenyeyGreenstein { g: number("phase.g", g)? }),
            Some(PhaseJson::Schlick(SchlickJson { k })) => AnyPhase::Schlick(Schlick { k: number("phase.k", k)? }),
            Some(PhaseJson::CornetteShanks(AsymmetryJson { g })) => AnyPhase::CornetteShanks(CornetteShanks { g: number("phase.g", g)? }),
            Some(PhaseJson::TwoLobeHenyeyGreenstein(TwoLobeJson { g1, g2, w })) => AnyPhase::TwoLobeHenyeyGreenstein(TwoLobeHenyeyGreenstein {
                g1: number("phase.g1", g1)?,
                g2: number("phase.g2", g2)?,
                w: number("phase.w", w)?,
            }),
        };
        Ok((medium, phase))
    }

    /// The kernel's point-light record in precision `T`, validated as [`airlight::Scene::new`]
    /// does; a segment light is an error (see [`SceneJson::to_any`]).
    pub fn to_record<T: Real>(&self) -> Result<SceneRecord<T>, FieldError> {
        self.to_any()?.into_point()
    }
}

/// serde's message for an unknown key or kind, with the closest expected name (by the
/// Jaro–Winkler similarity clap uses for its suggestions) when one is close.
fn with_suggestion(message: String) -> String {
    // serde writes "unknown field `x`, expected one of `a`, `b`" (likewise "unknown variant",
    // "expected `a`", "expected `a` or `b`")
    let Some(rest) = message.strip_prefix("unknown field `").or_else(|| message.strip_prefix("unknown variant `")) else {
        return message;
    };
    if let Some(name) = rest.strip_suffix("`, there are no fields") {
        return format!("unknown field `{name}` (this kind has no fields)");
    }
    let Some((name, expected)) = rest.split_once("`, expected ") else { return message };
    let closest = expected
        .split('`')
        .skip(1)
        .step_by(2)
        .map(|k| (strsim::jaro_winkler(name, k), k))
        .filter(|(score, _)| *score > 0.7)
        .max_by(|a, b| a.0.total_cmp(&b.0));
    let what = if message.starts_with("unknown field") { "unknown field" } else { "unknown kind" };
    match closest {
        Some((_, k)) => format!("{what} `{name}` (did you mean `{k}`?)"),
        None => format!("{what} `{name}` (expected {expected})"),
    }
}

/// Decodes one record (already parsed as JSON) into its serde form.
fn decode(root: &Value) -> Result<SceneJson, FieldError> {
    serde_path_to_error::deserialize(root).map_err(|e| {
        let path = e.path().to_string();
        let message = e.into_inner().to_string();
        // an error inside a kind's fields carries its inner path (see `fields`)
        let (field, message) = match message.split(INNER_PATH).collect::<Vec<_>>()[..] {
            [_, inner, message] => (format!("{path}.{inner}"), message.to_string()),
            _ if message.starts_with("unknown variant") && path == "light" => (format!("{path}.shape"), message),
            _ if message.starts_with("unknown variant") => (format!("{path}.kind"), message),
            _ if path == "." => ("(record)".to_string(), message),
            _ => (path, message),
        };
        let message = with_suggestion(message);
        let message = if field.ends_with(".shape") { message.replacen("unknown kind", "unknown shape", 1) } else { message };
        FieldError { field, message }
    })
}

/// Parses one point-light record (already decoded as JSON).
pub fn parse_value<T: Real>(root: &Value) -> Result<SceneRecord<T>, FieldError> {
    decode(root)?.to_record()
}

/// Parses one record of any light shape (already decoded as JSON).
pub fn parse_any_value<T: Real>(root: &Value) -> Result<AnyRecord<T>, FieldError> {
    decode(root)?.to_any()
}

/// Parses one JSON line (a point light's record).
pub fn parse_line<T: Real>(line: &str) -> Result<SceneRecord<T>, FieldError> {
    parse_line_with_id::<T>(line).1?.into_point()
}

/// Parses one JSON line of any light shape, and returns with it the record's `"id"` annotation
/// (any JSON value) when the line is a JSON object that has one, valid record or not.
pub fn parse_line_with_id<T: Real>(line: &str) -> (Option<Value>, Result<AnyRecord<T>, FieldError>) {
    let v: Value = match serde_json::from_str(line) {
        Ok(v) => v,
        Err(e) => return (None, Err(FieldError { field: "(record)".into(), message: format!("invalid JSON: {e}") })),
    };
    if !v.is_object() {
        return (None, Err(FieldError { field: "(record)".into(), message: "expected a JSON object".into() }));
    }
    (v.get("id").cloned(), parse_any_value(&v))
}
