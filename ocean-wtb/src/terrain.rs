//! Terrain: a height map sampled exactly on the water grid (paper §2, "Land and depth").
//!
//! One `f32` per water grid point, row-major (`j·nx + i`), giving the height of the ground above
//! the sea at rest: a height `h < 0` is sea floor at depth `−h`, `h ≥ 0` is land (a point exactly
//! at the rest level counts as land: there is no water above it). A terrain built with
//! [`Terrain::deep`] is open sea of infinite depth everywhere, with no storage.
//!
//! Outside the water grid the terrain is **deep water** (height −∞, depth +∞): boxes that hang
//! over the grid's edge see open sea there.

use alloc::vec::Vec;

use glam::DVec2;
use ocean_core::Depth;

use crate::error::WtbError;
use crate::grid::WaterGrid;

/// A height map on a [`WaterGrid`] (see the module documentation).
#[derive(Clone, Debug, PartialEq)]
pub struct Terrain {
    grid: WaterGrid,
    /// `None`: deep sea everywhere.
    heights: Option<Vec<f32>>,
    has_land: bool,
}

impl Terrain {
    /// Open sea of infinite depth over the whole grid: no land, [`Depth::Deep`] everywhere.
    pub fn deep(grid: &WaterGrid) -> Self {
        Self {
            grid: *grid,
            heights: None,
            has_land: false,
        }
    }

    /// A height map from one height per grid point, row-major, metres above the sea at rest.
    ///
    /// # Errors
    ///
    /// [`WtbError::TerrainSize`] when `heights.len() != grid.len()`, [`WtbError::TerrainNotFinite`]
    /// for the first NaN or infinite height.
    pub fn from_heights(grid: &WaterGrid, heights: Vec<f32>) -> Result<Self, WtbError> {
        if heights.len() != grid.len() {
            return Err(WtbError::TerrainSize {
                expected: grid.len(),
                got: heights.len(),
            });
        }
        if let Some(index) = heights.iter().position(|h| !h.is_finite()) {
            return Err(WtbError::TerrainNotFinite { index });
        }
        let has_land = heights.iter().any(|&h| h >= 0.0);
        Ok(Self {
            grid: *grid,
            heights: Some(heights),
            has_land,
        })
    }

    /// As [`Terrain::from_heights`], copying a slice.
    ///
    /// # Errors
    ///
    /// As [`Terrain::from_heights`].
    pub fn from_slice(grid: &WaterGrid, heights: &[f32]) -> Result<Self, WtbError> {
        if heights.len() != grid.len() {
            return Err(WtbError::TerrainSize {
                expected: grid.len(),
                got: heights.len(),
            });
        }
        Self::from_heights(grid, heights.to_vec())
    }

    /// A height map from a function of each grid point's world (x, z).
    ///
    /// # Errors
    ///
    /// [`WtbError::TerrainNotFinite`] when the function returns NaN or ±∞.
    pub fn from_fn(grid: &WaterGrid, mut f: impl FnMut(DVec2) -> f32) -> Result<Self, WtbError> {
        let mut heights = Vec::with_capacity(grid.len());
        for j in 0..grid.nz() {
            for i in 0..grid.nx() {
                heights.push(f(grid.point(i, j)));
            }
        }
        Self::from_heights(grid, heights)
    }

    /// The water grid the heights are sampled on.
    #[inline]
    pub fn grid(&self) -> &WaterGrid {
        &self.grid
    }

    /// The heights, row-major, or `None` for a [`Terrain::deep`] sea.
    #[inline]
    pub fn heights(&self) -> Option<&[f32]> {
        self.heights.as_deref()
    }

    /// Whether any grid point is land (height ≥ 0).
    #[inline]
    pub fn has_land(&self) -> bool {
        self.has_land
    }

    /// Height of the ground at grid point (i, j), metres above the sea at rest; −∞ for deep sea
    /// and outside the grid.
    #[inline]
    pub fn height(&self, i: usize, j: usize) -> f32 {
        match (&self.heights, self.grid.index(i, j)) {
            (Some(h), Some(idx)) => h[idx],
            _ => f32::NEG_INFINITY,
        }
    }

    /// Height at a row-major index; −∞ for deep sea and past the last point.
    #[inline]
    pub fn height_at_index(&self, index: usize) -> f32 {
        match &self.heights {
            Some(h) => h.get(index).copied().unwrap_or(f32::NEG_INFINITY),
            None => f32::NEG_INFINITY,
        }
    }

    /// Water depth at grid point (i, j): `−height`, metres; +∞ for deep sea and outside the grid,
    /// ≤ 0 on land.
    #[inline]
    pub fn depth(&self, i: usize, j: usize) -> f64 {
        -(self.height(i, j) as f64)
    }

    /// Whether grid point (i, j) is land (height ≥ 0). Outside the grid: `false` (deep sea).
    #[inline]
    pub fn is_land(&self, i: usize, j: usize) -> bool {
        self.height(i, j) >= 0.0
    }

    /// The depth at grid point (i, j) as ocean-core's dispersion input: `None` on land,
    /// [`Depth::Deep`] for deep sea and outside the grid, else [`Depth::Finite`].
    #[inline]
    pub fn water_depth(&self, i: usize, j: usize) -> Option<Depth> {
        to_depth(self.depth(i, j))
    }

    /// Ground height at any world (x, z), bilinear between the four surrounding grid points; −∞
    /// (deep sea) outside the grid's rectangle `[origin, max_corner]` and everywhere on a
    /// [`Terrain::deep`] sea. Exactly the stored height at grid points.
    pub fn height_at(&self, p: DVec2) -> f64 {
        let Some(h) = &self.heights else {
            return f64::NEG_INFINITY;
        };
        let Some((i, j)) = self.grid.locate(p) else {
            return f64::NEG_INFINITY;
        };
        let nx = self.grid.nx();
        // The cell's lower corner, so that (i + 1, j + 1) exists; the far edges use the last cell
        // with a fraction of 1.
        let i0 = i.min(nx - 2);
        let j0 = j.min(self.grid.nz() - 2);
        let l = self.grid.to_local(p);
        let fx = (l.x - i0 as f64).clamp(0.0, 1.0);
        let fz = (l.y - j0 as f64).clamp(0.0, 1.0);
        let at = |i: usize, j: usize| h[j * nx + i] as f64;
        let h0 = at(i0, j0) + (at(i0 + 1, j0) - at(i0, j0)) * fx;
        let h1 = at(i0, j0 + 1) + (at(i0 + 1, j0 + 1) - at(i0, j0 + 1)) * fx;
        h0 + (h1 - h0) * fz
    }

    /// Water depth at any world (x, z): `−height_at(p)`; +∞ outside the grid.
    #[inline]
    pub fn depth_at(&self, p: DVec2) -> f64 {
        -self.height_at(p)
    }

    /// Whether world (x, z) is land by the bilinear height (≥ 0).
    #[inline]
    pub fn is_land_at(&self, p: DVec2) -> bool {
        self.height_at(p) >= 0.0
    }
}

/// A water depth in metres as a dispersion input: `None` for land (depth ≤ 0) or NaN,
/// [`Depth::Deep`] for +∞, else [`Depth::Finite`].
#[inline]
pub fn to_depth(depth: f64) -> Option<Depth> {
    if depth == f64::INFINITY {
        Some(Depth::Deep)
    } else if depth > 0.0 {
        Some(Depth::Finite(depth))
    } else {
        None
    }
}
