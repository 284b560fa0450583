//! The distributed AO sample pass (§2.3): Eq. 1 or the appendix's falloff over the spiral
//! samples (Eq. 6–8), each read from the MIP level of Eq. 9–10, then the 2×2 quad bilateral.

use alloc::vec;
use alloc::vec::Vec;

use glam::Vec3;

use crate::for_rows;
use crate::hierarchy::ZHierarchy;
use crate::params::{Estimator, SaoParams};
use crate::reconstruct::{FaceNormal, NormalEstimate, ProjectionInfo, SKY_Z, face_normal};
use crate::spiral::{Spiral, hash_angle, mip_level};
use crate::viewport::Viewport;

/// The estimator's host-side constants.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum EstimatorConstants {
    /// Eq. 1: `A = max(0, 1 − two_sigma·Σ/n)^k`.
    Alchemy {
        /// `2σ`.
        two_sigma: f32,
        /// β.
        beta: f32,
        /// k.
        k: f32,
    },
    /// The appendix: `A = max(0, 1 − five_intensity·Σ/n)`.
    Falloff {
        /// `5·intensity`.
        five_intensity: f32,
        /// β (metres).
        beta: f32,
    },
}

/// Every constant the sample pass uses, computed once on the host (in `f64`, rounded once):
/// the content of the GPU twin's uniform block.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SampleConstants {
    /// The spiral (Eq. 6–7).
    pub spiral: Spiral,
    /// `r·S'` (Eq. 5's numerator).
    pub radius_pixels: f32,
    /// `r²`.
    pub radius2: f32,
    /// `1/r²`.
    pub inv_radius2: f32,
    /// ε.
    pub epsilon: f32,
    /// `log₂ q'` (Eq. 9).
    pub mip_switch_log2: u32,
    /// Highest level read (Eq. 9's clamp; at most the hierarchy's top level).
    pub max_mip: u32,
    /// The estimator's constants.
    pub estimator: EstimatorConstants,
    /// How face normals are reconstructed.
    pub normals: NormalEstimate,
    /// `1/cos γ_max` of the normal rejection, if enabled.
    pub normal_limit: Option<f32>,
}

impl SampleConstants {
    /// Derives the constants from validated parameters and Eq. 5's `S'`.
    pub fn new(params: &SaoParams, info: &ProjectionInfo) -> Self {
        let r = f64::from(params.radius);
        let estimator = match params.estimator {
            Estimator::Alchemy { sigma, beta, k } => EstimatorConstants::Alchemy {
                two_sigma: 2.0 * sigma,
                beta,
                k,
            },
            Estimator::Falloff { beta, intensity } => EstimatorConstants::Falloff {
                five_intensity: 5.0 * intensity,
                beta,
            },
        };
        Self {
            spiral: Spiral::new(params.samples, params.spiral_turns),
            radius_pixels: (r * f64::from(info.pixels_per_metre)) as f32,
            radius2: (r * r) as f32,
            inv_radius2: (1.0 / (r * r)) as f32,
            epsilon: params.epsilon,
            mip_switch_log2: params.mip_switch_log2,
            max_mip: params.max_mip,
            estimator,
            normals: params.normals,
            normal_limit: params
                .normal_rejection
                .map(|n| (1.0 / ocean_core::math::cos(f64::from(n.max_incidence))) as f32),
        }
    }
}

