//! One trochoid (Gerstner) wave train: amplitude, wave vector, angular frequency and phase.

use core::f64::consts::TAU;

use glam::DVec2;

use crate::dispersion::{self, Depth};
use crate::error::WaveError;
use crate::math;

/// Slack on the steepness test so that A = λ/2π, which rounds to k·A = 1 + 1 ulp, is accepted
/// as the limiting cusp rather than rejected.
const STEEPNESS_SLACK: f64 = 8.0 * f64::EPSILON;

/// A wave as a user describes it; [`WaveDesc::build`] turns it into a [`Wave`].
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct WaveDesc {
    /// Amplitude A in metres (half the crest-to-trough height), ≥ 0.
    pub amplitude: f64,
    /// Wavelength λ in metres, > 0; the wavenumber is k = 2π/λ.
    pub wavelength: f64,
    /// Direction of travel in the (x, z) plane; any finite non-zero length.
    pub direction: DVec2,
    /// Phase shift Φ in radians (Eq. 6, 7).
    pub phase: f64,
    /// Water depth, which sets the angular frequency through Eq. 4 (or Eq. 5 in deep water).
    pub depth: Depth,
}

impl WaveDesc {
    /// Validates the description and derives the wave vector and angular frequency.
    pub fn build(&self) -> Result<Wave, WaveError> {
        if !(self.wavelength.is_finite() && self.wavelength > 0.0) {
            return Err(WaveError::Wavelength(self.wavelength));
        }
        let dir = self.direction;
        let len = math::sqrt(dir.x * dir.x + dir.y * dir.y);
        if !(len.is_finite() && len > 0.0) {
            return Err(WaveError::Direction(dir.x, dir.y));
        }
        let k = TAU / self.wavelength;
        let omega = dispersion::angular_frequency(k, self.depth)?;
        Wave::from_parts(self.amplitude, dir * (k / len), omega, self.phase)
    }
}

/// A validated trochoid wave train, evaluated by Eq. 6 and 7 of Yrjölä & Larsson:
///
/// p = p₀ − (k/|k|) A sin(k·p₀ − ωt + Φ),  y = A cos(k·p₀ − ωt + Φ).
///
/// Invariant: every field is finite, A ≥ 0, |k| > 0, ω > 0, and the steepness |k|·A ≤ 1. At
/// |k|·A = 1 the crest is a cusp; above it the trochoid would loop over itself, so such waves
/// are refused (scale A down to 1/|k| to clamp).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Wave {
    amplitude: f64,
    wave_vector: DVec2,
    wavenumber: f64,
    angular_frequency: f64,
    phase: f64,
}

impl Wave {
    /// Builds a wave from its raw parameters: amplitude (m), wave vector (rad/m, in (x, z)),
    /// angular frequency (rad/s) and phase (rad). Use this to pick ω freely, for instance to keep
    /// the propagation speed of a wave that enters shallow water.
    pub fn from_parts(
        amplitude: f64,
        wave_vector: DVec2,
        angular_frequency: f64,
        phase: f64,
    ) -> Result<Self, WaveError> {
        if !(amplitude.is_finite() && amplitude >= 0.0) {
            return Err(WaveError::Amplitude(amplitude));
        }
        if !(wave_vector.x.is_finite() && wave_vector.y.is_finite()) {
            return Err(WaveError::Direction(wave_vector.x, wave_vector.y));
        }
        let k = math::sqrt(wave_vector.x * wave_vector.x + wave_vector.y * wave_vector.y);
        if !(k.is_finite() && k > 0.0) {
            return Err(WaveError::Wavenumber(k));
        }
        if !(angular_frequency.is_finite() && angular_frequency > 0.0) {
            return Err(WaveError::AngularFrequency(angular_frequency));
        }
        if !phase.is_finite() {
            return Err(WaveError::Phase(phase));
        }
        let steepness = k * amplitude;
        if steepness > 1.0 + STEEPNESS_SLACK {
            return Err(WaveError::TooSteep(steepness));
        }
        Ok(Self {
            amplitude,
            wave_vector,
            wavenumber: k,
            angular_frequency,
            phase,
        })
    }

