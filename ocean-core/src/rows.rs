//! Row-parallel loops for the CPU reference kernels of the other crates.

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
