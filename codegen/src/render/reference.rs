//! The reference: brute-force adaptive Gauss–Kronrod quadrature of the contract integral
//! (docs/DESIGN.md §1), with none of the kernel's closed forms; and the surface's air-light
//! over the hemisphere of such rays.

use super::world::{Hit, SceneDesc};
use airlight::extended::gauss_kronrod_15;
use airlight::glam::DVec3;
use airlight::light::AnyDistribution;
use airlight::phase::AnyPhase;
use airlight::{LightDistribution, Medium, PhaseFunction, PointLight};

/// Globally adaptive Gauss–Kronrod over `edges` (QUADPACK's QAG strategy): keeps bisecting
/// the panel with the largest error estimate `|K15 − G7|` until the sum of the estimates is
/// at most `rel_tol` of the sum of the values (the integrand is positive, so that bounds the
/// relative error of every part too), or `max_panels` panels.
pub(crate) fn adapt(f: &impl Fn(f64) -> f64, edges: &[f64], rel_tol: f64, max_panels: usize) -> f64 {
    struct Panel {
        a: f64,
        b: f64,
        k: f64,
        err: f64,
    }
    impl PartialEq for Panel {
        fn eq(&self, o: &Self) -> bool {
            self.err == o.err
        }
    }
    impl Eq for Panel {}
    impl PartialOrd for Panel {
        fn partial_cmp(&self, o: &Self) -> Option<std::cmp::Ordering> {
            Some(self.cmp(o))
        }
    }
    impl Ord for Panel {
        fn cmp(&self, o: &Self) -> std::cmp::Ordering {
            self.err.total_cmp(&o.err)
        }
    }
    let panel = |a: f64, b: f64| {
        let (k, g) = gauss_kronrod_15(&mut |x| f(x), a, b);
        Panel { a, b, k, err: (k - g).abs() }
    };
    let mut heap: std::collections::BinaryHeap<Panel> = edges.windows(2).map(|e| panel(e[0], e[1])).collect();
    let (mut total, mut err): (f64, f64) = heap.iter().fold((0.0, 0.0), |(t, e), p| (t + p.k, e + p.err));
    while heap.len() < max_panels && err > rel_tol * total.abs() && total.is_finite() {
        let Some(worst) = heap.pop() else { break };
        let m = 0.5 * (worst.a + worst.b);
        if !(m > worst.a && m < worst.b) {
            heap.push(worst);
            break;
        }
        let (l, r) = (panel(worst.a, m), panel(m, worst.b));
        total += l.k + r.k - worst.k;
        err += l.err + r.err - worst.err;
        heap.push(l);
        heap.push(r);
    }
    // re-sum: the running sums drift by rounding
    heap.iter().map(|p| p.k).sum()
}

/// Relative tolerance of the reference quadrature (per segment, on the `|K15 − G7|` error
/// estimate, which overstates the error of the returned K15 value by orders of magnitude on
/// smooth panels).
pub const REFERENCE_TOL: f64 = 1e-9;

/// Panel budget of the reference quadrature per segment (never reached in the four scenes).
const MAX_PANELS: usize = 4000;

