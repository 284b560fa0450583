//! Enumerations from C, written once.
//!
//! Every enumeration of the header is a `#[repr(u32)]` Rust enum that cbindgen emits as a C enum
//! (in C++ and C23 with `uint32_t` as its underlying type). A C caller may still store any
//! integer where one is expected, and a Rust enum holding a value that is none of its variants
//! is undefined behaviour. So the library never reads such a value as the enum directly:
//!
//! - a struct with enumeration members ([`CheckedStruct`]) is read from the caller's memory as
//!   bytes by [`read_checked`](super::read_checked), which checks each member's raw `u32` (in
//!   declaration order, with the message that names the member and the value) before the
//!   checked cast of the whole struct (`bytemuck::checked`);
//! - a function parameter stays `uint32_t` in Rust and in the header (an `extern "C"` parameter
//!   of an enum type would be read as that type at the call), and [`check_enum`] turns it into
//!   the enum.

use bytemuck::CheckedBitPattern;

use crate::status::{Error, OceanStatus};

/// A `#[repr(u32)]` enumeration of the C ABI.
pub(crate) trait CEnum: CheckedBitPattern<Bits = u32> + Copy + 'static {
    /// What a message says after `{name} = {value}` when the value is none of the enumerators,
    /// e.g. `is not an OceanRefraction (0, 1 or 2)`.
    const REFUSAL: &'static str;
}

/// The enumeration `E` that `v` holds, or `OCEAN_STATUS_INVALID_ARGUMENT` with the message
/// "`{name} = {v}` followed by [`CEnum::REFUSAL`]".
pub(crate) fn check_enum<E: CEnum>(name: &str, v: u32) -> Result<E, Error> {
    bytemuck::checked::try_cast::<u32, E>(v).map_err(|_| refused(name, v, E::REFUSAL))
}

fn refused(name: &str, v: u32, refusal: &str) -> Error {
    Error::new(
        OceanStatus::InvalidArgument,
        format!("{name} = {v} {refusal}"),
    )
}

/// An enumeration member of an input struct: where it lies and which values it may hold.
pub(crate) struct EnumField {
    /// The member as messages name it after `{struct}->`, e.g. `blur.weight`.
    name: &'static str,
    /// Its byte offset in the struct (`core::mem::offset_of!`, summed for a nested member).
    offset: usize,
    /// Whether a raw value is one of the enumerators.
    valid: fn(u32) -> bool,
    /// [`CEnum::REFUSAL`] of its enumeration.
    refusal: &'static str,
}

fn is_valid<E: CEnum>(v: u32) -> bool {
    E::is_valid_bit_pattern(&v)
}

impl EnumField {
    /// The member `name` at byte `offset`, of the enumeration `E`.
    pub(crate) const fn of<E: CEnum>(name: &'static str, offset: usize) -> Self {
        Self {
            name,
            offset,
            valid: is_valid::<E>,
            refusal: E::REFUSAL,
        }
    }
}

/// A `#[repr(C)]` input struct that holds enumerations, directly or in a nested struct.
pub(crate) trait CheckedStruct: CheckedBitPattern + Copy {
    /// Every enumeration member, in declaration order.
    const ENUM_FIELDS: &'static [EnumField];

    /// Checks of members that the header's error order puts before the enumerations (a NaN
    /// matrix element of a camera is reported before its depth convention), on the raw bits.
    /// None by default.
    fn check_first(_bits: &Self::Bits, _name: &str) -> Result<(), Error> {
        Ok(())
    }
}

