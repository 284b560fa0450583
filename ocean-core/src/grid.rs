//! A regular grid of rest positions on the sea plane.

use glam::DVec2;

use crate::error::EvalError;

/// `size.0 × size.1` rest positions `origin + (i · spacing.x, j · spacing.y)` in the (x, z)
/// plane, for `i < size.0` (columns, along x) and `j < size.1` (rows, along z).
///
/// Batch outputs are row-major: point (i, j) is element `j * size.0 + i`. Output positions are
/// relative to `origin` (which is `f64`), so a renderer can place the grid far from the world
/// origin without losing `f32` precision.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Grid {
    /// World (x, z) of point (0, 0), metres.
    pub origin: DVec2,
    /// Distance between neighbouring points along x and along z, metres, > 0.
    pub spacing: DVec2,
    /// Number of columns (along x) and rows (along z), each ≥ 1.
    pub size: (usize, usize),
}

impl Grid {
    /// A square grid of `n × n` points centred on `centre`.
    pub fn centred(centre: DVec2, spacing: f64, n: usize) -> Self {
        let half = spacing * (n.saturating_sub(1)) as f64 * 0.5;
        Self {
            origin: centre - DVec2::splat(half),
            spacing: DVec2::splat(spacing),
            size: (n, n),
        }
    }

    /// Number of points, or an error if the grid is empty, not finite or too large.
    pub fn point_count(&self) -> Result<usize, EvalError> {
        if !(self.origin.x.is_finite() && self.origin.y.is_finite()) {
            return Err(EvalError::Position { index: 0 });
        }
        let s = self.spacing;
        if !(s.x.is_finite() && s.y.is_finite() && s.x > 0.0 && s.y > 0.0) {
            return Err(EvalError::Grid("spacing must be finite and > 0"));
        }
        let (nx, nz) = self.size;
        if nx == 0 || nz == 0 {
            return Err(EvalError::Grid("size must be at least 1 x 1"));
        }
        // Column indices are converted to f32 exactly, which holds below 2^24.
        if nx > 1 << 24 || nz > 1 << 24 {
            return Err(EvalError::Grid("at most 2^24 points per side"));
        }
        nx.checked_mul(nz)
            .ok_or(EvalError::Grid("point count overflows usize"))
    }

    /// Position of point (i, j) relative to the origin, as the `f32` kernels compute it.
    #[inline]
    pub fn local(&self, i: usize, j: usize) -> (f32, f32) {
        (
            i as f32 * self.spacing.x as f32,
            j as f32 * self.spacing.y as f32,
        )
    }
}

/// A rectangle of grid points: columns `i0..i0 + nx`, rows `j0..j0 + nz`.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct GridRect {
    /// First column.
    pub i0: usize,
    /// First row.
    pub j0: usize,
    /// Number of columns.
    pub nx: usize,
    /// Number of rows.
    pub nz: usize,
}

impl GridRect {
    /// Number of points.
    pub fn len(&self) -> usize {
        self.nx * self.nz
    }

    /// Whether the rectangle holds no point.
    pub fn is_empty(&self) -> bool {
        self.nx == 0 || self.nz == 0
    }

    /// Whether the rectangle lies inside a grid of `size` (columns, rows) points; an empty
    /// rectangle does if its first point does or it sits on the far edge.
    pub fn fits(&self, size: (usize, usize)) -> bool {
        let inside =
            |start: usize, len: usize, n: usize| start.checked_add(len).is_some_and(|end| end <= n);
        inside(self.i0, self.nx, size.0) && inside(self.j0, self.nz, size.1)
    }

    /// Index into a row-major array over this rectangle of grid point (i, j), if inside.
    #[inline]
    pub fn index(&self, i: usize, j: usize) -> Option<usize> {
        let (di, dj) = (i.checked_sub(self.i0)?, j.checked_sub(self.j0)?);
        (di < self.nx && dj < self.nz).then_some(dj * self.nx + di)
    }
}
