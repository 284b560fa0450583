//! Level of detail: relief textures with mip levels of their own surface, and the level a
//! fragment reads (§18.5; the tracer's texture fetches at a minified view).
//!
//! A relief drawn small is minified: a pixel covers several texels, and a tracer that reads
//! level 0 shimmers (neighbouring pixels hit unrelated texels) and trashes the texture cache.
//! The cure is a texture's: read a coarser level. For a relief texture that means the tracer
//! must see a coarser **surface**, and the cones it reads must be valid for that surface.
//!
//! **The chain.** Level `l + 1`'s depth is the 2×2 mean of level `l`'s (a box-filtered mip, what
//! a minified height map shows; both edge modes, since a power-of-two side tiles into whole
//! groups), and its cones are generated for that surface by the same generator and parameters
//! ([`ConeMap::generate`], [`QuadConeMap::generate`]). Each level is then a relief texture in its
//! own right, valid by construction ([`crate::cone`]'s proof holds for any height map), and the
//! tracer at level `l` is the level-0 tracer on a map of side `N/2^l`: the same arithmetic,
//! texture coordinates and depths (ratios and clearances are in texture widths, near caps per
//! unit depth, so no channel rescales).
//!
//! **Why not the 4×4-window chain of [`crate::mip`].** Its cones are valid for rays over the
//! level-0 surface, for a tracer that reads depths from level 0 and cones from a coarser level
//! (cones stored at a lower resolution than depths). Paired with coarse depths they describe
//! another surface than the one they bound: `tests/lod.rs` finds rays that cross the mean
//! surface twice inside such cones (level 1 of a 64² map of boxes, where the mean turns a wall
//! into a ramp). Generating each level costs at most a third more than level
//! 0 alone (each level has a quarter of the texels of the one above).
//!
//! **The level** ([`mip_level`]): the nearest level to `log₂ ρ`, where `ρ` is the larger of the
//! lengths of the texture coordinates' screen derivatives in level-0 texels per pixel (the
//! isotropic rule of the graphics APIs' `NEAREST_MIPMAP` filters), clamped to the levels
//! present. The fragment shader takes it once, before the tracer's loops, from the derivatives
//! of the polygon's texture coordinates (where the ray enters), and the viewing ray, its binary
//! search, the light ray of the self-shadow test and the relief normal all read that one level.
//! One level, not a blend of two: a trilinear blend would double every fetch of the loops, and
//! two traced surfaces cannot be blended into one hit.
//!
//! **The atlas** ([`atlas_size`], [`atlas_origin`], [`Mips::atlas`]): the GPU reads the levels
//! from one texture level, packed side by side, level 0 at `(0, 0)` and level `l ≥ 1` in a
//! column to its right at `(N, N − N/2^(l−1))`; a `(3N/2) × N` texture for two levels or more.
//! Not a mip chain, because a relief texture is `rgba32float`, which is not filterable, and
//! OpenGL makes such a texture complete only with a non-mipmapped minification filter (wgpu's GL
//! backend sets `NEAREST`), under which `texelFetch` of a level above the base is undefined.
//! Measured on llvmpipe: the lanes of one shader invocation group that read different levels
//! all fetch the first lane's level. The tracer resolves texel indices inside the level's
//! `N/2^l` square (wrap or clamp) before it offsets them, so levels never bleed into each other.

use alloc::vec;
use alloc::vec::Vec;

use glam::Vec2;

use crate::ReliefError;
use crate::cone::{ConeMap, ConeParams};
use crate::map::{Edge, HeightMap, HeightRange};
use crate::quad::{QuadConeMap, QuadReliefTexture};
use crate::relief::ReliefTexture;

/// The level-`l + 1` map of a level-`l` map of power-of-two side `n ≥ 4`: each depth the mean
/// `((a + b) + (c + d))/4` of its 2×2 group (row above first, left texel first).
///
/// # Errors
///
/// [`ReliefError::NotPowerOfTwo`] unless the side is a power of two; [`ReliefError::MapSize`]
/// below 4 (the result would be smaller than [`HeightMap::MIN_SIDE`]).
pub fn downsample(map: &HeightMap) -> Result<HeightMap, ReliefError> {
    let n = map.size();
    if !n.is_power_of_two() {
        return Err(ReliefError::NotPowerOfTwo(n));
    }
    let h = n / 2;
    if h < HeightMap::MIN_SIDE {
        return Err(ReliefError::MapSize {
            width: h,
            height: h,
            min: HeightMap::MIN_SIDE,
            max: crate::MAX_SIDE,
        });
    }
    let d = map.depths();
    let depths: Vec<f32> = (0..h * h)
        .map(|k| {
            let (i, j) = (2 * (k % h), 2 * (k / h));
            let (a, b) = (d[j * n + i], d[j * n + i + 1]);
            let (c, e) = (d[(j + 1) * n + i], d[(j + 1) * n + i + 1]);
            ((a + b) + (c + e)) * 0.25
        })
        .collect();
    HeightMap::from_depths(h, h, &depths, map.edge(), HeightRange::Refuse)
}

