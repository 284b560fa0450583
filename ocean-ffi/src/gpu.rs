//! The GPU ocean renderer (crate `ocean-gpu`, Bruneton, Neyret & Holzschuch 2010) on the
//! library's own headless device: `OceanGpuContext` (adapter chosen by `WGPU_BACKEND`),
//! `OceanRenderer` (projected grid, filtered trochoids, Algorithm 5.1, sky) and a readback of
//! each frame as RGBA8 into the caller's buffer.
//!
//! An engine that draws with its own OpenGL (or Vulkan, D3D, Metal) pipeline uses the shader
//! export of `shader_export.rs` instead; this path is for tools, tests, thumbnails and engines
//! that composite a CPU-side image.

use core::ffi::c_char;
use std::ffi::CString;
use std::sync::atomic::{AtomicU64, Ordering};
use std::sync::{Arc, Mutex, MutexGuard, PoisonError};

use ocean_brdf::{Filter, FilteredSurface};
use ocean_gpu::{GpuContext, GpuError, OceanOptions, OceanRenderer as GpuRenderer};

use crate::boundary::OceanNext;
use crate::boundary::{
    borrow, byte_len, check_finite, check_flag, check_len, check_ptr, check_time, destroy,
    read_params, write_handle, write_out,
};
use crate::lighting::{OceanLighting, brdf_error};

use crate::camera::{OceanCamera, read_camera};
use crate::lighting_spectrum::OceanSpectrum;
use crate::status::{Error, OceanStatus, guard};
use crate::waves_domain::Reach;

/// A headless GPU device and queue that the library created (opaque). Create with
/// `ocean_gpu_context_create`, free with `ocean_gpu_context_destroy`. A
/// `const OceanGpuContext *` may be used by any number of threads at once.
pub struct OceanGpuContext {
    ctx: GpuContext,
    /// Distinguishes contexts, so a renderer refuses a context it was not created on.
    id: u64,
    /// `GpuContext::describe`, NUL-terminated.
    description: CString,
}

/// How an `OceanRenderer` draws. `ocean_renderer_options_default` fills in the library's
/// defaults. Colour is fixed to 8-bit RGBA (sRGB-encoded, tone-mapped) and the renderer draws
/// with a 32-bit float depth buffer of its own.
#[repr(C)]
#[derive(Clone, Copy, Debug, Default, PartialEq, bytemuck::Zeroable, bytemuck::Pod)]
pub struct OceanRendererOptions {
    /// Extensions: NULL, or the first extension struct (see `OceanChain`); the `_default`
    /// function sets NULL.
    pub next: OceanNext,
    /// Screen-space size of a projected-grid cell, pixels, in [1, 256] (the paper: 8). Smaller
    /// cells resolve shorter waves in the geometry and cost more vertices.
    pub cell_px: f64,
    /// How far the grid extends beyond the viewport on every side, as a fraction of the
    /// viewport's width (left and right) and height (top and bottom), in [0, 2]: large waves
    /// pull the grid's edges inwards, and the margin keeps them off screen.
    pub margin: f64,
    /// Distance cap of the rays' sea-plane hits, metres, in (0, 1e7]: rays above the horizon,
    /// or meeting the sea farther, stop there.
    pub max_distance: f64,
    /// Exposure of the tone mapping 1 - exp(-exposure * L), in (0, 1e6]
    /// (`OCEAN_DEFAULT_EXPOSURE` by default).
    pub exposure: f64,
    /// Level-0 size of the sky map texture, a power of two in [`OCEAN_SKY_MAP_MIN_SIZE`,
    /// `OCEAN_SKY_MAP_MAX_SIZE`] (and at most the device's largest texture).
    pub sky_map_size: u32,
    /// 1: draw the sky background (the sky map's radiance towards each pixel and the Sun's
    /// disc) behind the sea; 0: leave those pixels black (alpha 255). Other values are refused.
    pub draw_sky: u32,
}