/// Checks the raw enumeration members of a `T` in `bytes` (exactly `size_of::<T>()` of them),
/// then casts: `name` is the parameter, as messages name it (`params` gives
/// `params->mip_filter = 7 ...`).
pub(crate) fn checked_from_bytes<T: CheckedStruct>(bytes: &[u8], name: &str) -> Result<T, Error> {
    let bits: T::Bits = bytemuck::try_pod_read_unaligned(bytes).map_err(|e| {
        Error::new(
            OceanStatus::Panic,
            format!(
                "{name}: {} bytes read as {}: {e}",
                bytes.len(),
                type_name::<T>()
            ),
        )
    })?;
    T::check_first(&bits, name)?;
    for f in T::ENUM_FIELDS {
        let raw = bytes
            .get(f.offset..f.offset + 4)
            .and_then(|b| <[u8; 4]>::try_from(b).ok())
            .map(u32::from_ne_bytes)
            .ok_or_else(|| {
                Error::new(
                    OceanStatus::Panic,
                    format!("{name}->{}: offset {} outside the struct", f.name, f.offset),
                )
            })?;
        if !(f.valid)(raw) {
            return Err(refused(&format!("{name}->{}", f.name), raw, f.refusal));
        }
    }
    bytemuck::checked::try_pod_read_unaligned::<T>(bytes).map_err(|e| {
        // Every enumeration member was checked above, so only a member missing from
        // `ENUM_FIELDS` gets here: refused all the same, never read.
        Error::new(
            OceanStatus::InvalidArgument,
            format!("{name} is not a valid {}: {e}", type_name::<T>()),
        )
    })
}

/// The C name of `T` (the last segment of its Rust path).
fn type_name<T>() -> &'static str {
    let full = core::any::type_name::<T>();
    full.rsplit("::").next().unwrap_or(full)
}

/// `value` as a C caller could pass it with the raw `u32` at byte `offset` replaced by `raw`,
/// read as [`read_checked`](super::read_checked) reads it.
#[cfg(test)]
pub(crate) fn read_poked<T: CheckedStruct + bytemuck::NoUninit>(
    value: &T,
    name: &str,
    offset: usize,
    raw: u32,
) -> Result<T, Error> {
    let mut bytes = bytemuck::bytes_of(value).to_vec();
    bytes[offset..offset + 4].copy_from_slice(&raw.to_ne_bytes());
    checked_from_bytes(&bytes, name)
}

/// A `T` as a C caller could pass it with the raw `u32` at byte `offset` replaced by `raw`
/// (perhaps none of an enumeration's values): memory aligned for `T` that Rust never reads as
/// a `T`, only passes by pointer.
#[cfg(test)]
pub(crate) struct Poked<T>(core::mem::MaybeUninit<T>);

#[cfg(test)]
impl<T: bytemuck::NoUninit> Poked<T> {
    pub(crate) fn new(value: &T, offset: usize, raw: u32) -> Self {
        let mut bytes = bytemuck::bytes_of(value).to_vec();
        bytes[offset..offset + 4].copy_from_slice(&raw.to_ne_bytes());
        let mut m = core::mem::MaybeUninit::<T>::uninit();
        // SAFETY: `bytes` holds `size_of::<T>()` bytes, copied into the `T`-sized buffer.
        unsafe {
            core::ptr::copy_nonoverlapping(bytes.as_ptr(), m.as_mut_ptr().cast(), bytes.len());
        }
        Self(m)
    }

    pub(crate) fn as_ptr(&self) -> *const T {
        self.0.as_ptr()
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::wtb_params::{OceanEffects, OceanRefraction};

    #[test]
    fn parameters_and_members_are_checked_before_any_enum_is_made() {
        assert_eq!(
            check_enum::<OceanRefraction>("r", 2).unwrap(),
            OceanRefraction::Dispersion
        );
        let e = check_enum::<OceanRefraction>("r", 3).unwrap_err();
        assert_eq!(e.status, OceanStatus::InvalidArgument);
        assert_eq!(e.message, "r = 3 is not an OceanRefraction (0, 1 or 2)");
        let at = core::mem::offset_of!(OceanEffects, refraction);
        let d = OceanEffects::default();
        assert_eq!(
            read_poked(&d, "effects", at, 1).unwrap().refraction,
            OceanRefraction::PhaseShift
        );
        for raw in [3, 7, u32::MAX] {
            let e = read_poked(&d, "effects", at, raw).unwrap_err();
            assert_eq!(e.status, OceanStatus::InvalidArgument);
            assert_eq!(
                e.message,
                format!("effects->refraction = {raw} is not an OceanRefraction (0, 1 or 2)")
            );
        }
    }
}
