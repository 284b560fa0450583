//! Ocean lighting (crate `ocean-brdf`, Bruneton, Neyret & Holzschuch 2010), part 3 of 3: the
//! Sun, the sky and the sea (`OceanLighting`), the mip-mapped sky map (`OceanSkyMap`) and the
//! sea's colour of Algorithm 5.1, one pixel at a time or batched.
//!
//! The spectrum and its slope variances live in `lighting_spectrum.rs`, the BRDF and Fresnel
//! evaluations in `lighting_brdf.rs`; the helpers shared by the three files live here.
//!
//! World space is right-handed with y up, the sea at rest on y = 0; radiances and irradiances
//! are linear RGB in any consistent unit (the defaults take the Sun's irradiance at normal
//! incidence as about 1).

use core::mem::{align_of, size_of};

use glam::DVec3;
use ocean_brdf::sky::CieSky;
use ocean_brdf::sky_map::{SKY_MAP_EXTENT, SKY_MAP_MAX_SIZE, SKY_MAP_MIN_SIZE};
use ocean_brdf::{BrdfError, Lighting, SeaParams, SkyParams};

use crate::boundary::OceanNext;
use crate::boundary::{
    borrow, check_finite, check_ptr, destroy, read_params, write_handle, write_out,
};
use crate::status::{Error, OceanStatus, guard};
use crate::waves::OceanDVec3;

/// Half-width E of the square of the stereographic plane a sky map covers: texel (i, j) of a
/// level of size S shows u = (2 t - 1) E, t = ((i + 0.5)/S, (j + 0.5)/S). Equal to
/// `ocean_brdf::sky_map::SKY_MAP_EXTENT`.
pub const OCEAN_SKY_MAP_EXTENT: f64 = 1.1;
/// Smallest level-0 size of a sky map (a power of two).
pub const OCEAN_SKY_MAP_MIN_SIZE: u32 = 4;
/// Largest level-0 size of a sky map (a power of two).
pub const OCEAN_SKY_MAP_MAX_SIZE: u32 = 4096;

const _: () = assert!(OCEAN_SKY_MAP_EXTENT == SKY_MAP_EXTENT);
const _: () = assert!(OCEAN_SKY_MAP_MIN_SIZE == SKY_MAP_MIN_SIZE);
const _: () = assert!(OCEAN_SKY_MAP_MAX_SIZE == SKY_MAP_MAX_SIZE);

/// A linear RGB triple in double precision (radiance, irradiance or reflectance, as documented
/// where it is used).
#[repr(C)]
#[derive(Clone, Copy, Debug, Default, PartialEq, bytemuck::Zeroable, bytemuck::Pod)]
pub struct OceanRgb {
    /// Red.
    pub r: f64,
    /// Green.
    pub g: f64,
    /// Blue.
    pub b: f64,
}

impl OceanRgb {
    pub(crate) fn from_dvec3(c: DVec3) -> Self {
        Self {
            r: c.x,
            g: c.y,
            b: c.z,
        }
    }

    pub(crate) fn to_dvec3(self) -> DVec3 {
        DVec3::new(self.r, self.g, self.b)
    }
}

/// The coefficients of a CIE standard sky type (ISO 15469 / CIE S 011): the gradation
/// phi(theta) = 1 + a exp(b / cos theta) (theta the zenith angle of the sky element) and the
/// indicatrix f(gamma) = 1 + c (exp(d gamma) - exp(d pi/2)) + e cos^2 gamma (gamma its angle
/// from the Sun). Each in [-1000, 1000], b and d in [-1000, 0] (as in every CIE standard type:
/// with b > 0 the gradation grows without bound towards the horizon); the sky's relative
/// radiance must stay positive at the zenith and non-negative elsewhere. The default (`ocean_sky_params_default`) is type 12,
/// "standard clear sky, low turbidity": a = -1, b = -0.32, c = 10, d = -3, e = 0.45.
#[repr(C)]
#[derive(Clone, Copy, Debug, Default, PartialEq, bytemuck::Zeroable, bytemuck::Pod)]
pub struct OceanCieSky {
    /// Gradation a.
    pub a: f64,
    /// Gradation b, in [-1000, 0] (negative: the sky brightens towards the horizon).
    pub b: f64,
    /// Indicatrix c (the circumsolar brightening).
    pub c: f64,
    /// Indicatrix d, in [-1000, 0].
    pub d: f64,
    /// Indicatrix e (the forward-scattering term).
    pub e: f64,
}

