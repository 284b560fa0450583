//! Threaded loops on the current rayon pool (with `std`): [`for_rows`], which the CPU
//! reference kernels of the other crates run their rows through (in order without `std`), the
//! task sizes every threaded loop of the crate shares, and the threaded grid and point
//! evaluations of [`WaveSet`]. Each is bit-identical to its single-threaded
//! twin for every thread count.

#[cfg(feature = "std")]
use alloc::vec;

#[cfg(feature = "std")]
use glam::{DVec2, Vec2, Vec3};
#[cfg(feature = "std")]
use rayon::prelude::*;

#[cfg(feature = "std")]
use crate::error::EvalError;
#[cfg(feature = "std")]
use crate::grid::Grid;
#[cfg(feature = "std")]
use crate::kernel::ColumnSinCos;
#[cfg(feature = "std")]
use crate::trochoid::{GridPlan, Points, WaveSet, dispatch};

/// Runs `f(row index, row)` over the rows of `data` (rows of `width` values; the last may be
/// shorter), on the current rayon pool with `std`, in order without. Each row is computed
/// independently of the others, so the result is the same on any thread count.
pub fn for_rows<T: Send>(data: &mut [T], width: usize, f: impl Fn(usize, &mut [T]) + Sync) {
    #[cfg(feature = "std")]
    {
        use rayon::prelude::*;
        data.par_chunks_mut(width.max(1))
            .enumerate()
            .for_each(|(j, row)| f(j, row));
    }
    #[cfg(not(feature = "std"))]
    for (j, row) in data.chunks_mut(width.max(1)).enumerate() {
        f(j, row);
    }
}

#[cfg(feature = "std")]
/// Points per parallel task: large enough to amortise rayon's scheduling (about a
/// microsecond per task), small enough to balance the load over many threads.
pub(crate) const POINTS_PER_TASK: usize = 16 * 1024;

#[cfg(feature = "std")]
/// Whole grid rows per parallel task for rows of `nx` points.
pub fn rows_per_task(nx: usize) -> usize {
    (POINTS_PER_TASK / nx.max(1)).max(1)
}

#[cfg(feature = "std")]
impl WaveSet {
    /// [`WaveSet::evaluate_grid`] on the current rayon thread pool (run it inside
    /// `ThreadPool::install` to choose the thread count). Output is bit-identical to the
    /// single-threaded path for every thread count.
    pub fn evaluate_grid_par(
        &self,
        grid: &Grid,
        t: f64,
        out_pos: &mut [Vec3],
        out_nrm: &mut [Vec3],
    ) -> Result<(), EvalError> {
        let plan = GridPlan::new(self, grid, t, out_pos, out_nrm)?;
        let mut cols = vec![ColumnSinCos::ZERO; plan.col_table_len()];
        let block = plan.waves;
        cols.par_chunks_mut(block * 16)
            .enumerate()
            .for_each(|(c, chunk)| plan.fill_columns(chunk, c * 16));
        let nx = grid.size.0;
        let rows = rows_per_task(nx);
        out_pos
            .par_chunks_mut(nx * rows)
            .zip(out_nrm.par_chunks_mut(nx * rows))
            .enumerate()
            .for_each(|(task, (p, n))| {
                for (r, (p, n)) in p.chunks_mut(nx).zip(n.chunks_mut(nx)).enumerate() {
                    plan.row(&self.coeffs, &cols, task * rows + r, p, n);
                }
            });
        Ok(())
    }

    /// [`WaveSet::evaluate_points`] on the current rayon thread pool; bit-identical to it.
    pub fn evaluate_points_par(
        &self,
        origin: DVec2,
        local: &[Vec2],
        t: f64,
        out_pos: &mut [Vec3],
        out_nrm: &mut [Vec3],
    ) -> Result<(), EvalError> {
        let timed = self.check_points(origin, local, t, out_pos, out_nrm)?;
        local
            .par_chunks(POINTS_PER_TASK)
            .zip(out_pos.par_chunks_mut(POINTS_PER_TASK))
            .zip(out_nrm.par_chunks_mut(POINTS_PER_TASK))
            .for_each(|((l, p), n)| {
                dispatch(Points {
                    coeffs: &self.coeffs,
                    timed: &timed,
                    local: l,
                    pos: p,
                    nrm: n,
                });
            });
        Ok(())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_row_once_with_its_index() {
        let mut v = [0u32; 10];
        for_rows(&mut v, 4, |j, row| {
            for (i, x) in row.iter_mut().enumerate() {
                *x = 10 * j as u32 + i as u32;
            }
        });
        assert_eq!(v, [0, 1, 2, 3, 10, 11, 12, 13, 20, 21]);
    }
}
