//! The reference: brute-force adaptive Gauss–Kronrod quadrature of the contract integral
//! (docs/DESIGN.md §1), with none of the kernel's closed forms.

use super::world::{Hit, Light, SceneDesc};
use airlight::extended::gauss_kronrod_15;
use airlight::glam::DVec3;
use airlight::light::AnyDistribution;
use airlight::phase::AnyPhase;
use airlight::{LightDistribution, Medium, PhaseFunction, PointLight};

/// Globally adaptive Gauss–Kronrod over `edges` (QUADPACK's QAG strategy): keeps bisecting
/// the panel with the largest error estimate `|K15 − G7|` until the sum of the estimates is
/// at most `rel_tol` of the sum of the values (the integrand is positive, so that bounds the
/// relative error of every part too), or `max_panels` panels.
fn adapt(f: &impl Fn(f64) -> f64, edges: &[f64], rel_tol: f64, max_panels: usize) -> f64 {
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
pub(super) fn surface_reference(scene: &SceneDesc, d: DVec3, hit: &Hit, light: &Light) -> f64 {
    if !hit.t.is_finite() {
        return 0.0;
    }
    let x = scene.camera.position + d * hit.t;
    let to_light = light.light.position - x;
    let r = to_light.length();
    if !(r > 0.0) {
        return 0.0;
    }
    let wi = to_light / r;
    let cos = wi.dot(hit.normal).max(0.0);
    let ax = DVec3::from_array(light.light.distribution.axis()).normalize();
    let dist = LightDistribution::<f64>::eval(&light.light.distribution, -wi.dot(ax));
    let st = scene.medium.sigma_t;
    (-st * (hit.t + r)).exp() / (r * r) * light.light.intensity * dist * cos * std::f64::consts::FRAC_1_PI
}