/// The GPU ocean renderer (opaque): a projected screen-space grid displaced by the filtered
/// trochoids of a spectrum (Eq. 2), per-pixel filtered normals and slope variances (Eq. 3, 4)
/// lit by the Sun, the sky and the sea (Algorithm 5.1), tone-mapped, over a sky background.
///
/// Create with `ocean_renderer_create` on a context, give it a spectrum
/// (`ocean_renderer_set_spectrum`) and a lighting (`ocean_renderer_set_lighting`), then render
/// frames with `ocean_renderer_render_rgba8`. Free with `ocean_renderer_destroy`. It works
/// only with the context it was created on. Every call locks the renderer, so any thread may
/// use it, but calls on one renderer run one at a time.
pub struct OceanRenderer {
    /// `OceanGpuContext::id` of its context.
    context: u64,
    state: Mutex<RendererState>,
}

struct RendererState {
    renderer: GpuRenderer,
    /// The reach of the spectrum's waves, once one is set: bounds the time of a frame.
    reach: Option<Reach>,
    has_surface: bool,
    has_lighting: bool,
}

impl OceanGpuContext {
    /// The device and queue.
    pub(crate) fn context(&self) -> &GpuContext {
        &self.ctx
    }

    /// What distinguishes it from other contexts.
    pub(crate) fn id(&self) -> u64 {
        self.id
    }
}

impl OceanRenderer {
    fn lock(&self) -> MutexGuard<'_, RendererState> {
        // A panic inside a call (reported as OCEAN_STATUS_PANIC) poisons the lock; the renderer
        // stays usable, since each setter replaces its state only once everything succeeded.
        self.state.lock().unwrap_or_else(PoisonError::into_inner)
    }
}

const _: () = {
    const fn shareable<T: Send + Sync>() {}
    shareable::<OceanGpuContext>();
    shareable::<OceanRenderer>();
};

static NEXT_CONTEXT_ID: AtomicU64 = AtomicU64::new(1);

/// The error of a crate call as a status, with the crate's message (`?` converts).
impl From<GpuError> for Error {
    fn from(e: GpuError) -> Self {
        gpu_error("", e)
    }
}

/// The status of an `ocean-gpu` error, with its message prefixed by `context`.
pub(crate) fn gpu_error(context: &str, e: GpuError) -> Error {
    let status = match &e {
        GpuError::NoAdapter { .. }
        | GpuError::UnsuitableAdapter { .. }
        | GpuError::RequestDevice(_) => OceanStatus::NoAdapter,
        GpuError::Brdf(b) => return brdf_error(context, *b),
        GpuError::Wtb(w) => return crate::wtb_params::wtb_error(context, *w),
        GpuError::Sao(e) => return crate::sao::sao_error(context, *e),
        GpuError::Relief(e) => return crate::relief::relief_error(context, *e),
        GpuError::Eval(ocean_core::EvalError::Time(_)) => OceanStatus::NonFinite,
        GpuError::Eval(_)
        | GpuError::InvalidInput { .. }
        | GpuError::InvalidResource { .. }
        | GpuError::NotConfigured { .. }
        | GpuError::TooLarge { .. } => OceanStatus::InvalidArgument,
        _ => OceanStatus::GpuFailure,
    };
    Error::new(status, format!("{context}{e}"))
}

