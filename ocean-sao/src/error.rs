//! The error type of this crate.

use ocean_core::CameraError;
use ocean_core::Num;

/// Why an SAO pass could not run. Nothing is written to an output buffer when an error is
/// returned, and no input can make a pass panic or read out of bounds.
#[derive(Clone, Copy, Debug, PartialEq, thiserror::Error)]
#[non_exhaustive]
pub enum SaoError {
    /// The projection is invalid (ocean-core's checks).
    #[error("invalid projection: {0}")]
    Camera(#[from] CameraError),
    /// The projection is valid in `f64` but one of the `f32` constants the passes use (Eq. 2's
    /// triple, Eq. 3's scale and offset, Eq. 5's `S'`) is zero, infinite or NaN after rounding,
    /// or the reconstructed near or far plane is not finite: the passes could not tell depths
    /// apart.
    #[error("the projection is degenerate in f32: `{0}`")]
    DegenerateProjection(&'static str),
    /// An image side is outside `2 ..= MAX_SIDE` ([`crate::MAX_SIDE`]).
    #[error("image size {width} x {height} is outside 2 x 2 ..= {max} x {max}", max = crate::MAX_SIDE)]
    ImageSize {
        /// Width in pixels.
        width: usize,
        /// Height in pixels.
        height: usize,
    },
    /// The guard band leaves no output pixel: `2·guard` must be below both input sides.
    #[error("guard band of {guard} px leaves no output in a {width} x {height} input")]
    GuardBand {
        /// Guard band width in pixels (on every side).
        guard: usize,
        /// Input width.
        width: usize,
        /// Input height.
        height: usize,
    },
    /// A buffer does not hold one value per pixel.
    #[error("buffer `{name}` holds {got} values, expected {expected}")]
    BufferSize {
        /// Which buffer.
        name: &'static str,
        /// Values expected.
        expected: usize,
        /// Values given.
        got: usize,
    },
    /// A depth value is NaN or infinite.
    #[error("depth at ({x}, {y}) is not finite")]
    DepthNotFinite {
        /// Column of the first offending pixel (row-major scan).
        x: usize,
        /// Row of the first offending pixel.
        y: usize,
    },
    /// A depth value lies outside the range of the depth convention.
    #[error("depth {} at ({x}, {y}) is outside [{}, {}]", Num(*.value), Num(*.min), Num(*.max))]
    DepthOutOfRange {
        /// Column of the first offending pixel (row-major scan).
        x: usize,
        /// Row of the first offending pixel.
        y: usize,
        /// The value.
        value: f32,
        /// Lowest accepted depth.
        min: f32,
        /// Highest accepted depth.
        max: f32,
    },
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
    /// The test rasteriser cannot store depth this way.
    #[error("unsupported depth format: {0}")]
    UnsupportedFormat(&'static str),
    /// The blur's tap count must be odd (a centre tap and the same number on each side).
    #[error("blur tap count must be odd, got {0}")]
    EvenTaps(u32),
}

/// Checks that `value` is finite and within `[min, max]`, compared in the value's own type: an
/// `f32` parameter is compared with `f32` bounds, so a C caller's float literal of a documented
/// bound (`1e-4f`, whose nearest float lies below 1e-4) is accepted.
pub(crate) fn check_range<T: Copy + PartialOrd + Into<f64>>(
    name: &'static str,
    value: T,
    min: T,
    max: T,
) -> Result<(), SaoError> {
    if !value.into().is_finite() {
        return Err(SaoError::NotFinite(name));
    }
    if value < min || value > max {
        return Err(SaoError::OutOfRange {
            name,
            value: value.into(),
            min: min.into(),
            max: max.into(),
        });
    }
    Ok(())
}
