//! # ocean-core
//!
//! `no_std` math shared by every ocean crate: trochoid (Gerstner) waves with analytic
//! derivatives, the dispersion relation, cameras and projections, frustum planes with AABB and
//! OBB tests, and a deterministic random number generator.
//!
//! ## Conventions
//!
//! - Units: metres, seconds, radians. Gravity is [`GRAVITY`] = 9.81 m/s² (the value of the
//!   lighting paper, Bruneton et al. 2010 §3.1).
//! - Axes: right-handed, **y up**; the sea at rest is the plane y = 0, so rest positions and wave
//!   vectors live in the (x, z) plane. The papers write (x, y) for the horizontal plane and z for
//!   height; that conversion happens once, in this crate's wave code.
//! - Matrices: glam's column-major `Mat4`, column vectors (`clip = proj * view * world`); the same
//!   memory layout as GLM.
//! - Time is `f64` seconds at every public boundary; each wave's phase is reduced modulo 2π in
//!   `f64` before it reaches `f32`, so waves at t = 10⁶ s, 100 km from the origin, do not jitter.
//!
//! ## Determinism
//!
//! The `f32` wave kernels use only IEEE-754 additions, multiplications, square roots and
//! divisions, in a fixed order, with no fused multiply-add and no platform `sin`/`cos`
//! ([`sincos`] is this crate's own). The same inputs therefore give bit-identical outputs on every
//! platform, for every SIMD width and thread count. Enable the `libm` feature to make the `f64`
//! set-up functions (`tanh`, `sqrt` in the dispersion relation, the `f64` reference path) pure Rust
//! too.
//!
//! ## Features
//!
//! - `std` (default): multi-threaded batch evaluation (rayon), run-time SIMD dispatch,
//!   `std::error::Error` on the error types.
//! - `libm`: pure-Rust `f64` transcendental functions; required when `std` is off.
#![no_std]
#![forbid(unsafe_code)]
#![warn(missing_docs)]

extern crate alloc;

#[cfg(feature = "std")]
extern crate std;

#[cfg(not(any(feature = "std", feature = "libm")))]
compile_error!("ocean-core needs the `std` or the `libm` feature for its f64 math functions");

pub mod camera;
pub mod dispersion;
mod error;
pub mod frustum;
pub mod grid;
pub mod kernel;
pub mod math;
pub mod phase;
pub mod rng;
pub mod sincos;
pub mod trochoid;
pub mod wave;

pub use dispersion::{Depth, GRAVITY};
pub use error::{EvalError, WaveError};
pub use grid::Grid;
pub use kernel::WaveCoeffs;
pub use trochoid::{Sample, SampleF64, WaveSet};
pub use wave::{Wave, WaveDesc};

pub use glam;
