//! Local waves on the filtered open sea (Bruneton, Neyret & Holzschuch 2010, §6): wave trains
//! whose amplitude and phase vary over the sea, such as the trains of wave train boxes near a
//! shore, lit by the same model as the open sea's spectrum.
//!
//! §6 asks only that the local waves' wavelengths and slope variances be known. A train of a
//! wave train box is a trochoid of known wavelength multiplied, at each point, by the box's
//! complex amplitude μ = m·e^{iφ} (Yrjölä & Larsson Eq. 6, 7; `ocean_core::layers`). So each
//! train is filtered like a spectrum wave, by the weights of §3.2 for the footprint at hand:
//! - Eq. 2 (geometry): the train's displacement times w_p and μ;
//! - Eq. 3 (normals): its derivatives times w_n and μ, added to the open sea's sums (Eq. 3 is
//!   linear in the waves' derivatives; μ is taken as locally constant, as the wave train
//!   evaluation does);
//! - Eq. 4 (BRDF): the slope variance of a trochoid of steepness k·A·m·w_r, added to the open
//!   sea's (variances of independent waves add).
//!
//! The open sea's own waves are multiplied by an amplitude factor s ∈ [0, 1] given over the same
//! grid, so that the scene can let the wave trains take over where the open sea's deep-water
//! spectrum does not apply (over a shelf, on land). With s, the open sea contributes s times its
//! displacement and derivatives and s² times its variance (the small-slope form of Appendix A's
//! `1 − √(1 − s²k²A²)`; within 2 % of it for k·A ≤ 0.3).
//!
//! μ and s are given at the points of a regular grid (a wave train box scene's water grid) and
//! read bilinearly between them; outside the grid μ is 0 and s is 1, so the open sea resumes.
//! This is the CPU twin of the local waves of `ocean_gpu::OceanRenderer`.

use alloc::vec;
use alloc::vec::Vec;

use glam::{DVec2, DVec3};
use ocean_core::{Modulation, PointSums, WaveSet};

use crate::error::{BrdfError, check};
use crate::filter::Filter;
use crate::surface::{FilteredSurface, PixelSurface};
use crate::variance::{SlopeVariance, trochoid_slope_variance, wave_variance_term};

/// Most wave sets (boxes) one [`LocalWaves`] holds: the GPU keeps one texture layer per set
/// plus one for the open sea's factor, within WebGPU's guaranteed 256 array layers.
pub const MAX_LOCAL_SETS: usize = 255;

/// Most trains over all sets (one texel column each on the GPU).
pub const MAX_LOCAL_TRAINS: usize = 4096;

/// One modulated wave set: its trains and μ at every grid point.
#[derive(Clone, Debug)]
struct LocalSet {
    waves: WaveSet,
    /// Per train: (k·A clamped to 1, (k̂·wind)²), `wave_variance_term`.
    terms: Vec<(f64, f64)>,
    /// μ = [m cos φ, m sin φ] at every grid point, row-major, 0 outside the set's rectangle.
    mu: Vec<[f32; 2]>,
}

/// Local waves over a grid (see the module documentation).
#[derive(Clone, Debug)]
pub struct LocalWaves {
    origin: DVec2,
    spacing: f64,
    nx: usize,
    nz: usize,
    wind: DVec2,
    filter: Filter,
    /// The open sea's amplitude factor at every grid point, row-major.
    open_scale: Vec<f32>,
    sets: Vec<LocalSet>,
}

/// What the open sea with its local waves is at one point, for one pair of footprints.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct LocalPoint {
    /// Eq. 2: the displaced position (world) of the rest point for the grid-cell footprint.
    pub position: DVec3,
    /// Eq. 3: the unit normal for the pixel footprint.
    pub normal: DVec3,
    /// Eq. 4: the slope variances of what the pixel footprint does not resolve, along the
    /// open sea's wind and across it.
    pub variance: SlopeVariance,
    /// The unit normal of the displaced geometry of `position` (Eq. 2's waves, open sea and
    /// trains, weighted by `w_p` for the grid-cell footprint).
    pub geometry_normal: DVec3,
    /// The slope variances of what the normal resolves and the geometry does not (weights
    /// `w_n − w_p`): s² times the open sea's
    /// ([`FilteredSurface::normal_only_variance`]) plus each train's, of steepness
    /// k·A·|μ|·(w_n − w_p).
    pub normal_only: SlopeVariance,
}

