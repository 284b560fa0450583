//! Mip chains of cone maps: the 4×4-window rule keeps every level valid under bilinear
//! sampling, for isotropic maps and for each layer of a quadrant map; the book's 2×2 group
//! minimum does not, nor does a window trimmed on either side of a quadrant layer's rays.

mod common;

use common::maps;
use ocean_relief::check::{Channels, CheckParams, check, check_quadrant};
use ocean_relief::mip::{MipRule, chain, quad_chain};
use ocean_relief::{
    ConeKind, ConeMap, ConeParams, Edge, HeightMap, QuadConeMap, Quadrant, ReliefError,
};

/// Sizes halve down to 1×1, and each coarse texel is the minimum of its 4×4 window of the finer
/// level (checked here on a map whose texel values are all distinct).
#[test]
fn window_rule_values() {
    let n = 8;
    let ratios: Vec<f32> = (0..n * n).map(|k| 1.0 + k as f32).collect();
    let cones = ConeMap::from_ratios(n, Edge::Wrap, ratios.clone()).unwrap();
    let levels = chain(&cones, MipRule::Window).unwrap();
    assert_eq!(
        levels.iter().map(|l| l.size()).collect::<Vec<_>>(),
        [8, 4, 2, 1]
    );
    let l1 = levels[1].ratios();
    for j in 0..4i64 {
        for i in 0..4i64 {
            let mut m = f32::INFINITY;
            for dj in -1..=2 {
                for di in -1..=2 {
                    let (x, y) = ((2 * i + di).rem_euclid(8), (2 * j + dj).rem_euclid(8));
                    m = m.min(ratios[(y * 8 + x) as usize]);
                }
            }
            assert_eq!(l1[(j * 4 + i) as usize], m);
        }
    }
    // Texel (1, 1) of level 1 covers level-0 texels 1..=4 in each axis: its minimum is texel (1, 1).
    assert_eq!(l1[5], ratios[9]);
}

/// Levels 1–3 of the window chain pass the exhaustive check against the full-resolution surface
/// (2×2 apexes per fine cell, 24 directions, all heights; levels 1 and 2 in clamp mode); the
/// group chain fails on the boxes and pins maps, where a coarse texel's bilinear support reaches
/// half a coarse texel past its group, next to a feature.
#[test]
fn window_chain_is_valid_group_chain_is_not() {
    let params = CheckParams {
        apexes: 2,
        directions: 24,
        usage: false,
    };
    for edge in [Edge::Wrap, Edge::Clamp] {
        for (name, map) in maps(32, edge) {
            let cones = ConeMap::generate(&map, ConeParams::relaxed(4.0)).unwrap();
            let window = chain(&cones, MipRule::Window).unwrap();
            let last = if edge == Edge::Wrap { 3 } else { 2 };
            for level in &window[1..=last] {
                let r = check(&map, Channels::of(level), ConeKind::Relaxed, params).unwrap();
                assert_eq!(
                    r.violations,
                    0,
                    "{name} {edge:?} level {}²: {:?}",
                    level.size(),
                    r.worst
                );
            }
            if name == "boxes" || name == "pins" {
                let group = chain(&cones, MipRule::Group).unwrap();
                let bad: u64 = group[1..=3]
                    .iter()
                    .map(|l| {
                        check(&map, Channels::of(l), ConeKind::Relaxed, params)
                            .unwrap()
                            .violations
                    })
                    .sum();
                assert!(bad > 0, "{name} {edge:?}: the group rule passed");
            }
        }
    }
}

/// A chain needs a power-of-two side.
#[test]
fn chain_needs_power_of_two() {
    let cones = ConeMap::from_ratios(12, Edge::Wrap, vec![0.5; 144]).unwrap();
    assert_eq!(
        chain(&cones, MipRule::Window).unwrap_err(),
        ReliefError::NotPowerOfTwo(12)
    );
}

/// One level down with the window `xlo..=xhi` along x (offsets from `2i`) and the full
/// `-1..=2` along y: the `mip` module's reduction with a trimmed ring, for the test below.
fn reduce_trimmed_x(fine: &ConeMap, xlo: i64, xhi: i64) -> ConeMap {
    let (n, edge) = (fine.size(), fine.edge());
    let h = n / 2;
    let reduce = |v: &[f32]| {
        (0..h * h)
            .map(|k| {
                let (i, j) = ((k % h) as i64, (k / h) as i64);
                let mut m = f32::INFINITY;
                for dj in -1..=2 {
                    for di in xlo..=xhi {
                        let x = edge.resolve(2 * i + di, n);
                        let y = edge.resolve(2 * j + dj, n);
                        m = m.min(v[y * n + x]);
                    }
                }
                m
            })
            .collect::<Vec<f32>>()
    };
    ConeMap::from_channels(
        h,
        edge,
        reduce(fine.ratios()),
        reduce(fine.clearance()),
        reduce(fine.near_cap()),
    )
    .unwrap()
}

