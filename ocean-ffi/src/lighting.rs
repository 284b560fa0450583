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

use glam::{DVec2, DVec3};
use ocean_brdf::sea::{SeaLight, sea_color};
use ocean_brdf::sky::CieSky;
use ocean_brdf::sky_map::{SKY_MAP_EXTENT, SKY_MAP_MAX_SIZE, SKY_MAP_MIN_SIZE};
use ocean_brdf::{BrdfError, Lighting, SeaParams, SkyMap, SkyParams, SlopeVariance};

use crate::boundary::OceanNext;
use crate::boundary::{
    borrow, byte_len, check_disjoint, check_finite, check_len, check_ptr, destroy, read_params,
    write_handle, write_out,
};
use crate::status::{Error, OceanStatus, guard};
use crate::waves::{OceanDVec2, OceanDVec3};

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

/// The three terms of the sea's radiance towards the viewer (Algorithm 5.1), linear RGB in the
/// unit of the lighting's radiances; their sum is the pixel's colour before tone mapping.
#[repr(C)]
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct OceanSeaLight {
    /// I_sun, the Sun's reflection (Eq. 15), with the slope variances raised to the solar
    /// disc's.
    pub sun: OceanRgb,
    /// I_sky = F_bar L_bar, the sky's reflection (Eq. 21, 26, 27).
    pub sky: OceanRgb,
    /// I_sea = L_sea (1 - F_bar), the light refracted out of the water (Eq. 28).
    pub sea: OceanRgb,
}

impl OceanSeaLight {
    fn from_core(s: &SeaLight) -> Self {
        Self {
            sun: OceanRgb::from_dvec3(s.sun),
            sky: OceanRgb::from_dvec3(s.sky),
            sea: OceanRgb::from_dvec3(s.sea),
        }
    }
}

/// One input of `ocean_sea_color_batch`: the arguments of `ocean_sea_color`.
#[repr(C)]
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct OceanSeaColorInput {
    /// Unit vector from the surface point towards the viewer, world space (y up).
    pub v: OceanDVec3,
    /// The filtered unit surface normal (Eq. 3), world space.
    pub n: OceanDVec3,
    /// The horizontal wind direction (x, z) along which `sigma_x2` is measured; any finite,
    /// non-zero length.
    pub wind: OceanDVec2,
    /// Slope variance of the unresolved waves along the wind (Eq. 4), finite and >= 0.
    pub sigma_x2: f64,
    /// Slope variance across the wind, finite and >= 0.
    pub sigma_y2: f64,
}

/// The Sun, the sky and the sea, validated, with their derived radiances (opaque). Create with
/// `ocean_lighting_create`, free with `ocean_lighting_destroy`. Immutable: a
/// `const OceanLighting *` may be used by any number of threads at once.
pub struct OceanLighting {
    pub(crate) lighting: Lighting,
}

/// A mip-mapped sky map of one lighting (opaque): the sky's radiance in the stereographic
/// parameterisation (paper section 5.2), level 0 of size N, each coarser level the 2x2 mean of
/// the one above, down to 1x1. Create with `ocean_lighting_sky_map_create`, free with
/// `ocean_sky_map_destroy`. Immutable and shareable between threads.
pub struct OceanSkyMap {
    map: SkyMap,
    /// The lighting it was rendered from: `ocean_sea_color` refuses a map of another one.
    lighting: Lighting,
}