/// Creates a headless GPU device and stores a new context in `*out`.
///
/// The adapter is chosen from the environment: `WGPU_BACKEND` selects the backends (`vulkan`,
/// `gl`, `metal`, `dx12`, or a comma-separated list; all compiled in when unset),
/// `WGPU_POWER_PREF` (`low`, `high`) and `WGPU_ADAPTER_NAME` (a substring of the adapter's name)
/// narrow the choice. Software adapters are accepted: Mesa's lavapipe (Vulkan) and llvmpipe
/// (OpenGL through EGL, `WGPU_BACKEND=gl`). The device asks only for WebGPU's downlevel limits.
/// Creating a device takes from milliseconds to a second or so: create one context and keep it.
///
/// Returns `OCEAN_STATUS_NULL_POINTER` / `_MISALIGNED_POINTER` for a bad `out`,
/// `OCEAN_STATUS_NO_ADAPTER` when no usable adapter exists (the message says what to install),
/// `OCEAN_STATUS_GPU_FAILURE` for another device error. On failure `*out` is unchanged. Free
/// the context with `ocean_gpu_context_destroy`.
///
/// # Safety
///
/// `out` must point to a writable pointer.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn ocean_gpu_context_create(out: *mut *mut OceanGpuContext) -> OceanStatus {
    guard("ocean_gpu_context_create", || {
        check_ptr(out.cast_const(), "out")?;
        let ctx = GpuContext::headless()?;
        let description = CString::new(ctx.describe().replace('\0', " "))
            .expect("interior NUL bytes were replaced");
        let id = NEXT_CONTEXT_ID.fetch_add(1, Ordering::Relaxed);
        // SAFETY: forwarded from this function's contract.
        unsafe {
            write_handle(
                out,
                OceanGpuContext {
                    ctx,
                    id,
                    description,
                },
            )
        }
    })
}

/// Frees a context. NULL does nothing; a handle of another kind or already destroyed frees nothing
/// and sets the last-error message (see the header's notes on handles). Renderers created on it
/// keep the device alive until they are destroyed, but can no longer be used (every renderer call
/// needs the context).
#[unsafe(no_mangle)]
pub extern "C" fn ocean_gpu_context_destroy(ctx: *mut OceanGpuContext) {
    destroy(ctx, "ocean_gpu_context_destroy", "ctx");
}

/// Stores in `*out` a one-line, NUL-terminated UTF-8 description of the context's adapter
/// (name, backend, device type, driver), for logs and bug reports. The text is owned by the
/// context, fixed for its life and valid until it is destroyed, as the texts of an
/// `OceanShaderExport` are.
///
/// Returns `OCEAN_STATUS_NULL_POINTER` / `_MISALIGNED_POINTER` for a bad `ctx` or `out`, which
/// is then left unchanged.
///
/// # Safety
///
/// `out` must be writable and untouched by other threads during the call.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn ocean_gpu_context_describe(
    ctx: *const OceanGpuContext,
    out: *mut *const c_char,
) -> OceanStatus {
    guard("ocean_gpu_context_describe", || {
        let c = borrow(ctx, "ctx")?;
        // The text lives in the registry's entry, which stays until the context is destroyed.
        // SAFETY: forwarded from this function's contract.
        unsafe { write_out(out, "out", c.description.as_ptr()) }
    })
}

fn options_from_default() -> OceanRendererOptions {
    let d = OceanOptions::default();
    OceanRendererOptions {
        next: OceanNext::NULL,
        cell_px: d.cell_px,
        margin: d.margin,
        max_distance: d.max_distance,
        exposure: d.exposure,
        sky_map_size: d.sky_map_size,
        draw_sky: u32::from(d.draw_sky),
    }
}

/// Stores the default renderer options in `*out`: 8-pixel cells, a 10 % margin, a 50 km
/// distance cap, exposure `OCEAN_DEFAULT_EXPOSURE`, a 512 x 512 sky map, sky drawn.
///
/// Returns `OCEAN_STATUS_NULL_POINTER` (or `_MISALIGNED_POINTER`) for a bad `out`, which is
/// then left unchanged.
///
/// # Safety
///
/// `out` must be writable.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn ocean_renderer_options_default(
    out: *mut OceanRendererOptions,
) -> OceanStatus {
    guard("ocean_renderer_options_default", || {
        // SAFETY: forwarded from this function's contract.
        unsafe { write_out(out, "out", options_from_default()) }
    })
}

fn options_to_gpu(o: &OceanRendererOptions) -> Result<OceanOptions, Error> {
    check_finite(
        "options->",
        &[
            ("cell_px", o.cell_px),
            ("margin", o.margin),
            ("max_distance", o.max_distance),
            ("exposure", o.exposure),
        ],
    )?;
    let draw_sky = check_flag("options->draw_sky", o.draw_sky)?;
    Ok(OceanOptions {
        color_format: ocean_gpu::wgpu::TextureFormat::Rgba8Unorm,
        depth_format: Some(ocean_gpu::wgpu::TextureFormat::Depth32Float),
        cell_px: o.cell_px,
        margin: o.margin,
        max_distance: o.max_distance,
        sky_map_size: o.sky_map_size,
        exposure: o.exposure,
        draw_sky,
    })
}

