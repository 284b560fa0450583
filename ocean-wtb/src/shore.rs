//! Smoothing of the land factor across the grid: coastlines and the lateral edges of shadows.
//!
//! Along a wave ray the land factor f is 0 on land, recovers linearly behind it (Fig. 5) and is 1
//! elsewhere. Across rays, and at a cliff-like shore, it jumps from 0 to 1 between neighbouring
//! grid points. A Gerstner wave moves points horizontally by up to its amplitude A, so where the
//! amplitude changes by Δm over a distance d the displaced surface has the Jacobian
//! det J ≥ 1 − Σk·A − A·Δm/d, which is negative (the surface folds over itself) once d < A.
//! On a fine grid (0.5 m spacing under a 7 m/s wind, A ≈ 0.5 m) a one-cell jump therefore
//! folds the grid, and no height query can match a folded surface. The jump also made the
//! result depend on the grid spacing.
//!
//! So the factor changes over a distance in metres, tied to the waves' displacement: an erosion
//! (minimum over a square of radius R cells), then a box mean of the same radius, with
//! R = ⌈w / (2·spacing)⌉ and w = [`SHORE_WIDTH_PER_AMPLITUDE`]·ΣA. The erosion brings the zeros
//! R cells out into the water, and the mean then ramps linearly from 0 at the last land point to
//! 1 at 2R + 1 cells from it, a gradient of 1/((2R + 1)·spacing) < 1/w. The fold term A·Δm/d
//! is then below ΣA/w = 1/8. Land itself stays exactly 0. Shadows behind land (Fig. 5) keep
//! their recovery along the rays; their edges across the rays get the same ramp.

use alloc::vec;
use alloc::vec::Vec;

/// Width of the land factor's ramps per metre of a box's summed train amplitude (see the
/// [module documentation](self)).
pub const SHORE_WIDTH_PER_AMPLITUDE: f64 = 8.0;

/// The smoothing radius in cells for a box of summed amplitude `amplitude` metres on a grid of
/// `spacing` metres.
pub fn radius(amplitude: f64, spacing: f64) -> usize {
    let cells = SHORE_WIDTH_PER_AMPLITUDE * amplitude / (2.0 * spacing);
    // A box's amplitude is bounded by Eq. 1 (tens of metres at most), so this is a few hundred
    // cells; the clamp only guards the conversion.
    crate::grid::ceil_i64(cells.clamp(0.0, 4096.0)) as usize
}

/// Erodes then box-filters `f` (`nx` × `nz`, row-major) with radius `r` in place, then sets
/// every point of `land` back to exactly 0. Windows are clipped at the array's edges. Both
/// filters are separable and cost O(nx·nz) whatever `r`.
pub fn smooth(f: &mut [f32], land: &[bool], nx: usize, nz: usize, r: usize) {
    if r == 0 || nx == 0 || nz == 0 {
        return;
    }
    separable(f, nx, nz, |src, dst| min_line(src, dst, r));
    separable(f, nx, nz, |src, dst| mean_line(src, dst, r));
    for (v, &l) in f.iter_mut().zip(land) {
        if l {
            *v = 0.0;
        }
    }
}

/// Applies the line filter `line(src, dst)` to every row of `f`, then to every column.
fn separable(f: &mut [f32], nx: usize, nz: usize, mut line: impl FnMut(&[f32], &mut [f32])) {
    let mut out = vec![0.0f32; nx.max(nz)];
    for row in f.chunks_exact_mut(nx) {
        line(row, &mut out[..nx]);
        row.copy_from_slice(&out[..nx]);
    }
    let mut column = vec![0.0f32; nz];
    for i in 0..nx {
        for (j, c) in column.iter_mut().enumerate() {
            *c = f[j * nx + i];
        }
        line(&column, &mut out[..nz]);
        for (j, &v) in out[..nz].iter().enumerate() {
            f[j * nx + i] = v;
        }
    }
}

