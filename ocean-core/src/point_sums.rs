//! The `f64` sums of a wave set at one point (Eq. 6, 7 and their derivatives): the reference
//! path every `f32` kernel is tested against, and the sums that height queries invert.

use glam::{DVec2, DVec3};

use crate::error::EvalError;
use crate::math;
use crate::phase::reduce_angle_f32;
use crate::sincos::sincos;
use crate::trochoid::{WaveSet, check_time};

/// Surface point from the `f64` reference path.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SampleF64 {
    /// Displaced position minus rest position: (Δx, y, Δz), metres.
    pub displacement: DVec3,
    /// Unit surface normal (y up).
    pub normal: DVec3,
}

/// The running sums of a surface at one point, in `f64` (Eq. 6, 7 and their derivatives).
///
/// `jxx`, `jxz`, `jzz` form the horizontal Jacobian ∂p/∂p₀ of the displaced position with respect
/// to the rest position, and (`sx`, `sz`) the height gradient ∂y/∂p₀; start from
/// [`PointSums::REST`] (the identity and zero) and add wave sets with
/// [`WaveSet::add_sums_f64`].
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct PointSums {
    /// Horizontal displacement along x, metres.
    pub dx: f64,
    /// Height, metres.
    pub y: f64,
    /// Horizontal displacement along z, metres.
    pub dz: f64,
    /// ∂pₓ/∂x₀.
    pub jxx: f64,
    /// ∂pₓ/∂z₀ = ∂p_z/∂x₀.
    pub jxz: f64,
    /// ∂p_z/∂z₀.
    pub jzz: f64,
    /// ∂y/∂x₀.
    pub sx: f64,
    /// ∂y/∂z₀.
    pub sz: f64,
}

impl PointSums {
    /// The sea at rest: no displacement, identity Jacobian, flat.
    pub const REST: Self = Self {
        dx: 0.0,
        y: 0.0,
        dz: 0.0,
        jxx: 1.0,
        jxz: 0.0,
        jzz: 1.0,
        sx: 0.0,
        sz: 0.0,
    };

    /// (Δx, y, Δz).
    pub fn displacement(&self) -> DVec3 {
        DVec3::new(self.dx, self.y, self.dz)
    }

    /// The unit normal ∂p/∂z₀ × ∂p/∂x₀ (y up), or +y where it vanishes (a cusp).
    pub fn normal(&self) -> DVec3 {
        let n = DVec3::new(
            self.sz * self.jxz - self.jzz * self.sx,
            self.jzz * self.jxx - self.jxz * self.jxz,
            self.jxz * self.sx - self.sz * self.jxx,
        );
        let len = math::sqrt(n.length_squared());
        if len > 0.0 { n / len } else { DVec3::Y }
    }

    /// det ∂p/∂p₀: positive where the surface does not fold.
    pub fn jacobian_det(&self) -> f64 {
        self.jxx * self.jzz - self.jxz * self.jxz
    }
}

impl WaveSet {
    /// The `f64` reference: every quantity in double precision with the platform's (or libm's)
    /// `sin` and `cos`. Slow; the oracle the `f32` paths are tested against.
    pub fn sample_f64(&self, rest: DVec2, t: f64) -> Result<SampleF64, EvalError> {
        let mut sums = PointSums::REST;
        self.add_sums_f64(rest, t, [1.0, 0.0], &mut sums)?;
        Ok(SampleF64 {
            displacement: sums.displacement(),
            normal: sums.normal(),
        })
    }

    /// Adds this set's contribution at world rest position `rest` and time `t`, multiplied by
    /// the complex amplitude `mu` = [m cos φ, m sin φ] (amplitudes m·Aᵢ, phases θᵢ + φ; `[1, 0]`
    /// for the plain sum), to `sums`, in `f64`. Several sets, or several layers of
    /// [`crate::layers`], add into the same sums; [`PointSums`] then gives the displacement,
    /// the normal and the horizontal Jacobian that a height query inverts.
    pub fn add_sums_f64(
        &self,
        rest: DVec2,
        t: f64,
        mu: [f64; 2],
        sums: &mut PointSums,
    ) -> Result<(), EvalError> {
        check_time(t)?;
        if !rest.is_finite() {
            return Err(EvalError::Position { index: 0 });
        }
        if !(mu[0].is_finite() && mu[1].is_finite()) {
            return Err(EvalError::Position { index: 0 });
        }
        self.accumulate_sums(rest, t, mu, sums, |theta| {
            (math::sin(theta), math::cos(theta))
        });
        Ok(())
    }