/// Compiles the renderer's shaders and creates its buffers and textures on `ctx`'s device, and
/// stores a new renderer in `*out`. It draws nothing until it has a spectrum and a lighting.
///
/// Returns `OCEAN_STATUS_NULL_POINTER` / `_MISALIGNED_POINTER` for a bad pointer,
/// `OCEAN_STATUS_NON_FINITE` for a NaN or infinite option, `OCEAN_STATUS_INVALID_ARGUMENT` for
/// an option outside its documented range (the message names it), `OCEAN_STATUS_GPU_FAILURE` if
/// the device refuses an object. On failure `*out` is unchanged. Free the renderer with
/// `ocean_renderer_destroy`.
///
/// # Safety
///
/// `options` point to a readable `OceanRendererOptions` and `out`
/// to a writable pointer; `options` is not retained.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn ocean_renderer_create(
    ctx: *const OceanGpuContext,
    options: *const OceanRendererOptions,
    out: *mut *mut OceanRenderer,
) -> OceanStatus {
    guard("ocean_renderer_create", || {
        let c = borrow(ctx, "ctx")?;
        // SAFETY: forwarded from this function's contract.
        let o = unsafe { read_params(options, "options") }?;
        check_ptr(out.cast_const(), "out")?;
        let options = options_to_gpu(&o)?;
        let renderer = GpuRenderer::new(&c.ctx, options).map_err(|e| gpu_error("options: ", e))?;
        let value = OceanRenderer {
            context: c.id,
            state: Mutex::new(RendererState {
                renderer,
                reach: None,
                has_surface: false,
                has_lighting: false,
            }),
        };
        // SAFETY: forwarded from this function's contract.
        unsafe { write_handle(out, value) }
    })
}

/// Frees a renderer and its GPU resources. NULL does nothing; a handle of another kind or already
/// destroyed frees nothing and sets the last-error message (see the header's notes on handles). It
/// may outlive its context.
#[unsafe(no_mangle)]
pub extern "C" fn ocean_renderer_destroy(renderer: *mut OceanRenderer) {
    destroy(renderer, "ocean_renderer_destroy", "renderer");
}

/// Borrows a renderer and its context, checking that the renderer was created on it.
fn renderer_and_context(
    renderer: *const OceanRenderer,
    ctx: *const OceanGpuContext,
) -> Result<(Arc<OceanRenderer>, Arc<OceanGpuContext>), Error> {
    let r = borrow(renderer, "renderer")?;
    let c = borrow(ctx, "ctx")?;
    if r.context != c.id {
        return Err(Error::new(
            OceanStatus::InvalidArgument,
            "`renderer` was created on another context: pass the OceanGpuContext given to \
             ocean_renderer_create",
        ));
    }
    Ok((r, c))
}

