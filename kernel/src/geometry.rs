//! World space → the canonical integral (paper §3.1–3.2, eq. 4–6; DESIGN §2).
//!
//! `x_h = (p − o)·d` is where the light's perpendicular meets the ray line, `h` the light's
//! distance from that line, `d_el = d·a` and `d_c = (o + x_h d − p)·a / h` the two direction
//! cosines that fix `c(u) = (d_el u + d_c)/√(1+u²)`.

use crate::real::Real;

/// `a · b`.
#[inline]
pub fn dot<T: Real>(a: [T; 3], b: [T; 3]) -> T {
    a[0] * b[0] + a[1] * b[1] + a[2] * b[2]
}

/// `a − b`.
#[inline]
pub fn sub<T: Real>(a: [T; 3], b: [T; 3]) -> [T; 3] {
    [a[0] - b[0], a[1] - b[1], a[2] - b[2]]
}

/// `|a|`, without overflow or underflow of the squares (scaled by the largest component).
#[inline]
pub fn length<T: Real>(a: [T; 3]) -> T {
    let m = a[0].abs().max(a[1].abs()).max(a[2].abs());
    if m == T::zero() || !m.is_finite() {
        return m;
    }
    let s = [a[0] / m, a[1] / m, a[2] / m];
    m * dot(s, s).sqrt()
}

/// `a / |a|` (zero stays zero). Scaled by the largest component first, so that tiny
/// (subnormal) or huge vectors normalise as accurately as ordinary ones.
#[inline]
pub fn normalize<T: Real>(a: [T; 3]) -> [T; 3] {
    let m = a[0].abs().max(a[1].abs()).max(a[2].abs());
    if !(m > T::zero() && m.is_finite()) {
        return a;
    }
    let s = [a[0] / m, a[1] / m, a[2] / m];
    let l = dot(s, s).sqrt();
    [s[0] / l, s[1] / l, s[2] / l]
}

/// The ray segment and light in the canonical frame of the light's foot.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Canonical<T> {
    /// Distance from the light to the ray line.
    pub h: T,
    /// Ray parameter of the light's foot.
    pub x_h: T,
    /// `d·a`: cosine between ray direction and light axis.
    pub d_el: T,
    /// `(o + x_h d − p)·a / h` (0 when `h = 0`).
    pub d_c: T,
    /// Segment start (distance along the normalised ray).
    pub t0: T,
    /// Segment end (`+∞` allowed).
    pub t1: T,
}

impl<T: Real> Canonical<T> {
    /// Reduces a world-space ray (`dir` any non-zero length) and light to canonical form.
    pub fn new(origin: [T; 3], dir: [T; 3], t0: T, t1: T, light: [T; 3], axis: [T; 3]) -> Self {
        let d = normalize(dir);
        let a = normalize(axis);
        let to_light = sub(light, origin);
        let x_h = dot(to_light, d);
        // o + x_h d − p = x_h d − (p − o)
        let perp = [x_h * d[0] - to_light[0], x_h * d[1] - to_light[1], x_h * d[2] - to_light[2]];
        // Only an exact h = 0 puts the light on the line: a light within rounding distance of
        // it gets the (huge, finite) value of the h that rounding produced, which is of the
        // right order, rather than +∞.
        let h = length(perp);
        let d_c = if h > T::zero() { dot(perp, a) / h } else { T::zero() };
        Canonical { h, x_h, d_el: dot(d, a), d_c, t0, t1 }
    }

    /// `u = (t − x_h)/h` of a segment end.
    #[inline]
    pub fn u(&self, t: T) -> T {
        (t - self.x_h) / self.h
    }
}
