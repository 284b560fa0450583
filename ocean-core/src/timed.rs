//! A wave set frozen at one instant, for many point evaluations (height queries).
//!
//! [`WaveSet::add_sums`] forms each phase θ = k·p₀ − ωt + Φ (Eq. 6, 7) and checks its
//! arguments on every call. A height query calls it a few times per Newton step for every
//! layer, always at the same t, so [`TimedWaves`] does the time-dependent half once: it keeps
//! Φ − ωt reduced modulo 2π in `f64` per wave, and an evaluation is k·p₀ plus that offset,
//! reduced again, then the kernel's [`sincos`]. The result differs from
//! [`WaveSet::add_sums`] only by the rounding of the phase's sum (below 10⁻¹⁵ rad at the
//! phases a grid holds), far below the `f32` sine's own error.

use alloc::vec::Vec;

use glam::DVec2;

use crate::error::EvalError;
use crate::phase::{reduce_angle, reduce_angle_f32};
use crate::sincos::sincos;
use crate::trochoid::{PointSums, WaveSet, check_time};

/// One wave at one instant.
#[derive(Clone, Copy, Debug, PartialEq)]
struct TimedWave {
    k: DVec2,
    /// Φ − ωt, reduced to [-π, π].
    offset: f64,
    /// The wave's `f64` constants, as [`WaveSet`] keeps them.
    c: [f64; 8],
}

/// A [`WaveSet`] at a fixed time: see the module documentation.
#[derive(Clone, Debug, PartialEq)]
pub struct TimedWaves {
    waves: Vec<TimedWave>,
}

impl WaveSet {
    /// This set at time `t` (seconds), for [`TimedWaves::add_sums`].
    ///
    /// # Errors
    ///
    /// [`EvalError::Time`] for a non-finite `t`.
    pub fn at_time(&self, t: f64) -> Result<TimedWaves, EvalError> {
        check_time(t)?;
        Ok(TimedWaves {
            waves: self
                .waves()
                .iter()
                .zip(self.coeffs_f64())
                .map(|(w, c)| TimedWave {
                    k: w.wave_vector(),
                    offset: reduce_angle(w.phase_at(DVec2::ZERO, t)),
                    c: *c,
                })
                .collect(),
        })
    }
}

impl TimedWaves {
    /// Adds the set's contribution at world rest position `rest`, multiplied by the complex
    /// amplitude `mu` = [m cos φ, m sin φ], to `sums`: [`WaveSet::add_sums`] at this set's
    /// time. The caller passes finite values (a non-finite one gives NaN sums, not an
    /// error: this is the inner loop of queries whose inputs were checked once).
    #[inline]
    pub fn add_sums(&self, rest: DVec2, mu: [f64; 2], sums: &mut PointSums) {
        for w in &self.waves {
            let (sin, cos) = sincos(reduce_angle_f32(w.k.dot(rest) + w.offset));
            let (sin, cos) = (f64::from(sin), f64::from(cos));
            // m sin(θ + φ) and m cos(θ + φ), as in the layers kernel.
            let s = sin * mu[0] + cos * mu[1];
            let c = cos * mu[0] - sin * mu[1];
            let [a, ahx, ahz, cxx, cxz, czz, gx, gz] = w.c;
            sums.dx -= ahx * s;
            sums.dz -= ahz * s;
            sums.y += a * c;
            sums.jxx -= cxx * c;
            sums.jxz -= cxz * c;
            sums.jzz -= czz * c;
            sums.sx -= gx * s;
            sums.sz -= gz * s;
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::dispersion::Depth;
    use crate::wave::WaveDesc;

    fn set() -> WaveSet {
        let w = |amplitude, wavelength, dir: f64, phase| {
            WaveDesc {
                amplitude,
                wavelength,
                direction: DVec2::new(dir.cos(), dir.sin()),
                phase,
                depth: Depth::Deep,
            }
            .build()
            .unwrap()
        };
        WaveSet::new(&[w(0.4, 12.0, 0.3, 0.5), w(0.15, 4.5, 2.0, -1.0)]).unwrap()
    }

    #[test]
    fn matches_the_per_call_sums() {
        // The same sums as WaveSet::add_sums to within the phase's rounding: at |θ| ≈ 10⁵ rad
        // (1e4 s, 5 km out) an f64 ulp of θ is 1.5e-11 rad, so 1e-9 of the amplitudes bounds it.
        let s = set();
        for &(t, x, z) in &[(0.0, 0.0, 0.0), (37.5, 12.25, -3.5), (1.0e4, 5.0e3, -2.0e3)] {
            let timed = s.at_time(t).unwrap();
            let rest = DVec2::new(x, z);
            let mu = [0.8, -0.3];
            let mut want = PointSums::REST;
            s.add_sums(rest, t, mu, &mut want).unwrap();
            let mut got = PointSums::REST;
            timed.add_sums(rest, mu, &mut got);
            for (a, b) in [
                (got.dx, want.dx),
                (got.y, want.y),
                (got.dz, want.dz),
                (got.jxx, want.jxx),
                (got.jxz, want.jxz),
                (got.jzz, want.jzz),
                (got.sx, want.sx),
                (got.sz, want.sz),
            ] {
                assert!((a - b).abs() <= 1e-9, "t {t} at ({x}, {z}): {a} vs {b}");
            }
        }
    }

    #[test]
    fn refuses_a_non_finite_time() {
        assert!(matches!(set().at_time(f64::NAN), Err(EvalError::Time(t)) if t.is_nan()));
        assert!(matches!(
            set().at_time(f64::INFINITY),
            Err(EvalError::Time(_))
        ));
    }
}
