//! Ocean lighting (crate `ocean-brdf`), part 2 of 3: stateless evaluations of the Ross BRDF
//! (section 4), the Sun's reflection (Eq. 15), Schlick's Fresnel factor (Eq. 14), the effective
//! Fresnel reflectance of rough water (Eq. 24, 26) and the tone mapping.
//!
//! The BRDF functions take vectors in the surface's **tangent frame**: x along the wind, y
//! across it, z along the (mean) surface normal; not world space. `OceanDVec3`'s members keep
//! their names (x, y, z) but mean these axes here.

use glam::DVec3;
use ocean_brdf::fresnel::{WATER_R, effective_fresnel_fit, effective_fresnel_integral, schlick};
use ocean_brdf::fresnel_table::effective_fresnel_table;
use ocean_brdf::ross::{brdf, sun_radiance};
use ocean_brdf::tonemap::{DEFAULT_EXPOSURE, linear_to_srgb, tone_map};

use crate::boundary::{Num, check_finite, check_ptr, write_out};
use crate::lighting::{OceanRgb, finite_dvec3};
use crate::status::{Error, OceanStatus, guard};
use crate::waves::OceanDVec3;

/// Reflectance of water at normal incidence, R of Eq. 14 (a refractive index of 1.33).
pub const OCEAN_WATER_R: f64 = 0.02;
/// The default exposure of `ocean_tone_map`: maps the default sky's zenith (radiance about
/// 0.05) to about 0.33 and the default sea's refracted light (about 0.01) to about 0.08.
pub const OCEAN_DEFAULT_EXPOSURE: f64 = 8.0;

const _: () = assert!(OCEAN_WATER_R == WATER_R);
const _: () = assert!(OCEAN_DEFAULT_EXPOSURE == DEFAULT_EXPOSURE);

/// Checks the pointer, computes, and writes `*out` only on success.
///
/// # Safety
///
/// `out` must be NULL, misaligned, or writable.
unsafe fn evaluate<T>(
    function: &str,
    out: *mut T,
    f: impl FnOnce() -> Result<T, Error>,
) -> OceanStatus {
    guard(function, || {
        check_ptr(out.cast_const(), "out")?;
        let value = f()?;
        // SAFETY: forwarded from the caller's contract.
        unsafe { write_out(out, "out", value) }
    })
}

/// Finite scalar arguments, or `OCEAN_STATUS_NON_FINITE` naming the first bad one.
fn finite(fields: &[(&str, f64)]) -> Result<(), Error> {
    check_finite("", fields)
}

/// The Ross BRDF (Eq. 13) with Schlick's Fresnel factor (Eq. 14), 1/steradian, stored in
/// `*out`:
///
/// brdf = p(zeta_h) F(v.h) / (4 h_z^4 cos(theta_v) cos(theta_l) (1 + Lambda(a_v) + Lambda(a_l)))
///
/// with h = normalize(v + l), zeta_h = -(h_x, h_y)/h_z, p the Gaussian slope density of Eq. 7,
/// Lambda(a) = (exp(-a^2) - a sqrt(pi) erfc(a)) / (2 a sqrt(pi)) (Eq. 8) and Smith's
/// a = d_z / sqrt(2 (sigma_x2 d_x^2 + sigma_y2 d_y^2)) (Eq. 9 with the tan^2 the normalisation of
/// Eq. 11 requires; the transcription's tan is a misprint). 0 when `v` or `l` is on or below
/// the horizon (z <= 0). Symmetric in `v` and `l`.
///
/// - `v`, `l`: unit vectors towards the viewer and the light, **tangent frame** (x along the
///   wind, y across it, z along the normal), lengths within 1e-6 of 1;
/// - `sigma_x2`, `sigma_y2`: slope variances along x and y, in [DBL_MIN, DBL_MAX] (a zero
///   variance has no density);
/// - `r`: reflectance at normal incidence, in [0, 1] (water: `OCEAN_WATER_R`).
///
/// Returns `OCEAN_STATUS_NULL_POINTER` / `_MISALIGNED_POINTER` for a bad `out`,
/// `OCEAN_STATUS_NON_FINITE` for a NaN or infinite argument, `OCEAN_STATUS_INVALID_ARGUMENT` for
/// one out of its range. `*out` is written only on success.
///
/// # Safety
///
/// `out` must be writable.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn ocean_ross_brdf(
    v: OceanDVec3,
    l: OceanDVec3,
    sigma_x2: f64,
    sigma_y2: f64,
    r: f64,
    out: *mut f64,
) -> OceanStatus {
    // SAFETY: forwarded from this function's contract.
    unsafe {
        evaluate("ocean_ross_brdf", out, || {
            let v = finite_dvec3("v", &v)?;
            let l = finite_dvec3("l", &l)?;
            finite(&[("sigma_x2", sigma_x2), ("sigma_y2", sigma_y2), ("r", r)])?;
            brdf(v, l, sigma_x2, sigma_y2, r).map_err(Error::from)
        })
    }
}

