//! Height queries on the drawn surface: the triangles of the frame's grid.
//!
//! An engine draws the grid that [`Frame::evaluate`] writes as a triangle mesh. Each cell
//! (i, j)–(i+1, j+1) is split along the diagonal from (i+1, j) to (i, j+1) into
//!
//! - the **lower** triangle (i, j), (i+1, j), (i, j+1), and
//! - the **upper** triangle (i+1, j), (i+1, j+1), (i, j+1),
//!
//! wound counter-clockwise seen from above (+y), with the displaced vertices as the grid
//! writes them. A drawn query intersects the vertical line through world (x, z) with those
//! triangles: the height is the triangle's plane there, the normal the triangle's own.
//!
//! The vertices are not read from the caller's buffers: the query evaluates the blocks of
//! the grid around its points with the grid's own kernel ([`ocean_core::LayersEvaluator`]),
//! which gives each vertex exactly the bits [`Frame::evaluate`] gives it, so the answer is
//! that of the mesh the caller draws from the same frame.
//!
//! # Finding the triangle
//!
//! A vertex moves horizontally by at most D = Σ over layers of max |μ| · Σ A (the
//! modulation's bound times the trains' amplitudes), so every triangle over a point has its
//! rest triangle within D of the point: the query's **window** of cells. Within it the query
//! guesses the rest cell by a fixed-point step on the vertices' displacement, then walks
//! from triangle to triangle across the edge the point lies beyond, which ends at the one
//! triangle over the point wherever the mesh does not fold. Where any triangle of the window is
//! inverted or degenerate (the mesh folds: a crest past the trochoid's limit, Σ k·A·|μ| > 1),
//! or the walk leaves the window, every triangle of the window is tested and the **highest**
//! over the point is the answer: the surface seen from above.
//!
//! Outside the mesh (beyond the grid, or past a grid edge that the waves pull inwards) no
//! triangle lies over the point and the water is at rest there, as it is everywhere beyond
//! the grid: height 0, normal +y, [`DrawnSample::triangle`] `None`.

// The triangle loops index corners, weights and normals in step.
#![allow(clippy::needless_range_loop)]

use alloc::vec;
use alloc::vec::Vec;

use glam::{DVec2, DVec3, Vec3};
use ocean_core::{GridRect, LayersEvaluator};

#[cfg(feature = "std")]
use crate::batch::QUERY_SORT_MIN;
use crate::batch::{check_batch, grid_order, nearest_point, sorted_batch};
use crate::error::WtbError;
use crate::frame::Frame;

/// The triangle of the drawn mesh that a query landed on.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct DrawnTriangle {
    /// The cell's first grid point (i, j).
    pub cell: [u32; 2],
    /// `false`: the lower triangle (i, j), (i+1, j), (i, j+1); `true`: the upper triangle
    /// (i+1, j), (i+1, j+1), (i, j+1).
    pub upper: bool,
    /// The query's barycentric weights on the triangle's vertices, in that order (each in
    /// [0, 1] up to rounding, summing to 1).
    pub weights: [f64; 3],
}

/// A drawn query's answer.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct DrawnSample {
    /// Height of the drawn triangle over the queried (x, z), metres above the sea at rest.
    pub height: f64,
    /// The triangle's unit normal, on its upper side.
    pub normal: DVec3,
    /// The vertex normals blended by the barycentric weights and normalised: the normal a
    /// renderer interpolating the grid's normals shades the point with.
    pub shading_normal: DVec3,
    /// World (x, z) of the rest position that the mesh carries to the query: the triangle's
    /// rest vertices blended by the same weights.
    pub rest: DVec2,
    /// The triangle, or `None` where no triangle lies over the point (the sea at rest).
    pub triangle: Option<DrawnTriangle>,
}

impl Default for DrawnSample {
    /// The sea at rest over the origin.
    fn default() -> Self {
        Self::rest(DVec2::ZERO)
    }
}

