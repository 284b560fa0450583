//! Per-wave filtering from geometry to normals to BRDF (§3.2, Fig. 3).
//!
//! Each trochoid is weighted by how well the screen resolves it: in the displaced positions by
//! w_p = w(N_min, N_max, λ/L), with L the projected grid-cell size (Eq. 2); in the per-pixel
//! normals by w_n = w(N_min, N_max, λ/l), with l the projected pixel size (Eq. 3); what the
//! normals lose goes into the BRDF's slope variance with w_r = 1 − w_n (Eq. 4). A wave shorter
//! than N_min cells (or pixels) is gone from the geometry (or the normals), a wave longer than
//! N_max fully present, and w blends smoothly in between, so nothing pops.

use crate::error::{BrdfError, check};

pub use ocean_core::math::smooth_weight;

/// The N_min and N_max of the weights: how many cells or pixels a wavelength must span to start
/// and to finish appearing.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Filter {
    n_min: f64,
    n_max: f64,
}

impl Default for Filter {
    /// [`Filter::PAPER`].
    fn default() -> Self {
        Self::PAPER
    }
}

impl Filter {
    /// The paper's values, N_min = 1.0 and N_max = 2.5 (§7.1: Nyquist's 2 "gives too much
    /// blur").
    pub const PAPER: Self = Self {
        n_min: 1.0,
        n_max: 2.5,
    };

    /// A filter with the given thresholds, in cells (or pixels) per wavelength.
    ///
    /// # Errors
    ///
    /// [`BrdfError`] unless 0 < `n_min` < `n_max` ≤ 1e6, both finite.
    pub fn new(n_min: f64, n_max: f64) -> Result<Self, BrdfError> {
        check("N_min", n_min, f64::MIN_POSITIVE, 1e6)?;
        check("N_max", n_max, n_min, 1e6)?;
        if n_max == n_min {
            return Err(BrdfError::OutOfRange {
                name: "N_max",
                value: n_max,
                min: n_min,
                max: 1e6,
            });
        }
        Ok(Self { n_min, n_max })
    }

    /// N_min.
    pub fn n_min(&self) -> f64 {
        self.n_min
    }

    /// N_max.
    pub fn n_max(&self) -> f64 {
        self.n_max
    }

    /// The weight of a wave of length `wavelength` seen at a footprint of `size` metres (a grid
    /// cell for w_p, a pixel for w_n): w(N_min, N_max, λ / size). A zero footprint resolves every
    /// wave (weight 1); an infinite one none (weight 0).
    #[inline]
    pub fn weight(&self, wavelength: f64, size: f64) -> f64 {
        if size <= 0.0 {
            return 1.0;
        }
        smooth_weight(self.n_min, self.n_max, wavelength / size)
    }

    /// w_p of Eq. 2 for a projected grid cell of `cell` metres.
    #[inline]
    pub fn position_weight(&self, wavelength: f64, cell: f64) -> f64 {
        self.weight(wavelength, cell)
    }

    /// w_n of Eq. 3 for a projected pixel of `pixel` metres.
    #[inline]
    pub fn normal_weight(&self, wavelength: f64, pixel: f64) -> f64 {
        self.weight(wavelength, pixel)
    }

    /// w_r = 1 − w_n of Eq. 4: the share of a wave that lives in the BRDF.
    #[inline]
    pub fn brdf_weight(&self, wavelength: f64, pixel: f64) -> f64 {
        1.0 - self.normal_weight(wavelength, pixel)
    }

    /// The indices of `wavelengths` (sorted ascending) whose weight at footprint `size` is not
    /// zero: the longest waves, λ > N_min · size. A sum over them gives the same result as over
    /// all waves, which is what makes distant views cheaper (§7.1).
    pub fn resolved(&self, wavelengths: &[f64], size: f64) -> core::ops::Range<usize> {
        let first = wavelengths.partition_point(|&l| self.weight(l, size) == 0.0);
        first..wavelengths.len()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn smooth_weight_is_the_smoothstep_of_the_paper() {
        assert_eq!(smooth_weight(1.0, 2.5, 0.5), 0.0);
        assert_eq!(smooth_weight(1.0, 2.5, 1.0), 0.0);
        assert_eq!(smooth_weight(1.0, 2.5, 2.5), 1.0);
        assert_eq!(smooth_weight(1.0, 2.5, 9.0), 1.0);
        // Midpoint: x̄ = 1/2 gives 3/4 − 2/8 = 1/2; x̄ = 1/3 gives 1/3 − 2/27 = 7/27.
        assert!((smooth_weight(1.0, 2.5, 1.75) - 0.5).abs() < 1e-15);
        assert!((smooth_weight(1.0, 2.5, 1.5) - 7.0 / 27.0).abs() < 1e-15);
        // C¹ at both ends: the slope vanishes (finite differences of 1e-6 give ~1e-12).
        let d = |x: f64| (smooth_weight(1.0, 2.5, x + 1e-6) - smooth_weight(1.0, 2.5, x)) / 1e-6;
        assert!(d(1.0).abs() < 1e-5 && d(2.5 - 1e-6).abs() < 1e-5);
    }

    #[test]
    fn weights_follow_wavelength_over_footprint() {
        let f = Filter::PAPER;
        // A 1 m wave in 0.25 m pixels spans 4 pixels: fully in the normals, not in the BRDF.
        assert_eq!(f.normal_weight(1.0, 0.25), 1.0);
        assert_eq!(f.brdf_weight(1.0, 0.25), 0.0);
        // In 2 m pixels it spans half a pixel: entirely in the BRDF.
        assert_eq!(f.normal_weight(1.0, 2.0), 0.0);
        assert_eq!(f.brdf_weight(1.0, 2.0), 1.0);
        // 1.75 pixels per wavelength: half and half.
        assert!((f.normal_weight(1.75, 1.0) - 0.5).abs() < 1e-15);
        assert_eq!(f.position_weight(3.0, 0.0), 1.0);
        assert_eq!(f.position_weight(3.0, f64::INFINITY), 0.0);
    }

    #[test]
    fn resolved_waves_are_a_suffix_with_every_non_zero_weight() {
        let f = Filter::PAPER;
        let lambdas: [f64; 8] = [0.02, 0.05, 0.3, 0.99, 1.0, 1.01, 4.0, 30.0];
        let r = f.resolved(&lambdas, 1.0);
        assert_eq!(r, 5..8, "λ > N_min·size = 1 m");
        for (i, &l) in lambdas.iter().enumerate() {
            assert_eq!(f.weight(l, 1.0) > 0.0, r.contains(&i), "wave {i}");
        }
        assert_eq!(f.resolved(&lambdas, 100.0), 8..8);
        assert_eq!(f.resolved(&lambdas, 0.0), 0..8);
    }

    #[test]
    fn bad_thresholds_are_refused() {
        assert!(Filter::new(1.0, 2.5).is_ok());
        assert!(Filter::new(2.0, 2.0).is_err());
        assert!(Filter::new(2.5, 1.0).is_err());
        assert!(Filter::new(0.0, 1.0).is_err());
        assert!(Filter::new(f64::NAN, 1.0).is_err());
        assert!(Filter::new(1.0, f64::INFINITY).is_err());
    }
}
