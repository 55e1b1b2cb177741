//! The combined formulation (paper §3.5, eq. 20): split the segment at the light's foot
//! `u = 0`, integrate the part before it with the first reformulation (`v ∈ (0, 1]`) and the
//! part after it with the second (`w ∈ [−1, 0)`), so that the expansion variable never exceeds 1.
//!
//! `L_m = L_before + e^{−σt(x_h − t0)} L_after`, each `L = (2σs I/h) e^{−σt r_s} Σ a_k m_k`
//! (`r_s`: light distance at the part's start; moments in [`crate::integrals`]), plus the exact
//! limits for a light on the ray line (`h → 0`).

use crate::angle::Route;
use crate::expansion::{Expandable, Expansion};
use crate::geometry::Canonical;
use crate::integrals::{moment_zero, moments, ExpIntegral, Half, SharedEnds};
use crate::light::LightDistribution;
use crate::panels::{integrate_piece, Control, Running};
use crate::phase::PhaseFunction;
use crate::real::{hypot1, log2_floor, Real};
use crate::scene::{Medium, PointLight};
use crate::scalar::Scalar;
use crate::special::en_scaled;

/// Everything the canonical integral needs besides the geometry.
#[derive(Clone, Copy, Debug)]
pub struct Physics<'a, T, D, P> {
    /// Scattering coefficient `σs`.
    pub sigma_s: T,
    /// Extinction coefficient `σt`.
    pub sigma_t: T,
    /// Light intensity `I`.
    pub intensity: T,
    /// Light distribution `D`.
    pub light: &'a D,
    /// Phase function `P`.
    pub phase: &'a P,
}

impl<'a, T: Real, D, P> Physics<'a, T, D, P> {
    /// The physics of a point light `light` in `medium` with the phase function `phase`.
    pub fn new(light: &'a PointLight<T, D>, medium: &Medium<T>, phase: &'a P) -> Self {
        Physics { sigma_s: medium.sigma_s, sigma_t: medium.sigma_t, intensity: light.intensity, light: &light.distribution, phase }
    }
}

/// `F(y) = D(c(y))·P(μ(y))` on one half (module docs of [`crate::integrals`]):
/// `μ = −σ(1 − y²)/(1 + y²)`, `c = (σ d_el (1 − y²) + 2 d_c y)/(1 + y²)`, `σ = ∓1` before/after.
struct HalfIntegrand<'a, T, D, P> {
    sigma: T,
    /// Pass `1 ∓ μ` exactly to the phase function ([`PhaseFunction::eval_sides`]); the fixed
    /// method forms them from `μ`, as the paper's method does.
    exact_sides: bool,
    d_el: T,
    d_c: T,
    light: &'a D,
    phase: &'a P,
}

impl<T: Real, D: LightDistribution<T>, P: PhaseFunction<T>> HalfIntegrand<'_, T, D, P> {
    /// `(c, μ, 1 − μ, 1 + μ, 1/(1 + y²))` at `y`, the half's `σ` given; the sides only where
    /// [`exact_sides`](Self::exact_sides) (zero otherwise).
    #[inline]
    fn geometry<S: Scalar<T>>(&self, y: S, sigma: T) -> (S, S, S, S, S) {
        let y2 = y * y;
        let inv = y2.shift(T::one()).recip();
        let one_minus = S::cst(T::one()) - y2;
        let mu = (one_minus * inv).scale(-sigma);
        let c = (one_minus.scale(sigma * self.d_el) + y.scale(self.d_c + self.d_c)) * inv;
        let (minus, plus) = if self.exact_sides {
            // 1 − μ and 1 + μ are 2y²/(1+y²) and 2/(1+y²), in the order σ decides
            let (far, near) = ((y2 * inv).scale(T::lit(2.0)), inv.scale(T::lit(2.0)));
            if sigma < T::zero() {
                (far, near)
            } else {
                (near, far)
            }
        } else {
            (S::cst(T::zero()), S::cst(T::zero()))
        };
        (c, mu, minus, plus, inv)
    }

    /// `(F(y), 1/(1 + y²))`.
    #[inline]
    fn with_over<S: Scalar<T>>(&self, y: S) -> (S, S) {
        let (c, mu, minus, plus, inv) = self.geometry(y, self.sigma);
        let p = if self.exact_sides { self.phase.eval_sides(mu, minus, plus) } else { self.phase.eval(mu) };
        (self.light.eval(c) * p, inv)
    }
}

