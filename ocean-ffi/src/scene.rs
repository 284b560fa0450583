//! The composed scene of `ocean render` (crate `ocean-scene`) through the C ABI: a scene
//! description in TOML (the built-in one from `ocean_scene_builtin_description`, or the
//! caller's), built once into an `OceanScene` on an `OceanGpuContext`, and its frames rendered
//! into the caller's RGBA8 buffer: the open sea and its sky, the island with the wave train
//! boxes that reach its shore, relief-mapped rocks and pier, ambient obscurance and the
//! composition, exactly as `ocean render` draws them.

use core::ffi::c_char;
use std::ffi::CString;
use std::sync::{LazyLock, Mutex, MutexGuard, PoisonError};

use ocean_scene::renderer::RenderOptions;
use ocean_scene::{Preset, SceneDescription, SceneError, SceneRenderer};

use crate::boundary::OceanNext;
use crate::boundary::{
    CEnum, borrow, byte_len, check_enum, check_len, check_ptr, check_time, destroy, input,
    read_params, write_handle, write_out,
};
use crate::gpu::{OceanGpuContext, gpu_error};
use crate::status::{Error, OceanStatus, guard};

/// The camera a scene's frames are seen from (`OceanSceneOptions::camera`, a `uint32_t`).
#[repr(u32)]
#[derive(
    Clone, Copy, Debug, Default, PartialEq, Eq, bytemuck::NoUninit, bytemuck::CheckedBitPattern,
)]
pub enum OceanSceneCamera {
    /// The description's `[camera]` section.
    #[default]
    Description = 0,
    /// 6 m above the water, looking 8 degrees down.
    Shore = 1,
    /// 4 m above the water, looking at the horizon.
    Horizon = 2,
    /// 120 m up, looking 30 degrees down.
    High = 3,
    /// 10 m up, circling the point 40 m ahead once a minute of scene time, looking at it.
    Orbit = 4,
}

impl CEnum for OceanSceneCamera {
    const REFUSAL: &'static str = "is not an OceanSceneCamera (0 to 4)";
}

impl OceanSceneCamera {
    fn preset(self) -> Option<Preset> {
        match self {
            Self::Description => None,
            Self::Shore => Some(Preset::Shore),
            Self::Horizon => Some(Preset::Horizon),
            Self::High => Some(Preset::High),
            Self::Orbit => Some(Preset::Orbit),
        }
    }
}

/// How `ocean_scene_create` builds a scene: overrides of the description's `[render]` and
/// `[camera]` sections. `ocean_scene_options_default` keeps the description's everywhere.
#[repr(C)]
#[derive(Clone, Copy, Debug, Default, PartialEq, bytemuck::Zeroable, bytemuck::Pod)]
pub struct OceanSceneOptions {
    /// Extensions: NULL, or the first extension struct (see `OceanChain`); the `_default`
    /// function sets NULL.
    pub next: OceanNext,
    /// Frame width in pixels; 0: the description's `[render] width`. The description's limits
    /// apply (1 to 8192).
    pub width: u32,
    /// Frame height in pixels; 0: the description's `[render] height` (1 to 8192).
    pub height: u32,
    /// Samples per pixel, 1 or 4; 0: the description's `[render] samples`. Where the device
    /// cannot draw multisampled targets (OpenGL), one.
    pub samples: u32,
    /// An `OceanSceneCamera`.
    pub camera: u32,
}

/// A scene built on a GPU context (opaque): every renderer, texture and wave train box of a
/// scene description, made once. Create with `ocean_scene_create`, render frames with
/// `ocean_scene_render_rgba8`, free with `ocean_scene_destroy`. It works only with the context
/// it was created on. Every call locks the scene, so any thread may use it, but calls on one
/// scene run one at a time.
pub struct OceanScene {
    /// `OceanGpuContext::id` of its context.
    context: u64,
    renderer: Mutex<SceneRenderer>,
}

impl OceanScene {
    fn lock(&self) -> MutexGuard<'_, SceneRenderer> {
        // A frame that fails leaves the renderer as it was: its next frame starts afresh.
        self.renderer.lock().unwrap_or_else(PoisonError::into_inner)
    }
}

const _: () = {
    const fn shareable<T: Send + Sync>() {}
    shareable::<OceanScene>();
};

/// The status of a scene error, with its message.
fn scene_error(e: SceneError) -> Error {
    match e {
        SceneError::Gpu(e) => gpu_error("", e),
        e => Error::new(OceanStatus::InvalidArgument, e.to_string()),
    }
}

/// The built-in scene description, NUL-terminated, for the life of the process.
static BUILTIN: LazyLock<CString> = LazyLock::new(|| {
    CString::new(ocean_scene::DEFAULT_SCENE).expect("the built-in scene holds no NUL byte")
});

