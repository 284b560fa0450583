//! Cone maps: per texel the plain cone ratio in the book's units (texture widths of horizontal
//! reach per unit of depth, §18.4.1: "width/height ratio"), and two channels that let rays close
//! to the surface step farther, all valid for the bilinear tracer.
//!
//! Generation ([`ConeMap::generate`]) bounds the cone of every cell ([`crate::bound`]) and gives
//! texel `k` the smallest value of the four cells that share its centre: the tracer blends four
//! texels with convex weights at any point of a cell, and each of those texels holds at most the
//! cell's value, so the blend is valid wherever it is read. With nearest sampling the same map is
//! valid too (the nearest texel's four cells contain the sample point). Values are computed in
//! `f64`, rounded **down** to `f32`, and capped at [`ConeParams::max_ratio`] (the book clamps at
//! 1.0 to store the ratio in 8 bits; a larger cap keeps wider cones for float storage,
//! [`crate::storage`]).
//!
//! ## Clearance `D` and near cap `E`
//!
//! Cone stepping creeps towards the surface at grazing angles: a step covers the fraction
//! `c/(ρ + c)` of the height `h` above the surface, so a ray skimming a floor with `ρ ≫ c` never
//! reaches it in a few steps. But a ray that passes the apex's axis `h` above the surface (at
//! depth `z₀ = S(p) − h`) goes down, so it can only leave the solid at depths `≥ z₀`. Redoing
//! the proof of [`crate::bound`] while keeping the exit's depth `z_b ≥ z₀`: for the exit's cell
//! `C`, `s/(S(p) − z_b) ≥ dist(q, C)/min(Smax(q) − m_C, h)` and `≥ B`, so the cone valid for
//! that ray is at least `c(h) = min over candidates of max(dist_C/min(Smax(q) − m_C, h), B_C)`,
//! which equals `min over candidates of max(dist_C/h, v_C)` with `v_C = max(A, B)` the cell's
//! plain value. Two numbers per texel bound it from below: split the candidates into **near**
//! ones (cell distance below one texel) and **far** ones, let `E` be the smallest `v_C` of the
//! near ones and `D` the smallest distance of the far ones. Every candidate has `v_C ≥ E` or
//! `dist_C ≥ D`, so `max(dist_C/h, v_C) ≥ min(D/h, E)`, and
//!
//! `c(h) ≥ max(c, min(D/h, E))`.
//!
//! As `h → 0` over open ground this grows like `D/h` and the ray lands on the surface in a step or
//! two. The tracer's step for it needs no division by `h` ([`crate::trace::step_length`]).
//! Texels take the minimum over their four cells for `D` and `E` too (the bound only grows with
//! each); both are capped like the ratio, `D` in texture widths and `E` per unit depth. A cell
//! whose plain cone `c` is the cap stores the cap in `D` and `E`: every limit there is at least
//! the cap, which `min(D/h, E) ≤ E` never exceeds, so the tracer's cone stays valid, and the
//! search for them is skipped (`search.rs`). Validity
//! holds up to the rounding of the tracer's `f32` height and step.

use alloc::vec;
use alloc::vec::Vec;

use crate::bound::{ConeKind, Grid};
use crate::map::{Edge, HeightMap};
use crate::progress::{NoProgress, Progress, band_rows};
use crate::quadrant::Quadrant;
use crate::round::down32;
use crate::search::{CHANNELS, Pyramid, Scratch, Search};
use crate::{ReliefError, brute, check_range, for_rows};

/// Largest [`ConeParams::max_ratio`] accepted: a cone that reaches 64 texture widths per unit
/// depth already crosses the whole tile in one step at any view angle.
pub const MAX_RATIO_LIMIT: f32 = 64.0;

/// Largest side the brute-force oracle accepts: it is `Θ(N⁴)` (about a second at 64²).
pub const MAX_BRUTE_SIDE: usize = 128;