impl DrawnSample {
    /// The sea at rest over `at`: the answer off the mesh.
    fn rest(at: DVec2) -> Self {
        Self {
            height: 0.0,
            normal: DVec3::Y,
            shading_normal: DVec3::Y,
            rest: at,
            triangle: None,
        }
    }
}

/// Side of a block of evaluated vertices, a power of two: one 16-lane chunk of the kernel.
const TILE: usize = 16;
const TILE_SHIFT: u32 = TILE.trailing_zeros();

/// A tile not evaluated.
const NONE: u32 = u32::MAX;

/// Triangle-to-triangle steps a walk may take before the query tests its whole window.
const MAX_WALK: usize = 64;

/// A barycentric weight at least this far below zero puts the point outside a triangle. Points
/// on an edge (weight ±1e-16 from rounding) belong to both triangles there, which give the same
/// height.
const EDGE: f64 = -1e-12;

impl Frame<'_> {
    /// The drawn surface over world (x, z) = `at`: the triangle of the frame's grid that lies
    /// over it (see [`crate::drawn`] for the triangulation and the rule where the mesh folds),
    /// or the sea at rest where none does.
    ///
    /// # Errors
    ///
    /// [`WtbError::NotFinite`] for a non-finite position.
    pub fn drawn_height_at(&self, at: DVec2) -> Result<DrawnSample, WtbError> {
        let mut out = [DrawnSample::rest(DVec2::ZERO)];
        self.drawn_heights(&[at], &mut out)?;
        Ok(out[0])
    }

    /// [`Frame::drawn_height_at`] for many points; the answers do not depend on the batch. The
    /// vertices around the points are evaluated once for the batch (a batch spread over the
    /// whole grid costs about one evaluation of the grid, plus the walks); a batch of 256 or
    /// more is then answered in the order of the grid points nearest the queries, so that the
    /// walks read the vertices row by row.
    ///
    /// # Errors
    ///
    /// [`WtbError::Eval`] when `out` is not as long as `at`; [`WtbError::NotFinite`] for a
    /// non-finite position. Nothing is written on error.
    pub fn drawn_heights(&self, at: &[DVec2], out: &mut [DrawnSample]) -> Result<(), WtbError> {
        check_batch(at, out.len())?;
        self.mesh(Some(at), false)?.solve_batch(at, out);
        Ok(())
    }

    /// [`Frame::drawn_heights`] on the current rayon thread pool; the same bits on any number
    /// of threads.
    ///
    /// # Errors
    ///
    /// As [`Frame::drawn_heights`].
    #[cfg(feature = "std")]
    pub fn drawn_heights_par(&self, at: &[DVec2], out: &mut [DrawnSample]) -> Result<(), WtbError> {
        check_batch(at, out.len())?;
        self.mesh(Some(at), true)?.solve_batch_par(at, out);
        Ok(())
    }

    /// The whole drawn mesh of this frame, every vertex evaluated (what [`Frame::evaluate`]
    /// writes, bit for bit), for many batches of drawn queries on one frame: each batch then
    /// only walks the mesh ([`DrawnMesh::heights`]). Building it costs about one evaluation of
    /// the grid and keeps its positions and normals (24 bytes a point).
    ///
    /// # Errors
    ///
    /// [`WtbError::Eval`] if the frame's layers do not fit its grid (a library bug).
    pub fn drawn_mesh(&self) -> Result<DrawnMesh, WtbError> {
        self.mesh(None, false)
    }

    /// [`Frame::drawn_mesh`] on the current rayon thread pool; the same mesh.
    ///
    /// # Errors
    ///
    /// As [`Frame::drawn_mesh`].
    #[cfg(feature = "std")]
    pub fn drawn_mesh_par(&self) -> Result<DrawnMesh, WtbError> {
        self.mesh(None, true)
    }

    /// Evaluates the tiles of vertices that the windows of `at` reach (every tile for `None`).
    fn mesh(&self, at: Option<&[DVec2]>, parallel: bool) -> Result<DrawnMesh, WtbError> {
        let (nx, nz) = (self.grid.nx(), self.grid.nz());
        let tiles = (nx.div_ceil(TILE), nz.div_ceil(TILE));
        let radius = self.displacement_bound() * self.inv_spacing + 1e-3;
        let origin = self.grid.origin();
        let mut wanted = vec![at.is_none(); tiles.0 * tiles.1];
        for p in at.unwrap_or_default() {
            let Some(w) = window(*p, origin, self.inv_spacing, radius, nx, nz) else {
                continue;
            };
            // Cells c0..=c1 read vertices c0..=c1 + 1.
            for tz in (w.j0 >> TILE_SHIFT)..=((w.j1 + 1) >> TILE_SHIFT) {
                wanted[tz * tiles.0 + (w.i0 >> TILE_SHIFT)
                    ..=tz * tiles.0 + ((w.i1 + 1) >> TILE_SHIFT)]
                    .fill(true);
            }
        }
        // The runs of wanted tiles along each tile row, in row-major order: one block
        // evaluation a run, straight into its storage, which costs what those points cost in a
        // whole-grid evaluation (row set-up is paid once a run, not once a tile).
        let mut runs: Vec<Run> = Vec::new();
        let mut count = 0usize;
        for (t, &w) in wanted.iter().enumerate() {
            if !w {
                continue;
            }
            let (tx, tz) = (t % tiles.0, t / tiles.0);
            match runs.last_mut() {
                Some(r) if r.tz == tz && r.tx0 + r.len == tx => r.len += 1,
                _ => runs.push(Run {
                    tz,
                    tx0: tx,
                    len: 1,
                    slot0: count,
                }),
            }
            count += 1;
        }
        // Each run's block is stored row-major with its own width: each tile's vertex (0, 0)
        // and row stride (at most 4096² points, so u32 holds them).
        let mut place = vec![[NONE, 0]; wanted.len()];
        let mut points = 0usize;
        for r in &runs {
            let b = r.block((nx, nz));
            for k in 0..r.len {
                place[r.tile(tiles.0) + k] = [(points + k * TILE) as u32, b.nx as u32];
            }
            points += b.len();
        }
        let layers = self.core_layers();
        let eval = LayersEvaluator::new(
            self.grid.grid(),
            self.time(),
            &layers,
            self.height.as_deref(),
        )
        .map_err(WtbError::Eval)?;
        let (mut pos, mut nrm) = (vec![Vec3::ZERO; points], vec![Vec3::ZERO; points]);
        let mut folds = vec![false; count];
        // Each run's share of the storage.
        let mut parts = Vec::with_capacity(runs.len());
        {
            let (mut p, mut n, mut f) = (&mut pos[..], &mut nrm[..], &mut folds[..]);
            for r in &runs {
                let len = r.block((nx, nz)).len();
                let (rp, tp) = core::mem::take(&mut p).split_at_mut(len);
                let (rn, tn) = core::mem::take(&mut n).split_at_mut(len);
                let (rf, tf) = core::mem::take(&mut f).split_at_mut(r.len);
                (p, n, f) = (tp, tn, tf);
                parts.push((*r, rp, rn, rf));
            }
        }
        let run = |(r, p, n, f): (Run, &mut [Vec3], &mut [Vec3], &mut [bool])| {
            evaluate_run(&eval, r, (nx, nz), p, n, f)
        };
        #[cfg(feature = "std")]
        if parallel {
            use rayon::prelude::*;
            parts
                .into_par_iter()
                .try_for_each(run)
                .map_err(WtbError::Eval)?;
        } else {
            parts
                .into_iter()
                .try_for_each(run)
                .map_err(WtbError::Eval)?;
        }
        #[cfg(not(feature = "std"))]
        {
            let _ = parallel;
            parts
                .into_iter()
                .try_for_each(run)
                .map_err(WtbError::Eval)?;
        }
        // Indexed by tile from here.
        let mut tile_folds = vec![false; wanted.len()];
        for r in &runs {
            let t = r.tile(tiles.0);
            tile_folds[t..t + r.len].copy_from_slice(&folds[r.slot0..r.slot0 + r.len]);
        }
        let mut mesh = DrawnMesh {
            origin,
            spacing: self.grid.spacing(),
            inv_spacing: self.inv_spacing,
            radius,
            nx,
            nz,
            tiles_x: tiles.0,
            place,
            pos,
            nrm,
            folds: tile_folds,
        };
        // The cells across a run's far edges, whose vertices other runs hold.
        for r in &runs {
            if mesh.run_edge_folds(r) {
                let t = r.tile(tiles.0);
                mesh.folds[t..t + r.len].fill(true);
            }
        }
        Ok(mesh)
    }
}

