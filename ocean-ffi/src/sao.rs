//! Scalable Ambient Obscurance (crate `ocean-sao`; McGuire, Mara & Luebke, HPG 2012), part 2 of
//! 2: the parameters, the `OceanSao` handle and the passes on a caller's depth buffer. The
//! camera is the library's `OceanCamera` (`camera.rs`), of which SAO reads the projection; what
//! the depth buffer holds is in `sao_depth.rs`.
//!
//! This is the CPU reference: every pass in the arithmetic its GPU twin follows, for tools,
//! tests and engines that render AO offline or check their own shader against it.

use ocean_core::camera::{Far, Projection};
use ocean_sao::{
    BlurParams, BlurWeight, Estimator, MipFilter, NormalEstimate, NormalRejection, Sao, SaoError,
    SaoParams, Viewport,
};

use core::mem::offset_of;

use crate::boundary::OceanNext;
use crate::boundary::{
    CEnum, CheckedStruct, EnumField, borrow, byte_len, check_disjoint, check_flag, check_len,
    check_ptr, destroy, read_params_checked, write_handle, write_out,
};
use crate::camera::{OceanCamera, camera_status, read_camera};
use crate::sao_depth::source_from;
use crate::status::{Error, OceanStatus, guard};

/// `OceanSaoParams::mip_filter`: how a MIP level of z is made from the one below.
#[repr(u32)]
#[derive(
    Clone, Copy, Debug, Default, PartialEq, Eq, bytemuck::NoUninit, bytemuck::CheckedBitPattern,
)]
pub enum OceanSaoMipFilter {
    /// Rotated grid subsampling (Table 1), the paper's choice: every MIP texel is one of its
    /// children, a true scene value.
    #[default]
    RotatedGrid = 0,
    /// The arithmetic mean of the 2x2 children.
    ArithmeticMean = 1,
    /// The harmonic mean of the 2x2 children (Table 1 misprints it as a sixteenth of that;
    /// ocean-sao implements the mean).
    HarmonicMean = 2,
    /// The minimum z of the children (the farthest).
    Min = 3,
    /// The maximum z of the children (the nearest).
    Max = 4,
}

impl CEnum for OceanSaoMipFilter {
    const REFUSAL: &'static str = "is not an OCEAN_SAO_MIP_FILTER_* value (0 to 4)";
}

/// `OceanSaoParams::estimator`: the obscurance estimator.
#[repr(u32)]
#[derive(
    Clone, Copy, Debug, Default, PartialEq, Eq, bytemuck::NoUninit, bytemuck::CheckedBitPattern,
)]
pub enum OceanSaoEstimator {
    /// The updated falloff of the paper's appendix,
    /// A = max(0, 1 - (5 intensity / (r^6 n)) sum max(r^2 - v.v, 0)^3 max((v.n - beta)/(v.v + eps), 0)).
    #[default]
    Falloff = 0,
    /// AlchemyAO's estimator, the paper's Eq. 1,
    /// A = max(0, 1 - (2 sigma / n) sum max(0, v.n + z_C beta)/(v.v + eps))^k.
    Alchemy = 1,
}

impl CEnum for OceanSaoEstimator {
    const REFUSAL: &'static str =
        "is neither OCEAN_SAO_ESTIMATOR_FALLOFF (0) nor OCEAN_SAO_ESTIMATOR_ALCHEMY (1)";
}

/// `OceanSaoParams::normals`: how each pixel's normal is reconstructed from depth.
#[repr(u32)]
#[derive(
    Clone, Copy, Debug, Default, PartialEq, Eq, bytemuck::NoUninit, bytemuck::CheckedBitPattern,
)]
pub enum OceanSaoNormals {
    /// The paper's Eq. 4, differences within each pixel's 2x2 quad (a silhouette pixel whose
    /// quad partner is on the background gets a normal across the edge).
    #[default]
    Quad = 0,
    /// The default: along each axis, the difference to whichever adjacent pixel is nearer in
    /// depth, so silhouette pixels keep their own surface's normal.
    Nearest = 1,
}

impl CEnum for OceanSaoNormals {
    const REFUSAL: &'static str =
        "is neither OCEAN_SAO_NORMALS_QUAD (0) nor OCEAN_SAO_NORMALS_NEAREST (1)";
}

/// `OceanSaoBlurParams::weight`: what a blur tap's depth key is compared with.
#[repr(u32)]
#[derive(
    Clone, Copy, Debug, Default, PartialEq, Eq, bytemuck::NoUninit, bytemuck::CheckedBitPattern,
)]
pub enum OceanSaoBlurWeight {
    /// The paper's: the centre's key (taps on surfaces sloped to the view are rejected and the
    /// sampling pattern stays visible there).
    #[default]
    Depth = 0,
    /// The default: the key the plane through the centre pixel predicts there, its slope from
    /// the adjacent pixel nearer in depth.
    Plane = 1,
}