    /// A deep-water wave (Eq. 5) of the given amplitude, wavelength, direction and phase.
    pub fn deep(
        amplitude: f64,
        wavelength: f64,
        direction: DVec2,
        phase: f64,
    ) -> Result<Self, WaveError> {
        WaveDesc {
            amplitude,
            wavelength,
            direction,
            phase,
            depth: Depth::Deep,
        }
        .build()
    }

    /// Amplitude A (m).
    pub fn amplitude(&self) -> f64 {
        self.amplitude
    }
    /// Wave vector k = (k_x, k_z) (rad/m).
    pub fn wave_vector(&self) -> DVec2 {
        self.wave_vector
    }
    /// Wavenumber |k| (rad/m).
    pub fn wavenumber(&self) -> f64 {
        self.wavenumber
    }
    /// Wavelength 2π/|k| (m).
    pub fn wavelength(&self) -> f64 {
        TAU / self.wavenumber
    }
    /// Unit direction of travel k/|k|.
    pub fn direction(&self) -> DVec2 {
        self.wave_vector / self.wavenumber
    }
    /// Angular frequency ω (rad/s).
    pub fn angular_frequency(&self) -> f64 {
        self.angular_frequency
    }
    /// Phase shift Φ (rad).
    pub fn phase(&self) -> f64 {
        self.phase
    }
    /// Steepness |k|·A, in [0, 1].
    pub fn steepness(&self) -> f64 {
        self.wavenumber * self.amplitude
    }

    /// The same wave with its amplitude scaled by `factor` (≥ 0), for instance a filtering weight
    /// or a fade; the steepness limit is checked again.
    pub fn scaled(&self, factor: f64) -> Result<Self, WaveError> {
        Self::from_parts(
            self.amplitude * factor,
            self.wave_vector,
            self.angular_frequency,
            self.phase,
        )
    }

    /// The phase k·p₀ − ωt + Φ at rest position `rest` and time `t`, unreduced, in `f64`.
    pub fn phase_at(&self, rest: DVec2, t: f64) -> f64 {
        self.wave_vector.dot(rest) - self.angular_frequency * t + self.phase
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn desc_builds_wave_vector_and_frequency() {
        let w = WaveDesc {
            amplitude: 0.5,
            wavelength: 20.0,
            direction: DVec2::new(3.0, 4.0),
            phase: 0.25,
            depth: Depth::Deep,
        }
        .build()
        .unwrap();
        let k = TAU / 20.0;
        assert!((w.wave_vector() - DVec2::new(0.6 * k, 0.8 * k)).length() < 1e-15);
        assert!((w.angular_frequency() - math::sqrt(9.81 * k)).abs() < 1e-15);
        assert!((w.wavelength() - 20.0).abs() < 1e-12);
    }

    #[test]
    fn steepness_limit() {
        let lambda = 10.0;
        // A = λ/2π is exactly the cusp and accepted.
        assert!(Wave::deep(lambda / TAU, lambda, DVec2::X, 0.0).is_ok());
        // Anything measurably steeper is refused with its steepness.
        match Wave::deep(1.001 * lambda / TAU, lambda, DVec2::X, 0.0) {
            Err(WaveError::TooSteep(s)) => assert!((s - 1.001).abs() < 1e-12),
            other => panic!("expected TooSteep, got {other:?}"),
        }
    }

    #[test]
    fn rejects_non_finite_and_degenerate_input() {
        let ok = Wave::deep(0.1, 10.0, DVec2::X, 0.0).unwrap();
        assert!(Wave::deep(f64::NAN, 10.0, DVec2::X, 0.0).is_err());
        assert!(Wave::deep(-0.1, 10.0, DVec2::X, 0.0).is_err());
        assert!(Wave::deep(0.1, f64::INFINITY, DVec2::X, 0.0).is_err());
        assert!(Wave::deep(0.1, 0.0, DVec2::X, 0.0).is_err());
        assert!(Wave::deep(0.1, 10.0, DVec2::ZERO, 0.0).is_err());
        assert!(Wave::deep(0.1, 10.0, DVec2::new(f64::NAN, 1.0), 0.0).is_err());
        assert!(Wave::deep(0.1, 10.0, DVec2::X, f64::INFINITY).is_err());
        assert!(Wave::from_parts(0.1, ok.wave_vector(), 0.0, 0.0).is_err());
        assert!(ok.scaled(f64::NAN).is_err());
    }
}
