//! The paper's validation (§7.2, Fig. 10): per-row mean radiance of the filtered model against
//! a reference made of detailed geometry and a perfect mirror, for the Sun, the sky and the
//! refracted light separately, with a constant-BRDF model alongside.
//!
//! Scene: a camera `eye_height` above the sea looking horizontally (along −z), a square image.
//! Only rows below the horizon whose upper edge still meets the sea are compared.
//!
//! **Reference.** The image is cut into vertical planes through the eye (a horizontal camera
//! without roll maps every pixel column `x_ndc` to one such plane); in each plane the sea's
//! profile is walked every `profile_step` metres (5 mm: the shortest wave, 2 cm, gets four
//! samples; 2.5 and 1.25 mm change the row means by less than 0.5 %) with the waves at least
//! `geometry_min_wavelength` long (by default every wave: waves kept out of the geometry are
//! not masked, and 22–24 % of the slope variance lies below 10 cm), each point found by
//! inverting the trochoids' horizontal displacement (Newton), so it lies exactly in the plane.
//! One walk from the eye outwards gives, for every ray of the plane, the first profile point
//! above it (occlusion by the waves included); the walk skips the distances where no ray can
//! meet the sea (below `Σ A`). At that point the normal is exact, from every wave; the
//! surface is a perfect mirror with Schlick's Fresnel (Eq. 14): the sky term is
//! `F L_env(r)` with the analytic sky (not the sky map), the refracted term `(1 − F) L_sea`,
//! and the Sun term `F L_sun` when the mirror direction falls inside the Sun's disc.
//! `rays_per_pixel` rays per pixel row and plane, stratified, for the sky and refracted terms.
//!
//! **The Sun's reference.** A perfect mirror sends a ray into the Sun's disc only where the
//! facet's normal lies within about ρ/2 of the half vector: with the paper's Sun (1/8000 of
//! the hemisphere, the default here) 0.2–0.8 % of the rays, in glints far smaller than a pixel.
//! The Sun's term is therefore sampled by its own `sun_rays_per_pixel` rays per pixel row and
//! plane (on the same walks, so it costs one normal per ray), and each row's mean comes with
//! its standard error, [`RowMeans::reference_sun_error`], estimated from the spread of the
//! planes' own row means. Those are far apart (a plane crosses a row's strip of sea in a few
//! glinting facets), so the planes, not the rays, set the error: measured on the default
//! scene, 32 planes give 13–84 % per row at 46–300 m and 7–23 % beyond, and 4 to 32 times
//! more rays per plane leave those figures as they are (ocean-brdf/tests/validation.rs).
//!
//! **Model.** One ray per pixel row and plane, through the pixel centre, against the profile of
//! the *filtered* surface (Eq. 2 with w_p for a grid cell of `cell_px` pixels); at the hit, the
//! pixel as the renderer's fragment stage has it ([`FilteredSurface::pixel`]: Eq. 3's normal,
//! Eq. 4's variance for the pixel's footprint, the geometry's normal and the normal-only
//! variance for the cell) lit as the renderer lights it ([`pixel_color`]: Eq. 3's normal made
//! masking-aware for the waves the geometry lacks, [`crate::sea::visible_normal`], then
//! Algorithm 5.1 with the sky map). The constant-BRDF model differs only in its variance: the
//! foreground's (bottom row's), everywhere.

use alloc::vec::Vec;

use glam::{DVec2, DVec3};
use ocean_core::PointSums;
use ocean_core::{Camera, DepthConvention, Far, Projection, WaveSet};
use rayon::prelude::*;

use crate::error::{BrdfError, check};
use crate::filter::Filter;
use crate::fresnel::schlick;
use crate::sea::{Lighting, SeaLight, SeaParams, pixel_color, sea_color_unchecked};
use crate::sky::SkyParams;
use crate::sky_map::SkyMap;
use crate::spectrum::{Spectrum, SpectrumParams};
use crate::surface::{FilteredSurface, pixel_footprint};