impl CEnum for OceanSaoBlurWeight {
    const REFUSAL: &'static str =
        "is neither OCEAN_SAO_BLUR_WEIGHT_DEPTH (0) nor OCEAN_SAO_BLUR_WEIGHT_PLANE (1)";
}

/// The camera-space z that `ocean_sao_view_z` stores for background pixels (depth at the far
/// end of the range): -1e9 m, a finite stand-in for infinity.
pub const OCEAN_SAO_SKY_Z: f32 = -1.0e9;
/// The largest input width or height accepted, in pixels.
pub const OCEAN_SAO_MAX_SIDE: u32 = 16_384;

const _: () = assert!(OCEAN_SAO_SKY_Z == ocean_sao::SKY_Z);
const _: () = assert!(OCEAN_SAO_MAX_SIDE as usize == ocean_sao::MAX_SIDE);

/// The bilateral reconstruction (paper section 2.4): a horizontal then a vertical pass of `taps`
/// taps `stride` pixels apart, weighted by exp(-t^2 / (2 sigma^2)) for tap t (counted in taps)
/// times max(0, 1 - depth_scale |key_t - key_ref|), with key = z / z_min and key_ref the
/// centre's key (`OCEAN_SAO_BLUR_WEIGHT_DEPTH`) or its plane's prediction
/// (`OCEAN_SAO_BLUR_WEIGHT_PLANE`, which also fades taps with their distance in metres).
/// Background pixels neither change nor contribute.
#[repr(C)]
#[derive(
    Clone, Copy, Debug, Default, PartialEq, bytemuck::NoUninit, bytemuck::CheckedBitPattern,
)]
pub struct OceanSaoBlurParams {
    /// Tap count, odd, 1 to 63 (default 13; the paper: 7; its released shader: 9). 1 disables
    /// the blur.
    pub taps: u32,
    /// Pixels between taps, 1 to 64 (default 1; the paper: 3; its released shader: 2).
    pub stride: u32,
    /// Depth-difference scale, in [0, 1e9] (the paper: 2^11 = 2048): with z_min = -200 m,
    /// pixels more than 200/2048 m (about 0.1 m) apart in depth do not mix.
    pub depth_scale: f32,
    /// Gaussian standard deviation in taps, in [1e-3, 1e3] (default 3: the outermost of 13
    /// taps weighs e^-2 of the centre; the paper's 7 taps: 1.5).
    pub sigma: f32,
    /// `OCEAN_SAO_BLUR_WEIGHT_PLANE` (default) or `OCEAN_SAO_BLUR_WEIGHT_DEPTH` (the paper's);
    /// other values are refused.
    pub weight: OceanSaoBlurWeight,
    /// With the plane weight: the distance from the centre pixel, as a fraction of `radius`,
    /// at which a tap's weight fades to 0, in [0, 1e3] (default 0.5; 0: no fade).
    pub world_extent: f32,
}

