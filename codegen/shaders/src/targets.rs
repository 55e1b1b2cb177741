//! Shader emission: the WGSL source of truth (`codegen/shaders/shader/*.wgsl`) → naga front end →
//! validator → naga back ends, in the two shapes engines use (docs/DESIGN.md §5):
//!
//! * the **compute entry point** `airlight_main` over a storage buffer of records
//!   ([`crate::layout`]): WGSL, GLSL 450, SPIR-V 1.0 (Vulkan 1.0), HLSL (SM 5.1), MSL;
//! * the **include library**: the functions alone, every public name prefixed `airlight_`:
//!   WGSL, GLSL 450, GLSL ES 3.00 (WebGL2), HLSL, MSL. Back ends other than WGSL need an
//!   entry point to write anything, so the library module gets a dummy one
//!   (`airlight_library_entry`), written with `INCLUDE_UNUSED_ITEMS`, and cut away again at
//!   its signature.
//!
//! Every artifact comes from a module naga has validated; output is deterministic, so
//! `check` can compare the committed `shaders-out/` byte for byte.

use crate::unrolled;
use airlight::Real;
use naga::back::{glsl, hlsl, msl, spv, wgsl};
use naga::proc::{BoundsCheckPolicies, BoundsCheckPolicy};
use naga::valid::{Capabilities, ModuleInfo, ValidationFlags, Validator};
use std::collections::BTreeMap;
use std::fmt;
use std::path::{Path, PathBuf};

const LIBRARY: &str = include_str!("../shader/airlight.wgsl");
const COMPUTE: &str = include_str!("../shader/compute.wgsl");
const LIBRARY_ENTRY: &str = "airlight_library_entry";
const COMPUTE_ENTRY: &str = "airlight_main";

/// A dummy entry point that keeps every library function reachable for the back ends (the four
/// public entries: `airlight_in_scatter`, the point light's `airlight_in_scatter_point`, the
/// first pass's `airlight_in_scatter_route` and the area light's `airlight_in_scatter_area`).
const LIBRARY_STUB: &str = "
@compute @workgroup_size(1)
fn airlight_library_entry() {
    let s = AirlightScene(vec3<f32>(0.0), 0.0, vec3<f32>(1.0, 0.0, 0.0), 1.0,
        vec3<f32>(0.0, 1.0, 0.0), 1.0, vec3<f32>(0.0, 0.0, 1.0), 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0u, 0u, 0u, 0.0, 0u, 0.0, vec3<f32>(0.0, 1.0, 0.0), 0u, vec3<f32>(0.0));
    let r = airlight_in_scatter(s);
    let q = airlight_in_scatter_point(s);
    let p = airlight_in_scatter_route(s);
    let a = airlight_in_scatter_area(s);
}
";

/// A fragment stub for GLSL ES 3.00, which has no compute shaders.
const LIBRARY_STUB_ES: &str = "
@fragment
fn airlight_library_entry() -> @location(0) vec4<f32> {
    let s = AirlightScene(vec3<f32>(0.0), 0.0, vec3<f32>(1.0, 0.0, 0.0), 1.0,
        vec3<f32>(0.0, 1.0, 0.0), 1.0, vec3<f32>(0.0, 0.0, 1.0), 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0u, 0u, 0u, 0.0, 0u, 0.0, vec3<f32>(0.0, 1.0, 0.0), 0u, vec3<f32>(0.0));
    let r = airlight_in_scatter(s);
    let q = airlight_in_scatter_point(s);
    let p = airlight_in_scatter_route(s);
    let a = airlight_in_scatter_area(s);
    return vec4<f32>(r.in_scatter, q.in_scatter, p.in_scatter, a.in_scatter);
}
";

/// The emitted node counts per panel.
pub const NODE_COUNTS: [usize; 2] = [8, 12];

/// An output language.
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord, Hash)]
pub enum Target {
    /// WGSL (wgpu, Bevy, browsers).
    Wgsl,
    /// GLSL 450 (Vulkan/OpenGL, Godot) and GLSL ES 3.00 (WebGL2, library only).
    Glsl,
    /// SPIR-V 1.0 binary (Vulkan 1.0).
    Spirv,
    /// HLSL, shader model 5.1 (D3D, Unity, Unreal).
    Hlsl,
    /// Metal Shading Language.
    Msl,
}

impl Target {
    /// All targets.
    pub const ALL: [Target; 5] = [Target::Wgsl, Target::Glsl, Target::Spirv, Target::Hlsl, Target::Msl];

    /// Parses `wgsl`, `glsl`, `spirv` (or `spv`), `hlsl`, `msl` (or `metal`).
    pub fn parse(s: &str) -> Result<Target, EmitError> {
        match s.trim().to_ascii_lowercase().as_str() {
            "wgsl" => Ok(Target::Wgsl),
            "glsl" => Ok(Target::Glsl),
            "spirv" | "spv" => Ok(Target::Spirv),
            "hlsl" => Ok(Target::Hlsl),
            "msl" | "metal" => Ok(Target::Msl),
            other => Err(EmitError::Usage(format!("unknown target '{other}' (expected wgsl, glsl, spirv, hlsl, msl)"))),
        }
    }
}

/// What to emit.
#[derive(Clone, Debug, PartialEq)]
pub struct EmitOptions {
    /// Node counts per panel (each 8 or 12).
    pub terms: Vec<usize>,
    /// Output languages.
    pub targets: Vec<Target>,
    /// The panels' relative tolerance, in [`TOLERANCE_RANGE`] (default: the kernel's
    /// [`airlight::SHADER_CONTROL`], 1e-3, which shaders-out/ is emitted with). Looser trades
    /// accuracy for speed as `Scene::in_scatter_controlled` does on the CPU.
    pub tolerance: f32,
}

impl Default for EmitOptions {
    fn default() -> Self {
        EmitOptions { terms: NODE_COUNTS.to_vec(), targets: Target::ALL.to_vec(), tolerance: airlight::SHADER_CONTROL.tolerance }
    }
}

/// The panel tolerances a shader may be emitted with: from f32's own default
/// ([`airlight::Real::PANEL_TOLERANCE`], 1e-5; below it the estimate measures rounding, not the
/// rule) to 1e-1.
pub const TOLERANCE_RANGE: core::ops::RangeInclusive<f32> = 1e-5..=1e-1;

