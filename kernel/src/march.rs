//! Ray marching: the fixed-step quadrature of the contract integral (docs/DESIGN.md §1) that the
//! analytic form replaces. Not on the data path — the benchmarks' baseline and an independent
//! check (no closed form, no expansion: it samples `e^{−σt(t−t0)} e^{−σt r}/r² D(c) P(μ)`).
//!
//! * [`Steps::Uniform`]: equal steps in `t`, the midpoint rule — what an engine's fog
//!   marcher does.
//! * [`Steps::Equiangular`]: equal steps in the angle `θ = atan((t − x_h)/h)` seen from the
//!   light, the midpoint rule in `θ` (`dt/r² = dθ/h`: the `1/r²` peak is absorbed; the angle
//!   formulation of Sun et al. 2005 and Hong's 2006 thesis, and the equiangular
//!   sampling of Kulla & Fajardo 2012). A much stronger baseline for lights close to the ray.
//!
//! An unbounded segment is cut where the transmittance `e^{−σt(t − t0)}` has fallen to
//! `e^{−14} < 1e-6`; with `σt = 0` the equiangular rule integrates to `θ = π/2` exactly and the
//! uniform one stops at `x_h + 1e4·(h + |x_h − t0|)` (the `1/t` tail beyond is below 1e-4).

use crate::geometry::{dot, normalize, sub, Canonical};
use crate::light::LightDistribution;
use crate::phase::PhaseFunction;
use crate::real::Real;

/// Where a ray marcher puts its samples.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Steps {
    /// Equal steps in `t` (midpoint rule).
    Uniform,
    /// Equal steps in the angle seen from the light (midpoint rule in `θ`).
    Equiangular,
}

/// `L_m` by `steps` samples of the integrand (module docs). `origin`, `dir` (any non-zero
/// length) and `light` in world space, `axis` the light distribution's axis. No input checks:
/// call it on validated scenes ([`crate::Scene::ray_march`]). The equiangular rule needs the
/// light off the ray line (`h > 0`).
#[allow(clippy::too_many_arguments)]
pub fn ray_march<T, D, P>(
    origin: [T; 3],
    dir: [T; 3],
    t0: T,
    t1: T,
    light: [T; 3],
    sigma_s: T,
    sigma_t: T,
    intensity: T,
    distribution: &D,
    phase: &P,
    rule: Steps,
    steps: usize,
) -> T
where
    T: Real,
    D: LightDistribution<T>,
    P: PhaseFunction<T>,
{
    let g = Canonical::new(origin, dir, t0, t1, light, distribution.axis());
    let d = normalize(dir);
    let a = normalize(distribution.axis());
    let n = T::from(steps.max(1)).unwrap();
    // Integrand without the constant σs·I, at the ray parameter t.
    let sample = |t: T| {
        let x = [origin[0] + t * d[0], origin[1] + t * d[1], origin[2] + t * d[2]];
        let to = sub(x, light);
        let r2 = dot(to, to);
        let r = r2.sqrt();
        let c = dot(to, a) / r;
        let mu = -dot(to, d) / r;
        let f: T = distribution.eval(c) * phase.eval(mu);
        (-sigma_t * (t - t0 + r)).exp() * f / r2
    };
    let mut sum = T::zero();
    match rule {
        Steps::Uniform => {
            let end = if t1.is_finite() {
                t1
            } else if sigma_t > T::zero() {
                t0 + T::lit(14.0) / sigma_t
            } else {
                g.x_h + T::lit(1e4) * (g.h + (g.x_h - t0).abs())
            };
            let dt = (end - t0) / n;
            for i in 0..steps {
                sum = sum + sample(t0 + dt * (T::from(i).unwrap() + T::lit(0.5)));
            }
            sigma_s * intensity * sum * dt
        }
        Steps::Equiangular => {
            let theta = |t: T| if t.is_finite() { g.u(t).atan() } else { T::FRAC_PI_2() };
            let end = if t1.is_finite() || sigma_t == T::zero() { t1 } else { t0 + T::lit(14.0) / sigma_t };
            let (th0, th1) = (theta(t0), theta(end));
            let dth = (th1 - th0) / n;
            for i in 0..steps {
                let th = th0 + dth * (T::from(i).unwrap() + T::lit(0.5));
                // dt = h/cos²θ dθ
                let cos = th.cos();
                sum = sum + sample(g.x_h + g.h * th.tan()) / (cos * cos);
            }
            sigma_s * intensity * sum * dth * g.h
        }
    }
}

