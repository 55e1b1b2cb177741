//! Surface radiance from air-light: the light the medium scatters onto a surface point from
//! every direction of its hemisphere (Sun et al. 2005; Hong 2006, §4.2.2; docs/DESIGN.md §11),
//! as the crate's own ray integral integrated over the hemisphere.
//!
//! At a surface point `s` with unit normal `n`,
//! `L_{p,a} = ∫_{n·ω>0} L_a(s, ω) f_r(ω) (n·ω) dω`, where `L_a(s, ω)` is the in-scattered
//! radiance along the ray from `s` in direction `ω`, `t ∈ [0, ∞)` ([`Scene::in_scatter`]) and
//! `f_r` the BRDF ([`Brdf`]). Directions are written about the light's direction `ℓ` from
//! `s`: `ω = cos γ ℓ + sin γ (cos φ e₁ + sin φ e₂)`, `dω = sin γ dγ dφ`. Then
//! * `L_a` grows like `1/sin γ` towards the light (the ray passes the light at `h = d sin γ`),
//!   which `sin γ` cancels: the integrand is bounded;
//! * for a light without an axis (omni) `L_a` depends on `γ` alone, and the inner integral is
//!   `L_a(γ)` times the BRDF's `∫ f_r (n·ω)⁺ dφ` (for Lambert in closed form:
//!   `∫_{−ψ}^{ψ} (A + B cos x) dx = 2(Aψ + B sin ψ)`);
//! * for a light whose distribution is one polynomial of degree `p` in the cosine (`c^p`),
//!   `L_a` at `γ` is a polynomial of degree `p` in `cos(φ − φ_a)` (`φ_a` the axis's azimuth):
//!   `p + 1` rays give it exactly ([`MAX_INTERPOLATED_DEGREE`], `lobatto_coefficients`), and the
//!   inner integral needs no more; for a Lambertian point that integral is a weighted sum of
//!   the rays, which share their panel in the light angle, and on the default path it is taken
//!   as one ray integral of the weighted sum of their distributions where that route meets the
//!   rays' tolerance (`SurfaceScene::arc_sum`); other lights with an axis take a ray at every
//!   inner node;
//! * `(n·ω)⁺ = (A + B cos(φ − φ_n))⁺` with `A = cos γ (n·ℓ)`, `B = sin γ |n − (n·ℓ)ℓ|`: the arc
//!   of the hemisphere at `γ` is `|φ − φ_n| < ψ = arccos(−A/B)`; it is the whole circle below
//!   `γ = |π/2 − α_n|` (or empty) and changes kind again at `π − |π/2 − α_n|`, `α_n` the
//!   angle between `n` and `ℓ`: the outer integral is split there. A Phong lobe `(r·ω)⁺ⁿ` adds
//!   its own arc, its peak `γ = α_r` and its arc's turning points.
//!
//! Both integrals are globally adaptive Gauss–Kronrod (QUADPACK's QAG, as
//! [`crate::extended`]), the inner to a tenth of the outer tolerance, each ray integral
//! ([`Scene::in_scatter_controlled`]) to a tenth as well, with a bounded number of panels; at
//! loose tolerances a light without an axis in a thin medium may give `L_a(γ)` from an
//! interpolant of the logarithm of a few rays instead (`RayInterpolant`), and a narrow Phong
//! lobe over it is then integrated about its own axis (`SurfaceScene::mirror_cone`). In
//! isotropic fog such a light's ray from the point has its light-angle integral in closed form
//! (`open_ray_isotropic`, complex `E1` at an argument of known angle): a Lambertian point takes
//! it at every outer node, with neither ray integrals nor an interpolant.

use core::cell::{Cell, RefCell};

use crate::error::{check_finite, check_non_negative, check_vector, ErrorKind, InputError};
use crate::extended::{adaptive, edges_between, inner_control, outer_rule, outer_tolerance, working_tolerance};
use crate::expansion::chebyshev_series;
use crate::geometry::{basis, cross, dot, length, normalize, sub};
use crate::light::{whole_polynomial_degree, LightDistribution};
use crate::phase::PhaseFunction;
use crate::real::{exp_nonpositive_polynomial, ln_1p, sin_cos_half_turn, sin_cos_quarter, sin_cos_turns, Real};
use crate::special::{e1_scaled_cf, ein_at_most, in_series_region, C, EIN_COEFFS, EULER_GAMMA};
use crate::scalar::Scalar;
use crate::panels::Control;
use crate::combined::Physics;
use crate::geometry::Canonical;
use crate::scene::{default_panels, panels_with_nodes, validate, Medium, PointLight, Ray};
#[cfg(doc)]
use crate::scene::Scene;

/// The surface's reflectance.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Brdf<T: Real> {
    /// Lambertian: `f_r = albedo/π`.
    Lambert {
        /// Albedo `ρ ≥ 0`.
        albedo: T,
    },
    /// A normalised Phong lobe about the mirror direction:
    /// `f_r(ω) = k_s (n + 2)/(2π) · max(0, r·ω)ⁿ`, `r` the mirror image of `view` about the
    /// normal.
    Phong {
        /// Specular coefficient `k_s ≥ 0`.
        k_s: T,
        /// Exponent `n ≥ 0`.
        exponent: T,
        /// From the surface towards the eye (any non-zero length).
        view: T::Vec3,
    },
}

/// A surface point and its normal.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Surface<T: Real> {
    /// The point `s`.
    pub position: T::Vec3,
    /// Its normal (any non-zero length; the lit side is the one it points to).
    pub normal: T::Vec3,
}

/// A Lambertian point's air-light *without extinction*, in closed form: `L = ρ σs I (E(sin²α) +
/// cos α)/(2π d)`, `d` the light's distance from the point, `α` its angle from the normal and
/// `E` the complete elliptic integral of the second kind ([`crate::special::elliptic_e`];
/// docs/DESIGN.md §11 derives it). It equals [`SurfaceScene::air_light`] where `σt = 0`, the
/// phase function is isotropic and the light has no axis (tests/surface.rs
/// `non_absorbing_isotropic_closed_forms`: within 3e-15 of the default path at 25 normals). In a
/// medium it leaves out the extinction and so bounds that air-light from above, by a margin that
/// grows like `σt d ln(1/(σt d))`: on the `lambert_thin` points of tests/reference/surface.jsonl
/// 1.8 % high at `σt·d = 0.0034`, 5.0–6.4 % at 0.015–0.019, 23 % at 0.059 and 48 % at 0.15, and
/// 24 to 3e8 times the value on the `lambert_thick` ones (`σt·d` 2 to 17;
/// `vacuum_form_bounds_the_medium_from_above`, tests/surface.rs, prints them). The surface's
/// analogue of [`crate::atan_form`]: no ray integral. No input checks; a light at the point gives
/// `+∞` or NaN.
pub fn lambert_vacuum_form<T: Real>(surface: &Surface<T>, light_position: T::Vec3, intensity: T, albedo: T, sigma_s: T) -> T {
    let p = T::vec3_to_array(surface.position);
    let l = T::vec3_to_array(light_position);
    let n = T::vec3_to_array(surface.normal);
    let to_light = sub(l, p);
    let d = length(to_light);
    let cos_a = (dot(n, to_light) / (length(n) * d)).max(-T::one()).min(T::one());
    let e = crate::special::elliptic_e((T::one() - cos_a) * (T::one() + cos_a), cos_a.abs());
    albedo * sigma_s * intensity * (e + cos_a) / (T::lit(2.0) * T::PI() * d)
}

/// The most Gauss–Kronrod panels of each of the two integrals over the hemisphere.
pub const MAX_SURFACE_PANELS: usize = 48;

/// The most Gauss–Kronrod panels of the outer integral of a surface point in the shaders
/// ([`SurfaceScene::air_light_panels_counted`]; `7·(2·6 − 1) = 77` rays at most): within
/// 5.7e-6 of the references of the 30 Lambertian records lit by omni lights in
/// tests/reference/surface.jsonl in f32 (4 panels: 4.8e-3; 8 or 12: no change).
pub const SHADER_SURFACE_PANELS: usize = 6;

/// The most Gauss–Kronrod panels of the outer integral of a Phong surface point in the shaders
/// (at most `7·(2·16 − 1) = 217` rays; up to 12 panels come from the cuts alone): the f32 mirror
/// at 8 nodes is within 5.5e-6 of the 6 Phong records of tests/reference/surface.jsonl and within
/// 1.2e-5 of the f64 default on 200 random Phong points (12 panels: 4.9e-5 and 3.0e-3); the
/// shaders' own figures are tests/gpu_agreement.rs `surfaces_agree_with_the_cpu_kernel`.
pub const SHADER_PHONG_PANELS: usize = 16;

/// The Gauss–Legendre rule of [`lobe_arcs`], the shaders' inner integral of a Phong lobe
/// lit by a light without an axis: 10 points per piece (`GL10`, its nodes `x > 0`). Against
/// adaptive quadrature to 1e-13 over 40 random frames × 25 angles `γ` per exponent (0…1000), the
/// largest error is 1.0e-5 of the lobe's integral at its peak, at n = 50 (the test below; in a
/// first trial, 8 points left 1.3e-4 there).
pub const LOBE_RULE: &[(f64, f64)] = &crate::expansion::gauss_table::GL10;

/// Where [`lobe_arcs`] ends a Phong lobe `(C + D cos x)ⁿ`: at `1e-9` of its peak `(C + D)ⁿ`;
/// what lies beyond adds less than `2π·1e-9` of the peak, far below the shaders' target of 1e-4.
pub const LOBE_FLOOR: f64 = 1e-9;

/// The loosest outer tolerances at which [`SurfaceScene::air_light_counted`] takes a Phong lobe
/// lit by a light without an axis by [`lobe_arcs`] instead of adaptive quadrature: from `2e-4`
/// the inner integrals' tolerance (a tenth of the outer) is at least the `2e-5` of the lobe's
/// peak integral that `lobe_arcs` is held to (its test below; 1.0e-5 measured).
pub const FIXED_LOBE_TOLERANCE: f64 = 2e-4;

/// The rules of [`lobe_arcs`] by outer tolerance, `(from, rule)`: the first whose `from` the
/// outer tolerance is at least. Each is held to a tenth of its `from` of the lobe's peak
/// integral (the inner integrals' tolerance; the test below): Gauss–Legendre 8 from `2e-3`
/// (1.3e-4 measured), [`LOBE_RULE`]'s 10 from [`FIXED_LOBE_TOLERANCE`] (1.0e-5). Six points
/// (3.8e-3) would serve from `5e-2`, but left 1.2e-3 on the references at 1e-1, above the
/// 1e-3 level BENCHMARKS.md picks a tolerance for, where 8 points leave 3.9e-5.
pub const LOBE_RULES: [(f64, &[(f64, f64)]); 2] = [(2e-3, &crate::expansion::gauss_table::GL8), (FIXED_LOBE_TOLERANCE, LOBE_RULE)];

/// The largest degree `p` of a light's distribution (a polynomial in the cosine `c` without
/// kinks, as [`crate::light::TwoLobed`]) for which the hemisphere's inner integral over `φ`
/// takes `L_a` from `p + 1` rays: `L_a` at `γ` is then a polynomial of degree `p` in
/// `cos(φ − φ_a)` (`lobatto_coefficients`), known exactly from its values at the `p + 1`
/// Chebyshev–Lobatto points. Above it, adaptive quadrature in `φ` evaluates a ray at every node.
pub const MAX_INTERPOLATED_DEGREE: usize = 32;

/// The Chebyshev–Lobatto points `x_j = cos(jπ/p)`, `j = 0 … p` (`p ≤ MAX_INTERPOLATED_DEGREE`).
pub(crate) fn lobatto_points<T: Real>(p: usize) -> [T; MAX_INTERPOLATED_DEGREE + 1] {
    let mut points = [T::zero(); MAX_INTERPOLATED_DEGREE + 1];
    for (j, x) in points.iter_mut().enumerate().take(p + 1) {
        *x = (T::PI() * T::from(j).unwrap_or(T::zero()) / T::from(p.max(1)).unwrap_or(T::one())).cos();
    }
    points
}

/// The Chebyshev coefficients `b_k` of the polynomial `P` of degree `p = values.len() − 1` through
/// `values[j]` at the Chebyshev–Lobatto points `x_j = cos(jπ/p)` (`points`, [`lobatto_points`]):
/// `P(x) = Σ_k b_k T_k(x)` with `b_k = (ε_k/p) Σ_j ε_j L_j cos(jkπ/p)`, `ε` 1 inside and 1/2 at
/// `0` and `p` on both sums (the discrete cosine transform of the points, DCT-I; Trefethen,
/// Approximation Theory and Approximation Practice, ch. 3 and 19), each `b_k` as the series
/// `Σ_j ε_j L_j T_j` at `x_k` by [`chebyshev_sum`]: `O(p²)` once, where the
/// inner integral then evaluates `P` at every node in `O(p)` ([`chebyshev_sum`]) instead of the
/// barycentric formula's `p + 1` divisions. Writes `out[..=p]`, `p ≤ MAX_INTERPOLATED_DEGREE`.
pub(crate) fn lobatto_coefficients<T: Real>(values: &[T], points: &[T], out: &mut [T]) {
    let p = values.len().saturating_sub(1);
    if p == 0 {
        out[0] = values.first().copied().unwrap_or(T::zero());
        return;
    }
    let half = |i: usize| if i == 0 || i == p { T::lit(0.5) } else { T::one() };
    let scale = T::from(p).unwrap_or(T::one()).recip();
    // Σ_j ε_j L_j cos(jkπ/p) = Σ_j ε_j L_j T_j(x_k) at the point x_k: Clenshaw's sum, in f64
    // (in f32 its rounding near x = ±1, up to (p + 1)² ulp of Σ|L_j|, took a c^16 Phong point's
    // default error from 1.9e-7 to 1.8e-6)
    let mut weighted = [0.0f64; MAX_INTERPOLATED_DEGREE + 1];
    for (j, (w, &l)) in weighted.iter_mut().zip(values).enumerate() {
        *w = (half(j) * l).to_f64_exact();
    }
    for (k, b) in out.iter_mut().enumerate().take(p + 1) {
        *b = half(k) * scale * T::lit(2.0 * chebyshev_sum(&weighted[..=p], points[k].to_f64_exact()));
    }
}

/// `Σ_k b_k T_k(x)` by Clenshaw's recurrence, `x ∈ [−1, 1]`.
pub(crate) fn chebyshev_sum<T: Real>(b: &[T], x: T) -> T {
    let Some((&first, rest)) = b.split_first() else {
        return T::zero();
    };
    let (mut b1, mut b2, two_x) = (T::zero(), T::zero(), x + x);
    for &c in rest.iter().rev() {
        let b0 = c + two_x * b1 - b2;
        b2 = b1;
        b1 = b0;
    }
    first + x * b1 - b2
}

