//! The bilateral reconstruction (§2.4): a horizontal and a vertical 1D pass over the packed
//! texels.
//!
//! At output pixel `c` with key `k_c` (a fraction of `z_min`, [`crate::pack`]), tap
//! `t = −R..=R` (in that order) reads the texel `p = stride·t` pixels away along the axis and
//! weighs its A by
//!
//! ```text
//! w_t = gauss[|t|] · max(0, 1 − depth_scale·|k_t − k_ref(p)|)
//! ```
//!
//! the result being `Σ w_t·A_t / Σ w_t` (the centre tap always weighs `gauss[0]`, so the sum is
//! never 0). Taps outside the output rectangle and sky taps are skipped; a sky centre passes
//! through unchanged (the paper draws these passes with a reverse depth test so that pixels at
//! infinity neither change nor contribute). The horizontal pass writes packed texels (A
//! re-quantised to 8 bits, the key unchanged), as an RGBA8 render target would; the vertical
//! pass returns `f32`.
//!
//! ## The reference key
//!
//! - [`BlurWeight::Depth`] (the paper): `k_ref = k_c`.
//! - [`BlurWeight::Plane`]: the key the plane through the centre predicts at the tap. On a plane
//!   seen in perspective `1/z` is affine in screen coordinates (in an orthographic view `z`
//!   itself is), so with `u(k) = 1/max(k, ½/65535)` (orthographic: `u(k) = k`), the slope is
//!   `s = u_c − u_{−1}` or `s = u_{+1} − u_c` from the adjacent pixels along the axis, whichever
//!   is smaller in magnitude (the left one on a tie; a missing or sky neighbour leaves the other;
//!   none leaves `s = 0`), and `k_ref(p) = u⁻¹(u_c + p·s)` for `p ≠ 0` (no plane point, weight 0, where
//!   `u_c + p·s ≤ 0` in perspective). Taking the gentler side keeps the plane of the centre's own
//!   surface at a depth edge or a crease; on a sloped face every tap of the face is then within
//!   the key's quantisation of `k_ref`, where the paper's weight drops taps a few pixels away.
//!   The slope comes from two 16-bit keys, so it is uncertain by up to one key step per pixel:
//!   the deviation that counts is `max(0, |k_t − k_ref| − |p|/65535)` (at most 9 key steps,
//!   27 mm at the default `z_min`, for the paper's 7 taps of stride 3, against the 32 steps at
//!   which `2¹¹` reaches weight 0).
//! - With the plane weight, taps also fade with their distance from the centre in metres,
//!   `max(0, 1 − d/(world_extent·r))` with `d = √((p·f·|z_c|)² + (z_t − z_c)²)` (`f` Eq. 3's
//!   `|scale|` along the axis, `|z_c|` replaced by 1 for an orthographic camera, `z = key·z_min`).
//!   On a floor seen at 74° a tap 9 px away lies half a metre off, where the obscurance itself
//!   has changed: without this limit the plane weight would average a crease's contact
//!   darkness half a radius outward (measured on the analytic crease at 112 × 80: MSE 0.0105
//!   against the estimator's own 256-sample limit, against 0.0046 for the paper's weight and
//!   for `world_extent` 0.5; see [`BlurParams::world_extent`] for the trade-off).
//!   This is the idea behind the depth-slope-aware edges of later screen-space AO denoisers,
//!   written for the separable 1D passes and the 16-bit key.

use alloc::vec;
use alloc::vec::Vec;

use crate::for_rows;
use crate::pack::{SKY_KEY, Texel, decode_key, dequantise_ao, pack, texel_key};
use crate::params::{BlurParams, BlurWeight};
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
    /// What a tap's key is compared with.
    pub weight: BlurWeight,
    /// The projection is a perspective (`1/z` affine on planes) rather than orthographic.
    pub perspective: bool,
    /// Metres per pixel along x and y (at `|z| = 1` m for a perspective).
    pub footprint: [f32; 2],
    /// `z_min` of the key.
    pub z_min: f32,
    /// `1/(extent·r)`: the reciprocal of the world distance at which a plane tap's weight
    /// reaches 0 (0: no limit).
    pub inv_extent: f32,
}

/// The smallest key the plane weight divides by: half a key step (z within about 1.5 mm of the
/// camera at the default `z_min` has key 0).
const MIN_PLANE_KEY: f32 = 0.5 / 65535.0;