/// Every parameter of the passes. Start from `ocean_sao_params_default` and change what you
/// need. Lengths are metres; the default is the paper's set-up for human-scale scenes.
#[repr(C)]
#[derive(
    Clone, Copy, Debug, Default, PartialEq, bytemuck::NoUninit, bytemuck::CheckedBitPattern,
)]
pub struct OceanSaoParams {
    /// Extensions: NULL, or the first extension struct (see `OceanChain`); the `_default`
    /// function sets NULL.
    pub next: OceanNext,
    /// World-space radius r of the obscurance ball, metres, in [1e-4, 1e4] (default 1).
    pub radius: f32,
    /// Samples per pixel, 1 to 64 (default 9, the paper's).
    pub samples: u32,
    /// Turns of the sample spiral (Eq. 6-7), in [1e-3, 1e3] (default 7, the paper's value for
    /// 9 samples). It does not follow `samples`: when changing the sample count, set it too.
    /// ocean-sao's convention is the integer nearest 7 * samples / 9 that is coprime with the
    /// sample count (ties to the smaller), so every sample direction differs.
    pub spiral_turns: f32,
    /// log2 of q' in Eq. 9, 0 to 8 (default 3): a sample h pixels from the centre reads MIP
    /// level floor(log2(h)) - mip_switch_log2, clamped to [0, max_mip].
    pub mip_switch_log2: u32,
    /// Highest MIP level read, 0 to 13 (default 5); 0 reads every sample from full resolution.
    pub max_mip: u32,
    /// How a MIP level is made from the one below: an `OCEAN_SAO_MIP_FILTER_*` value (default
    /// `OCEAN_SAO_MIP_FILTER_ROTATED_GRID`); other values are refused.
    pub mip_filter: OceanSaoMipFilter,
    /// `OCEAN_SAO_ESTIMATOR_FALLOFF` (default) or `OCEAN_SAO_ESTIMATOR_ALCHEMY`; other values
    /// are refused. Only the chosen estimator's constants below are read and checked.
    pub estimator: OceanSaoEstimator,
    /// Falloff: bias beta, metres, in [0, 1e3] (default 0.01: 1 cm).
    pub falloff_beta: f32,
    /// Falloff: intensity multiplier, in [0, 1e3] (default 1, the appendix's formula).
    pub falloff_intensity: f32,
    /// Eq. 1: intensity sigma, metres, in [0, 1e4] (default 0.25).
    pub alchemy_sigma: f32,
    /// Eq. 1: depth-proportional bias beta, in [0, 1] (default 1e-3: 1 cm at 10 m).
    pub alchemy_beta: f32,
    /// Eq. 1: contrast exponent k, in [1e-2, 16] (default 1).
    pub alchemy_k: f32,
    /// epsilon of both estimators, square metres, in [1e-12, 1e4] (default 0.01).
    pub epsilon: f32,
    /// 1: the 2x2 quad bilateral of section 2.3 (default); 0: off. Other values are refused.
    pub quad_filter: u32,
    /// The quad bilateral averages two neighbours when their z differ by less than this many
    /// metres, in [0, 1e6] (default 0.02). Read only when `quad_filter` is 1.
    pub quad_depth_threshold: f32,
    /// `OCEAN_SAO_NORMALS_NEAREST` (default) or `OCEAN_SAO_NORMALS_QUAD` (the paper's Eq. 4);
    /// other values are refused.
    pub normals: OceanSaoNormals,
    /// 1: treat pixels whose reconstructed normal is unreliable (a depth edge inside their 2x2
    /// quad) as unoccluded; 0: the paper's behaviour (default). Other values are refused.
    pub normal_rejection: u32,
    /// The rejection's largest apparent incidence angle, radians, in [1e-3, pi/2 - 1e-3]
    /// (default 85 degrees, 1.4835 rad). Read only when `normal_rejection` is 1.
    pub normal_max_incidence: f32,
    /// z_min of the depth key the blur compares (section 2.3), metres, negative, in
    /// [-1e8, -1e-4] (default -200): the farthest view depth at which sharp AO edges matter.
    pub z_min: f32,
    /// The blur passes.
    pub blur: OceanSaoBlurParams,
    /// Set to 0 (fills the struct to a multiple of 8 bytes, the alignment of `next`).
    pub reserved: u32,
}

impl CheckedStruct for OceanSaoParams {
    const ENUM_FIELDS: &'static [EnumField] = &[
        EnumField::of::<OceanSaoMipFilter>("mip_filter", offset_of!(OceanSaoParams, mip_filter)),
        EnumField::of::<OceanSaoEstimator>("estimator", offset_of!(OceanSaoParams, estimator)),
        EnumField::of::<OceanSaoNormals>("normals", offset_of!(OceanSaoParams, normals)),
        EnumField::of::<OceanSaoBlurWeight>(
            "blur.weight",
            offset_of!(OceanSaoParams, blur) + offset_of!(OceanSaoBlurParams, weight),
        ),
    ];
}

/// Default incidence limit of the normal rejection: 85 degrees.
const DEFAULT_MAX_INCIDENCE: f32 = 85.0 * (core::f32::consts::PI / 180.0);

