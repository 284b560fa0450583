//! A wave set frozen at one instant, for many point evaluations (height queries).

// Lane loops index several arrays in step; that indexed shape is what LLVM vectorises.
#![allow(clippy::needless_range_loop)]
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
use crate::phase::{reduce_angle, reduce_angle_f32, reduce_angle_fast};
use crate::point_sums::PointSums;
use crate::sincos::sincos;
use crate::trochoid::{WaveSet, check_time};

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
    /// error: this is the inner loop of queries whose inputs were checked once). Nothing is
    /// added where `mu` is zero.
    #[inline]
    pub fn add_sums(&self, rest: DVec2, mu: [f64; 2], sums: &mut PointSums) {
        let mut lanes = LaneSums::<1>::REST;
        lanes.set(0, sums);
        self.add_sums_lanes(&[rest.x], &[rest.y], &[mu[0]], &[mu[1]], &mut lanes);
        *sums = lanes.get(0);
    }

    /// [`TimedWaves::add_sums`] for `Q` points at once, lane `l` at rest position
    /// (`x[l]`, `z[l]`) with amplitude (`mu_re[l]`, `mu_im[l]`). Each lane performs exactly
    /// the operations of [`TimedWaves::add_sums`] (which is this with one lane), so its bits
    /// do not depend on `Q` or on its neighbours; the lanes are written element-wise for
    /// LLVM to vectorise. Lanes whose `mu` is zero are left as they are.
    #[inline(always)]
    pub fn add_sums_lanes<const Q: usize>(
        &self,
        x: &[f64; Q],
        z: &[f64; Q],
        mu_re: &[f64; Q],
        mu_im: &[f64; Q],
        sums: &mut LaneSums<Q>,
    ) {
        let mut live = [false; Q];
        for l in 0..Q {
            live[l] = mu_re[l] != 0.0 || mu_im[l] != 0.0;
        }
        if !live.iter().any(|&b| b) {
            return;
        }
        for w in &self.waves {
            let mut theta = [0.0f64; Q];
            for l in 0..Q {
                theta[l] = w.k.x * x[l] + w.k.y * z[l] + w.offset;
            }
            let phase = reduce_lanes(&theta);
            let mut sin = [0.0f64; Q];
            let mut cos = [0.0f64; Q];
            for l in 0..Q {
                let (s, c) = sincos(phase[l]);
                (sin[l], cos[l]) = (f64::from(s), f64::from(c));
            }
            let [a, ahx, ahz, cxx, cxz, czz, gx, gz] = w.c;
            for l in 0..Q {
                // m sin(θ + φ) and m cos(θ + φ), as in the layers kernel.
                let s = sin[l] * mu_re[l] + cos[l] * mu_im[l];
                let c = cos[l] * mu_re[l] - sin[l] * mu_im[l];
                let on = live[l];
                let pick = |new: f64, old: f64| if on { new } else { old };
                sums.dx[l] = pick(sums.dx[l] - ahx * s, sums.dx[l]);
                sums.dz[l] = pick(sums.dz[l] - ahz * s, sums.dz[l]);
                sums.y[l] = pick(sums.y[l] + a * c, sums.y[l]);
                sums.jxx[l] = pick(sums.jxx[l] - cxx * c, sums.jxx[l]);
                sums.jxz[l] = pick(sums.jxz[l] - cxz * c, sums.jxz[l]);
                sums.jzz[l] = pick(sums.jzz[l] - czz * c, sums.jzz[l]);
                sums.sx[l] = pick(sums.sx[l] - gx * s, sums.sx[l]);
                sums.sz[l] = pick(sums.sz[l] - gz * s, sums.sz[l]);
            }
        }
    }
}

/// [`reduce_angle_f32`] of every lane: its fast path element-wise, and the lanes beyond that
/// path's range (phases of over 10¹⁵ turns, which a query meets only at absurd times far from
/// the grid's phase origin) redone by [`reduce_angle_f32`] itself, so each lane's bits are
/// those of [`reduce_angle_f32`].
#[inline(always)]
fn reduce_lanes<const Q: usize>(theta: &[f64; Q]) -> [f32; Q] {
    let mut out = [0.0f32; Q];
    let mut slow = false;
    for l in 0..Q {
        let (r, fast) = reduce_angle_fast(theta[l]);
        out[l] = r as f32;
        slow |= !fast;
    }
    if slow {
        for l in 0..Q {
            out[l] = reduce_angle_f32(theta[l]);
        }
    }
    out
}

/// Sums for `Q` points, lane by lane: [`PointSums`] as a structure of arrays, for
/// [`TimedWaves::add_sums_lanes`].
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct LaneSums<const Q: usize> {
    /// [`PointSums::dx`] per lane.
    pub dx: [f64; Q],
    /// [`PointSums::y`] per lane.
    pub y: [f64; Q],
    /// [`PointSums::dz`] per lane.
    pub dz: [f64; Q],
    /// [`PointSums::jxx`] per lane.
    pub jxx: [f64; Q],
    /// [`PointSums::jxz`] per lane.
    pub jxz: [f64; Q],
    /// [`PointSums::jzz`] per lane.
    pub jzz: [f64; Q],
    /// [`PointSums::sx`] per lane.
    pub sx: [f64; Q],
    /// [`PointSums::sz`] per lane.
    pub sz: [f64; Q],
}

impl<const Q: usize> LaneSums<Q> {
    /// Every lane at rest ([`PointSums::REST`]).
    pub const REST: Self = Self {
        dx: [0.0; Q],
        y: [0.0; Q],
        dz: [0.0; Q],
        jxx: [1.0; Q],
        jxz: [0.0; Q],
        jzz: [1.0; Q],
        sx: [0.0; Q],
        sz: [0.0; Q],
    };

    /// Lane `l`'s sums.
    #[inline]
    pub fn get(&self, l: usize) -> PointSums {
        PointSums {
            dx: self.dx[l],
            y: self.y[l],
            dz: self.dz[l],
            jxx: self.jxx[l],
            jxz: self.jxz[l],
            jzz: self.jzz[l],
            sx: self.sx[l],
            sz: self.sz[l],
        }
    }

    /// Sets lane `l` to `s`.
    #[inline]
    pub fn set(&mut self, l: usize, s: &PointSums) {
        self.dx[l] = s.dx;
        self.y[l] = s.y;
        self.dz[l] = s.dz;
        self.jxx[l] = s.jxx;
        self.jxz[l] = s.jxz;
        self.jzz[l] = s.jzz;
        self.sx[l] = s.sx;
        self.sz[l] = s.sz;
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