/// The Sun's reflected radiance I_sun of Eq. 15, stored in `*out`:
/// `l_sun * omega_sun * brdf(v, l) * l_z` with `brdf` as in `ocean_ross_brdf` (the BRDF taken as
/// constant over the solar disc), in the unit of `l_sun`.
///
/// To show the Sun as a disc on a flat sea rather than a point, raise the variances to at
/// least rho^2 / 16 (rho = 4.653e-3 rad, the Sun's angular radius) first, as `ocean_sea_color`
/// does.
///
/// - `v`, `l`, `sigma_x2`, `sigma_y2`, `r`: as in `ocean_ross_brdf` (tangent frame);
/// - `l_sun`: the Sun's radiance, finite and >= 0;
/// - `omega_sun`: its solid angle, steradians, in [0, 2 pi].
///
/// Returns as `ocean_ross_brdf`. `*out` is written only on success.
///
/// # Safety
///
/// `out` must be writable.
#[unsafe(no_mangle)]
#[allow(clippy::too_many_arguments)]
pub unsafe extern "C" fn ocean_sun_radiance(
    v: OceanDVec3,
    l: OceanDVec3,
    sigma_x2: f64,
    sigma_y2: f64,
    l_sun: f64,
    omega_sun: f64,
    r: f64,
    out: *mut f64,
) -> OceanStatus {
    // SAFETY: forwarded from this function's contract.
    unsafe {
        evaluate("ocean_sun_radiance", out, || {
            let v = finite_dvec3("v", &v)?;
            let l = finite_dvec3("l", &l)?;
            finite(&[
                ("sigma_x2", sigma_x2),
                ("sigma_y2", sigma_y2),
                ("l_sun", l_sun),
                ("omega_sun", omega_sun),
                ("r", r),
            ])?;
            sun_radiance(v, l, sigma_x2, sigma_y2, l_sun, omega_sun, r).map_err(Error::from)
        })
    }
}

/// Schlick's Fresnel factor, Eq. 14: F = r + (1 - r) (1 - c)^5 with c = `cos_theta` clamped to
/// [0, 1] (a back-facing cosine gives 1), stored in `*out`. F(1) = r, F(0) = 1.
///
/// `cos_theta`: the cosine between the direction and the facet normal, finite; `r`: the
/// reflectance at normal incidence, in [0, 1].
///
/// Returns `OCEAN_STATUS_NULL_POINTER` / `_MISALIGNED_POINTER` for a bad `out`,
/// `OCEAN_STATUS_NON_FINITE` for a NaN or infinite argument, `OCEAN_STATUS_INVALID_ARGUMENT` for
/// `r` outside [0, 1]. `*out` is written only on success.
///
/// # Safety
///
/// `out` must be writable.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn ocean_schlick(cos_theta: f64, r: f64, out: *mut f64) -> OceanStatus {
    // SAFETY: forwarded from this function's contract.
    unsafe {
        evaluate("ocean_schlick", out, || {
            finite(&[("cos_theta", cos_theta), ("r", r)])?;
            if !(0.0..=1.0).contains(&r) {
                return Err(Error::new(
                    OceanStatus::InvalidArgument,
                    format!("r = {} is outside [0, 1]", Num(r)),
                ));
            }
            Ok(schlick(cos_theta, r))
        })
    }
}

/// The paper's fit of the effective Fresnel reflectance of rough water, Eq. 26, stored in
/// `*out`:
///
/// F_bar = r + (1 - r) (1 - cos_theta_v)^(5 exp(-2.69 sigma_v)) / (1 + 22.7 sigma_v^1.5)
///
/// equal to `ocean_schlick(cos_theta_v, r)` bit for bit at sigma_v = 0. Fitted for slope
/// deviations below 0.5.
///
/// - `cos_theta_v`: cosine of the view's angle to the mean normal, in [0, 1];
/// - `sigma_v`: the slope **standard deviation** in the view's azimuth,
///   sqrt(sigma_x2 cos^2 phi_v + sigma_y2 sin^2 phi_v) (Eq. 25, phi_v measured from the wind),
///   finite and >= 0;
/// - `r`: reflectance at normal incidence, in [0, 1].
///
/// Returns `OCEAN_STATUS_NULL_POINTER` / `_MISALIGNED_POINTER` for a bad `out`,
/// `OCEAN_STATUS_NON_FINITE` for a NaN or infinite argument, `OCEAN_STATUS_INVALID_ARGUMENT` for
/// one out of its range. `*out` is written only on success.
///
/// # Safety
///
/// `out` must be writable.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn ocean_effective_fresnel_fit(
    cos_theta_v: f64,
    sigma_v: f64,
    r: f64,
    out: *mut f64,
) -> OceanStatus {
    // SAFETY: forwarded from this function's contract.
    unsafe {
        evaluate("ocean_effective_fresnel_fit", out, || {
            finite(&[("cos_theta_v", cos_theta_v), ("sigma_v", sigma_v), ("r", r)])?;
            effective_fresnel_fit(cos_theta_v, sigma_v, r).map_err(Error::from)
        })
    }
}