/// Gives the renderer the waves of `spectrum`, filtered with the thresholds `n_min` and
/// `n_max` (paper section 7.1: a wave enters the geometry once its wavelength spans n_min grid
/// cells and is fully present from n_max, and likewise in the normals per pixel; the rest goes
/// into the BRDF's slope variance). `OCEAN_FILTER_N_MIN` and `OCEAN_FILTER_N_MAX` are the
/// paper's. The waves are copied: the spectrum may be destroyed afterwards.
///
/// Returns `OCEAN_STATUS_NULL_POINTER` / `_MISALIGNED_POINTER` for a bad pointer,
/// `OCEAN_STATUS_NON_FINITE` for a NaN or infinite threshold, `OCEAN_STATUS_INVALID_ARGUMENT`
/// unless 0 < n_min < n_max <= 1e6, for more waves than the device's largest texture is wide,
/// or for a context other than the renderer's; `OCEAN_STATUS_GPU_FAILURE` for a device error.
/// On failure the renderer keeps its previous spectrum.
#[unsafe(no_mangle)]
pub extern "C" fn ocean_renderer_set_spectrum(
    renderer: *mut OceanRenderer,
    ctx: *const OceanGpuContext,
    spectrum: *const OceanSpectrum,
    n_min: f64,
    n_max: f64,
) -> OceanStatus {
    guard("ocean_renderer_set_spectrum", || {
        let (r, c) = renderer_and_context(renderer, ctx)?;
        let s = borrow(spectrum, "spectrum")?;
        check_finite("", &[("n_min", n_min), ("n_max", n_max)])?;
        let filter = Filter::new(n_min, n_max)?;
        let surface = FilteredSurface::new(&s.spectrum, filter)?;
        let reach = Reach::of_spectrum(&s.spectrum)?;
        let mut state = r.lock();
        state.renderer.set_surface(&c.ctx, &surface)?;
        state.has_surface = true;
        state.reach = Some(reach);
        Ok(())
    })
}

/// Gives the renderer the Sun, the sky and the sea of `lighting`: renders its sky map at
/// `options->sky_map_size` with every mip level (as `ocean_lighting_sky_map_create`) and
/// uploads it, and keeps the Sun's and the sea's radiances. The lighting is copied: it may be
/// destroyed afterwards.
///
/// Returns `OCEAN_STATUS_NULL_POINTER` / `_MISALIGNED_POINTER` for a bad pointer,
/// `OCEAN_STATUS_INVALID_ARGUMENT` for a context other than the renderer's or a radiance beyond
/// binary16's range (65504: scale the radiance unit down), `OCEAN_STATUS_GPU_FAILURE` for a
/// device error. On failure the renderer keeps its previous lighting.
#[unsafe(no_mangle)]
pub extern "C" fn ocean_renderer_set_lighting(
    renderer: *mut OceanRenderer,
    ctx: *const OceanGpuContext,
    lighting: *const OceanLighting,
) -> OceanStatus {
    guard("ocean_renderer_set_lighting", || {
        let (r, c) = renderer_and_context(renderer, ctx)?;
        let l = borrow(lighting, "lighting")?;
        let mut state = r.lock();
        state.renderer.set_lighting(&c.ctx, &l.lighting)?;
        state.has_lighting = true;
        Ok(())
    })
}

