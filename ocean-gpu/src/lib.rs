//! # ocean-gpu
//!
//! The wgpu backend of the ocean crates:
//!
//! - [`GpuContext`]: a headless device (adapter chosen by `WGPU_BACKEND`, software adapters
//!   accepted), or a wrapper around the caller's own `wgpu::Device` and `wgpu::Queue`.
//! - [`readback`]: copying buffers and textures back to the CPU (with the 256-byte row padding
//!   of texture copies) and GPU timestamps ([`GpuTimer`]) where the adapter has them.
//! - [`shaders`]: every WGSL source of the crate, validated by naga and exportable to GLSL,
//!   GLSL ES, HLSL, MSL and SPIR-V with its binding layout listed.
//! - [`TrochoidPass`]: the trochoid (Gerstner) displacement of a grid as a compute pass, the GPU
//!   twin of [`ocean_core::WaveSet::evaluate_grid`].
//! - [`LayersPass`]: sums of wave sets modulated by complex amplitude fields over grid
//!   rectangles, plus an additive height field (the wave-train-box primitive), the GPU twin of
//!   [`ocean_core::evaluate_layers`]. It writes into the same [`TrochoidTarget`] buffers.
//! - [`WtbMarchPass`]: wave train boxes from an `ocean_wtb` plan, their wave rays marched on the
//!   GPU (one invocation per ray: land, shadows, shoaling, refraction) and evaluated by the
//!   layers pass; the GPU twin of `ocean_wtb::march::MarchBox::march` and `Frame::evaluate`.
//! - [`SaoPass`]: Scalable Ambient Obscurance (McGuire, Mara & Luebke 2012) from the caller's
//!   depth texture: z reconstruction (Eq. 2), the z MIP levels (Table 1), the spiral samples
//!   over them (Eq. 1, 3–10, the appendix's falloff) with the 2×2 quad bilateral, and the
//!   separable bilateral blur (§2.4), into an obscurance texture; the GPU twin of
//!   [`ocean_sao::Sao`], with per-pass timestamps ([`SaoTimer`]).
//! - [`OceanRenderer`]: the ocean surface renderer of Bruneton et al. (2010): a projected grid
//!   displaced by filtered trochoids, per-pixel filtered normals and slope variances lit by the
//!   Sun, the sky and the sea (Algorithm 5.1), and a sky background, into the caller's targets
//!   or a headless image; the GPU twin of `ocean_brdf`'s surface and sea colour.
//! - [`LightTargets`]: the split direct and ambient light of a frame that several renderers
//!   share, with one sample per pixel or [`MSAA_SAMPLES`] (antialiased; composed by
//!   [`OceanRenderer::compose`], which tone-maps each sample before averaging), and
//!   [`DepthResolve`], each pixel's nearest depth sample for single-sampled readers.
//! - [`ReliefRenderer`]: relief mapping by relaxed cone stepping (Policarpo & Oliveira, *GPU
//!   Gems 3* ch. 18): a relief-mapped quad traced per pixel (linear, cone step or relaxed cone
//!   stepping with the three binary searches), self-shadowed and writing the hit's depth, into
//!   the caller's targets or a headless image, with a probe of its tracer; and
//!   [`ConeMapGenerator`], relaxed and conservative cone maps generated in a compute pass; the
//!   GPU twins of `ocean_relief`'s tracers, shadow test, occlusion depth and
//!   `ConeMap::generate`.
//!
//! ## Conventions
//!
//! Metres, seconds, radians; right-handed, **y up**, the sea at rest is y = 0. Time is `f64`
//! seconds at every public boundary: wave phases are formed and reduced modulo 2π in `f64` on the
//! host, which uploads the sines and cosines of their per-row and per-column parts; the GPU only
//! combines those by angle addition, as the CPU grid kernel does. Grid outputs are positions
//! relative to the grid origin, row-major (point (i, j) is element `j * nx + i`).
//!
//! ## Errors
//!
//! Every fallible function returns [`GpuError`]; invalid input (an empty grid, a non-finite
//! time, a buffer too small or without the right usage, a grid beyond the device's limits) is
//! reported, never a panic. wgpu validation errors raised by this crate's own calls are caught
//! with error scopes and returned as [`GpuError::Wgpu`].
#![forbid(unsafe_code)]
#![warn(missing_docs)]

pub mod context;
mod depth_resolve;
pub mod layers;
mod light_targets;
pub mod ocean;
mod ocean_local;
mod pipeline;
pub mod readback;
pub mod relief;
pub mod sao;
pub mod shaders;
pub mod trochoid;
pub mod wtb;

pub use context::{ContextOptions, GpuContext};
pub use depth_resolve::DepthResolve;
pub use layers::{DeviceLayer, LayerDesc, LayersInput, LayersParams, LayersPass, LayersStats};
pub use light_targets::{LightTargets, MSAA_SAMPLES, RADIANCE_FORMAT};
pub use ocean::{
    ComposeInputs, FrameUniform, MeshGeometry, MeshGrid, OceanOptions, OceanRenderer,
    SeaColorInput, SurfaceProbe, WaveTexels, frame_uniform, fresnel_table_texels,
};
pub use readback::{GpuDuration, GpuTimer, TextureData};
pub use relief::{
    ConeGenTimes, ConeMapGenerator, ReliefImage, ReliefLayout, ReliefOptions, ReliefProbe,
    ReliefRay, ReliefRenderer, ReliefScene, TangentFrame, scene_uniforms,
};
pub use sao::{GpuZLevel, SaoPass, SaoStage, SaoStages, SaoTimer, SaoTimes};
pub use shaders::{Code, Export, ExportFile, Language, ShaderError};
pub use trochoid::{
    GridOutput, TrochoidInput, TrochoidParams, TrochoidPass, TrochoidStats, TrochoidTarget,
};
pub use wtb::{MarchParams, WtbMarchPass};