/// The weights `c_j` of a Lambertian arc's inner integral from the values `L_j` of a polynomial
/// of degree `p` in `cos(φ − φ_a)` at the Chebyshev–Lobatto points `φ_j = φ_a + jπ/p`:
/// `∫_{−ψ}^{ψ} (A + B cos x) P(cos(x + δ)) dx = Σ_j c_j L_j` (`x = φ − φ_n`, `δ = φ_n − φ_a`),
/// in closed form. With `P(cos θ) = Σ''_k b_k cos kθ`, `b_k = (2/p) Σ''_j L_j cos(jkπ/p)` (the
/// discrete cosine transform of the points; `''` halves the first and last terms), the odd part
/// of `cos(k(x + δ))` integrates to 0 and `∫ (A + B cos x) cos kx dx = A S_k + (B/2)(S_{k−1} +
/// S_{k+1})`, `S_m = 2 sin(mψ)/m` (`S_0 = 2ψ`), so `c_j = (2/p) ε_j Σ_k ε_k cos(jkπ/p) cos(kδ)
/// (A S_k + (B/2)(S_{|k−1|} + S_{k+1}))`, each `c_j` as the series `Σ_k g_k T_k` at the point
/// `x_j` ([`lobatto_points`]) by [`chebyshev_sum`]. Writes `out[..=p]`, `p ≤ MAX_INTERPOLATED_DEGREE`.
pub(crate) fn lambert_chebyshev_weights<T: Real>(p: usize, a: T, b: T, psi: T, delta: T, points: &[T], out: &mut [T]) {
    // S_m for m = 0 … p + 1, each once
    let mut s = [T::zero(); MAX_INTERPOLATED_DEGREE + 2];
    for (m, sm) in s.iter_mut().enumerate().take(p + 2) {
        *sm = if m == 0 { psi + psi } else { let m = T::from(m).unwrap_or(T::one()); T::lit(2.0) * (m * psi).sin() / m };
    }
    let w = |k: usize| a * s[k] + b * T::lit(0.5) * (s[k.abs_diff(1)] + s[k + 1]);
    if p == 0 {
        out[0] = w(0);
        return;
    }
    let pf = T::from(p).unwrap_or(T::one());
    let half = |i: usize| if i == 0 || i == p { T::lit(0.5) } else { T::one() };
    // ε_k cos(kδ) W_k, the same for every j
    let mut g = [T::zero(); MAX_INTERPOLATED_DEGREE + 1];
    for (k, gk) in g.iter_mut().enumerate().take(p + 1) {
        *gk = half(k) * (T::from(k).unwrap_or(T::zero()) * delta).cos() * w(k);
    }
    // Σ_k g_k cos(jkπ/p) = Σ_k g_k T_k(x_j) at the point x_j = cos(jπ/p): Clenshaw's sum, in
    // f64 (as `lobatto_coefficients`)
    let g = g.map(|x| x.to_f64_exact());
    for (j, c) in out.iter_mut().enumerate().take(p + 1) {
        *c = T::lit(2.0) / pf * half(j) * T::lit(chebyshev_sum(&g[..=p], points[j].to_f64_exact()));
    }
}

/// A validated surface point lit by air-light of a point light.
#[derive(Clone, Copy, Debug)]
pub struct SurfaceScene<T: Real, D, P> {
    surface: Surface<T>,
    brdf: Brdf<T>,
    light: PointLight<T, D>,
    medium: Medium<T>,
    phase: P,
}

/// The frame about the light's direction and the cosines the hemisphere's arcs need.
struct Frame<T> {
    /// Distance to the light and its direction `ℓ`, with `e₁, e₂ ⊥ ℓ`.
    d: T,
    l: [T; 3],
    e1: [T; 3],
    e2: [T; 3],
    /// The normal's and the mirror direction's `(cos α, sin α, φ)` about `ℓ`.
    n: (T, T, T),
    r: (T, T, T),
    /// The unit normal and the mirror direction (Phong).
    n_dir: [T; 3],
    r_dir: [T; 3],
}

/// `(cos α, sin α, φ)` of a unit vector `v` in the frame `(ℓ, e₁, e₂)`; `φ` only where
/// `azimuth` (else 0: a Lambertian point lit by a light without an axis needs none).
fn polar<T: Real>(v: [T; 3], l: [T; 3], e1: [T; 3], e2: [T; 3], azimuth: bool) -> (T, T, T) {
    let (c, x, y) = (dot(v, l), dot(v, e1), dot(v, e2));
    // (x, y ≤ 1: no scaling needed)
    (c, (x * x + y * y).sqrt(), if azimuth { y.atan2(x) } else { T::zero() })
}

/// `∫ (A + B cos(x − Δ))⁺ (C + D cos x)⁺ⁿ dx` over the circle (`x = φ − φ_r`; `A, B` the
/// normal's `cos α cos γ, sin α sin γ`, `C, D` the mirror direction's, `Δ = φ_n − φ_r` with its
/// cosine and sine, `ψ_n` the normal's half-arc), by a fixed rule. With `s = sin(x/2)` the lobe
/// is `(C + D)(1 − k s²)`, `k = 2D/(C + D)`, `C + D = cos(γ − α_r)`, so its `n`-th power is
/// `exp(n (ln cos(γ − α_r) + ln(1 − k s²)))` from two `ln(1 + x)` without cancellation (Vulkan
/// allows `log` an absolute error of 2⁻²¹ near 1, which `n = 200` would make 7e-5; the shaders'
/// form), or for a whole `n ≤ 2¹⁶` the peak's power once and `(1 − k s²)ⁿ` by repeated squaring
/// in f64 (docs/DESIGN.md §11: no logarithm or exponential a node). The lobe is
/// ended at [`LOBE_FLOOR`] of its peak (`s² = (1 − floor^{1/n})/k`; all of it where that passes
/// 1). The lobe is even in `x`: the rule runs over `[0, cut]`, each node serving `x` and `−x`
/// (one sine, exponential and logarithm for two, docs/DESIGN.md §11), cut at the normal's arc
/// ends' distances from the peak, and `rule` (the shaders' [`LOBE_RULE`], or one of
/// [`LOBE_RULES`]) is taken on every piece where the integrand lives — in `x` itself or, for
/// `n < 1`, where `(ψ_r − x)ⁿ` ends a piece with a kink of infinite slope, in the smoothstep of
/// the piece (as the outer integral takes `γ`). `gap = γ − α_r`; the lobe is empty unless
/// `|gap| < π/2`. The exponential by `exp_nonpositive_polynomial` in both precisions: within
/// 2e-8 relative, where the rules are held to 1e-5 of the lobe's peak integral.
pub fn lobe_arcs<T: Real>(rule: &[(f64, f64)], normal: (T, T), mirror: (T, T), gap: T, (delta, cos_delta, sin_delta): (T, T, T), psi_n: T, exponent: T) -> T {
    let ((a, b), (c, d)) = (normal, mirror);
    let (pi, half, two) = (T::PI(), T::lit(0.5), T::lit(2.0));
    let peak = c + d;
    if !(peak > T::zero()) {
        return T::zero();
    }
    let k = two * d / peak;
    let sin_gap = (gap * half).sin();
    let log_peak = ln_1p(-two * sin_gap * sin_gap);
    // where the lobe ends: s² = (1 − floor^{1/n})/k (n = 0: 1/k, its arc), at most 1
    let reach = if exponent > T::zero() { -(T::lit(LOBE_FLOOR).ln() / exponent).exp_m1() } else { T::one() };
    let s2 = if reach < k { reach / k } else { T::one() };
    let cut = two * s2.sqrt().asin();
    // the half-range's edges: the peak, `cut`, the normal's arc ends' distances from the peak
    // (so neither x nor −x has a kink inside a piece)
    let mut edges = [T::zero(), cut, T::zero(), T::zero()];
    let mut count = 2;
    if psi_n < pi {
        for end in [delta - psi_n, delta + psi_n] {
            let y = if end > pi { end - pi - pi } else if end < -pi { end + pi + pi } else { end };
            if y.abs() < cut {
                edges[count] = y.abs();
                count += 1;
            }
        }
    }
    let used = &mut edges[..count];
    used.sort_unstable_by(|x, y| x.partial_cmp(y).unwrap_or(core::cmp::Ordering::Equal));
    // a whole exponent (every Phong exponent of tests/reference/surface.jsonl): `(1 − k s²)ⁿ`
    // by repeated squaring in f64 and the peak's `(C + D)ⁿ` once, no logarithm or exponential
    // a node; in f64 the products' rounding is at most `2n` f64 ulp (`n ≤ 2¹⁶`: 1.5e-11), and
    // `1 − k s²` is formed as exactly as `ln(1 − k s²)` was
    let whole = whole_exponent(exponent);
    let peak_power = exp_nonpositive_polynomial(exponent * log_peak);
    // the normal's clip of x and −x together and the lobe's fall `k s²` at x
    let clip_fall = |x: T| {
        // |x/2| ≤ π/2: the minimax pair, odd and even in x
        let (s, h) = sin_cos_quarter(x * half);
        let (cos_x, sin_x) = (T::one() - two * s * s, two * s * h);
        let (even, odd) = (a + b * cos_x * cos_delta, b * sin_x * sin_delta);
        ((even + odd).max(T::zero()) + (even - odd).max(T::zero()), k * s * s)
    };
    let smooth = exponent < T::one();
    let mut sum = T::zero();
    for piece in used.windows(2) {
        let (lo, hi) = (piece[0], piece[1]);
        // a piece where the lobe or the clip is empty at the middle is empty throughout
        let (clip, fall) = clip_fall((lo + hi) * half);
        if !(hi > lo) || !(clip > T::zero() && fall < T::one()) {
            continue;
        }
        let w = hi - lo;
        for &(x, weight) in rule {
            for u in [half - half * T::lit(x), half + half * T::lit(x)] {
                let (at, jacobian) = if smooth { (lo + w * u * u * (T::lit(3.0) - u - u), w * T::lit(6.0) * u * (T::one() - u)) } else { (lo + w * u, w) };
                let (clip, fall) = clip_fall(at);
                if fall < T::one() && clip > T::zero() {
                    let power = match whole {
                        Some(n) => peak_power * T::lit(Scalar::powi(1.0 - fall.to_f64_exact(), n)),
                        None => exp_nonpositive_polynomial(exponent * (log_peak + ln_1p(-fall))),
                    };
                    sum = sum + T::lit(weight) * half * jacobian * clip * power;
                }
            }
        }
    }
    sum
}

/// A Phong exponent that is a whole number `n ≤ 2¹⁶` (every one of tests/reference/surface.jsonl),
/// whose powers are taken by repeated squaring in f64 ([`lobe_power`], [`lobe_arcs`]).
fn whole_exponent<T: Real>(exponent: T) -> Option<i32> {
    if exponent >= T::zero() && exponent <= T::lit(65536.0) && exponent.floor() == exponent {
        exponent.to_i32()
    } else {
        None
    }
}

/// `cⁿ` for `c > 0`: for a whole `n` ([`whole_exponent`]) by repeated squaring in f64 (at most
/// `2n` f64 ulp, then one rounding to `T`), where the library's `powf` took a logarithm and an
/// exponential of extended precision at every node of a numerical inner integral.
fn lobe_power<T: Real>(c: T, exponent: T) -> T {
    match whole_exponent(exponent) {
        Some(n) => T::lit(Scalar::powi(c.to_f64_exact(), n)),
        None => c.powf(exponent),
    }
}

/// The angle from a Phong lobe's axis at which `cosⁿθ` falls to `floor` of its peak:
/// `arccos(floor^{1/n})` (`π/2` for `n = 0`).
fn lobe_cone<T: Real>(floor: T, exponent: T) -> T {
    (floor.ln() / exponent).exp().acos()
}

/// The arc `|φ − φ_c| < ψ` where `A + B cos(φ − φ_c) > 0` (`A = cos α cos γ`, `B = sin α sin γ`),
/// as `ψ ∈ [0, π]`, and `sin ψ` (`√((1 − x)(1 + x))`, `x = −A/B`, without the sine of the arc
/// cosine; 0 where the arc is the whole circle or empty).
fn half_arc_and_sine<T: Real>(a: T, b: T) -> (T, T) {
    if b <= a.abs() {
        return (if a > T::zero() { T::PI() } else { T::zero() }, T::zero());
    }
    let x = (-a / b).max(-T::one()).min(T::one());
    (x.acos(), ((T::one() - x) * (T::one() + x)).sqrt())
}

/// A Lambertian point's outer integrand at `γ` over the rays' interpolant, without `2ρ/π`:
/// `∫ (A + B cos x)⁺ dx / 2 · L_a sin γ = (Aψ + B sin ψ) · L_a sin γ` (`A = cos α_n cos γ`, `B =
/// sin α_n sin γ`, [`half_arc_and_sine`]; `L_a sin γ` by [`RayPieces::light_sin`];
/// docs/DESIGN.md §11), with `sin γ = 2 sin(γ/2) cos(γ/2)` and `cos γ =
/// (cos(γ/2) − sin(γ/2))(cos(γ/2) + sin(γ/2))` from one [`sin_cos_quarter`] of `γ/2 ∈ [0, π/2]`:
/// no square root or division for the half angle, and `cos γ` within a few ε absolutely, as
/// [`sin_cos_half_turn`]'s.
fn lambert_node<T: Real>((cos_n, sin_n, _): (T, T, T), g: T, light_sin: impl FnOnce(T, T, T) -> T) -> T {
    let (s, c) = sin_cos_quarter(g * T::lit(0.5));
    let (sin_g, cos_g) = ((s + s) * c, (c - s) * (c + s));
    let (a, b) = (cos_n * cos_g, sin_n * sin_g);
    let (psi, sin_psi) = half_arc_and_sine(a, b);
    if !(psi > T::zero()) {
        return T::zero();
    }
    (a * psi + b * sin_psi) * light_sin(s, c, cos_g)
}

/// `K(γ) = ∫ e^{−σt(t + r − d)} dθ` over the open ray from a point at distance `d` from an omni
/// light, at angle `γ` from the light's direction (`θ` the angle seen from the light, from
/// `γ − π/2` to `π/2`; `L_a sin γ = σs I P e^{−σt·d} K(γ)/d` with an isotropic `P`; `π − γ`
/// without extinction): with `Y = tan(θ/2 + π/4)` the exponent is `−σt·d sin γ (Y − tan(γ/2))`
/// and `dθ = 2 dY/(1 + Y²)` (docs/DESIGN.md §4.3), so `K = 2 Im[e^w E1(w)]`, `w = σt·d (1 −
/// e^{iγ}) = 2σt·d sin(γ/2)(sin(γ/2) − i cos(γ/2))` — the ray's exponential integral with its
/// argument's angle `γ/2 − π/2` known, no arc tangent. In `E1`'s series region
/// ([`in_series_region`]) by `E1 = −γ_E − ln w + Ein(w)` (A&S 5.1.11):
/// `K/2 = e^{Re w}[sin(Im w)(Re Ein − γ_E − ln|w|) + cos(Im w)(Im Ein + (π − γ)/2)]`, each term
/// within a few ε of `|w|` or of the arc (towards `γ = π`, where `K ∝ π − γ`, that is more of
/// `K`: `tests::open_ray_against_quadrature`); outside it by the continued fraction
/// ([`e1_scaled_cf`]). Given `σt·d`, `γ` and `γ/2`'s sine and cosine, and `cos γ`
/// (`e^{Re w − σt·d} = e^{−σt·d cos γ}` is returned folded in: the value is `e^{−σt·d} K`), and
/// `Ein`'s term count ([`open_ray_terms`]).
#[inline(always)]
fn open_ray_isotropic<T: Real>(depth: T, g: T, (s, c, cos_g): (T, T, T), terms: usize) -> T {
    // (π − γ)/2 with π in two parts: the rounded π is ε·π off, which near γ = π would be
    // ε·π/(π − γ) of the arc (π − fl64(π) = sin(fl64(π)) = 1.2246467991473532e-16)
    let pi_low = T::lit(core::f64::consts::PI - T::PI().to_f64_exact() + 1.2246467991473532e-16);
    let arc = ((T::PI() - g) + pi_low) * T::lit(0.5);
    let w = C::new(T::lit(2.0) * depth * s * s, -(T::lit(2.0) * depth * s * c));
    if !(w.im < T::zero()) {
        // no extinction, or along the light's direction or away from it: the vacuum's angle
        return (arc + arc) * (-depth).exp();
    }
    if !in_series_region(w) {
        return T::lit(2.0) * (-depth).exp() * e1_scaled_cf(w).im;
    }
    let ein = ein_at_most(w, terms);
    let (sin_im, cos_im) = if -w.im <= T::FRAC_PI_4() { sin_cos_quarter(-w.im) } else { sin_cos_turns(-w.im) };
    let log_w = (T::lit(2.0) * depth * s).ln();
    let half = cos_im * (ein.im + arc) - sin_im * (ein.re - T::lit(EULER_GAMMA) - log_w);
    T::lit(2.0) * (-(depth * cos_g)).exp() * half
}

