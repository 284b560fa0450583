//! Brute-force obscurance on the analytic scenes, in `f64`, to measure the passes against.
//!
//! Both references use the appendix's falloff with the same `r`, `β`, `ε` and intensity as the
//! passes, `F(v) = max(r² − v·v, 0)³·max((v·n̂ − β)/(v·v + ε), 0)`, the exact visible point `C`
//! of each output pixel's centre and its exact normal `n̂`, and
//! `A = max(0, 1 − (5·intensity/r⁶)·mean F)`; background pixels are 1. They differ in where the
//! occluding points come from:
//!
//! - [`ball_obscurance`]: **exact visibility over the ball.** Rays leave `C` in `N × N`
//!   stratified directions uniform in solid angle over the hemisphere about `n̂`
//!   (`cos θ = (i + ½)/N`, `ϕ = 2π(j + ½)/N`); the first surface hit closer than `r` is the
//!   occluder `v = t·ω`, a miss contributes 0. This is ambient obscurance from true 3D
//!   visibility: no depth buffer, no thin-shell assumption, no screen edge.
//! - [`screen_obscurance`]: **the estimator's own limit.** The screen-space disk of Eq. 5's
//!   radius `r'` is sampled as the spiral samples it (radius `r'·α` with `α` uniform, direction
//!   uniform), densely (`N × N` strata, continuous positions), and each sample's occluder is the
//!   exact visible point under it, as a perfect depth buffer would hold. Samples outside the
//!   input image are skipped, as in the sample pass. This is what the sample pass converges to
//!   with infinitely many samples, exact depth and no MIP levels, so its difference from the
//!   passes measures their discretisation (9 samples, MIP levels, depth precision, quad
//!   normals, the blur) rather than the screen-space model.
//! - [`buffer_obscurance`]: **the estimator's limit on a depth buffer**, for scenes known only
//!   by their depth (a renderer's frame): as [`screen_obscurance`], but `C`, its normal and
//!   every occluder come from the buffer's own texels (the occluder is the texel under the
//!   sample, at full resolution, no MIP level; the normal is the nearest-neighbour one, from
//!   the smaller of the two one-sided differences along each axis, facing the eye).

use alloc::vec;
use alloc::vec::Vec;
use core::f64::consts::TAU;

use glam::DVec3;
use ocean_core::math::{cos, sin, sqrt};

use crate::SaoError;
use crate::analytic::{CameraRays, Scene};
use crate::for_rows;
use crate::params::{Estimator, SaoParams};
use crate::viewport::Viewport;

/// The falloff's parameters and the number of strata.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ReferenceParams {
    /// Radius r (m).
    pub radius: f64,
    /// β (m).
    pub beta: f64,
    /// ε (m²).
    pub epsilon: f64,
    /// Intensity.
    pub intensity: f64,
    /// `N`: `N²` directions or disk samples per pixel.
    pub strata: usize,
}

impl ReferenceParams {
    /// The falloff of `params` (which must use [`Estimator::Falloff`]) with `strata` strata.
    ///
    /// # Errors
    ///
    /// [`SaoError::UnsupportedFormat`] for the Eq. 1 estimator; the parameters' range errors.
    pub fn from_params(params: &SaoParams, strata: usize) -> Result<Self, SaoError> {
        params.validate()?;
        let Estimator::Falloff { beta, intensity } = params.estimator else {
            return Err(SaoError::UnsupportedFormat(
                "the references use the appendix falloff",
            ));
        };
        Ok(Self {
            radius: f64::from(params.radius),
            beta: f64::from(beta),
            epsilon: f64::from(params.epsilon),
            intensity: f64::from(intensity),
            strata: strata.max(1),
        })
    }

    fn falloff(&self, v: DVec3, n: DVec3) -> f64 {
        let r2 = self.radius * self.radius;
        let vv = v.dot(v);
        let inside = vv < r2;
        if !inside {
            return 0.0;
        }
        let f = (r2 - vv) / r2;
        f * f * f * ((v.dot(n) - self.beta) / (vv + self.epsilon)).max(0.0)
    }

    /// The visibility of `c` (normal `normal`) from Eq. 5's disk of `r_px` pixels around
    /// pixel position `centre`, sampled in `N × N` strata as the spiral samples it (radius
    /// `r_px·α` with `α` uniform, direction uniform); samples outside a `size` image are
    /// skipped, and each other sample's occluder is `occluder(px, py)` (none: no surface).
    fn disk(
        &self,
        r_px: f64,
        (cx, cy): (f64, f64),
        (w, h): (f64, f64),
        c: DVec3,
        normal: DVec3,
        occluder: impl Fn(f64, f64) -> Option<DVec3>,
    ) -> f32 {
        let n = self.strata;
        let mut sum = 0.0;
        let mut count = 0;
        for i in 0..n {
            let hp = r_px * (i as f64 + 0.5) / n as f64;
            for j in 0..n {
                let theta = TAU * (j as f64 + 0.5) / n as f64;
                let (px, py) = (cx + hp * cos(theta), cy + hp * sin(theta));
                if !(px >= 0.0 && py >= 0.0 && px < w && py < h) {
                    continue;
                }
                count += 1;
                if let Some(q) = occluder(px, py) {
                    sum += self.falloff(q - c, normal);
                }
            }
        }
        self.visibility(sum, count)
    }

