//! A cone map's texels as the C entry points hand them out: the relief texture's RGBA floats,
//! and the three cone channels interleaved in a storage encoding.

use core::ffi::c_void;

use ocean_relief::storage::{Encoded, Encoding, encode};
use ocean_relief::{ConeMap, HeightMap};

use crate::boundary::{check_ptr, write_slice};
use crate::status::Error;

/// `[depth, c, D, E]` per texel, flattened.
pub(crate) fn texels(map: &HeightMap, cones: &ConeMap) -> Vec<f32> {
    let (d, c0, c1, c2) = (
        map.depths(),
        cones.ratios(),
        cones.clearance(),
        cones.near_cap(),
    );
    (0..d.len())
        .flat_map(|k| [d[k], c0[k], c1[k], c2[k]])
        .collect()
}

pub(crate) fn interleave<T: Copy>(channels: [Vec<T>; 3]) -> Vec<T> {
    let [a, b, c] = channels;
    a.iter()
        .zip(&b)
        .zip(&c)
        .flat_map(|((&x, &y), &z)| [x, y, z])
        .collect()
}

/// The three cone channels of `cones` encoded, interleaved `[c, D, E]` per texel.
pub(crate) enum Interleaved {
    U8(Vec<u8>),
    U16(Vec<u16>),
    F32(Vec<f32>),
}

pub(crate) fn encode_cones(cones: &ConeMap, encoding: Encoding) -> Interleaved {
    let chans = [cones.ratios(), cones.clearance(), cones.near_cap()].map(|v| encode(v, encoding));
    match chans {
        [Encoded::Unorm8(a), Encoded::Unorm8(b), Encoded::Unorm8(c)] => {
            Interleaved::U8(interleave([a, b, c]))
        }
        [Encoded::F16(a), Encoded::F16(b), Encoded::F16(c)] => {
            Interleaved::U16(interleave([a, b, c]))
        }
        [Encoded::F32(a), Encoded::F32(b), Encoded::F32(c)] => {
            Interleaved::F32(interleave([a, b, c]))
        }
        _ => unreachable!("one encoding gives one variant for every channel"),
    }
}

/// The element size of an encoding, bytes.
pub(crate) fn element_size(encoding: Encoding) -> usize {
    match encoding {
        Encoding::Unorm8 | Encoding::Unorm8Sqrt => 1,
        Encoding::F16 => 2,
        Encoding::F32 => 4,
    }
}

/// Checks a caller's encoded output (`len` elements of the encoding's type, aligned for it).
pub(crate) fn check_encoded_out(out: *mut c_void, encoding: Encoding) -> Result<(), Error> {
    match element_size(encoding) {
        1 => check_ptr(out.cast_const().cast::<u8>(), "out"),
        2 => check_ptr(out.cast_const().cast::<u16>(), "out"),
        _ => check_ptr(out.cast_const().cast::<f32>(), "out"),
    }
}

/// Writes encoded cones to a checked output.
///
/// # Safety
///
/// `out` must point to as many writable elements of the encoding's type as `values` holds.
pub(crate) unsafe fn write_encoded(out: *mut c_void, values: &Interleaved) -> Result<(), Error> {
    match values {
        // SAFETY: forwarded from this function's contract.
        Interleaved::U8(v) => unsafe { write_slice(out.cast::<u8>(), "out", v) },
        // SAFETY: forwarded from this function's contract.
        Interleaved::U16(v) => unsafe { write_slice(out.cast::<u16>(), "out", v) },
        // SAFETY: forwarded from this function's contract.
        Interleaved::F32(v) => unsafe { write_slice(out.cast::<f32>(), "out", v) },
    }
}