/// The effective Fresnel reflectance of Eq. 24 from its table, what the sea colour
/// (`ocean_sea_color`) and the GPU renderer use, stored in `*out`:
///
/// F_bar = r + (1 - r) ((1 - cos_theta_v)^5 + D(cos_theta_v, sigma_v))
///
/// with D the tabulated roughness correction (33 x 33 nodes over sqrt(cos_theta_v) and
/// sqrt(sigma_v), bilinear; sigma_v above 1 clamps to 1). Within about 0.02 of
/// `ocean_effective_fresnel_integral` for slope deviations below 0.5 (the fit: about 0.045), and
/// Schlick's value for sigma_v = 0. Arguments and statuses as `ocean_effective_fresnel_fit`.
///
/// # Safety
///
/// `out` must be writable.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn ocean_effective_fresnel_table(
    cos_theta_v: f64,
    sigma_v: f64,
    r: f64,
    out: *mut f64,
) -> OceanStatus {
    // SAFETY: forwarded from this function's contract.
    unsafe {
        evaluate("ocean_effective_fresnel_table", out, || {
            finite(&[("cos_theta_v", cos_theta_v), ("sigma_v", sigma_v), ("r", r)])?;
            effective_fresnel_table(cos_theta_v, sigma_v, r).map_err(Error::from)
        })
    }
}

/// The effective Fresnel reflectance of Eq. 24 by numerical integration (the reference Eq. 26
/// fits), stored in `*out`:
///
/// F_bar(v) = r + (1 - r) integral of q^e_vn(zeta, v) (1 - v.f(zeta))^5 d^2 zeta
///
/// over the visible facets (Eq. 10), by a deterministic Gauss-Legendre rule (accurate to about
/// 1e-9 for sigma_x, sigma_y <= 1). About 16 000 integrand evaluations per call: for per-pixel
/// use take `ocean_effective_fresnel_fit`.
///
/// - `v`: unit vector towards the viewer, **tangent frame** (x along the wind, y across it, z
///   along the normal), with v_z >= 0;
/// - `sigma_x2`, `sigma_y2`: slope variances, finite and >= 0 (both 0: Schlick's F(v_z));
/// - `r`: reflectance at normal incidence, in [0, 1].
///
/// Returns `OCEAN_STATUS_NULL_POINTER` / `_MISALIGNED_POINTER` for a bad `out`,
/// `OCEAN_STATUS_NON_FINITE` for a NaN or infinite argument, `OCEAN_STATUS_INVALID_ARGUMENT` for
/// one out of its range (v not a unit vector, v_z < 0, ...). `*out` is written only on success.
///
/// # Safety
///
/// `out` must be writable.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn ocean_effective_fresnel_integral(
    v: OceanDVec3,
    sigma_x2: f64,
    sigma_y2: f64,
    r: f64,
    out: *mut f64,
) -> OceanStatus {
    // SAFETY: forwarded from this function's contract.
    unsafe {
        evaluate("ocean_effective_fresnel_integral", out, || {
            let v = finite_dvec3("v", &v)?;
            finite(&[("sigma_x2", sigma_x2), ("sigma_y2", sigma_y2), ("r", r)])?;
            effective_fresnel_integral(v, sigma_x2, sigma_y2, r).map_err(Error::from)
        })
    }
}

