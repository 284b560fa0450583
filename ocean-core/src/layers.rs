//! Sums of modulated wave sets on a grid: the evaluation primitive of wave train boxes.
//!
//! A [`Layer`] is a wave set whose contribution at each point of a grid rectangle is multiplied
//! by a complex amplitude μ = m·e^{iφ}, stored as `[m cos φ, m sin φ]` in a [`Modulation`]
//! (checked once when built, with each row's span of non-zero values): the point's trains are
//! evaluated with amplitude m·Aᵢ and phase θᵢ + φ (Yrjölä & Larsson Eq. 6, 7). The amplitude
//! factor m carries everything that scales a box's waves locally (the side smoothing of Fig. 4,
//! the build-up envelope, land, shadow and shoaling along the rays, the irregular height of
//! Eq. 8), the phase φ everything that shifts them (depth refraction, Fig. 6; round waves,
//! Eq. 10). Layers add up where they overlap (§2.2), and an optional additive height field
//! carries height-only terms (capillary noise, Eq. 9; run-up).
//!
//! The arithmetic is the grid kernel's: per wave, sin θ and cos θ by angle addition of the row
//! and column tables, then
//!
//! m sin(θ + φ) = sin θ·(m cos φ) + cos θ·(m sin φ),  m cos(θ + φ) = cos θ·(m cos φ) − sin θ·(m sin φ),
//!
//! accumulated like an unmodulated wave. With μ = [1, 0] everywhere a layer gives exactly
//! [`WaveSet::evaluate_grid`]'s result.
//!
//! The horizontal derivatives used for the normals treat μ as locally constant: the normal is
//! that of the modulated waves, not of the modulation itself.

// Lane loops index several arrays in step; that indexed shape is what LLVM vectorises.
#![allow(clippy::needless_range_loop)]

use alloc::vec;
use alloc::vec::Vec;

use glam::Vec3;

use pulp::WithSimd;

use crate::error::EvalError;
use crate::grid::Grid;
pub use crate::grid::GridRect;
use crate::isa::{Isa, Kernel};
use crate::kernel::{Acc, HALF, LANES};
use crate::kernel::{ActiveLayer, ColumnSinCos, LANE_INDEX, LayerRow};
use crate::modulation::Modulation;
use crate::trochoid::{GridPlan, WaveSet, check_outputs, check_time};

/// One wave set modulated over a rectangle of the grid (see the module documentation).
#[derive(Clone, Copy, Debug)]
pub struct Layer<'a> {
    /// The waves.
    pub waves: &'a WaveSet,
    /// μ over the rectangle where the layer acts; outside it the layer contributes nothing.
    pub modulation: &'a Modulation,
}

impl Layer<'_> {
    /// Where the layer acts: its modulation's rectangle.
    pub fn rect(&self) -> GridRect {
        self.modulation.rect()
    }
}

/// Validated inputs with their per-layer tables.
struct Plan<'a> {
    grid: &'a Grid,
    layers: &'a [Layer<'a>],
    plans: Vec<GridPlan<'a>>,
    cols: Vec<Vec<ColumnSinCos>>,
    height: Option<&'a [f32]>,
    /// The instruction set the rows run on.
    kernel: Kernel,
}