const _: () = {
    const fn shareable<T: Send + Sync>() {}
    shareable::<OceanLighting>();
    shareable::<OceanSkyMap>();
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

/// The environment's irradiance on a surface of any orientation, E(n) = sum_i k[i] Y_i(n)
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

/// Renders the sky map of `lighting`, `size` x `size` texels at level 0, and stores a new
/// handle in `*out`.
///
/// Texel (i, j) of level 0 (row-major: element j*size + i) holds the environment's radiance
/// (`ocean_lighting_environment_radiance`) towards the direction whose stereographic projection
/// is u = (2 t - 1) E, with t = ((i + 0.5)/size, (j + 0.5)/size) and E = `OCEAN_SKY_MAP_EXTENT`:
/// the direction r = (2 u_x, 1 - |u|^2, 2 u_y) / (1 + |u|^2) (so u = (r_x, r_z)/(1 + r_y); the
/// zenith is at the centre, the horizon on the circle |u| = 1), and the below-horizon radiance
/// outside that circle. Each coarser level is the 2x2 mean of the one above, down to 1x1. Every
/// channel is rounded to binary16 (the precision of the GPU's `rgba16float` texture), stored as
/// float; alpha is 1.
///
/// Returns `OCEAN_STATUS_NULL_POINTER` / `_MISALIGNED_POINTER` for a bad pointer,
/// `OCEAN_STATUS_INVALID_ARGUMENT` if `size` is not a power of two in
/// [`OCEAN_SKY_MAP_MIN_SIZE`, `OCEAN_SKY_MAP_MAX_SIZE`] or a radiance exceeds binary16's range
/// (65504: scale the radiance unit down). On failure `*out` is unchanged. Free the map with
/// `ocean_sky_map_destroy`.
///
/// # Safety
///
/// `out` must point to a writable pointer.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn ocean_lighting_sky_map_create(
    lighting: *const OceanLighting,
    size: u32,
    out: *mut *mut OceanSkyMap,
) -> OceanStatus {
    guard("ocean_lighting_sky_map_create", || {
        let l = borrow(lighting, "lighting")?;
        check_ptr(out.cast_const(), "out")?;
        let map = l.lighting.sky_map(size)?;
        let value = OceanSkyMap {
            map,
            lighting: l.lighting,
        };
        // SAFETY: forwarded from this function's contract.
        unsafe { write_handle(out, value) }
    })
}

/// Frees a sky map. NULL does nothing; a handle of another kind or already destroyed frees nothing
/// and sets the last-error message (see the header's notes on handles).
#[unsafe(no_mangle)]
pub extern "C" fn ocean_sky_map_destroy(sky_map: *mut OceanSkyMap) {
    destroy(sky_map, "ocean_sky_map_destroy", "sky_map");
}

/// Stores the number of mip levels of the map, log2(size) + 1, in `*out_count`.
///
/// Returns `OCEAN_STATUS_NULL_POINTER` / `_MISALIGNED_POINTER` for a bad pointer; `*out_count`
/// is written only on success.
///
/// # Safety
///
/// `out_count` must be writable.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn ocean_sky_map_level_count(
    sky_map: *const OceanSkyMap,
    out_count: *mut u32,
) -> OceanStatus {
    guard("ocean_sky_map_level_count", || {
        let m = borrow(sky_map, "sky_map")?;
        // SAFETY: forwarded from this function's contract.
        unsafe { write_out(out_count, "out_count", m.map.level_count()) }
    })
}

/// The texels of `level`, or `OCEAN_STATUS_INVALID_ARGUMENT`.
fn level(m: &OceanSkyMap, level: u32) -> Result<&[[f32; 4]], Error> {
    m.map.level(level).ok_or_else(|| {
        Error::new(
            OceanStatus::InvalidArgument,
            format!(
                "level {level} does not exist: the map has levels 0 to {}",
                m.map.level_count() - 1
            ),
        )
    })
}

/// Stores the side of mip `level` in texels, max(size >> level, 1), in `*out_size`: the level
/// holds out_size * out_size RGBA texels.
///
/// Returns `OCEAN_STATUS_NULL_POINTER` / `_MISALIGNED_POINTER` for a bad pointer,
/// `OCEAN_STATUS_INVALID_ARGUMENT` if `level` >= the level count. `*out_size` is written only on
/// success.
///
/// # Safety
///
/// `out_size` must be writable.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn ocean_sky_map_level_info(
    sky_map: *const OceanSkyMap,
    level: u32,
    out_size: *mut u32,
) -> OceanStatus {
    guard("ocean_sky_map_level_info", || {
        let m = borrow(sky_map, "sky_map")?;
        check_ptr(out_size.cast_const(), "out_size")?;
        self::level(&m, level)?;
        let side = (m.map.size() >> level).max(1);
        // SAFETY: forwarded from this function's contract.
        unsafe { write_out(out_size, "out_size", side) }
    })
}

