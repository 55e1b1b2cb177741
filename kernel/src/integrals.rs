//! Closed forms of the two reformulations (paper §3.3–3.4, eq. 8–19), as *moments*.
//!
//! After the split at the light's foot (see [`crate::combined`]), each half of the segment is an
//! integral over a bounded variable `y ∈ [y_lo, y_hi] ⊂ [0, 1]`:
//!
//! * first reformulation (before the foot): `y = v = u + √(1+u²)`, weight `e^{−H y}`;
//! * second reformulation (after the foot): `y = −w = 1/v`, weight `e^{−H/y}`.
//!
//! In both, `du/(1+u²) = 2 dy/(1+y²)` (eq. 8, 14). With the expansion `F ≈ Σ a_k s^k` in the
//! *local* offset `s = y − y_c` from the sub-interval's midpoint `y_c`, the half integral is
//! `Σ a_k m_k` with the moments
//!
//! `m_k = ∫ e^{−H(v − v_s)} s^k / (1 + y²) dy`   (`v_s`: smallest `v` on the half),
//!
//! scaled by `e^{H v_s}` so that nothing overflows (docs/DESIGN.md §3). Since `1/(1+y²) = Im 1/(y−i)`,
//! `m_k = Im Q_k` with `Q_k = ∫ e^{…} s^k/(y − i) dy`, and `s^k/(s + b) = s^{k−1} − b s^{k−1}/(s + b)`
//! (`b = y_c − i`) gives `Q_k = R_{k−1} − b Q_{k−1}`, `R_j = ∫ e^{…} s^j dy`: the paper's
//! reduction of `vⁿ/(1+v²)` (eq. 12–13, 18–19), in the local variable. Working locally keeps the
//! products `a_k·m_k` accurate even on tiny sub-intervals, where monomials in `y` would cancel.
//!
//! `Q_0` is where the exponential integral enters: with `C = ∫_{v_s}^{v_e} e^{−H(v−v_s)}/(v − i) dv`
//! (docs/DESIGN.md §2: `C = e^{Hv_s}(G(v_e) − G(v_s))`, `G(v) = −e^{−iH}E1(H(v − i))`),
//! * first half: `Q_0 = C`;
//! * second half: `Q_0 = T_1 − conj(C)`, `T_n = ∫ e^{−H(v−v_s)} v^{−n} dv` (eq. 17, 35: the
//!   paper's `J_e` is `T_1`).
//!
//! Three evaluation routes, chosen per half:
//! 1. **short** (`H·Δv ≤ 1`, `Δy ≤ 1/4`, and on the second half `Δy ≤ y_lo/2`): a
//!    Gauss–Legendre rule in `y`. Every closed form here is a difference of two nearly equal
//!    values, and the moment recurrence below loses `(|b|/r)^k` ulps on a sub-interval of
//!    half-width `r`; on such an interval the integrand is analytic well beyond it (poles at
//!    `±i` at ≥ 8 half-widths, `y = 0` at ≥ 4 on the second half; `e^{−Hv}` changes by at most
//!    `e^1`), so the rule is exact to rounding: the error of an `n`-point rule on `e^{−λx}`
//!    over `[0, 1]` is `≈ λ^{2n}/(2^{2n}(2n)!) ≤ 1e-18` (f64, 8 points) and `2e-10` (f32, 4
//!    points) at `λ = 1`, and `≈ ρ^{−2n}` for the poles, `ρ ≥ 8`.
//! 2. **near** (`H·|v_e − i| ≤ 1`, including `H = 0`): the `ln z` of both `E1` values is
//!    combined analytically (`ln((v_e − i)/(v_s − i))`, no `ln H`), the rest is a divided
//!    difference of `Ein`; exact at `H = 0` (the Macklin/Packard `atan` form).
//! 3. **far**: scaled `e^z E1(z)` at both ends, `C = S(z_s) − e^{−HΔv} S(z_e)`; for `Im Q_0`
//!    alone the far end only where its weight `e^{−HΔv}` exceeds `ε/4` ([`FAR_END_NEGLIGIBLE`]),
//!    and an isotropic first half with its near end in `E1`'s series region folds that end's
//!    `e^{Hv_s}` into the caller's weight ([`moment_zero`]).

