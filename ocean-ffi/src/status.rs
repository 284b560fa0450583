//! Status codes, the thread-local last-error message and the panic boundary.

use core::ffi::{CStr, c_char};
use std::any::Any;
use std::cell::RefCell;
use std::ffi::CString;
use std::panic::{AssertUnwindSafe, catch_unwind};

/// Result of every fallible `ocean_*` function.
///
/// `OCEAN_STATUS_OK` (0) is success; any other value is a failure, after which no output
/// parameter has been written and `ocean_last_error_message()` describes what went wrong.
/// The numeric values are stable: new codes are only ever appended.
#[repr(u32)]
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum OceanStatus {
    /// Success.
    Ok = 0,
    /// A required pointer argument was NULL.
    NullPointer = 1,
    /// A pointer argument was not aligned for its type.
    MisalignedPointer = 2,
    /// An argument is out of its documented range (zero direction, depth <= 0, wavelength <= 0,
    /// negative amplitude, grid spacing <= 0, overlapping buffers, ...).
    InvalidArgument = 3,
    /// A floating-point argument (time, a wave parameter, a position) was NaN or infinite where
    /// a finite value is required.
    NonFinite = 4,
    /// A count was zero (no waves, no points, an empty grid).
    Empty = 5,
    /// A count is so large that its size in bytes would exceed `PTRDIFF_MAX` (`isize::MAX`), or
    /// a grid's point count overflows `size_t`.
    LengthOverflow = 6,
    /// A wave's steepness k*A exceeds 1, where the trochoid would loop over itself.
    TooSteep = 7,
    /// The library panicked (a bug in ocean); the panic was caught at the boundary. Output
    /// buffers of an evaluation may then hold partial results.
    Panic = 8,
    /// A handle's member named by the caller does not exist (a wave train box id that was
    /// removed, never issued, or belongs to another scene).
    NotFound = 9,
    /// A wave train box cannot touch the water grid: its rectangle at full fetch lies wholly
    /// outside the grid's rectangle, so it could never move a single point.
    OutsideGrid = 10,
    /// No usable GPU adapter: none was found for the backends `WGPU_BACKEND` selects (all when
    /// unset), or the one found lacks compute shaders or WebGPU's downlevel limits, or refused
    /// to create a device. The message says what to install (Mesa's lavapipe, or llvmpipe
    /// through `WGPU_BACKEND=gl`).
    NoAdapter = 11,
    /// The GPU backend failed: the device reported a validation, out-of-memory or device-lost
    /// error, reading an image back failed, or naga could not translate a shader. The message
    /// carries the backend's text.
    GpuFailure = 12,
    /// A buffer's length (`len`, `n`, `*_len`) is not the exact length the call needs: the
    /// function's documentation says how to know it beforehand (from the call's own arguments,
    /// a constant such as `OCEAN_SAO_UNIFORMS_SIZE`, or a named size query). Nothing was read
    /// or written through the buffer.
    LengthMismatch = 13,
    /// The caller's progress callback asked to stop (returned nonzero); nothing was written.
    Cancelled = 14,
    /// A call answers for what the last evaluation drew, and there is none: the scene was
    /// never evaluated, or changed since (a box, the terrain, the effects, the budget or the
    /// train filter). Evaluate it again first.
    NotEvaluated = 15,
    /// A handle argument is not a live handle of its kind: it is of another kind (an
    /// `OceanSpectrum *` passed as an `OceanLighting *`), was destroyed, or is a value no
    /// function of this library returned (zeroed or freed memory). Nothing was read through
    /// it. A destroy function given such a handle frees nothing and sets this message.
    InvalidHandle = 16,
    /// `ocean_check_version`: the program was compiled against a header whose ABI this library
    /// does not provide (another major version, another minor version before 1.0, or a newer
    /// header than the library).
    VersionMismatch = 17,
}

/// Every status, in numeric order.
const ALL_STATUSES: [OceanStatus; 18] = [
    OceanStatus::Ok,
    OceanStatus::NullPointer,
    OceanStatus::MisalignedPointer,
    OceanStatus::InvalidArgument,
    OceanStatus::NonFinite,
    OceanStatus::Empty,
    OceanStatus::LengthOverflow,
    OceanStatus::TooSteep,
    OceanStatus::Panic,
    OceanStatus::NotFound,
    OceanStatus::OutsideGrid,
    OceanStatus::NoAdapter,
    OceanStatus::GpuFailure,
    OceanStatus::LengthMismatch,
    OceanStatus::Cancelled,
    OceanStatus::NotEvaluated,
    OceanStatus::InvalidHandle,
    OceanStatus::VersionMismatch,
];

