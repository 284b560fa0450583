//! Scalable Ambient Obscurance (crate `ocean-sao`): what the caller's depth buffer holds. The
//! camera that produced it is an `OceanCamera` (`camera.rs`); SAO works in view space and reads
//! only its projection.

use ocean_sao::DepthSource;

use crate::boundary::{CEnum, check_enum};
use crate::status::Error;

/// What a depth buffer holds (`ocean_sao_create`'s `depth_source`, a `uint32_t` parameter).
#[repr(u32)]
#[derive(Clone, Copy, Debug, PartialEq, Eq, bytemuck::NoUninit, bytemuck::CheckedBitPattern)]
pub enum OceanSaoDepth {
    /// Window depth, the value a depth texture stores (`glDepthRange(0, 1)`), always in
    /// [0, 1]: `(ndc + 1)/2` under `OCEAN_DEPTH_CONVENTION_NEG_ONE_TO_ONE`, NDC depth itself
    /// under the [0, 1] conventions. This is what `glReadPixels(..., GL_DEPTH_COMPONENT,
    /// GL_FLOAT, ...)` and a sampled depth texture give.
    Window = 0,
    /// NDC depth (clip z / clip w), in the convention's range: [-1, 1] under
    /// `OCEAN_DEPTH_CONVENTION_NEG_ONE_TO_ONE`, [0, 1] otherwise (where it equals window depth).
    Ndc = 1,
}

impl CEnum for OceanSaoDepth {
    const REFUSAL: &'static str =
        "is neither OCEAN_SAO_DEPTH_WINDOW (0) nor OCEAN_SAO_DEPTH_NDC (1)";
}

/// Reads `depth_source`.
pub(crate) fn source_from(v: u32) -> Result<DepthSource, Error> {
    Ok(match check_enum::<OceanSaoDepth>("depth_source", v)? {
        OceanSaoDepth::Window => DepthSource::Window,
        OceanSaoDepth::Ndc => DepthSource::Ndc,
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::status::OceanStatus;

    #[test]
    fn depth_sources_are_checked() {
        assert_eq!(source_from(0).unwrap(), DepthSource::Window);
        assert_eq!(source_from(1).unwrap(), DepthSource::Ndc);
        let e = source_from(2).unwrap_err();
        assert_eq!(e.status, OceanStatus::InvalidArgument);
        assert_eq!(
            e.message,
            "depth_source = 2 is neither OCEAN_SAO_DEPTH_WINDOW (0) nor OCEAN_SAO_DEPTH_NDC (1)"
        );
    }
}