/// The terms of `Ein(w)` that [`open_ray_isotropic`] takes at `|w| ≤ 2σt·d` (its series region):
/// the fewest whose tail, `Σ_{k>n} |w|^k/(k·k!) ≤ r^{n+1}/((n+1)(n+1)!)/(1 − r/(n+2))` at
/// `r = 2σt·d` (each term at most `r/(k+1)` of the one before), is within a thousandth of
/// `tolerance`, for `r < 1` (from `r = 1` on all 40 of [`EIN_COEFFS`]; at each `w` no more
/// than `E1`'s own series takes there, [`Real::E1_SERIES_BANDS`], for the precision's last
/// bits). The tail moves `K` by at most `√2 e^{Re w}` times it, and `K` is about `π − γ`, whose
/// integral against the Lambertian arcs is at least half theirs (the vacuum's closed form,
/// docs/DESIGN.md §11): with `σt·d < 1/2` that stays within a hundredth of the tolerance. (At
/// outer tolerance 1e-1, 4 terms where `σt·d ≤ 0.15`, where f64's series takes 9–13.)
fn open_ray_terms<T: Real>(depth: T, tolerance: T) -> usize {
    let r = (T::lit(2.0) * depth).to_f64_exact();
    let most = EIN_COEFFS.len();
    if !(r < 1.0) {
        return most;
    }
    let target = tolerance.to_f64_exact() * 1e-3;
    let mut power = r;
    for n in 1..most {
        // r^{n+1}/((n+1)(n+1)!) = |c_{n+1}| r^{n+1}
        power *= r;
        let next = EIN_COEFFS[n].abs() * power;
        if r < n as f64 + 2.0 && next / (1.0 - r / (n as f64 + 2.0)) <= target {
            return n;
        }
    }
    most
}

/// `f(γ)·dγ/dx` at the outer variable `x`, `(γ, dγ/dx)` by `piece` (0 where the map's
/// Jacobian vanishes, at a smoothstep piece's ends).
#[inline(always)]
fn weighted_at<T: Real>(piece: &impl Fn(T) -> (T, T), f: impl FnOnce(T) -> T, x: T) -> T {
    let (g, jacobian) = piece(x);
    if jacobian > T::zero() {
        f(g) * jacobian
    } else {
        T::zero()
    }
}

/// `(sin(γ/2), cos(γ/2))` for `γ ∈ [0, π]` from `γ`'s sine and cosine, each as a square root
/// of `(1 ∓ cos γ)/2` where that is at least `1/2` and the other from `sin γ = 2 sin(γ/2)
/// cos(γ/2)`: no cancellation at either end.
fn half_angle<T: Real>(sin_g: T, cos_g: T) -> (T, T) {
    if cos_g >= T::zero() {
        let c = ((T::one() + cos_g) * T::lit(0.5)).sqrt();
        (sin_g / (c + c), c)
    } else {
        let s = ((T::one() - cos_g) * T::lit(0.5)).sqrt();
        (s, sin_g / (s + s))
    }
}

/// The canonical `(d_el, d_c)` (docs/DESIGN.md §2) of the hemisphere ray at `γ` (cosine and
/// sine given) whose direction `u ⊥ ℓ` has `u·a = axis_u`, `ℓ·a = axis_l` (`a` the light's
/// axis): `d_el = cos γ (ℓ·a) + sin γ (u·a)`, `d_c = cos γ (u·a) − sin γ (ℓ·a)` (docs/DESIGN.md
/// §11).
fn axis_cosines<T: Real>(cos_g: T, sin_g: T, axis_l: T, axis_u: T) -> (T, T) {
    (cos_g * axis_l + sin_g * axis_u, cos_g * axis_u - sin_g * axis_l)
}

/// [`half_arc_and_sine`]'s `ψ` alone, for the arc of `(cos α, sin α, ·)` at `γ`.
fn half_arc<T: Real>((cos_a, sin_a, _): (T, T, T), cos_g: T, sin_g: T) -> T {
    half_arc_and_sine(cos_a * cos_g, sin_a * sin_g).0
}