impl OceanStatus {
    fn message(self) -> &'static CStr {
        match self {
            OceanStatus::Ok => c"ok",
            OceanStatus::NullPointer => c"a required pointer argument is NULL",
            OceanStatus::MisalignedPointer => c"a pointer argument is misaligned for its type",
            OceanStatus::InvalidArgument => c"an argument is out of range",
            OceanStatus::NonFinite => c"a floating-point argument is NaN or infinite",
            OceanStatus::Empty => c"a count is zero",
            OceanStatus::LengthOverflow => c"a count is too large: its size in bytes overflows",
            OceanStatus::TooSteep => c"a wave is too steep (k*A > 1): the trochoid would loop",
            OceanStatus::Panic => c"internal error: the library panicked",
            OceanStatus::NotFound => c"no such object (an unknown or removed id)",
            OceanStatus::OutsideGrid => c"a wave train box lies wholly outside the water grid",
            OceanStatus::NoAdapter => c"no usable GPU adapter",
            OceanStatus::GpuFailure => c"the GPU backend failed",
            OceanStatus::LengthMismatch => {
                c"a buffer's length is not the exact length the call needs"
            }
            OceanStatus::Cancelled => c"cancelled by the caller's progress callback",
            OceanStatus::NotEvaluated => c"no evaluated frame to answer for: evaluate first",
            OceanStatus::InvalidHandle => {
                c"not a live handle of its kind (another kind, destroyed, or never made)"
            }
            OceanStatus::VersionMismatch => {
                c"the program's header and this library have incompatible versions"
            }
        }
    }
}

/// A static, NUL-terminated English description of a status code.
///
/// `status` is taken as a plain integer so that any value is safe to pass; values that are not an
/// `OceanStatus` give "unknown status". Never NULL, never fails, any thread. The detailed message
/// of the last failure is `ocean_last_error_message()`.
#[unsafe(no_mangle)]
pub extern "C" fn ocean_status_message(status: u32) -> *const c_char {
    ALL_STATUSES
        .iter()
        .find(|s| **s as u32 == status)
        .map_or(c"unknown status", |s| s.message())
        .as_ptr()
}

thread_local! {
    static LAST_ERROR: RefCell<Option<CString>> = const { RefCell::new(None) };
}

/// Replaces the calling thread's last-error message (`None` clears it).
pub(crate) fn set_last_error(message: Option<String>) {
    let message = message
        .map(|m| CString::new(m.replace('\0', "\\0")).expect("interior NUL bytes were replaced"));
    // `try_with` fails only during thread teardown, when nobody can read the message any more.
    let _ = LAST_ERROR.try_with(|e| *e.borrow_mut() = message);
}

/// The detailed message of the most recent failed `ocean_*` call on the calling thread, as a
/// NUL-terminated UTF-8 string, or "" when the most recent fallible call succeeded (or there was
/// none).
///
/// The message is thread-local: a failure on one thread never changes another thread's message.
/// Every function that returns an `OceanStatus` replaces it (clearing it on success); the
/// functions that do not return a status (`ocean_version`, `ocean_status_message`,
/// `ocean_last_error_message`, `ocean_waves_destroy`) leave it alone. The returned pointer is
/// owned by the library and stays valid until the next call of a status-returning function on
/// the same thread, or until the thread exits; copy the text to keep it longer. Never NULL.
#[unsafe(no_mangle)]
pub extern "C" fn ocean_last_error_message() -> *const c_char {
    LAST_ERROR
        .try_with(|e| {
            // The CString's heap buffer outlives the borrow; it is freed only when a later
            // `set_last_error` on this thread replaces it, which the contract above allows.
            e.borrow().as_ref().map_or(c"".as_ptr(), |m| m.as_ptr())
        })
        .unwrap_or(c"".as_ptr())
}

/// A failure: its status and the detailed message.
#[derive(Debug)]
pub(crate) struct Error {
    pub(crate) status: OceanStatus,
    pub(crate) message: String,
}

