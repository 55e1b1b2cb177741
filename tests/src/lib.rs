//! Shared helpers of the integration tests: reference files, error measures, a deterministic
//! random source and scene generators.

use std::path::PathBuf;

/// The repository root.
pub fn repo_root() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR")).parent().unwrap().to_path_buf()
}

/// The surface point of Hong 2006's `J(T, θ_s)` (thesis eq. 4.13): at the origin, normal `+z`,
/// an omni light of intensity 1 at distance 1 and angle `θ_s` from the normal, `σt = T`,
/// `σs = 1`, a Lambertian BRDF of albedo 1, isotropic scattering — its air-light is `J` itself.
pub fn canonical_surface<T: airlight::Real>(t: T, theta: T) -> airlight::SurfaceScene<T, airlight::light::Omni, airlight::phase::Isotropic> {
    use airlight::{Brdf, Medium, PointLight, Surface, SurfaceScene};
    let (s, c) = theta.sin_cos();
    let (zero, one) = (T::zero(), T::one());
    let surface = Surface { position: T::vec3_from_array([zero; 3]), normal: T::vec3_from_array([zero, zero, one]) };
    let light = PointLight { position: T::vec3_from_array([s, zero, c]), intensity: one, distribution: airlight::light::Omni };
    SurfaceScene::new(surface, Brdf::Lambert { albedo: one }, light, Medium { sigma_s: one, sigma_t: t }, airlight::phase::Isotropic).expect("a valid canonical surface")
}

/// Lines of a reference file under `tests/reference/`, parsed as JSON.
pub fn reference_lines(name: &str) -> Vec<serde_json::Value> {
    let path = repo_root().join("tests/reference").join(name);
    let text = std::fs::read_to_string(&path).unwrap_or_else(|e| panic!("cannot read {}: {e}", path.display()));
    text.lines().filter(|l| !l.trim().is_empty()).map(|l| serde_json::from_str(l).unwrap()).collect()
}

/// One scene of the hard classes (`tests/reference/classes.jsonl`, made by
/// `tests/reference/gen_classes.py`), with its mpmath value and the integrand's scale.
pub struct ClassCase {
    /// The scene class (`hg_0.99`, `near_light`, …).
    pub category: String,
    /// The scene; its inputs are exact in binary32.
    pub rec: airlight::record::SceneRecord<f64>,
    /// The integral by mpmath quadrature.
    pub exact: f64,
    /// The integral with `F = D·P` replaced by its maximum on the segment.
    pub scale: f64,
    /// Judged in f32: the value is at least 1e-30, far inside f32's normal range.
    pub f32_ok: bool,
}

impl ClassCase {
    /// `|x − exact| / max(|exact|, τ·scale)`, the accuracy measure of docs/DESIGN.md §8.
    pub fn err(&self, x: f64, tau: f64) -> f64 {
        (x - self.exact).abs() / self.exact.abs().max(tau * self.scale)
    }

    /// Whether the scene is judged at `tau` (1e-4: f32, where its value must be at least
    /// 1e-30; 1e-10: f64, where it must be a normal number).
    pub fn judged(&self, tau: f64) -> bool {
        if tau > 1e-6 {
            self.f32_ok
        } else {
            self.exact >= f64::MIN_POSITIVE
        }
    }
}

/// Every scene of `tests/reference/classes.jsonl`.
pub fn class_cases() -> Vec<ClassCase> {
    let lines = reference_lines("classes.jsonl");
    assert!(lines.len() >= 300, "classes.jsonl too small: {}", lines.len());
    lines
        .iter()
        .map(|v| {
            let rec = airlight_codegen::scene_json::parse_value::<f64>(v).unwrap_or_else(|e| panic!("record invalid: {e}: {v}"));
            let exact = v["in_scatter"].as_f64().unwrap();
            ClassCase { category: v["category"].as_str().unwrap().to_string(), rec, exact, scale: v["scale"].as_f64().unwrap(), f32_ok: exact >= 1e-30 }
        })
        .collect()
}

/// A record of `tests/reference/surface.jsonl` as the surface point it describes, in `T`
/// (panics on anything else: every line of that file is a valid surface point).
pub fn surface_record<T: airlight::Real>(v: &serde_json::Value) -> airlight::SurfaceScene<T, airlight::light::AnyDistribution<T>, airlight::phase::AnyPhase<T>> {
    use airlight_codegen::scene_json::{parse_any_value, AnyRecord};
    match parse_any_value::<T>(v).unwrap_or_else(|e| panic!("reference record invalid: {e}: {v}")) {
        AnyRecord::Surface(s) => s,
        _ => panic!("not a surface record in surface.jsonl: {v}"),
    }
}

/// `|a − b| / |b|` (0 when both are 0; ∞ when only `b` is 0).
pub fn rel_err(a: f64, b: f64) -> f64 {
    if a == b {
        0.0
    } else {
        (a - b).abs() / b.abs()
    }
}

/// SplitMix64: a small, deterministic, well-mixed generator (Steele, Lea & Flood 2014).
pub struct Rng(pub u64);

impl Rng {
    /// Next 64 random bits.
    pub fn next_u64(&mut self) -> u64 {
        self.0 = self.0.wrapping_add(0x9E37_79B9_7F4A_7C15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
        z ^ (z >> 31)
    }
    /// Uniform in `[0, 1)`.
    pub fn unit(&mut self) -> f64 {
        (self.next_u64() >> 11) as f64 / (1u64 << 53) as f64
    }
    /// Uniform in `[a, b)`.
    pub fn range(&mut self, a: f64, b: f64) -> f64 {
        a + (b - a) * self.unit()
    }
    /// Log-uniform in `[a, b)`, `0 < a < b`.
    pub fn log_range(&mut self, a: f64, b: f64) -> f64 {
        (a.ln() + (b.ln() - a.ln()) * self.unit()).exp()
    }
    /// A uniformly random unit vector.
    pub fn unit_vector(&mut self) -> [f64; 3] {
        loop {
            let v = [self.range(-1.0, 1.0), self.range(-1.0, 1.0), self.range(-1.0, 1.0)];
            let n = (v[0] * v[0] + v[1] * v[1] + v[2] * v[2]).sqrt();
            if n > 0.1 && n <= 1.0 {
                return [v[0] / n, v[1] / n, v[2] / n];
            }
        }
    }
    /// One of `items`.
    pub fn pick<'a, X>(&mut self, items: &'a [X]) -> &'a X {
        &items[(self.next_u64() % items.len() as u64) as usize]
    }
}

pub mod scenes;
