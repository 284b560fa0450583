//! The water grid (paper §2): a uniformly sampled height field over which the wave train boxes
//! are laid.
//!
//! [`WaterGrid`] wraps an [`ocean_core::Grid`] and adds the constraints of the paper's model:
//!
//! - **Square spacing.** A box's internal frame steps by the grid spacing along both of its axes u
//!   and v ("the lengths of these vectors are the actual uniform lengths between the water grid
//!   points", §2), so the spacing along x and z must be equal.
//! - **Size cap** of [`MIN_SIDE`] to [`MAX_SIDE`] points per side. At least 2 × 2 so that every
//!   point has a neighbour along both axes (normals, bilinear terrain sampling). At most 4096 × 4096
//!   (16.8 M points): the output positions and normals alone then take 400 MB in `f32`, far beyond
//!   what a frame can recompute (the paper's 512² took 199 ms), and every index stays below 2²⁴,
//!   so grid indices are exact in `f32` and in `u32`, and the box traversal's lattice arithmetic
//!   ([`crate::frame`]) stays exact.
//! - **Spacing** in [[`MIN_SPACING`], [`MAX_SPACING`]] (1 mm, the scale of capillary waves, to
//!   10 km) and **origin** coordinates within ±[`MAX_COORDINATE`] (10⁹ m, where `f64` still resolves
//!   0.12 µm), so that every derived position is finite and precise.
//!
//! Points are `origin + (i·s, j·s)` for columns `i < nx` (along x) and rows `j < nz` (along z),
//! stored row-major at `j·nx + i`, exactly as [`ocean_core::Grid`].

use glam::DVec2;
use ocean_core::Grid;

use crate::error::WtbError;

/// Fewest points along each side of a water grid.
pub const MIN_SIDE: usize = 2;
/// Most points along each side of a water grid (see the module documentation).
pub const MAX_SIDE: usize = 4096;
/// Smallest grid spacing, metres.
pub const MIN_SPACING: f64 = 1e-3;
/// Largest grid spacing, metres.
pub const MAX_SPACING: f64 = 1e4;
/// Largest magnitude of a world coordinate accepted for origins, metres.
pub const MAX_COORDINATE: f64 = 1e9;

/// Checks that a world position is finite and within ±[`MAX_COORDINATE`].
pub(crate) fn check_position(name: &'static str, p: DVec2) -> Result<DVec2, WtbError> {
    if !p.is_finite() {
        return Err(WtbError::NotFinite(name));
    }
    for value in [p.x, p.y] {
        if value.abs() > MAX_COORDINATE {
            return Err(WtbError::OutOfRange {
                name,
                value,
                min: -MAX_COORDINATE,
                max: MAX_COORDINATE,
            });
        }
    }
    Ok(p)
}

/// Checks that `value` is finite and within `[min, max]`.
pub(crate) fn check_range(
    name: &'static str,
    value: f64,
    min: f64,
    max: f64,
) -> Result<f64, WtbError> {
    if !value.is_finite() {
        return Err(WtbError::NotFinite(name));
    }
    if !(min..=max).contains(&value) {
        return Err(WtbError::OutOfRange {
            name,
            value,
            min,
            max,
        });
    }
    Ok(value)
}

/// `⌊x⌋` as an integer, for finite `|x| < 2⁶²` (`core` has no `f64::floor` without `std`).
#[inline]
pub(crate) fn floor_i64(x: f64) -> i64 {
    let t = x as i64; // truncates toward zero
    if (t as f64) > x { t - 1 } else { t }
}

/// `⌈x⌉` as an integer, for finite `|x| < 2⁶²`.
#[inline]
pub(crate) fn ceil_i64(x: f64) -> i64 {
    let t = x as i64;
    if (t as f64) < x { t + 1 } else { t }
}

/// The paper's water grid: a validated [`ocean_core::Grid`] with square spacing and a size cap
/// (see the module documentation).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct WaterGrid {
    grid: Grid,
}

impl WaterGrid {
    /// A grid of `nx × nz` points `origin + (i·spacing, j·spacing)`.
    ///
    /// # Errors
    ///
    /// [`WtbError::NotFinite`] or [`WtbError::OutOfRange`] for the origin or spacing,
    /// [`WtbError::GridSize`] when a side is outside [`MIN_SIDE`]..=[`MAX_SIDE`].
    pub fn new(origin: DVec2, spacing: f64, nx: usize, nz: usize) -> Result<Self, WtbError> {
        Self::from_grid(Grid {
            origin,
            spacing: DVec2::splat(spacing),
            size: (nx, nz),
        })
    }

    /// A square grid of `n × n` points centred on `centre` (as [`Grid::centred`]).
    ///
    /// # Errors
    ///
    /// As [`WaterGrid::new`].
    pub fn centred(centre: DVec2, spacing: f64, n: usize) -> Result<Self, WtbError> {
        check_position("centre", centre)?;
        check_range("spacing", spacing, MIN_SPACING, MAX_SPACING)?;
        if !(MIN_SIDE..=MAX_SIDE).contains(&n) {
            return Err(grid_size(n, n));
        }
        Self::from_grid(Grid::centred(centre, spacing, n))
    }

