//! The paper's own complex `Ei` (Pegoraro, Schott & Parker 2009, eq. 21–27 and fig. 2), kept
//! as a named variant so that the production path can be compared against it (accuracy in the
//! tests, speed in the benchmarks).
//!
//! It switches between the convergent power series (eq. 22–23) and the divergent asymptotic
//! series (eq. 25–26) by the rule of eq. 27, `1 ≤ ρ ∧ x − ⌊ρ⌋ < ln ε − 1`, which controls only
//! the *absolute* error `ε`, and iterates until a term drops below `ε` (at most
//! `max_iterations`).

use super::{C, EULER_GAMMA};
use crate::real::Real;

/// `Ei(x + iy)` by fig. 2 of the paper, off the real axis. Returns the value and the number
/// of loop iterations it took.
pub fn ei_paper<T: Real>(z: C<T>, precision: T, max_iterations: usize) -> (C<T>, usize) {
    let (x, y) = (z.re, z.im);
    let rho = x.hypot(y);
    let phi = y.atan2(x);
    let mut iterations = 0;
    if rho >= T::one() && x - rho.floor() < precision.ln() - T::one() {
        // asymptotic series, eq. 25–26
        let mut eix = T::zero();
        let mut eiy = if y > T::zero() { T::PI() } else { -T::PI() };
        let mut term = x.exp() / rho;
        let k_max = max_iterations.min(rho.floor().to_usize().unwrap_or(usize::MAX).saturating_add(1));
        for k in 1..=k_max {
            iterations = k;
            let kf = T::from(k).unwrap();
            let angle = y - kf * phi;
            eix = eix + term * angle.cos();
            eiy = eiy + term * angle.sin();
            if term < precision {
                break;
            }
            term = term * kf / rho;
        }
        (C::new(eix, eiy), iterations)
    } else {
        // power series, eq. 22–23
        let mut eix = T::lit(EULER_GAMMA) + rho.ln();
        let mut eiy = phi;
        let mut powfac = T::one();
        for k in 1..=max_iterations {
            iterations = k;
            let kf = T::from(k).unwrap();
            powfac = powfac * rho / kf;
            let term = powfac / kf;
            let angle = kf * phi;
            eix = eix + term * angle.cos();
            eiy = eiy + term * angle.sin();
            if term < precision {
                break;
            }
        }
        (C::new(eix, eiy), iterations)
    }
}

/// `e^z E1(z)` through [`ei_paper`]: `E1(z) = −Ei(−z) − iπ·sign(Im z)`.
pub fn e1_scaled_paper<T: Real>(z: C<T>, precision: T, max_iterations: usize) -> C<T> {
    let (ei, _) = ei_paper(-z, precision, max_iterations);
    let s = if z.im > T::zero() { T::PI() } else if z.im < T::zero() { -T::PI() } else { T::zero() };
    (-ei - C::new(T::zero(), s)) * z.exp()
}
