//! Helpers shared by the integration tests: the map set, rays and the snapshot format.
#![allow(dead_code)]

use glam::{Vec2, Vec3};
use ocean_core::rng::Pcg32;
use ocean_relief::maps::{boxes, bumps, pins, thin_walls, to_map, value_noise, white_noise};
use ocean_relief::{Edge, HeightMap, Ray};

/// Random and structured maps of side `n` with the given edge mode, named.
pub fn maps(n: usize, edge: Edge) -> Vec<(&'static str, HeightMap)> {
    [
        ("white noise", white_noise(n, 3)),
        ("fBm", value_noise(n, (n / 8).max(2), 4, 2)),
        ("boxes", boxes(n, n * n / 128, 1)),
        ("bumps", bumps(n, (n * n / 200).max(2), n as f64 / 6.0, 1)),
        ("thin walls", thin_walls(n, (n / 4).max(4))),
        ("pins", pins(n, 20, 3)),
    ]
    .into_iter()
    .map(|(name, h)| (name, to_map(n, &h, edge).unwrap()))
    .collect()
}

/// A map from a function of the texel `(i, j)` giving the **height**.
pub fn from_fn(n: usize, edge: Edge, f: impl Fn(usize, usize) -> f32) -> HeightMap {
    let h: Vec<f32> = (0..n * n).map(|k| f(k % n, k / n)).collect();
    to_map(n, &h, edge).unwrap()
}

/// `count` rays with uniformly random starts and azimuths, view angles uniform in
/// `[lo, hi]` degrees, for a relief `depth` texture widths deep.
pub fn rays(count: usize, lo: f32, hi: f32, depth: f32, seed: u64) -> Vec<Ray> {
    let mut rng = Pcg32::new(seed, 11);
    (0..count)
        .map(|_| {
            let start = Vec2::new(rng.next_f32(), rng.next_f32());
            let phi = std::f32::consts::TAU * rng.next_f32();
            let theta = (lo + (hi - lo) * rng.next_f32()).to_radians();
            let view = Vec3::new(
                theta.sin() * phi.cos(),
                theta.sin() * phi.sin(),
                -theta.cos(),
            );
            Ray::from_view(start, view, depth).unwrap()
        })
        .collect()
}

/// One hexadecimal byte per value, a row per line: for snapshots of quantised maps.
pub fn hex_grid(codes: &[u8], width: usize) -> String {
    codes
        .chunks(width)
        .map(|row| row.iter().map(|c| format!("{c:02x}")).collect::<String>())
        .collect::<Vec<_>>()
        .join("\n")
}