impl<T, D, P> SurfaceScene<T, D, P>
where
    T: Real,
    D: LightDistribution<T> + Clone,
    P: PhaseFunction<T> + Clone,
{
    /// Validates and builds a scene.
    ///
    /// # Errors
    /// [`InputError`] naming the first invalid field: `surface.position`, `surface.normal` (also
    /// zero), `brdf.albedo`, `brdf.k_s`, `brdf.exponent` (negative or non-finite), `brdf.view`
    /// (also zero), then the light, medium and phase function as [`Scene::new`] names them.
    pub fn new(surface: Surface<T>, brdf: Brdf<T>, light: PointLight<T, D>, medium: Medium<T>, phase: P) -> Result<Self, InputError> {
        check_vector(T::vec3_to_array(surface.position), "surface.position", false)?;
        check_vector(T::vec3_to_array(surface.normal), "surface.normal", true)?;
        match brdf {
            Brdf::Lambert { albedo } => check_non_negative(albedo, "brdf.albedo")?,
            Brdf::Phong { k_s, exponent, view } => {
                check_non_negative(k_s, "brdf.k_s")?;
                check_non_negative(exponent, "brdf.exponent")?;
                check_vector(T::vec3_to_array(view), "brdf.view", true)?;
            }
        }
        // the rays start at the surface point: their fields are valid by the checks above
        let ray = Ray { origin: surface.position, dir: surface.normal, t_min: T::zero(), t_max: T::infinity() };
        validate(&ray, &light, &medium, &phase)?;
        check_finite(light.intensity, "light.intensity")?;
        if length(sub(T::vec3_to_array(light.position), T::vec3_to_array(surface.position))).is_infinite() {
            return Err(InputError::new("light.position", ErrorKind::NonFinite));
        }
        Ok(SurfaceScene { surface, brdf, light, medium, phase })
    }

    /// The surface point.
    pub fn surface(&self) -> &Surface<T> {
        &self.surface
    }
    /// The BRDF.
    pub fn brdf(&self) -> &Brdf<T> {
        &self.brdf
    }
    /// The point light.
    pub fn light(&self) -> &PointLight<T, D> {
        &self.light
    }
    /// The medium.
    pub fn medium(&self) -> &Medium<T> {
        &self.medium
    }
    /// The phase function.
    pub fn phase(&self) -> &P {
        &self.phase
    }

    /// Whether `q(γ)` ([`Shape`]) is predicted smooth enough on the outer range for
    /// [`RayInterpolant`]'s few nodes, and its rays cheaper than a ray at every outer node: the
    /// medium thin over the light's distance (`σt·d ≤` [`LAYER_FROM`]); or thicker, where
    /// [`Map::Layer`] grades the piece from the light's direction to the layer there, while
    /// `e^{−σt·d}` is above the square root of the smallest normal number (`σt·d` ≤ 354 in f64,
    /// 43 in f32; beyond it the rays' values underflow), in fog without a lobe that splits the
    /// range ([`SMOOTH_PHASE_GAP`]), for a Phong point (its light's frame takes a ray at every
    /// node of the pieces of its lobe); not for a thicker Lambertian point (in anisotropic fog
    /// its 6 nodes failed on half of the random points of docs/DESIGN.md §11; in isotropic fog
    /// it takes [`open_ray_isotropic`] at every node instead). A prediction of cost only: the
    /// interpolant's estimate decides.
    fn smooth_rays(&self, d: T) -> bool {
        let depth = self.medium.sigma_t * d;
        let graded = matches!(self.brdf, Brdf::Phong { .. });
        depth <= T::lit(LAYER_FROM) || (graded && depth <= -T::min_positive_value().ln() * T::lit(0.5) && self.phase_lobes(SMOOTH_PHASE_GAP).next().is_none())
    }

    /// The phase function's lobes at `μ = ±1` whose singularity lies less than `below` past it:
    /// `(forward, gap, width)`, a lobe of `L_a` at `γ = 0` (forward) or `π` of angular width
    /// `√(2·gap)` (at the surface point light scatters into `ω` at `μ = cos γ`).
    fn phase_lobes(&self, below: f64) -> impl Iterator<Item = (bool, T, T)> {
        self.phase.singularities().into_iter().flat_map(|s| s.cosines).filter_map(move |mu| {
            let gap = mu.abs() - T::one();
            (gap > T::zero() && gap < T::lit(below)).then(|| (mu > T::zero(), gap, (gap + gap).sqrt()))
        })
    }

    /// `f_r(ω)` for a unit direction `ω` (without the hemisphere's clip).
    fn brdf_at(&self, frame: &Frame<T>, w: [T; 3]) -> T {
        match self.brdf {
            Brdf::Lambert { albedo } => albedo * T::FRAC_1_PI(),
            Brdf::Phong { k_s, exponent, .. } => {
                let c = dot(frame.r_dir, w);
                if c > T::zero() {
                    k_s * (exponent + T::lit(2.0)) * T::FRAC_1_PI() * T::lit(0.5) * lobe_power(c, exponent)
                } else {
                    T::zero()
                }
            }
        }
    }

    /// The frame about the light's direction; the normal's azimuth `φ_n` only where
    /// `azimuths`.
    fn frame(&self, azimuths: bool) -> Frame<T> {
        let s = T::vec3_to_array(self.surface.position);
        let to_light = sub(T::vec3_to_array(self.light.position), s);
        let d = length(to_light);
        let l = to_light.map(|x| x / d);
        let (e1, e2) = basis(l);
        let n = normalize(T::vec3_to_array(self.surface.normal));
        let normal = polar(n, l, e1, e2, azimuths);
        let (r_dir, r) = match self.brdf {
            Brdf::Phong { view, .. } => {
                let v = normalize(T::vec3_to_array(view));
                let twice = T::lit(2.0) * dot(n, v);
                let r_dir = normalize([twice * n[0] - v[0], twice * n[1] - v[1], twice * n[2] - v[2]]);
                (r_dir, polar(r_dir, l, e1, e2, true))
            }
            Brdf::Lambert { .. } => (n, normal),
        };
        Frame { d, l, e1, e2, n: normal, r, n_dir: n, r_dir }
    }

    /// Direct + air-light radiance leaving the surface towards the eye: the surface term of
    /// paper eq. 7 (`e^{−σt d}/d² · I·D(c) · f_r(ℓ) · (n·ℓ)⁺`, `ℓ` towards the light at
    /// distance `d`) plus [`SurfaceScene::air_light`].
    pub fn radiance(&self) -> T {
        self.direct() + self.air_light()
    }

    /// The surface term of paper eq. 7 alone (light reaching the point unscattered).
    pub fn direct(&self) -> T {
        let f = self.frame(false);
        if !(f.d > T::zero()) {
            return T::zero();
        }
        let cos = f.n.0.max(T::zero());
        let c = -dot(f.l, normalize(self.light.distribution.axis()));
        let emitted: T = self.light.distribution.eval(c);
        (-self.medium.sigma_t * f.d).exp() / (f.d * f.d) * self.light.intensity * emitted * self.brdf_at(&f, f.l) * cos
    }

    /// Surface radiance from air-light, error-controlled to [`outer_tolerance`]. `+∞` when the
    /// light sits on the surface point and `σs·I > 0`.
    pub fn air_light(&self) -> T {
        self.air_light_counted(outer_tolerance()).0
    }

    /// [`SurfaceScene::air_light`] to a relative tolerance of the outer estimate (no finer than
    /// [`Real::PANEL_TOLERANCE`], the rays' own), and the ray integrals it evaluated. From
    /// [`FIXED_LOBE_TOLERANCE`] up, a Phong lobe lit by a light without an axis is taken by
    /// [`lobe_arcs`], as in the shaders, with the rule of [`LOBE_RULES`] the tolerance allows;
    /// from 5e-2 up, a point lit by one in a thin medium takes its rays from an interpolant of
    /// their logarithm at 6 or 12 where that meets the tolerance; a phase function's lobe narrower
    /// than [`PHASE_LOBE_GAP`] allows is cut at its extent; a Lambertian point lit by a `c^p`
    /// beam takes the `p + 1` rays at each outer node as one ray integral where the light angle's
    /// route passes on it, counted as one; a Lambertian point lit by a light without an axis in
    /// isotropic fog takes its ray in closed form at every outer node (`open_ray_isotropic`,
    /// each counted as a ray) (docs/DESIGN.md §11).
    pub fn air_light_counted(&self, tolerance: T) -> (T, usize) {
        let tolerance = working_tolerance(tolerance);
        let control = inner_control(tolerance);
        let lobe = LOBE_RULES.iter().find(|&&(from, _)| tolerance >= T::lit(from)).map(|&(_, rule)| rule);
        self.integrate(tolerance, MAX_SURFACE_PANELS, lobe, true, |g, phys| default_panels(g, phys, control).0)
    }

    /// What the shaders compute (fixed cost): the outer rule of `outer_rule` to
    /// `control.tolerance`, at most `max_panels` panels of the outer integral (the shaders:
    /// [`SHADER_SURFACE_PANELS`], [`SHADER_PHONG_PANELS`] for a Phong lobe), every ray integral as
    /// [`Scene::in_scatter_panels`]`::<N>(control)`, a Phong lobe lit by a light without an axis
    /// by [`lobe_arcs`]; and the ray integrals evaluated. The shaders have this for Lambertian and
    /// Phong surfaces lit by a light without an axis, where the hemisphere's inner integral needs
    /// no rays (Lambert's in closed form) and the outer one is the only loop of rays.
    pub fn air_light_panels_counted<const N: usize>(&self, control: Control<T>, max_panels: usize) -> (T, usize) {
        self.integrate(control.tolerance, max_panels, Some(LOBE_RULE), false, |g, phys| panels_with_nodes::<T, D, P, N>(g, phys, control).0)
    }

    /// The `p + 1` rays at `γ` (cosine and sine given) and `φ_j = φ_a + jπ/p` (`cos(φ_j − φ_a)`
    /// the Chebyshev–Lobatto `points`, [`lobatto_points`]) on their shared panel in the light angle (`crate::angle`):
    /// they share `h`, `x_h` and their ends, only `D` differs. The panel's plan, the rays'
    /// canonical form with `(d_el, d_c)` left 0, and each ray's `(d_el, d_c)` ([`axis_cosines`], `u·a = A
    /// cos(jπ/p)`); `None` where the route cannot be taken (the
    /// light on the rays' line) or a thick medium, where each ray tries Gauss–Laguerre in the
    /// optical depth first.
    #[allow(clippy::too_many_arguments)]
    fn arc(&self, phys: &Physics<'_, T, D, P>, fr: &Frame<T>, cos_g: T, sin_g: T, (axis_l, axis_a): (T, T), points: &[T], control: &Control<T>) -> Option<Arc<T>> {
        let g = Canonical { h: fr.d * sin_g, x_h: fr.d * cos_g, d_el: T::zero(), d_c: T::zero(), t0: T::zero(), t1: T::infinity() };
        let ends = crate::angle::Ends::new(&g, phys)?;
        if ends.thick() {
            return None;
        }
        let plan = crate::angle::Plan::from_ends(&ends, &g, control)?;
        let mut rays = [(T::zero(), T::zero()); MAX_INTERPOLATED_DEGREE + 1];
        for (ray, &x) in rays.iter_mut().zip(points) {
            *ray = axis_cosines(cos_g, sin_g, axis_l, axis_a * x);
        }
        Some(Arc { plan, g, rays, sixteen: T::PANEL_NODES == 16 && !(control.tolerance >= T::lit(crate::scene::FEWER_NODES_FROM)) })
    }

    /// `Σ_j c_j L_a(γ, φ_j)` over an [`Arc`]'s rays (`c_j` = `weights`) as one ray integral whose
    /// light factor is `Σ_j c_j D(c_j(θ))` (`F` is linear in `D`): taken where the panel's first
    /// try or its wider rules meet `control` on the sum (its own estimate, against the sum's
    /// value), on the whole panel or on its pieces ([`SurfaceScene::arc_pieces`]); else `None`,
    /// and the rays one by one.
    fn arc_sum(&self, phys: &Physics<'_, T, D, P>, arc: &Arc<T>, weights: &[T], control: &Control<T>) -> Option<T> {
        let emission = ArcSum { light: phys.light, rays: &arc.rays[..weights.len()], weights };
        let mut out = [None];
        self.arc_pieces(phys, arc, control, &mut out, |plan, g, slot| {
            if slot[0].is_none() {
                slot[0] = if arc.sixteen { plan.tries::<D, P, _, 16>(g, phys, control, &emission).0 } else { plan.tries::<D, P, _, 8>(g, phys, control, &emission).0 };
            }
        });
        out[0]
    }

    /// Each of an [`Arc`]'s rays on the panel's shared samples (`Plan::tries_each`), on the
    /// whole panel or on its pieces ([`SurfaceScene::arc_pieces`]): `out[j]` where a rule meets
    /// `control` on ray `j` (its own estimate), else `None`.
    fn arc_rays(&self, phys: &Physics<'_, T, D, P>, arc: &Arc<T>, control: &Control<T>, out: &mut [Option<T>]) {
        let rays = &arc.rays[..out.len()];
        self.arc_pieces(phys, arc, control, out, |plan, g, slots| {
            if arc.sixteen {
                plan.tries_each::<D, P, 16>(g, phys, control, rays, slots);
            } else {
                plan.tries_each::<D, P, 8>(g, phys, control, rays, slots);
            }
        });
    }

    /// An [`Arc`]'s rays by `tries` (which fills the slots left `None` on a piece of the rays'
    /// segment, given the piece's plan and canonical form): on the arc's whole panel, then, for
    /// the rays whose rules did not pass on it, on its two parts split at `Plan::split_point`,
    /// each split again where they do not pass on it, up to [`MAX_ARC_PIECES`] pieces (a beam's lobe
    /// `c^p` and the extinction's layer at the far end on one panel of nearly `π`, where the arc
    /// passes the light: each piece within `control` of its own value, so their sum is). A piece
    /// from `t_s` carries `e^{−σt(t_s − t0)}`, the extinction to its start (docs/DESIGN.md §1).
    /// `out[j]`: ray `j`'s value where it passed on every piece, else `None` (at most 64 rays).
    fn arc_pieces(&self, phys: &Physics<'_, T, D, P>, arc: &Arc<T>, control: &Control<T>, out: &mut [Option<T>], mut tries: impl FnMut(&crate::angle::Plan<T>, &Canonical<T>, &mut [Option<T>])) {
        tries(&arc.plan, &arc.g, out);
        for v in out.iter_mut() {
            *v = v.filter(|x| x.is_finite());
        }
        let mut pending: u64 = out.iter().enumerate().fold(0, |m, (j, v)| if v.is_none() { m | 1 << j } else { m });
        let split = arc.plan.split_point(&arc.g);
        if pending == 0 || !(split > arc.g.t0 && split < arc.g.t1) {
            return;
        }
        let mut sums = [T::zero(); MAX_INTERPOLATED_DEGREE + 1];
        let mut stack = [(T::zero(), T::zero(), 0u64); MAX_ARC_PIECES];
        stack[0] = (split, arc.g.t1, pending);
        stack[1] = (arc.g.t0, split, pending);
        let (mut held, mut pieces) = (2, 2);
        let mut slots = [None; MAX_INTERPOLATED_DEGREE + 1];
        let slots = &mut slots[..out.len()];
        while held > 0 {
            held -= 1;
            let (a, b, mask) = stack[held];
            let g = Canonical { t0: a, t1: b, ..arc.g };
            let Some(plan) = crate::angle::Plan::new(&g, phys, control) else {
                pending &= !mask;
                continue;
            };
            for (j, slot) in slots.iter_mut().enumerate() {
                *slot = if mask >> j & 1 == 1 { None } else { Some(T::zero()) };
            }
            tries(&plan, &g, slots);
            let extinction = (-phys.sigma_t * (a - arc.g.t0)).exp();
            let mut failed = 0u64;
            for (j, slot) in slots.iter().enumerate().filter(|&(j, _)| mask >> j & 1 == 1) {
                match slot.filter(|v| v.is_finite()) {
                    Some(v) => sums[j] = sums[j] + v * extinction,
                    None => failed |= 1 << j,
                }
            }
            if failed == 0 {
                continue;
            }
            let split = plan.split_point(&g);
            if pieces < MAX_ARC_PIECES && split > a && split < b {
                stack[held] = (split, b, failed);
                stack[held + 1] = (a, split, failed);
                held += 2;
                pieces += 1;
            } else {
                pending &= !failed;
            }
        }
        for (j, v) in out.iter_mut().enumerate() {
            if pending >> j & 1 == 1 {
                *v = Some(sums[j]);
            }
        }
    }

    /// A Phong point's air-light about the lobe's own axis `r` (at `alpha_r` from `ℓ`;
    /// docs/DESIGN.md §11), from the rays' interpolant `pieces` of a light without an axis, where the lobe above `1e-3 ·
    /// tolerance` of its peak — the cone `θ ≤ reach` about `r` — lies inside the hemisphere and
    /// at least `1.5·reach` from `±ℓ` (where `L_a` is not smooth on the sphere), and where the
    /// rules' estimates meet `tolerance` (relative); else `None`. With `ω = cos θ r + sin θ (cos φ e₁ +
    /// sin φ e₂)`, `e₁` towards `ℓ`, and `z = −(n + 1) ln cos θ`,
    /// `∫ cosⁿθ (n·ω) L_a sin θ dθ dφ = (2π/(n + 1)) ∫_0^∞ e^{−z} Ḡ(z) dz`, `Ḡ` the mean over `φ`
    /// of `(n·ω) L_a` — smooth in `z` (even in `θ`) and periodic in `φ`: Gauss–Laguerre in `z`
    /// (6 nodes, else 12; the estimate from the last two coefficients of the discrete Laguerre
    /// transform, twice them, against the two before), the trapezoid rule in `φ` (8 nodes,
    /// folded to 5 since `L_a` is even in `φ` and the odd part of `n·ω` cancels; the estimate
    /// its difference from the 4-node rule on the same nodes).
    fn mirror_cone(&self, fr: &Frame<T>, alpha_r: T, pieces: &RayPieces<T>, tolerance: T) -> Option<T> {
        let Brdf::Phong { k_s, exponent, .. } = self.brdf else {
            return None;
        };
        let reach = lobe_cone(tolerance * T::lit(1e-3), exponent);
        let (cos_r, sin_r) = (fr.r.0, fr.r.1);
        // n·r and n·e₁, e₁ = (ℓ − cos α_r r)/sin α_r
        let n_r = dot(fr.n_dir, fr.r_dir);
        let n_e1 = (fr.n.0 - cos_r * n_r) / sin_r;
        // the cone inside the hemisphere (n·ω ≥ cos(β + reach) > 0, β the angle from n to r)
        // and at least 1.5·reach from ±ℓ
        let beta = n_r.max(-T::one()).min(T::one()).acos();
        let margin = T::lit(1.5) * reach;
        if !(beta + reach < T::FRAC_PI_2() && alpha_r >= margin && T::PI() - alpha_r >= margin && pieces.count > 0) {
            return None;
        }
        let two = T::lit(2.0);
        // cos φ at φ = 0, π/4, π/2, 3π/4, π and the folded trapezoid weights, 8 and 4 nodes
        let cos_phi = [T::one(), T::FRAC_1_SQRT_2(), T::zero(), -T::FRAC_1_SQRT_2(), -T::one()];
        let (fine, coarse) = ([0.125, 0.25, 0.25, 0.25, 0.125], [0.25, 0.0, 0.5, 0.0, 0.25]);
        let scale = T::one() / (exponent + T::one());
        let mean = |z: T| -> (T, T) {
            // cos θ = e^{−z/(n+1)}, sin θ = √(1 − cos²θ) = √(−expm1(−2z/(n+1)))
            let cos_t = (-z * scale).exp();
            let sin_t = (-(-(z + z) * scale).exp_m1()).max(T::zero()).sqrt();
            let (mut f8, mut f4) = (T::zero(), T::zero());
            for (j, &c) in cos_phi.iter().enumerate() {
                let cos_g = (cos_t * cos_r + sin_t * c * sin_r).max(-T::one()).min(T::one());
                let cosine = (cos_t * n_r + sin_t * c * n_e1).max(T::zero());
                let value = cosine * pieces.light(cos_g);
                f8 = f8 + T::lit(fine[j]) * value;
                f4 = f4 + T::lit(coarse[j]) * value;
            }
            (f8, (f8 - f4).abs())
        };
        for count in [6, 12] {
            let (rule, transform) = crate::expansion::laguerre_table::rule(count)?;
            let mut values = [T::zero(); 12];
            let (mut sum, mut phi_error) = (T::zero(), T::zero());
            for (i, &(z, w)) in rule.iter().enumerate() {
                let (v, e) = mean(T::lit(z));
                values[i] = v;
                sum = sum + T::lit(w) * v;
                phi_error = phi_error + T::lit(w) * e;
            }
            // the last four coefficients a_k = Σ_i w_i L_k(z_i) Ḡ(z_i)
            let c = crate::expansion::last_laguerre_coefficients(transform, &values[..count]);
            let (recent, earlier) = (c[3].abs() + c[2].abs(), c[1].abs() + c[0].abs());
            let z_error = if recent < earlier { two * recent } else { T::infinity() };
            if z_error + phi_error <= tolerance * sum.abs() {
                return Some(k_s * (exponent + two) * scale * sum);
            }
        }
        None
    }

    /// The hemisphere's integral to `tolerance` (the outer one; the inner ones to a tenth),
    /// at most `max_panels` panels each, every ray integral by `ray_integral`, a Phong lobe lit by
    /// a light without an axis by [`lobe_arcs`] with the `lobe` rule if one is given (else by
    /// adaptive quadrature); and the rays evaluated. `default_path`: with what the shaders do
    /// not have, the rays' interpolant ([`RayInterpolant`]) and the cuts at the phase function's
    /// lobe ([`PHASE_LOBE_GAP`]).
    fn integrate(&self, tolerance: T, max_panels: usize, lobe: Option<&[(f64, f64)]>, default_path: bool, ray_integral: impl Fn(&Canonical<T>, &Physics<'_, T, D, P>) -> T) -> (T, usize) {
        if self.light.intensity == T::zero() || self.medium.sigma_s == T::zero() {
            return (T::zero(), 0);
        }
        let omni = self.light.distribution.is_isotropic();
        // (φ_n serves a light with an axis and a numerical inner integral, not a Lambertian
        // point lit by a light without one)
        let fr = self.frame(!(omni && matches!(self.brdf, Brdf::Lambert { .. })));
        if !(fr.d > T::zero()) {
            return (T::infinity(), 0);
        }
        if let Brdf::Lambert { albedo } = self.brdf {
            if albedo == T::zero() {
                return (T::zero(), 0);
            }
        }
        if let Brdf::Phong { k_s, .. } = self.brdf {
            if k_s == T::zero() {
                return (T::zero(), 0);
            }
        }
        let inner_tolerance = tolerance * T::lit(0.1);
        let rule = outer_rule(tolerance);
        let phong = matches!(self.brdf, Brdf::Phong { .. });
        let rays = Cell::new(0);
        let phys = Physics::new(&self.light, &self.medium, &self.phase);
        // the light's axis in the frame (ℓ, e₁, e₂)
        let axis = normalize(self.light.distribution.axis());
        let (axis_l, axis_e1, axis_e2) = (dot(axis, fr.l), dot(axis, fr.e1), dot(axis, fr.e2));
        // L_a along ω = cos γ ℓ + sin γ u, u = cos φ e₁ + sin φ e₂: its canonical form
        // (docs/DESIGN.md §2) is known exactly, the light at x_h = d cos γ, h = d sin γ from the
        // ray and the axis's cosines d·a = cos γ (ℓ·a) + sin γ (u·a) and (cos γ u − sin γ ℓ)·a
        // (the unit vector from the light to its foot is sin γ ℓ − cos γ u): no reduction of
        // world vectors, which would lose ε·d/h of h towards the light
        // a distribution that is one polynomial of degree p in c: along ω, d_el and d_c are
        // affine in u·a = A cos(φ − φ_a), so L_a at γ is a polynomial of degree p in
        // cos(φ − φ_a), and p + 1 rays give it exactly (MAX_INTERPOLATED_DEGREE)
        let beam = if omni { None } else { whole_polynomial_degree(&self.light.distribution) };
        let polynomial = beam.map(|p| p as usize).filter(|&p| p <= MAX_INTERPOLATED_DEGREE);
        // (cos(jπ/p) once a point: the rays' axis cosines, the Lambertian weights and the
        // interpolant's transform read them at every outer node)
        let points = lobatto_points::<T>(polynomial.unwrap_or(0));
        // (the axis's and the mirror direction's angles only where they are used: for a
        // Lambertian point lit by an omni light they were 2–3 % of its instructions)
        let (phi_a, axis_a) = if polynomial.is_some() { (axis_e2.atan2(axis_e1), axis_e1.hypot(axis_e2)) } else { (T::zero(), T::zero()) };
        // the default path takes a Lambertian arc's rays about an axis as one (`arc_sum`)
        let arc_control = default_path.then(|| inner_control(tolerance));
        let along = |cos_g: T, sin_g: T, phi: T| {
            rays.set(rays.get() + 1);
            let sin_g = sin_g.max(T::zero());
            // (an omni light has no axis to turn: D ignores c)
            let axis_u = if omni {
                T::zero()
            } else {
                let (s, c) = sin_cos_turns(phi);
                c * axis_e1 + s * axis_e2
            };
            let h = fr.d * sin_g;
            let (d_el, d_c) = axis_cosines(cos_g, sin_g, axis_l, axis_u);
            let d_c = if h > T::zero() { d_c } else { T::zero() };
            let g = Canonical { h, x_h: fr.d * cos_g, d_el, d_c, t0: T::zero(), t1: T::infinity() };
            ray_integral(&g, &phys)
        };
        // ω at (γ, φ) from the sines and cosines of both
        let direction = |cos_g: T, sin_g: T, (s, c): (T, T)| core::array::from_fn(|i| cos_g * fr.l[i] + sin_g * (c * fr.e1[i] + s * fr.e2[i]));
        // φ_n's and φ_a's sines and cosines, so that a numerical inner integral takes
        // cos(φ − φ_n) and cos(φ − φ_a) from φ's own (one sin_cos a node instead of two cosines
        // more)
        let numerical = phong || !omni;
        let ((sin_n, cos_n), (sin_a, cos_a)) = if numerical { (fr.n.2.sin_cos(), phi_a.sin_cos()) } else { ((T::zero(), T::one()), (T::zero(), T::one())) };
        // the mirror direction's angle from ℓ and Δ = φ_n − φ_r with its cosine and sine, the
        // same at every outer node
        let alpha_r = if phong { fr.r.1.atan2(fr.r.0) } else { T::zero() };
        let delta = fr.n.2 - fr.r.2;
        let (sin_delta, cos_delta) = if phong { delta.sin_cos() } else { (T::zero(), T::one()) };
        // a light without an axis: L_a(γ) sin γ from the rays' interpolants (`RayPieces`) once
        // they are sampled, else a ray at every outer node
        let source: RefCell<RayPieces<T>> = RefCell::new(RayPieces::none());
        let outer = |g: T| -> T {
            let (sin_g, cos_g) = sin_cos_half_turn(g);
            // the normal's arc, and A, B and sin ψ for Lambert's closed form
            let (a_n, b_n) = (fr.n.0 * cos_g, fr.n.1 * sin_g);
            let (psi_n, sin_psi_n) = half_arc_and_sine(a_n, b_n);
            if !(psi_n > T::zero()) {
                return T::zero();
            }
            let phi_n = fr.n.2;
            // L_a(γ) sin γ of a light without an axis (from the rays' interpolant where there is
            // one) times `inner`, the inner integral of the BRDF and the cosine at this node
            let omni_times = |inner: T| {
                let pieces = source.borrow();
                let light = if pieces.count > 0 {
                    pieces.light_sin(g, || half_angle(sin_g, cos_g).1)
                } else {
                    along(cos_g, sin_g, phi_n) * sin_g
                };
                light * inner
            };
            if let (true, Brdf::Lambert { albedo }) = (omni, self.brdf) {
                // ∫ (A + B cos x)⁺ over the arc, closed form
                let arc = T::lit(2.0) * (a_n * psi_n + b_n * sin_psi_n);
                return omni_times(albedo * T::FRAC_1_PI() * arc);
            }
            let cosine = |(s, c): (T, T)| (fr.n.0 * cos_g + fr.n.1 * sin_g * (c * cos_n + s * sin_n)).max(T::zero());
            let psi_r = if phong { half_arc(fr.r, cos_g, sin_g) } else { T::PI() };
            if !(psi_r > T::zero()) {
                return T::zero();
            }
            // the arc's ends, and a Phong lobe's ends and peak: the edges of the inner panels, which
            // only a numerical inner integral needs
            let circle = || {
                let mut edges = [T::zero(); 8];
                let mut count = 0;
                let mut push = |x: T| {
                    edges[count] = x;
                    count += 1;
                };
                if psi_n < T::PI() {
                    push(phi_n - psi_n);
                    push(phi_n + psi_n);
                }
                if phong {
                    if psi_r < T::PI() {
                        push(fr.r.2 - psi_r);
                        push(fr.r.2 + psi_r);
                    }
                    push(fr.r.2);
                }
                sorted_circle(&mut edges[..count], phi_n)
            };
            // f_r (n·ω)⁺ at φ
            let geometric_at = |sc: (T, T)| cosine(sc) * self.brdf_at(&fr, direction(cos_g, sin_g, sc));
            let geometric = |phi: T| geometric_at(sin_cos_turns(phi));
            // n·ω and a Phong lobe's r·ω keep their signs between the edges, so a panel where
            // either is not positive at the middle is skipped — their signs, not f_r (n·ω)⁺
            // itself, whose power (r·ω)ⁿ may underflow to 0 at the middle of a panel whose
            // end holds the lobe's peak
            let open = |phi: T| {
                let sc = sin_cos_turns(phi);
                cosine(sc) > T::zero() && (!phong || dot(fr.r_dir, direction(cos_g, sin_g, sc)) > T::zero())
            };
            let inner_sum = |f: &mut dyn FnMut(T) -> T| -> T {
                let mut sum = T::zero();
                for pair in circle().windows(2) {
                    let (a, b) = (pair[0], pair[1]);
                    if !(b > a) || !open((a + b) * T::lit(0.5)) {
                        continue;
                    }
                    sum = sum + adaptive(rule, &mut |x| f(x), &[a, b], inner_tolerance, max_panels).0;
                }
                sum
            };
            if omni {
                let inner = match (self.brdf, lobe) {
                    (Brdf::Phong { k_s, exponent, .. }, Some(rule)) => {
                        let (normal, mirror) = ((fr.n.0 * cos_g, fr.n.1 * sin_g), (fr.r.0 * cos_g, fr.r.1 * sin_g));
                        let arcs = lobe_arcs(rule, normal, mirror, g - alpha_r, (delta, cos_delta, sin_delta), psi_n, exponent);
                        k_s * (exponent + T::lit(2.0)) * T::FRAC_1_PI() * T::lit(0.5) * arcs
                    }
                    _ => inner_sum(&mut |phi| geometric(phi)),
                };
                return omni_times(inner);
            }
            let value = match polynomial {
                Some(p) => {
                    // L_a at φ_j = φ_a + jπ/p, where cos(φ_j − φ_a) are the Chebyshev–Lobatto points
                    let mut values = [T::zero(); MAX_INTERPOLATED_DEGREE + 1];
                    let step = if p > 0 { T::PI() / T::from(p).unwrap_or(T::one()) } else { T::zero() };
                    // a Lambertian arc's integral in closed form, Σ_j c_j L_j (lambert_chebyshev_weights)
                    let mut weights = [T::zero(); MAX_INTERPOLATED_DEGREE + 1];
                    let lambert = match self.brdf {
                        Brdf::Lambert { albedo } => {
                            lambert_chebyshev_weights(p, fr.n.0 * cos_g, fr.n.1 * sin_g, psi_n, phi_n - phi_a, &points, &mut weights);
                            Some(albedo)
                        }
                        Brdf::Phong { .. } => None,
                    };
                    // the p + 1 rays share their panel in the light angle, only D differs (`arc`): a
                    // Lambertian arc's sum as one ray integral of Σ_j c_j D(c_j), a Phong arc's rays
                    // on the panel's shared samples, the rest one by one
                    let mut known = [None; MAX_INTERPOLATED_DEGREE + 1];
                    if let Some(control) = arc_control {
                        if let Some(arc) = self.arc(&phys, &fr, cos_g, sin_g, (axis_l, axis_a), &points[..=p], &control) {
                            match lambert {
                                Some(albedo) => {
                                    if let Some(sum) = self.arc_sum(&phys, &arc, &weights[..=p], &control) {
                                        rays.set(rays.get() + 1);
                                        return sum * albedo * T::FRAC_1_PI() * sin_g;
                                    }
                                }
                                None => {
                                    self.arc_rays(&phys, &arc, &control, &mut known[..=p]);
                                    rays.set(rays.get() + known.iter().flatten().count());
                                }
                            }
                        }
                    }
                    for (j, v) in values.iter_mut().enumerate().take(p + 1) {
                        *v = match known[j] {
                            Some(value) => value,
                            None => along(cos_g, sin_g, phi_a + step * T::from(j).unwrap_or(T::zero())),
                        };
                    }
                    let values = &values[..=p];
                    if let Some(albedo) = lambert {
                        let sum = values.iter().zip(&weights).fold(T::zero(), |acc, (&l, &c)| acc + l * c);
                        return sum * albedo * T::FRAC_1_PI() * sin_g;
                    }
                    let mut coefficients = [T::zero(); MAX_INTERPOLATED_DEGREE + 1];
                    lobatto_coefficients(values, &points, &mut coefficients);
                    let coefficients = &coefficients[..=p];
                    inner_sum(&mut |phi| {
                        let (s, c) = sin_cos_turns(phi);
                        let f = geometric_at((s, c));
                        if f > T::zero() {
                            f * chebyshev_sum(coefficients, c * cos_a + s * sin_a)
                        } else {
                            T::zero()
                        }
                    })
                }
                None => inner_sum(&mut |phi| {
                    let f = geometric(phi);
                    if f > T::zero() {
                        f * along(cos_g, sin_g, phi)
                    } else {
                        T::zero()
                    }
                }),
            };
            value * sin_g
        };
        // outer edges: where the arcs change kind and where the arcs' ends meet (kinks: an arc
        // opens or closes there), a lobe's peak and extent, a beam's axis and a phase lobe's
        // extent (smooth: the pieces need not crowd their nodes towards them, piece_map); at most
        // 2 + 9 (Phong) + 2 (beam) + 4 (phase)
        let mut cuts = [T::zero(); 18];
        let mut kinds = [Cut::Kink; 18];
        let mut count = 0;
        let turning = |(cos_a, sin_a, _): (T, T, T)| {
            let alpha = sin_a.atan2(cos_a);
            let first = (T::FRAC_PI_2() - alpha).abs();
            [first, T::PI() - first]
        };
        let mut push = |c: T, kind: Cut| {
            cuts[count] = c;
            kinds[count] = kind;
            count += 1;
        };
        let normal_turns = turning(fr.n);
        normal_turns.into_iter().for_each(|c| push(c, Cut::Kink));
        if let Brdf::Phong { exponent, .. } = self.brdf {
            // the mirror direction's turning points and the crossings of n·ω = 0 with r·ω = 0
            // are kinks of the inner integral only for a broad lobe: there (r·ω)⁺ⁿ vanishes, and
            // the arc that opens or closes adds `|γ − γ*|^{n + 1/2}` — on the default path, from
            // SMOOTH_MIRROR_FROM on smooth enough for the outer rules (docs/DESIGN.md §11; the
            // shaders' method, `air_light_panels_counted`, keeps the shaders' cuts)
            let mirror_kinks = !default_path || exponent < T::lit(SMOOTH_MIRROR_FROM);
            if mirror_kinks {
                turning(fr.r).into_iter().for_each(|c| push(c, Cut::Kink));
            }
            push(alpha_r, Cut::Lobe);
            // the lobe's extent in γ: (cos δ)ⁿ ≈ e^{−nδ²/2} is 0.32 at δ = 1.5/√n, 3e-4 at 4/√n
            // (not for a broad lobe at the loosest tolerance on the default path: BROAD_LOBE_BELOW)
            let broad = default_path && exponent <= T::lit(BROAD_LOBE_BELOW) && tolerance >= T::lit(0.1);
            if exponent > T::one() && !broad {
                for k in [1.5, 4.0] {
                    let width = T::lit(k) / exponent.sqrt();
                    push(alpha_r - width, Cut::Lobe);
                    push(alpha_r + width, Cut::Lobe);
                }
            }
            // the great circles n·ω = 0 and r·ω = 0 cross at ±u, u ∥ n × r
            let u = cross(fr.n_dir, fr.r_dir);
            let norm = length(u);
            if mirror_kinks && norm > T::epsilon() {
                let c = (dot(u, fr.l) / norm).max(-T::one()).min(T::one());
                push(c.acos(), Cut::Kink);
                push(T::PI() - c.acos(), Cut::Kink);
            }
        }
        // a beam c^p: rays along ±a (at γ_a and π − γ_a from ℓ) see its lobe to their far end,
        // a peak of width ~1/√p in γ, cut there (without the cuts a c^32 point at tolerance 1e-2
        // passed the outer estimate 1.6e-2 off its reference; with them within 6.7e-5, and the
        // lobe's extent ±1.5/√p, ±4/√p cut as well, as a Phong lobe's, doubled the rays for no
        // test that needed it)
        if beam.is_some_and(|p| p >= 2) {
            let gamma_a = axis_e1.hypot(axis_e2).atan2(axis_l);
            push(gamma_a, Cut::Peak);
            push(T::PI() - gamma_a, Cut::Peak);
        }
        // the phase function's lobe: at the point itself light scatters into ω at μ = ℓ·ω =
        // cos γ, so a lobe at μ = ±1 is one of L_a at γ = 0 or π, of the lobe's angular width
        // √(2·gap) (a singularity gap past ±1; Henyey–Greenstein (1 − |g|)/√|g|); where it is
        // narrower than PHASE_LOBE_GAP allows, cut at 1.5 and 4 widths from its peak, as a Phong
        // lobe's extent (the default path only; docs/DESIGN.md §11)
        if default_path && !self.phase.is_isotropic() {
            for (forward, _, width) in self.phase_lobes(PHASE_LOBE_GAP) {
                for k in [1.5, 4.0] {
                    let c = T::lit(k) * width;
                    push(if forward { c } else { T::PI() - c }, Cut::Peak);
                }
            }
        }
        // only γ ∈ (α_n − π/2, α_n + π/2) sees the hemisphere (the largest n·ω at γ is
        // cos(γ − α_n)): beyond it every arc is empty, and no outer node is spent there
        // (the end is the normal's turning point itself, so that no sliver is left beside it)
        let (lo, hi) = if fr.n.0 < T::zero() { (normal_turns[0], T::PI()) } else { (T::zero(), normal_turns[1]) };
        // a Phong lobe from the tolerance at which lobe_arcs serves on (the default path, any
        // light): on the arc at γ the lobe is at most cosⁿ(γ − α_r) of its peak (the largest r·ω
        // there), and where that is below LOBE_FLOOR, as lobe_arcs ends it within an arc, no
        // outer node is spent; the range's ends are then smooth cuts (docs/DESIGN.md §11)
        let lobe_reach = match self.brdf {
            Brdf::Phong { exponent, .. } if default_path && lobe.is_some() => lobe_cone(T::lit(LOBE_FLOOR), exponent),
            _ => T::infinity(),
        };
        let (lobe_lo, lobe_hi) = (alpha_r - lobe_reach, alpha_r + lobe_reach);
        let (lo, hi) = (lo.max(lobe_lo), hi.min(lobe_hi));
        if !(hi > lo) {
            return (T::zero(), rays.get());
        }
        let mut values = cuts;
        let (edges, n): ([T; 20], usize) = edges_between(lo, hi, &mut values[..count]);
        // the inner edges where no arc opens or closes (the range's ends are arcs' ends)
        let mut smooth = [false; 20];
        for (i, flag) in smooth.iter_mut().enumerate().take(n).skip(1) {
            *flag = !cuts[..count].iter().zip(&kinds).any(|(&c, &k)| c == edges[i] && k == Cut::Kink);
        }
        (smooth[0], smooth[n]) = (lo == lobe_lo, hi == lobe_hi);
        let mut knots = [T::zero(); 20];
        for (i, k) in knots.iter_mut().enumerate().take(n + 1) {
            *k = T::from(i).unwrap_or(T::zero());
        }
        // `(γ, dγ/dx)` at the outer variable `x`, piece `⌊x⌋` mapped by `piece_map`
        let piece = |x: T| {
            // (x ≥ 0: the conversion's truncation is the floor, without a call to it)
            let i = x.to_usize().unwrap_or(0).min(n - 1);
            piece_map(edges[i], edges[i + 1], smooth[i], smooth[i + 1], x - knots[i])
        };
        let mut mapped = |x: T| weighted_at(&piece, &outer, x);
        // a smooth piece within a Phong lobe's extent (between its outermost cuts) is a slice of
        // its peak at most 2.5/√n wide (where (cos δ)ⁿ ≈ e^{−nδ²/2}): where a tenth of the value
        // will do, 5 points
        let lobe_cuts = cuts[..count].iter().zip(&kinds).filter(|&(_, &k)| k == Cut::Lobe).map(|(&c, _)| c);
        let (first, last) = (lobe_cuts.clone().fold(T::infinity(), T::min), lobe_cuts.fold(-T::infinity(), T::max));
        // (and from the range's ends where the lobe ends them)
        let (first, last) = if lobe_lo.is_finite() { (first.min(lobe_lo), last.max(lobe_hi)) } else { (first, last) };
        let coarse = crate::extended::segment_rule(tolerance);
        let rule_of = |a: T, _b: T| {
            let i = a.to_usize().unwrap_or(0).min(n - 1);
            if first <= edges[i] && edges[i + 1] <= last && smooth[i] && smooth[i + 1] { coarse } else { rule }
        };
        // a Lambertian point lit by an omni light in isotropic fog, on the default path:
        // L_a(γ) sin γ = σs I P e^{−σt·d} K(γ)/d in closed form (`open_ray_isotropic`) at every
        // outer node, where e^{−σt·d} is well inside the float range (as `smooth_rays`'s
        // bound): no ray integral and no interpolant (a node costs less than one ray). (A Phong
        // point's rays the same way: 1–12 % fewer instructions, but in f32 `phong_thick` took
        // 14.3–14.9 µs a class against 12.9–14.1.)
        let depth = self.medium.sigma_t * fr.d;
        let open = default_path && omni && self.phase.is_isotropic() && depth <= -T::min_positive_value().ln() * T::lit(0.5);
        if let (true, Brdf::Lambert { albedo }) = (open, self.brdf) {
            let scale = T::lit(2.0) * albedo * T::FRAC_1_PI() * self.medium.sigma_s * self.light.intensity * self.phase.eval(T::zero()) / fr.d;
            let terms = open_ray_terms(depth, tolerance);
            let mut lambert = |x: T| {
                weighted_at(&piece, |g| {
                    rays.set(rays.get() + 1);
                    lambert_node(fr.n, g, |s, c, cos_g| open_ray_isotropic(depth, g, (s, c, cos_g), terms)) * scale
                }, x)
            };
            let (value, _) = crate::extended::adaptive_by(&rule_of, &mut lambert, &knots[..=n], tolerance, max_panels);
            return (value, rays.get());
        }
        if default_path && omni && tolerance >= T::lit(INTERPOLATED_FROM) && self.smooth_rays(fr.d) {
            // L_a(γ) is smooth where the outer integrand's kinks are (they are the inner
            // integral's): q = ln(L_a(γ) sin γ / w(γ)) (`Shape`) interpolated from RAY_NODES rays, the outer
            // integral needs no more. The interpolant's estimate is then one of L_a's relative
            // error, wherever the BRDF's weight lies: at most half the tolerance to it, what it
            // leaves to the outer integral (docs/DESIGN.md §11). Else more nodes, then a ray at
            // every outer node.
            //
            // A phase lobe narrower than SMOOTH_PHASE_GAP allows is one of L_a at γ = 0 or π
            // (as for the outer cuts above): the range is split at 4 of its widths from the
            // peak, an interpolant on each side.
            let mut ends = [hi; 3];
            let mut parts = 1;
            // (a lobe narrower than PHASE_LOBE_GAP allows: the piece beyond it geometric)
            let mut narrow = [false; 2];
            for (forward, gap, width) in self.phase_lobes(SMOOTH_PHASE_GAP) {
                let reach = T::lit(4.0) * width;
                let c = if forward { reach } else { T::PI() - reach };
                if c > lo && c < hi {
                    ends[parts - 1] = c;
                    ends[parts] = hi;
                    parts += 1;
                    narrow[usize::from(!forward)] = gap < T::lit(PHASE_LOBE_GAP);
                }
            }
            ends[..parts].sort_unstable_by(|x, y| x.partial_cmp(y).unwrap_or(core::cmp::Ordering::Equal));
            let bound = (T::one() + tolerance * T::lit(0.5)).ln();
            // in thin isotropic fog the vacuum's shape divided out, and from 4 nodes (THIN_PER_TOLERANCE)
            let thin = self.phase.is_isotropic() && depth <= tolerance * T::lit(THIN_PER_TOLERANCE);
            let shape = if thin { Shape::Vacuum } else { Shape::HalfAngle };
            let ray = |g: T| {
                let (sin_g, cos_g) = sin_cos_half_turn(g);
                let light = along(cos_g, sin_g, fr.n.2);
                match shape {
                    // (π − γ as sin γ's own reduction forms it beyond π/2, so their ratio is exact there)
                    Shape::Vacuum => (light * sin_g / (T::PI() - g)).ln(),
                    Shape::HalfAngle => (light * half_angle(sin_g, cos_g).0).ln(),
                }
            };
            // each piece's map: squared from the light's direction (graded to the layer there
            // beyond LAYER_FROM), geometric away from a narrow lobe's peak where one ends the
            // piece on one side only, else linear
            let starts = [lo, ends[0], ends[1]];
            let map_of = |i: usize| {
                let (a, b) = (starts[i], ends[i]);
                let after = i > 0 && a < T::FRAC_PI_2() && narrow[0];
                let before = i + 1 < parts && b > T::FRAC_PI_2() && narrow[1];
                match (after, before) {
                    (true, false) => Map::Geometric { pole: T::zero(), side: T::one(), near: a, ln_ratio: (b / a).ln() },
                    (false, true) => Map::Geometric { pole: T::PI(), side: -T::one(), near: T::PI() - b, ln_ratio: ((T::PI() - a) / (T::PI() - b)).ln() },
                    _ if !(a > T::zero()) && depth > T::lit(LAYER_FROM) => Map::layer(depth.recip(), b - a),
                    _ if !(a > T::zero()) => Map::Squared,
                    _ => Map::Linear,
                }
            };
            let first = usize::from(!thin);
            for &count in &RAY_NODES[first..] {
                // (sampled in place: the pieces are a few hundred bytes each)
                let (passed, worst) = {
                    let mut pieces = source.borrow_mut();
                    pieces.ends = ends;
                    pieces.shape = shape;
                    for i in 0..parts {
                        pieces.parts[i].sample(count, starts[i], ends[i], map_of(i), ray);
                    }
                    let used = &pieces.parts[..parts];
                    // (and e^{top} finite: a value beyond the range takes the rays one by one)
                    let passed = used.iter().all(|p| p.estimate <= bound && p.exp_top.is_finite());
                    let worst = used.iter().fold(T::zero(), |m, p| m.max(p.estimate));
                    if passed {
                        pieces.count = parts;
                    }
                    (passed, worst)
                };
                if passed {
                    // the outer integral to what the interpolant leaves: L_a within a relative
                    // `spent`, the quadrature within ε of that, (1 + spent)(1 + ε) − 1 ≤ tolerance
                    let spent = worst.exp_m1();
                    let left = (tolerance - spent) / (T::one() + spent);
                    // a narrow Phong lobe clear of the horizon and of ±ℓ: about its own axis
                    if let Some(value) = self.mirror_cone(&fr, alpha_r, &source.borrow(), left) {
                        return (value, rays.get());
                    }
                    let (value, _) = match self.brdf {
                        // a Lambertian node: the arc's closed form times the interpolant's `L_a sin
                        // γ`, with γ's sine and cosine from γ/2's (`lambert_node`)
                        Brdf::Lambert { albedo } => {
                            let (pieces, scale) = (source.borrow(), T::lit(2.0) * albedo * T::FRAC_1_PI());
                            let mut lambert = |x: T| weighted_at(&piece, |g| lambert_node(fr.n, g, |_, c, _| pieces.light_sin(g, || c)) * scale, x);
                            crate::extended::adaptive_by(&rule_of, &mut lambert, &knots[..=n], left, max_panels)
                        }
                        Brdf::Phong { .. } => crate::extended::adaptive_by(&rule_of, &mut mapped, &knots[..=n], left, max_panels),
                    };
                    return (value, rays.get());
                }
            }
        }
        let (value, _) = crate::extended::adaptive_by(rule_of, &mut mapped, &knots[..=n], tolerance, max_panels);
        (value, rays.get())
    }
}

/// The light factor of several rays that share a panel in the light angle, weighted:
/// `Σ_j w_j D(d_el,j sin θ + d_c,j cos θ)` ([`SurfaceScene::arc_sum`]).
struct ArcSum<'a, T, D> {
    light: &'a D,
    /// `(d_el, d_c)` of each ray.
    rays: &'a [(T, T)],
    /// `w` of each ray.
    weights: &'a [T],
}

