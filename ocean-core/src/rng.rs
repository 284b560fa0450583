//! A small, deterministic random number generator: **PCG32** (PCG-XSH-RR 64/32).
//!
//! M. E. O'Neill, *PCG: A Family of Simple Fast Space-Efficient Statistically Good Algorithms for
//! Random Number Generation*, Harvey Mudd College tech. report HMC-CS-2014-0905 (2014), and the
//! reference implementation `pcg-c-basic` (<https://www.pcg-random.org>).
//!
//! # Algorithm
//!
//! State: a 64-bit `state` and a 64-bit odd increment `inc` (the *stream*). Each step
//!
//! ```text
//! old   = state
//! state = old · 6364136223846793005 + inc              (mod 2^64)
//! xs    = (((old >> 18) ^ old) >> 27) as u32            (xorshift high)
//! rot   = (old >> 59) as u32
//! out   = xs.rotate_right(rot)                          (random rotation)
//! ```
//!
//! Seeding follows `pcg32_srandom_r(initstate, initseq)`: `inc = (initseq << 1) | 1`, `state = 0`,
//! one step, `state += initstate`, one step. Two generators with different `stream` values produce
//! different, independent-looking sequences from the same `seed`. Period: 2^64 per stream.
//!
//! With seed 42 and stream 54 the first outputs are `0xa15c02b7 0x7b47f409 0xba1d3330 0x83d2f293
//! 0xbfa4784b 0xcbed606e` (the `pcg32-demo` output of `pcg-c-basic`), which the tests check.
//!
//! # Determinism
//!
//! Everything here uses integer arithmetic and IEEE-754 `+ − × ÷ √` only (the natural logarithm
//! that the Gaussian needs is computed in this module from those), so a given seed gives
//! bit-identical sequences, floats included, on every platform and with or without `std`/`libm`.
//! This is **not** a cryptographic generator.

use crate::math::sqrt;
use crate::num::Num;

/// Why an RNG helper refused its arguments.
#[derive(Clone, Copy, Debug, PartialEq, thiserror::Error)]
#[non_exhaustive]
pub enum RngError {
    /// The half-open range `[low, high)` is empty (`low >= high`), or a bound of 0 was asked for.
    #[error("empty range: [{}, {})", Num(*.low), Num(*.high))]
    EmptyRange {
        /// Lower bound (inclusive).
        low: f64,
        /// Upper bound (exclusive).
        high: f64,
    },
    /// A floating-point argument is NaN or infinite, or the range width overflows.
    #[error("`{0}` must be finite")]
    NotFinite(&'static str),
    /// A standard deviation is negative.
    #[error("standard deviation must be >= 0, got {}", Num(*.0))]
    NegativeStdDev(f64),
}

/// The PCG multiplier for 64-bit LCG state (Knuth's MMIX constant).
pub const PCG_MULTIPLIER: u64 = 6364136223846793005;

/// PCG32 (PCG-XSH-RR 64/32) generator; see the module documentation.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct Pcg32 {
    state: u64,
    inc: u64,
}

impl Pcg32 {
    /// Seeds a generator exactly as `pcg32_srandom_r(seed, stream)` of `pcg-c-basic`. Only the low
    /// 63 bits of `stream` matter (the increment is `(stream << 1) | 1`).
    pub const fn new(seed: u64, stream: u64) -> Self {
        let mut rng = Self {
            state: 0,
            inc: (stream << 1) | 1,
        };
        rng.step();
        rng.state = rng.state.wrapping_add(seed);
        rng.step();
        rng
    }

    #[inline(always)]
    const fn step(&mut self) {
        self.state = self
            .state
            .wrapping_mul(PCG_MULTIPLIER)
            .wrapping_add(self.inc);
    }

    /// The next 32 random bits.
    #[inline]
    pub const fn next_u32(&mut self) -> u32 {
        let old = self.state;
        self.step();
        let xorshifted = (((old >> 18) ^ old) >> 27) as u32;
        let rot = (old >> 59) as u32;
        xorshifted.rotate_right(rot)
    }