impl OceanSaoParams {
    /// ocean-sao's defaults; the estimator not chosen gets its own defaults.
    fn defaults() -> Self {
        let d = SaoParams::default();
        let Estimator::Falloff {
            beta: falloff_beta,
            intensity: falloff_intensity,
        } = Estimator::FALLOFF
        else {
            unreachable!("Estimator::FALLOFF is the falloff")
        };
        let Estimator::Alchemy {
            sigma: alchemy_sigma,
            beta: alchemy_beta,
            k: alchemy_k,
        } = Estimator::ALCHEMY
        else {
            unreachable!("Estimator::ALCHEMY is Eq. 1")
        };
        let (quad_filter, quad_depth_threshold) = match d.quad_depth_threshold {
            Some(t) => (1, t),
            None => (0, 0.0),
        };
        let (normal_rejection, normal_max_incidence) = match d.normal_rejection {
            Some(r) => (1, r.max_incidence),
            None => (0, DEFAULT_MAX_INCIDENCE),
        };
        Self {
            next: OceanNext::NULL,
            reserved: 0,
            radius: d.radius,
            samples: d.samples,
            spiral_turns: d.spiral_turns,
            mip_switch_log2: d.mip_switch_log2,
            max_mip: d.max_mip,
            mip_filter: match d.mip_filter {
                MipFilter::RotatedGrid => OceanSaoMipFilter::RotatedGrid,
                MipFilter::ArithmeticMean => OceanSaoMipFilter::ArithmeticMean,
                MipFilter::HarmonicMean => OceanSaoMipFilter::HarmonicMean,
                MipFilter::Min => OceanSaoMipFilter::Min,
                MipFilter::Max => OceanSaoMipFilter::Max,
            },
            estimator: match d.estimator {
                Estimator::Falloff { .. } => OceanSaoEstimator::Falloff,
                Estimator::Alchemy { .. } => OceanSaoEstimator::Alchemy,
            },
            falloff_beta,
            falloff_intensity,
            alchemy_sigma,
            alchemy_beta,
            alchemy_k,
            epsilon: d.epsilon,
            quad_filter,
            quad_depth_threshold,
            normals: match d.normals {
                NormalEstimate::Quad => OceanSaoNormals::Quad,
                NormalEstimate::Nearest => OceanSaoNormals::Nearest,
            },
            normal_rejection,
            normal_max_incidence,
            z_min: d.z_min,
            blur: OceanSaoBlurParams {
                taps: d.blur.taps,
                stride: d.blur.stride,
                depth_scale: d.blur.depth_scale,
                sigma: d.blur.sigma,
                weight: match d.blur.weight {
                    BlurWeight::Depth => OceanSaoBlurWeight::Depth,
                    BlurWeight::Plane => OceanSaoBlurWeight::Plane,
                },
                world_extent: d.blur.world_extent,
            },
        }
    }
}

/// Converts and validates the caller's parameters (ocean-sao's ranges).
fn params_from(p: &OceanSaoParams) -> Result<SaoParams, Error> {
    let mip_filter = match p.mip_filter {
        OceanSaoMipFilter::RotatedGrid => MipFilter::RotatedGrid,
        OceanSaoMipFilter::ArithmeticMean => MipFilter::ArithmeticMean,
        OceanSaoMipFilter::HarmonicMean => MipFilter::HarmonicMean,
        OceanSaoMipFilter::Min => MipFilter::Min,
        OceanSaoMipFilter::Max => MipFilter::Max,
    };
    let estimator = match p.estimator {
        OceanSaoEstimator::Falloff => Estimator::Falloff {
            beta: p.falloff_beta,
            intensity: p.falloff_intensity,
        },
        OceanSaoEstimator::Alchemy => Estimator::Alchemy {
            sigma: p.alchemy_sigma,
            beta: p.alchemy_beta,
            k: p.alchemy_k,
        },
    };
    let normals = match p.normals {
        OceanSaoNormals::Quad => NormalEstimate::Quad,
        OceanSaoNormals::Nearest => NormalEstimate::Nearest,
    };
    let weight = match p.blur.weight {
        OceanSaoBlurWeight::Depth => BlurWeight::Depth,
        OceanSaoBlurWeight::Plane => BlurWeight::Plane,
    };
    let quad_depth_threshold =
        check_flag("params->quad_filter", p.quad_filter)?.then_some(p.quad_depth_threshold);
    let normal_rejection =
        check_flag("params->normal_rejection", p.normal_rejection)?.then_some(NormalRejection {
            max_incidence: p.normal_max_incidence,
        });
    let params = SaoParams {
        radius: p.radius,
        samples: p.samples,
        spiral_turns: p.spiral_turns,
        mip_switch_log2: p.mip_switch_log2,
        max_mip: p.max_mip,
        mip_filter,
        estimator,
        epsilon: p.epsilon,
        quad_depth_threshold,
        normals,
        normal_rejection,
        z_min: p.z_min,
        blur: BlurParams {
            taps: p.blur.taps,
            stride: p.blur.stride,
            depth_scale: p.blur.depth_scale,
            sigma: p.blur.sigma,
            weight,
            world_extent: p.blur.world_extent,
        },
    };
    params.validate().map_err(|e| sao_error("params: ", e))?;
    Ok(params)
}

/// The error of a crate call as a status, with the crate's message (`?` converts).
impl From<SaoError> for Error {
    fn from(e: SaoError) -> Self {
        sao_error("", e)
    }
}

