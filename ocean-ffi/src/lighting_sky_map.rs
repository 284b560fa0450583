//! The sky map of a lighting (`OceanSkyMap`): the stereographic, mip-mapped environment that
//! the sea colour reads, and its levels for a caller's own texture.

use ocean_brdf::{Lighting, SkyMap};

use crate::boundary::{borrow, byte_len, check_len, check_ptr, destroy, write_handle, write_out};
use crate::lighting::OceanLighting;
use crate::status::{Error, OceanStatus, guard};

/// A mip-mapped sky map of one lighting (opaque): the sky's radiance in the stereographic
/// parameterisation (paper section 5.2), level 0 of size N, each coarser level the 2x2 mean of
/// the one above, down to 1x1. Create with `ocean_lighting_sky_map_create`, free with
/// `ocean_sky_map_destroy`. Immutable and shareable between threads.
pub struct OceanSkyMap {
    pub(crate) map: SkyMap,
    /// The lighting it was rendered from: `ocean_sea_color` refuses a map of another one.
    pub(crate) lighting: Lighting,
}

const _: () = {
    const fn shareable<T: Send + Sync>() {}
    shareable::<OceanSkyMap>();
};

/// Renders the sky map of `lighting`, `size` x `size` texels at level 0, and stores a new
/// handle in `*out`.
///
/// Texel (i, j) of level 0 (row-major: element j*size + i) holds the environment's radiance
/// (`ocean_lighting_environment_radiance`) towards the direction whose stereographic projection
/// is u = (2 t - 1) E, with t = ((i + 0.5)/size, (j + 0.5)/size) and E = `OCEAN_SKY_MAP_EXTENT`:
/// the direction r = (2 u_x, 1 - |u|^2, 2 u_y) / (1 + |u|^2) (so u = (r_x, r_z)/(1 + r_y); the
/// zenith is at the centre, the horizon on the circle |u| = 1), and the below-horizon radiance
/// outside that circle. Each coarser level is the 2x2 mean of the one above, down to 1x1. Every
/// channel is rounded to binary16 (the precision of the GPU's `rgba16float` texture), stored as
/// float; alpha is 1.
///
/// Returns `OCEAN_STATUS_NULL_POINTER` / `_MISALIGNED_POINTER` for a bad pointer,
/// `OCEAN_STATUS_INVALID_ARGUMENT` if `size` is not a power of two in
/// [`OCEAN_SKY_MAP_MIN_SIZE`, `OCEAN_SKY_MAP_MAX_SIZE`] or a radiance exceeds binary16's range
/// (65504: scale the radiance unit down). On failure `*out` is unchanged. Free the map with
/// `ocean_sky_map_destroy`.
///
/// # Safety
///
/// `out` must point to a writable pointer.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn ocean_lighting_sky_map_create(
    lighting: *const OceanLighting,
    size: u32,
    out: *mut *mut OceanSkyMap,
) -> OceanStatus {
    guard("ocean_lighting_sky_map_create", || {
        let l = borrow(lighting, "lighting")?;
        check_ptr(out.cast_const(), "out")?;
        let map = l.lighting.sky_map(size)?;
        let value = OceanSkyMap {
            map,
            lighting: l.lighting,
        };
        // SAFETY: forwarded from this function's contract.
        unsafe { write_handle(out, value) }
    })
}

/// Frees a sky map. NULL does nothing; a handle of another kind or already destroyed frees nothing
/// and sets the last-error message (see the header's notes on handles).
#[unsafe(no_mangle)]
pub extern "C" fn ocean_sky_map_destroy(sky_map: *mut OceanSkyMap) {
    destroy(sky_map, "ocean_sky_map_destroy", "sky_map");
}