/// Copies mip `level` into `rgba`: side * side texels (side from `ocean_sky_map_level_info`),
/// row-major from texture coordinate (0, 0) (texel (i, j) at element j*side + i), 4 floats
/// each (R, G, B, A = 1), the layout an `RGBA32F` or (after conversion) `RGBA16F` texture
/// upload expects. `len` counts floats and must be exactly side * side * 4.
///
/// Returns `OCEAN_STATUS_NULL_POINTER` / `_MISALIGNED_POINTER` for a bad pointer (4-byte
/// alignment for `rgba`), `OCEAN_STATUS_INVALID_ARGUMENT` if `level` does not exist,
/// `OCEAN_STATUS_LENGTH_MISMATCH` if `len` is not side * side * 4,
/// `OCEAN_STATUS_LENGTH_OVERFLOW` if `len * sizeof(float)` exceeds
/// `PTRDIFF_MAX`. Nothing is written on failure.
///
/// # Safety
///
/// `rgba` must point to `len` writable floats that no other
/// thread touches during the call.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn ocean_sky_map_copy_level(
    sky_map: *const OceanSkyMap,
    level: u32,
    rgba: *mut f32,
    len: usize,
) -> OceanStatus {
    guard("ocean_sky_map_copy_level", || {
        let m = borrow(sky_map, "sky_map")?;
        check_ptr(rgba.cast_const(), "rgba")?;
        byte_len::<f32>(len, "rgba")?;
        let texels = self::level(&m, level)?;
        let want = texels.len() * 4;
        check_len(
            "len",
            len,
            want,
            &format!("level {level} (4 floats a texel)"),
        )?;
        // SAFETY: non-NULL and 4-aligned (checked), `len` floats whose byte size fits in isize
        // (checked: it equals the level's size), writable and untouched by others (caller's
        // guarantee).
        let out = unsafe { core::slice::from_raw_parts_mut(rgba, len) };
        out.copy_from_slice(bytemuck::cast_slice(texels));
        Ok(())
    })
}

/// Checks that `map` was rendered from `lighting`'s parameters.
fn same_lighting(lighting: &OceanLighting, map: &OceanSkyMap) -> Result<(), Error> {
    if map.lighting == lighting.lighting {
        Ok(())
    } else {
        Err(Error::new(
            OceanStatus::InvalidArgument,
            "`sky_map` was rendered from another lighting (different Sun, sky or sea \
             parameters): make it with ocean_lighting_sky_map_create from this one",
        ))
    }
}

/// Validates one input and runs Algorithm 5.1. Messages name the input's members (`v.x`,
/// `wind`); callers prefix the input's own name. Nothing is formatted unless an input is
/// refused: a batch's cost stays the lighting's.
fn sea_color_one(
    lighting: &Lighting,
    map: &SkyMap,
    input: &OceanSeaColorInput,
) -> Result<SeaLight, Error> {
    let (v, n) = (&input.v, &input.n);
    check_finite(
        "",
        &[
            ("v.x", v.x),
            ("v.y", v.y),
            ("v.z", v.z),
            ("n.x", n.x),
            ("n.y", n.y),
            ("n.z", n.z),
            ("wind.x", input.wind.x),
            ("wind.z", input.wind.z),
            ("sigma_x2", input.sigma_x2),
            ("sigma_y2", input.sigma_y2),
        ],
    )?;
    if input.wind.x == 0.0 && input.wind.z == 0.0 {
        return Err(Error::new(
            OceanStatus::InvalidArgument,
            "wind is (0, 0): the wind direction must be non-zero",
        ));
    }
    let variance = SlopeVariance {
        x: input.sigma_x2,
        y: input.sigma_y2,
    };
    sea_color(
        lighting,
        map,
        DVec3::new(v.x, v.y, v.z),
        DVec3::new(n.x, n.y, n.z),
        DVec2::new(input.wind.x, input.wind.z),
        variance,
    )
    .map_err(Error::from)
}

