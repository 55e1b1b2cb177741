//! The float abstraction: one generic implementation serves `f32` and `f64`.
//!
//! [`Real`] adds to `num_traits::Float` the few things the kernel needs per precision:
//! the glam vector type of that precision, and the tuning constants of the exponential
//! integral's region selection (docs/DESIGN.md §3), which differ between f32 and f64 because the
//! iteration budgets do (16 loop iterations per f32 evaluation, 40 per f64).

use core::fmt::{Debug, Display};
use num_traits::{Float, FloatConst};

/// A floating-point type the kernel runs in: `f32` or `f64`.
///
/// The associated constants are the *only* precision-dependent part of the algorithm; each is
/// derived in `special/e1.rs` (region boundaries and term counts, measured against mpmath).
pub trait Real: Float + FloatConst + Debug + Display + Default + Send + Sync + 'static {
    /// The glam vector of this precision (`glam::Vec3` or `glam::DVec3`).
    type Vec3: Copy + Debug + PartialEq;

    /// Semi-axes `(a, b)` of the ellipse `(Re z/a)² + (Im z/b)² < 1` inside which `E1(z)`
    /// is evaluated by its power series; outside, by the continued fraction.
    const E1_SERIES_ELLIPSE: (f64, f64);
    /// Number of power-series terms used at the ellipse's edge: the most any series in the
    /// kernel sums (fixed, no early exit).
    const E1_SERIES_TERMS: usize;
    /// Power-series terms by band of `|z|` inside the ellipse (as the fraction's depths): the
    /// first entry whose bound exceeds `|z|` gives the count; the last entry, unbounded, is
    /// [`Real::E1_SERIES_TERMS`].
    const E1_SERIES_BANDS: &'static [(f64, usize)];
    /// Terms of [`ein_divided_difference`](crate::special::ein_divided_difference) by band of
    /// `max(|a|, |b|)` (as the series bands; the last entry serves up to the routine's domain
    /// bound, 1).
    const E1_DD_BANDS: &'static [(f64, usize)];
    /// Continued-fraction depth by band of `|z|`: the first entry whose bound exceeds `|z|`
    /// gives the depth; the last entry applies to all larger `|z|`.
    const E1_CF_DEPTH: &'static [(f64, usize)];
    /// Continued-fraction depth by band of `|z|` (the bounds of [`Real::E1_CF_DEPTH`]) within
    /// 45° of the real axis, `|Im z| ≤ Re z`, where the fraction converges faster than near
    /// the imaginary axis (the isotropic path's far ends, `z = H(v − i)` with `v ≥ 1`).
    const E1_CF_DEPTH_NEAR_REAL: &'static [(f64, usize)];
    /// Depth of the real `e^x E_n(x)` fraction ([`en_scaled`](crate::special::en_scaled)) by
    /// band of `x` (the bounds of [`Real::E1_CF_DEPTH`]), for every pivot order `n ≤ min(⌈x⌉,
    /// 32)`: on the real axis it converges faster than the complex `E1` fraction near the
    /// imaginary axis, but for large `n` more slowly than for `n = 1`.
    const EN_CF_DEPTH: &'static [(f64, usize)];
    /// Gauss–Legendre nodes on `[-1, 1]` (positive half) and weights for short sub-intervals.
    const GAUSS_NODES: &'static [(f64, f64)];
    /// The default error-controlled path ([`crate::panels`]): Gauss–Legendre nodes per panel,
    /// tolerance of the per-panel estimate, relative floor (the accuracy target's `τ`) and the
    /// most panels per piece.
    const PANEL_NODES: usize;
    /// See [`Real::PANEL_NODES`].
    const PANEL_TOLERANCE: f64;
    /// See [`Real::PANEL_NODES`].
    const PANEL_FLOOR: f64;
    /// See [`Real::PANEL_NODES`].
    const MAX_PANELS: usize;


    /// Veltkamp's splitting constant `2^⌈p/2⌉ + 1` (`p`: significand bits) of the exact
    /// products in [`crate::geometry::Canonical::new_accurate`].
    const SPLITTER: f64;

    /// Magnitudes (and reciprocals) within which the exact products of
    /// [`crate::geometry::Canonical::new_accurate`] stay normal: 2^450 in f64, 2^30 in f32
    /// (products of two, and the `2^⌈p/2⌉` split, stay within the exponent range).
    const EXACT_RANGE: f64;

    /// Converts an `f64` constant to this precision (rounding to nearest).
    fn lit(x: f64) -> Self;
    /// Converts to `f64` (exact for both precisions).
    fn to_f64_exact(self) -> f64;
    /// The components of a glam vector of this precision.
    fn vec3_to_array(v: Self::Vec3) -> [Self; 3];
    /// A glam vector of this precision from components.
    fn vec3_from_array(a: [Self; 3]) -> Self::Vec3;
    /// `2^k` for an integral `k` within the normal exponents (`−126 ≤ k ≤ 127` in f32,
    /// `−1022 ≤ k ≤ 1023` in f64), from its bits.
    fn exp2_integral(k: Self) -> Self;
}