impl Error {
    pub(crate) fn new(status: OceanStatus, message: impl Into<String>) -> Self {
        Self {
            status,
            message: message.into(),
        }
    }
}

fn panic_text(payload: &(dyn Any + Send)) -> &str {
    if let Some(s) = payload.downcast_ref::<&'static str>() {
        s
    } else if let Some(s) = payload.downcast_ref::<String>() {
        s
    } else {
        "non-string panic payload"
    }
}

/// The panic boundary and error reporting of every status-returning function: runs `body`,
/// catches any panic, records the message of a failure (prefixed with `function`) as the thread's
/// last error, or clears it on success, and returns the status.
pub(crate) fn guard(function: &str, body: impl FnOnce() -> Result<(), Error>) -> OceanStatus {
    let outcome = catch_unwind(AssertUnwindSafe(body));
    let (status, message) = match outcome {
        Ok(Ok(())) => (OceanStatus::Ok, None),
        Ok(Err(e)) => (e.status, Some(format!("{function}: {}", e.message))),
        Err(payload) => {
            let text = format!("{function}: panic: {}", panic_text(&*payload));
            // Dropping a payload runs arbitrary Drop code; keep that inside a boundary too.
            let _ = catch_unwind(AssertUnwindSafe(move || drop(payload)));
            (OceanStatus::Panic, Some(text))
        }
    };
    set_last_error(message);
    status
}

/// The thread's last error message, copied (for the tests of every module).
#[cfg(test)]
pub(crate) fn last_error() -> String {
    // SAFETY: `ocean_last_error_message` returns a valid NUL-terminated string that lives until
    // the next status-returning call on this thread; it is copied at once.
    unsafe { CStr::from_ptr(ocean_last_error_message()) }
        .to_string_lossy()
        .into_owned()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_status_has_a_distinct_message_and_unknown_values_are_safe() {
        let mut seen = std::collections::HashSet::new();
        for (i, s) in ALL_STATUSES.iter().enumerate() {
            // The codes are consecutive from 0, as the header promises.
            assert_eq!(*s as u32, i as u32);
            // SAFETY: `ocean_status_message` returns a static NUL-terminated string.
            let m = unsafe { CStr::from_ptr(ocean_status_message(*s as u32)) };
            assert!(!m.is_empty());
            assert!(seen.insert(m.to_owned()), "duplicate message {m:?}");
        }
        for bad in [ALL_STATUSES.len() as u32, 1000, u32::MAX] {
            // SAFETY: as above.
            let m = unsafe { CStr::from_ptr(ocean_status_message(bad)) };
            assert_eq!(m, c"unknown status");
        }
    }

    #[test]
    fn guard_reports_errors_clears_on_success_and_catches_panics() {
        let s = guard("f", || Err(Error::new(OceanStatus::TooSteep, "detail 1.5")));
        assert_eq!(s, OceanStatus::TooSteep);
        assert_eq!(last_error(), "f: detail 1.5");

        assert_eq!(guard("g", || Ok(())), OceanStatus::Ok);
        assert_eq!(last_error(), "");

        let s = guard("h", || panic!("boom {}", 42));
        assert_eq!(s, OceanStatus::Panic);
        assert_eq!(last_error(), "h: panic: boom 42");

        let s = guard("i", || std::panic::panic_any(7_i32));
        assert_eq!(s, OceanStatus::Panic);
        assert_eq!(last_error(), "i: panic: non-string panic payload");
    }

    #[test]
    fn messages_with_nul_bytes_are_kept_readable() {
        let s = guard("f", || {
            Err(Error::new(OceanStatus::InvalidArgument, "a\0b"))
        });
        assert_eq!(s, OceanStatus::InvalidArgument);
        assert_eq!(last_error(), "f: a\\0b");
    }

    #[test]
    fn last_error_is_thread_local() {
        guard("main", || Err(Error::new(OceanStatus::Empty, "here")));
        std::thread::spawn(|| {
            assert_eq!(last_error(), "");
            guard("other", || Err(Error::new(OceanStatus::NonFinite, "there")));
            assert_eq!(last_error(), "other: there");
        })
        .join()
        .unwrap();
        assert_eq!(last_error(), "main: here");
    }
}