use crate::real::{hypot1, Real};
use crate::special::{e1_by_series, ein_divided_difference, en_scaled, in_series_region, C};

/// Which exponential integral the closed forms use: the production one, or the paper's.
pub trait ExpIntegral<T: Real> {
    /// `e^z E1(z)` for `Re z ≥ 0`.
    fn e1_scaled(&self, z: C<T>) -> C<T>;
    /// Whether the regularised near-origin route (2 above) and the short-interval route (1)
    /// are used. The paper's algorithm has neither.
    fn stabilised(&self) -> bool {
        true
    }
    /// `E1(z)` itself where the implementation sums it as a series, without forming the factor
    /// `e^z` of [`e1_scaled`](Self::e1_scaled) (a caller may fold that factor into a weight of its
    /// own: [`moment_zero`]); `None` elsewhere, and by default.
    fn e1_series(&self, z: C<T>) -> Option<C<T>> {
        let _ = z;
        None
    }
}

/// The production exponential integral: [`crate::special::e1_scaled`].
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Production;

impl<T: Real> ExpIntegral<T> for Production {
    #[inline]
    fn e1_scaled(&self, z: C<T>) -> C<T> {
        crate::special::e1_scaled(z)
    }
    #[inline]
    fn e1_series(&self, z: C<T>) -> Option<C<T>> {
        (z.re >= T::zero() && in_series_region(z)).then(|| e1_by_series(z))
    }
}

/// The paper's algorithm as published: its `Ei` (eq. 27, fig. 2) in the plain closed forms,
/// without the regularised or short-interval routes. For comparison only.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct PaperEq27<T> {
    /// Absolute tolerance `ε` of eq. 27.
    pub precision: T,
    /// Iteration cap of fig. 2.
    pub max_iterations: usize,
}

impl<T: Real> ExpIntegral<T> for PaperEq27<T> {
    #[inline]
    fn e1_scaled(&self, z: C<T>) -> C<T> {
        crate::special::paper::e1_scaled_paper(z, self.precision, self.max_iterations)
    }
    fn stabilised(&self) -> bool {
        false
    }
}

/// An [`ExpIntegral`] that remembers its last value: the two halves share the foot `v = 1`,
/// where the first half's far end and the second half's near end are the same `e^z E1(z)`,
/// `z = H(1 − i)` (route 3), so a segment across the foot evaluates it once.
#[derive(Debug)]
pub struct SharedEnds<'a, T: Real, E> {
    inner: &'a E,
    last: core::cell::Cell<Option<(C<T>, C<T>)>>,
}

impl<'a, T: Real, E: ExpIntegral<T>> SharedEnds<'a, T, E> {
    /// Wraps `inner`, remembering nothing yet.
    pub fn new(inner: &'a E) -> Self {
        SharedEnds { inner, last: core::cell::Cell::new(None) }
    }
}

impl<T: Real, E: ExpIntegral<T>> ExpIntegral<T> for SharedEnds<'_, T, E> {
    #[inline]
    fn e1_scaled(&self, z: C<T>) -> C<T> {
        if let Some((at, value)) = self.last.get() {
            if at.re == z.re && at.im == z.im {
                return value;
            }
        }
        let value = self.inner.e1_scaled(z);
        self.last.set(Some((z, value)));
        value
    }
    fn stabilised(&self) -> bool {
        self.inner.stabilised()
    }
    #[inline]
    fn e1_series(&self, z: C<T>) -> Option<C<T>> {
        self.inner.e1_series(z)
    }
}

/// One half of the split segment, in the bounded variable `y` (see the module docs).
#[derive(Clone, Copy, Debug)]
pub struct Half<T: Real> {
    /// `false`: first reformulation (`y = v`); `true`: second (`y = 1/v`).
    pub second: bool,
    /// Optical distance from the light to the ray line, `H = σt·h`.
    pub big_h: T,
    /// Lower end of `y`.
    pub y_lo: T,
    /// Upper end of `y`.
    pub y_hi: T,
    /// `y_hi − y_lo`, computed without cancellation by the caller.
    pub dy: T,
    /// `Δv = v_e − v_s` (`+∞` when the half reaches `t = +∞`).
    pub dv: T,
}

