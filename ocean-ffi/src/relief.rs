//! Relief mapping by relaxed cone stepping (crate `ocean-relief`; Policarpo & Oliveira, *GPU
//! Gems 3* ch. 18), part 1 of 2: height maps from a caller's buffer, cone-map generation with a
//! progress callback and cancellation (into a handle or straight into a caller's buffer), the
//! storage encodings, mip chains and normal maps. Tracing and shadows are in `relief_trace.rs`.
//!
//! Conventions (ocean-relief's `map` module): the map is square, row-major, texel `(i, j)` at
//! element `j * N + i` with its centre at texture coordinates `((i + 0.5)/N, (j + 0.5)/N)`; the
//! inputs are **heights** (1 = the polygon surface, 0 = the bottom), stored as the book's
//! **depths** `1 - height`; the surface the tracers see is the bilinear interpolation of the
//! texel depths. Cone values are in texture widths (per unit of depth for the ratio `c` and the
//! near cap `E`, plain texture widths for the clearance `D`).

use crate::relief_encode::{check_encoded_out, encode_cones, texels, write_encoded};
use core::ffi::{c_int, c_void};

use ocean_relief::storage::Encoding;
use ocean_relief::{
    ConeKind, ConeMap, ConeParams, Edge, HeightMap, HeightRange, ReliefError, ReliefTexture,
};

use crate::boundary::OceanNext;
use crate::boundary::{
    CheckedStruct, EnumField, borrow, check_enum, check_len, check_ptr, destroy, input,
    read_params_checked, write_handle, write_out, write_slice,
};
use crate::camera::camera_status;
pub use crate::relief_enums::{
    OceanReliefConeKind, OceanReliefEdge, OceanReliefEncoding, OceanReliefMip, OceanReliefRange,
};
use crate::status::{Error, OceanStatus, guard};

/// The smallest side of a height map, texels (a bilinear cell needs two texel centres).
pub const OCEAN_RELIEF_MIN_SIDE: u32 = 2;
/// The largest side of a height map, texels (16.7 M texels; a generation at this size needs
/// about 77 bytes a texel, 1.29 GB).
pub const OCEAN_RELIEF_MAX_SIDE: u32 = 4096;
/// The largest `OceanReliefConeParams::max_ratio`, texture widths per unit depth.
pub const OCEAN_RELIEF_MAX_RATIO_LIMIT: f32 = 64.0;
/// The most bands a generation with a progress callback is split into: the callback is called
/// at most `OCEAN_RELIEF_PROGRESS_BANDS + 1` times.
pub const OCEAN_RELIEF_PROGRESS_BANDS: u32 = 64;

const _: () = assert!(OCEAN_RELIEF_MIN_SIDE as usize == HeightMap::MIN_SIDE);
const _: () = assert!(OCEAN_RELIEF_MAX_SIDE as usize == ocean_relief::MAX_SIDE);
const _: () = assert!(OCEAN_RELIEF_MAX_RATIO_LIMIT == ocean_relief::MAX_RATIO_LIMIT);
const _: () = assert!(OCEAN_RELIEF_PROGRESS_BANDS as usize == ocean_relief::progress::BANDS);

/// A progress callback: `done` of `total` units of work are finished (rows of bilinear cells:
/// `total` is N in wrap mode and N + 1 in clamp mode). Return 0 to go on, nonzero to cancel:
/// the function then returns `OCEAN_STATUS_CANCELLED` and writes nothing.
///
/// It is called on the thread that called the generating function, never concurrently with
/// itself: once with `done` = 0 before any work, then after each band of rows (at most
/// `OCEAN_RELIEF_PROGRESS_BANDS`), the last time with `done` = `total`. `user` is passed through
/// untouched. The callback must not unwind (C++ exceptions, `longjmp`) out of the call.
pub type OceanReliefProgress =
    Option<unsafe extern "C" fn(user: *mut c_void, done: usize, total: usize) -> c_int>;