/// Width and height of the atlas of `levels` levels of side `n` (module documentation):
/// `n × n` for one level, `(n + n/2) × n` for more.
pub fn atlas_size(n: usize, levels: usize) -> (usize, usize) {
    if levels > 1 { (n + n / 2, n) } else { (n, n) }
}

/// Where level `level` of a chain of side `n` starts in its atlas: `(0, 0)` for level 0,
/// `(n, n − n/2^(level−1))` for the others (module documentation).
pub fn atlas_origin(n: usize, level: usize) -> (usize, usize) {
    if level == 0 {
        (0, 0)
    } else {
        (n, n - (n >> (level - 1)))
    }
}

/// Most levels a relief texture of side `n` can have: `log₂ n` for a power of two `≥ 2` (down to
/// 2×2), 1 for any other side `≥ 2` (level 0 alone), 0 below 2.
pub fn max_levels(n: usize) -> usize {
    match n {
        0 | 1 => 0,
        _ if n.is_power_of_two() => n.ilog2() as usize,
        _ => 1,
    }
}

/// The height maps of levels `0 .. levels` of `map` (module documentation): `map` itself, then
/// each the [`downsample`] of the one before. What the levels' cones are generated from, and
/// what a normal map of each level is computed from.
///
/// # Errors
///
/// [`ReliefError::NotPowerOfTwo`] unless the side is a power of two;
/// [`ReliefError::OutOfRange`] for `levels` outside 1 to [`max_levels`].
pub fn level_maps(map: &HeightMap, levels: usize) -> Result<Vec<HeightMap>, ReliefError> {
    let n = map.size();
    if !n.is_power_of_two() {
        return Err(ReliefError::NotPowerOfTwo(n));
    }
    crate::check_range("levels", levels as f64, 1.0, max_levels(n) as f64)?;
    let mut maps = Vec::with_capacity(levels);
    maps.push(map.clone());
    while maps.len() < levels {
        let next = downsample(&maps[maps.len() - 1])?;
        maps.push(next);
    }
    Ok(maps)
}

/// What a level of a [`Mips`] chain has to say about itself.
pub trait MipTexture {
    /// Side in texels.
    fn side(&self) -> usize;
    /// Edge mode.
    fn edge_mode(&self) -> Edge;
    /// The texels of each layer, row-major.
    fn layer_texels(&self) -> Vec<&[[f32; 4]]>;
}

impl MipTexture for ReliefTexture {
    fn side(&self) -> usize {
        self.size()
    }
    fn edge_mode(&self) -> Edge {
        self.edge()
    }
    fn layer_texels(&self) -> Vec<&[[f32; 4]]> {
        vec![self.texels()]
    }
}

impl MipTexture for QuadReliefTexture {
    fn side(&self) -> usize {
        self.size()
    }
    fn edge_mode(&self) -> Edge {
        self.edge()
    }
    fn layer_texels(&self) -> Vec<&[[f32; 4]]> {
        self.layers().iter().map(|l| l.texels()).collect()
    }
}

/// A relief texture and its coarser levels, each level valid for its own surface (module
/// documentation). Level `l` has side `N/2^l`; every level has the same edge mode.
#[derive(Clone, Debug, PartialEq)]
pub struct Mips<T> {
    levels: Vec<T>,
}

/// Isotropic relief textures by level ([`ReliefTexture`]).
pub type ReliefMips = Mips<ReliefTexture>;
/// Quad-directional relief textures by level ([`QuadReliefTexture`], §18.1).
pub type QuadReliefMips = Mips<QuadReliefTexture>;