/// Gauss–Legendre in the angle seen from the light: the strongest simple alternative to the
/// closed forms, what a renderer engineer writes instead. With `t − x_h = h tan θ`,
/// `dt/r² = dθ/h`, so `L_m = σs I/h ∫ e^{−σt(t − t0 + r)} D(c) P(μ) dθ` over
/// `[atan u_0, atan u_1]` with `μ = −sin θ`, `c = d_el sin θ + d_c cos θ` (docs/DESIGN.md §2): no
/// `1/r²` peak left, noise-free, a fixed cost of one `sin_cos`, one `exp` and `F` per node.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct GaussAngle<T> {
    /// Nodes per panel (4, 6, 8, 10, 12, 16, 20, 24, 32, 48 or 64; others give 0).
    pub nodes: usize,
    /// Equal panels per part, each with the `nodes`-point rule (composite Gauss–Legendre, how
    /// a user goes past the largest tabulated rule); 0 counts as 1.
    pub panels: usize,
    /// Split at the light's foot `θ = 0` (two parts of `nodes` each when the segment
    /// straddles it).
    pub split: bool,
    /// Cut each part where the extinction exponent `σt(t − t0 + r)` has grown by this much
    /// from its smallest value (it increases with `θ`: `σt h tan(θ/2 + π/4)` + const), e.g.
    /// 40 in f64 (`e^{−40} ≈ 4e-18`); `None`: integrate to the segment's end.
    pub cut: Option<T>,
}

/// `L_m` by [`GaussAngle`] (no input checks; `h > 0` needed). Returns the value and the number
/// of integrand evaluations.
#[allow(clippy::too_many_arguments)]
pub fn gauss_angle<T, D, P>(
    g: &Canonical<T>,
    sigma_s: T,
    sigma_t: T,
    intensity: T,
    distribution: &D,
    phase: &P,
    rule: GaussAngle<T>,
) -> (T, usize)
where
    T: Real,
    D: LightDistribution<T>,
    P: PhaseFunction<T>,
{
    let Some(table) = crate::expansion::gauss_table::rule(rule.nodes) else {
        return (T::zero(), 0);
    };
    let theta = |t: T| if t.is_finite() { g.u(t).atan() } else { T::FRAC_PI_2() };
    let (th0, mut th1) = (theta(g.t0), theta(g.t1));
    let big_h = sigma_t * g.h;
    // the exponent's growth from θ0 is σt h (tan(θ/2 + π/4) − tan(θ0/2 + π/4))
    if let (Some(bound), true) = (rule.cut, big_h > T::zero()) {
        let y0 = (th0 * T::lit(0.5) + T::FRAC_PI_4()).tan();
        let th_cut = T::lit(2.0) * (y0 + bound / big_h).atan() - T::FRAC_PI_2();
        th1 = th1.min(th_cut);
    }
    let mut parts = [(th0, th1), (th1, th1)];
    if rule.split && th0 < T::zero() && th1 > T::zero() {
        parts = [(th0, T::zero()), (T::zero(), th1)];
    }
    let mut sum = T::zero();
    let mut evaluations = 0;
    for (a, b) in parts {
        if !(b > a) {
            continue;
        }
        let panels = rule.panels.max(1);
        let hw = (b - a) * T::lit(0.5) / T::from(panels).unwrap();
        let mut part = T::zero();
        for p in 0..panels {
            let mid = a + hw * T::from(2 * p + 1).unwrap();
            for &(x, w) in table {
                for sign in [-T::one(), T::one()] {
                    let th = mid + hw * T::lit(x) * sign;
                    let (s, c) = th.sin_cos();
                    // t − t0 + r = (x_h − t0) + h (tan θ + sec θ)
                    let exponent = sigma_t * ((g.x_h - g.t0) + g.h * (s + T::one()) / c);
                    let f: T = distribution.eval(g.d_el * s + g.d_c * c) * phase.eval(-s);
                    part = part + T::lit(w) * (-exponent).exp() * f;
                    evaluations += 1;
                }
            }
        }
        sum = sum + part * hw;
    }
    (sigma_s * intensity / g.h * sum, evaluations)
}