/// The conversions of [`Real`], alike for both precisions.
macro_rules! conversions {
    ($t:ty) => {
        #[inline(always)]
        fn lit(x: f64) -> Self {
            x as $t
        }
        #[inline(always)]
        fn to_f64_exact(self) -> f64 {
            self as f64
        }
        #[inline(always)]
        fn vec3_to_array(v: Self::Vec3) -> [Self; 3] {
            v.to_array()
        }
        #[inline(always)]
        fn vec3_from_array(a: [Self; 3]) -> Self::Vec3 {
            Self::Vec3::from_array(a)
        }
    };
}

impl Real for f64 {
    type Vec3 = glam::DVec3;
    const SPLITTER: f64 = 134_217_729.0; // 2^27 + 1
    const EXACT_RANGE: f64 = 2.9073548971824276e135; // 2^450
    // Target 1e-10 of max(|exact|, 1e-10·scale); the estimate is kept 10× below it (it is itself
    // conservative: the largest error measured over tests/reference/classes.jsonl is 3.3e-13).
    const PANEL_NODES: usize = 16;
    const PANEL_TOLERANCE: f64 = 1e-11;
    const PANEL_FLOOR: f64 = 1e-10;
    const MAX_PANELS: usize = 64;
    const E1_SERIES_ELLIPSE: (f64, f64) = (2.5, 4.0);
    // E1 tuning: tests/reference/gen_e1_tuning.py derives the term count and depths from the
    // region bounds (truncation ≤ 8 unit roundoffs, measured against mpmath).
    const E1_SERIES_TERMS: usize = 29;
    const E1_SERIES_BANDS: &'static [(f64, usize)] = &[(0.125, 9), (0.5, 13), (1.0, 16), (2.0, 22), (f64::INFINITY, 29)];
    const E1_DD_BANDS: &'static [(f64, usize)] = &[(0.125, 10), (0.5, 14), (f64::INFINITY, 17)];
    const E1_CF_DEPTH: &'static [(f64, usize)] = &[
        (5.0, 39),
        (6.0, 31),
        (8.0, 26),
        (11.0, 20),
        (15.0, 15),
        (25.0, 11),
        (50.0, 7),
        (100.0, 5),
        (300.0, 4),
        (f64::INFINITY, 2),
    ];
    const E1_CF_DEPTH_NEAR_REAL: &'static [(f64, usize)] = &[
        (5.0, 36),
        (6.0, 22),
        (8.0, 19),
        (11.0, 15),
        (15.0, 12),
        (25.0, 9),
        (50.0, 7),
        (100.0, 5),
        (300.0, 3),
        (f64::INFINITY, 2),
    ];
    const EN_CF_DEPTH: &'static [(f64, usize)] = &[
        (5.0, 37),
        (6.0, 21),
        (8.0, 19),
        (11.0, 15),
        (15.0, 13),
        (25.0, 11),
        (50.0, 8),
        (100.0, 6),
        (300.0, 4),
        (f64::INFINITY, 3),
    ];
    // 8-point Gauss–Legendre (Abramowitz & Stegun table 25.4).
    const GAUSS_NODES: &'static [(f64, f64)] = &[
        (0.183_434_642_495_649_8, 0.362_683_783_378_362_0),
        (0.525_532_409_916_329_0, 0.313_706_645_877_887_3),
        (0.796_666_477_413_626_7, 0.222_381_034_453_374_5),
        (0.960_289_856_497_536_2, 0.101_228_536_290_376_3),
    ];
    conversions!(f64);
    #[inline(always)]
    fn exp2_integral(k: Self) -> Self {
        f64::from_bits(((k as i64 + 1023) as u64) << 52)
    }
}

