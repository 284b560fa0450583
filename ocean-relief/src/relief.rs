//! The relief texture the tracers read: depth and cone ratios in one texel (§18.4.1: "both a
//! depth and a cone map can be stored using a single luminance-alpha texture"; with height bands,
//! [`crate::cone`], an RGBA texel `[depth, cone, cone₁, cone₂]`), and the normal map by central
//! differences (§18.2), kept apart as the book recommends.

use alloc::vec::Vec;

use glam::Vec3;

use crate::cone::ConeMap;
use crate::map::{Edge, HeightMap};
use crate::sample::Taps;
use crate::{ReliefError, check_range};

/// Per texel `[depth, cone, clearance, near cap]`, row-major ([`crate::cone`]).
#[derive(Clone, Debug, PartialEq)]
pub struct ReliefTexture {
    size: usize,
    edge: Edge,
    texels: Vec<[f32; 4]>,
}

impl ReliefTexture {
    /// Pairs the depths of `map` with `cones`.
    ///
    /// # Errors
    ///
    /// [`ReliefError::Mismatch`] if the cone map has another size or edge mode.
    pub fn new(map: &HeightMap, cones: &ConeMap) -> Result<Self, ReliefError> {
        if cones.size() != map.size() || cones.edge() != map.edge() {
            return Err(ReliefError::Mismatch("cones"));
        }
        let (c0, c1, c2) = (cones.ratios(), cones.clearance(), cones.near_cap());
        let texels = map
            .depths()
            .iter()
            .enumerate()
            .map(|(k, &d)| [d, c0[k], c1[k], c2[k]])
            .collect();
        Ok(Self {
            size: map.size(),
            edge: map.edge(),
            texels,
        })
    }

    /// Side in texels.
    pub fn size(&self) -> usize {
        self.size
    }

    /// Edge mode.
    pub fn edge(&self) -> Edge {
        self.edge
    }

    /// The texels, `[depth, cone, clearance, near cap]`.
    pub fn texels(&self) -> &[[f32; 4]] {
        &self.texels
    }

    /// One bilinear fetch of `[depth, cone, clearance, near cap]` at texture coordinates
    /// `(u, v)` ([`crate::sample`]).
    #[inline(always)]
    pub fn fetch(&self, u: f32, v: f32) -> [f32; 4] {
        Taps::new(self.size, self.edge, u, v).blend4(&self.texels)
    }
}

/// Tangent-space normals by central differences, for a relief `depth` texels deep (the full
/// depth range spans that many texel widths).
///
/// Tangent space here is the book's: `x` along the texture's `u` (columns), `y` along `v` (rows),
/// `z` out of the polygon. The surface height is `−depth·d(x, y)`, so the normal is
/// `normalize(depth·∂d/∂u, depth·∂d/∂v, 1)` with `∂d/∂u ≈ (d(i+1, j) − d(i−1, j))/2` per texel;
/// neighbours follow the map's edge mode (clamp repeats the border texel, which halves the
/// difference there).
///
/// # Errors
///
/// [`ReliefError::NotFinite`] / [`ReliefError::OutOfRange`] unless `0 ≤ depth ≤ 1e6`.
pub fn normals(map: &HeightMap, depth: f32) -> Result<Vec<Vec3>, ReliefError> {
    check_range("depth", f64::from(depth), 0.0, 1.0e6)?;
    let n = map.size();
    Ok((0..n * n)
        .map(|k| {
            let (i, j) = ((k % n) as i64, (k / n) as i64);
            let du = (map.depth(i + 1, j) - map.depth(i - 1, j)) * 0.5;
            let dv = (map.depth(i, j + 1) - map.depth(i, j - 1)) * 0.5;
            Vec3::new(depth * du, depth * dv, 1.0).normalize()
        })
        .collect())
}
