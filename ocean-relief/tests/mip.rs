//! Mip chains of cone maps: the 4×4-window rule keeps every level valid under bilinear
//! sampling; the book's 2×2 group minimum does not.

mod common;

use common::maps;
use ocean_relief::check::{Channels, CheckParams, check};
use ocean_relief::mip::{MipRule, chain};
use ocean_relief::{ConeKind, ConeMap, ConeParams, Edge, ReliefError};

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