impl Real for f32 {
    type Vec3 = glam::Vec3;
    // Target 1e-4 of max(|exact|, 1e-4·scale); the estimate is kept 10× below it (its own
    // rounding noise is ~N·ε ≈ 1e-6). 8 nodes: at this tolerance 8, 10 and 12 nodes are within
    // 10 % of each other over tests/reference/classes.jsonl, while at tolerance 1e-3 the
    // estimate holds with 8 (largest error 5.8e-5) and not with 12 (3.1e-3); BENCHMARKS.md,
    // "node count".
    const SPLITTER: f64 = 4097.0; // 2^12 + 1
    const EXACT_RANGE: f64 = 1_073_741_824.0; // 2^30
    const PANEL_NODES: usize = 8;
    const PANEL_TOLERANCE: f64 = 1e-5;
    const PANEL_FLOOR: f64 = 1e-4;
    const MAX_PANELS: usize = 32;
    const E1_SERIES_ELLIPSE: (f64, f64) = (1.3, 2.1);
    // E1 tuning: derived by tests/reference/gen_e1_tuning.py, as for f64.
    const E1_SERIES_TERMS: usize = 13;
    const E1_SERIES_BANDS: &'static [(f64, usize)] = &[(0.25, 5), (0.5, 6), (1.0, 9), (f64::INFINITY, 13)];
    const E1_DD_BANDS: &'static [(f64, usize)] = &[(0.125, 5), (0.5, 7), (f64::INFINITY, 10)];
    const E1_CF_DEPTH: &'static [(f64, usize)] =
        &[(2.5, 14), (3.0, 11), (4.0, 9), (5.0, 7), (7.0, 6), (10.0, 4), (15.0, 3), (30.0, 2), (f64::INFINITY, 1)];
    // The main table: f32's fractions run in f64, where fewer levels save little, and the 8
    // unit roundoffs the sector's depths would allow (8, 7, 5, 5 levels from 2.5 to 7) instead
    // of the 0.3–0.5 the main depths leave there reach the fixed method's moment recurrence
    // (f32 against f64 at 4 terms, tests/tests/properties.rs: 1.08e-4 → 1.48e-4 of the scale).
    const E1_CF_DEPTH_NEAR_REAL: &'static [(f64, usize)] = Self::E1_CF_DEPTH;
    const EN_CF_DEPTH: &'static [(f64, usize)] =
        &[(2.5, 14), (3.0, 7), (4.0, 6), (5.0, 5), (7.0, 4), (10.0, 3), (15.0, 2), (30.0, 2), (f64::INFINITY, 1)];
    // 4-point Gauss–Legendre (Abramowitz & Stegun table 25.4).
    const GAUSS_NODES: &'static [(f64, f64)] = &[
        (0.339_981_043_584_856_3, 0.652_145_154_862_546_1),
        (0.861_136_311_594_052_6, 0.347_854_845_137_453_9),
    ];
    conversions!(f32);
    #[inline(always)]
    fn exp2_integral(k: Self) -> Self {
        f32::from_bits(((k as i32 + 127) as u32) << 23)
    }
}

/// `1/n` for the orders the kernel uses (`n < 32`: `N + 2` with `N ≤ 16` nodes or terms, or the
/// fixed method's `N ≤ 16` terms) from a table, a division beyond. The table's entry rounded
/// to `T` is half an ulp from `1/n`: a step of `E_n`'s upward recurrence
/// (special/en.rs) does not amplify it on its stable side, and the tail panel's rounding bound
/// (panels.rs) is a bound, not a value.
#[inline]
pub(crate) fn reciprocal<T: Real>(n: usize) -> T {
    const INVERSES: [f64; 32] = {
        let mut t = [0.0; 32];
        let mut n = 1;
        while n < 32 {
            t[n] = 1.0 / n as f64;
            n += 1;
        }
        t
    };
    match INVERSES.get(n) {
        Some(&inv) if n > 0 => T::lit(inv),
        _ => T::from(n).unwrap().recip(),
    }
}

/// `√(1 + x²)` without overflow for huge `|x|` (where it is `|x|` to the last bit:
/// `x² > 2^p` makes the `1` vanish). Cheaper than a general `hypot`.
#[inline]
pub(crate) fn hypot1<T: Real>(x: T) -> T {
    let a = x.abs();
    if a < T::lit(1e15) {
        (T::one() + a * a).sqrt()
    } else {
        a
    }
}

