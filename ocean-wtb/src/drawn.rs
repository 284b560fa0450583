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
//! guesses the rest cell by two fixed-point steps on the vertices' displacement, then walks
//! from triangle to triangle across the edge the point lies beyond, which ends at the one
//! triangle over the point wherever the mesh does not fold. Where any triangle of the window is
//! inverted or degenerate (the mesh folds: a crest past the trochoid's limit, Σ k·A·|μ| > 1),
//! or the walk leaves the window, every triangle of the window is tested and the **highest**
//! over the point is the answer: the surface seen from above.
//!
//! Outside the mesh (beyond the grid, or past a grid edge that the waves pull inwards) no
//! triangle lies over the point and the water is at rest there, as it is everywhere beyond
//! the grid: height 0, normal +y, [`DrawnSample::triangle`] `None`.

// Lane-free code, but the triangle tables index several arrays in step.
#![allow(clippy::needless_range_loop)]

use alloc::vec;
use alloc::vec::Vec;

use glam::{DVec2, DVec3, Vec3};
use ocean_core::{GridRect, LayersEvaluator};

use crate::batch::{check_batch, grid_order, scatter, sorted_batch};
use crate::error::WtbError;
use crate::scene::Frame;

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

/// No tile evaluated in this slot.
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
    /// more is then answered in grid order, as [`Frame::continuous_heights`] is.
    ///
    /// # Errors
    ///
    /// [`WtbError::Eval`] when `out` is not as long as `at`; [`WtbError::NotFinite`] for a
    /// non-finite position. Nothing is written on error.
    pub fn drawn_heights(&self, at: &[DVec2], out: &mut [DrawnSample]) -> Result<(), WtbError> {
        check_batch(at, out.len())?;
        let mesh = self.mesh(at, false)?;
        if !sorted_batch(at.len()) {
            for (o, p) in out.iter_mut().zip(at) {
                *o = mesh.solve(*p);
            }
            return Ok(());
        }
        let cells: Vec<[u32; 2]> = at.iter().map(|p| self.query_cell(*p)).collect();
        let order = grid_order(&cells, self.grid.nx(), self.grid.nz());
        let sorted: Vec<DrawnSample> = order.iter().map(|&q| mesh.solve(at[q as usize])).collect();
        scatter(&order, sorted, out);
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
        use rayon::prelude::*;
        check_batch(at, out.len())?;
        let mesh = self.mesh(at, true)?;
        if !sorted_batch(at.len()) {
            out.iter_mut()
                .zip(at)
                .for_each(|(o, p)| *o = mesh.solve(*p));
            return Ok(());
        }
        let cells: Vec<[u32; 2]> = at.par_iter().map(|p| self.query_cell(*p)).collect();
        let order = grid_order(&cells, self.grid.nx(), self.grid.nz());
        let sorted: Vec<DrawnSample> = order
            .par_iter()
            .map(|&q| mesh.solve(at[q as usize]))
            .collect();
        let mut rank = vec![0u32; order.len()];
        for (r, &q) in order.iter().enumerate() {
            rank[q as usize] = r as u32;
        }
        out.par_iter_mut()
            .zip(rank.par_iter())
            .for_each(|(o, r)| *o = sorted[*r as usize]);
        Ok(())
    }

    /// Evaluates the tiles of vertices that the windows of `at` reach.
    fn mesh(&self, at: &[DVec2], parallel: bool) -> Result<Mesh, WtbError> {
        let (nx, nz) = (self.grid.nx(), self.grid.nz());
        let tiles = (nx.div_ceil(TILE), nz.div_ceil(TILE));
        let radius = self.displacement_bound() * self.inv_spacing + 1e-3;
        let origin = self.grid.origin();
        let mut slot = vec![NONE; tiles.0 * tiles.1];
        let mut wanted = Vec::new();
        for p in at {
            let Some(w) = window(*p, origin, self.inv_spacing, radius, nx, nz) else {
                continue;
            };
            // Cells c0..=c1 read vertices c0..=c1 + 1.
            for tz in (w.j0 >> TILE_SHIFT)..=((w.j1 + 1) >> TILE_SHIFT) {
                for tx in (w.i0 >> TILE_SHIFT)..=((w.i1 + 1) >> TILE_SHIFT) {
                    let s = &mut slot[tz * tiles.0 + tx];
                    if *s == NONE {
                        *s = wanted.len() as u32;
                        wanted.push((tx, tz));
                    }
                }
            }
        }
        let layers = self.core_layers();
        let eval = LayersEvaluator::new(
            self.grid.grid(),
            self.time(),
            &layers,
            self.height.as_deref(),
        )
        .map_err(WtbError::Eval)?;
        let per = TILE * TILE;
        let mut pos = vec![Vec3::ZERO; wanted.len() * per];
        let mut nrm = vec![Vec3::ZERO; wanted.len() * per];
        let tile = |(tx, tz): (usize, usize), p: &mut [Vec3], n: &mut [Vec3]| {
            let block = GridRect {
                i0: tx * TILE,
                j0: tz * TILE,
                nx: TILE.min(nx - tx * TILE),
                nz: TILE.min(nz - tz * TILE),
            };
            // Stored with a row stride of TILE whatever the block's width.
            let (mut bp, mut bn) = (vec![Vec3::ZERO; block.len()], vec![Vec3::ZERO; block.len()]);
            eval.evaluate_block(block, &mut bp, &mut bn)?;
            for r in 0..block.nz {
                let (src, dst) = (
                    r * block.nx..(r + 1) * block.nx,
                    r * TILE..r * TILE + block.nx,
                );
                p[dst.clone()].copy_from_slice(&bp[src.clone()]);
                n[dst].copy_from_slice(&bn[src]);
            }
            Ok::<(), ocean_core::EvalError>(())
        };
        #[cfg(feature = "std")]
        if parallel {
            use rayon::prelude::*;
            pos.par_chunks_mut(per)
                .zip(nrm.par_chunks_mut(per))
                .zip(wanted.par_iter())
                .try_for_each(|((p, n), &t)| tile(t, p, n))
                .map_err(WtbError::Eval)?;
        }
        let _ = parallel;
        if !cfg!(feature = "std") || !parallel {
            for ((p, n), &t) in pos.chunks_mut(per).zip(nrm.chunks_mut(per)).zip(&wanted) {
                tile(t, p, n).map_err(WtbError::Eval)?;
            }
        }
        let mut mesh = Mesh {
            origin,
            spacing: self.grid.spacing(),
            inv_spacing: self.inv_spacing,
            radius,
            nx,
            nz,
            tiles_x: tiles.0,
            slot,
            pos,
            nrm,
            folds: vec![false; wanted.len()],
        };
        mesh.folds = wanted
            .iter()
            .map(|&(tx, tz)| mesh.tile_folds(tx, tz))
            .collect();
        Ok(mesh)
    }
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
    let clamp = |v: f64, last: f64| v.floor().clamp(0.0, last - 1.0) as usize;
    Some(Window {
        i0: clamp(lo.x, cx),
        i1: clamp(hi.x, cx),
        j0: clamp(lo.y, cz),
        j1: clamp(hi.y, cz),
    })
}

