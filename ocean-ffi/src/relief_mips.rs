//! Mip chains of cone maps (`OceanReliefMips`): level 0 down to 1x1, each level valid for its
//! own surface, and each level's encoded texels.

use core::ffi::c_void;

use ocean_relief::ConeMap;
use ocean_relief::mip::{MipRule, chain};

use crate::boundary::{borrow, check_enum, check_len, check_ptr, destroy, write_handle, write_out};
use crate::relief::*;
use crate::relief_encode::{check_encoded_out, encode_cones, write_encoded};
use crate::status::{Error, OceanStatus, guard};

/// A mip chain of a cone map, level 0 (the cone map) down to 1x1 (opaque). Create with
/// `ocean_relief_mips_create`, free with `ocean_relief_mips_destroy`. Immutable and shareable.
pub struct OceanReliefMips {
    levels: Vec<ConeMap>,
}

/// Builds the mip chain of the cone map of `cones`, level 0 (the cone map) down to 1x1, and
/// stores a handle in `*out`. `rule`: `OCEAN_RELIEF_MIP_WINDOW` (the 4x4-window minimum, valid
/// under bilinear sampling; use it) or `OCEAN_RELIEF_MIP_GROUP` (the book's 2x2 minimum, valid
/// under nearest sampling only). Every channel takes the same minimum.
///
/// Returns `OCEAN_STATUS_NULL_POINTER` / `_MISALIGNED_POINTER` for a bad pointer,
/// `OCEAN_STATUS_INVALID_ARGUMENT` for an unknown rule or a side that is not a power of two.
/// `*out` is written only on success.
///
/// # Safety
///
/// `out` must be writable.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn ocean_relief_mips_create(
    cones: *const OceanReliefCones,
    rule: u32,
    out: *mut *mut OceanReliefMips,
) -> OceanStatus {
    guard("ocean_relief_mips_create", || {
        let c = borrow(cones, "cones")?;
        check_ptr(out.cast_const(), "out")?;
        let rule = match check_enum::<OceanReliefMip>("`rule`", rule)? {
            OceanReliefMip::Window => MipRule::Window,
            OceanReliefMip::Group => MipRule::Group,
        };
        let levels = chain(&c.cones, rule)?;
        // SAFETY: forwarded from this function's contract.
        unsafe { write_handle(out, OceanReliefMips { levels }) }
    })
}

/// Frees a mip chain. NULL does nothing; a handle of another kind or already destroyed frees
/// nothing and sets the last-error message (see the header's notes on handles).
#[unsafe(no_mangle)]
pub extern "C" fn ocean_relief_mips_destroy(mips: *mut OceanReliefMips) {
    destroy(mips, "ocean_relief_mips_destroy", "mips");
}

/// Stores the number of levels, log2(N) + 1, in `*out_count`.
///
/// Returns `OCEAN_STATUS_NULL_POINTER` / `_MISALIGNED_POINTER` for a bad pointer; `*out_count`
/// is written only on success.
///
/// # Safety
///
/// `out_count` must be writable.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn ocean_relief_mips_level_count(
    mips: *const OceanReliefMips,
    out_count: *mut u32,
) -> OceanStatus {
    guard("ocean_relief_mips_level_count", || {
        let m = borrow(mips, "mips")?;
        // At most 13 levels (N <= 4096).
        let count = m.levels.len() as u32;
        // SAFETY: forwarded from this function's contract.
        unsafe { write_out(out_count, "out_count", count) }
    })
}

pub(crate) fn level(m: &OceanReliefMips, level: u32) -> Result<&ConeMap, Error> {
    m.levels.get(level as usize).ok_or_else(|| {
        Error::new(
            OceanStatus::InvalidArgument,
            format!(
                "level {level} does not exist: the chain has levels 0 to {}",
                m.levels.len() - 1
            ),
        )
    })
}

/// Stores the side of mip `level`, N >> level texels, in `*out_size`.
///
/// Returns `OCEAN_STATUS_NULL_POINTER` / `_MISALIGNED_POINTER` for a bad pointer,
/// `OCEAN_STATUS_INVALID_ARGUMENT` if `level` >= the level count. `*out_size` is written only on
/// success.
///
/// # Safety
///
/// `out_size` must be writable.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn ocean_relief_mips_level_size(
    mips: *const OceanReliefMips,
    level: u32,
    out_size: *mut u32,
) -> OceanStatus {
    guard("ocean_relief_mips_level_size", || {
        let m = borrow(mips, "mips")?;
        check_ptr(out_size.cast_const(), "out_size")?;
        // At most OCEAN_RELIEF_MAX_SIDE.
        let side = self::level(&m, level)?.size() as u32;
        // SAFETY: forwarded from this function's contract.
        unsafe { write_out(out_size, "out_size", side) }
    })
}

/// Encodes mip `level` and copies it into `out`: `len` = 3 side * side elements (side from
/// `ocean_relief_mips_level_size`) of the encoding's type, `[c, D, E]` per texel, row-major,
/// rounded down, as `ocean_relief_cones_encode` writes level 0.
///
/// Returns `OCEAN_STATUS_NULL_POINTER` / `_MISALIGNED_POINTER` for a bad pointer,
/// `OCEAN_STATUS_INVALID_ARGUMENT` for an unknown encoding or a level that does not exist,
/// `OCEAN_STATUS_LENGTH_MISMATCH` for a `len` that is not 3 side * side. Nothing is written
/// on failure.
///
/// # Safety
///
/// `out` must point to `len` writable elements of the encoding's
/// type that no other thread touches during the call.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn ocean_relief_mips_copy_level(
    mips: *const OceanReliefMips,
    level: u32,
    encoding: u32,
    out: *mut c_void,
    len: usize,
) -> OceanStatus {
    guard("ocean_relief_mips_copy_level", || {
        let m = borrow(mips, "mips")?;
        check_ptr(out.cast_const().cast::<u8>(), "out")?;
        let encoding = encoding_from(encoding)?;
        check_encoded_out(out, encoding)?;
        let l = self::level(&m, level)?;
        let side = l.size();
        check_len(
            "len",
            len,
            3 * side * side,
            &format!("level {level} (3 values a texel)"),
        )?;
        let values = encode_cones(l, encoding);
        // SAFETY: forwarded from this function's contract.
        unsafe { write_encoded(out, &values) }
    })
}

const _: () = {
    const fn shareable<T: Send + Sync>() {}
    shareable::<OceanReliefMips>();
};

crate::boundary::handle::handles!(OceanReliefMips);
