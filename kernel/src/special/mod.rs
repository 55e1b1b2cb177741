//! Exponential integrals (docs/DESIGN.md §3, paper §4.1–4.2).
//!
//! * [`e1`], [`e1_scaled`], [`ei`]: complex `E1(z)`, `e^z E1(z)` and `Ei(z)` for `Re z ≥ 0`
//!   (for `Ei`: `Re z ≤ 0`), the production path: power series inside an ellipse around the
//!   origin, continued fraction outside, each with a fixed term count chosen by region
//!   ([`Real::E1_SERIES_TERMS`](crate::Real::E1_SERIES_TERMS),
//!   [`Real::E1_CF_DEPTH`](crate::Real::E1_CF_DEPTH)).
//! * [`ein_divided_difference`]: `(Ein(b) − Ein(a))/(b − a)` without cancellation, for
//!   differences of `E1` at nearby points with the logarithm split off.
//! * [`en_scaled`]: real `e^x E_n(x)`, `n = 1, 2, …`.
//! * [`paper`]: the paper's own power/asymptotic `Ei` (eq. 21–27, fig. 2), kept for comparison.

mod complex;
mod continued_fraction;
mod e1;
mod en;
pub mod paper;
mod series;

pub use complex::{cdiv, csqrt, C};
pub use continued_fraction::{e1_scaled_cf, PLAIN_FROM};
pub use e1::{e1, e1_scaled, ei, in_series_region};
pub use en::en_scaled;
pub use series::{ein, ein_divided_difference, ein_real, EIN_COEFFS};

/// Euler–Mascheroni constant γ (A&S 6.1.3).
pub const EULER_GAMMA: f64 = 0.577_215_664_901_532_860_606_512_090_082;