impl<T: Real> Half<T> {
    /// The smallest `v` on the half (where the weight is scaled to 1).
    #[inline]
    fn v_s(&self) -> T {
        if self.second {
            self.y_hi.recip()
        } else {
            self.y_lo
        }
    }
    /// The largest `v` on the half (`+∞` possible).
    #[inline]
    fn v_e(&self) -> T {
        if self.second {
            if self.y_lo == T::zero() {
                T::infinity()
            } else {
                self.y_lo.recip()
            }
        } else {
            self.y_hi
        }
    }
    /// The part `[lo, hi] ⊂ [y_lo, y_hi]` as a half of its own, and the factor
    /// `e^{−H(v_s(part) − v_s(self))}` that rescales its moments to this half's weight.
    pub fn part(&self, lo: T, hi: T) -> (Half<T>, T) {
        let dy = hi - lo;
        let (dv, offset) = if self.second {
            // Δv = 1/lo − 1/hi (∞ at lo = 0, the segment's end at t = ∞); v_s moves to 1/hi
            let dv = if lo == T::zero() { T::infinity() } else { dy / (lo * hi) };
            (dv, (self.y_hi - hi) / (hi * self.y_hi))
        } else {
            (dy, lo - self.y_lo)
        };
        let part = Half { second: self.second, big_h: self.big_h, y_lo: lo, y_hi: hi, dy, dv };
        (part, (-self.big_h * offset).exp())
    }

    /// Midpoint `y_c` of the sub-interval (the expansion point).
    #[inline]
    pub fn y_mid(&self) -> T {
        self.y_lo + self.dy * T::lit(0.5)
    }
}

/// The largest supported term count.
pub const MAX_TERMS: usize = 16;

/// Fills `m[0..count]` with the moments `m_k` of `half` (module docs), `count ≤ N`.
/// `N ≤ MAX_TERMS` is checked at compile time.
pub fn moments<T: Real, E: ExpIntegral<T>, const N: usize>(
    half: &Half<T>,
    ei: &E,
    count: usize,
) -> [T; N] {
    const { assert!(N <= MAX_TERMS, "at most MAX_TERMS expansion terms") };
    let mut m = [T::zero(); N];
    let count = count.min(N);
    if count == 0 || !(half.dy > T::zero()) {
        return m;
    }
    if ei.stabilised() && is_short(half) {
        moments_gauss(half, &mut m[..count]);
        return m;
    }
    let yc = half.y_mid();
    let q0 = q0(half, ei, count > 1);
    m[0] = q0.im;
    if count > 1 {
        let mut r = [T::zero(); N];
        if half.second {
            r_second(half, yc, &mut r[..count - 1]);
        } else {
            r_first(half, &mut r[..count - 1]);
        }
        let b = C::new(yc, -T::one());
        let mut q = q0;
        for k in 1..count {
            q = C::new(r[k - 1], T::zero()) - b * q;
            m[k] = q.im;
        }
    }
    m
}

/// Route 1 applies (see module docs).
#[inline]
fn is_short<T: Real>(half: &Half<T>) -> bool {
    let quarter = T::lit(0.25);
    let ok_exp = half.big_h * half.dv <= T::one();
    let ok_len = half.dy <= quarter && (!half.second || half.dy <= half.y_lo * T::lit(0.5));
    ok_exp && ok_len
}

/// Gauss–Legendre moments (route 1).
fn moments_gauss<T: Real>(half: &Half<T>, m: &mut [T]) {
    let hw = half.dy * T::lit(0.5);
    let yc = half.y_mid();
    for k in 0..m.len() {
        m[k] = T::zero();
    }
    for &(xi, w) in T::GAUSS_NODES {
        for sign in [-T::one(), T::one()] {
            let xi = T::lit(xi) * sign;
            let s = hw * xi;
            let y = yc + s;
            // v − v_s, without cancellation
            let dv = if half.second {
                // 1/y − 1/y_hi = (y_hi − y)/(y·y_hi), y_hi − y = hw(1 − ξ)
                hw * (T::one() - xi) / (y * half.y_hi)
            } else {
                hw * (T::one() + xi)
            };
            let weight = T::lit(w) * hw * (-half.big_h * dv).exp() / (T::one() + y * y);
            let mut p = weight;
            for mk in m.iter_mut() {
                *mk = *mk + p;
                p = p * s;
            }
        }
    }
}