/// Quadrant layers (`mip` module, "Quadrant layers"): levels 1–3 of every layer of the window
/// chain pass the exhaustive check for the layer's own quadrant ([`check_quadrant`]: 2×2 apexes
/// per fine cell, the 7 of 24 directions in the closed quadrant, all heights) on the six maps
/// at 32² in both edge modes. The restriction to a quadrant does not let the rule shrink: the
/// group chain fails on the boxes and pins maps (as for isotropic maps), and so, on the boxes
/// map in both edge modes, do windows that drop the ring column behind the layer's rays
/// (`2J − 1` for `uₓ ≥ 0`, `2J + 2` for `uₓ ≤ 0`) or the one ahead of them: the apexes in the
/// outer half texel on that side are then served by no texel of the window. (Measured: window 0
/// violations everywhere; boxes, summed over layers and levels, trailing trim 27 (wrap) and 42
/// (clamp), leading trim 13 and 12, group 329 and 774.)
#[test]
fn quad_window_chain_is_valid_group_and_trimmed_windows_are_not() {
    let params = CheckParams {
        apexes: 2,
        directions: 24,
        usage: false,
    };
    let violations = |map: &HeightMap, cones: &ConeMap, q| {
        check_quadrant(map, Channels::of(cones), ConeKind::Relaxed, params, q)
            .unwrap()
            .violations
    };
    for edge in [Edge::Wrap, Edge::Clamp] {
        for (name, map) in maps(32, edge) {
            let cones = QuadConeMap::generate(&map, ConeParams::relaxed(4.0)).unwrap();
            let window = quad_chain(&cones, MipRule::Window).unwrap();
            assert_eq!(
                window.iter().map(|l| l.size()).collect::<Vec<_>>(),
                [32, 16, 8, 4, 2, 1]
            );
            let group = quad_chain(&cones, MipRule::Group).unwrap();
            let (mut bad_group, mut bad_trail, mut bad_lead) = (0, 0, 0);
            for q in Quadrant::ALL {
                // Offsets of the window along x without its trailing or its leading column.
                let (trail, lead) = if q.x_neg {
                    ((-1, 1), (0, 2))
                } else {
                    ((0, 2), (-1, 1))
                };
                let (mut t, mut l) = (cones.layer(q).clone(), cones.layer(q).clone());
                for level in 1..=3 {
                    let w = window[level].layer(q);
                    assert_eq!(*w, chain(cones.layer(q), MipRule::Window).unwrap()[level]);
                    let r = check_quadrant(&map, Channels::of(w), ConeKind::Relaxed, params, q)
                        .unwrap();
                    assert_eq!(
                        r.violations,
                        0,
                        "{name} {edge:?} {q:?} level {}²: {:?}",
                        w.size(),
                        r.worst
                    );
                    // Cells × apexes × 7 directions × (plain + 5 heights).
                    let cells = if edge == Edge::Wrap { 32 * 32 } else { 33 * 33 };
                    assert_eq!(r.lines, cells * 4 * 7 * 6);
                    bad_group += violations(&map, group[level].layer(q), q);
                    t = reduce_trimmed_x(&t, trail.0, trail.1);
                    l = reduce_trimmed_x(&l, lead.0, lead.1);
                    bad_trail += violations(&map, &t, q);
                    bad_lead += violations(&map, &l, q);
                }
            }
            if name == "boxes" || name == "pins" {
                assert!(bad_group > 0, "{name} {edge:?}: the group rule passed");
            }
            if name == "boxes" {
                assert!(bad_trail > 0, "{name} {edge:?}: trailing trim passed");
                assert!(bad_lead > 0, "{name} {edge:?}: leading trim passed");
            }
            println!(
                "{name:12} {edge:?}: group {bad_group}, trailing trim {bad_trail}, leading trim {bad_lead}"
            );
        }
    }
}

/// A quadrant chain needs a power-of-two side too.
#[test]
fn quad_chain_needs_power_of_two() {
    let cones = ConeMap::from_ratios(12, Edge::Wrap, vec![0.5; 144]).unwrap();
    let quad =
        QuadConeMap::from_layers([cones.clone(), cones.clone(), cones.clone(), cones]).unwrap();
    assert_eq!(
        quad_chain(&quad, MipRule::Window).unwrap_err(),
        ReliefError::NotPowerOfTwo(12)
    );
}
