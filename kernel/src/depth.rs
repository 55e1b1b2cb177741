//! A route by cost for a thick medium: the whole segment by Gauss–Laguerre in the optical depth
//! seen from the light, tried where the light is at least a mean free path from the ray's line
//! ([`Ends::thick`]) and taken where its error estimate meets the panels' target
//! (docs/DESIGN.md §4.3); otherwise [`crate::combined`] goes on to the light-angle route
//! ([`crate::angle`]) and the closed-form panels.
//!
//! With `Y = tan(θ/2 + π/4)` as in [`crate::angle`] (`θ` the angle seen from the light), the
//! extinction exponent past the segment's start is `s = H(Y − Y0)`, `H = σt h`, and
//! `dθ = 2 dY/(1 + Y²)`, so
//!
//! `∫_{θ0}^{θ1} e^{−H(Y − Y0)} F dθ = (1/H) ∫_0^S e^{−s} G(s) ds`, `G = F · 2/(1 + Y²)`,
//! `S = H(Y1 − Y0)`,
//!
//! and in `Y` the angle's sine and cosine are rational: `sin θ = (Y² − 1)/(Y² + 1)`,
//! `cos θ = 2Y/(1 + Y²)`, `1 − sin θ = 2/(1 + Y²)`, `1 + sin θ = 2Y²/(1 + Y²)`, each without
//! cancellation. A sample costs one division besides `D` and `P`: no trigonometric function and
//! no exponential (the weight `e^{−s}` is the rule's). `∫_0^S = ∫_0^∞ − e^{−S} ∫_0^∞ e^{−x}
//! G(S + x) dx`: one `N`-node Gauss–Laguerre rule, and for a finite segment whose `e^{−S}` is
//! not below the float range a second at `S` (`G` continued past the segment's end, the same
//! analytic function along the ray's line). Where `e^{−S}` is at most the panels' cut
//! resolution `δ·τ` (`crate::combined::cut_resolution`: a tail the panels would drop), that
//! second rule is the 6-node one and the whole of its term counts as error: it only has to
//! show that the tail is that small (a `G` far larger past the end than on the segment fails
//! the estimate instead).
//!
//! Where the medium is thick and the light not next to the ray, `G` is smooth on the scale of
//! the weight and a few nodes reach the target where Gauss–Legendre in `θ` needs the segment
//! cut at the extinction's boundary layer and 8–24 nodes over it. `G` is analytic but where
//! `Y = ±i` (`2/(1 + Y²)`, the light's `c` and a phase function's growth) and at the phase
//! function's singularities, `sin θ = −μ*`: `Y² = (1 − μ*)/(1 + μ*)`, `Y = ±i·b` with
//! `b = √((μ* − 1)/(μ* + 1))` for a forward lobe (`μ* > 1`; a backward one's `b > 1` lies
//! beyond `±i`). In `s` they sit at `s* = H(−Y0 ± i·b)`, and the Laguerre coefficients of a
//! function analytic inside the parabola with focus 0 through `s*` fall like `exp(−2σ√k)`,
//! `σ = Re √(−s*) = √(H(√(Y0² + b²) + Y0)/2)` (Szegő, *Orthogonal Polynomials*, §9.1: a
//! Laguerre series converges inside such parabolas), the nearest `b` giving the smallest `σ`
//! (on the `thick` scenes of tests/reference/classes.jsonl the rule's errors follow
//! `exp(−4σ√N)` within about 10×).
//!
//! The error estimate is the panels' model ([`crate::panels`], [`crate::angle`]) with
//! Laguerre's sub-geometric decay: the two last coefficients `|a_{N−1}| + |a_{N−2}|` carried
//! from degree `N − 3/2` to the degree `2N − m` the rule leaves (`m` =
//! [`ALIASING_MARGIN`]) by the slower of the decay the last four show, read as `exp(−2σ√k)`
//! (its power's exponent rounded down, which only raises it), and the nearest singularity's,
//! times 2 (an `N`-node rule integrates `L_k` to within
//! `Σ w_i |L_k(x_i)| ≤ Σ w_i e^{x_i/2} ≈ 2`, `|L_k(x)| ≤ e^{x/2}`, Szegő (7.21.3)); the route is
//! taken where it is below `tolerance × max(|value|, floor × scale)`, the panels' acceptance
//! test (tests/tests/classes.rs checks the results against the mpmath references).
//!
//! It is tried only where it is likely to pass, judged before any sample (cost, never
//! accuracy): the singularities' prediction `4·exp(−2σ√(2N − m))`, times `(2N − m)^{α−1}` where
//! the nearest is a forward lobe's of order `α` (its coefficients' polynomial factor `k^{α−1}`,
//! whose step ratio the panels' `crate::panels::order_step` takes), and a light's lobe `c^p`,
//! which varies at the rate `ℓ = √p · dθ/ds = 2√p/(H(1 + Y0²))` at the start (the largest:
//! `dθ/ds` falls with `Y`), as `e^{iℓs}`, whose Laguerre coefficients fall like
//! `(ℓ/√(1 + ℓ²))^k`: `2·(ℓ/√(1 + ℓ²))^{2N − m}`, each within the tolerance. A light
//! distribution with kinks, or a phase function or distribution not known to be analytic,
//! declines it, as the light-angle route.