    /// The next 64 random bits: the first 32-bit output is the **high** half, the second the low
    /// half.
    #[inline]
    pub const fn next_u64(&mut self) -> u64 {
        let hi = self.next_u32() as u64;
        let lo = self.next_u32() as u64;
        (hi << 32) | lo
    }

    /// Uniform in `[0, 1)`: the 24 high bits of [`Pcg32::next_u32`] times 2⁻²⁴ (every value is a
    /// multiple of 2⁻²⁴, exactly representable; 1 is never returned).
    #[inline]
    pub fn next_f32(&mut self) -> f32 {
        (self.next_u32() >> 8) as f32 * (1.0 / 16_777_216.0)
    }

    /// Uniform in `[0, 1)`: the 53 high bits of [`Pcg32::next_u64`] times 2⁻⁵³.
    #[inline]
    pub fn next_f64(&mut self) -> f64 {
        (self.next_u64() >> 11) as f64 * (1.0 / 9_007_199_254_740_992.0)
    }

    /// Uniform integer in `[0, bound)` without bias, by Lemire's multiply-and-reject method
    /// (D. Lemire, *Fast Random Integer Generation in an Interval*, ACM TOMACS 29(1), 2019): the
    /// high half of `x · bound` is the result, and the draw is rejected when the low half falls
    /// below `2³² mod bound`.
    ///
    /// # Errors
    ///
    /// [`RngError::EmptyRange`] when `bound == 0`.
    pub fn below_u32(&mut self, bound: u32) -> Result<u32, RngError> {
        if bound == 0 {
            return Err(RngError::EmptyRange {
                low: 0.0,
                high: 0.0,
            });
        }
        let mut m = self.next_u32() as u64 * bound as u64;
        if (m as u32) < bound {
            let threshold = bound.wrapping_neg() % bound;
            while (m as u32) < threshold {
                m = self.next_u32() as u64 * bound as u64;
            }
        }
        Ok((m >> 32) as u32)
    }

    /// Uniform integer in `[0, bound)` without bias (Lemire's method on 64 bits; see
    /// [`Pcg32::below_u32`]).
    ///
    /// # Errors
    ///
    /// [`RngError::EmptyRange`] when `bound == 0`.
    pub fn below_u64(&mut self, bound: u64) -> Result<u64, RngError> {
        if bound == 0 {
            return Err(RngError::EmptyRange {
                low: 0.0,
                high: 0.0,
            });
        }
        let mut m = self.next_u64() as u128 * bound as u128;
        if (m as u64) < bound {
            let threshold = bound.wrapping_neg() % bound;
            while (m as u64) < threshold {
                m = self.next_u64() as u128 * bound as u128;
            }
        }
        Ok((m >> 64) as u64)
    }

    /// Uniform integer in `[low, high)` without bias.
    ///
    /// # Errors
    ///
    /// [`RngError::EmptyRange`] when `low >= high`.
    pub fn range_i32(&mut self, low: i32, high: i32) -> Result<i32, RngError> {
        if low >= high {
            return Err(RngError::EmptyRange {
                low: low as f64,
                high: high as f64,
            });
        }
        let width = high.wrapping_sub(low) as u32;
        Ok(low.wrapping_add(self.below_u32(width)? as i32))
    }

    /// Uniform integer in `[low, high)` without bias.
    ///
    /// # Errors
    ///
    /// [`RngError::EmptyRange`] when `low >= high`.
    pub fn range_i64(&mut self, low: i64, high: i64) -> Result<i64, RngError> {
        if low >= high {
            return Err(RngError::EmptyRange {
                low: low as f64,
                high: high as f64,
            });
        }
        let width = high.wrapping_sub(low) as u64;
        Ok(low.wrapping_add(self.below_u64(width)? as i64))
    }