/// `⌊log₂ x⌋` of a positive finite `x` (subnormals included) from its bits, no library call:
/// `x = m·2^e` with the integer mantissa `m` of `integer_decode`, whose highest set bit is
/// `63 − m.leading_zeros()`.
#[inline]
pub(crate) fn log2_floor<T: Real>(x: T) -> i32 {
    let (mantissa, exponent, _) = x.integer_decode();
    i32::from(exponent) + 63 - mantissa.leading_zeros() as i32
}

/// The larger of `a` and `b` by one comparison, for running maxima over samples: `max`'s
/// handling of NaN (either operand) costs a few instructions per call, and here a NaN `b` is
/// skipped all the same (`b > a` is false), as `max` skips it.
#[inline(always)]
pub(crate) fn larger<T: Real>(a: T, b: T) -> T {
    if b > a {
        b
    } else {
        a
    }
}

/// `atan2(y, x)` for `y > 0` (the upper half-plane, `(0, π)`) by one [`atan_nonnegative`], of
/// `y/x` where `x > 0`, else `π/2 + atan(−x/y)`: one rounding more than that `atan` (the
/// quotient's, at most half an ulp relative, which `atan` does not amplify: `|x atan′(x)| ≤
/// atan x`), at the cost of one `atan` instead of `atan2`'s general reduction. The shaders'
/// `airlight_atan2_upper` computes the same angle with their own `atan`.
#[inline]
pub(crate) fn atan2_upper<T: Real>(y: T, x: T) -> T {
    if x > T::zero() {
        atan_nonnegative(y / x)
    } else {
        T::FRAC_PI_2() + atan_nonnegative(-x / y)
    }
}

/// `atan a` for `a ≥ 0` (`π/2` at `+∞`, NaN for NaN): the light angle's ends and width
/// (docs/DESIGN.md §4.2). In f32 without a library call: `t = min(a, 1/a)`, `atan t = t·A(t²)`
/// with `A` minimax in the relative error on `[0, 1]` (`scripts/gen_minimax.py`: 10 terms within
/// 4.8e-9, 0.04 ε), and `π/2 − atan(1/a)` above 1 with `π/2` split in two; measured within 1.7 ulp
/// of the exact value (2.0 with `π/2` rounded once; the unit test allows 2). In f64 the library's
/// `atan`: the same construction would need about 22 terms (the error falls by `3 + √8` a term,
/// the ellipse through `atan`'s branch points `z = −1`).
#[inline]
pub(crate) fn atan_nonnegative<T: Real>(a: T) -> T {
    // scripts/gen_minimax.py (relative 4.79e-9)
    const ATAN_F32: [f64; 10] = [
        1.0,
        -0.3333328366279602,
        0.1999826580286026,
        -0.142619326710701,
        0.1094203069806099,
        -0.0837731584906578,
        0.05755210295319557,
        -0.030804598703980446,
        0.010726944543421268,
        -0.0017539301188662648,
    ];
    if T::epsilon() < T::lit(1e-10) {
        return a.atan();
    }
    let above = a > T::one();
    let t = if above { a.recip() } else { a };
    let z = t * t;
    let p = t * ATAN_F32.iter().rev().fold(T::zero(), |p, &c| p * z + T::lit(c));
    if above {
        // π/2 as the precision's rounding plus the rest: its rounding alone is 0.7 ulp of a
        // result in [π/4, 1)
        let high = T::FRAC_PI_2();
        let low = T::lit(core::f64::consts::FRAC_PI_2 - core::f64::consts::FRAC_PI_2 as f32 as f64);
        (high - p) + low
    } else {
        p
    }
}

