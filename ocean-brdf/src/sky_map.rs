//! The sky map (§5.2): the sky's radiance in the stereographic parameterisation, with a mip
//! chain, and the two lookups of Eq. 27.
//!
//! Texel `(i, j)` of level 0 (of size `N`) holds the radiance towards
//! `inverse_stereographic(u)` with `u = (2 t - 1) E`, `t = ((i + ½)/N, (j + ½)/N)` and
//! `E =` [`SKY_MAP_EXTENT`]: the disc `|u| ≤ 1` is the sky, the ring outside it the
//! directions just below the horizon (which the sea's multiple reflections light, §6). Each
//! coarser level is the 2×2 mean of the level above. Values are rounded to binary16, the
//! precision of the `rgba16float` texture the GPU samples, so the CPU and the GPU read the
//! same numbers.
//!
//! Lookups (texture coordinates in `[0, 1]`, clamp to edge, texel centres at half-integers as
//! in every graphics API):
//! - [`SkyMap::gaussian`]: the reference. The exact elliptical Gaussian filter of Eq. 22
//!   (without the Heaviside term, as the paper drops it) under the linearisation of Fig. 8: the
//!   slopes `ζ ~ N(0, diag(σ_x², σ_y²))` map to `u0 + (∂u/∂ζ_x) ζ_x + (∂u/∂ζ_y) ζ_y`. Integrated
//!   by quadrature over level 0.
//! - [`SkyMap::grad_fetch`]: what the GPU computes instead of `texture2DGrad`, and its CPU twin:
//!   a 3×3 Gauss–Hermite rule on the same Gaussian (9 trilinear samples; the paper reports
//!   that nine samples inside the elliptical support fixed `texture2DGrad`'s artefacts near the
//!   horizon, §7.3), each sample taken at the mip level whose texel matches the ellipse's minor
//!   standard deviation, so the rule's nodes need no finer detail than that level holds. It is
//!   deterministic on every GPU (explicit LOD, no hardware anisotropy), which the parity test
//!   relies on.

use alloc::vec::Vec;

use glam::{DVec2, DVec3};

use crate::error::BrdfError;
use crate::quadrature::{composite_nodes, gauss_legendre, standard_normal};
use crate::sky::{Sky, check_rgb, inverse_stereographic};

/// Half-width of the square of the stereographic plane the map covers: `u ∈ [-E, E]²`. 1.1
/// keeps reflections down to 5.4° below the horizon inside the map (`|u| = 1.1` is
/// `r_y = -0.095`); lookups beyond clamp to the edge, which holds the below-horizon radiance.
pub const SKY_MAP_EXTENT: f64 = 1.1;

/// Smallest and largest accepted level-0 sizes (powers of two).
pub const SKY_MAP_MIN_SIZE: u32 = 4;
/// See [`SKY_MAP_MIN_SIZE`].
pub const SKY_MAP_MAX_SIZE: u32 = 4096;

/// A mip-mapped sky map: RGBA texels (A = 1) as binary16 values stored in f32.
#[derive(Clone, Debug, PartialEq)]
pub struct SkyMap {
    size: u32,
    levels: Vec<Vec<[f32; 4]>>,
}

impl SkyMap {
    /// Renders `sky` into a `size`² map (a power of two in
    /// [[`SKY_MAP_MIN_SIZE`], [`SKY_MAP_MAX_SIZE`]]) with `below_horizon` radiance outside the
    /// horizon circle, and builds its mip chain down to 1×1.
    pub fn new(sky: &Sky, below_horizon: DVec3, size: u32) -> Result<Self, BrdfError> {
        if !size.is_power_of_two() || !(SKY_MAP_MIN_SIZE..=SKY_MAP_MAX_SIZE).contains(&size) {
            return Err(BrdfError::OutOfRange {
                name: "sky map size (a power of two)",
                value: size as f64,
                min: SKY_MAP_MIN_SIZE as f64,
                max: SKY_MAP_MAX_SIZE as f64,
            });
        }
        check_rgb("below_horizon", below_horizon)?;
        let n = size as usize;
        let mut base = Vec::with_capacity(n * n);
        for j in 0..n {
            for i in 0..n {
                let u = texel_u(i, j, n);
                let radiance = if u.dot(u) < 1.0 {
                    sky.radiance(inverse_stereographic(u))
                } else {
                    below_horizon
                };
                base.push(texel(radiance)?);
            }
        }
        let mut levels = Vec::new();
        levels.push(base);
        let mut s = n;
        while s > 1 {
            let prev = levels.last().expect("level 0 exists");
            let h = s / 2;
            let mut next = Vec::with_capacity(h * h);
            for j in 0..h {
                for i in 0..h {
                    let mut sum = DVec3::ZERO;
                    for (di, dj) in [(0, 0), (1, 0), (0, 1), (1, 1)] {
                        let t = prev[(2 * j + dj) * s + 2 * i + di];
                        sum += DVec3::new(t[0] as f64, t[1] as f64, t[2] as f64);
                    }
                    // Means of representable values stay representable.
                    next.push(texel(sum * 0.25)?);
                }
            }
            levels.push(next);
            s = h;
        }
        Ok(Self { size, levels })
    }

