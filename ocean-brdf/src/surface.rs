//! The filtered sea surface of §3.2 for one screen point: position (Eq. 2), normal (Eq. 3) and
//! slope variance (Eq. 4), with the footprints they are filtered on; the CPU twin of the GPU
//! renderer's vertex and fragment stages.
//!
//! Footprints. The paper filters each wave on "the projected grid cell size L" (positions) and
//! "the projected size of a pixel l" (normals). A pixel projects onto the sea as an ellipse,
//! elongated by 1/sin(elevation) towards the viewer; this crate takes its **longer axis**
//! (see [`pixel_footprint`]), so no wave aliases in either direction, and what the normals lose
//! across the view goes into the BRDF, whose variance accounts for it. `L` is the same for a
//! grid cell of `cell_px` pixels: `cell_px` times the pixel footprint at the vertex.
//!
//! World space is right-handed with y up; rest positions are `(x, z)` on the plane y = 0.

use alloc::vec::Vec;

use glam::{DVec2, DVec3};
use ocean_core::PointSums;
use ocean_core::{Camera, WaveDesc, WaveSet};

use crate::error::{BrdfError, check};
use crate::filter::Filter;
use crate::spectrum::Spectrum;
use crate::variance::{SlopeVariance, VarianceTable};

/// A wave set filtered per wave, sorted by wavelength from the longest: the resolved waves for
/// any footprint are then a prefix, and the GPU stops at the first zero weight.
#[derive(Clone, Debug)]
pub struct FilteredSurface {
    waves: WaveSet,
    wavelengths: Vec<f64>,
    filter: Filter,
    variance: VarianceTable,
    wind: DVec2,
}

impl FilteredSurface {
    /// The surface of a sampled spectrum.
    pub fn new(spectrum: &Spectrum, filter: Filter) -> Result<Self, BrdfError> {
        Self::from_waves(spectrum.waves(), spectrum.wind(), filter)
    }

    /// The surface of any deep- or finite-depth wave set (§6, local waves: any wave train whose
    /// wavelength and slope variance are known), with variances measured along `wind` and
    /// across it.
    pub fn from_waves(waves: &[WaveDesc], wind: DVec2, filter: Filter) -> Result<Self, BrdfError> {
        let len = wind.length();
        if !len.is_finite() || len == 0.0 {
            return Err(BrdfError::NotUnit("wind direction"));
        }
        let mut sorted: Vec<WaveDesc> = waves.to_vec();
        // Longest first; ties keep their order (a stable sort), so equal inputs give equal sets.
        sorted.sort_by(|a, b| b.wavelength.total_cmp(&a.wavelength));
        let set = WaveSet::from_descs(&sorted).map_err(|_| BrdfError::OutOfRange {
            name: "wave (a wave that ocean-core refuses)",
            value: f64::NAN,
            min: 0.0,
            max: 0.0,
        })?;
        let wavelengths = set.waves().iter().map(|w| w.wavelength()).collect();
        let variance = VarianceTable::new(&sorted, wind / len)?;
        Ok(Self {
            waves: set,
            wavelengths,
            filter,
            variance,
            wind: wind / len,
        })
    }

    /// The waves, longest first.
    pub fn wave_set(&self) -> &WaveSet {
        &self.waves
    }

    /// The wavelengths, longest first.
    pub fn wavelengths(&self) -> &[f64] {
        &self.wavelengths
    }

    /// The filter thresholds.
    pub fn filter(&self) -> &Filter {
        &self.filter
    }

    /// The unit wind direction `(x, z)`: the x axis of the slope variances.
    pub fn wind(&self) -> DVec2 {
        self.wind
    }

    /// The variance table of every wave (total and per wave).
    pub fn variance_table(&self) -> &VarianceTable {
        &self.variance
    }

    /// The number of waves with a non-zero weight for a footprint `size` (metres): they are
    /// the first ones, longest first.
    pub fn resolved_count(&self, size: f64) -> usize {
        self.wavelengths
            .iter()
            .take_while(|&&l| self.filter.weight(l, size) > 0.0)
            .count()
    }

