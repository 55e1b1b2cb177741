//! The complete elliptic integral of the second kind by the arithmetic–geometric mean (DLMF
//! 19.8.1, 19.8.6): the closed form of a Lambertian surface's air-light without extinction
//! ([`crate::surface::lambert_vacuum_form`], docs/DESIGN.md §11).

use crate::real::Real;

/// `E(m) = ∫_0^{π/2} √(1 − m sin²θ) dθ` for `m ∈ [0, 1]`, given `k' = √(1 − m)` as well (formed by
/// the caller without cancellation, e.g. `|cos α|` for `m = sin²α`): with `a_0 = 1`, `b_0 = k'`,
/// `c_0² = m`, `a_{n+1} = (a_n + b_n)/2`, `b_{n+1} = √(a_n b_n)`, `c_{n+1} = (a_n − b_n)/2`,
/// `K = π/(2 a_∞)` and `E = K (1 − Σ_{n≥0} 2^{n−1} c_n²)` (DLMF 19.8.1, 19.8.6); `E(1) = 1` where
/// `k' = 0`. The means meet quadratically once `c_n ≪ a_n` (from `k' = 0.1`, 5 steps in f64),
/// after about `log₂ ln(4/k')` more for a small `k'`. The difference `1 − Σ ≈ 1/K` loses
/// `log₁₀ K` digits as `m → 1`: a few `K·ε` relative (`K ≈ ln(4/k')`: at most 710 in f64 and 90 in
/// f32 for a normal `k'`; the unit test holds it to `4Kε` against mpmath).
pub fn elliptic_e<T: Real>(m: T, k_prime: T) -> T {
    if !(k_prime > T::zero()) {
        return T::one();
    }
    let half = T::lit(0.5);
    let (mut a, mut b) = (T::one(), k_prime);
    let (mut sum, mut power) = (m * half, half);
    // (from the least normal k' the means meet within 4ε in 15 steps: 64 bound the loop)
    for _ in 0..64 {
        let c = (a - b) * half;
        power = power + power;
        sum = sum + power * c * c;
        let next = (a + b) * half;
        b = (a * b).sqrt();
        a = next;
        if !(c > T::epsilon() * a) {
            break;
        }
    }
    T::FRAC_PI_2() / a * (T::one() - sum)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Against mpmath 1.3.0's `ellipe(m)` (30 digits) from `m = 0` (`π/2`) to `1 − 1e-12` and
    /// `m = 1` (`1`), A&S table 17.5's `E(1/2) = 1.35064 38810 47676` among them: within `4Kε`
    /// of the value, `K = K(m)` (mpmath's `ellipk`, to two digits; the bound of the docs: the
    /// sum's rounding, a few ε absolutely, times `K` in `E = K(1 − Σ)`), in f64 and in f32 (`m`
    /// and `k'` rounded to f32 first).
    #[test]
    fn elliptic_e_against_mpmath() {
        // (m, E(m), K(m))
        let table = [
            (0.0, 1.570_796_326_794_896_6, 1.6),
            (0.1, 1.530_757_636_897_763_2, 1.7),
            (0.5, 1.350_643_881_047_675_5, 1.9),
            (0.9, 1.104_774_732_704_073_3, 2.6),
            (0.99, 1.015_993_545_025_223_9, 3.7),
            (1.0 - 1e-12, 1.000_000_000_007_350_9, 15.3),
            (1.0, 1.0, 1.0),
        ];
        for (m, want, k) in table {
            let k_prime = (1.0f64 - m).sqrt();
            let got = elliptic_e(m, k_prime);
            assert!((got - want).abs() <= 4.0 * k * f64::EPSILON * want, "E({m}) = {got} vs {want}");
            let got32 = elliptic_e(m as f32, k_prime as f32) as f64;
            assert!((got32 - want).abs() <= 4.0 * k * f32::EPSILON as f64 * want, "f32 E({m}) = {got32} vs {want}");
        }
    }
}