/// How the cones are made. Start from `ocean_relief_cone_params_default`.
#[repr(C)]
#[derive(
    Clone, Copy, Debug, Default, PartialEq, bytemuck::NoUninit, bytemuck::CheckedBitPattern,
)]
pub struct OceanReliefConeParams {
    /// Extensions: NULL, or the first extension struct (see `OceanChain`); the `_default`
    /// function sets NULL.
    pub next: OceanNext,
    /// `OCEAN_RELIEF_CONE_KIND_RELAXED` (default) or `OCEAN_RELIEF_CONE_KIND_CONSERVATIVE`;
    /// other values are refused.
    pub kind: OceanReliefConeKind,
    /// Cap on the cone ratios (texture widths per unit depth) and the clearances (texture
    /// widths), in (0, `OCEAN_RELIEF_MAX_RATIO_LIMIT`]. Default 1.0, the book's, for 8-bit
    /// storage (which clamps at 1.0 anyway); a larger cap keeps wider cones for f16 / f32.
    pub max_ratio: f32,
}

impl CheckedStruct for OceanReliefConeParams {
    const ENUM_FIELDS: &'static [EnumField] = &[EnumField::of::<OceanReliefConeKind>(
        "kind",
        core::mem::offset_of!(OceanReliefConeParams, kind),
    )];
}

/// A square height map with its edge mode (opaque). Create with one of
/// `ocean_relief_map_create_f32` / `_u8` / `_u16`, free with `ocean_relief_map_destroy`.
/// Immutable: a `const OceanReliefMap *` may be used by any number of threads at once.
pub struct OceanReliefMap {
    pub(crate) map: HeightMap,
}

/// A cone map together with the height map it was made for: what the CPU tracers read
/// (opaque). Create with `ocean_relief_cones_create` (or `ocean_relief_cones_quantize`), free
/// with `ocean_relief_cones_destroy`. Immutable and shareable between threads.
pub struct OceanReliefCones {
    pub(crate) map: HeightMap,
    pub(crate) cones: ConeMap,
    pub(crate) texture: ReliefTexture,
}

impl OceanReliefCones {
    fn new(map: HeightMap, cones: ConeMap) -> Result<Self, Error> {
        let texture = ReliefTexture::new(&map, &cones)?;
        Ok(Self {
            map,
            cones,
            texture,
        })
    }

    /// The relief texture the tracers read.
    pub(crate) fn texture(&self) -> &ReliefTexture {
        &self.texture
    }
}

const _: () = {
    const fn shareable<T: Send + Sync>() {}
    shareable::<OceanReliefMap>();
    shareable::<OceanReliefCones>();
};

/// The error of a crate call as a status, with the crate's message (`?` converts).
impl From<ReliefError> for Error {
    fn from(e: ReliefError) -> Self {
        relief_error("", e)
    }
}

/// The status of an `ocean-relief` error, and its message prefixed with `context`.
pub(crate) fn relief_error(context: &str, e: ReliefError) -> Error {
    let status = match &e {
        ReliefError::MapSize { width, height, .. } if *width == 0 || *height == 0 => {
            OceanStatus::Empty
        }
        ReliefError::MapSize { .. } => OceanStatus::InvalidArgument,
        ReliefError::NotSquare { .. } => OceanStatus::InvalidArgument,
        ReliefError::BufferSize { .. } => OceanStatus::InvalidArgument,
        ReliefError::HeightNotFinite { .. } => OceanStatus::NonFinite,
        ReliefError::HeightOutOfRange { .. } => OceanStatus::InvalidArgument,
        ReliefError::NotFinite(_) => OceanStatus::NonFinite,
        ReliefError::OutOfRange { .. } => OceanStatus::InvalidArgument,
        ReliefError::Mismatch(_) => OceanStatus::InvalidArgument,
        ReliefError::NotPowerOfTwo(_) => OceanStatus::InvalidArgument,
        ReliefError::RayDirection | ReliefError::RayTooFlat => OceanStatus::InvalidArgument,
        ReliefError::Cancelled => OceanStatus::Cancelled,
        ReliefError::Camera(c) => camera_status(c),
        // `ReliefError` is non-exhaustive: a variant added later is an argument out of range
        // until it gets a status of its own.
        _ => OceanStatus::InvalidArgument,
    };
    Error::new(status, format!("{context}{e}"))
}

pub(crate) fn edge_from(edge: u32) -> Result<Edge, Error> {
    Ok(match check_enum::<OceanReliefEdge>("`edge`", edge)? {
        OceanReliefEdge::Wrap => Edge::Wrap,
        OceanReliefEdge::Clamp => Edge::Clamp,
    })
}