/// Stores in `*out` the built-in scene description: NUL-terminated UTF-8 TOML, owned by the
/// library and valid for the life of the process. It is the reference of the format (every key
/// commented) and what `ocean render` draws without `--scene`; pass it to `ocean_scene_create`
/// with `strlen` as its length, or edit a copy.
///
/// Returns `OCEAN_STATUS_NULL_POINTER` / `_MISALIGNED_POINTER` for a bad `out`, which is then
/// left unchanged.
///
/// # Safety
///
/// `out` must be writable and untouched by other threads during the call.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn ocean_scene_builtin_description(out: *mut *const c_char) -> OceanStatus {
    guard("ocean_scene_builtin_description", || {
        // SAFETY: forwarded from this function's contract.
        unsafe { write_out(out, "out", BUILTIN.as_ptr()) }
    })
}

/// Stores the default scene options in `*out`: every member 0 (the description's size, samples
/// and camera), `next` NULL.
///
/// Returns `OCEAN_STATUS_NULL_POINTER` (or `_MISALIGNED_POINTER`) for a bad `out`, which is
/// then left unchanged.
///
/// # Safety
///
/// `out` must be writable and untouched by other threads during the call.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn ocean_scene_options_default(out: *mut OceanSceneOptions) -> OceanStatus {
    guard("ocean_scene_options_default", || {
        // SAFETY: forwarded from this function's contract.
        unsafe { write_out(out, "out", OceanSceneOptions::default()) }
    })
}

/// Parses the scene description `text` (`len` bytes of UTF-8 TOML, no NUL needed), builds
/// everything its frames are drawn with on `ctx` (spectrum and filtering, sky map, island and
/// wave train boxes, terrain, rocks and pier with their cone maps, obscurance, targets) and
/// stores the scene in `*out`. Cone maps are read from and written to the cache of
/// `ocean render` (`$OCEAN_CACHE_DIR`, else `$XDG_CACHE_HOME/ocean`, else
/// `$HOME/.cache/ocean`) when there is one; a cache that cannot be written costs only time.
///
/// Returns `OCEAN_STATUS_NULL_POINTER` / `_MISALIGNED_POINTER` for a bad pointer,
/// `OCEAN_STATUS_INVALID_HANDLE` for a bad `ctx`, `OCEAN_STATUS_EMPTY` if `len` is 0,
/// `OCEAN_STATUS_INVALID_ARGUMENT` for text that is not UTF-8, a description that does not
/// parse or is out of range (the message names the line and the key), an option out of range,
/// or a piece that cannot be built from it (the message names it); `OCEAN_STATUS_NO_ADAPTER` /
/// `_GPU_FAILURE` for a device error. On failure `*out` is unchanged. Building takes from a
/// fraction of a second to seconds (cone maps not in the cache).
///
/// # Safety
///
/// `text` must point to `len` readable bytes, `options` to a readable `OceanSceneOptions` and
/// `out` to a writable pointer; neither `text` nor `options` is retained.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn ocean_scene_create(
    ctx: *const OceanGpuContext,
    text: *const c_char,
    len: usize,
    options: *const OceanSceneOptions,
    out: *mut *mut OceanScene,
) -> OceanStatus {
    guard("ocean_scene_create", || {
        let c = borrow(ctx, "ctx")?;
        // SAFETY: forwarded from this function's contract.
        let bytes = unsafe { input(text.cast::<u8>(), len, "text") }?;
        // SAFETY: as above.
        let o = unsafe { read_params(options, "options") }?;
        check_ptr(out.cast_const(), "out")?;
        if bytes.is_empty() {
            // Empty TOML is a valid document (every section at its default): refused, so that
            // a length forgotten as 0 does not silently draw the open sea.
            return Err(Error::new(
                OceanStatus::Empty,
                "text is empty (len = 0): pass a scene description, e.g. \
                 ocean_scene_builtin_description's",
            ));
        }
        let camera: OceanSceneCamera = check_enum("options->camera", o.camera)?;
        let text = std::str::from_utf8(bytes).map_err(|e| {
            Error::new(
                OceanStatus::InvalidArgument,
                format!("text is not UTF-8: {e}"),
            )
        })?;
        let mut scene =
            SceneDescription::parse(text, "the scene description").map_err(scene_error)?;
        if o.width != 0 {
            scene.render.width = o.width;
        }
        if o.height != 0 {
            scene.render.height = o.height;
        }
        let options = RenderOptions {
            preset: camera.preset(),
            samples: (o.samples != 0).then_some(o.samples),
            read_depth: false,
        };
        let renderer = SceneRenderer::with_context(c.context().clone(), &scene, options).map_err(
            |e| match e {
                SceneError::Description(why) => Error::new(
                    OceanStatus::InvalidArgument,
                    format!("options or description: {why}"),
                ),
                e => scene_error(e),
            },
        )?;
        let value = OceanScene {
            context: c.id(),
            renderer: Mutex::new(renderer),
        };
        // SAFETY: forwarded from this function's contract.
        unsafe { write_handle(out, value) }
    })
}

