//! A route by cost: the whole segment as one Gauss–Legendre panel in the angle seen from the
//! light, taken where its error estimate meets the panels' target (docs/DESIGN.md §4.2);
//! otherwise [`crate::combined`] goes on to the closed-form panels.
//!
//! With `t − x_h = h tan θ`, `dt/r² = dθ/h` and the extinction exponent is
//! `σt(t − t0 + r) = σt r0 + H (Y(θ) − Y(θ0))`, `H = σt h`, with
//! `Y = tan(θ/2 + π/4) = (1 + sin θ)/cos θ = cos θ/(1 − sin θ)` — the panels' `v`
//! ([`crate::panels`]) — so
//!
//! `L_m = (σs I/h) e^{−σt r0} ∫_{θ0}^{θ1} e^{−H(Y − Y0)} F dθ`,
//! `F = D(d_el sin θ + d_c cos θ) · P(−sin θ)`.
//!
//! No `1/r²` peak is left: where the medium is thin and the light is not next to the segment
//! this integrand is smooth over the whole segment, and `N` samples of it (`N` the panels'
//! nodes) cost less than the closed forms' `E1` values and moments. The nodes are placed by
//! their distances from the poles `θ = ∓π/2` and a panel narrower than 1 its width from the
//! segment's length (`atan2(u1 − u0, 1 + u0 u1)`; a wider one as `π − ψ0 − ψ1`, within `πε`),
//! so that `cos θ`, `1 ± sin θ` and the width keep full relative accuracy: formed from `θ`
//! itself they lose `ε/cos θ` and `επ/Δθ`, which a peaked phase function amplifies (1.9e-4 in
//! f32 on HG `g = 0.9`, the peer's floor).
//!
//! The samples' Legendre coefficients `c_k` estimate the error by the panels' model
//! (`crate::panels::error_factor`, as on a y-panel, whose weight is 1 too):
//! `2·hw·(|c_{N−1}| + |c_{N−2}|)·q^{N+1−m}` (`m` = [`crate::panels::ALIASING_MARGIN`]), `q` the decay of the last four coefficients raised to the floor of the
//! nearest singularity — the phase function's (`P(−sin θ)` is singular where
//! `sin θ = −μ*`, at `θ = ∓π/2 ± i·acosh|μ*|`) or the exponential's (`Y` has a pole at
//! `θ = π/2`, essential in `e^{−HY}`, which is analytic inside the Bernstein ellipse through
//! it) — and where that floor reaches 1, the panels' cautious `q^{N/4}`. The route is taken
//! when the estimate is below `tolerance × max(|value|, floor × scale)`, the panels' own
//! acceptance test, so the accuracy targets hold as on the panels (tests/tests/classes.rs).
//!
//! It is tried only where it is likely to pass, judged before any sample from predicted
//! sizes of `|c_N/c_0|` (they decide cost, never accuracy):
//! * the exponential and the light's lobe as one rate `λ`: `λ^N/(3·5⋯(2N+1))`, the leading
//!   term of `i_N(λ)` (DLMF 10.53.1; `e^{−λξ}`'s `N`-th Legendre coefficient is `(2N+1) i_N(λ)`
//!   in size, the estimate's aliased part far less), measured to decline mostly samples that
//!   would not pass (tests/classes.rs `light_angle_route_meets_its_tolerance` prints how
//!   often each outcome happens per class); `λ` is the
//!   exponent's mean rate `ΔE/2` or `hw` times its rate where the weight has fallen to `e^{−1}`,
//!   whichever is less (`E` is convex in `θ`), plus `√p·hw` for a distribution of degree `p`
//!   (`c^p ≈ e^{−pφ²/2}`) — large next to the light and in thick media, where the extinction
//!   has a boundary layer and the closed forms stay the method; where `λ` is large but
//!   nothing is singular near the panel (a thick medium, the light away from the ray), the
//!   first try is still made if the estimate's own form, the last two coefficients times its
//!   factor, is predicted within the tolerance;
//! * the lobe alone as a Gaussian's (below, as on the wider rules): a `c^16` lobe inside a
//!   panel 3 wide passes the rate's prediction at 8 nodes and fails the estimate, so its first
//!   try is declined and the 16-node rule follows at once; formed only where the rate's
//!   prediction of the lobe, times the most the Gaussian's exceeds it, is above the tolerance;
//! * the phase's singularities: `ρ^{−N}`, `ρ` of the panel's Bernstein ellipse through the
//!   nearest (a Henyey–Greenstein peak inside the segment has `ρ → 1`).
//!
//! Where the first try of `N` nodes is declined or fails, a light with an axis gets wider rules
//! of `2N`, then `4N` nodes on the same panel ([`Plan::rule`] with `wider`; 8 → 16 → 32;
//! after 16 only 24), and so does a light without one after 8 nodes where the extinction's
//! rate is `λ ≤ 1` (the phase function's peak failed the first try, [`Plan::widens`]),
//! if the phase function's, the extinction's and the lobe's predictions pass at the wider
//! count, each on its own — the lobe's as a Gaussian's: `c^p` is
//! `e^{−pφ²/2}`, whose coefficients fall later than the rate `√p·hw` above says
//! (docs/DESIGN.md §4.2). In a thick medium ([`Plan::thick`]) a light without an axis whose
//! 16-node first try is declined before any sample takes 24 nodes as its first try: the
//! extinction cuts the panel short there, and what declines 16 is mostly the phase function's
//! singularity, which 24 resolve. 16 or 32 samples still cost less than the closed-form panels, also
//! where `N` missed the extinction's rise at the end of a long ray in thin fog. For the same
//! reason a wider rule's estimate, where the last coefficients do not yet fall (a lobe inside
//! the panel, whose coefficients oscillate with `P_k` at its centre), takes the lobe's own decay
//! from the degree it reads, `N − 1`, to the one the rule leaves, `2N − m` — the Gaussian's
//! `I_{N−m/2}(z)/I_{(N−1)/2}(z)` — but never more than the phase function's rate allows
//! (`rate^{N+1−m}`): the lobe is entire, so only the singularities bound the decay from below.
//! The exponential's (Y's pole just past the end of a long ray's panel) is a property of the
//! weight `e^{−H(Y − Y0)}`, not of the lobe: its part is the weight's own last coefficients
//! (the samples' weights, transformed as the samples are) carried at that rate, times `F`'s
//! largest sample, and added — the weight's tail is small where the medium is thin, while
//! the lobe's is large at degree `N` but falls as a Gaussian's. The lesser of this and the
//! ordinary estimate is taken.
//!
//! A light distribution with kinks (a cone's edge) or that is no polynomial in `c` declines
//! the route, and so does a phase function that does not declare its singularities: `F` would
//! not be analytic in `θ`, or not known to be.
//!
//! Rays that share the panel — the same `h`, `x_h` and ends, only `d_el`, `d_c` differing, as a
//! surface point's rays about a beam's axis at one `γ` (`crate::surface`, docs/DESIGN.md §11) —
//! share a rule's nodes, extinction weights and `P`: each is judged on its own `D` and estimate
//! (`Plan::tries_each`), or, `F` being linear in `D`, a weighted sum of them is sampled as one
//! light (`Emission`).

