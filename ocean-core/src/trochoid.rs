//! The sum of trochoid waves (Yrjölä & Larsson Eq. 6 and 7; Bruneton et al. Eq. 2) with its
//! analytic derivatives, at single points and in batches.

// Lane loops index several arrays in step; that indexed shape is what LLVM vectorises.
#![allow(clippy::needless_range_loop)]

use alloc::vec;
use alloc::vec::Vec;

use glam::{DVec2, Vec2, Vec3};

use crate::error::{EvalError, WaveError};
use crate::grid::Grid;
use crate::kernel::{Acc, ColumnSinCos, GridRow, HALF, LANE_INDEX, LANES, WaveCoeffs};
use crate::phase::reduce_angle_f32;
use crate::sincos::sincos;
use crate::wave::{Wave, WaveDesc};

/// Surface point from the `f32` kernel.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Sample {
    /// Displaced position minus rest position: (Δx, y, Δz), metres.
    pub displacement: Vec3,
    /// Unit surface normal (y up).
    pub normal: Vec3,
}

/// A sum of trochoid waves, evaluated by
///
/// p = p₀ − Σᵢ k̂ᵢ Aᵢ sin θᵢ,  y = Σᵢ Aᵢ cos θᵢ,  θᵢ = kᵢ·p₀ − ωᵢ t + Φᵢ   (Eq. 6, 7)
///
/// with normals from the analytic derivatives of p and y with respect to p₀.
///
/// Each wave has steepness kᵢAᵢ ≤ 1. The *sum* still loops over itself where the horizontal
/// Jacobian det(∂p/∂p₀) turns negative, which cannot happen while
/// [`WaveSet::steepness_sum`] ≤ 1; sets above that are allowed (the lighting paper's spectra
/// exceed it) and produce folded crests where the waves align.
#[derive(Clone, Debug, PartialEq)]
pub struct WaveSet {
    pub(crate) waves: Vec<Wave>,
    pub(crate) coeffs: Vec<WaveCoeffs>,
    /// The `f64` twins of `coeffs` for the point paths: A, A kₓ/|k|, A k_z/|k|, A kₓ²/|k|,
    /// A kₓk_z/|k|, A k_z²/|k|, A kₓ, A k_z, each formed in the order the reference once
    /// formed it per call (so results are unchanged) but without a division per evaluation.
    pub(crate) coeffs64: Vec<[f64; 8]>,
}

/// Per-wave `f64` constants for one evaluation time.
#[derive(Clone, Copy)]
pub(crate) struct Timed {
    k: DVec2,
    /// k·origin − ωt + Φ, unreduced.
    base: f64,
}

pub(crate) fn check_time(t: f64) -> Result<(), EvalError> {
    if t.is_finite() {
        Ok(())
    } else {
        Err(EvalError::Time(t))
    }
}

pub(crate) fn check_outputs<P>(n: usize, pos: &[P], nrm: &[Vec3]) -> Result<(), EvalError> {
    if n == 0 {
        return Err(EvalError::Empty);
    }
    if pos.len() != n || nrm.len() != n {
        return Err(EvalError::OutputLength {
            expected: n,
            positions: pos.len(),
            normals: nrm.len(),
        });
    }
    Ok(())
}

/// Runs a kernel compiled for AVX2 on x86-64 when the CPU has it (pulp's best level
/// elsewhere). The kernel avoids fused multiply-add, so every level yields the same bits.
///
/// pulp compiles [`pulp::WithSimd::with_simd`] inside a `#[target_feature]` function; the
/// kernels are `#[inline(always)]` all the way down so that they are vectorised there. Not
/// AVX-512 (pulp's `x86-v4` level, enabled for the hand-written kernels of `crate::avx512`):
/// LLVM's vectorisation for it ran the layers loops slower than for AVX2 and the grid loops
/// no faster.
#[inline(always)]
pub(crate) fn dispatch<K: pulp::WithSimd>(kernel: K) -> K::Output {
    #[cfg(target_arch = "x86_64")]
    return match pulp::x86::V3::try_new() {
        Some(simd) => pulp::Simd::vectorize(simd, kernel),
        None => kernel.with_simd(pulp::Scalar::new()),
    };
    #[cfg(not(target_arch = "x86_64"))]
    pulp::Arch::new().dispatch(kernel)
}