/// The validation's scene and sampling.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ValidationParams {
    /// The sea.
    pub spectrum: SpectrumParams,
    /// The Sun and the sky.
    pub sky: SkyParams,
    /// The water body.
    pub sea: SeaParams,
    /// Camera height above the sea at rest, metres.
    pub eye_height: f64,
    /// Image width and height, pixels (square pixels).
    pub size: u32,
    /// Vertical field of view, radians.
    pub fov_y: f64,
    /// Time, seconds.
    pub time: f64,
    /// Projected grid cell, pixels (the model's position filter, §3.2).
    pub cell_px: f64,
    /// Vertical planes of the reference, stratified across the width.
    pub planes: usize,
    /// Vertical planes of the two models (one ray per pixel row in each), stratified across
    /// the width: their filtered profiles are cheap, so they can sample every column.
    pub model_planes: usize,
    /// Reference rays per pixel row and plane, stratified (the sky and refracted terms).
    pub rays_per_pixel: usize,
    /// Reference rays per pixel row and plane for the Sun's term alone, stratified: a
    /// perfect mirror catches the Sun's disc in few of them (see the module documentation).
    pub sun_rays_per_pixel: usize,
    /// Reference profile spacing, metres (fine enough for the shortest geometry wave).
    pub profile_step: f64,
    /// Shortest wave of the reference's geometry; every wave shapes its normals.
    pub geometry_min_wavelength: f64,
    /// Where the profiles end, metres from the eye.
    pub max_distance: f64,
    /// Sky map size.
    pub sky_map_size: u32,
}

impl Default for ValidationParams {
    /// The paper's setting: a horizontal view 4 m above the sea, 256 pixels, out to about 6 km
    /// (a 10° field of view puts the second row below the horizon at 2.9–5.9 km), with every
    /// wave in the reference's geometry, sampled every 5 mm (the paper's reference had 5 cm
    /// triangles), and the paper's Sun: 1/8000 of the hemisphere, ρ = acos(1 − 1/8000) ≈ 0.906°
    /// ([`PAPER_SUN_ANGULAR_RADIUS`]; the real Sun's disc is 11.6 times smaller and would need
    /// as many more reference rays). Only the Sun's term depends on ρ.
    fn default() -> Self {
        Self {
            spectrum: SpectrumParams::default(),
            sky: SkyParams {
                sun_angular_radius: PAPER_SUN_ANGULAR_RADIUS,
                ..SkyParams::default()
            },
            sea: SeaParams::default(),
            eye_height: 4.0,
            size: 256,
            fov_y: 10f64.to_radians(),
            time: 0.0,
            cell_px: 8.0,
            planes: 32,
            model_planes: 256,
            rays_per_pixel: 32,
            sun_rays_per_pixel: 1024,
            profile_step: 0.005,
            geometry_min_wavelength: 0.0,
            max_distance: 8000.0,
            sky_map_size: 512,
        }
    }
}

/// The Sun's angular radius of the paper's validation (§7.2: the Sun "occupies only 1/8000th
/// of the hemisphere"): Ω_sun = 2π(1 − cos ρ) = 2π/8000, ρ ≈ 0.906°.
pub const PAPER_SUN_ANGULAR_RADIUS: f64 = 0.015_811_553_007_438_42;

/// One image row's mean radiance per component (linear RGB), for the three methods.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct RowMeans {
    /// Pixel row, from the top.
    pub row: u32,
    /// Distance from the eye to where the row's centre ray meets the sea at rest, metres.
    pub distance: f64,
    /// Detailed geometry, perfect mirror (its `sun` from the `sun_rays_per_pixel` rays).
    pub reference: SeaLight,
    /// The standard error of `reference.sun`, per channel (the Sun's colour is the same in
    /// every ray, so the error of the channels' sum is the sum of these): from the planes' own
    /// row means `y_k` (k across the width), `sqrt(Σ (y_{k+1} − y_k)² / (2 (M − 1)) / M)`, the
    /// successive-difference estimate for systematic samples, which does not count the
    /// glitter's smooth change across the width (the Sun's azimuth) as noise.
    pub reference_sun_error: DVec3,
    /// The filtered model (§3–5).
    pub model: SeaLight,
    /// The same with the foreground's BRDF everywhere.
    pub constant: SeaLight,
}

