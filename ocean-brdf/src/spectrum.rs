//! The wave spectrum: Pierson–Moskowitz amplitudes (Eq. 1) with Hasselmann's directional
//! spreading (§3.1, §7.1), sampled into trochoids.
//!
//! The n wavelengths form a geometric progression from λ_min to λ_max (§7.1), sorted from the
//! shortest. Each wave stands for the band of angular frequencies around its own, halfway (in
//! log ω) to its neighbours, and takes that band's energy: A²/2 = S(ω) Δω, so the height
//! variance of the sum is the spectrum's over the band λ_min..λ_max. Directions are drawn from
//! Hasselmann's cos^{2s}(θ/2) spreading around the wind (with s ≥ [`SPREAD_MIN_EXPONENT`]),
//! and phases uniformly, from a PCG32
//! stream seeded by the caller: the same parameters give the same waves on every platform.

use alloc::vec::Vec;
use core::f64::consts::{PI, TAU};

use glam::DVec2;
use ocean_core::{Depth, GRAVITY, Pcg32, WaveDesc, WaveSet};

use crate::error::{BrdfError, check};
use crate::variance::{SlopeVariance, VarianceTable};

/// α of Eq. 1 (Phillips' constant).
pub const PM_ALPHA: f64 = 8.1e-3;
/// β of Eq. 1.
pub const PM_BETA: f64 = 0.74;

/// S(ω) of Eq. 1, m²·s: the Pierson–Moskowitz spectrum of a fully developed sea under a wind of
/// `wind_speed` m/s at 20 m, with ω₀ = g / V₂₀.
pub fn pierson_moskowitz(omega: f64, wind_speed: f64) -> f64 {
    if omega <= 0.0 || wind_speed <= 0.0 {
        return 0.0;
    }
    let w0 = GRAVITY / wind_speed;
    let r = w0 / omega;
    PM_ALPHA * GRAVITY * GRAVITY / libm::pow(omega, 5.0) * libm::exp(-PM_BETA * r * r * r * r)
}

/// The peak angular frequency of Eq. 1, where dS/dω = 0: ω_p = (4β/5)^{1/4} g / V₂₀.
pub fn peak_frequency(wind_speed: f64) -> f64 {
    libm::pow(0.8 * PM_BETA, 0.25) * GRAVITY / wind_speed
}

/// Hasselmann et al. (1980)'s spreading exponent s(ω) of cos^{2s}(θ/2): 6.97 (ω/ω_p)^4.06 below
/// the peak, 9.77 (ω/ω_p)^μ above it with μ = −2.33 − 1.45 (V ω_p / g − 1.17).
pub fn hasselmann_exponent(omega: f64, wind_speed: f64) -> f64 {
    let wp = peak_frequency(wind_speed);
    let r = omega / wp;
    if r <= 1.0 {
        6.97 * libm::pow(r, 4.06)
    } else {
        let mu = -2.33 - 1.45 * (wind_speed * wp / GRAVITY - 1.17);
        9.77 * libm::pow(r, mu)
    }
}

/// The least spreading exponent [`spreading_exponent`] allows.
///
/// Hasselmann's fit was measured up to about three times the peak frequency. Beyond, its s
/// falls towards 0, an isotropic sea, and the short waves that carry most of the slope variance
/// would lose the anisotropy Cox & Munk measured (§3.1): a crosswind to upwind slope variance
/// ratio of about 0.7 (0.0222 / 0.0316 at 10 m/s). For cos^{2s}(θ/2) that ratio is
/// E(sin²θ) / E(cos²θ) = (1 − b₂)/(1 + b₂) with b₂ = E(cos 2θ) = s(s − 1)/((s + 1)(s + 2)),
/// which is 0.70 at s = 2.06; s is held at 2 or more.
pub const SPREAD_MIN_EXPONENT: f64 = 2.0;

/// The spreading exponent used for the waves: [`hasselmann_exponent`], at least
/// [`SPREAD_MIN_EXPONENT`].
pub fn spreading_exponent(omega: f64, wind_speed: f64) -> f64 {
    hasselmann_exponent(omega, wind_speed).max(SPREAD_MIN_EXPONENT)
}

/// What to sample.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SpectrumParams {
    /// Wind speed 20 m above the sea, m/s (V₂₀ of Eq. 1), > 0.
    pub wind_speed: f64,
    /// Wind direction in the (x, z) plane, any non-zero length.
    pub wind_direction: DVec2,
    /// Number of trochoids (the paper uses 60), 1..=1024.
    pub waves: usize,
    /// Shortest wavelength, metres (the paper's demo: 0.02).
    pub min_wavelength: f64,
    /// Longest wavelength, metres (the paper's demo: 30), > `min_wavelength`.
    pub max_wavelength: f64,
    /// Largest steepness k·A of any one wave; longer amplitudes are clamped to it. Each
    /// trochoid must stay below 1 or it loops over itself (Fig. 2). At most 1.
    pub max_steepness: f64,
    /// Seed of the directions and phases.
    pub seed: u64,
}

