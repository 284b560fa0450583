//! The fast generator against its brute-force oracle, determinism, analytic cones, and
//! snapshots of small quantised cone maps.

mod common;

use common::{from_fn, hex_grid, maps};
use ocean_relief::storage::{Encoded, Encoding, encode};
use ocean_relief::{ConeMap, ConeParams, Edge};

/// The branch-and-bound returns the brute force's bits, every channel, on random and structured
/// maps up to 64², both edge modes, relaxed and conservative, with the book's cap and a larger
/// one (the search visits tile copies and more nodes then).
#[test]
fn fast_generator_matches_brute_force() {
    let mut compared = 0;
    for (n, edges) in [
        (16, [Edge::Wrap, Edge::Clamp]),
        (32, [Edge::Wrap, Edge::Clamp]),
    ] {
        for edge in edges {
            for (name, map) in maps(n, edge) {
                for params in [
                    ConeParams::relaxed(1.0),
                    ConeParams::conservative(1.0),
                    ConeParams::relaxed(3.5),
                ] {
                    let fast = ConeMap::generate(&map, params).unwrap();
                    let brute = ConeMap::brute_force(&map, params).unwrap();
                    assert!(fast == brute, "{name} {n}² {edge:?} {params:?}");
                    compared += 1;
                }
            }
        }
    }
    // And at 64², the largest size of the validity target, on two maps.
    for (name, map) in maps(64, Edge::Wrap)
        .into_iter()
        .filter(|(n, _)| *n == "fBm" || *n == "boxes")
    {
        let params = ConeParams::relaxed(1.0);
        assert!(
            ConeMap::generate(&map, params).unwrap() == ConeMap::brute_force(&map, params).unwrap(),
            "{name} 64²"
        );
        compared += 1;
    }
    assert_eq!(compared, 2 * 2 * 6 * 3 + 2);
}

/// Same input, same bits, on one thread or several.
#[test]
fn same_bits_for_any_thread_count() {
    for (name, map) in maps(48, Edge::Wrap) {
        let run = |threads: usize| {
            rayon::ThreadPoolBuilder::new()
                .num_threads(threads)
                .build()
                .unwrap()
                .install(|| ConeMap::generate(&map, ConeParams::relaxed(4.0)).unwrap())
        };
        let one = run(1);
        for threads in [2, 3, 5] {
            assert!(run(threads) == one, "{name} with {threads} threads");
        }
    }
}

/// A relaxed cone is never narrower than the conservative one, channel by channel: relaxed
/// candidates are a subset of the conservative ones and their bounds are at least as large.
#[test]
fn relaxed_cones_contain_conservative_ones() {
    for edge in [Edge::Wrap, Edge::Clamp] {
        for (name, map) in maps(32, edge) {
            let r = ConeMap::generate(&map, ConeParams::relaxed(4.0)).unwrap();
            let c = ConeMap::generate(&map, ConeParams::conservative(4.0)).unwrap();
            for (a, b) in [
                (r.ratios(), c.ratios()),
                (r.clearance(), c.clearance()),
                (r.near_cap(), c.near_cap()),
            ] {
                assert!(a.iter().zip(b).all(|(x, y)| x >= y), "{name} {edge:?}");
            }
        }
    }
}

/// A flat map has no candidate at all: every channel is the cap (2.5 texture widths).
#[test]
fn flat_map_gets_the_cap() {
    for edge in [Edge::Wrap, Edge::Clamp] {
        let map = from_fn(16, edge, |_, _| 0.4);
        for params in [ConeParams::relaxed(2.5), ConeParams::conservative(2.5)] {
            let cones = ConeMap::generate(&map, params).unwrap();
            for v in [cones.ratios(), cones.clearance(), cones.near_cap()] {
                assert!(v.iter().all(|&r| r == 2.5), "{edge:?} {params:?}");
            }
        }
    }
}

