//! Slope variances of the unresolved waves (Eq. 4, Appendix A, §5.1, §7.1).
//!
//! The waves a pixel cannot show in its normal are summed into an elliptical Gaussian slope
//! distribution whose variances, along the wind and across it, are the sums of the trochoids'
//! own slope variances (central limit theorem, §3.2). A trochoid of steepness kA has slope
//! variance 1 − √(1 − k²A²) (Appendix A), shared between the two axes as k_x²/|k|² and
//! k_y²/|k|².

use alloc::vec::Vec;

use glam::DVec2;
use ocean_core::{Wave, WaveDesc};

use crate::error::BrdfError;
use crate::filter::Filter;

/// Slope variance of one trochoid of steepness `ka` = k·A ∈ [0, 1] (Appendix A):
/// 1 − √(1 − k²A²), written as k²A² / (1 + √(1 − k²A²)) to keep its digits when kA is small
/// (the variance is then ≈ k²A²/2, a sine's).
#[inline]
pub fn trochoid_slope_variance(ka: f64) -> f64 {
    let s = ka * ka;
    s / (1.0 + libm::sqrt((1.0 - s).max(0.0)))
}

/// Slope variances along the two axes of a frame: σ_x² along the wind, σ_y² across it.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct SlopeVariance {
    /// σ_x², along the wind.
    pub x: f64,
    /// σ_y², across the wind.
    pub y: f64,
}

impl SlopeVariance {
    /// Both variances raised to at least `min` (see [`SUN_MIN_VARIANCE`]).
    pub fn at_least(self, min: f64) -> Self {
        Self {
            x: self.x.max(min),
            y: self.y.max(min),
        }
    }

    /// The sum of two variances (independent waves add, §3.2 and §6's local waves).
    pub fn plus(self, other: Self) -> Self {
        Self {
            x: self.x + other.x,
            y: self.y + other.y,
        }
    }
}

/// The Sun's mean angular radius, radians (0.2666°).
pub const SUN_ANGULAR_RADIUS: f64 = 4.653e-3;

/// The smallest slope variance Eq. 15 is evaluated with, so that a flat sea reflects the Sun as
/// a disc rather than a point (§5.1).
///
/// A facet tilted by δ turns the reflected ray by 2δ, so the solar disc of radius ρ seen in a
/// mirror corresponds to facet slopes within ρ/2. A uniform disc of radius R has a variance of
/// R²/4 along each axis; matched to a Gaussian, σ² = (ρ/2)²/4 = ρ²/16 ≈ 1.35·10⁻⁶.
pub const SUN_MIN_VARIANCE: f64 = SUN_ANGULAR_RADIUS * SUN_ANGULAR_RADIUS / 16.0;

/// One wave's share of Eq. 4 in the frame of the unit `wind` direction: its steepness k·A
/// (clamped to 1, the trochoid's limit) and `(k̂·wind)²`, the part of its slope variance
/// [`trochoid_slope_variance`]`(w k·A)` that lies along the wind (the rest lies across it).
pub fn wave_variance_term(wave: &Wave, wind: DVec2) -> (f64, f64) {
    let k = wave.wave_vector();
    let m = wave.wavenumber();
    let along = k.dot(wind) / m;
    ((m * wave.amplitude()).min(1.0), (along * along).min(1.0))
}

/// One wave's share of the variance, precomputed.
#[derive(Clone, Copy, Debug, PartialEq)]
struct Term {
    wavelength: f64,
    /// k·A.
    ka: f64,
    /// k_x²/|k|² in the wind frame (k_y²/|k|² is 1 minus it).
    cos2: f64,
}

impl Term {
    fn variance(&self, w: f64) -> SlopeVariance {
        let v = trochoid_slope_variance(self.ka * w);
        SlopeVariance {
            x: v * self.cos2,
            y: v * (1.0 - self.cos2),
        }
    }
}

/// The waves of a spectrum, sorted by wavelength, with their total slope variance: Eq. 4 for
/// any pixel size at a cost that follows the number of waves a pixel resolves (§7.1).
#[derive(Clone, Debug, PartialEq)]
pub struct VarianceTable {
    terms: Vec<Term>,
    wavelengths: Vec<f64>,
    total: SlopeVariance,
}