/// The status of an `ocean-sao` error, and its message prefixed with `context`.
pub(crate) fn sao_error(context: &str, e: SaoError) -> Error {
    let status = match &e {
        SaoError::Camera(c) => camera_status(c),
        SaoError::DegenerateProjection(_) => OceanStatus::InvalidArgument,
        SaoError::ImageSize { width, height } if *width == 0 || *height == 0 => OceanStatus::Empty,
        SaoError::ImageSize { .. } => OceanStatus::InvalidArgument,
        SaoError::GuardBand { .. } => OceanStatus::InvalidArgument,
        SaoError::BufferSize { .. } => OceanStatus::InvalidArgument,
        SaoError::DepthNotFinite { .. } => OceanStatus::NonFinite,
        SaoError::DepthOutOfRange { .. } => OceanStatus::InvalidArgument,
        SaoError::NotFinite(_) => OceanStatus::NonFinite,
        SaoError::OutOfRange { .. } => OceanStatus::InvalidArgument,
        SaoError::UnsupportedFormat(_) => OceanStatus::InvalidArgument,
        SaoError::EvenTaps(_) => OceanStatus::InvalidArgument,
        // `SaoError` is non-exhaustive: a variant added later is an argument out of range
        // until it gets a status of its own.
        _ => OceanStatus::InvalidArgument,
    };
    Error::new(status, format!("{context}{e}"))
}

/// A validated SAO set-up (opaque): image sizes, guard band, camera and parameters. Create with
/// `ocean_sao_create`, free with `ocean_sao_destroy`. Immutable: a `const OceanSao *` may run
/// on any number of threads at once.
pub struct OceanSao {
    sao: Sao,
    orthographic: bool,
    near: f64,
    far: f64,
}

impl OceanSao {
    /// The validated set-up.
    #[cfg(feature = "gpu")]
    pub(crate) fn sao(&self) -> &Sao {
        &self.sao
    }
}

const _: () = {
    const fn shareable<T: Send + Sync>() {}
    shareable::<OceanSao>();
};

/// What an `OceanSao` was made of, as `ocean_sao_describe` reports it: the sizes, the planes read
/// from the projection matrix, and the constants of the passes (the values a GPU shader that
/// follows ocean-sao needs).
#[repr(C)]
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct OceanSaoInfo {
    /// Width of the depth buffer, pixels.
    pub input_width: u32,
    /// Height of the depth buffer, pixels.
    pub input_height: u32,
    /// Guard band on every side, pixels.
    pub guard: u32,
    /// Width of the AO image: input_width - 2 guard.
    pub output_width: u32,
    /// Height of the AO image: input_height - 2 guard.
    pub output_height: u32,
    /// 1 for an orthographic projection, 0 for a perspective.
    pub orthographic: u32,
    /// Near-plane distance read from the matrix, metres (in front of the camera; an
    /// orthographic box may start at or behind it: <= 0).
    pub near: f64,
    /// Far-plane distance read from the matrix, metres; `INFINITY` for an infinite perspective.
    pub far: f64,
    /// Eq. 2 with ocean-sao's fourth constant: the view-space z (negative in front) of a depth
    /// d is (`c[0]` + `c[3]` d) / (`c[1]` d + `c[2]`), in float arithmetic (`c[3]` = 0 for a
    /// perspective, `c[1]` = 0 for an orthographic box), for every depth but `far_depth`.
    pub z_constants: [f32; 4],
    /// The depth value of the near plane (0, -1 for NDC depth under [-1, 1], or 1 reversed).
    pub near_depth: f32,
    /// The depth value of the far plane, or of infinity: the clear value, read as background.
    pub far_depth: f32,
    /// Eq. 5's S' = input_height P11 / 2: pixels per metre at 1 m in front of a perspective
    /// camera, pixels per metre everywhere for an orthographic one.
    pub pixels_per_metre: f32,
    /// Written as 0: room for a later member, and no padding the caller cannot see.
    pub reserved: u32,
}

/// Stores ocean-sao's default parameters in `*out` (the paper's set-up: r = 1 m, 9 samples,
/// 7 spiral turns, MIP levels 0 to 5 by rotated grid subsampling from q' = 8, the appendix's
/// falloff with beta = 1 cm, the 2x2 quad filter at 2 cm, no normal rejection, z_min = -200 m;
/// beyond it: nearest-neighbour normals and a blur of 13 adjacent taps, sigma 3, weighed by the
/// plane through the centre, depth scale 2048, world extent 0.5. The paper's blur is taps 7,
/// stride 3, sigma 1.5, `OCEAN_SAO_BLUR_WEIGHT_DEPTH`). The members of the estimator not
/// chosen hold that estimator's defaults too.
///
/// Returns `OCEAN_STATUS_NULL_POINTER` (or `_MISALIGNED_POINTER`) for a bad `out`, which is
/// then left unchanged.
///
/// # Safety
///
/// `out` must be writable.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn ocean_sao_params_default(out: *mut OceanSaoParams) -> OceanStatus {
    guard("ocean_sao_params_default", || {
        let p = OceanSaoParams::defaults();
        // SAFETY: forwarded from this function's contract.
        unsafe { write_out(out, "out", p) }
    })
}