/// A surface point's rays about a light's axis at one `γ`, on their shared panel in the light
/// angle ([`SurfaceScene::arc`]).
struct Arc<T> {
    plan: crate::angle::Plan<T>,
    /// Their canonical form, `(d_el, d_c)` left 0.
    g: Canonical<T>,
    /// Each ray's `(d_el, d_c)`.
    rays: [(T, T); MAX_INTERPOLATED_DEGREE + 1],
    /// The rules start at 16 nodes, as `default_panels` takes its rays (else 8).
    sixteen: bool,
}

impl<T: Real, D: LightDistribution<T>> crate::angle::Emission<T> for ArcSum<'_, T, D> {
    fn at<const N: usize>(&self, angles: &[(T, T); N]) -> [T; N] {
        let mut sum = [T::zero(); N];
        for (&(d_el, d_c), &w) in self.rays.iter().zip(self.weights) {
            for (acc, d) in sum.iter_mut().zip(crate::angle::along(self.light, d_el, d_c, angles)) {
                *acc = *acc + w * d;
            }
        }
        sum
    }
}

/// The largest gap `|μ*| − 1` of a phase function's singularity past `μ = ±1` whose lobe the
/// default path cuts the outer integral at ([`SurfaceScene::air_light_counted`]): a gap of 0.01,
/// a lobe `√(2·gap)` = 0.14 wide (Henyey–Greenstein `|g|` ≳ 0.87). Measured on
/// tests/reference/surface.jsonl at tolerance 1e-1: uncut, a `g = 0.95` point was 4.8e-3 off
/// (28 rays; 4.4e-5 cut, 28 rays); cutting from a gap of 0.1 (`|g|` ≳ 0.64) cost `near` and
/// `phong` 20 % more instructions with no error that needed it (docs/DESIGN.md §11). Beyond such
/// a lobe the rays' interpolant maps its piece geometrically in the distance from the peak.
pub const PHASE_LOBE_GAP: f64 = 0.01;

