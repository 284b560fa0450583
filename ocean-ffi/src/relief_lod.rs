//! Relief mapping's level of detail (ocean-relief's `lod` module): the coarser height maps of a
//! relief texture's mip levels and the level a fragment reads, for engines that draw the
//! exported `relief` shader with mip levels (`ocean_relief_uniforms`' `levels`).
//!
//! Level l + 1's depth is the 2x2 mean of level l's, and each level needs cones of its own
//! surface: make them with `ocean_relief_cones_create` (or `ocean_relief_quad_cones_create`)
//! on the map `ocean_relief_map_downsample` returns. The 4x4-window chain of
//! `ocean_relief_mips_create` keeps cones valid over level 0's surface only.

use glam::Vec2;
use ocean_relief::lod::{downsample, max_levels, mip_level};

use crate::lighting::{borrow, write_handle};
use crate::relief::{OceanReliefMap, relief_error};
use crate::status::{Error, OceanStatus, guard};
use crate::waves::{check_ptr, write_out};

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
/// `map` must be a live handle and `out` writable.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn ocean_relief_map_downsample(
    map: *const OceanReliefMap,
    out: *mut *mut OceanReliefMap,
) -> OceanStatus {
    guard("ocean_relief_map_downsample", || {
        // SAFETY: forwarded from this function's contract.
        let m = unsafe { borrow(map, "map") }?;
        check_ptr(out.cast_const(), "out")?;
        let half = downsample(&m.map).map_err(|e| relief_error("map: ", e))?;
        // SAFETY: forwarded from this function's contract.
        unsafe { write_handle(out, OceanReliefMap { map: half }) }
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
        let n = size as usize;
        if !(2..=ocean_relief::MAX_SIDE).contains(&n) {
            return Err(Error::new(
                OceanStatus::InvalidArgument,
                format!("`size` = {size} is outside 2 to {}", ocean_relief::MAX_SIDE),
            ));
        }
        let most = if n.is_power_of_two() {
            max_levels(n)
        } else {
            1
        };
        if levels == 0 || levels as usize > most {
            return Err(Error::new(
                OceanStatus::InvalidArgument,
                format!("`levels` = {levels} is outside 1 to {most} for a side of {size}"),
            ));
        }
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