/// Creates an SAO set-up for depth buffers of `input_width` x `input_height` pixels with a
/// guard band of `guard` pixels on every side, and stores the handle in `*out`.
///
/// The paper renders depth larger than the screen so that geometry just outside the frame can
/// still occlude: the AO image is the input inset by `guard` on every side,
/// (input_width - 2 guard) x (input_height - 2 guard) pixels. Any guard band is accepted and
/// gives the interior an aligned one gives: the z MIP levels are anchored at guard modulo
/// 2^max_mip (the uniform block of `ocean_sao_uniforms` carries the anchor to the GPU passes).
/// `camera` is the camera that rendered the whole input, guard band included (see
/// `OceanCamera`): SAO works in view space and reads only its projection, whose aspect
/// P11/P00 is that of the input's pixels (it need not equal width/height: non-square pixels are
/// allowed). Mirrored or y-flipped projections are refused: image rows already run top-down
/// (see `ocean_sao_run`). `depth_source` says what the depth buffer holds:
/// `OCEAN_SAO_DEPTH_WINDOW` or `OCEAN_SAO_DEPTH_NDC`. `params` are the passes (see
/// `OceanSaoParams`). Both structs are copied; neither is retained.
///
/// Returns `OCEAN_STATUS_NULL_POINTER` / `_MISALIGNED_POINTER` for a bad pointer,
/// `OCEAN_STATUS_EMPTY` if `input_width` or `input_height` is 0, `OCEAN_STATUS_NON_FINITE` for
/// a NaN or infinite matrix element or parameter (the message names it),
/// `OCEAN_STATUS_INVALID_ARGUMENT` for a side outside 2 to `OCEAN_SAO_MAX_SIDE`, a guard band
/// that leaves no output pixel (2 guard must be below both sides), an unknown enumeration
/// value or flag, a matrix that is not a supported projection for its depth convention or whose
/// constants degenerate in float, and a parameter out of its documented range. `*out` is
/// written only on success. Free the handle with `ocean_sao_destroy`.
///
/// # Safety
///
/// `camera` and `params` must point to readable structs and `out` to a writable pointer.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn ocean_sao_create(
    input_width: u32,
    input_height: u32,
    guard: u32,
    camera: *const OceanCamera,
    depth_source: u32,
    params: *const OceanSaoParams,
    out: *mut *mut OceanSao,
) -> OceanStatus {
    self::guard("ocean_sao_create", || {
        check_ptr(camera, "camera")?;
        check_ptr(params, "params")?;
        check_ptr(out.cast_const(), "out")?;
        if input_width == 0 || input_height == 0 {
            return Err(Error::new(
                OceanStatus::Empty,
                format!("the depth buffer is {input_width} x {input_height} pixels: empty"),
            ));
        }
        // SAFETY: forwarded from this function's contract.
        let camera = unsafe { read_camera(camera) }?;
        let source = source_from(depth_source)?;
        // SAFETY: forwarded from this function's contract (the pointer checked above).
        let params = params_from(&unsafe { read_params_checked(params, "params") }?)?;
        let viewport = Viewport::new(input_width as usize, input_height as usize, guard as usize)?;
        let projection = camera.projection();
        let sao = Sao::new(&projection, camera.depth(), source, viewport, params)
            .map_err(|e| sao_error("camera: ", e))?;
        let orthographic = matches!(projection, Projection::Orthographic { .. });
        let near = projection.near();
        let far = match projection.far() {
            Far::Finite(f) => f,
            Far::Infinite => f64::INFINITY,
        };
        // SAFETY: forwarded from this function's contract.
        unsafe {
            write_handle(
                out,
                OceanSao {
                    sao,
                    orthographic,
                    near,
                    far,
                },
            )
        }
    })
}

/// Frees an SAO set-up. NULL does nothing; a handle of another kind or already destroyed frees
/// nothing and sets the last-error message (see the header's notes on handles).
#[unsafe(no_mangle)]
pub extern "C" fn ocean_sao_destroy(sao: *mut OceanSao) {
    destroy(sao, "ocean_sao_destroy", "sao");
}