/// The Sun and the sky (paper section 5.1, 5.2). `ocean_sky_params_default` fills in a clear
/// afternoon.
#[repr(C)]
#[derive(Clone, Copy, Debug, Default, PartialEq, bytemuck::Zeroable, bytemuck::Pod)]
pub struct OceanSkyParams {
    /// Extensions: NULL, or the first extension struct (see `OceanChain`); the `_default`
    /// function sets NULL.
    pub next: OceanNext,
    /// Unit vector towards the Sun, world space (y up); its length must be within 1e-6 of 1
    /// and its elevation in [0, 90] degrees (y >= 0): the model has no twilight.
    pub sun_direction: OceanDVec3,
    /// The Sun's irradiance on a surface facing it, linear RGB, each channel in [0, 1e30].
    pub sun_irradiance: OceanRgb,
    /// The sky's radiance at the zenith, linear RGB, each channel in [0, 1e30].
    pub zenith_radiance: OceanRgb,
    /// The sky's relative radiance distribution.
    pub cie: OceanCieSky,
    /// The Sun's angular radius, radians, in [1e-5, 0.25] (default: the real Sun's, 4.653e-3).
    /// It sets the Sun's solid angle (Eq. 15) and the least slope variance of its reflection
    /// (rho^2 / 16, section 5.1).
    pub sun_angular_radius: f64,
}

/// The water body under the surface (paper section 5.3). `ocean_sea_params_default` fills in a
/// deep blue open ocean.
#[repr(C)]
#[derive(Clone, Copy, Debug, Default, PartialEq, bytemuck::Zeroable, bytemuck::Pod)]
pub struct OceanSeaParams {
    /// Extensions: NULL, or the first extension struct (see `OceanChain`); the `_default`
    /// function sets NULL.
    pub next: OceanNext,
    /// Diffuse reflectance of the water body, linear RGB, each channel in [0, 1]: the light
    /// scattered back up is L_sea = albedo (E_sun sin(elevation) + E_sky) / pi.
    pub albedo: OceanRgb,
    /// Fresnel reflectance at normal incidence, R of Eq. 14, in [0, 1] (water: 0.02,
    /// `OCEAN_WATER_R`).
    pub fresnel_r: f64,
}

/// The Sun, the sky and the sea, validated, with their derived radiances (opaque). Create with
/// `ocean_lighting_create`, free with `ocean_lighting_destroy`. Immutable: a
/// `const OceanLighting *` may be used by any number of threads at once.
pub struct OceanLighting {
    pub(crate) lighting: Lighting,
}

const _: () = {
    const fn shareable<T: Send + Sync>() {}
    shareable::<OceanLighting>();
};

/// The error of a crate call as a status, with the crate's message (`?` converts).
impl From<BrdfError> for Error {
    fn from(e: BrdfError) -> Self {
        brdf_error("", e)
    }
}

/// The status of an `ocean-brdf` error (NaN and infinities: `OCEAN_STATUS_NON_FINITE`;
/// everything else: `OCEAN_STATUS_INVALID_ARGUMENT`), with its message prefixed by `context`.
pub(crate) fn brdf_error(context: &str, e: BrdfError) -> Error {
    let status = match e {
        BrdfError::NotFinite(_) => OceanStatus::NonFinite,
        _ => OceanStatus::InvalidArgument,
    };
    Error::new(status, format!("{context}{e}"))
}

/// `OCEAN_STATUS_NON_FINITE` unless every component of `v` is finite, naming `name.x` etc.
pub(crate) fn finite_dvec3(name: &str, v: &OceanDVec3) -> Result<DVec3, Error> {
    check_finite(name, &[(".x", v.x), (".y", v.y), (".z", v.z)])?;
    Ok(DVec3::new(v.x, v.y, v.z))
}

