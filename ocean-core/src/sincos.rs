//! Deterministic single-precision sine and cosine.
//!
//! Platform `sinf`/`cosf` differ in their last bits between C libraries, and GPU `sin`/`cos` are
//! looser still, so the wave kernels use this implementation instead. It is built from IEEE-754
//! additions and multiplications only (no fused multiply-add, no table, no branch), so it returns
//! the same bits on every platform, in scalar or SIMD code, and the WGSL twin in `ocean-gpu`
//! follows the same arithmetic.
//!
//! Algorithm: Cody–Waite reduction by π/2 with a three-part constant, then the Cephes minimax
//! polynomials for sin and cos on [-π/4, π/4], and the quadrant applied by swapping and sign
//! flips.

use core::f32::consts::FRAC_2_PI;

/// 1.5 · 2²³: adding and subtracting it rounds an `f32` of magnitude below 2²² to the nearest
/// integer (ties to even) with plain additions.
const ROUND_MAGIC: f32 = 12_582_912.0;

// π/2 = PIO2_HI + PIO2_MID + PIO2_LO. PIO2_HI and PIO2_MID have few significant bits, so their
// products with a quadrant number below 2¹³ are exact without a fused multiply-add.
const PIO2_HI: f32 = 1.570_312_5;
const PIO2_MID: f32 = 4.837_513e-4;
const PIO2_LO: f32 = 7.549_79e-8;

// Cephes sinf/cosf minimax coefficients on [-π/4, π/4].
const S1: f32 = -1.666_665_5e-1;
const S2: f32 = 8.332_161e-3;
const S3: f32 = -1.951_529_6e-4;
const C1: f32 = 4.166_664_6e-2;
const C2: f32 = -1.388_731_6e-3;
const C3: f32 = 2.443_315_7e-5;

/// Largest |x| for which [`sincos`] keeps its stated accuracy. Callers reduce phases to
/// [-π, π] in `f64` first (see [`crate::phase`]), far inside this bound.
pub const SINCOS_MAX_ARG: f32 = 8192.0;

/// Returns `(sin x, cos x)`.
///
/// Absolute error at most 1.5 · 10⁻⁷ for |x| ≤ 2π (measured in this module's tests against
/// `f64`), and below 10⁻⁵ up to [`SINCOS_MAX_ARG`]. Bit-identical on every platform.
#[inline(always)]
pub fn sincos(x: f32) -> (f32, f32) {
    let biased = x * FRAC_2_PI + ROUND_MAGIC;
    let q = biased - ROUND_MAGIC;
    let r = ((x - q * PIO2_HI) - q * PIO2_MID) - q * PIO2_LO;
    let z = r * r;
    let s = ((S3 * z + S2) * z + S1) * z * r + r;
    let c = ((C3 * z + C2) * z + C1) * z * z - 0.5 * z + 1.0;
    // `biased` is 1.5·2²³ + q, so its low mantissa bits are q in two's complement: a bit cast
    // gives the quadrant without a (saturating, scalarised) float-to-int conversion.
    let qi = biased.to_bits();
    let (s, c) = if qi & 1 != 0 { (c, s) } else { (s, c) };
    // Quadrant q: sin(x) = [s, c, -s, -c][q mod 4], cos(x) = [c, -s, -c, s][q mod 4].
    let sin_sign = (qi & 2) << 30;
    let cos_sign = (qi.wrapping_add(1) & 2) << 30;
    (
        f32::from_bits(s.to_bits() ^ sin_sign),
        f32::from_bits(c.to_bits() ^ cos_sign),
    )
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::math;

    fn max_error(lo: f64, hi: f64, n: u32) -> f64 {
        let mut worst = 0.0f64;
        for i in 0..=n {
            let x = (lo + (hi - lo) * f64::from(i) / f64::from(n)) as f32;
            let (s, c) = sincos(x);
            let xd = f64::from(x);
            worst = worst
                .max((f64::from(s) - math::sin(xd)).abs())
                .max((f64::from(c) - math::cos(xd)).abs());
        }
        worst
    }

    #[test]
    fn accurate_on_two_turns() {
        // The kernels call sincos on sums of two phases reduced to [-π, π].
        let tau = core::f64::consts::TAU;
        let err = max_error(-tau, tau, 2_000_000);
        assert!(err <= 1.5e-7, "max abs error {err:e}");
    }

    #[test]
    fn accurate_up_to_stated_bound() {
        let m = f64::from(SINCOS_MAX_ARG);
        let err = max_error(-m, m, 2_000_000);
        assert!(err <= 1e-5, "max abs error {err:e}");
    }

    #[test]
    fn exact_at_quadrant_points() {
        assert_eq!(sincos(0.0), (0.0, 1.0));
        let (s, c) = sincos(core::f32::consts::FRAC_PI_2);
        assert!((s - 1.0).abs() <= f32::EPSILON && c.abs() < 1e-7);
        let (s, c) = sincos(-core::f32::consts::PI);
        assert!(s.abs() < 1e-7 && (c + 1.0).abs() <= f32::EPSILON);
    }

    #[test]
    fn odd_and_even() {
        // From the first non-zero sample: the sign of sin(±0) is not part of the contract.
        for i in 1..10_000 {
            let x = i as f32 * 1.3e-3;
            let (sp, cp) = sincos(x);
            let (sn, cn) = sincos(-x);
            assert_eq!(sp.to_bits(), (-sn).to_bits(), "sin not odd at {x}");
            assert_eq!(cp.to_bits(), cn.to_bits(), "cos not even at {x}");
        }
    }
}