impl pulp::WithSimd for GridRow<'_> {
    type Output = ();
    #[inline(always)]
    fn with_simd<S: pulp::Simd>(self, _: S) {
        grid_row_kernel(
            self.coeffs,
            self.rows,
            self.cols,
            self.dx,
            self.z,
            self.pos,
            self.nrm,
        );
    }
}

/// A run of scattered points: the arguments of [`points_kernel`].
pub(crate) struct Points<'a> {
    pub(crate) coeffs: &'a [WaveCoeffs],
    pub(crate) timed: &'a [Timed],
    pub(crate) local: &'a [Vec2],
    pub(crate) pos: &'a mut [Vec3],
    pub(crate) nrm: &'a mut [Vec3],
}

impl pulp::WithSimd for Points<'_> {
    type Output = ();
    #[inline(always)]
    fn with_simd<S: pulp::Simd>(self, _: S) {
        points_kernel(self.coeffs, self.timed, self.local, self.pos, self.nrm);
    }
}

impl WaveSet {
    /// A set of already validated waves; at least one.
    pub fn new(waves: &[Wave]) -> Result<Self, WaveError> {
        if waves.is_empty() {
            return Err(WaveError::Empty);
        }
        Ok(Self {
            waves: waves.to_vec(),
            coeffs: waves.iter().map(WaveCoeffs::of).collect(),
            coeffs64: waves
                .iter()
                .map(|w| {
                    let (a, k, m) = (w.amplitude(), w.wave_vector(), w.wavenumber());
                    [
                        a,
                        a * k.x / m,
                        a * k.y / m,
                        a * k.x * k.x / m,
                        a * k.x * k.y / m,
                        a * k.y * k.y / m,
                        a * k.x,
                        a * k.y,
                    ]
                })
                .collect(),
        })
    }

    /// Builds every description and collects them into a set.
    pub fn from_descs(descs: &[WaveDesc]) -> Result<Self, WaveError> {
        let waves = descs
            .iter()
            .map(WaveDesc::build)
            .collect::<Result<Vec<_>, _>>()?;
        Self::new(&waves)
    }

    /// The waves, in evaluation order.
    pub fn waves(&self) -> &[Wave] {
        &self.waves
    }

    /// The per-wave `f64` constants of the point paths (see the field).
    pub(crate) fn coeffs_f64(&self) -> &[[f64; 8]] {
        &self.coeffs64
    }

    /// The per-wave `f32` kernel constants, as the GPU pass uploads them.
    pub fn coeffs(&self) -> &[WaveCoeffs] {
        &self.coeffs
    }

    /// Σ kᵢAᵢ. At most 1 guarantees the summed surface never folds over itself.
    pub fn steepness_sum(&self) -> f64 {
        self.waves.iter().map(Wave::steepness).sum()
    }

    /// Σ Aᵢ: the largest height above (and depth below) y = 0 and the largest horizontal
    /// displacement any point can reach. Use it for bounding volumes and culling margins.
    pub fn max_amplitude(&self) -> f64 {
        self.waves.iter().map(Wave::amplitude).sum()
    }

    pub(crate) fn timed(&self, origin: DVec2, t: f64) -> Vec<Timed> {
        self.waves
            .iter()
            .map(|w| Timed {
                k: w.wave_vector(),
                base: w.phase_at(origin, t),
            })
            .collect()
    }