impl<'a> Plan<'a> {
    #[allow(clippy::too_many_arguments)]
    fn new(
        isa: Isa,
        grid: &'a Grid,
        t: f64,
        layers: &'a [Layer<'a>],
        height: Option<&'a [f32]>,
        parallel: bool,
    ) -> Result<Self, EvalError> {
        check_time(t)?;
        let n = grid.point_count()?;
        for layer in layers {
            // The modulation's values were checked when it was built; only the fit is left.
            if !layer.rect().fits(grid.size) {
                return Err(EvalError::Grid("layer rectangle outside the grid"));
            }
        }
        if let Some(h) = height {
            if h.len() != n {
                return Err(EvalError::Grid(
                    "height field must hold one value per grid point",
                ));
            }
            if !all_finite(h, parallel) {
                let index = h.iter().position(|v| !v.is_finite()).unwrap_or(0);
                return Err(EvalError::Position { index });
            }
        }
        let plans: Vec<GridPlan<'a>> = layers
            .iter()
            .map(|l| GridPlan::unchecked(l.waves, grid, t))
            .collect();
        let cols = plans
            .iter()
            .map(|p| {
                let mut c = vec![ColumnSinCos::ZERO; p.col_table_len()];
                p.fill_columns(&mut c, 0);
                c
            })
            .collect();
        Ok(Self {
            grid,
            layers,
            plans,
            cols,
            height,
            kernel: Kernel::new(isa).ok_or(EvalError::Isa(isa))?,
        })
    }

    /// The grid columns `a..b` of the 16-column chunks `chunks` (the last one cut at the
    /// grid's edge).
    fn chunk_columns(&self, chunks: &core::ops::Range<usize>) -> (usize, usize) {
        (
            chunks.start * LANES,
            (chunks.end * LANES).min(self.grid.size.0),
        )
    }

    /// Evaluates the chunks `chunks` of row `j` into `pos` and `nrm`, which hold the columns
    /// [`Plan::chunk_columns`] of those chunks.
    fn row<'p>(
        &'p self,
        j: usize,
        chunks: core::ops::Range<usize>,
        pos: &mut [Vec3],
        nrm: &mut [Vec3],
        scratch: &mut Scratch<'p>,
    ) {
        let nx = self.grid.size.0;
        let c0 = chunks.start;
        let (a, b) = self.chunk_columns(&chunks);
        debug_assert!(pos.len() == b - a && nrm.len() == b - a);
        // The layers with non-zero modulation on this row, with their row tables.
        scratch.active.clear();
        scratch.rows.clear();
        for ((layer, plan), cols) in self.layers.iter().zip(&self.plans).zip(&self.cols) {
            let m = layer.modulation;
            let r = m.rect();
            if j < r.j0 || j >= r.j0 + r.nz {
                continue;
            }
            let span = m.span(j - r.j0);
            if span.is_empty() || r.i0 + span.end <= a || r.i0 + span.start >= b {
                continue;
            }
            let waves = layer.waves.coeffs().len();
            let start = scratch.rows.len();
            scratch.rows.resize(start + waves, [0.0; 2]);
            plan.row_sin_cos(j, &mut scratch.rows[start..]);
            scratch.active.push(ActiveLayer {
                coeffs: layer.waves.coeffs(),
                rows: start..start + waves,
                cols,
                first: r.i0 + span.start,
                modulation: &m.row(j - r.j0)[span],
            });
        }
        let height = self.height.map(|h| &h[j * nx..(j + 1) * nx]);
        let row = LayerRow {
            layers: &scratch.active,
            rows: &scratch.rows,
            height,
            first_chunk: c0,
            dx: self.grid.spacing.x as f32,
            z: self.grid.local(0, j).1,
            pos,
            nrm,
        };
        match self.kernel {
            // Built for the compilation target (SSE2 on x86-64, NEON on AArch64).
            Kernel::Portable => row.with_simd(pulp::Scalar::new()),
            #[cfg(target_arch = "x86_64")]
            Kernel::Avx2(simd) => pulp::Simd::vectorize(simd, crate::avx2::Half(simd, row)),
            #[cfg(target_arch = "x86_64")]
            Kernel::Avx512(simd) => pulp::Simd::vectorize(simd, crate::avx512::Wide(simd, row)),
        }
    }
}

/// What [`Plan::row`] builds for each row, kept from row to row so that a row allocates
/// nothing.
#[derive(Default)]
struct Scratch<'p> {
    /// The active layers' row tables, one after another.
    rows: Vec<[f32; 2]>,
    active: Vec<ActiveLayer<'p>>,
}

impl pulp::WithSimd for LayerRow<'_> {
    type Output = ();
    #[inline(always)]
    fn with_simd<S: pulp::Simd>(self, _: S) {
        layer_row_kernel(self);
    }
}

