//! The five passes in order: z (Eq. 2), z MIP levels (Table 1), AO samples with the quad
//! bilateral and the packing (§2.3), horizontal and vertical blur (§2.4).

use alloc::vec::Vec;

use ocean_core::{Camera, DepthConvention, Projection};

use crate::SaoError;
use crate::blur::BlurConstants;
use crate::hierarchy::ZHierarchy;
use crate::pack::{Texel, pack_pass};
use crate::params::SaoParams;
use crate::reconstruct::{DepthSource, ProjectionInfo, ZConstants};
use crate::sample::{SampleConstants, quad_bilateral, sample_pass};
use crate::viewport::Viewport;

/// A validated SAO set-up: the camera's constants, the image sizes and the parameters.
#[derive(Clone, Debug, PartialEq)]
pub struct Sao {
    viewport: Viewport,
    z: ZConstants,
    info: ProjectionInfo,
    params: SaoParams,
    sample: SampleConstants,
    blur: BlurConstants,
}

/// Every intermediate image of one run (for tests, debugging and GPU parity).
#[derive(Clone, Debug, PartialEq)]
pub struct Stages {
    /// The z hierarchy; level 0 is the z pass (input size).
    pub hierarchy: ZHierarchy,
    /// The raw sample-pass obscurance (output size).
    pub raw: Vec<f32>,
    /// After the 2×2 quad bilateral (equal to `raw` when it is disabled).
    pub quad: Vec<f32>,
    /// Packed A and key (§2.3).
    pub packed: Vec<Texel>,
    /// After the horizontal blur.
    pub horizontal: Vec<Texel>,
    /// The final A after the vertical blur, in `[0, 1]`.
    pub ao: Vec<f32>,
}

impl Sao {
    /// Validates the projection (in `f32` too), the sizes and the parameters.
    ///
    /// # Errors
    ///
    /// [`SaoError::Camera`], [`SaoError::DegenerateProjection`] and the parameters' range errors.
    pub fn new(
        projection: &Projection,
        convention: DepthConvention,
        source: DepthSource,
        viewport: Viewport,
        params: SaoParams,
    ) -> Result<Self, SaoError> {
        params.validate()?;
        let z = ZConstants::new(projection, convention, source)?;
        let info = ProjectionInfo::new(
            projection,
            convention,
            viewport.input_width(),
            viewport.input_height(),
        )?;
        let sample = SampleConstants::new(&params, &info);
        if !(sample.radius_pixels.is_finite() && sample.inv_radius2.is_finite()) {
            return Err(SaoError::DegenerateProjection("r·S'"));
        }
        Ok(Self {
            viewport,
            z,
            info,
            params,
            sample,
            blur: BlurConstants::with_geometry(
                &params.blur,
                info.perspective,
                [info.scale[0].abs(), info.scale[1].abs()],
                params.z_min,
                params.radius,
            ),
        })
    }

    /// [`Sao::new`] with a camera's projection and depth convention (the view matrix plays no
    /// part: SAO works in camera space).
    ///
    /// # Errors
    ///
    /// As [`Sao::new`].
    pub fn from_camera(
        camera: &Camera,
        source: DepthSource,
        viewport: Viewport,
        params: SaoParams,
    ) -> Result<Self, SaoError> {
        Self::new(
            &camera.projection(),
            camera.depth(),
            source,
            viewport,
            params,
        )
    }

    /// The sizes.
    pub fn viewport(&self) -> &Viewport {
        &self.viewport
    }

    /// Eq. 2's constants.
    pub fn z_constants(&self) -> &ZConstants {
        &self.z
    }

    /// Eq. 3 and Eq. 5's constants.
    pub fn projection_info(&self) -> &ProjectionInfo {
        &self.info
    }

    /// The parameters.
    pub fn params(&self) -> &SaoParams {
        &self.params
    }

    /// The sample pass's constants.
    pub fn sample_constants(&self) -> &SampleConstants {
        &self.sample
    }

    /// The blur's constants.
    pub fn blur_constants(&self) -> &BlurConstants {
        &self.blur
    }

    /// The level-0 pixel the MIP levels are anchored at: the guard band modulo `2^M`, `M` the
    /// highest level built (see [`crate::hierarchy`]), so that any guard band gives the interior
    /// an aligned one gives.
    pub fn mip_origin(&self) -> usize {
        let (w, h) = (self.viewport.input_width(), self.viewport.input_height());
        let top = crate::hierarchy::level_count(w, h, self.params.max_mip) - 1;
        self.viewport.guard() % (1usize << top)
    }

    /// The z pass and the MIP levels.
    ///
    /// # Errors
    ///
    /// As [`ZConstants::z_pass`].
    pub fn hierarchy(&self, depth: &[f32]) -> Result<ZHierarchy, SaoError> {
        let z0 = self.z.z_pass(&self.viewport, depth)?;
        ZHierarchy::build_anchored(
            z0,
            self.viewport.input_width(),
            self.viewport.input_height(),
            self.params.mip_filter,
            self.params.max_mip,
            self.mip_origin(),
        )
    }

    /// Runs every pass on `depth` (input size, row-major, row 0 at the top) and keeps every
    /// intermediate.
    ///
    /// # Errors
    ///
    /// As [`ZConstants::z_pass`].
    pub fn stages(&self, depth: &[f32]) -> Result<Stages, SaoError> {
        let hierarchy = self.hierarchy(depth)?;
        let raw = sample_pass(&self.sample, &self.info, &self.viewport, &hierarchy);
        let z0 = hierarchy.base().z();
        let quad = match self.params.quad_depth_threshold {
            Some(t) => quad_bilateral(&self.viewport, z0, &raw, t),
            None => raw.clone(),
        };
        let packed = pack_pass(&self.viewport, z0, &quad, self.params.z_min);
        let horizontal = self.blur.horizontal(&self.viewport, &packed);
        let ao = self.blur.vertical(&self.viewport, &horizontal);
        Ok(Stages {
            hierarchy,
            raw,
            quad,
            packed,
            horizontal,
            ao,
        })
    }

    /// Runs every pass and writes the final A (output size, row-major) into `ao`.
    ///
    /// # Errors
    ///
    /// [`SaoError::BufferSize`] when `ao` is not output-sized (checked first; nothing is
    /// written on error), then as [`ZConstants::z_pass`].
    pub fn run(&self, depth: &[f32], ao: &mut [f32]) -> Result<(), SaoError> {
        let expected = self.viewport.output_len();
        if ao.len() != expected {
            return Err(SaoError::BufferSize {
                name: "ao",
                expected,
                got: ao.len(),
            });
        }
        let stages = self.stages(depth)?;
        ao.copy_from_slice(&stages.ao);
        Ok(())
    }
}