/// Runs the validation; rows from the bottom of the image (nearest) to the farthest compared.
pub fn validate(params: &ValidationParams) -> Result<Vec<RowMeans>, BrdfError> {
    let p = *params;
    check("eye_height", p.eye_height, 0.1, 1e4)?;
    check("fov_y", p.fov_y, 1e-3, 3.0)?;
    check("time", p.time, -1e9, 1e9)?;
    check("cell_px", p.cell_px, 1.0, 256.0)?;
    check("profile_step", p.profile_step, 1e-3, 10.0)?;
    check("max_distance", p.max_distance, 10.0, 1e6)?;
    check(
        "geometry_min_wavelength",
        p.geometry_min_wavelength,
        0.0,
        1e4,
    )?;
    for (name, v) in [
        ("size", p.size as usize),
        ("planes", p.planes),
        ("model_planes", p.model_planes),
        ("rays_per_pixel", p.rays_per_pixel),
        ("sun_rays_per_pixel", p.sun_rays_per_pixel),
    ] {
        check(name, v as f64, 2.0, 1e5)?;
    }
    let spectrum = Spectrum::new(p.spectrum)?;
    let lighting = Lighting::new(p.sky, p.sea)?;
    let map = lighting.sky_map(p.sky_map_size)?;
    let surface = FilteredSurface::new(&spectrum, Filter::PAPER)?;
    let geometry = {
        let long: Vec<_> = spectrum
            .waves()
            .iter()
            .filter(|w| w.wavelength >= p.geometry_min_wavelength)
            .copied()
            .collect();
        WaveSet::from_descs(&long).map_err(|_| BrdfError::NotFinite("geometry waves"))?
    };
    let n = p.size as f64;
    let camera = Camera::look_at(
        DVec3::new(0.0, p.eye_height, 0.0),
        DVec3::new(0.0, p.eye_height, -1.0),
        DVec3::Y,
        Projection::Perspective {
            fov_y: p.fov_y,
            aspect: 1.0,
            near: 0.05,
            far: Far::Infinite,
        },
        DepthConvention::ZERO_TO_ONE,
    )
    .map_err(|_| BrdfError::NotFinite("camera"))?;
    let tan_half = libm::tan(0.5 * p.fov_y);
    // Rows whose upper edge is below the horizon and meets the sea within the profiles.
    let first_row = (0..p.size)
        .find(|&j| {
            let y_top = 1.0 - 2.0 * j as f64 / n;
            let depression = -y_top * tan_half;
            depression > 0.0 && p.eye_height / depression < p.max_distance * 0.75
        })
        .ok_or(BrdfError::NotFinite("no row meets the sea"))?;
    let rows: Vec<u32> = (first_row..p.size).rev().collect();

    let ctx = Ctx {
        p,
        lighting: &lighting,
        map: &map,
        surface: &surface,
        geometry: &geometry,
        camera: &camera,
        tan_half,
        rows: &rows,
    };
    // Planes in parallel, summed in plane order: the same bits whatever the thread count.
    let reference: Vec<Vec<(SeaLight, DVec3)>> = (0..p.planes)
        .into_par_iter()
        .map(|k| ctx.reference_plane(k))
        .collect();
    let models: Vec<Vec<[SeaLight; 2]>> = (0..p.model_planes)
        .into_par_iter()
        .map(|k| ctx.model_plane(k))
        .collect();
    let mut out = Vec::with_capacity(rows.len());
    for (i, &row) in rows.iter().enumerate() {
        let mut sums = [SeaLight::default(); 3];
        for plane in &reference {
            add(&mut sums[0], &plane[i].0, 1.0 / p.planes as f64);
        }
        let m = p.planes as f64;
        sums[0].sun = reference.iter().map(|plane| plane[i].1).sum::<DVec3>() / m;
        let spread = reference
            .windows(2)
            .map(|w| {
                let d = w[1][i].1 - w[0][i].1;
                d * d
            })
            .sum::<DVec3>()
            / (2.0 * (m - 1.0));
        for plane in &models {
            add(&mut sums[1], &plane[i][0], 1.0 / p.model_planes as f64);
            add(&mut sums[2], &plane[i][1], 1.0 / p.model_planes as f64);
        }
        let y = 1.0 - 2.0 * (row as f64 + 0.5) / n;
        out.push(RowMeans {
            row,
            distance: p.eye_height / (-y * tan_half),
            reference: sums[0],
            reference_sun_error: (spread / m).map(libm::sqrt),
            model: sums[1],
            constant: sums[2],
        });
    }
    Ok(out)
}

