//! Pointers, lengths and out-parameters from C: every check that turns a raw pointer into a
//! Rust reference or slice, written once.

use super::chain::{Extensible, check_chain};
use super::enums::{CheckedStruct, checked_from_bytes};
use crate::status::{Error, OceanStatus};

/// `OCEAN_STATUS_NULL_POINTER` for NULL, `OCEAN_STATUS_MISALIGNED_POINTER` for a pointer not
/// aligned for `T`.
pub(crate) fn check_ptr<T>(p: *const T, name: &str) -> Result<(), Error> {
    if p.is_null() {
        return Err(Error::new(
            OceanStatus::NullPointer,
            format!("`{name}` is NULL"),
        ));
    }
    if !p.is_aligned() {
        return Err(Error::new(
            OceanStatus::MisalignedPointer,
            format!(
                "`{name}` ({p:p}) is not aligned to {} bytes",
                align_of::<T>()
            ),
        ));
    }
    Ok(())
}

/// Size in bytes of `n` elements of `T`, if it fits in `isize::MAX` (the limit of every Rust and
/// C object).
pub(crate) fn byte_len<T>(n: usize, name: &str) -> Result<usize, Error> {
    n.checked_mul(size_of::<T>())
        .filter(|&b| b <= isize::MAX as usize)
        .ok_or_else(|| {
            Error::new(
                OceanStatus::LengthOverflow,
                format!(
                    "{n} elements of {} bytes for `{name}` exceed PTRDIFF_MAX bytes",
                    size_of::<T>()
                ),
            )
        })
}

/// Fails if the byte ranges `[a, a + a_len)` and `[b, b + b_len)` intersect.
pub(crate) fn check_disjoint(
    (a, a_len, a_name): (*const u8, usize, &str),
    (b, b_len, b_name): (*const u8, usize, &str),
) -> Result<(), Error> {
    let (a0, b0) = (a as usize, b as usize);
    if a0 < b0.saturating_add(b_len) && b0 < a0.saturating_add(a_len) {
        return Err(Error::new(
            OceanStatus::InvalidArgument,
            format!("`{a_name}` and `{b_name}` overlap"),
        ));
    }
    Ok(())
}

/// Reads a caller's input struct after checking the pointer. Only for structs that every bit
/// pattern is valid for (`AnyBitPattern`): one holding an enumeration is read by
/// [`read_checked`].
///
/// # Safety
///
/// `p` must be NULL, misaligned, or point to a readable `T`.
pub(crate) unsafe fn read_in<T: bytemuck::AnyBitPattern>(
    p: *const T,
    name: &str,
) -> Result<T, Error> {
    check_ptr(p, name)?;
    // SAFETY: non-NULL and aligned (checked); readable (caller's guarantee); copied out.
    Ok(unsafe { p.read() })
}

/// Reads a caller's input struct that holds enumerations (see [`super::enums`]) after checking
/// the pointer: as bytes, each enumeration member's raw value checked in declaration order
/// (`OCEAN_STATUS_INVALID_ARGUMENT`, naming `{name}->{member}` and the value), then cast.
///
/// # Safety
///
/// `p` must be NULL, misaligned, or point to a readable `T`.
pub(crate) unsafe fn read_checked<T: CheckedStruct>(p: *const T, name: &str) -> Result<T, Error> {
    check_ptr(p, name)?;
    // SAFETY: non-NULL and aligned (checked); `size_of::<T>()` readable bytes (caller's
    // guarantee), all initialised: the header's structs have no padding (its conventions), and
    // bytes of any value are valid `u8`. Only read while the call lasts.
    let bytes = unsafe { core::slice::from_raw_parts(p.cast::<u8>(), size_of::<T>()) };
    checked_from_bytes::<T>(bytes, name)?;
    // The value is read again, typed, rather than cast from the bytes: a pointer member
    // (`next`) keeps its provenance that way, and may be followed.
    // SAFETY: as above; every enumeration member holds one of its values (checked), and
    // nothing writes the struct during the call (caller's guarantee).
    Ok(unsafe { p.read() })
}

/// Reads a caller's parameter struct (one that starts with `next`, see [`crate::chain`]) as
/// [`read_in`] does, then checks its extensions.
///
/// # Safety
///
/// As [`read_in`], and the struct's `next` must be NULL, misaligned or point to a readable
/// `OceanChain`.
pub(crate) unsafe fn read_params<T: bytemuck::AnyBitPattern + Extensible>(
    p: *const T,
    name: &str,
) -> Result<T, Error> {
    // SAFETY: forwarded from this function's contract.
    let v = unsafe { read_in(p, name) }?;
    // SAFETY: as above.
    unsafe { check_chain(&v, &format!("{name}->next")) }?;
    Ok(v)
}

/// [`read_params`] for a parameter struct that holds enumerations, read by [`read_checked`].
///
/// # Safety
///
/// As [`read_params`].
pub(crate) unsafe fn read_params_checked<T: CheckedStruct + Extensible>(
    p: *const T,
    name: &str,
) -> Result<T, Error> {
    // SAFETY: forwarded from this function's contract.
    let v = unsafe { read_checked(p, name) }?;
    // SAFETY: as above.
    unsafe { check_chain(&v, &format!("{name}->next")) }?;
    Ok(v)
}

/// Writes `*out` through a checked pointer, after `value` has been computed.
///
/// # Safety
///
/// `out` must be NULL, misaligned, or writable.
pub(crate) unsafe fn write_out<T>(out: *mut T, name: &str, value: T) -> Result<(), Error> {
    check_ptr(out, name)?;
    // SAFETY: non-NULL and aligned (checked); writable (caller's guarantee).
    unsafe { out.write(value) };
    Ok(())
}