impl<T: MipTexture> Mips<T> {
    /// A chain from its levels, finest first: sides must halve from a power of two (any side for
    /// a single level), every level with the first one's edge mode. Use it for cones made otherwise (quantised ones, say);
    /// each level must hold cones valid for its own depths.
    ///
    /// # Errors
    ///
    /// [`ReliefError::OutOfRange`] for no level; [`ReliefError::NotPowerOfTwo`] for several
    /// levels unless level 0's side is a power of two; [`ReliefError::Mismatch`] for a level of the wrong side or edge
    /// mode.
    pub fn from_levels(levels: Vec<T>) -> Result<Self, ReliefError> {
        let Some(first) = levels.first() else {
            return Err(ReliefError::OutOfRange {
                name: "levels",
                value: 0.0,
                min: 1.0,
                max: max_levels(crate::MAX_SIDE) as f64,
            });
        };
        let (n, edge) = (first.side(), first.edge_mode());
        if levels.len() > 1 && !n.is_power_of_two() {
            return Err(ReliefError::NotPowerOfTwo(n));
        }
        for (l, t) in levels.iter().enumerate() {
            if t.side() != n >> l || t.edge_mode() != edge {
                return Err(ReliefError::Mismatch("mip level"));
            }
        }
        Ok(Self { levels })
    }

    /// The chain of `levels` levels of `map`, each level's texture made by `texture` from its
    /// own map.
    fn generate_levels(
        map: &HeightMap,
        levels: usize,
        texture: impl Fn(&HeightMap) -> Result<T, ReliefError>,
    ) -> Result<Self, ReliefError> {
        let textures = level_maps(map, levels)?
            .iter()
            .map(texture)
            .collect::<Result<Vec<_>, _>>()?;
        Self::from_levels(textures)
    }

    /// The levels, finest first.
    pub fn levels(&self) -> &[T] {
        &self.levels
    }

    /// Level `l`, clamped to the coarsest level present.
    pub fn level(&self, l: usize) -> &T {
        &self.levels[l.min(self.levels.len() - 1)]
    }

    /// Number of levels (at least 1).
    pub fn len(&self) -> usize {
        self.levels.len()
    }

    /// Always `false`: a chain has level 0.
    pub fn is_empty(&self) -> bool {
        self.levels.is_empty()
    }

    /// Level 0's side.
    pub fn size(&self) -> usize {
        self.levels[0].side()
    }

    /// The edge mode of every level.
    pub fn edge(&self) -> Edge {
        self.levels[0].edge_mode()
    }

    /// The atlas of the levels' texels (module documentation), row-major, [`atlas_size`] wide;
    /// texels outside every level are zero.
    pub fn atlas(&self) -> Vec<[f32; 4]> {
        self.atlas_layers().swap_remove(0)
    }

    /// The levels' atlases, one per layer (one layer for isotropic textures, four for quadrant
    /// textures in [`crate::Quadrant::index`] order): what a texture array uploads, layer by
    /// layer.
    pub fn atlas_layers(&self) -> Vec<Vec<[f32; 4]>> {
        let n = self.size();
        let (w, h) = atlas_size(n, self.len());
        let layers = self.levels[0].layer_texels().len();
        let mut out = vec![vec![[0.0f32; 4]; w * h]; layers];
        for (l, t) in self.levels.iter().enumerate() {
            let side = n >> l;
            let (x0, y0) = atlas_origin(n, l);
            for (atlas, texels) in out.iter_mut().zip(t.layer_texels()) {
                for j in 0..side {
                    let row = &texels[j * side..(j + 1) * side];
                    atlas[(y0 + j) * w + x0..(y0 + j) * w + x0 + side].copy_from_slice(row);
                }
            }
        }
        out
    }

    /// The level [`mip_level`] picks for screen derivatives `du`, `dv` of the texture
    /// coordinates (texture widths per pixel), and the texture it reads.
    pub fn for_footprint(&self, du: Vec2, dv: Vec2) -> (usize, &T) {
        let l = mip_level(du, dv, self.size(), self.len());
        (l, &self.levels[l])
    }
}

impl ReliefMips {
    /// `levels` levels of `map` (1 to [`max_levels`] of its side), each with cones `params` of
    /// its own surface (module documentation); every level's generation runs in parallel with
    /// `std` and is bit-identical for any thread count ([`ConeMap::generate`]).
    ///
    /// # Errors
    ///
    /// [`ReliefError::NotPowerOfTwo`] unless the side is a power of two;
    /// [`ReliefError::OutOfRange`] for `levels`; [`ConeMap::generate`]'s errors.
    pub fn generate(
        map: &HeightMap,
        params: ConeParams,
        levels: usize,
    ) -> Result<Self, ReliefError> {
        Self::generate_levels(map, levels, |m| {
            ReliefTexture::new(m, &ConeMap::generate(m, params)?)
        })
    }
}

impl QuadReliefMips {
    /// [`ReliefMips::generate`] with quadrant cones ([`QuadConeMap::generate`]) at every level.
    ///
    /// # Errors
    ///
    /// As [`ReliefMips::generate`].
    pub fn generate(
        map: &HeightMap,
        params: ConeParams,
        levels: usize,
    ) -> Result<Self, ReliefError> {
        Self::generate_levels(map, levels, |m| {
            QuadReliefTexture::new(m, &QuadConeMap::generate(m, params)?)
        })
    }
}