fn finite_rgb(name: &str, c: &OceanRgb) -> Result<DVec3, Error> {
    check_finite(name, &[(".r", c.r), (".g", c.g), (".b", c.b)])?;
    Ok(c.to_dvec3())
}

fn sky_params_from(p: &OceanSkyParams) -> Result<SkyParams, Error> {
    let sun_direction = finite_dvec3("sky->sun_direction", &p.sun_direction)?;
    let sun_irradiance = finite_rgb("sky->sun_irradiance", &p.sun_irradiance)?;
    let zenith_radiance = finite_rgb("sky->zenith_radiance", &p.zenith_radiance)?;
    let c = &p.cie;
    check_finite(
        "sky->cie.",
        &[("a", c.a), ("b", c.b), ("c", c.c), ("d", c.d), ("e", c.e)],
    )?;
    check_finite("sky->", &[("sun_angular_radius", p.sun_angular_radius)])?;
    Ok(SkyParams {
        sun_direction,
        sun_irradiance,
        zenith_radiance,
        cie: CieSky {
            a: c.a,
            b: c.b,
            c: c.c,
            d: c.d,
            e: c.e,
        },
        sun_angular_radius: p.sun_angular_radius,
    })
}

fn sky_params_to(p: &SkyParams) -> OceanSkyParams {
    OceanSkyParams {
        next: OceanNext::NULL,
        sun_direction: OceanDVec3::from_dvec3(p.sun_direction),
        sun_irradiance: OceanRgb::from_dvec3(p.sun_irradiance),
        zenith_radiance: OceanRgb::from_dvec3(p.zenith_radiance),
        cie: OceanCieSky {
            a: p.cie.a,
            b: p.cie.b,
            c: p.cie.c,
            d: p.cie.d,
            e: p.cie.e,
        },
        sun_angular_radius: p.sun_angular_radius,
    }
}

fn sea_params_from(p: &OceanSeaParams) -> Result<SeaParams, Error> {
    let albedo = finite_rgb("sea->albedo", &p.albedo)?;
    check_finite("sea->", &[("fresnel_r", p.fresnel_r)])?;
    Ok(SeaParams {
        albedo,
        fresnel_r: p.fresnel_r,
    })
}

/// Stores the default Sun and sky in `*out`: a clear afternoon with the Sun 25 degrees above
/// the horizon towards -z, sun_direction = (0, sin 25deg, -cos 25deg), a slightly warm Sun of
/// irradiance (1, 0.96, 0.90), a blue zenith of radiance (0.025, 0.045, 0.09) and the CIE clear
/// sky (type 12).
///
/// Returns `OCEAN_STATUS_NULL_POINTER` (or `_MISALIGNED_POINTER`) for a bad `out`, which is
/// then left unchanged.
///
/// # Safety
///
/// `out` must be writable.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn ocean_sky_params_default(out: *mut OceanSkyParams) -> OceanStatus {
    guard("ocean_sky_params_default", || {
        // SAFETY: forwarded from this function's contract.
        unsafe { write_out(out, "out", sky_params_to(&SkyParams::default())) }
    })
}

/// Stores the default water body in `*out`: albedo (10, 40, 120)/255 * 0.1 (deep blue open
/// ocean) and R = 0.02.
///
/// Returns `OCEAN_STATUS_NULL_POINTER` (or `_MISALIGNED_POINTER`) for a bad `out`, which is
/// then left unchanged.
///
/// # Safety
///
/// `out` must be writable.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn ocean_sea_params_default(out: *mut OceanSeaParams) -> OceanStatus {
    guard("ocean_sea_params_default", || {
        let d = SeaParams::default();
        let p = OceanSeaParams {
            next: OceanNext::NULL,
            albedo: OceanRgb::from_dvec3(d.albedo),
            fresnel_r: d.fresnel_r,
        };
        // SAFETY: forwarded from this function's contract.
        unsafe { write_out(out, "out", p) }
    })
}