impl<T: Real, D: LightDistribution<T>, P: PhaseFunction<T>> HalfIntegrand<'_, T, D, P> {
    /// `c(y)` alone.
    #[inline]
    fn cosine(&self, y: T) -> T {
        let y2 = y * y;
        ((T::one() - y2) * (self.sigma * self.d_el) + (y + y) * self.d_c) / (T::one() + y2)
    }

    /// Whether the light is dark on all of the piece `[lo, hi]` of `half` — `D = 0` below the
    /// cosine `bound` ([`LightDistribution::dark_below`]) — checked where `c` can be largest:
    /// `c < bound` at the piece's middle, at the stationary points of `c` inside it (`c' = 0`:
    /// `d_c y² + 2σd_el y − d_c = 0`, whose roots multiply to `−1`) and at those of its ends that
    /// are the half's ends. Its other ends are crossings of a kink, where `c` equals the kink
    /// up to rounding: a piece between crossings lies on one side of every kink, and its middle
    /// tells which. (A crossing the rounding missed — `c` grazing a kink — leaves `c` above
    /// `bound` at a stationary point or an end, so that piece is integrated.)
    fn dark(&self, bound: T, lo: T, hi: T, half: &Half<T>) -> bool {
        let below = |y: T| self.cosine(y) < bound;
        if !below((lo + hi) * T::lit(0.5)) || (lo == half.y_lo && !below(lo)) || (hi == half.y_hi && !below(hi)) {
            return false;
        }
        let (a, d) = (self.sigma * self.d_el, self.d_c);
        if d == T::zero() {
            // c = a(1 − y²)/(1 + y²) is monotone in y ≥ 0
            return true;
        }
        // y₁ = (√(a² + d²) − a)/d without cancellation, y₂ = −1/y₁
        let root = (a * a + d * d).sqrt();
        let y1 = if a > T::zero() { d / (a + root) } else { (root - a) / d };
        [y1, -y1.recip()].into_iter().all(|y| !(y > lo && y < hi) || below(y))
    }
}

impl<T: Real, D: LightDistribution<T>, P: PhaseFunction<T>> Expandable<T> for HalfIntegrand<'_, T, D, P> {
    #[inline]
    fn eval<S: Scalar<T>>(&self, y: S) -> S {
        self.with_over(y).0
    }
    #[inline]
    fn eval_over(&self, y: T) -> (T, T) {
        self.with_over(y)
    }
    /// With `y = 1/v`: `(1 − y²)/(1 + y²) = −(1 − v²)/(1 + v²)` and `2y/(1 + y²) = 2v/(1 + v²)`,
    /// so `F(1/v)` is this integrand with `σ` negated, at `v`.
    #[inline]
    fn eval_over_reciprocal(&self, v: T) -> (T, T) {
        HalfIntegrand { sigma: -self.sigma, ..*self }.with_over(v)
    }
    /// `D` for all `N` at once ([`LightDistribution::eval_each`]), then `P` point by point.
    /// The points' geometry is formed twice, for `c` and again for `μ`, `1 ∓ μ`: kept as an
    /// array of five per point instead it cost 2–10 % more instructions per ray (f32
    /// `long_ray`, `near_light`, `hg_0.99`, `beam_c64` at tolerance 1e-3, f64 `thick` at 1e-4;
    /// `long_ray` 8 668 → 9 533), the stores outweighing a division and a few products.
    fn eval_over_each<const N: usize>(&self, points: &[T; N], reciprocal: bool) -> [(T, T); N] {
        let sigma = if reciprocal { -self.sigma } else { self.sigma };
        let mut d = points.map(|y| self.geometry(y, sigma).0);
        self.light.eval_each(&mut d);
        core::array::from_fn(|i| {
            let (_, mu, minus, plus, inv) = self.geometry(points[i], sigma);
            let p = if self.exact_sides { self.phase.eval_sides(mu, minus, plus) } else { self.phase.eval(mu) };
            (d[i] * p, inv)
        })
    }
    /// `c(y)` and `μ(y)` have simple poles at `y = ±i`, where `D(c)·P(μ)/(1 + y²)` has one of
    /// order `deg D + max(growth, 0) + 1`; a phase singularity at `μ*` is where
    /// `−σ(1 − y²)/(1 + y²) = μ*`, i.e. `y² = (1 − κ)/(1 + κ)` with `κ = −μ*/σ`, `|κ| > 1`:
    /// `y = ±i√((κ − 1)/(κ + 1))`, from the gap `|μ*| − 1` without cancellation.
    fn singularities(&self) -> Option<[(T, T); 3]> {
        let degree = self.light.polynomial_degree()?;
        let p = self.phase.singularities()?;
        let [a, b] = p.cosines;
        let height = |mu: T| {
            let gap = mu.abs() - T::one();
            if !(gap > T::zero()) {
                return T::zero();
            }
            if !gap.is_finite() {
                return T::one();
            }
            let two = T::lit(2.0);
            // κ > 0 when μ* and −σ agree in sign
            if (mu > T::zero()) == (self.sigma < T::zero()) {
                (gap / (two + gap)).sqrt()
            } else {
                ((two + gap) / gap).sqrt()
            }
        };
        let at_i = T::from(degree).unwrap_or(T::infinity()) + p.growth.max(T::zero()) + T::one();
        Some([(T::one(), at_i), (height(a), p.order), (height(b), p.order)])
    }
}

/// How `F` is integrated on each half.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Method<T> {
    /// One `N`-term expansion per piece between kinks (the paper's fixed-cost method).
    Fixed(Expansion),
    /// Error-controlled panels ([`crate::panels`]) with `N` Gauss–Legendre nodes each.
    Panels(Control<T>),
}

/// `1/(a + √(1+a²))` for `a ≥ 0`: the bounded variable `y` at `|u| = a` (`+∞ ↦ 0`).
#[inline]
pub(crate) fn bounded<T: Real>(a: T) -> T {
    if a.is_finite() {
        (a + hypot1(a)).recip()
    } else {
        T::zero()
    }
}

