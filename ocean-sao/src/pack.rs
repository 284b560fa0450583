//! A and z packed into one 8-bit-per-channel texel at the end of the AO pass (§2.3), so the
//! blur passes read one texture.
//!
//! The paper writes `(R, G, B) = (A, fix(256·z/z_min)/256, fract(256·z/z_min))`: the key
//! `z/z_min ∈ [0, 1]` split into a coarse and a fine part. Written literally into UNORM8
//! channels that split is not invertible: `G = k/256` is stored as `round(255·k/256)`, which
//! sends both `k = 128` and `k = 129` to 128, and the fine part loses its last bits the same
//! way. This module stores the same two bytes exactly:
//!
//! ```text
//! key = clamp(z·(1/z_min), 0, 1)              (f32; 1/z_min from the host)
//! q   = min(u32(key·65535 + 0.5), 65534)      (16-bit key; 65535 is reserved for sky)
//! texel = (round(A·255), q >> 8, q & 255, 255) as RGBA8 (WebGPU has no RGB8 storage format)
//! key' = q / 65535
//! ```
//!
//! so `|key − key'| ≤ 0.5/65535` below `z_min` and `q` survives exactly; with `z_min = −200 m`
//! the depth step is 3 mm. Background pixels get `q = 65535` ([`SKY_KEY`]) so the blur can tell
//! them apart at any `z_min`. On the GPU, `q = u32(round(g·255))·256 + u32(round(b·255))` from
//! the UNORM channels.

use alloc::vec;
use alloc::vec::Vec;

use crate::for_rows;
use crate::reconstruct::SKY_Z;
use crate::viewport::Viewport;

/// One packed texel: `[A, key_hi, key_lo, 255]`.
pub type Texel = [u8; 4];

/// The key of background (sky) pixels.
pub const SKY_KEY: u16 = 0xffff;
/// The largest key of geometry (`z` at or beyond `z_min`).
pub const MAX_KEY: u16 = 0xfffe;

/// The 16-bit depth key of camera-space `z` with `inv_z_min = f32(1/z_min)`.
#[inline]
pub fn encode_key(z: f32, inv_z_min: f32) -> u16 {
    if z == SKY_Z {
        return SKY_KEY;
    }
    let key = z * inv_z_min;
    // Written so that NaN goes to 0 (`clamp` would keep it).
    let key = if key > 0.0 { key.min(1.0) } else { 0.0 };
    ((key * 65535.0 + 0.5) as u32).min(u32::from(MAX_KEY)) as u16
}

/// The key as a fraction of `z_min`: `q/65535`.
#[inline]
pub fn decode_key(q: u16) -> f32 {
    f32::from(q) / 65535.0
}

/// `round(clamp(A, 0, 1)·255)`.
#[inline]
pub fn quantise_ao(a: f32) -> u8 {
    let a = if a > 0.0 { a.min(1.0) } else { 0.0 };
    (a * 255.0 + 0.5) as u8
}

/// The UNORM8 value as a float: `a/255`.
#[inline]
pub fn dequantise_ao(a: u8) -> f32 {
    f32::from(a) / 255.0
}

/// Packs A and a 16-bit key.
#[inline]
pub fn pack(a: f32, key: u16) -> Texel {
    [quantise_ao(a), (key >> 8) as u8, (key & 0xff) as u8, 255]
}

/// The key of a texel.
#[inline]
pub fn texel_key(t: Texel) -> u16 {
    (u16::from(t[1]) << 8) | u16::from(t[2])
}

/// The packing at every output pixel: `ao` (output size) with level-0 z (input size).
pub fn pack_pass(viewport: &Viewport, z0: &[f32], ao: &[f32], z_min: f32) -> Vec<Texel> {
    let inv_z_min = (1.0 / f64::from(z_min)) as f32;
    let (ow, g, w) = (
        viewport.output_width(),
        viewport.guard(),
        viewport.input_width(),
    );
    let mut out = vec![[0u8; 4]; viewport.output_len()];
    for_rows(&mut out, ow, |y, row| {
        for (x, t) in row.iter_mut().enumerate() {
            let z = z0[(y + g) * w + x + g];
            *t = pack(ao[y * ow + x], encode_key(z, inv_z_min));
        }
    });
    out
}