/// The level a fragment reads (module documentation): with `ρ² = max(|du|², |dv|²)·N²` (level-0
/// texels per pixel, squared; `|du|² = du.x·du.x + du.y·du.y` rounded as written), the largest
/// `l < levels` with `ρ² ≥ 2^(2l − 1)` (so `ρ ≥ 2^(l − ½)`: level 1 from `ρ ≥ √2`), or 0. `du`
/// and `dv` are the texture coordinates' derivatives along the screen's x and y, in texture
/// widths per pixel (WGSL `dpdx(uv)`, `dpdy(uv)`). A NaN footprint reads level 0, an infinite
/// one the coarsest level. The WGSL (`relief_lod` in ocean-gpu's `relief_common.wgsl`) rounds
/// the same operations, so both pick the same level for the same derivatives.
pub fn mip_level(du: Vec2, dv: Vec2, size: usize, levels: usize) -> usize {
    let sx = du.x * du.x + du.y * du.y;
    let sy = dv.x * dv.x + dv.y * dv.y;
    let n = size as f32;
    let s = sx.max(sy) * (n * n);
    let mut level = 0;
    // 2^(2l − 1) for l = level + 1: exact powers of two.
    let mut threshold = 2.0f32;
    while level + 1 < levels && s >= threshold {
        level += 1;
        threshold *= 4.0;
    }
    level
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Thresholds at `ρ = 2^(l − ½)`: just below stays, at it moves up; clamped to the levels.
    #[test]
    fn level_thresholds() {
        let n = 64;
        let texel = 1.0 / n as f32;
        let at = |rho: f32, levels| mip_level(Vec2::new(rho * texel, 0.0), Vec2::ZERO, n, levels);
        assert_eq!(at(1.0, 6), 0);
        assert_eq!(at(1.41, 6), 0);
        assert_eq!(at(1.415, 6), 1);
        assert_eq!(at(2.82, 6), 1);
        assert_eq!(at(2.83, 6), 2);
        assert_eq!(at(100.0, 6), 5);
        assert_eq!(at(100.0, 3), 2);
        assert_eq!(at(100.0, 1), 0);
        assert_eq!(at(f32::INFINITY, 4), 3);
        assert_eq!(at(f32::NAN, 4), 0);
        // The longer of the two derivatives decides, whichever axis it lies on.
        let l = mip_level(
            Vec2::new(0.0, texel),
            Vec2::new(3.0 * texel, 3.0 * texel),
            n,
            6,
        );
        assert_eq!(l, 2, "ρ = 3√2 ≈ 4.24 lies in [2^1.5, 2^2.5)");
    }

    /// Levels sit side by side without overlap and inside the atlas, for every side and count.
    #[test]
    fn atlas_levels_do_not_overlap() {
        for k in 1..=12 {
            let n = 1usize << k;
            for levels in 1..=max_levels(n) {
                let (w, h) = atlas_size(n, levels);
                let mut used = vec![false; w * h];
                for l in 0..levels {
                    let (x0, y0) = atlas_origin(n, l);
                    let side = n >> l;
                    assert!(x0 + side <= w && y0 + side <= h, "{n} {l}");
                    for j in y0..y0 + side {
                        for i in x0..x0 + side {
                            assert!(!used[j * w + i], "{n} level {l} overlaps at ({i}, {j})");
                            used[j * w + i] = true;
                        }
                    }
                }
            }
        }
        assert_eq!(atlas_size(64, 6), (96, 64));
        assert_eq!(atlas_origin(64, 1), (64, 0));
        assert_eq!(atlas_origin(64, 2), (64, 32));
        assert_eq!(atlas_origin(64, 5), (64, 60));
    }

    #[test]
    fn downsample_means_groups() {
        let depths: Vec<f32> = (0..16).map(|k| k as f32 / 16.0).collect();
        let map = HeightMap::from_depths(4, 4, &depths, Edge::Clamp, HeightRange::Refuse).unwrap();
        let half = downsample(&map).unwrap();
        assert_eq!(half.size(), 2);
        assert_eq!(half.edge(), Edge::Clamp);
        // Group (0, 0): texels 0, 1, 4, 5 → mean 2.5/16.
        assert_eq!(
            half.depths(),
            &[2.5 / 16.0, 4.5 / 16.0, 10.5 / 16.0, 12.5 / 16.0]
        );
        assert!(downsample(&half).is_err(), "1×1 is below the smallest map");
    }
}
