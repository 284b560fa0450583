//! The environment's irradiance on a surface of any orientation, for the ambient light of
//! solids (terrain, rocks, posts) lit by the same sky as the sea.
//!
//! The environment is [`Lighting::environment_radiance`]: the sky above the horizon (the Sun's
//! disc excluded: it is direct light) and the sea's below-horizon radiance below it. Its
//! irradiance on a unit normal `n`, `E(n) = ∫ L(ω) max(0, n·ω) dω`, is a smooth function of
//! `n`: the clamped cosine passes almost nothing above spherical-harmonic order 2 (Ramamoorthi &
//! Hanrahan, "An Efficient Representation for Irradiance Environment Maps", 2001), so
//!
//! ```text
//! E(n) ≈ Σ_{l ≤ 2} Σ_m Â_l L_lm Y_lm(n),   Â₀ = π, Â₁ = 2π/3, Â₂ = π/4,
//! L_lm = ∫ L(ω) Y_lm(ω) dω
//! ```
//!
//! with the real, orthonormal `Y_lm` below (polar axis y, world coordinates). The nine
//! `k_lm = Â_l L_lm` are computed once by quadrature (composite Gauss–Legendre in `ω.y` with a
//! panel edge at the horizon, where the environment jumps, times 256 azimuths) and evaluated
//! per pixel in nine multiply-adds, the same on the CPU and in WGSL. Order 2 is exact for a
//! radiance of degree ≤ 2 in `ω`; on the default clear sky over the default sea it stays within
//! 3.1% of the upward irradiance of a brute-force `E(n)` for every normal, the worst facing
//! the horizon where the environment jumps (`tests/irradiance.rs`).

use glam::DVec3;

use crate::quadrature::{composite_nodes, gauss_legendre};
use crate::sea::Lighting;

/// Azimuths of the projection's quadrature.
const AZIMUTHS: usize = 256;

/// The nine real spherical harmonics of order ≤ 2 at the unit vector `d`, in the order
/// `Y₀₀; x, y, z; xy, yz, 3y² − 1, xz, x² − z²` (each with its normalisation).
pub fn sh_basis(d: DVec3) -> [f64; 9] {
    const C0: f64 = 0.282_094_791_773_878_14; // ½√(1/π)
    const C1: f64 = 0.488_602_511_902_919_9; // √(3/4π)
    const C2: f64 = 1.092_548_430_592_079_2; // ½√(15/π)
    const C20: f64 = 0.315_391_565_252_520_05; // ¼√(5/π)
    const C22: f64 = 0.546_274_215_296_039_6; // ¼√(15/π)
    let (x, y, z) = (d.x, d.y, d.z);
    [
        C0,
        C1 * x,
        C1 * y,
        C1 * z,
        C2 * x * y,
        C2 * y * z,
        C20 * (3.0 * y * y - 1.0),
        C2 * x * z,
        C22 * (x * x - z * z),
    ]
}

/// `Â_l` for each of the nine basis functions.
const A_HAT: [f64; 9] = {
    use core::f64::consts::PI;
    let (a0, a1, a2) = (PI, 2.0 * PI / 3.0, PI / 4.0);
    [a0, a1, a1, a1, a2, a2, a2, a2, a2]
};

/// The order-2 irradiance of an environment: `E(n) = Σ k_lm Y_lm(n)`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Irradiance {
    k: [DVec3; 9],
}

impl Irradiance {
    /// The irradiance of `lighting`'s environment (sky and below-horizon radiance).
    pub fn new(lighting: &Lighting) -> Self {
        Self::from_radiance(|d| lighting.environment_radiance(d))
    }

    /// The irradiance of any radiance field `radiance(ω)` (linear RGB, world directions) that
    /// is smooth above and below the horizon.
    pub fn from_radiance(radiance: impl Fn(DVec3) -> DVec3) -> Self {
        let gl = gauss_legendre::<8>();
        let mut nodes = [(0.0, 0.0); 128];
        let below = composite_nodes(&gl, -1.0, 0.0, 1.0 / 8.0, &mut nodes[..64]);
        let above = composite_nodes(&gl, 0.0, 1.0, 1.0 / 8.0, &mut nodes[64..]);
        let d_phi = core::f64::consts::TAU / AZIMUTHS as f64;
        let mut l = [DVec3::ZERO; 9];
        let rows = nodes[..below].iter().chain(&nodes[64..64 + above]);
        for &(mu, w) in rows {
            let s = libm::sqrt((1.0 - mu * mu).max(0.0));
            for j in 0..AZIMUTHS {
                let phi = (j as f64 + 0.5) * d_phi;
                let d = DVec3::new(s * libm::cos(phi), mu, s * libm::sin(phi));
                let r = radiance(d) * (w * d_phi);
                for (acc, y) in l.iter_mut().zip(sh_basis(d)) {
                    *acc += r * y;
                }
            }
        }
        let mut k = [DVec3::ZERO; 9];
        for i in 0..9 {
            k[i] = l[i] * A_HAT[i];
        }
        Self { k }
    }

    /// The irradiance of the coefficients `k_lm = Â_l L_lm` in [`sh_basis`]'s order (those of
    /// [`Irradiance::coefficients`]).
    pub fn from_coefficients(k: [DVec3; 9]) -> Self {
        Self { k }
    }

    /// `k_lm = Â_l L_lm`, in [`sh_basis`]'s order.
    pub fn coefficients(&self) -> &[DVec3; 9] {
        &self.k
    }

    /// `E(n)` for the unit normal `n` (world, y up), clamped at 0 per channel (an order-2
    /// series can dip slightly below 0 facing a black part of the environment).
    pub fn at(&self, n: DVec3) -> DVec3 {
        let mut e = DVec3::ZERO;
        for (k, y) in self.k.iter().zip(sh_basis(n)) {
            e += *k * y;
        }
        e.max(DVec3::ZERO)
    }

    /// The coefficients as nine `f32` RGB rows padded to `vec4` (std140), for a uniform
    /// block; a shader evaluates `max(Σ row_i.rgb · Y_i(n), 0)` with [`sh_basis`]'s functions.
    pub fn gpu_rows(&self) -> [[f32; 4]; 9] {
        self.scaled_rows(1.0)
    }

    /// [`Irradiance::gpu_rows`] times `scale` (`1/π`: the radiance of a white Lambertian
    /// surface, `E/π`).
    pub fn scaled_rows(&self, scale: f64) -> [[f32; 4]; 9] {
        self.k.map(|c| {
            let c = c * scale;
            [c.x as f32, c.y as f32, c.z as f32, 0.0]
        })
    }
}
