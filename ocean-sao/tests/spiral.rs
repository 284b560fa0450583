//! The spiral (Eq. 6–7), the hash rotation (Eq. 8) and the MIP level (Eq. 9).

use std::f64::consts::TAU;

use ocean_sao::MAX_SIDE;
use ocean_sao::spiral::{
    HASH_BYTE_TURNS, Spiral, default_spiral_turns, hash, hash_angle, mip_level,
};

/// The paper uses τ = 7 turns for s = 9 samples; the convention reproduces it.
#[test]
fn paper_turns() {
    assert_eq!(default_spiral_turns(9), 7);
    assert_eq!(default_spiral_turns(1), 1);
    assert_eq!(default_spiral_turns(2), 1);
}

/// The reason for the convention: with τ coprime to s the s angles `2πτ(i + ½)/s` are the s
/// equally spaced directions `2πk/s + πτ/s`, each once ("equal angular distribution"). Checked
/// for every s ≤ 64 through the taps the sample pass uses (φ = 0), within the `f32` angle error.
#[test]
fn turns_give_equal_angular_distribution() {
    for s in 1..=64u32 {
        let tau = default_spiral_turns(s);
        let spiral = Spiral::new(s, tau as f32);
        let spacing = TAU / f64::from(s);
        let offset = std::f64::consts::PI * f64::from(tau) / f64::from(s);
        let mut seen = vec![false; s as usize];
        for i in 0..s {
            let d = spiral.tap(i, 0.0).dir;
            let a = f64::from(d[1]).atan2(f64::from(d[0]));
            let steps = (a - offset) / spacing;
            let k = steps.round();
            assert!(
                (steps - k).abs() * spacing < 1e-4,
                "s {s} τ {tau}: tap {i} off the grid"
            );
            let k = (k as i64).rem_euclid(i64::from(s)) as usize;
            assert!(!seen[k], "s {s} τ {tau}: direction {k} twice");
            seen[k] = true;
        }
    }
}

/// Eq. 6–7: `α_i = (i + ½)/s`, `θ_i = 2πτα_i + φ`, against `f64`.
#[test]
fn taps_follow_eq6_and_eq7() {
    let spiral = Spiral::new(9, 7.0);
    for i in 0..9 {
        let phi = 1.234f32;
        let tap = spiral.tap(i, phi);
        let alpha = (f64::from(i) + 0.5) / 9.0;
        assert!((f64::from(tap.alpha) - alpha).abs() < 1e-7);
        let theta = TAU * 7.0 * alpha + f64::from(phi);
        assert!((f64::from(tap.dir[0]) - theta.cos()).abs() < 1e-5);
        assert!((f64::from(tap.dir[1]) - theta.sin()).abs() < 1e-5);
    }
}

/// Eq. 8 with C's precedence, `(30x) ^ (y + 10xy)`, worked by hand: (1, 1) → 30 ^ 11 = 21;
/// (3, 2) → 90 ^ 62 = 100. At the largest image no `u32` arithmetic wraps (the value equals the
/// same expression in `u64`).
#[test]
fn hash_values() {
    assert_eq!(hash(0, 0), 0);
    assert_eq!(hash(1, 0), 30);
    assert_eq!(hash(0, 5), 5);
    assert_eq!(hash(1, 1), 21);
    assert_eq!(hash(3, 2), 100);
    let m = MAX_SIDE as u64 - 1;
    for (x, y) in [(m, m), (m, 0), (0, m), (m / 2, m)] {
        let wide = (30 * x) ^ (y + 10 * x * y);
        assert!(wide < 1 << 32);
        assert_eq!(u64::from(hash(x as u32, y as u32)), wide, "({x}, {y})");
    }
}

/// The byte weights are `2^(8k) mod 2π` rounded to `f32`: within half an `f32` ulp of the value
/// computed in `f64` (whose own error, from `f64` 2π, is below 10⁻⁹).
#[test]
fn hash_byte_weights() {
    for (k, &m) in HASH_BYTE_TURNS.iter().enumerate() {
        let exact = 2f64.powi(8 * k as i32) % TAU;
        let half_ulp = f64::from(f32::EPSILON) * 0.5 * exact.abs().max(1.0);
        assert!(
            (f64::from(m) - exact).abs() <= half_ulp + 1e-9,
            "k {k}: {m} vs {exact}"
        );
    }
}

/// Eq. 8's angle reduced modulo 2π stays within 2·10⁻³ rad (circularly) of the exact
/// `hash mod 2π` over the whole range of pixel coordinates: the error budget of the byte-wise
/// reduction is ~1.7·10⁻³ (three weights rounded to `f32`, three products and sums below 6500,
/// the final reduction by an `f32` 2π).
#[test]
fn hash_angle_is_reduced_modulo_2pi() {
    let mut worst = 0.0f64;
    let step = 97;
    for y in (0..MAX_SIDE as u32).step_by(step) {
        for x in (0..MAX_SIDE as u32).step_by(step) {
            let exact = f64::from(hash(x, y)) % TAU;
            let got = f64::from(hash_angle(x, y));
            assert!((-2e-3..TAU + 2e-3).contains(&got), "({x}, {y}): {got}");
            let d = (got - exact).rem_euclid(TAU);
            worst = worst.max(d.min(TAU - d));
        }
    }
    println!("worst |φ − (hash mod 2π)| = {worst:.2e} rad");
    assert!(worst <= 2e-3, "{worst}");
}

/// Eq. 9: `m = ⌊log₂(h/q')⌋` clamped to `[0, max]`, as the index of the highest set bit.
#[test]
fn mip_levels() {
    let cases = [
        (0.0, 0),
        (0.99, 0),
        (7.99, 0),
        (8.0, 0),
        (15.99, 0),
        (16.0, 1),
        (31.99, 1),
        (32.0, 2),
        (255.0, 4),
        (256.0, 5),
        (1e6, 5),
        (f32::NAN, 0),
        (-3.0, 0),
    ];
    for (h, m) in cases {
        assert_eq!(mip_level(h, 3, 5), m, "h = {h}");
    }
    for log_q in 0..=5u32 {
        let q = f64::from(1u32 << log_q);
        for k in 0..4000 {
            let h = (1.003f64.powi(k) * q) as f32;
            let want = ((f64::from(h) / q).log2().floor() as u32).min(9);
            assert_eq!(mip_level(h, log_q, 9), want, "h {h} q' {q}");
        }
    }
}
