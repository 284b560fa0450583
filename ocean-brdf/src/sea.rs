//! The sea's colour: Algorithm 5.1 (Fig. 9) on the CPU, the twin of the GPU renderer's
//! fragment shader.
//!
//! For a point of the sea seen along `v` with the filtered normal `n` (Eq. 3) and the slope
//! variances of the unresolved waves (Eq. 4) along and across the wind, the radiance towards
//! the viewer is the sum of three terms, kept apart so each can be validated (§7.2, Fig. 10):
//! - the Sun's reflection, Eq. 15, with the variances raised to the Sun's disc (§5.1);
//! - the sky's reflection `F̄ L̄` (Eq. 21): the effective Fresnel (Eq. 24, tabulated rather
//!   than the fit of Eq. 26, see [`crate::fresnel_table`]) times the sky map filtered over the
//!   visible slopes' footprint (Eq. 27, see [`visible_sky_footprint`]);
//! - the light refracted out of the water, `L_sea (1 − F̄)` (Eq. 28), with `L_sea` diffuse and
//!   proportional to the Sun's and the sky's irradiance (§5.3).
//!
//! World space is right-handed with y up; every direction is a unit vector.

use glam::{DVec2, DVec3};

use crate::error::check_direction;
use crate::error::{BrdfError, check};
use crate::fresnel::{WATER_R, sigma_v2};
use crate::fresnel_table::effective_fresnel_table_unchecked;
use crate::ross::sun_radiance_unchecked;
use crate::sky::{Sky, SkyParams, check_rgb, stereographic};
use crate::sky_map::SkyMap;
use crate::surface::PixelSurface;
pub use crate::surface::{tangent_frame, visible_normal};
use crate::variance::SlopeVariance;

/// The finite-difference step of Algorithm 5.1's slope derivatives of `U` (Fig. 9: "precise
/// enough with ε = 10⁻³").
pub const SLOPE_EPSILON: f64 = 1e-3;

/// The water body under the surface.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SeaParams {
    /// Diffuse reflectance of the water body (linear RGB, in `[0, 1]`): the light scattered back
    /// up to the surface is `L_sea = albedo (E_sun + E_sky)/π` (§5.3).
    pub albedo: DVec3,
    /// Fresnel reflectance at normal incidence, `R` of Eq. 14.
    pub fresnel_r: f64,
}

impl Default for SeaParams {
    /// Deep blue open ocean: the reference implementation's sea colour, (10, 40, 120)/255
    /// scaled by 0.1, and water's `R = 0.02`.
    fn default() -> Self {
        Self {
            albedo: DVec3::new(10.0, 40.0, 120.0) / 255.0 * 0.1,
            fresnel_r: WATER_R,
        }
    }
}

/// The Sun, the sky and the sea, validated, with the radiances Algorithm 5.1 needs.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Lighting {
    sky: Sky,
    sea: SeaParams,
    sea_radiance: DVec3,
    below_horizon: DVec3,
}

impl Lighting {
    /// Validates both parameter sets and derives `L_sea` and the below-horizon radiance.
    pub fn new(sky: SkyParams, sea: SeaParams) -> Result<Self, BrdfError> {
        let sky = Sky::new(sky)?;
        for v in check_rgb("albedo", sea.albedo)?.to_array() {
            check("albedo", v, 0.0, 1.0)?;
        }
        check("fresnel_r", sea.fresnel_r, 0.0, 1.0)?;
        let irradiance = sky.sun_irradiance_horizontal() + sky.sky_irradiance();
        let sea_radiance = sea.albedo * irradiance / core::f64::consts::PI;
        // §6, multiple reflections: a view ray reflected below the horizon meets another wave,
        // which returns the sky's mean radiance E_sky/π times its Fresnel reflectance, plus the
        // refracted L_sea times the transmittance. The reflectance is Schlick's averaged over a
        // cosine-weighted hemisphere: R + (1 − R) ∫₀¹ (1 − μ)⁵ 2μ dμ = R + (1 − R)/21.
        let r = sea.fresnel_r;
        let f_hemi = r + (1.0 - r) / 21.0;
        let below_horizon =
            sky.sky_irradiance() / core::f64::consts::PI * f_hemi + sea_radiance * (1.0 - f_hemi);
        Ok(Self {
            sky,
            sea,
            sea_radiance,
            below_horizon,
        })
    }

