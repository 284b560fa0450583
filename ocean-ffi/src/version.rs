//! Version macros and `ocean_version`.

use core::ffi::{CStr, c_char};

use crate::status::{Error, OceanStatus, guard};

/// Major version of the library this header belongs to (the `ocean-ffi` crate version).
pub const OCEAN_VERSION_MAJOR: u32 = 0;
/// Minor version of the library this header belongs to.
pub const OCEAN_VERSION_MINOR: u32 = 1;
/// Patch version of the library this header belongs to.
pub const OCEAN_VERSION_PATCH: u32 = 0;

/// The header's version as one number, (MAJOR << 16) | (MINOR << 8) | PATCH, for
/// `ocean_check_version(OCEAN_VERSION)` and for comparisons in the preprocessor.
pub const OCEAN_VERSION: u32 =
    (OCEAN_VERSION_MAJOR << 16) | (OCEAN_VERSION_MINOR << 8) | OCEAN_VERSION_PATCH;

/// Parses a decimal `u32` at compile time.
const fn parse_u32(s: &str) -> u32 {
    let b = s.as_bytes();
    assert!(!b.is_empty(), "empty version component");
    let mut i = 0;
    let mut v: u32 = 0;
    while i < b.len() {
        assert!(b[i].is_ascii_digit(), "version component is not a number");
        v = v * 10 + (b[i] - b'0') as u32;
        i += 1;
    }
    v
}

// cbindgen can only emit `#define`s for literal constants, so the literals above are checked
// against the crate version here: bumping the version without them fails to compile.
const _: () = assert!(parse_u32(env!("CARGO_PKG_VERSION_MAJOR")) == OCEAN_VERSION_MAJOR);
const _: () = assert!(parse_u32(env!("CARGO_PKG_VERSION_MINOR")) == OCEAN_VERSION_MINOR);
const _: () = assert!(parse_u32(env!("CARGO_PKG_VERSION_PATCH")) == OCEAN_VERSION_PATCH);

const VERSION: &CStr =
    match CStr::from_bytes_with_nul(concat!(env!("CARGO_PKG_VERSION"), "\0").as_bytes()) {
        Ok(v) => v,
        Err(_) => panic!("crate version contains a NUL byte"),
    };

/// The version of the linked library as a static NUL-terminated string "MAJOR.MINOR.PATCH".
///
/// Compare it with the `OCEAN_VERSION_*` macros to detect a header/library mismatch. Never NULL,
/// never fails, safe to call from any thread.
#[unsafe(no_mangle)]
pub extern "C" fn ocean_version() -> *const c_char {
    VERSION.as_ptr()
}

/// The linked library's version as one number, (MAJOR << 16) | (MINOR << 8) | PATCH: the
/// `OCEAN_VERSION` of the header it was built with. Never fails, safe from any thread.
#[unsafe(no_mangle)]
pub extern "C" fn ocean_version_number() -> u32 {
    OCEAN_VERSION
}

/// Whether the linked library provides the ABI of the header a program was compiled against:
/// call `ocean_check_version(OCEAN_VERSION)` once at start-up, before anything else (a program
/// linked against a shared library of another version would otherwise misread structs).
///
/// Compatible: the same major version, and before 1.0 the same minor version too (a minor
/// version may change the ABI until then, as the shared library's SONAME `libocean.so.0.MINOR`
/// says), and a library at least as new as the header (a newer header may declare what an
/// older library lacks).
///
/// Returns `OCEAN_STATUS_OK`, or `OCEAN_STATUS_VERSION_MISMATCH` with both versions in the
/// last-error message.
#[unsafe(no_mangle)]
pub extern "C" fn ocean_check_version(header_version: u32) -> OceanStatus {
    guard("ocean_check_version", || {
        let part = |v: u32, shift: u32| (v >> shift) & 0xff;
        let show = |v: u32| format!("{}.{}.{}", part(v, 16), part(v, 8), part(v, 0));
        let (major, minor) = (part(header_version, 16), part(header_version, 8));
        let compatible = header_version >> 24 == 0
            && major == OCEAN_VERSION_MAJOR
            && (major != 0 || minor == OCEAN_VERSION_MINOR)
            && header_version <= OCEAN_VERSION;
        if compatible {
            Ok(())
        } else {
            Err(Error::new(
                OceanStatus::VersionMismatch,
                format!(
                    "the program was compiled against ocean.h {} ({header_version:#x}), but \
                     this library is {}: {}",
                    show(header_version),
                    show(OCEAN_VERSION),
                    if header_version >> 24 != 0 {
                        "that is not an OCEAN_VERSION value"
                    } else if major != OCEAN_VERSION_MAJOR {
                        "the major versions differ"
                    } else if header_version > OCEAN_VERSION {
                        "the header is newer than the library"
                    } else {
                        "before 1.0 the minor versions must match"
                    }
                ),
            ))
        }
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The library accepts its own header and the patch levels below it, and refuses another
    /// major version, another minor version (before 1.0), a newer patch and a value that is
    /// not a version, each with its reason in the message.
    #[test]
    fn version_check_follows_the_compatibility_rules() {
        use crate::status::last_error;
        assert_eq!(ocean_version_number(), OCEAN_VERSION);
        assert_eq!(ocean_check_version(OCEAN_VERSION), OceanStatus::Ok);
        assert_eq!(OCEAN_VERSION, 0x00_01_00, "0.1.0");
        for (v, reason) in [
            (0x01_01_00, "the major versions differ"),
            (0x00_02_00, "the header is newer"),
            (0x00_00_09, "the minor versions must match"),
            (0x00_01_01, "the header is newer"),
            (0x7f_00_01_00, "not an OCEAN_VERSION value"),
        ] {
            assert_eq!(
                ocean_check_version(v),
                OceanStatus::VersionMismatch,
                "{v:#x}"
            );
            let message = last_error();
            assert!(message.contains(reason), "{v:#x}: {message}");
            assert!(message.contains("this library is 0.1.0"), "{message}");
        }
    }

    #[test]
    fn version_string_matches_the_macros() {
        let expected = format!("{OCEAN_VERSION_MAJOR}.{OCEAN_VERSION_MINOR}.{OCEAN_VERSION_PATCH}");
        assert_eq!(VERSION.to_str().unwrap(), expected);
        assert_eq!(VERSION.to_str().unwrap(), env!("CARGO_PKG_VERSION"));
    }
}
