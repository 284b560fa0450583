//! Height queries on the continuous surface: the model between grid points, the limit of an
//! ever finer grid.
//!
//! The frame's model is a sum of layers: each box's trains, multiplied by its modulation μ,
//! which the grid stores at its points (zero at every point outside the box, by the inside
//! rule of [`crate::frame`]) and which is **bilinear** between them, as the additive height
//! field is. Every position then has an exact surface: the trochoids of Eq. 6–7 at the
//! interpolated μ. At a grid point it is the grid's own vertex (to the kernel's `f32`
//! rounding); between grid points it is what a finer grid would draw, and what the
//! projected-grid renderer (`ocean_gpu::OceanRenderer`, which evaluates the trains at each of
//! its vertices) approaches. The drawn mesh ([`crate::drawn`]) differs from it inside cells
//! by the linear interpolation of the trains: about A·(1 − cos(π·s/λ)) for a train of
//! amplitude A and wavelength λ on a grid of spacing s.
//!
//! Gerstner waves move points horizontally, so a query first finds the rest position p₀ whose
//! displaced point lies over (x, z), by Newton's method on p₀ + D(p₀) = (x, z), then reads the
//! height and normal there. Batches are solved four queries at a time in lock step: every
//! Newton round evaluates the waves for all the lanes that still iterate with one lane loop
//! ([`ocean_core::TimedWaves::add_sums_lanes`]), whose lanes do exactly the operations of a single query,
//! so a batched answer has the bits of [`Frame::continuous_height_at`] for the same point.

// Lane loops index several arrays in step; that indexed shape is what LLVM vectorises.
#![allow(clippy::needless_range_loop)]

use alloc::vec;
use alloc::vec::Vec;

use glam::{DVec2, DVec3};
use ocean_core::LaneSums;

#[cfg(feature = "std")]
use crate::batch::QUERY_SORT_MIN;
use crate::batch::{check_batch, grid_order, nearest_point, scatter, sorted_batch};
use crate::error::WtbError;
use crate::frame::{Frame, FrameLayer};

/// A continuous height query's answer.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct HeightSample {
    /// Water height at the queried (x, z), metres.
    pub height: f64,
    /// Unit surface normal there.
    pub normal: DVec3,
    /// The rest position whose displaced point lies over the queried (x, z).
    pub rest: DVec2,
    /// Horizontal distance between the displaced rest position and the query, metres.
    pub residual: f64,
}

impl Default for HeightSample {
    /// The sea at rest over the origin.
    fn default() -> Self {
        Self::REST
    }
}

impl HeightSample {
    /// The sea at rest at the origin: the placeholder a batch starts from.
    const REST: Self = Self {
        height: 0.0,
        normal: DVec3::Y,
        rest: DVec2::ZERO,
        residual: 0.0,
    };
}

/// Horizontal residual at which a continuous height query stops, metres: 10 µm, which moves
/// the height by at most the slope times that (Newton's last step, quadratic, usually ends
/// far below it).
pub const QUERY_TOLERANCE: f64 = 1e-5;

/// Newton steps a continuous height query may take.
pub const QUERY_MAX_ITERATIONS: usize = 16;

/// Queries solved together: four `f64` lanes, one AVX2 register or two SSE2 ones.
const LANES: usize = 4;