/// Consecutive wanted tiles along tile row `tz`: columns of tiles `tx0..tx0 + len`, the
/// `slot0`-th to the `slot0 + len`-th evaluated.
#[derive(Clone, Copy, Debug)]
struct Run {
    tz: usize,
    tx0: usize,
    len: usize,
    slot0: usize,
}

impl Run {
    /// Index of its first tile in a row-major array of tiles `tiles_x` wide.
    fn tile(&self, tiles_x: usize) -> usize {
        self.tz * tiles_x + self.tx0
    }

    /// The run's grid points, clipped to a grid of `size` points.
    fn block(&self, (nx, nz): (usize, usize)) -> GridRect {
        let (i0, j0) = (self.tx0 * TILE, self.tz * TILE);
        GridRect {
            i0,
            j0,
            nx: (self.len * TILE).min(nx - i0),
            nz: TILE.min(nz - j0),
        }
    }
}

/// Evaluates a run's block into its storage (row-major over the block) and flags the tiles
/// holding an inverted or degenerate triangle among the cells whose four vertices the block
/// holds.
fn evaluate_run(
    eval: &LayersEvaluator<'_>,
    run: Run,
    size: (usize, usize),
    pos: &mut [Vec3],
    nrm: &mut [Vec3],
    folds: &mut [bool],
) -> Result<(), ocean_core::EvalError> {
    let block = run.block(size);
    eval.evaluate_block(block, pos, nrm)?;
    let bp = &*pos;
    let w = block.nx;
    // The cells' orientations, a row pair and a tile at a time: the differences of the f32
    // corners taken in f64 (exact), the two triangles' signed areas, and one flag a tile.
    for r in 0..block.nz.saturating_sub(1) {
        let (row0, row1) = (&bp[r * w..(r + 1) * w], &bp[(r + 1) * w..(r + 2) * w]);
        for (t, fold) in folds.iter_mut().enumerate() {
            let (c0, c1) = (t * TILE, ((t + 1) * TILE).min(w - 1));
            let mut ok = true;
            for c in c0..c1 {
                let (a, b, d, e) = (row0[c], row0[c + 1], row1[c], row1[c + 1]);
                let f = |u: f32, v: f32| f64::from(u) - f64::from(v);
                // Lower (a, b, d) and upper (b, e, d).
                let lower = f(b.x, a.x) * f(d.z, a.z) - f(b.z, a.z) * f(d.x, a.x);
                let upper = f(e.x, b.x) * f(d.z, b.z) - f(e.z, b.z) * f(d.x, b.x);
                ok &= lower > 0.0 && upper > 0.0;
            }
            *fold |= !ok;
        }
    }
    Ok(())
}