    /// Adds `Σᵢ wᵢ · waveᵢ` at world rest position `rest` and time `t` to `sums`, in `f64`: each
    /// wave scaled by its own real weight, as the lighting paper's filters do (Bruneton et al.
    /// Eq. 2 and 3, weights w_p and w_n). `weights` gives the weights of the first waves, in
    /// order; the waves after its end have weight zero and are not visited, nor are waves of
    /// weight zero, so the cost follows the number of resolved waves (a prefix, when the set is
    /// sorted by wavelength from the longest). Allocates nothing.
    ///
    /// # Errors
    ///
    /// [`EvalError::Position`] for a non-finite position or weight, or more weights than waves;
    /// [`EvalError::Time`] for a non-finite time. `sums` is unchanged on error.
    pub fn add_weighted_sums_f64(
        &self,
        rest: DVec2,
        t: f64,
        weights: impl IntoIterator<Item = f64>,
        sums: &mut PointSums,
    ) -> Result<(), EvalError> {
        self.add_filtered_sums_f64(rest, t, weights, [1.0, 0.0], sums)
    }

    /// [`WaveSet::add_weighted_sums_f64`] with the waves also multiplied by the complex
    /// amplitude `mu` = [m cos φ, m sin φ] (amplitudes m·wᵢ·Aᵢ, phases θᵢ + φ), as
    /// [`WaveSet::add_sums_f64`]: a wave train box's trains at one point, filtered per wave
    /// (local waves on the filtered ocean of Bruneton et al., their §6). With `mu` = [1, 0]
    /// the sums equal those of [`WaveSet::add_weighted_sums_f64`] (up to the sign of zeros).
    ///
    /// # Errors
    ///
    /// As [`WaveSet::add_weighted_sums_f64`], and [`EvalError::Position`] for a non-finite
    /// `mu`. `sums` is unchanged on error.
    pub fn add_filtered_sums_f64(
        &self,
        rest: DVec2,
        t: f64,
        weights: impl IntoIterator<Item = f64>,
        mu: [f64; 2],
        sums: &mut PointSums,
    ) -> Result<(), EvalError> {
        check_time(t)?;
        if !(rest.is_finite() && mu[0].is_finite() && mu[1].is_finite()) {
            return Err(EvalError::Position { index: 0 });
        }
        let mut acc = *sums;
        let mut waves = self.waves.iter().zip(&self.coeffs64);
        for m in weights {
            let Some((w, c64)) = waves.next() else {
                return Err(EvalError::Position { index: 0 });
            };
            if !m.is_finite() {
                return Err(EvalError::Position { index: 0 });
            }
            if m == 0.0 {
                continue;
            }
            let theta = w.phase_at(rest, t);
            let (sin, cos) = (math::sin(theta), math::cos(theta));
            // sin(θ + φ), cos(θ + φ) times |μ| by angle addition; exact for μ = [1, 0].
            let s = m * (sin * mu[0] + cos * mu[1]);
            let c = m * (cos * mu[0] - sin * mu[1]);
            let [a, ahx, ahz, cxx, cxz, czz, gx, gz] = *c64;
            acc.dx -= ahx * s;
            acc.dz -= ahz * s;
            acc.y += a * c;
            acc.jxx -= cxx * c;
            acc.jxz -= cxz * c;
            acc.jzz -= czz * c;
            acc.sx -= gx * s;
            acc.sz -= gz * s;
        }
        *sums = acc;
        Ok(())
    }

    /// [`WaveSet::add_sums_f64`] with each phase reduced in `f64` and its sine and cosine from
    /// the kernel's deterministic [`sincos`] (absolute error ≤ 1.5·10⁻⁷), several times faster:
    /// for point queries, where micrometres do not matter and throughput does. Many evaluations
    /// at one time (a frame's height queries) go faster still through
    /// [`WaveSet::at_time`] and [`crate::TimedWaves`], which reduce Φ − ωt once per wave.
    pub fn add_sums(
        &self,
        rest: DVec2,
        t: f64,
        mu: [f64; 2],
        sums: &mut PointSums,
    ) -> Result<(), EvalError> {
        check_time(t)?;
        if !(rest.is_finite() && mu[0].is_finite() && mu[1].is_finite()) {
            return Err(EvalError::Position { index: 0 });
        }
        self.accumulate_sums(rest, t, mu, sums, |theta| {
            let (s, c) = sincos(reduce_angle_f32(theta));
            (f64::from(s), f64::from(c))
        });
        Ok(())
    }

    #[inline(always)]
    fn accumulate_sums(
        &self,
        rest: DVec2,
        t: f64,
        mu: [f64; 2],
        sums: &mut PointSums,
        sin_cos: impl Fn(f64) -> (f64, f64),
    ) {
        for (w, c64) in self.waves.iter().zip(&self.coeffs64) {
            let (sin, cos) = sin_cos(w.phase_at(rest, t));
            // m sin(θ + φ) and m cos(θ + φ), as in the layers kernel.
            let s = sin * mu[0] + cos * mu[1];
            let c = cos * mu[0] - sin * mu[1];
            let [a, ahx, ahz, cxx, cxz, czz, gx, gz] = *c64;
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