struct Ctx<'a> {
    p: ValidationParams,
    lighting: &'a Lighting,
    map: &'a SkyMap,
    surface: &'a FilteredSurface,
    geometry: &'a WaveSet,
    camera: &'a Camera,
    tan_half: f64,
    rows: &'a [u32],
}

/// A sea profile along one vertical plane: for each sample, the distance from the eye along
/// the plane, the tangent of the elevation angle from the eye, and the rest position.
struct Profile {
    s: Vec<f64>,
    elevation: Vec<f64>,
    rest: Vec<DVec2>,
}

impl Ctx<'_> {
    /// The plane of index `k` of `count`: its `x_ndc`, its horizontal direction (x, z), and the
    /// factor from a ray's `y_ndc` to its slope per unit horizontal distance.
    fn plane_geometry(&self, k: usize, count: usize) -> (f64, DVec2, f64) {
        let x_ndc = -1.0 + 2.0 * (k as f64 + 0.5) / count as f64;
        let hx = x_ndc * self.tan_half;
        let hlen = libm::hypot(hx, 1.0);
        (
            x_ndc,
            DVec2::new(hx / hlen, -1.0 / hlen),
            self.tan_half / hlen,
        )
    }

    /// Where the profiles start: well before the bottom row's rays meet the sea at rest (a
    /// crest meets them earlier).
    fn near(&self, slope_per_ndc: f64) -> f64 {
        0.3 * self.p.eye_height / slope_per_ndc
    }

    /// The reference's mean radiance of every row for the plane `k` (its `sun` left zero), and
    /// the Sun's from the `sun_rays_per_pixel` rays.
    ///
    /// The detailed profile is walked once from the eye outwards, every `profile_step`, and
    /// not stored (5 mm over kilometres). The rays are taken nearest (steepest) first; before
    /// the walk meets a ray it may skip ahead, safely: no point of the sea is higher than
    /// `Σ A` (the geometry's [`WaveSet::max_amplitude`]), so a ray of depression `m` cannot
    /// meet the sea nearer than `(eye_height − Σ A)/m`, nor can any shallower ray.
    fn reference_plane(&self, k: usize) -> Vec<(SeaLight, DVec3)> {
        let p = &self.p;
        let n = p.size as f64;
        let (_, h, slope_per_ndc) = self.plane_geometry(k, p.planes);
        let y_max = self.geometry.max_amplitude();
        let mut walk = Walk::new(self, h, self.near(slope_per_ndc));
        let (m, m_sun) = (p.rays_per_pixel, p.sun_rays_per_pixel);
        let sky = self.lighting.sky();
        let sun_cos = libm::cos(sky.sun_angular_radius());
        self.rows
            .iter()
            .map(|&row| {
                let mut acc = SeaLight::default();
                let mut sun = DVec3::ZERO;
                // Both sets of stratified rays, merged nearest (steepest) first, so the walk
                // only moves forward.
                let slope = |r: usize, count: usize| {
                    let y_ndc = 1.0 - 2.0 * (row as f64 + (r as f64 + 0.5) / count as f64) / n;
                    y_ndc * slope_per_ndc
                };
                let (mut r, mut r_sun) = (m, m_sun);
                while r > 0 || r_sun > 0 {
                    let is_sun = r == 0 || (r_sun > 0 && slope(r_sun - 1, m_sun) < slope(r - 1, m));
                    let ray = if is_sun {
                        r_sun -= 1;
                        slope(r_sun, m_sun)
                    } else {
                        r -= 1;
                        slope(r, m)
                    };
                    if ray < 0.0 {
                        let skip = (p.eye_height - y_max) / -ray;
                        if skip > walk.s + p.profile_step {
                            walk.jump(skip);
                        }
                    }
                    let Some(rest) = walk.hit(ray) else {
                        continue;
                    };
                    let v = -DVec3::new(h.x, ray, h.y).normalize();
                    let Some((n, f)) = self.facet(rest, v) else {
                        continue;
                    };
                    let reflected = n * (2.0 * n.dot(v).clamp(0.0, 1.0)) - v;
                    if is_sun {
                        if reflected.dot(sky.sun_direction()) >= sun_cos {
                            sun += sky.sun_radiance() * (f / m_sun as f64);
                        }
                    } else {
                        let light = SeaLight {
                            sun: DVec3::ZERO,
                            sky: self.lighting.environment_radiance(reflected) * f,
                            sea: self.lighting.sea_radiance() * (1.0 - f),
                        };
                        add(&mut acc, &light, 1.0 / m as f64);
                    }
                }
                (acc, sun)
            })
            .collect()
    }

    /// The filtered model's and the constant-BRDF model's radiance of every row for the model
    /// plane `k` (one ray per pixel row).
    fn model_plane(&self, k: usize) -> Vec<[SeaLight; 2]> {
        let p = &self.p;
        let n = p.size as f64;
        let (x_ndc, h, slope_per_ndc) = self.plane_geometry(k, p.model_planes);
        let e = p.eye_height;
        let pixel_angle = 2.0 * self.tan_half / n;
        // ds/dδ for the ray meeting the plane at distance s is (s² + e²)/e per radian: the
        // grid cell's footprint L for Eq. 2's w_p, and a profile step that resolves the
        // filtered geometry (an eighth of L, at least the reference's step).
        let cell = |s: f64| p.cell_px * (s * s + e * e) / e * pixel_angle;
        let profile = self.profile(
            h,
            self.near(slope_per_ndc),
            |s| Some(cell(s)),
            |s| (cell(s) / 8.0).max(p.profile_step),
        );
        let bottom_pixel = DVec2::new((x_ndc + 1.0) * 0.5 * n, n - 0.5);
        let l_bottom = pixel_footprint(self.camera, n, n, bottom_pixel, p.max_distance)
            .unwrap_or(p.profile_step);
        let constant_var = self.surface.variance(l_bottom);
        let wind = self.surface.wind();
        let mut cursor = 0;
        self.rows
            .iter()
            .map(|&row| {
                let y_ndc = 1.0 - 2.0 * (row as f64 + 0.5) / n;
                let pixel = DVec2::new((x_ndc + 1.0) * 0.5 * n, row as f64 + 0.5);
                let l = pixel_footprint(self.camera, n, n, pixel, p.max_distance)
                    .unwrap_or(p.max_distance);
                let Some((rest, v, s)) = hit(&profile, &mut cursor, h, y_ndc * slope_per_ndc)
                else {
                    return [SeaLight::default(); 2];
                };
                // The pixel as the renderer's fragment stage has it (`FilteredSurface::pixel`),
                // with the geometry's w_p for the grid cell at the hit, and Algorithm 5.1 as it
                // draws it (`pixel_color`: the masking-aware normal of §3.2).
                let Ok(surface) = self.surface.pixel(rest, p.time, l, cell(s)) else {
                    return [SeaLight::default(); 2];
                };
                let normal = surface.visible_normal(v, wind);
                [
                    pixel_color(self.lighting, self.map, v, &surface, wind),
                    sea_color_unchecked(self.lighting, self.map, v, normal, wind, constant_var),
                ]
            })
            .collect()
    }

    /// Samples the sea along the plane of horizontal direction `h` from `near` to
    /// `max_distance`: heights of the geometry waves (`cell` = None) or of the filtered
    /// surface with w_p for the cell size `cell(s)`.
    fn profile(
        &self,
        h: DVec2,
        near: f64,
        cell: impl Fn(f64) -> Option<f64>,
        step: impl Fn(f64) -> f64,
    ) -> Profile {
        let p = &self.p;
        let mut out = Profile {
            s: Vec::new(),
            elevation: Vec::new(),
            rest: Vec::new(),
        };
        let mut weights = Vec::with_capacity(self.surface.wavelengths().len());
        let mut x = h * near;
        let mut s = near;
        while s <= p.max_distance {
            let target = h * s;
            // The position weights w_p depend on the distance only: once per profile point.
            let size = cell(s);
            if let Some(size) = size {
                let filter = self.surface.filter();
                weights.clear();
                weights.extend(
                    self.surface
                        .wavelengths()
                        .iter()
                        .map(|&l| filter.position_weight(l, size))
                        .take_while(|&w| w > 0.0),
                );
            }
            let sums_at = |x: DVec2| -> PointSums {
                let mut sums = PointSums::REST;
                let _ = match size {
                    None => self.geometry.add_sums_f64(x, p.time, [1.0, 0.0], &mut sums),
                    Some(_) => self.surface.wave_set().add_weighted_sums_f64(
                        x,
                        p.time,
                        weights.iter().copied(),
                        &mut sums,
                    ),
                };
                sums
            };
            let (x_new, sums) = invert(x, target, sums_at);
            x = x_new;
            out.s.push(s);
            out.elevation.push((sums.y - p.eye_height) / s);
            out.rest.push(x);
            let ds = step(s);
            x += predict(&sums, h * ds);
            s += ds;
        }
        out
    }

    /// The reference's perfect mirror at the rest point `rest`, seen along `v` (towards the
    /// eye): the exact unit normal (turned towards the viewer) and Schlick's Fresnel (Eq. 14).
    fn facet(&self, rest: DVec2, v: DVec3) -> Option<(DVec3, f64)> {
        let mut sums = PointSums::REST;
        self.surface
            .wave_set()
            .add_sums_f64(rest, self.p.time, [1.0, 0.0], &mut sums)
            .ok()?;
        let mut n = sums.normal();
        let nv = n.dot(v);
        if nv < 0.0 {
            // A fold of the detailed surface seen from behind: the same rule as the model's.
            n -= v * (2.0 * nv);
        }
        let cos = n.dot(v).clamp(0.0, 1.0);
        Some((n, schlick(cos, self.lighting.sea().fresnel_r)))
    }
}