/// `Q_0` (module docs); `with_re`: whether the real part is needed (moments above 0).
fn q0<T: Real, E: ExpIntegral<T>>(half: &Half<T>, ei: &E, with_re: bool) -> C<T> {
    let big_h = half.big_h;
    let (v_s, v_e) = (half.v_s(), half.v_e());
    if ei.stabilised() && is_near(big_h, v_e) {
        q0_near(half, v_s, v_e, with_re)
    } else {
        q0_far(half, ei, v_s, v_e, with_re)
    }
}

/// Route 2 applies (`H·|v − i| ≤ 1` at both ends, or `H = 0`), for the half's largest `v_e`.
#[inline]
fn is_near<T: Real>(big_h: T, v_e: T) -> bool {
    big_h == T::zero() || (v_e.is_finite() && big_h * hypot1(v_e) <= T::one())
}

/// `m_0` of a half whose `F` is constant, with the exponent `x` of the weight `e^{−x}` the
/// caller puts on it: returns `(m, x')` with `e^{−x'} m = e^{−x} m_0`. On route 3 of a first
/// half whose near end lies in `E1`'s series region ([`ExpIntegral::e1_series`]) that is
/// `m = e^{−Hv_s} m_0` and `x' = x − Hv_s`: `e^{−Hv_s} S(z_s) = e^{−iH} E1(z_s)`, so the factor
/// `e^{Hv_s}` of the scaled `E1` is never formed (one exponential fewer), and the far end enters
/// as `e^{−Hv_e} Im S(z_e)`, left out where `e^{−HΔv} ≤ ε/4` ([`FAR_END_NEGLIGIBLE`]). With
/// `v_s ≤ 1` on a first half and `|z_s| < 4` in the series region, `e^{−Hv_s} > e^{−4}`: `m`
/// keeps `m_0`'s scale. Elsewhere `(m_0, x)`.
pub fn moment_zero<T: Real, E: ExpIntegral<T>>(half: &Half<T>, ei: &E, x: T) -> (T, T) {
    let big_h = half.big_h;
    let (v_s, v_e) = (half.v_s(), half.v_e());
    let far_route = ei.stabilised() && !half.second && half.dy > T::zero() && !is_short(half) && !is_near(big_h, v_e);
    let e1_s = if far_route { ei.e1_series(C::new(big_h * v_s, -big_h)) } else { None };
    let Some(e1_s) = e1_s else {
        let m: [T; 1] = moments(half, ei, 1);
        return (m[0], x);
    };
    let near = (e1_s * C::new(big_h.cos(), -big_h.sin())).im;
    // e^{−HΔv} > δ ⇔ HΔv < ln(1/δ)
    let far_needed = big_h * half.dv < -(T::epsilon() * T::lit(FAR_END_NEGLIGIBLE)).ln();
    let far = if far_needed && (big_h * v_e).is_finite() {
        (-big_h * v_e).exp() * ei.e1_scaled(C::new(big_h * v_e, -big_h)).im
    } else {
        T::zero()
    };
    (near - far, x - big_h * v_s)
}