    /// Displacement and normal at one world rest position, through the `f32` kernel (the same
    /// arithmetic as [`WaveSet::evaluate_points`]).
    pub fn sample(&self, rest: DVec2, t: f64) -> Result<Sample, EvalError> {
        let mut pos = [Vec3::ZERO];
        let mut nrm = [Vec3::ZERO];
        self.evaluate_points(rest, &[Vec2::ZERO], t, &mut pos, &mut nrm)?;
        Ok(Sample {
            displacement: pos[0],
            normal: nrm[0],
        })
    }

    /// Evaluates rest points `origin + local[n]` at time `t`.
    ///
    /// Writes positions relative to `origin` (`local + displacement`) and unit normals. Phases
    /// are formed in `f64` per point, so `local` may span any distance. Nothing is written if
    /// an argument is invalid.
    pub fn evaluate_points(
        &self,
        origin: DVec2,
        local: &[Vec2],
        t: f64,
        out_pos: &mut [Vec3],
        out_nrm: &mut [Vec3],
    ) -> Result<(), EvalError> {
        let timed = self.check_points(origin, local, t, out_pos, out_nrm)?;
        dispatch(Points {
            coeffs: &self.coeffs,
            timed: &timed,
            local,
            pos: out_pos,
            nrm: out_nrm,
        });
        Ok(())
    }

    pub(crate) fn check_points(
        &self,
        origin: DVec2,
        local: &[Vec2],
        t: f64,
        out_pos: &[Vec3],
        out_nrm: &[Vec3],
    ) -> Result<Vec<Timed>, EvalError> {
        check_time(t)?;
        check_outputs(local.len(), out_pos, out_nrm)?;
        if !origin.is_finite() {
            return Err(EvalError::Position { index: 0 });
        }
        if let Some(index) = local.iter().position(|p| !p.is_finite()) {
            return Err(EvalError::Position { index });
        }
        Ok(self.timed(origin, t))
    }

    /// Evaluates every point of `grid` at time `t` into row-major outputs (see [`Grid`]):
    /// positions relative to `grid.origin`, and unit normals.
    pub fn evaluate_grid(
        &self,
        grid: &Grid,
        t: f64,
        out_pos: &mut [Vec3],
        out_nrm: &mut [Vec3],
    ) -> Result<(), EvalError> {
        let plan = GridPlan::new(self, grid, t, out_pos, out_nrm)?;
        let mut cols = vec![ColumnSinCos::ZERO; plan.col_table_len()];
        plan.fill_columns(&mut cols, 0);
        let nx = grid.size.0;
        for (j, (p, n)) in out_pos
            .chunks_mut(nx)
            .zip(out_nrm.chunks_mut(nx))
            .enumerate()
        {
            plan.row(&self.coeffs, &cols, j, p, n);
        }
        Ok(())
    }

    /// Fills the tables from which the grid kernels form every wave's sine and cosine, as the
    /// GPU pass uploads them: `rows[w * size.1 + j]` = [sin R, cos R] and
    /// `cols[w * size.0 + i]` = [sin C, cos C], where R and C are the phase parts of wave `w`
    /// for row `j` and column `i` (R = k·origin − ωt + Φ + k_z j Δz and C = k_x i Δx, each
    /// reduced to [-π, π] in `f64`, then [`sincos`]). The phase at point (i, j) is R + C, so
    ///
    /// sin θ = sin R cos C + cos R sin C,  cos θ = cos R cos C − sin R sin C,
    ///
    /// which is the arithmetic of [`WaveSet::evaluate_grid`] and of the GPU pass.
    pub fn grid_sin_cos(
        &self,
        grid: &Grid,
        t: f64,
        rows: &mut [[f32; 2]],
        cols: &mut [[f32; 2]],
    ) -> Result<(), EvalError> {
        check_time(t)?;
        grid.point_count()?;
        let (nx, nz) = grid.size;
        let w = self.waves.len();
        if rows.len() != w * nz || cols.len() != w * nx {
            return Err(EvalError::Grid(
                "sin/cos tables must hold waves x rows and waves x columns pairs",
            ));
        }
        let pair = |phase: f32| {
            let (s, c) = sincos(phase);
            [s, c]
        };
        let timed = self.timed(grid.origin, t);
        for (wi, tw) in timed.iter().enumerate() {
            for j in 0..nz {
                rows[wi * nz + j] = pair(row_phase(tw, grid, j));
            }
            for i in 0..nx {
                cols[wi * nx + i] = pair(col_phase(tw, grid, i));
            }
        }
        Ok(())
    }
}