/// Which cones, capped where.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ConeParams {
    /// Relaxed (default) or conservative.
    pub kind: ConeKind,
    /// Cap on the ratios, in texture widths per unit depth, in `(0, MAX_RATIO_LIMIT]`, and on the
    /// clearance, in texture widths. The book clamps at 1.0 (default) for 8-bit storage.
    pub max_ratio: f32,
    /// How finely the plain cone is bounded: the apex cell and each candidate cell are halved
    /// this many times in turn (`refine.rs`), at most [`MAX_PARTS`]. 0 is the bound of whole
    /// cells (`bound.rs`), the one the GPU generator computes; the default, 2, bounds half
    /// cells against half cells: on the family of `maps::family` at 64², 0.883 of the widest
    /// valid cone on average against 0.826, at about twice the time. 4 gives 0.912 at three to
    /// five times the time of 0 (`BENCHMARKS.md`). Every setting is valid.
    pub parts: u32,
}

impl Default for ConeParams {
    fn default() -> Self {
        Self {
            kind: ConeKind::Relaxed,
            max_ratio: 1.0,
            parts: DEFAULT_PARTS,
        }
    }
}

/// Largest [`ConeParams::parts`]: 8 halvings make apex and candidate parts `1/16` of a cell on
/// a side.
pub const MAX_PARTS: u32 = 8;

/// The default [`ConeParams::parts`].
pub const DEFAULT_PARTS: u32 = 2;

impl ConeParams {
    /// Relaxed cones capped at `max_ratio`.
    pub fn relaxed(max_ratio: f32) -> Self {
        Self {
            kind: ConeKind::Relaxed,
            max_ratio,
            parts: DEFAULT_PARTS,
        }
    }

    /// Conservative cones capped at `max_ratio`.
    pub fn conservative(max_ratio: f32) -> Self {
        Self {
            kind: ConeKind::Conservative,
            max_ratio,
            parts: DEFAULT_PARTS,
        }
    }

    /// The same cones bounded over parts halved `parts` times ([`ConeParams::parts`]).
    pub fn with_parts(mut self, parts: u32) -> Self {
        self.parts = parts;
        self
    }

    fn validate(&self) -> Result<(), ReliefError> {
        check_range(
            "max_ratio",
            f64::from(self.max_ratio),
            f64::MIN_POSITIVE,
            f64::from(MAX_RATIO_LIMIT),
        )?;
        check_range("parts", f64::from(self.parts), 0.0, f64::from(MAX_PARTS))
    }
}

/// Per texel, row-major, in texture widths: the plain cone ratio `c` (per unit depth), the
/// clearance `D` and the near cap `E` (per unit depth) (see the module documentation).
#[derive(Clone, Debug, PartialEq)]
pub struct ConeMap {
    size: usize,
    edge: Edge,
    channels: [Vec<f32>; CHANNELS],
}

impl ConeMap {
    /// Relaxed or conservative cones of `map` by branch-and-bound (`search.rs`); rows in
    /// parallel with `std`, the same bits for any thread count.
    ///
    /// # Errors
    ///
    /// [`ReliefError::OutOfRange`] / [`ReliefError::NotFinite`] for `max_ratio`.
    pub fn generate(map: &HeightMap, params: ConeParams) -> Result<Self, ReliefError> {
        Self::generate_in_bands(map, params, None::<&mut NoProgress>)
    }

    /// [`ConeMap::generate`] with progress reports and cancellation ([`crate::progress`]).
    ///
    /// The unit of work is a row of bilinear cells: `total` is `N` in wrap mode and `N + 1` in
    /// clamp mode. `progress` is called on the calling thread, once with `done = 0` before any
    /// work and then after each band of rows (at most [`crate::progress::BANDS`] bands), the last
    /// call with `done = total`. The result is bit-identical to [`ConeMap::generate`]'s.
    ///
    /// # Errors
    ///
    /// As [`ConeMap::generate`] (checked before the first report); [`ReliefError::Cancelled`]
    /// when `progress` returns `false`, at any call, the last one included.
    pub fn generate_with<P: Progress + ?Sized>(
        map: &HeightMap,
        params: ConeParams,
        progress: &mut P,
    ) -> Result<Self, ReliefError> {
        Self::generate_in_bands(map, params, Some(progress))
    }

