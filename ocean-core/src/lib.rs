//! # ocean-core
//!
//! `no_std` math shared by every ocean crate: trochoid (Gerstner) waves with analytic
//! derivatives ([`trochoid`], [`wave`], [`dispersion`]), cameras and projections for every depth
//! convention ([`camera`]), frustum planes with conservative sphere, AABB and OBB tests
//! ([`frustum`]), and a deterministic random number generator ([`rng`], PCG32).
//!
//! ## Example
//!
//! ```
//! use glam::{DVec2, Vec3};
//! use ocean_core::{Depth, Grid, WaveDesc, WaveSet};
//!
//! let waves = WaveSet::from_descs(&[WaveDesc {
//!     amplitude: 0.5,                  // m
//!     wavelength: 20.0,                // m
//!     direction: DVec2::new(1.0, 0.3), // (x, z), any length
//!     phase: 0.0,                      // rad
//!     depth: Depth::Finite(8.0),       // ω from Eq. 4; Depth::Deep for Eq. 5
//! }])?;
//! let grid = Grid::centred(DVec2::new(1.0e5, 0.0), 0.5, 256); // 256 × 256 points, 0.5 m apart
//! let mut pos = vec![Vec3::ZERO; 256 * 256];
//! let mut nrm = vec![Vec3::ZERO; 256 * 256];
//! waves.evaluate_grid_par(&grid, 1.0e6, &mut pos, &mut nrm)?; // relative to grid.origin
//! let buoy = waves.sample(DVec2::new(1.0e5, 3.0), 1.0e6)?; // displacement and normal
//! assert!(buoy.displacement.y.abs() <= 0.5 && (nrm[0].length() - 1.0).abs() < 1e-6);
//! # Ok::<(), Box<dyn std::error::Error>>(())
//! ```
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
//! platform, for every SIMD width and thread count: the instruction set chosen at run time
//! ([`Isa`]) changes only the speed. Enable the `libm` feature to make the `f64`
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

#[cfg(target_arch = "x86_64")]
mod avx2;
#[cfg(target_arch = "x86_64")]
mod avx512;
pub mod camera;
pub mod dispersion;
mod error;
pub mod frustum;
pub mod gpu_params;
pub mod grid;
pub mod isa;
pub mod kernel;
pub mod layers;
pub mod math;
pub mod modulation;
pub mod num;
pub mod parallel;
pub mod phase;
pub mod point_sums;
pub mod rng;
pub mod sincos;
pub mod timed;
pub mod trochoid;
#[cfg(target_arch = "x86_64")]
mod vector;
pub mod wave;
pub mod world;

pub use camera::{
    Camera, CameraError, DepthConvention, DepthDirection, DepthRange, Far, Projection,
};
pub use dispersion::{Depth, GRAVITY};
pub use error::{EvalError, WaveError};
pub use frustum::{Containment, Frustum, FrustumError};
pub use grid::Grid;
pub use isa::Isa;
pub use kernel::WaveCoeffs;
pub use layers::{
    GridRect, Layer, LayersEvaluator, evaluate_layers, evaluate_layers_isa, evaluate_layers_region,
};
#[cfg(feature = "std")]
pub use layers::{evaluate_layers_par, evaluate_layers_region_par};
pub use modulation::Modulation;
pub use num::Num;
pub use point_sums::{PointSums, SampleF64};
pub use rng::Pcg32;
pub use timed::{LaneSums, TimedWaves};
pub use trochoid::{Sample, WaveSet};
pub use wave::{Wave, WaveDesc};

pub use glam;
