//! The sample pattern: the spiral of Eq. 6–7, the per-pixel rotation of Eq. 8 and the MIP level
//! of Eq. 9.
//!
//! Every operation is spelled out so that the WGSL twin computes the same values: `u32`
//! arithmetic for the hash, `f32` products and sums for the angles (no division on the GPU
//! side: WGSL's `/` is not correctly rounded, so reciprocals come from the host), ocean-core's
//! [`sincos`] on the CPU (the GPU's `sin`/`cos` differ by ~1e-6, far below the AO tolerance),
//! and the index of the highest set bit for `⌊log₂⌋`.

use core::f64::consts::TAU;

use ocean_core::sincos::sincos;

/// `2^(8k) mod 2π` for `k = 0..4`, rounded to `f32` (checked against an exact computation in
/// the tests): the weights that reduce Eq. 8's hash modulo 2π byte by byte.
pub const HASH_BYTE_TURNS: [f32; 4] = [1.0, 4.672_588, 2.377_246_1, 5.389_216_4];

/// The spiral-turn convention of this crate: the integer `τ` in `1 ..= max(1, s − 1)`, coprime
/// with `s`, nearest to `7s/9` (ties to the smaller).
///
/// `7s/9` is the paper's ratio (τ = 7 for s = 9, the value it uses). Coprimality is what makes
/// the angular distribution equal (the paper's stated reason for choosing τ): the angles
/// `2πτ(i + ½)/s`, `i = 0..s`, are then the `s` directions `2πk/s + πτ/s` each exactly once, so
/// every sample direction differs from every other, and the tests check it for every `s ≤ 64`.
/// (Later G3D code uses a min-discrepancy table instead; its values differ.)
pub fn default_spiral_turns(samples: u32) -> u32 {
    let s = samples.max(1);
    let hi = (s - 1).max(1);
    let mut best = 1;
    let mut best_err = u64::MAX;
    for tau in 1..=hi {
        if gcd(tau, s) != 1 {
            continue;
        }
        let err = (9 * u64::from(tau)).abs_diff(7 * u64::from(s));
        if err < best_err {
            best = tau;
            best_err = err;
        }
    }
    best
}

fn gcd(mut a: u32, mut b: u32) -> u32 {
    while b != 0 {
        (a, b) = (b, a % b);
    }
    a
}

/// Eq. 8, AlchemyAO's XOR hash, as an integer number of radians: `30x ^ y + 10xy` read with
/// C's precedence (the paper prints it in C notation; `^` binds loosest):
/// `(30·x) ^ (y + 10·x·y)` in `u32`. `x`, `y` are output coordinates; below
/// [`crate::MAX_SIDE`] nothing wraps. WGSL needs the parentheses: `(30u * x) ^ (y + 10u * x * y)`.
#[inline]
pub fn hash(x: u32, y: u32) -> u32 {
    (30u32.wrapping_mul(x)) ^ y.wrapping_add(10u32.wrapping_mul(x).wrapping_mul(y))
}

/// Eq. 8's angle `φ` reduced modulo 2π in `f32`.
///
/// The hash reaches ~10⁸–10⁹ at 4K (larger than `f32` holds exactly), so it is reduced in
/// integer-sized steps: with its bytes `b₀..b₃` (`hash = Σ b_k·2^(8k)`),
/// `s = ((b₀·M₀ + b₁·M₁) + b₂·M₂) + b₃·M₃` with `M = [`HASH_BYTE_TURNS`]`, then
/// `φ = s − 2π·⌊s·(1/2π)⌋` with `2π` and `1/2π` as `f32` constants. Every intermediate is below
/// 6500, so the result is within ~10⁻³ rad of the exact `hash mod 2π` and within a few `f32`
/// ulps of 6500 of any other evaluation order (a GPU that fuses a multiply-add). The result lies
/// in `[0, 2π]` up to that rounding.
#[inline]
pub fn hash_angle(x: u32, y: u32) -> f32 {
    let h = hash(x, y);
    let b = |k: u32| ((h >> (8 * k)) & 0xff) as f32;
    let s = ((b(0) * HASH_BYTE_TURNS[0] + b(1) * HASH_BYTE_TURNS[1]) + b(2) * HASH_BYTE_TURNS[2])
        + b(3) * HASH_BYTE_TURNS[3];
    const TWO_PI: f32 = TAU as f32;
    const INV_TWO_PI: f32 = (1.0 / TAU) as f32;
    s - TWO_PI * floor_f32(s * INV_TWO_PI)
}

/// `⌊x⌋` for `0 ≤ x < 2²³` without std (truncation equals floor there).
#[inline]
fn floor_f32(x: f32) -> f32 {
    (x as i32) as f32
}

/// Eq. 9: the MIP level of a sample at screen radius `h` pixels,
/// `m = clamp(msb(u32(h)) − log₂q', 0, max_mip)`, where `u32(h)` truncates toward zero and
/// `msb` is the index of the highest set bit (WGSL `firstLeadingBit`), taken as −1 for 0. This
/// is `⌊log₂(h/q')⌋` for `h ≥ q'` with `q' = 2^log_q`, and 0 below.
#[inline]
pub fn mip_level(h: f32, log_q: u32, max_mip: u32) -> u32 {
    let hi = h as u32; // saturating, NaN → 0
    if hi == 0 {
        return 0;
    }
    let msb = 31 - hi.leading_zeros();
    msb.saturating_sub(log_q).min(max_mip)
}

/// The spiral of Eq. 6–7 for `s` samples and `τ` turns, with the host-side constants the GPU
/// twin receives.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Spiral {
    /// Number of samples `s`.
    pub samples: u32,
    /// `f32(1/s)`.
    pub inv_samples: f32,
    /// `f32(2π·τ)`.
    pub two_pi_turns: f32,
}

/// One sample of the spiral at one pixel.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Tap {
    /// `α_i = (i + ½)·(1/s)` (Eq. 6).
    pub alpha: f32,
    /// `û_i = (cos θ_i, sin θ_i)` with `θ_i = α_i·(2πτ) + φ` (Eq. 6–7), x right, y down (input
    /// rows).
    pub dir: [f32; 2],
}

impl Spiral {
    /// The spiral for `samples` samples and `turns` turns (the constants are computed in `f64`
    /// and rounded once).
    pub fn new(samples: u32, turns: f32) -> Self {
        Self {
            samples,
            inv_samples: (1.0 / f64::from(samples.max(1))) as f32,
            two_pi_turns: (TAU * f64::from(turns)) as f32,
        }
    }

    /// Sample `i` rotated by `phi` ([`hash_angle`]).
    #[inline]
    pub fn tap(&self, i: u32, phi: f32) -> Tap {
        let alpha = (i as f32 + 0.5) * self.inv_samples;
        let theta = alpha * self.two_pi_turns + phi;
        let (s, c) = sincos(theta);
        Tap { alpha, dir: [c, s] }
    }
}