    /// The generator: all rows in one parallel loop without `progress`, else in bands with a
    /// report after each.
    fn generate_in_bands<P: Progress + ?Sized>(
        map: &HeightMap,
        params: ConeParams,
        progress: Option<&mut P>,
    ) -> Result<Self, ReliefError> {
        Self::generate_sector(map, params, None, progress, crate::progress::BANDS)
    }

    /// The generator for the cones that serve every direction (`sector = None`) or only the
    /// rays whose horizontal direction lies in one closed quadrant ([`crate::quad`]); with
    /// `progress`, the rows in at most `bands` bands.
    pub(crate) fn generate_sector<P: Progress + ?Sized>(
        map: &HeightMap,
        params: ConeParams,
        sector: Option<Quadrant>,
        mut progress: Option<&mut P>,
        bands: usize,
    ) -> Result<Self, ReliefError> {
        params.validate()?;
        let grid = Grid::new(map);
        let pyramid = Pyramid::new(&grid, params.kind);
        let search = Search {
            grid: &grid,
            pyramid: &pyramid,
            kind: params.kind,
            cap: f64::from(params.max_ratio) * grid.n as f64,
            parts: params.parts,
        };
        let rows = grid.nc;
        let mut cells = vec![[0.0f32; CHANNELS]; grid.nc * grid.nc];
        let band = match progress {
            Some(_) => band_rows(rows, bands),
            None => rows,
        };
        let mut report = |done: usize| match progress.as_mut() {
            Some(p) => {
                if p.report(done, rows) {
                    Ok(())
                } else {
                    Err(ReliefError::Cancelled)
                }
            }
            None => Ok(()),
        };
        report(0)?;
        for (b, chunk) in cells.chunks_mut(band * grid.nc).enumerate() {
            let first = b * band;
            for_rows(chunk, grid.nc, |y, row| {
                let mut scratch = Scratch::default();
                let mut seeds = [None; CHANNELS];
                let qj = grid.origin + (first + y) as i64;
                for (x, out) in row.iter_mut().enumerate() {
                    let q = grid.apex(grid.origin + x as i64, qj);
                    let q = match sector {
                        Some(s) => q.within(s),
                        None => q,
                    };
                    let best = search.cell_cone(&q, &seeds, &mut scratch);
                    *out = Self::texture_units(&grid, best.value);
                    for (s, c) in seeds.iter_mut().zip(best.cell) {
                        *s = c.or(*s);
                    }
                }
            });
            report(first + chunk.len() / grid.nc)?;
        }
        Ok(Self::from_cells(&grid, &cells))
    }

    /// The same cones by visiting every pair of cells (`brute.rs`): the oracle of
    /// [`ConeMap::generate`], for maps up to [`MAX_BRUTE_SIDE`].
    ///
    /// # Errors
    ///
    /// [`ReliefError::MapSize`] above [`MAX_BRUTE_SIDE`]; the parameters as in `generate`.
    pub fn brute_force(map: &HeightMap, params: ConeParams) -> Result<Self, ReliefError> {
        Self::brute_force_sector(map, params, None)
    }

    /// [`ConeMap::brute_force`] for the cones of one quadrant, or of every direction.
    pub(crate) fn brute_force_sector(
        map: &HeightMap,
        params: ConeParams,
        sector: Option<Quadrant>,
    ) -> Result<Self, ReliefError> {
        params.validate()?;
        crate::map::check_size(map.size(), map.size(), 2, MAX_BRUTE_SIDE)?;
        let grid = Grid::new(map);
        let mut cells = vec![[0.0f32; CHANNELS]; grid.nc * grid.nc];
        for_rows(&mut cells, grid.nc, |y, row| {
            for (x, out) in row.iter_mut().enumerate() {
                let (qi, qj) = (grid.origin + x as i64, grid.origin + y as i64);
                *out = Self::texture_units(&grid, brute::cell_cone(&grid, qi, qj, sector, params));
            }
        });
        Ok(Self::from_cells(&grid, &cells))
    }

    /// A cell's values in the map's units: divided by `N`, rounded down to `f32`. Kept per cell
    /// in `f32` (12 bytes, not 24): both steps are monotone, so the texels' minima over these
    /// are the rounded minima of the `f64` values, bit for bit.
    fn texture_units(grid: &Grid<'_>, v: [f64; CHANNELS]) -> [f32; CHANNELS] {
        v.map(|a| down32(a / grid.n as f64))
    }