/// Frees a scene and its GPU resources. NULL does nothing; a handle of another kind or already
/// destroyed frees nothing and sets the last-error message (see the header's notes on handles).
/// It may outlive its context.
#[unsafe(no_mangle)]
pub extern "C" fn ocean_scene_destroy(scene: *mut OceanScene) {
    destroy(scene, "ocean_scene_destroy", "scene");
}

/// Stores the size of the scene's frames in pixels in `*width` and `*height`: the description's
/// `[render]` size, or the options' overrides.
///
/// Returns `OCEAN_STATUS_NULL_POINTER` / `_MISALIGNED_POINTER` for a bad pointer,
/// `OCEAN_STATUS_INVALID_HANDLE` for a bad `scene`. On failure nothing is written.
///
/// # Safety
///
/// `width` and `height` must be writable and untouched by other threads during the call.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn ocean_scene_size(
    scene: *const OceanScene,
    width: *mut u32,
    height: *mut u32,
) -> OceanStatus {
    guard("ocean_scene_size", || {
        let s = borrow(scene, "scene")?;
        check_ptr(width.cast_const(), "width")?;
        check_ptr(height.cast_const(), "height")?;
        let (w, h) = s.lock().size();
        // SAFETY: forwarded from this function's contract (both checked above, so the first
        // write cannot be left alone by a failing second).
        unsafe { write_out(width, "width", w) }?;
        // SAFETY: as above.
        unsafe { write_out(height, "height", h) }
    })
}

/// Renders the scene's frame at scene `time` (seconds) on the GPU: the wave train boxes
/// marched to `time` on the CPU, then the sea, the island, the rocks and the pier, their
/// ambient obscurance and the composition, as `ocean render` draws the same description; waits
/// for it and copies it into `out`.
///
/// Format: `len` = width * height * 4 bytes exactly (`ocean_scene_size`); rows from the top of
/// the image, each `width` pixels of R, G, B, A bytes from left to right, tightly packed.
/// Colours are tone-mapped and sRGB-encoded (display-ready bytes for an `SRGB8_ALPHA8` texture
/// or an image file); alpha is 255.
///
/// Returns `OCEAN_STATUS_NULL_POINTER` / `_MISALIGNED_POINTER` for a bad `out`,
/// `OCEAN_STATUS_INVALID_HANDLE` for a bad `scene` or `ctx`, `OCEAN_STATUS_LENGTH_MISMATCH` if
/// `len` is not width * height * 4, `OCEAN_STATUS_NON_FINITE` for a NaN or infinite `time`,
/// `OCEAN_STATUS_INVALID_ARGUMENT` for a context other than the scene's or a `time` at which
/// the camera or the wave trains cannot be evaluated, `OCEAN_STATUS_GPU_FAILURE` for a device
/// error. Nothing is written to `out` on failure.
///
/// # Safety
///
/// `out` must point to `len` writable bytes that no other thread touches during the call.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn ocean_scene_render_rgba8(
    scene: *const OceanScene,
    ctx: *const OceanGpuContext,
    time: f64,
    out: *mut u8,
    len: usize,
) -> OceanStatus {
    guard("ocean_scene_render_rgba8", || {
        let s = borrow(scene, "scene")?;
        let c = borrow(ctx, "ctx")?;
        if s.context != c.id() {
            return Err(Error::new(
                OceanStatus::InvalidArgument,
                "`scene` was created on another context: pass the OceanGpuContext given to \
                 ocean_scene_create",
            ));
        }
        check_ptr(out.cast_const(), "out")?;
        check_time(time)?;
        let mut renderer = s.lock();
        let (width, height) = renderer.size();
        // Both sides are at most 8192 (the description's limit): no overflow.
        let want = width as usize * height as usize * 4;
        byte_len::<u8>(want, "out")?;
        check_len(
            "len",
            len,
            want,
            &format!("a {width} x {height} RGBA8 image (bytes)"),
        )?;
        let frame = renderer.frame(time, false).map_err(scene_error)?;
        drop(renderer);
        if frame.rgba.len() != want {
            return Err(Error::new(
                OceanStatus::GpuFailure,
                format!(
                    "the readback holds {} bytes, expected {want}",
                    frame.rgba.len()
                ),
            ));
        }
        // SAFETY: non-NULL (checked; `u8` needs no alignment), `len` = `want` bytes whose size
        // fits in isize (checked), writable and untouched by others (caller's guarantee).
        let out = unsafe { core::slice::from_raw_parts_mut(out, len) };
        out.copy_from_slice(&frame.rgba);
        Ok(())
    })
}

crate::boundary::chain::extensible!(OceanSceneOptions);

crate::boundary::handle::handles!(OceanScene);