#[inline(always)]
fn row_phase(tw: &Timed, grid: &Grid, j: usize) -> f32 {
    reduce_angle_f32(tw.base + tw.k.y * (j as f64 * grid.spacing.y))
}

#[inline(always)]
fn col_phase(tw: &Timed, grid: &Grid, i: usize) -> f32 {
    reduce_angle_f32(tw.k.x * (i as f64 * grid.spacing.x))
}

/// Everything a grid evaluation needs besides the column table.
pub(crate) struct GridPlan<'a> {
    grid: &'a Grid,
    timed: Vec<Timed>,
    pub(crate) waves: usize,
    chunks: usize,
    /// The instruction set the rows run on: [`Isa::best`](crate::Isa::best)'s.
    kernel: crate::isa::Kernel,
}

impl<'a> GridPlan<'a> {
    pub(crate) fn new(
        set: &WaveSet,
        grid: &'a Grid,
        t: f64,
        out_pos: &[Vec3],
        out_nrm: &[Vec3],
    ) -> Result<Self, EvalError> {
        check_time(t)?;
        let n = grid.point_count()?;
        check_outputs(n, out_pos, out_nrm)?;
        Ok(Self::unchecked(set, grid, t))
    }

    /// The plan of `set` over `grid` at `t`, whose validity the caller has checked.
    pub(crate) fn unchecked(set: &WaveSet, grid: &'a Grid, t: f64) -> Self {
        Self {
            grid,
            timed: set.timed(grid.origin, t),
            waves: set.waves.len(),
            chunks: grid.size.0.div_ceil(LANES),
            kernel: crate::isa::Kernel::best(),
        }
    }

    /// sin and cos of every wave's row phase at row `j`, into `out` (one pair per wave).
    pub(crate) fn row_sin_cos(&self, j: usize, out: &mut [[f32; 2]]) {
        for (v, tw) in out.iter_mut().zip(&self.timed) {
            let (s, c) = sincos(row_phase(tw, self.grid, j));
            *v = [s, c];
        }
    }

    /// Column table, chunk-major: `[chunk][wave]`, so a chunk streams one contiguous block.
    pub(crate) fn col_table_len(&self) -> usize {
        self.chunks * self.waves
    }

    /// Fills `out`, which starts at chunk `first_chunk`, with sin and cos of column phases.
    pub(crate) fn fill_columns(&self, out: &mut [ColumnSinCos], first_chunk: usize) {
        let nx = self.grid.size.0;
        for (c, block) in out.chunks_mut(self.waves).enumerate() {
            let i0 = (first_chunk + c) * LANES;
            for (tw, col) in self.timed.iter().zip(block) {
                for l in 0..LANES {
                    // Padding lanes past the last column get phase 0; they are never written.
                    let phase = if i0 + l < nx {
                        col_phase(tw, self.grid, i0 + l)
                    } else {
                        0.0
                    };
                    (col.sin[l], col.cos[l]) = sincos(phase);
                }
            }
        }
    }

