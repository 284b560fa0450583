//! How parameter structs grow without breaking callers: chained extension structs, the scheme
//! of webgpu.h (`nextInChain`) and Vulkan (`pNext`).
//!
//! Every parameter struct (the ones with an `ocean_*_default` function) starts with
//! `const OceanChain *next`. Its layout is frozen: a later version of the library never adds
//! a member to it, so a `_default` function can never write more than the caller's struct
//! holds, and a program built against an older header keeps working against a newer library.
//! New parameters come instead as extension structs, each starting with an [`OceanChain`]
//! whose `s_type` names it, linked from `next` (and from each other's `next`).
//!
//! The library refuses, with `OCEAN_STATUS_INVALID_ARGUMENT`, every extension whose `s_type`
//! it does not know, naming the member and the value: a program built against a newer header
//! that asks for a newer parameter gets an error from an older library, never a result computed
//! without it. This version defines no extension, so `next` must be NULL (as the `_default`
//! functions and zero-initialisation set it).

use crate::status::{Error, OceanStatus};

/// The head of an extension struct: the link to the next extension and the type of this one.
/// An extension struct starts with this member, so a pointer to it is a pointer to its head.
#[repr(C)]
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct OceanChain {
    /// The next extension of the same parameter struct, or NULL.
    pub next: *const OceanChain,
    /// Which extension struct this head begins (an `OCEAN_S_TYPE_*` value; this version of
    /// the library defines none and refuses every value).
    pub s_type: u32,
    /// Set to 0.
    pub reserved: u32,
}

/// The type of the `next` member of a parameter struct, `const OceanChain *`: NULL, or a
/// pointer to the head of an extension struct.
#[repr(transparent)]
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct OceanNext(pub *const OceanChain);

impl OceanNext {
    /// No extension.
    pub(crate) const NULL: Self = Self(core::ptr::null());
}

impl Default for OceanNext {
    fn default() -> Self {
        Self::NULL
    }
}

// SAFETY: a raw pointer is valid for every bit pattern and has no padding; `OceanNext` is
// `repr(transparent)` over one. The library dereferences a `next` only after reading its
// struct from the caller with a typed read ([`crate::boundary::read_in`],
// [`crate::boundary::read_checked`]), which keeps the pointer's provenance; it never
// dereferences one made from bytes.
unsafe impl bytemuck::Zeroable for OceanNext {}
// SAFETY: as above.
unsafe impl bytemuck::Pod for OceanNext {}

/// A parameter struct whose first member is `next`.
pub(crate) trait Extensible {
    /// The struct's `next` member.
    fn next(&self) -> OceanNext;
}

/// Checks the extensions chained to parameter struct `p`, whose `next` the caller knows as
/// `member` (`params->next`, or `scene->method.next` for a struct inside another): NULL is
/// none; a misaligned pointer is `OCEAN_STATUS_MISALIGNED_POINTER`; an extension of a type this
/// library does not know (every type, in this version) is `OCEAN_STATUS_INVALID_ARGUMENT`,
/// naming `member` and the `s_type`.
///
/// # Safety
///
/// `p.next()` must be NULL, misaligned, or point to a readable [`OceanChain`] (the header's
/// Safety sections say so of every parameter struct).
pub(crate) unsafe fn check_chain<T: Extensible>(p: &T, member: &str) -> Result<(), Error> {
    let next = p.next().0;
    if next.is_null() {
        return Ok(());
    }
    super::check_ptr(next, member)?;
    // SAFETY: non-NULL and aligned (checked); readable (caller's guarantee); copied out.
    let head = unsafe { next.read() };
    Err(Error::new(
        OceanStatus::InvalidArgument,
        format!(
            "`{member}` links an extension with s_type {}, which this library ({}) does not \
             know: set `next` to NULL, or link only the extensions its header defines",
            head.s_type,
            env!("CARGO_PKG_VERSION")
        ),
    ))
}

/// Implements [`Extensible`] for parameter structs, and proves at compile time that `next`
/// is each one's first member (so that an `OceanChain *` cast from any of them reads it).
macro_rules! extensible {
    ($($t:ty),* $(,)?) => {$(
        impl $crate::boundary::chain::Extensible for $t {
            fn next(&self) -> $crate::boundary::chain::OceanNext {
                self.next
            }
        }
        const _: () = assert!(core::mem::offset_of!($t, next) == 0);
    )*};
}
pub(crate) use extensible;

#[cfg(test)]
mod tests {
    use super::*;

    /// A parameter struct of the shape every one has: `next` first.
    #[repr(C)]
    struct Params {
        next: OceanNext,
        value: f32,
    }
    extensible!(Params);

    fn status(p: &Params) -> Result<(), (OceanStatus, String)> {
        // SAFETY: every `next` below is NULL, misaligned, or points to a live `OceanChain`.
        unsafe { check_chain(p, "params->next") }.map_err(|e| (e.status, e.message))
    }

    /// No extension passes; an extension of any type is refused (this version knows none),
    /// naming the member and the type; a misaligned link is refused before it is read.
    #[test]
    fn unknown_extensions_are_refused_before_anything_is_computed() {
        let none = Params {
            next: OceanNext::NULL,
            value: 1.0,
        };
        assert_eq!(status(&none), Ok(()));
        assert_eq!(none.value, 1.0);
        for s_type in [0, 1, 7, u32::MAX] {
            let head = OceanChain {
                next: core::ptr::null(),
                s_type,
                reserved: 0,
            };
            let p = Params {
                next: OceanNext(&raw const head),
                value: 1.0,
            };
            let (st, msg) = status(&p).unwrap_err();
            assert_eq!(st, OceanStatus::InvalidArgument);
            assert!(
                msg.contains("`params->next`") && msg.contains(&format!("s_type {s_type}")),
                "{msg}"
            );
        }
        let storage = [0u64; 4];
        let misaligned = storage
            .as_ptr()
            .cast::<u8>()
            .wrapping_add(4)
            .cast::<OceanChain>();
        let p = Params {
            next: OceanNext(misaligned),
            value: 1.0,
        };
        assert_eq!(status(&p).unwrap_err().0, OceanStatus::MisalignedPointer);
    }
}
