//! The records of the compute entry point: [`Record`] in (the WGSL `AirlightScene`, 144 bytes,
//! std430 / WGSL storage layout; the offset table is in shaders-out/README.md), [`GpuResult`]
//! out (8 bytes), both plain `#[repr(C)]` types the host writes and reads with bytemuck; a test
//! checks their offsets and strides against naga's layout of the WGSL structs. Also the kind and
//! status codes the shader takes from here at emission, and the workgroup size.

use airlight::light::AnyDistribution;
use airlight::phase::AnyPhase;
use airlight::{AreaScene, Brdf, Emission, Emitter, Medium, PointLight, Ray, SegmentScene, SurfaceScene};

/// Bytes per input record.
pub const RECORD_SIZE: usize = 144;
/// Bytes `0..FLOAT_INPUTS_END` of a record are its f32 inputs (origin … phase_param_c) but for
/// a segment light's `light_end`; the u32 kinds and flags follow.
pub const FLOAT_INPUTS_END: usize = 88;
/// Bytes per output record.
pub const RESULT_SIZE: usize = 8;
/// Status: value is valid.
pub const STATUS_OK: u32 = 0;
/// Status: the record was invalid; value 0.
pub const STATUS_INVALID: u32 = 1;
/// Status: the light lies on the segment (or the value overflowed); value `f32::MAX`.
pub const STATUS_INFINITE: u32 = 2;
/// Status of the route entry alone (`airlight_in_scatter_route`): the light-angle route does not
/// meet the tolerance on this record; value 0, and the record is to be run through the point
/// entry ([`crate::gpu::run_deferred`]). No other entry gives it.
pub const STATUS_DEFERRED: u32 = 3;

/// `light_kind` of an omni light ([`AnyDistribution::Omni`]).
pub const LIGHT_OMNI: u32 = 0;
/// `light_kind` of a two-lobed `c^p` light (`light_param_a` = p).
pub const LIGHT_TWO_LOBED: u32 = 1;
/// `light_kind` of a spot cone (`light_param_a`, `_b` = cos_inner, cos_outer).
pub const LIGHT_SPOT: u32 = 2;
/// `light_shape` of a point light.
pub const SHAPE_POINT: u32 = 0;
/// `light_shape` of a segment light `light_position → light_end`, `intensity` per unit length
/// ([`airlight::SegmentLight`]).
pub const SHAPE_SEGMENT: u32 = 1;
/// `light_shape` of a disc of radiance `intensity`: centre `light_position`, normal
/// `light_axis`, radius `light_param_a`, emission power `light_param_b` ([`airlight::Emitter::Disc`]).
pub const SHAPE_DISC: u32 = 2;
/// `light_shape` of a parallelogram of radiance `intensity`: corner `light_position`, edges
/// `light_axis` (u) and `light_end` (v), emission power `light_param_b`
/// ([`airlight::Emitter::Rectangle`]).
pub const SHAPE_RECTANGLE: u32 = 3;
/// `light_shape` of a sphere of radiance `intensity`: centre `light_position`, radius
/// `light_param_a`, emission power `light_param_b` ([`airlight::Emitter::Sphere`]).
pub const SHAPE_SPHERE: u32 = 4;
/// `surface_kind` of a ray record: the in-scattered radiance along the ray.
pub const SURFACE_NONE: u32 = 0;
/// `surface_kind` of a Lambertian surface point (`origin`, normal `dir`, albedo
/// `brdf_scale`) lit by a light without an axis: its surface radiance from air-light
/// ([`airlight::SurfaceScene::air_light`]).
pub const SURFACE_LAMBERT: u32 = 1;
/// `surface_kind` of a Phong surface point (`origin`, normal `dir`; `k_s` = `brdf_scale`,
/// exponent `brdf_exponent`, towards the eye `brdf_view`) lit by a light without an axis.
pub const SURFACE_PHONG: u32 = 2;
/// `phase_kind` of isotropic scattering.
pub const PHASE_ISOTROPIC: u32 = 0;
/// `phase_kind` of Rayleigh scattering.
pub const PHASE_RAYLEIGH: u32 = 1;
/// `phase_kind` of Henyey–Greenstein (`phase_param_a` = g).
pub const PHASE_HENYEY_GREENSTEIN: u32 = 2;
/// `phase_kind` of Schlick (`phase_param_a` = k).
pub const PHASE_SCHLICK: u32 = 3;
/// `phase_kind` of Cornette–Shanks (`phase_param_a` = g).
pub const PHASE_CORNETTE_SHANKS: u32 = 4;
/// `phase_kind` of two-lobe Henyey–Greenstein (`phase_param_a`, `_b`, `_c` = g1, g2, w).
pub const PHASE_TWO_LOBE_HG: u32 = 5;
/// Invocations per workgroup of the compute entry point (dispatch `⌈n / WORKGROUP_SIZE⌉`).
pub const WORKGROUP_SIZE: u32 = 64;

