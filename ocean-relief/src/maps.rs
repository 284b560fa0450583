//! Procedural height maps for tests, the accuracy table and benchmarks: smooth and rough noise,
//! and structured maps with steep walls and thin features. All are deterministic (ocean-core's
//! PCG32) and return heights in `[0, 1]` (`1` = the polygon surface), row-major, `n × n`.

use alloc::vec;
use alloc::vec::Vec;

use ocean_core::rng::Pcg32;

use crate::ReliefError;
use crate::map::{Edge, HeightMap, HeightRange};

/// Periodic value noise (fBm): `octaves` octaves of a lattice with `cells` lattice cells across
/// the texture at the first octave (doubling each octave, amplitude halving), smoothstep
/// interpolation, normalised to `[0, 1]`. Tiles seamlessly.
pub fn value_noise(n: usize, cells: usize, octaves: u32, seed: u64) -> Vec<f32> {
    let mut rng = Pcg32::new(seed, 0x5eed);
    let mut out = vec![0.0f64; n * n];
    let mut amp = 1.0;
    let mut lattice = cells.max(1);
    for _ in 0..octaves {
        let values: Vec<f64> = (0..lattice * lattice).map(|_| rng.next_f64()).collect();
        let at = |i: usize, j: usize| values[(j % lattice) * lattice + i % lattice];
        for j in 0..n {
            for i in 0..n {
                let x = (i as f64 + 0.5) * lattice as f64 / n as f64;
                let y = (j as f64 + 0.5) * lattice as f64 / n as f64;
                let (x0, y0) = (libm::floor(x), libm::floor(y));
                let (fx, fy) = (smooth(x - x0), smooth(y - y0));
                let (a, b) = (x0 as usize, y0 as usize);
                let top = at(a, b) * (1.0 - fx) + at(a + 1, b) * fx;
                let bottom = at(a, b + 1) * (1.0 - fx) + at(a + 1, b + 1) * fx;
                out[j * n + i] += amp * (top * (1.0 - fy) + bottom * fy);
            }
        }
        amp *= 0.5;
        lattice *= 2;
    }
    normalise(&out)
}

fn smooth(t: f64) -> f64 {
    t * t * (3.0 - 2.0 * t)
}

fn normalise(v: &[f64]) -> Vec<f32> {
    let lo = v.iter().copied().fold(f64::INFINITY, f64::min);
    let hi = v.iter().copied().fold(f64::NEG_INFINITY, f64::max);
    let span = if hi > lo { hi - lo } else { 1.0 };
    v.iter().map(|&x| ((x - lo) / span) as f32).collect()
}

/// Independent uniform heights in `[0, 1)`: the roughest map there is.
pub fn white_noise(n: usize, seed: u64) -> Vec<f32> {
    let mut rng = Pcg32::new(seed, 0xb1a5);
    (0..n * n).map(|_| rng.next_f32()).collect()
}

/// `count` axis-aligned boxes, 2 to `n/4` texels a side, tops at heights in `[0.3, 1]`, on a
/// floor at height 0; a later box overwrites an earlier one. Steep walls and flat tops.
pub fn boxes(n: usize, count: usize, seed: u64) -> Vec<f32> {
    let mut rng = Pcg32::new(seed, 0xb0c5);
    let mut h = vec![0.0f32; n * n];
    if n == 0 {
        return h;
    }
    let max_side = (n / 4).max(2) as u32;
    for _ in 0..count {
        let w = 2 + rng.below_u32(max_side - 1).unwrap_or(0) as usize;
        let d = 2 + rng.below_u32(max_side - 1).unwrap_or(0) as usize;
        let x = rng.below_u32(n as u32).unwrap_or(0) as usize;
        let y = rng.below_u32(n as u32).unwrap_or(0) as usize;
        let top = 0.3 + 0.7 * rng.next_f32();
        for j in y..y + d {
            for i in x..x + w {
                h[(j % n) * n + i % n] = top;
            }
        }
    }
    h
}

/// Thin walls: one texel wide, at full height, every `spacing` texels along both axes, on a
/// floor at height 0. The features a linear search steps over.
pub fn thin_walls(n: usize, spacing: usize) -> Vec<f32> {
    let s = spacing.max(2);
    (0..n * n)
        .map(|k| {
            let (i, j) = (k % n, k / n);
            if i % s == s / 2 || j % s == s / 2 {
                1.0
            } else {
                0.0
            }
        })
        .collect()
}

/// Isolated one-texel pins of random heights in `[0.5, 1]` on a floor at 0, one in `density`
/// texels on average: thin features in every direction.
pub fn pins(n: usize, density: u32, seed: u64) -> Vec<f32> {
    let mut rng = Pcg32::new(seed, 0x9175);
    (0..n * n)
        .map(|_| {
            if rng.below_u32(density.max(1)).unwrap_or(1) == 0 {
                0.5 + 0.5 * rng.next_f32()
            } else {
                0.0
            }
        })
        .collect()
}

/// Round bumps (raised cosines) of radius `radius` texels at random places, heights up to 1,
/// on a floor at 0; overlapping bumps take the maximum. Smooth hills with gentle tops.
pub fn bumps(n: usize, count: usize, radius: f64, seed: u64) -> Vec<f32> {
    let mut rng = Pcg32::new(seed, 0xb4b5);
    let centres: Vec<(f64, f64, f64)> = (0..count)
        .map(|_| {
            (
                rng.next_f64() * n as f64,
                rng.next_f64() * n as f64,
                0.4 + 0.6 * rng.next_f64(),
            )
        })
        .collect();
    let nf = n as f64;
    (0..n * n)
        .map(|k| {
            let (x, y) = ((k % n) as f64, (k / n) as f64);
            let mut h = 0.0f64;
            for &(cx, cy, top) in &centres {
                // Nearest periodic copy: the map tiles.
                let dx = wrap(x - cx + nf * 1.5, nf) - nf * 0.5;
                let dy = wrap(y - cy + nf * 1.5, nf) - nf * 0.5;
                let r = libm::sqrt(dx * dx + dy * dy) / radius;
                if r < 1.0 {
                    h = h.max(top * 0.5 * (1.0 + libm::cos(core::f64::consts::PI * r)));
                }
            }
            h as f32
        })
        .collect()
}

/// `a` modulo `m` in `[0, m)`.
fn wrap(a: f64, m: f64) -> f64 {
    let r = a % m;
    if r < 0.0 { r + m } else { r }
}

/// A height map from generated heights (which are always in range).
///
/// # Errors
///
/// The size errors of [`HeightMap::from_heights`].
pub fn to_map(n: usize, heights: &[f32], edge: Edge) -> Result<HeightMap, ReliefError> {
    HeightMap::from_heights(n, n, heights, edge, HeightRange::Refuse)
}
