//! Error-controlled panels on one half: the default path ([`crate::combined`] calls it for each
//! piece between the light's kinks).
//!
//! On either half (module docs of [`crate::integrals`]) the integral is
//! `∫ e^{−H(v − v_s)} G(v) dv` with `G(v) = F(y(v))/(1 + v²)`: `v = y` before the foot,
//! `v = 1/y` after it (`du/(1+u²) = 2 dy/(1+y²) = 2 dv/(1+v²)`). The exponential is the
//! boundary layer (thick media, long rays, a light next to the ray); `F = D·P` holds the peaks
//! (Henyey–Greenstein near `|g| = 1` at `y = 0`, with half-width `(1 − |g|)/(1 + |g|)`; a narrow
//! beam where it crosses the ray). So the exponential is integrated exactly and only `G` is
//! approximated, on panels refined until it is resolved:
//!
//! * **v-panel** `[v_a, v_b]`: `G` at the `N` Gauss–Legendre nodes → its Legendre series
//!   `Σ c_k P_k(ξ)` (discrete transform, exact to degree `N − 1`) → `∫ = r Σ c_k M_k(H r)`,
//!   `r` the half-width, with the exponential's Legendre moments
//!   `M_k(λ) = ∫_{−1}^{1} e^{−λ(1+ξ)} P_k(ξ) dξ = 2(−1)^k e^{−λ} i_k(λ)` (`i_k`: modified
//!   spherical Bessel function, DLMF 10.54.2), computed stably for every `k` and `λ`
//!   ([`exp_legendre_moments`]): nothing amplifies rounding with the term index.
//! * **tail panel** `[y_a, y_b]` after the foot with `y_a ≤ y_b/4` (it reaches far along the
//!   ray, or to `t = ∞` at `y_a = 0`): `G̃(y) = F(y)/(1+y²)` as a polynomial `Σ q_k (y/y_b)^k`,
//!   against `U_k = ∫ e^{−H(1/y − 1/y_b)} (y/y_b)^k dy = y_b s_{k+2}(H/y_b) − e^{−H(1/y_a − 1/y_b)}
//!   y_a (y_a/y_b)^k s_{k+2}(H/y_a)`, `s_n(x) = e^x E_n(x)` (A&S 5.1.4): both terms positive,
//!   the second at most a quarter of the first.
//! * **y-panel** after the foot, for a panel that is no tail and across which the exponent grows
//!   by at most 4 (`Y_PANEL_EXPONENT`; beyond it, a v-panel): the whole integrand by the rule in
//!   `y`, where `1/(1+v²)` would put its poles close to a wide v-panel.
//!
//! The estimate of a panel's error is its weight mass times `|c_{N−1}| + |c_{N−2}|`, scaled by
//! the coefficients' decay (`error_factor`: no faster than the Bernstein ellipse through the
//! integrand's nearest singularity allows, where the phase function and distribution declare
//! them) and, on a tail panel, plus the monomial
//! conversion's rounding (0 once it is below the transform's own rounding, where splitting
//! cannot help). A piece is done when the sum of its panels' estimates is below
//! `tolerance × max(|their sum|, floor × scale)` (`scale`: the piece's integral with `F`
//! replaced by the largest `F` seen on the segment) — the accuracy target's form. Until then
//! the panel with the largest estimate is split (global adaptive refinement, as QUADPACK's
//! QAG): a bounded budget is spent where the error is, not on the first panel the order of a
//! recursion reaches. It is split at its midpoint in `y`, or nearer a known singularity close
//! to its start (`graded_split`), and a piece that starts next to one is split so at once. At most `max_panels` panels are evaluated per
//! piece (a fixed worst case); where the bound is hit the sum so far is returned, finite.

use crate::expansion::{gauss_table, Expandable};
use crate::integrals::Half;
use crate::real::{exp_nonpositive, larger, reciprocal, Real};
use crate::scalar::Scalar;
use crate::special::en_scaled;

/// Error control of the panel integration.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Control<T> {
    /// Largest accepted error estimate of a panel, relative to its value (or to `floor` times
    /// its scale, whichever is larger).
    pub tolerance: T,
    /// Relative floor: the accuracy target is relative to `max(|exact|, floor·scale)`.
    pub floor: T,
    /// Most panels evaluated per piece.
    pub max_panels: usize,
}

/// Running state shared by the pieces of one segment.
#[derive(Clone, Copy, Debug)]
pub struct Running<T> {
    /// Largest `|F|` sampled so far.
    pub f_max: T,
    /// Panels evaluated so far.
    pub panels: usize,
}

/// The most panels a piece's list holds (each split adds one: `(max_panels + 1)/2` at most).
const LIST: usize = 64;
/// The most Legendre terms a panel may use (the largest tabulated rule with `N ≤ MAX_N`).
pub const MAX_N: usize = 16;