#[inline(always)]
fn layer_row_kernel(row: LayerRow<'_>) {
    let LayerRow {
        layers,
        rows,
        height,
        first_chunk,
        dx,
        z,
        pos: out_pos,
        nrm: out_nrm,
    } = row;
    for (n, (pos, nrm)) in out_pos
        .chunks_mut(LANES)
        .zip(out_nrm.chunks_mut(LANES))
        .enumerate()
    {
        let c = first_chunk + n;
        let first_col = c * LANES;
        // Each half chunk sums every layer's waves with its sums in registers (eight AVX2
        // registers), then the halves meet for the normalisation and the stores.
        let lo = half_sums(layers, rows, c, first_col);
        let hi = half_sums(layers, rows, c, first_col + HALF);
        let mut acc = Acc::from_halves(&lo, &hi);
        if let Some(h) = height {
            let mut add = [0.0f32; LANES];
            let n = pos.len().min(LANES);
            add[..n].copy_from_slice(&h[first_col..first_col + n]);
            acc.add_height(&add);
        }
        let first = first_col as f32;
        let mut x = [0.0f32; LANES];
        for l in 0..LANES {
            x[l] = (first + LANE_INDEX[l]) * dx;
        }
        acc.finish(&x, &[z; LANES], pos, nrm);
    }
}