impl Frame<'_> {
    /// The continuous surface over world (x, z) = `at` (see [`crate::continuous`]): the
    /// model, not the drawn mesh ([`Frame::drawn_height_at`]). Gerstner waves move points
    /// horizontally, so the rest position p₀ whose displaced point lies over `at` is found
    /// first by Newton's method on p₀ + D(p₀) = `at` (the Jacobian is ∂p/∂p₀, positive definite
    /// while no crest folds, so the iteration converges quadratically from p₀ = `at`; where it
    /// is singular a fixed-point step is taken instead), to a residual of
    /// [`QUERY_TOLERANCE`]. The modulation and the height field are bilinear between grid
    /// points, and zero beyond the grid, where the water is at rest.
    ///
    /// # Errors
    ///
    /// [`WtbError::NotFinite`] for a non-finite position.
    pub fn continuous_height_at(&self, at: DVec2) -> Result<HeightSample, WtbError> {
        if !at.is_finite() {
            return Err(WtbError::NotFinite("query position"));
        }
        let mut out = [HeightSample::REST];
        self.solve_all(&[at], &mut out);
        Ok(out[0])
    }

    /// [`Frame::continuous_height_at`] for many points, each answer bit-identical to its own
    /// [`Frame::continuous_height_at`]. A batch of 256 or more is answered in the order of the grid
    /// points nearest the queries (row-major, by a radix sort) rather than in the caller's
    /// order (the answers still land at the queries' indices): random queries then read the
    /// modulation row by row, not one cache miss at a time. This costs four `u32` and one
    /// [`HeightSample`] per query of scratch memory.
    ///
    /// # Errors
    ///
    /// [`WtbError::Eval`] when `out` is not as long as `at`; [`WtbError::NotFinite`] for a
    /// non-finite position. Nothing is written on error.
    pub fn continuous_heights(
        &self,
        at: &[DVec2],
        out: &mut [HeightSample],
    ) -> Result<(), WtbError> {
        check_batch(at, out.len())?;
        if !sorted_batch(at.len()) {
            self.solve_all(at, out);
            return Ok(());
        }
        let cells: Vec<[u32; 2]> = at.iter().map(|p| self.query_cell(*p)).collect();
        let order = grid_order(&cells, self.grid.nx(), self.grid.nz());
        let mut sorted = vec![HeightSample::REST; order.len()];
        self.solve_keys(at, &order, &mut sorted);
        scatter(&order, sorted, out);
        Ok(())
    }

    /// [`Frame::continuous_heights`] on the current rayon thread pool; the same bits on any number of
    /// threads.
    ///
    /// # Errors
    ///
    /// As [`Frame::continuous_heights`].
    #[cfg(feature = "std")]
    pub fn continuous_heights_par(
        &self,
        at: &[DVec2],
        out: &mut [HeightSample],
    ) -> Result<(), WtbError> {
        use rayon::prelude::*;
        check_batch(at, out.len())?;
        if !sorted_batch(at.len()) {
            at.par_chunks(QUERY_SORT_MIN)
                .zip(out.par_chunks_mut(QUERY_SORT_MIN))
                .for_each(|(at, out)| self.solve_all(at, out));
            return Ok(());
        }
        let cells: Vec<[u32; 2]> = at.par_iter().map(|p| self.query_cell(*p)).collect();
        // The radix sort is a few linear passes, a small share of the solving: serial.
        let order = grid_order(&cells, self.grid.nx(), self.grid.nz());
        // Answers in row order (each task reads a band of grid rows), then gathered back to
        // the queries' indices through the inverse permutation.
        let mut sorted = vec![HeightSample::REST; order.len()];
        sorted
            .par_chunks_mut(QUERY_SORT_MIN)
            .zip(order.par_chunks(QUERY_SORT_MIN))
            .for_each(|(out, keys)| self.solve_keys(at, keys, out));
        let mut rank = vec![0u32; order.len()];
        for (r, &q) in order.iter().enumerate() {
            rank[q as usize] = r as u32;
        }
        out.par_iter_mut()
            .zip(rank.par_iter())
            .for_each(|(o, r)| *o = sorted[*r as usize]);
        Ok(())
    }

    /// Solves `at` in the caller's order, [`LANES`] at a time.
    fn solve_all(&self, at: &[DVec2], out: &mut [HeightSample]) {
        self.solve_batch(at, None, out);
    }

    /// Solves the queries `order` names (indices into `at`) into `out`, in that order.
    fn solve_keys(&self, at: &[DVec2], order: &[u32], out: &mut [HeightSample]) {
        self.solve_batch(at, Some(order), out);
    }

    /// The grid point nearest `p`, or (nx, nz) off the grid (see [`nearest_point`]).
    pub(crate) fn query_cell(&self, p: DVec2) -> [u32; 2] {
        let size = (self.grid.nx(), self.grid.nz());
        nearest_point(self.grid.origin(), self.inv_spacing, size, p)
    }

    /// Solves a batch [`LANES`] queries at a time: `at` in the caller's order, or the queries
    /// `order` names in that order. (Compiled for the baseline target: measured here, the lane
    /// loops ran about 1.5 times faster with SSE2 than inside an AVX2 dispatch.)
    fn solve_batch(&self, at: &[DVec2], order: Option<&[u32]>, out: &mut [HeightSample]) {
        let reach = self.displacement_bound();
        match order {
            None => {
                for (at, out) in at.chunks(LANES).zip(out.chunks_mut(LANES)) {
                    self.solve(at, reach, out);
                }
            }
            Some(order) => {
                for (order, out) in order.chunks(LANES).zip(out.chunks_mut(LANES)) {
                    let mut lanes = [DVec2::ZERO; LANES];
                    for (p, &q) in lanes.iter_mut().zip(order) {
                        *p = at[q as usize];
                    }
                    self.solve(&lanes[..order.len()], reach, out);
                }
            }
        }
    }

    /// Solves up to [`LANES`] finite queries in lock step into `out` (as long as `at`).
    ///
    /// Each lane follows [`Frame::continuous_height_at`]'s iteration: evaluate at p₀ = `at`
    /// (moved onto the grid's rectangle); then, until the residual is within
    /// [`QUERY_TOLERANCE`] or [`QUERY_MAX_ITERATIONS`] rounds have run, take a Newton step,
    /// kept on the rectangle, and evaluate again. A lane that has stopped is carried along
    /// unchanged.
    ///
    /// The surface is the image of the grid's rectangle of rest positions (its edge points
    /// may move outwards, over the sea beyond, or inwards). A query farther than `reach` (the
    /// largest displacement) from the rectangle, or one whose iteration ends on the
    /// rectangle's edge unconverged (outside the image), is over the sea at rest.
    #[inline(always)]
    fn solve(&self, at: &[DVec2], reach: f64, out: &mut [HeightSample]) {
        let n = at.len();
        debug_assert!(n <= LANES && out.len() == n);
        let (lo, hi) = (self.grid.origin(), self.grid.max_corner());
        let mut p0 = [DVec2::ZERO; LANES];
        let mut iterating = [false; LANES];
        for l in 0..n {
            p0[l] = at[l].clamp(lo, hi);
            iterating[l] = (at[l] - p0[l]).length() <= reach;
        }
        let off_grid = iterating.map(|b| !b);
        let mut sums = LaneSums::<LANES>::REST;
        self.sums_lanes(&p0, &iterating, &mut sums);
        let mut residual = [f64::INFINITY; LANES];
        for _ in 0..QUERY_MAX_ITERATIONS {
            for l in 0..n {
                if !iterating[l] {
                    continue;
                }
                let s = sums.get(l);
                let f = p0[l] + DVec2::new(s.dx, s.dz) - at[l];
                residual[l] = f.length();
                if residual[l] <= QUERY_TOLERANCE {
                    iterating[l] = false;
                    continue;
                }
                let det = s.jacobian_det();
                let step = if det > 1e-6 {
                    DVec2::new(s.jzz * f.x - s.jxz * f.y, s.jxx * f.y - s.jxz * f.x) / det
                } else {
                    f
                };
                p0[l] = (p0[l] - step).clamp(lo, hi);
            }
            if !iterating.iter().any(|&b| b) {
                break;
            }
            self.sums_lanes(&p0, &iterating, &mut sums);
        }
        for l in 0..n {
            let p = p0[l];
            let on_edge = p.x == lo.x || p.y == lo.y || p.x == hi.x || p.y == hi.y;
            if off_grid[l] || (residual[l] > QUERY_TOLERANCE && on_edge) {
                out[l] = HeightSample {
                    rest: at[l],
                    ..HeightSample::REST
                };
                continue;
            }
            let s = sums.get(l);
            out[l] = HeightSample {
                height: s.y + self.height_offset(p0[l]),
                normal: s.normal(),
                rest: p0[l],
                residual: residual[l],
            };
        }
    }

    /// The surface sums of every layer at the rest positions `p0` of the lanes `on`, with
    /// bilinearly interpolated modulation; the other lanes are left as they are. A lane
    /// outside the grid is at rest.
    #[inline(always)]
    fn sums_lanes(&self, p0: &[DVec2; LANES], on: &[bool; LANES], sums: &mut LaneSums<LANES>) {
        let mut cells: [Option<Cell>; LANES] = [None; LANES];
        let (mut x, mut z) = ([0.0; LANES], [0.0; LANES]);
        for l in 0..LANES {
            if on[l] {
                sums.set(l, &ocean_core::PointSums::REST);
                cells[l] = self.cell(p0[l]);
            }
            (x[l], z[l]) = (p0[l].x, p0[l].y);
        }
        for layer in &self.layers {
            // Zero amplitude where a lane rests or lies outside the grid: the lane loop then
            // leaves it alone, as a single query skips such a layer.
            let (mut re, mut im) = ([0.0; LANES], [0.0; LANES]);
            for l in 0..LANES {
                if let Some(c) = &cells[l] {
                    [re[l], im[l]] = modulation_at(layer, c);
                }
            }
            // p0 is finite (the query was checked, and a Newton step from a finite point with
            // a finite Jacobian stays finite), and so is every modulation value.
            layer.timed.add_sums_lanes(&x, &z, &re, &im, sums);
        }
    }

    fn height_offset(&self, p0: DVec2) -> f64 {
        let (Some(h), Some(cell)) = (&self.height, self.cell(p0)) else {
            return 0.0;
        };
        let nx = self.grid.nx();
        bilinear(&cell, |i, j| [f64::from(h[j * nx + i]), 0.0])[0]
    }

    /// The grid cell holding `p` and the fractions across it; `None` outside the grid.
    #[inline(always)]
    fn cell(&self, p: DVec2) -> Option<Cell> {
        let l = (p - self.grid.origin()) * self.inv_spacing;
        let last = self.last_point;
        // A point clamped onto the rectangle's far edge can land a rounding past it in grid
        // units: within a millionth of a cell it is on the edge.
        let slack = 1e-6;
        if !(l.x >= -slack && l.y >= -slack && l.x <= last.x + slack && l.y <= last.y + slack) {
            return None;
        }
        let l = l.clamp(DVec2::ZERO, last);
        // 0 ≤ l ≤ n − 1 < 4096 (the grid's cap, [`crate::grid::MAX_SIDE`]) here, so
        // truncation through u32 is the floor, one instruction where a conversion to usize
        // takes a branchy sequence.
        let i = (l.x as u32).min(self.last_cell.0) as usize;
        let j = (l.y as u32).min(self.last_cell.1) as usize;
        Some(Cell {
            i,
            j,
            fx: l.x - i as f64,
            fz: l.y - j as f64,
        })
    }
}