    /// Uniform real in `[low, high)`: `low + (high − low)·u` with `u` from [`Pcg32::next_f64`];
    /// when rounding would give `high` the largest `f64` below `high` is returned instead.
    ///
    /// # Errors
    ///
    /// [`RngError::NotFinite`] for a non-finite bound or width, [`RngError::EmptyRange`] when
    /// `low >= high`.
    pub fn uniform_f64(&mut self, low: f64, high: f64) -> Result<f64, RngError> {
        if !low.is_finite() {
            return Err(RngError::NotFinite("low"));
        }
        if !high.is_finite() {
            return Err(RngError::NotFinite("high"));
        }
        if low >= high {
            return Err(RngError::EmptyRange { low, high });
        }
        let width = high - low;
        if !width.is_finite() {
            return Err(RngError::NotFinite("high - low"));
        }
        let x = low + width * self.next_f64();
        Ok(if x < high { x } else { high.next_down() })
    }

    /// Uniform real in `[low, high)` in `f32` (as [`Pcg32::uniform_f64`], with
    /// [`Pcg32::next_f32`]).
    ///
    /// # Errors
    ///
    /// As [`Pcg32::uniform_f64`].
    pub fn uniform_f32(&mut self, low: f32, high: f32) -> Result<f32, RngError> {
        if !low.is_finite() {
            return Err(RngError::NotFinite("low"));
        }
        if !high.is_finite() {
            return Err(RngError::NotFinite("high"));
        }
        if low >= high {
            return Err(RngError::EmptyRange {
                low: low as f64,
                high: high as f64,
            });
        }
        let width = high - low;
        if !width.is_finite() {
            return Err(RngError::NotFinite("high - low"));
        }
        let x = low + width * self.next_f32();
        Ok(if x < high { x } else { high.next_down() })
    }

    /// Two independent standard normal variates (mean 0, variance 1) by Marsaglia's polar method
    /// (G. Marsaglia, T. A. Bray, *A Convenient Method for Generating Normal Variables*, SIAM
    /// Review 6(3), 1964), the rejection form of Box–Muller that needs no sine or cosine:
    /// draw `u, v` uniform in `[−1, 1)` until `0 < s = u² + v² < 1`, then return
    /// `(u·f, v·f)` with `f = √(−2 ln s / s)`. About 1.27 pairs of draws per result on average.
    pub fn normal_pair(&mut self) -> (f64, f64) {
        loop {
            let u = 2.0 * self.next_f64() - 1.0;
            let v = 2.0 * self.next_f64() - 1.0;
            let s = u * u + v * v;
            if s > 0.0 && s < 1.0 {
                let f = sqrt(-2.0 * ln(s) / s);
                return (u * f, v * f);
            }
        }
    }

    /// One standard normal variate (the first of [`Pcg32::normal_pair`]; the second is discarded so
    /// that the generator holds no hidden cache).
    pub fn standard_normal(&mut self) -> f64 {
        self.normal_pair().0
    }

    /// A normal variate with the given mean and standard deviation.
    ///
    /// # Errors
    ///
    /// [`RngError::NotFinite`], [`RngError::NegativeStdDev`].
    pub fn normal(&mut self, mean: f64, std_dev: f64) -> Result<f64, RngError> {
        if !mean.is_finite() {
            return Err(RngError::NotFinite("mean"));
        }
        if !std_dev.is_finite() {
            return Err(RngError::NotFinite("std_dev"));
        }
        if std_dev < 0.0 {
            return Err(RngError::NegativeStdDev(std_dev));
        }
        Ok(mean + std_dev * self.standard_normal())
    }