pub(crate) fn encoding_from(encoding: u32) -> Result<Encoding, Error> {
    Ok(
        match check_enum::<OceanReliefEncoding>("`encoding`", encoding)? {
            OceanReliefEncoding::Unorm8 => Encoding::Unorm8,
            OceanReliefEncoding::Unorm8Sqrt => Encoding::Unorm8Sqrt,
            OceanReliefEncoding::F16 => Encoding::F16,
            OceanReliefEncoding::F32 => Encoding::F32,
        },
    )
}

pub(crate) fn params_from(p: &OceanReliefConeParams) -> Result<ConeParams, Error> {
    let kind = match p.kind {
        OceanReliefConeKind::Relaxed => ConeKind::Relaxed,
        OceanReliefConeKind::Conservative => ConeKind::Conservative,
    };
    if !p.max_ratio.is_finite() {
        return Err(Error::new(
            OceanStatus::NonFinite,
            format!("params->max_ratio must be finite, got {}", p.max_ratio),
        ));
    }
    if !(p.max_ratio > 0.0 && p.max_ratio <= OCEAN_RELIEF_MAX_RATIO_LIMIT) {
        return Err(Error::new(
            OceanStatus::InvalidArgument,
            format!(
                "params->max_ratio = {} is outside (0, {OCEAN_RELIEF_MAX_RATIO_LIMIT}]",
                p.max_ratio
            ),
        ));
    }
    Ok(ConeParams {
        kind,
        max_ratio: p.max_ratio,
        ..ConeParams::default()
    })
}

/// The side and texel count of a `width` x `height` input, checked the way the crate checks it
/// (with `OCEAN_STATUS_EMPTY` for a zero side), and `len` against it.
fn map_dims(width: u32, height: u32, len: usize) -> Result<usize, Error> {
    if width == 0 || height == 0 {
        return Err(Error::new(
            OceanStatus::Empty,
            format!("the height map is {width} x {height} texels: empty"),
        ));
    }
    let (w, h) = (width as usize, height as usize);
    let max = ocean_relief::MAX_SIDE;
    if w < HeightMap::MIN_SIDE || h < HeightMap::MIN_SIDE || w > max || h > max {
        return Err(Error::new(
            OceanStatus::InvalidArgument,
            format!(
                "the height map is {width} x {height} texels, outside {0} x {0} to {max} x {max} \
                 (OCEAN_RELIEF_MIN_SIDE, OCEAN_RELIEF_MAX_SIDE)",
                HeightMap::MIN_SIDE
            ),
        ));
    }
    if w != h {
        return Err(Error::new(
            OceanStatus::InvalidArgument,
            format!("the height map is {width} x {height} texels; relief maps must be square"),
        ));
    }
    // Both sides are at most 4096: the product fits.
    let texels = w * h;
    check_len("len", len, texels, &format!("a {width} x {height} map"))?;
    Ok(texels)
}

