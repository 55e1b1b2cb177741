//! From images to pictures: per-pixel relative errors, false-colour heat maps, tone mapping,
//! PNG files.

use super::world::SceneDesc;
use super::Image;
use std::path::Path;

/// Per-pixel relative error of `test` against `reference`: the largest over the channels of
/// `|test − ref| / max(ref, floor)`. Two equal infinities count as 0.
pub fn relative_errors(test: &Image, reference: &Image, floor: f64) -> Vec<f64> {
    test.pixels
        .iter()
        .zip(&reference.pixels)
        .map(|(a, b)| {
            (0..3)
                .map(|c| {
                    if a[c] == b[c] {
                        0.0
                    } else {
                        let e = (a[c] - b[c]).abs() / b[c].max(floor);
                        if e.is_nan() { f64::INFINITY } else { e }
                    }
                })
                .fold(0.0, f64::max)
        })
        .collect()
}

/// The error floor for a scene: `1e-4 / exposure`, i.e. a ten-thousandth of the radiance the
/// tone map shows at 63 % of white (1/40 of one 8-bit display step near black); smaller
/// absolute differences are invisible.
pub fn error_floor(scene: &SceneDesc) -> f64 {
    1e-4 / scene.exposure
}

/// Maximum and median of a list of errors.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ErrorStats {
    /// Largest error.
    pub max: f64,
    /// Median error.
    pub median: f64,
}

/// Max and median of `errors` (`NaN` counts as `+∞`).
pub fn error_stats(errors: &[f64]) -> ErrorStats {
    let mut v: Vec<f64> = errors.iter().map(|e| if e.is_nan() { f64::INFINITY } else { *e }).collect();
    v.sort_by(f64::total_cmp);
    let median = if v.is_empty() { 0.0 } else { v[v.len() / 2] };
    ErrorStats { max: v.last().copied().unwrap_or(0.0), median }
}

/// The heat map's scale: `log10` of the relative error from this …
pub const HEAT_LOG10_MIN: f64 = -7.0;
/// … to this (errors outside are clamped).
pub const HEAT_LOG10_MAX: f64 = -1.0;

/// False colour of a relative error on the log scale [`HEAT_LOG10_MIN`]..[`HEAT_LOG10_MAX`]:
/// black → blue → green → yellow → red (an error of exactly 0 is black).
pub fn heat_color(err: f64) -> [u8; 3] {
    let x = if err > 0.0 { ((err.log10() - HEAT_LOG10_MIN) / (HEAT_LOG10_MAX - HEAT_LOG10_MIN)).clamp(0.0, 1.0) } else { 0.0 };
    const STOPS: [[f64; 3]; 5] = [[0.0, 0.0, 0.0], [0.0, 0.2, 1.0], [0.0, 0.85, 0.2], [1.0, 0.95, 0.0], [1.0, 0.0, 0.0]];
    let s = x * 4.0;
    let i = (s.floor() as usize).min(3);
    let f = s - i as f64;
    let mut out = [0u8; 3];
    for c in 0..3 {
        out[c] = ((STOPS[i][c] * (1.0 - f) + STOPS[i + 1][c] * f) * 255.0).round() as u8;
    }
    out
}

/// 8-bit RGB of the error heat map (with a colour bar of the scale along the bottom 4 % of
/// rows, left = `10^HEAT_LOG10_MIN`, right = `10^HEAT_LOG10_MAX`).
pub fn heat_map(errors: &[f64], width: u32, height: u32) -> Vec<u8> {
    let bar = (height / 25).max(2).min(height);
    let mut out = Vec::with_capacity(width as usize * height as usize * 3);
    for y in 0..height {
        for x in 0..width {
            let rgb = if y >= height - bar {
                let l = HEAT_LOG10_MIN + (HEAT_LOG10_MAX - HEAT_LOG10_MIN) * (x as f64 + 0.5) / width as f64;
                heat_color(10f64.powf(l))
            } else {
                heat_color(errors[(y * width + x) as usize])
            };
            out.extend_from_slice(&rgb);
        }
    }
    out
}

fn srgb(v: f64) -> u8 {
    let v = v.clamp(0.0, 1.0);
    let e = if v <= 0.0031308 { 12.92 * v } else { 1.055 * v.powf(1.0 / 2.4) - 0.055 };
    (e * 255.0).round() as u8
}

/// 8-bit sRGB of an image: `1 − e^{−x·exposure}` per channel, then the sRGB curve.
pub fn tone_map(image: &Image, exposure: f64) -> Vec<u8> {
    image
        .pixels
        .iter()
        .flat_map(|p| p.map(|v| srgb(if v.is_nan() { 1.0 } else { 1.0 - (-v.max(0.0) * exposure).exp() })))
        .collect()
}

/// Writes 8-bit RGB data as a PNG file.
///
/// # Errors
/// The I/O or encoder error as text.
pub fn write_png(path: &Path, width: u32, height: u32, rgb: &[u8]) -> Result<(), String> {
    let file = std::fs::File::create(path).map_err(|e| format!("{}: {e}", path.display()))?;
    let mut enc = png::Encoder::new(std::io::BufWriter::new(file), width, height);
    enc.set_color(png::ColorType::Rgb);
    enc.set_depth(png::BitDepth::Eight);
    let mut w = enc.write_header().map_err(|e| format!("{}: {e}", path.display()))?;
    w.write_image_data(rgb).map_err(|e| format!("{}: {e}", path.display()))?;
    w.finish().map_err(|e| format!("{}: {e}", path.display()))
}