/// Validates the Sun, the sky and the sea and stores a new lighting in `*out`.
///
/// It derives the sky's irradiance E_sky on the horizontal sea (by quadrature of the CIE
/// radiance over the upper hemisphere), the water's radiance
/// L_sea = albedo (E_sun sin(elevation) + E_sky) / pi (paper section 5.3) and the radiance
/// shown below the horizon (the sky's mean radiance E_sky/pi times Schlick's reflectance
/// averaged over a cosine-weighted hemisphere, R + (1 - R)/21, plus L_sea times the rest).
///
/// Returns `OCEAN_STATUS_NULL_POINTER` / `_MISALIGNED_POINTER` for a bad pointer,
/// `OCEAN_STATUS_NON_FINITE` for a NaN or infinite member (the message names it),
/// `OCEAN_STATUS_INVALID_ARGUMENT` for a member out of its documented range (a Sun direction
/// that is not a unit vector or lies below the horizon, a negative irradiance or radiance, an
/// albedo or R outside [0, 1], a CIE type outside [-1000, 1000] or giving negative radiance).
/// On failure `*out` is unchanged. Free the handle with `ocean_lighting_destroy`.
///
/// # Safety
///
/// `sky` and `sea` must point to readable structs and `out` to a writable pointer; none is
/// retained.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn ocean_lighting_create(
    sky: *const OceanSkyParams,
    sea: *const OceanSeaParams,
    out: *mut *mut OceanLighting,
) -> OceanStatus {
    guard("ocean_lighting_create", || {
        // SAFETY: forwarded from this function's contract.
        check_ptr(sky, "sky")?;
        check_ptr(sea, "sea")?;
        check_ptr(out.cast_const(), "out")?;
        // SAFETY: forwarded from this function's contract.
        let sky = sky_params_from(&unsafe { read_params(sky, "sky") }?)?;
        // SAFETY: forwarded from this function's contract.
        let sea = sea_params_from(&unsafe { read_params(sea, "sea") }?)?;
        let lighting = Lighting::new(sky, sea)?;
        // SAFETY: forwarded from this function's contract.
        unsafe { write_handle(out, OceanLighting { lighting }) }
    })
}

/// Frees a lighting. NULL does nothing; a handle of another kind or already destroyed frees nothing
/// and sets the last-error message (see the header's notes on handles). Sky maps made from it stay
/// valid.
#[unsafe(no_mangle)]
pub extern "C" fn ocean_lighting_destroy(lighting: *mut OceanLighting) {
    destroy(lighting, "ocean_lighting_destroy", "lighting");
}

/// Runs `f` on a borrowed lighting and writes its RGB result to `*out`.
///
/// # Safety
///
/// `out` must be NULL, misaligned or writable.
unsafe fn lighting_rgb(
    function: &str,
    lighting: *const OceanLighting,
    out: *mut OceanRgb,
    f: impl FnOnce(&Lighting) -> DVec3,
) -> OceanStatus {
    guard(function, || {
        let l = borrow(lighting, "lighting")?;
        check_ptr(out.cast_const(), "out")?;
        let c = OceanRgb::from_dvec3(f(&l.lighting));
        // SAFETY: forwarded from the caller's contract.
        unsafe { write_out(out, "out", c) }
    })
}

/// Stores the sky's irradiance on the horizontal sea, E_sky = integral of L_sky cos(theta)
/// over the upper hemisphere (the Sun's disc excluded), linear RGB, in `*out`.
///
/// Returns `OCEAN_STATUS_NULL_POINTER` / `_MISALIGNED_POINTER` for a bad pointer; `*out` is
/// written only on success.
///
/// # Safety
///
/// `out` must be writable.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn ocean_lighting_sky_irradiance(
    lighting: *const OceanLighting,
    out: *mut OceanRgb,
) -> OceanStatus {
    // SAFETY: forwarded from this function's contract.
    unsafe {
        lighting_rgb("ocean_lighting_sky_irradiance", lighting, out, |l| {
            l.sky().sky_irradiance()
        })
    }
}