impl Default for SpectrumParams {
    /// 60 waves from 2 cm to 30 m under a 10 m/s wind along +x, steepness at most 0.5.
    fn default() -> Self {
        Self {
            wind_speed: 10.0,
            wind_direction: DVec2::X,
            waves: 60,
            min_wavelength: 0.02,
            max_wavelength: 30.0,
            max_steepness: 0.5,
            seed: 0,
        }
    }
}

/// A sampled spectrum: its trochoids and the statistics a renderer needs.
#[derive(Clone, Debug)]
pub struct Spectrum {
    params: SpectrumParams,
    wind: DVec2,
    waves: Vec<WaveDesc>,
    clamped: usize,
    variance: VarianceTable,
}

/// Bins of the tabulated inverse CDF of the spreading function.
const SPREAD_BINS: usize = 512;

impl Spectrum {
    /// Samples the spectrum.
    ///
    /// # Errors
    ///
    /// [`BrdfError`] for a parameter that is not finite or out of its range (see
    /// [`SpectrumParams`]).
    pub fn new(params: SpectrumParams) -> Result<Self, BrdfError> {
        check("wind speed", params.wind_speed, 1e-3, 200.0)?;
        let len = params.wind_direction.length();
        if !len.is_finite() || len == 0.0 {
            return Err(BrdfError::NotUnit("wind direction"));
        }
        if params.waves == 0 || params.waves > 1024 {
            return Err(BrdfError::OutOfRange {
                name: "waves",
                value: params.waves as f64,
                min: 1.0,
                max: 1024.0,
            });
        }
        check("min wavelength", params.min_wavelength, 1e-4, 1e5)?;
        check(
            "max wavelength",
            params.max_wavelength,
            params.min_wavelength,
            1e5,
        )?;
        if params.waves > 1 && params.max_wavelength == params.min_wavelength {
            return Err(BrdfError::OutOfRange {
                name: "max wavelength",
                value: params.max_wavelength,
                min: params.min_wavelength,
                max: 1e5,
            });
        }
        check("max steepness", params.max_steepness, 0.0, 1.0)?;
        let wind = params.wind_direction / len;
        let n = params.waves;
        let mut rng = Pcg32::new(params.seed, 0x6f63_6561_6e21);
        // ω of a deep-water wave of length λ: √(g·2π/λ). The band of wave i spans, in log ω,
        // half the step to each neighbour (a lone wave takes no band and gets no energy).
        let ratio = if n > 1 {
            libm::pow(
                params.max_wavelength / params.min_wavelength,
                1.0 / (n - 1) as f64,
            )
        } else {
            1.0
        };
        // ω scales as λ^{-1/2}: the ω ratio between neighbours is ratio^{-1/2}, and a band
        // reaches ratio^{±1/4} around its centre.
        let half = libm::pow(ratio, 0.25);
        let mut waves = Vec::with_capacity(n);
        let mut clamped = 0;
        for i in 0..n {
            let lambda = params.min_wavelength * libm::pow(ratio, i as f64);
            let k = TAU / lambda;
            let omega = libm::sqrt(GRAVITY * k);
            let d_omega = omega * (half - 1.0 / half);
            let mut amplitude =
                libm::sqrt(2.0 * pierson_moskowitz(omega, params.wind_speed) * d_omega);
            if k * amplitude > params.max_steepness {
                amplitude = params.max_steepness / k;
                clamped += 1;
            }
            let theta = sample_spread(&mut rng, spreading_exponent(omega, params.wind_speed));
            let (s, c) = (libm::sin(theta), libm::cos(theta));
            let direction = DVec2::new(wind.x * c - wind.y * s, wind.x * s + wind.y * c);
            let phase = TAU * rng.next_f64();
            waves.push(WaveDesc {
                amplitude,
                wavelength: lambda,
                direction,
                phase,
                depth: Depth::Deep,
            });
        }
        let variance = VarianceTable::new(&waves, wind)?;
        Ok(Self {
            params,
            wind,
            waves,
            clamped,
            variance,
        })
    }

    /// The parameters it was sampled with.
    pub fn params(&self) -> &SpectrumParams {
        &self.params
    }

    /// The unit wind direction in the (x, z) plane.
    pub fn wind(&self) -> DVec2 {
        self.wind
    }

    /// The trochoids, shortest first.
    pub fn waves(&self) -> &[WaveDesc] {
        &self.waves
    }

    /// How many amplitudes [`SpectrumParams::max_steepness`] clamped.
    pub fn clamped(&self) -> usize {
        self.clamped
    }

    /// The trochoids as an `ocean_core` wave set.
    ///
    /// # Errors
    ///
    /// None for a spectrum built by [`Spectrum::new`]; the `Result` is `WaveSet`'s.
    pub fn wave_set(&self) -> Result<WaveSet, ocean_core::WaveError> {
        WaveSet::from_descs(&self.waves)
    }

