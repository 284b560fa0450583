//! Scalable Ambient Obscurance (crate `ocean-sao`): what the caller's depth buffer holds. The
//! camera that produced it is an `OceanCamera` (`camera.rs`); SAO works in view space and reads
//! only its projection.

use ocean_sao::DepthSource;

use crate::status::{Error, OceanStatus};

/// `ocean_sao_create`'s `depth_source`: the depth buffer holds window depth, the value a depth
/// texture stores (`glDepthRange(0, 1)`), always in [0, 1]: `(ndc + 1)/2` under
/// `OCEAN_DEPTH_CONVENTION_NEG_ONE_TO_ONE`, NDC depth itself under the [0, 1] conventions.
/// This is what `glReadPixels(..., GL_DEPTH_COMPONENT, GL_FLOAT, ...)` and a sampled depth
/// texture give.
pub const OCEAN_SAO_DEPTH_WINDOW: u32 = 0;
/// `ocean_sao_create`'s `depth_source`: the depth buffer holds NDC depth (clip z / clip w), in
/// the convention's range: [-1, 1] under `OCEAN_DEPTH_CONVENTION_NEG_ONE_TO_ONE`, [0, 1]
/// otherwise (where it equals window depth).
pub const OCEAN_SAO_DEPTH_NDC: u32 = 1;

/// Reads `depth_source`.
pub(crate) fn source_from(v: u32) -> Result<DepthSource, Error> {
    match v {
        OCEAN_SAO_DEPTH_WINDOW => Ok(DepthSource::Window),
        OCEAN_SAO_DEPTH_NDC => Ok(DepthSource::Ndc),
        _ => Err(Error::new(
            OceanStatus::InvalidArgument,
            format!(
                "depth_source = {v} is neither OCEAN_SAO_DEPTH_WINDOW (0) nor \
                 OCEAN_SAO_DEPTH_NDC (1)"
            ),
        )),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn depth_sources_are_checked() {
        assert_eq!(source_from(0).unwrap(), DepthSource::Window);
        assert_eq!(source_from(1).unwrap(), DepthSource::Ndc);
        let e = source_from(2).unwrap_err();
        assert_eq!(e.status, OceanStatus::InvalidArgument);
        assert!(e.message.contains("depth_source = 2"), "{}", e.message);
    }
}