    fn visibility(&self, sum: f64, count: usize) -> f32 {
        if count == 0 {
            return 1.0;
        }
        (1.0 - 5.0 * self.intensity * sum / count as f64).max(0.0) as f32
    }
}

/// The exact visible point and normal at output pixel `(x, y)`'s centre.
fn centre(
    rays: &CameraRays,
    scene: &Scene,
    viewport: &Viewport,
    x: usize,
    y: usize,
) -> Option<(DVec3, DVec3)> {
    let g = viewport.guard() as f64;
    let hit = rays.trace(scene, x as f64 + g + 0.5, y as f64 + g + 0.5)?;
    Some((hit.point, hit.normal))
}

/// Ambient obscurance with exact visibility over the ball (see the module doc), output size.
pub fn ball_obscurance(
    scene: &Scene,
    rays: &CameraRays,
    viewport: &Viewport,
    params: &ReferenceParams,
) -> Vec<f32> {
    let ow = viewport.output_width();
    let n = params.strata;
    let mut out = vec![1.0f32; viewport.output_len()];
    for_rows(&mut out, ow, |y, row| {
        for (x, a) in row.iter_mut().enumerate() {
            let Some((c, normal)) = centre(rays, scene, viewport, x, y) else {
                continue;
            };
            let (t, b) = basis(normal);
            let t_min = 1.0e-9 * (1.0 + c.length());
            let mut sum = 0.0;
            for i in 0..n {
                let cos_t = (i as f64 + 0.5) / n as f64;
                let sin_t = sqrt((1.0 - cos_t * cos_t).max(0.0));
                for j in 0..n {
                    let phi = TAU * (j as f64 + 0.5) / n as f64;
                    let dir = (t * cos(phi) + b * sin(phi)) * sin_t + normal * cos_t;
                    if let Some(hit) = scene.trace(c, dir, t_min, params.radius) {
                        sum += params.falloff(hit.point - c, normal);
                    }
                }
            }
            *a = params.visibility(sum, n * n);
        }
    });
    out
}

/// The converged screen-space estimator with exact depth (see the module doc), output size.
pub fn screen_obscurance(
    scene: &Scene,
    rays: &CameraRays,
    viewport: &Viewport,
    params: &ReferenceParams,
) -> Vec<f32> {
    let ow = viewport.output_width();
    let (w, h) = (
        viewport.input_width() as f64,
        viewport.input_height() as f64,
    );
    let g = viewport.guard() as f64;
    let s_prime = rays.pixels_per_metre();
    let mut out = vec![1.0f32; viewport.output_len()];
    for_rows(&mut out, ow, |y, row| {
        for (x, a) in row.iter_mut().enumerate() {
            let Some((c, normal)) = centre(rays, scene, viewport, x, y) else {
                continue;
            };
            let z = rays.to_view(c).z;
            let r_px = if rays.is_perspective() {
                params.radius * s_prime / -z
            } else {
                params.radius * s_prime
            };
            let centre = (x as f64 + g + 0.5, y as f64 + g + 0.5);
            *a = params.disk(r_px, centre, (w, h), c, normal, |px, py| {
                rays.trace(scene, px, py).map(|hit| hit.point)
            });
        }
    });
    out
}

/// View-space positions of a `width × height` window-depth buffer (rows from the top) seen by
/// `camera`: each texel's centre taken back through the inverse view-projection; `None` where
/// the depth lies on the far plane or at infinity (the background).
pub fn view_positions(
    camera: &ocean_core::Camera,
    depth: &[f32],
    width: usize,
    height: usize,
) -> Vec<Option<DVec3>> {
    let convention = camera.depth();
    let clear = convention.clear_depth();
    let gl = convention.range() == ocean_core::DepthRange::NegOneToOne;
    let window_clear = if gl { 0.5 * clear + 0.5 } else { clear };
    let view = camera.view_f64();
    depth
        .iter()
        .enumerate()
        .map(|(i, &d)| {
            let d = f64::from(d);
            if d == window_clear {
                return None;
            }
            let ndc_z = if gl { 2.0 * d - 1.0 } else { d };
            let (x, y) = ((i % width) as f64 + 0.5, (i / width) as f64 + 0.5);
            let ndc = DVec3::new(
                2.0 * x / width as f64 - 1.0,
                1.0 - 2.0 * y / height as f64,
                ndc_z,
            );
            let p = camera.ndc_to_world(ndc).ok()?;
            let v = view.transform_point3(p);
            v.is_finite().then_some(v)
        })
        .collect()
}