/// Creates a height map from `len` = width * height floats, row-major (texel (i, j) at element
/// j * width + i), each a **height** (1 = the polygon surface, 0 = the bottom), and stores the
/// handle in `*out`.
///
/// `edge`: `OCEAN_RELIEF_EDGE_WRAP` or `_CLAMP`. `range`: `OCEAN_RELIEF_RANGE_REFUSE` (heights
/// must lie in [0, 1]) or `OCEAN_RELIEF_RANGE_NORMALIZE` (the smallest becomes 0, the largest 1).
/// The heights are copied.
///
/// Returns `OCEAN_STATUS_NULL_POINTER` / `_MISALIGNED_POINTER` for a bad pointer (4-byte
/// alignment for `heights`), `OCEAN_STATUS_EMPTY` if `width` or `height` is 0,
/// `OCEAN_STATUS_INVALID_ARGUMENT` if a side is outside 2 to `OCEAN_RELIEF_MAX_SIDE`, the map is
/// not square, `len` is not width * height, `edge` or `range` is unknown, or (with `_REFUSE`) a
/// height lies outside [0, 1], `OCEAN_STATUS_NON_FINITE` for a NaN or infinite height (the
/// message names the first bad texel). `*out` is written only on success.
///
/// # Safety
///
/// `heights` must point to `len` readable floats and `out` to a writable pointer.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn ocean_relief_map_create_f32(
    heights: *const f32,
    len: usize,
    width: u32,
    height: u32,
    edge: u32,
    range: u32,
    out: *mut *mut OceanReliefMap,
) -> OceanStatus {
    guard("ocean_relief_map_create_f32", || {
        check_ptr(heights, "heights")?;
        check_ptr(out.cast_const(), "out")?;
        // SAFETY: forwarded from this function's contract.
        let heights = unsafe { input(heights, len, "heights") }?;
        let edge = edge_from(edge)?;
        let range = match check_enum::<OceanReliefRange>("`range`", range)? {
            OceanReliefRange::Refuse => HeightRange::Refuse,
            OceanReliefRange::Normalize => HeightRange::Normalize,
        };
        map_dims(width, height, len)?;
        let map = HeightMap::from_heights(width as usize, height as usize, heights, edge, range)?;
        // SAFETY: forwarded from this function's contract.
        unsafe { write_handle(out, OceanReliefMap { map }) }
    })
}

/// Creates a height map from `len` = width * height 8-bit heights (height v / 255, depth
/// (255 - v) / 255), row-major, and stores the handle in `*out`. Statuses as
/// `ocean_relief_map_create_f32` (every 8-bit value is in range).
///
/// # Safety
///
/// `heights` must point to `len` readable bytes and `out` to a writable pointer.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn ocean_relief_map_create_u8(
    heights: *const u8,
    len: usize,
    width: u32,
    height: u32,
    edge: u32,
    out: *mut *mut OceanReliefMap,
) -> OceanStatus {
    // SAFETY: forwarded from this function's contract.
    unsafe {
        create_integer_map(
            "ocean_relief_map_create_u8",
            heights,
            len,
            (width, height, edge),
            out,
            HeightMap::from_u8,
        )
    }
}

/// Creates a height map from `len` = width * height 16-bit heights (height v / 65535, depth
/// (65535 - v) / 65535), row-major, and stores the handle in `*out`. Statuses as
/// `ocean_relief_map_create_f32` (2-byte alignment for `heights`).
///
/// # Safety
///
/// `heights` must point to `len` readable `uint16_t` and `out` to a writable pointer.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn ocean_relief_map_create_u16(
    heights: *const u16,
    len: usize,
    width: u32,
    height: u32,
    edge: u32,
    out: *mut *mut OceanReliefMap,
) -> OceanStatus {
    // SAFETY: forwarded from this function's contract.
    unsafe {
        create_integer_map(
            "ocean_relief_map_create_u16",
            heights,
            len,
            (width, height, edge),
            out,
            HeightMap::from_u16,
        )
    }
}

/// The body of the integer `ocean_relief_map_create_*` functions: `make` builds the map from the
/// checked buffer.
///
/// # Safety
///
/// As those functions: `heights` points to `len` readable values, `out` to a writable pointer.
unsafe fn create_integer_map<T>(
    name: &str,
    heights: *const T,
    len: usize,
    (width, height, edge): (u32, u32, u32),
    out: *mut *mut OceanReliefMap,
    make: fn(usize, usize, &[T], Edge) -> Result<HeightMap, ocean_relief::ReliefError>,
) -> OceanStatus {
    guard(name, || {
        check_ptr(heights, "heights")?;
        check_ptr(out.cast_const(), "out")?;
        // SAFETY: forwarded from the caller's contract.
        let heights = unsafe { input(heights, len, "heights") }?;
        let edge = edge_from(edge)?;
        map_dims(width, height, len)?;
        let map = make(width as usize, height as usize, heights, edge)?;
        // SAFETY: forwarded from the caller's contract.
        unsafe { write_handle(out, OceanReliefMap { map }) }
    })
}

/// Frees a height map. NULL does nothing; a handle of another kind or already destroyed frees
/// nothing and sets the last-error message (see the header's notes on handles).
#[unsafe(no_mangle)]
pub extern "C" fn ocean_relief_map_destroy(map: *mut OceanReliefMap) {
    destroy(map, "ocean_relief_map_destroy", "map");
}

