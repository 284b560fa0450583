//! Trains a grid can carry: per-train filtering of the geometry on the grid's cell.
//!
//! A grid of spacing s samples a train of wavelength λ at λ/s points per wavelength. Below 2
//! (Nyquist) the mesh aliases it into a longer wave that is not there; at a few points per
//! wavelength the triangles between the vertices cut its crests and troughs by about
//! A·(1 − cos(π·s/λ)), 29 % of the amplitude at 4 cells. As the lighting paper filters each
//! wave of the sea by the footprint of a projected grid cell (Bruneton, Neyret & Holzschuch
//! §3.2, w_p of Eq. 2), a scene weights each train's amplitude in the geometry by
//! w_p = w(N_min, N_max, λ/s), the smooth step of `ocean_core::math::smooth_weight`: gone below
//! N_min cells, whole from N_max, blended between so that nothing pops. The frame's grid, its
//! vertex normals, both height queries and the GPU twins all see the filtered trains.
//!
//! What the geometry loses goes to the BRDF, as Eq. 4's slope variance does in the lighting
//! paper: [`crate::scene::FrameStats::filtered_slope_variance`] reports
//! Σ ((1 − w_p)·k·A)²/2 over the filtered trains, the slope variance of the waves left out
//! where a box's modulation is 1, for a renderer to add to its roughness (or to resolve per
//! pixel, as `ocean_gpu::OceanRenderer` does with its own footprints).

use crate::error::WtbError;

/// The thresholds of the per-train geometry filter, in grid cells per wavelength (see the
/// [module documentation](self)).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct TrainFilter {
    min_cells: f64,
    max_cells: f64,
}

impl Default for TrainFilter {
    /// [`TrainFilter::DEFAULT`].
    fn default() -> Self {
        Self::DEFAULT
    }
}

impl TrainFilter {
    /// Trains shorter than 2 cells (Nyquist) are left out, trains longer than 4 cells kept
    /// whole: at 4 cells the mesh still holds 71 % of a crest's height between vertices.
    pub const DEFAULT: Self = Self {
        min_cells: 2.0,
        max_cells: 4.0,
    };

    /// A filter that leaves out trains shorter than `min_cells` grid cells and keeps those
    /// longer than `max_cells` whole.
    ///
    /// # Errors
    ///
    /// [`WtbError::NotFinite`] or [`WtbError::OutOfRange`] unless
    /// 0 ≤ `min_cells` < `max_cells` ≤ 10⁶.
    pub fn new(min_cells: f64, max_cells: f64) -> Result<Self, WtbError> {
        let min_cells = crate::grid::check_range("filter min cells", min_cells, 0.0, 1e6)?;
        let max_cells = crate::grid::check_range("filter max cells", max_cells, 0.0, 1e6)?;
        if max_cells <= min_cells {
            return Err(WtbError::OutOfRange {
                name: "filter max cells",
                value: max_cells,
                min: min_cells,
                max: 1e6,
            });
        }
        Ok(Self {
            min_cells,
            max_cells,
        })
    }

    /// N_min, cells.
    pub fn min_cells(&self) -> f64 {
        self.min_cells
    }

    /// N_max, cells.
    pub fn max_cells(&self) -> f64 {
        self.max_cells
    }

    /// w_p for a train of `wavelength` metres on a grid of `spacing` metres.
    pub fn weight(&self, wavelength: f64, spacing: f64) -> f64 {
        ocean_core::math::smooth_weight(self.min_cells, self.max_cells, wavelength / spacing)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn weights_follow_cells_per_wavelength() {
        let f = TrainFilter::DEFAULT;
        // On a 0.5 m grid: 1 m is 2 cells (gone), 2 m is 4 cells (whole), 1.5 m is the middle
        // of the smooth step (x̄ = 1/2: 3/4 − 2/8 = 1/2).
        assert_eq!(f.weight(0.9, 0.5), 0.0);
        assert_eq!(f.weight(1.0, 0.5), 0.0);
        assert_eq!(f.weight(2.0, 0.5), 1.0);
        assert!((f.weight(1.5, 0.5) - 0.5).abs() < 1e-15);
        assert!(TrainFilter::new(3.0, 3.0).is_err());
        assert!(TrainFilter::new(f64::NAN, 3.0).is_err());
        assert!(TrainFilter::new(-1.0, 3.0).is_err());
        assert_eq!(TrainFilter::new(1.0, 2.5).unwrap().max_cells(), 2.5);
    }
}