/// One record of the compute entry point's input buffer: the WGSL `AirlightScene` struct of
/// `codegen/shaders/shader/airlight.wgsl` as the host writes it (std430 / WGSL storage layout, so each
/// `vec3` is followed by a scalar in its 16-byte slot). `record_matches_the_wgsl_struct` checks
/// every offset and the array stride against naga's layout of the WGSL struct.
#[repr(C)]
#[derive(Clone, Copy, Debug, Default, PartialEq, bytemuck::Pod, bytemuck::Zeroable)]
pub struct Record {
    /// Ray origin.
    pub origin: [f32; 3],
    /// Segment start (world distance).
    pub t_min: f32,
    /// Ray direction, any non-zero length.
    pub dir: [f32; 3],
    /// Segment end (world distance); ignored when `flags` bit 0 is set.
    pub t_max: f32,
    /// Light position.
    pub light_position: [f32; 3],
    /// Light intensity.
    pub intensity: f32,
    /// Two-lobed / spot axis.
    pub light_axis: [f32; 3],
    /// Two-lobed: power; spot: cos_inner.
    pub light_param_a: f32,
    /// Spot: cos_outer.
    pub light_param_b: f32,
    /// Scattering coefficient.
    pub sigma_s: f32,
    /// Extinction coefficient.
    pub sigma_t: f32,
    /// g (Henyey–Greenstein, Cornette–Shanks), k (Schlick), g1 (two-lobe HG).
    pub phase_param_a: f32,
    /// g2 (two-lobe HG).
    pub phase_param_b: f32,
    /// w (two-lobe HG).
    pub phase_param_c: f32,
    /// `LIGHT_*`.
    pub light_kind: u32,
    /// `PHASE_*`.
    pub phase_kind: u32,
    /// Bit 0: `t_max = +∞`.
    pub flags: u32,
    /// A surface's albedo ρ (`SURFACE_LAMBERT`) or `k_s` (`SURFACE_PHONG`).
    pub brdf_scale: f32,
    /// `SURFACE_*`.
    pub surface_kind: u32,
    /// A Phong lobe's exponent `n`.
    pub brdf_exponent: f32,
    /// A segment light's other end.
    pub light_end: [f32; 3],
    /// `SHAPE_*`.
    pub light_shape: u32,
    /// A Phong lobe's direction from the surface towards the eye (any non-zero length).
    pub brdf_view: [f32; 3],
    /// Up to the record's 16-byte alignment.
    pub padding: u32,
}

/// One output of the compute entry point: the WGSL `AirlightResult` struct.
#[repr(C)]
#[derive(Clone, Copy, Debug, Default, PartialEq, bytemuck::Pod, bytemuck::Zeroable)]
pub struct GpuResult {
    /// `L_m` (0 for an invalid record, `f32::MAX` for an infinite one).
    pub in_scatter: f32,
    /// `STATUS_*`.
    pub status: u32,
}

impl Record {
    /// The record of a scene given as the kernel's types.
    pub fn new(ray: &Ray<f32>, light: &PointLight<f32, AnyDistribution<f32>>, medium: &Medium<f32>, phase: &AnyPhase<f32>) -> Self {
        Self::with_shape(ray, light, medium, phase, SHAPE_POINT, light.position.to_array())
    }

    /// The record of a segment light (its `a` the record's `light_position`).
    pub fn segment(scene: &SegmentScene<f32, AnyDistribution<f32>, AnyPhase<f32>>) -> Self {
        let l = scene.light();
        let light = PointLight { position: l.a, intensity: l.intensity, distribution: l.distribution };
        Self::with_shape(scene.ray(), &light, scene.medium(), scene.phase(), SHAPE_SEGMENT, l.b.to_array())
    }

    /// The record of an area light (the fields of [`SHAPE_DISC`], [`SHAPE_RECTANGLE`],
    /// [`SHAPE_SPHERE`]).
    pub fn area(scene: &AreaScene<f32, AnyPhase<f32>>) -> Self {
        let l = scene.light();
        let (shape, anchor, axis, end, radius) = match l.emitter {
            Emitter::Disc { center, normal, radius } => (SHAPE_DISC, center, normal.to_array(), [0.0; 3], radius),
            Emitter::Rectangle { corner, edge_u, edge_v } => (SHAPE_RECTANGLE, corner, edge_u.to_array(), edge_v.to_array(), 0.0),
            Emitter::Sphere { center, radius } => (SHAPE_SPHERE, center, [0.0, 0.0, 1.0], [0.0; 3], radius),
        };
        let light = PointLight { position: anchor, intensity: l.radiance, distribution: AnyDistribution::Omni };
        let mut record = Self::with_shape(scene.ray(), &light, scene.medium(), scene.phase(), shape, end);
        record.light_axis = axis;
        record.light_param_a = radius;
        record.light_param_b = match l.emission {
            Emission::Lambertian => 1.0,
            Emission::CosineLobe { power } => power as f32,
        };
        record
    }

