//! Version macros and `ocean_version`.

use core::ffi::{CStr, c_char};

/// Major version of the library this header belongs to (the `ocean-ffi` crate version).
pub const OCEAN_VERSION_MAJOR: u32 = 0;
/// Minor version of the library this header belongs to.
pub const OCEAN_VERSION_MINOR: u32 = 1;
/// Patch version of the library this header belongs to.
pub const OCEAN_VERSION_PATCH: u32 = 0;

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

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn version_string_matches_the_macros() {
        let expected = format!("{OCEAN_VERSION_MAJOR}.{OCEAN_VERSION_MINOR}.{OCEAN_VERSION_PATCH}");
        assert_eq!(VERSION.to_str().unwrap(), expected);
        assert_eq!(VERSION.to_str().unwrap(), env!("CARGO_PKG_VERSION"));
    }
}
