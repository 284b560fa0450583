//! The Sun and the sky (§5.1, §5.2): a default sky model and the stereographic parameterisation
//! of sky directions.
//!
//! The paper leaves the sky model open (any hemispherical environment map). The default here is
//! the CIE standard clear sky (ISO 15469 / CIE S 011, type 12): its relative radiance
//! distribution, scaled per colour channel by a zenith radiance, and the Sun as a disc of the
//! real angular radius carrying a given irradiance. Every parameter is public and documented;
//! radiances and irradiances are linear RGB in any consistent unit (the defaults take the Sun's
//! irradiance at normal incidence as about 1).
//!
//! Directions are world-space unit vectors, right-handed with y up (the paper's z up becomes y
//! here). [`stereographic`] maps a direction `r` to `u = (r_x, r_z)/(1 + r_y)`: the zenith
//! goes to the origin, the horizon to the unit circle, directions below the horizon outside it
//! (§5.2; the paper's `[r_x r_y]/(1 + r_z)` with its z up).

use glam::{DVec2, DVec3};

use crate::error::check_direction;
use crate::error::{BrdfError, check};
use crate::quadrature::{composite_nodes, gauss_legendre};
use crate::variance::SUN_ANGULAR_RADIUS;

/// The stereographic projection of a world direction (y up) from the nadir onto the horizontal
/// plane: `u = (r_x, r_z)/(1 + r_y)` (§5.2).
///
/// `u` is finite for every direction but the nadir, where it is capped at a length of 1e6 in
/// the direction of `(r_x, r_z)` (a texture lookup clamps it to the map's edge anyway).
#[inline]
pub fn stereographic(r: DVec3) -> DVec2 {
    let d = 1.0 + r.y;
    let xz = DVec2::new(r.x, r.z);
    if d > 1e-12 {
        xz / d
    } else {
        let len = libm::hypot(xz.x, xz.y);
        if len > 0.0 {
            xz * (1e6 / len)
        } else {
            DVec2::new(1e6, 0.0)
        }
    }
}

/// The inverse of [`stereographic`]: the unit direction whose projection is `u`,
/// `r = (2 u_x, 1 - |u|², 2 u_y)/(1 + |u|²)`.
#[inline]
pub fn inverse_stereographic(u: DVec2) -> DVec3 {
    let q = u.dot(u);
    DVec3::new(2.0 * u.x, 1.0 - q, 2.0 * u.y) / (1.0 + q)
}

/// The five coefficients of a CIE sky type: the gradation `φ(θ) = 1 + a exp(b / cos θ)` (θ the
/// zenith angle of the sky element) and the indicatrix
/// `f(γ) = 1 + c (exp(d γ) - exp(d π/2)) + e cos² γ` (γ its angle from the Sun).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct CieSky {
    /// Gradation `a`.
    pub a: f64,
    /// Gradation `b`, in [-1000, 0] (negative: the sky brightens towards the horizon).
    pub b: f64,
    /// Indicatrix `c` (the circumsolar brightening).
    pub c: f64,
    /// Indicatrix `d`, in [-1000, 0].
    pub d: f64,
    /// Indicatrix `e` (the forward-scattering term).
    pub e: f64,
}

impl CieSky {
    /// CIE standard sky type 12, "standard clear sky, low turbidity".
    pub const CLEAR: Self = Self {
        a: -1.0,
        b: -0.32,
        c: 10.0,
        d: -3.0,
        e: 0.45,
    };

    /// The gradation `φ(cos θ)`; 1 at and below the horizon (its limit there, as `b < 0`).
    #[inline]
    fn gradation(&self, cos_theta: f64) -> f64 {
        if cos_theta > 0.0 {
            1.0 + self.a * libm::exp(self.b / cos_theta)
        } else {
            1.0
        }
    }

    /// The scattering indicatrix `f(γ)` from `cos γ`.
    #[inline]
    fn indicatrix(&self, cos_gamma: f64) -> f64 {
        let gamma = libm::acos(cos_gamma.clamp(-1.0, 1.0));
        1.0 + self.c
            * (libm::exp(self.d * gamma) - libm::exp(self.d * core::f64::consts::FRAC_PI_2))
            + self.e * cos_gamma * cos_gamma
    }
}