/// `(sin x, cos x)` for `|x| ≤ π/2` (a distance from a pole of the light angle, docs/DESIGN.md
/// §4.2; half a Phong lobe's angle, §11) by minimax polynomials in `z = x²` in Horner's form,
/// without the library's range reduction: `sin x = x·S(z)` (odd in `x`), `S` minimax in the
/// relative error (so `sin` keeps it as `x → 0`, where the light angle's `cos θ` needs it),
/// `cos x = C(z)`, `C` minimax in the absolute error (`cos x` near `π/2` is a distance from the
/// other pole: a few ε absolutely suffice). The
/// coefficients are `scripts/gen_minimax.py`'s (the Remez exchange at 40 digits, each rounded
/// once to the precision): 9 and 9 in f64, the rounded polynomials within 2.7e-17 relative and
/// 6.4e-17 absolute (≤ 0.3 ε); 5 and 6 in f32, within 1.5e-8 and 5.9e-9 (≤ 0.13 ε) — where
/// Taylor's series takes 11 and 7 terms for the same. The shaders' `airlight_cos_sin` is another
/// function: Taylor's series to `x¹⁷/17!` and `x¹⁶/16!` on `|x| ≤ 2.2` (it also serves the
/// complex exponential of the E1 series region).
#[inline]
pub(crate) fn sin_cos_quarter<T: Real>(x: T) -> (T, T) {
    // scripts/gen_minimax.py (f64: sin relative 2.67e-17, cos absolute 6.34e-17; f32: 1.51e-8, 5.83e-9)
    const SIN_F64: [f64; 9] = [
        1.0,
        -0.16666666666666666,
        0.008333333333333165,
        -0.0001984126984120184,
        2.7557319210152765e-06,
        -2.5052106798275132e-08,
        1.6058936490395973e-10,
        -7.642917807462814e-13,
        2.7204791012982254e-15,
    ];
    const COS_F64: [f64; 9] = [
        1.0,
        -0.4999999999999997,
        0.04166666666666389,
        -0.0013888888888773173,
        2.4801587277443952e-05,
        -2.7557316393535467e-07,
        2.0876561960136667e-09,
        -1.1462904899600055e-11,
        4.609007376607723e-14,
    ];
    const SIN_F32: [f64; 5] = [1.0, -0.16666656732559204, 0.008333025500178337, -0.00019807419448625296, 2.6019031338364584e-06];
    const COS_F32: [f64; 6] = [1.0, -0.5, 0.04166663810610771, -0.0013888361863791943, 2.476016197761055e-05, -2.605149518331018e-07];
    let horner = |coefficients: &[f64], z: T| coefficients.iter().rev().fold(T::zero(), |p, &c| p * z + T::lit(c));
    let z = x * x;
    if T::epsilon() < T::lit(1e-10) {
        (x * horner(&SIN_F64, z), horner(&COS_F64, z))
    } else {
        (x * horner(&SIN_F32, z), horner(&COS_F32, z))
    }
}

/// `e^x` for `x ≤ 0` (the light angle's sample weights `e^{−H(Y − Y0)}`, docs/DESIGN.md §4.2). In
/// f32 inline and without a branch, so that a rule's `N` weights vectorise where `N` calls of the
/// library's `expf` do not: `x = k ln 2 + r`, `k = round(x/ln 2)` (by adding and subtracting
/// `1.5/ε`), `r` by Cody and Waite's split of `ln 2` as Cephes's `expf` takes it (`0.693359375`,
/// 9 bits, so `k·C1` is exact for `|k| < 2^15`), then `e^r` on `|r| ≤ ln 2/2` by a minimax
/// polynomial in the relative error (`scripts/gen_minimax.py`: 7 terms within 1.7e-8, 0.15 ε)
/// times `2^k` from its bits; with Horner's roundings measured within 0.79 ε relative of the
/// library's (the unit test allows 4 ulp). In f64 the library's `exp`: the same construction
/// (fdlibm's split, 12 terms within 0.2 ε) took no more instructions but 13–18 % more time per
/// ray (f64 `street_aniso`, `thick`; the 12-deep Horner chain's latency, two lanes). `0` where
/// `e^x` is below the smallest normal (`x < −708` in f64, `< −87` in f32, where the library
/// gives subnormals), `1` at `x = 0`, NaN for NaN.
#[inline]
pub(crate) fn exp_nonpositive<T: Real>(x: T) -> T {
    if T::epsilon() < T::lit(1e-10) {
        return if x < T::lit(-708.0) { T::zero() } else { x.exp() };
    }
    exp_nonpositive_polynomial(x)
}

/// [`exp_nonpositive`]'s f32 construction in either precision: in f64 within 2e-8 relative of
/// the exact value (the polynomial's 1.73e-8; Cephes's split of `ln 2` is within 8e-14 of it,
/// which `|k| ≤ 1021` keeps below 6e-11 in `r`), for loose tolerances where a few f64 ulp buy
/// nothing (the surface's ray interpolant, from tolerance 5e-2; the unit test below). `0` below
/// the smallest normal, `1` at `x = 0`, NaN for NaN.
#[inline]
pub(crate) fn exp_nonpositive_polynomial<T: Real>(x: T) -> T {
    // scripts/gen_minimax.py (relative 1.73e-8)
    const EXP_F32: [f64; 7] = [1.0, 1.0, 0.49999991059303284, 0.16666419804096222, 0.04166822507977486, 0.008374815806746483, 0.0013836845755577087];
    // the smallest normal is 2^−1022 / 2^−126: k ≥ −1021 / −125 here
    let lowest = T::lit(if T::epsilon() < T::lit(1e-10) { -708.0 } else { -87.0 });
    let clamped = if x < lowest { lowest } else { x };
    let shift = T::lit(1.5) / T::epsilon();
    let k = (clamped * T::LOG2_E() + shift) - shift;
    // ln 2 = C1 − C2, Cephes expf's
    let r = (clamped - k * T::lit(0.693359375)) - k * T::lit(-2.12194440e-4);
    let e_r = EXP_F32.iter().rev().fold(T::zero(), |p, &c| p * r + T::lit(c));
    // formed before the test, so that the test is a select, not a branch
    let e_x = e_r * T::exp2_integral(k);
    if x < lowest {
        T::zero()
    } else {
        e_x
    }
}