/// Why emission failed.
#[derive(Debug)]
pub enum EmitError {
    /// Bad options (unknown target, unsupported node count).
    Usage(String),
    /// The shader source did not parse or validate, or a back end failed.
    Shader(String),
    /// Writing the output failed.
    Io(PathBuf, std::io::Error),
}

impl fmt::Display for EmitError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            EmitError::Usage(m) => write!(f, "{m}"),
            EmitError::Shader(m) => write!(f, "shader: {m}"),
            EmitError::Io(p, e) => write!(f, "cannot write {}: {e}", p.display()),
        }
    }
}

impl std::error::Error for EmitError {}

/// The numbers the WGSL template (`codegen/shaders/shader/*.wgsl`) leaves open, each taken from the
/// kernel or the record layout at emission: placeholder → WGSL text. f32 values are written as
/// the shortest decimal that reads back to the same f32 (the kernel's `T::lit` rounding).
#[derive(Clone, Debug, PartialEq)]
pub struct Constants {
    /// `("@NAME@", text)` pairs, every placeholder of the template once.
    pub fills: Vec<(&'static str, String)>,
    /// Gauss–Legendre nodes per panel: the count `@EACH_TERM@` lines repeat for.
    pub terms: usize,
}

impl Constants {
    /// The kernel's values for a shader with `terms` Gauss–Legendre nodes per panel: the rule
    /// and the Legendre transform (`expansion::gauss_table`), the shaders' control
    /// (`SHADER_CONTROL`), the y-panel bound, the exact-product range and the exponential
    /// integrals' tuning of `f32` (`Real`), the short route's Gauss rule, the two-lobed light's
    /// largest power, and the record's kind and status codes and workgroup size
    /// ([`crate::layout`]).
    ///
    /// # Panics
    /// If `terms` has no tabulated rule (the emitted counts, [`NODE_COUNTS`], have).
    pub fn from_kernel(terms: usize) -> Constants {
        Constants::from_kernel_with(terms, airlight::SHADER_CONTROL.tolerance)
    }