impl LocalPoint {
    /// What Algorithm 5.1 takes of this point (see [`PixelSurface::visible_normal`]).
    pub fn pixel(&self) -> PixelSurface {
        PixelSurface {
            normal: self.normal,
            geometry_normal: self.geometry_normal,
            variance: self.variance,
            normal_only: self.normal_only,
        }
    }
}

impl LocalWaves {
    /// No local waves yet over an `nx × nz` grid of points `spacing` metres apart, point (0, 0)
    /// at world `(x, z)` = `origin`; variances measured along `wind` (the open sea's, so both
    /// are in one frame); trains filtered by `filter` (the open sea's). The open sea's factor
    /// starts at 1 everywhere.
    ///
    /// # Errors
    ///
    /// [`BrdfError::NotFinite`] for a non-finite origin; [`BrdfError::OutOfRange`] for a
    /// spacing that is not positive and finite or an empty grid, or one over 2²⁴ points a side;
    /// [`BrdfError::NotUnit`] for a zero or non-finite wind.
    pub fn new(
        origin: DVec2,
        spacing: f64,
        nx: usize,
        nz: usize,
        wind: DVec2,
        filter: Filter,
    ) -> Result<Self, BrdfError> {
        if !origin.is_finite() {
            return Err(BrdfError::NotFinite("local grid origin"));
        }
        check("local grid spacing", spacing, f64::MIN_POSITIVE, f64::MAX)?;
        const MAX_SIDE: f64 = (1u32 << 24) as f64;
        check("local grid columns", nx as f64, 1.0, MAX_SIDE)?;
        check("local grid rows", nz as f64, 1.0, MAX_SIDE)?;
        let len = wind.length();
        if !len.is_finite() || len == 0.0 {
            return Err(BrdfError::NotUnit("wind direction"));
        }
        Ok(Self {
            origin,
            spacing,
            nx,
            nz,
            wind: wind / len,
            filter,
            open_scale: vec![1.0; nx * nz],
            sets: Vec::new(),
        })
    }

    /// The grid: point (0, 0)'s world `(x, z)`, the spacing, and the points per row and rows.
    pub fn grid(&self) -> (DVec2, f64, usize, usize) {
        (self.origin, self.spacing, self.nx, self.nz)
    }

    /// The unit wind direction the variances are measured along.
    pub fn wind(&self) -> DVec2 {
        self.wind
    }

    /// The filter of the trains.
    pub fn filter(&self) -> &Filter {
        &self.filter
    }

    /// The open sea's amplitude factor at every grid point, row-major.
    pub fn open_scale(&self) -> &[f32] {
        &self.open_scale
    }

    /// Sets the open sea's amplitude factor at every grid point (row-major, one per point,
    /// each in `[0, 1]`).
    ///
    /// # Errors
    ///
    /// [`BrdfError::OutOfRange`] for a length other than the grid's or a value outside
    /// `[0, 1]` (NaN included); nothing changes then.
    pub fn set_open_scale(&mut self, values: &[f32]) -> Result<(), BrdfError> {
        check(
            "open-sea factors (one per grid point)",
            values.len() as f64,
            self.open_scale.len() as f64,
            self.open_scale.len() as f64,
        )?;
        for &v in values {
            check("open-sea factor", f64::from(v), 0.0, 1.0)?;
        }
        self.open_scale.copy_from_slice(values);
        Ok(())
    }

    /// Removes every wave set (the open sea's factor stays).
    pub fn clear_sets(&mut self) {
        self.sets.clear();
    }

    /// The number of wave sets.
    pub fn set_count(&self) -> usize {
        self.sets.len()
    }

    /// The number of trains over all sets.
    pub fn train_count(&self) -> usize {
        self.sets.iter().map(|s| s.waves.waves().len()).sum()
    }