/// A layer's modulation interpolated bilinearly over `cell`; zero outside its rectangle.
#[inline(always)]
fn modulation_at(layer: &FrameLayer<'_>, cell: &Cell) -> [f64; 2] {
    let r = layer.rect();
    let m = layer.modulation().values();
    let at = |q: usize| [f64::from(m[q][0]), f64::from(m[q][1])];
    // The common case: the whole cell inside the rectangle, corners at fixed offsets. A cell
    // left of or above the rectangle wraps to an offset near usize::MAX, which fails the test
    // as a cell at or past the far edge does (its corners i + 1 would leave the rectangle).
    let (di, dj) = (cell.i.wrapping_sub(r.i0), cell.j.wrapping_sub(r.j0));
    if di < r.nx.saturating_sub(1) && dj < r.nz.saturating_sub(1) {
        let q = dj * r.nx + di;
        return lerp2(cell, at(q), at(q + 1), at(q + r.nx), at(q + r.nx + 1));
    }
    bilinear(cell, |i, j| r.index(i, j).map_or([0.0, 0.0], at))
}

/// A grid cell: its first point (i, j) and a position's fractions across it.
#[derive(Clone, Copy)]
struct Cell {
    i: usize,
    j: usize,
    fx: f64,
    fz: f64,
}

fn bilinear(c: &Cell, f: impl Fn(usize, usize) -> [f64; 2]) -> [f64; 2] {
    lerp2(
        c,
        f(c.i, c.j),
        f(c.i + 1, c.j),
        f(c.i, c.j + 1),
        f(c.i + 1, c.j + 1),
    )
}

/// Bilinear interpolation across `c` of the values at its corners (i, j), (i+1, j), (i, j+1),
/// (i+1, j+1).
#[inline(always)]
fn lerp2(c: &Cell, a: [f64; 2], b: [f64; 2], d: [f64; 2], e: [f64; 2]) -> [f64; 2] {
    let mut out = [0.0; 2];
    for n in 0..2 {
        let top = a[n] + (b[n] - a[n]) * c.fx;
        let bottom = d[n] + (e[n] - d[n]) * c.fx;
        out[n] = top + (bottom - top) * c.fz;
    }
    out
}