impl VarianceTable {
    /// The table of `waves` in the frame of `wind` (any non-zero (x, z) direction).
    ///
    /// # Errors
    ///
    /// [`BrdfError`] for a wind direction that is zero or not finite, or a wave that is not
    /// valid (see [`WaveDesc::build`]).
    pub fn new(waves: &[WaveDesc], wind: DVec2) -> Result<Self, BrdfError> {
        let len = wind.length();
        if !len.is_finite() || len == 0.0 {
            return Err(BrdfError::NotUnit("wind direction"));
        }
        let wind = wind / len;
        let mut terms = Vec::with_capacity(waves.len());
        for d in waves {
            let wave = d.build().map_err(|_| BrdfError::NotFinite("wave"))?;
            let (ka, cos2) = wave_variance_term(&wave, wind);
            terms.push(Term {
                wavelength: core::f64::consts::TAU / wave.wavenumber(),
                ka,
                cos2,
            });
        }
        terms.sort_by(|a, b| a.wavelength.total_cmp(&b.wavelength));
        let total = terms
            .iter()
            .fold(SlopeVariance::default(), |s, t| s.plus(t.variance(1.0)));
        let wavelengths = terms.iter().map(|t| t.wavelength).collect();
        Ok(Self {
            terms,
            wavelengths,
            total,
        })
    }

    /// The slope variance of every wave (w_r = 1 for all).
    pub fn total(&self) -> SlopeVariance {
        self.total
    }

    /// The wavelengths, ascending.
    pub fn wavelengths(&self) -> &[f64] {
        &self.wavelengths
    }

    /// Eq. 4: the slope variance of what a pixel of `pixel` metres does not resolve, each wave
    /// weighted by w_r = 1 − w_n. Computed as the total minus the resolved part (§7.1): only the
    /// waves with w_n > 0 are visited. Rounding can leave the difference a few ulps below zero
    /// when everything is resolved; it is clamped at 0.
    ///
    /// §7.1 is a way of evaluating Eq. 4, not another model: "we also evaluate Eq. 4 by
    /// subtracting from the total variance ... the variance of the resolved waves". So the part
    /// subtracted for a wave is what Eq. 4 takes away from it, var(A) − var(w_r A), and the
    /// result is Eq. 4's Σ var(w_r A) to rounding ([`VarianceTable::unresolved_direct`]). A
    /// partly resolved wave then appears as var(w_n A) in the normals and var(w_r A) in the
    /// BRDF, less than its var(A) (the two parts are one wave, fully correlated); subtracting
    /// var(w_n A) instead would keep the total but is not Eq. 4 (for small slopes it amounts to
    /// w_r = √(1 − w_n²) instead of 1 − w_n), so it is not done.
    pub fn unresolved(&self, filter: &Filter, pixel: f64) -> SlopeVariance {
        let mut v = self.total;
        for t in &self.terms[filter.resolved(&self.wavelengths, pixel)] {
            let (all, left) = (
                t.variance(1.0),
                t.variance(filter.brdf_weight(t.wavelength, pixel)),
            );
            v.x -= all.x - left.x;
            v.y -= all.y - left.y;
        }
        SlopeVariance {
            x: v.x.max(0.0),
            y: v.y.max(0.0),
        }
    }

    /// The slope variances of the waves that a pixel of `pixel` metres resolves in its normal
    /// (Eq. 3) but a grid cell of `cell` metres does not resolve in its geometry (Eq. 2): each
    /// wave with the weight `w_n − w_p` by which the pixel's normal differs from the normal of
    /// the displaced grid. These are the slopes of Eq. 3's normal relative to the geometry's,
    /// which the geometry does not mask (§3.2, "the apparent normals become wrong"); see
    /// [`crate::sea::visible_normal`]. Only the waves with `w_n > 0` are visited (the weights
    /// are zero elsewhere), so the cost follows the resolved waves as Eq. 4's does (§7.1).
    pub fn normal_only(&self, filter: &Filter, pixel: f64, cell: f64) -> SlopeVariance {
        self.terms[filter.resolved(&self.wavelengths, pixel)]
            .iter()
            .fold(SlopeVariance::default(), |s, t| {
                let w = filter.normal_weight(t.wavelength, pixel)
                    - filter.position_weight(t.wavelength, cell);
                s.plus(t.variance(w.max(0.0)))
            })
    }

    /// Eq. 4 for the waves with their amplitudes scaled by `scale` ∈ [0, 1], summed directly:
    /// for local waves (§6) whose amplitude varies over the sea, such as wave trains modulated
    /// by a wave train box's `|μ|`. `scale = 1` is [`VarianceTable::unresolved_direct`].
    pub fn unresolved_scaled(&self, filter: &Filter, pixel: f64, scale: f64) -> SlopeVariance {
        let scale = if scale.is_nan() {
            0.0
        } else {
            scale.clamp(0.0, 1.0)
        };
        self.terms.iter().fold(SlopeVariance::default(), |s, t| {
            s.plus(t.variance(filter.brdf_weight(t.wavelength, pixel) * scale))
        })
    }

    /// Eq. 4 summed over every wave, as printed: the reference for [`VarianceTable::unresolved`].
    pub fn unresolved_direct(&self, filter: &Filter, pixel: f64) -> SlopeVariance {
        self.terms.iter().fold(SlopeVariance::default(), |s, t| {
            s.plus(t.variance(filter.brdf_weight(t.wavelength, pixel)))
        })
    }
}