use crate::angle::{Ends, Route};
use crate::combined::{cut_resolution, weighted, Physics};
use crate::expansion::{laguerre_table, last_laguerre_coefficients};
use crate::geometry::Canonical;
use crate::light::LightDistribution;
use crate::panels::{order_power, power, Control, ALIASING_MARGIN};
use crate::phase::PhaseFunction;
use crate::real::{exp_nonpositive, hypot1, larger, Real};

/// The rule that sizes a tail below the panels' cut ([`whole_segment`]), and its table.
const SIZING_NODES: usize = 6;
const SIZING_RULE: (&[(f64, f64)], &[f64]) = match laguerre_table::rule(SIZING_NODES) {
    Some(rule) => rule,
    None => panic!("the sizing rule is tabulated"),
};

/// The route as the default path takes it: [`whole_segment`] with 6 nodes where the light-angle
/// rules have `N ≤ 8` (f32), else 12 (f64) and, where 12's predictions decline it before any
/// sample, 24 (docs/DESIGN.md §4.3), from the segment's [`Ends`] formed here, before any
/// of the light angle's plan. Cold and not inlined, so that the default path's code for the rays
/// that do not take it stays as it was (measured: inlined, or only not inlined, the plan's
/// `atan2_upper` and `cut_length` were no longer inlined there, +2–4 % instructions per ray
/// on every f32 class of tests/reference/classes.jsonl but `thick`).
#[cold]
#[inline(never)]
pub(crate) fn thick_route<T, D, P, const N: usize>(g: &Canonical<T>, phys: &Physics<'_, T, D, P>, control: &Control<T>) -> Route<T>
where
    T: Real,
    D: LightDistribution<T>,
    P: PhaseFunction<T>,
{
    match Ends::new(g, phys) {
        Some(ends) if N <= 8 => whole_segment::<T, D, P, 6>(&ends, g, phys, control),
        Some(ends) => match whole_segment::<T, D, P, 12>(&ends, g, phys, control) {
            Route::Declined => whole_segment::<T, D, P, 24>(&ends, g, phys, control),
            route => route,
        },
        None => Route::Declined,
    }
}

/// The whole segment `[t0, t1]` by `N`-node Gauss–Laguerre in the optical depth (module docs),
/// from the segment's [`Ends`] (its `Y0`, `Y1`, `H`, the lobe's degree and the nearest
/// singularity), if the predictions and then the estimate meet `control`.
pub fn whole_segment<T, D, P, const N: usize>(ends: &Ends<T>, g: &Canonical<T>, phys: &Physics<'_, T, D, P>, control: &Control<T>) -> Route<T>
where
    T: Real,
    D: LightDistribution<T>,
    P: PhaseFunction<T>,
{
    let Some((rule, transform)) = laguerre_table::rule(N) else {
        return Route::Declined;
    };
    let Ends { u0, big_h, y0, y1, degree, singular, .. } = *ends;
    // `μ* − 1` of the nearest forward singularity (`μ* > 1`; `+∞` without one)
    let gap = singular.cosines.iter().fold(T::infinity(), |m, &mu| if mu > T::one() && mu.is_finite() { m.min(mu - T::one()) } else { m });
    if !(big_h > T::zero()) || !big_h.is_finite() {
        return Route::Declined;
    }
    let tolerance = control.tolerance;
    // √(2N − m), √(N − 3/2), √(N − 7/2): the degrees the estimate reads and carries the last
    // coefficients to (module docs)
    let (top, last, first) = (T::from(2 * N - ALIASING_MARGIN).unwrap().sqrt(), T::lit(N as f64 - 1.5).sqrt(), T::lit(N as f64 - 3.5).sqrt());
    // before any sample: the singularities' prediction and the lobe's (module docs)
    // the nearest singularity: Y = ±i (b = 1) or a forward lobe's ±i·b, b² = gap/(2 + gap)
    let b2 = if gap < T::infinity() { (gap / (T::lit(2.0) + gap)).min(T::one()) } else { T::one() };
    let sigma = (big_h * ((y0 * y0 + b2).sqrt() + y0) * T::lit(0.5)).sqrt();
    let predicted = T::lit(4.0) * exp_nonpositive(-(top + top) * sigma);
    if !(predicted <= tolerance) {
        return Route::Declined;
    }
    // a forward lobe's singularity of order α: its coefficients carry a factor k^{α−1} besides
    // the rate (whose step ratio the panels' `order_step` takes), here at k = 2N − m
    if b2 < T::one() && !(predicted * order_power(top, singular.order) <= tolerance) {
        return Route::Declined;
    }
    if degree > T::zero() {
        let rate = T::lit(2.0) * degree.sqrt() / (big_h * (T::one() + y0 * y0));
        let decay = rate / hypot1(rate);
        if !(T::lit(2.0) * power(decay, 2 * N - ALIASING_MARGIN) <= tolerance) {
            return Route::Declined;
        }
    }
    // the estimate: the slower of the decay the last four show and the singularity's
    let floor_factor = exp_nonpositive(-T::lit(2.0) * (top - last) * sigma);
    // the measured decay per degree q = √(recent/earlier), read as exp(−2σ√k) between the
    // degrees N − 7/2 and N − 3/2, carried on to 2N − m: q^{2κ}, κ = (√(2N − m) − √(N − 3/2))/
    // (√(N − 3/2) − √(N − 7/2)), the exponent rounded down (the factor only larger; no `powf`)
    let steps = ((top - last) / (last - first) * T::lit(2.0)).floor().to_usize().unwrap_or(0);
    let estimate = |c: &[T; 4]| {
        let recent = c[3].abs() + c[2].abs();
        let earlier = c[1].abs() + c[0].abs();
        let factor = if recent < earlier { power((recent / earlier).sqrt(), steps).max(floor_factor) } else { T::one() };
        T::lit(2.0) * recent * factor
    };
    // the rule at the start and, for a finite segment whose e^{−S} is representable, at its end
    // (sized by 6 nodes where e^{−S} is below the cut's resolution, all of it then error: module
    // docs)
    let far = exp_nonpositive(-(big_h * (y1 - y0)));
    let head = laguerre::<T, D, P, N>(g, phys, rule, transform, y0, big_h);
    let (mut value, mut mass, mut f_max) = (head.value, head.mass, head.f_max);
    let mut error = estimate(&head.last);
    if y1.is_finite() && far > T::zero() {
        let sized_only = N > SIZING_NODES && far <= cut_resolution(control);
        let end = if sized_only {
            laguerre::<T, D, P, SIZING_NODES>(g, phys, SIZING_RULE.0, SIZING_RULE.1, y1, big_h)
        } else {
            laguerre::<T, D, P, N>(g, phys, rule, transform, y1, big_h)
        };
        value = value - far * end.value;
        mass = mass - far * end.mass;
        f_max = larger(f_max, end.f_max);
        error = error + if sized_only { far * end.value.abs() } else { far * estimate(&end.last) };
    }
    let target = tolerance * value.abs().max(control.floor * f_max * mass);
    if !(error <= target) {
        return Route::Failed;
    }
    // (σs I/h) e^{−σt r0} ∫ dθ, ∫ dθ = value/H, handed over as the light-angle route does
    let (h, x) = (g.h, phys.sigma_t * (g.h * hypot1(u0)));
    Route::Taken(weighted(phys.sigma_s, phys.intensity, h, x, value / big_h * T::lit(0.5)))
}

/// One Gauss–Laguerre rule's sums from `Y_s` on ([`laguerre`]).
struct Sums<T> {
    /// `Σ w_i G(Y_s + x_i/H)`.
    value: T,
    /// The last four Laguerre coefficients `a_{N−4} … a_{N−1}`.
    last: [T; 4],
    /// `Σ w_i · 2/(1 + Y_i²)`: the value with `F = 1`, for the floor's scale.
    mass: T,
    /// The largest `|F|` sampled.
    f_max: T,
}

/// The `N`-node rule's [`Sums`] from `Y_s` on.
#[inline]
fn laguerre<T, D, P, const N: usize>(g: &Canonical<T>, phys: &Physics<'_, T, D, P>, rule: &[(f64, f64)], transform: &[f64], y_s: T, big_h: T) -> Sums<T>
where
    T: Real,
    D: LightDistribution<T>,
    P: PhaseFunction<T>,
{
    let inv_h = big_h.recip();
    // the nodes' Y and 2/(1 + Y²) = 1 − sin θ; 1 + sin θ = Y²·(1 − sin θ), sin θ = (Y² − 1)/(Y² + 1),
    // cos θ = Y·(1 − sin θ)
    let mut minus = [T::zero(); N];
    let mut plus = [T::zero(); N];
    let mut lights = [T::zero(); N];
    let mut sines = [T::zero(); N];
    for i in 0..N {
        let y = y_s + T::lit(rule[i].0) * inv_h;
        let m = T::lit(2.0) / (T::one() + y * y);
        let p = y * y * m;
        let s = (p - m) * T::lit(0.5);
        minus[i] = m;
        plus[i] = p;
        sines[i] = s;
        lights[i] = g.d_el * s + g.d_c * (y * m);
    }
    phys.light.eval_each(&mut lights);
    // μ = −sin θ: 1 − μ = 1 + sin θ, 1 + μ = 1 − sin θ
    let phases = phys.phase.eval_sides_each(&sines.map(|s| -s), &plus, &minus);
    let mut samples = [T::zero(); N];
    let (mut value, mut mass, mut f_max) = (T::zero(), T::zero(), T::zero());
    for i in 0..N {
        let f = lights[i] * phases[i];
        let w = T::lit(rule[i].1);
        samples[i] = f * minus[i];
        value = value + w * samples[i];
        mass = mass + w * minus[i];
        f_max = larger(f_max, f.abs());
    }
    Sums { value, last: last_laguerre_coefficients(transform, &samples), mass, f_max }
}

#[cfg(test)]
mod tests {
    use crate::expansion::laguerre_table;

    /// The generated tables (scripts/gen_gauss_laguerre.py) against what they stand for: each
    /// `N`-node rule integrates `x^j e^{−x}` over `[0, ∞)` to `j!` for `j < 2N` (Gauss), and
    /// its transform row `k` is `w_i · L_k(x_i)` with `L_k` by its three-term recurrence
    /// (A&S 22.7.12), both within `1e-13` relative (`x^j` and the recurrence round a few ε
    /// times the largest term, `j!` up to `47!` summed from terms up to ~8× it); the transform
    /// relative to the recurrence's largest term so far (`w_i` times it): near a zero of `L_k`
    /// the value is far below the terms that cancel to it (24 points: 1.7e-13 of the value at
    /// `k = 22`, `x ≈ 50`).
    #[test]
    fn tables_are_gauss_laguerre_rules() {
        for n in [6usize, 12, 24] {
            let (rule, transform) = laguerre_table::rule(n).expect("tabulated");
            assert_eq!((rule.len(), transform.len()), (n, n * n));
            let mut factorial = 1.0f64;
            for j in 0..2 * n {
                if j > 0 {
                    factorial *= j as f64;
                }
                let moment: f64 = rule.iter().map(|&(x, w)| w * libm::pow(x, j as f64)).sum();
                assert!((moment / factorial - 1.0).abs() < 1e-13, "n {n}, j {j}: {moment:e} vs {factorial:e}");
            }
            for (i, &(x, w)) in rule.iter().enumerate() {
                let (mut previous, mut current, mut largest) = (0.0f64, 1.0f64, 1.0f64);
                for k in 0..n {
                    let expected = w * current;
                    let table = transform[k * n + i];
                    assert!((table - expected).abs() <= 1e-13 * w * largest, "n {n}, k {k}, i {i}: {table:e} vs {expected:e}");
                    let (a, b) = (((2 * k + 1) as f64 - x) * current / (k + 1) as f64, k as f64 * previous / (k + 1) as f64);
                    largest = largest.max(a.abs()).max(b.abs());
                    (previous, current) = (current, a - b);
                }
            }
        }
    }
}