/// Route 2: `H·|v − i| ≤ 1` at both ends, or `H = 0`.
fn q0_near<T: Real>(half: &Half<T>, v_s: T, v_e: T, with_re: bool) -> C<T> {
    let big_h = half.big_h;
    let dv = half.dv;
    let half_t = T::lit(0.5);
    // D = ln((v_e − i)/(v_s − i)) = ½ log1p(Δv(v_s+v_e)/(1+v_s²)) + i atan(Δv/(1 + v_s v_e))
    let d_im = if v_e.is_finite() {
        (dv / (T::one() + v_s * v_e)).atan()
    } else {
        // v_e = ∞ (only with H = 0): atan(∞) − atan(v_s) = atan(1/v_s)
        v_s.recip().atan()
    };
    let d_re = if v_e.is_finite() {
        let x = dv * (v_s + v_e) / (T::one() + v_s * v_s);
        if x.is_finite() {
            half_t * x.ln_1p()
        } else {
            // the product overflows (Δv and v_e near the range's end) while its logarithm does
            // not: an infinite Re D would reach Im C through e^{−iH}'s sin H
            half_t * (dv.ln() + (v_s + v_e).ln() - (v_s * v_s).ln_1p())
        }
    } else {
        T::infinity()
    };
    if big_h == T::zero() {
        // Exact: C = D (the atan form of Macklin/Packard), and T_1 − Re C = −½[log1p(1/v²)].
        if !half.second {
            return C::new(d_re, d_im);
        }
        let n1 = if with_re { n1_log_part(v_s, v_e) } else { T::zero() };
        return C::new(n1, d_im);
    }
    // C = e^{−iH} [D − HΔv · EinDD(z_s, z_e)], scaled by e^{H v_s}.
    let z_s = C::new(big_h * v_s, -big_h);
    let z_e = C::new(big_h * v_e, -big_h);
    let hdv = big_h * dv;
    let ein_dd = ein_divided_difference(z_s, z_e);
    let rot = C::new(big_h.cos(), -big_h.sin());
    let scale = (big_h * v_s).exp();
    let d = C::new(d_re, d_im);
    let c = rot * (d - ein_dd * hdv) * scale;
    if !half.second {
        return c;
    }
    // Second half: Q_0 = T_1 − conj(C) = N_1 + i·Im C, with N_1 regularised:
    // N_1 = −½[log1p(1/v²)] + 2 sin²(H/2) Re D − sin H · Im D
    //       − HΔv [EinDD(Hv_s, Hv_e) − Re(e^{−iH} EinDD(z_s, z_e))].
    let n1 = if with_re {
        let sh = (big_h * half_t).sin();
        let ein_dd_real = ein_divided_difference(
            C::new(big_h * v_s, T::zero()),
            C::new(big_h * v_e, T::zero()),
        );
        (n1_log_part(v_s, v_e) + (sh * sh + sh * sh) * d_re - big_h.sin() * d_im
            - hdv * (ein_dd_real.re - (rot * ein_dd).re))
            * scale
    } else {
        T::zero()
    };
    C::new(n1, c.im)
}

/// `[ln(v/|v − i|)]_{v_s}^{v_e} = −½ (log1p(1/v_e²) − log1p(1/v_s²))`.
#[inline]
fn n1_log_part<T: Real>(v_s: T, v_e: T) -> T {
    let half_t = T::lit(0.5);
    let at = |v: T| if v.is_finite() { (v * v).recip().ln_1p() } else { T::zero() };
    -half_t * (at(v_e) - at(v_s))
}

/// Route 3: scaled `E1` at both ends.
fn q0_far<T: Real, E: ExpIntegral<T>>(half: &Half<T>, ei: &E, v_s: T, v_e: T, with_re: bool) -> C<T> {
    let big_h = half.big_h;
    let s_s = ei.e1_scaled(C::new(big_h * v_s, -big_h));
    // The far end contributes e^{−HΔv}·S(z_e); where H·v_e overflows that is 0, and it is
    // left out where it is below half a rounding of Im Q_0 (FAR_END_NEGLIGIBLE).
    let v_e = if (big_h * v_e).is_finite() { v_e } else { T::infinity() };
    let decay = if v_e.is_finite() { (-big_h * half.dv).exp() } else { T::zero() };
    let s_e = if decay > far_end_negligible(with_re, ei) { ei.e1_scaled(C::new(big_h * v_e, -big_h)) } else { C::new(T::zero(), T::zero()) };
    let c = s_s - s_e * decay;
    if !half.second {
        return c;
    }
    // Q_0 = T_1 − conj(C), so Re Q_0 = N_1 = ∫ e^{…} dv / (v(1+v²)).
    let n1 = if !with_re {
        T::zero()
    } else if half.y_hi <= T::lit(0.25) {
        n1_series(half)
    } else {
        // T_1 − Re C with T_1 = s_1(Hv_s) − e^{−HΔv} s_1(Hv_e): the two agree to a factor
        // 1 + v² ≤ 17 here, so the difference keeps its accuracy.
        let mut e_s = [T::zero(); 1];
        en_scaled(big_h * v_s, &mut e_s);
        let mut tail = T::zero();
        if v_e.is_finite() {
            let mut e_e = [T::zero(); 1];
            en_scaled(big_h * v_e, &mut e_e);
            tail = (e_e[0] - s_e.re) * decay;
        }
        (e_s[0] - s_s.re) - tail
    };
    C::new(n1, c.im)
}

