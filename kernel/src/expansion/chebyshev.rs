//! Interpolation at Chebyshev nodes, converted to local monomial coefficients.

use crate::real::Real;

/// Coefficients `a_k` with `Σ a_k s^k` interpolating `f(y_c + s)` at the `N` Chebyshev nodes
/// `s_j = r cos(π(2j+1)/(2N))` of `[−r, r]`.
///
/// Steps: node values → Chebyshev series `Σ c_k T_k(s/r)` (discrete orthogonality) →
/// monomials in `ξ = s/r` → divide by `r^k`. The conversion amplifies rounding noise by at
/// most the ℓ1 norm of the monomial coefficients of `T_k`, `((1+√2)^k + (1−√2)^k)/2`; monomial
/// coefficients below `4N·ε·(1+√2)^N·Σ|c_k|` carry no information and are set to 0, so that
/// dividing by `r^k` on a tiny sub-interval cannot blow noise up.
pub fn chebyshev_coefficients<T: Real, const N: usize>(f: impl Fn(T) -> T, y_c: T, r: T) -> [T; N] {
    let mut a = [T::zero(); N];
    if N == 0 {
        return a;
    }
    let nf = T::from(N).unwrap();
    // Nodes ξ_j = cos((2j+1)θ), θ = π/(2N), by the three-term recurrence of cosines.
    let theta = T::PI() / (nf + nf);
    let mut xi = [T::zero(); N];
    let c2 = (theta + theta).cos();
    let mut prev = theta.cos(); // cos(−θ) = cos θ
    let mut cur = prev; // cos(θ)
    for x in xi.iter_mut() {
        *x = cur;
        let next = (c2 + c2) * cur - prev;
        prev = cur;
        cur = next;
    }
    let mut values = [T::zero(); N];
    for j in 0..N {
        values[j] = f(y_c + r * xi[j]);
    }
    let mut cheb = [T::zero(); N];
    chebyshev_series(&xi, &values, &mut cheb);
    // Σ c_k T_k(ξ) → monomials in ξ, with T_k as coefficient arrays.
    let mut t_km1 = [T::zero(); N];
    let mut t_k = [T::zero(); N];
    t_km1[0] = T::one(); // T_0
    if N > 1 {
        t_k[1] = T::one(); // T_1
    }
    let mut hat = [T::zero(); N];
    hat[0] = cheb[0];
    for k in 1..N {
        for i in 0..N {
            hat[i] = hat[i] + cheb[k] * t_k[i];
        }
        // T_{k+1} = 2ξ T_k − T_{k−1}
        let mut t_next = [T::zero(); N];
        for i in 0..N {
            let shifted = if i > 0 { t_k[i - 1] } else { T::zero() };
            t_next[i] = shifted + shifted - t_km1[i];
        }
        t_km1 = t_k;
        t_k = t_next;
    }
    let mut scale_sum = T::zero();
    for c in cheb.iter() {
        scale_sum = scale_sum + c.abs();
    }
    let noise = T::lit(4.0) * nf * T::epsilon() * T::lit(core::f64::consts::SQRT_2 + 1.0).powi(N as i32) * scale_sum;
    let mut rk = T::one();
    for k in 0..N {
        let ak = hat[k] / rk;
        a[k] = if k > 0 && (hat[k].abs() <= noise || !ak.is_finite()) { T::zero() } else { ak };
        rk = rk * r;
    }
    a
}

/// The Chebyshev series `Σ_{k<M} c_k T_k(ξ)` through `values` at the `M = c.len()` points of
/// the first kind of `[−1, 1]`, `nodes` (`ξ_j = cos((2j+1)π/(2M))`, formed by the caller), into
/// `c`: `c_k = (2/M) Σ_j f_j T_k(ξ_j)` (discrete orthogonality), `c_0` halved.
#[inline]
pub(crate) fn chebyshev_series<T: Real>(nodes: &[T], values: &[T], c: &mut [T]) {
    let n = c.len();
    for (&xi, &value) in nodes.iter().zip(values).take(n) {
        let (mut t_prev, mut t_cur) = (T::one(), xi);
        for (k, ck) in c.iter_mut().enumerate() {
            let tk = if k == 0 { T::one() } else { t_cur };
            *ck = *ck + value * tk;
            if k >= 1 {
                let t_next = (xi + xi) * t_cur - t_prev;
                t_prev = t_cur;
                t_cur = t_next;
            }
        }
    }
    if n == 0 {
        return;
    }
    let two_over_n = (T::one() + T::one()) / T::from(n).unwrap();
    for ck in c.iter_mut() {
        *ck = *ck * two_over_n;
    }
    c[0] = c[0] * T::lit(0.5);
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Interpolation at `N` nodes is exact for a polynomial of degree below `N`: the cubic
    /// `2 − y + 3y³` about `y_c = 0.5` is `1.875 + 1.25 s + 4.5 s² + 3 s³` (expanded by hand).
    #[test]
    fn reproduces_a_cubic() {
        let a: [f64; 6] = chebyshev_coefficients(|y: f64| 2.0 - y + 3.0 * y * y * y, 0.5, 0.25);
        let want = [1.875, 1.25, 4.5, 3.0, 0.0, 0.0];
        for (k, (&got, &w)) in a.iter().zip(&want).enumerate() {
            assert!((got - w).abs() <= 1e-12, "a_{k} = {got}, want {w}");
        }
    }
}