use crate::combined::{bounded, cut_length, weighted, Physics};
use crate::expansion::gauss_table;
use crate::geometry::Canonical;
use crate::light::{whole_polynomial_degree, LightDistribution};
use crate::panels::{bernstein_rho, legendre_from, node_f64, order_step, power, tail_estimate, transform_noise, unit_weight_factor, Control, ALIASING_MARGIN};
use crate::phase::{PhaseFunction, Singularities};
use crate::real::{atan2_upper, atan_nonnegative, exp_nonpositive, hypot1, larger, sin_cos_quarter, Real};
use crate::scalar::Scalar;

/// What the route did.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Route<T> {
    /// Not tried: `F` is not analytic in `θ`, or a predicted coefficient is above the
    /// tolerance.
    Declined,
    /// Tried (one panel of samples spent), the estimate above the target.
    Failed,
    /// Taken: `L_m`.
    Taken(T),
}

/// The light's factor of `F` at a rule's nodes, from their `(cos θ, sin θ)`: one ray's
/// distribution ([`Along`]), or a weighted sum of several rays' that share the panel
/// (`crate::surface`'s arc of rays about a light's axis).
pub(crate) trait Emission<T> {
    /// The factor at each node.
    fn at<const N: usize>(&self, angles: &[(T, T); N]) -> [T; N];
}

/// One ray's `D(d_el sin θ + d_c cos θ)`.
pub(crate) struct Along<'a, T, D> {
    pub(crate) light: &'a D,
    pub(crate) d_el: T,
    pub(crate) d_c: T,
}

impl<T: Real, D: LightDistribution<T>> Emission<T> for Along<'_, T, D> {
    #[inline]
    fn at<const N: usize>(&self, angles: &[(T, T); N]) -> [T; N] {
        along(self.light, self.d_el, self.d_c, angles)
    }
}

/// `D(d_el sin θ + d_c cos θ)` at each of the nodes `(cos θ, sin θ)`.
#[inline]
pub(crate) fn along<T: Real, D: LightDistribution<T>, const N: usize>(light: &D, d_el: T, d_c: T, angles: &[(T, T); N]) -> [T; N] {
    let mut lights = [T::zero(); N];
    for (&(c, s), d) in angles.iter().zip(lights.iter_mut()) {
        *d = d_el * s + d_c * c;
    }
    light.eval_each(&mut lights);
    lights
}