/// The environment's irradiance on a surface of any orientation, E(n) = sum_i `k[i]` Y_i(n)
/// (order-2 real spherical harmonics, world space, y up), the nine Y_i in the order
/// 1; x, y, z; xy, yz, 3y^2 - 1, xz, x^2 - z^2 with their orthonormal normalisations; linear
/// RGB per coefficient. All zero: no environment light.
#[repr(C)]
#[derive(Clone, Copy, Debug, Default, PartialEq, bytemuck::Zeroable, bytemuck::Pod)]
pub struct OceanIrradiance {
    /// `k[i] = A_l L_i`: the environment's projection on `Y_i` times the clamped cosine's
    /// factor (pi, 2 pi / 3, pi / 4 for orders 0, 1, 2).
    pub k: [OceanRgb; 9],
}

impl OceanIrradiance {
    pub(crate) fn from_irradiance(e: &ocean_brdf::Irradiance) -> Self {
        Self {
            k: e.coefficients().map(OceanRgb::from_dvec3),
        }
    }

    /// The irradiance, or none for all-zero coefficients; an error for a non-finite one.
    #[cfg(feature = "gpu")]
    pub(crate) fn irradiance(&self, what: &str) -> Result<Option<ocean_brdf::Irradiance>, Error> {
        let mut k = [DVec3::ZERO; 9];
        for (i, (out, c)) in k.iter_mut().zip(&self.k).enumerate() {
            *out = finite_rgb(&format!("{what}.k[{i}]"), c)?;
        }
        Ok((k != [DVec3::ZERO; 9]).then(|| ocean_brdf::Irradiance::from_coefficients(k)))
    }
}

/// Stores the irradiance of the lighting's environment (the sky above the horizon without the
/// Sun's disc, the sea's below-horizon radiance below it) on every orientation in `*out`: the
/// ambient light of solids lit by the same sky as the sea (`OceanReliefScene::sky`). Within
/// 3.1 % of the upward irradiance of a brute-force integration for every normal on the default
/// sky and sea, the worst facing the horizon.
///
/// Returns `OCEAN_STATUS_NULL_POINTER` / `_MISALIGNED_POINTER` for a bad pointer; `*out` is
/// written only on success.
///
/// # Safety
///
/// `out` must be writable.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn ocean_lighting_irradiance(
    lighting: *const OceanLighting,
    out: *mut OceanIrradiance,
) -> OceanStatus {
    guard("ocean_lighting_irradiance", || {
        let l = borrow(lighting, "lighting")?;
        check_ptr(out.cast_const(), "out")?;
        let e = OceanIrradiance::from_irradiance(&ocean_brdf::Irradiance::new(&l.lighting));
        // SAFETY: forwarded from this function's contract.
        unsafe { write_out(out, "out", e) }
    })
}

/// Stores L_sea = albedo (E_sun sin(elevation) + E_sky) / pi, the diffuse radiance leaving the
/// water body (paper section 5.3), linear RGB, in `*out`.
///
/// Returns `OCEAN_STATUS_NULL_POINTER` / `_MISALIGNED_POINTER` for a bad pointer; `*out` is
/// written only on success.
///
/// # Safety
///
/// `out` must be writable.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn ocean_lighting_sea_radiance(
    lighting: *const OceanLighting,
    out: *mut OceanRgb,
) -> OceanStatus {
    // SAFETY: forwarded from this function's contract.
    unsafe {
        lighting_rgb("ocean_lighting_sea_radiance", lighting, out, |l| {
            l.sea_radiance()
        })
    }
}

/// Stores the radiance the environment shows at and below the horizon (paper section 6,
/// multiple reflections; see `ocean_lighting_create`), linear RGB, in `*out`: the value of the
/// sky map outside the horizon circle.
///
/// Returns `OCEAN_STATUS_NULL_POINTER` / `_MISALIGNED_POINTER` for a bad pointer; `*out` is
/// written only on success.
///
/// # Safety
///
/// `out` must be writable.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn ocean_lighting_below_horizon_radiance(
    lighting: *const OceanLighting,
    out: *mut OceanRgb,
) -> OceanStatus {
    // SAFETY: forwarded from this function's contract.
    unsafe {
        lighting_rgb(
            "ocean_lighting_below_horizon_radiance",
            lighting,
            out,
            |l| l.below_horizon_radiance(),
        )
    }
}

