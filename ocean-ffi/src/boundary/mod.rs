//! The boundary: every check between a C caller and the library, written once.
//!
//! Every entry point of the C ABI is a thin function that states its contract by calling these
//! helpers, inside [`crate::status::guard`] (the panic boundary and the last-error message):
//!
//! - [`handle`]: opaque handles, a registry of live objects with kinds ([`borrow`],
//!   [`write_handle`], [`destroy`]);
//! - [`pointer`]: pointers, lengths, input slices and out-parameters;
//! - [`value`]: finiteness and the brief printing of numbers in messages;
//! - [`enums`]: enumerations, in structs ([`read_checked`]) and parameters ([`check_enum`]);
//! - [`chain`]: the extensions chained to parameter structs ([`read_params`]).
//!
//! # The contract every function follows
//!
//! A status-returning function checks its arguments in this order and reports the first
//! failure (the precedence of errors that `include/ocean.h` documents in `OceanStatus`):
//!
//! 1. handles, in parameter order: NULL is `OCEAN_STATUS_NULL_POINTER`; another kind, a
//!    destroyed handle or a value the library never returned is `OCEAN_STATUS_INVALID_HANDLE`;
//! 2. other pointers, in parameter order: `OCEAN_STATUS_NULL_POINTER`, then
//!    `OCEAN_STATUS_MISALIGNED_POINTER`;
//! 3. counts: `OCEAN_STATUS_EMPTY` for zero, then `OCEAN_STATUS_LENGTH_OVERFLOW` when a byte
//!    size exceeds `PTRDIFF_MAX`, then `OCEAN_STATUS_LENGTH_MISMATCH` for a buffer whose length
//!    is not the exact length the call needs ([`check_len`]; after the values that decide that
//!    length, where some do: a level, the cone parameters), then
//!    `OCEAN_STATUS_INVALID_ARGUMENT` for buffers that overlap;
//! 4. values, in parameter order and struct fields in declaration order:
//!    `OCEAN_STATUS_NON_FINITE` for NaN and infinities, then the range checks
//!    (`OCEAN_STATUS_INVALID_ARGUMENT`, `OCEAN_STATUS_TOO_STEEP`, ...);
//! 5. the state of a handle (`OCEAN_STATUS_NOT_FOUND`, `OCEAN_STATUS_NOT_EVALUATED`,
//!    `OCEAN_STATUS_OUTSIDE_GRID`) and the work itself: a result that would not be finite is
//!    `OCEAN_STATUS_INVALID_ARGUMENT`, naming the inputs that cause it.
//!
//! No output is written on failure.
//!
//! # One sizing convention
//!
//! Every output array has a length the caller knows before the call: one result per input, or
//! an exact length from the call's own arguments, a constant of the header
//! (`OCEAN_*_UNIFORMS_SIZE`) or a named size query. The caller passes that length and
//! [`check_len`] holds it to it, so a buffer sized for another texture or another version of a
//! block is refused rather than half-filled. Text the library owns is returned as a pointer,
//! never copied into a caller's buffer.

pub(crate) mod chain;
pub(crate) mod enums;
pub(crate) mod handle;
pub(crate) mod pointer;
pub(crate) mod value;

pub(crate) use chain::check_chain;
pub use chain::{OceanChain, OceanNext};
pub(crate) use enums::{CEnum, CheckedStruct, EnumField, check_enum};
pub(crate) use handle::{borrow, destroy, write_handle};
pub(crate) use pointer::{
    byte_len, check_disjoint, check_len, check_ptr, input, read_checked, read_in, read_params,
    read_params_checked, write_out, write_slice,
};
#[cfg(feature = "gpu")]
pub(crate) use pointer::{check_block_out, write_block};
pub(crate) use value::{Approx, Num, check_finite, check_flag, check_reserved, check_time};