/// A ramp has no peak: along any line its height is monotone, so no ray can enter it and come
/// out; clamp mode extends it by strips that are flat along the ramp and repeat it across, which
/// add none. Relaxed cones are the cap (4). The conservative cone must avoid the rising part: a
/// line up the ramp from the near edge of a cell that rises `σ` over its texel width reaches
/// that height difference in one texel, so texel `k`, read over the cells `k − 1` and `k`, may
/// hold at most `1/(σ N)` texture widths for each of them; no line rises faster than the
/// steepest cell, so `1/(σ_max N)` is always allowed. (The `f32` depths make `σ` differ from
/// cell to cell by a few parts in a million.) The bound stays within those two, up to the
/// rounding of the gradient bound and the final `f32` (relative 1e-6).
///
/// (A plane tilted along both axes is not peak-free in clamp mode: beyond its high edge the strip
/// keeps the slope of the other axis, so a line climbing to the edge and running slightly
/// downhill along it has a genuine peak on the edge.)
#[test]
fn ramp_cones() {
    let n = 32;
    let map = from_fn(n, Edge::Clamp, |i, _| i as f32 * (0.9 / 64.0) + 0.05);
    let relaxed = ConeMap::generate(&map, ConeParams::relaxed(4.0)).unwrap();
    assert!(relaxed.ratios().iter().all(|&r| r == 4.0));
    // σ of each cell along the ramp: 0.9/64 up to the rounding of the f32 depths.
    let d = map.depths();
    let sigma: Vec<f64> = (0..n - 1)
        .map(|i| f64::from(d[i]) - f64::from(d[i + 1]))
        .collect();
    let steepest = sigma.iter().copied().fold(0.0, f64::max);
    assert!((steepest - 0.9 / 64.0).abs() < 1e-6);
    let cons = ConeMap::generate(&map, ConeParams::conservative(4.0)).unwrap();
    for (k, &r) in cons.ratios().iter().enumerate() {
        let (i, r) = (k % n, f64::from(r));
        let local = [i.wrapping_sub(1), i]
            .iter()
            .filter_map(|&c| sigma.get(c))
            .copied()
            .fold(0.0, f64::max);
        let (upper, lower) = (1.0 / (local * n as f64), 1.0 / (steepest * n as f64));
        assert!(
            r <= upper && r >= lower * (1.0 - 1e-6),
            "{k}: {r} not in [{lower}, {upper}]"
        );
    }
}

fn snapshot_of(cones: &ConeMap) -> String {
    let n = cones.size();
    let grid = |v: &[f32], enc| match encode(v, enc) {
        Encoded::Unorm8(codes) => hex_grid(&codes, n),
        _ => unreachable!("8-bit encodings"),
    };
    format!(
        "ratio, 8-bit sqrt:\n{}\n\nclearance, 8-bit:\n{}\n\nnear cap, 8-bit:\n{}",
        grid(cones.ratios(), Encoding::Unorm8Sqrt),
        grid(cones.clearance(), Encoding::Unorm8),
        grid(cones.near_cap(), Encoding::Unorm8)
    )
}

/// A 12² map with one raised box (heights 0.8 on 4×3 texels) on a floor at 0.2, clamped.
#[test]
fn snapshot_box() {
    let map = from_fn(12, Edge::Clamp, |i, j| {
        if (4..8).contains(&i) && (5..8).contains(&j) {
            0.8
        } else {
            0.2
        }
    });
    insta::assert_snapshot!(snapshot_of(
        &ConeMap::generate(&map, ConeParams::relaxed(1.0)).unwrap()
    ));
}

/// A 12² tiled map with a one-texel wall along x = 3 and a pin at (8, 8).
#[test]
fn snapshot_wall_and_pin() {
    let map = from_fn(12, Edge::Wrap, |i, j| {
        if i == 3 || (i, j) == (8, 8) { 1.0 } else { 0.0 }
    });
    insta::assert_snapshot!(snapshot_of(
        &ConeMap::generate(&map, ConeParams::relaxed(1.0)).unwrap()
    ));
}