    /// The record of a Lambertian or Phong surface point lit by a light without an axis (the
    /// shaders' surfaces); `None` for a light with an axis.
    pub fn surface(scene: &SurfaceScene<f32, AnyDistribution<f32>, AnyPhase<f32>>) -> Option<Self> {
        if !matches!(scene.light().distribution, AnyDistribution::Omni) {
            return None;
        }
        let s = scene.surface();
        let ray = Ray { origin: s.position, dir: s.normal, t_min: 0.0, t_max: f32::INFINITY };
        let mut record = Self::with_shape(&ray, scene.light(), scene.medium(), scene.phase(), SHAPE_POINT, scene.light().position.to_array());
        match *scene.brdf() {
            Brdf::Lambert { albedo } => {
                record.brdf_scale = albedo;
                record.surface_kind = SURFACE_LAMBERT;
            }
            Brdf::Phong { k_s, exponent, view } => {
                record.brdf_scale = k_s;
                record.brdf_exponent = exponent;
                record.brdf_view = view.to_array();
                record.surface_kind = SURFACE_PHONG;
            }
        }
        Some(record)
    }

    fn with_shape(ray: &Ray<f32>, light: &PointLight<f32, AnyDistribution<f32>>, medium: &Medium<f32>, phase: &AnyPhase<f32>, light_shape: u32, light_end: [f32; 3]) -> Self {
        let (light_kind, light_axis, light_param_a, light_param_b) = match light.distribution {
            AnyDistribution::Omni => (LIGHT_OMNI, [0.0, 0.0, 1.0], 0.0, 0.0),
            AnyDistribution::TwoLobed(d) => (LIGHT_TWO_LOBED, d.axis.to_array(), d.power as f32, 0.0),
            AnyDistribution::SpotCone(d) => (LIGHT_SPOT, d.axis.to_array(), d.cos_inner, d.cos_outer),
        };
        let (phase_kind, phase_param_a, phase_param_b, phase_param_c) = phase_fields(phase);
        let infinite = ray.t_max == f32::INFINITY;
        Record {
            origin: ray.origin.to_array(),
            t_min: ray.t_min,
            dir: ray.dir.to_array(),
            t_max: if infinite { 0.0 } else { ray.t_max },
            light_position: light.position.to_array(),
            intensity: light.intensity,
            light_axis,
            light_param_a,
            light_param_b,
            sigma_s: medium.sigma_s,
            sigma_t: medium.sigma_t,
            phase_param_a,
            phase_param_b,
            phase_param_c,
            light_kind,
            phase_kind,
            flags: infinite as u32,
            brdf_scale: 0.0,
            surface_kind: SURFACE_NONE,
            brdf_exponent: 0.0,
            light_end,
            light_shape,
            brdf_view: [0.0; 3],
            padding: 0,
        }
    }

    /// Its bytes, as the compute entry point reads them.
    pub fn bytes(&self) -> [u8; RECORD_SIZE] {
        bytemuck::cast(*self)
    }

    /// Its f32 inputs, `origin` … `phase_param_c` (the kinds and flags follow them).
    pub fn float_inputs(&self) -> &[f32] {
        &bytemuck::cast_slice(bytemuck::bytes_of(self))[..FLOAT_INPUTS_END / 4]
    }
}

/// A phase function's record fields: its kind (`PHASE_*`) and up to three parameters.
pub fn phase_fields(phase: &AnyPhase<f32>) -> (u32, f32, f32, f32) {
    match *phase {
        AnyPhase::Isotropic => (PHASE_ISOTROPIC, 0.0, 0.0, 0.0),
        AnyPhase::Rayleigh => (PHASE_RAYLEIGH, 0.0, 0.0, 0.0),
        AnyPhase::HenyeyGreenstein(p) => (PHASE_HENYEY_GREENSTEIN, p.g, 0.0, 0.0),
        AnyPhase::Schlick(p) => (PHASE_SCHLICK, p.k, 0.0, 0.0),
        AnyPhase::CornetteShanks(p) => (PHASE_CORNETTE_SHANKS, p.g, 0.0, 0.0),
        AnyPhase::TwoLobeHenyeyGreenstein(p) => (PHASE_TWO_LOBE_HG, p.g1, p.g2, p.w),
    }
}

/// Packs one scene into its 144-byte record (little-endian, as every GPU wgpu runs on).
pub fn pack(ray: &Ray<f32>, light: &PointLight<f32, AnyDistribution<f32>>, medium: &Medium<f32>, phase: &AnyPhase<f32>) -> [u8; RECORD_SIZE] {
    bytemuck::cast(Record::new(ray, light, medium, phase))
}