/// The sea's colour for one pixel: Algorithm 5.1 (paper Fig. 9), the three terms of the
/// radiance towards the viewer, stored in `*out`.
///
/// - `v`: unit vector from the surface point towards the viewer, world space (y up);
/// - `n`: the filtered unit normal of Eq. 3, world space (a normal facing away from `v` is
///   reflected about the plane normal to `v`, paper section 3.2);
/// - `wind`: the horizontal wind direction (x, z), any finite non-zero length; the tangent
///   frame is t_x = the wind projected on the surface, t_y = n x t_x (for n = +y and wind +x,
///   t_y = -z);
/// - `sigma_x2`, `sigma_y2`: the slope variances of the unresolved waves along t_x and t_y
///   (Eq. 4, from `ocean_spectrum_slope_variance`), finite and >= 0 (0: a mirror);
/// - `sky_map`: a map made from this `lighting` (any size).
///
/// The Sun's term uses the variances raised to at least rho^2/16 (the solar disc, rho = 4.653e-3
/// rad), the sky's term the effective Fresnel fit F_bar of Eq. 26 times the sky map filtered
/// over the slopes' Gaussian (Eq. 27, a 9-sample trilinear rule), the sea's term
/// L_sea (1 - F_bar) (Eq. 28). Deterministic: the same bits on every platform.
///
/// Returns `OCEAN_STATUS_NULL_POINTER` / `_MISALIGNED_POINTER` for a bad pointer,
/// `OCEAN_STATUS_NON_FINITE` for a NaN or infinite input, `OCEAN_STATUS_INVALID_ARGUMENT` if `v`
/// or `n` is not a unit vector (length within 1e-6 of 1), the wind is zero, a variance is
/// negative, or `sky_map` was made from a lighting with other parameters. `*out` is written only
/// on success.
///
/// # Safety
///
/// `out` writable.
#[unsafe(no_mangle)]
#[allow(clippy::too_many_arguments)]
pub unsafe extern "C" fn ocean_sea_color(
    lighting: *const OceanLighting,
    sky_map: *const OceanSkyMap,
    v: OceanDVec3,
    n: OceanDVec3,
    wind: OceanDVec2,
    sigma_x2: f64,
    sigma_y2: f64,
    out: *mut OceanSeaLight,
) -> OceanStatus {
    guard("ocean_sea_color", || {
        let l = borrow(lighting, "lighting")?;
        let m = borrow(sky_map, "sky_map")?;
        check_ptr(out.cast_const(), "out")?;
        same_lighting(&l, &m)?;
        let input = OceanSeaColorInput {
            v,
            n,
            wind,
            sigma_x2,
            sigma_y2,
        };
        let light = sea_color_one(&l.lighting, &m.map, &input)?;
        // SAFETY: forwarded from this function's contract.
        unsafe { write_out(out, "out", OceanSeaLight::from_core(&light)) }
    })
}

/// `ocean_sea_color` for `n` pixels: `out[i]` receives the colour of `inputs[i]`, bit-identical
/// to `ocean_sea_color` with the same arguments.
///
/// Every input is validated before anything is written: on failure the message names the
/// first bad one (`inputs[i].member`) and `out` is untouched.
///
/// Returns `OCEAN_STATUS_NULL_POINTER` / `_MISALIGNED_POINTER` for a bad pointer (8-byte
/// alignment), `OCEAN_STATUS_EMPTY` if `n` is 0, `OCEAN_STATUS_LENGTH_OVERFLOW` if
/// `n * sizeof(OceanSeaColorInput)` exceeds `PTRDIFF_MAX`, `OCEAN_STATUS_INVALID_ARGUMENT` if the
/// two arrays overlap, and the statuses of `ocean_sea_color` for a bad input.
///
/// # Safety
///
/// `inputs` point to `n` readable
/// `OceanSeaColorInput`s and `out` to `n` writable `OceanSeaLight`s, none modified by another
/// thread during the call.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn ocean_sea_color_batch(
    lighting: *const OceanLighting,
    sky_map: *const OceanSkyMap,
    inputs: *const OceanSeaColorInput,
    n: usize,
    out: *mut OceanSeaLight,
) -> OceanStatus {
    guard("ocean_sea_color_batch", || {
        let l = borrow(lighting, "lighting")?;
        let m = borrow(sky_map, "sky_map")?;
        check_ptr(inputs, "inputs")?;
        check_ptr(out.cast_const(), "out")?;
        if n == 0 {
            return Err(Error::new(
                OceanStatus::Empty,
                "`n` is 0: no pixels to light",
            ));
        }
        let in_bytes = byte_len::<OceanSeaColorInput>(n, "inputs")?;
        let out_bytes = byte_len::<OceanSeaLight>(n, "out")?;
        check_disjoint(
            (inputs.cast::<u8>(), in_bytes, "inputs"),
            (out.cast_const().cast::<u8>(), out_bytes, "out"),
        )?;
        same_lighting(&l, &m)?;
        // SAFETY: non-NULL and aligned (checked), the byte size fits in isize (checked), and
        // the caller guarantees `n` readable inputs that nothing writes during the call.
        let inputs = unsafe { core::slice::from_raw_parts(inputs, n) };
        // Every input is lit (and so validated) before the first output is written.
        let mut lights = Vec::with_capacity(n);
        for (i, input) in inputs.iter().enumerate() {
            // The element's name is formatted only for a message: once per element it would
            // cost as much as a small batch's lighting.
            let light = sea_color_one(&l.lighting, &m.map, input).map_err(|e| Error {
                message: format!("inputs[{i}].{}", e.message),
                ..e
            })?;
            lights.push(OceanSeaLight::from_core(&light));
        }
        // SAFETY: non-NULL and aligned (checked), byte size fits in isize and disjoint from
        // `inputs` (checked); `n` writable elements untouched by others (caller's guarantee).
        let out = unsafe { core::slice::from_raw_parts_mut(out, n) };
        out.copy_from_slice(&lights);
        Ok(())
    })
}