/// What the Sun and the sky are.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SkyParams {
    /// Unit vector towards the Sun (world space, y up). Its elevation must be in `[0°, 90°]`:
    /// the model has no twilight.
    pub sun_direction: DVec3,
    /// The Sun's irradiance on a surface facing it (linear RGB, ≥ 0).
    pub sun_irradiance: DVec3,
    /// The sky's radiance at the zenith (linear RGB, ≥ 0).
    pub zenith_radiance: DVec3,
    /// The relative radiance distribution (CIE sky type).
    pub cie: CieSky,
    /// The Sun's angular radius, radians, in `[1e-5, 0.25]`: the real Sun's
    /// ([`SUN_ANGULAR_RADIUS`]) by default. It sets the Sun's solid angle (Eq. 15) and the
    /// least slope variance of its reflection (§5.1, `ρ²/16`); the paper's validation used a
    /// Sun of 1/8000 of the hemisphere (ρ ≈ 0.91°).
    pub sun_angular_radius: f64,
}

impl Default for SkyParams {
    /// A clear afternoon: the Sun 25° above the horizon towards −z (ahead of a default camera,
    /// which looks along −z), a slightly warm Sun of irradiance about 1 and a blue zenith of
    /// radiance about 1/20 of the Sun's irradiance per steradian (clear skies measure
    /// 0.03–0.08 for the ratio of zenith luminance to direct normal illuminance at these Sun
    /// elevations).
    fn default() -> Self {
        let elevation = 25f64.to_radians();
        Self {
            sun_direction: DVec3::new(0.0, libm::sin(elevation), -libm::cos(elevation)),
            sun_irradiance: DVec3::new(1.0, 0.96, 0.90),
            zenith_radiance: DVec3::new(0.025, 0.045, 0.09),
            cie: CieSky::CLEAR,
            sun_angular_radius: SUN_ANGULAR_RADIUS,
        }
    }
}

/// A validated sky with its derived quantities (the Sun's radiance and solid angle, the sky's
/// irradiance on the sea).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Sky {
    params: SkyParams,
    /// `φ(0) f(θ_s)`, the CIE normalisation: the zenith's relative radiance.
    zenith_norm: f64,
    sun_solid_angle: f64,
    sky_irradiance: DVec3,
}

impl Sky {
    /// Validates the parameters and derives the Sun's radiance and the sky's irradiance.
    pub fn new(params: SkyParams) -> Result<Self, BrdfError> {
        let sun = check_direction("sun_direction", params.sun_direction)?;
        check("sun elevation sin", sun.y, 0.0, 1.0)?;
        check_rgb("sun_irradiance", params.sun_irradiance)?;
        check_rgb("zenith_radiance", params.zenith_radiance)?;
        let cie = params.cie;
        for (name, v) in [
            ("cie.a", cie.a),
            ("cie.b", cie.b),
            ("cie.c", cie.c),
            ("cie.d", cie.d),
            ("cie.e", cie.e),
        ] {
            check(name, v, -1e3, 1e3)?;
        }
        // The gradation a exp(b / cos θ) and the indicatrix's exp(d γ) stay bounded only for
        // b, d <= 0 (every CIE standard type): with b > 0 the gradation grows without bound
        // towards the horizon and the irradiance quadrature overflows.
        check("cie.b", cie.b, -1e3, 0.0)?;
        check("cie.d", cie.d, -1e3, 0.0)?;
        let params = SkyParams {
            sun_direction: sun,
            ..params
        };
        let zenith_norm = cie.gradation(1.0) * cie.indicatrix(sun.y);
        if !(zenith_norm.is_finite() && zenith_norm > 0.0) {
            // A CIE type whose zenith is dark or negative cannot be scaled by a zenith radiance.
            return Err(BrdfError::OutOfRange {
                name: "cie zenith relative radiance",
                value: zenith_norm,
                min: f64::MIN_POSITIVE,
                max: f64::MAX,
            });
        }
        let rho = check("sun_angular_radius", params.sun_angular_radius, 1e-5, 0.25)?;
        let cos_rho = libm::cos(rho);
        let mut sky = Self {
            params,
            zenith_norm,
            sun_solid_angle: core::f64::consts::TAU * (1.0 - cos_rho),
            sky_irradiance: DVec3::ZERO,
        };
        sky.sky_irradiance = sky.integrate_irradiance();
        // A negative relative radiance anywhere (a CIE type outside its domain) would make
        // negative light: refuse it through the irradiance and the horizon samples.
        let irradiance = sky.sky_irradiance;
        let valid = irradiance.is_finite()
            && irradiance.min_element() >= 0.0
            && sky.relative_radiance(DVec3::X) >= 0.0;
        if !valid {
            return Err(BrdfError::OutOfRange {
                name: "cie relative radiance",
                value: sky.sky_irradiance.min_element(),
                min: 0.0,
                max: f64::MAX,
            });
        }
        Ok(sky)
    }

    /// The parameters (with the Sun's direction normalised).
    pub fn params(&self) -> &SkyParams {
        &self.params
    }