/// Stores the number of mip levels of the map, log2(size) + 1, in `*out_count`.
///
/// Returns `OCEAN_STATUS_NULL_POINTER` / `_MISALIGNED_POINTER` for a bad pointer; `*out_count`
/// is written only on success.
///
/// # Safety
///
/// `out_count` must be writable.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn ocean_sky_map_level_count(
    sky_map: *const OceanSkyMap,
    out_count: *mut u32,
) -> OceanStatus {
    guard("ocean_sky_map_level_count", || {
        let m = borrow(sky_map, "sky_map")?;
        // SAFETY: forwarded from this function's contract.
        unsafe { write_out(out_count, "out_count", m.map.level_count()) }
    })
}

/// The texels of `level`, or `OCEAN_STATUS_INVALID_ARGUMENT`.
pub(crate) fn level(m: &OceanSkyMap, level: u32) -> Result<&[[f32; 4]], Error> {
    m.map.level(level).ok_or_else(|| {
        Error::new(
            OceanStatus::InvalidArgument,
            format!(
                "level {level} does not exist: the map has levels 0 to {}",
                m.map.level_count() - 1
            ),
        )
    })
}

/// Stores the side of mip `level` in texels, max(size >> level, 1), in `*out_size`: the level
/// holds out_size * out_size RGBA texels.
///
/// Returns `OCEAN_STATUS_NULL_POINTER` / `_MISALIGNED_POINTER` for a bad pointer,
/// `OCEAN_STATUS_INVALID_ARGUMENT` if `level` >= the level count. `*out_size` is written only on
/// success.
///
/// # Safety
///
/// `out_size` must be writable.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn ocean_sky_map_level_info(
    sky_map: *const OceanSkyMap,
    level: u32,
    out_size: *mut u32,
) -> OceanStatus {
    guard("ocean_sky_map_level_info", || {
        let m = borrow(sky_map, "sky_map")?;
        check_ptr(out_size.cast_const(), "out_size")?;
        self::level(&m, level)?;
        let side = (m.map.size() >> level).max(1);
        // SAFETY: forwarded from this function's contract.
        unsafe { write_out(out_size, "out_size", side) }
    })
}

/// Copies mip `level` into `rgba`: side * side texels (side from `ocean_sky_map_level_info`),
/// row-major from texture coordinate (0, 0) (texel (i, j) at element j*side + i), 4 floats
/// each (R, G, B, A = 1), the layout an `RGBA32F` or (after conversion) `RGBA16F` texture
/// upload expects. `len` counts floats and must be exactly side * side * 4.
///
/// Returns `OCEAN_STATUS_NULL_POINTER` / `_MISALIGNED_POINTER` for a bad pointer (4-byte
/// alignment for `rgba`), `OCEAN_STATUS_INVALID_ARGUMENT` if `level` does not exist,
/// `OCEAN_STATUS_LENGTH_MISMATCH` if `len` is not side * side * 4,
/// `OCEAN_STATUS_LENGTH_OVERFLOW` if `len * sizeof(float)` exceeds
/// `PTRDIFF_MAX`. Nothing is written on failure.
///
/// # Safety
///
/// `rgba` must point to `len` writable floats that no other
/// thread touches during the call.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn ocean_sky_map_copy_level(
    sky_map: *const OceanSkyMap,
    level: u32,
    rgba: *mut f32,
    len: usize,
) -> OceanStatus {
    guard("ocean_sky_map_copy_level", || {
        let m = borrow(sky_map, "sky_map")?;
        check_ptr(rgba.cast_const(), "rgba")?;
        byte_len::<f32>(len, "rgba")?;
        let texels = self::level(&m, level)?;
        let want = texels.len() * 4;
        check_len(
            "len",
            len,
            want,
            &format!("level {level} (4 floats a texel)"),
        )?;
        // SAFETY: non-NULL and 4-aligned (checked), `len` floats whose byte size fits in isize
        // (checked: it equals the level's size), writable and untouched by others (caller's
        // guarantee).
        let out = unsafe { core::slice::from_raw_parts_mut(rgba, len) };
        out.copy_from_slice(bytemuck::cast_slice(texels));
        Ok(())
    })
}

crate::boundary::handle::handles!(OceanSkyMap);