    /// Eq. 2: the displaced position of the rest point `rest` = (x, z) at time `t`, each wave
    /// weighted by `w_p = w(N_min, N_max, λ/L)` for the grid-cell footprint `cell` (metres).
    pub fn position(&self, rest: DVec2, t: f64, cell: f64) -> Result<DVec3, BrdfError> {
        let sums = self.sums(rest, t, cell)?;
        Ok(DVec3::new(rest.x, 0.0, rest.y) + sums.displacement())
    }

    /// Eq. 3: the unit normal at the rest point `rest`, each wave weighted by
    /// `w_n = w(N_min, N_max, λ/l)` for the pixel footprint `pixel` (metres). Not derived from
    /// the filtered positions: normals stay exact farther than the geometry (§3.2).
    pub fn normal(&self, rest: DVec2, t: f64, pixel: f64) -> Result<DVec3, BrdfError> {
        Ok(self.sums(rest, t, pixel)?.normal())
    }

    /// Eq. 4: the slope variances of what the normals of footprint `pixel` do not resolve,
    /// `w_r = 1 − w_n`, as the total minus the resolved waves' share (§7.1).
    pub fn variance(&self, pixel: f64) -> SlopeVariance {
        self.variance.unresolved(&self.filter, pixel)
    }

    /// The slope variances of the waves that the normal of a pixel of `pixel` metres resolves
    /// (Eq. 3) and the geometry of a grid cell of `cell` metres does not (Eq. 2), see
    /// [`VarianceTable::normal_only`].
    pub fn normal_only_variance(&self, pixel: f64, cell: f64) -> SlopeVariance {
        self.variance.normal_only(&self.filter, pixel, cell)
    }

    /// What Algorithm 5.1 needs of the surface at one pixel (§3.2): Eq. 3's normal and Eq. 4's
    /// variance for the pixel footprint `pixel` (l, metres), the normal of Eq. 2's geometry for
    /// the grid-cell footprint `cell` (L, metres) and the slope variance of the waves resolved
    /// in the former and not in the latter. The CPU twin of the fragment stage's
    /// `pixel_surface` (ocean_common.wgsl), which the renderer calls with `cell = cell_px · l`.
    ///
    /// # Errors
    ///
    /// As [`FilteredSurface::normal`], for either footprint.
    pub fn pixel(
        &self,
        rest: DVec2,
        t: f64,
        pixel: f64,
        cell: f64,
    ) -> Result<PixelSurface, BrdfError> {
        Ok(PixelSurface {
            normal: self.normal(rest, t, pixel)?,
            geometry_normal: self.normal(rest, t, cell)?,
            variance: self.variance(pixel),
            normal_only: self.normal_only_variance(pixel, cell),
        })
    }

    /// §6, local waves: adds this surface's Eq. 3 terms (waves weighted by `w_n` for the
    /// footprint `pixel`, times `scale`, for instance a wave train box's `|μ|` at the point) to
    /// `sums`. Surfaces add: the normal of the open sea with local waves on it is
    /// `PointSums::normal` of the sums of both, since Eq. 3 is linear in the waves' derivatives.
    pub fn add_normal_sums(
        &self,
        rest: DVec2,
        t: f64,
        pixel: f64,
        scale: f64,
        sums: &mut PointSums,
    ) -> Result<(), BrdfError> {
        let s = self.weighted_sums(rest, t, pixel, scale)?;
        sums.dx += s.dx;
        sums.y += s.y;
        sums.dz += s.dz;
        sums.jxx += s.jxx - 1.0;
        sums.jxz += s.jxz;
        sums.jzz += s.jzz - 1.0;
        sums.sx += s.sx;
        sums.sz += s.sz;
        Ok(())
    }

    /// §6, local waves: Eq. 4 for this surface's waves with their amplitudes scaled by
    /// `scale` ∈ [0, 1]; add it to the open sea's [`FilteredSurface::variance`] (variances of
    /// independent waves add, §3.2). Build the local surface with the open sea's wind so the
    /// two are in the same frame.
    pub fn local_variance(&self, pixel: f64, scale: f64) -> SlopeVariance {
        self.variance.unresolved_scaled(&self.filter, pixel, scale)
    }