/// `δ/ε`: route 3 leaves out the far end of `Im Q_0` where its weight `e^{−HΔv}` is at most
/// `δ = ε/4`. With `G(v) = e^{−H(v−v_s)}/(1+v²)` decreasing, `Im C = ∫_{v_s}^{v_e} G ≥
/// (1 − e^{−HΔv})/(H(1+v_e²))`, and the far end's part `e^{−HΔv} Im S(z_e) = ∫_{v_e}^∞ G` is at
/// most `e^{−HΔv}/(H(1+v_e²))`: so what is left out is at most `δ/(1 − δ)` of `Im Q_0`, under
/// half a rounding. Only where the real part is not needed (`Re Q_0` has no such bound), and
/// not in the paper's algorithm, which evaluates both ends. The shader takes the same `δ`.
pub const FAR_END_NEGLIGIBLE: f64 = 0.25;

/// The weight `e^{−HΔv}` at or below which route 3 leaves out the far end
/// ([`FAR_END_NEGLIGIBLE`]; 0 where it never does).
#[inline]
fn far_end_negligible<T: Real, E: ExpIntegral<T>>(with_re: bool, ei: &E) -> T {
    if with_re || !ei.stabilised() {
        T::zero()
    } else {
        T::epsilon() * T::lit(FAR_END_NEGLIGIBLE)
    }
}

/// `N_1 = ∫ e^{−H(v−v_s)} dv/(v(1+v²))` far from the foot (`y ≤ 1/4`), where `T_1 − Re C`
/// would cancel (both ≈ `∫ e^{…}/v`, their difference `≈ y²` times smaller): the convergent
/// expansion `1/(v(1+v²)) = Σ_j (−1)^j v^{−3−2j}` (ratio `y² ≤ 1/16`) gives
/// `N_1 = Σ_j (−1)^j T_{3+2j}`, with `T_n` as in [`r_second`].
fn n1_series<T: Real>(half: &Half<T>) -> T {
    // Terms until (1/16)^J < ε: 13 in f64, 6 in f32.
    const ORDERS: usize = 3 + 2 * 13;
    let terms = if T::epsilon() < T::lit(1e-10) { 13 } else { 6 };
    let top = 3 + 2 * (terms - 1);
    let mut t = [T::zero(); ORDERS + 1];
    t_moments(half, &mut t[..top]);
    let mut sum = T::zero();
    for j in (0..terms).rev() {
        let tn = t[3 + 2 * j - 1];
        sum = if j % 2 == 0 { sum + tn } else { sum - tn };
    }
    sum
}

/// `out[n−1] = T_n = ∫_{v_s}^{v_e} e^{−H(v−v_s)} v^{−n} dv = y_hi^{n−1} s_n(Hv_s) − e^{−HΔv} y_lo^{n−1} s_n(Hv_e)`
/// for `n ≥ 2` (`out[0]` is left 0; `T_1` needs the log-regularised forms).
fn t_moments<T: Real>(half: &Half<T>, out: &mut [T]) {
    const MAX: usize = 32;
    let n = out.len().min(MAX);
    let big_h = half.big_h;
    let mut s_s = [T::zero(); MAX];
    en_scaled(big_h * half.y_hi.recip(), &mut s_s[..n]);
    // (where H/y_lo overflows the far end's e^{−HΔv} is 0)
    let far_end = half.y_lo > T::zero() && (big_h / half.y_lo).is_finite();
    let mut s_e = [T::zero(); MAX];
    let decay = if far_end { (-big_h * half.dv).exp() } else { T::zero() };
    if far_end {
        en_scaled(big_h * half.y_lo.recip(), &mut s_e[..n]);
    }
    let (mut p_hi, mut p_lo) = (half.y_hi, half.y_lo);
    for order in 2..=n {
        let head = p_hi * s_s[order - 1];
        let tail = if far_end { p_lo * s_e[order - 1] * decay } else { T::zero() };
        out[order - 1] = head - tail;
        p_hi = p_hi * half.y_hi;
        p_lo = p_lo * half.y_lo;
    }
}