    /// Adds a wave set modulated by `modulation`, whose rectangle is in this grid's points
    /// (a wave train box of a scene on this grid: `ocean_core::layers::Layer`).
    ///
    /// # Errors
    ///
    /// [`BrdfError::OutOfRange`] if the rectangle does not fit the grid, or beyond
    /// [`MAX_LOCAL_SETS`] sets or [`MAX_LOCAL_TRAINS`] trains; nothing changes then.
    pub fn add_set(&mut self, waves: &WaveSet, modulation: &Modulation) -> Result<(), BrdfError> {
        let rect = modulation.rect();
        if !rect.fits((self.nx, self.nz)) {
            return Err(BrdfError::OutOfRange {
                name: "modulation rectangle (past the local grid)",
                value: (rect.i0 + rect.nx).max(rect.j0 + rect.nz) as f64,
                min: 0.0,
                max: self.nx.max(self.nz) as f64,
            });
        }
        check(
            "local wave sets",
            (self.sets.len() + 1) as f64,
            0.0,
            MAX_LOCAL_SETS as f64,
        )?;
        check(
            "local trains",
            (self.train_count() + waves.waves().len()) as f64,
            0.0,
            MAX_LOCAL_TRAINS as f64,
        )?;
        let mut mu = vec![[0.0f32; 2]; self.nx * self.nz];
        for r in 0..rect.nz {
            let row = (rect.j0 + r) * self.nx + rect.i0;
            mu[row..row + rect.nx].copy_from_slice(modulation.row(r));
        }
        let terms = waves
            .waves()
            .iter()
            .map(|w| wave_variance_term(w, self.wind))
            .collect();
        self.sets.push(LocalSet {
            waves: waves.clone(),
            terms,
            mu,
        });
        Ok(())
    }

    /// The trains of set `k` (in the order given), and μ at every grid point.
    pub fn set(&self, k: usize) -> Option<(&WaveSet, &[[f32; 2]])> {
        self.sets.get(k).map(|s| (&s.waves, s.mu.as_slice()))
    }

    /// Bilinear read of a per-point field at world `(x, z)` = `p`, `outside` past the grid.
    fn bilinear(&self, p: DVec2, outside: f64, at: impl Fn(usize) -> f64) -> f64 {
        let g = (p - self.origin) / self.spacing;
        let (fi, fj) = (libm::floor(g.x), libm::floor(g.y));
        let (tx, tz) = (g.x - fi, g.y - fj);
        let texel = |di: f64, dj: f64| {
            let (i, j) = (fi + di, fj + dj);
            if i >= 0.0 && j >= 0.0 && i < self.nx as f64 && j < self.nz as f64 {
                at(j as usize * self.nx + i as usize)
            } else {
                outside
            }
        };
        let a = texel(0.0, 0.0) * (1.0 - tx) + texel(1.0, 0.0) * tx;
        let b = texel(0.0, 1.0) * (1.0 - tx) + texel(1.0, 1.0) * tx;
        a * (1.0 - tz) + b * tz
    }

    /// The open sea's amplitude factor at world `(x, z)` = `p`: bilinear between the grid
    /// points, 1 beyond them.
    pub fn open_scale_at(&self, p: DVec2) -> f64 {
        self.bilinear(p, 1.0, |k| f64::from(self.open_scale[k]))
    }

    /// μ of set `k` at world `(x, z)` = `p`: bilinear between the grid points, 0 beyond them
    /// (and for a set that does not exist).
    pub fn modulation_at(&self, k: usize, p: DVec2) -> [f64; 2] {
        let Some(s) = self.sets.get(k) else {
            return [0.0, 0.0];
        };
        [
            self.bilinear(p, 0.0, |i| f64::from(s.mu[i][0])),
            self.bilinear(p, 0.0, |i| f64::from(s.mu[i][1])),
        ]
    }

    /// Adds the trains at rest point `p`, time `t`, each weighted by w(N_min, N_max, λ/size)
    /// (w_p for a grid cell, w_n for a pixel) and by its set's μ there, to `sums`.
    ///
    /// # Errors
    ///
    /// [`BrdfError::NotFinite`] for a non-finite point or time, or a footprint that is not
    /// positive; `sums` is unchanged then.
    pub fn add_sums(
        &self,
        p: DVec2,
        t: f64,
        size: f64,
        sums: &mut PointSums,
    ) -> Result<(), BrdfError> {
        if !(size.is_finite() && size > 0.0) {
            return Err(BrdfError::NotFinite("footprint (must be positive)"));
        }
        let mut acc = *sums;
        for (k, s) in self.sets.iter().enumerate() {
            let mu = self.modulation_at(k, p);
            let weights = s
                .waves
                .waves()
                .iter()
                .map(|w| self.filter.weight(w.wavelength(), size));
            s.waves
                .add_filtered_sums_f64(p, t, weights, mu, &mut acc)
                .map_err(|_| BrdfError::NotFinite("rest position or time"))?;
        }
        *sums = acc;
        Ok(())
    }