/// Renders the sea and the sky seen by `camera` at `time` (seconds) into a `width` x `height`
/// image on the GPU, waits for it and copies it into `out`.
///
/// Format: `len` = width * height * 4 bytes exactly; rows from the top of the image, each
/// `width` pixels of R, G, B, A bytes from left to right, tightly packed (no row padding).
/// Colours are tone-mapped (1 - exp(-exposure * L)) and sRGB-encoded: display-ready bytes for
/// an `SRGB8_ALPHA8` texture or a plain image file. Alpha is 255. `camera` is an `OceanCamera`
/// above the sea (world space right-handed with y up, the sea at rest on y = 0), in any depth
/// convention (the image does not depend on it, but for the depth range the renderer folds it
/// into); its projection's aspect P11/P00 should be width / height for undistorted pixels.
///
/// The sky is drawn where the sea is not (`options->draw_sky`); the grid covers the viewport
/// plus the margin. Each call allocates its targets and waits for the GPU: a one-off, not a
/// frame loop at full speed.
///
/// Returns `OCEAN_STATUS_NULL_POINTER` / `_MISALIGNED_POINTER` for a bad pointer,
/// `OCEAN_STATUS_EMPTY` if `width` or `height` is 0, `OCEAN_STATUS_LENGTH_MISMATCH` if `len`
/// is not width * height * 4, `OCEAN_STATUS_INVALID_ARGUMENT` if a side exceeds the device's
/// largest texture, the camera is out of its documented ranges or not above the sea
/// (eye y <= 0), the context is not the renderer's, or the renderer has no spectrum or no
/// lighting yet; `OCEAN_STATUS_LENGTH_OVERFLOW` if
/// width * height * 4 overflows; `OCEAN_STATUS_NON_FINITE` for a NaN or infinite `time` or
/// camera member; `OCEAN_STATUS_INVALID_ARGUMENT` for a `time` whose phase leaves the domain
/// of `ocean_waves_evaluate` (|omega t| of the fastest wave above 1e15 rad);
/// `OCEAN_STATUS_GPU_FAILURE` for a device error. Nothing is written to `out` on failure.
///
/// # Safety
///
/// `camera` readable, and `out` point to `len`
/// writable bytes that no other thread touches during the call.
#[unsafe(no_mangle)]
#[allow(clippy::too_many_arguments)]
pub unsafe extern "C" fn ocean_renderer_render_rgba8(
    renderer: *const OceanRenderer,
    ctx: *const OceanGpuContext,
    camera: *const OceanCamera,
    time: f64,
    width: u32,
    height: u32,
    out: *mut u8,
    len: usize,
) -> OceanStatus {
    guard("ocean_renderer_render_rgba8", || {
        let (r, c) = renderer_and_context(renderer, ctx)?;
        check_ptr(camera, "camera")?;
        check_ptr(out.cast_const(), "out")?;
        if width == 0 || height == 0 {
            return Err(Error::new(
                OceanStatus::Empty,
                format!("the image is {width} x {height} pixels: both sizes must be >= 1"),
            ));
        }
        let want = usize::try_from(u64::from(width) * u64::from(height))
            .ok()
            .and_then(|n| n.checked_mul(4))
            .ok_or_else(|| {
                Error::new(
                    OceanStatus::LengthOverflow,
                    format!("{width} x {height} x 4 bytes overflow size_t"),
                )
            })?;
        byte_len::<u8>(want, "out")?;
        check_len(
            "len",
            len,
            want,
            &format!("a {width} x {height} RGBA8 image (bytes)"),
        )?;
        check_time(time)?;
        // SAFETY: forwarded from this function's contract (the pointer checked above).
        let camera = unsafe { read_camera(camera) }?;
        let eye = camera.eye();
        if eye.y <= 0.0 {
            return Err(Error::new(
                OceanStatus::InvalidArgument,
                format!(
                    "the camera's eye at ({}, {}, {}) must be above the sea (y > 0)",
                    eye.x, eye.y, eye.z
                ),
            ));
        }
        let state = r.lock();
        let Some(reach) = state.reach.filter(|_| state.has_surface) else {
            return Err(Error::new(
                OceanStatus::InvalidArgument,
                "the renderer has no spectrum yet: call ocean_renderer_set_spectrum first",
            ));
        };
        reach.check_time(time)?;
        if !state.has_lighting {
            return Err(Error::new(
                OceanStatus::InvalidArgument,
                "the renderer has no lighting yet: call ocean_renderer_set_lighting first",
            ));
        }
        let image = state
            .renderer
            .render_image(&c.ctx, &camera, time, width, height)?;
        drop(state);
        if image.len() != want {
            return Err(Error::new(
                OceanStatus::GpuFailure,
                format!("the readback holds {} bytes, expected {want}", image.len()),
            ));
        }
        // SAFETY: non-NULL (checked; `u8` needs no alignment), `len` = `want` bytes whose size
        // fits in isize (checked), writable and untouched by others (caller's guarantee).
        let out = unsafe { core::slice::from_raw_parts_mut(out, len) };
        out.copy_from_slice(&image);
        Ok(())
    })
}

crate::boundary::chain::extensible!(OceanRendererOptions);

crate::boundary::handle::handles!(OceanGpuContext, OceanRenderer);

#[cfg(test)]
mod tests {
    use super::*;
    use crate::lighting::{
        OceanSeaParams, OceanSkyParams, ocean_lighting_create, ocean_lighting_destroy,
        ocean_sea_params_default, ocean_sky_params_default,
    };
    use crate::lighting_spectrum::{
        OceanSpectrumParams, ocean_spectrum_create, ocean_spectrum_destroy,
        ocean_spectrum_params_default,
    };

    use crate::status::last_error;

