//! The enumerations of the relief entry points: edge modes, height ranges, cone kinds,
//! storage encodings and mip rules.

use crate::boundary::CEnum;

/// How texel indices outside the map are read (the `edge` parameter, a `uint32_t`).
#[repr(u32)]
#[derive(Clone, Copy, Debug, PartialEq, Eq, bytemuck::NoUninit, bytemuck::CheckedBitPattern)]
pub enum OceanReliefEdge {
    /// The texture tiles (sampler addressing *repeat*).
    Wrap = 0,
    /// Texel indices clamp to the border (sampler addressing *clamp-to-edge*).
    Clamp = 1,
}

impl CEnum for OceanReliefEdge {
    const REFUSAL: &'static str =
        "is neither OCEAN_RELIEF_EDGE_WRAP (0) nor OCEAN_RELIEF_EDGE_CLAMP (1)";
}

/// What `ocean_relief_map_create_f32` does with heights outside [0, 1] (its `range` parameter,
/// a `uint32_t`).
#[repr(u32)]
#[derive(Clone, Copy, Debug, PartialEq, Eq, bytemuck::NoUninit, bytemuck::CheckedBitPattern)]
pub enum OceanReliefRange {
    /// A height outside [0, 1] is refused (`OCEAN_STATUS_INVALID_ARGUMENT`, the message names
    /// the first such texel).
    Refuse = 0,
    /// The smallest height becomes 0 and the largest 1 (affinely; a constant map becomes a flat
    /// map at height 1, the polygon surface).
    Normalize = 1,
}

impl CEnum for OceanReliefRange {
    const REFUSAL: &'static str =
        "is neither OCEAN_RELIEF_RANGE_REFUSE (0) nor OCEAN_RELIEF_RANGE_NORMALIZE (1)";
}

/// `OceanReliefConeParams::kind`: which cones are made.
#[repr(u32)]
#[derive(
    Clone, Copy, Debug, Default, PartialEq, Eq, bytemuck::NoUninit, bytemuck::CheckedBitPattern,
)]
pub enum OceanReliefConeKind {
    /// Relaxed cones (section 18.4): a ray may enter the relief inside a cone but never leave
    /// it. For `OCEAN_RELIEF_TRACER_RELAXED`.
    #[default]
    Relaxed = 0,
    /// Conservative cones (Dummer 2006): the cone holds no solid. For
    /// `OCEAN_RELIEF_TRACER_CONE_STEP`.
    Conservative = 1,
}

impl CEnum for OceanReliefConeKind {
    const REFUSAL: &'static str =
        "is neither OCEAN_RELIEF_CONE_KIND_RELAXED (0) nor OCEAN_RELIEF_CONE_KIND_CONSERVATIVE (1)";
}

/// How cone values are stored (the `encoding` parameter, a `uint32_t`).
#[repr(u32)]
#[derive(Clone, Copy, Debug, PartialEq, Eq, bytemuck::NoUninit, bytemuck::CheckedBitPattern)]
pub enum OceanReliefEncoding {
    /// 8-bit unorm (`uint8_t`), clamped to 1.0: code k = floor(255 min(r, 1)), read back as
    /// k / 255 (a GPU's `R8Unorm` conversion).
    Unorm8 = 0,
    /// 8-bit unorm of the square root (`uint8_t`), clamped to 1.0: read back as (k / 255)^2.
    Unorm8Sqrt = 1,
    /// IEEE binary16 bit patterns (`uint16_t`), unclamped (up to 65504), rounded toward zero.
    F16 = 2,
    /// `float`, the generator's values as they are.
    F32 = 3,
}

impl CEnum for OceanReliefEncoding {
    const REFUSAL: &'static str = "is not an OCEAN_RELIEF_ENCODING_* value (0 to 3)";
}

/// How `ocean_relief_mips_create` makes a coarse texel (its `rule` parameter, a `uint32_t`).
#[repr(u32)]
#[derive(Clone, Copy, Debug, PartialEq, Eq, bytemuck::NoUninit, bytemuck::CheckedBitPattern)]
pub enum OceanReliefMip {
    /// The minimum of a 4x4 window of the finer level (its 2x2 group and a one-texel ring):
    /// valid under bilinear sampling.
    Window = 0,
    /// The book's 2x2 group minimum, valid under nearest sampling only.
    Group = 1,
}

impl CEnum for OceanReliefMip {
    const REFUSAL: &'static str =
        "is neither OCEAN_RELIEF_MIP_WINDOW (0) nor OCEAN_RELIEF_MIP_GROUP (1)";
}
