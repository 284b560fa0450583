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

/// Ridged noise: `1 − |2·f − 1|` of [`value_noise`] `f`, renormalised: sharp crests along
/// the noise's mid level, the ridges of eroded terrain.
pub fn ridged(n: usize, cells: usize, octaves: u32, seed: u64) -> Vec<f32> {
    let v: Vec<f64> = value_noise(n, cells, octaves, seed)
        .iter()
        .map(|&f| 1.0 - libm::fabs(2.0 * f64::from(f) - 1.0))
        .collect();
    normalise(&v)
}

/// A plane rising along `x` from 0 at the first column to 1 at the last: smooth, every line
/// through it monotone (wrapped, a cliff at the seam).
pub fn ramp(n: usize) -> Vec<f32> {
    let last = n.saturating_sub(1).max(1) as f64;
    (0..n * n).map(|k| ((k % n) as f64 / last) as f32).collect()
}

/// [`ramp`] in `steps` flat treads of equal width and height: what an 8-bit encoding makes of
/// a smooth slope.
pub fn stairs(n: usize, steps: usize) -> Vec<f32> {
    let steps = steps.clamp(1, n.max(1));
    let last = steps.saturating_sub(1).max(1) as f64;
    (0..n * n)
        .map(|k| ((((k % n) * steps) / n.max(1)) as f64 / last) as f32)
        .collect()
}

/// One cone centred on the map, height 1 at its apex falling linearly to 0 at `radius` texels.
pub fn cone(n: usize, radius: f64) -> Vec<f32> {
    let c = (n as f64 - 1.0) * 0.5;
    (0..n * n)
        .map(|k| {
            let (dx, dy) = ((k % n) as f64 - c, (k / n) as f64 - c);
            (1.0 - libm::sqrt(dx * dx + dy * dy) / radius.max(1.0e-9)).max(0.0) as f32
        })
        .collect()
}

/// `count` round pits of radius 2 to `max_radius` texels with steep (one-texel) rims, floors at
/// depths up to 1, in a plain at height 1: the inverse of pins, holes the ray must find.
pub fn pits(n: usize, count: usize, max_radius: f64, seed: u64) -> Vec<f32> {
    let mut rng = Pcg32::new(seed, 0x9175_0001);
    let mut h = vec![1.0f32; n * n];
    for _ in 0..count {
        let (cx, cy) = (rng.next_f64() * n as f64, rng.next_f64() * n as f64);
        let r = 2.0 + (max_radius - 2.0).max(0.0) * rng.next_f64();
        let floor = (1.0 - rng.next_f64()) as f32;
        stamp(n, cx, cy, r, &mut h, |_, cur| cur.min(floor));
    }
    h
}

/// `count` hemispheres of radius 2 to `max_radius` texels on a floor at 0, heights scaled to
/// at most 1 (a sphere's top is flat, its rim vertical): smooth tops with a grazing silhouette.
pub fn spheres(n: usize, count: usize, max_radius: f64, seed: u64) -> Vec<f32> {
    let mut rng = Pcg32::new(seed, 0x5fe7);
    let mut h = vec![0.0f32; n * n];
    for _ in 0..count {
        let (cx, cy) = (rng.next_f64() * n as f64, rng.next_f64() * n as f64);
        let r = 2.0 + (max_radius - 2.0).max(0.0) * rng.next_f64();
        let top = 0.3 + 0.7 * rng.next_f64();
        stamp(n, cx, cy, r, &mut h, |d, cur| {
            let t = d / r;
            cur.max((top * libm::sqrt((1.0 - t * t).max(0.0))) as f32)
        });
    }
    h
}

/// `count` strokes like engraved letters: polylines of 2 to 4 segments, 1 to 2 texels wide,
/// 3 to `n/8` texels long, raised to heights in `[0.5, 1]` on a floor at 0.
pub fn strokes(n: usize, count: usize, seed: u64) -> Vec<f32> {
    let mut rng = Pcg32::new(seed, 0x57e0);
    let mut h = vec![0.0f32; n * n];
    let longest = (n as f64 / 8.0).max(3.0);
    for _ in 0..count {
        let (mut x, mut y) = (rng.next_f64() * n as f64, rng.next_f64() * n as f64);
        let width = 0.5 + 0.5 * rng.next_f64();
        let top = (0.5 + 0.5 * rng.next_f64()) as f32;
        let segments = 2 + rng.below_u32(3).unwrap_or(0);
        for _ in 0..segments {
            let a = core::f64::consts::TAU * rng.next_f64();
            let len = 3.0 + (longest - 3.0) * rng.next_f64();
            let steps = (len * 4.0) as usize;
            for s in 0..=steps {
                let t = s as f64 / 4.0;
                let (px, py) = (x + t * libm::cos(a), y + t * libm::sin(a));
                stamp(n, px, py, width, &mut h, |_, cur| cur.max(top));
            }
            x += len * libm::cos(a);
            y += len * libm::sin(a);
        }
    }
    h
}

/// Applies `f(distance, current)` to every texel within `r` of `(cx, cy)` (the nearest periodic
/// copy: the maps tile).
fn stamp(n: usize, cx: f64, cy: f64, r: f64, h: &mut [f32], f: impl Fn(f64, f32) -> f32) {
    let nf = n as f64;
    let reach = libm::ceil(r) as i64;
    let (x0, y0) = (libm::floor(cx) as i64, libm::floor(cy) as i64);
    for j in y0 - reach..=y0 + reach + 1 {
        for i in x0 - reach..=x0 + reach + 1 {
            let (dx, dy) = (i as f64 - cx, j as f64 - cy);
            let d = libm::sqrt(dx * dx + dy * dy);
            if d <= r {
                let k = (wrap(j as f64, nf) as usize) * n + wrap(i as f64, nf) as usize;
                h[k] = f(d, h[k]);
            }
        }
    }
}

/// The twelve kinds of map the cone generator's width and speed are measured on, at side `n`
/// (at least 16), named: smooth and rough noise, smooth monotone slopes, staircases, a cone,
/// pits, spheres, boxes, thin walls, pins and strokes.
pub fn family(n: usize) -> Vec<(&'static str, Vec<f32>)> {
    let nf = n as f64;
    let area = n * n;
    vec![
        ("fBm", value_noise(n, (n / 16).max(2), 6, 1)),
        ("value noise", value_noise(n, (n / 16).max(2), 1, 2)),
        ("ridged", ridged(n, (n / 32).max(2), 5, 3)),
        ("ramp", ramp(n)),
        ("stairs", stairs(n, (n / 8).max(2))),
        ("cone", cone(n, nf * 0.45)),
        ("pits", pits(n, (area / 512).max(2), nf / 16.0, 4)),
        ("spheres", spheres(n, (area / 512).max(2), nf / 12.0, 5)),
        ("boxes", boxes(n, (area / 512).max(2), 6)),
        ("thin walls", thin_walls(n, (n / 8).max(4))),
        ("pins", pins(n, 40, 7)),
        ("strokes", strokes(n, (area / 1024).max(2), 8)),
    ]
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