/// `∫ e^{−H(v − v_s)} G(v) dv` over `y ∈ [lo, hi] ⊂ [half.y_lo, half.y_hi]`, in the half's
/// scaling (weight 1 at the half's `v_s`). `N`: Gauss–Legendre nodes per panel (4, 6, 8, 10,
/// 12 or 16; other counts give 0).
pub fn integrate_piece<T, F, const N: usize>(
    half: &Half<T>,
    lo: T,
    hi: T,
    f: &F,
    control: &Control<T>,
    run: &mut Running<T>,
) -> T
where
    T: Real,
    F: Expandable<T>,
{
    let rule = match gauss_table::rule(N) {
        Some(r) if N <= MAX_N => r,
        _ => return T::zero(),
    };
    if !(hi > lo) {
        return T::zero();
    }
    // the accuracy target's form: tolerance × max(|sum|, floor × scale)
    let target = |total: T, mass: T, f_max: T| control.tolerance * total.abs().max(control.floor * f_max * mass);
    // G's singularities once per piece, in the panels' variables
    let singular = f.singularities().map(|s| Singular::new::<N>(s, half.second));
    let mut budget = control.max_panels.saturating_sub(1);
    let (mut list, mut count) = match graded_split(lo, hi, singular.as_ref()) {
        // a piece that starts next to a known singularity is graded at once: one panel over
        // all of it would fail its estimate
        Some(p) if budget >= 1 => {
            let first = listed::<T, F, N>(half, lo, p, f, rule, singular.as_ref(), run);
            let mut list = [first; LIST];
            list[1] = listed::<T, F, N>(half, p, hi, f, rule, singular.as_ref(), run);
            budget -= 1;
            (list, 2)
        }
        _ => {
            let first = listed::<T, F, N>(half, lo, hi, f, rule, singular.as_ref(), run);
            // most pieces are done in one panel: no list for them
            if first.error <= target(first.value, first.mass_over, run.f_max) || budget < 2 {
                return first.value;
            }
            ([first; LIST], 1)
        }
    };
    loop {
        let (mut total, mut errors, mut mass) = (T::zero(), T::zero(), T::zero());
        let mut worst = 0;
        for (i, p) in list.iter().enumerate().take(count) {
            total = total + p.value;
            errors = errors + p.error;
            mass = mass + p.mass_over;
            if p.error > list[worst].error {
                worst = i;
            }
        }
        if errors <= target(total, mass, run.f_max) || !(list[worst].error > T::zero()) || budget < 2 || count == LIST {
            return total;
        }
        let (a, b) = (list[worst].a, list[worst].b);
        if !((b - a) > T::epsilon() * b) {
            list[worst].error = T::zero();
            continue;
        }
        let mid = graded_split(a, b, singular.as_ref()).unwrap_or(a + (b - a) * T::lit(0.5));
        list[worst] = listed::<T, F, N>(half, a, mid, f, rule, singular.as_ref(), run);
        list[count] = listed::<T, F, N>(half, mid, b, f, rule, singular.as_ref(), run);
        count += 1;
        budget -= 2;
    }
}

/// Where the panel `[a, b]` (in `y`) is split if not at its midpoint: where `G`'s nearest
/// known singularity (at `±it`, so at the distance `d = |a + it|` from the panel's start) is
/// closer than a quarter of the width, at `a + 2d` — graded towards it geometrically, as its
/// Bernstein ellipses need (a lobe of width `t` at `y = 0`, as Henyey–Greenstein's: two
/// panels where halving takes four or five). The factor 2 and the quarter: of 1.5 … 4 and
/// 1/8 … 1/4, the fewest instructions per ray over the peaked classes (callgrind, f32 at the
/// tolerances that meet 1e-3, f64 at the default).
fn graded_split<T: Real>(a: T, b: T, singular: Option<&Singular<T>>) -> Option<T> {
    let s = singular?;
    graded_point(a, b, s.y.iter().take(s.count).copied())
}

/// [`graded_split`]'s point for the singularities at the heights `heights` (`±it` in `y`).
pub(crate) fn graded_point<T: Real>(a: T, b: T, heights: impl Iterator<Item = T>) -> Option<T> {
    let t = heights.fold(T::infinity(), |m, t| m.min(t));
    let d = (a * a + t * t).sqrt();
    (d > T::zero() && d < (b - a) * T::lit(0.25)).then(|| a + d * T::lit(2.0))
}

/// A panel in a piece's list.
#[derive(Clone, Copy)]
struct Listed<T> {
    a: T,
    b: T,
    value: T,
    /// The error estimate; 0 once it is at the transform's own rounding, where splitting
    /// cannot help.
    error: T,
    mass_over: T,
}

/// Evaluates the panel `[a, b]` and counts it.
fn listed<T: Real, F: Expandable<T>, const N: usize>(
    half: &Half<T>,
    a: T,
    b: T,
    f: &F,
    rule: &[(f64, f64)],
    singular: Option<&Singular<T>>,
    run: &mut Running<T>,
) -> Listed<T> {
    let p = panel::<T, F, N>(half, a, b, f, rule, singular);
    run.panels += 1;
    run.f_max = run.f_max.max(p.f_max);
    let error = if p.error <= p.noise { T::zero() } else { p.error };
    Listed { a, b, value: p.value, error, mass_over: p.mass_over }
}

/// The panel kind for `[a, b]` (module docs): tail, y- or v-panel.
fn panel<T: Real, F: Expandable<T>, const N: usize>(half: &Half<T>, a: T, b: T, f: &F, rule: &[(f64, f64)], singular: Option<&Singular<T>>) -> Panel<T> {
    if half.second && a <= b * T::lit(0.25) {
        tail_panel::<T, F, N>(half, a, b, f, rule)
    } else if half.second && half.big_h * ((b - a) / (a * b)) <= T::lit(Y_PANEL_EXPONENT) {
        y_panel::<T, F, N>(half, a, b, f, rule, singular)
    } else {
        v_panel::<T, F, N>(half, a, b, f, rule, singular)
    }
}

/// `G`'s singularities at `±it` ([`Expandable::singularities`]): heights in `y` and in the
/// v-panels' variable (`1/t` after the foot), and each one's bound on the coefficients' step
/// ratio beyond the last computed one, per unit of `1/ρ`; `count` distinct ones (a phase
/// function without singularities of its own repeats the poles at `±i`).
struct Singular<T> {
    y: [T; 3],
    v: [T; 3],
    /// `1/step`, `step = (N/(N − 1))^{max(α − 1, 0)}`: near a singularity of order `α` the
    /// coefficients go as `k^{α−1} ρ^{−k}`, whose step ratio `((k+1)/k)^{α−1}/ρ` is largest at
    /// the first step beyond `c_{N−1}` (a high-order pole — the `c^p` beam's `p`-fold one at
    /// `y = ±i` — keeps the coefficients from their asymptotic rate well past `N`). Stored
    /// inverted: the floor is `1/min(ρ/step)`, one division per panel.
    inv_step: [T; 3],
    count: usize,
}