/// The converged screen-space estimator on a depth buffer (see the module doc), output size:
/// `positions` are the input image's view-space positions ([`view_positions`]), `rays` give the
/// projection's scale.
pub fn buffer_obscurance(
    positions: &[Option<DVec3>],
    rays: &CameraRays,
    viewport: &Viewport,
    params: &ReferenceParams,
) -> Vec<f32> {
    let ow = viewport.output_width();
    let (iw, ih) = (viewport.input_width(), viewport.input_height());
    let g = viewport.guard();
    let s_prime = rays.pixels_per_metre();
    let at = |x: i64, y: i64| {
        if x < 0 || y < 0 || x >= iw as i64 || y >= ih as i64 {
            None
        } else {
            positions[y as usize * iw + x as usize]
        }
    };
    // The one-sided difference of smaller depth change, or the other where one is missing.
    let nearest = |c: DVec3, a: Option<DVec3>, b: Option<DVec3>| match (a, b) {
        (Some(a), Some(b)) if (a.z - c.z).abs() < (b.z - c.z).abs() => Some(c - a),
        (_, Some(b)) => Some(b - c),
        (Some(a), None) => Some(c - a),
        (None, None) => None,
    };
    let mut out = vec![1.0f32; viewport.output_len()];
    for_rows(&mut out, ow, |y, row| {
        for (x, a) in row.iter_mut().enumerate() {
            let (ix, iy) = ((x + g) as i64, (y + g) as i64);
            let Some(c) = at(ix, iy) else {
                continue;
            };
            let dx = nearest(c, at(ix - 1, iy), at(ix + 1, iy));
            let dy = nearest(c, at(ix, iy - 1), at(ix, iy + 1));
            let (Some(dx), Some(dy)) = (dx, dy) else {
                continue;
            };
            // Rows run downwards: x × (−y) faces the eye for a surface facing it.
            let mut normal = dy.cross(dx).normalize_or_zero();
            let to_eye = if rays.is_perspective() { -c } else { DVec3::Z };
            if normal.dot(to_eye) < 0.0 {
                normal = -normal;
            }
            if normal == DVec3::ZERO {
                continue;
            }
            let r_px = if rays.is_perspective() {
                params.radius * s_prime / -c.z
            } else {
                params.radius * s_prime
            };
            let centre = (ix as f64 + 0.5, iy as f64 + 0.5);
            let size = (iw as f64, ih as f64);
            *a = params.disk(r_px, centre, size, c, normal, |px, py| {
                at(px as i64, py as i64)
            });
        }
    });
    out
}

/// An orthonormal basis `(t, b)` completing the unit vector `n`.
fn basis(n: DVec3) -> (DVec3, DVec3) {
    let helper = if n.x.abs() < 0.9 { DVec3::X } else { DVec3::Y };
    let t = n.cross(helper).normalize();
    (t, n.cross(t))
}

/// Mean squared error and Pearson correlation between two images over selected pixels.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Comparison {
    /// Pixels compared.
    pub pixels: usize,
    /// Mean squared difference.
    pub mse: f64,
    /// Pearson correlation coefficient (NaN when either image is constant).
    pub correlation: f64,
    /// Mean of the first image.
    pub mean_a: f64,
    /// Mean of the second image.
    pub mean_b: f64,
}

/// Compares `a` and `b` over the pixels `i` where `keep(i)` holds.
pub fn compare(a: &[f32], b: &[f32], keep: impl Fn(usize) -> bool) -> Comparison {
    let idx: Vec<usize> = (0..a.len().min(b.len())).filter(|&i| keep(i)).collect();
    let k = idx.len().max(1) as f64;
    let mean_a = idx.iter().map(|&i| f64::from(a[i])).sum::<f64>() / k;
    let mean_b = idx.iter().map(|&i| f64::from(b[i])).sum::<f64>() / k;
    let (mut sab, mut saa, mut sbb, mut se) = (0.0, 0.0, 0.0, 0.0);
    for &i in &idx {
        let (da, db) = (f64::from(a[i]) - mean_a, f64::from(b[i]) - mean_b);
        sab += da * db;
        saa += da * da;
        sbb += db * db;
        let d = f64::from(a[i]) - f64::from(b[i]);
        se += d * d;
    }
    Comparison {
        pixels: idx.len(),
        mse: se / k,
        correlation: sab / sqrt(saa * sbb),
        mean_a,
        mean_b,
    }
}