/// `L_m` of one segment by brute-force quadrature of the contract integral (docs/DESIGN.md §1),
///
/// ```text
/// L_m = σs·I·∫_{t0}^{t1} e^{−σt(t−t0)} · e^{−σt r}/r² · D(c) · P(μ) dt,
/// r = |x(t) − p|, c = (x − p)·a/r, μ = −(x − p)·d/r,
/// ```
///
/// with none of the kernel's closed forms: `D` and `P` are evaluated pointwise through
/// [`LightDistribution::eval`] and [`PhaseFunction::eval`] (their definitions). The variable
/// is `u = atan((t − x_h)/h)` (`x_h` the foot of the perpendicular from the light to the ray,
/// `h` its length): `dt/r² = du/h`, so the `1/r²` peak becomes a bounded integrand on a finite
/// interval, `t1 = ∞` included (`u1 = π/2`). It is integrated by adaptive Gauss–Kronrod 7/15
/// from 16 equal starting panels, globally adaptive, until the summed error estimates are at
/// most `rel_tol` of the integral. `+∞` when the light
/// lies on the segment.
pub fn reference_in_scatter(
    origin: DVec3,
    dir: DVec3,
    t0: f64,
    t1: f64,
    light: &PointLight<f64, AnyDistribution<f64>>,
    medium: &Medium<f64>,
    phase: &AnyPhase<f64>,
    rel_tol: f64,
) -> f64 {
    let d = dir.normalize();
    let p = light.position;
    let ax = DVec3::from_array(light.distribution.axis()).normalize();
    let v = p - origin;
    let x_h = v.dot(d);
    let h = (v - d * x_h).length();
    let scale = medium.sigma_s * light.intensity;
    if scale == 0.0 || !(t1 > t0) {
        return 0.0;
    }
    let st = medium.sigma_t;
    if h <= 1e-12 * v.length().max(1.0) {
        if x_h >= t0 && x_h <= t1 {
            return f64::INFINITY;
        }
        // The light on the ray's line outside the segment: `r = |t − x_h|`, no peak inside;
        // integrate in `s ∈ [0, 1)`, `t = t0 + s/(1 − s)`, clipped to `t1`.
        let s1 = if t1.is_finite() { (t1 - t0) / (1.0 + t1 - t0) } else { 1.0 };
        let f = |s: f64| -> f64 {
            let t = t0 + s / (1.0 - s);
            let w = origin + d * t - p;
            let r = w.length();
            let c = w.dot(ax) / r;
            let mu = -w.dot(d) / r;
            let jac = 1.0 / ((1.0 - s) * (1.0 - s));
            let val = (-st * ((t - t0) + r)).exp() / (r * r) * jac;
            if val == 0.0 || !val.is_finite() {
                return 0.0;
            }
            val * LightDistribution::<f64>::eval(&light.distribution, c) * PhaseFunction::<f64>::eval(phase, mu)
        };
        let edges: Vec<f64> = (0..=16).map(|i| s1 * i as f64 / 16.0).collect();
        return scale * adapt(&f, &edges, rel_tol, MAX_PANELS);
    }
    let g = |u: f64| -> f64 {
        let t = x_h + h * u.tan();
        if !t.is_finite() {
            return 0.0;
        }
        let w = origin + d * t - p;
        let r = w.length();
        let att = (-st * ((t - t0) + r)).exp();
        if att == 0.0 {
            return 0.0;
        }
        let c = w.dot(ax) / r;
        let mu = -w.dot(d) / r;
        att * LightDistribution::<f64>::eval(&light.distribution, c) * PhaseFunction::<f64>::eval(phase, mu)
    };
    let u0 = ((t0 - x_h) / h).atan();
    let u1 = if t1.is_finite() { ((t1 - x_h) / h).atan() } else { std::f64::consts::FRAC_PI_2 };
    const PANELS: usize = 16;
    let du = (u1 - u0) / PANELS as f64;
    let edges: Vec<f64> = (0..=PANELS).map(|i| if i == PANELS { u1 } else { u0 + du * i as f64 }).collect();
    scale / h * adapt(&g, &edges, rel_tol, MAX_PANELS)
}

/// Surface term for the reference, written out from paper eq. 7 (no kernel code):
/// `e^{−σt t_hit} · e^{−σt r_b}/r_b² · I·D(c_b) · max(0, ω_i·n)/π`.
pub(super) fn surface_reference(scene: &SceneDesc, d: DVec3, hit: &Hit, light: &PointLight<f64, AnyDistribution<f64>>) -> f64 {
    if !hit.t.is_finite() {
        return 0.0;
    }
    let x = scene.surface_point(d, hit);
    let to_light = light.position - x;
    let r = to_light.length();
    if !(r > 0.0) {
        return 0.0;
    }
    let wi = to_light / r;
    let cos = wi.dot(hit.normal).max(0.0);
    let ax = DVec3::from_array(light.distribution.axis()).normalize();
    let dist = LightDistribution::<f64>::eval(&light.distribution, -wi.dot(ax));
    let st = scene.medium.sigma_t;
    (-st * (hit.t + r)).exp() / (r * r) * light.intensity * dist * cos * std::f64::consts::FRAC_1_PI
}