impl<T: Real> Singular<T> {
    fn new<const N: usize>(s: [(T, T); 3], second: bool) -> Self {
        let (mut y, mut step, mut count) = ([T::zero(); 3], [T::zero(); 3], 0);
        for (t, order) in s {
            let factor = order_step(order, N);
            match (0..count).find(|&i| y[i] == t) {
                Some(i) => step[i] = step[i].max(factor),
                None => {
                    y[count] = t;
                    step[count] = factor;
                    count += 1;
                }
            }
        }
        Singular { y, v: if second { y.map(|t| t.recip()) } else { y }, inv_step: step.map(|s| s.recip()), count }
    }

    /// The least rate the coefficients on `[c − r, c + r]` (in the heights `ts`' variable) can
    /// fall at beyond `c_{N−1}`: the largest `step/ρ`, and with `origin` at least `1/ρ` of a
    /// singularity at 0 (the exponential's, on a y-panel).
    fn floor(&self, ts: &[T; 3], c: T, r: T, origin: bool) -> T {
        let inv = r.recip();
        let re = c * inv;
        let mut rho = if origin { bernstein_rho(re, T::zero()) } else { T::infinity() };
        for (&t, &inv_step) in ts.iter().zip(&self.inv_step).take(self.count) {
            rho = rho.min(bernstein_rho(re, t * inv) * inv_step);
        }
        rho.recip()
    }
}

/// What one panel's samples say, in the half's scaling.
struct Panel<T> {
    /// The panel's integral.
    value: T,
    /// Its error estimate: weight mass × the last two Legendre coefficients of `G`.
    error: T,
    /// The error rounding alone leaves in the estimate and the value: no refinement goes below.
    noise: T,
    /// Weight mass × largest `1/(1+v²)`: the panel's scale per unit of `F`.
    mass_over: T,
    /// Largest `|F|` at the nodes.
    f_max: T,
}

/// `(N/(N − 1))^{max(α − 1, 0)}`, the step-ratio bound of a singularity of order `α` beyond
/// `c_{N−1}` ([`Singular`]): `√(N/(N − 1))` to the power `⌈2(α − 1)⌉` by squaring — exact for the
/// built-in orders (whole and half), larger otherwise; no library power per piece.
pub(crate) fn order_step<T: Real>(order: T, n: usize) -> T {
    order_power((T::from(n).unwrap() / T::from(n.saturating_sub(1).max(1)).unwrap()).sqrt(), order)
}

/// `x^{max(α − 1, 0)}` for `root = √x` and a singularity of order `α`: `root` to the power
/// `⌈2(α − 1)⌉` by squaring (`+∞` where that power leaves `i32`) — exact for the built-in
/// orders (whole and half), larger otherwise; no library power. The polynomial factor `k^{α−1}`
/// of such a singularity's coefficients, and its step ratio ([`order_step`]).
pub(crate) fn order_power<T: Real>(root: T, order: T) -> T {
    let twice = ((order - T::one()) * T::lit(2.0)).ceil();
    if twice > T::zero() {
        twice.to_i32().map_or(T::infinity(), |k| Scalar::powi(root, k))
    } else {
        T::one()
    }
}

/// The discrete transform's rounding, the floor below which no refinement helps: about `Nε`
/// of the weighted mean of the samples' magnitudes per coefficient, times the weight mass
/// (`4Nε·mass·mean`).
pub(crate) fn transform_noise<T: Real, const N: usize>(mass: T, mean_abs: T) -> T {
    T::from(4 * N).unwrap() * T::epsilon() * mass * mean_abs
}

/// `e^{−H(v_s(panel) − v_s(half))}` for the panel `[a, b]` in `y`.
fn factor<T: Real>(half: &Half<T>, a: T, b: T) -> T {
    let offset = if half.second { (half.y_hi - b) / (b * half.y_hi) } else { a - half.y_lo };
    let x = half.big_h * offset;
    if x > T::zero() {
        (-x).exp()
    } else {
        T::one()
    }
}

/// Legendre coefficients of the samples `g(ξ_j)` at the rule's nodes (order: `−x_1, x_1, …`),
/// by the tabulated discrete transform (`P_k(−x) = (−1)^k P_k(x)`).
pub(crate) fn legendre<T: Real, const N: usize>(g: &[T; N]) -> [T; N] {
    legendre_from::<T, N>(g, 0)
}

/// [`legendre`]'s coefficients of degree `from` and above, the others 0: an error estimate that
/// reads only the last few costs `N/2` products per coefficient instead of `N²/2` in all.
#[inline(always)]
pub(crate) fn legendre_from<T: Real, const N: usize>(g: &[T; N], from: usize) -> [T; N] {
    let mut c = [T::zero(); N];
    let Some(table) = gauss_table::transform(N) else {
        return c;
    };
    let half = N / 2;
    for (k, ck) in c.iter_mut().enumerate().skip(from) {
        let row = &table[k * half..(k + 1) * half];
        let mut sum = T::zero();
        for (j, &l) in row.iter().enumerate() {
            let (minus, plus) = (g[2 * j], g[2 * j + 1]);
            let pair = if k % 2 == 0 { plus + minus } else { plus - minus };
            sum = sum + T::lit(l) * pair;
        }
        *ck = sum;
    }
    c
}

/// The nodes `ξ_j` of the rule in the order [`legendre`] expects.
fn node<T: Real>(rule: &[(f64, f64)], i: usize) -> T {
    T::lit(node_f64(rule, i))
}

/// [`node`] in the table's own precision (`−x_1, x_1, −x_2, …`), for sums formed there first.
pub(crate) fn node_f64(rule: &[(f64, f64)], i: usize) -> f64 {
    let x = rule[i / 2].0;
    if i % 2 == 0 {
        -x
    } else {
        x
    }
}

