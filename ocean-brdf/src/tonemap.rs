//! Tone mapping from the lighting's linear radiance to display values, shared by the CPU and
//! the GPU renderer (the paper leaves it open; its reference code uses the same exponential
//! curve).

use glam::DVec3;

/// The default exposure: maps the default sky's zenith (radiance ≈ 0.05) to about 0.33 and
/// the default sea's refracted light (≈ 0.01) to about 0.08 before sRGB encoding.
pub const DEFAULT_EXPOSURE: f64 = 8.0;

/// Exponential tone mapping, `1 − exp(−exposure · L)` per channel: linear for dim values,
/// saturating smoothly at 1 for the Sun's glitter. Negative or NaN radiance maps to 0.
pub fn tone_map(radiance: DVec3, exposure: f64) -> DVec3 {
    let f = |x: f64| {
        let y = 1.0 - libm::exp(-exposure * x);
        if y > 0.0 { y.min(1.0) } else { 0.0 }
    };
    DVec3::new(f(radiance.x), f(radiance.y), f(radiance.z))
}

/// The sRGB transfer function (IEC 61966-2-1) from linear `[0, 1]` to encoded `[0, 1]`.
pub fn linear_to_srgb(c: f64) -> f64 {
    let c = if c > 0.0 { c.min(1.0) } else { 0.0 };
    if c <= 0.003_130_8 {
        12.92 * c
    } else {
        1.055 * libm::pow(c, 1.0 / 2.4) - 0.055
    }
}