/// Whether the triangle a, b, c winds counter-clockwise seen from above (its area in the
/// (x, z) plane is positive).
#[inline]
fn positive(a: DVec2, b: DVec2, c: DVec2) -> bool {
    cross2(b - a, c - a) > 0.0
}

/// The cells a query's triangle can be in: columns `i0..=i1`, rows `j0..=j1`.
#[derive(Clone, Copy, Debug)]
struct Window {
    i0: usize,
    i1: usize,
    j0: usize,
    j1: usize,
}

impl Window {
    fn contains(&self, i: i64, j: i64) -> bool {
        i >= self.i0 as i64 && i <= self.i1 as i64 && j >= self.j0 as i64 && j <= self.j1 as i64
    }
}

/// The cells whose rest squares come within `radius` grid units of `at`, clipped to the
/// grid's cells; `None` when there are none (the point is far off the grid).
fn window(
    at: DVec2,
    origin: DVec2,
    inv_spacing: f64,
    radius: f64,
    nx: usize,
    nz: usize,
) -> Option<Window> {
    let g = (at - origin) * inv_spacing;
    let (cx, cz) = ((nx - 1) as f64, (nz - 1) as f64);
    // Cell c covers [c, c + 1]; the window reaches [g − radius, g + radius].
    let (lo, hi) = (g - DVec2::splat(radius), g + DVec2::splat(radius));
    if !(hi.x >= 0.0 && hi.y >= 0.0 && lo.x <= cx && lo.y <= cz) {
        return None;
    }
    // Within the grid's cells here, so the conversions are in range.
    // Truncating a value ≥ 0 is its floor.
    let clamp = |v: f64, last: f64| v.max(0.0).min(last - 1.0) as usize;
    Some(Window {
        i0: clamp(lo.x, cx),
        i1: clamp(hi.x, cx),
        j0: clamp(lo.y, cz),
        j1: clamp(hi.y, cz),
    })
}