    /// Unit vector towards the Sun.
    pub fn sun_direction(&self) -> DVec3 {
        self.params.sun_direction
    }

    /// The Sun's angular radius ρ, radians.
    pub fn sun_angular_radius(&self) -> f64 {
        self.params.sun_angular_radius
    }

    /// The least slope variance of the Sun's reflection, `ρ²/16` (§5.1; see
    /// [`crate::variance::SUN_MIN_VARIANCE`], the real Sun's).
    pub fn sun_min_variance(&self) -> f64 {
        let rho = self.params.sun_angular_radius;
        rho * rho / 16.0
    }

    /// The Sun's solid angle Ω_sun = 2π (1 − cos ρ) (Eq. 15).
    pub fn sun_solid_angle(&self) -> f64 {
        self.sun_solid_angle
    }

    /// The Sun's radiance L_sun = E_sun / Ω_sun (Eq. 15), uniform over its disc.
    pub fn sun_radiance(&self) -> DVec3 {
        self.params.sun_irradiance / self.sun_solid_angle
    }

    /// The Sun's irradiance on the horizontal sea, `E_sun sin(elevation)`.
    pub fn sun_irradiance_horizontal(&self) -> DVec3 {
        self.params.sun_irradiance * self.params.sun_direction.y
    }

    /// The sky's irradiance on the horizontal sea, `∫ L_sky cos θ dω` over the upper
    /// hemisphere (by quadrature, once, in [`Sky::new`]).
    pub fn sky_irradiance(&self) -> DVec3 {
        self.sky_irradiance
    }

    /// The sky's radiance towards the unit direction `dir` (world, y up) for directions above
    /// the horizon, the Sun's disc excluded (it is handled by Eq. 15); zero at and below the
    /// horizon (see [`crate::sea::Lighting::below_horizon_radiance`] for what the sea uses
    /// there).
    pub fn radiance(&self, dir: DVec3) -> DVec3 {
        if dir.y <= 0.0 {
            return DVec3::ZERO;
        }
        self.params.zenith_radiance * self.relative_radiance(dir)
    }

    /// `L(dir)/L_zenith` of the CIE model, for `dir` at or above the horizon.
    fn relative_radiance(&self, dir: DVec3) -> f64 {
        let cie = &self.params.cie;
        let cos_gamma = dir.dot(self.params.sun_direction);
        cie.gradation(dir.y) * cie.indicatrix(cos_gamma) / self.zenith_norm
    }

    /// `∫ L cos θ dω` over the upper hemisphere: composite Gauss–Legendre in `cos θ` (8 panels
    /// of 8 nodes) times the midpoint rule in azimuth (256 intervals, exact for the
    /// trigonometric polynomials a smooth azimuthal profile is made of). The circumsolar peak
    /// is a kink in γ only at the Sun itself, where its weight is negligible; measured
    /// convergence in tests/sky.rs.
    fn integrate_irradiance(&self) -> DVec3 {
        const AZIMUTHS: usize = 256;
        let gl = gauss_legendre::<8>();
        let mut mu_nodes = [(0.0, 0.0); 64];
        let n = composite_nodes(&gl, 0.0, 1.0, 1.0 / 8.0, &mut mu_nodes);
        let d_phi = core::f64::consts::TAU / AZIMUTHS as f64;
        let mut sum = 0.0;
        for &(mu, w) in &mu_nodes[..n] {
            let s = libm::sqrt((1.0 - mu * mu).max(0.0));
            let mut ring = 0.0;
            for j in 0..AZIMUTHS {
                let phi = (j as f64 + 0.5) * d_phi;
                let dir = DVec3::new(s * libm::cos(phi), mu, s * libm::sin(phi));
                ring += self.relative_radiance(dir);
            }
            sum += w * mu * ring * d_phi;
        }
        self.params.zenith_radiance * sum
    }
}

/// Largest irradiance or radiance accepted in any channel (any unit). The Sun's radiance is
/// its irradiance over a solid angle of about 6.8e-5 sr, and the sky's irradiance integrates
/// radiances over the hemisphere: with inputs up to 1e30 every derived quantity stays below
/// 1e35, finite as a double and as the float the GPU reads (FLT_MAX is 3.4e38).
pub const MAX_RADIOMETRIC: f64 = 1e30;

/// Validates an RGB quantity: finite, non-negative and at most [`MAX_RADIOMETRIC`] in every
/// channel.
pub(crate) fn check_rgb(name: &'static str, c: DVec3) -> Result<DVec3, BrdfError> {
    for v in c.to_array() {
        check(name, v, 0.0, MAX_RADIOMETRIC)?;
    }
    Ok(c)
}