    /// The sky and the Sun.
    pub fn sky(&self) -> &Sky {
        &self.sky
    }

    /// The water body.
    pub fn sea(&self) -> &SeaParams {
        &self.sea
    }

    /// `L_sea`, the diffuse radiance leaving the water body (§5.3).
    pub fn sea_radiance(&self) -> DVec3 {
        self.sea_radiance
    }

    /// The radiance the environment shows below the horizon (§6's multiple reflections).
    pub fn below_horizon_radiance(&self) -> DVec3 {
        self.below_horizon
    }

    /// The environment's radiance towards `dir`: the sky above the horizon (the Sun's disc
    /// excluded), [`Lighting::below_horizon_radiance`] at and below it.
    pub fn environment_radiance(&self, dir: DVec3) -> DVec3 {
        if dir.y > 0.0 {
            self.sky.radiance(dir)
        } else {
            self.below_horizon
        }
    }

    /// The sky map of this environment, `size`² at level 0 (see [`SkyMap::new`]).
    pub fn sky_map(&self, size: u32) -> Result<SkyMap, BrdfError> {
        SkyMap::new(&self.sky, self.below_horizon, size)
    }
}

/// The three terms of the sea's radiance towards the viewer (linear RGB).
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct SeaLight {
    /// `I_sun`, Eq. 15.
    pub sun: DVec3,
    /// `I_sky = F̄ L̄`, Eq. 21 and 27.
    pub sky: DVec3,
    /// `I_sea = L_sea (1 − F̄)`, Eq. 28.
    pub sea: DVec3,
}

impl SeaLight {
    /// `I_sun + I_sky + I_sea`.
    pub fn total(&self) -> DVec3 {
        self.sun + self.sky + self.sea
    }
}

/// Algorithm 5.1, `SEACOLOR(v, l, n, t_x, t_y, σ_x, σ_y)`, with validated inputs.
///
/// - `v`: unit vector from the surface towards the viewer;
/// - `n`: the filtered unit normal of Eq. 3 (a back-facing one is reflected, §3.2);
/// - `wind`: the horizontal wind direction `(x, z)` that the variances are measured along;
/// - `variance`: σ_x², σ_y² of the unresolved waves (Eq. 4), ≥ 0;
/// - `sky_map`: the environment of `lighting` (see [`Lighting::sky_map`]).
pub fn sea_color(
    lighting: &Lighting,
    sky_map: &SkyMap,
    v: DVec3,
    n: DVec3,
    wind: DVec2,
    variance: SlopeVariance,
) -> Result<SeaLight, BrdfError> {
    let v = check_direction("v", v)?;
    let n = check_direction("n", n)?;
    if !wind.is_finite() {
        return Err(BrdfError::NotFinite("wind"));
    }
    if wind == DVec2::ZERO {
        return Err(BrdfError::NotUnit("wind"));
    }
    check("sigma_x2", variance.x, 0.0, f64::MAX)?;
    check("sigma_y2", variance.y, 0.0, f64::MAX)?;
    Ok(sea_color_unchecked(lighting, sky_map, v, n, wind, variance))
}