/// The first profile point at or above the ray of slope `slope` (negative: downwards; rays
/// processed in order of decreasing slope, so `cursor` only moves forward): its rest position
/// and distance along the plane (interpolated between samples) and the unit direction towards
/// the eye.
fn hit(profile: &Profile, cursor: &mut usize, h: DVec2, slope: f64) -> Option<(DVec2, DVec3, f64)> {
    let ray = slope;
    while *cursor < profile.s.len() && profile.elevation[*cursor] < ray {
        *cursor += 1;
    }
    let i = *cursor;
    if i >= profile.s.len() {
        return None;
    }
    let (rest, s) = if i == 0 {
        (profile.rest[0], profile.s[0])
    } else {
        let (a, b) = (profile.elevation[i - 1], profile.elevation[i]);
        let t = if b > a {
            ((ray - a) / (b - a)).clamp(0.0, 1.0)
        } else {
            1.0
        };
        (
            profile.rest[i - 1].lerp(profile.rest[i], t),
            profile.s[i - 1] + (profile.s[i] - profile.s[i - 1]) * t,
        )
    };
    let dir = DVec3::new(h.x, slope, h.y).normalize();
    Some((rest, -dir, s))
}

/// Newton on `x + D(x) = target`, from `x`: the rest point whose displaced position lies at
/// `target` (to 0.1 mm), and the sums there.
fn invert(mut x: DVec2, target: DVec2, sums_at: impl Fn(DVec2) -> PointSums) -> (DVec2, PointSums) {
    let mut sums = sums_at(x);
    for _ in 0..8 {
        let res = x + DVec2::new(sums.dx, sums.dz) - target;
        if res.length() < 1e-4 {
            break;
        }
        let det = sums.jacobian_det();
        if det.abs() < 1e-6 {
            // A fold: keep the last point, as a rasteriser keeps a folded triangle.
            break;
        }
        x -= DVec2::new(
            (sums.jzz * res.x - sums.jxz * res.y) / det,
            (sums.jxx * res.y - sums.jxz * res.x) / det,
        );
        sums = sums_at(x);
    }
    (x, sums)
}