/// The optical distance `σt·d` to the light beyond which [`RayInterpolant`] maps a piece from
/// the light's direction by [`Map::Layer`], graded to the layer of width `1/(σt·d)` there,
/// instead of [`Map::Squared`]: on tests/reference/surface.jsonl the points of `σt·d` 2.0 and
/// 2.8 pass at 6 nodes squared, those of 5.6–17 only at 12 (so they took a ray at every outer
/// node, 14, instead), graded at 6; below it the grading cost 6 nodes more often than it saved
/// (docs/DESIGN.md §11).
const LAYER_FROM: f64 = 3.0;

/// The node counts of [`RayInterpolant`] tried in turn before a ray at every outer node: from
/// the first only where [`THIN_PER_TOLERANCE`] predicts it passes, else from the second.
const RAY_NODES: [usize; 3] = [4, 6, 12];

/// `σt·d / tolerance` up to which the rays' interpolant of a point in isotropic fog takes
/// [`Shape::Vacuum`] and starts from 4 nodes instead of 6: `q` then varies by `O(σt·d)` only.
/// Passing, 4 save 2 rays; failing, they cost 4 more, so they pay where they pass more than two
/// times in three. Passed at 4, of 40 Lambertian points per `σt·d` (the light at distance 1,
/// 0.04 to 3.06 from the normal; 4 tried at every depth, the points of `cargo run --release -p
/// airlight-tests --example surface_rays`): at outer tolerance 1e-1 all 40 up to `σt·d = 0.03`,
/// 39 at 0.1, 30 at 0.3, 19 at 0.6, 11 at 1; at 5e-2 all up to 0.03, 18 at 0.1, 3 at 0.3 — so
/// the bound, 0.15 and 0.075 there, stays where they pass nearly always (docs/DESIGN.md §11). A
/// prediction of cost only: the estimate decides.
const THIN_PER_TOLERANCE: f64 = 1.5;

/// The finest outer tolerance at which [`RayInterpolant`] is tried: finer, its 12 nodes rarely
/// pass, and the rays it spent are lost (docs/DESIGN.md §11).
const INTERPOLATED_FROM: f64 = 5e-2;

/// The Phong exponent from which the default path's outer integral is not cut where the mirror
/// direction's arcs open or close (its turning points, and where `n·ω = 0` crosses `r·ω = 0`): the inner
/// integral has `|γ − γ*|^{n + 1/2}` there, from `n = 4` at least four times differentiable.
/// Measured over 120 random Phong points (`n` 1 to 12, `σt·d` 0.01 to 30, isotropic and
/// Henyey–Greenstein `g` 0.3, 0.8): the default path's values move by at most 1.2e-11 (`n` =
/// 4), the errors at outer tolerances 1e-1 … 1e-3 stay within a fiftieth of them, and 15–22 %
/// fewer rays are spent (docs/DESIGN.md §11).
const SMOOTH_MIRROR_FROM: f64 = 4.0;

/// The Phong exponent up to which the default path's outer integral is not cut at the lobe's extent
/// (`α_r ± 1.5/√n`, `± 4/√n`) at outer tolerance 1e-1: a lobe at least `1.5/√8 ≈ 0.53` wide is
/// smooth on the scale of the outer pieces, which its cuts only multiply (finer tolerances keep
/// them, for the adaptive rule's first split). Measured over 120 random Phong points (`n` 1 to
/// 12, as [`SMOOTH_MIRROR_FROM`]) at 1e-1: 5 % fewer rays, the largest error 2.0e-3; on the
/// `phong_broad` references 23 % fewer instructions a point (docs/DESIGN.md §11).
const BROAD_LOBE_BELOW: f64 = 8.0;

/// The largest of [`RAY_NODES`].
const MAX_RAY_NODES: usize = RAY_NODES[RAY_NODES.len() - 1];

/// The most pieces [`SurfaceScene::arc_pieces`] splits an arc's panel in the light angle into.
const MAX_ARC_PIECES: usize = 16;

/// `q(γ)` ([`RayInterpolant`]) on the outer range as up to three interpolants, the `i`-th ending
/// at `ends[i]` (the first starting at the range's start), split where a phase lobe narrower
/// than [`SMOOTH_PHASE_GAP`] allows makes one of `L_a` at `γ = 0` or `π`.
#[derive(Clone, Copy)]
struct RayPieces<T> {
    ends: [T; 3],
    count: usize,
    shape: Shape,
    parts: [RayInterpolant<T>; 3],
}

/// What the interpolated `q(γ) = ln(L_a(γ) sin γ / w(γ))` divides out. `Vacuum`: `w = π − γ`,
/// the shape of `L_a sin γ` with an isotropic phase function as `σt·d → 0` (the angle the ray
/// subtends at the light: `L_a → σs I/(4π) · (π − γ)/(d sin γ)`), so that `q` carries only the
/// extinction's effect, `O(σt·d)` — in thin isotropic fog, where 4 nodes then pass
/// ([`THIN_PER_TOLERANCE`]; from `σt·d` 2–3 on, where the layer at the light's direction shapes
/// `L_a`, one or two in 40 points more took 18 rays with it at tolerances 1e-1 and 5e-2). Else
/// `HalfAngle`: `w = 2 cos(γ/2)`, `q = ln(L_a sin(γ/2))`. Both keep `q` finite on all of `[0, π]`
/// (docs/DESIGN.md §11).
#[derive(Clone, Copy, PartialEq)]
enum Shape {
    Vacuum,
    HalfAngle,
}

impl<T: Real> RayPieces<T> {
    /// No pieces (`count` 0): a ray at every outer node.
    fn none() -> Self {
        RayPieces { ends: [T::zero(); 3], count: 0, shape: Shape::HalfAngle, parts: [RayInterpolant::none(); 3] }
    }

    /// `L_a(γ) sin γ = w(γ) e^{q(γ)}` from the interpolant ([`Shape`], [`RayPieces::exp_at`]),
    /// with `cos(γ/2)` formed only where `w` needs it.
    fn light_sin(&self, gamma: T, cos_half: impl FnOnce() -> T) -> T {
        let w = match self.shape {
            Shape::Vacuum => T::PI() - gamma,
            Shape::HalfAngle => T::lit(2.0) * cos_half(),
        };
        w * self.exp_at(gamma)
    }

    /// `L_a(γ)` itself at `γ = arccos(cos_g)`: `(π − γ) e^q / sin γ` or `e^q / sin(γ/2)`
    /// ([`Shape`]), one square root either way.
    fn light(&self, cos_g: T) -> T {
        let gamma = cos_g.acos();
        let value = self.exp_at(gamma);
        match self.shape {
            Shape::Vacuum => value * (T::PI() - gamma) / ((T::one() - cos_g) * (T::one() + cos_g)).sqrt(),
            Shape::HalfAngle => value / ((T::one() - cos_g) * T::lit(0.5)).sqrt(),
        }
    }

    /// `e^{q(γ)}` from the interpolant whose piece holds `γ`.
    fn exp_at(&self, gamma: T) -> T {
        let i = if self.count > 1 { self.ends[..self.count - 1].iter().filter(|&&end| gamma >= end).count() } else { 0 };
        self.parts[i].exp_at(gamma)
    }
}

/// The smallest gap `|μ*| − 1` of a phase function's singularity past `μ = ±1` at which
/// `L_a(γ)` is interpolated across the phase function's lobe at `γ = 0` or `π` (Henyey–Greenstein
/// `|g| ≲ 0.64`); a narrower lobe splits the interpolated range at 4 lobe widths `√(2·gap)` from
/// its peak (`SurfaceScene::air_light_counted`; docs/DESIGN.md §11).
const SMOOTH_PHASE_GAP: f64 = 0.1;

/// `q(γ) = ln(L_a(γ) sin γ / w(γ))` ([`Shape`]) of a light without an axis on the outer range
/// `[lo, hi]` (finite on the whole of `[0, π]`: `L_a` grows like `1/γ` towards the light and is
/// finite away from it), interpolated at the Chebyshev points of the first kind (inside the range: none on the
/// light's direction `γ = 0`; their cosines directly, for the accuracy of the nodes, by
/// `sin_cos_quarter` in the lower half and by symmetry in the upper; the series by
/// `chebyshev_series`) in `τ ∈ [−1, 1]`, `γ = lo + (hi − lo)·(1 +
/// τ)/2` — or its square where the range starts at `γ = 0`, where `L_a sin γ` has a `γ ln γ`
/// term (the ray passing the light, scaled by `σt·d`), graded to the layer there in a thick
/// medium, or geometric beyond a narrow phase lobe ([`Map`]). `estimate`: the interpolant's largest
/// error, `2 Σ_{k ≥ M} |c_k|` (Trefethen, Approximation Theory and Approximation Practice, Thm.
/// 4.2) with the tail summed from the last two coefficients, `last`, at the decay they show but
/// at least `M/8` of them (an algebraic tail's; `∞` where they fall by less than half from the
/// two before — at `M = 4`, where those would hold the mean `c_0`, from the pair one degree
/// before, the ratio squared): an error `e` of `q` is one of `e^e − 1` relative in `L_a`, wherever it lies.
/// `top = c_0 + Σ_{k≥1} |c_k|` bounds the interpolant from above (`|T_k| ≤ 1`), so that
/// `e^{q − top}` takes an exponential of a non-positive argument.
#[derive(Clone, Copy)]
struct RayInterpolant<T> {
    lo: T,
    width: T,
    map: Map<T>,
    count: usize,
    coefficients: [T; MAX_RAY_NODES],
    estimate: T,
    top: T,
    exp_top: T,
}

impl<T: Real> RayInterpolant<T> {
    /// An interpolant not yet sampled.
    fn none() -> Self {
        let zero = T::zero();
        RayInterpolant { lo: zero, width: zero, map: Map::Linear, count: 0, coefficients: [zero; MAX_RAY_NODES], estimate: T::infinity(), top: zero, exp_top: zero }
    }