pub(crate) fn tail_estimate<T: Real, const N: usize>(c: &[T; N]) -> T {
    if N >= 2 {
        c[N - 1].abs() + c[N - 2].abs()
    } else {
        T::zero()
    }
}

/// The error of `Σ_{k<N} c_k M_k` against the exact `∫ w G`, per unit of the tail `|c_{N−1}| +
/// |c_{N−2}|` and of the weight mass `M_0`: the neglected terms `Σ_{k≥N} c_k M_k` and what the
/// degree-`N` and higher parts of `G` alias into the computed `c_k` (the `N`-point rule is
/// exact to degree `2N − 1`, so `c_j` takes the alias of `c_{2N−j}`). With geometric decay
/// `c_k ≈ C q^k`, `q` from the last four coefficients, the first is about `q·|M_{N−1}|/M_0` of
/// the tail.
///
/// * Where `G`'s singularities are known (`floor`: the largest step ratio they allow beyond
///   `c_{N−1}`, `1/ρ` of the Bernstein ellipse through each ([`bernstein_rho`]) times its order's
///   factor, [`Singular`]) the coefficients fall no faster than `floor` — a lobe just beyond
///   the panel's end whose peak the nodes miss cannot hide behind steeply falling first
///   coefficients — so `q` is raised to it, and the aliasing is its model
///   `Σ_j q^{N+1−j−m} |M_j|/M_0` with a margin `q^{−m}`, `m` = [`ALIASING_MARGIN`].
/// * Otherwise — a user's phase function or distribution that does not say, or a floor of 1 or
///   more (a pole of high order near the panel: the `c^64` beam's 64-fold one at `y = ±i`) —
///   nothing is assumed about the rate: the aliasing is taken as `q^{N/4}` (in f32, `q^{N/2}` let panels
///   with 3e-3 errors through on the near-light class), and `q^{N/6}` where some `|c_k|`
///   exceeds `1.2|c_0|` — a peak at or just beyond the panel's end (`q^{N/4}` let 3.1× the
///   tolerance through there: 12 nodes, HG `g = 0.9`, tolerance 1e-3).
///
/// Where the coefficients do not decay (`q ≥ 1`) the factor is 1: the plain interpolation
/// error.
pub(crate) fn error_factor<T: Real, const N: usize>(c: &[T; N], m: &[T; N], floor: Option<T>) -> T {
    if !(m[0] > T::zero()) {
        return T::one();
    }
    let Some(q) = tail_decay(c) else {
        return T::one();
    };
    // the truncation's moment: the neglected terms meet M_k no larger than these
    let tail_moment = m[N - 1].abs().max(m[N - 2].abs());
    // the rate the nearest singularity allows, where the samples show a faster one; at or
    // above 1 (a high-order pole near the panel) it says nothing, and the cautious form below
    // holds
    if let Some(q) = floor.map(|f| q.max(f)).filter(|&q| q < T::one()) {
        // c_j takes the alias of c_{2N−j} ≈ |c_{N−1}| q^{N+1−j}: Σ_j q^{N+1−j−margin} |M_j|
        // by Horner over j < top (exponents top − 1 − j), exponents below 0 taken as 0
        let top = N + 2 - ALIASING_MARGIN;
        let mut aliasing = T::zero();
        for (j, mj) in m.iter().enumerate() {
            aliasing = if j < top { aliasing * q + mj.abs() } else { aliasing + mj.abs() };
        }
        return ((aliasing + q * tail_moment) / m[0]).min(T::one());
    }
    let truncation = q * tail_moment / m[0];
    (cautious_aliasing(c, q) + truncation).min(T::one())
}

/// The coefficients' decay per degree `q = √((|c_{N−1}| + |c_{N−2}|)/(|c_{N−3}| + |c_{N−4}|))`,
/// where they decay (`None`: fewer than four, or not falling).
fn tail_decay<T: Real, const N: usize>(c: &[T; N]) -> Option<T> {
    if N < 4 {
        return None;
    }
    let last = c[N - 1].abs() + c[N - 2].abs();
    let before = c[N - 3].abs() + c[N - 4].abs();
    (before > T::zero() && last < before).then(|| (last / before).sqrt())
}

/// The aliasing where no singularity bounds the rate: `q^{N/4}`, or `q^{N/6}` where a
/// coefficient exceeds `1.2|c_0|` — a peak at or just beyond the panel's end, whose mass between
/// the last node and the end the nodes miss.
fn cautious_aliasing<T: Real, const N: usize>(c: &[T; N], q: T) -> T {
    let c_max = c.iter().fold(T::zero(), |a, x| larger(a, x.abs()));
    power(q, if c_max > T::lit(1.2) * c[0].abs() { N / 6 } else { N / 4 })
}

/// [`error_factor`] for the weight 1 (moments `M_0 = 2`, `M_k = 0`: the light-angle route's
/// panel, `crate::angle`), where its model reduces to `q^{N+1−m}` below a rate of 1 — from the
/// last four coefficients alone, which is all the route transforms there — and to the cautious
/// form at or above it; the same value, without the moments' Horner sum.
pub(crate) fn unit_weight_factor<T: Real, const N: usize>(c: &[T; N], floor: T) -> T {
    let Some(q) = tail_decay(c) else {
        return T::one();
    };
    let floored = q.max(floor);
    if floored < T::one() {
        return power(floored, N + 1 - ALIASING_MARGIN).min(T::one());
    }
    cautious_aliasing(c, q).min(T::one())
}