/// `R_j = ∫ e^{−H(y − y_lo)} (y − y_c)^j dy` on the first half, from
/// `φ_i(x) = ∫₀¹ e^{−xt} t^i dt`: with `τ = y − y_lo ∈ [0, Δ]` and `s = τ − Δ/2`,
/// `R_j = Σ_i C(j,i) Δ^{i+1} φ_i(HΔ) (−Δ/2)^{j−i}`.
fn r_first<T: Real>(half: &Half<T>, r: &mut [T]) {
    const MAX: usize = MAX_TERMS;
    let n = r.len().min(MAX);
    let delta = half.dy;
    let mut phi = [T::zero(); MAX];
    phi_moments(half.big_h * delta, &mut phi[..n]);
    // tau_i = Δ^{i+1} φ_i
    let mut tau = [T::zero(); MAX];
    let mut p = delta;
    for i in 0..n {
        tau[i] = p * phi[i];
        p = p * delta;
    }
    binomial_shift(&tau[..n], -delta * T::lit(0.5), r);
}

/// `out_j = Σ_i C(j,i) x_i c^{j−i}`: moments about a point shifted by `c`.
fn binomial_shift<T: Real>(x: &[T], c: T, out: &mut [T]) {
    for j in 0..out.len() {
        let mut sum = T::zero();
        let mut binom = T::one();
        // i from j down to 0: term C(j,i) x_i c^{j−i}
        let mut cp = T::one();
        for i in (0..=j).rev() {
            sum = sum + binom * x[i] * cp;
            // next: C(j, i−1) = C(j,i)·i/(j−i+1)
            binom = binom * T::from(i).unwrap() / T::from(j - i + 1).unwrap();
            cp = cp * c;
        }
        out[j] = sum;
    }
}

/// `φ_i(x) = ∫₀¹ e^{−xt} tⁱ dt`, `i = 0..out.len()`, `x ≥ 0`. Small `x`: the all-positive
/// series `e^{−x} Σ_j x^j / ((i+1)…(i+j+1))` (A&S 6.5.29 for `γ(i+1, x)`); large `x`: the
/// upward recurrence `φ_i = (i φ_{i−1} − e^{−x})/x`, stable there.
fn phi_moments<T: Real>(x: T, out: &mut [T]) {
    let switch = T::lit(2.0 * T::E1_SERIES_ELLIPSE.0);
    let ex = (-x).exp();
    if x <= switch {
        for (i, o) in out.iter_mut().enumerate() {
            let mut term = T::one() / T::from(i + 1).unwrap();
            let mut sum = term;
            for j in 1..=T::E1_SERIES_TERMS {
                term = term * x / T::from(i + j + 1).unwrap();
                sum = sum + term;
            }
            *o = ex * sum;
        }
    } else {
        let mut prev = -(-x).exp_m1() / x;
        for (i, o) in out.iter_mut().enumerate() {
            if i > 0 {
                prev = (T::from(i).unwrap() * prev - ex) / x;
            }
            *o = prev;
        }
    }
}

/// `R_j = ∫ e^{−H(1/y − v_s)} (y − y_c)^j dy` on the second half: `y^i dy = v^{−i−2} dv`, so
/// `R_j = Σ_i C(j,i) (−y_c)^{j−i} T_{i+2}` with
/// `T_n = y_hi^{n−1} s_n(H v_s) − e^{−HΔv} y_lo^{n−1} s_n(H v_e)`, `s_n = e^x E_n(x)`.
fn r_second<T: Real>(half: &Half<T>, yc: T, r: &mut [T]) {
    const MAX: usize = MAX_TERMS + 2;
    let n = r.len().min(MAX - 2);
    let mut t = [T::zero(); MAX];
    t_moments(half, &mut t[..n + 2]);
    // R_j = Σ_i C(j,i) (−y_c)^{j−i} T_{i+2}
    binomial_shift(&t[1..n + 1], -yc, r);
}