/// [`sea_color`] without validation (for inner loops whose inputs are known to be valid).
pub fn sea_color_unchecked(
    lighting: &Lighting,
    sky_map: &SkyMap,
    v: DVec3,
    n: DVec3,
    wind: DVec2,
    variance: SlopeVariance,
) -> SeaLight {
    // §3.2: normals filtered apart from the geometry can face away from the viewer; reflect
    // them about the plane normal to v (n·v becomes −n·v, and n stays unit).
    let n_dot_v = n.dot(v);
    let n = if n_dot_v < 0.0 {
        n - v * (2.0 * n_dot_v)
    } else {
        n
    };
    let (tx, ty) = tangent_frame(n, wind);
    let to_tangent = |d: DVec3| DVec3::new(d.dot(tx), d.dot(ty), d.dot(n));
    let v_t = to_tangent(v);
    let sky = lighting.sky();
    let l = sky.sun_direction();
    let l_t = to_tangent(l);
    let r = lighting.sea().fresnel_r;

    // Sun (Eq. 15), with the variances raised to the solar disc's (§5.1). The reflected ray
    // must leave upwards in world space too: a Sun under the local horizon of a tilted facet
    // is already zero through l_t.z, and one below the world's horizon cannot be (y ≥ 0).
    let sun_var = variance.at_least(sky.sun_min_variance());
    let sun = sky.sun_radiance()
        * sun_radiance_unchecked(
            v_t,
            l_t,
            sun_var.x,
            sun_var.y,
            1.0,
            sky.sun_solid_angle(),
            r,
        );

    // Effective Fresnel (Eq. 24–25), tabulated: closer to the integral than Eq. 26's fit at
    // the grazing views that dominate a view of the sea (see `fresnel_table`).
    let cos_theta_v = v_t.z.clamp(0.0, 1.0);
    let phi_v = libm::atan2(v_t.y, v_t.x);
    let sigma_v = libm::sqrt(sigma_v2(phi_v, variance.x, variance.y));
    let f_bar = effective_fresnel_table_unchecked(cos_theta_v, sigma_v, r);

    // Sky (Eq. 27), over the visible slopes (see `visible_sky_footprint`).
    let fp = visible_sky_footprint(v, n, tx, ty, variance);
    let l_bar = sky_map.grad_fetch(fp.u0, fp.du_x, fp.du_y);

    SeaLight {
        sun,
        sky: l_bar * f_bar,
        sea: lighting.sea_radiance() * (1.0 - f_bar),
    }
}

/// Algorithm 5.1 for one pixel of the filtered surface seen along `v` (unit, towards the
/// viewer): [`sea_color_unchecked`] with the masking-aware normal of §3.2
/// ([`PixelSurface::visible_normal`], Eq. 10 for the slopes only the normal resolves) and the
/// BRDF's variance of Eq. 4. What the renderer's fragment stage draws (`ocean_fs`), and what the
/// validation (§7.2) measures as the model. `wind` is the surface's wind.
pub fn pixel_color(
    lighting: &Lighting,
    sky_map: &SkyMap,
    v: DVec3,
    pixel: &PixelSurface,
    wind: DVec2,
) -> SeaLight {
    let n = pixel.visible_normal(v, wind);
    sea_color_unchecked(lighting, sky_map, v, n, wind, pixel.variance)
}

/// Where the sky map is read for one pixel (Eq. 27): the centre `u0 = U(0)` and the axes
/// `Δu_x = 2σ_x ∂U/∂ζ_x`, `Δu_y = 2σ_y ∂U/∂ζ_y`, in stereographic units.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SkyFootprint {
    /// `U(0)`: where the mirror reflection of `v` about `n` lands.
    pub u0: DVec2,
    /// `Δu_x`.
    pub du_x: DVec2,
    /// `Δu_y`.
    pub du_y: DVec2,
}

/// `U(ζ)` of Fig. 9: the stereographic coordinates of `v` reflected by the facet of slopes `ζ`
/// in the tangent frame `(t_x, t_y, n)`.
pub fn reflected_u(v: DVec3, n: DVec3, tx: DVec3, ty: DVec3, zeta: DVec2) -> DVec2 {
    let f = DVec3::new(-zeta.x, -zeta.y, 1.0).normalize();
    let f = tx * f.x + ty * f.y + n * f.z;
    stereographic(f * (2.0 * f.dot(v)) - v)
}

