//! The dispersion relation of linear water waves (Yrjölä & Larsson, Eq. 4 and 5).

use crate::error::WaveError;
use crate::math;

/// Gravitational acceleration, m/s². The lighting paper's value (Bruneton et al. 2010, §3.1).
pub const GRAVITY: f64 = 9.81;

/// Water depth under a wave.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Depth {
    /// Deep water: tanh(kD) = 1 and ω = √(g k) (Eq. 5).
    Deep,
    /// Finite depth in metres, > 0: ω = √(g k tanh(k D)) (Eq. 4).
    Finite(f64),
}

impl Depth {
    fn validate(self) -> Result<Self, WaveError> {
        match self {
            Depth::Finite(d) if !(d.is_finite() && d > 0.0) => Err(WaveError::Depth(d)),
            d => Ok(d),
        }
    }

    /// tanh(k D), exactly 1 in deep water.
    fn tanh_kd(self, k: f64) -> f64 {
        match self {
            Depth::Deep => 1.0,
            Depth::Finite(d) => math::tanh(k * d),
        }
    }
}

fn check_wavenumber(k: f64) -> Result<f64, WaveError> {
    if k.is_finite() && k > 0.0 {
        Ok(k)
    } else {
        Err(WaveError::Wavenumber(k))
    }
}

/// Angular frequency ω (rad/s) of a wave of wavenumber `k` (rad/m) over `depth`:
/// ω = √(g k tanh(k D)) (Eq. 4), or √(g k) in deep water (Eq. 5).
pub fn angular_frequency(k: f64, depth: Depth) -> Result<f64, WaveError> {
    let k = check_wavenumber(k)?;
    let depth = depth.validate()?;
    Ok(math::sqrt(GRAVITY * k * depth.tanh_kd(k)))
}

/// Phase speed ω/k (m/s).
pub fn phase_speed(k: f64, depth: Depth) -> Result<f64, WaveError> {
    Ok(angular_frequency(k, depth)? / k)
}

/// Wavenumber k (rad/m) of a wave of angular frequency `omega` (rad/s) over `depth`: the inverse
/// of Eq. 4, solved by Newton's method on x tanh x = ω² D / g with x = k D.
pub fn wavenumber(omega: f64, depth: Depth) -> Result<f64, WaveError> {
    if !(omega.is_finite() && omega > 0.0) {
        return Err(WaveError::AngularFrequency(omega));
    }
    let d = match depth.validate()? {
        Depth::Deep => return Ok(omega * omega / GRAVITY),
        Depth::Finite(d) => d,
    };
    let y = omega * omega * d / GRAVITY;
    // Eckart's approximation x ≈ y / √tanh(y) is within 5% everywhere, so Newton converges in a
    // handful of steps; f(x) = x tanh x − y is increasing and convex for x > 0.
    let mut x = y / math::sqrt(math::tanh(y));
    for _ in 0..64 {
        let t = math::tanh(x);
        let f = x * t - y;
        let df = t + x * (1.0 - t * t);
        let step = f / df;
        x -= step;
        if step.abs() <= 1e-15 * x {
            break;
        }
    }
    Ok(x / d)
}

#[cfg(test)]
mod tests {
    use super::*;
    use core::f64::consts::TAU;

    /// Shore Protection Manual (1984) Table C-1: d/L₀ against d/L, where L₀ = gT²/2π is the
    /// deep-water wavelength of the same period. Values as printed (4 significant digits).
    const SPM_TABLE_C1: [(f64, f64); 6] = [
        (0.01, 0.04032),
        (0.05, 0.09416),
        (0.10, 0.1410),
        (0.20, 0.2251),
        (0.30, 0.3121),
        (0.50, 0.5018),
    ];

    #[test]
    fn deep_water_wavelength_of_a_period() {
        // L₀ = g T² / (2π): 1.5613 m for 1 s and 156.13 m for 10 s with g = 9.81.
        for (period, expected) in [(1.0, 1.5613), (10.0, 156.13)] {
            let k = wavenumber(TAU / period, Depth::Deep).unwrap();
            let l = TAU / k;
            assert!((l - expected).abs() < 0.5e-4 * expected, "T={period}: {l}");
        }
    }

    #[test]
    fn finite_depth_matches_spm_table() {
        let depth = 10.0;
        for (d_over_l0, d_over_l) in SPM_TABLE_C1 {
            let l0 = depth / d_over_l0;
            let omega = math::sqrt(GRAVITY * TAU / l0);
            let k = wavenumber(omega, Depth::Finite(depth)).unwrap();
            let got = depth * k / TAU;
            assert!(
                (got - d_over_l).abs() <= 6e-5 * d_over_l.max(0.1) / 0.1,
                "d/L0={d_over_l0}: d/L={got}, table {d_over_l}"
            );
            // And forward again through Eq. 4.
            let w = angular_frequency(k, Depth::Finite(depth)).unwrap();
            assert!((w - omega).abs() <= 1e-12 * omega);
        }
    }

    #[test]
    fn ten_second_wave_in_ten_metres() {
        // Dean & Dalrymple's worked example: T = 10 s, h = 10 m gives L ≈ 92.4 m.
        let k = wavenumber(TAU / 10.0, Depth::Finite(10.0)).unwrap();
        assert!((TAU / k - 92.4).abs() < 0.05, "{}", TAU / k);
    }

    #[test]
    fn shallow_limit_is_sqrt_gd() {
        // kD → 0: c → √(g D) (the waves "queue up" towards land, wave-train-boxes Fig. 7).
        let depth = 0.5;
        let k = 1e-4;
        let c = phase_speed(k, Depth::Finite(depth)).unwrap();
        assert!((c - math::sqrt(GRAVITY * depth)).abs() < 1e-6 * c);
        // and deep water is the limit of large depth
        let deep = angular_frequency(2.0, Depth::Deep).unwrap();
        let finite = angular_frequency(2.0, Depth::Finite(100.0)).unwrap();
        assert_eq!(deep, finite);
    }

    #[test]
    fn rejects_bad_input() {
        assert!(angular_frequency(f64::NAN, Depth::Deep).is_err());
        assert!(angular_frequency(-1.0, Depth::Deep).is_err());
        assert!(angular_frequency(1.0, Depth::Finite(0.0)).is_err());
        assert!(angular_frequency(1.0, Depth::Finite(f64::INFINITY)).is_err());
        assert!(wavenumber(0.0, Depth::Deep).is_err());
        assert!(wavenumber(1.0, Depth::Finite(f64::NAN)).is_err());
    }
}
