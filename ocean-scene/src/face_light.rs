//! How relief-mapped faces and plain solids are lit: the scene's Sun and the environment's
//! irradiance, in the sea's radiance units, so land, rocks and water share one exposure.

use glam::DVec3;
use ocean_brdf::{Irradiance, Lighting};

/// The lighting of relief faces in the sea's radiance units (a Lambertian face's radiance is
/// albedo × E/π): the Sun's direction and its irradiance over π, and the environment's
/// irradiance on every orientation (`ocean_brdf::Irradiance`: the sky above the horizon, the
/// sea below it), in linear RGB, as the terrain is lit.
#[derive(Clone, Copy, Debug)]
pub struct FaceLight {
    pub sun_dir: DVec3,
    pub sun: DVec3,
    pub sky: Irradiance,
}

impl FaceLight {
    /// A Sun from above and in front, and a sky brighter towards the zenith: the light of the
    /// unit tests.
    #[cfg(test)]
    pub fn for_tests() -> Self {
        Self {
            sun_dir: DVec3::new(0.3, 0.8, -0.5),
            sun: DVec3::new(0.3, 0.25, 0.2),
            sky: Irradiance::from_radiance(|d| DVec3::splat(0.1 * d.y.max(0.0))),
        }
    }

    pub fn new(lighting: &Lighting) -> Self {
        let sky = lighting.sky();
        Self {
            sun_dir: sky.sun_direction(),
            sun: sky.sun_radiance() * sky.sun_solid_angle() / std::f64::consts::PI,
            sky: Irradiance::new(lighting),
        }
    }
}