/// Stores the side N of the map, texels, in `*out_size`.
///
/// Returns `OCEAN_STATUS_NULL_POINTER` / `_MISALIGNED_POINTER` for a bad pointer; `*out_size`
/// is written only on success.
///
/// # Safety
///
/// `out_size` must be writable.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn ocean_relief_map_size(
    map: *const OceanReliefMap,
    out_size: *mut u32,
) -> OceanStatus {
    guard("ocean_relief_map_size", || {
        let m = borrow(map, "map")?;
        // At most OCEAN_RELIEF_MAX_SIDE.
        let side = m.map.size() as u32;
        // SAFETY: forwarded from this function's contract.
        unsafe { write_out(out_size, "out_size", side) }
    })
}

/// Copies the map's depths (1 - height, after normalisation if asked for; in [0, 1]) into
/// `depths`: `len` = N * N floats, row-major. These are the depths the cones are valid for:
/// upload them as the depth channel of the relief texture.
///
/// Returns `OCEAN_STATUS_NULL_POINTER` / `_MISALIGNED_POINTER` for a bad pointer,
/// `OCEAN_STATUS_LENGTH_MISMATCH` if `len` is not N * N. Nothing is written on failure.
///
/// # Safety
///
/// `depths` must point to `len` writable floats that no other thread
/// touches during the call.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn ocean_relief_map_depths(
    map: *const OceanReliefMap,
    depths: *mut f32,
    len: usize,
) -> OceanStatus {
    guard("ocean_relief_map_depths", || {
        let m = borrow(map, "map")?;
        check_ptr(depths.cast_const(), "depths")?;
        let d = m.map.depths();
        check_len("len", len, d.len(), "the map")?;
        // SAFETY: forwarded from this function's contract.
        unsafe { write_slice(depths, "depths", d) }
    })
}

/// Computes the tangent-space normal map of `map` for a relief `depth` texel widths deep (the
/// full depth range spans that many texel widths) by central differences, and stores it in
/// `xyz`: `len` = 3 N * N floats, row-major, (x, y, z) per texel, unit length, z out of the
/// polygon, x along the texture's u, y along v; neighbours follow the map's edge mode.
///
/// Returns `OCEAN_STATUS_NULL_POINTER` / `_MISALIGNED_POINTER` for a bad pointer,
/// `OCEAN_STATUS_NON_FINITE` for a NaN or infinite `depth`, `OCEAN_STATUS_INVALID_ARGUMENT` if
/// `depth` is outside [0, 1e6], `OCEAN_STATUS_LENGTH_MISMATCH` if `len` is not 3 N * N.
/// Nothing is written on failure.
///
/// # Safety
///
/// `xyz` must point to `len` writable floats that no other thread
/// touches during the call.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn ocean_relief_normals(
    map: *const OceanReliefMap,
    depth: f32,
    xyz: *mut f32,
    len: usize,
) -> OceanStatus {
    guard("ocean_relief_normals", || {
        let m = borrow(map, "map")?;
        check_ptr(xyz.cast_const(), "xyz")?;
        let n = m.map.size();
        check_len("len", len, 3 * n * n, "the normal map (3 floats a texel)")?;
        let normals = ocean_relief::relief::normals(&m.map, depth)?;
        let flat: Vec<f32> = normals.iter().flat_map(|v| v.to_array()).collect();
        // SAFETY: forwarded from this function's contract.
        unsafe { write_slice(xyz, "xyz", &flat) }
    })
}

/// Stores the default cone parameters in `*out`: relaxed cones, capped at 1.0 (the book's).
///
/// Returns `OCEAN_STATUS_NULL_POINTER` (or `_MISALIGNED_POINTER`) for a bad `out`, which is
/// then left unchanged.
///
/// # Safety
///
/// `out` must be writable.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn ocean_relief_cone_params_default(
    out: *mut OceanReliefConeParams,
) -> OceanStatus {
    guard("ocean_relief_cone_params_default", || {
        let d = ConeParams::default();
        let p = OceanReliefConeParams {
            next: OceanNext::NULL,
            kind: match d.kind {
                ConeKind::Relaxed => OceanReliefConeKind::Relaxed,
                ConeKind::Conservative => OceanReliefConeKind::Conservative,
            },
            max_ratio: d.max_ratio,
        };
        // SAFETY: forwarded from this function's contract.
        unsafe { write_out(out, "out", p) }
    })
}