    /// Validates an [`ocean_core::Grid`] as a water grid.
    ///
    /// # Errors
    ///
    /// As [`WaterGrid::new`], and [`WtbError::NonSquareSpacing`] when `spacing.x != spacing.y`.
    pub fn from_grid(grid: Grid) -> Result<Self, WtbError> {
        check_position("origin", grid.origin)?;
        let s = grid.spacing;
        check_range("spacing.x", s.x, MIN_SPACING, MAX_SPACING)?;
        check_range("spacing.z", s.y, MIN_SPACING, MAX_SPACING)?;
        if s.x != s.y {
            return Err(WtbError::NonSquareSpacing { x: s.x, z: s.y });
        }
        let (nx, nz) = grid.size;
        if !(MIN_SIDE..=MAX_SIDE).contains(&nx) || !(MIN_SIDE..=MAX_SIDE).contains(&nz) {
            return Err(grid_size(nx, nz));
        }
        Ok(Self { grid })
    }

    /// The underlying [`ocean_core::Grid`] (for ocean-core's batch evaluators).
    #[inline]
    pub fn grid(&self) -> &Grid {
        &self.grid
    }

    /// World (x, z) of point (0, 0), metres.
    #[inline]
    pub fn origin(&self) -> DVec2 {
        self.grid.origin
    }

    /// Distance between neighbouring points along x and along z, metres.
    #[inline]
    pub fn spacing(&self) -> f64 {
        self.grid.spacing.x
    }

    /// Columns (along x) and rows (along z).
    #[inline]
    pub fn size(&self) -> (usize, usize) {
        self.grid.size
    }

    /// Columns, along x.
    #[inline]
    pub fn nx(&self) -> usize {
        self.grid.size.0
    }

    /// Rows, along z.
    #[inline]
    pub fn nz(&self) -> usize {
        self.grid.size.1
    }

    /// Number of points, `nx · nz` (at most 2²⁴).
    #[inline]
    pub fn len(&self) -> usize {
        self.grid.size.0 * self.grid.size.1
    }

    /// Always `false`: a water grid has at least 2 × 2 points.
    #[inline]
    pub fn is_empty(&self) -> bool {
        false
    }

    /// World (x, z) of the last point, `(nx − 1, nz − 1)`.
    #[inline]
    pub fn max_corner(&self) -> DVec2 {
        self.point(self.nx() - 1, self.nz() - 1)
    }

    /// Row-major index `j·nx + i` of point (i, j), or `None` when (i, j) is outside the grid.
    #[inline]
    pub fn index(&self, i: usize, j: usize) -> Option<usize> {
        (i < self.nx() && j < self.nz()).then(|| j * self.nx() + i)
    }

    /// (i, j) of a row-major index, or `None` past the last point.
    #[inline]
    pub fn ij(&self, index: usize) -> Option<(usize, usize)> {
        (index < self.len()).then(|| (index % self.nx(), index / self.nx()))
    }

    /// Whether the signed indices (i, j) name a point of the grid.
    #[inline]
    pub fn contains_index(&self, i: i64, j: i64) -> bool {
        i >= 0 && j >= 0 && (i as u64) < self.nx() as u64 && (j as u64) < self.nz() as u64
    }

    /// World (x, z) of point (i, j): `origin + (i·s, j·s)`. Defined for any (i, j), in the grid or
    /// not.
    #[inline]
    pub fn point(&self, i: usize, j: usize) -> DVec2 {
        let s = self.spacing();
        self.grid.origin + DVec2::new(i as f64 * s, j as f64 * s)
    }

    /// Fractional grid coordinates of a world position: `(p − origin) / s`, so that point (i, j)
    /// maps to (i, j).
    #[inline]
    pub fn to_local(&self, p: DVec2) -> DVec2 {
        (p - self.grid.origin) / self.spacing()
    }

    /// The grid cell holding world position `p`: `(⌊(x − x₀)/s⌋, ⌊(z − z₀)/s⌋)`, signed (it may
    /// lie outside the grid), or `None` when `p` is not finite or so far away that the index
    /// would not fit in 62 bits.
    #[inline]
    pub fn cell_of(&self, p: DVec2) -> Option<(i64, i64)> {
        let l = self.to_local(p);
        const LIMIT: f64 = (1u64 << 62) as f64;
        if !(l.x.abs() < LIMIT && l.y.abs() < LIMIT) {
            return None;
        }
        Some((floor_i64(l.x), floor_i64(l.y)))
    }

    /// The grid point whose cell (the square from it to its +x, +z neighbours) holds world
    /// position `p`, if that point is in the grid. Points on the far edges (x = x_max or
    /// z = z_max) belong to the last column or row, so every `p` with [`WaterGrid::contains`]
    /// maps to a point.
    #[inline]
    pub fn locate(&self, p: DVec2) -> Option<(usize, usize)> {
        if !self.contains(p) {
            return None;
        }
        let (i, j) = self.cell_of(p)?;
        let i = (i.max(0) as usize).min(self.nx() - 1);
        let j = (j.max(0) as usize).min(self.nz() - 1);
        Some((i, j))
    }

    /// Whether world position `p` lies in the grid's rectangle `[origin, max_corner]` (closed).
    #[inline]
    pub fn contains(&self, p: DVec2) -> bool {
        let lo = self.grid.origin;
        let hi = self.max_corner();
        p.x >= lo.x && p.y >= lo.y && p.x <= hi.x && p.y <= hi.y
    }
}

/// [`WtbError::GridSize`] for a grid of `nx × nz` points.
fn grid_size(nx: usize, nz: usize) -> WtbError {
    WtbError::GridSize {
        nx,
        nz,
        min: MIN_SIDE,
        max: MAX_SIDE,
    }
}
