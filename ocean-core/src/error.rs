use crate::num::Num;

/// Why a wave or wave set could not be built.
#[derive(Clone, Copy, Debug, PartialEq, thiserror::Error)]
#[non_exhaustive]
pub enum WaveError {
    /// Amplitude must be finite and ≥ 0 (metres).
    #[error("wave amplitude must be finite and >= 0 m, got {}", Num(*.0))]
    Amplitude(f64),
    /// Wavelength must be finite and > 0 (metres).
    #[error("wavelength must be finite and > 0 m, got {}", Num(*.0))]
    Wavelength(f64),
    /// Wavenumber must be finite and > 0 (rad/m).
    #[error("wavenumber must be finite and > 0 rad/m, got {}", Num(*.0))]
    Wavenumber(f64),
    /// Angular frequency must be finite and > 0 (rad/s).
    #[error("angular frequency must be finite and > 0 rad/s, got {}", Num(*.0))]
    AngularFrequency(f64),
    /// Direction must be a finite, non-zero vector.
    #[error("wave direction must be a finite non-zero (x, z) vector, got ({}, {})", Num(*.0), Num(*.1))]
    Direction(f64, f64),
    /// Phase must be finite (radians).
    #[error("wave phase must be finite, got {}", Num(*.0))]
    Phase(f64),
    /// Depth must be finite and > 0 (metres), or deep water.
    #[error("water depth must be finite and > 0 m (or deep water), got {}", Num(*.0))]
    Depth(f64),
    /// A wave set needs at least one wave.
    #[error("a wave set needs at least one wave")]
    Empty,
    /// Steepness k·A above 1 makes the trochoid loop over itself.
    #[error("wave steepness k*A = {} exceeds 1: the trochoid would loop (clamp the amplitude to 1/k)", Num(*.0))]
    TooSteep(f64),
}

/// Why a batch evaluation was refused. Nothing is written to the outputs in that case.
#[derive(Clone, Copy, Debug, PartialEq, thiserror::Error)]
#[non_exhaustive]
pub enum EvalError {
    /// Time must be finite (seconds).
    #[error("time must be finite, got {}", Num(*.0))]
    Time(f64),
    /// A rest position or origin coordinate is NaN or infinite.
    #[error("rest position {index} is not finite")]
    Position {
        /// Index of the offending position (0 for an origin).
        index: usize,
    },
    /// There are no points to evaluate.
    #[error("no points to evaluate")]
    Empty,
    /// Output slices must hold exactly as many elements as there are rest points.
    #[error("output buffers hold {positions} positions and {normals} normals, expected {expected}")]
    OutputLength {
        /// Points to evaluate.
        expected: usize,
        /// Length of the position output.
        positions: usize,
        /// Length of the normal output.
        normals: usize,
    },
    /// The grid description is invalid.
    #[error("invalid grid: {0}")]
    Grid(&'static str),
    /// The instruction set asked for ([`crate::evaluate_layers_isa`]) is not available on this
    /// CPU.
    #[error("instruction set {0:?} is not available on this CPU")]
    Isa(crate::Isa),
}
