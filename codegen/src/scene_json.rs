//! Scene records as JSON lines (docs/DESIGN.md §6) → kernel types, with errors that name the field.
//!
//! ```json
//! {"ray": {"origin": [0,0,0], "dir": [1,0,0], "t_min": 0.0, "t_max": 25.0},
//!  "medium": {"sigma_s": 0.08, "sigma_t": 0.1},
//!  "light": {"position": [5,1,0], "intensity": 100.0,
//!            "distribution": {"kind": "two_lobed", "axis": [0,-1,0], "power": 4}},
//!  "phase": {"kind": "henyey_greenstein", "g": 0.5}}
//! ```
//! `t_max: null` (or absent) means `+∞`, an absent `t_min` 0, an absent `distribution` or
//! `phase` isotropic. Any other key is an error naming it (with the closest known key when one
//! is close), except the annotations [`ANNOTATIONS`], which never change the evaluation.
//! Numbers are read as f64 and rounded to the evaluation precision; one that overflows it is
//! an error.

use airlight::light::{AnyDistribution, SpotCone, TwoLobed};
use airlight::phase::{AnyPhase, CornetteShanks, HenyeyGreenstein, Schlick, TwoLobeHenyeyGreenstein};
use airlight::record::SceneRecord;
use airlight::{Medium, PointLight, Ray, Real};
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

fn err<X>(field: &str, message: &str) -> Result<X, FieldError> {
    Err(FieldError { field: field.to_string(), message: message.to_string() })
}

fn object<'a>(v: &'a Value, field: &str) -> Result<&'a serde_json::Map<String, Value>, FieldError> {
    match v.get_path(field) {
        Some(Value::Object(m)) => Ok(m),
        Some(_) => err(field, "expected an object"),
        None => err(field, "missing"),
    }
}

trait GetPath {
    fn get_path(&self, path: &str) -> Option<&Value>;
}

impl GetPath for Value {
    fn get_path(&self, path: &str) -> Option<&Value> {
        let mut cur = self;
        for key in path.split('.') {
            cur = cur.get(key)?;
        }
        Some(cur)
    }
}

/// Top-level keys a record may carry besides `ray`, `medium`, `light` and `phase`, ignored by
/// the evaluation: `id`, `comment` and `category` (free text), `in_scatter` and `scale` (a
/// reference value and its scale, as the committed references carry them).
pub const ANNOTATIONS: [&str; 5] = ["id", "comment", "category", "in_scatter", "scale"];

/// Every key of the object at `path` (`""`: the record) is one of `known`.
fn known_keys(root: &Value, path: &str, known: &[&str]) -> Result<(), FieldError> {
    let object = if path.is_empty() { root.as_object() } else { root.get_path(path).and_then(Value::as_object) };
    let Some(object) = object else { return Ok(()) };
    for key in object.keys() {
        if !known.contains(&key.as_str()) {
            let field = if path.is_empty() { key.clone() } else { format!("{path}.{key}") };
            // the closest known key, by the Jaro–Winkler similarity clap uses for suggestions
            let closest = known.iter().map(|k| (strsim::jaro_winkler(key, k), *k)).filter(|(score, _)| *score > 0.7).max_by(|a, b| a.0.total_cmp(&b.0));
            let message = match closest {
                Some((_, k)) => format!("unknown field (did you mean `{k}`?)"),
                None => format!("unknown field (expected one of {})", known.join(", ")),
            };
            return Err(FieldError { field, message });
        }
    }
    Ok(())
}

/// The keys of a light distribution, per kind.
const DISTRIBUTION_FIELDS: [(&str, &[&str]); 4] = [
    ("isotropic", &["kind"]),
    ("omni", &["kind"]),
    ("two_lobed", &["kind", "axis", "power"]),
    ("spot", &["kind", "axis", "cos_inner", "cos_outer"]),
];

/// The keys of a phase function, per kind.
const PHASE_FIELDS: [(&str, &[&str]); 6] = [
    ("isotropic", &["kind"]),
    ("rayleigh", &["kind"]),
    ("henyey_greenstein", &["kind", "g"]),
    ("schlick", &["kind", "k"]),
    ("cornette_shanks", &["kind", "g"]),
    ("two_lobe_henyey_greenstein", &["kind", "g1", "g2", "w"]),
];

/// The `kind` of the object at `path`, after checking that its other keys are that kind's
/// ([`known_keys`]); an unknown kind is returned as it is, for the caller to report.
fn fields_known<'a>(root: &'a Value, path: &str, kinds: &[(&str, &[&str])]) -> Result<&'a str, FieldError> {
    let k = kind(root, &format!("{path}.kind"))?;
    if let Some((_, fields)) = kinds.iter().find(|(name, _)| *name == k) {
        known_keys(root, path, fields)?;
    }
    Ok(k)
}

fn number<T: Real>(root: &Value, field: &str) -> Result<T, FieldError> {
    match root.get_path(field) {
        Some(Value::Number(n)) => match n.as_f64() {
            Some(x) if x.is_finite() && !T::lit(x).is_finite() => {
                err(field, &format!("{x:e} is beyond the range of {}", if T::epsilon() > T::lit(1e-10) { "f32" } else { "f64" }))
            }
            Some(x) => Ok(T::lit(x)),
            None => err(field, "expected a number"),
        },
        Some(_) => err(field, "expected a number"),
        None => err(field, "missing"),
    }
}