/// The vertices of the tiles a batch reaches.
struct Mesh {
    origin: DVec2,
    spacing: f64,
    inv_spacing: f64,
    /// The window's radius, grid units.
    radius: f64,
    nx: usize,
    nz: usize,
    tiles_x: usize,
    /// Per tile (row-major), its index in `pos`/`nrm`/`folds`, or [`NONE`].
    slot: Vec<u32>,
    pos: Vec<Vec3>,
    nrm: Vec<Vec3>,
    /// Per evaluated tile: whether a triangle of a cell whose first vertex it holds is
    /// inverted or degenerate (the cells whose vertices are not all evaluated are not in any
    /// window and are skipped).
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

impl Mesh {
    /// Vertex (i, j), which must lie in an evaluated tile: position (relative to the grid's
    /// origin) and normal.
    #[inline]
    fn vertex(&self, i: usize, j: usize) -> (Vec3, Vec3) {
        let t = self.slot[(j >> TILE_SHIFT) * self.tiles_x + (i >> TILE_SHIFT)];
        debug_assert!(t != NONE);
        let k = t as usize * TILE * TILE + (j & (TILE - 1)) * TILE + (i & (TILE - 1));
        (self.pos[k], self.nrm[k])
    }

    fn has_vertex(&self, i: usize, j: usize) -> bool {
        i < self.nx
            && j < self.nz
            && self.slot[(j >> TILE_SHIFT) * self.tiles_x + (i >> TILE_SHIFT)] != NONE
    }

    /// The horizontal corners of a triangle, relative to the grid's origin.
    #[inline]
    fn corners(&self, t: &Tri) -> [DVec2; 3] {
        t.vertices().map(|(i, j)| {
            let p = self.vertex(i as usize, j as usize).0;
            DVec2::new(f64::from(p.x), f64::from(p.z))
        })
    }

    /// Whether a triangle of a cell whose first vertex lies in tile (tx, tz) is inverted or
    /// degenerate.
    fn tile_folds(&self, tx: usize, tz: usize) -> bool {
        let (i0, j0) = (tx * TILE, tz * TILE);
        for j in j0..(j0 + TILE).min(self.nz - 1) {
            for i in i0..(i0 + TILE).min(self.nx - 1) {
                let present = self.has_vertex(i + 1, j)
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
                    if cross2(c[1] - c[0], c[2] - c[0]) <= 0.0 {
                        return true;
                    }
                }
            }
        }
        false
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
                .any(|tx| self.folds[self.slot[tz * self.tiles_x + tx] as usize])
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
        let c = |v: f64, lo: usize, hi: usize| {
            if v.is_nan() {
                lo
            } else {
                (v.floor().clamp(lo as f64, hi as f64)) as usize
            }
        };
        (c(g.x, w.i0, w.i1), c(g.y, w.j0, w.j1))
    }

    /// Walks from a guessed triangle to the one over `q` (metres from the grid's origin);
    /// `None` if the walk leaves the window or runs too long.
    fn walk(&self, q: DVec2, w: &Window) -> Option<(Tri, [f64; 3])> {
        // Two fixed-point steps on g = (q − d(g))/s, with d the displacement bilinear over
        // the guessed cell, put the guess within a triangle or two of the answer.
        let mut g = q * self.inv_spacing;
        for _ in 0..2 {
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
    Some([
        cross2(b, d) / area,
        cross2(d, a) / area,
        cross2(a, b) / area,
    ])
}