/// The margin `m` of the panels' aliasing model (`error_factor`): the estimate is `q^{−m}` above
/// the geometric model. Measured over tests/reference/classes.jsonl with `m = 3` (largest error
/// over every record of every class): with 4 … 16 nodes per panel at tolerances 1e-1 … 1e-4
/// (f32) and 1e-2 … 1e-10 (f64) at most 0.37 of the tolerance (f32 12 nodes at 1e-2,
/// near_light); f64 16 nodes 2.2e-8 at 1e-6, 1.9e-10 at 1e-8, 9.9e-14 at the default 1e-11.
/// `m = 2` and `m = 4` moved the panel counts by at most 3 % and the largest errors by less
/// than 2×. Without the singularities' rate the same model let 1.8e-4 through at 1e-6, and
/// without their orders 2.4e-2 at 1e-2 (f32, 8 nodes, a `c^64` beam): `tests/classes.rs`
/// `error_estimate_holds_at_loose_tolerances`.
pub const ALIASING_MARGIN: usize = 3;

/// `ρ` of the Bernstein ellipse of `[−1, 1]` through `re + i·im` (a panel `[c − r, c + r]`
/// scaled to it: foci at the ends, `ρ = A + √(A² − 1)`, `A` half the sum of the distances to
/// them): the Legendre coefficients of a function singular there fall like `ρ^{−k}` and no
/// faster. (Squares that overflow give `ρ = ∞`, rate 0: a singularity that far constrains
/// nothing.)
pub(crate) fn bernstein_rho<T: Real>(re: T, im: T) -> T {
    let im2 = im * im;
    let a = (((re - T::one()) * (re - T::one()) + im2).sqrt() + ((re + T::one()) * (re + T::one()) + im2).sqrt()) * T::lit(0.5);
    a + (a * a - T::one()).max(T::zero()).sqrt()
}

/// `q^k` for the small `k` of [`error_factor`], by products (no library call).
#[inline]
pub(crate) fn power<T: Real>(q: T, k: usize) -> T {
    (0..k).fold(T::one(), |p, _| p * q)
}

/// A v-panel (module docs).
fn v_panel<T: Real, F: Expandable<T>, const N: usize>(half: &Half<T>, a: T, b: T, f: &F, rule: &[(f64, f64)], singular: Option<&Singular<T>>) -> Panel<T> {
    // v ∈ [1/b, 1/a] after the foot, [a, b] before it; r its half-width, without cancellation
    let (vc, r) = if half.second {
        let r = (b - a) / (a * b) * T::lit(0.5);
        (b.recip() + r, r)
    } else {
        let r = (b - a) * T::lit(0.5);
        (a + r, r)
    };
    // v = y before the foot, 1/y after it
    let values = f.eval_over_each::<N>(&core::array::from_fn(|i| vc + r * node::<T>(rule, i)), half.second);
    let mut g = [T::zero(); N];
    let (mut f_max, mut over_max, mut g_avg) = (T::zero(), T::zero(), T::zero());
    for (i, gi) in g.iter_mut().enumerate() {
        let (fy, over) = values[i];
        *gi = fy * over;
        f_max = larger(f_max, fy.abs());
        over_max = larger(over_max, over);
        g_avg = g_avg + T::lit(rule[i / 2].1 * 0.5) * gi.abs();
    }
    let c = legendre::<T, N>(&g);
    let mut m = [T::zero(); N];
    exp_legendre_moments(half.big_h * r, &mut m);
    let mut sum = T::zero();
    for k in 0..N {
        sum = sum + c[k] * m[k];
    }
    let w = factor(half, a, b) * r;
    let mass = w * m[0];
    let noise = transform_noise::<T, N>(mass, g_avg);
    let floor = singular.map(|s| s.floor(&s.v, vc, r, false));
    let error = mass * tail_estimate(&c) * error_factor(&c, &m, floor);
    Panel { value: w * sum, error, noise, mass_over: mass * over_max, f_max }
}

/// The largest growth `H(1/a − 1/b)` of the exponent across a y-panel: an `N ≥ 8` point rule
/// integrates `e^{−λx}` on `[0, 1]` to `λ^{2N}/(2^{2N}(2N)!)` (`< 1e-18` at `λ = 4`, `N = 8`).
pub const Y_PANEL_EXPONENT: f64 = 4.0;

/// A y-panel: `[a, b]` after the foot with `b < 4a` and an exponent that grows by at most
/// [`Y_PANEL_EXPONENT`] across it. There the whole integrand `e^{−H(1/y − 1/b)} F/(1+y²)` is
/// smooth in `y` (its singularities, `y = 0` and `±i`, lie at least 1.2 half-widths away),
/// while in `v = 1/y` the poles of `1/(1+v²)` come close to a panel whose `b/a` is near 4: so
/// it is integrated by the Gauss–Legendre rule in `y`, the estimate from the product's
/// Legendre tail.
fn y_panel<T: Real, F: Expandable<T>, const N: usize>(half: &Half<T>, a: T, b: T, f: &F, rule: &[(f64, f64)], singular: Option<&Singular<T>>) -> Panel<T> {
    let r = (b - a) * T::lit(0.5);
    let yc = a + r;
    let big_h = half.big_h;
    let values = f.eval_over_each::<N>(&core::array::from_fn(|i| yc + r * node::<T>(rule, i)), false);
    let mut p = [T::zero(); N];
    let (mut f_max, mut over_max, mut mass, mut p_avg) = (T::zero(), T::zero(), T::zero(), T::zero());
    for (i, pi) in p.iter_mut().enumerate() {
        let xi = node::<T>(rule, i);
        let y = yc + r * xi;
        // H(1/y − 1/b) = H (b − y)/(y b), b − y = r(1 − ξ)
        let weight = exp_nonpositive(-big_h * (r * (T::one() - xi)) / (y * b));
        let (fy, over) = values[i];
        *pi = fy * over * weight;
        f_max = larger(f_max, fy.abs());
        over_max = larger(over_max, over);
        mass = mass + T::lit(rule[i / 2].1) * weight;
        p_avg = p_avg + T::lit(rule[i / 2].1 * 0.5) * pi.abs();
    }
    let c = legendre::<T, N>(&p);
    let w = factor(half, a, b) * r;
    let mass = w * mass;
    // the rule's own weights: the panel's value is 2r·c_0; the error has no truncation term
    // (no moment weights the tail), only the aliasing one
    let mut m = [T::zero(); N];
    m[0] = T::lit(2.0);
    let noise = transform_noise::<T, N>(w * T::lit(2.0), p_avg);
    // the exponential's essential singularity at y = 0 as well
    let floor = singular.map(|s| s.floor(&s.y, yc, r, true));
    let error = w * T::lit(2.0) * tail_estimate(&c) * error_factor(&c, &m, floor);
    Panel { value: w * T::lit(2.0) * c[0], error, noise, mass_over: mass * over_max, f_max }
}

