//! A layer's complex amplitude over a grid rectangle, checked once when it is built.
//!
//! Wave train boxes keep a box's static modulation (side fades, land, shoaling, refraction)
//! for as long as the box stands still, and evaluate it every frame. Checking every entry for
//! finiteness on every evaluation cost a fifth of a 1024² frame, so the check happens here,
//! once, and an evaluation only checks that the rectangle fits its grid.
//!
//! Each row also records the columns between its first and last non-zero entry. A rotated box's
//! bounding rectangle covers up to twice the box's area; outside the box μ is exactly zero, and
//! the evaluators skip those columns without reading them.

use alloc::vec::Vec;
use core::ops::Range;

use crate::error::EvalError;
use crate::grid::GridRect;

/// `[m cos φ, m sin φ]` per point of a grid rectangle, row-major, every value finite (see the
/// [module documentation](self) and [`crate::layers`]).
#[derive(Clone, Debug, PartialEq)]
pub struct Modulation {
    rect: GridRect,
    values: Vec<[f32; 2]>,
    /// Per row of `rect`: the columns (relative to `rect.i0`) from the first to past the last
    /// non-zero entry; `[0, 0]` for a row of zeros.
    spans: Vec<[u32; 2]>,
    /// An upper bound of |μ| over the rectangle (see [`Modulation::magnitude_bound`]).
    bound: f32,
}

impl Modulation {
    /// Wraps `values`, one per point of `rect`, row-major.
    ///
    /// # Errors
    ///
    /// [`EvalError::Grid`] for an empty rectangle, one wider than `u32::MAX` columns, or a
    /// length other than `rect.len()`; [`EvalError::Position`] with the index of the first
    /// entry that is NaN or infinite.
    pub fn new(rect: GridRect, values: Vec<[f32; 2]>) -> Result<Self, EvalError> {
        if rect.is_empty() {
            return Err(EvalError::Grid("modulation rectangle is empty"));
        }
        if u32::try_from(rect.nx).is_err() {
            return Err(EvalError::Grid("modulation rectangle is too wide"));
        }
        if rect.nx.checked_mul(rect.nz) != Some(values.len()) {
            return Err(EvalError::Grid(
                "layer modulation must hold one entry per point of its rectangle",
            ));
        }
        let spans = row_spans(&values, rect.nx);
        match spans {
            Some(rows) => {
                let (spans, peaks): (Vec<[u32; 2]>, Vec<[f32; 2]>) = rows.into_iter().unzip();
                let peak = peaks
                    .iter()
                    .fold([0.0f32; 2], |a, p| [a[0].max(p[0]), a[1].max(p[1])]);
                // Rounded up by a relative 2⁻²⁰: the square root and the sum each round by
                // at most half an ulp (2⁻²⁴), so the bound never falls below max |μ|.
                let bound = crate::math::sqrtf(peak[0] * peak[0] + peak[1] * peak[1])
                    * (1.0 + 1.0 / (1u32 << 20) as f32);
                Ok(Self {
                    rect,
                    values,
                    spans,
                    bound,
                })
            }
            None => {
                let index = values
                    .iter()
                    .position(|m| !(m[0].is_finite() && m[1].is_finite()))
                    .unwrap_or(0);
                Err(EvalError::Position { index })
            }
        }
    }

    /// μ = 1 (the layer's waves unchanged) over the whole of `rect`.
    ///
    /// # Errors
    ///
    /// As [`Modulation::new`], for an empty or too large rectangle.
    pub fn unit(rect: GridRect) -> Result<Self, EvalError> {
        let n = rect
            .nx
            .checked_mul(rect.nz)
            .ok_or(EvalError::Grid("modulation rectangle is too large"))?;
        Self::new(rect, alloc::vec![[1.0, 0.0]; n])
    }

    /// The rectangle.
    pub fn rect(&self) -> GridRect {
        self.rect
    }

    /// Every value, row-major over the rectangle.
    pub fn values(&self) -> &[[f32; 2]] {
        &self.values
    }

    /// Row `r` of the rectangle (`0..rect.nz`).
    ///
    /// # Panics
    ///
    /// If `r` is not a row of the rectangle.
    #[inline]
    pub fn row(&self, r: usize) -> &[[f32; 2]] {
        let nx = self.rect.nx;
        &self.values[r * nx..(r + 1) * nx]
    }

    /// The columns of row `r` (relative to the rectangle's first column) outside which μ is
    /// exactly zero; empty for a row of zeros.
    ///
    /// # Panics
    ///
    /// If `r` is not a row of the rectangle.
    #[inline]
    pub fn span(&self, r: usize) -> Range<usize> {
        let [a, b] = self.spans[r];
        a as usize..b as usize
    }

    /// An upper bound of |μ| = m over the rectangle, from the largest |m cos φ| and |m sin φ|
    /// of its entries (at most √2 times max |μ|; exact for a real or imaginary μ). A layer's
    /// waves move a point horizontally by at most this times the sum of their amplitudes.
    #[inline]
    pub fn magnitude_bound(&self) -> f32 {
        self.bound
    }