/// The raw obscurance of output pixel `(x, y)` (before any filter): 1 for sky and for pixels
/// whose normal is undefined or rejected.
///
/// With `C` the pixel's Eq. 3 position at input `(x', y') = (x + guard, y + guard)`, `n̂` its
/// Eq. 4 normal, `r'` its Eq. 5 radius and `φ` = [`hash_angle`]`(x, y)`, sample `i` is
///
/// 1. `h = r'·α_i` and `û_i` from [`Spiral::tap`];
/// 2. the input pixel `p = (x', y') + (i32(h·û.x), i32(h·û.y))`, each product truncated toward
///    zero; a sample outside the input image is skipped (and not counted);
/// 3. `m = `[`mip_level`]`(h)`, `z = z^m(p >> m)` (Eq. 10, clamped to the level);
/// 4. `Q = ` Eq. 3 with that z at the position the texel stands for ([`ZHierarchy::sample`]:
///    for the rotated grid, the level-0 pixel its z was copied from), `v = Q − C`;
/// 5. the estimator's term when `v·v < r²`.
///
/// The sum is normalised by the number `n` of samples inside the image (no sample inside: 1).
pub fn sample_pixel(
    k: &SampleConstants,
    info: &ProjectionInfo,
    viewport: &Viewport,
    z: &ZHierarchy,
    x: usize,
    y: usize,
) -> f32 {
    let g = viewport.guard();
    let (w, h) = (viewport.input_width(), viewport.input_height());
    let (xi, yi) = (x + g, y + g);
    let z0 = z.base().z();
    let z_c = z0[yi * w + xi];
    if z_c == SKY_Z {
        return 1.0;
    }
    let n_c = match face_normal(info, viewport, z0, x, y, k.normals, k.normal_limit) {
        FaceNormal::Valid(n) => n,
        FaceNormal::Undefined | FaceNormal::Rejected => return 1.0,
    };
    let c = info.position(xi as i32, yi as i32, z_c);
    let r_px = info.screen_radius(k.radius_pixels, z_c);
    let phi = hash_angle(x as u32, y as u32);
    let max_mip = k.max_mip.min(z.max_level());
    let mut sum = 0.0f32;
    let mut count = 0u32;
    for i in 0..k.spiral.samples {
        let tap = k.spiral.tap(i, phi);
        let hp = r_px * tap.alpha;
        let px = xi as i32 + (hp * tap.dir[0]) as i32;
        let py = yi as i32 + (hp * tap.dir[1]) as i32;
        if px < 0 || py < 0 || px >= w as i32 || py >= h as i32 {
            continue;
        }
        count += 1;
        let m = mip_level(hp, k.mip_switch_log2, max_mip);
        let (zq, u, vq) = z.sample(m, px, py);
        let v = info.position_at(u, vq, zq) - c;
        sum += term(k, v, n_c, z_c);
    }
    if count == 0 {
        return 1.0;
    }
    let n = count as f32;
    match k.estimator {
        EstimatorConstants::Alchemy { two_sigma, k, .. } => {
            let a = (1.0 - two_sigma * sum / n).max(0.0);
            if k == 1.0 { a } else { libm::powf(a, k) }
        }
        EstimatorConstants::Falloff { five_intensity, .. } => {
            (1.0 - five_intensity * sum / n).max(0.0)
        }
    }
}

/// One sample's contribution (zero outside the ball).
#[inline]
fn term(k: &SampleConstants, v: Vec3, n: Vec3, z_c: f32) -> f32 {
    let vv = v.dot(v);
    // Written so that NaN is outside.
    let inside = vv < k.radius2;
    if !inside {
        return 0.0;
    }
    let vn = v.dot(n);
    match k.estimator {
        EstimatorConstants::Alchemy { beta, .. } => (vn + z_c * beta).max(0.0) / (vv + k.epsilon),
        EstimatorConstants::Falloff { beta, .. } => {
            let f = (k.radius2 - vv).max(0.0) * k.inv_radius2;
            f * f * f * ((vn - beta) / (vv + k.epsilon)).max(0.0)
        }
    }
}

/// The sample pass over every output pixel (row-major output image).
pub fn sample_pass(
    k: &SampleConstants,
    info: &ProjectionInfo,
    viewport: &Viewport,
    z: &ZHierarchy,
) -> Vec<f32> {
    let ow = viewport.output_width();
    let mut out = vec![0.0f32; viewport.output_len()];
    for_rows(&mut out, ow, |y, row| {
        for (x, a) in row.iter_mut().enumerate() {
            *a = sample_pixel(k, info, viewport, z, x, y);
        }
    });
    out
}

/// The 2×2 quad bilateral that ends the sample pass (§2.3): within each quad of output pixels
/// (`x ^ 1`, `y ^ 1`), first each horizontal pair is replaced by its mean `(A_left + A_right)·½`
/// when its level-0 z differ by less than `threshold` metres, then each vertical pair of the
/// result likewise (the order of the shader's `dFdx` then `dFdy` steps). A pixel whose partner
/// lies outside the output (odd sizes) keeps its value.
///
/// # Panics
///
/// Never for buffers of the viewport's sizes (the pipeline checks them).
pub fn quad_bilateral(viewport: &Viewport, z0: &[f32], raw: &[f32], threshold: f32) -> Vec<f32> {
    let (ow, oh) = (viewport.output_width(), viewport.output_height());
    let (g, w) = (viewport.guard(), viewport.input_width());
    let zat = |x: usize, y: usize| z0[(y + g) * w + x + g];
    let mut horizontal = vec![0.0f32; raw.len()];
    for_rows(&mut horizontal, ow, |y, row| {
        for (x, out) in row.iter_mut().enumerate() {
            let p = x ^ 1;
            let a = raw[y * ow + x];
            *out = if p < ow && (zat(x, y) - zat(p, y)).abs() < threshold {
                let (l, r) = (x.min(p), x.max(p));
                (raw[y * ow + l] + raw[y * ow + r]) * 0.5
            } else {
                a
            };
        }
    });
    let mut out = vec![0.0f32; raw.len()];
    for_rows(&mut out, ow, |y, row| {
        let p = y ^ 1;
        for (x, o) in row.iter_mut().enumerate() {
            let a = horizontal[y * ow + x];
            *o = if p < oh && (zat(x, y) - zat(x, p)).abs() < threshold {
                let (t, b) = (y.min(p), y.max(p));
                (horizontal[t * ow + x] + horizontal[b * ow + x]) * 0.5
            } else {
                a
            };
        }
    });
    out
}