    pub(crate) fn row(
        &self,
        coeffs: &[WaveCoeffs],
        cols: &[ColumnSinCos],
        j: usize,
        pos: &mut [Vec3],
        nrm: &mut [Vec3],
    ) {
        let mut stack = [[0.0f32; 2]; 256];
        let mut heap;
        let rows: &mut [[f32; 2]] = if self.waves <= stack.len() {
            &mut stack[..self.waves]
        } else {
            heap = vec![[0.0f32; 2]; self.waves];
            &mut heap
        };
        self.row_sin_cos(j, rows);
        let z = self.grid.local(0, j).1;
        let row = GridRow {
            coeffs,
            rows,
            cols,
            dx: self.grid.spacing.x as f32,
            z,
            pos,
            nrm,
        };
        use crate::isa::Kernel;
        match self.kernel {
            Kernel::Portable => pulp::WithSimd::with_simd(row, pulp::Scalar::new()),
            #[cfg(target_arch = "x86_64")]
            Kernel::Avx2(simd) => pulp::Simd::vectorize(simd, crate::avx2::HalfGrid(simd, row)),
            #[cfg(target_arch = "x86_64")]
            Kernel::Avx512(simd) => pulp::Simd::vectorize(simd, crate::avx512::WideGrid(simd, row)),
        }
    }
}

/// One grid row. The phase of wave w at column i of row j is R_j + C_i, so its sine and cosine
/// follow from the angle-addition identities
///
/// sin(R + C) = sin R cos C + cos R sin C,  cos(R + C) = cos R cos C − sin R sin C,
///
/// with sin and cos of R per row and of C per column computed once by [`sincos`]: four
/// multiplications and two additions per wave and point instead of a polynomial evaluation.
/// The sums over every wave for lanes `OFFSET..OFFSET + HALF` of one chunk.
#[inline(always)]
fn half_sums<const OFFSET: usize>(
    coeffs: &[WaveCoeffs],
    rows: &[[f32; 2]],
    table: &[ColumnSinCos],
) -> Acc<HALF> {
    let mut acc = Acc::<HALF>::new();
    for ((coeff, &[rs, rc]), col) in coeffs.iter().zip(rows).zip(table) {
        let mut s = [0.0f32; HALF];
        let mut co = [0.0f32; HALF];
        for l in 0..HALF {
            let (cs, cc) = (col.sin[OFFSET + l], col.cos[OFFSET + l]);
            s[l] = rs * cc + rc * cs;
            co[l] = rc * cc - rs * cs;
        }
        acc.add_sin_cos(coeff, &s, &co);
    }
    acc
}

#[inline(always)]
fn grid_row_kernel(
    coeffs: &[WaveCoeffs],
    rows: &[[f32; 2]],
    cols: &[ColumnSinCos],
    dx: f32,
    z: f32,
    out_pos: &mut [Vec3],
    out_nrm: &mut [Vec3],
) {
    let block = coeffs.len();
    for (c, (pos, nrm)) in out_pos
        .chunks_mut(LANES)
        .zip(out_nrm.chunks_mut(LANES))
        .enumerate()
    {
        let table = &cols[c * block..(c + 1) * block];
        let acc = Acc::from_halves(
            &half_sums::<0>(coeffs, rows, table),
            &half_sums::<HALF>(coeffs, rows, table),
        );
        // (c·LANES + l) as f32, formed by one conversion and exact float additions (all
        // integers below 2²⁴), so it vectorises.
        let first = (c * LANES) as f32;
        let mut x = [0.0f32; LANES];
        for l in 0..LANES {
            x[l] = (first + LANE_INDEX[l]) * dx;
        }
        acc.finish(&x, &[z; LANES], pos, nrm);
    }
}