    fn sums(&self, rest: DVec2, t: f64, size: f64) -> Result<PointSums, BrdfError> {
        self.weighted_sums(rest, t, size, 1.0)
    }

    fn weighted_sums(
        &self,
        rest: DVec2,
        t: f64,
        size: f64,
        scale: f64,
    ) -> Result<PointSums, BrdfError> {
        check("scale", scale, 0.0, 1.0)?;
        if !(size.is_finite() && size > 0.0) {
            return Err(BrdfError::OutOfRange {
                name: "footprint",
                value: size,
                min: f64::MIN_POSITIVE,
                max: f64::MAX,
            });
        }
        // The resolved waves are the first ones: weigh those, and the sum stops there.
        let n = self.resolved_count(size);
        let weights = self.wavelengths[..n]
            .iter()
            .map(|&l| self.filter.weight(l, size) * scale);
        let mut sums = PointSums::REST;
        self.waves
            .add_weighted_sums_f64(rest, t, weights, &mut sums)
            .map_err(|_| BrdfError::NotFinite("rest position or time"))?;
        Ok(sums)
    }
}

/// The filtered surface at one pixel, as Algorithm 5.1 takes it (see [`FilteredSurface::pixel`]
/// and, with local waves, [`crate::LocalPoint::pixel`]).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct PixelSurface {
    /// Eq. 3: the unit normal, each wave weighted by `w_n` for the pixel footprint `l`.
    pub normal: DVec3,
    /// The unit normal of the displaced geometry (Eq. 2's waves, each weighted by `w_p` for the
    /// grid-cell footprint `L`): the surface that masks what lies below it (§3.2).
    pub geometry_normal: DVec3,
    /// Eq. 4: σ_x², σ_y² of what the normal does not resolve (`w_r = 1 − w_n`), along the wind
    /// and across it: the BRDF's slopes.
    pub variance: SlopeVariance,
    /// The slope variances of the waves resolved in the normal but not in the geometry
    /// (weights `w_n − w_p`, [`VarianceTable::normal_only`]): the slopes of `normal` relative to
    /// `geometry_normal`, which the geometry does not mask.
    pub normal_only: SlopeVariance,
}

impl PixelSurface {
    /// The normal Algorithm 5.1 is evaluated with for a viewer along `v` (unit, towards the
    /// viewer): Eq. 3's normal made masking-aware for the waves the geometry lacks (§3.2, Eq. 10,
    /// [`visible_normal`]), with `wind` the variances' axis (the surface's wind).
    pub fn visible_normal(&self, v: DVec3, wind: DVec2) -> DVec3 {
        visible_normal(
            v,
            self.normal,
            self.geometry_normal,
            wind,
            self.normal_only,
            self.variance,
        )
    }
}

/// The smallest depression of a view ray below the horizon for which the sea plane is hit: a
/// ray above (or along) it meets the plane at [`sea_plane_hit`]'s distance cap instead.
pub const MIN_DEPRESSION: f64 = 1e-6;

/// Where the ray from `eye` (its origin) along the unit direction `dir` meets the sea at rest (y = 0),
/// at most `max_distance` along the ray. Rays that go up, run along the horizon, or would meet
/// the plane beyond the cap are stopped at the cap, projected onto the plane: the projected
/// grid folds the sky part of the screen onto the far sea, as the paper's grid does, and the
/// renderer draws those cells at the horizon. `None` if the eye is not above the sea
/// (`eye.y ≤ 0`) or the inputs are not finite.
pub fn sea_plane_hit(eye: DVec3, dir: DVec3, max_distance: f64) -> Option<DVec2> {
    if !(eye.is_finite() && dir.is_finite() && max_distance > 0.0) || eye.y <= 0.0 {
        return None;
    }
    let down = -dir.y;
    let s = if down > MIN_DEPRESSION {
        (eye.y / down).min(max_distance)
    } else {
        max_distance
    };
    let p = eye + dir * s;
    Some(DVec2::new(p.x, p.z))
}