    /// Samples `f` at `count` nodes of `[lo, hi]` in `map` (in place).
    fn sample(&mut self, count: usize, lo: T, hi: T, map: Map<T>, f: impl Fn(T) -> T) {
        let width = hi - lo;
        let mut values = [T::zero(); MAX_RAY_NODES];
        let mut nodes = [T::zero(); MAX_RAY_NODES];
        let m = T::from(count).unwrap_or(T::one());
        for j in 0..count {
            // the upper half by symmetry, cos(π − θ) = −cos θ: half the cosines
            let tau = if 2 * j >= count { -nodes[count - 1 - j] } else { sin_cos_quarter(T::PI() * (T::from(j).unwrap_or(T::zero()) + T::lit(0.5)) / m).1 };
            let s = (T::one() + tau) * T::lit(0.5);
            let g = match map {
                Map::Linear => lo + width * s,
                Map::Squared => lo + width * s * s,
                Map::Layer { near, rate } => {
                    let x = (rate * s * T::lit(0.5)).sinh();
                    lo + near * x * x
                }
                Map::Geometric { pole, side, near, ln_ratio } => pole + side * near * (s * ln_ratio).exp(),
            };
            nodes[j] = tau;
            values[j] = f(g);
        }
        let coefficients = &mut self.coefficients;
        coefficients.fill(T::zero());
        chebyshev_series(&nodes, &values, &mut coefficients[..count]);
        let last = coefficients[count - 1].abs() + coefficients[count - 2].abs();
        // the pair before the last two, or at 4 nodes (where it would hold the mean c_0, no
        // measure of the decay) the pair one degree before, its ratio squared
        let lag = if count >= 6 { 2 } else { 1 };
        let before = coefficients[count - 1 - lag].abs() + coefficients[count - 2 - lag].abs();
        let ratio = if last < before { last / before } else { T::one() };
        let q2 = if lag == 2 { ratio } else { ratio * ratio };
        // the tail as geometric at the decay shown, but no less than an algebraic one's: the
        // γ ln γ term makes the coefficients fall like a power of k in the squared map, where the
        // error of the M-node interpolant measured 0.26 and 2.0 times `last` at M = 6 and 12
        // (`tests::ray_interpolant_is_exact_for_its_degree_and_its_estimate_holds`)
        let factor = (q2 / (T::one() - q2)).max(m * T::lit(0.125));
        let estimate = if q2 < T::lit(0.5) { T::lit(2.0) * last * factor } else { T::infinity() };
        let top = coefficients[1..count].iter().fold(coefficients[0], |acc, c| acc + c.abs());
        (self.lo, self.width, self.map, self.count, self.estimate, self.top, self.exp_top) = (lo, width, map, count, estimate, top, top.exp());
    }

    /// `e^{q(γ)}` from the interpolant, as `e^{q − top} e^{top}` ([`exp_nonpositive_polynomial`]:
    /// within 2e-8, far below the tolerances from [`INTERPOLATED_FROM`] it serves).
    fn exp_at(&self, gamma: T) -> T {
        exp_nonpositive_polynomial(self.at(gamma) - self.top) * self.exp_top
    }

    /// The interpolant at `γ` (Clenshaw's recurrence, [`chebyshev_sum`]).
    fn at(&self, gamma: T) -> T {
        let x = ((gamma - self.lo) / self.width).max(T::zero()).min(T::one());
        let s = match self.map {
            Map::Linear => x,
            Map::Squared => x.sqrt(),
            // 2 asinh(√y) = 2 ln(√y + √(1 + y)), y = (γ − lo)/near (the logarithm within ε
            // absolutely, so `s` within a few `ε/rate`; with the library's asinh an f32
            // `lambert_thick` point took 2 141 ns against 1 766)
            Map::Layer { near, rate } => {
                let y = (gamma - self.lo).max(T::zero()) / near;
                ((y.sqrt() + (y + T::one()).sqrt()).ln() * T::lit(2.0) / rate).min(T::one())
            }
            Map::Geometric { pole, near, ln_ratio, .. } => (((gamma - pole).abs() / near).ln() / ln_ratio).max(T::zero()).min(T::one()),
        };
        chebyshev_sum(&self.coefficients[..self.count], s + s - T::one())
    }
}

/// How a piece of the outer range is mapped from `s ∈ [0, 1]` (the Chebyshev variable `τ = 2s −
/// 1` of [`RayInterpolant`]) to `γ ∈ [lo, lo + width]`.
#[derive(Clone, Copy, PartialEq)]
enum Map<T> {
    /// `γ = lo + width·s`.
    Linear,
    /// `γ = lo + width·s²`: from the light's direction, where `L_a sin γ` has a `γ ln γ` term.
    Squared,
    /// `γ = lo + near·sinh²(rate·s/2)`: from the light's direction in a thick medium, squared
    /// within the layer of width `near` there (`L_a` goes from `∝ 1/γ` to `∝ 1/(σt·d·γ²)` across
    /// it, where `σt·d·sin γ ≈ 1`) and geometric beyond, where `q ≈ −ln γ` is linear in `s`.
    Layer { near: T, rate: T },
    /// `γ = pole + side·near·e^{s·ln_ratio}`: the distance from a phase lobe's peak `pole` (`0`
    /// or `π`, `side` `±1` towards the range) growing geometrically from `near` to `near·e^{ln_ratio}`
    /// — beyond a lobe, where Henyey–Greenstein's `ln P ≈ −3 ln δ` of the distance `δ` is linear
    /// in `s`.
    Geometric { pole: T, side: T, near: T, ln_ratio: T },
}

impl<T: Real> Map<T> {
    /// [`Map::Layer`] over `[lo, lo + width]` for a layer of width `near`.
    fn layer(near: T, width: T) -> Self {
        Map::Layer { near, rate: T::lit(2.0) * (width / near).sqrt().asinh() }
    }
}

/// What an outer cut of a surface's integral is: where an arc opens or closes (`|γ − γ*|^{3/2}`),
/// a Phong lobe's peak or extent, or a beam's axis or the phase function's lobe's extent (all
/// smooth points of the integrand).
#[derive(Clone, Copy, PartialEq)]
enum Cut {
    Kink,
    Lobe,
    Peak,
}

/// `(γ, dγ/dt)` at `t ∈ [0, 1]` on the outer piece `[a, b]`: where an arc opens or closes at an
/// end the inner integral goes like `|γ − γ*|^{3/2}`, smooth in `t` where `γ − γ*` goes like
/// `t²` — the smoothstep `a + (b − a)(3t² − 2t³)` with both ends such, `a + (b − a)t²` or
/// `b − (b − a)(1 − t)²` with one; between smooth cuts `γ` itself (docs/DESIGN.md §11).
fn piece_map<T: Real>(a: T, b: T, smooth_a: bool, smooth_b: bool, t: T) -> (T, T) {
    let (w, s) = (b - a, T::one() - t);
    match (smooth_a, smooth_b) {
        (false, false) => (a + w * t * t * (T::lit(3.0) - t - t), w * T::lit(6.0) * t * s),
        (false, true) => (a + w * t * t, w * (t + t)),
        (true, false) => (b - w * s * s, w * (s + s)),
        (true, true) => (a + w * t, w),
    }
}

/// The edges `x` brought into `[φ₀ − π, φ₀ + π]` and sorted, with the circle's two ends
/// `φ₀ ± π` (the point opposite `φ₀`, where no arc about `φ₀` ends) added: consecutive pairs
/// tile the circle.
fn sorted_circle<T: Real>(x: &mut [T], phi0: T) -> [T; 10] {
    let two_pi = T::PI() + T::PI();
    let mut out = [phi0 + T::PI(); 10];
    out[0] = phi0 - T::PI();
    for (i, v) in x.iter().enumerate() {
        let mut y = *v;
        while y < phi0 - T::PI() {
            y = y + two_pi;
        }
        while y > phi0 + T::PI() {
            y = y - two_pi;
        }
        out[i + 1] = y;
    }
    let used = &mut out[..x.len() + 2];
    used.sort_unstable_by(|a, b| a.partial_cmp(b).unwrap_or(core::cmp::Ordering::Equal));
    out
}


#[cfg(test)]
mod tests {
    extern crate std;
    use super::*;
    use crate::extended::{adaptive, GAUSS_KRONROD_15};

    /// [`open_ray_isotropic`] against mpmath's quadrature of its integral in `Y`, `e^{−σt·d} · 2∫_0^∞
    /// e^{−Hx}/(1 + (x + tan(γ/2))²) dx`, `H = σt·d sin γ` (30 digits; tests/reference/gen_open_ray.py,
    /// which also checks them against mpmath's own `E1`), at `γ` and `σt·d` exact in binary32, from
    /// `σt·d` 1e-3 to 40 and `γ` from 0.016 to 3.09: Ein's series inside its region and the
    /// continued fraction outside. Held to `(16 + 4σt·d + 8|w|/(π − γ))ε` relative: `γ/2`'s sine
    /// and cosine and `cos γ` are each within an ulp, and `K` moves with them by about `2σt·d`
    /// times their relative error (`w ∝ σt·d sin(γ/2)` in the exponent), plus some sixteen
    /// roundings of the sum — whose terms, `Ein`'s imaginary part among them, are within a few
    /// ε of `|w|`, where towards `γ = π` the value is `∝ π − γ` (measured: f64 within 85 ε at
    /// `(3.09, 0.5)`, where the bound is 185, and 17 ε elsewhere; f32 within 9.3 ε).
    #[test]
    fn open_ray_against_quadrature() {
        const CASES: [(f64, f64, f64); 12] = [
            (0.015625, 0.0009765625, 3.1225658165588597636),
            (0.3125, 0.046875, 2.5771827575302356388),
            (1.0, 0.146484375, 1.4145308812684338275),
            (2.0, 0.25, 0.50933699804247086569),
            (3.09375, 0.5, 0.011714756390456984494),
            (0.5, 1.5, 0.27194222251519337544),
            (1.5, 3.0, 0.013441731234603445708),
            (2.5, 1.0, 0.067354346769070556507),
            (0.0625, 17.0, 4.880410762682015665e-8),
            (1.0, 17.0, 4.1978499051926505505e-9),
            (2.875, 8.0, 5.025967639665803184e-6),
            (3.0, 40.0, 7.3502081809547905998e-21),
        ];
        fn check<T: Real>() -> f64 {
            let mut worst = 0.0f64;
            for (g, depth, exact) in CASES {
                // (the library's, each within an ulp relatively; the kernel's cosine of γ/2 is
                // within a few ε absolutely, which near γ = π is more of it)
                let (s, c, cos_g) = (T::lit((g * 0.5).sin()), T::lit((g * 0.5).cos()), T::lit(g.cos()));
                let value = open_ray_isotropic(T::lit(depth), T::lit(g), (s, c, cos_g), open_ray_terms(T::lit(depth), T::zero())).to_f64_exact();
                let error = ((value - exact) / exact).abs() / T::epsilon().to_f64_exact();
                // |w| = 2σt·d sin(γ/2)
                let bound = 16.0 + 4.0 * depth + 8.0 * 2.0 * depth * (g * 0.5).sin() / (core::f64::consts::PI - g);
                assert!(error <= bound, "γ = {g}, σt·d = {depth}: {value:e} against {exact:e}, {error:.1} ε");
                worst = worst.max(error);
            }
            worst
        }
        std::println!("open ray: f64 within {:.1} ε, f32 within {:.1} ε", check::<f64>(), check::<f32>());
    }

    /// [`open_ray_terms`]' tail bound holds: at `|w| = 2σt·d` (every angle of a half circle)
    /// `Ein`'s first `n` terms are within a thousandth of the tolerance of all 40 (the series
    /// to far below f64's ε there), for `σt·d` from 0.005 to 0.45 and tolerances 1e-1 to 1e-9;
    /// and with one term fewer the tail at `w = −r` (its terms all of one sign there) is more than
    /// half that, so the count is no larger than the bound's slack needs.
    #[test]
    fn open_ray_terms_bound_the_tail() {
        let horner = |n: usize, w: C<f64>| EIN_COEFFS[..n].iter().rev().fold(C::new(0.0, 0.0), |sum, &k| sum * w + k) * w;
        for depth in [0.005, 0.05, 0.15, 0.3, 0.45] {
            for tolerance in [1e-1, 1e-3, 1e-5, 1e-9] {
                let n = open_ray_terms(depth, tolerance);
                let r = 2.0 * depth;
                assert!(n < EIN_COEFFS.len(), "σt·d {depth}, tolerance {tolerance:e}: {n} terms");
                for k in 0..=16 {
                    let w = C::from_polar(r, -core::f64::consts::PI * k as f64 / 16.0);
                    let tail = (horner(n, w) - horner(EIN_COEFFS.len(), w)).norm();
                    assert!(tail <= tolerance * 1e-3, "σt·d {depth}, tolerance {tolerance:e}, {n} terms: tail {tail:e}");
                }
                if n > 1 {
                    let w = C::new(-r, 0.0);
                    let tail = (horner(n - 1, w) - horner(EIN_COEFFS.len(), w)).norm();
                    assert!(tail > tolerance * 1e-3 * 0.5, "σt·d {depth}, tolerance {tolerance:e}: {} terms leave {tail:e}", n - 1);
                }
            }
        }
    }

    /// `RayInterpolant` reproduces a polynomial of degree `M − 1` in `τ` from its `M` values (to
    /// rounding: within `8Mε` of `Σ|c_k|`, the Lebesgue constant of the first-kind points being
    /// below 3 here), on every map; and on smooth functions — an entire one, `γ ln γ`-like ones on
    /// a range from `γ = 0`, the shape its squared map is for, and the logarithm of a
    /// Henyey–Greenstein lobe (`g = 0.95`) on its piece from `γ = 0` and beyond it, in the
    /// geometric map (where `SurfaceScene::air_light_counted` splits at 4 lobe widths) — its
    /// estimate bounds the error it makes at 400 points of the range wherever the estimate is
    /// finite; at every node count of `RAY_NODES` (at 4, errors 0.14–0.17 of the estimate).
    #[test]
    fn ray_interpolant_is_exact_for_its_degree_and_its_estimate_holds() {
        let sampled = |count: usize, lo: f64, hi: f64, map: Map<f64>, f: &dyn Fn(f64) -> f64| {
            let mut p = RayInterpolant::none();
            p.sample(count, lo, hi, map, f);
            p
        };
        let pi = core::f64::consts::PI;
        let forward = |near: f64, far: f64| Map::Geometric { pole: 0.0, side: 1.0, near, ln_ratio: (far / near).ln() };
        let (g0, reach) = (0.95f64, 4.0 * (2.0 * ((1.0 - 0.95f64).powi(2) / 1.9)).sqrt());
        let hg = move |g: f64| -1.5 * ((1.0 - g0).powi(2) + 2.0 * g0 * (1.0 - g.cos())).ln();
        for count in RAY_NODES {
            let maps = [
                (0.3, 2.5, Map::Linear),
                (0.0, 2.5, Map::Squared),
                (0.2, 2.5, forward(0.2, 2.5)),
                (0.3, pi - 0.2, Map::Geometric { pole: pi, side: -1.0, near: 0.2, ln_ratio: ((pi - 0.3) / 0.2).ln() }),
                (0.0, 2.5, Map::layer(0.05, 2.5)),
            ];
            for (lo, hi, map) in maps {
                let tau = |g: f64| {
                    let x: f64 = (g - lo) / (hi - lo);
                    let s = match map {
                        Map::Linear => x,
                        Map::Squared => x.sqrt(),
                        Map::Geometric { pole, near, ln_ratio, .. } => ((g - pole).abs() / near).ln() / ln_ratio,
                        Map::Layer { near, rate } => 2.0 * (g / near).sqrt().asinh() / rate,
                    };
                    2.0 * s - 1.0
                };
                // Σ_k c_k τ^k, c_k = (−0.7)^k: degree M − 1
                let poly = |g: f64| (0..count).rev().fold(0.0, |acc, k| acc * tau(g) + (-0.7f64).powi(k as i32));
                let p = sampled(count, lo, hi, map, &poly);
                let sum: f64 = (0..count).map(|k| 0.7f64.powi(k as i32)).sum();
                for i in 0..=400 {
                    let g = lo + (hi - lo) * i as f64 / 400.0;
                    let err = (p.at(g) - poly(g)).abs();
                    assert!(err <= 8.0 * count as f64 * f64::EPSILON * sum, "M {count}, γ {g}: {err:e}");
                }
            }
            // q of a thick medium's layer at the light's direction, of width γ₀ = 1/(σt·d) =
            // 0.05: L_a = 1/(γ √(1 + (γ/γ₀)²)), ∝ 1/γ within it and ∝ γ₀/γ² beyond
            let layer = |g: f64| if g > 0.0 { ((0.5 * g).sin() / g).ln() } else { 0.5f64.ln() } - 0.5 * (g / 0.05).powi(2).ln_1p();
            let cases: [(f64, f64, Map<f64>, &dyn Fn(f64) -> f64); 6] = [
                (0.3, 2.5, Map::Linear, &|g: f64| (0.5 * g).exp() * g.cos()),
                (0.0, 2.5, Map::Squared, &|g: f64| 1.0 + 0.05 * g * (g + 1e-300).ln() + 0.3 * g),
                (0.0, 3.0, Map::Squared, &|g: f64| (3.0 - g) * (1.0 - 0.2 * g * (g + 1e-300).ln())),
                (0.0, reach, Map::Squared, &hg),
                (reach, 2.5, forward(reach, 2.5), &hg),
                (0.0, 2.5, Map::layer(0.05, 2.5), &layer),
            ];
            for (lo, hi, map, f) in cases {
                let p = sampled(count, lo, hi, map, f);
                if !p.estimate.is_finite() {
                    continue;
                }
                let worst = (0..=400).map(|i| lo + (hi - lo) * i as f64 / 400.0).map(|g| (p.at(g) - f(g)).abs()).fold(0.0, f64::max);
                std::println!("M {count} on [{lo:.3}, {hi}]: largest error {worst:.1e}, estimate {:.1e}", p.estimate);
                assert!(worst <= p.estimate, "M {count} on [{lo}, {hi}]: {worst:e} > {:e}", p.estimate);
            }
        }
    }