    /// [`Constants::from_kernel`] with the panels' relative tolerance `tolerance` in place of
    /// the kernel's shader default.
    ///
    /// # Panics
    /// As [`Constants::from_kernel`].
    pub fn from_kernel_with(terms: usize, tolerance: f32) -> Constants {
        use crate::layout as l;
        use airlight::expansion::gauss_table;
        let f = |x: f64| format!("{:?}", x as f32);
        let list = |xs: Vec<String>| xs.join(", ");
        let rule = gauss_table::rule(terms).expect("a tabulated Gauss–Legendre rule");
        let transform = gauss_table::transform(terms).expect("a tabulated Legendre transform");
        let control = airlight::SHADER_CONTROL;
        let panel_list = 1 + (control.max_panels - 1) / 2;
        let (re, im) = <f32 as Real>::E1_SERIES_ELLIPSE;
        let (depth, en_depth) = (<f32 as Real>::E1_CF_DEPTH, <f32 as Real>::EN_CF_DEPTH);
        let chain = |depth: &[(f64, usize)], square: bool| {
            let mut body = String::new();
            for &(bound, d) in depth {
                if bound.is_finite() {
                    let (var, b) = if square { ("r2", bound * bound) } else { ("r", bound) };
                    body.push_str(&format!("    if ({var} < {}) {{ return {d}u; }}\n", f(b)));
                } else {
                    body.push_str(&format!("    return {d}u;"));
                }
            }
            body
        };
        let short: Vec<String> = <f32 as Real>::GAUSS_NODES
            .iter()
            .flat_map(|&(x, w)| [(-x, w), (x, w)])
            .map(|(x, w)| format!("vec2<f32>({}, {})", f(x), f(w)))
            .collect();
        let max_power = airlight::light::TwoLobed::<f32>::MAX_POWER;
        // each phase kind's singularities (phase.rs `singularities`) as a WGSL switch body: the
        // order at its cosines and its growth at infinity (0 if bounded)
        let singular_phases = {
            use airlight::phase::*;
            use airlight::PhaseFunction;
            // one of each kind; its code from the record layout
            let phases: [AnyPhase<f32>; 6] = [
                AnyPhase::Isotropic,
                AnyPhase::Rayleigh,
                AnyPhase::HenyeyGreenstein(HenyeyGreenstein { g: 0.5 }),
                AnyPhase::Schlick(Schlick { k: 0.5 }),
                AnyPhase::CornetteShanks(CornetteShanks { g: 0.5 }),
                AnyPhase::TwoLobeHenyeyGreenstein(TwoLobeHenyeyGreenstein { g1: 0.5, g2: 0.5, w: 0.5 }),
            ];
            let mut body = String::new();
            for phase in phases {
                let kind = l::phase_fields(&phase).0;
                let p = phase.singularities().expect("every built-in phase function declares its singularities");
                body.push_str(&format!("        case {kind}u: {{ order = {}; growth = {}; }}\n", f(p.order as f64), f(p.growth.max(0.0) as f64)));
            }
            body.push_str("        default: {}");
            body
        };
        let spot_degree = {
            use airlight::LightDistribution;
            let spot = airlight::light::SpotCone::<f32> { axis: airlight::glam::Vec3::X, cos_inner: 0.9, cos_outer: 0.8 };
            spot.polynomial_degree().expect("a spot cone is a polynomial between its kinks")
        };
        let outer_list = airlight::SHADER_SEGMENT_PANELS.max(airlight::SHADER_SURFACE_PANELS).max(airlight::SHADER_PHONG_PANELS);
        // a Phong lobe's arcs: the rule's pairs of nodes u = (1 ∓ x)/2 on each piece, weight w/2
        let lobe_rule = list(airlight::surface::LOBE_RULE.iter().map(|&(x, w)| format!("vec2<f32>({}, {})", f(0.5 - 0.5 * x), f(0.5 * w))).collect());
        // the weight at or below which the isotropic moment leaves its far end out (f32's ε/4)
        let far_end = airlight::integrals::FAR_END_NEGLIGIBLE * f32::EPSILON as f64;
        // area lights (area/outer.rs): the azimuths of AZIMUTHAL as (cos ψ, sin ψ, weight) over the
        // circle [0, 2π] and the half [−π/2, π/2], in its order; TRIANGLE_AZIMUTHAL as (x, w) on [−1, 1]
        let azimuths = |c: f64, hw: f64| {
            let nodes = airlight::area::outer::AZIMUTHAL.iter().flat_map(|&(x, w)| [(c - x * hw, w * hw), (c + x * hw, w * hw)]);
            list(nodes.map(|(psi, w)| format!("vec3<f32>({}, {}, {})", f(psi.cos()), f(psi.sin()), f(w))).collect())
        };
        let triangle = list(airlight::area::outer::TRIANGLE_AZIMUTHAL.iter().flat_map(|&(x, w)| [(-x, w), (x, w)]).map(|(x, w)| format!("vec2<f32>({}, {})", f(x), f(w))).collect());
        let radial = &airlight::area::outer::RADIAL;
        let emission_bits = u32::BITS - (airlight::Emission::MAX_POWER - 1).leading_zeros();
        let fills = vec![
            ("@TERMS@", terms.to_string()),
            ("@HALF_TERMS@", (terms / 2).to_string()),
            ("@ZEROS_TERMS@", list(vec!["0.0".to_string(); terms])),
            ("@PANEL_TOLERANCE@", f(tolerance as f64)),
            ("@PANEL_FLOOR@", f(control.floor as f64)),
            ("@MAX_PANELS@", control.max_panels.to_string()),
            ("@PANEL_LIST@", panel_list.to_string()),
            ("@ZEROS_LIST@", list(vec!["0.0".to_string(); panel_list])),
            ("@ZEROS_LIST4@", list(vec!["vec4<f32>(0.0)".to_string(); panel_list])),
            ("@Y_PANEL_EXPONENT@", f(airlight::panels::Y_PANEL_EXPONENT)),
            ("@ALIASING_MARGIN@", airlight::panels::ALIASING_MARGIN.to_string()),
            ("@INV_ODD_FACTORIAL@", f(airlight::angle::inv_odd_factorial(terms))),
            ("@INV_ODD_FACTORIAL_1@", f(airlight::angle::inv_odd_factorial(terms - 1))),
            ("@INV_ODD_FACTORIAL_2@", f(airlight::angle::inv_odd_factorial(terms - 2))),
            ("@UNCUT_SPAN@", f(airlight::combined::uncut_span(&airlight::panels::Control { tolerance, ..control }) as f64)),
            ("@CUT_RESOLUTION@", f(airlight::combined::cut_resolution(&airlight::panels::Control { tolerance, ..control }) as f64)),
            ("@SINGULAR_PHASES@", singular_phases),
            ("@SPOT_DEGREE@", f(spot_degree as f64)),
            ("@EXACT_RANGE@", f(<f32 as Real>::EXACT_RANGE)),
            ("@GAUSS_RULE@", list(rule.iter().map(|&(x, w)| format!("vec2<f32>({}, {})", f(x), f(w))).collect())),
            ("@LEGENDRE_BODY@", unrolled::legendre_body(terms, transform)),
            ("@MILLER_STORED@", unrolled::miller_stored(terms)),
            ("@MOMENTS_UPWARD@", unrolled::moments_upward(terms)),
            ("@MOMENTS_SIGNS@", unrolled::moments_signs(terms)),
            ("@LEGENDRE_TO_MONOMIAL_BODY@", unrolled::legendre_to_monomial_body(terms, &airlight::panels::LEGENDRE_MONOMIAL)),
            ("@MONOMIAL_SHIFT@", unrolled::monomial_shift(terms)),
            ("@EN_ORDERS@", (terms + 2).to_string()),
            ("@ZEROS_EN@", list(vec!["0.0".to_string(); terms + 2])),
            ("@EN_AT_ZERO@", unrolled::en_scaled_at_zero(terms + 2)),
            ("@EN_RECURRENCES@", unrolled::en_scaled_recurrences(terms + 2)),
            ("@E1_SERIES_TERMS@", <f32 as Real>::E1_SERIES_TERMS.to_string()),
            ("@EIN_DD_TERMS@", <f32 as Real>::E1_DD_BANDS.last().map_or(<f32 as Real>::E1_SERIES_TERMS, |b| b.1).to_string()),
            ("@EIN_COEFFS@", list(airlight::special::EIN_COEFFS[..<f32 as Real>::E1_SERIES_TERMS].iter().map(|&c| f(c)).collect())),
            ("@E1_CF_PLAIN_FROM@", airlight::special::PLAIN_FROM.to_string()),
            ("@E1_INV_RE@", f(1.0 / re)),
            ("@E1_INV_IM@", f(1.0 / im)),
            ("@E1_CF_MAX_DEPTH@", depth.iter().chain(en_depth).map(|d| d.1).max().unwrap_or(0).to_string()),
            ("@E1_CF_DEPTH_SQUARED@", chain(depth, true)),
            ("@EN_CF_DEPTH@", chain(en_depth, false)),
            ("@FAR_END_NEGLIGIBLE@", f(far_end)),
            ("@FAR_END_EXPONENT@", f(-far_end.ln())),
            ("@SHORT_NODES@", short.len().to_string()),
            ("@SHORT_RULE@", list(short)),
            ("@MAX_POWER@", max_power.to_string()),
            ("@MAX_POWER_BITS@", (u32::BITS - max_power.leading_zeros()).to_string()),
            ("@PHASE_ISOTROPIC@", l::PHASE_ISOTROPIC.to_string()),
            ("@PHASE_RAYLEIGH@", l::PHASE_RAYLEIGH.to_string()),
            ("@PHASE_HENYEY_GREENSTEIN@", l::PHASE_HENYEY_GREENSTEIN.to_string()),
            ("@PHASE_SCHLICK@", l::PHASE_SCHLICK.to_string()),
            ("@PHASE_CORNETTE_SHANKS@", l::PHASE_CORNETTE_SHANKS.to_string()),
            ("@PHASE_TWO_LOBE_HG@", l::PHASE_TWO_LOBE_HG.to_string()),
            ("@LIGHT_OMNI@", l::LIGHT_OMNI.to_string()),
            ("@LIGHT_TWO_LOBED@", l::LIGHT_TWO_LOBED.to_string()),
            ("@LIGHT_SPOT@", l::LIGHT_SPOT.to_string()),
            ("@SHAPE_POINT@", l::SHAPE_POINT.to_string()),
            ("@SHAPE_SEGMENT@", l::SHAPE_SEGMENT.to_string()),
            ("@SHAPE_DISC@", l::SHAPE_DISC.to_string()),
            ("@SHAPE_RECTANGLE@", l::SHAPE_RECTANGLE.to_string()),
            ("@SHAPE_SPHERE@", l::SHAPE_SPHERE.to_string()),
            ("@AREA_RAY_PANELS@", airlight::area::outer::BOUNDED_RAY_PANELS.to_string()),
            ("@AREA_RAY_TOLERANCE@", f(airlight::area::outer::BOUNDED_RAY_TOLERANCE)),
            ("@LOBE_REACH@", f(airlight::area::outer::LOBE_REACH)),
            ("@LOBE_TAIL@", f(airlight::area::outer::LOBE_TAIL)),
            ("@BESIDE_SCALE@", f(airlight::area::outer::BESIDE_SCALE)),
            ("@EDGE_REACH@", f(airlight::area::outer::EDGE_REACH)),
            ("@CROSSING_REACH@", f(airlight::area::outer::CROSSING_REACH)),
            ("@EMISSION_MAX_POWER@", airlight::Emission::MAX_POWER.to_string()),
            ("@EMISSION_POWER_STEPS@", unrolled::power_steps(emission_bits)),
            (
                "@KRONROD15_RULE@",
                list(airlight::extended::GAUSS_KRONROD_15.iter().map(|&(x, k, g)| format!("vec3<f32>({}, {}, {})", f(x), f(k), f(g))).collect()),
            ),
            ("@AZIMUTHS_CIRCLE@", azimuths(std::f64::consts::PI, std::f64::consts::PI)),
            ("@AZIMUTHS_HALF@", azimuths(0.0, std::f64::consts::FRAC_PI_2)),
            ("@TRIANGLE_RULE@", triangle),
            ("@MERCATOR_CUTS@", list(airlight::area::outer::MERCATOR_CUTS.iter().map(|&c| f(c)).collect())),
            ("@RADIAL_NODES@", (2 * radial.len()).to_string()),
            ("@ZEROS_RADIAL_ROWS@", list(vec!["vec3<f32>(0.0)".to_string(); 2 * radial.len()])),
            ("@RADIAL_FLAT@", unrolled::gauss_lines(radial, "    sum += @W@ * hw * airlight_flat_node(s, a, above, e, graded, @NODE@);\n")),
            ("@RADIAL_CAP_ROWS@", unrolled::gauss_lines(radial, "    rows[@K@] = airlight_cap_row(s, cap, graded, @NODE@, @W@ * hw);\n")),
            ("@RADIAL_CAP_CONSTANT@", unrolled::gauss_lines(radial, "        sum += rows[@K@].x * around;\n")),
            ("@RADIAL_CAP_AROUND@", unrolled::gauss_lines(radial, "        at += rows[@K@].x * airlight_area_phase(s, rows[@K@].y * ad + rows[@K@].z * across);\n")),
            ("@RADIAL_RULE@", list(radial.iter().flat_map(|&(x, w)| [(-x, w), (x, w)]).map(|(x, w)| format!("vec2<f32>({}, {})", f(x), f(w))).collect())),
            ("@RADIAL_FLAT_LOBE@", unrolled::gauss_lines(radial, "    sum += @W@ * hw * airlight_flat_lobe_node(s, z, lobe, k, start, graded, @NODE@);\n")),
            ("@RADIAL_LOBE@", unrolled::gauss_lines(radial, "        around += @W@ * hw * airlight_sphere_lobe_node(s, cap, sign, cos_p, big_b, start, graded, @NODE@);\n")),
            ("@SURFACE_NONE@", l::SURFACE_NONE.to_string()),
            ("@SURFACE_LAMBERT@", l::SURFACE_LAMBERT.to_string()),
            ("@SEGMENT_PANELS@", airlight::SHADER_SEGMENT_PANELS.to_string()),
            ("@SURFACE_PANELS@", airlight::SHADER_SURFACE_PANELS.to_string()),
            ("@PHONG_PANELS@", airlight::SHADER_PHONG_PANELS.to_string()),
            ("@SURFACE_PHONG@", l::SURFACE_PHONG.to_string()),
            ("@LN_LOBE_FLOOR@", f(airlight::surface::LOBE_FLOOR.ln())),
            ("@LOBE_RULE@", lobe_rule),
            ("@LOBE_PAIRS@", airlight::surface::LOBE_RULE.len().to_string()),
            // one panel list serves every outer integral
            ("@ZEROS_SEGMENT_LIST@", list(vec!["vec4<f32>(0.0)".to_string(); outer_list])),
            ("@SEGMENT_LIST_FIELDS@", unrolled::list_fields(outer_list)),
            ("@SEGMENT_LIST_GET@", unrolled::list_get(outer_list)),
            ("@SEGMENT_LIST_SET@", unrolled::list_set(outer_list)),
            ("@SEGMENT_LIST_SCAN@", unrolled::list_scan(outer_list)),
            (
                "@KRONROD_RULE@",
                list(airlight::extended::GAUSS_KRONROD_7.iter().map(|&(x, k, g)| format!("vec3<f32>({}, {}, {})", f(x), f(k), f(g))).collect()),
            ),
            ("@STATUS_OK@", l::STATUS_OK.to_string()),
            ("@STATUS_INVALID@", l::STATUS_INVALID.to_string()),
            ("@STATUS_INFINITE@", l::STATUS_INFINITE.to_string()),
            ("@STATUS_DEFERRED@", l::STATUS_DEFERRED.to_string()),
            ("@WORKGROUP_SIZE@", l::WORKGROUP_SIZE.to_string()),
        ];
        Constants { fills, terms }
    }

