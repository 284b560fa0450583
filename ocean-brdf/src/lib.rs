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
//! - [`spectrum`]: Pierson–Moskowitz amplitudes (Eq. 1), Hasselmann spreading, seeded
//!   trochoids and the statistics a renderer needs.
//! - [`filter`]: the weights w_p, w_n and w_r that move each wave from the geometry to the
//!   normals to the BRDF (§3.2).
//! - [`variance`]: the slope variance of the unresolved waves (Eq. 4, Appendix A).
//! - [`ross`]: the Ross BRDF (§4) and the Sun's reflection (Eq. 15).
//! - [`fresnel`]: Schlick's Fresnel (Eq. 14) and the effective Fresnel of rough water
//!   (Eq. 24–26).
//! - [`fresnel_table`]: Eq. 24 tabulated over (θ_v, σ_v), more exact than Eq. 26's fit.
//! - [`sky`]: the Sun, a default sky (CIE clear sky) and the stereographic parameterisation
//!   (§5.2).
//! - [`sky_map`]: the mip-mapped sky map and the filtered lookup of Eq. 27.
//! - [`irradiance`]: the environment's irradiance on any normal (order-2 spherical
//!   harmonics), the ambient light of solids lit by the sea's sky.
//! - [`sea`]: Algorithm 5.1, the Sun's, the sky's and the refracted light for one pixel.
//! - [`surface`]: the filtered surface (Eq. 2–4) at a screen point and the footprints it is
//!   filtered on: the CPU twin of the GPU renderer's geometry.
//! - [`local`]: local waves (§6): wave trains modulated over the sea (a wave train box's μ),
//!   filtered per train and added to the open sea's position, normal and variance.
//! - [`tonemap`]: exposure and sRGB encoding.
//! - `validation` (feature `std`): the paper's Fig. 10 comparison against a detailed-geometry,
//!   perfect-mirror reference.
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
pub mod filter;
pub mod fresnel;
pub mod fresnel_table;
pub mod gpu_params;
pub mod irradiance;
pub mod local;
mod quadrature;
pub mod ross;
pub mod sea;
pub mod sky;
pub mod sky_map;
pub mod spectrum;
pub mod surface;
pub mod tonemap;
#[cfg(feature = "std")]
pub mod validation;
pub mod variance;

pub use error::BrdfError;
pub use filter::Filter;
pub use irradiance::Irradiance;
pub use local::{LocalPoint, LocalWaves};
pub use sea::{Lighting, SeaLight, SeaParams};
pub use sky::{MAX_RADIOMETRIC, Sky, SkyParams};
pub use sky_map::SkyMap;
pub use spectrum::{Spectrum, SpectrumParams};
pub use surface::{FilteredSurface, PixelSurface};
pub use variance::{SlopeVariance, VarianceTable};