    #[test]
    fn default_options_are_the_crates() {
        let mut o = OceanRendererOptions::default();
        // SAFETY: writable.
        let s = unsafe { ocean_renderer_options_default(&mut o) };
        assert_eq!(s, OceanStatus::Ok);
        let back = options_to_gpu(&o).unwrap();
        assert_eq!(back, OceanOptions::default());
        let bad = OceanRendererOptions { draw_sky: 2, ..o };
        let e = options_to_gpu(&bad).unwrap_err();
        assert_eq!(e.status, OceanStatus::InvalidArgument);
        let bad = OceanRendererOptions {
            exposure: f64::NAN,
            ..o
        };
        assert_eq!(
            options_to_gpu(&bad).unwrap_err().status,
            OceanStatus::NonFinite
        );
    }

    #[test]
    fn gpu_errors_get_their_statuses() {
        let no = GpuError::NoAdapter {
            backends: "vulkan".into(),
            reason: "none".into(),
        };
        let e = gpu_error("", no);
        assert_eq!(e.status, OceanStatus::NoAdapter);
        assert!(e.message.contains("mesa-vulkan-drivers"), "{}", e.message);
        let e = gpu_error("", GpuError::Wgpu("lost".into()));
        assert_eq!(e.status, OceanStatus::GpuFailure);
        let e = gpu_error(
            "",
            GpuError::Eval(ocean_core::EvalError::Time(f64::INFINITY)),
        );
        assert_eq!(e.status, OceanStatus::NonFinite);
    }

    #[test]
    fn null_handles_are_refused_without_a_device() {
        let mut text = c"untouched".as_ptr();
        // SAFETY: every pointer is NULL or valid.
        unsafe {
            let s = ocean_gpu_context_describe(core::ptr::null(), &mut text);
            assert_eq!(s, OceanStatus::NullPointer);
            assert_eq!(core::ffi::CStr::from_ptr(text), c"untouched");
            assert!(last_error().contains("ctx"), "{}", last_error());
            let s = ocean_gpu_context_create(core::ptr::null_mut());
            assert_eq!(s, OceanStatus::NullPointer);
            let mut buf = [9u8; 16];
            let s = ocean_renderer_render_rgba8(
                core::ptr::null(),
                core::ptr::null(),
                core::ptr::null(),
                0.0,
                2,
                2,
                buf.as_mut_ptr(),
                16,
            );
            assert_eq!(s, OceanStatus::NullPointer);
            assert_eq!(buf, [9u8; 16]);
            ocean_gpu_context_destroy(core::ptr::null_mut());
            ocean_renderer_destroy(core::ptr::null_mut());
        }
    }

    /// The context, or `None` when no adapter exists (a failure under `OCEAN_REQUIRE_GPU=1`).
    fn context() -> Option<*mut OceanGpuContext> {
        let mut ctx = core::ptr::null_mut();
        // SAFETY: writable out.
        let s = unsafe { ocean_gpu_context_create(&mut ctx) };
        if s == OceanStatus::NoAdapter
            && std::env::var("OCEAN_REQUIRE_GPU").map_or(true, |v| v.trim() != "1")
        {
            eprintln!("SKIPPED: {}", last_error());
            return None;
        }
        assert_eq!(s, OceanStatus::Ok, "{}", last_error());
        Some(ctx)
    }