/// The view ray through the screen point `pixel` (pixel units, origin at the top-left corner,
/// y down, pixel centres at half-integers) of a `width` × `height` viewport: its origin on the
/// near plane and its unit direction (perspective or orthographic alike).
pub fn pixel_ray(camera: &Camera, width: f64, height: f64, pixel: DVec2) -> Option<(DVec3, DVec3)> {
    let ndc_x = pixel.x / width * 2.0 - 1.0;
    let ndc_y = 1.0 - pixel.y / height * 2.0;
    let depth = camera.depth();
    let near = depth.near_ndc();
    // Halfway to the far plane in NDC: finite even for an infinite far plane.
    let mid = 0.5 * (near + depth.far_ndc());
    let a = camera.ndc_to_world(DVec3::new(ndc_x, ndc_y, near)).ok()?;
    let b = camera.ndc_to_world(DVec3::new(ndc_x, ndc_y, mid)).ok()?;
    let d = b - a;
    let len = d.length();
    (len > 0.0 && len.is_finite()).then(|| (a, d / len))
}

/// The footprint `l` of a pixel on the sea plane (metres): the longer of the distances between
/// the plane hits of the rays through the pixel's opposite edge midpoints, horizontally
/// (`pixel ± (½, 0)`) and vertically (`pixel ± (0, ½)`). Rays beyond the horizon hit at
/// `max_distance` (see [`sea_plane_hit`]). `None` where a ray is undefined or starts below the
/// sea.
pub fn pixel_footprint(
    camera: &Camera,
    width: f64,
    height: f64,
    pixel: DVec2,
    max_distance: f64,
) -> Option<f64> {
    let hit = |p: DVec2| {
        let (origin, dir) = pixel_ray(camera, width, height, p)?;
        sea_plane_hit(origin, dir, max_distance)
    };
    let dx = hit(pixel + DVec2::new(0.5, 0.0))? - hit(pixel - DVec2::new(0.5, 0.0))?;
    let dy = hit(pixel + DVec2::new(0.0, 0.5))? - hit(pixel - DVec2::new(0.0, 0.5))?;
    Some(dx.length().max(dy.length()))
}

/// The tangent frame of Algorithm 5.1: `t_x` along the wind projected on the surface, `t_y`
/// across it, with `(t_x, t_y, n)` right-handed. `wind` is a horizontal direction `(x, z)`
/// (any length but zero); should it be parallel to `n`, any tangent is used.
pub fn tangent_frame(n: DVec3, wind: DVec2) -> (DVec3, DVec3) {
    let w = DVec3::new(wind.x, 0.0, wind.y);
    let mut tx = w - n * w.dot(n);
    let len = tx.length();
    if len > 1e-9 * w.length() && len > 0.0 {
        tx /= len;
    } else {
        tx = n.any_orthonormal_vector();
    }
    (tx, n.cross(tx))
}

