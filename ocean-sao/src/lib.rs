//! # ocean-sao
//!
//! The CPU reference of Scalable Ambient Obscurance (McGuire, Mara & Luebke, HPG 2012): every
//! pass of the paper, in the arithmetic its GPU twin follows, with the analytic scenes and the
//! brute-force obscurance its accuracy is measured against.
//!
//! Conventions are ocean-core's: metres, right-handed, y up, the camera looks down −z (the
//! paper's camera-space z is this view-space z: negative in front), column-major matrices.
//! Images are row-major with row 0 at the top.
//!
//! - [`reconstruct`]: z from depth for every depth convention (Eq. 2, one constant set for
//!   forward / reversed, `[0, 1]` / `[−1, 1]`, finite / infinite far, orthographic), positions
//!   (Eq. 3), face normals from 2×2 quad differences (Eq. 4) with the optional rejection at
//!   depth edges, the screen radius (Eq. 5).
//! - [`hierarchy`]: the z MIP levels and the five filters of Table 1.
//! - [`spiral`]: the spiral (Eq. 6–7), the hash rotation (Eq. 8) reduced modulo 2π, the MIP
//!   level (Eq. 9).
//! - [`sample`]: the sample pass (Eq. 1 or the appendix's falloff, Eq. 10) and the 2×2 quad
//!   bilateral.
//! - [`pack`]: A and z in one RGBA8 texel (§2.3).
//! - [`blur`]: the separable bilateral reconstruction (§2.4).
//! - [`pipeline`]: [`Sao`], the passes in order.
//! - [`analytic`], [`reference`](mod@reference): analytic scenes, an exact rasteriser and brute-force obscurance.
//!
//! ```
//! use ocean_core::{DepthConvention, Far, Projection};
//! use ocean_sao::analytic::{AnalyticView, DepthFormat};
//! use ocean_sao::{DepthSource, Sao, SaoParams, Viewport};
//!
//! let view = AnalyticView::box_in_room();
//! let projection = Projection::Perspective {
//!     fov_y: 1.0,        // rad
//!     aspect: 80.0 / 64.0, // of the whole input, guard band included
//!     near: 0.1,
//!     far: Far::Infinite,
//! };
//! let camera = view.camera(projection, DepthConvention::ZERO_TO_ONE_REVERSED)?;
//! let (w, h, guard) = (80, 64, 8); // the depth buffer is 8 px larger on every side
//! let raster = view.scene.rasterise(&camera, w, h, DepthSource::Window, DepthFormat::F32)?;
//!
//! let sao = Sao::from_camera(&camera, DepthSource::Window, Viewport::new(w, h, guard)?, SaoParams::default())?;
//! let mut ao = vec![0.0f32; sao.viewport().output_len()]; // 64 × 48
//! sao.run(&raster.depth, &mut ao)?;
//! assert!(ao.iter().all(|a| (0.0..=1.0).contains(a)));
//! assert!(ao.iter().any(|&a| a < 0.8)); // the box darkens the floor where it stands
//! # Ok::<(), ocean_sao::SaoError>(())
//! ```
//!
//! ## Determinism
//!
//! Every pass computes each output row independently from read-only inputs, in `f32` with a
//! fixed order of operations and no platform `sin`/`cos` (ocean-core's [`ocean_core::sincos`]),
//! so the output is bit-identical for any number of threads.
//!
//! ## Features
//!
//! - `std` (default): rows in parallel (rayon), `std::error::Error`.
//! - `libm`: ocean-core's pure-Rust `f64` math; required without `std`.
#![no_std]
#![forbid(unsafe_code)]
#![warn(missing_docs)]

extern crate alloc;
#[cfg(feature = "std")]
extern crate std;

pub mod analytic;
pub mod blur;
pub mod error;
pub mod gpu_params;
pub mod hierarchy;
pub mod pack;
pub mod params;
pub mod pipeline;
pub mod reconstruct;
pub mod reference;
pub mod sample;
pub mod spiral;
pub mod viewport;

pub use error::SaoError;
pub use gpu_params::SaoUniforms;
pub use hierarchy::{MipFilter, ZHierarchy};
pub use params::{BlurParams, BlurWeight, Estimator, SaoParams};
pub use pipeline::{Sao, Stages};
pub use reconstruct::{
    DepthSource, NormalEstimate, NormalRejection, ProjectionInfo, SKY_Z, ZConstants,
};
pub use viewport::{MAX_SIDE, Viewport};

pub(crate) use ocean_core::parallel::for_rows;