/// A tail panel (module docs): `[a, b]` after the foot, `a ≤ b/4`.
fn tail_panel<T: Real, F: Expandable<T>, const N: usize>(half: &Half<T>, a: T, b: T, f: &F, rule: &[(f64, f64)]) -> Panel<T> {
    let r = (b - a) * T::lit(0.5);
    let yc = a + r;
    let values = f.eval_over_each::<N>(&core::array::from_fn(|i| yc + r * node::<T>(rule, i)), false);
    let mut g = [T::zero(); N];
    let (mut f_max, mut g_avg) = (T::zero(), T::zero());
    for (i, gi) in g.iter_mut().enumerate() {
        let (fy, over) = values[i];
        *gi = fy * over;
        f_max = larger(f_max, fy.abs());
        g_avg = g_avg + T::lit(rule[i / 2].1 * 0.5) * gi.abs();
    }
    let c = legendre::<T, N>(&g);
    // Σ c_k P_k(ξ) → Σ q_k u^k, u = y/b, ξ = (y − yc)/r = α u + β
    let (alpha, beta) = (b / r, -yc / r);
    let hat = legendre_to_monomial(&c);
    let mut q = [T::zero(); N];
    for j in (0..N).rev() {
        // q ← q·(αu + β) + hat_j
        let mut next = [T::zero(); N];
        for i in 0..N {
            let shifted = if i > 0 { q[i - 1] * alpha } else { T::zero() };
            next[i] = shifted + q[i] * beta;
        }
        next[0] = next[0] + hat[j];
        q = next;
    }
    // U_k = b s_{k+2}(H/b) − e^{−H(1/a − 1/b)} a (a/b)^k s_{k+2}(H/a)
    let big_h = half.big_h;
    let mut s_b = [T::zero(); MAX_N + 2];
    en_scaled(big_h / b, &mut s_b[..N + 2]);
    let mut s_a = [T::zero(); MAX_N + 2];
    // the far end's terms are at most `decay` of the near end's (s_n is decreasing and
    // a (a/b)^k ≤ b): below ε/4 of them they change nothing and are not computed
    let far = a > T::zero() && (big_h / a).is_finite();
    let decay = if far { (-big_h * ((b - a) / (a * b))).exp() } else { T::zero() };
    let decay = if decay > T::epsilon() * T::lit(0.25) { decay } else { T::zero() };
    if far && decay > T::zero() {
        en_scaled(big_h / a, &mut s_a[..N + 2]);
    }
    let (mut sum, mut mass) = (T::zero(), T::zero());
    let mut ratio = T::one();
    let ab = if b > T::zero() { a / b } else { T::zero() };
    for k in 0..N {
        let tail = if decay > T::zero() { decay * a * ratio * s_a[k + 1] } else { T::zero() };
        let u = b * s_b[k + 1] - tail;
        if k == 0 {
            mass = u;
        }
        sum = sum + q[k] * u;
        ratio = ratio * ab;
    }
    let w = factor(half, a, b);
    let mass = w * mass;
    // Rounding: the conversion to monomials in u sums terms up to L_k(|α| + |β|)·|c_k|, L_k the
    // monomial coefficients of P_k in absolute value summed at x (by the recurrence with every
    // sign made positive; at x = 3, the case a = 0, it bounds the central Delannoy numbers
    // 1, 3, 13, 63, …, OEIS A001850). On a resolved panel |c_k| falls faster than L_k grows.
    let x = alpha.abs() + beta.abs();
    let (mut l_prev, mut l_cur) = (T::zero(), T::one());
    let mut spread = T::zero();
    for (k, ck) in c.iter().enumerate() {
        spread = spread + l_cur * ck.abs();
        let kf = T::from(k).unwrap();
        let next = ((kf + kf + T::one()) * x * l_cur + kf * l_prev) * reciprocal::<T>(k + 1);
        l_prev = l_cur;
        l_cur = next;
    }
    // the conversion's rounding is an error like the truncation's (splitting the panel
    // reduces it: the c_k fall faster); the floor is only the transform's own 4Nε
    let conversion = T::epsilon() * mass * spread;
    let noise = transform_noise::<T, N>(mass, g_avg);
    Panel { value: w * sum, error: mass * tail_estimate(&c) + conversion, noise, mass_over: mass, f_max }
}

/// `2^k P_k(ξ) = Σ_j (−1)^j C(k, j) C(2k − 2j, k) ξ^{k−2j}` (DLMF 18.5.8 with `n = k`), row `k`
/// holding the coefficient of `ξ^i` at `i`: integers below `2^31` for `k < MAX_N`, exact in
/// f32 and f64 once scaled by `2^{−k}`.
pub const LEGENDRE_MONOMIAL: [[i64; MAX_N]; MAX_N] = legendre_monomial_table();

const fn binomial(n: i64, k: i64) -> i64 {
    let mut out = 1;
    let mut i = 0;
    while i < k {
        out = out * (n - i) / (i + 1);
        i += 1;
    }
    out
}