/// Stores what `sao` was made of in `*out` (see `OceanSaoInfo`): the sizes, the near and far
/// planes read from the projection matrix (compare them with yours: a matrix passed with the
/// wrong depth convention shows here) and the constants of the passes.
///
/// Returns `OCEAN_STATUS_NULL_POINTER` (or `_MISALIGNED_POINTER`) for a bad `sao` or `out`;
/// `*out` is written only on success.
///
/// # Safety
///
/// `out` must be writable.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn ocean_sao_describe(
    sao: *const OceanSao,
    out: *mut OceanSaoInfo,
) -> OceanStatus {
    guard("ocean_sao_describe", || {
        let s = borrow(sao, "sao")?;
        let v = s.sao.viewport();
        let z = s.sao.z_constants();
        // Every side is at most OCEAN_SAO_MAX_SIDE (Viewport::new checked), so u32 holds it.
        let side = |n: usize| n as u32;
        let info = OceanSaoInfo {
            input_width: side(v.input_width()),
            input_height: side(v.input_height()),
            guard: side(v.guard()),
            output_width: side(v.output_width()),
            output_height: side(v.output_height()),
            orthographic: u32::from(s.orthographic),
            near: s.near,
            far: s.far,
            z_constants: z.c,
            near_depth: z.near_depth,
            far_depth: z.far_depth,
            pixels_per_metre: s.sao.projection_info().pixels_per_metre,
            reserved: 0,
        };
        // SAFETY: forwarded from this function's contract.
        unsafe { write_out(out, "out", info) }
    })
}

/// The checked input and output buffers of a pass over `sao`'s images.
pub(crate) struct Buffers<'a> {
    pub(crate) depth: &'a [f32],
    out: *mut f32,
    out_len: usize,
}

/// Checks `depth` (`depth_len` floats, the input size) and `out` (`out_len` floats, `want`
/// values), both for NULL, alignment, size and overlap, and borrows `depth`.
///
/// # Safety
///
/// `depth` must be NULL, misaligned, or point to `depth_len` readable floats that nothing
/// writes during the borrow; `out` NULL, misaligned, or `out_len` writable floats.
pub(crate) unsafe fn buffers<'a>(
    sao: &OceanSao,
    depth: *const f32,
    depth_len: usize,
    (out, out_len, out_name, want, what): (*mut f32, usize, &str, usize, &str),
) -> Result<Buffers<'a>, Error> {
    check_ptr(depth, "depth")?;
    check_ptr(out.cast_const(), out_name)?;
    let depth_bytes = byte_len::<f32>(depth_len, "depth")?;
    let out_bytes = byte_len::<f32>(out_len, out_name)?;
    let v = sao.sao.viewport();
    let (w, h) = (v.input_width(), v.input_height());
    check_len(
        "depth_len",
        depth_len,
        v.input_len(),
        &format!("the {w} x {h} depth buffer"),
    )?;
    check_len(&format!("{out_name}_len"), out_len, want, what)?;
    check_disjoint(
        (depth.cast::<u8>(), depth_bytes, "depth"),
        (out.cast_const().cast::<u8>(), out_bytes, out_name),
    )?;
    // SAFETY: non-NULL and 4-aligned (checked), `depth_len` floats whose byte size fits in
    // isize (checked), readable and unmodified during the call (caller's guarantee), and
    // disjoint from the output (checked).
    let depth = unsafe { core::slice::from_raw_parts(depth, depth_len) };
    Ok(Buffers {
        depth,
        out,
        out_len,
    })
}

impl Buffers<'_> {
    /// Copies a finished result into the caller's output.
    ///
    /// # Safety
    ///
    /// As `buffers`: `out` points to `out_len` writable floats untouched by others.
    pub(crate) unsafe fn write(self, result: &[f32]) {
        debug_assert_eq!(result.len(), self.out_len);
        // SAFETY: non-NULL and 4-aligned, byte size fits in isize, disjoint from `depth`
        // (checked in `buffers`); writable and untouched by others (caller's guarantee).
        let out = unsafe { core::slice::from_raw_parts_mut(self.out, self.out_len) };
        out.copy_from_slice(result);
    }
}