    /// The template with every placeholder filled: the library, plus the compute entry point
    /// when `compute` is set.
    ///
    /// # Panics
    /// If a placeholder of the template has no fill (a template and this table that disagree).
    pub fn source(&self, compute: bool) -> String {
        let mut s = LIBRARY.to_string();
        if compute {
            s.push_str(COMPUTE);
        }
        for (key, value) in &self.fills {
            s = s.replace(key, value);
        }
        s = unrolled::expand_each_term(&s, self.terms);
        if let Some(at) = s.find('@').filter(|&i| s[i + 1..].starts_with(|c: char| c.is_ascii_uppercase())) {
            let name: String = s[at..].chars().take_while(|c| !c.is_whitespace()).collect();
            panic!("the shader template's placeholder {name} has no value");
        }
        s
    }
}

/// The WGSL source for `terms` Gauss–Legendre nodes per panel, filled from the kernel
/// ([`Constants::from_kernel`]): the library, plus the compute entry point when `compute` is
/// set.
pub fn source(terms: usize, compute: bool) -> String {
    Constants::from_kernel(terms).source(compute)
}

/// The committed WGSL compute shader (`shaders-out/wgsl/airlight_{8,12}.wgsl`) for `terms` (8,
/// else 12): what `airlight eval --backend gpu`, `verify`, `render` and the GPU bench run.
pub fn compute_wgsl(terms: usize) -> &'static str {
    match terms {
        8 => include_str!("../../../shaders-out/wgsl/airlight_8.wgsl"),
        _ => include_str!("../../../shaders-out/wgsl/airlight_12.wgsl"),
    }
}