    /// Texel `k` takes the smallest of its four cells (already in texture units).
    fn from_cells(grid: &Grid<'_>, cells: &[[f32; CHANNELS]]) -> Self {
        let n = grid.n;
        let mut channels: [Vec<f32>; CHANNELS] = core::array::from_fn(|_| vec![0.0f32; n * n]);
        for k in 0..n * n {
            let (i, j) = ((k % n) as i64, (k / n) as i64);
            let mut v = [f32::INFINITY; CHANNELS];
            // The cells whose corner is texel (i, j) sit at spatial positions i − 1 and i.
            for cj in [j - 1, j] {
                for ci in [i - 1, i] {
                    if let Some(c) = grid.index(ci, cj) {
                        for (a, b) in v.iter_mut().zip(cells[c]) {
                            *a = a.min(b);
                        }
                    }
                }
            }
            for (ch, a) in channels.iter_mut().zip(v) {
                ch[k] = a;
            }
        }
        Self {
            size: n,
            edge: grid.edge,
            channels,
        }
    }

    /// A cone map with only the plain cone (clearance and near cap 0, so the tracers take the
    /// book's step alone) from raw ratios, for example decoded from storage, checked: finite and
    /// non-negative.
    ///
    /// # Errors
    ///
    /// [`ReliefError::MapSize`], [`ReliefError::NotSquare`], [`ReliefError::BufferSize`],
    /// [`ReliefError::NotFinite`] / [`ReliefError::OutOfRange`] for a bad ratio.
    pub fn from_ratios(size: usize, edge: Edge, ratios: Vec<f32>) -> Result<Self, ReliefError> {
        crate::map::check_size(size, size, 1, crate::MAX_SIDE)?;
        crate::map::check_len("ratios", size * size, ratios.len())?;
        for &r in &ratios {
            check_range("cone ratio", f64::from(r), 0.0, f64::from(f32::MAX))?;
        }
        let zeros = vec![0.0; ratios.len()];
        Ok(Self {
            size,
            edge,
            channels: [ratios, zeros.clone(), zeros],
        })
    }

    /// A cone map from its three channels ([`ConeMap::ratios`], [`ConeMap::clearance`],
    /// [`ConeMap::near_cap`]), checked: finite and non-negative.
    ///
    /// # Errors
    ///
    /// As [`ConeMap::from_ratios`], for each channel.
    pub fn from_channels(
        size: usize,
        edge: Edge,
        ratios: Vec<f32>,
        clearance: Vec<f32>,
        near_cap: Vec<f32>,
    ) -> Result<Self, ReliefError> {
        crate::map::check_size(size, size, 1, crate::MAX_SIDE)?;
        for (name, v) in [
            ("ratios", &ratios),
            ("clearance", &clearance),
            ("near_cap", &near_cap),
        ] {
            crate::map::check_len(name, size * size, v.len())?;
            for &r in v.iter() {
                check_range(name, f64::from(r), 0.0, f64::from(f32::MAX))?;
            }
        }
        Ok(Self {
            size,
            edge,
            channels: [ratios, clearance, near_cap],
        })
    }

    /// Side in texels.
    pub fn size(&self) -> usize {
        self.size
    }

    /// The edge mode of the height map the cones were made for.
    pub fn edge(&self) -> Edge {
        self.edge
    }

    /// Clearances `D`, texture widths: every far candidate lies at least this far from the
    /// texel's cells (the cap for a cell whose plain cone is the cap).
    pub fn clearance(&self) -> &[f32] {
        &self.channels[1]
    }

    /// Near caps `E`, texture widths per unit depth: the smallest bound of the near candidates.
    /// A ray `h` above the surface may use the cone `max(c, min(D/h, E))`.
    pub fn near_cap(&self) -> &[f32] {
        &self.channels[2]
    }

    /// The plain cone ratios (the book's cone map), row-major, texture widths per unit depth.
    pub fn ratios(&self) -> &[f32] {
        &self.channels[0]
    }
}