/// `ln(1 + x)` for `x > −1`. In f32 `2 atanh(x/(2 + x))` by its series where `−1/2 ≤ x ≤ 1`
/// (`s = x/(2 + x)`, `s² ≤ 1/9`: 9 terms, the first left out `s¹⁸/19 < 1.2e-9` of the sum; the
/// shaders' `airlight_log1p`), `ln(1 + x)` elsewhere (`1 + x` exact for `−1 < x < −1/2`, and at
/// least `1/2` from 1 beyond 1): within 3 ulp of the exact value (the unit test), where glibc's
/// `log1pf` behind its error-handling wrapper took 2.1× the instructions (a Phong lobe's
/// `lobe_arcs`, two per node). In f64 the library's `ln_1p`.
#[inline]
pub(crate) fn ln_1p<T: Real>(x: T) -> T {
    if T::epsilon() < T::lit(1e-10) {
        return x.ln_1p();
    }
    if x > T::one() || x < T::lit(-0.5) {
        return (T::one() + x).ln();
    }
    let s = x / (T::lit(2.0) + x);
    let z = s * s;
    let sum = [17.0, 15.0, 13.0, 11.0, 9.0, 7.0, 5.0, 3.0].iter().fold(T::zero(), |acc, &k| (acc + T::lit(1.0 / k)) * z) + T::one();
    (s + s) * sum
}

/// `(sin x, cos x)` for `0 ≤ x ≤ π` by [`sin_cos_quarter`] of `x` or of `π − x` (rounded `π`:
/// `sin` within `ε·π` absolutely of the library's near `x = π`, relatively everywhere else).
#[inline]
pub(crate) fn sin_cos_half_turn<T: Real>(x: T) -> (T, T) {
    if x <= T::FRAC_PI_2() {
        sin_cos_quarter(x)
    } else {
        let (s, c) = sin_cos_quarter(T::PI() - x);
        (s, -c)
    }
}

/// `(sin x, cos x)` for `|x| ≤ 64` (an angle of a few turns: a surface's azimuths about the
/// light, docs/DESIGN.md §11) by [`sin_cos_quarter`] of `r = x − kπ/2`, `k` the whole number
/// nearest `2x/π`, and the quadrant `k mod 4`; `r` by Cody and Waite's three-part split of `π/2`
/// as Cephes's `sinf` takes it for `π/4`, doubled (`1.5703125`, 9 bits, so `k·P1` is exact for
/// `|k| < 2^15` in either precision; the three parts within 1e-24 of `π/2`): within 2 ε
/// absolutely of the library's (the unit test), where glibc's `sincos` took about 100
/// instructions a call (a beam's inner integral on a surface, at each of its nodes).
#[inline]
pub(crate) fn sin_cos_turns<T: Real>(x: T) -> (T, T) {
    // (k by adding and subtracting 1.5/ε, as `exp_nonpositive_polynomial` rounds)
    let shift = T::lit(1.5) / T::epsilon();
    let k = (x * T::FRAC_2_PI() + shift) - shift;
    let r = ((x - k * T::lit(1.5703125)) - k * T::lit(4.837512969970703125e-4)) - k * T::lit(7.549789954891882e-8);
    let (s, c) = sin_cos_quarter(r);
    match k.to_i32().unwrap_or(0) & 3 {
        0 => (s, c),
        1 => (c, -s),
        2 => (-s, -c),
        _ => (-c, s),
    }
}

#[cfg(test)]
mod tests {
    extern crate std;
    use super::{atan_nonnegative, exp_nonpositive, exp_nonpositive_polynomial, ln_1p, log2_floor, sin_cos_quarter, sin_cos_turns};