fn vec3<T: Real>(root: &Value, field: &str) -> Result<T::Vec3, FieldError> {
    match root.get_path(field) {
        Some(Value::Array(a)) if a.len() == 3 => {
            let mut out = [T::zero(); 3];
            for (o, x) in out.iter_mut().zip(a) {
                match x.as_f64() {
                    Some(x) => *o = T::lit(x),
                    None => return err(field, "expected an array of 3 numbers"),
                }
            }
            Ok(T::vec3_from_array(out))
        }
        Some(_) => err(field, "expected an array of 3 numbers"),
        None => err(field, "missing"),
    }
}

fn kind<'a>(root: &'a Value, field: &str) -> Result<&'a str, FieldError> {
    match root.get_path(field) {
        Some(Value::String(s)) => Ok(s.as_str()),
        Some(_) => err(field, "expected a string"),
        None => err(field, "missing"),
    }
}

/// Parses one record (already decoded as JSON).
pub fn parse_value<T: Real>(root: &Value) -> Result<SceneRecord<T>, FieldError> {
    let mut top = vec!["ray", "medium", "light", "phase"];
    top.extend(ANNOTATIONS);
    known_keys(root, "", &top)?;
    object(root, "ray")?;
    known_keys(root, "ray", &["origin", "dir", "t_min", "t_max"])?;
    let t_max = match root.get_path("ray.t_max") {
        None | Some(Value::Null) => T::infinity(),
        Some(Value::String(s)) if s == "inf" => T::infinity(),
        Some(_) => number(root, "ray.t_max")?,
    };
    let ray = Ray {
        origin: vec3::<T>(root, "ray.origin")?,
        dir: vec3::<T>(root, "ray.dir")?,
        t_min: match root.get_path("ray.t_min") {
            None => T::zero(),
            Some(_) => number(root, "ray.t_min")?,
        },
        t_max,
    };
    object(root, "medium")?;
    known_keys(root, "medium", &["sigma_s", "sigma_t"])?;
    let medium = Medium { sigma_s: number(root, "medium.sigma_s")?, sigma_t: number(root, "medium.sigma_t")? };
    object(root, "light")?;
    known_keys(root, "light", &["position", "intensity", "distribution"])?;
    let distribution = match root.get_path("light.distribution") {
        None | Some(Value::Null) => AnyDistribution::Omni,
        Some(_) => match fields_known(root, "light.distribution", &DISTRIBUTION_FIELDS)? {
            "isotropic" | "omni" => AnyDistribution::Omni,
            "two_lobed" => {
                let p: f64 = number(root, "light.distribution.power")?;
                if !(p >= 0.0 && p.fract() == 0.0 && p <= 1024.0 && (p as u32) % 2 == 0) {
                    return err("light.distribution.power", "must be an even non-negative integer");
                }
                AnyDistribution::TwoLobed(TwoLobed { axis: vec3::<T>(root, "light.distribution.axis")?, power: p as u32 })
            }
            "spot" => AnyDistribution::SpotCone(SpotCone {
                axis: vec3::<T>(root, "light.distribution.axis")?,
                cos_inner: number(root, "light.distribution.cos_inner")?,
                cos_outer: number(root, "light.distribution.cos_outer")?,
            }),
            _ => return err("light.distribution.kind", "unknown kind (isotropic, two_lobed, spot)"),
        },
    };
    let light = PointLight {
        position: vec3::<T>(root, "light.position")?,
        intensity: number(root, "light.intensity")?,
        distribution,
    };
    let phase = match root.get_path("phase") {
        None | Some(Value::Null) => AnyPhase::Isotropic,
        Some(_) => match fields_known(root, "phase", &PHASE_FIELDS)? {
            "isotropic" => AnyPhase::Isotropic,
            "rayleigh" => AnyPhase::Rayleigh,
            "henyey_greenstein" => AnyPhase::HenyeyGreenstein(HenyeyGreenstein { g: number(root, "phase.g")? }),
            "schlick" => AnyPhase::Schlick(Schlick { k: number(root, "phase.k")? }),
            "cornette_shanks" => AnyPhase::CornetteShanks(CornetteShanks { g: number(root, "phase.g")? }),
            "two_lobe_henyey_greenstein" => AnyPhase::TwoLobeHenyeyGreenstein(TwoLobeHenyeyGreenstein {
                g1: number(root, "phase.g1")?,
                g2: number(root, "phase.g2")?,
                w: number(root, "phase.w")?,
            }),
            _ => {
                return err(
                    "phase.kind",
                    "unknown kind (isotropic, rayleigh, henyey_greenstein, schlick, cornette_shanks, two_lobe_henyey_greenstein)",
                )
            }
        },
    };
    airlight::scene::validate(&ray, &light, &medium, &phase)
        .map_err(|e| FieldError { field: e.field.to_string(), message: e.to_string()[e.field.len() + 2..].to_string() })?;
    Ok(SceneRecord { ray, light, medium, phase })
}

/// Parses one JSON line.
pub fn parse_line<T: Real>(line: &str) -> Result<SceneRecord<T>, FieldError> {
    parse_line_with_id(line).1
}

/// Parses one JSON line, and returns with it the record's `"id"` annotation (any JSON value)
/// when the line is a JSON object that has one, valid record or not.
pub fn parse_line_with_id<T: Real>(line: &str) -> (Option<Value>, Result<SceneRecord<T>, FieldError>) {
    let v: Value = match serde_json::from_str(line) {
        Ok(v) => v,
        Err(e) => return (None, Err(FieldError { field: "(record)".into(), message: format!("invalid JSON: {e}") })),
    };
    if !v.is_object() {
        return (None, err("(record)", "expected a JSON object"));
    }
    (v.get("id").cloned(), parse_value(&v))
}