pub use naga;
pub use wgpu;

/// Why a GPU operation failed.
#[derive(Debug, thiserror::Error)]
#[non_exhaustive]
pub enum GpuError {
    /// No adapter matched the requested backends.
    #[error(
        "no GPU adapter found (backends: {backends}): {reason}. On a machine without a GPU, \
         install Mesa's software drivers (`apt-get install mesa-vulkan-drivers` for lavapipe on \
         Vulkan) or use Mesa's llvmpipe through EGL with `WGPU_BACKEND=gl`"
    )]
    NoAdapter {
        /// The backends that were searched, as `WGPU_BACKEND` would spell them.
        backends: String,
        /// What wgpu reported.
        reason: String,
    },
    /// The adapter cannot run this crate's passes.
    #[error("adapter {adapter:?} is unsuitable: {reason}")]
    UnsuitableAdapter {
        /// Adapter name.
        adapter: String,
        /// What it lacks.
        reason: String,
    },
    /// The device could not be created.
    #[error("could not create a device: {0}")]
    RequestDevice(#[from] wgpu::RequestDeviceError),
    /// A wgpu validation or out-of-memory error raised by one of this crate's calls.
    #[error("wgpu error: {0}")]
    Wgpu(String),
    /// Waiting for the GPU failed.
    #[error("waiting for the GPU failed: {0}")]
    Poll(#[from] wgpu::PollError),
    /// Mapping a buffer for reading failed.
    #[error("mapping a buffer for reading failed: {0}")]
    Map(#[from] wgpu::BufferAsyncError),
    /// The wave evaluation inputs are invalid (time, grid).
    #[error(transparent)]
    Eval(#[from] ocean_core::EvalError),
    /// A size exceeds what the device (or a 32-bit index) allows.
    #[error("{what} needs {needed}, but the limit is {limit}")]
    TooLarge {
        /// What was being sized.
        what: &'static str,
        /// The size needed.
        needed: u64,
        /// The limit.
        limit: u64,
    },
    /// A caller-provided resource does not fit the request.
    #[error("invalid {what}: {reason}")]
    InvalidResource {
        /// Which resource.
        what: &'static str,
        /// Why it does not fit.
        reason: String,
    },
    /// A shader could not be parsed, validated or translated.
    #[error(transparent)]
    Shader(#[from] ShaderError),
    /// An argument is outside its documented range (a viewport size, an option, a camera).
    #[error("invalid {what}: {reason}")]
    InvalidInput {
        /// Which argument.
        what: &'static str,
        /// Why it is refused.
        reason: String,
    },
    /// A call needs state that has not been given yet.
    #[error("no {what} yet: call {call} first")]
    NotConfigured {
        /// What is missing.
        what: &'static str,
        /// The call that provides it.
        call: &'static str,
    },
    /// The lighting or surface model refused its inputs.
    #[error(transparent)]
    Brdf(#[from] ocean_brdf::BrdfError),
    /// The wave-train-box model refused its inputs (a terrain of another grid, a box frame of
    /// another spacing).
    #[error(transparent)]
    Wtb(#[from] ocean_wtb::WtbError),
    /// The ambient obscurance set-up or its input refused (a depth slice of the wrong length,
    /// a depth value outside the convention's range).
    #[error(transparent)]
    Sao(#[from] ocean_sao::SaoError),
    /// The relief-mapping model refused its inputs (a step count out of range, a non-finite
    /// depth scale, a shadow bias outside `[0, 1]`, a cone cap out of range, a map size).
    #[error(transparent)]
    Relief(#[from] ocean_relief::ReliefError),
}

/// Runs `f` inside validation, out-of-memory and internal error scopes on `device` and returns
/// the first error a scope caught, so wgpu errors come back as values instead of reaching the
/// device's uncaptured-error handler (which panics by default).
pub(crate) fn scoped<R>(
    device: &wgpu::Device,
    f: impl FnOnce() -> Result<R, GpuError>,
) -> Result<R, GpuError> {
    let internal = device.push_error_scope(wgpu::ErrorFilter::Internal);
    let oom = device.push_error_scope(wgpu::ErrorFilter::OutOfMemory);
    let validation = device.push_error_scope(wgpu::ErrorFilter::Validation);
    let result = f();
    let validation = pollster::block_on(validation.pop());
    let oom = pollster::block_on(oom.pop());
    // Internal errors: a backend that cannot translate a shader (naga's GLSL writer).
    let internal = pollster::block_on(internal.pop());
    if let Some(e) = validation.or(oom).or(internal) {
        return Err(GpuError::Wgpu(e.to_string()));
    }
    result
}