    /// `lobatto_coefficients` and `chebyshev_sum` reproduce a polynomial of degree `p` from its
    /// values at the `p + 1` points exactly (to rounding), between the points and at them, for
    /// every degree up to [`MAX_INTERPOLATED_DEGREE`]: `Σ_k c_k x^k` with coefficients of both
    /// signs, against its Horner value, within `4(p + 1)ε` of `Σ|c_k|` (each `b_k` a sum of
    /// `p + 1` values `≤ Σ|c_k|` with weights summing to at most 2, and Clenshaw's recurrence
    /// within a few `(p + 1)ε` of `Σ|b_k|`); from one point fewer it is off by at least the best
    /// approximation's `|c_p| 2^{1−p}`.
    #[test]
    fn lobatto_interpolant_is_exact_for_its_degree() {
        let chebyshev_lobatto = |values: &[f64], points: &[f64], x: f64| {
            let mut b = [0.0; MAX_INTERPOLATED_DEGREE + 1];
            lobatto_coefficients(values, points, &mut b);
            chebyshev_sum(&b[..values.len()], x)
        };
        let poly = |c: &[f64], x: f64| c.iter().rev().fold(0.0, |a, &k| a * x + k);
        for p in 0..=MAX_INTERPOLATED_DEGREE {
            let c: std::vec::Vec<f64> = (0..=p).map(|k| ((k * 7919 % 13) as f64 - 6.5) / 3.0).collect();
            let size: f64 = c.iter().map(|k| k.abs()).sum();
            let values: std::vec::Vec<f64> = (0..=p).map(|j| poly(&c, (core::f64::consts::PI * j as f64 / p.max(1) as f64).cos())).collect();
            for i in 0..=200 {
                let x = -1.0 + i as f64 / 100.0;
                let err = (chebyshev_lobatto(&values, &lobatto_points::<f64>(p), x) - poly(&c, x)).abs();
                assert!(err <= 4.0 * (p + 1) as f64 * f64::EPSILON * size, "p = {p}, x = {x}: {err:e}");
            }
            if p >= 2 {
                // the same data without its last point cannot hold a polynomial of degree p
                let short: std::vec::Vec<f64> = (0..p).map(|j| poly(&c, (core::f64::consts::PI * j as f64 / (p - 1) as f64).cos())).collect();
                let worst = (0..=200).map(|i| -1.0 + i as f64 / 100.0).map(|x| (chebyshev_lobatto(&short, &lobatto_points::<f64>(p - 1), x) - poly(&c, x)).abs()).fold(0.0, f64::max);
                // no polynomial of degree p − 1 comes closer to c_p x^p + … than |c_p| 2^{1−p}
                // (the monic Chebyshev polynomial's norm)
                let bound = c[p].abs() * 2f64.powi(1 - p as i32);
                assert!(worst >= bound * (1.0 - 1e-6), "p = {p}: degree {p} data one point short interpolates within {worst:e}");
            }
        }
    }

    /// A Lambertian and a Phong point lit by `c^p` beams (p = 2 … 32) in HG fog: the hemisphere
    /// with `L_a` interpolated from `p + 1` rays per `γ` against the same integral with a ray
    /// at every inner node (`MAX_INTERPOLATED_DEGREE` bypassed by a spot-free distribution
    /// that declares no degree), both at the default tolerance 1e-10: within 1e-9.
    #[test]
    fn interpolated_beams_match_a_ray_per_node() {
        use crate::glam::DVec3;
        use crate::light::TwoLobed;
        use crate::phase::HenyeyGreenstein;
        #[derive(Clone)]
        struct Undeclared(TwoLobed<f64>);
        impl LightDistribution<f64> for Undeclared {
            fn axis(&self) -> [f64; 3] {
                self.0.axis()
            }
            fn eval<S: crate::scalar::Scalar<f64>>(&self, c: S) -> S {
                self.0.eval(c)
            }
        }
        let surface = Surface { position: DVec3::new(0.3, -0.2, 0.1), normal: DVec3::new(0.2, 1.0, -0.3) };
        let medium = Medium { sigma_s: 0.04, sigma_t: 0.07 };
        let phase = HenyeyGreenstein { g: 0.7 };
        for (i, power) in [2u32, 4, 8, 16, 32].into_iter().enumerate() {
            let axis = DVec3::new(0.6, -0.7 + 0.2 * i as f64, 0.4);
            let position = DVec3::new(-0.8, 1.4, 0.6 + 0.1 * i as f64);
            let beam = TwoLobed { axis, power };
            let brdfs = [Brdf::Lambert { albedo: 0.5 }, Brdf::Phong { k_s: 0.7, exponent: 30.0, view: DVec3::new(0.1, 0.8, 0.5) }];
            for brdf in brdfs {
                let fast = SurfaceScene::new(surface, brdf, PointLight { position, intensity: 20.0, distribution: beam }, medium, phase).unwrap();
                let slow = SurfaceScene::new(surface, brdf, PointLight { position, intensity: 20.0, distribution: Undeclared(beam) }, medium, phase).unwrap();
                let ((a, rays_a), (b, rays_b)) = (fast.air_light_counted(1e-10), slow.air_light_counted(1e-10));
                let err = (a - b).abs() / b;
                std::println!("p = {power}: {a:e} ({rays_a} rays) against {b:e} ({rays_b} rays): {err:.1e}");
                assert!(err <= 1e-9, "p = {power}, {brdf:?}: {a} against {b} ({err:e})");
                assert!(rays_a < rays_b, "p = {power}: {rays_a} rays against {rays_b}");
            }
        }
    }

    /// An arc of rays about a beam's axis on its shared panel (`SurfaceScene::arc`) against the
    /// rays one by one, each to 1e-12: Lambertian points lit by `c^p` beams (p = 2 … 32) in HG
    /// fog, thin and thicker, at 40 angles `γ` across the hemisphere, at tolerances 1e-2 and
    /// 1e-3. `arc_sum` within the tolerance of the rays' weighted sum where it is taken, and
    /// taken at 95 % of the nodes or more; `arc_rays` within it of each ray where a rule passed
    /// on that ray, and passed on 95 % of them or more (on the whole panel alone, before
    /// `SurfaceScene::arc_pieces`: 551 of 620 nodes and 6 709 of 8 188 rays; with its pieces
    /// every one, `--nocapture` prints the counts).
    #[test]
    fn arcs_of_rays_match_the_rays_one_by_one() {
        use crate::glam::DVec3;
        use crate::light::TwoLobed;
        use crate::phase::HenyeyGreenstein;
        let (mut taken, mut tried, mut worst) = (0, 0, 0.0f64);
        let (mut rays_taken, mut rays_tried, mut rays_worst) = (0, 0, 0.0f64);
        for (i, power) in [2u32, 4, 8, 16, 32].into_iter().enumerate() {
            for (sigma_s, sigma_t) in [(0.02, 0.03), (0.2, 0.4)] {
                let surface = Surface { position: DVec3::new(0.3, -0.2, 0.1), normal: DVec3::new(0.2, 1.0, -0.3 + 0.1 * i as f64) };
                let light = PointLight { position: DVec3::new(-0.8, 1.4, 0.6 + 0.1 * i as f64), intensity: 20.0, distribution: TwoLobed { axis: DVec3::new(0.6, -0.7 + 0.2 * i as f64, 0.4), power } };
                let scene = SurfaceScene::new(surface, Brdf::Lambert { albedo: 0.5 }, light, Medium { sigma_s, sigma_t }, HenyeyGreenstein { g: 0.6 }).unwrap();
                let (fr, phys) = (scene.frame(true), Physics::new(&scene.light, &scene.medium, &scene.phase));
                let axis: [f64; 3] = normalize(scene.light.distribution.axis());
                let (axis_l, axis_e1, axis_e2): (f64, f64, f64) = (dot(axis, fr.l), dot(axis, fr.e1), dot(axis, fr.e2));
                let (phi_a, axis_a, p) = (axis_e2.atan2(axis_e1), axis_e1.hypot(axis_e2), power as usize);
                let step = core::f64::consts::PI / p as f64;
                for k in 1..40 {
                    let g = core::f64::consts::PI * k as f64 / 40.0;
                    let (sin_g, cos_g) = g.sin_cos();
                    let (psi_n, _) = half_arc_and_sine(fr.n.0 * cos_g, fr.n.1 * sin_g);
                    if !(psi_n > 0.0) {
                        continue;
                    }
                    let mut weights = [0.0; MAX_INTERPOLATED_DEGREE + 1];
                    lambert_chebyshev_weights(p, fr.n.0 * cos_g, fr.n.1 * sin_g, psi_n, fr.n.2 - phi_a, &lobatto_points::<f64>(p), &mut weights);
                    let each: std::vec::Vec<f64> = (0..=p)
                        .map(|j| {
                            let axis_u = axis_a * (step * j as f64).cos();
                            let ray = Canonical { h: fr.d * sin_g, x_h: fr.d * cos_g, d_el: cos_g * axis_l + sin_g * axis_u, d_c: cos_g * axis_u - sin_g * axis_l, t0: 0.0, t1: f64::INFINITY };
                            default_panels(&ray, &phys, Control { tolerance: 1e-12, ..crate::default_control() }).0
                        })
                        .collect();
                    let exact: f64 = each.iter().zip(&weights).map(|(l, c)| l * c).sum();
                    for tolerance in [1e-2, 1e-3] {
                        let control = Control { tolerance, ..crate::default_control() };
                        tried += 1;
                        let arc = scene.arc(&phys, &fr, cos_g, sin_g, (axis_l, axis_a), &lobatto_points::<f64>(p)[..=p], &control);
                        if let Some(sum) = arc.as_ref().and_then(|arc| scene.arc_sum(&phys, arc, &weights[..=p], &control)) {
                            let err = (sum - exact).abs() / exact.abs();
                            worst = worst.max(err / tolerance);
                            assert!(err <= tolerance, "p = {power}, σt = {sigma_t}, γ = {g}, tolerance {tolerance:e}: {sum:e} against {exact:e} ({err:.1e})");
                            taken += 1;
                        }
                        let mut out = [None; MAX_INTERPOLATED_DEGREE + 1];
                        if let Some(arc) = &arc {
                            scene.arc_rays(&phys, arc, &control, &mut out[..=p]);
                        }
                        for (j, (value, exact)) in out.iter().zip(&each).enumerate() {
                            rays_tried += 1;
                            if let Some(value) = value {
                                let err = (value - exact).abs() / exact.abs();
                                rays_worst = rays_worst.max(err / tolerance);
                                assert!(err <= tolerance, "p = {power}, σt = {sigma_t}, γ = {g}, ray {j}, tolerance {tolerance:e}: {value:e} against {exact:e} ({err:.1e})");
                                rays_taken += 1;
                            }
                        }
                    }
                }
            }
        }
        std::println!("the sum taken at {taken} of {tried} nodes, largest error {worst:.2} of the tolerance; the rays at {rays_taken} of {rays_tried}, {rays_worst:.2}");
        assert!(20 * taken >= 19 * tried, "the sum taken at {taken} of {tried}");
        assert!(20 * rays_taken >= 19 * rays_tried, "the rays taken at {rays_taken} of {rays_tried}");
    }

    /// [`lobe_arcs`] with each rule of [`LOBE_RULES`] against the same integral by adaptive
    /// Gauss–Kronrod 7/15 to 1e-13, split at the arcs' ends and the peak, with the lobe as a
    /// plain power: over random frames (normal, mirror direction, `Δ`; the same for each rule),
    /// 25 angles `γ` each and exponents 0 to 1000, within a tenth of the rule's outer tolerance
    /// of the lobe's integral at its peak `γ = α_r` — for the shaders' [`LOBE_RULE`] 2e-5, a
    /// fifth of their target of 1e-4 of scale, the rest left to the outer integral and the rays
    /// (`--nocapture` prints the largest error per rule and exponent).
    #[test]
    fn lobe_arcs_against_adaptive_quadrature() {
        let pi = core::f64::consts::PI;
        let wrap = |x: f64| if x > pi { x - 2.0 * pi } else if x < -pi { x + 2.0 * pi } else { x };
        for (from, rule) in LOBE_RULES {
            let mut seed = 7u64;
            let mut unit = || {
                seed = seed.wrapping_mul(6364136223846793005).wrapping_add(1442695040888963407);
                (seed >> 11) as f64 / (1u64 << 53) as f64
            };
            for n in [0.0, 0.5, 1.0, 3.0, 10.0, 50.0, 200.0, 1000.0] {
                let mut worst = 0.0f64;
                for _ in 0..40 {
                    let (alpha_n, alpha_r, delta) = (pi * unit(), pi * unit(), pi * (2.0 * unit() - 1.0));
                    let (cn, sn, cr, sr) = (alpha_n.cos(), alpha_n.sin(), alpha_r.cos(), alpha_r.sin());
                    let peak_lobe = |x: f64| (cr * cr + sr * sr * x.cos()).max(0.0).powf(n);
                    let scale = adaptive(&GAUSS_KRONROD_15, &mut |x| peak_lobe(x), &[-pi, 0.0, pi], 1e-13, 48).0;
                    for j in 0..25 {
                        let g = pi * (j as f64 + 0.5) / 25.0;
                        let (cg, sg) = (g.cos(), g.sin());
                        let ((a, b), (c, d)) = ((cn * cg, sn * sg), (cr * cg, sr * sg));
                        let psi_n = half_arc((cn, sn, 0.0), cg, sg);
                        let psi_r = half_arc((cr, sr, 0.0), cg, sg);
                        let got = lobe_arcs(rule, (a, b), (c, d), g - alpha_r, (delta, delta.cos(), delta.sin()), psi_n, n);
                        let f = |x: f64| {
                            let lobe = c + d * x.cos();
                            let clip = a + b * (x - delta).cos();
                            if lobe > 0.0 && clip > 0.0 { clip * lobe.powf(n) } else { 0.0 }
                        };
                        let mut edges = [-pi, 0.0, pi, wrap(delta - psi_n), wrap(delta + psi_n), -psi_r, psi_r];
                        edges.sort_by(|x, y| x.partial_cmp(y).unwrap());
                        let exact = adaptive(&GAUSS_KRONROD_15, &mut |x| f(x), &edges, 1e-13, 48).0;
                        worst = worst.max((got - exact).abs() / scale);
                    }
                }
                std::println!("{} points, n = {n}: largest error {worst:.1e} of the peak's integral", 2 * rule.len());
                assert!(worst <= 0.1 * from, "{} points, n = {n}: lobe_arcs {worst:.1e} off", 2 * rule.len());
            }
        }
    }
}
