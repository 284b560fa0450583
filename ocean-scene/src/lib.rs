//! # ocean-scene
//!
//! The pieces of a composed scene that are not one paper's technique, written once for every
//! program that draws them: `ocean render` builds its scene from them, and so can an engine.
//!
//! - [`rock`]: low-poly rocks from noise ([`RockShape`] → [`RockMesh`]), closed, outward
//!   triangles, the same bits on every platform; relief-map their faces with
//!   `ocean_gpu::ReliefScene::on_polygon`.
//!
//! Conventions are the workspace's: metres and radians, right-handed, `y` up, the sea at rest
//! is `y = 0`.
#![forbid(unsafe_code)]
#![warn(missing_docs)]

pub mod rock;

pub use rock::{RockMesh, RockShape};

/// What a scene piece refuses.
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
pub enum SceneError {
    /// A parameter outside its documented range.
    #[error("{what}: {reason}")]
    Invalid {
        /// The parameter.
        what: &'static str,
        /// Why, with the value.
        reason: String,
    },
}

impl SceneError {
    pub(crate) fn invalid(what: &'static str, reason: impl Into<String>) -> Self {
        Self::Invalid {
            what,
            reason: reason.into(),
        }
    }
}
