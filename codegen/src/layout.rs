//! The record layout of the compute entry point (std430 / WGSL storage layout), and a packer
//! from kernel types. Byte offsets (112 bytes per record, 16-byte aligned):
//!
//! | offset | field | type | meaning |
//! |---|---|---|---|
//! | 0 | origin | vec3 f32 | ray origin |
//! | 12 | t_min | f32 | segment start |
//! | 16 | dir | vec3 f32 | ray direction (any non-zero length) |
//! | 28 | t_max | f32 | segment end (ignored if flags bit 0) |
//! | 32 | light_position | vec3 f32 | |
//! | 44 | intensity | f32 | |
//! | 48 | light_axis | vec3 f32 | two-lobed / spot axis |
//! | 60 | light_param0 | f32 | two-lobed: power; spot: cos_inner |
//! | 64 | light_param1 | f32 | spot: cos_outer |
//! | 68 | sigma_s | f32 | |
//! | 72 | sigma_t | f32 | |
//! | 76 | phase_param0 | f32 | g (HG, Cornette–Shanks), k (Schlick), g1 (two-lobe HG) |
//! | 80 | phase_param1 | f32 | g2 (two-lobe HG) |
//! | 84 | phase_param2 | f32 | w (two-lobe HG) |
//! | 88 | light_kind | u32 | 0 omni, 1 two-lobed, 2 spot |
//! | 92 | phase_kind | u32 | 0 isotropic, 1 Rayleigh, 2 HG, 3 Schlick, 4 Cornette–Shanks, 5 two-lobe HG |
//! | 96 | flags | u32 | bit 0: t_max = +∞ |
//! | 100 | (padding) | 12 bytes | |
//!
//! Output, 8 bytes per record: `in_scatter: f32` at 0, `status: u32` at 4 (0 ok, 1 invalid
//! record → value 0, 2 infinite → value `f32::MAX`).

use airlight::light::AnyDistribution;
use airlight::phase::AnyPhase;
use airlight::{Medium, PointLight, Ray};

/// Bytes per input record.
pub const RECORD_SIZE: usize = 112;
/// Bytes `0..FLOAT_INPUTS_END` of a record are its f32 inputs (origin … phase_param2); the
/// u32 kinds and flags follow.
pub const FLOAT_INPUTS_END: usize = 88;
/// Bytes per output record.
pub const RESULT_SIZE: usize = 8;
/// Status: value is valid.
pub const STATUS_OK: u32 = 0;
/// Status: the record was invalid; value 0.
pub const STATUS_INVALID: u32 = 1;
/// Status: the light lies on the segment (or the value overflowed); value `f32::MAX`.
pub const STATUS_INFINITE: u32 = 2;

/// `light_kind` of an omni light ([`AnyDistribution::Omni`]).
pub const LIGHT_OMNI: u32 = 0;
/// `light_kind` of a two-lobed `c^p` light (`light_param_a` = p).
pub const LIGHT_TWO_LOBED: u32 = 1;
/// `light_kind` of a spot cone (`light_param_a`, `_b` = cos_inner, cos_outer).
pub const LIGHT_SPOT: u32 = 2;
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

/// Packs one scene into its 112-byte record.
pub fn pack(ray: &Ray<f32>, light: &PointLight<f32, AnyDistribution<f32>>, medium: &Medium<f32>, phase: &AnyPhase<f32>) -> [u8; RECORD_SIZE] {
    let mut w = [0u32; RECORD_SIZE / 4];
    let mut put3 = |at: usize, v: [f32; 3]| {
        for (i, x) in v.iter().enumerate() {
            w[at / 4 + i] = x.to_bits();
        }
    };
    put3(0, ray.origin.to_array());
    put3(16, ray.dir.to_array());
    put3(32, light.position.to_array());
    let (kind, axis, p0, p1) = match light.distribution {
        AnyDistribution::Omni => (LIGHT_OMNI, [0.0, 0.0, 1.0], 0.0, 0.0),
        AnyDistribution::TwoLobed(d) => (LIGHT_TWO_LOBED, d.axis.to_array(), d.power as f32, 0.0),
        AnyDistribution::SpotCone(d) => (LIGHT_SPOT, d.axis.to_array(), d.cos_inner, d.cos_outer),
    };
    put3(48, axis);
    let (pk, q0, q1, q2) = match phase {
        AnyPhase::Isotropic => (PHASE_ISOTROPIC, 0.0, 0.0, 0.0),
        AnyPhase::Rayleigh => (PHASE_RAYLEIGH, 0.0, 0.0, 0.0),
        AnyPhase::HenyeyGreenstein(p) => (PHASE_HENYEY_GREENSTEIN, p.g, 0.0, 0.0),
        AnyPhase::Schlick(p) => (PHASE_SCHLICK, p.k, 0.0, 0.0),
        AnyPhase::CornetteShanks(p) => (PHASE_CORNETTE_SHANKS, p.g, 0.0, 0.0),
        AnyPhase::TwoLobeHenyeyGreenstein(p) => (PHASE_TWO_LOBE_HG, p.g1, p.g2, p.w),
    };
    let infinite = ray.t_max == f32::INFINITY;
    w[3] = ray.t_min.to_bits();
    w[7] = if infinite { 0 } else { ray.t_max.to_bits() };
    w[11] = light.intensity.to_bits();
    w[15] = f32::to_bits(p0);
    w[16] = f32::to_bits(p1);
    w[17] = medium.sigma_s.to_bits();
    w[18] = medium.sigma_t.to_bits();
    w[19] = f32::to_bits(q0);
    w[20] = f32::to_bits(q1);
    w[21] = f32::to_bits(q2);
    w[22] = kind;
    w[23] = pk;
    w[24] = infinite as u32;
    let mut out = [0u8; RECORD_SIZE];
    for (i, x) in w.iter().enumerate() {
        out[i * 4..i * 4 + 4].copy_from_slice(&x.to_le_bytes());
    }
    out
}

/// Reads one result: `(in_scatter, status)`.
pub fn unpack_result(bytes: &[u8]) -> (f32, u32) {
    let v = f32::from_le_bytes(bytes[0..4].try_into().unwrap());
    let s = u32::from_le_bytes(bytes[4..8].try_into().unwrap());
    (v, s)
}