/// The whole segment `[t0, t1]` (`h > 0`) by one `N`-node Gauss–Legendre panel in `θ`, cut where
/// the panels cut a half (`crate::combined::cut_length`), if its estimate meets `control`:
/// [`Plan::new`], then [`Plan::rule`] without a lobe's condition.
pub fn whole_segment<T, D, P, const N: usize>(g: &Canonical<T>, phys: &Physics<'_, T, D, P>, control: &Control<T>) -> Route<T>
where
    T: Real,
    D: LightDistribution<T>,
    P: PhaseFunction<T>,
{
    match Plan::new(g, phys, control) {
        Some(plan) => plan.rule::<D, P, N>(g, phys, control, false),
        None => Route::Declined,
    }
}

/// What the routes' predictions read before any angle is formed: the segment's ends in `Y`, `H`,
/// the light's degree and the phase function's singularities. Gauss–Laguerre in
/// the optical depth ([`crate::depth`]), tried first in a thick medium, needs no more, so it
/// pays for none of [`Plan`]'s angles and rates.
#[derive(Clone, Copy, Debug)]
pub struct Ends<T> {
    /// `u0 = (t0 − x_h)/h`.
    pub(crate) u0: T,
    /// `u1 = (t1 − x_h)/h` (`+∞` for an infinite ray).
    u1: T,
    /// `H = σt h`.
    pub(crate) big_h: T,
    /// `Y` at the start.
    pub(crate) y0: T,
    /// `Y` at the end (`+∞` for an infinite ray).
    pub(crate) y1: T,
    /// The light distribution's degree `p` in `c` (0 without an axis).
    pub(crate) degree: T,
    /// The phase function's singularities.
    pub(crate) singular: Singularities<T>,
}

impl<T: Real> Ends<T> {
    /// `None` where the route cannot be taken at all: `F` not analytic in `θ` or not known to
    /// be, the light on the ray's line.
    #[inline]
    pub fn new<D, P>(g: &Canonical<T>, phys: &Physics<'_, T, D, P>) -> Option<Self>
    where
        D: LightDistribution<T>,
        P: PhaseFunction<T>,
    {
        let degree = whole_polynomial_degree(phys.light)?;
        let singular = phys.phase.singularities()?;
        let h = g.h;
        if !(h > T::zero()) {
            return None;
        }
        let (u0, u1) = (g.u(g.t0), g.u(g.t1));
        // Y = u + √(1+u²) without cancellation: the halves' bounded y before the foot
        let y_at = |u: T| if u < T::zero() { bounded(-u) } else { u + hypot1(u) };
        Some(Ends { u0, u1, big_h: phys.sigma_t * h, y0: y_at(u0), y1: y_at(u1), degree: T::from(degree).unwrap(), singular })
    }

    /// Whether the medium is thick where the light is: `σt·h ≥ 1`, the light at least a mean
    /// free path from the ray's line, so that the extinction falls by `e` or more within the
    /// light's distance. There Gauss–Laguerre in the optical depth, whose weight the
    /// extinction is, is tried first ([`crate::depth`]); in thinner media the weight is
    /// smooth in the angle, and the light angle's first try passes where that one would.
    pub fn thick(&self) -> bool {
        thick(self.big_h)
    }
}

/// [`Ends::thick`] from `H = σt·h`.
#[inline]
pub(crate) fn thick<T: Real>(big_h: T) -> bool {
    big_h >= T::one()
}

/// What every rule of the route shares: the panel in `θ` and the predicted rates, formed once
/// for the first try's `N` nodes and the wider rules after it (`2N`, then `4N`).
#[derive(Clone, Copy, Debug)]
pub struct Plan<T> {
    /// `u0 = (t0 − x_h)/h`.
    u0: T,
    /// `H = σt h`.
    big_h: T,
    /// `Y` at the start.
    y0: T,
    /// The ends' distances from the poles: `ψ0 = θ0 + π/2`, `ψ1 = π/2 − θ1` (`θ1` the cut end).
    psi0: T,
    psi1: T,
    /// The panel's half-width in `θ`.
    hw: T,
    /// The extinction's rate `λ` over the panel (module docs).
    lambda: T,
    /// The lobe's `√p·hw` (0 without an axis).
    lobe: T,
    /// `1/ρ` of the phase function's nearest singularity: `ρ` of the panel's Bernstein
    /// ellipse through it (0 without one).
    phase: T,
    /// Its order ([`crate::phase::Singularities::order`]).
    order: T,
    /// `1/ρ` of the ellipse through `Y`'s pole at `θ = π/2`, where `e^{−HY}` is singular (0
    /// without extinction).
    exponential: T,
}

impl<T: Real> Plan<T> {
    /// The panel and its rates; `None` where the route cannot be taken at all: `F` not
    /// analytic in `θ` or not known to be, the light on the ray's line, an empty panel.
    #[inline]
    pub fn new<D, P>(g: &Canonical<T>, phys: &Physics<'_, T, D, P>, control: &Control<T>) -> Option<Self>
    where
        D: LightDistribution<T>,
        P: PhaseFunction<T>,
    {
        Self::from_ends(&Ends::new(g, phys)?, g, control)
    }

    /// [`Plan::new`] from the segment's [`Ends`], formed before.
    #[inline(always)]
    pub fn from_ends(ends: &Ends<T>, g: &Canonical<T>, control: &Control<T>) -> Option<Self> {
        let Ends { u0, u1, big_h, y0, y1, degree, singular, .. } = *ends;
        let h = g.h;
        let y_cut = y0 + cut_length(big_h, y0, y1 - y0, control);
        // The ends as their distances from the poles θ = ∓π/2 (ψ0 = θ0 + π/2, ψ1 = π/2 − θ1),
        // to full relative accuracy: F's lobes and the exponential's layer sit at the poles,
        // where cos θ formed from θ itself would lose ε/cos θ of it (and a peaked phase
        // function amplifies that, as for the panels' `1 ∓ μ`).
        let psi0 = atan2_upper(T::one(), -u0);
        // ψ1, and the width as k·atan2(y, x) from the segment's length, not from the difference
        // of the ends' angles (ε·π/Δθ of it lost on a short segment): atan u1 − atan u0 =
        // atan2(u1 − u0, 1 + u0 u1), 2(atan Y_cut − atan Y0) = 2 atan2(Y_cut − Y0, 1 + Y0 Y_cut)
        let (psi1, (k, y, x)) = if y_cut < y1 {
            (T::lit(2.0) * atan_nonnegative(y_cut.recip()), (T::lit(2.0), y_cut - y0, T::one() + y0 * y_cut))
        } else if u1.is_finite() {
            (atan2_upper(T::one(), u1), (T::one(), (g.t1 - g.t0) / h, T::one() + u0 * u1))
        } else {
            (T::zero(), (T::one(), T::one(), u0))
        };
        // a width of at least 1 as π − ψ0 − ψ1 loses at most πε of it: no second atan
        let difference = T::PI() - psi0 - psi1;
        let width = if difference >= T::one() { difference } else { k * atan2_upper(y, x) };
        let hw = width * T::lit(0.5);
        if !(hw > T::zero()) {
            return None;
        }
        // The extinction's rate: e^{−E} with E rising at the rate λ/hw is e^{−λ(1+ξ)} on the
        // panel. E is convex in θ (dE/dθ = H/(1 − sin θ) = H(1 + Y²)/2), so λ is the lesser of
        // two: the mean rate, ΔE/2 with ΔE = H(Y_end − Y0), and hw times the rate where the
        // weight has fallen to e^{−1} (beyond it the weight is small however fast it falls).
        let y_end = y1.min(y_cut);
        let y_e = (y0 + big_h.recip()).min(y_end);
        let lambda = if big_h > T::zero() { (big_h * (y_end - y0)).min(hw * big_h * (T::one() + y_e * y_e)) * T::lit(0.5) } else { T::zero() };
        // D, a polynomial of degree p in c = A cos(θ − θ_axis): a lobe c^p ≈ e^{−pφ²/2} of
        // angular width about 1/√p
        let lobe = degree.sqrt() * hw;
        // The phase function's nearest singularity, at sin θ = −μ*, θ = ∓π/2 ± i·acosh|μ*|: 1/ρ
        // of the panel's Bernstein ellipse through it, the pole ψ0 before the panel's start or ψ1
        // past its end (1 + ψ/hw from its centre, in units of hw)
        let inv_hw = hw.recip();
        let mut phase = T::zero();
        for mu in singular.cosines {
            let gap = mu.abs() - T::one();
            if !(gap > T::zero()) || !gap.is_finite() {
                continue;
            }
            let offset = if mu > T::zero() { psi0 } else { psi1 };
            phase = phase.max(pole_rate(gap, offset, inv_hw));
        }
        // Y's pole, ψ1 past the panel's end: on the real axis at 1 + d, d = ψ1/hw, so ρ = 1 +
        // `axis_excess(d)` (`bernstein_rho` on the axis, one square root, and d to full accuracy
        // where the pole is close)
        let exponential = if big_h > T::zero() { (T::one() + axis_excess(psi1 * inv_hw)).recip() } else { T::zero() };
        Some(Plan { u0, big_h, y0, psi0, psi1, hw, lambda, lobe, phase, order: singular.order, exponential })
    }

    /// [`Ends::thick`].
    pub fn thick(&self) -> bool {
        thick(self.big_h)
    }

    /// Where a panel the rules do not pass on is split (`t`, of `g`, the segment it was formed
    /// for): where the extinction's exponent has risen by 1 from the start (`Y = Y0 + 1/H`), if
    /// its rate over the panel is above 1 (`λ > 1`: the layer at a long ray's far end, where
    /// halves in `θ` would shrink towards the end one at a time) and that lies inside; else at
    /// the middle in `θ`, `θ = (ψ0 − ψ1)/2` (the cut end's `ψ1`).
    pub(crate) fn split_point(&self, g: &Canonical<T>) -> T {
        if self.lambda > T::one() && self.big_h > T::zero() {
            // t − x_h = h·u, u = (Y − 1/Y)/2
            let y = self.y0 + self.big_h.recip();
            let t = g.x_h + g.h * ((y - y.recip()) * T::lit(0.5));
            if t > g.t0 && t < g.t1 {
                return t;
            }
        }
        g.x_h + g.h * ((self.psi0 - self.psi1) * T::lit(0.5)).tan()
    }

    /// Where a graded route may end this panel's first part (`crate::combined`'s graded
    /// route): the second half's grading point `y_p` ([`crate::panels::graded_point`], `y` of the
    /// second half, whose ends are `y_lo`, `y_hi`) towards the phase function's nearest backward
    /// singularity (`μ* < −1`, at the height `√(gap/(2 + gap))` in `y`, `gap = |μ*| − 1`), if
    /// `N` nodes are predicted to pass on `[θ0, θ_p]`: the forward singularities as
    /// [`Plan::rule`] predicts them on this panel (a part with this one's start and an earlier
    /// end has them no nearer in its own units), and the backward one, `ψ_p = 2 atan y_p` past
    /// the part's end, with ten times less (measured: with no margin, seven of the 30
    /// `near_light` rays of tests/reference/classes.jsonl failed the part's estimate in f32 at
    /// tolerance 1e-3). `None` without a backward singularity or where a prediction fails. Formed
    /// only where the whole segment's tries did not pass, not in [`Plan::new`].
    pub(crate) fn graded_point<P: PhaseFunction<T>, const N: usize>(&self, phase: &P, y_lo: T, y_hi: T, tolerance: T) -> Option<T> {
        let singular = phase.singularities()?;
        let gap = singular.cosines.iter().fold(T::infinity(), |m, &mu| if mu < -T::one() { m.min(-mu - T::one()) } else { m });
        if !gap.is_finite() {
            return None;
        }
        let y_p = crate::panels::graded_point(y_lo, y_hi, core::iter::once((gap / (T::lit(2.0) + gap)).sqrt()))?;
        // the part's half-width and the singularities' rates on it, as `Plan::new` forms them
        let psi_p = T::lit(2.0) * atan_nonnegative(y_p);
        let hw = (T::PI() - self.psi0 - psi_p) * T::lit(0.5);
        let step = order_step(singular.order, N);
        let inv_hw = self.hw.recip();
        let forward = singular.cosines.iter().fold(T::zero(), |m, &mu| if mu > T::one() && mu.is_finite() { m.max(step * pole_rate(mu - T::one(), self.psi0, inv_hw)) } else { m });
        let backward = step * pole_rate(gap, psi_p, hw.recip());
        (hw > T::zero() && power(forward, N) <= tolerance && power(backward, N) * T::lit(10.0) <= tolerance).then_some(y_p)
    }

    /// Whether wider rules may follow a first try of `n` nodes: always for a light's lobe;
    /// without an axis (the phase function's peak alone) only after fewer than 16 nodes and
    /// where the extinction's rate is `λ ≤ 1` (the weight falls by at most `e^{−2}` over the
    /// panel). A larger `λ` is the extinction's layer at the panel's end (a long ray's rise),
    /// which the closed-form panels resolve at less cost and far below the tolerance; after 16
    /// nodes, 24 rarely resolve a peak that 16 did not (docs/DESIGN.md §4.2 has the measurements).
    pub fn widens(&self, n: usize) -> bool {
        self.lobe > T::zero() || (n < 16 && self.lambda <= T::one())
    }

    /// The panel by `N` Gauss–Legendre nodes, if the predicted coefficients are below the
    /// tolerance and then the estimate meets it.
    ///
    /// `wider`: a wider rule after a first try of fewer nodes ([`Plan::widens`]), for a light's
    /// lobe, the extinction's layer at the panel's end or the phase function's nearest
    /// singularity: declined unless each prediction passes on its own at `N`, the lobe's as a
    /// Gaussian's (module docs).
    pub fn rule<D, P, const N: usize>(&self, g: &Canonical<T>, phys: &Physics<'_, T, D, P>, control: &Control<T>, wider: bool) -> Route<T>
    where
        D: LightDistribution<T>,
        P: PhaseFunction<T>,
    {
        self.rule_of::<D, P, _, N>(g, phys, control, wider, &Along { light: phys.light, d_el: g.d_el, d_c: g.d_c })
    }

    /// The first try of `N` nodes and the wider rules after it where [`Plan::widens`] (`2N`,
    /// then `4N`; after 16 only 24: 32 cost f64 more than they saved on four of the five classes
    /// with an axis, docs/DESIGN.md §4.2), the light sampled by `emission`; and the rules
    /// sampled. In a thick medium ([`Plan::thick`]) a light without an axis whose 16 nodes are
    /// declined before any sample gets 24 as its first try instead.
    #[inline(always)]
    pub(crate) fn tries<D, P, E, const N: usize>(&self, g: &Canonical<T>, phys: &Physics<'_, T, D, P>, control: &Control<T>, emission: &E) -> (Option<T>, usize)
    where
        P: PhaseFunction<T>,
        E: Emission<T>,
    {
        let mut one = One { plan: self, g, phys, control, emission, value: None };
        let tried = self.sequence::<_, N>(&mut one);
        (one.value, tried)
    }

    /// [`Plan::tries`] for several rays that share this panel (`h`, `x_h`, the ends), `(d_el,
    /// d_c)` each, on the rules' shared samples (the nodes, the extinction's weights, `P`), each
    /// ray judged on its own estimate: `out[k]` is ray `k`'s value where a rule passed on it,
    /// else left `None` (`out` as long as `rays`). The rules sampled.
    pub(crate) fn tries_each<D, P, const N: usize>(&self, g: &Canonical<T>, phys: &Physics<'_, T, D, P>, control: &Control<T>, rays: &[(T, T)], out: &mut [Option<T>]) -> usize
    where
        D: LightDistribution<T>,
        P: PhaseFunction<T>,
    {
        self.sequence::<_, N>(&mut Each { plan: self, g, phys, control, rays, out })
    }

    /// The first rule of `N` nodes, then the wider ones (module docs), until `rules` has its
    /// values; the rules sampled.
    #[inline(always)]
    fn sequence<R: Rules, const N: usize>(&self, rules: &mut R) -> usize {
        let (sampled, mut done) = rules.run::<N>(false);
        let mut tried = usize::from(sampled);
        // a thick medium's 16 declined before any sample (a light without an axis): 24 as the
        // first try, whose predictions the phase function's singularity passes more often
        // than 16's (docs/DESIGN.md §4.2)
        if !sampled && N == 16 && !self.widens(N) && self.thick() {
            return usize::from(rules.run::<24>(false).0);
        }
        let counts: &[usize] = if !self.widens(N) {
            &[]
        } else if N == 16 {
            &[24]
        } else {
            &[2 * N, 4 * N]
        };
        for &n in counts {
            if done {
                break;
            }
            let (sampled, now) = match n {
                8 => rules.run::<8>(true),
                12 => rules.run::<12>(true),
                16 => rules.run::<16>(true),
                24 if N == 16 => rules.run::<24>(true),
                32 if N == 8 => rules.run::<32>(true),
                _ => (false, false),
            };
            tried += usize::from(sampled);
            done = now;
        }
        tried
    }

    /// [`Plan::rule`] with the light sampled by `emission`.
    fn rule_of<D, P, E, const N: usize>(&self, g: &Canonical<T>, phys: &Physics<'_, T, D, P>, control: &Control<T>, wider: bool, emission: &E) -> Route<T>
    where
        P: PhaseFunction<T>,
        E: Emission<T>,
    {
        let judged = self.sampled::<D, P, _, N>(g, phys, control, wider, |shared| {
            let lights = emission.at(&shared.angles);
            shared.judge(phys, control, &lights, &shared.phases, &mut None)
        });
        match judged {
            None => Route::Declined,
            Some(value) => value.map_or(Route::Failed, Route::Taken),
        }
    }

    /// The rule of `N` nodes for each ray of `rays` whose `out` is `None`, on shared samples;
    /// whether it was sampled (`false`: declined before any sample).
    fn rule_each<D, P, const N: usize>(&self, g: &Canonical<T>, phys: &Physics<'_, T, D, P>, control: &Control<T>, wider: bool, rays: &[(T, T)], out: &mut [Option<T>]) -> bool
    where
        D: LightDistribution<T>,
        P: PhaseFunction<T>,
    {
        self.sampled::<D, P, _, N>(g, phys, control, wider, |shared| {
            let mut model = None;
            for (&(d_el, d_c), slot) in rays.iter().zip(out.iter_mut()) {
                if slot.is_none() {
                    *slot = shared.judge(phys, control, &along(phys.light, d_el, d_c, &shared.angles), &shared.phases, &mut model);
                }
            }
        })
        .is_some()
    }

    /// The predictions of an `N`-node rule (`None` where one declines it), then `judge` on the
    /// samples every ray on the panel shares: the nodes' angles, the extinction's weights and
    /// `P`.
    #[inline(always)]
    fn sampled<D, P, R, const N: usize>(&self, g: &Canonical<T>, phys: &Physics<'_, T, D, P>, control: &Control<T>, wider: bool, judge: impl FnOnce(&Shared<T, N>) -> R) -> Option<R>
    where
        P: PhaseFunction<T>,
    {
        let (Some(rule), Some(_), true) = (gauss_table::rule(N), gauss_table::transform(N), N >= 4) else {
            return None;
        };
        let Plan { u0, big_h, y0, psi0, psi1, hw, lambda, lobe, phase, order, exponential } = *self;
        let tolerance = control.tolerance;
        // The predicted coefficients, before any sample: the extinction's e^{−λ(1+ξ)} has
        // the N-th Legendre coefficient (2N+1)·i_N(λ) of its mean, i_N(λ) ≈
        // λ^N/(3·5⋯(2N+1)) (module docs); on the first try the lobe as the exponential with
        // λ = √p·hw, the two rates added, and on every rule by its own prediction too; where
        // c_N's declines a first try, the estimate's own form may still let it through
        // (`predicted_estimate`: a steep extinction with nothing singular near the panel)
        // (the phase function's rate ρ^{−1} with its order's step as the panels take it, formed
        // once for this and its own prediction below)
        let singular_rate = order_step(order, N) * phase;
        let rate = if wider { lambda } else { lambda + lobe };
        if !(predicted_coefficient(rate, N) <= tolerance) && (wider || !(predicted_estimate::<T, N>(rate, singular_rate, exponential) <= tolerance)) {
            return None;
        }
        // the lobe e^{−p·hw²ξ²/2} as a Bessel function's terms, z = p·hw²/4: the estimate adds
        // two coefficients, each about its degree-(2N − m) one (m = ALIASING_MARGIN),
        // 2·I_n(z)/I_0(z) of the mean with n = N − m/2, ≈ 2 exp(√(n² + z²) − n asinh(n/z) − z)
        // (uniform asymptotics, DLMF 10.41.3). On the first try it is formed only where it can
        // decline: it exceeds the lobe's prediction as a rate by at most `gaussian_over_rate(N)`.
        let z = lobe * lobe * T::lit(0.25);
        if z > T::zero() && (wider || predicted_coefficient(lobe, N) * T::lit(gaussian_over_rate(N)) > tolerance) {
            if !(gaussian_prediction(z, N) <= tolerance) {
                return None;
            }
        }
        // The singularities': ρ^{−N} of the nearest (`Plan::phase`), with its order's step as
        // the panels take it, and the exponential's own, Y's pole at θ = π/2 (essential in
        // e^{−HY}, which is analytic inside the ellipse through it).
        let rate = singular_rate;
        if !(power(rate, N) <= tolerance) {
            return None;
        }
        // Without an axis a wider rule serves the phase function's peak; it declines where Y's
        // pole lies so close past the panel's end that N nodes do not resolve it (ρ^N < e, the
        // last node farther from the end than the pole): there the extinction's layer at the
        // end (a light next to the ray) is not yet in the last coefficients, and the estimate
        // misses it (a near_light ray of tests/reference/classes.jsonl: 2.4e-5 off at 32 nodes
        // with an estimate of 8.3e-7).
        if wider && !(z > T::zero()) && !(power(exponential, N) <= T::lit(core::f64::consts::E.recip())) {
            return None;
        }
        let (phase_rate, rate) = (rate, rate.max(exponential));

        // The samples, in the order `legendre` expects (−x_1, x_1, −x_2, …), in passes — the
        // nodes' cos θ and sin θ, then Y and 1 ± sin θ, then the weights, then D and P, each for
        // all N at once (`eval_each`, `eval_sides_each`: a branch on the parameters taken once),
        // then F — so that each pass's calls and divisions are independent of one another and
        // overlap instead of waiting in turn.
        // θ = θ0 + hw(1 + x) = θ1 − hw(1 − x), formed as a distance from the nearer pole, so cos θ
        // keeps full relative accuracy; sin θ's sign then says which pole is nearer, and
        // 1 ∓ sin θ, Y follow without cancellation.
        let mut angles = [(T::zero(), T::zero()); N];
        for (i, angle) in angles.iter_mut().enumerate() {
            let x = node_f64(rule, i);
            let lower = psi0 + hw * T::lit(1.0 + x);
            *angle = if lower <= T::FRAC_PI_2() {
                let (c, minus_s) = sin_cos_quarter(lower);
                (c, -minus_s)
            } else {
                sin_cos_quarter(psi1 + hw * T::lit(1.0 - x))
            };
        }
        // of 1 ± sin θ, far = 1 + |sin θ| stays at least 1 and near = cos²θ/far vanishes at the
        // nearer pole, both without cancellation; Y = (1 + sin θ)/cos θ = cos θ/(1 − sin θ)
        let mut sides = [(T::zero(), T::zero(), T::zero()); N];
        for (&(c, s), side) in angles.iter().zip(sides.iter_mut()) {
            let far = T::one() + s.abs();
            let near = c * c / far;
            *side = if s > T::zero() { (far / c, far, near) } else { (c / far, near, far) };
        }
        // e^{−H(Y − Y0)} by `exp_nonpositive`: in f32 inline, so that the pass vectorises
        let mut weights = [T::zero(); N];
        for ((&(c, _), &(y, _, _)), weight) in angles.iter().zip(sides.iter()).zip(weights.iter_mut()) {
            *weight = if c > T::zero() { exp_nonpositive(-(big_h * (y - y0)).max(T::zero())) } else { T::zero() };
        }
        // μ = −sin θ: 1 − μ = 1 + sin θ, 1 + μ = 1 − sin θ
        let phases = phys.phase.eval_sides_each(&angles.map(|(_, s)| -s), &sides.map(|(_, plus, _)| plus), &sides.map(|(_, _, minus)| minus));
        Some(judge(&Shared { rule, angles, phases, weights, rate, phase_rate, z, exponential, wider, tolerance, h: g.h, u0, hw }))
    }
}

/// What the rays on one panel share at a rule of `N` nodes ([`Plan::rule`]'s samples but `D`).
struct Shared<T, const N: usize> {
    rule: &'static [(f64, f64)],
    /// `(cos θ, sin θ)` at the nodes.
    angles: [(T, T); N],
    /// `P(−sin θ)` at the nodes.
    phases: [T; N],
    /// `e^{−H(Y − Y0)}` at the nodes.
    weights: [T; N],
    /// The estimate's rate, the phase function's alone, the lobe's `z` and the exponential's.
    rate: T,
    phase_rate: T,
    z: T,
    exponential: T,
    wider: bool,
    tolerance: T,
    h: T,
    u0: T,
    hw: T,
}

impl<T: Real, const N: usize> Shared<T, N> {
    /// One ray's value from its `D` at the nodes, where its estimate meets the target; `model`
    /// keeps a wider rule's lobe model and the weight's tail, the same for every ray, once
    /// formed.
    #[inline(always)]
    fn judge<D, P>(&self, phys: &Physics<'_, T, D, P>, control: &Control<T>, lights: &[T; N], phases: &[T; N], model: &mut Option<(T, T)>) -> Option<T> {
        let Shared { rule, weights, rate, phase_rate, z, exponential, wider, tolerance, h, u0, hw, .. } = *self;
        let mut samples = [T::zero(); N];
        let (mut value, mut mass, mut f_max) = (T::zero(), T::zero(), T::zero());
        for (i, sample) in samples.iter_mut().enumerate() {
            let weight = weights[i];
            let f = lights[i] * phases[i];
            let gw = weight * f;
            *sample = gw;
            let w = T::lit(rule[i / 2].1);
            value = value + w * gw;
            mass = mass + w * weight;
            f_max = larger(f_max, f.abs());
        }
        // below a rate of 1 the estimate reads only the last four coefficients
        // (`error_factor`'s model with the weight 1: q^{N+1−m}); at or above it, all of them
        let c = if rate < T::one() { legendre_from::<T, N>(&samples, N - 4) } else { legendre_from::<T, N>(&samples, 0) };
        // the panels' model with the weight 1 (moments M_0 = 2, M_k = 0): q^{N+1−m} where the
        // rate is known and below 1, the cautious q^{N/4} where it is not
        let factor = unit_weight_factor::<T, N>(&c, rate);
        let last = tail_estimate::<T, N>(&c);
        // in units of hw: the integral of Σ c_k P_k is 2c_0; the transform's rounding as on a
        // y-panel (mass 2 times the samples' weighted mean magnitude), formed only where the
        // estimate misses the target
        let error = T::lit(2.0) * last * factor;
        let target = tolerance * value.abs().max(control.floor * f_max * mass);
        let noise = if error <= target {
            T::zero()
        } else {
            let magnitude = samples.iter().enumerate().fold(T::zero(), |m, (i, gw)| m + T::lit(rule[i / 2].1) * gw.abs());
            transform_noise::<T, N>(T::lit(2.0), magnitude * T::lit(0.5))
        };
        if !(error <= target || error <= noise) {
            // A wider rule is spent on the lobe c^p, whose coefficients fall faster than
            // geometrically: where the last ones do not yet fall (the lobe inside the panel),
            // from the degree the estimate reads to the one the rule leaves by the lobe's own
            // model, never faster than the phase function's rate allows; the exponential's
            // slower rate (Y's pole past the panel's end) is carried on the weight's own
            // coefficients, times F's largest sample, not on the lobe's (module docs).
            // (without an axis, no lobe: the ordinary estimate stands)
            if !(wider && rate < T::one() && z > T::zero()) {
                return None;
            }
            let (lobe_factor, weight_tail) = match *model {
                Some(known) => known,
                None => {
                    let cw = legendre_from::<T, N>(&weights, N - 4);
                    *model.insert((lobe_decay::<T>(z, N).max(power(phase_rate, N + 1 - ALIASING_MARGIN)), T::lit(2.0) * tail_estimate::<T, N>(&cw) * unit_weight_factor::<T, N>(&cw, exponential)))
                }
            };
            let error = (T::lit(2.0) * last * lobe_factor + weight_tail * f_max).min(error);
            if !(error <= target || error <= noise) {
                return None;
            }
        }
        // (σs I/h) e^{−σt r0} ∫ as the halves form it: no ∞·0 where σs I/h overflows, and without
        // extinction the exponent 0, not 0·∞ where r0 overflows
        let x = if phys.sigma_t > T::zero() { phys.sigma_t * (h * hypot1(u0)) } else { T::zero() };
        Some(weighted(phys.sigma_s, phys.intensity, h, x, value * hw * T::lit(0.5)))
    }
}

/// A sequence of rules on one panel ([`Plan::sequence`]).
trait Rules {
    /// The rule of `N` nodes: whether it was sampled, and whether every value is now known.
    fn run<const N: usize>(&mut self, wider: bool) -> (bool, bool);
}

/// One ray's rules, its light sampled by an [`Emission`].
struct One<'a, T, D, P, E> {
    plan: &'a Plan<T>,
    g: &'a Canonical<T>,
    phys: &'a Physics<'a, T, D, P>,
    control: &'a Control<T>,
    emission: &'a E,
    value: Option<T>,
}

impl<T: Real, D, P: PhaseFunction<T>, E: Emission<T>> Rules for One<'_, T, D, P, E> {
    #[inline(always)]
    fn run<const N: usize>(&mut self, wider: bool) -> (bool, bool) {
        match self.plan.rule_of::<D, P, E, N>(self.g, self.phys, self.control, wider, self.emission) {
            Route::Taken(value) => {
                self.value = Some(value);
                (true, true)
            }
            Route::Failed => (true, false),
            Route::Declined => (false, false),
        }
    }
}

/// Several rays' rules ([`Plan::tries_each`]).
struct Each<'a, T, D, P> {
    plan: &'a Plan<T>,
    g: &'a Canonical<T>,
    phys: &'a Physics<'a, T, D, P>,
    control: &'a Control<T>,
    rays: &'a [(T, T)],
    out: &'a mut [Option<T>],
}

impl<T: Real, D: LightDistribution<T>, P: PhaseFunction<T>> Rules for Each<'_, T, D, P> {
    fn run<const N: usize>(&mut self, wider: bool) -> (bool, bool) {
        let sampled = self.plan.rule_each::<D, P, N>(self.g, self.phys, self.control, wider, self.rays, self.out);
        (sampled, self.out.iter().all(Option::is_some))
    }
}

/// The lobe `c^p ≈ e^{−p·hw²ξ²/2}`'s coefficients from the degree the estimate reads, `N − 1`, to
/// the one an `N`-node rule leaves, `2N − m` (`m` = [`ALIASING_MARGIN`]), by its model (module
/// docs): the ratio `I_{N−m/2}(z)/I_{(N−1)/2}(z)`, `z = p·hw²/4 > 0` (a light without an axis
/// has no lobe, and its wider rules the ordinary estimate only), by [`bessel_exponent`]; the prefactors' ratio
/// `((ν_1² + z²)/(ν_2² + z²))^{1/4}` ≤ 1 is left out, which can only raise it.
fn lobe_decay<T: Real>(z: T, n: usize) -> T {
    let exponent = |nu: f64| bessel_exponent(T::lit(nu), z);
    (exponent(n as f64 - ALIASING_MARGIN as f64 * 0.5) - exponent((n as f64 - 1.0) * 0.5)).exp().min(T::one())
}

/// The lobe's Gaussian prediction of an `n`-node rule's estimate relative to the mean,
/// `4·I_{n−m/2}(z)/I_0(z)` (`m` = [`ALIASING_MARGIN`]) by [`bessel_exponent`]: the estimate
/// adds two coefficients (`|c_{n−1}| + |c_{n−2}|`, carried to the degree `2n − m` the rule
/// leaves), each about the degree-`(2n − m)` one, `2·I_{n−m/2}(z)/I_0(z)` ([`Plan::rule`]).
/// With one coefficient's size (half this) the 16-node rule was tried and failed on five
/// `c^52 … c^64` rays of tests/reference/classes.jsonl in f32 (that size 0.65–0.82 of the
/// tolerance 1e-1, where every 16-node rule that passed on the beam classes had at most 0.005
/// of it), 16 samples spent before the 32 that pass.
#[inline]
fn gaussian_prediction<T: Real>(z: T, n: usize) -> T {
    T::lit(4.0) * (bessel_exponent(T::lit(n as f64 - ALIASING_MARGIN as f64 * 0.5), z) - z).exp()
}

/// The largest ratio of the lobe's Gaussian prediction `4·I_{N−m/2}(z)/I_0(z)` ([`gaussian_prediction`],
/// `m` = [`ALIASING_MARGIN`]) to its prediction as a rate, `(2√z)^N/(3·5⋯(2N+1))`, over every
/// `z > 0`, rounded up (`tests::gaussian_over_rate_bounds_the_ratio` checks it on a grid: 22.8,
/// 18.6, 22.6, 35.2, 66.0, 358.4 at 4, 6, 8, 10, 12, 16 nodes); `∞` for other counts. Where the
/// rate's prediction times this is within the tolerance, the Gaussian's cannot decline.
fn gaussian_over_rate(n: usize) -> f64 {
    match n {
        0..=8 => 24.0,
        9..=10 => 36.0,
        11..=12 => 68.0,
        13..=16 => 360.0,
        _ => f64::INFINITY,
    }
}

/// `√(ν² + z²) − ν asinh(ν/z)`: the exponent of Debye's uniform form `I_ν(z) ≈
/// e^{√(ν² + z²) − ν asinh(ν/z)} / (2π√(ν² + z²))^{1/2}` (DLMF 10.41.3), the lobe's model in the
/// wider rules' prediction and estimate.
#[inline]
fn bessel_exponent<T: Real>(nu: T, z: T) -> T {
    (nu * nu + z * z).sqrt() - nu * (nu / z).asinh()
}

/// The first try's estimate as predicted where `c_N`'s prediction declines it: the two
/// coefficients the estimate reads, `λ^{N−1}/(2N−1)!! + λ^{N−2}/(2N−3)!!`, times its factor
/// `q^{N+1−m}` with `q` the larger of the weight's own decay `λ/(2N − 1)` (the ratio
/// `c_{k+1}/c_k ≈ λ/(2k + 1)` of `e^{−λξ}` near the last degree) and the singularities' rates
/// (the phase function's, `Y`'s pole). Where `λ` is large but nothing is singular near the panel
/// — a thick medium's steep, smooth extinction with the light away from the ray — this is far
/// below `c_N`'s, and the first try passes. Against `c_N`'s prediction alone, the outcomes that
/// tests/classes.rs `light_angle_route_meets_its_tolerance` prints: f32, 8 nodes, tolerances
/// 1e-1 … 1e-5, 16 more first tries passed (9 `behind`, 2 `thick`, 2 `beam_c16`, 2
/// `schlick_0.95`, 1 `hg_0.9`) and 5 more failed; f64, 16 nodes, 1e-1 … 1e-11, 24 passed (16
/// `thick`) and 3 failed; the largest errors taken unchanged. Like every prediction it decides
/// cost, never accuracy.
#[inline]
fn predicted_estimate<T: Real, const N: usize>(rate: T, singular: T, exponential: T) -> T {
    let decay = (rate * T::lit(1.0 / (2 * N - 1) as f64)).max(singular).max(exponential);
    (predicted_coefficient(rate, N - 1) + predicted_coefficient(rate, N - 2)) * power(decay, N + 1 - ALIASING_MARGIN)
}

/// `1/ρ` of the Bernstein ellipse of a panel of half-width `1/inv_hw` through a phase
/// singularity at `|μ*| = 1 + gap`: on the light angle it lies `offset` past the panel's nearer
/// end and `acosh(1 + gap)` off the real axis. `acosh(1 + gap) = ln(1 + y)`, `y = gap + √(gap(2 +
/// gap))`, is taken from below by `2y/(2 + y)` (equal at `y = 0` with its first two derivatives;
/// 4 % low at Henyey–Greenstein's `g = 0.5`, 0.4 % at 0.8): the singularity no farther than it
/// is, so the rate is never understated, without the library's `ln_1p`.
#[inline]
fn pole_rate<T: Real>(gap: T, offset: T, inv_hw: T) -> T {
    let y = axis_excess(gap);
    let im = (y + y) / (T::lit(2.0) + y);
    bernstein_rho(T::one() + offset * inv_hw, im * inv_hw).recip()
}

/// `x + √(x(2 + x)) = e^{acosh(1 + x)} − 1` for `x ≥ 0`, without cancellation near 0: `ρ − 1` of
/// the Bernstein ellipse through the real point `1 + x` (`crate::panels::bernstein_rho` on the
/// axis), and `acosh(1 + x) = ln(1 + ·)` of it.
#[inline]
fn axis_excess<T: Real>(x: T) -> T {
    x + (x * (T::lit(2.0) + x)).sqrt()
}

/// `λ^n/(3·5⋯(2n+1))`, the route's predicted coefficient (module docs), in two halves so that
/// no factor leaves f32's range up to `n = 32` (there `1/65!!` ≈ 1e-46 underflows, and `λ^32`
/// overflows from `λ` ≈ 16: their product was 0 or NaN). `λ` beyond ≈ 260 gives `+∞`.
#[inline]
fn predicted_coefficient<T: Real>(rate: T, n: usize) -> T {
    let half = n / 2;
    let lower = T::lit(inv_odd_factorial(half));
    let upper = T::lit(inv_odd_factorial(n) / inv_odd_factorial(half));
    Scalar::powi(rate, half as i32) * lower * (Scalar::powi(rate, (n - half) as i32) * upper)
}

/// `1/(3·5⋯(2n+1))`: `i_n(λ) ≈ λ^n` times this for `λ ≪ n` (DLMF 10.53.1), the route's
/// predicted coefficient (module docs; the shaders take it from here). Inlined, so that for the
/// route's const `N` the product folds to a constant (not inlined it was 5 % of the route's time).
#[inline]
pub fn inv_odd_factorial(n: usize) -> f64 {
    (1..=n).fold(1.0, |p, k| p / (2 * k + 1) as f64)
}

#[cfg(test)]
mod tests {
    use crate::glam::DVec3;
    use crate::phase::HenyeyGreenstein;
    use crate::{light::Omni, Medium, PointLight, Ray, Scene};

    /// The predicted coefficient `λ^n/(3·5⋯(2n+1))` in f32 at the wider rules' 32 nodes: formed
    /// as `λ^32 · (1/65!!)` it was 0 (`1/65!!` ≈ 1e-46 underflows) or NaN (`λ^32` overflows
    /// from `λ` ≈ 16). Against the f64 product `Π λ/(2k+1)`: within `4e-6`, the rate's f32
    /// rounding raised to the 32nd power (`32·2⁻²⁴`) and about 12 products' (`12·2⁻²⁴`).
    #[test]
    fn predicted_coefficients_stay_in_f32_range() {
        for n in [8, 12, 16, 32] {
            for rate in [1e-3, 0.5, 1.0, 4.0, 12.0, 16.0, 20.0, 25.0, 40.0] {
                let exact = (1..=n).fold(1.0f64, |p, k| p * rate / (2 * k + 1) as f64);
                let f32_value = super::predicted_coefficient(rate as f32, n) as f64;
                let f64_value = super::predicted_coefficient(rate, n);
                assert!((f64_value - exact).abs() <= 1e-13 * exact, "f64 n {n} rate {rate}: {f64_value} vs {exact}");
                if exact > 1e-30 && exact < 1e30 {
                    assert!((f32_value - exact).abs() <= 4e-6 * exact, "f32 n {n} rate {rate}: {f32_value} vs {exact}");
                } else {
                    // outside f32's range: 0 or +∞ on the side of the truth, never NaN
                    assert!(if exact < 1.0 { f32_value < 1e-30 } else { f32_value > 1e30 }, "f32 n {n} rate {rate}: {f32_value} vs {exact}");
                }
            }
        }
    }

    /// The lobe's decay model against the ratio of modified Bessel functions it stands for,
    /// `I_{N−m/2}(z)/I_{(N−1)/2}(z)` by their power series (DLMF 10.25.2): never below it (the
    /// estimate it enters must not shrink), and within 1.5× (the uniform form's `O(1/ν)` and the
    /// prefactors left out: 1.0–1.4× here).
    #[test]
    fn lobe_decay_bounds_the_bessel_ratio() {
        fn series(nu: f64, z: f64) -> f64 {
            // Σ (z/2)^{2k} / (k! (ν+1)_k), the series without its factor (z/2)^ν / Γ(ν+1)
            let (mut term, mut sum, mut k) = (1.0f64, 1.0f64, 0.0f64);
            while term > 1e-18 * sum {
                term *= (0.5 * z) * (0.5 * z) / ((k + 1.0) * (k + nu + 1.0));
                sum += term;
                k += 1.0;
            }
            sum
        }
        let m = super::ALIASING_MARGIN as f64;
        for n in [8usize, 16, 24, 32] {
            for z in [0.5f64, 2.0, 5.0, 10.0, 20.0, 40.0, 100.0] {
                let (nu1, nu2) = ((n as f64 - 1.0) * 0.5, n as f64 - m * 0.5);
                let log_ratio = (nu2 - nu1) * (0.5 * z).ln() + libm::lgamma(nu1 + 1.0) - libm::lgamma(nu2 + 1.0) + (series(nu2, z) / series(nu1, z)).ln();
                let model = super::lobe_decay(z, n);
                let quotient = model / log_ratio.exp();
                assert!((1.0..=1.5).contains(&quotient), "n {n}, z {z}: model {model:e}, Bessel ratio {:e}", log_ratio.exp());
            }
        }
    }

    /// [`super::gaussian_over_rate`] bounds the Gaussian's prediction over the rate's on a grid
    /// of `z` from 1e-3 to 200 (step 1e-3 below 20, 1e-2 beyond), in f64: the first try's gate
    /// may skip forming the Gaussian only where it could not decline.
    #[test]
    fn gaussian_over_rate_bounds_the_ratio() {
        for n in [4usize, 6, 8, 10, 12, 16] {
            let bound = super::gaussian_over_rate(n);
            let grid = (1..20_000).map(|i| i as f64 * 1e-3).chain((2_000..20_000).map(|i| i as f64 * 1e-2));
            for z in grid {
                let gaussian: f64 = super::gaussian_prediction(z, n);
                let rate = super::predicted_coefficient(2.0 * z.sqrt(), n);
                assert!(gaussian <= bound * rate, "n {n}, z {z}: Gaussian {gaussian:e}, rate's {rate:e} × {bound}");
            }
        }
    }

    /// Found by the `kernel` fuzz target: no extinction, the light's distance `r0` beyond the
    /// float range (`σt·r0` was `0·∞`, NaN).
    #[test]
    fn no_extinction_and_an_overflowing_distance_stay_finite() {
        let ray = Ray {
            origin: DVec3::new(1.7976931348623157e308, 5.562684646268003e-309, 7.291122019556398e-304),
            dir: DVec3::new(5.389374880406e-312, 0.0, 1.30375421396906e-310),
            t_min: -4.383618698016806e-193,
            t_max: f64::INFINITY,
        };
        let light = PointLight { position: DVec3::new(19.21487565134086, 99.6844362745098, 19.215686274509807), intensity: 596.0784313725491, distribution: Omni };
        let medium = Medium { sigma_s: 2.775706331448191e-10, sigma_t: 0.0 };
        let scene = Scene::new(ray, light, medium, HenyeyGreenstein { g: 2.2343899670179833e-264 }).unwrap();
        let value = scene.in_scatter();
        assert!(value >= 0.0, "{value}");
    }
}