    /// The size of level 0.
    pub fn size(&self) -> u32 {
        self.size
    }

    /// The number of mip levels (`log2(size) + 1`).
    pub fn level_count(&self) -> u32 {
        self.levels.len() as u32
    }

    /// The texels of `level`, row-major from `t = (0, 0)`, RGBA.
    pub fn level(&self, level: u32) -> Option<&[[f32; 4]]> {
        self.levels.get(level as usize).map(Vec::as_slice)
    }

    /// Texture coordinates of a point `u` of the stereographic plane.
    #[inline]
    pub fn texcoord(u: DVec2) -> DVec2 {
        u / (2.0 * SKY_MAP_EXTENT) + DVec2::splat(0.5)
    }

    /// Bilinear sample of `level` (clamped to the chain) at texture coordinates `t`, clamp to
    /// edge.
    pub fn bilinear(&self, level: u32, t: DVec2) -> DVec3 {
        let l = (level as usize).min(self.levels.len() - 1);
        let s = (self.size as usize >> l).max(1);
        let texels = &self.levels[l];
        let x = t.x * s as f64 - 0.5;
        let y = t.y * s as f64 - 0.5;
        let (x0, y0) = (libm::floor(x), libm::floor(y));
        let (fx, fy) = (x - x0, y - y0);
        let fetch = |i: f64, j: f64| {
            // Clamp in f64 first: `as` saturates, but NaN or huge coordinates must land on an
            // edge texel too.
            let i = if i.is_nan() {
                0.0
            } else {
                i.clamp(0.0, (s - 1) as f64)
            } as usize;
            let j = if j.is_nan() {
                0.0
            } else {
                j.clamp(0.0, (s - 1) as f64)
            } as usize;
            let t = texels[j * s + i];
            DVec3::new(t[0] as f64, t[1] as f64, t[2] as f64)
        };
        let top = fetch(x0, y0) * (1.0 - fx) + fetch(x0 + 1.0, y0) * fx;
        let bottom = fetch(x0, y0 + 1.0) * (1.0 - fx) + fetch(x0 + 1.0, y0 + 1.0) * fx;
        top * (1.0 - fy) + bottom * fy
    }

    /// Trilinear sample at texture coordinates `t` and level of detail `lod` (clamped to
    /// `[0, levels - 1]`), as `textureSampleLevel` with linear mip filtering.
    pub fn sample_level(&self, t: DVec2, lod: f64) -> DVec3 {
        let max = (self.levels.len() - 1) as f64;
        let lod = if lod.is_nan() {
            0.0
        } else {
            lod.clamp(0.0, max)
        };
        let l0 = libm::floor(lod);
        let f = lod - l0;
        let a = self.bilinear(l0 as u32, t);
        if f == 0.0 {
            a
        } else {
            a * (1.0 - f) + self.bilinear(l0 as u32 + 1, t) * f
        }
    }

    /// Eq. 27 as the GPU computes it: the mean radiance over the slopes' Gaussian mapped to the
    /// stereographic plane, centred on `u0` with axes `du_x = 2σ_x ∂u/∂ζ_x` and
    /// `du_y = 2σ_y ∂u/∂ζ_y` (Algorithm 5.1's `Δu_x`, `Δu_y`, in stereographic units), by a
    /// 3×3 Gauss–Hermite rule of trilinear samples (see the module documentation).
    pub fn grad_fetch(&self, u0: DVec2, du_x: DVec2, du_y: DVec2) -> DVec3 {
        let scale = 1.0 / (2.0 * SKY_MAP_EXTENT);
        // Standard deviations along the two axes, in texture units: ζ_x ~ N(0, σ_x²) moves u
        // by ∂u/∂ζ_x ζ_x, whose deviation is σ_x ∂u/∂ζ_x = du_x / 2.
        let a = du_x * (0.5 * scale);
        let b = du_y * (0.5 * scale);
        let t0 = Self::texcoord(u0);
        let lod = self.gaussian_lod(a, b);
        // Probabilists' Gauss–Hermite, 3 nodes: 0 (weight 2/3) and ±√3 (weights 1/6).
        const NODES: [(f64, f64); 3] = [
            (-1.732_050_807_568_877_2, 1.0 / 6.0),
            (0.0, 2.0 / 3.0),
            (1.732_050_807_568_877_2, 1.0 / 6.0),
        ];
        let mut sum = DVec3::ZERO;
        for (xi, wi) in NODES {
            for (xj, wj) in NODES {
                sum += self.sample_level(t0 + a * xi + b * xj, lod) * (wi * wj);
            }
        }
        sum
    }

