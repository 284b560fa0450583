//! Structs as a C caller holds them: the bytes of a valid struct with some enumeration members
//! replaced by any `u32`, perhaps none of the enum's values. A Rust struct with an enum member
//! cannot hold such a value, so the library's checks of it (`read_checked` in
//! `ocean-ffi/src/boundary/pointer.rs`) are fuzzed through this, which is passed by pointer
//! only and never read as the struct unless its bytes are valid.

use std::fmt;
use std::mem::MaybeUninit;

use bytemuck::{CheckedBitPattern, NoUninit};

use crate::input::Input;

/// A `T` in memory aligned for it, its bytes perhaps not a valid `T`.
#[derive(Clone, Copy)]
pub struct CMem<T: Copy> {
    mem: MaybeUninit<T>,
}

impl<T: NoUninit + CheckedBitPattern> CMem<T> {
    pub fn new(value: T) -> Self {
        Self {
            mem: MaybeUninit::new(value),
        }
    }

    /// The bytes (all initialised: written from a `T` without padding, then by `poke`).
    pub fn bytes(&self) -> &[u8] {
        // SAFETY: `mem` holds `size_of::<T>()` initialised bytes (above).
        unsafe { std::slice::from_raw_parts(self.mem.as_ptr().cast(), size_of::<T>()) }
    }

    /// Overwrites the bytes at `offset` with `bytes`.
    pub fn poke_bytes(&mut self, offset: usize, bytes: &[u8]) {
        assert!(
            offset + bytes.len() <= size_of::<T>(),
            "poke past the struct"
        );
        // SAFETY: in bounds (asserted); `u8` has no invalid values and the `MaybeUninit` never
        // becomes a `T` unless `get` finds its bytes valid.
        unsafe {
            std::ptr::copy_nonoverlapping(
                bytes.as_ptr(),
                self.mem.as_mut_ptr().cast::<u8>().add(offset),
                bytes.len(),
            );
        }
    }

    /// Replaces the `u32` at `offset` (an enumeration member) one time in four by any
    /// [`Input::u32`], as `call::tweak_u32` does for plain members.
    pub fn tweak_u32(&mut self, inp: &mut Input, offset: usize) {
        if inp.u8() % 4 == 3 {
            self.poke_bytes(offset, &inp.u32().to_ne_bytes());
        }
    }

    /// The struct, if its bytes are a valid `T`.
    pub fn get(&self) -> Option<T> {
        bytemuck::checked::try_pod_read_unaligned(self.bytes()).ok()
    }

    /// What a C caller passes.
    pub fn as_ptr(&self) -> *const T {
        self.mem.as_ptr()
    }
}

impl<T: NoUninit + CheckedBitPattern + fmt::Debug> fmt::Debug for CMem<T> {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self.get() {
            Some(v) => v.fmt(f),
            None => write!(
                f,
                "{} with an invalid enumeration member, bytes {:02x?}",
                std::any::type_name::<T>(),
                self.bytes()
            ),
        }
    }
}

/// Any value of a `#[repr(u32)]` enumeration `E` that has a variant for every value below `n`:
/// `inp.u32() % n`.
pub fn enum_below<E: CheckedBitPattern<Bits = u32>>(inp: &mut Input, n: u32) -> E {
    bytemuck::checked::cast(inp.u32() % n)
}