/// The surface radiance from air-light of a Lambertian surface (albedo 1) at `x` with unit
/// normal `n` lit by a point light without an axis, written out from its definition
/// (docs/DESIGN.md §11) with none of the kernel's code: `∫_{n·ω>0} L_a(x, ω) (1/π)(n·ω) dω`.
/// Without an axis `L_a` depends on the angle `γ` between `ω` and the light's direction `ℓ`
/// alone; with `dω = sin γ dγ dφ` about `ℓ`, the azimuth's integral of `(n·ω)⁺ = (A + B cos φ)⁺`
/// is `2(Aψ + B sin ψ)` (`A = cos α cos γ`, `B = sin α sin γ`, `α` the angle of `n` from `ℓ`,
/// `ψ = arccos(−A/B)` clamped to `[0, π]`). The integral over `γ ∈ [0, π]` is split where the
/// arc changes kind (`|π/2 − α|`, `π − |π/2 − α|`), each piece taken in `s` with
/// `γ = a + (b − a)(3s² − 2s³)` (at those points the azimuth's integral goes like
/// `|γ − γ*|^{3/2}`), by adaptive Gauss–Kronrod 7/15 to `rel_tol`; every `L_a` by [`reference_in_scatter`] over
/// `[0, ∞)` to `rel_tol`.
pub fn reference_air_light(x: DVec3, n: DVec3, light: &PointLight<f64, AnyDistribution<f64>>, medium: &Medium<f64>, phase: &AnyPhase<f64>, rel_tol: f64) -> f64 {
    let to_light = light.position - x;
    let d = to_light.length();
    if !(d > 0.0) {
        return f64::INFINITY;
    }
    let l = to_light / d;
    let n = n.normalize();
    let cos_a = n.dot(l).clamp(-1.0, 1.0);
    let across = n - l * cos_a;
    let sin_a = across.length();
    let u = if sin_a > 1e-300 { across / sin_a } else { l.any_orthonormal_vector() };
    let alpha = sin_a.atan2(cos_a);
    let first = (std::f64::consts::FRAC_PI_2 - alpha).abs();
    let mut edges = vec![0.0];
    for c in [first.min(std::f64::consts::PI - first), first.max(std::f64::consts::PI - first)] {
        if c > *edges.last().unwrap() && c < std::f64::consts::PI {
            edges.push(c);
        }
    }
    edges.push(std::f64::consts::PI);
    let pieces = edges.len() - 1;
    let g = |s: f64| -> f64 {
        let i = (s.floor() as usize).min(pieces - 1);
        let t = s - i as f64;
        let (a, b) = (edges[i], edges[i + 1]);
        let gamma = a + (b - a) * t * t * (3.0 - 2.0 * t);
        let jacobian = (b - a) * 6.0 * t * (1.0 - t);
        let (sin_g, cos_g) = gamma.sin_cos();
        let (big_a, big_b) = (cos_a * cos_g, sin_a * sin_g);
        let psi = if big_b <= big_a.abs() {
            if big_a > 0.0 {
                std::f64::consts::PI
            } else {
                0.0
            }
        } else {
            (-big_a / big_b).clamp(-1.0, 1.0).acos()
        };
        if !(psi > 0.0) || !(jacobian > 0.0) {
            return 0.0;
        }
        let arc = 2.0 * (big_a * psi + big_b * psi.sin());
        let omega = l * cos_g + u * sin_g;
        let la = reference_in_scatter(x, omega, 0.0, f64::INFINITY, light, medium, phase, rel_tol);
        la * arc * std::f64::consts::FRAC_1_PI * sin_g * jacobian
    };
    let knots: Vec<f64> = (0..=pieces).map(|i| i as f64).collect();
    adapt(&g, &knots, rel_tol, MAX_PANELS)
}