/// The committed WGSL include library (`shaders-out/wgsl/airlight_lib_{8,12}.wgsl`) for `terms`
/// (8, else 12).
pub fn library_wgsl(terms: usize) -> &'static str {
    match terms {
        8 => include_str!("../../../shaders-out/wgsl/airlight_lib_8.wgsl"),
        _ => include_str!("../../../shaders-out/wgsl/airlight_lib_12.wgsl"),
    }
}

/// A compute shader for records that are all point lights without a surface: the committed
/// include library ([`library_wgsl`]) with [`point_compute_entry`]. What `airlight eval --backend
/// gpu` runs when every record is a point light.
pub fn point_compute_wgsl(terms: usize) -> String {
    format!("{}\n{}", library_wgsl(terms), point_compute_entry())
}

/// The compute entry point `airlight_main` (`codegen/shaders/shader/compute.wgsl`, same bindings
/// and workgroup size) calling the point-light entry `airlight_in_scatter_point` instead of
/// `airlight_in_scatter`, to append to a WGSL include library
/// (`shaders-out/wgsl/airlight_lib_{8,12}.wgsl`): a compute shader for records that are all
/// point lights without a surface ([`point_compute_wgsl`]). Not emitted as a file.
pub fn point_compute_entry() -> String {
    compute_entry_calling("airlight_in_scatter_point")
}

/// A compute shader running the route entry `airlight_in_scatter_route` over point lights
/// without a surface: the committed include library ([`library_wgsl`]) with
/// [`route_compute_entry`]. Its records of status
/// [`STATUS_DEFERRED`](crate::layout::STATUS_DEFERRED) go through [`point_compute_wgsl`] next
/// ([`crate::gpu::run_deferred`]).
pub fn route_compute_wgsl(terms: usize) -> String {
    format!("{}\n{}", library_wgsl(terms), route_compute_entry())
}

/// The compute entry point as [`point_compute_entry`], calling the route entry
/// `airlight_in_scatter_route` (the first of two passes, docs/DESIGN.md §4.1). Not emitted as a
/// file.
pub fn route_compute_entry() -> String {
    compute_entry_calling("airlight_in_scatter_route")
}

/// A compute shader for area-light records: the committed include library ([`library_wgsl`])
/// with [`area_compute_entry`]. What `airlight eval --backend gpu` runs for area lights.
pub fn area_compute_wgsl(terms: usize) -> String {
    format!("{}\n{}", library_wgsl(terms), area_compute_entry())
}

/// The compute entry point as [`point_compute_entry`], calling the area-light entry
/// `airlight_in_scatter_area` (docs/DESIGN.md §12). Not emitted as a file.
pub fn area_compute_entry() -> String {
    compute_entry_calling("airlight_in_scatter_area")
}

/// The SPIR-V (naga's back end, as the committed `shaders-out/spirv/` is written) of a WGSL
/// compute shader `src`, compacted to what its entry point reaches.
pub fn spirv_of_compute(src: &str) -> Result<Vec<u32>, EmitError> {
    let (module, info) = compute_module(src)?;
    spirv_of(&module, &info)
}

/// `compute.wgsl` with its one call of `airlight_in_scatter` replaced by `entry`.
fn compute_entry_calling(entry: &str) -> String {
    assert_eq!(COMPUTE.matches("airlight_in_scatter(").count(), 1, "compute.wgsl calls airlight_in_scatter once");
    COMPUTE.replace("airlight_in_scatter(", &format!("{entry}(")).replace("@WORKGROUP_SIZE@", &crate::layout::WORKGROUP_SIZE.to_string())
}

/// Parses and validates WGSL.
pub fn validate(src: &str) -> Result<(naga::Module, ModuleInfo), EmitError> {
    let module = naga::front::wgsl::parse_str(src).map_err(|e| EmitError::Shader(e.emit_to_string(src)))?;
    let info = Validator::new(ValidationFlags::all(), Capabilities::default())
        .validate(&module)
        .map_err(|e| EmitError::Shader(e.emit_to_string(src)))?;
    Ok((module, info))
}

/// The compute shader's module: validated, then compacted to what `airlight_main` reaches (the
/// library's scene constructors are for shaders that include it, not for the record buffer),
/// and validated again.
fn compute_module(src: &str) -> Result<(naga::Module, ModuleInfo), EmitError> {
    let (mut module, _) = validate(src)?;
    naga::compact::compact(&mut module, naga::compact::KeepUnused::No);
    let info = Validator::new(ValidationFlags::all(), Capabilities::default())
        .validate(&module)
        .map_err(|e| EmitError::Shader(format!("after compaction: {}", e.emit_to_string(src))))?;
    Ok((module, info))
}

/// Index clamping everywhere: out-of-range indices read a valid element (the shader only
/// indexes in range; this makes the guarantee explicit and identical on every target).
fn policies() -> BoundsCheckPolicies {
    BoundsCheckPolicies {
        index: BoundsCheckPolicy::Restrict,
        buffer: BoundsCheckPolicy::Restrict,
        image_load: BoundsCheckPolicy::Restrict,
        binding_array: BoundsCheckPolicy::Restrict,
    }
}

fn header(comment: &str, terms: usize, tolerance: f32, what: &str) -> String {
    format!(
        "{comment} airlight {what}, error-controlled panels of {terms} nodes, tolerance {tolerance:e}, f32. Generated by\n\
         {comment} `airlight emit` from codegen/shaders/shader/*.wgsl through naga {}; do not edit. See shaders-out/README.md.\n",
        "30"
    )
}

/// Cuts `text` before the first line that contains `marker` (the dummy entry point).
fn cut_before(text: &str, marker: &str) -> Result<String, EmitError> {
    let mut out = String::new();
    let mut found = false;
    for line in text.lines() {
        if line.contains(marker) {
            found = true;
            break;
        }
        out.push_str(line);
        out.push('\n');
    }
    if !found {
        return Err(EmitError::Shader(format!("library stub '{marker}' not found in back-end output")));
    }
    // drop trailing attribute lines that belonged to the stub (HLSL [numthreads], MSL none)
    while out.trim_end().ends_with(']') && out.trim_end().rsplit('\n').next().is_some_and(|l| l.trim_start().starts_with('[')) {
        let t = out.trim_end().to_string();
        let cut = t.rfind('\n').map(|i| i + 1).unwrap_or(0);
        out = t[..cut].to_string();
    }
    Ok(out.trim_end().to_string() + "\n")
}