/// Exponential tone mapping, 1 - exp(-exposure * L) per channel (negative radiance maps to 0,
/// the result is in [0, 1]), stored in `*out` as linear values; encode them for display with
/// `ocean_linear_to_srgb`. The GPU renderer uses the same curve.
///
/// `radiance`: linear RGB, every channel finite; `exposure`: finite and >= 0 (the default is
/// `OCEAN_DEFAULT_EXPOSURE`).
///
/// Returns `OCEAN_STATUS_NULL_POINTER` / `_MISALIGNED_POINTER` for a bad `out`,
/// `OCEAN_STATUS_NON_FINITE` for a NaN or infinite argument, `OCEAN_STATUS_INVALID_ARGUMENT` for
/// a negative exposure. `*out` is written only on success.
///
/// # Safety
///
/// `out` must be writable.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn ocean_tone_map(
    radiance: OceanRgb,
    exposure: f64,
    out: *mut OceanRgb,
) -> OceanStatus {
    // SAFETY: forwarded from this function's contract.
    unsafe {
        evaluate("ocean_tone_map", out, || {
            finite(&[
                ("radiance.r", radiance.r),
                ("radiance.g", radiance.g),
                ("radiance.b", radiance.b),
                ("exposure", exposure),
            ])?;
            if exposure < 0.0 {
                return Err(Error::new(
                    OceanStatus::InvalidArgument,
                    format!("exposure must be >= 0, got {}", Num(exposure)),
                ));
            }
            let c = tone_map(DVec3::new(radiance.r, radiance.g, radiance.b), exposure);
            Ok(OceanRgb::from_dvec3(c))
        })
    }
}

/// The sRGB transfer function (IEC 61966-2-1) from a linear value to an encoded one, both in
/// [0, 1] (the input is clamped to [0, 1] first), stored in `*out`: 12.92 c up to 0.0031308,
/// 1.055 c^(1/2.4) - 0.055 above.
///
/// Returns `OCEAN_STATUS_NULL_POINTER` / `_MISALIGNED_POINTER` for a bad `out`,
/// `OCEAN_STATUS_NON_FINITE` for a NaN or infinite `linear`. `*out` is written only on success.
///
/// # Safety
///
/// `out` must be writable.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn ocean_linear_to_srgb(linear: f64, out: *mut f64) -> OceanStatus {
    // SAFETY: forwarded from this function's contract.
    unsafe {
        evaluate("ocean_linear_to_srgb", out, || {
            finite(&[("linear", linear)])?;
            Ok(linear_to_srgb(linear))
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use core::ffi::CStr;

    fn last_error() -> String {
        // SAFETY: a valid NUL-terminated string until the next status call; copied at once.
        unsafe { CStr::from_ptr(crate::ocean_last_error_message()) }
            .to_string_lossy()
            .into_owned()
    }

    fn d3(x: f64, y: f64, z: f64) -> OceanDVec3 {
        let n = (x * x + y * y + z * z).sqrt();
        OceanDVec3 {
            x: x / n,
            y: y / n,
            z: z / n,
        }
    }

    #[test]
    fn evaluations_are_the_crates_and_errors_leave_out_untouched() {
        let (v, l) = (d3(0.3, 0.1, 0.9), d3(-0.4, 0.2, 0.8));
        let mut out = -1.0;
        // SAFETY: writable out.
        let st = unsafe { ocean_ross_brdf(v, l, 0.02, 0.01, 0.02, &mut out) };
        assert_eq!(st, OceanStatus::Ok, "{}", last_error());
        let want = brdf(
            DVec3::new(v.x, v.y, v.z),
            DVec3::new(l.x, l.y, l.z),
            0.02,
            0.01,
            0.02,
        )
        .unwrap();
        assert_eq!(out, want);

        let mut out = -1.0;
        // SAFETY: writable out.
        let st = unsafe { ocean_ross_brdf(v, l, f64::NAN, 0.01, 0.02, &mut out) };
        assert_eq!(st, OceanStatus::NonFinite);
        assert!(last_error().contains("sigma_x2"), "{}", last_error());
        assert_eq!(out, -1.0);
        // SAFETY: writable out.
        let st = unsafe { ocean_ross_brdf(v, d3(1.0, 0.0, 0.0), 0.0, 0.01, 0.02, &mut out) };
        assert_eq!(st, OceanStatus::InvalidArgument);
        assert_eq!(out, -1.0);
        let bad = OceanDVec3 {
            x: 0.0,
            y: 0.0,
            z: 2.0,
        };
        // SAFETY: writable out.
        let st = unsafe { ocean_effective_fresnel_integral(bad, 0.01, 0.01, 0.02, &mut out) };
        assert_eq!(st, OceanStatus::InvalidArgument);
        assert!(last_error().contains("unit"), "{}", last_error());
        assert_eq!(out, -1.0);
        // SAFETY: NULL out is refused.
        let st = unsafe { ocean_schlick(0.5, 0.02, core::ptr::null_mut()) };
        assert_eq!(st, OceanStatus::NullPointer);
    }
}