const fn legendre_monomial_table() -> [[i64; MAX_N]; MAX_N] {
    let mut table = [[0; MAX_N]; MAX_N];
    let mut k = 0;
    while k < MAX_N {
        let mut j = 0;
        while 2 * j <= k {
            let sign = if j % 2 == 0 { 1 } else { -1 };
            table[k][k - 2 * j] = sign * binomial(k as i64, j as i64) * binomial((2 * k - 2 * j) as i64, k as i64);
            j += 1;
        }
        k += 1;
    }
    table
}

/// The monomial coefficients in `ξ` of `Σ c_k P_k(ξ)` ([`LEGENDRE_MONOMIAL`]). On a resolved
/// panel `|c_k|` decays faster than the `< (1+√2)^k` growth of `P_k`'s monomial coefficients,
/// so the rounding this adds stays of the order of `ε Σ|c_k|`.
fn legendre_to_monomial<T: Real, const N: usize>(c: &[T; N]) -> [T; N] {
    let mut hat = [T::zero(); N];
    let mut scale = T::one();
    for (k, ck) in c.iter().enumerate().take(MAX_N) {
        let ck = *ck * scale;
        for (i, h) in hat.iter_mut().enumerate().take(k + 1) {
            *h = *h + ck * T::lit(LEGENDRE_MONOMIAL[k][i] as f64);
        }
        scale = scale * T::lit(0.5);
    }
    hat
}

