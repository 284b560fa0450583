//! # ocean-relief
//!
//! Relief mapping by relaxed cone stepping (Policarpo & Oliveira, *GPU Gems 3*, ch. 18): cone
//! maps that are **provably valid** for the bilinear surface the tracer sees, a fast exact
//! generator with a brute-force oracle, quantised storage that rounds down, valid mip chains, and
//! CPU tracers written as the `f32` arithmetic a WGSL port copies, measured against an exact
//! ground truth.
//!
//! - [`map`]: the height map (depth convention, texel centres, [`Edge`] wrap / clamp, the input
//!   checks) and [`sample`], the bilinear fetch.
//! - [`bound`]: what a relaxed cone must guarantee (Lemma 1, the "peak rule") and the per-cell
//!   bound with its proof, sharpened over parts of cells (`refine.rs`, [`ConeParams::parts`]);
//!   [`cone`]: [`ConeMap`] (plain ratio, clearance, near cap) by branch-and-bound over a
//!   min-depth pyramid, or by brute force; [`book`]: Listing 18-2 as printed, the oracle of the
//!   book's semantics.
//! - [`check`]: the exact validity check (no ray through a cone's axis crosses the surface twice
//!   inside it); [`mip`]: the 4×4-window mip rule and its proof; [`lod`]: mip levels that each
//!   carry their own box-filtered surface and its cones ([`ReliefMips`], [`QuadReliefMips`]) and
//!   the level a fragment reads; [`storage`]: 8-bit, 8-bit square-root, `f16` and `f32`
//!   encodings, all rounding down.
//! - [`quad`]: quad-directional cone maps (§18.1, Fig. 18-8b), relaxed or conservative: one cone
//!   per closed quadrant of the ray's direction, by the same bound and generators, and the
//!   tracer that picks the ray's layer.
//! - [`relief`]: the texture the tracers read and the normal map; [`trace`]: linear + binary,
//!   cone step mapping, relaxed cone stepping + binary; [`shadow`]: self-shadowing;
//!   [`occlusion`]: the hit's depth for the z-buffer; [`truth`]: the exact first hit.
//! - [`widest`]: the widest valid cone of every texel, sampled, and how much of it a map uses.
//! - [`accuracy`]: the accuracy table; [`maps`]: procedural test maps and the family of twelve
//!   kinds the generator is measured on.
//!
//! ```
//! use glam::{Vec2, Vec3};
//! use ocean_relief::maps::{to_map, value_noise};
//! use ocean_relief::trace::BinarySearch;
//! use ocean_relief::{ConeMap, ConeParams, Edge, Method, Ray, ReliefTexture};
//!
//! let map = to_map(64, &value_noise(64, 4, 4, 1), Edge::Wrap)?; // heights in [0, 1]
//! let cones = ConeMap::generate(&map, ConeParams::relaxed(1.0))?;
//! let texture = ReliefTexture::new(&map, &cones)?;
//! // A view 60° from the normal, relief 0.1 texture widths deep.
//! let (s, c) = 60f32.to_radians().sin_cos();
//! let ray = Ray::from_view(Vec2::new(0.3, 0.7), Vec3::new(s, 0.0, -c), 0.1)?;
//! let method = Method::Relaxed { cone: 15, binary: 6, search: BinarySearch::Shared };
//! let hit = method.trace(&texture, &ray)?;
//! let exact = ocean_relief::truth::first_hit(&map, &ray)?;
//! assert!((f64::from(hit.pos.z) - exact.z).abs() < 0.05);
//! # Ok::<(), ocean_relief::ReliefError>(())
//! ```
//!
//! ## Departures from the book, and why
//!
//! - **What "valid" means.** Listing 18-1 bounds each cone with rays cast from the top of its
//!   axis through texel centres. Listing 18-3 reuses the cone for rays that pass the axis at any
//!   depth and slope, and its bilinear fetch reads cones between texel centres. This crate's cones
//!   are valid for exactly that use ([`bound`]): the book's cones are not, and the tests show
//!   rays that go through features with them.
//! - **Two extra channels** (clearance `D`, near cap `E`, [`cone`]) let a ray close to the surface
//!   take longer steps, still provably valid; the book's one-channel map is channel 0.
//! - **Binary search over the last step** (or a shared fetch budget), not over the whole range.
//! - **Mip chains** take a 4×4 window, not the 2×2 group ([`mip`]).
//!
//! ## Determinism
//!
//! The generator computes every cell independently from read-only data and takes exact minima,
//! so cone maps are bit-identical for any thread count; the tracers are plain `f32` code with a
//! fixed order of operations.
//!
//! ## Features
//!
//! - `std` (default): rows in parallel (rayon), `std::error::Error`.
//! - `libm`: ocean-core's pure-Rust math; required without `std`. This crate calls `libm`
//!   directly for `sqrt`, `floor` and `ceil`, which are exact either way.
#![cfg_attr(not(feature = "std"), no_std)]
#![forbid(unsafe_code)]
#![warn(missing_docs)]

extern crate alloc;

pub mod accuracy;
pub(crate) mod arc;
pub mod book;
pub mod bound;
pub(crate) mod brute;
pub mod check;
pub mod cone;
pub mod error;
pub mod gpu_params;
pub mod line;
pub mod lod;
pub mod map;
pub mod maps;
pub mod mip;
pub mod occlusion;
pub mod progress;
pub mod quad;
pub mod quadrant;
pub(crate) mod refine;
pub mod relief;
mod round;
pub mod sample;
pub(crate) mod search;
pub mod shadow;
pub mod storage;
pub mod trace;
pub mod truth;
pub mod widest;

pub use bound::ConeKind;
pub use cone::{ConeMap, ConeParams, DEFAULT_PARTS, MAX_BRUTE_SIDE, MAX_PARTS, MAX_RATIO_LIMIT};
pub use error::ReliefError;
pub(crate) use error::check_range;
pub use lod::{QuadReliefMips, ReliefMips};
pub use map::{Edge, HeightMap, HeightRange, MAX_SIDE};
pub use quad::{QuadConeMap, QuadReliefTexture, Quadrant};
pub use relief::ReliefTexture;
pub use trace::{BinarySearch, Hit, MAX_TEXCOORD, Method, Ray};

pub(crate) use ocean_core::parallel::for_rows;