const _: () = assert!(size_of::<OceanRgb>() == 24 && align_of::<OceanRgb>() == 8);

crate::boundary::chain::extensible!(OceanSkyParams, OceanSeaParams);

#[cfg(test)]
mod tests {
    use super::*;

    use crate::status::last_error;

    fn lighting() -> *mut OceanLighting {
        let mut sky = OceanSkyParams::default();
        let mut sea = OceanSeaParams::default();
        let mut l = core::ptr::null_mut();
        // SAFETY: valid pointers.
        unsafe {
            assert_eq!(ocean_sky_params_default(&mut sky), OceanStatus::Ok);
            assert_eq!(ocean_sea_params_default(&mut sea), OceanStatus::Ok);
            assert_eq!(ocean_lighting_create(&sky, &sea, &mut l), OceanStatus::Ok);
        }
        l
    }

    fn sky_map(l: *const OceanLighting, size: u32) -> *mut OceanSkyMap {
        let mut m = core::ptr::null_mut();
        // SAFETY: live lighting, writable out.
        let s = unsafe { ocean_lighting_sky_map_create(l, size, &mut m) };
        assert_eq!(s, OceanStatus::Ok, "{}", last_error());
        m
    }

    /// The wrapper adds nothing to the arithmetic: the defaults, the derived radiances, the
    /// sky map's levels and the sea's colour are the crate's, bit for bit.
    #[test]
    fn matches_the_crate_bit_for_bit() {
        let l = lighting();
        let core = Lighting::new(SkyParams::default(), SeaParams::default()).unwrap();
        let mut rgb = OceanRgb::default();
        // SAFETY: live handle, writable out.
        unsafe {
            assert_eq!(ocean_lighting_sea_radiance(l, &mut rgb), OceanStatus::Ok);
            assert_eq!(rgb.to_dvec3(), core.sea_radiance());
            assert_eq!(ocean_lighting_sky_irradiance(l, &mut rgb), OceanStatus::Ok);
            assert_eq!(rgb.to_dvec3(), core.sky().sky_irradiance());
        }
        let m = sky_map(l, 16);
        let core_map = core.sky_map(16).unwrap();
        for level in 0..5 {
            let mut side = 0;
            // SAFETY: live handle, writable out.
            let s = unsafe { ocean_sky_map_level_info(m, level, &mut side) };
            assert_eq!(s, OceanStatus::Ok);
            assert_eq!(side, 16 >> level);
            let n = (side * side * 4) as usize;
            let mut buf = vec![0.0f32; n];
            // SAFETY: n writable floats.
            let s = unsafe { ocean_sky_map_copy_level(m, level, buf.as_mut_ptr(), n) };
            assert_eq!(s, OceanStatus::Ok, "{}", last_error());
            let want: &[f32] = bytemuck::cast_slice(core_map.level(level).unwrap());
            assert_eq!(buf, want);
        }
        let input = OceanSeaColorInput {
            v: OceanDVec3 {
                x: 0.3,
                y: 0.8,
                z: -0.6,
            },
            n: OceanDVec3 {
                x: 0.1,
                y: 0.99,
                z: 0.05,
            },
            wind: OceanDVec2 { x: 1.0, z: 0.5 },
            sigma_x2: 0.02,
            sigma_y2: 0.01,
        };
        let nv = |d: OceanDVec3| {
            let v = DVec3::new(d.x, d.y, d.z).normalize();
            OceanDVec3 {
                x: v.x,
                y: v.y,
                z: v.z,
            }
        };
        let input = OceanSeaColorInput {
            v: nv(input.v),
            n: nv(input.n),
            ..input
        };
        let mut one = OceanSeaLight::default();
        let mut batch = [OceanSeaLight::default(); 2];
        // SAFETY: live handles, writable outputs, two inputs and two outputs.
        unsafe {
            let s = ocean_sea_color(
                l,
                m,
                input.v,
                input.n,
                input.wind,
                input.sigma_x2,
                input.sigma_y2,
                &mut one,
            );
            assert_eq!(s, OceanStatus::Ok, "{}", last_error());
            let inputs = [input, input];
            let s = ocean_sea_color_batch(l, m, inputs.as_ptr(), 2, batch.as_mut_ptr());
            assert_eq!(s, OceanStatus::Ok, "{}", last_error());
        }
        let want = sea_color(
            &core,
            &core_map,
            DVec3::new(input.v.x, input.v.y, input.v.z),
            DVec3::new(input.n.x, input.n.y, input.n.z),
            DVec2::new(1.0, 0.5),
            SlopeVariance { x: 0.02, y: 0.01 },
        )
        .unwrap();
        assert_eq!(one, OceanSeaLight::from_core(&want));
        assert_eq!(batch, [one, one]);
        ocean_sky_map_destroy(m);
        ocean_lighting_destroy(l);
    }