    /// Eq. 4 for the trains at rest point `p` and pixel footprint `pixel`: each train's slope
    /// variance for the steepness k·A·|μ|·w_r, along the wind and across it.
    pub fn variance_at(&self, p: DVec2, pixel: f64) -> SlopeVariance {
        let mut v = SlopeVariance::default();
        for (k, s) in self.sets.iter().enumerate() {
            let [re, im] = self.modulation_at(k, p);
            let m = libm::sqrt(re * re + im * im);
            for (w, &(ka, cos2)) in s.waves.waves().iter().zip(&s.terms) {
                let left = trochoid_slope_variance(
                    (ka * m * self.filter.brdf_weight(w.wavelength(), pixel)).min(1.0),
                );
                v = v.plus(SlopeVariance {
                    x: left * cos2,
                    y: left * (1.0 - cos2),
                });
            }
        }
        v
    }

    /// The slope variances of the trains at rest point `p` that the pixel footprint `pixel`
    /// resolves in the normal and the grid-cell footprint `cell` does not resolve in the
    /// geometry: each train's trochoid of steepness k·A·|μ|·(w_n − w_p), as
    /// [`crate::VarianceTable::normal_only`] for the open sea (§3.2).
    pub fn normal_only_at(&self, p: DVec2, pixel: f64, cell: f64) -> SlopeVariance {
        let mut v = SlopeVariance::default();
        for (k, s) in self.sets.iter().enumerate() {
            let [re, im] = self.modulation_at(k, p);
            let m = libm::sqrt(re * re + im * im);
            for (w, &(ka, cos2)) in s.waves.waves().iter().zip(&s.terms) {
                let l = w.wavelength();
                let weight = (self.filter.weight(l, pixel) - self.filter.weight(l, cell)).max(0.0);
                let only = trochoid_slope_variance((ka * m * weight).min(1.0));
                v = v.plus(SlopeVariance {
                    x: only * cos2,
                    y: only * (1.0 - cos2),
                });
            }
        }
        v
    }