/// How far the rest point moves when its displaced position moves by `d`: about `J⁻¹ d`.
fn predict(sums: &PointSums, d: DVec2) -> DVec2 {
    let det = sums.jacobian_det();
    if det.abs() > 1e-6 {
        DVec2::new(
            (sums.jzz * d.x - sums.jxz * d.y) / det,
            (sums.jxx * d.y - sums.jxz * d.x) / det,
        )
    } else {
        d
    }
}

/// The reference's detailed profile along one plane, walked outwards one `profile_step` at a
/// time: the current point (distance `s`, elevation angle's tangent from the eye, rest
/// position) and the one before it.
struct Walk<'a> {
    geometry: &'a WaveSet,
    time: f64,
    eye_height: f64,
    step: f64,
    max_distance: f64,
    h: DVec2,
    s: f64,
    x: DVec2,
    sums: PointSums,
    elevation: f64,
    prev: Option<(f64, DVec2)>,
}

impl<'a> Walk<'a> {
    fn new(ctx: &Ctx<'a>, h: DVec2, near: f64) -> Self {
        let mut walk = Self {
            geometry: ctx.geometry,
            time: ctx.p.time,
            eye_height: ctx.p.eye_height,
            step: ctx.p.profile_step,
            max_distance: ctx.p.max_distance,
            h,
            s: near,
            x: h * near,
            sums: PointSums::REST,
            elevation: 0.0,
            prev: None,
        };
        walk.solve();
        walk
    }