    /// The wrapper adds nothing: the image is `ocean_gpu`'s own for the same inputs, byte for
    /// byte, and the description is the context's.
    #[test]
    fn renders_what_ocean_gpu_renders() {
        let Some(ctx) = context() else { return };
        let (w, h) = (32u32, 24u32);
        let mut opts = OceanRendererOptions::default();
        let mut sp = OceanSpectrumParams::default();
        let mut sky = OceanSkyParams::default();
        let mut sea = OceanSeaParams::default();
        let (mut r, mut spectrum, mut lighting) = (
            core::ptr::null_mut(),
            core::ptr::null_mut(),
            core::ptr::null_mut(),
        );
        let view = ocean_core::camera::look_at(
            glam::DVec3::new(0.0, 4.0, 0.0),
            glam::DVec3::new(0.0, 4.0, -1.0),
            glam::DVec3::Y,
        )
        .unwrap();
        let cam = OceanCamera::from_camera(
            &ocean_core::Camera::new(
                view,
                ocean_core::Projection::Perspective {
                    fov_y: 1.0,
                    aspect: f64::from(w) / f64::from(h),
                    near: 0.1,
                    far: ocean_core::Far::Finite(1e5),
                },
                ocean_core::camera::DepthConvention::ZERO_TO_ONE,
            )
            .unwrap(),
        );
        let mut image = vec![0u8; (w * h * 4) as usize];
        // SAFETY: live handles and valid pointers throughout.
        unsafe {
            let mut text = core::ptr::null();
            let s = ocean_gpu_context_describe(ctx, &mut text);
            assert_eq!(s, OceanStatus::Ok, "{}", last_error());
            assert_eq!(
                core::ffi::CStr::from_ptr(text).to_str().unwrap(),
                crate::boundary::borrow(ctx, "ctx").unwrap().ctx.describe()
            );
            assert_eq!(
                ocean_gpu_context_describe(ctx, core::ptr::null_mut()),
                OceanStatus::NullPointer
            );

            assert_eq!(ocean_renderer_options_default(&mut opts), OceanStatus::Ok);
            opts.sky_map_size = 64;
            let s = ocean_renderer_create(ctx, &opts, &mut r);
            assert_eq!(s, OceanStatus::Ok, "{}", last_error());
            let s = ocean_renderer_render_rgba8(
                r,
                ctx,
                &cam,
                1.5,
                w,
                h,
                image.as_mut_ptr(),
                image.len(),
            );
            assert_eq!(s, OceanStatus::InvalidArgument);
            assert!(last_error().contains("no spectrum"), "{}", last_error());

            ocean_spectrum_params_default(&mut sp);
            assert_eq!(ocean_spectrum_create(&sp, &mut spectrum), OceanStatus::Ok);
            ocean_sky_params_default(&mut sky);
            ocean_sea_params_default(&mut sea);
            assert_eq!(
                ocean_lighting_create(&sky, &sea, &mut lighting),
                OceanStatus::Ok
            );
            let s = ocean_renderer_set_spectrum(r, ctx, spectrum, 1.0, 2.5);
            assert_eq!(s, OceanStatus::Ok, "{}", last_error());
            let s = ocean_renderer_set_lighting(r, ctx, lighting);
            assert_eq!(s, OceanStatus::Ok, "{}", last_error());
            let s = ocean_renderer_render_rgba8(
                r,
                ctx,
                &cam,
                1.5,
                w,
                h,
                image.as_mut_ptr(),
                image.len(),
            );
            assert_eq!(s, OceanStatus::Ok, "{}", last_error());
        }
        let c = GpuContext::headless().unwrap();
        let mut gpu = GpuRenderer::new(&c, options_to_gpu(&opts).unwrap()).unwrap();
        let spectrum_core =
            ocean_brdf::Spectrum::new(ocean_brdf::SpectrumParams::default()).unwrap();
        let surface = FilteredSurface::new(&spectrum_core, Filter::PAPER).unwrap();
        gpu.set_surface(&c, &surface).unwrap();
        let lighting_core = ocean_brdf::Lighting::new(
            ocean_brdf::SkyParams::default(),
            ocean_brdf::SeaParams::default(),
        )
        .unwrap();
        gpu.set_lighting(&c, &lighting_core).unwrap();
        let want = gpu
            .render_image(&c, &crate::camera::camera_from(&cam).unwrap(), 1.5, w, h)
            .unwrap();
        assert!(image == want, "the C ABI's image differs from ocean_gpu's");
        assert!(image.chunks_exact(4).all(|p| p[3] == 255));
        ocean_renderer_destroy(r);
        ocean_lighting_destroy(lighting);
        ocean_spectrum_destroy(spectrum);
        ocean_gpu_context_destroy(ctx);
    }
}
