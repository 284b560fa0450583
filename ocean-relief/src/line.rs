//! An exact walk along a horizontal line over the bilinear cells, in `f64`: on each cell the
//! surface restricted to the line is a quadratic. The ground-truth tracer and the validity check
//! are built on it.
//!
//! Coordinates are texel-centre coordinates (texel `(i, j)`'s centre is `(i, j)`); cell
//! `(ci, cj)` is the square `[ci, ci + 1] × [cj, cj + 1]` whose corners are texels `ci, ci + 1`
//! and `cj, cj + 1` (resolved by the map's edge mode).

use crate::map::HeightMap;

/// The surface along one cell's piece of the line: `S(s₀ + τ) = k0 + k1·τ + k2·τ²` for
/// `τ ∈ [0, s₁ − s₀]`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Piece {
    /// Cell column (spatial, unwrapped).
    pub ci: i64,
    /// Cell row.
    pub cj: i64,
    /// Distance along the line where the piece starts.
    pub s0: f64,
    /// Where it ends.
    pub s1: f64,
    /// Surface depth at `s0`.
    pub k0: f64,
    /// Slope at `s0` (depth per unit of `s`).
    pub k1: f64,
    /// Half the second derivative.
    pub k2: f64,
}

impl Piece {
    /// Depth at `s` (`s0 ≤ s ≤ s1`).
    #[inline]
    pub fn at(&self, s: f64) -> f64 {
        let t = s - self.s0;
        self.k0 + (self.k1 + self.k2 * t) * t
    }
}

/// Walks the line `(px, py) + s·(ux, uy)`, `0 ≤ s ≤ s_max`, calling `f` for each cell piece in
/// order until it returns `false`. `(ux, uy)` need not be unit: `s` is in units of its length.
pub fn walk(
    map: &HeightMap,
    px: f64,
    py: f64,
    ux: f64,
    uy: f64,
    s_max: f64,
    mut f: impl FnMut(&Piece) -> bool,
) {
    // The cell the line enters: on a boundary, the one on the side it moves to.
    let mut ci = if ux >= 0.0 {
        libm::floor(px)
    } else {
        libm::ceil(px) - 1.0
    } as i64;
    let mut cj = if uy >= 0.0 {
        libm::floor(py)
    } else {
        libm::ceil(py) - 1.0
    } as i64;
    let mut s0 = 0.0f64;
    // A line longer than a few million cells is not something anyone traces; the cap keeps a
    // degenerate call finite.
    for _ in 0..(1usize << 24) {
        let tx = if ux > 0.0 {
            ((ci + 1) as f64 - px) / ux
        } else if ux < 0.0 {
            (ci as f64 - px) / ux
        } else {
            f64::INFINITY
        };
        let ty = if uy > 0.0 {
            ((cj + 1) as f64 - py) / uy
        } else if uy < 0.0 {
            (cj as f64 - py) / uy
        } else {
            f64::INFINITY
        };
        let s1 = tx.min(ty).min(s_max).max(s0);
        let d00 = f64::from(map.depth(ci, cj));
        let d10 = f64::from(map.depth(ci + 1, cj));
        let d01 = f64::from(map.depth(ci, cj + 1));
        let d11 = f64::from(map.depth(ci + 1, cj + 1));
        let (ex, ey, dd) = (d10 - d00, d01 - d00, d00 - d10 - d01 + d11);
        // Local coordinates of the piece's start, clamped against rounding.
        let fx = (px + s0 * ux - ci as f64).clamp(0.0, 1.0);
        let fy = (py + s0 * uy - cj as f64).clamp(0.0, 1.0);
        let piece = Piece {
            ci,
            cj,
            s0,
            s1,
            k0: d00 + ex * fx + ey * fy + dd * fx * fy,
            k1: ex * ux + ey * uy + dd * (fx * uy + fy * ux),
            k2: dd * ux * uy,
        };
        if !f(&piece) || s1 >= s_max {
            return;
        }
        if tx <= ty {
            ci += if ux > 0.0 { 1 } else { -1 };
        }
        if ty <= tx {
            cj += if uy > 0.0 { 1 } else { -1 };
        }
        s0 = s1;
    }
}