    fn solve(&mut self) {
        let (geometry, time) = (self.geometry, self.time);
        let (x, sums) = invert(self.x, self.h * self.s, |x| {
            let mut sums = PointSums::REST;
            let _ = geometry.add_sums_f64(x, time, [1.0, 0.0], &mut sums);
            sums
        });
        self.x = x;
        self.sums = sums;
        self.elevation = (sums.y - self.eye_height) / self.s;
    }

    fn advance(&mut self) {
        self.prev = Some((self.elevation, self.x));
        self.x += predict(&self.sums, self.h * self.step);
        self.s += self.step;
        self.solve();
    }

    /// Moves to the distance `s` without visiting the points before it.
    fn jump(&mut self, s: f64) {
        self.prev = None;
        self.x += predict(&self.sums, self.h * (s - self.s));
        self.s = s;
        self.solve();
    }

    /// The rest position where the ray of slope `slope` first meets the profile (linear
    /// between the two points around the crossing), walking forwards; `None` beyond
    /// `max_distance`.
    fn hit(&mut self, slope: f64) -> Option<DVec2> {
        while self.elevation < slope {
            if self.s + self.step > self.max_distance {
                return None;
            }
            self.advance();
        }
        Some(match self.prev {
            Some((a, rest)) if self.elevation > a => {
                let t = ((slope - a) / (self.elevation - a)).clamp(0.0, 1.0);
                rest.lerp(self.x, t)
            }
            _ => self.x,
        })
    }
}

fn add(acc: &mut SeaLight, v: &SeaLight, w: f64) {
    acc.sun += v.sun * w;
    acc.sky += v.sky * w;
    acc.sea += v.sea * w;
}