/// The masking-aware normal of a pixel: Eq. 3's normal `n` with the slopes that the filtered
/// geometry does not mask redistributed to the slopes a viewer sees.
///
/// §3.2 notes that the normals of Eq. 3 stay exact farther than the geometry of Eq. 2, but
/// that the *apparent* normals become wrong, because the waves resolved in the normals and not
/// in the geometry (weights `w_n − w_p`, slope variances `normal_only`, see
/// [`crate::FilteredSurface::normal_only_variance`]) are no longer masked: a pixel samples
/// their slopes `ζ_n` (relative to the geometry's normal `n_geo`) with the density `p_n`, as if
/// the viewer saw every facet, while a viewer sees facets with the visible-slope density of
/// Eq. 10. The paper only reflects the normals that end up back-facing. Here the whole
/// distribution is corrected, in Ross's own model (Eq. 5–11):
///
/// - in the tangent frame of `n_geo`, the surface below the geometry is the sum of the
///   normal-only slopes `ζ_n ~ N(0, Σ_n)` and of the BRDF's `ζ_r ~ N(0, Σ_r)` (`brdf`, Eq. 4),
///   and the facets seen from `v` have the density `p_n(ζ_n) p_r(ζ_r) (v_z − (ζ_n + ζ_r)·v_xy)⁺`
///   normalised by `(1 + Λ) cos θ_v` of the summed variances (Eq. 10, 11);
/// - its conditional density of `ζ_r` given `ζ_n` is Eq. 10 in the frame of the normal of
///   slopes `ζ_n`, which is what Algorithm 5.1 evaluates around the normal it is given; so only
///   the marginal of `ζ_n` must change, from `p_n` to the visible one;
/// - in whitened slopes, along the axis `e` of `(σ_nx v_x, σ_ny v_y)` (length `c_n`; `c_r`
///   likewise for the BRDF's slopes, `c² = c_n² + c_r²`), the visible density of the combined
///   coordinate `t` is a Gaussian times the ramp `(a − t)⁺`, `a = v_z / c`, with mean
///   `μ = −Φ(a)/Z` and second moment `(a Φ(a) + 2 φ(a))/Z`, `Z = a Φ(a) + φ(a)` (the moments
///   [`crate::sea::visible_sky_footprint`] uses); the normal-only coordinate `s_n = (c_n t + c_r w)/c`
///   (`w` standard normal, independent) then has the visible mean `(c_n/c) μ` and variance
///   `(c_n/c)² Var t + (c_r/c)²`, and the coordinate across `e` keeps its density.
///
/// The pixel's `s_n` (standard normal over the sea, since it is a fixed function of the rest
/// position) is mapped affinely onto that mean and variance: a monotone map, so the pattern of
/// the normals is kept (crests stay crests), and the visible slopes get Eq. 10's first two
/// moments. With no normal-only waves (`c_n = 0`), a normal view (`a → ∞`, `μ → 0`,
/// `Var → 1`) or everything in the geometry, `n` is returned unchanged. Vectors are unit, in
/// world space; `wind` as in [`crate::sea::sea_color`].
pub fn visible_normal(
    v: DVec3,
    n: DVec3,
    n_geo: DVec3,
    wind: DVec2,
    normal_only: SlopeVariance,
    brdf: SlopeVariance,
) -> DVec3 {
    let (tx, ty) = tangent_frame(n_geo, wind);
    let v_t = DVec3::new(v.dot(tx), v.dot(ty), v.dot(n_geo));
    let n_t = DVec3::new(n.dot(tx), n.dot(ty), n.dot(n_geo));
    let sn = DVec2::new(libm::sqrt(normal_only.x), libm::sqrt(normal_only.y));
    let sr = DVec2::new(libm::sqrt(brdf.x), libm::sqrt(brdf.y));
    let axis = sn * DVec2::new(v_t.x, v_t.y);
    let c_n = axis.length();
    let c_r = (sr * DVec2::new(v_t.x, v_t.y)).length();
    if !(c_n > 0.0 && v_t.z > 0.0 && n_t.z > 0.0 && sn.min_element() > 0.0) {
        return n;
    }
    let c = libm::hypot(c_n, c_r);
    let e = axis / c_n;
    let a = v_t.z / c;
    let cdf = 0.5 * libm::erfc(-a * core::f64::consts::FRAC_1_SQRT_2);
    let pdf = libm::exp(-0.5 * a * a) * 0.398_942_280_401_432_7;
    let z = a * cdf + pdf;
    let mean_t = -cdf / z;
    let var_t = ((a * cdf + 2.0 * pdf) / z - mean_t * mean_t).max(0.0);
    let (kn, kr) = (c_n / c, c_r / c);
    let mean = kn * mean_t;
    let dev = libm::sqrt(kn * kn * var_t + kr * kr);
    // The pixel's slopes relative to the geometry, whitened.
    let zeta = DVec2::new(-n_t.x, -n_t.y) / n_t.z;
    let u = zeta / sn;
    let s = u.dot(e);
    let u = u + e * (mean + dev * s - s);
    let f = crate::ross::facet_normal(u * sn);
    (tx * f.x + ty * f.y + n_geo * f.z).normalize()
}