/// In-scattered radiance `L_m` of the canonical problem with `N` expansion terms (or nodes
/// per panel).
pub fn in_scatter_canonical<T, D, P, E, const N: usize>(
    g: &Canonical<T>,
    phys: &Physics<'_, T, D, P>,
    method: Method<T>,
    ei: &E,
) -> T
where
    T: Real,
    D: LightDistribution<T>,
    P: PhaseFunction<T>,
    E: ExpIntegral<T>,
{
    in_scatter_counted::<T, D, P, E, N>(g, phys, method, ei).0
}

/// [`in_scatter_canonical`] and the number of panels [`Method::Panels`] evaluated (0 for the
/// fixed method and the exact limits).
pub fn in_scatter_counted<T, D, P, E, const N: usize>(
    g: &Canonical<T>,
    phys: &Physics<'_, T, D, P>,
    method: Method<T>,
    ei: &E,
) -> (T, usize)
where
    T: Real,
    D: LightDistribution<T>,
    P: PhaseFunction<T>,
    E: ExpIntegral<T>,
{
    // every entry point reaches this: a count the kernel cannot compute fails to compile
    const { assert!(N >= 1 && N <= crate::integrals::MAX_TERMS, "1 to 16 terms or nodes") };
    let (t0, t1) = (g.t0, g.t1);
    if !(t1 > t0) || phys.sigma_s * phys.intensity == T::zero() {
        return (T::zero(), 0);
    }
    let (h, x_h) = (g.h, g.x_h);
    let inside = t0 <= x_h && x_h <= t1;
    // Distance from the foot to the nearest segment end.
    let gap = if x_h < t0 { t0 - x_h } else if x_h > t1 { x_h - t1 } else { T::zero() };
    if !inside && h <= gap * T::epsilon() * T::epsilon() {
        return (on_line(g, phys), 0);
    }
    if h == T::zero() {
        // The light sits on the segment itself: the integral diverges.
        return (T::infinity(), 0);
    }
    let sigma_t = phys.sigma_t;
    let big_h = sigma_t * h;
    let ei = &SharedEnds::new(ei);
    let isotropic = phys.light.is_isotropic() && phys.phase.is_isotropic();
    let count = if isotropic { 1 } else { N };

    if isotropic && ei.stabilised() && t0 < x_h && x_h < t1 {
        return (whole_line(g, phys, big_h, ei), 0);
    }
    // a route by cost first: the whole segment in the light angle, where that meets the target
    let mut tried = 0;
    if let (Method::Panels(control), false) = (method, isotropic) {
        // a thick medium (the light a mean free path or more from the ray's line):
        // Gauss–Laguerre in the optical depth, whose weight the extinction is
        // (`crate::depth`; fewer samples, no trigonometric function or exponential in them,
        // and none of the light angle's plan formed where it is taken)
        if crate::angle::thick(big_h) {
            match crate::depth::thick_route::<T, D, P, N>(g, phys, &control) {
                Route::Taken(value) => return (value, 1),
                Route::Failed => tried = 1,
                Route::Declined => {}
            }
        }
        if let Some(plan) = crate::angle::Plan::new(g, phys, &control) {
            // N nodes, then twice and four times as many for a light's lobe, the extinction's
            // layer or the phase function's singularity that N do not resolve (`Plan::widens`
            // and the plan's predictions decide): that still costs less than the closed-form
            // panels
            let emission = crate::angle::Along { light: phys.light, d_el: g.d_el, d_c: g.d_c };
            match plan.tries::<D, P, _, N>(g, phys, &control, &emission) {
                (Some(value), n) => return (value, tried + n),
                (None, n) => tried += n,
            }
            // the light angle on the part before a backward lobe at the far end, the closed
            // forms on the rest
            match graded_route::<T, D, P, _, N>(g, phys, &plan, &control, ei) {
                (Route::Taken(value), panels) => return (value, tried + panels),
                (Route::Failed, _) => tried += 1,
                (Route::Declined, _) => {}
            }
        }
    }
    let mut total = T::zero();
    let mut run = Running { f_max: T::zero(), panels: tried };
    // panels only: the exponent's boundary layer is cut where the rest is below what the
    // target resolves
    let cut = match method {
        Method::Panels(control) if !isotropic => Some(control),
        _ => None,
    };
    let mut behind_cut = false;
    // First reformulation: t ∈ [t0, min(t1, x_h)], a = −u from a_s down to a_e.
    if t0 < x_h {
        let a_s = (x_h - t0) / h;
        let t_end = if t1 < x_h { t1 } else { x_h };
        let a_e = (x_h - t_end) / h;
        let (r_s, r_e) = (hypot1(a_s), hypot1(a_e));
        let (y_lo, y_hi) = (bounded(a_s), bounded(a_e));
        let da = (t_end - t0) / h;
        let dy = da * (T::one() + (a_s + a_e) / (r_s + r_e)) * y_lo * y_hi;
        let mut half = Half { second: false, big_h: optical(big_h, dy), y_lo, y_hi, dy, dv: dy };
        if let Some(control) = cut {
            let dv = cut_length(half.big_h, y_lo, dy, &control);
            if dv < dy {
                // the rest of this half and all of the second lie beyond the cut
                half = Half { y_hi: y_lo + dv, dy: dv, dv, ..half };
                behind_cut = true;
            }
        }
        let j = half_integral::<T, D, P, _, N>(&half, g, phys, -T::one(), method, ei, isotropic, count, &mut run);
        total = total + weighted(phys.sigma_s, phys.intensity, h, big_h * r_s, j);
    }
    // Second reformulation: t ∈ [max(t0, x_h), t1], a = u from a_s up to a_e (maybe ∞).
    if t1 > x_h && !behind_cut {
        let t_start = if t0 > x_h { t0 } else { x_h };
        let (half, x) = second_half(g, sigma_t, t_start, cut);
        let j = half_integral::<T, D, P, _, N>(&half, g, phys, T::one(), method, ei, isotropic, count, &mut run);
        total = total + weighted(phys.sigma_s, phys.intensity, h, x, j);
    }
    // The integrand is ≥ 0; a polynomial that dips below 0 where F vanishes (outside a spot
    // cone) must not make the sum negative. Clamping can only reduce the error.
    (total.max(T::zero()), run.panels)
}