/// Borrows `len` values of `T` from a caller's input buffer, after checking the pointer and the
/// byte size.
///
/// # Safety
///
/// `p` must be NULL, misaligned, or point to `len` readable values that nothing writes during
/// the borrow.
pub(crate) unsafe fn input<'a, T>(p: *const T, len: usize, name: &str) -> Result<&'a [T], Error> {
    check_ptr(p, name)?;
    byte_len::<T>(len, name)?;
    // SAFETY: non-NULL and aligned (checked), `len` values whose byte size fits in isize
    // (checked), readable and unmodified during the borrow (caller's guarantee).
    Ok(unsafe { core::slice::from_raw_parts(p, len) })
}

/// Checks that a caller's buffer of `len` values is exactly `want` long.
///
/// A count above `PTRDIFF_MAX` is `OCEAN_STATUS_LENGTH_OVERFLOW` (its byte size overflows
/// whatever the element), reported before the mismatch as the header's error order says.
pub(crate) fn check_len(name: &str, len: usize, want: usize, what: &str) -> Result<(), Error> {
    byte_len::<u8>(len, name)?;
    if len != want {
        return Err(Error::new(
            OceanStatus::LengthMismatch,
            format!("`{name}` is {len} values long, {what} holds exactly {want}"),
        ));
    }
    Ok(())
}

/// Copies a finished result into a caller's output buffer (checked for NULL and alignment).
///
/// # Safety
///
/// `p` must be NULL, misaligned, or point to `values.len()` writable `T` that no other thread
/// touches during the call and that do not overlap any input still borrowed.
pub(crate) unsafe fn write_slice<T: Copy>(
    p: *mut T,
    name: &str,
    values: &[T],
) -> Result<(), Error> {
    check_ptr(p.cast_const(), name)?;
    byte_len::<T>(values.len(), name)?;
    // SAFETY: non-NULL and aligned (checked), `values.len()` elements whose byte size fits in
    // isize (checked), writable and untouched by others (caller's guarantee).
    let out = unsafe { core::slice::from_raw_parts_mut(p, values.len()) };
    out.copy_from_slice(values);
    Ok(())
}

/// Copies a uniform block, the bytes of a `Pod` struct, into the caller's `out`, whose `len`
/// must be exactly the block's size (the header's `OCEAN_*_UNIFORMS_SIZE`).
///
/// The pointer and the length are checked before the block is computed, by
/// [`check_block_out`]; this checks them again (cheaply) so that no caller can skip them.
///
/// # Safety
///
/// `out` must be NULL or point to `len` writable bytes that no other thread touches during the
/// call.
#[cfg(feature = "gpu")]
pub(crate) unsafe fn write_block<T: bytemuck::Pod>(
    out: *mut u8,
    len: usize,
    block: &T,
) -> Result<(), Error> {
    let bytes = bytemuck::bytes_of(block);
    check_block_out::<T>(out, len)?;
    // SAFETY: non-NULL (checked; `u8` needs no alignment), `len` = the block's size (checked),
    // writable and untouched by others (caller's guarantee).
    unsafe { core::slice::from_raw_parts_mut(out, len) }.copy_from_slice(bytes);
    Ok(())
}

/// The checks of a uniform block's output, in the header's order: `out` NULL, then `len`
/// (overflow, then not exactly `size_of::<T>()`). A function calls it before its values.
#[cfg(feature = "gpu")]
pub(crate) fn check_block_out<T>(out: *mut u8, len: usize) -> Result<(), Error> {
    check_ptr(out.cast_const(), "out")?;
    check_len("len", len, size_of::<T>(), "the uniform block (bytes)")
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A count above PTRDIFF_MAX is an overflow before it is a mismatch (the header's order:
    /// EMPTY, then LENGTH_OVERFLOW, then LENGTH_MISMATCH); the bad-input matrix
    /// (`tests/tests/c_matrix.rs`) found exact-length buffers answering the mismatch first.
    #[test]
    fn check_len_reports_overflow_before_mismatch() {
        for len in [usize::MAX, usize::MAX / 2 + 1] {
            let e = check_len("len", len, 16, "the map").unwrap_err();
            assert_eq!(
                e.status,
                OceanStatus::LengthOverflow,
                "{len}: {}",
                e.message
            );
        }
        for len in [usize::MAX / 2, 17, 15, 0] {
            let e = check_len("len", len, 16, "the map").unwrap_err();
            assert_eq!(e.status, OceanStatus::LengthMismatch, "{}", e.message);
        }
        assert!(check_len("len", 16, 16, "the map").is_ok());
    }

    /// A uniform block's output: NULL first, then any length but the block's own (one byte
    /// more is refused as well as one less: a buffer sized for another version of the block).
    #[cfg(feature = "gpu")]
    #[test]
    fn check_block_out_wants_exactly_the_block() {
        let mut buf = [0u8; 9];
        let out = buf.as_mut_ptr();
        let status = |o, len| check_block_out::<[u32; 2]>(o, len).map_err(|e| e.status);
        assert_eq!(status(out, 8), Ok(()));
        assert_eq!(
            status(core::ptr::null_mut(), 8),
            Err(OceanStatus::NullPointer)
        );
        assert_eq!(status(out, 9), Err(OceanStatus::LengthMismatch));
        assert_eq!(status(out, 7), Err(OceanStatus::LengthMismatch));
        assert_eq!(status(out, usize::MAX), Err(OceanStatus::LengthOverflow));
        let mut block = [0u8; 8];
        // SAFETY: `block` is 8 writable bytes.
        assert!(unsafe { write_block(block.as_mut_ptr(), 8, &[1u32, 2u32]) }.is_ok());
        assert_eq!(block, bytemuck::bytes_of(&[1u32, 2u32]));
    }
}