/// The sky footprint of Fig. 9, with forward differences of step [`SLOPE_EPSILON`].
pub fn sky_footprint(
    v: DVec3,
    n: DVec3,
    tx: DVec3,
    ty: DVec3,
    variance: SlopeVariance,
) -> SkyFootprint {
    let u0 = reflected_u(v, n, tx, ty, DVec2::ZERO);
    let sx = libm::sqrt(variance.x);
    let sy = libm::sqrt(variance.y);
    let ux = reflected_u(v, n, tx, ty, DVec2::new(SLOPE_EPSILON, 0.0));
    let uy = reflected_u(v, n, tx, ty, DVec2::new(0.0, SLOPE_EPSILON));
    SkyFootprint {
        u0,
        du_x: (ux - u0) * (2.0 * sx / SLOPE_EPSILON),
        du_y: (uy - u0) * (2.0 * sy / SLOPE_EPSILON),
    }
}

/// The sky footprint over the slopes the viewer *sees*, this crate's refinement of Eq. 22.
///
/// Eq. 22 averages the sky over the slope density `p(ζ)`, and Eq. 21 multiplies that by the
/// effective Fresnel `F̄`, an average over the visible slopes `q^e_vn` (Eq. 10). At grazing
/// views the two weightings differ most: facets turned away from the viewer are hidden, and
/// they are exactly those whose mirror directions fall below the horizon, so `p` darkens `L̄`
/// with reflections nobody sees (the validation, §7.2, measured the paper's form 20–35 % low
/// in the sky term over the whole 4 m view). Here `L̄` is averaged over `q^e_vn` as well, so
/// `I_sky ≈ (∫ q^e_vn F)(∫ q^e_vn L)`, exact when either factor is constant.
///
/// In whitened slopes `ζ = (σ_x u, σ_y w)`, `q^e_vn ∝ φ(u) φ(w) (v_z − c s)⁺` with `s` the
/// coordinate along `e = (σ_x v_x, σ_y v_y)/c` (as in [`crate::fresnel`]'s quadrature). Along
/// `e` the density is a Gaussian times a truncated ramp, whose moments are closed forms with
/// `a = v_z/c`, `Z = a Φ(a) + φ(a)`: mean `−Φ(a)/Z`, second moment `(a Φ(a) + 2 φ(a))/Z`;
/// across `e` it stays standard normal. The footprint is the Gaussian with these two moments,
/// mapped to the stereographic plane through `U` at the mean slope (finite differences of step
/// [`SLOPE_EPSILON`] along the two axes). With `c = 0` (a normal view, or no variance along
/// it) this is [`sky_footprint`].
pub fn visible_sky_footprint(
    v: DVec3,
    n: DVec3,
    tx: DVec3,
    ty: DVec3,
    variance: SlopeVariance,
) -> SkyFootprint {
    let sx = libm::sqrt(variance.x);
    let sy = libm::sqrt(variance.y);
    let v_t = DVec3::new(v.dot(tx), v.dot(ty), v.dot(n));
    let axis = DVec2::new(sx * v_t.x, sy * v_t.y);
    let c = axis.length();
    if c.is_nan() || c <= 0.0 {
        return sky_footprint(v, n, tx, ty, variance);
    }
    let e = axis / c;
    let a = v_t.z.max(0.0) / c;
    let cdf = 0.5 * libm::erfc(-a * core::f64::consts::FRAC_1_SQRT_2);
    let pdf = libm::exp(-0.5 * a * a) * 0.398_942_280_401_432_7;
    let z = a * cdf + pdf;
    let mean = -cdf / z;
    let var = ((a * cdf + 2.0 * pdf) / z - mean * mean).max(0.0);
    let scale = DVec2::new(sx, sy);
    let along = scale * e * libm::sqrt(var);
    let across = scale * DVec2::new(-e.y, e.x);
    let zeta0 = scale * e * mean;
    let u0 = reflected_u(v, n, tx, ty, zeta0);
    let axis_du = |dir: DVec2| {
        let len = dir.length();
        if len > 0.0 {
            let h = SLOPE_EPSILON / len;
            (reflected_u(v, n, tx, ty, zeta0 + dir * h) - u0) * (2.0 / h)
        } else {
            DVec2::ZERO
        }
    };
    SkyFootprint {
        u0,
        du_x: axis_du(along),
        du_y: axis_du(across),
    }
}