/// Runs the generator with the caller's callback (NULL: no reports).
fn generate(
    map: &HeightMap,
    params: ConeParams,
    progress: OceanReliefProgress,
    user: *mut c_void,
) -> Result<ConeMap, Error> {
    with_progress(progress, user, |report| match report {
        None => ConeMap::generate(map, params),
        Some(r) => ConeMap::generate_with(map, params, r),
    })
}

/// Runs `run` with the caller's callback as a `Progress` (`None` for NULL: no reports).
pub(crate) fn with_progress<T>(
    progress: OceanReliefProgress,
    user: *mut c_void,
    run: impl FnOnce(Option<&mut dyn ocean_relief::progress::Progress>) -> Result<T, ReliefError>,
) -> Result<T, Error> {
    let result = match progress {
        None => run(None),
        Some(callback) => {
            let mut report = |done: usize, total: usize| {
                // SAFETY: the caller guarantees that `callback` may be called with `user` (this
                // function's callers' contracts); it runs on this thread.
                unsafe { callback(user, done, total) == 0 }
            };
            run(Some(&mut report))
        }
    };
    result.map_err(Error::from)
}

/// Generates the cone map of `map` (see `OceanReliefConeParams`) and stores a handle that holds
/// it and a copy of the map in `*out`: what `ocean_relief_trace` and `ocean_relief_shadow` read.
///
/// Every texel gets three channels, each rounded down to float and capped at
/// `params->max_ratio`: the cone ratio c (texture widths per unit depth, the book's cone map),
/// the clearance D (texture widths) and the near cap E (per unit depth); a ray h above the
/// surface may use the cone max(c, min(D/h, E)). The cones are valid for the bilinear surface
/// of the map's depths, read bilinearly or nearest. The result is bit-identical to
/// `ocean_relief::ConeMap::generate` on every thread count, with or without `progress`.
///
/// `progress` (may be NULL) is called as `OceanReliefProgress` describes, with `user`; a nonzero
/// return cancels. Rows of the map are computed on all the threads of the library's pool.
///
/// Returns `OCEAN_STATUS_NULL_POINTER` / `_MISALIGNED_POINTER` for a bad pointer,
/// `OCEAN_STATUS_NON_FINITE` for a NaN or infinite `max_ratio`, `OCEAN_STATUS_INVALID_ARGUMENT`
/// for an unknown kind or a `max_ratio` outside (0, `OCEAN_RELIEF_MAX_RATIO_LIMIT`],
/// `OCEAN_STATUS_CANCELLED` when the callback returned nonzero (the arguments are checked before
/// the first call). `*out` is written only on success.
///
/// # Safety
///
/// `params` readable, `out` writable; `progress`, if not NULL,
/// must be safe to call with `user` from this thread.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn ocean_relief_cones_create(
    map: *const OceanReliefMap,
    params: *const OceanReliefConeParams,
    progress: OceanReliefProgress,
    user: *mut c_void,
    out: *mut *mut OceanReliefCones,
) -> OceanStatus {
    guard("ocean_relief_cones_create", || {
        let m = borrow(map, "map")?;
        check_ptr(params, "params")?;
        check_ptr(out.cast_const(), "out")?;
        // SAFETY: forwarded from this function's contract (the pointer checked above).
        let params = params_from(&unsafe { read_params_checked(params, "params") }?)?;
        let cones = generate(&m.map, params, progress, user)?;
        let handle = OceanReliefCones::new(m.map.clone(), cones)?;
        // SAFETY: forwarded from this function's contract.
        unsafe { write_handle(out, handle) }
    })
}

/// Frees a cone map. NULL does nothing; a handle of another kind or already destroyed frees nothing
/// and sets the last-error message (see the header's notes on handles).
#[unsafe(no_mangle)]
pub extern "C" fn ocean_relief_cones_destroy(cones: *mut OceanReliefCones) {
    destroy(cones, "ocean_relief_cones_destroy", "cones");
}