/// `out[k] = M_k(λ) = ∫_{−1}^{1} e^{−λ(1+ξ)} P_k(ξ) dξ = 2(−1)^k e^{−λ} i_k(λ)`, `λ ≥ 0`,
/// `k < out.len() ≤ MAX_N`. The three-term recurrence `i_{k−1} − i_{k+1} = (2k+1) i_k/λ`
/// (DLMF 10.51.4) is stable upward while `k ≲ λ` and downward above, so:
/// * `0 < λ < 2K` (`K = out.len()`): Miller's backward recurrence from order
///   `k0 = max(K, ⌊λ⌋ + 1)` plus `s + 2` steps, `s` the fewest with `(λ/2k0)^{2s} ≤ ε` (at most
///   28: above `k0` the error's share shrinks by `(λ/2k)² ≤ 1/4` per step down, much faster
///   for small `λ`),
///   normalised by `e^{−λ} i_0 = (1 − e^{−2λ})/(2λ)`, rescaled by 1e-20 whenever a value
///   passes 1e20 (for small `λ` each step grows by `(2k+1)/λ`);
/// * `λ ≥ 2K`: upward from `e^{−λ} i_0` and `e^{−λ} i_1 = ((1 + e^{−2λ})/2 − (1 − e^{−2λ})/(2λ))/λ`
///   (upward is stable while `k ≤ λ/2`; at `k ≈ λ` it loses a few dozen ulps).
pub fn exp_legendre_moments<T: Real>(lambda: T, out: &mut [T]) {
    let n = out.len().min(MAX_N);
    if n == 0 {
        return;
    }
    for o in out.iter_mut() {
        *o = T::zero();
    }
    if !(lambda > T::zero()) {
        out[0] = T::lit(2.0);
        return;
    }
    if !lambda.is_finite() {
        return;
    }
    let two = T::lit(2.0);
    // e^{−λ} i_0(λ)
    let i0 = -(-(lambda + lambda)).exp_m1() / (lambda + lambda);
    if lambda < T::epsilon() {
        // M_0 = 2 e^{−λ} i_0, M_1 = −(2/3)λ + O(λ²), the rest O(λ²): below rounding of M_0
        out[0] = i0;
        if n > 1 {
            out[1] = lambda * T::lit(1.0 / 3.0);
        }
    } else if lambda < T::from(2 * n).unwrap() {
        let inv = lambda.recip();
        // Above k0 = max(K, ⌊λ⌋ + 1) the error's share shrinks by (λ/(2k))² ≤ 1/4 per step
        // down (the minimal solution falls by λ/(2k+3) per step up, the other grows by
        // (2k+1)/λ): enough steps for ε, plus two.
        let k0 = n.max(lambda.to_usize().map_or(n, |k| k + 1));
        // the fewest steps s with (λ/(2k0))^{2s} ≤ ε (at most 28), by products: no logarithm
        let x = lambda / T::from(2 * k0).unwrap();
        let per_step = x * x;
        let (mut share, mut steps) = (per_step, 1);
        while share > T::epsilon() && steps < 28 {
            share = share * per_step;
            steps += 1;
        }
        let top = k0 + steps + 2;
        let (mut above, mut cur) = (T::zero(), T::lit(1e-20));
        let mut odd = T::from(2 * top + 1).unwrap(); // 2k + 1
        // cur = f_k, above = f_{k+1}; f_{k−1} = f_{k+1} + (2k+1)/λ f_k
        for k in (1..=top).rev() {
            if k < n {
                out[k] = cur;
            }
            let below = above + odd * inv * cur;
            odd = odd - two;
            above = cur;
            cur = below;
            if cur > T::lit(1e20) {
                let s = T::lit(1e-20);
                cur = cur * s;
                above = above * s;
                for o in out.iter_mut().take(n) {
                    *o = *o * s;
                }
            }
        }
        out[0] = cur;
        let norm = i0 / cur;
        for o in out.iter_mut().take(n) {
            *o = *o * norm;
        }
    } else {
        let e2 = (-(lambda + lambda)).exp();
        let inv = lambda.recip();
        out[0] = i0;
        if n > 1 {
            out[1] = ((T::one() + e2) * T::lit(0.5) - i0) * inv;
        }
        for k in 1..n.saturating_sub(1) {
            out[k + 1] = out[k - 1] - T::from(2 * k + 1).unwrap() * inv * out[k];
        }
    }
    for (k, o) in out.iter_mut().enumerate().take(n) {
        *o = *o * two;
        if k % 2 == 1 {
            *o = -*o;
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The route's factor is the panels' with the moments `(2, 0, …, 0)`, bit for bit, on
    /// coefficients that decay, grow and stall, with floors below and above 1.
    #[test]
    fn unit_weight_factor_is_error_factor_with_the_weight_1() {
        fn check<const N: usize>() {
            let mut moments = [0.0f64; N];
            moments[0] = 2.0;
            let mut state = 0x2545_f491_4f6c_dd1du64;
            for case in 0..2000 {
                let mut c = [0.0f64; N];
                for (k, ck) in c.iter_mut().enumerate() {
                    state ^= state << 13;
                    state ^= state >> 7;
                    state ^= state << 17;
                    let r = (state >> 11) as f64 / (1u64 << 53) as f64;
                    // geometric decay at rates 0.1 … 1.3, signs and noise from the same stream
                    let rate = 0.1 + 1.2 * (case % 13) as f64 / 12.0;
                    *ck = rate.powi(k as i32) * (r - 0.3);
                }
                for floor in [0.0, 0.3, 0.9, 1.0, 1.7] {
                    let (a, b) = (unit_weight_factor::<f64, N>(&c, floor), error_factor::<f64, N>(&c, &moments, Some(floor)));
                    assert_eq!(a.to_bits(), b.to_bits(), "N = {N}, floor {floor}, c = {c:?}");
                }
            }
        }
        check::<4>();
        check::<8>();
        check::<16>();
        check::<32>();
    }

    /// `M_0(λ) = (1 − e^{−2λ})/λ` and, with `w = 1 + ξ`, `M_1(λ) = ∫_0^2 (w − 1) e^{−λw} dw =
    /// −2e^{−2λ}/λ + (1 − e^{−2λ})/λ² − M_0`, integrated by hand; at `λ` in the Miller branch
    /// (0.3, 3) and the upward one (50, 1e3).
    #[test]
    fn first_moments_by_hand() {
        for lambda in [0.3f64, 3.0, 50.0, 1e3] {
            let mut m = [0.0f64; 12];
            exp_legendre_moments(lambda, &mut m);
            let e2 = (-2.0 * lambda).exp();
            let m0 = (1.0 - e2) / lambda;
            let m1 = -2.0 * e2 / lambda + (1.0 - e2) / (lambda * lambda) - m0;
            assert!((m[0] - m0).abs() <= 4.0 * f64::EPSILON * m0, "λ = {lambda}: M_0 {} vs {m0}", m[0]);
            assert!((m[1] - m1).abs() <= 16.0 * f64::EPSILON * m0, "λ = {lambda}: M_1 {} vs {m1}", m[1]);
        }
        let mut m = [0.0f64; 4];
        exp_legendre_moments(0.0, &mut m);
        assert_eq!(m, [2.0, 0.0, 0.0, 0.0], "λ = 0: ∫ P_k = 2δ_k0");
    }

    /// Every tabulated discrete Legendre transform (`gauss_table::transform`) takes the samples
    /// of `P_j` at its rule's nodes to the `j`-th unit vector (`j < n`: the Gauss rule is exact
    /// for `P_j P_k` up to degree `2n − 1`), `P_j` by [`bonnet`], not by the tables' generator.
    /// Bound: the sum's and the recurrence's roundings, `(n + 2k + 2)ε` times the sum of the terms'
    /// magnitudes.
    #[test]
    fn transforms_invert_the_legendre_samples() {
        for n in [4, 6, 8, 10, 12, 16, 24, 32] {
            let (rule, table) = (gauss_table::rule(n).unwrap(), gauss_table::transform(n).unwrap());
            let half = n / 2;
            for j in 0..n {
                for k in 0..n {
                    let (mut sum, mut magnitude) = (0.0f64, 0.0f64);
                    for (i, &(x, _)) in rule.iter().enumerate() {
                        let pair = if k % 2 == 0 { bonnet(j, x) + bonnet(j, -x) } else { bonnet(j, x) - bonnet(j, -x) };
                        let term = table[k * half + i] * pair;
                        sum += term;
                        magnitude += term.abs();
                    }
                    let expected = if j == k { 1.0 } else { 0.0 };
                    let bound = (n + 2 * k + 2) as f64 * f64::EPSILON * magnitude;
                    assert!((sum - expected).abs() <= bound, "n {n}: row {k} of P_{j}: {sum} (bound {bound:e})");
                }
            }
        }
    }

    /// The tabulated coefficients against Bonnet's recurrence
    /// `(k+1) P_{k+1} = (2k+1) ξ P_k − k P_{k−1}` (DLMF 18.9.1), a different route to `P_k`.
    #[test]
    fn legendre_monomials_match_bonnet() {
        for &x in &[-0.97f64, -0.31, 0.0, 0.42, 0.999] {
            for (k, row) in LEGENDRE_MONOMIAL.iter().enumerate() {
                let from_table = row.iter().rev().fold(0.0, |acc, &a| acc * x + a as f64) / (1u64 << k) as f64;
                let cur = bonnet(k, x);
                // the sum's rounding: ε Σ|a_i x^i| / 2^k ≤ ε (1+√2)^k
                let bound = 4.0 * f64::EPSILON * (1.0 + 2f64.sqrt()).powi(k as i32);
                assert!((from_table - cur).abs() <= bound, "P_{k}({x}): table {from_table}, recurrence {cur}");
            }
        }
    }

    /// `P_j(x)` by Bonnet's recurrence `(k+1) P_{k+1} = (2k+1) x P_k − k P_{k−1}` (DLMF 18.9.1):
    /// the tests' route to the Legendre polynomials apart from the tables and their generator.
    fn bonnet(j: usize, x: f64) -> f64 {
        let (mut prev, mut cur) = (0.0f64, 1.0f64);
        for k in 0..j {
            let kf = k as f64;
            let next = ((2.0 * kf + 1.0) * x * cur - kf * prev) / (kf + 1.0);
            prev = cur;
            cur = next;
        }
        cur
    }
}
