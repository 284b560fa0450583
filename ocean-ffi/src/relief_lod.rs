//! Relief mapping's level of detail (ocean-relief's `lod` module): the coarser height maps of a
//! relief texture's mip levels and the level a fragment reads, for engines that draw the
//! exported `relief` shader with mip levels (`ocean_relief_uniforms`' `levels`).
//!
//! Level l + 1's depth is the 2x2 mean of level l's, and each level needs cones of its own
//! surface: make them with `ocean_relief_cones_create` (or `ocean_relief_quad_cones_create`)
//! on the map `ocean_relief_map_downsample` returns. The 4x4-window chain of
//! `ocean_relief_mips_create` keeps cones valid over level 0's surface only.
//!
//! The shader reads the levels from one texture level, side by side (the atlas:
//! `ocean_relief_mip_atlas_size`, `ocean_relief_mip_atlas_origin`), not from a mip chain: the
//! relief texture is `GL_RGBA32F`, which is not filterable, and OpenGL defines `texelFetch` of
//! such a texture's levels above the base only with a mipmapping minification filter that makes
//! it incomplete.

use glam::Vec2;
use ocean_relief::lod::{atlas_origin, atlas_size, downsample, max_levels, mip_level};

use crate::boundary::{borrow, check_ptr, write_handle, write_out};
use crate::relief::{OceanReliefMap, relief_error};
use crate::status::{Error, OceanStatus, guard};

/// Makes the next mip level of `map`: side N / 2, each depth the mean ((a + b) + (c + d)) / 4
/// of its 2x2 group (row above first, left texel first), the same edge mode; stores the handle
/// in `*out`.
///
/// Returns `OCEAN_STATUS_NULL_POINTER` / `_MISALIGNED_POINTER` for a bad pointer,
/// `OCEAN_STATUS_INVALID_ARGUMENT` if the side is not a power of two or below 4. `*out` is
/// written only on success.
///
/// # Safety
///
/// `out` must be writable.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn ocean_relief_map_downsample(
    map: *const OceanReliefMap,
    out: *mut *mut OceanReliefMap,
) -> OceanStatus {
    guard("ocean_relief_map_downsample", || {
        let m = borrow(map, "map")?;
        check_ptr(out.cast_const(), "out")?;
        let half = downsample(&m.map).map_err(|e| relief_error("map: ", e))?;
        // SAFETY: forwarded from this function's contract.
        unsafe { write_handle(out, OceanReliefMap { map: half }) }
    })
}

/// Checks a side and a level count as the shader's uniform block does: `size` in 2 to
/// `OCEAN_RELIEF_MAX_SIDE`, `levels` in 1 to log2 `size` (1 for a side that is not a power of
/// two).
fn check_levels(size: u32, levels: u32) -> Result<usize, Error> {
    let n = size as usize;
    if !(2..=ocean_relief::MAX_SIDE).contains(&n) {
        return Err(Error::new(
            OceanStatus::InvalidArgument,
            format!("`size` = {size} is outside 2 to {}", ocean_relief::MAX_SIDE),
        ));
    }
    let most = max_levels(n);
    if levels == 0 || levels as usize > most {
        return Err(Error::new(
            OceanStatus::InvalidArgument,
            format!("`levels` = {levels} is outside 1 to {most} for a side of {size}"),
        ));
    }
    Ok(n)
}

/// Stores the width and height of the relief texture that holds `levels` levels of side `size`
/// for the `relief` shaders: `size` x `size` for one level, (`size` + `size` / 2) x `size` for
/// more (level 0 on the left, the others in a column to its right; see
/// `ocean_relief_mip_atlas_origin`).
///
/// Returns `OCEAN_STATUS_NULL_POINTER` / `_MISALIGNED_POINTER` for a bad pointer,
/// `OCEAN_STATUS_INVALID_ARGUMENT` for a `size` or `levels` `ocean_relief_mip_level` refuses.
/// Nothing is written on failure.
///
/// # Safety
///
/// `out_width` and `out_height` must be writable.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn ocean_relief_mip_atlas_size(
    size: u32,
    levels: u32,
    out_width: *mut u32,
    out_height: *mut u32,
) -> OceanStatus {
    guard("ocean_relief_mip_atlas_size", || {
        check_ptr(out_width.cast_const(), "out_width")?;
        check_ptr(out_height.cast_const(), "out_height")?;
        let n = check_levels(size, levels)?;
        let (w, h) = atlas_size(n, levels as usize);
        // SAFETY: forwarded from this function's contract (both checked above).
        unsafe { write_out(out_width, "out_width", w as u32) }?;
        // SAFETY: as above.
        unsafe { write_out(out_height, "out_height", h as u32) }
    })
}