    /// [`sin_cos_turns`] against the library's `sin_cos` (glibc's, within an ulp) of the same
    /// argument at 20 001 points of `[−20, 20]` and at the quadrants' ends `kπ/4`: within 2 ε
    /// absolutely for both (`--nocapture` prints the largest: 1.0 ε in f64, 0.64 ε in f32).
    #[test]
    fn sin_cos_turns_matches_the_library() {
        fn check<T: super::Real>(eps: f64) {
            let mut worst = 0.0f64;
            let points = (0..=20000).map(|i| -20.0 + 40.0 * i as f64 / 20000.0).chain((-25..=25).map(|k| k as f64 * core::f64::consts::FRAC_PI_4));
            for x in points {
                let xt = T::lit(x);
                let (s, c) = sin_cos_turns(xt);
                let (rs, rc) = xt.to_f64().unwrap().sin_cos();
                worst = worst.max((s.to_f64().unwrap() - rs).abs().max((c.to_f64().unwrap() - rc).abs()) / eps);
            }
            std::println!("sin_cos_turns: {worst:.2} ε");
            assert!(worst <= 2.0, "{worst} ε");
        }
        check::<f64>(f64::EPSILON);
        check::<f32>(f32::EPSILON as f64);
    }

    /// f32 against the exact `ln(1 + x)` (f64's, within half an f32 ulp of it) at 40 001 points
    /// of `(−1, 2]` and the ends of the series' range: within 3 ulp of the value (the division's
    /// and Horner's roundings); 0 at 0, `−∞` at −1, NaN for NaN.
    #[test]
    fn ln_1p_matches_the_library() {
        let mut worst = (0.0f64, 0.0f32);
        for x in (1..=40000).map(|i| -1.0 + 3.0 * i as f32 / 40000.0).chain([-0.5, -0.4999999, -0.5000001, 1.0, 1.0000001, 1e-30, -1e-30, 1e-6]) {
            let exact = (x as f64).ln_1p();
            let ulp = f32::EPSILON as f64 * 2f64.powi((exact.abs() as f32).log2().floor() as i32);
            let e = (ln_1p(x) as f64 - exact).abs() / ulp;
            if e > worst.0 {
                worst = (e, x);
            }
        }
        assert!(worst.0 <= 3.0, "f32 ln_1p within {} ulp (at {})", worst.0, worst.1);
        assert!(ln_1p(0.0f32) == 0.0 && ln_1p(-1.0f32) == f32::NEG_INFINITY && ln_1p(f32::NAN).is_nan());
        assert!(ln_1p(0.3f64) == 0.3f64.ln_1p());
    }

    /// f32 against the exact `atan` (f64's, within half an f32 ulp of it) at 20 001 points of
    /// `[0, 1]`, their reciprocals and the ends `0`, `+∞`: within 2 ulp of the value (three
    /// roundings of Horner's form, the reciprocal's and the subtraction from `π/2`, on a
    /// polynomial within 0.04 ε); f64 is the library's.
    #[test]
    fn atan_nonnegative_matches_the_library() {
        let mut worst = 0.0f64;
        for i in 0..=20_000 {
            let t = i as f32 / 20_000.0;
            for a in [t, 1.0 / t] {
                let exact = (a as f64).atan();
                let got = atan_nonnegative(a) as f64;
                let ulp = f32::EPSILON as f64 * 2f64.powi((exact as f32).log2().floor() as i32);
                worst = worst.max((got - exact).abs() / ulp);
            }
        }
        assert!(worst <= 2.0, "f32 atan within {worst} ulp");
        assert_eq!(atan_nonnegative(0.0f32), 0.0);
        assert_eq!(atan_nonnegative(f32::INFINITY), core::f32::consts::FRAC_PI_2);
        assert!(atan_nonnegative(f32::NAN).is_nan());
        assert_eq!(atan_nonnegative(0.75f64), 0.75f64.atan());
    }

    /// `2^n ≤ x < 2^{n+1}` (powers of two formed exactly) for `n = log2_floor(x)` at every power
    /// of two and its two neighbours, normal and subnormal, in both precisions.
    #[test]
    fn log2_floor_brackets_its_argument() {
        let power = |n: i32| if n < -1000 { 2f64.powi(n + 100) * 2f64.powi(-100) } else { 2f64.powi(n) };
        for k in -1074..1024 {
            let x = power(k);
            for y in [x, x * (1.0 + f64::EPSILON), x * (1.0 - f64::EPSILON / 2.0)] {
                if y > 0.0 && y.is_finite() {
                    let n = log2_floor(y);
                    assert!(power(n) <= y && (n == 1023 || y < power(n + 1)), "f64 {y:e}: {n}");
                }
            }
        }
        for k in -149..128 {
            let x = 2f32.powi(k);
            for y in [x, x * (1.0 + f32::EPSILON), x * (1.0 - f32::EPSILON / 2.0)] {
                if y > 0.0 && y.is_finite() {
                    let n = log2_floor(y);
                    assert!(power(n) <= y as f64 && (y as f64) < power(n + 1), "f32 {y:e}: {n}");
                }
            }
        }
    }