    /// The open sea `open` with these local waves at rest point `p` and time `t`: the
    /// position for the grid-cell footprint `cell`, the normal and the variances for the pixel
    /// footprint `pixel` (what the GPU renderer's vertex and fragment stages compute).
    ///
    /// # Errors
    ///
    /// [`BrdfError::NotFinite`] / [`BrdfError::OutOfRange`] for a non-finite point or time, or a
    /// footprint that is not positive and finite.
    pub fn point(
        &self,
        open: &FilteredSurface,
        p: DVec2,
        t: f64,
        cell: f64,
        pixel: f64,
    ) -> Result<LocalPoint, BrdfError> {
        let s = self.open_scale_at(p).clamp(0.0, 1.0);
        let mut geometry = PointSums::REST;
        open.add_normal_sums(p, t, cell, s, &mut geometry)?;
        self.add_sums(p, t, cell, &mut geometry)?;
        let mut normal = PointSums::REST;
        open.add_normal_sums(p, t, pixel, s, &mut normal)?;
        self.add_sums(p, t, pixel, &mut normal)?;
        let v = open.variance(pixel);
        let variance = SlopeVariance {
            x: s * s * v.x,
            y: s * s * v.y,
        }
        .plus(self.variance_at(p, pixel));
        let only = open.normal_only_variance(pixel, cell);
        let normal_only = SlopeVariance {
            x: s * s * only.x,
            y: s * s * only.y,
        }
        .plus(self.normal_only_at(p, pixel, cell));
        Ok(LocalPoint {
            position: DVec3::new(p.x, 0.0, p.y) + geometry.displacement(),
            normal: normal.normal(),
            variance,
            geometry_normal: geometry.normal(),
            normal_only,
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use ocean_core::layers::GridRect;
    use ocean_core::{Depth, WaveDesc};

    fn train(wavelength: f64, amplitude: f64, direction: DVec2, phase: f64) -> WaveDesc {
        WaveDesc {
            amplitude,
            wavelength,
            direction,
            phase,
            depth: Depth::Deep,
        }
    }

    fn open() -> FilteredSurface {
        let descs = [
            train(40.0, 0.5, DVec2::new(1.0, 0.2), 0.3),
            train(7.0, 0.1, DVec2::new(0.4, 1.0), 1.1),
            train(0.8, 0.01, DVec2::new(-0.3, 1.0), 2.0),
        ];
        FilteredSurface::from_waves(&descs, DVec2::new(1.0, 0.2), Filter::PAPER).unwrap()
    }

    /// A 9 × 7 grid 2 m apart at (−4, −6), with one set of two trains over its middle.
    fn local(mu: [f32; 2]) -> (LocalWaves, WaveSet) {
        let mut l = LocalWaves::new(
            DVec2::new(-4.0, -6.0),
            2.0,
            9,
            7,
            DVec2::new(1.0, 0.2),
            Filter::PAPER,
        )
        .unwrap();
        let set = WaveSet::from_descs(&[
            train(12.0, 0.3, DVec2::new(0.0, 1.0), 0.5),
            train(3.0, 0.05, DVec2::new(1.0, 1.0), 2.5),
        ])
        .unwrap();
        let rect = GridRect {
            i0: 2,
            j0: 1,
            nx: 5,
            nz: 4,
        };
        let m = Modulation::new(rect, vec![mu; rect.len()]).unwrap();
        l.add_set(&set, &m).unwrap();
        (l, set)
    }

    /// With no set and a factor of 1 the point is the open sea's, exactly: positions, normals
    /// and variances of `FilteredSurface` (what the renderer draws without local waves).
    #[test]
    fn without_local_waves_the_open_sea_is_unchanged() {
        let sea = open();
        let l = LocalWaves::new(DVec2::ZERO, 1.0, 4, 4, sea.wind(), Filter::PAPER).unwrap();
        for (p, cell, pixel) in [
            (DVec2::new(1.5, 2.5), 0.4, 0.05),
            (DVec2::new(-30.0, 7.0), 8.0, 1.0),
        ] {
            let got = l.point(&sea, p, 3.0, cell, pixel).unwrap();
            assert_eq!(got.position, sea.position(p, 3.0, cell).unwrap());
            assert_eq!(got.normal, sea.normal(p, 3.0, pixel).unwrap());
            assert_eq!(got.variance, sea.variance(pixel));
            assert_eq!(got.pixel(), sea.pixel(p, 3.0, pixel, cell).unwrap());
        }
    }

    /// At a grid point inside the set's rectangle with μ = m e^{iφ}, the trains are trochoids
    /// of amplitude m·A and phase θ + φ: the point equals that of one surface made of the open
    /// sea and the trains so scaled and shifted (§6: surfaces add), for footprints that resolve
    /// every train (normals) and none of them (variances).
    #[test]
    fn trains_add_as_scaled_and_shifted_trochoids() {
        let (m, phi) = (0.6f64, 0.9f64);
        let mu = [(m * phi.cos()) as f32, (m * phi.sin()) as f32];
        let (l, set) = local(mu);
        let sea = open();
        // Grid point (4, 3): world (4, 0), inside the rectangle.
        let p = DVec2::new(4.0, 0.0);
        let mu64 = [f64::from(mu[0]), f64::from(mu[1])];
        let m64 = (mu64[0] * mu64[0] + mu64[1] * mu64[1]).sqrt();
        let phi64 = mu64[1].atan2(mu64[0]);
        let shifted: Vec<WaveDesc> = set
            .waves()
            .iter()
            .map(|w| WaveDesc {
                amplitude: w.amplitude() * m64,
                wavelength: w.wavelength(),
                direction: w.direction(),
                phase: w.phase() + phi64,
                depth: Depth::Deep,
            })
            .collect();
        let shifted = WaveSet::from_descs(&shifted).unwrap();
        let t = 4.25;
        // A tiny footprint resolves everything (w = 1 for all): positions and normals.
        let got = l.point(&sea, p, t, 1e-3, 1e-3).unwrap();
        let mut want = PointSums::REST;
        sea.add_normal_sums(p, t, 1e-3, 1.0, &mut want).unwrap();
        shifted.add_sums_f64(p, t, [1.0, 0.0], &mut want).unwrap();
        let want_pos = DVec3::new(p.x, 0.0, p.y) + want.displacement();
        assert!((got.position - want_pos).length() < 1e-12, "{got:?}");
        assert!((got.normal - want.normal()).length() < 1e-12, "{got:?}");
        assert_eq!(got.variance, SlopeVariance::default());
        // A huge footprint resolves nothing: the variances are the open sea's total plus each
        // train's 1 − √(1 − (k m A)²), split by (k̂·wind)².
        let far = l.point(&sea, p, t, 1e4, 1e4).unwrap();
        let mut v = sea.variance(1e4);
        for w in set.waves() {
            let (ka, cos2) = wave_variance_term(w, sea.wind());
            let s = trochoid_slope_variance(ka * m64);
            v = v.plus(SlopeVariance {
                x: s * cos2,
                y: s * (1.0 - cos2),
            });
        }
        assert!((far.variance.x - v.x).abs() < 1e-15 && (far.variance.y - v.y).abs() < 1e-15);
        assert_eq!(far.position, DVec3::new(p.x, 0.0, p.y));
    }

    /// Bilinear between points, 0 (μ) and 1 (factor) beyond the grid, half-way at half a cell
    /// outside the edge.
    #[test]
    fn fields_are_bilinear_and_fade_at_the_grid_edge() {
        let (mut l, _) = local([0.8, 0.0]);
        // Between columns 1 (μ = 0) and 2 (0.8) of row 2: 0.8 at 3/4 of the way.
        let p = DVec2::new(-4.0 + 2.0 * 1.75, -6.0 + 2.0 * 2.0);
        assert!((l.modulation_at(0, p)[0] - 0.6).abs() < 1e-7);
        assert_eq!(l.modulation_at(1, p), [0.0, 0.0]);
        let mut scale = vec![0.5f32; 63];
        scale[0] = 0.0;
        l.set_open_scale(&scale).unwrap();
        assert_eq!(l.open_scale_at(DVec2::new(-4.0, -6.0)), 0.0);
        assert_eq!(l.open_scale_at(DVec2::new(0.0, 0.0)), 0.5);
        // Half a cell left of column 0 (row 3): halfway between 0.5 and the outside's 1.
        assert!((l.open_scale_at(DVec2::new(-5.0, 0.0)) - 0.75).abs() < 1e-15);
        assert_eq!(l.open_scale_at(DVec2::new(-100.0, 0.0)), 1.0);
    }

    /// The open sea's factor s scales its displacement by s and its variance by s².
    #[test]
    fn open_scale_scales_the_open_sea() {
        let sea = open();
        let mut l = LocalWaves::new(DVec2::ZERO, 1.0, 3, 3, sea.wind(), Filter::PAPER).unwrap();
        l.set_open_scale(&[0.25; 9]).unwrap();
        let p = DVec2::new(1.0, 1.0);
        let got = l.point(&sea, p, 2.0, 0.5, 50.0).unwrap();
        let full = sea.position(p, 2.0, 0.5).unwrap() - DVec3::new(p.x, 0.0, p.y);
        let want = DVec3::new(p.x, 0.0, p.y) + 0.25 * full;
        assert!((got.position - want).length() < 1e-12);
        let v = sea.variance(50.0);
        assert!((got.variance.x - v.x / 16.0).abs() < 1e-15);
    }

    #[test]
    fn bad_input_is_refused() {
        let w = DVec2::X;
        let f = Filter::PAPER;
        assert!(LocalWaves::new(DVec2::NAN, 1.0, 2, 2, w, f).is_err());
        assert!(LocalWaves::new(DVec2::ZERO, 0.0, 2, 2, w, f).is_err());
        assert!(LocalWaves::new(DVec2::ZERO, 1.0, 0, 2, w, f).is_err());
        assert!(LocalWaves::new(DVec2::ZERO, 1.0, 2, 2, DVec2::ZERO, f).is_err());
        let (mut l, set) = local([1.0, 0.0]);
        assert!(l.set_open_scale(&[0.5; 3]).is_err());
        let mut bad = vec![0.5f32; 63];
        bad[7] = f32::NAN;
        assert!(l.set_open_scale(&bad).is_err());
        bad[7] = 1.5;
        assert!(l.set_open_scale(&bad).is_err());
        assert!(l.open_scale().iter().all(|&v| v == 1.0));
        let past = Modulation::new(
            GridRect {
                i0: 6,
                j0: 0,
                nx: 4,
                nz: 1,
            },
            vec![[1.0, 0.0]; 4],
        )
        .unwrap();
        assert!(l.add_set(&set, &past).is_err());
        assert_eq!(l.set_count(), 1);
        let mut s = PointSums::REST;
        assert!(l.add_sums(DVec2::ZERO, 0.0, 0.0, &mut s).is_err());
        assert!(l.add_sums(DVec2::ZERO, f64::NAN, 1.0, &mut s).is_err());
        assert_eq!(s, PointSums::REST);
    }
}
