//! The error type of this crate.

use ocean_core::{Num, WaveError};

/// Why an `ocean-wtb` object could not be built or used. Nothing is modified when an error is
/// returned.
#[derive(Clone, Copy, Debug, PartialEq, thiserror::Error)]
#[non_exhaustive]
pub enum WtbError {
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
    /// The water grid has fewer than `min` ([`crate::grid::MIN_SIDE`]) or more than `max`
    /// ([`crate::grid::MAX_SIDE`]) points along a side.
    #[error("water grid size {nx} x {nz} is outside {min} x {min} ..= {max} x {max}")]
    GridSize {
        /// Columns (along x).
        nx: usize,
        /// Rows (along z).
        nz: usize,
        /// Fewest points a side may have.
        min: usize,
        /// Most points a side may have.
        max: usize,
    },
    /// The water grid's spacing differs along x and z (a box's internal frame has the grid's
    /// spacing along both of its axes, paper §2).
    #[error("water grid spacing must be square, got {} along x and {} along z", Num(*.x), Num(*.z))]
    NonSquareSpacing {
        /// Spacing along x (m).
        x: f64,
        /// Spacing along z (m).
        z: f64,
    },
    /// A direction vector is zero (or its length overflows).
    #[error("`{0}` must be a non-zero direction")]
    ZeroDirection(&'static str),
    /// A height map does not hold one value per water grid point.
    #[error("terrain holds {got} heights, the water grid has {expected} points")]
    TerrainSize {
        /// Water grid points.
        expected: usize,
        /// Heights given.
        got: usize,
    },
    /// A terrain height is NaN or infinite.
    #[error("terrain height {index} is not finite")]
    TerrainNotFinite {
        /// Row-major index of the offending height.
        index: usize,
    },
    /// A box frame was traversed over a water grid of another spacing.
    #[error("box frame spacing {} m differs from the water grid spacing {} m", Num(*.frame), Num(*.grid))]
    SpacingMismatch {
        /// The frame's spacing (m).
        frame: f64,
        /// The grid's spacing (m).
        grid: f64,
    },
    /// The summed steepness Σ kᵢAᵢ of a box's wave trains exceeds the limit, so the surface could
    /// fold over itself.
    #[error("summed steepness of the wave trains is {}, above the limit {}", Num(*.total), Num(*.max))]
    TooSteep {
        /// Σ kᵢAᵢ.
        total: f64,
        /// The limit.
        max: f64,
    },
    /// A wave train description was refused by `ocean-core`.
    #[error("wave train {index}: {source}")]
    Wave {
        /// Index of the train.
        index: usize,
        /// The reason.
        source: WaveError,
    },
    /// No box has this id in the scene (removed, or from another scene).
    #[error("no box with id {0} in this scene")]
    UnknownBox(u32),
    /// An evaluation was refused by `ocean-core` (output buffers of the wrong length, ...).
    #[error("evaluation: {0}")]
    Eval(ocean_core::EvalError),
    /// A box that can never touch the water grid, even at its full fetch.
    #[error("the box lies entirely outside the water grid")]
    OutsideGrid,
}
