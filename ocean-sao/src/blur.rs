//! The bilateral reconstruction (§2.4): a horizontal and a vertical 1D pass over the packed
//! texels.
//!
//! At output pixel `c` with key `k_c` (a fraction of `z_min`, [`crate::pack`]), tap
//! `t = −R..=R` (in that order) reads the texel `stride·t` pixels away along the axis and
//! weighs its A by
//!
//! ```text
//! w_t = gauss[|t|] · max(0, 1 − depth_scale·|k_t − k_c|)
//! ```
//!
//! the result being `Σ w_t·A_t / Σ w_t` (the centre tap always weighs `gauss[0]`, so the sum is
//! never 0). Taps outside the output rectangle and sky taps are skipped; a sky centre passes
//! through unchanged (the paper draws these passes with a reverse depth test so that pixels at
//! infinity neither change nor contribute). The horizontal pass writes packed texels (A
//! re-quantised to 8 bits, the key unchanged), as an RGBA8 render target would; the vertical
//! pass returns `f32`.

use alloc::vec;
use alloc::vec::Vec;

use crate::for_rows;
use crate::pack::{SKY_KEY, Texel, decode_key, dequantise_ao, pack, texel_key};
use crate::params::BlurParams;
use crate::viewport::Viewport;

/// The direction of a blur pass.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Axis {
    /// Along rows.
    Horizontal,
    /// Along columns.
    Vertical,
}

/// A blur's host-side constants.
#[derive(Clone, Debug, PartialEq)]
pub struct BlurConstants {
    /// `gauss[t]` for `t = 0..=R` (unnormalised).
    pub gauss: Vec<f32>,
    /// Pixels between taps.
    pub stride: u32,
    /// Depth-difference scale.
    pub depth_scale: f32,
}

impl BlurConstants {
    /// From validated parameters.
    pub fn new(params: &BlurParams) -> Self {
        Self {
            gauss: params.gaussian(),
            stride: params.stride,
            depth_scale: params.depth_scale,
        }
    }

    /// The blurred A of output pixel `(x, y)` of an `ow × oh` packed image.
    pub fn blur_pixel(
        &self,
        packed: &[Texel],
        ow: usize,
        oh: usize,
        x: usize,
        y: usize,
        axis: Axis,
    ) -> f32 {
        let centre = packed[y * ow + x];
        let kq = texel_key(centre);
        if kq == SKY_KEY {
            return dequantise_ao(centre[0]);
        }
        let kc = decode_key(kq);
        let r = self.gauss.len() as i64 - 1;
        let (pos, len) = match axis {
            Axis::Horizontal => (x as i64, ow as i64),
            Axis::Vertical => (y as i64, oh as i64),
        };
        let mut sum = 0.0f32;
        let mut wsum = 0.0f32;
        for t in -r..=r {
            let p = pos + t * i64::from(self.stride);
            if p < 0 || p >= len {
                continue;
            }
            let p = p as usize;
            let tap = match axis {
                Axis::Horizontal => packed[y * ow + p],
                Axis::Vertical => packed[p * ow + x],
            };
            let tq = texel_key(tap);
            if tq == SKY_KEY {
                continue;
            }
            let w = self.gauss[t.unsigned_abs() as usize]
                * (1.0 - self.depth_scale * (decode_key(tq) - kc).abs()).max(0.0);
            sum += w * dequantise_ao(tap[0]);
            wsum += w;
        }
        sum / wsum
    }

    /// The horizontal pass: packed texels in, packed texels out.
    pub fn horizontal(&self, viewport: &Viewport, packed: &[Texel]) -> Vec<Texel> {
        let (ow, oh) = (viewport.output_width(), viewport.output_height());
        let mut out = vec![[0u8; 4]; packed.len()];
        for_rows(&mut out, ow, |y, row| {
            for (x, t) in row.iter_mut().enumerate() {
                let a = self.blur_pixel(packed, ow, oh, x, y, Axis::Horizontal);
                *t = pack(a, texel_key(packed[y * ow + x]));
            }
        });
        out
    }

    /// The vertical pass: packed texels in, the final A out.
    pub fn vertical(&self, viewport: &Viewport, packed: &[Texel]) -> Vec<f32> {
        let (ow, oh) = (viewport.output_width(), viewport.output_height());
        let mut out = vec![0.0f32; packed.len()];
        for_rows(&mut out, ow, |y, row| {
            for (x, a) in row.iter_mut().enumerate() {
                *a = self.blur_pixel(packed, ow, oh, x, y, Axis::Vertical);
            }
        });
        out
    }
}