/// A frame's drawn mesh with its vertices evaluated ([`Frame::drawn_mesh`]; a batch of
/// [`Frame::drawn_heights`] builds one over the tiles it reaches): answers drawn queries by
/// walking it, without evaluating anything.
#[derive(Clone, Debug)]
pub struct DrawnMesh {
    origin: DVec2,
    spacing: f64,
    inv_spacing: f64,
    /// The window's radius, grid units.
    radius: f64,
    nx: usize,
    nz: usize,
    tiles_x: usize,
    /// Per tile (row-major): where its vertex (0, 0) lies in `pos`/`nrm` ([`NONE`] for a tile
    /// not evaluated), and the row stride (its run's width).
    place: Vec<[u32; 2]>,
    pos: Vec<Vec3>,
    nrm: Vec<Vec3>,
    /// Per tile: whether a triangle of a cell whose first vertex it holds is inverted or
    /// degenerate (the cells whose vertices are not all evaluated are not in any window and are
    /// skipped). A run's flags are set together where its far edges fold.
    folds: Vec<bool>,
}

/// A triangle of the mesh: its cell and half.
#[derive(Clone, Copy, Debug, PartialEq)]
struct Tri {
    i: i64,
    j: i64,
    upper: bool,
}

impl Tri {
    /// Its vertices in the order of [`DrawnTriangle::weights`].
    fn vertices(&self) -> [(i64, i64); 3] {
        let (i, j) = (self.i, self.j);
        if self.upper {
            [(i + 1, j), (i + 1, j + 1), (i, j + 1)]
        } else {
            [(i, j), (i + 1, j), (i, j + 1)]
        }
    }

    /// The triangle across the edge opposite vertex `k`.
    fn across(&self, k: usize) -> Tri {
        let (i, j) = (self.i, self.j);
        let (di, dj, upper) = match (self.upper, k) {
            // Lower: opposite (i, j) is the diagonal, shared with this cell's upper triangle;
            // opposite (i+1, j) the left edge; opposite (i, j+1) the bottom edge.
            (false, 0) => (0, 0, true),
            (false, 1) => (-1, 0, true),
            (false, _) => (0, -1, true),
            // Upper: opposite (i+1, j) the top edge; opposite (i+1, j+1) the diagonal;
            // opposite (i, j+1) the right edge.
            (true, 0) => (0, 1, false),
            (true, 1) => (0, 0, false),
            (true, _) => (1, 0, false),
        };
        Tri {
            i: i + di,
            j: j + dj,
            upper,
        }
    }
}