/// The minimum over the window of radius `r` around each element of a line, with a monotone
/// queue of candidate indices (each index enters and leaves once).
fn min_line(src: &[f32], dst: &mut [f32], r: usize) {
    let n = src.len();
    let mut queue = alloc::collections::VecDeque::with_capacity(2 * r + 1);
    let mut next = 0;
    for (k, d) in dst.iter_mut().enumerate() {
        // Admit every index up to k + r; a new value retires the larger ones before it.
        while next < n && next <= k + r {
            while queue.back().is_some_and(|&b: &usize| src[b] >= src[next]) {
                queue.pop_back();
            }
            queue.push_back(next);
            next += 1;
        }
        while queue.front().is_some_and(|&a| a + r < k) {
            queue.pop_front();
        }
        *d = src[*queue.front().expect("the window holds index k")];
    }
}

/// The mean over the window of radius `r` around each element of a line, by running sums in
/// f64 (exact enough: at most 8193 terms of [0, 1]).
fn mean_line(src: &[f32], dst: &mut [f32], r: usize) {
    let n = src.len();
    let mut prefix = Vec::with_capacity(n + 1);
    prefix.push(0.0f64);
    let mut s = 0.0f64;
    for &v in src {
        s += f64::from(v);
        prefix.push(s);
    }
    for (k, d) in dst.iter_mut().enumerate() {
        let (a, b) = (k.saturating_sub(r), (k + r + 1).min(n));
        *d = ((prefix[b] - prefix[a]) / (b - a) as f64) as f32;
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_cliff_becomes_a_ramp_of_the_stated_width_and_land_stays_zero() {
        // Land in columns 0..10, water (f = 1) beyond, r = 3. The erosion zeroes columns
        // 10..=9 + r; the mean at column k then counts the ones in [k - r, k + r], which start at
        // 10 + r: k - 9 of them. So f rises linearly by 1/(2r + 1) per column from the last land
        // column (9) and is 1 from column 10 + 2r on; land stays exactly 0.
        let (nx, nz, r) = (40, 5, 3);
        let land: Vec<bool> = (0..nx * nz).map(|k| k % nx < 10).collect();
        let mut f: Vec<f32> = land.iter().map(|&l| if l { 0.0 } else { 1.0 }).collect();
        smooth(&mut f, &land, nx, nz, r);
        for j in 0..nz {
            let row = &f[j * nx..(j + 1) * nx];
            assert!(row[..10].iter().all(|&v| v == 0.0));
            let width = 2.0 * r as f64 + 1.0;
            for (k, &v) in row.iter().enumerate().skip(10) {
                let expect = ((k as f64 - 9.0).min(width) / width) as f32;
                assert!((v - expect).abs() < 1e-6, "column {k}: {v} vs {expect}");
            }
            assert_eq!(row[10 + 2 * r], 1.0);
        }
    }

    #[test]
    fn the_sliding_minimum_is_the_minimum_of_each_clipped_window() {
        // Against the definition, on a line with repeats, plateaus and both edges.
        let src: Vec<f32> = (0..97u32)
            .map(|k| ((k * 37 + 11) % 23) as f32 * 0.125 - if k % 9 == 0 { 1.0 } else { 0.0 })
            .collect();
        for r in [1, 2, 5, 40, 200] {
            let mut dst = vec![0.0f32; src.len()];
            min_line(&src, &mut dst, r);
            for (k, &d) in dst.iter().enumerate() {
                let (a, b) = (k.saturating_sub(r), (k + r + 1).min(src.len()));
                let expect = src[a..b].iter().copied().fold(f32::INFINITY, f32::min);
                assert_eq!(d, expect, "r = {r}, element {k}");
            }
        }
    }

    #[test]
    fn no_land_and_no_shadow_changes_nothing() {
        let (nx, nz) = (17, 9);
        let land = vec![false; nx * nz];
        let mut f = vec![1.0f32; nx * nz];
        smooth(&mut f, &land, nx, nz, 4);
        assert!(f.iter().all(|&v| v == 1.0));
    }

    #[test]
    fn radius_follows_the_amplitude_in_metres_not_cells() {
        // w = 8 ΣA: 0.5 m of amplitude is a 4 m ramp, R = 2 cells at 1 m, 4 at 0.5 m.
        assert_eq!(radius(0.5, 1.0), 2);
        assert_eq!(radius(0.5, 0.5), 4);
        assert_eq!(radius(0.5, 2.0), 1);
        assert_eq!(radius(0.0, 1.0), 0);
    }
}
