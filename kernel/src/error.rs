//! Typed errors of the checked API: which field of the input is wrong, and how.

use core::fmt;

/// What is wrong with a field.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum ErrorKind {
    /// NaN or infinite where a finite number is required.
    NonFinite,
    /// A direction or axis whose length is zero, or overflows (it is used to normalise).
    ZeroVector,
    /// A coefficient or intensity below zero.
    Negative,
    /// `t_min > t_max`.
    EmptyRange,
    /// An asymmetry parameter outside `(−1, 1)`.
    OutOfRange,
    /// A two-lobed power that is not an even non-negative integer.
    OddPower,
    /// An area light's cosine-lobe power outside `1 ..= 1024`.
    LobePower,
    /// A spot cone whose outer cosine is not below its inner cosine.
    InvertedCone,
    /// A cosine outside `[−1, 1]`.
    NotACosine,
    /// A weight outside `[0, 1]`.
    NotAFraction,
    /// A kind code (of a flat record, e.g. the C ABI's) that names no phase function or light
    /// distribution.
    UnknownKind,
}

/// An invalid input, naming the field by its path in the JSON scene record (docs/DESIGN.md §6),
/// e.g. `ray.dir` or `phase.g`.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct InputError {
    /// Path of the offending field.
    pub field: &'static str,
    /// What is wrong with it.
    pub kind: ErrorKind,
}

impl InputError {
    /// An error of `kind` at `field`.
    pub const fn new(field: &'static str, kind: ErrorKind) -> Self {
        InputError { field, kind }
    }
}

impl fmt::Display for InputError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let what = match self.kind {
            ErrorKind::NonFinite => "must be finite",
            ErrorKind::ZeroVector => "must have a non-zero length that does not overflow",
            ErrorKind::Negative => "must not be negative",
            ErrorKind::EmptyRange => "t_min must not exceed t_max",
            ErrorKind::OutOfRange => "must lie strictly between -1 and 1",
            ErrorKind::OddPower => "must be an even non-negative integer",
            ErrorKind::LobePower => "must be an integer from 1 to 1024",
            ErrorKind::InvertedCone => "cos_outer must be below cos_inner",
            ErrorKind::NotACosine => "must lie in [-1, 1]",
            ErrorKind::NotAFraction => "must lie in [0, 1]",
            ErrorKind::UnknownKind => "is not a known kind code",
        };
        write!(f, "{}: {}", self.field, what)
    }
}

impl core::error::Error for InputError {}

/// Checks that `x` is finite.
pub(crate) fn check_finite<T: crate::Real>(x: T, field: &'static str) -> Result<(), InputError> {
    if x.is_finite() {
        Ok(())
    } else {
        Err(InputError::new(field, ErrorKind::NonFinite))
    }
}

/// Checks that `x` is finite and not negative.
pub(crate) fn check_non_negative<T: crate::Real>(x: T, field: &'static str) -> Result<(), InputError> {
    check_finite(x, field)?;
    if x < T::zero() {
        Err(InputError::new(field, ErrorKind::Negative))
    } else {
        Ok(())
    }
}

/// Checks that every component is finite and, if `nonzero`, that the vector is not zero.
pub(crate) fn check_vector<T: crate::Real>(v: [T; 3], field: &'static str, nonzero: bool) -> Result<(), InputError> {
    for x in v {
        check_finite(x, field)?;
    }
    if nonzero && v.iter().all(|x| *x == T::zero()) {
        return Err(InputError::new(field, ErrorKind::ZeroVector));
    }
    // The squared length must not overflow (it is used to normalise).
    let len = crate::geometry::length(v);
    if nonzero && !(len.is_finite() && len > T::zero()) {
        return Err(InputError::new(field, ErrorKind::ZeroVector));
    }
    Ok(())
}

/// Checks an asymmetry parameter `|g| < 1`.
pub(crate) fn check_asymmetry<T: crate::Real>(g: T, field: &'static str) -> Result<(), InputError> {
    check_finite(g, field)?;
    if g.abs() < T::one() {
        Ok(())
    } else {
        Err(InputError::new(field, ErrorKind::OutOfRange))
    }
}