/// u × v in the horizontal plane, (x, z) as a right-handed pair seen from above.
#[inline]
fn cross2(u: DVec2, v: DVec2) -> f64 {
    u.x * v.y - u.y * v.x
}

impl DrawnMesh {
    /// Vertex (i, j), which must lie in an evaluated tile: position (relative to the grid's
    /// origin) and normal.
    #[inline]
    fn vertex(&self, i: usize, j: usize) -> (Vec3, Vec3) {
        let [first, stride] = self.place[(j >> TILE_SHIFT) * self.tiles_x + (i >> TILE_SHIFT)];
        debug_assert!(first != NONE);
        let k = first as usize + (j & (TILE - 1)) * stride as usize + (i & (TILE - 1));
        (self.pos[k], self.nrm[k])
    }

    fn has_vertex(&self, i: usize, j: usize) -> bool {
        i < self.nx
            && j < self.nz
            && self.place[(j >> TILE_SHIFT) * self.tiles_x + (i >> TILE_SHIFT)][0] != NONE
    }

    /// The horizontal corners of a triangle, relative to the grid's origin.
    #[inline]
    fn corners(&self, t: &Tri) -> [DVec2; 3] {
        t.vertices().map(|(i, j)| {
            let p = self.vertex(i as usize, j as usize).0;
            DVec2::new(f64::from(p.x), f64::from(p.z))
        })
    }

    /// Whether a cell across the far edges of a run's block (its last column and last row,
    /// whose other vertices lie in the next tiles) holds an inverted or degenerate triangle;
    /// cells whose vertices are not all evaluated are in no window and are skipped.
    fn run_edge_folds(&self, r: &Run) -> bool {
        let b = r.block((self.nx, self.nz));
        let (i_last, j_last) = (b.i0 + b.nx - 1, b.j0 + b.nz - 1);
        let edge = (b.i0..=i_last)
            .map(|i| (i, j_last))
            .chain((b.j0..j_last).map(|j| (i_last, j)));
        for (i, j) in edge {
            let present = i + 1 < self.nx
                && j + 1 < self.nz
                && self.has_vertex(i + 1, j)
                && self.has_vertex(i, j + 1)
                && self.has_vertex(i + 1, j + 1);
            if !present {
                continue;
            }
            for upper in [false, true] {
                let c = self.corners(&Tri {
                    i: i as i64,
                    j: j as i64,
                    upper,
                });
                if !positive(c[0], c[1], c[2]) {
                    return true;
                }
            }
        }
        false
    }

    /// [`Frame::drawn_height_at`] on this mesh.
    ///
    /// # Errors
    ///
    /// [`WtbError::NotFinite`] for a non-finite position.
    pub fn height_at(&self, at: DVec2) -> Result<DrawnSample, WtbError> {
        check_batch(&[at], 1)?;
        Ok(self.solve(at))
    }

    /// [`Frame::drawn_heights`] on this mesh: the same answers, bit for bit.
    ///
    /// # Errors
    ///
    /// As [`Frame::drawn_heights`].
    pub fn heights(&self, at: &[DVec2], out: &mut [DrawnSample]) -> Result<(), WtbError> {
        check_batch(at, out.len())?;
        self.solve_batch(at, out);
        Ok(())
    }

    /// [`DrawnMesh::heights`] on the current rayon thread pool; the same bits on any number of
    /// threads.
    ///
    /// # Errors
    ///
    /// As [`Frame::drawn_heights`].
    #[cfg(feature = "std")]
    pub fn heights_par(&self, at: &[DVec2], out: &mut [DrawnSample]) -> Result<(), WtbError> {
        check_batch(at, out.len())?;
        self.solve_batch_par(at, out);
        Ok(())
    }