/// Stores the side N of the cone map (that of its height map), texels, in `*out_size`.
///
/// Returns `OCEAN_STATUS_NULL_POINTER` / `_MISALIGNED_POINTER` for a bad pointer; `*out_size`
/// is written only on success.
///
/// # Safety
///
/// `out_size` must be writable.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn ocean_relief_cones_size(
    cones: *const OceanReliefCones,
    out_size: *mut u32,
) -> OceanStatus {
    guard("ocean_relief_cones_size", || {
        let c = borrow(cones, "cones")?;
        // At most OCEAN_RELIEF_MAX_SIDE.
        let side = c.cones.size() as u32;
        // SAFETY: forwarded from this function's contract.
        unsafe { write_out(out_size, "out_size", side) }
    })
}

/// Copies the relief texture into `rgba`: `len` = 4 N * N floats, row-major, `[depth, c, D, E]`
/// per texel (the depth of the map and the three cone channels), the layout of an `RGBA32F`
/// texture and exactly what the CPU tracers read.
///
/// Returns `OCEAN_STATUS_NULL_POINTER` / `_MISALIGNED_POINTER` for a bad pointer,
/// `OCEAN_STATUS_LENGTH_MISMATCH` if `len` is not 4 N * N. Nothing is written on failure.
///
/// # Safety
///
/// `rgba` must point to `len` writable floats that no other thread
/// touches during the call.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn ocean_relief_cones_texels(
    cones: *const OceanReliefCones,
    rgba: *mut f32,
    len: usize,
) -> OceanStatus {
    guard("ocean_relief_cones_texels", || {
        let c = borrow(cones, "cones")?;
        check_ptr(rgba.cast_const(), "rgba")?;
        let n = c.cones.size();
        check_len("len", len, 4 * n * n, "the texture (4 floats a texel)")?;
        let t = texels(&c.map, &c.cones);
        // SAFETY: forwarded from this function's contract.
        unsafe { write_slice(rgba, "rgba", &t) }
    })
}

/// Encodes the three cone channels for storage and copies them into `out`: `len` = 3 N * N
/// elements of the encoding's type (`uint8_t` for `OCEAN_RELIEF_ENCODING_UNORM8` and
/// `_UNORM8_SQRT`, `uint16_t` binary16 bit patterns for `_F16`, `float` for `_F32`), row-major,
/// `[c, D, E]` per texel. Every value is rounded **down** (a stored cone is never wider than
/// the exact one, so it stays valid); the 8-bit encodings clamp at 1.0. The depth channel is
/// not included: take it from `ocean_relief_map_depths` (the cones are valid for those depths).
///
/// Returns `OCEAN_STATUS_NULL_POINTER` / `_MISALIGNED_POINTER` for a bad pointer (aligned for
/// the element type), `OCEAN_STATUS_INVALID_ARGUMENT` for an unknown encoding,
/// `OCEAN_STATUS_LENGTH_MISMATCH` for a `len` that is not 3 N * N. Nothing is written on failure.
///
/// # Safety
///
/// `out` must point to `len` writable elements of the encoding's
/// type that no other thread touches during the call.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn ocean_relief_cones_encode(
    cones: *const OceanReliefCones,
    encoding: u32,
    out: *mut c_void,
    len: usize,
) -> OceanStatus {
    guard("ocean_relief_cones_encode", || {
        let c = borrow(cones, "cones")?;
        check_ptr(out.cast_const().cast::<u8>(), "out")?;
        let encoding = encoding_from(encoding)?;
        check_encoded_out(out, encoding)?;
        let n = c.cones.size();
        check_len("len", len, 3 * n * n, "the cone map (3 values a texel)")?;
        let values = encode_cones(&c.cones, encoding);
        // SAFETY: forwarded from this function's contract.
        unsafe { write_encoded(out, &values) }
    })
}