/// Stores where level `level` (side `size` >> `level`) starts in the relief texture of
/// `ocean_relief_mip_atlas_size`, in texels from its first row's first texel: (0, 0) for level
/// 0, (`size`, `size` - (`size` >> (`level` - 1))) for the others. Copy the level's texels
/// (`ocean_relief_cones_texels` of its own cones) there, row by row.
///
/// Returns `OCEAN_STATUS_NULL_POINTER` / `_MISALIGNED_POINTER` for a bad pointer,
/// `OCEAN_STATUS_INVALID_ARGUMENT` for a `size` `ocean_relief_mip_level` refuses or a `level`
/// at or beyond log2 `size`. Nothing is written on failure.
///
/// # Safety
///
/// `out_x` and `out_y` must be writable.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn ocean_relief_mip_atlas_origin(
    size: u32,
    level: u32,
    out_x: *mut u32,
    out_y: *mut u32,
) -> OceanStatus {
    guard("ocean_relief_mip_atlas_origin", || {
        check_ptr(out_x.cast_const(), "out_x")?;
        check_ptr(out_y.cast_const(), "out_y")?;
        let n = check_levels(size, level.saturating_add(1)).map_err(|_| {
            Error::new(
                OceanStatus::InvalidArgument,
                format!("`level` = {level} is not a level of a relief texture of side {size}"),
            )
        })?;
        let (x, y) = atlas_origin(n, level as usize);
        // SAFETY: forwarded from this function's contract (both checked above).
        unsafe { write_out(out_x, "out_x", x as u32) }?;
        // SAFETY: as above.
        unsafe { write_out(out_y, "out_y", y as u32) }
    })
}

/// Stores in `*out_level` the mip level a fragment of the `relief` shader reads for the screen
/// derivatives (du_x, du_y) = dFdx(uv) and (dv_x, dv_y) = dFdy(uv) of its texture coordinates
/// (texture widths per pixel), for a texture of side `size` with `levels` levels: with
/// rho^2 = max(|du|^2, |dv|^2) size^2, the largest l < `levels` with rho^2 >= 2^(2l - 1) (rho >=
/// 2^(l - 1/2)), or 0. A NaN footprint reads level 0, an infinite one the last level. The shader
/// rounds the same operations, so this is its CPU twin.
///
/// Returns `OCEAN_STATUS_NULL_POINTER` / `_MISALIGNED_POINTER` for a bad pointer,
/// `OCEAN_STATUS_INVALID_ARGUMENT` if `size` is outside 2 to `OCEAN_RELIEF_MAX_SIDE` or `levels`
/// outside 1 to log2 `size` (1 for a side that is not a power of two). `*out_level` is written
/// only on success.
///
/// # Safety
///
/// `out_level` must be writable.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn ocean_relief_mip_level(
    du_x: f32,
    du_y: f32,
    dv_x: f32,
    dv_y: f32,
    size: u32,
    levels: u32,
    out_level: *mut u32,
) -> OceanStatus {
    guard("ocean_relief_mip_level", || {
        check_ptr(out_level.cast_const(), "out_level")?;
        let n = check_levels(size, levels)?;
        let l = mip_level(
            Vec2::new(du_x, du_y),
            Vec2::new(dv_x, dv_y),
            n,
            levels as usize,
        );
        // SAFETY: forwarded from this function's contract.
        unsafe { write_out(out_level, "out_level", l as u32) }
    })
}

#[cfg(test)]
mod tests {
    use core::ptr::{null, null_mut};

    use super::*;
    use crate::relief::{
        ocean_relief_map_create_f32, ocean_relief_map_depths, ocean_relief_map_destroy,
    };
    use crate::status::last_error;