    /// Answers `at` into `out`: in grid order for a batch of 256 or more, each answer written
    /// straight to its query's place.
    fn solve_batch(&self, at: &[DVec2], out: &mut [DrawnSample]) {
        if !sorted_batch(at.len()) {
            for (o, p) in out.iter_mut().zip(at) {
                *o = self.solve(*p);
            }
            return;
        }
        let size = (self.nx, self.nz);
        let cells: Vec<[u32; 2]> = at
            .iter()
            .map(|p| nearest_point(self.origin, self.inv_spacing, size, *p))
            .collect();
        for q in grid_order(&cells, self.nx, self.nz) {
            out[q as usize] = self.solve(at[q as usize]);
        }
    }

    /// [`DrawnMesh::solve_batch`] over the rayon pool: each task answers a share of the batch
    /// in its own grid order, straight into its share of `out` (no batch-sized buffer of
    /// answers: fresh memory costs more than the walks on the machines measured).
    #[cfg(feature = "std")]
    fn solve_batch_par(&self, at: &[DVec2], out: &mut [DrawnSample]) {
        use rayon::prelude::*;
        let share = at
            .len()
            .div_ceil(rayon::current_num_threads())
            .max(QUERY_SORT_MIN);
        at.par_chunks(share)
            .zip(out.par_chunks_mut(share))
            .for_each(|(at, out)| self.solve_batch(at, out));
    }

    /// The drawn surface over `at`.
    fn solve(&self, at: DVec2) -> DrawnSample {
        let Some(w) = window(
            at,
            self.origin,
            self.inv_spacing,
            self.radius,
            self.nx,
            self.nz,
        ) else {
            return DrawnSample::rest(at);
        };
        let q = at - self.origin;
        let folds = ((w.j0 >> TILE_SHIFT)..=((w.j1 + 1) >> TILE_SHIFT)).any(|tz| {
            ((w.i0 >> TILE_SHIFT)..=((w.i1 + 1) >> TILE_SHIFT))
                .any(|tx| self.folds[tz * self.tiles_x + tx])
        });
        if !folds && let Some(s) = self.walk(q, &w) {
            return self.sample(s.0, s.1);
        }
        match self.highest(q, &w) {
            Some((t, b)) => self.sample(t, b),
            None => DrawnSample::rest(at),
        }
    }

    /// The rest cell holding grid coordinates `g`, clamped into the window.
    fn cell_in(&self, g: DVec2, w: &Window) -> (usize, usize) {
        // max then min (a NaN gives `lo`); truncating a value ≥ 0 is its floor.
        let c = |v: f64, lo: usize, hi: usize| v.max(lo as f64).min(hi as f64) as usize;
        (c(g.x, w.i0, w.i1), c(g.y, w.j0, w.j1))
    }

    /// Walks from a guessed triangle to the one over `q` (metres from the grid's origin);
    /// `None` if the walk leaves the window or runs too long.
    fn walk(&self, q: DVec2, w: &Window) -> Option<(Tri, [f64; 3])> {
        // One fixed-point step on g = (q − d(g))/s, with d the displacement bilinear over the
        // cell under the query, starts the walk on the answer's triangle for at least 96 % of random
        // queries on the paper's scenario 1 (1.04 triangles visited on average; a second step
        // gives 1.004 for four more vertex reads, none 1.8).
        let mut g = q * self.inv_spacing;
        {
            let (i, j) = self.cell_in(g, w);
            let f = g - DVec2::new(i as f64, j as f64);
            let d = |i: usize, j: usize| {
                let p = self.vertex(i, j).0;
                DVec2::new(f64::from(p.x), f64::from(p.z))
                    - DVec2::new(i as f64, j as f64) * self.spacing
            };
            let (a, b, c, e) = (d(i, j), d(i + 1, j), d(i, j + 1), d(i + 1, j + 1));
            let disp =
                (a * (1.0 - f.x) + b * f.x) * (1.0 - f.y) + (c * (1.0 - f.x) + e * f.x) * f.y;
            g = (q - disp) * self.inv_spacing;
        }
        let (i, j) = self.cell_in(g, w);
        let f = g - DVec2::new(i as f64, j as f64);
        let mut t = Tri {
            i: i as i64,
            j: j as i64,
            upper: f.x + f.y > 1.0,
        };
        for _ in 0..MAX_WALK {
            let c = self.corners(&t);
            let b = weights(&c, q)?;
            let (k, min) =
                b.iter().enumerate().fold(
                    (0, f64::INFINITY),
                    |m, (k, &v)| if v < m.1 { (k, v) } else { m },
                );
            if min >= EDGE {
                return Some((t, b));
            }
            t = t.across(k);
            if !w.contains(t.i, t.j) {
                return None;
            }
        }
        None
    }