/// Stores in `*out` a new handle whose cones are those of `cones` after a round trip through
/// `encoding` (each channel encoded, rounding down, and decoded): what a tracer reading the
/// stored texture sees. Trace it to measure what a storage format costs.
///
/// Returns `OCEAN_STATUS_NULL_POINTER` / `_MISALIGNED_POINTER` for a bad pointer,
/// `OCEAN_STATUS_INVALID_ARGUMENT` for an unknown encoding. `*out` is written only on success.
///
/// # Safety
///
/// `out` must be writable.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn ocean_relief_cones_quantize(
    cones: *const OceanReliefCones,
    encoding: u32,
    out: *mut *mut OceanReliefCones,
) -> OceanStatus {
    guard("ocean_relief_cones_quantize", || {
        let c = borrow(cones, "cones")?;
        check_ptr(out.cast_const(), "out")?;
        let encoding = encoding_from(encoding)?;
        let q = c.cones.quantized(encoding)?;
        let handle = OceanReliefCones::new(c.map.clone(), q)?;
        // SAFETY: forwarded from this function's contract.
        unsafe { write_handle(out, handle) }
    })
}

/// Generates the cone map of `map` straight into `rgba` (no handle): `len` = 4 N * N floats,
/// `[depth, c, D, E]` per texel, as `ocean_relief_cones_texels` writes them. Arguments,
/// callback and statuses as `ocean_relief_cones_create`, with `OCEAN_STATUS_LENGTH_MISMATCH`
/// for a `len` that is not 4 N * N (checked before any work). `rgba` is written only on
/// success, and then wholly.
///
/// # Safety
///
/// `params` readable, `rgba` point to `len` writable floats that
/// no other thread touches during the call; `progress`, if not NULL, must be safe to call with
/// `user` from this thread.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn ocean_relief_generate_texels(
    map: *const OceanReliefMap,
    params: *const OceanReliefConeParams,
    progress: OceanReliefProgress,
    user: *mut c_void,
    rgba: *mut f32,
    len: usize,
) -> OceanStatus {
    guard("ocean_relief_generate_texels", || {
        let m = borrow(map, "map")?;
        check_ptr(params, "params")?;
        check_ptr(rgba.cast_const(), "rgba")?;
        // SAFETY: forwarded from this function's contract (the pointer checked above).
        let params = params_from(&unsafe { read_params_checked(params, "params") }?)?;
        let n = m.map.size();
        check_len("len", len, 4 * n * n, "the texture (4 floats a texel)")?;
        let cones = generate(&m.map, params, progress, user)?;
        let t = texels(&m.map, &cones);
        // SAFETY: forwarded from this function's contract.
        unsafe { write_slice(rgba, "rgba", &t) }
    })
}

/// Generates the cone map of `map` and encodes its three channels straight into `out` (no
/// handle): `len` = 3 N * N elements of the encoding's type, `[c, D, E]` per texel, as
/// `ocean_relief_cones_encode` writes them. Arguments, callback and statuses as
/// `ocean_relief_cones_create` and `ocean_relief_cones_encode` (the encoding, the pointer and
/// `len` are checked before any work). `out` is written only on success, and then wholly.
///
/// # Safety
///
/// `params` readable, `out` point to `len` writable elements of
/// the encoding's type that no other thread touches during the call; `progress`, if not NULL,
/// must be safe to call with `user` from this thread.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn ocean_relief_generate_encoded(
    map: *const OceanReliefMap,
    params: *const OceanReliefConeParams,
    progress: OceanReliefProgress,
    user: *mut c_void,
    encoding: u32,
    out: *mut c_void,
    len: usize,
) -> OceanStatus {
    guard("ocean_relief_generate_encoded", || {
        let m = borrow(map, "map")?;
        check_ptr(params, "params")?;
        check_ptr(out.cast_const().cast::<u8>(), "out")?;
        let encoding = encoding_from(encoding)?;
        check_encoded_out(out, encoding)?;
        // SAFETY: forwarded from this function's contract (the pointer checked above).
        let params = params_from(&unsafe { read_params_checked(params, "params") }?)?;
        let n = m.map.size();
        check_len("len", len, 3 * n * n, "the cone map (3 values a texel)")?;
        let cones = generate(&m.map, params, progress, user)?;
        let values = encode_cones(&cones, encoding);
        // SAFETY: forwarded from this function's contract.
        unsafe { write_encoded(out, &values) }
    })
}

crate::boundary::chain::extensible!(OceanReliefConeParams);

crate::boundary::handle::handles!(OceanReliefMap, OceanReliefCones);

#[cfg(test)]
#[path = "relief_tests.rs"]
mod tests;
