//! Pointers, lengths and out-parameters from C: every check that turns a raw pointer into a
//! Rust reference or slice, written once.

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
    checked_from_bytes(bytes, name)
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

/// The pointer and count checks of [`write_sized`], in parameter order: `out` NULL with `len`
/// != 0 (`OCEAN_STATUS_NULL_POINTER`), `needed`, then `len` beyond `PTRDIFF_MAX`. A function
/// calls it before its values, which the header's error order reports later.
#[cfg(feature = "gpu")]
pub(crate) fn check_sized(
    out: *const u8,
    out_name: &str,
    len: usize,
    needed: *const usize,
) -> Result<(), Error> {
    if out.is_null() && len != 0 {
        return Err(Error::new(
            OceanStatus::NullPointer,
            format!("`{out_name}` is NULL but `len` is {len} (pass NULL and 0 to query the size)"),
        ));
    }
    check_ptr(needed, "needed")?;
    byte_len::<u8>(len, out_name)?;
    Ok(())
}

/// Checks that a caller's buffer of `len` values is exactly `want` long.
///
/// A count above `PTRDIFF_MAX` is `OCEAN_STATUS_LENGTH_OVERFLOW` (its byte size overflows
/// whatever the element), reported before the mismatch as the header's error order says.
pub(crate) fn check_len(name: &str, len: usize, want: usize, what: &str) -> Result<(), Error> {
    byte_len::<u8>(len, name)?;
    if len != want {
        return Err(Error::new(
            OceanStatus::InvalidArgument,
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

/// Copies a byte block into a caller's buffer by the size-query protocol that every function
/// writing bytes follows (`ocean_gpu_context_describe`, the uniform blocks):
///
/// - `out` NULL and `len` 0: a pure query, `*needed` = the block's size, `OCEAN_STATUS_OK`;
/// - `len` >= the size: the block is copied to `out[0..size]` and `*needed` = the size;
/// - `len` smaller: `OCEAN_STATUS_BUFFER_TOO_SMALL`, `*needed` = the size (the one output
///   written on a failure), `out` untouched.
///
/// The pointers and the count are checked first, by [`check_sized`].
///
/// # Safety
///
/// `out` must be NULL or point to `len` writable bytes that no other thread touches during the
/// call; `needed` must be NULL, misaligned or writable.
#[cfg(feature = "gpu")]
pub(crate) unsafe fn write_sized(
    out: *mut u8,
    out_name: &str,
    len: usize,
    needed: *mut usize,
    bytes: &[u8],
    what: &str,
) -> Result<(), Error> {
    check_sized(out.cast_const(), out_name, len, needed.cast_const())?;
    let n = bytes.len();
    if out.is_null() {
        // SAFETY: non-NULL and aligned (checked), writable (caller's guarantee).
        unsafe { needed.write(n) };
        return Ok(());
    }
    // SAFETY: as above.
    unsafe { needed.write(n) };
    if len < n {
        return Err(Error::new(
            OceanStatus::BufferTooSmall,
            format!("`len` is {len} bytes, {what} needs {n}"),
        ));
    }
    // SAFETY: non-NULL, `n` <= `len` bytes whose size fits in isize (checked), writable and
    // untouched by others (caller's guarantee); `u8` has alignment 1.
    unsafe { core::slice::from_raw_parts_mut(out, n) }.copy_from_slice(bytes);
    Ok(())
}

/// [`write_sized`] for a uniform block, the bytes of a `Pod` struct, into the caller's `out`.
///
/// # Safety
///
/// As [`write_sized`].
#[cfg(feature = "gpu")]
pub(crate) unsafe fn write_block<T: bytemuck::Pod>(
    out: *mut u8,
    len: usize,
    needed: *mut usize,
    block: &T,
) -> Result<(), Error> {
    // SAFETY: forwarded from this function's contract.
    unsafe {
        write_sized(
            out,
            "out",
            len,
            needed,
            bytemuck::bytes_of(block),
            "the uniform block",
        )
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A count above PTRDIFF_MAX is an overflow before it is a mismatch (the header's order:
    /// EMPTY, then LENGTH_OVERFLOW, then INVALID_ARGUMENT); the bad-input matrix
    /// (`tests/tests/c_matrix.rs`) found exact-length buffers answering INVALID_ARGUMENT.
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
        let e = check_len("len", usize::MAX / 2, 16, "the map").unwrap_err();
        assert_eq!(e.status, OceanStatus::InvalidArgument, "{}", e.message);
        assert!(check_len("len", 16, 16, "the map").is_ok());
    }

    /// The size query's pointers and count, in parameter order, whatever the values after them.
    #[cfg(feature = "gpu")]
    #[test]
    fn check_sized_checks_pointers_then_the_count() {
        let mut buf = [0u8; 8];
        let mut needed = 0usize;
        let (out, nd) = (buf.as_mut_ptr().cast_const(), &raw mut needed);
        let status = |o, len, n| check_sized(o, "out", len, n).map_err(|e| e.status);
        assert_eq!(status(out, 8, nd.cast_const()), Ok(()));
        // The pure query.
        assert_eq!(status(core::ptr::null(), 0, nd.cast_const()), Ok(()));
        assert_eq!(
            status(core::ptr::null(), 8, core::ptr::null()),
            Err(OceanStatus::NullPointer)
        );
        assert_eq!(
            status(out, 8, core::ptr::null()),
            Err(OceanStatus::NullPointer)
        );
        assert_eq!(
            status(out, usize::MAX, nd.cast_const()),
            Err(OceanStatus::LengthOverflow)
        );
    }
}
