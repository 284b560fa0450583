//! # ocean-scene
//!
//! The composed scene of `ocean render` as a library, written once for every program that draws
//! it: the command line, the C ABI (`ocean_scene_*` in `include/ocean.h`) and Rust engines.
//!
//! - **Description** ([`description`]): the scene as TOML (`scenes/default.toml` is the built-in
//!   scene and the format's reference), parsed strictly into [`SceneDescription`].
//! - **Pieces**: the island's terrain and the wave train boxes that reach its shore
//!   ([`island`], drawn by [`terrain`]); noise rocks ([`rock`] makes the mesh,
//!   [`rock_placement`] stands it on the shore); the pier ([`pier`]: relief-mapped [`blocks`]
//!   on plain [`solids`]).
//! - **The frame** ([`renderer`]): [`SceneRenderer`] builds every renderer once and draws a
//!   frame as a sequence of passes ([`frame`]: clear, sea, island, rocks and pier,
//!   [`obscurance`], compose, readback), each timed.
//!
//! Conventions are the workspace's: metres, seconds and radians, right-handed, `y` up, the sea
//! at rest is `y = 0`; cameras use WebGPU's forward depth range `[0, 1]`.
#![forbid(unsafe_code)]

pub mod blocks;
pub mod check;
pub mod cone_cache;
pub mod description;
pub mod face_light;
pub mod frame;
pub mod image_file;
pub mod island;
pub mod obscurance;
pub mod pier;
mod relief_draws;
pub mod renderer;
pub mod rock;
pub mod rock_placement;
pub mod solids;
mod targets;
pub mod terrain;

pub use description::{DEFAULT_SCENE, Preset, SceneDescription};
pub use renderer::{Backend, BuildTimes, COLOR_FORMAT, Frame, FrameTimes, SceneRenderer};
pub use rock::{RockMesh, RockShape};

/// What building or drawing a scene refuses.
#[derive(Debug, thiserror::Error)]
pub enum SceneError {
    /// A piece's parameter outside its documented range.
    #[error("{what}: {reason}")]
    Invalid {
        /// The parameter.
        what: &'static str,
        /// Why, with the value.
        reason: String,
    },
    /// A scene description that cannot be parsed or built: the message names the document, the
    /// line and the key, or the piece (island, box, rock) that failed and why.
    #[error("{0}")]
    Description(String),
    /// What the device cannot do for this scene (reading depth back on OpenGL).
    #[error("{0}")]
    Unsupported(String),
    /// The device failed.
    #[error(transparent)]
    Gpu(#[from] ocean_gpu::GpuError),
}

impl SceneError {
    pub(crate) fn invalid(what: &'static str, reason: impl Into<String>) -> Self {
        Self::Invalid {
            what,
            reason: reason.into(),
        }
    }
}

impl From<String> for SceneError {
    fn from(message: String) -> Self {
        Self::Description(message)
    }
}
