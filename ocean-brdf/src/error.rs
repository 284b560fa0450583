//! Errors of the lighting model's inputs, and the checks that raise them.

use glam::DVec3;
use ocean_core::Num;

/// Why an input of the lighting model was refused.
#[derive(Clone, Copy, Debug, PartialEq, thiserror::Error)]
#[non_exhaustive]
pub enum BrdfError {
    /// A parameter is NaN or infinite.
    #[error("{0} must be finite")]
    NotFinite(&'static str),
    /// A parameter lies outside its documented range.
    #[error("{name} = {} is outside [{}, {}]", Num(*.value), Num(*.min), Num(*.max))]
    OutOfRange {
        /// The parameter.
        name: &'static str,
        /// The value given.
        value: f64,
        /// Smallest accepted value.
        min: f64,
        /// Largest accepted value.
        max: f64,
    },
    /// A direction that must be a unit vector is not (length off by more than 1e-6), or is
    /// zero.
    #[error("{0} must be a unit vector")]
    NotUnit(&'static str),
}

/// `Ok(v)` if `v` is finite and within `[min, max]`.
pub(crate) fn check(name: &'static str, v: f64, min: f64, max: f64) -> Result<f64, BrdfError> {
    if !v.is_finite() {
        return Err(BrdfError::NotFinite(name));
    }
    if v < min || v > max {
        return Err(BrdfError::OutOfRange {
            name,
            value: v,
            min,
            max,
        });
    }
    Ok(v)
}

/// How far a direction's length may be from 1 (the crate's documented tolerance).
const UNIT_TOLERANCE: f64 = 1e-6;

/// Validates a direction: finite, unit within the crate's tolerance; returns it normalised.
pub(crate) fn check_direction(name: &'static str, d: DVec3) -> Result<DVec3, BrdfError> {
    if !d.is_finite() {
        return Err(BrdfError::NotFinite(name));
    }
    let len = libm::sqrt(d.dot(d));
    if (len - 1.0).abs() > UNIT_TOLERANCE {
        return Err(BrdfError::NotUnit(name));
    }
    Ok(d / len)
}
