//! # ocean-brdf
//!
//! Ocean lighting from geometry to BRDF (Bruneton, Neyret & Holzschuch, "Real-time Realistic
//! Ocean Lighting using Seamless Transitions from Geometry to BRDF", 2010): a spectrum of
//! trochoids whose detail moves, wave by wave and with the viewing distance, from the geometry
//! into the normals and then into the slope variance of a BRDF.
//!
//! Conventions are ocean-core's: metres, seconds, radians, right-handed with y up in world
//! space, the sea at rest on y = 0. The paper works in z-up frames; the BRDF functions take
//! vectors in the surface's tangent frame (x along the wind, y across it, z along the normal),
//! and conversion happens once, where a world-space normal and wind meet the BRDF.
//!
//! Every transcendental function comes from `libm`, so results are the same on every
//! platform.
#![no_std]
#![forbid(unsafe_code)]
#![warn(missing_docs)]

extern crate alloc;
#[cfg(feature = "std")]
extern crate std;

pub mod error;
pub mod fresnel;
pub mod ross;

pub use error::BrdfError;
