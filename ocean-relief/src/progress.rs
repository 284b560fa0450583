//! Progress reports and cancellation for long computations: cone-map generation
//! ([`crate::ConeMap::generate_with`]) takes 0.1 s at 256² and seconds to minutes above 1024².
//!
//! A [`Progress`] is called on the **calling thread** only, between bands of work: the
//! generator splits the rows of cells into at most [`BANDS`] bands, runs each band's rows in
//! parallel (with `std`), and reports after each band. So a callback needs no locking, may
//! touch thread-affine state (a terminal, a GUI), and is never called concurrently with
//! itself. Returning `false` cancels: the computation stops at the end of the current band and
//! returns [`crate::ReliefError::Cancelled`], with nothing written.
//!
//! The result never depends on the callback: every cell is computed independently of the
//! others (see [`crate::cone`]), so splitting the rows into bands changes the order of work,
//! not the bits.

/// Receives `done` of `total` units of work; returns `true` to go on, `false` to cancel.
///
/// Any `FnMut(usize, usize) -> bool` closure is a `Progress`.
pub trait Progress {
    /// `done` of `total` units are finished (`done ≤ total`, non-decreasing from call to call).
    /// Return `false` to cancel.
    fn report(&mut self, done: usize, total: usize) -> bool;
}

impl<F: FnMut(usize, usize) -> bool> Progress for F {
    fn report(&mut self, done: usize, total: usize) -> bool {
        self(done, total)
    }
}

/// Never reports anything, never cancels.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct NoProgress;

impl Progress for NoProgress {
    fn report(&mut self, _done: usize, _total: usize) -> bool {
        true
    }
}

/// Largest number of bands a generation with progress is split into, so a [`Progress`] is
/// called at most `BANDS + 1` times (once with `done = 0` before any work, then after each
/// band). More bands would make reports finer but cost parallel efficiency: each band ends
/// when its slowest row does (about half a row's time idle per band and thread).
pub const BANDS: usize = 64;

/// Rows per band for `rows` rows of work split into at most `bands` bands (`≥ 1`):
/// `⌈rows / bands⌉`, at least 1.
pub(crate) fn band_rows(rows: usize, bands: usize) -> usize {
    rows.div_ceil(bands.max(1)).max(1)
}

#[cfg(test)]
mod tests {
    use alloc::vec::Vec;

    use super::*;
    use crate::maps::{to_map, value_noise};
    use crate::{ConeMap, ConeParams, Edge, HeightMap, ReliefError};

    fn map(n: usize, edge: Edge) -> HeightMap {
        to_map(n, &value_noise(n, 4, 3, 5), edge).unwrap()
    }

    /// Every call in order: starts at 0, never decreases, ends at `total`, at most `BANDS + 1`
    /// calls. The total is the number of rows of bilinear cells: `N` in wrap mode, `N + 1` in
    /// clamp mode (the border strips are cells too, `bound.rs`).
    #[test]
    fn progress_reaches_total_in_order() {
        for (n, edge, total) in [
            (40, Edge::Wrap, 40),
            (40, Edge::Clamp, 41),
            (200, Edge::Wrap, 200),
        ] {
            let mut calls: Vec<(usize, usize)> = Vec::new();
            let mut record = |done: usize, t: usize| {
                calls.push((done, t));
                true
            };
            ConeMap::generate_with(&map(n, edge), ConeParams::relaxed(1.0), &mut record).unwrap();
            assert_eq!(calls.first(), Some(&(0, total)), "{n} {edge:?}");
            assert_eq!(calls.last(), Some(&(total, total)), "{n} {edge:?}");
            assert!(calls.iter().all(|&(_, t)| t == total));
            assert!(calls.windows(2).all(|w| w[0].0 < w[1].0), "{calls:?}");
            // 40 rows: one row a band, 41 calls; 200 rows: ⌈200/64⌉ = 4 rows a band, 50 bands.
            let bands = total.div_ceil(band_rows(total, BANDS));
            assert_eq!(calls.len(), bands + 1);
            assert!(calls.len() <= BANDS + 1);
        }
    }

    /// Returning `false` on the k-th call (k = 1: before any work; k = 3: after two bands;
    /// the last call, when all the work is done) gives `Cancelled`, and no further call is
    /// made.
    #[test]
    fn cancel_after_n_calls_returns_cancelled() {
        let m = map(64, Edge::Wrap);
        // 64 rows: one row a band, 65 calls in all.
        for k in [1usize, 3, 65] {
            let mut calls = 0usize;
            let mut cancel_at_k = |_: usize, _: usize| {
                calls += 1;
                calls < k
            };
            let r = ConeMap::generate_with(&m, ConeParams::relaxed(1.0), &mut cancel_at_k);
            assert_eq!(r, Err(ReliefError::Cancelled), "k = {k}");
            assert_eq!(calls, k, "no call after the cancelling one");
        }
    }

    /// The same bits with and without a callback, for both kinds and edge modes, on one
    /// thread and on four (bands change the order of work only).
    #[test]
    fn output_identical_with_and_without_progress() {
        for edge in [Edge::Wrap, Edge::Clamp] {
            let m = map(48, edge);
            for params in [ConeParams::relaxed(4.0), ConeParams::conservative(1.0)] {
                let plain = ConeMap::generate(&m, params).unwrap();
                for threads in [1, 4] {
                    let with = rayon::ThreadPoolBuilder::new()
                        .num_threads(threads)
                        .build()
                        .unwrap()
                        .install(|| {
                            ConeMap::generate_with(&m, params, &mut |_: usize, _: usize| true)
                        })
                        .unwrap();
                    assert!(with == plain, "{edge:?} {params:?} {threads} threads");
                    let none = ConeMap::generate_with(&m, params, &mut NoProgress).unwrap();
                    assert!(none == plain);
                }
            }
        }
    }

    /// Parameter errors come before any report: a bad cap never calls the callback.
    #[test]
    fn bad_parameters_fail_before_reporting() {
        let mut called = false;
        let r = ConeMap::generate_with(
            &map(16, Edge::Wrap),
            ConeParams::relaxed(f32::NAN),
            &mut |_: usize, _: usize| {
                called = true;
                true
            },
        );
        assert_eq!(r, Err(ReliefError::NotFinite("max_ratio")));
        assert!(!called);
        assert_eq!(band_rows(0, BANDS), 1);
        assert_eq!(band_rows(64, BANDS), 1);
        assert_eq!(band_rows(65, BANDS), 2);
    }
}
