//! The sea colour of Algorithm 5.1 (Bruneton et al. 2010) at single points and in batches,
//! from a lighting and its sky map.

use glam::{DVec2, DVec3};
use ocean_brdf::sea::{SeaLight, sea_color};
use ocean_brdf::{Lighting, SkyMap, SlopeVariance};

use crate::boundary::{borrow, byte_len, check_disjoint, check_finite, check_ptr, write_out};
use crate::lighting::{OceanLighting, OceanRgb};
use crate::lighting_sky_map::OceanSkyMap;
use crate::status::{Error, OceanStatus, guard};
use crate::waves::{OceanDVec2, OceanDVec3};

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
    pub(crate) fn from_core(s: &SeaLight) -> Self {
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

/// Checks that `map` was rendered from `lighting`'s parameters.
pub(crate) fn same_lighting(lighting: &OceanLighting, map: &OceanSkyMap) -> Result<(), Error> {
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
pub(crate) fn sea_color_one(
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