    #[test]
    fn a_sky_map_of_another_lighting_is_refused() {
        let l = lighting();
        let mut sky = OceanSkyParams::default();
        let mut sea = OceanSeaParams::default();
        // SAFETY: valid pointers.
        unsafe {
            ocean_sky_params_default(&mut sky);
            ocean_sea_params_default(&mut sea);
        }
        sea.albedo.r = 0.5;
        let mut other = core::ptr::null_mut();
        // SAFETY: valid pointers.
        let s = unsafe { ocean_lighting_create(&sky, &sea, &mut other) };
        assert_eq!(s, OceanStatus::Ok);
        let m = sky_map(other, 4);
        let up = OceanDVec3 {
            x: 0.0,
            y: 1.0,
            z: 0.0,
        };
        let mut out = OceanSeaLight::default();
        // SAFETY: live handles.
        let s = unsafe {
            ocean_sea_color(
                l,
                m,
                up,
                up,
                OceanDVec2 { x: 1.0, z: 0.0 },
                0.0,
                0.0,
                &mut out,
            )
        };
        assert_eq!(s, OceanStatus::InvalidArgument);
        assert!(
            last_error().contains("another lighting"),
            "{}",
            last_error()
        );
        assert_eq!(out, OceanSeaLight::default());
        ocean_sky_map_destroy(m);
        ocean_lighting_destroy(other);
        ocean_lighting_destroy(l);
    }

    #[test]
    fn misaligned_handles_and_buffers_are_refused() {
        let l = lighting();
        let m = sky_map(l, 4);
        let mut storage = [0u64; 16];
        let base = storage.as_mut_ptr().cast::<u8>();
        let bad_map = base.wrapping_add(4).cast::<OceanSkyMap>().cast_const();
        let mut side = 7;
        // SAFETY: refused before any access.
        let s = unsafe { ocean_sky_map_level_info(bad_map, 0, &mut side) };
        // A handle is an id, never an address: a pointer into the caller's memory is not one.
        assert_eq!(s, OceanStatus::InvalidHandle);
        assert_eq!(side, 7);
        let bad_rgba = base.wrapping_add(2).cast::<f32>();
        // SAFETY: refused before any access.
        let s = unsafe { ocean_sky_map_copy_level(m, 2, bad_rgba, 4) };
        assert_eq!(s, OceanStatus::MisalignedPointer);
        assert!(storage.iter().all(|&v| v == 0));
        ocean_sky_map_destroy(bad_map.cast_mut());
        ocean_sky_map_destroy(m);
        ocean_lighting_destroy(l);
    }
}
