//! Storing cone maps: every encoding rounds **down** (a decoded ratio is never above the exact
//! one, so a valid cone stays valid), as a cone map must be.
//!
//! - [`Encoding::Unorm8`]: the book's 8-bit channel (§18.4.1), the ratio clamped to 1.0:
//!   `k = ⌊255·min(r, 1)⌋`, decoded as `k/255` (a GPU's unorm conversion).
//! - [`Encoding::Unorm8Sqrt`]: `k = ⌊255·√min(r, 1)⌋`, decoded as `(k/255)²`: more steps where
//!   cones are narrow, which is where a relative error costs most.
//! - [`Encoding::F16`]: IEEE binary16, unclamped (up to 65504), rounded toward zero.
//! - [`Encoding::F32`]: the generator's values as they are (already rounded down from `f64`).
//!
//! Each encoder checks its own result: after the arithmetic it steps the code down while the
//! decoded value (computed exactly as the decoder does) exceeds the input, so the guarantee does
//! not rest on the rounding of the encoding arithmetic. The clearance and near cap channels
//! ([`crate::cone`]) are stored the same way; clamping them to 1.0 only shrinks the cones.

use alloc::vec::Vec;

use crate::cone::ConeMap;
use crate::{ReliefError, check_range};

/// How a channel of ratios is stored.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Encoding {
    /// 8-bit unorm, clamped to 1.0.
    Unorm8,
    /// 8-bit unorm of the square root, clamped to 1.0.
    Unorm8Sqrt,
    /// 16-bit float, unclamped.
    F16,
    /// 32-bit float.
    F32,
}

/// Decodes an 8-bit code.
#[inline]
pub fn decode_unorm8(k: u8, sqrt: bool) -> f32 {
    let v = f32::from(k) / 255.0;
    if sqrt { v * v } else { v }
}

/// Encodes a ratio `r ≥ 0` (NaN is treated as 0) in 8 bits, rounding down: the largest `k` with
/// `decode_unorm8(k) ≤ min(r, 1)`.
pub fn encode_unorm8(r: f32, sqrt: bool) -> u8 {
    let r = if r >= 0.0 { r.min(1.0) } else { 0.0 };
    let x = if sqrt { libm::sqrtf(r) } else { r };
    let mut k = libm::floorf(x * 255.0).clamp(0.0, 255.0) as u8;
    while k > 0 && decode_unorm8(k, sqrt) > r {
        k -= 1;
    }
    // The floor may also have been one low after rounding; take the largest code that fits.
    while k < 255 && decode_unorm8(k + 1, sqrt) <= r {
        k += 1;
    }
    k
}

/// Decodes IEEE binary16 bits.
pub fn decode_f16(bits: u16) -> f32 {
    let sign = if bits & 0x8000 != 0 { -1.0f32 } else { 1.0 };
    let exp = i32::from((bits >> 10) & 0x1f);
    let man = f32::from(bits & 0x3ff);
    let mag = match exp {
        0 => man * (1.0 / 16_777_216.0), // subnormal: man·2⁻²⁴
        31 => {
            if man == 0.0 {
                f32::INFINITY
            } else {
                f32::NAN
            }
        }
        e => (1.0 + man / 1024.0) * pow2(e - 15),
    };
    sign * mag
}

/// `2^e` for `|e| ≤ 126`, exact.
fn pow2(e: i32) -> f32 {
    f32::from_bits(((e + 127) as u32) << 23)
}

/// Encodes a ratio `r ≥ 0` (NaN is treated as 0) as binary16 rounded toward zero: the largest
/// finite half with `decode_f16(bits) ≤ r`.
pub fn encode_f16(r: f32) -> u16 {
    if r.is_nan() || r <= 0.0 {
        return 0;
    }
    const MAX: u16 = 0x7bff; // 65504
    if r >= 65504.0 {
        return MAX;
    }
    // Truncate the f32 mantissa: exact for normal halves; subnormal halves are multiples of 2⁻²⁴.
    let b = r.to_bits();
    let exp = ((b >> 23) & 0xff) as i32 - 127;
    let mut h = if exp < -14 {
        libm::floorf(r * 16_777_216.0).min(1023.0) as u16
    } else {
        (((exp + 15) as u16) << 10) | ((b >> 13) & 0x3ff) as u16
    };
    while h > 0 && decode_f16(h) > r {
        h -= 1;
    }
    while h < MAX && decode_f16(h + 1) <= r {
        h += 1;
    }
    h
}

/// One channel of a cone map encoded.
#[derive(Clone, Debug, PartialEq)]
pub enum Encoded {
    /// 8-bit codes (`Unorm8` or `Unorm8Sqrt`).
    Unorm8(Vec<u8>),
    /// binary16 bits.
    F16(Vec<u16>),
    /// `f32` values.
    F32(Vec<f32>),
}

/// Encodes `values` (ratios, clearances or near caps) with `encoding`.
pub fn encode(values: &[f32], encoding: Encoding) -> Encoded {
    match encoding {
        Encoding::Unorm8 => {
            Encoded::Unorm8(values.iter().map(|&r| encode_unorm8(r, false)).collect())
        }
        Encoding::Unorm8Sqrt => {
            Encoded::Unorm8(values.iter().map(|&r| encode_unorm8(r, true)).collect())
        }
        Encoding::F16 => Encoded::F16(values.iter().map(|&r| encode_f16(r)).collect()),
        Encoding::F32 => Encoded::F32(values.to_vec()),
    }
}

/// Decodes a channel stored with `encoding` (`sqrt` matters for 8-bit codes only).
pub fn decode(encoded: &Encoded, sqrt: bool) -> Vec<f32> {
    match encoded {
        Encoded::Unorm8(v) => v.iter().map(|&k| decode_unorm8(k, sqrt)).collect(),
        Encoded::F16(v) => v.iter().map(|&h| decode_f16(h)).collect(),
        Encoded::F32(v) => v.clone(),
    }
}

impl ConeMap {
    /// The cone map after a round trip through `encoding` (every channel), which is what a
    /// tracer reading the stored texture sees. Every value is at most the original.
    ///
    /// # Errors
    ///
    /// None in practice (the decoded values are finite and non-negative); the constructor's
    /// checks are kept.
    pub fn quantized(&self, encoding: Encoding) -> Result<ConeMap, ReliefError> {
        let sqrt = encoding == Encoding::Unorm8Sqrt;
        let round = |v: &[f32]| decode(&encode(v, encoding), sqrt);
        let out = ConeMap::from_channels(
            self.size(),
            self.edge(),
            round(self.ratios()),
            round(self.clearance()),
            round(self.near_cap()),
        )?;
        for v in [out.ratios(), out.clearance(), out.near_cap()] {
            for &r in v {
                check_range("decoded ratio", f64::from(r), 0.0, f64::from(f32::MAX))?;
            }
        }
        Ok(out)
    }
}