    /// The highest triangle of the window over `q`, testing each (the first of equal heights
    /// in row-major order).
    fn highest(&self, q: DVec2, w: &Window) -> Option<(Tri, [f64; 3])> {
        let mut best: Option<(Tri, [f64; 3], f64)> = None;
        for j in w.j0..=w.j1 {
            for i in w.i0..=w.i1 {
                for upper in [false, true] {
                    let t = Tri {
                        i: i as i64,
                        j: j as i64,
                        upper,
                    };
                    let Some(b) = weights(&self.corners(&t), q) else {
                        continue;
                    };
                    if b.iter().any(|&v| v < EDGE) {
                        continue;
                    }
                    let h = self.height(&t, &b);
                    if best.is_none_or(|(_, _, top)| h > top) {
                        best = Some((t, b, h));
                    }
                }
            }
        }
        best.map(|(t, b, _)| (t, b))
    }

    fn height(&self, t: &Tri, b: &[f64; 3]) -> f64 {
        let v = t.vertices();
        (0..3)
            .map(|k| b[k] * f64::from(self.vertex(v[k].0 as usize, v[k].1 as usize).0.y))
            .sum()
    }

    /// The answer on triangle `t` with weights `b`.
    fn sample(&self, t: Tri, b: [f64; 3]) -> DrawnSample {
        let v = t.vertices();
        let (mut p, mut n) = ([DVec3::ZERO; 3], DVec3::ZERO);
        let mut rest = DVec2::ZERO;
        for k in 0..3 {
            let (pk, nk) = self.vertex(v[k].0 as usize, v[k].1 as usize);
            p[k] = pk.as_dvec3();
            n += b[k] * nk.as_dvec3();
            rest += b[k] * DVec2::new(v[k].0 as f64, v[k].1 as f64);
        }
        // (p₂ − p₀) × (p₁ − p₀) points up on a triangle wound counter-clockwise from above.
        let mut face = (p[2] - p[0]).cross(p[1] - p[0]);
        if face.y < 0.0 {
            face = -face;
        }
        let face = face.try_normalize().unwrap_or(DVec3::Y);
        DrawnSample {
            height: (0..3).map(|k| b[k] * p[k].y).sum(),
            normal: face,
            shading_normal: n.try_normalize().unwrap_or(DVec3::Y),
            rest: self.origin + rest * self.spacing,
            triangle: Some(DrawnTriangle {
                cell: [t.i as u32, t.j as u32],
                upper: t.upper,
                weights: b,
            }),
        }
    }
}

/// Barycentric weights of `q` on the triangle with horizontal corners `c`; `None` for a
/// degenerate triangle. On an inverted triangle the weights are those of the mirrored one, so
/// a point over it still has all three in [0, 1].
#[inline]
fn weights(c: &[DVec2; 3], q: DVec2) -> Option<[f64; 3]> {
    let area = cross2(c[1] - c[0], c[2] - c[0]);
    if area == 0.0 || !area.is_finite() {
        return None;
    }
    let (a, b, d) = (c[0] - q, c[1] - q, c[2] - q);
    let inv = 1.0 / area;
    Some([cross2(b, d) * inv, cross2(d, a) * inv, cross2(a, b) * inv])
}