    /// μ at grid point (i, j); zero outside the rectangle.
    #[inline]
    pub fn at(&self, i: usize, j: usize) -> [f32; 2] {
        self.rect.index(i, j).map_or([0.0, 0.0], |q| self.values[q])
    }
}

/// Each row's span of non-zero entries and its largest |m cos φ| and |m sin φ|, or `None` if
/// any value is not finite. With `std`, large arrays are split by rows over the current rayon
/// pool (the result does not depend on it).
#[allow(clippy::type_complexity)]
fn row_spans(values: &[[f32; 2]], nx: usize) -> Option<Vec<([u32; 2], [f32; 2])>> {
    #[cfg(feature = "std")]
    if values.len() >= 1 << 16 {
        use rayon::prelude::*;
        return values.par_chunks(nx).map(row_span).collect();
    }
    values.chunks(nx).map(row_span).collect()
}

/// One row's span of non-zero entries and its largest |m cos φ| and |m sin φ|, or `None` if a
/// value is not finite.
fn row_span(row: &[[f32; 2]]) -> Option<([u32; 2], [f32; 2])> {
    // x·0 is 0 for finite x and NaN otherwise: one vectorisable pass for the finiteness.
    let mut acc = [0.0f32; 2];
    let mut peak = [0.0f32; 2];
    for v in row {
        acc[0] += v[0] * 0.0;
        acc[1] += v[1] * 0.0;
        peak[0] = peak[0].max(v[0].abs());
        peak[1] = peak[1].max(v[1].abs());
    }
    if acc != [0.0, 0.0] {
        return None;
    }
    let zero = |v: &[f32; 2]| v[0] == 0.0 && v[1] == 0.0;
    let Some(first) = row.iter().position(|v| !zero(v)) else {
        return Some(([0, 0], peak));
    };
    let last = row.iter().rposition(|v| !zero(v)).unwrap_or(first);
    // The caller checked that the row length fits in u32.
    Some(([first as u32, last as u32 + 1], peak))
}

#[cfg(test)]
mod tests {
    use super::*;
    use alloc::vec;

    fn rect(nx: usize, nz: usize) -> GridRect {
        GridRect {
            i0: 3,
            j0: 5,
            nx,
            nz,
        }
    }

    #[test]
    fn spans_bound_the_non_zero_entries_of_each_row() {
        let z = [0.0, 0.0];
        let values = vec![
            z,
            [0.5, 0.0],
            z,
            [0.0, -0.25],
            z, // row 0: columns 1..4
            z,
            z,
            z,
            z,
            z, // row 1: none
            [1.0, 0.0],
            z,
            z,
            z,
            [0.0, 1e-30], // row 2: all
            z,
            z,
            [-0.0, 0.0],
            [0.0, -0.0],
            z, // row 3: signed zeros are zero
        ];
        let m = Modulation::new(rect(5, 4), values).unwrap();
        assert_eq!(m.span(0), 1..4);
        assert_eq!(m.span(1), 0..0);
        assert_eq!(m.span(2), 0..5);
        assert_eq!(m.span(3), 0..0);
        assert_eq!(m.at(3 + 1, 5), [0.5, 0.0]);
        assert_eq!(m.at(2, 5), [0.0, 0.0], "left of the rectangle");
        assert_eq!(m.row(2)[4], [0.0, 1e-30]);
        // The largest |re| is 1.0 and |im| 0.25: √(1 + 1/16), rounded up by 2⁻²⁰.
        let bound = f64::from(m.magnitude_bound());
        let exact = (1.0f64 + 0.0625).sqrt();
        assert!(bound >= exact && bound <= exact * (1.0 + 2e-6), "{bound}");
    }

    #[test]
    fn large_modulations_give_the_same_spans_as_row_by_row() {
        // Above the parallel threshold; a diagonal band of non-zero entries.
        let (nx, nz) = (300, 400);
        let mut values = vec![[0.0f32; 2]; nx * nz];
        for j in 0..nz {
            for i in (j / 2)..(j / 2 + 40).min(nx) {
                values[j * nx + i] = [0.25, 0.5];
            }
        }
        let m = Modulation::new(rect(nx, nz), values).unwrap();
        for j in 0..nz {
            let a = (j / 2).min(nx);
            let b = (j / 2 + 40).min(nx);
            assert_eq!(m.span(j), if a < b { a..b } else { 0..0 }, "row {j}");
        }
    }

    #[test]
    fn bad_modulations_are_refused() {
        let ok = vec![[1.0f32, 0.0]; 6];
        assert_eq!(
            Modulation::new(rect(3, 3), ok.clone()),
            Err(EvalError::Grid(
                "layer modulation must hold one entry per point of its rectangle"
            ))
        );
        assert_eq!(
            Modulation::new(rect(0, 3), Vec::new()),
            Err(EvalError::Grid("modulation rectangle is empty"))
        );
        for (index, bad) in [(4, f32::NAN), (0, f32::INFINITY), (5, f32::NEG_INFINITY)] {
            let mut v = ok.clone();
            v[index][index % 2] = bad;
            assert_eq!(
                Modulation::new(rect(3, 2), v),
                Err(EvalError::Position { index }),
                "{bad} at {index}"
            );
        }
        assert!(Modulation::unit(rect(usize::MAX, 2)).is_err());
    }
}