/// A route by cost on part of the segment (docs/DESIGN.md §4.4): where the second half starts
/// next to a backward singularity of the phase function — a backward lobe at a long ray's far
/// end — the panels would grade it at once (`panels::graded_point`); instead the light
/// angle's `N`-node panel takes everything before the grading point `t_s` (the first half and
/// the smooth part of the second) and the closed forms only `[t_s, t1]`, the piece next to the
/// singularity with the extinction's layer. Each part meets the target on its own, so their sum
/// does. Where the light is a mean free path or more from the ray (`Plan::thick`), or
/// `whole`'s predictions say the first part's panel would not pass
/// (`Plan::graded_point`), declined. Taken: the value and the panels spent
/// (the light angle's and the closed forms'). Not inlined: inlined, it made the whole-segment
/// tries' code 1–3 % costlier on rays that never reach it (instructions per ray).
#[inline(never)]
pub fn graded_route<T, D, P, E, const N: usize>(g: &Canonical<T>, phys: &Physics<'_, T, D, P>, whole: &crate::angle::Plan<T>, control: &Control<T>, ei: &E) -> (Route<T>, usize)
where
    T: Real,
    D: LightDistribution<T>,
    P: PhaseFunction<T>,
    E: ExpIntegral<T>,
{
    let (h, x_h, t0, t1) = (g.h, g.x_h, g.t0, g.t1);
    if !(t1 > x_h) || whole.thick() {
        return (Route::Declined, 0);
    }
    // the second half's ends in y (uncut: a cut only moves y_lo up, and any t_s splits exactly)
    let y_hi = if t0 > x_h { bounded((t0 - x_h) / h) } else { T::one() };
    let y_lo = bounded((t1 - x_h) / h);
    let Some(y_p) = whole.graded_point::<P, N>(phys.phase, y_lo, y_hi, control.tolerance) else {
        return (Route::Declined, 0);
    };
    // t − x_h = h·u with y = 1/(u + √(1 + u²)): u = (1/y − y)/2
    let t_s = x_h + h * ((y_p.recip() - y_p) * T::lit(0.5));
    if !(t_s > t0 && t_s < t1) {
        return (Route::Declined, 0);
    }
    let before = Canonical { t1: t_s, ..*g };
    let Some(plan) = crate::angle::Plan::new(&before, phys, control) else {
        return (Route::Declined, 0);
    };
    let value = match plan.rule::<D, P, N>(&before, phys, control, false) {
        Route::Taken(value) => value,
        other => return (other, 0),
    };
    let (half, x) = second_half(g, phys.sigma_t, t_s, Some(*control));
    let mut run = Running { f_max: T::zero(), panels: 1 };
    let j = half_integral::<T, D, P, _, N>(&half, g, phys, T::one(), Method::Panels(*control), ei, false, N, &mut run);
    (Route::Taken((value + weighted(phys.sigma_s, phys.intensity, h, x, j)).max(T::zero())), run.panels)
}

/// The second half from `t_start ≥ x_h` to `t1` (module docs), cut where the panels' `control`
/// says (`cut_length`), and the exponent of its prefactor, `σt(t_start − t0) + H·r_s`.
fn second_half<T: Real>(g: &Canonical<T>, sigma_t: T, t_start: T, cut: Option<Control<T>>) -> (Half<T>, T) {
    let (h, x_h, t1) = (g.h, g.x_h, g.t1);
    let big_h = sigma_t * h;
    let a_s = (t_start - x_h) / h;
    let a_e = (t1 - x_h) / h;
    let r_s = hypot1(a_s);
    let (y_hi, y_lo) = (bounded(a_s), bounded(a_e));
    let dv = if a_e.is_finite() { (t1 - t_start) / h * (T::one() + (a_s + a_e) / (r_s + hypot1(a_e))) } else { T::infinity() };
    // An end so far out that y_lo or Δv leaves the float range is the end at t = ∞ (the
    // weight e^{−HΔv} and the part of the integrand beyond it are below the range too).
    let (y_lo, dv, dy) = if y_lo > T::zero() && dv.is_finite() { (y_lo, dv, dv * y_lo * y_hi) } else { (T::zero(), T::infinity(), y_hi) };
    let mut half = Half { second: true, big_h: optical(big_h, dv), y_lo, y_hi, dy, dv };
    if let Some(control) = cut {
        let cut_dv = cut_length(half.big_h, y_hi.recip(), dv, &control);
        // v_e = v_s + Δv: y_lo = 1/v_e, Δy = Δv·y_lo·y_hi
        let cut_y_lo = y_hi / (T::one() + y_hi * cut_dv);
        if cut_dv < dv && cut_y_lo > T::zero() {
            half = Half { y_lo: cut_y_lo, dy: cut_dv * cut_y_lo * y_hi, dv: cut_dv, ..half };
        }
    }
    (half, sigma_t * (t_start - g.t0) + big_h * r_s)
}

/// The length `Δv` of a half beyond which the error-controlled panels cut it (`+∞`: no cut),
/// for `H = σt·h`, the half's first `v_s` and the panels' control. The weight `e^{−H(v − v_s)}`
/// is then below `e^{−E}`: the part dropped is at most `F_max e^{−E}/(H(1 + v_s²))` (`G ≤
/// F_max/(1+v²)`), and behind a cut first half the whole second half at most
/// `F_max e^{−E}/(2H)` (its weight at the foot is below `e^{−E}`, and `∫_1^∞ e^{−H(v−1)}
/// dv/(1+v²) ≤ 1/(2H)`); the half's scale (its integral with `F` at its maximum) is at least
/// `F_max e^{−1}/(H(1 + (v_s + 1/H)²))`, from the first `1/H` of `v`, where the weight is at
/// least `e^{−1}`. So with `R = (1 + (v_s + 1/H)²)/(1 + v_s²) ≥ 1` everything dropped is at
/// most `8 R e^{1−E}` of the scale, and `E = 1 + ln(8R/(δ·τ))` (`τ`: the control's floor,
/// `δ = max(tolerance/10, ε)`) keeps it below a tenth of the smallest error the target allows,
/// `tolerance·τ·scale`, and never below one rounding of it: cut, the boundary layer of a thick
/// medium or a long ray is still integrated to the target, and the panels are spent on the
/// part that contributes, as the peer's cut does (`crate::march::GaussAngle::cut`).
///
/// `span`: the half's own length in `v` (or the light angle's panel's in `Y`). Where `H·span`
/// is at most [`uncut_span`], the cut lies beyond the span and `+∞` is returned without the
/// logarithm: the decision is the same, the street lamp's and most short rays' `ln` is saved.
#[inline]
pub(crate) fn cut_length<T: Real>(big_h: T, v_s: T, span: T, control: &Control<T>) -> T {
    let resolution = cut_resolution(control);
    if !(big_h > T::zero()) || !(resolution > T::zero()) || big_h * span <= uncut_span(control) {
        return T::infinity();
    }
    let inv_h = big_h.recip();
    let w = v_s + inv_h;
    let r = (T::one() + w * w) / (T::one() + v_s * v_s);
    let e = T::one() + (T::lit(8.0) * r / resolution).ln();
    e * inv_h
}

/// `δ·τ` of the panels' cut bound (`cut_length`) under `control`: `δ = max(tolerance/10, ε)` times the floor
/// `τ`, at least `ε` — the fraction of the scale the cut may drop. The shaders take it from here.
#[inline]
pub fn cut_resolution<T: Real>(control: &Control<T>) -> T {
    (control.tolerance * T::lit(0.1)).max(T::epsilon()) * control.floor.max(T::epsilon())
}

/// The largest `H·Δv` that the panels' cut of the extinction (`cut_length`) never cuts under
/// `control`: `1 + ln 2·(2 − ⌊log₂(δ·τ)⌋)` ([`cut_resolution`]), below the cut's smallest
/// exponent `E = 1 + ln(8R/(δ·τ))` since `R ≥ 1` and `ln(8/(δ·τ)) ≥ ln 2·(3 − ⌊log₂(δ·τ)⌋ −
/// 1)`; `⌊log₂⌋` from the float's bits, no library call. The shaders take it from here.
#[inline]
pub fn uncut_span<T: Real>(control: &Control<T>) -> T {
    T::one() + T::lit(core::f64::consts::LN_2) * T::from(2 - log2_floor(cut_resolution(control))).unwrap()
}

/// An isotropic segment across the foot, in one piece: with `F` constant there is nothing to
/// expand, and the first reformulation's `v = u + √(1+u²)` covers the whole line (`v > 1`
/// after the foot), so `L = (2σs I/h) e^{−H r_s} F ∫ e^{−H(v−v_s)} dv/(1+v²)` is one closed form
/// with two `e^z E1(z)` values. Split at the foot it needs three: the foot's value enters both
/// halves and cancels in their sum.
fn whole_line<T, D, P, E>(g: &Canonical<T>, phys: &Physics<'_, T, D, P>, big_h: T, ei: &E) -> T
where
    T: Real,
    D: LightDistribution<T>,
    P: PhaseFunction<T>,
    E: ExpIntegral<T>,
{
    let h = g.h;
    let (a_s, u_e) = ((g.x_h - g.t0) / h, (g.t1 - g.x_h) / h);
    let (r_s, r_e) = (hypot1(a_s), hypot1(u_e));
    let v_s = bounded(a_s);
    let v_e = u_e + r_e;
    // Δv = Δu (v_s + v_e)/(r_s + r_e), without cancellation; an end beyond the float range is
    // the end at t = ∞ (as in the second half)
    let dv = (g.t1 - g.t0) / h * ((v_s + v_e) / (r_s + r_e));
    let (v_e, dv) = if v_e.is_finite() && dv.is_finite() { (v_e, dv) } else { (T::infinity(), T::infinity()) };
    let half = Half { second: false, big_h: optical(big_h, dv), y_lo: v_s, y_hi: v_e, dy: dv, dv };
    let f = HalfIntegrand { sigma: -T::one(), exact_sides: true, d_el: g.d_el, d_c: g.d_c, light: phys.light, phase: phys.phase };
    // H·r_s = σt·|p − x(t0)|; where r_s overflows (a subnormal h) the distance is |x_h − t0|,
    // and without extinction the exponent is 0, not 0·∞
    let x = if r_s.is_finite() {
        big_h * r_s
    } else if phys.sigma_t > T::zero() {
        phys.sigma_t * (g.x_h - g.t0).abs()
    } else {
        T::zero()
    };
    let (m, x) = moment_zero(&half, ei, x);
    weighted(phys.sigma_s, phys.intensity, h, x, f.eval(T::zero()) * m)
}

/// `H` on one half: 0 where the weight `e^{−H(v − v_s)}` is 1 to working precision over the
/// half's `Δv` (`H·Δv < ε`; on an unbounded half `H < ε²`, since there the relative change
/// is `O(H ln(1/H))`). The exact `H = 0` closed forms then apply, and no `H`-sized
/// intermediate is left to become subnormal (which Vulkan may flush to zero; the shader
/// mirrors this).
#[inline]
fn optical<T: Real>(big_h: T, dv: T) -> T {
    let negligible = if dv.is_finite() { big_h * dv < T::epsilon() } else { big_h < T::epsilon() * T::epsilon() };
    if negligible {
        T::zero()
    } else {
        big_h
    }
}

/// `(2 σs I / h)·e^{−x}·j`: a half's prefactor, its folded exponent (`x ≥ 0`) and its sum
/// `j`. When the plain product is not finite — `σs I / h` overflowing while `e^{−x}` or `j`
/// underflows — it is formed through logarithms, so that a representable value never becomes
/// `∞·0` (NaN); a true value beyond the range stays `+∞`.
#[inline]
pub(crate) fn weighted<T: Real>(sigma_s: T, intensity: T, h: T, x: T, j: T) -> T {
    let plain = T::lit(2.0) * sigma_s * intensity / h * (-x).exp() * j;
    if plain.is_finite() {
        plain
    } else if !(j.abs() > T::zero()) {
        T::zero()
    } else {
        (T::LN_2() + sigma_s.ln() + intensity.ln() - h.ln() - x + j.abs().ln()).exp().copysign(j)
    }
}

/// `Σ a_k m_k` on one half, split where `c(y)` crosses a kink of the light distribution.
#[allow(clippy::too_many_arguments)]
fn half_integral<T, D, P, E, const N: usize>(
    half: &Half<T>,
    g: &Canonical<T>,
    phys: &Physics<'_, T, D, P>,
    sigma: T,
    method: Method<T>,
    ei: &E,
    isotropic: bool,
    count: usize,
    run: &mut Running<T>,
) -> T
where
    T: Real,
    D: LightDistribution<T>,
    P: PhaseFunction<T>,
    E: ExpIntegral<T>,
{
    let exact_sides = matches!(method, Method::Panels(_));
    let f = HalfIntegrand { sigma, exact_sides, d_el: g.d_el, d_c: g.d_c, light: phys.light, phase: phys.phase };
    if isotropic {
        let m: [T; N] = moments(half, ei, count);
        // F is constant: its value at y = 0 takes no division
        return f.eval(T::zero()) * m[0];
    }
    // Up to two kinks, each crossed at most twice: at most 5 pieces.
    let mut cuts = [T::zero(); 6];
    let mut n_cuts = 0;
    let mut add = |y: Option<T>| {
        if let Some(y) = y {
            if y > half.y_lo && y < half.y_hi {
                cuts[n_cuts] = y;
                n_cuts += 1;
            }
        }
    };
    for kink in phys.light.kinks().into_iter().flatten() {
        crossings(sigma, g.d_el, g.d_c, kink).into_iter().for_each(&mut add);
    }
    let cuts = &mut cuts[..n_cuts];
    cuts.sort_unstable_by(|a, b| a.partial_cmp(b).unwrap_or(core::cmp::Ordering::Equal));
    // The pieces between the cuts, each by the method's own rule; a half without cuts is one
    // piece in the fixed method's own scaling.
    let cuts = cuts.iter().copied();
    match method {
        Method::Fixed(expansion) if n_cuts == 0 => piece_integral::<T, _, E, N>(half, &f, expansion, ei),
        Method::Fixed(expansion) => sum_between(half.y_lo, half.y_hi, cuts, |lo, hi| {
            let (piece, weight) = half.part(lo, hi);
            weight * subdivided::<T, _, E, N>(&piece, &f, expansion, ei)
        }),
        Method::Panels(control) => {
            let dark_below = phys.light.dark_below();
            sum_between(half.y_lo, half.y_hi, cuts, |lo, hi| match dark_below {
                Some(bound) if f.dark(bound, lo, hi, half) => T::zero(),
                _ => integrate_piece::<T, _, N>(half, lo, hi, &f, &control, run),
            })
        }
    }
}

/// `Σ each(lo, hi)` over the parts of `[y_lo, y_hi]` between ascending `cuts`, empty parts
/// skipped.
fn sum_between<T: Real>(y_lo: T, y_hi: T, cuts: impl Iterator<Item = T>, mut each: impl FnMut(T, T) -> T) -> T {
    let mut total = T::zero();
    let mut lo = y_lo;
    for hi in cuts.chain([y_hi]) {
        if hi > lo {
            total = total + each(lo, hi);
        }
        lo = hi;
    }
    total
}

/// A piece between kinks, where `F` may change by its full range over a short sub-interval
/// (a cone's smoothstep edge): its expansion coefficients are large, `a_k ~ r^{−k}`, so its
/// moments must be accurate relative to `r^k`, which only the short route guarantees
/// (`H·Δv ≤ 1`). Thick media make `H·Δv` large: then the piece is cut into `⌈H·Δv⌉` parts of
/// equal length in `y` (at most 8; beyond that the weight has decayed by `e^{−8}` within the
/// first part and the rest contributes little).
fn subdivided<T: Real, F: Expandable<T>, E: ExpIntegral<T>, const N: usize>(
    piece: &Half<T>,
    f: &F,
    expansion: Expansion,
    ei: &E,
) -> T {
    let parts = (piece.big_h * piece.dv).ceil();
    if !(parts > T::one()) || piece.dy > T::lit(0.25) {
        return piece_integral::<T, _, E, N>(piece, f, expansion, ei);
    }
    let parts = parts.min(T::lit(8.0)).to_usize().unwrap_or(1);
    let step = piece.dy / T::from(parts).unwrap();
    let cuts = (1..parts).map(|i| piece.y_lo + step * T::from(i).unwrap());
    sum_between(piece.y_lo, piece.y_hi, cuts, |lo, hi| {
        let (part, weight) = piece.part(lo, hi);
        weight * piece_integral::<T, _, E, N>(&part, f, expansion, ei)
    })
}

/// `Σ a_k m_k` on one smooth piece.
fn piece_integral<T: Real, F: Expandable<T>, E: ExpIntegral<T>, const N: usize>(
    half: &Half<T>,
    f: &F,
    expansion: Expansion,
    ei: &E,
) -> T {
    let m: [T; N] = moments(half, ei, N);
    let a: [T; N] = expansion.coefficients(f, half.y_mid(), half.dy * T::lit(0.5));
    let mut j = T::zero();
    for k in 0..N {
        j = j + a[k] * m[k];
    }
    j
}

/// The `y ∈ (0, 1]` where `c(y) = (σ d_el (1 − y²) + 2 d_c y)/(1 + y²)` equals `k`:
/// roots of `(k + σ d_el) y² − 2 d_c y + (k − σ d_el) = 0`, by the cancellation-free form of
/// the quadratic formula, on the coefficients scaled by the largest (the roots do not change;
/// unscaled, `b²` of a tiny `b` underflowed to a zero discriminant, which doubled the root).
fn crossings<T: Real>(sigma: T, d_el: T, d_c: T, k: T) -> [Option<T>; 2] {
    let (a, b, c) = (k + sigma * d_el, -(d_c + d_c), k - sigma * d_el);
    let scale = a.abs().max(b.abs()).max(c.abs());
    if !(scale > T::zero()) || !scale.is_finite() {
        return [None, None];
    }
    let (a, b, c) = (a / scale, b / scale, c / scale);
    let disc = b * b - T::lit(4.0) * a * c;
    if !(disc >= T::zero()) {
        return [None, None];
    }
    let q = -T::lit(0.5) * (b + disc.sqrt().copysign(b));
    let r1 = if q != T::zero() { Some(c / q) } else { None };
    let r2 = if a != T::zero() { Some(q / a) } else { None };
    [r1, r2]
}

/// The exact limit for a light on the ray line outside the segment (`h → 0`): `μ = ±1` and
/// `c = ∓d_el` are constant, and
/// * light ahead (`x_h > t1`): `e^{−σt r} e^{−σt(t−t0)}` is constant, `∫ dt/r² = Δt/(r_0 r_1)`;
/// * light behind (`x_h < t0`): `s = t − x_h`, `∫ e^{−2σt s}/s² ds` is an `E_2` difference.
fn on_line<T: Real, D: LightDistribution<T>, P: PhaseFunction<T>>(
    g: &Canonical<T>,
    phys: &Physics<'_, T, D, P>,
) -> T {
    let (t0, t1, x_h) = (g.t0, g.t1, g.x_h);
    let sigma_t = phys.sigma_t;
    if x_h > t1 {
        let f: T = phys.light.eval(-g.d_el) * phys.phase.eval(T::one());
        let (r0, r1) = (x_h - t0, x_h - t1);
        // σs I f (Δt/r0)/r1 e^{−σt r0}: Δt/r0 ≤ 1 (r0 = Δt + r1), and the nearer end's 1/r1
        // in weighted()'s divisor, so that a tiny r1 goes through its logarithmic path instead
        // of overflowing here (halved where r0 leaves the range; the quotient is the same)
        let span = if r0.is_finite() { (t1 - t0) / r0 } else { (t1 * T::lit(0.5) - t0 * T::lit(0.5)) / (x_h * T::lit(0.5) - t0 * T::lit(0.5)) };
        weighted(phys.sigma_s, phys.intensity, r1 + r1, sigma_t * r0, f * span)
    } else {
        let f: T = phys.light.eval(g.d_el) * phys.phase.eval(-T::one());
        let (s0, s1) = (t0 - x_h, t1 - x_h);
        if sigma_t == T::zero() {
            let span = if s1.is_finite() { (s1 - s0) / s1 } else { T::one() };
            return weighted(phys.sigma_s, phys.intensity, s0 + s0, T::zero(), f * span);
        }
        let two_st = sigma_t + sigma_t;
        let span = t1 - t0;
        if s1.is_finite() && span <= s0 * T::lit(0.125) && two_st * span <= T::one() {
            // σs I f ∫ e^{−σt(2s − s0)}/s² ds over a span short against s0, where head − tail
            // below cancels to rounding (a span of 1e-13 against 179: −4e189 for a true 6e189):
            // Gauss–Legendre with 8 nodes in s, whose integrand e^{−2σt(s − s0)}/s² is smooth
            // there (1/s²'s pole at s = 0 is 17 half-widths from the middle: error ~34^{−16};
            // e^{−λ(1 + ξ)}, λ = σt·span ≤ 1/2: its 16th coefficient below 1e-20)
            let half = span * T::lit(0.5);
            let mut j = T::zero();
            for &(x, w) in &crate::expansion::gauss_table::GL8 {
                for s in [s0 + half * T::lit(1.0 - x), s0 + half * T::lit(1.0 + x)] {
                    j = j + T::lit(w) * (half / s) * (s0 / s) * (-two_st * (s - s0)).exp();
                }
            }
            // σs I f e^{−σt s0} j/s0 as weighted(σs, I, 2 s0, σt s0, f j)
            return weighted(phys.sigma_s, phys.intensity, s0 + s0, sigma_t * s0, f * j);
        }
        let mut e2 = [T::zero(); 2];
        en_scaled(two_st * s0, &mut e2);
        // σs I e^{−x}/s0 as weighted(σs, I, 2 s0, x) (its 2 cancels the 2)
        let head = weighted(phys.sigma_s, phys.intensity, s0 + s0, sigma_t * s0, f * e2[1]);
        let tail = if s1.is_finite() {
            en_scaled(two_st * s1, &mut e2);
            weighted(phys.sigma_s, phys.intensity, s1 + s1, sigma_t * (s1 - s0) + sigma_t * s1, f * e2[1])
        } else {
            T::zero()
        };
        // head ≥ tail in exact arithmetic; ∞ − ∞ (both overflowing) means the value overflows
        if head.is_infinite() { head } else { head - tail }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::light::Omni;
    use crate::phase::HenyeyGreenstein;

    /// `uncut_span` lies below the cut's exponent `E = H·Δv = 1 + ln(8R/(δ·τ))` for every start
    /// `v_s` and `H`, so the shortcut never changes a decision, and by at most `ln 2 + ln R`
    /// (`E − span = ln 2 + ln R − ln 2·frac(log₂(δ·τ))`): it drops only the logarithm.
    #[test]
    fn uncut_span_is_below_the_cut() {
        fn check<T: Real>() {
            for tolerance in [0.5, 1e-1, 3e-3, 1e-5, 1e-8, 1e-11, 1e-14, 1e-20] {
                for floor in [1e-1, 1e-4, 1e-10, 0.0] {
                    let control = Control { tolerance: T::lit(tolerance), floor: T::lit(floor), ..crate::default_control::<T>() };
                    let span = uncut_span(&control);
                    for big_h in [1e-3, 1.0, 7.5, 1e3] {
                        for v_s in [0.0, 0.3, 1.0, 10.0, 1e3] {
                            let e = T::lit(big_h) * cut_length(T::lit(big_h), T::lit(v_s), T::infinity(), &control);
                            let r = (1.0 + (v_s + 1.0 / big_h) * (v_s + 1.0 / big_h)) / (1.0 + v_s * v_s);
                            let slack = core::f64::consts::LN_2 + r.ln();
                            let (span, e) = (span.to_f64_exact(), e.to_f64_exact());
                            assert!(span < e && e - span <= slack * (1.0 + 1e-5) + 1e-5 * e, "tolerance {tolerance:e} floor {floor:e} H {big_h} v_s {v_s}: {span} vs {e}");
                        }
                    }
                }
            }
        }
        check::<f32>();
        check::<f64>();
    }

    /// The heights `t` the integrand declares (with their orders) are where `μ(y) = −σ(1 − y²)/(1 + y²)` reaches the
    /// phase function's singular cosine: at `y = it`, `μ = −σ(1 + t²)/(1 − t²)`; on both halves
    /// (`σ = ∓1`) and for lobes either way, including a near-peak `g = 0.999`.
    #[test]
    fn singular_heights_meet_the_phase_poles() {
        for g in [-0.999f64, -0.6, 0.2, 0.9, 0.999] {
            let phase = HenyeyGreenstein { g };
            let mu_star = phase.singularities().unwrap().cosines[0];
            for sigma in [-1.0f64, 1.0] {
                let f = HalfIntegrand { sigma, exact_sides: true, d_el: 0.3, d_c: 0.5, light: &Omni, phase: &phase };
                let [(one, at_i), (t, order), _] = f.singularities().unwrap();
                // Omni, HG: the pole of 1/(1 + y²) alone at ±i; HG's branch point of order 3/2
                assert_eq!((one, at_i, order), (1.0, 1.0, 1.5));
                let mu = -sigma * (1.0 + t * t) / (1.0 - t * t);
                assert!((mu - mu_star).abs() <= 1e-9 * mu_star.abs(), "g = {g}, σ = {sigma}: t = {t}, μ(it) = {mu}, μ* = {mu_star}");
            }
        }
    }
}