/// Computes ambient obscurance (visibility) from a depth buffer: every pass of the paper, in
/// ocean-sao's arithmetic, with its result bit-identical to `ocean_sao::Sao::run` on every
/// platform and thread count.
///
/// `depth`: `depth_len` = input_width * input_height floats, row-major, **row 0 at the top** of
/// the image (the layout of a wgpu, Vulkan, D3D or Metal texture read back; OpenGL's
/// `glReadPixels` returns rows bottom-up: flip them first). Each value must be finite and
/// within the range of the camera's depth source and convention: [0, 1] for window depth
/// (`OCEAN_SAO_DEPTH_WINDOW`) and for the [0, 1] conventions, [-1, 1] for NDC depth under
/// `OCEAN_DEPTH_CONVENTION_NEG_ONE_TO_ONE`. The far end of the range (`far_depth` of
/// `ocean_sao_describe`: 1, or 0 with reversed Z; the value a depth buffer is cleared to) is
/// background, at any far plane.
///
/// `ao`: `ao_len` = output_width * output_height floats (see `ocean_sao_create`), row-major,
/// row 0 at the top: `ao[y * output_width + x]` is the visibility A of input pixel
/// (x + guard, y + guard), in [0, 1]: 1 is unoccluded, 0 fully occluded; multiply ambient light
/// by it. Background pixels, and pixels whose normal is rejected, get 1.
///
/// The passes: view-space z from depth (Eq. 2), its MIP levels (Table 1), the spiral samples
/// (Eq. 6-10) with the chosen estimator, the 2x2 quad bilateral, A packed to 8 bits with a
/// 16-bit depth key (section 2.3), and the horizontal and vertical bilateral blur (section 2.4).
/// The result is computed in a buffer of the library's and copied to `ao` at the end.
///
/// Returns `OCEAN_STATUS_NULL_POINTER` / `_MISALIGNED_POINTER` for a bad pointer (4-byte
/// alignment for the floats), `OCEAN_STATUS_LENGTH_MISMATCH` if `depth_len` or `ao_len` is not
/// exactly the size above, `OCEAN_STATUS_INVALID_ARGUMENT` if the buffers overlap or a depth
/// value is outside the range (the
/// message gives the first one, in row-major order, with its pixel), `OCEAN_STATUS_NON_FINITE`
/// for a NaN or infinite depth value (likewise), `OCEAN_STATUS_LENGTH_OVERFLOW` if a length in
/// bytes exceeds `PTRDIFF_MAX`. `ao` is written only on success, and then wholly.
///
/// # Safety
///
/// `depth` point to `depth_len` readable floats and `ao` to
/// `ao_len` writable floats, neither touched by another thread during the call.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn ocean_sao_run(
    sao: *const OceanSao,
    depth: *const f32,
    depth_len: usize,
    ao: *mut f32,
    ao_len: usize,
) -> OceanStatus {
    guard("ocean_sao_run", || {
        let s = borrow(sao, "sao")?;
        let want = s.sao.viewport().output_len();
        let (ow, oh) = (
            s.sao.viewport().output_width(),
            s.sao.viewport().output_height(),
        );
        let what = format!("the {ow} x {oh} AO image");
        // SAFETY: forwarded from this function's contract.
        let b = unsafe { buffers(&s, depth, depth_len, (ao, ao_len, "ao", want, &what)) }?;
        let mut result = vec![0.0f32; want];
        s.sao.run(b.depth, &mut result)?;
        // SAFETY: forwarded from this function's contract (checked in `buffers`).
        unsafe { b.write(&result) };
        Ok(())
    })
}

/// Stores the view-space z of every depth value in `z` (the first pass of `ocean_sao_run`,
/// Eq. 2): `z_len` = input_width * input_height floats, the layout of `depth`, metres, negative
/// in front of the camera; `OCEAN_SAO_SKY_Z` (-1e9 m) for background (depth at the far end),
/// and never below it. Useful to linearise a depth buffer with exactly SAO's arithmetic, or to
/// check a shader's reconstruction.
///
/// `depth` as for `ocean_sao_run`. Returns the same statuses, with `z_len` in place of
/// `ao_len`; `z` is written only on success, and then wholly.
///
/// # Safety
///
/// `depth` point to `depth_len` readable floats and `z` to `z_len`
/// writable floats, neither touched by another thread during the call.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn ocean_sao_view_z(
    sao: *const OceanSao,
    depth: *const f32,
    depth_len: usize,
    z: *mut f32,
    z_len: usize,
) -> OceanStatus {
    guard("ocean_sao_view_z", || {
        let s = borrow(sao, "sao")?;
        let v = s.sao.viewport();
        let want = v.input_len();
        let what = format!(
            "the {} x {} depth buffer",
            v.input_width(),
            v.input_height()
        );
        // SAFETY: forwarded from this function's contract.
        let b = unsafe { buffers(&s, depth, depth_len, (z, z_len, "z", want, &what)) }?;
        let result = s.sao.z_constants().z_pass(v, b.depth)?;
        // SAFETY: forwarded from this function's contract (checked in `buffers`).
        unsafe { b.write(&result) };
        Ok(())
    })
}

crate::boundary::chain::extensible!(OceanSaoParams);

crate::boundary::handle::handles!(OceanSao);

#[cfg(test)]
#[path = "sao_tests.rs"]
mod tests;
