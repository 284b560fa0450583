//! The invariants checked after every C ABI call (FUZZING.md):
//!
//! - `OCEAN_STATUS_PANIC` never comes back: a caught panic is a bug in the library;
//! - a failure leaves a non-empty `ocean_last_error_message()`;
//! - a success leaves every floating-point output finite, unless the call is one of the known
//!   cases listed in `known.rs`.
//!
//! A broken invariant panics, which libFuzzer's hook turns into an abort and a saved crash.

use crate::known::Args;
use std::ffi::CStr;

use ocean::{OceanStatus, ocean_last_error_message};

use crate::finite::Finite;
use crate::known::known_non_finite;

/// Checks the status of `function` called with `inputs`: no panic, and a message with every
/// failure. Returns whether it succeeded.
pub fn status(function: &str, inputs: &dyn Args, status: OceanStatus) -> bool {
    if status == OceanStatus::Panic {
        panic!(
            "{function} returned OCEAN_STATUS_PANIC ({}) for {inputs:?}",
            last_error()
        );
    }
    if status != OceanStatus::Ok && last_error().is_empty() {
        panic!("{function} failed with {status:?} but left no error message, for {inputs:?}");
    }
    status == OceanStatus::Ok
}

/// [`status`], then, on success, every float of `outputs` finite.
pub fn outputs<T: Finite + std::fmt::Debug + ?Sized>(
    function: &str,
    inputs: &dyn Args,
    st: OceanStatus,
    outputs: &T,
) -> bool {
    let ok = status(function, inputs, st);
    if ok && !outputs.is_finite() && !known_non_finite(function, inputs) {
        panic!(
            "{function} succeeded with a non-finite output\n  inputs: {inputs:?}\n  outputs: \
             {outputs:?}"
        );
    }
    ok
}

/// The calling thread's last error message, copied.
pub fn last_error() -> String {
    let p = ocean_last_error_message();
    assert!(!p.is_null(), "ocean_last_error_message returned NULL");
    // SAFETY: `ocean_last_error_message` returns a NUL-terminated string that stays valid until
    // the next status-returning call on this thread (include/ocean.h); it is copied at once.
    unsafe { CStr::from_ptr(p) }.to_string_lossy().into_owned()
}