    /// Against the library's `sin`/`cos` (within half an ulp) over `[0, π/2]`, the ends and 4096
    /// points between: `sin` within 4 ulp relative (it must stay relative as `x → 0`), `cos`
    /// within 4 ε absolute — four roundings of Horner's form plus the reference's half.
    #[test]
    fn sin_cos_quarter_matches_the_library() {
        fn check<T: super::Real>(eps: f64) {
            let mut worst = (0.0f64, 0.0f64);
            for i in 0..=4096 {
                let x = core::f64::consts::FRAC_PI_2 * i as f64 / 4096.0;
                let xt = T::lit(x);
                let (s, c) = sin_cos_quarter(xt);
                let exact = xt.to_f64().unwrap();
                let (rs, rc) = (exact.sin(), exact.cos());
                let rel = if rs == 0.0 { s.to_f64().unwrap().abs() } else { (s.to_f64().unwrap() - rs).abs() / rs };
                worst = (worst.0.max(rel / eps), worst.1.max((c.to_f64().unwrap() - rc).abs() / eps));
            }
            for x in [1e-30, 1e-8, 1e-3] {
                let (s, _) = sin_cos_quarter(T::lit(x));
                worst.0 = worst.0.max((s.to_f64().unwrap() - x.sin()).abs() / x.sin() / eps);
            }
            assert!(worst.0 <= 4.0 && worst.1 <= 4.0, "sin {} ulp, cos {} ε", worst.0, worst.1);
        }
        check::<f64>(f64::EPSILON);
        check::<f32>(f32::EPSILON as f64);
    }

    /// Against the library's `exp` (glibc's, within an ulp) on `[lowest, 0]`: 20 001 points and
    /// the ends `−(k + 1/2) ln 2` of every reduction interval, within 4 ulp relative (Horner's
    /// roundings, the reduction's and the library's; f32's own polynomial, f64 the library's
    /// itself); 1 at 0, 0 below `lowest` and at `−∞`, NaN for NaN.
    #[test]
    fn exp_nonpositive_matches_the_library() {
        fn check<T: super::Real>(eps: f64, lowest: f64) {
            let ends = (0..1100).map(|k| -(k as f64 + 0.5) * core::f64::consts::LN_2);
            let mut worst = 0.0f64;
            for x in (0..=20000).map(|i| lowest * i as f64 / 20000.0).chain(ends).filter(|&x| x >= lowest) {
                let xt = T::lit(x);
                let exact = xt.to_f64().unwrap().exp();
                worst = worst.max((exp_nonpositive(xt).to_f64().unwrap() - exact).abs() / exact / eps);
            }
            assert!(worst <= 4.0, "exp {worst} ulp");
            assert!(exp_nonpositive(T::zero()) == T::one() && exp_nonpositive(-T::zero()) == T::one());
            assert!(exp_nonpositive(T::lit(lowest * 1.001)) == T::zero() && exp_nonpositive(T::neg_infinity()) == T::zero());
            assert!(exp_nonpositive(T::nan()).is_nan());
        }
        check::<f64>(f64::EPSILON, -708.0);
        check::<f32>(f32::EPSILON as f64, -87.0);
        // the polynomial in f64: within 2e-8 relative, the same ends
        let mut worst = 0.0f64;
        for x in (0..=20000).map(|i| -708.0 * i as f64 / 20000.0).chain((0..1021).map(|k| -(k as f64 + 0.5) * core::f64::consts::LN_2)) {
            worst = worst.max((exp_nonpositive_polynomial(x) - x.exp()).abs() / x.exp());
        }
        assert!(worst <= 2e-8, "f64 polynomial within {worst:e}");
        assert!(exp_nonpositive_polynomial(0.0f64) == 1.0 && exp_nonpositive_polynomial(-709.0f64) == 0.0 && exp_nonpositive_polynomial(f64::NAN).is_nan());
    }
}