/// Packs one segment light's scene into its record.
pub fn pack_segment(scene: &SegmentScene<f32, AnyDistribution<f32>, AnyPhase<f32>>) -> [u8; RECORD_SIZE] {
    bytemuck::cast(Record::segment(scene))
}

/// Packs an area light's scene into its record.
pub fn pack_area(scene: &AreaScene<f32, AnyPhase<f32>>) -> [u8; RECORD_SIZE] {
    bytemuck::cast(Record::area(scene))
}

/// Packs a Lambertian surface point lit by a light without an axis into its record (`None`
/// otherwise: the shaders have no other surfaces).
pub fn pack_surface(scene: &SurfaceScene<f32, AnyDistribution<f32>, AnyPhase<f32>>) -> Option<[u8; RECORD_SIZE]> {
    Record::surface(scene).map(bytemuck::cast)
}

/// Reads one result: `(in_scatter, status)`.
pub fn unpack_result(bytes: &[u8]) -> (f32, u32) {
    let r: GpuResult = bytemuck::pod_read_unaligned(&bytes[..RESULT_SIZE]);
    (r.in_scatter, r.status)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Every field of [`Record`] sits where naga lays out the same member of the WGSL
    /// `AirlightScene` (storage layout), the array stride is the record's size, and likewise
    /// for [`GpuResult`] / `AirlightResult`: the host and the shader read the same bytes.
    #[test]
    fn record_matches_the_wgsl_struct() {
        let (module, _) = crate::targets::validate(&crate::targets::source(4, true)).unwrap();
        let mut layouter = naga::proc::Layouter::default();
        layouter.update(module.to_ctx()).unwrap();
        let rust: [(&str, usize); 23] = [
            ("origin", core::mem::offset_of!(Record, origin)),
            ("t_min", core::mem::offset_of!(Record, t_min)),
            ("dir", core::mem::offset_of!(Record, dir)),
            ("t_max", core::mem::offset_of!(Record, t_max)),
            ("light_position", core::mem::offset_of!(Record, light_position)),
            ("intensity", core::mem::offset_of!(Record, intensity)),
            ("light_axis", core::mem::offset_of!(Record, light_axis)),
            ("light_param_a", core::mem::offset_of!(Record, light_param_a)),
            ("light_param_b", core::mem::offset_of!(Record, light_param_b)),
            ("sigma_s", core::mem::offset_of!(Record, sigma_s)),
            ("sigma_t", core::mem::offset_of!(Record, sigma_t)),
            ("phase_param_a", core::mem::offset_of!(Record, phase_param_a)),
            ("phase_param_b", core::mem::offset_of!(Record, phase_param_b)),
            ("phase_param_c", core::mem::offset_of!(Record, phase_param_c)),
            ("light_kind", core::mem::offset_of!(Record, light_kind)),
            ("phase_kind", core::mem::offset_of!(Record, phase_kind)),
            ("flags", core::mem::offset_of!(Record, flags)),
            ("brdf_scale", core::mem::offset_of!(Record, brdf_scale)),
            ("surface_kind", core::mem::offset_of!(Record, surface_kind)),
            ("brdf_exponent", core::mem::offset_of!(Record, brdf_exponent)),
            ("light_end", core::mem::offset_of!(Record, light_end)),
            ("light_shape", core::mem::offset_of!(Record, light_shape)),
            ("brdf_view", core::mem::offset_of!(Record, brdf_view)),
        ];
        let result: [(&str, usize); 2] = [("in_scatter", core::mem::offset_of!(GpuResult, in_scatter)), ("status", core::mem::offset_of!(GpuResult, status))];
        for (name, fields, size) in [("AirlightScene", &rust[..], core::mem::size_of::<Record>()), ("AirlightResult", &result[..], core::mem::size_of::<GpuResult>())] {
            let (handle, ty) = module.types.iter().find(|(_, t)| t.name.as_deref() == Some(name)).unwrap_or_else(|| panic!("no struct {name} in the WGSL"));
            let naga::TypeInner::Struct { members, .. } = &ty.inner else { panic!("{name} is not a struct") };
            let wgsl: Vec<(&str, usize)> = members.iter().map(|m| (m.name.as_deref().unwrap(), m.offset as usize)).collect();
            assert_eq!(wgsl, fields, "{name}: member offsets (naga) against the Rust struct's");
            assert_eq!(layouter[handle].to_stride() as usize, size, "{name}: array stride (naga) against size_of");
        }
        assert_eq!((core::mem::size_of::<Record>(), core::mem::size_of::<GpuResult>()), (RECORD_SIZE, RESULT_SIZE));
        assert_eq!(core::mem::offset_of!(Record, light_kind), FLOAT_INPUTS_END);
    }
}