fn glsl_text(module: &naga::Module, info: &ModuleInfo, version: glsl::Version, stage: naga::ShaderStage, entry: &str, flags: glsl::WriterFlags) -> Result<String, EmitError> {
    // records at binding 0, results at binding 1 of set/group 0
    let mut binding_map = glsl::BindingMap::default();
    binding_map.insert(naga::ResourceBinding { group: 0, binding: 0 }, 0);
    binding_map.insert(naga::ResourceBinding { group: 0, binding: 1 }, 1);
    let options = glsl::Options { version, writer_flags: flags, binding_map, zero_initialize_workgroup_memory: true };
    let pipeline = glsl::PipelineOptions { shader_stage: stage, entry_point: entry.to_string(), multiview: None };
    let mut out = String::new();
    let mut w = glsl::Writer::new(&mut out, module, info, &options, &pipeline, policies()).map_err(|e| EmitError::Shader(format!("glsl: {e}")))?;
    w.write().map_err(|e| EmitError::Shader(format!("glsl: {e}")))?;
    Ok(out)
}

fn hlsl_text(module: &naga::Module, info: &ModuleInfo, entry: &str) -> Result<String, EmitError> {
    let options = hlsl::Options { shader_model: hlsl::ShaderModel::V5_1, ..Default::default() };
    let pipeline = hlsl::PipelineOptions { entry_point: Some((naga::ShaderStage::Compute, entry.to_string())) };
    let mut out = String::new();
    let mut w = hlsl::Writer::new(&mut out, &options, &pipeline);
    w.write(module, info, None).map_err(|e| EmitError::Shader(format!("hlsl: {e}")))?;
    Ok(prefix_naga_names(&portable_hlsl_zero_arrays(&out)))
}

/// Whether `name` is one of naga's own helper names (not the source's): `naga_*` and `Naga*`
/// helpers, the HLSL array constructors `Constructarray*` and their return typedefs `ret_*`,
/// MSL's anonymous `type_N` structs and its `_msl*` buffer-size struct.
fn is_naga_name(name: &str) -> bool {
    name.starts_with("naga_")
        || name.starts_with("Naga")
        || name.starts_with("_msl")
        || name.starts_with("Constructarray")
        || name.starts_with("ret_")
        || name.strip_prefix("type_").is_some_and(|d| !d.is_empty() && d.bytes().all(|b| b.is_ascii_digit()))
}

/// Gives naga's helper names ([`is_naga_name`]) the library's `airlight_` prefix, so that the
/// library can share a translation unit with another naga-emitted file ("function already
/// has a body" otherwise). Identifiers are renamed whole; nothing else changes.
fn prefix_naga_names(text: &str) -> String {
    let mut out = String::with_capacity(text.len() + 1024);
    let bytes = text.as_bytes();
    let mut i = 0;
    while i < bytes.len() {
        let c = bytes[i];
        if c.is_ascii_alphabetic() || c == b'_' {
            let start = i;
            while i < bytes.len() && (bytes[i].is_ascii_alphanumeric() || bytes[i] == b'_') {
                i += 1;
            }
            let word = &text[start..i];
            if is_naga_name(word) {
                out.push_str("airlight_");
            }
            out.push_str(word);
        } else if c.is_ascii_digit() {
            // a number (with any letters of its suffix or exponent) is no identifier
            let start = i;
            while i < bytes.len() && (bytes[i].is_ascii_alphanumeric() || bytes[i] == b'_' || bytes[i] == b'.') {
                i += 1;
            }
            out.push_str(&text[start..i]);
        } else {
            let ch = text[i..].chars().next().expect("in bounds");
            out.push(ch);
            i += ch.len_utf8();
        }
    }
    out
}

/// An include library wrapped in a guard (`AIRLIGHT_LIB_<n>`, one per node count), so that a
/// file included twice defines everything once.
fn guarded(body: &str, terms: usize) -> String {
    format!("#ifndef AIRLIGHT_LIB_{terms}\n#define AIRLIGHT_LIB_{terms}\n{body}#endif // AIRLIGHT_LIB_{terms}\n")
}

/// naga zero-initialises local arrays as `(float[N])0`, a cast FXC and DXC accept but other
/// HLSL front ends (glslang) reject; the initialiser list `{0, …}` means the same everywhere.
fn portable_hlsl_zero_arrays(text: &str) -> String {
    let mut out = String::with_capacity(text.len());
    let mut rest = text;
    while let Some(i) = rest.find("(float[") {
        let (head, tail) = rest.split_at(i);
        out.push_str(head);
        let close = tail.find("])0").filter(|&c| tail[7..c].bytes().all(|b| b.is_ascii_digit()));
        match close {
            Some(c) => {
                let n: usize = tail[7..c].parse().unwrap_or(0);
                out.push('{');
                out.push_str(&vec!["0.0"; n].join(", "));
                out.push('}');
                rest = &tail[c + 3..];
            }
            None => {
                out.push_str("(float[");
                rest = &tail[7..];
            }
        }
    }
    out.push_str(rest);
    out
}

fn msl_text(module: &naga::Module, info: &ModuleInfo, entry: &str) -> Result<String, EmitError> {
    let options = msl::Options { lang_version: (2, 0), bounds_check_policies: policies(), fake_missing_bindings: true, ..Default::default() };
    let pipeline = msl::PipelineOptions { entry_point: Some((naga::ShaderStage::Compute, entry.to_string())), ..Default::default() };
    let (s, _) = msl::write_string(module, info, &options, &pipeline).map_err(|e| EmitError::Shader(format!("msl: {e}")))?;
    Ok(prefix_naga_names(&s))
}

/// SPIR-V words of the compute entry point (Vulkan 1.0 / SPIR-V 1.0, no debug info).
pub fn spirv_words(terms: usize) -> Result<Vec<u32>, EmitError> {
    let (module, info) = validate(&source(terms, true))?;
    spirv_of(&module, &info)
}

