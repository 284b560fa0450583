//! Phase reduction in `f64`, so the `f32` kernels only ever see angles in [-π, π].
//!
//! A wave's phase k·x − ωt + Φ reaches 10⁸ rad at t = 10⁶ s or 100 km from the origin, where an
//! `f32` cannot even hold it to within a turn. Every phase is therefore formed and reduced modulo
//! 2π in `f64`, and only the remainder is rounded to `f32`.

use core::f64::consts::{PI, TAU};

/// 1.5 · 2⁵²: adding and subtracting it rounds an `f64` below 2⁵¹ in magnitude to an integer.
const ROUND_MAGIC: f64 = 6_755_399_441_055_744.0;

/// Beyond this many turns the magic-number rounding no longer applies and `fmod` is used.
const FAST_TURNS: f64 = 1.0e15;

/// Reduces a phase counted in turns to [-½, ½]: `turns − round(turns)`, exact below 10¹⁵ turns
/// (the difference of two nearby `f64` loses nothing), `%` beyond.
///
/// Non-finite input gives NaN.
#[inline]
pub fn reduce_turns(turns: f64) -> f64 {
    if turns.abs() < FAST_TURNS {
        turns - ((turns + ROUND_MAGIC) - ROUND_MAGIC)
    } else {
        turns % 1.0
    }
}

/// Reduces `theta` to [-π, π] (the representative congruent modulo the `f64` value of 2π).
///
/// Non-finite input gives NaN; the public entry points reject such input before it gets here.
#[inline]
pub fn reduce_angle(theta: f64) -> f64 {
    match reduce_angle_fast(theta) {
        (r, true) => r,
        _ => fold(theta % TAU),
    }
}

/// [`reduce_angle`]'s fast path alone, without a branch: `(r, true)` with r exactly
/// [`reduce_angle`]'s value when |θ| is below 10¹⁵ turns, `(unspecified, false)` otherwise.
/// For lane loops that vectorise it and redo the rare slow lanes.
#[inline(always)]
pub fn reduce_angle_fast(theta: f64) -> (f64, bool) {
    let turns = theta * (1.0 / TAU);
    let n = (turns + ROUND_MAGIC) - ROUND_MAGIC;
    (fold(theta - n * TAU), turns.abs() < FAST_TURNS)
}

/// The rounding of a reduction can leave r a hair outside [-π, π]; this folds it back.
#[inline(always)]
fn fold(r: f64) -> f64 {
    if r > PI {
        r - TAU
    } else if r < -PI {
        r + TAU
    } else {
        r
    }
}

/// Reduces `theta` in `f64` and rounds the remainder to `f32`.
#[inline]
pub fn reduce_angle_f32(theta: f64) -> f32 {
    reduce_angle(theta) as f32
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::math;

    #[test]
    fn turns_reduce_exactly() {
        // Whole turns vanish; the remainder of a quarter survives at any size below 10¹⁵.
        for &n in &[0.0, 1.0, -3.0, 1.0e6, -7.0e9, 4.0e14] {
            assert_eq!(reduce_turns(n), 0.0, "{n}");
            assert_eq!(reduce_turns(n + 0.25), 0.25, "{n}");
            assert_eq!(reduce_turns(n - 0.25), -0.25, "{n}");
        }
        assert_eq!(reduce_turns(0.75), -0.25);
        assert_eq!(reduce_turns(3.0e15 + 2.0), 0.0);
        assert!(reduce_turns(f64::NAN).is_nan());
    }

    #[test]
    fn stays_in_range_and_congruent() {
        for &theta in &[
            0.0, 1.0, -1.0, PI, -PI, 3.5, -3.5, 7.0, 1.0e3, -2.5e7, 1.0e9, 3.0e14, -7.0e16, 1.0e20,
        ] {
            let r = reduce_angle(theta);
            assert!((-PI..=PI).contains(&r), "{theta} -> {r}");
            // Same point on the circle: compare sin and cos within the rounding of theta itself.
            let tol = 4.0 * f64::EPSILON * theta.abs().max(1.0);
            assert!((math::sin(r) - math::sin(theta)).abs() <= tol, "{theta}");
            assert!((math::cos(r) - math::cos(theta)).abs() <= tol, "{theta}");
        }
    }
}