    /// The mip level [`SkyMap::grad_fetch`] samples for a Gaussian with axes `a`, `b`
    /// (standard deviations in texture units): the level whose texel is as wide as the
    /// smallest standard deviation of `(a aᵀ + b bᵀ)`, `log2(N √λ_min)`, at least 0.
    pub fn gaussian_lod(&self, a: DVec2, b: DVec2) -> f64 {
        // Covariance [[p, q], [q, r]] and its smallest eigenvalue.
        let p = a.x * a.x + b.x * b.x;
        let q = a.x * a.y + b.x * b.y;
        let r = a.y * a.y + b.y * b.y;
        let mean = 0.5 * (p + r);
        let dev = libm::hypot(0.5 * (p - r), q);
        let lambda_min = (mean - dev).max(0.0);
        let texels = libm::sqrt(lambda_min) * self.size as f64;
        if texels > 1.0 {
            libm::log2(texels)
        } else {
            0.0
        }
    }

    /// The reference for Eq. 27: the same Gaussian as [`SkyMap::grad_fetch`] integrated over
    /// level 0 (bilinear) by a composite Gauss–Legendre rule, 12 panels of 4 nodes on ±6
    /// standard deviations along each axis (2304 samples). A zero axis collapses to one node.
    pub fn gaussian(&self, u0: DVec2, du_x: DVec2, du_y: DVec2) -> DVec3 {
        const HALF_WIDTH: f64 = 6.0;
        let scale = 1.0 / (2.0 * SKY_MAP_EXTENT);
        let a = du_x * (0.5 * scale);
        let b = du_y * (0.5 * scale);
        let t0 = Self::texcoord(u0);
        let gl = gauss_legendre::<4>();
        let mut nodes = [(0.0, 0.0); 48];
        let n = composite_nodes(&gl, -HALF_WIDTH, HALF_WIDTH, 1.0, &mut nodes);
        // Normal-weighted nodes; a zero axis collapses to one node of weight 1.
        let mut weighted = [(0.0, 0.0); 48];
        for (w, &(x, g)) in weighted.iter_mut().zip(&nodes[..n]) {
            *w = (x, g * standard_normal(x));
        }
        let single = [(0.0, 1.0)];
        let along = |v: DVec2| {
            if v == DVec2::ZERO {
                &single[..]
            } else {
                &weighted[..n]
            }
        };
        let mut sum = DVec3::ZERO;
        let mut mass = 0.0;
        for &(xi, wi) in along(a) {
            for &(xj, wj) in along(b) {
                let w = wi * wj;
                sum += self.bilinear(0, t0 + a * xi + b * xj) * w;
                mass += w;
            }
        }
        sum / mass
    }
}

/// The stereographic point at the centre of level-0 texel `(i, j)` of an `n`² map.
fn texel_u(i: usize, j: usize, n: usize) -> DVec2 {
    let t = DVec2::new((i as f64 + 0.5) / n as f64, (j as f64 + 0.5) / n as f64);
    (t * 2.0 - DVec2::ONE) * SKY_MAP_EXTENT
}

/// An RGBA texel with each channel rounded to binary16 (the GPU texture's format); radiances
/// beyond binary16's range are refused rather than turned into infinities.
fn texel(c: DVec3) -> Result<[f32; 4], BrdfError> {
    let max = f64::from(half::f16::MAX);
    let h = |v: f64| {
        if v <= max {
            Ok(half::f16::from_f64(v).to_f32())
        } else {
            Err(BrdfError::OutOfRange {
                name: "sky radiance (binary16 texels: scale the radiance unit down)",
                value: v,
                min: 0.0,
                max,
            })
        }
    };
    Ok([h(c.x)?, h(c.y)?, h(c.z)?, 1.0])
}