/// SPIR-V 1.0 words of a validated compute module.
fn spirv_of(module: &naga::Module, info: &ModuleInfo) -> Result<Vec<u32>, EmitError> {
    let options = spv::Options {
        lang_version: (1, 0),
        flags: spv::WriterFlags::ADJUST_COORDINATE_SPACE,
        bounds_check_policies: policies(),
        ..Default::default()
    };
    let pipeline = spv::PipelineOptions { shader_stage: naga::ShaderStage::Compute, entry_point: COMPUTE_ENTRY.to_string() };
    spv::write_vec(module, info, &options, Some(&pipeline)).map_err(|e| EmitError::Shader(format!("spirv: {e}")))
}

fn check_options(opts: &EmitOptions) -> Result<(), EmitError> {
    if opts.terms.is_empty() || opts.targets.is_empty() {
        return Err(EmitError::Usage("nothing to emit: give at least one node count and one target".into()));
    }
    for &t in &opts.terms {
        if !NODE_COUNTS.contains(&t) {
            return Err(EmitError::Usage(format!("unsupported node count {t} (expected 8 or 12)")));
        }
    }
    if !TOLERANCE_RANGE.contains(&opts.tolerance) {
        return Err(EmitError::Usage(format!("tolerance {:e} outside [{:e}, {:e}]", opts.tolerance, TOLERANCE_RANGE.start(), TOLERANCE_RANGE.end())));
    }
    Ok(())
}

/// Renders every artifact in memory: relative file name → bytes.
pub fn render(opts: &EmitOptions) -> Result<BTreeMap<String, Vec<u8>>, EmitError> {
    render_with(opts, |n| Constants::from_kernel_with(n, opts.tolerance))
}

/// [`render`] with the template's numbers from `constants` (per node count) instead of the
/// kernel: what a shader whose numbers drifted from the kernel's would emit.
pub fn render_with(opts: &EmitOptions, constants: impl Fn(usize) -> Constants) -> Result<BTreeMap<String, Vec<u8>>, EmitError> {
    check_options(opts)?;
    let mut files = BTreeMap::new();
    for &n in &opts.terms {
        let filled = constants(n);
        let (cm, ci) = compute_module(&filled.source(true))?;
        let library = filled.source(false);
        let (lm, li) = validate(&(library.clone() + LIBRARY_STUB))?;
        let (lone, lone_info) = validate(&library)?;
        for &t in &opts.targets {
            match t {
                Target::Wgsl => {
                    let flags = wgsl::WriterFlags::empty();
                    let c = wgsl::write_string(&cm, &ci, flags).map_err(|e| EmitError::Shader(format!("wgsl: {e}")))?;
                    files.insert(format!("wgsl/airlight_{n}.wgsl"), (header("//", n, opts.tolerance, "compute shader (entry airlight_main)") + &c).into_bytes());
                    let l = wgsl::write_string(&lone, &lone_info, flags).map_err(|e| EmitError::Shader(format!("wgsl: {e}")))?;
                    files.insert(format!("wgsl/airlight_lib_{n}.wgsl"), (header("//", n, opts.tolerance, "include library") + &l).into_bytes());
                    // the same library as a naga_oil / Bevy module: `#import airlight::{…}`
                    let import = format!("{}#define_import_path airlight\n\n{l}", header("//", n, opts.tolerance, "naga_oil import module"));
                    files.insert(format!("wgsl/airlight_lib_{n}_import.wgsl"), import.into_bytes());
                }
                Target::Glsl => {
                    let c = glsl_text(&cm, &ci, glsl::Version::Desktop(450), naga::ShaderStage::Compute, COMPUTE_ENTRY, glsl::WriterFlags::empty())?;
                    files.insert(format!("glsl/airlight_{n}.comp"), insert_after_version(&c, &header("//", n, opts.tolerance, "compute shader (GLSL 450)")).into_bytes());
                    let l = glsl_text(&lm, &li, glsl::Version::Desktop(450), naga::ShaderStage::Compute, LIBRARY_ENTRY, glsl::WriterFlags::INCLUDE_UNUSED_ITEMS)?;
                    let l = glsl_library(&l)?;
                    files.insert(format!("glsl/airlight_lib_{n}.glsl"), (header("//", n, opts.tolerance, "include library (GLSL 450)") + &guarded(&l, n)).into_bytes());
                    let (em, ei) = validate(&(library.clone() + LIBRARY_STUB_ES))?;
                    let e = glsl_text(&em, &ei, glsl::Version::Embedded { version: 300, is_webgl: true }, naga::ShaderStage::Fragment, LIBRARY_ENTRY, glsl::WriterFlags::INCLUDE_UNUSED_ITEMS)?;
                    let e = glsl_library(&e)?;
                    files.insert(format!("glsl/airlight_lib_{n}_es300.glsl"), (header("//", n, opts.tolerance, "include library (GLSL ES 3.00 / WebGL2)") + &guarded(&e, n)).into_bytes());
                }
                Target::Spirv => {
                    let words = spirv_of(&cm, &ci)?;
                    files.insert(format!("spirv/airlight_{n}.spv"), words.iter().flat_map(|w| w.to_le_bytes()).collect());
                }
                Target::Hlsl => {
                    let c = hlsl_text(&cm, &ci, COMPUTE_ENTRY)?;
                    files.insert(format!("hlsl/airlight_{n}.hlsl"), (header("//", n, opts.tolerance, "compute shader (HLSL SM 5.1, entry airlight_main)") + &c).into_bytes());
                    let l = hlsl_text(&lm, &li, LIBRARY_ENTRY)?;
                    let l = cut_before(&l, LIBRARY_ENTRY)?;
                    files.insert(format!("hlsl/airlight_lib_{n}.hlsl"), (header("//", n, opts.tolerance, "include library (HLSL)") + &guarded(&l, n)).into_bytes());
                }
                Target::Msl => {
                    let c = msl_text(&cm, &ci, COMPUTE_ENTRY)?;
                    files.insert(format!("msl/airlight_{n}.metal"), (header("//", n, opts.tolerance, "compute kernel (MSL 2.0, entry airlight_main)") + &c).into_bytes());
                    let l = msl_text(&lm, &li, LIBRARY_ENTRY)?;
                    let l = cut_before(&l, LIBRARY_ENTRY)?;
                    files.insert(format!("msl/airlight_lib_{n}.metal"), (header("//", n, opts.tolerance, "include library (MSL)") + &guarded(&l, n)).into_bytes());
                }
            }
        }
    }
    Ok(files)
}