/// The sums of every layer over the [`HALF`] lanes from grid column `first_col` (in chunk `c`
/// of the column tables).
#[inline(always)]
fn half_sums(
    layers: &[ActiveLayer<'_>],
    rows: &[[f32; 2]],
    c: usize,
    first_col: usize,
) -> Acc<HALF> {
    let mut acc = Acc::<HALF>::new();
    let offset = first_col - c * LANES;
    for layer in layers {
        if !layer.touches(first_col, HALF) {
            continue;
        }
        // The modulation of these lanes; zero outside the row's span.
        let (re, im) = match layer.run(first_col, HALF) {
            Some(run) => {
                // All lanes inside the span: one contiguous run to de-interleave.
                let (mut re, mut im) = ([0.0f32; HALF], [0.0f32; HALF]);
                for l in 0..HALF {
                    re[l] = run[l][0];
                    im[l] = run[l][1];
                }
                (re, im)
            }
            None => layer.partial::<HALF>(first_col),
        };
        // Where μ is zero (land inside a box), a layer's terms would add exactly ±0 to every
        // sum: skipping it changes no bit. The test ORs the magnitude bits, a reduction LLVM
        // vectorises (a float sum would be evaluated lane by lane, in order).
        let mut bits = 0u32;
        for l in 0..HALF {
            bits |= (re[l].to_bits() | im[l].to_bits()) & 0x7fff_ffff;
        }
        if bits == 0 {
            continue;
        }
        let rows = &rows[layer.rows.clone()];
        for ((coeff, &[rs, rc]), col) in layer.coeffs.iter().zip(rows).zip(layer.table(c)) {
            let mut s = [0.0f32; HALF];
            let mut co = [0.0f32; HALF];
            for l in 0..HALF {
                let (cs, cc) = (col.sin[offset + l], col.cos[offset + l]);
                let (sin, cos) = (rs * cc + rc * cs, rc * cc - rs * cs);
                let (mr, mi) = (re[l], im[l]);
                s[l] = sin * mr + cos * mi;
                co[l] = cos * mr - sin * mi;
            }
            acc.add_sin_cos(coeff, &s, &co);
        }
    }
    acc
}

/// Whether every value is finite, in a form LLVM vectorises: x·0 is 0 for finite x and NaN
/// for infinities and NaN, and a NaN survives the sums. With `parallel` (and `std`) the slice
/// is split over the current rayon pool.
fn all_finite(v: &[f32], parallel: bool) -> bool {
    #[cfg(feature = "std")]
    if parallel && v.len() >= 1 << 16 {
        use rayon::prelude::*;
        return v.par_chunks(1 << 15).all(|c| all_finite(c, false));
    }
    let _ = parallel;
    let mut acc = [0.0f32; 16];
    let mut chunks = v.chunks_exact(16);
    for c in &mut chunks {
        for l in 0..16 {
            acc[l] += c[l] * 0.0;
        }
    }
    for (l, x) in chunks.remainder().iter().enumerate() {
        acc[l] += x * 0.0;
    }
    acc.iter().all(|a| *a == 0.0)
}

/// Evaluates the sum of `layers` (plus `height`, if given, added to every point's height) on
/// every point of `grid` at time `t`: positions relative to `grid.origin` and unit normals,
/// row-major, as [`WaveSet::evaluate_grid`] writes them. Points no layer covers stay at rest
/// (normal +y). Nothing is written if an argument is invalid.
pub fn evaluate_layers(
    grid: &Grid,
    t: f64,
    layers: &[Layer<'_>],
    height: Option<&[f32]>,
    out_pos: &mut [Vec3],
    out_nrm: &mut [Vec3],
) -> Result<(), EvalError> {
    let all = whole(grid);
    evaluate_layers_region(grid, t, layers, height, all, out_pos, out_nrm)
}

/// [`evaluate_layers`] restricted to the points of `region`: every point of the region is
/// written, with the value [`evaluate_layers`] gives it; points outside it may be written too
/// (with that same value, the rest of their 16-column chunk), or left as they are. For callers
/// that keep their buffers between frames and know where the surface changed.
pub fn evaluate_layers_region(
    grid: &Grid,
    t: f64,
    layers: &[Layer<'_>],
    height: Option<&[f32]>,
    region: GridRect,
    out_pos: &mut [Vec3],
    out_nrm: &mut [Vec3],
) -> Result<(), EvalError> {
    region_on(
        Isa::best(),
        grid,
        t,
        layers,
        height,
        region,
        out_pos,
        out_nrm,
    )
}

/// [`evaluate_layers`] on the instruction set `isa` instead of the fastest one: the same bits
/// (see [`crate::isa`]), for tests that check that and for benchmarks.
///
/// # Errors
///
/// As [`evaluate_layers`]; [`EvalError::Isa`] if this CPU cannot run `isa`.
pub fn evaluate_layers_isa(
    isa: Isa,
    grid: &Grid,
    t: f64,
    layers: &[Layer<'_>],
    height: Option<&[f32]>,
    out_pos: &mut [Vec3],
    out_nrm: &mut [Vec3],
) -> Result<(), EvalError> {
    let all = whole(grid);
    region_on(isa, grid, t, layers, height, all, out_pos, out_nrm)
}

#[allow(clippy::too_many_arguments)]
fn region_on(
    isa: Isa,
    grid: &Grid,
    t: f64,
    layers: &[Layer<'_>],
    height: Option<&[f32]>,
    region: GridRect,
    out_pos: &mut [Vec3],
    out_nrm: &mut [Vec3],
) -> Result<(), EvalError> {
    check_outputs(grid.point_count()?, out_pos, out_nrm)?;
    let plan = Plan::new(isa, grid, t, layers, height, false)?;
    let Some((rows, chunks)) = region_span(grid, region)? else {
        return Ok(());
    };
    let nx = grid.size.0;
    let (a, b) = plan.chunk_columns(&chunks);
    let mut scratch = Scratch::default();
    for j in rows {
        let (p, n) = (
            &mut out_pos[j * nx + a..j * nx + b],
            &mut out_nrm[j * nx + a..j * nx + b],
        );
        plan.row(j, chunks.clone(), p, n, &mut scratch);
    }
    Ok(())
}

/// The whole grid as a rectangle.
fn whole(grid: &Grid) -> GridRect {
    GridRect {
        i0: 0,
        j0: 0,
        nx: grid.size.0,
        nz: grid.size.1,
    }
}

/// The rows and 16-column chunks holding `region`; `None` for an empty region.
#[allow(clippy::type_complexity)]
fn region_span(
    grid: &Grid,
    r: GridRect,
) -> Result<Option<(core::ops::Range<usize>, core::ops::Range<usize>)>, EvalError> {
    if r.is_empty() {
        return Ok(None);
    }
    if !r.fits(grid.size) {
        return Err(EvalError::Grid("region outside the grid"));
    }
    Ok(Some((
        r.j0..r.j0 + r.nz,
        r.i0 / LANES..(r.i0 + r.nx).div_ceil(LANES),
    )))
}

/// [`evaluate_layers`] on the current rayon thread pool; bit-identical to it.
#[cfg(feature = "std")]
pub fn evaluate_layers_par(
    grid: &Grid,
    t: f64,
    layers: &[Layer<'_>],
    height: Option<&[f32]>,
    out_pos: &mut [Vec3],
    out_nrm: &mut [Vec3],
) -> Result<(), EvalError> {
    let all = whole(grid);
    evaluate_layers_region_par(grid, t, layers, height, all, out_pos, out_nrm)
}

/// [`evaluate_layers_region`] on the current rayon thread pool; bit-identical to it.
#[cfg(feature = "std")]
pub fn evaluate_layers_region_par(
    grid: &Grid,
    t: f64,
    layers: &[Layer<'_>],
    height: Option<&[f32]>,
    region: GridRect,
    out_pos: &mut [Vec3],
    out_nrm: &mut [Vec3],
) -> Result<(), EvalError> {
    use rayon::prelude::*;
    check_outputs(grid.point_count()?, out_pos, out_nrm)?;
    let plan = Plan::new(Isa::best(), grid, t, layers, height, true)?;
    let Some((rows, chunks)) = region_span(grid, region)? else {
        return Ok(());
    };
    let nx = grid.size.0;
    let (a, b) = plan.chunk_columns(&chunks);
    let per_task = crate::parallel::rows_per_task(nx);
    let (first, last) = (rows.start, rows.end);
    out_pos[first * nx..last * nx]
        .par_chunks_mut(nx * per_task)
        .zip(out_nrm[first * nx..last * nx].par_chunks_mut(nx * per_task))
        .enumerate()
        .for_each(|(task, (p, n))| {
            let mut scratch = Scratch::default();
            for (r, (p, n)) in p.chunks_mut(nx).zip(n.chunks_mut(nx)).enumerate() {
                plan.row(
                    first + task * per_task + r,
                    chunks.clone(),
                    &mut p[a..b],
                    &mut n[a..b],
                    &mut scratch,
                );
            }
        });
    Ok(())
}

/// A frame's layers prepared once (validated, with their column tables) for evaluating blocks
/// of grid points on demand: each point gets the bits [`evaluate_layers`] gives it. Height
/// queries on the drawn mesh evaluate the few blocks around their points this way instead of
/// the whole grid.
pub struct LayersEvaluator<'a> {
    plan: Plan<'a>,
}

impl<'a> LayersEvaluator<'a> {
    /// Validates the inputs as [`evaluate_layers`] does and builds every layer's column tables.
    ///
    /// # Errors
    ///
    /// As [`evaluate_layers`], but for the output buffers.
    pub fn new(
        grid: &'a Grid,
        t: f64,
        layers: &'a [Layer<'a>],
        height: Option<&'a [f32]>,
    ) -> Result<Self, EvalError> {
        Ok(Self {
            plan: Plan::new(Isa::best(), grid, t, layers, height, false)?,
        })
    }

    /// The points of `block` into `pos` and `nrm`, row-major over the block (point (i, j) at
    /// `(j − block.j0)·block.nx + i − block.i0`), positions relative to the grid's origin, each
    /// the value [`evaluate_layers`] writes for it. A block whose columns start at a multiple
    /// of 16 and span whole 16-column chunks (or end at the grid's edge) costs no more than
    /// those points do in a whole-grid evaluation.
    ///
    /// # Errors
    ///
    /// [`EvalError::Empty`] for an empty block, [`EvalError::Grid`] for one outside the grid,
    /// [`EvalError::OutputLength`] unless
    /// both buffers hold `block.len()` points. Nothing is written then.
    pub fn evaluate_block(
        &self,
        block: GridRect,
        pos: &mut [Vec3],
        nrm: &mut [Vec3],
    ) -> Result<(), EvalError> {
        check_outputs(block.len(), pos, nrm)?;
        let grid = self.plan.grid;
        let Some((rows, chunks)) = region_span(grid, block)? else {
            return Ok(());
        };
        let (a, b) = self.plan.chunk_columns(&chunks);
        let aligned = a == block.i0 && b == block.i0 + block.nx;
        let mut row_pos = vec![Vec3::ZERO; if aligned { 0 } else { b - a }];
        let mut row_nrm = row_pos.clone();
        let mut scratch = Scratch::default();
        let w = block.nx;
        for (r, j) in rows.enumerate() {
            let (p, n) = (&mut pos[r * w..(r + 1) * w], &mut nrm[r * w..(r + 1) * w]);
            if aligned {
                self.plan.row(j, chunks.clone(), p, n, &mut scratch);
            } else {
                self.plan
                    .row(j, chunks.clone(), &mut row_pos, &mut row_nrm, &mut scratch);
                let from = block.i0 - a;
                p.copy_from_slice(&row_pos[from..from + w]);
                n.copy_from_slice(&row_nrm[from..from + w]);
            }
        }
        Ok(())
    }
}