#[inline(always)]
fn points_kernel(
    coeffs: &[WaveCoeffs],
    timed: &[Timed],
    local: &[Vec2],
    out_pos: &mut [Vec3],
    out_nrm: &mut [Vec3],
) {
    for ((pts, pos), nrm) in local
        .chunks(LANES)
        .zip(out_pos.chunks_mut(LANES))
        .zip(out_nrm.chunks_mut(LANES))
    {
        let mut x = [0.0f32; LANES];
        let mut z = [0.0f32; LANES];
        for (l, p) in pts.iter().enumerate() {
            x[l] = p.x;
            z[l] = p.y;
        }
        let mut acc = Acc::new();
        for (coeff, tw) in coeffs.iter().zip(timed) {
            let mut theta = [0.0f32; LANES];
            for l in 0..LANES {
                theta[l] =
                    reduce_angle_f32(tw.base + tw.k.x * f64::from(x[l]) + tw.k.y * f64::from(z[l]));
            }
            acc.add(coeff, &theta);
        }
        acc.finish(&x, &z, pos, nrm);
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::wave::Wave;

    /// The baseline build (SSE2 on x86-64, 4 lanes per instruction) and the best level the CPU
    /// offers (AVX2 where present, 8 lanes) must give the same bits: the kernel has no fused
    /// multiply-add and the same per-lane operation order.
    #[test]
    fn simd_levels_give_identical_bits() {
        let waves: Vec<Wave> = (0..7)
            .map(|i| {
                let a = 0.9 * i as f64;
                Wave::deep(
                    0.05 * (i + 1) as f64,
                    1.5 + 3.0 * i as f64,
                    DVec2::new(a.cos(), a.sin()),
                    a,
                )
                .unwrap()
            })
            .collect();
        let set = WaveSet::new(&waves).unwrap();
        let grid = Grid {
            origin: DVec2::new(1234.5, -987.25),
            spacing: DVec2::new(0.21, 0.33),
            size: (101, 3),
        };
        let plan =
            GridPlan::new(&set, &grid, 4321.0, &[Vec3::ZERO; 303], &[Vec3::ZERO; 303]).unwrap();
        let mut cols = vec![ColumnSinCos::ZERO; plan.col_table_len()];
        plan.fill_columns(&mut cols, 0);
        let rows: Vec<[f32; 2]> = plan
            .timed
            .iter()
            .map(|tw| {
                let (s, c) = sincos(row_phase(tw, &grid, 2));
                [s, c]
            })
            .collect();
        let dx = grid.spacing.x as f32;
        fn row<'a>(
            set: &'a WaveSet,
            rows: &'a [[f32; 2]],
            cols: &'a [ColumnSinCos],
            dx: f32,
            pos: &'a mut [Vec3],
            nrm: &'a mut [Vec3],
        ) -> GridRow<'a> {
            GridRow {
                coeffs: &set.coeffs,
                rows,
                cols,
                dx,
                z: 0.66,
                pos,
                nrm,
            }
        }
        let bits = |p: &[Vec3], n: &[Vec3]| -> Vec<u32> {
            p.iter()
                .chain(n)
                .flat_map(|v| [v.x.to_bits(), v.y.to_bits(), v.z.to_bits()])
                .collect()
        };
        let run = |arch: pulp::Arch| {
            let (mut p, mut n) = (vec![Vec3::ZERO; 101], vec![Vec3::ZERO; 101]);
            arch.dispatch(row(&set, &rows, &cols, dx, &mut p, &mut n));
            bits(&p, &n)
        };
        let best = pulp::Arch::new();
        std::println!("best SIMD level: {best:?}");
        let scalar = run(pulp::Arch::Scalar);
        assert_eq!(scalar, run(best));
        // The kernels written with intrinsics, where the CPU has them.
        #[cfg(target_arch = "x86_64")]
        if let Some(simd) = pulp::x86::V3::try_new() {
            let (mut p, mut n) = (vec![Vec3::ZERO; 101], vec![Vec3::ZERO; 101]);
            let half = crate::avx2::HalfGrid(simd, row(&set, &rows, &cols, dx, &mut p, &mut n));
            pulp::Simd::vectorize(simd, half);
            assert_eq!(scalar, bits(&p, &n));
        }
        #[cfg(target_arch = "x86_64")]
        if let Some(simd) = pulp::x86::V4::try_new() {
            let (mut p, mut n) = (vec![Vec3::ZERO; 101], vec![Vec3::ZERO; 101]);
            let wide = crate::avx512::WideGrid(simd, row(&set, &rows, &cols, dx, &mut p, &mut n));
            pulp::Simd::vectorize(simd, wide);
            assert_eq!(scalar, bits(&p, &n));
        }
    }
}