impl BlurConstants {
    /// From validated parameters, for a perspective or an orthographic projection, without the
    /// plane weight's world extent (no camera to measure distances with).
    pub fn new(params: &BlurParams, perspective: bool) -> Self {
        Self::with_geometry(params, perspective, [0.0; 2], -200.0, 0.0)
    }

    /// From validated parameters and the camera: `footprint` is Eq. 3's `|scale|` per axis
    /// (metres per pixel, at `|z| = 1` m for a perspective), `z_min` the key's and `radius`
    /// the obscurance radius the world extent is a fraction of.
    pub fn with_geometry(
        params: &BlurParams,
        perspective: bool,
        footprint: [f32; 2],
        z_min: f32,
        radius: f32,
    ) -> Self {
        let ext = f64::from(params.world_extent) * f64::from(radius);
        Self {
            gauss: params.gaussian(),
            stride: params.stride,
            depth_scale: params.depth_scale,
            weight: params.weight,
            perspective,
            footprint,
            z_min,
            inv_extent: if ext > 0.0 { (1.0 / ext) as f32 } else { 0.0 },
        }
    }

    /// `u(k)`: the quantity affine in screen coordinates on a plane.
    #[inline]
    fn plane_u(&self, k: f32) -> f32 {
        if self.perspective {
            1.0 / k.max(MIN_PLANE_KEY)
        } else {
            k
        }
    }

    /// The plane's key at `p` pixels from the centre (`u_c`, slope `s`); `f32::MAX` where a
    /// perspective plane has no point (weight 0 unless `depth_scale` is 0).
    #[inline]
    fn plane_key(&self, uc: f32, s: f32, p: f32) -> f32 {
        let u = uc + p * s;
        if !self.perspective {
            u
        } else if u > 0.0 {
            1.0 / u
        } else {
            f32::MAX
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
        let texel = |p: i64| -> Option<Texel> {
            if p < 0 || p >= len {
                return None;
            }
            let p = p as usize;
            let t = match axis {
                Axis::Horizontal => packed[y * ow + p],
                Axis::Vertical => packed[p * ow + x],
            };
            (texel_key(t) != SKY_KEY).then_some(t)
        };
        let key = |t: Texel| decode_key(texel_key(t));
        let (uc, slope) = match self.weight {
            BlurWeight::Depth => (0.0, 0.0),
            BlurWeight::Plane => {
                let uc = self.plane_u(kc);
                let left = texel(pos - 1).map(|t| uc - self.plane_u(key(t)));
                let right = texel(pos + 1).map(|t| self.plane_u(key(t)) - uc);
                let slope = match (left, right) {
                    (Some(l), Some(r)) => {
                        if r.abs() < l.abs() {
                            r
                        } else {
                            l
                        }
                    }
                    (Some(l), None) => l,
                    (None, Some(r)) => r,
                    (None, None) => 0.0,
                };
                (uc, slope)
            }
        };
        let fp = match axis {
            Axis::Horizontal => self.footprint[0],
            Axis::Vertical => self.footprint[1],
        };
        let zc = kc * self.z_min;
        // The plane weight's world distance: lateral pixels at the centre's depth and the
        // depth difference (the distance along a plane through both, to first order).
        let lateral = if self.perspective { fp * zc.abs() } else { fp };
        let mut sum = 0.0f32;
        let mut wsum = 0.0f32;
        for t in -r..=r {
            let p = t * i64::from(self.stride);
            let Some(tap) = texel(pos + p) else {
                continue;
            };
            // The centre compares with itself exactly (1/(1/k) need not round back to k).
            let deviation = match self.weight {
                BlurWeight::Plane if t != 0 => {
                    let k_ref = self.plane_key(uc, slope, p as f32);
                    ((key(tap) - k_ref).abs() - p.unsigned_abs() as f32 / 65535.0).max(0.0)
                }
                _ => (key(tap) - kc).abs(),
            };
            let mut w = self.gauss[t.unsigned_abs() as usize]
                * (1.0 - self.depth_scale * deviation).max(0.0);
            if self.weight == BlurWeight::Plane && self.inv_extent > 0.0 {
                let dz = key(tap) * self.z_min - zc;
                let dl = p as f32 * lateral;
                let d = ocean_core::math::sqrtf(dl * dl + dz * dz);
                w *= (1.0 - d * self.inv_extent).max(0.0);
            }
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