    #[test]
    fn downsample_means_each_group() {
        let heights: Vec<f32> = (0..16).map(|k| k as f32 / 15.0).collect();
        let mut map = null_mut();
        let mut half = null_mut();
        let mut depths = [0.0f32; 4];
        // SAFETY: valid buffers and out-pointers; handles destroyed below.
        unsafe {
            assert_eq!(
                ocean_relief_map_create_f32(heights.as_ptr(), 16, 4, 4, 0, 0, &mut map),
                OceanStatus::Ok,
                "{}",
                last_error()
            );
            assert_eq!(ocean_relief_map_downsample(map, &mut half), OceanStatus::Ok);
            assert_eq!(
                ocean_relief_map_depths(half, depths.as_mut_ptr(), 4),
                OceanStatus::Ok
            );
            let mut quarter = null_mut();
            assert_eq!(
                ocean_relief_map_downsample(half, &mut quarter),
                OceanStatus::InvalidArgument
            );
            assert!(quarter.is_null(), "written on failure");
            assert!(last_error().contains("map"), "{}", last_error());
            assert_eq!(
                ocean_relief_map_downsample(null(), &mut quarter),
                OceanStatus::NullPointer
            );
            assert_eq!(
                ocean_relief_map_downsample(map, null_mut()),
                OceanStatus::NullPointer
            );
            ocean_relief_map_destroy(half);
            ocean_relief_map_destroy(map);
        }
        // Depth 1 − k/15; group (0, 0) holds k = 0, 1, 4, 5: mean depth 1 − 2.5/15.
        let want = |k: f32| 1.0 - k / 15.0;
        for (d, k) in depths.iter().zip([2.5, 4.5, 10.5, 12.5]) {
            assert!((d - want(k)).abs() < 1.0e-6, "{d} vs {}", want(k));
        }
    }

    /// The crate's atlas: 64 texels and 6 levels make a 96 x 64 texture, level 2 at (64, 32);
    /// one level is the map alone; level 6 of 64 does not exist.
    #[test]
    fn atlas_is_the_crates() {
        let (mut w, mut h, mut x, mut y) = (0u32, 0u32, 0u32, 0u32);
        // SAFETY: writable out-parameters.
        unsafe {
            assert_eq!(
                ocean_relief_mip_atlas_size(64, 6, &mut w, &mut h),
                OceanStatus::Ok
            );
            assert_eq!((w, h), (96, 64));
            assert_eq!(
                ocean_relief_mip_atlas_size(64, 1, &mut w, &mut h),
                OceanStatus::Ok
            );
            assert_eq!((w, h), (64, 64));
            assert_eq!(
                ocean_relief_mip_atlas_origin(64, 2, &mut x, &mut y),
                OceanStatus::Ok
            );
            assert_eq!((x, y), (64, 32));
            assert_eq!(
                ocean_relief_mip_atlas_origin(64, 0, &mut x, &mut y),
                OceanStatus::Ok
            );
            assert_eq!((x, y), (0, 0));
            x = 7;
            assert_eq!(
                ocean_relief_mip_atlas_origin(64, 6, &mut x, &mut y),
                OceanStatus::InvalidArgument
            );
            assert_eq!(x, 7, "written on failure");
            assert!(last_error().contains("`level` = 6"), "{}", last_error());
            assert_eq!(
                ocean_relief_mip_atlas_size(64, 7, &mut w, &mut h),
                OceanStatus::InvalidArgument
            );
            assert_eq!(
                ocean_relief_mip_atlas_size(64, 2, null_mut(), &mut h),
                OceanStatus::NullPointer
            );
            assert_eq!(
                ocean_relief_mip_atlas_origin(64, 1, &mut x, null_mut()),
                OceanStatus::NullPointer
            );
        }
    }

    #[test]
    fn mip_level_is_the_crates() {
        let mut l = 99u32;
        let t = 1.0 / 64.0;
        // rho = 3 texels: 2^1.5 ≈ 2.83 <= 3 < 2^2.5, level 2.
        // SAFETY: `l` is writable.
        unsafe {
            assert_eq!(
                ocean_relief_mip_level(3.0 * t, 0.0, 0.0, t, 64, 6, &mut l),
                OceanStatus::Ok
            );
            assert_eq!(l, 2);
            assert_eq!(
                ocean_relief_mip_level(3.0 * t, 0.0, 0.0, t, 64, 2, &mut l),
                OceanStatus::Ok
            );
            assert_eq!(l, 1);
            for (size, levels) in [(64, 0), (64, 7), (48, 2), (1, 1), (8192, 1)] {
                l = 99;
                assert_eq!(
                    ocean_relief_mip_level(t, 0.0, 0.0, t, size, levels, &mut l),
                    OceanStatus::InvalidArgument,
                    "{size} {levels}"
                );
                assert_eq!(l, 99, "written on failure");
            }
            assert_eq!(
                ocean_relief_mip_level(t, 0.0, 0.0, t, 64, 1, null_mut()),
                OceanStatus::NullPointer
            );
        }
    }
}
