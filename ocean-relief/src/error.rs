//! The error type of this crate.

use ocean_core::Num;

/// Why a height map, cone map or tracer could not be built or run. No input makes this crate
/// panic or read out of bounds; a function that returns an error has written nothing.
#[derive(Clone, Copy, Debug, PartialEq, thiserror::Error)]
#[non_exhaustive]
pub enum ReliefError {
    /// A side is zero, below the minimum or above the cap of the operation.
    #[error("map size {width} x {height} is outside {min} x {min} ..= {max} x {max}")]
    MapSize {
        /// Width in texels.
        width: usize,
        /// Height in texels.
        height: usize,
        /// Smallest side accepted.
        min: usize,
        /// Largest side accepted (see [`crate::MAX_SIDE`] and the brute-force caps).
        max: usize,
    },
    /// Maps must be square: cone ratios are measured in texture widths, which are only
    /// isotropic when both sides are equal.
    #[error("map is {width} x {height}; relief maps must be square")]
    NotSquare {
        /// Width in texels.
        width: usize,
        /// Height in texels.
        height: usize,
    },
    /// A buffer does not hold one value per texel.
    #[error("buffer `{name}` holds {got} values, expected {expected}")]
    BufferSize {
        /// Which buffer.
        name: &'static str,
        /// Values expected.
        expected: usize,
        /// Values given.
        got: usize,
    },
    /// A height is NaN or infinite.
    #[error("height at ({x}, {y}) is not finite")]
    HeightNotFinite {
        /// Column of the first offending texel (row-major scan).
        x: usize,
        /// Row of the first offending texel.
        y: usize,
    },
    /// A height lies outside `[0, 1]` and the map was built with [`crate::HeightRange::Refuse`].
    #[error("height {} at ({x}, {y}) is outside [0, 1]", Num(*.value))]
    HeightOutOfRange {
        /// Column of the first offending texel (row-major scan).
        x: usize,
        /// Row of the first offending texel.
        y: usize,
        /// The value.
        value: f32,
    },
    /// A setting that this implementation does not offer (the message names it and the one to
    /// use instead).
    #[error("unsupported: {0}")]
    Unsupported(&'static str),
    /// A parameter is NaN or infinite.
    #[error("`{0}` must be finite")]
    NotFinite(&'static str),
    /// A parameter lies outside its documented range `[min, max]`.
    #[error("`{name}` = {} is outside [{}, {}]", Num(*.value), Num(*.min), Num(*.max))]
    OutOfRange {
        /// The parameter.
        name: &'static str,
        /// Its value.
        value: f64,
        /// Smallest accepted value.
        min: f64,
        /// Largest accepted value.
        max: f64,
    },
    /// Two maps that must describe the same texels differ in size or edge mode.
    #[error("`{0}` does not match the height map (size or edge mode)")]
    Mismatch(&'static str),
    /// A mip chain needs a power-of-two side.
    #[error("a mip chain needs a power-of-two side, got {0}")]
    NotPowerOfTwo(usize),
    /// A ray must point into the relief: its depth component must be positive.
    #[error("ray direction must have a positive, finite depth component and finite xy")]
    RayDirection,
    /// A ray so close to the relief's plane (a depth component of 1e-45 beside a unit xy)
    /// that its run per unit depth overflows a float: it never reaches a depth.
    #[error("ray direction is too close to the plane: its run per unit depth overflows a float")]
    RayTooFlat,
    /// A [`crate::progress::Progress`] asked to stop; nothing was computed or written.
    #[error("cancelled by the progress callback")]
    Cancelled,
    /// The projection rejected the hit point (ocean-core's checks).
    #[error("projection: {0}")]
    Camera(#[from] ocean_core::CameraError),
}

/// Checks that `value` is finite and within `[min, max]`.
pub(crate) fn check_range(
    name: &'static str,
    value: f64,
    min: f64,
    max: f64,
) -> Result<(), ReliefError> {
    if !value.is_finite() {
        return Err(ReliefError::NotFinite(name));
    }
    if value < min || value > max {
        return Err(ReliefError::OutOfRange {
            name,
            value,
            min,
            max,
        });
    }
    Ok(())
}