    /// The slope-variance table of the waves (Eq. 4) in the wind frame.
    pub fn variance(&self) -> &VarianceTable {
        &self.variance
    }

    /// The total slope variance of all waves, along and across the wind.
    pub fn slope_variance(&self) -> SlopeVariance {
        self.variance.total()
    }

    /// Σ A: the largest possible height, and horizontal displacement, of the sum (a bound for
    /// culling and for a projected grid's margins).
    pub fn max_amplitude(&self) -> f64 {
        self.waves.iter().map(|w| w.amplitude).sum()
    }

    /// Σ k·A: below 1, the surface cannot fold over itself whatever the phases.
    pub fn steepness_sum(&self) -> f64 {
        self.waves
            .iter()
            .map(|w| TAU / w.wavelength * w.amplitude)
            .sum()
    }

    /// The mean height of the surface, metres: a trochoid's crests are sharper than its troughs,
    /// and its mean height over x (not over the parameter) is −k·A²/2, so the sea's mean level
    /// sits Σ k·A²/2 below y = 0.
    pub fn mean_height_shift(&self) -> f64 {
        -self
            .waves
            .iter()
            .map(|w| 0.5 * TAU / w.wavelength * w.amplitude * w.amplitude)
            .sum::<f64>()
    }

    /// The variance of the height about its mean, m²: per trochoid the mean of y² over x is
    /// A²/2, less the squared mean (k·A²/2)²; independent waves add.
    pub fn height_variance(&self) -> f64 {
        self.waves
            .iter()
            .map(|w| {
                let m = 0.5 * TAU / w.wavelength * w.amplitude * w.amplitude;
                0.5 * w.amplitude * w.amplitude - m * m
            })
            .sum()
    }
}

/// An angle θ ∈ (−π, π] from the density ∝ cos^{2s}(θ/2), by inversion of its CDF tabulated
/// on [`SPREAD_BINS`] bins (linear within a bin).
fn sample_spread(rng: &mut Pcg32, s: f64) -> f64 {
    let u = rng.next_f64();
    let density = |theta: f64| libm::pow(libm::cos(0.5 * theta).abs(), 2.0 * s);
    let step = TAU / SPREAD_BINS as f64;
    // Trapezoid CDF over the bins; the total normalises it.
    let mut cdf = [0.0f64; SPREAD_BINS + 1];
    let mut prev = density(-PI);
    for b in 0..SPREAD_BINS {
        let next = density(-PI + step * (b + 1) as f64);
        cdf[b + 1] = cdf[b] + 0.5 * (prev + next) * step;
        prev = next;
    }
    let target = u * cdf[SPREAD_BINS];
    let b = cdf.partition_point(|&c| c <= target).clamp(1, SPREAD_BINS) - 1;
    let width = cdf[b + 1] - cdf[b];
    let f = if width > 0.0 {
        (target - cdf[b]) / width
    } else {
        0.5
    };
    -PI + step * (b as f64 + f)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn spread_samples_have_the_circular_moments_of_cos_2s() {
        // For a density ∝ cos^{2s}(θ/2): E[cos θ] = s/(s + 1) and E[cos 2θ] =
        // s(s − 1)/((s + 1)(s + 2)) (Longuet-Higgins et al. 1963). 10 000 draws: the standard
        // error of each mean is below 1/100, so 0.04 is four of them.
        for s in [0.5, 2.0, 10.0, 60.0] {
            let mut rng = Pcg32::new(9, 3);
            let n = 10_000;
            let (mut c1, mut c2) = (0.0, 0.0);
            for _ in 0..n {
                let t = sample_spread(&mut rng, s);
                assert!((-PI..=PI).contains(&t));
                c1 += libm::cos(t);
                c2 += libm::cos(2.0 * t);
            }
            let (c1, c2) = (c1 / n as f64, c2 / n as f64);
            let (e1, e2) = (s / (s + 1.0), s * (s - 1.0) / ((s + 1.0) * (s + 2.0)));
            assert!((c1 - e1).abs() < 0.04, "s = {s}: E[cos θ] {c1} vs {e1}");
            assert!((c2 - e2).abs() < 0.04, "s = {s}: E[cos 2θ] {c2} vs {e2}");
        }
    }

    #[test]
    fn the_floor_gives_cox_and_munks_anisotropy() {
        let s: f64 = 2.06;
        let b2 = s * (s - 1.0) / ((s + 1.0) * (s + 2.0));
        assert!(((1.0 - b2) / (1.0 + b2) - 0.70).abs() < 0.005);
        // Far above the peak Hasselmann's s is below the floor; near it, above.
        let v = 10.0;
        let wp = peak_frequency(v);
        assert!(hasselmann_exponent(20.0 * wp, v) < SPREAD_MIN_EXPONENT);
        assert_eq!(spreading_exponent(20.0 * wp, v), SPREAD_MIN_EXPONENT);
        assert_eq!(
            spreading_exponent(1.2 * wp, v),
            hasselmann_exponent(1.2 * wp, v)
        );
    }
}