fn insert_after_version(text: &str, header: &str) -> String {
    match text.split_once('\n') {
        Some((first, rest)) if first.starts_with("#version") => format!("{first}\n{header}{rest}"),
        _ => format!("{header}{text}"),
    }
}

/// The GLSL library: naga's output without the `#version`, `#extension` and `precision`
/// lines, the stub's interface declarations and the stub itself (cut at `void main(`).
fn glsl_library(text: &str) -> Result<String, EmitError> {
    let body = cut_before(text, "void main(")?;
    let kept: Vec<&str> = body
        .lines()
        .filter(|l| !l.starts_with("#version") && !l.starts_with("#extension") && !l.starts_with("layout(") && !l.starts_with("precision "))
        .collect();
    Ok(kept.join("\n").trim().to_string() + "\n")
}

/// The workspace's committed output folder.
pub fn default_out_dir() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR")).ancestors().nth(2).expect("workspace root").join("shaders-out")
}

/// Writes every artifact under `out_dir`. Nothing is half-written: everything is rendered and
/// validated first, then written to temporary files (removed again if any write fails), and
/// only then renamed into place.
pub fn emit(out_dir: &Path, opts: &EmitOptions) -> Result<Vec<PathBuf>, EmitError> {
    let files = render(opts)?;
    let mut staged: Vec<(PathBuf, PathBuf)> = Vec::new();
    let cleanup = |staged: &[(PathBuf, PathBuf)]| {
        for (tmp, _) in staged {
            let _ = std::fs::remove_file(tmp);
        }
    };
    for (rel, bytes) in &files {
        let path = out_dir.join(rel);
        let dir = path.parent().unwrap().to_path_buf();
        let tmp = path.with_extension("tmp");
        let result = std::fs::create_dir_all(&dir)
            .map_err(|e| EmitError::Io(dir.clone(), e))
            .and_then(|_| std::fs::write(&tmp, bytes).map_err(|e| EmitError::Io(tmp.clone(), e)));
        if let Err(e) = result {
            cleanup(&staged);
            return Err(e);
        }
        staged.push((tmp, path));
    }
    let mut written = Vec::new();
    for (tmp, path) in &staged {
        std::fs::rename(tmp, path).map_err(|e| EmitError::Io(path.clone(), e))?;
        written.push(path.clone());
    }
    Ok(written)
}

/// Compares `dir` with what the current source emits: the stale, missing and unexpected
/// files (empty when up to date). Only the folders of the requested targets are compared.
pub fn check(dir: &Path, opts: &EmitOptions) -> Result<Vec<String>, EmitError> {
    compare(dir, &render(opts)?)
}

/// The stale, missing and unexpected files of `dir` against `files`.
fn compare(dir: &Path, files: &BTreeMap<String, Vec<u8>>) -> Result<Vec<String>, EmitError> {
    let mut problems = Vec::new();
    for (rel, bytes) in files {
        match std::fs::read(dir.join(rel)) {
            Ok(old) if &old == bytes => {}
            Ok(_) => problems.push(format!("stale: {rel}")),
            Err(_) => problems.push(format!("missing: {rel}")),
        }
    }
    let folders: std::collections::BTreeSet<&str> = files.keys().filter_map(|k| k.split('/').next()).collect();
    for folder in folders {
        if let Ok(rd) = std::fs::read_dir(dir.join(folder)) {
            for entry in rd.flatten() {
                let rel = format!("{folder}/{}", entry.file_name().to_string_lossy());
                if !files.contains_key(&rel) {
                    problems.push(format!("unexpected: {rel}"));
                }
            }
        }
    }
    Ok(problems)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn wgsl_only() -> EmitOptions {
        EmitOptions { targets: vec![Target::Wgsl], ..EmitOptions::default() }
    }

    /// `tolerance` reaches the shader's panel constant and its header, and one outside
    /// [`TOLERANCE_RANGE`] is a usage error, not a shader.
    #[test]
    fn the_tolerance_is_the_emitted_one() {
        let opts = EmitOptions { tolerance: 1e-2, ..wgsl_only() };
        let files = render(&opts).unwrap();
        let text = String::from_utf8(files["wgsl/airlight_8.wgsl"].clone()).unwrap();
        assert!(text.lines().next().unwrap().contains("tolerance 1e-2"), "{}", text.lines().next().unwrap());
        let committed = String::from_utf8(render(&wgsl_only()).unwrap()["wgsl/airlight_8.wgsl"].clone()).unwrap();
        let constant = |t: &str| t.lines().find(|l| l.contains("const AIRLIGHT_PANEL_TOLERANCE")).map(str::to_string);
        assert_eq!(constant(&text).as_deref(), Some("const AIRLIGHT_PANEL_TOLERANCE: f32 = 0.01f;"));
        assert_eq!(constant(&committed).as_deref(), Some("const AIRLIGHT_PANEL_TOLERANCE: f32 = 0.001f;"));
        for bad in [0.0, 1e-6, 0.5, f32::NAN] {
            assert!(matches!(render(&EmitOptions { tolerance: bad, ..wgsl_only() }), Err(EmitError::Usage(_))), "{bad}");
        }
    }

    /// Every placeholder of the template has a value, for every emitted node count.
    #[test]
    fn every_placeholder_is_filled() {
        for n in NODE_COUNTS {
            let s = source(n, true);
            assert!(!s.contains("@TERMS@") && !s.contains("@GAUSS_RULE@"));
        }
    }

    /// The committed shaders carry the kernel's numbers: emitting them again from the kernel
    /// changes nothing, and a shader whose one number drifted from the kernel's (here the
    /// panel tolerance, ten times looser) no longer matches them — `airlight check` fails.
    #[test]
    fn a_drifted_constant_fails_the_check() {
        let dir = default_out_dir();
        assert_eq!(check(&dir, &wgsl_only()).unwrap(), Vec::<String>::new(), "shaders-out/ is stale: run `airlight emit`");
        let drifted = |n: usize| {
            let mut c = Constants::from_kernel(n);
            for (key, value) in &mut c.fills {
                if *key == "@PANEL_TOLERANCE@" {
                    *value = format!("{:?}", airlight::SHADER_CONTROL.tolerance * 10.0);
                }
            }
            c
        };
        let problems = compare(&dir, &render_with(&wgsl_only(), drifted).unwrap()).unwrap();
        assert!(problems.contains(&"stale: wgsl/airlight_8.wgsl".to_string()), "{problems:?}");
    }
}