    /// Jumps ahead by `delta` steps in O(log delta) (or back, since the period is 2⁶⁴: advancing by
    /// `2⁶⁴ − k`, i.e. `k.wrapping_neg()`, goes back `k` steps). The algorithm of
    /// `pcg32_advance_r`, after F. Brown, *Random Number Generation with Arbitrary Stride* (1994).
    pub fn advance(&mut self, mut delta: u64) {
        let mut cur_mult = PCG_MULTIPLIER;
        let mut cur_plus = self.inc;
        let mut acc_mult = 1u64;
        let mut acc_plus = 0u64;
        while delta > 0 {
            if delta & 1 == 1 {
                acc_mult = acc_mult.wrapping_mul(cur_mult);
                acc_plus = acc_plus.wrapping_mul(cur_mult).wrapping_add(cur_plus);
            }
            cur_plus = cur_mult.wrapping_add(1).wrapping_mul(cur_plus);
            cur_mult = cur_mult.wrapping_mul(cur_mult);
            delta >>= 1;
        }
        self.state = acc_mult.wrapping_mul(self.state).wrapping_add(acc_plus);
    }
}

/// Natural logarithm of a positive, finite `x`, from `+ − × ÷` only so that it is bit-identical on
/// every platform (`crate::math` has no `ln`, and the platform's may differ in the last bit).
///
/// `x = m·2^e` with `m ∈ [√½, √2)`; `ln m = 2 atanh(t)`, `t = (m − 1)/(m + 1)`, `|t| ≤ 0.1716`,
/// summed as `2(t + t³/3 + … + t²³/23)`: the first omitted term is below `t·0.0295¹²/25 < 10⁻²⁰·t`.
/// Accurate to a few ulps (checked against `std` in the unit test).
fn ln(x: f64) -> f64 {
    debug_assert!(x > 0.0 && x.is_finite());
    let (x, bias) = if x < f64::MIN_POSITIVE {
        (x * 18_014_398_509_481_984.0, -54) // × 2⁵⁴ to leave the subnormals
    } else {
        (x, 0)
    };
    let bits = x.to_bits();
    let mut e = ((bits >> 52) & 0x7ff) as i64 - 1023 + bias;
    let mut m = f64::from_bits((bits & 0x000f_ffff_ffff_ffff) | 0x3ff0_0000_0000_0000);
    if m > core::f64::consts::SQRT_2 {
        m *= 0.5;
        e += 1;
    }
    let t = (m - 1.0) / (m + 1.0);
    let t2 = t * t;
    // Horner on Σ_{k=0}^{11} t2^k / (2k + 1).
    let mut sum = 1.0 / 23.0;
    let mut k = 10;
    loop {
        sum = sum * t2 + 1.0 / (2 * k + 1) as f64;
        if k == 0 {
            break;
        }
        k -= 1;
    }
    e as f64 * core::f64::consts::LN_2 + 2.0 * t * sum
}

#[cfg(all(test, feature = "std"))]
mod tests {
    use super::ln;

    /// The private `ln` against the platform's over many magnitudes, within 4 ulps (relative
    /// 4·2⁻⁵² ≈ 8.9e-16) or 1e-300 absolute near ln = 0.
    #[test]
    fn ln_matches_std() {
        let mut x = 1e-310_f64;
        while x < 1e300 {
            // Either side of the √2 reduction boundary, and elsewhere in a binade.
            let r2 = core::f64::consts::SQRT_2;
            for f in [
                1.0,
                1.0 + 1e-12,
                1.37,
                r2 * (1.0 - 1e-12),
                r2 * (1.0 + 1e-12),
                1.999,
            ] {
                let y = x * f;
                let want = y.ln();
                let got = ln(y);
                let tol = 4.0 * f64::EPSILON * want.abs() + 1e-300;
                assert!((got - want).abs() <= tol, "ln({y}) = {got}, want {want}");
            }
            x *= 3.7;
        }
        // Near 1 the relative accuracy must hold too (ln(1+ε) ≈ ε).
        for y in [1.0 - 1e-15, 1.0 + 2e-16, 1.0 + 1e-9, 0.999999_f64] {
            let want = y.ln();
            assert!((ln(y) - want).abs() <= 4.0 * f64::EPSILON * want.abs());
        }
        assert_eq!(ln(1.0), 0.0);
    }
}