/// Stores the Sun's radiance L_sun = E_sun / Omega_sun (Eq. 15), uniform over its disc, linear
/// RGB, in `*out`.
///
/// Returns `OCEAN_STATUS_NULL_POINTER` / `_MISALIGNED_POINTER` for a bad pointer; `*out` is
/// written only on success.
///
/// # Safety
///
/// `out` must be writable.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn ocean_lighting_sun_radiance(
    lighting: *const OceanLighting,
    out: *mut OceanRgb,
) -> OceanStatus {
    // SAFETY: forwarded from this function's contract.
    unsafe {
        lighting_rgb("ocean_lighting_sun_radiance", lighting, out, |l| {
            l.sky().sun_radiance()
        })
    }
}

/// Stores the Sun's solid angle Omega_sun = 2 pi (1 - cos rho), steradians, with rho = 4.653e-3
/// rad its mean angular radius, in `*out`.
///
/// Returns `OCEAN_STATUS_NULL_POINTER` / `_MISALIGNED_POINTER` for a bad pointer; `*out` is
/// written only on success.
///
/// # Safety
///
/// `out` must be writable.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn ocean_lighting_sun_solid_angle(
    lighting: *const OceanLighting,
    out: *mut f64,
) -> OceanStatus {
    guard("ocean_lighting_sun_solid_angle", || {
        let l = borrow(lighting, "lighting")?;
        // SAFETY: forwarded from this function's contract.
        unsafe { write_out(out, "out", l.lighting.sky().sun_solid_angle()) }
    })
}

/// Stores the environment's radiance towards the unit direction `dir` (world space, y up),
/// linear RGB, in `*out`: the CIE sky above the horizon (the Sun's disc excluded, as Eq. 15
/// handles it), the below-horizon radiance (`ocean_lighting_below_horizon_radiance`) at and
/// below it. This is what level 0 of a sky map samples, before its binary16 rounding.
///
/// Returns `OCEAN_STATUS_NULL_POINTER` / `_MISALIGNED_POINTER` for a bad pointer,
/// `OCEAN_STATUS_NON_FINITE` for a NaN or infinite component of `dir`,
/// `OCEAN_STATUS_INVALID_ARGUMENT` if its length is not within 1e-6 of 1. `*out` is written only
/// on success.
///
/// # Safety
///
/// `out` must be writable.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn ocean_lighting_environment_radiance(
    lighting: *const OceanLighting,
    dir: OceanDVec3,
    out: *mut OceanRgb,
) -> OceanStatus {
    guard("ocean_lighting_environment_radiance", || {
        let l = borrow(lighting, "lighting")?;
        check_ptr(out.cast_const(), "out")?;
        let d = unit_dvec3("dir", &dir)?;
        let c = OceanRgb::from_dvec3(l.lighting.environment_radiance(d));
        // SAFETY: forwarded from this function's contract.
        unsafe { write_out(out, "out", c) }
    })
}

/// A finite vector whose length is within 1e-6 of 1 (the tolerance of `ocean-brdf`), normalised.
pub(crate) fn unit_dvec3(name: &str, v: &OceanDVec3) -> Result<DVec3, Error> {
    let d = finite_dvec3(name, v)?;
    let len = d.length();
    if (len - 1.0).abs() > 1e-6 {
        return Err(Error::new(
            OceanStatus::InvalidArgument,
            format!("{name} must be a unit vector (length within 1e-6 of 1), its length is {len}"),
        ));
    }
    Ok(d / len)
}

const _: () = assert!(size_of::<OceanRgb>() == 24 && align_of::<OceanRgb>() == 8);

crate::boundary::chain::extensible!(OceanSkyParams, OceanSeaParams);

crate::boundary::handle::handles!(OceanLighting);

#[cfg(test)]
#[path = "lighting_tests.rs"]
mod tests;
