//! Ocean lighting (crate `ocean-brdf`), part 1 of 3: the wave spectrum (Eq. 1, Hasselmann
//! spreading) sampled into trochoids, its statistics, the slope variance a pixel does not
//! resolve (Eq. 4) and the pixel footprint it is filtered on.

use glam::DVec2;
use ocean_brdf::surface::pixel_footprint;
use ocean_brdf::{Filter, SlopeVariance, Spectrum, SpectrumParams};
use ocean_core::{Depth, WaveDesc};

use crate::boundary::OceanNext;
use crate::boundary::{
    Num, borrow, byte_len, check_finite, check_len, check_ptr, destroy, read_params, write_handle,
    write_out,
};
use crate::lighting::brdf_error;

use crate::camera::{OceanCamera, read_camera};
use crate::status::{Error, OceanStatus, guard};
use crate::waves::OceanDVec2;
use crate::waves::OceanWaveDesc;

/// N_min of the paper's filter (section 7.1): a wave starts to appear in the normals (or the
/// geometry) once its wavelength spans this many pixels (or grid cells).
pub const OCEAN_FILTER_N_MIN: f64 = 1.0;
/// N_max of the paper's filter: a wave is fully present from this many pixels per wavelength.
pub const OCEAN_FILTER_N_MAX: f64 = 2.5;

/// What to sample (paper section 3.1, 7.1). `ocean_spectrum_params_default` fills in 60 waves
/// from 2 cm to 30 m under a 10 m/s wind along +x.
///
/// The `wave_count` wavelengths form a geometric progression from `min_wavelength` to
/// `max_wavelength`. Wave i (shortest first) stands for the band of angular frequencies around
/// its own omega_i = sqrt(g k_i), k_i = 2 pi / lambda_i, reaching halfway in log(omega) to its
/// neighbours, d_omega_i = omega_i (q - 1/q) with q = (lambda_max/lambda_min)^(1/(4 (n - 1)))
/// (0 for a single wave), and takes that band's energy: A_i = sqrt(2 S(omega_i) d_omega_i),
/// with S the Pierson-Moskowitz spectrum of Eq. 1,
/// S(omega) = 8.1e-3 g^2 / omega^5 exp(-0.74 (g / (V omega))^4), g = 9.81 m/s^2; then clamped
/// to k_i A_i <= `max_steepness`. Directions are drawn from Hasselmann's cos^2s(theta/2)
/// spreading around the wind (s >= 2), phases uniformly, from a PCG32 stream seeded by `seed`:
/// the same parameters give the same waves on every platform.
#[repr(C)]
#[derive(Clone, Copy, Debug, Default, PartialEq, bytemuck::Zeroable, bytemuck::Pod)]
pub struct OceanSpectrumParams {
    /// Extensions: NULL, or the first extension struct (see `OceanChain`); the `_default`
    /// function sets NULL.
    pub next: OceanNext,
    /// Wind speed 20 m above the sea, m/s (V_20 of Eq. 1), in [1e-3, 200].
    pub wind_speed: f64,
    /// x component of the direction the wind blows towards, on the sea plane; with
    /// `wind_direction_z` any finite, non-zero vector (it is normalised).
    pub wind_direction_x: f64,
    /// z component of the wind direction.
    pub wind_direction_z: f64,
    /// Number of trochoids, 1 to 1024 (the paper uses 60).
    pub wave_count: usize,
    /// Shortest wavelength, metres, in [1e-4, 1e5].
    pub min_wavelength: f64,
    /// Longest wavelength, metres, in [min_wavelength, 1e5]; strictly longer when
    /// `wave_count` > 1.
    pub max_wavelength: f64,
    /// Largest steepness k*A of any one wave, in [0, 1]: longer amplitudes are clamped to it
    /// (a trochoid with k*A > 1 loops over itself).
    pub max_steepness: f64,
    /// Seed of the directions and phases.
    pub seed: u64,
}

/// Slope variances of a Gaussian slope distribution (Eq. 4), dimensionless: along the wind and
/// across it (the x and y axes of the BRDF's tangent frame).
#[repr(C)]
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct OceanSlopeVariance {
    /// sigma_x^2, along the wind, >= 0.
    pub sigma_x2: f64,
    /// sigma_y^2, across the wind, >= 0.
    pub sigma_y2: f64,
}

impl OceanSlopeVariance {
    fn from_core(v: SlopeVariance) -> Self {
        Self {
            sigma_x2: v.x,
            sigma_y2: v.y,
        }
    }
}

/// A sampled wave spectrum (opaque): its trochoids and statistics. Create with
/// `ocean_spectrum_create`, free with `ocean_spectrum_destroy`. Immutable: a
/// `const OceanSpectrum *` may be used by any number of threads at once.
pub struct OceanSpectrum {
    pub(crate) spectrum: Spectrum,
}

const _: () = {
    const fn shareable<T: Send + Sync>() {}
    shareable::<OceanSpectrum>();
};

/// Stores the default spectrum parameters in `*out`: wind 10 m/s along +x, 60 waves from
/// 0.02 m to 30 m, steepness at most 0.5, seed 0.
///
/// Returns `OCEAN_STATUS_NULL_POINTER` (or `_MISALIGNED_POINTER`) for a bad `out`, which is
/// then left unchanged.
///
/// # Safety
///
/// `out` must be writable.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn ocean_spectrum_params_default(
    out: *mut OceanSpectrumParams,
) -> OceanStatus {
    guard("ocean_spectrum_params_default", || {
        let d = SpectrumParams::default();
        let p = OceanSpectrumParams {
            next: OceanNext::NULL,
            wind_speed: d.wind_speed,
            wind_direction_x: d.wind_direction.x,
            wind_direction_z: d.wind_direction.y,
            wave_count: d.waves,
            min_wavelength: d.min_wavelength,
            max_wavelength: d.max_wavelength,
            max_steepness: d.max_steepness,
            seed: d.seed,
        };
        // SAFETY: forwarded from this function's contract.
        unsafe { write_out(out, "out", p) }
    })
}

/// Samples a spectrum and stores a new handle in `*out` (see `OceanSpectrumParams` for the
/// sampling).
///
/// Returns `OCEAN_STATUS_NULL_POINTER` / `_MISALIGNED_POINTER` for a bad pointer,
/// `OCEAN_STATUS_EMPTY` if `wave_count` is 0, `OCEAN_STATUS_NON_FINITE` for a NaN or infinite
/// member (the message names it), `OCEAN_STATUS_INVALID_ARGUMENT` for a member out of its
/// documented range (a zero wind direction included). On failure `*out` is unchanged. Free the
/// handle with `ocean_spectrum_destroy`.
///
/// # Safety
///
/// `params` must point to a readable `OceanSpectrumParams` and `out` to a writable pointer;
/// neither is retained.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn ocean_spectrum_create(
    params: *const OceanSpectrumParams,
    out: *mut *mut OceanSpectrum,
) -> OceanStatus {
    guard("ocean_spectrum_create", || {
        check_ptr(params, "params")?;
        check_ptr(out.cast_const(), "out")?;
        // SAFETY: forwarded from this function's contract.
        let p = unsafe { read_params(params, "params") }?;
        check_finite(
            "params->",
            &[
                ("wind_speed", p.wind_speed),
                ("wind_direction_x", p.wind_direction_x),
                ("wind_direction_z", p.wind_direction_z),
                ("min_wavelength", p.min_wavelength),
                ("max_wavelength", p.max_wavelength),
                ("max_steepness", p.max_steepness),
            ],
        )?;
        if p.wind_direction_x == 0.0 && p.wind_direction_z == 0.0 {
            return Err(Error::new(
                OceanStatus::InvalidArgument,
                "params->wind_direction_x and _z are both 0: the wind direction must be non-zero",
            ));
        }
        if p.wave_count == 0 {
            return Err(Error::new(
                OceanStatus::Empty,
                "params->wave_count is 0: a spectrum needs at least one wave",
            ));
        }
        let spectrum = Spectrum::new(SpectrumParams {
            wind_speed: p.wind_speed,
            wind_direction: DVec2::new(p.wind_direction_x, p.wind_direction_z),
            waves: p.wave_count,
            min_wavelength: p.min_wavelength,
            max_wavelength: p.max_wavelength,
            max_steepness: p.max_steepness,
            seed: p.seed,
        })
        .map_err(|e| brdf_error("params: ", e))?;
        // SAFETY: forwarded from this function's contract.
        unsafe { write_handle(out, OceanSpectrum { spectrum }) }
    })
}

/// Frees a spectrum. NULL does nothing; a handle of another kind or already destroyed frees nothing
/// and sets the last-error message (see the header's notes on handles).
#[unsafe(no_mangle)]
pub extern "C" fn ocean_spectrum_destroy(spectrum: *mut OceanSpectrum) {
    destroy(spectrum, "ocean_spectrum_destroy", "spectrum");
}

/// Runs `f` on a borrowed spectrum and writes its result to `*out`.
///
/// # Safety
///
/// `out` must be NULL, misaligned or writable.
unsafe fn spectrum_out<T>(
    function: &str,
    spectrum: *const OceanSpectrum,
    out: *mut T,
    f: impl FnOnce(&Spectrum) -> T,
) -> OceanStatus {
    guard(function, || {
        let s = borrow(spectrum, "spectrum")?;
        check_ptr(out.cast_const(), "out")?;
        let value = f(&s.spectrum);
        // SAFETY: forwarded from the caller's contract.
        unsafe { write_out(out, "out", value) }
    })
}

/// Stores the number of waves (`params->wave_count`) in `*out`.
///
/// Returns `OCEAN_STATUS_NULL_POINTER` / `_MISALIGNED_POINTER` for a bad pointer; `*out` is
/// written only on success.
///
/// # Safety
///
/// `out` must be writable.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn ocean_spectrum_wave_count(
    spectrum: *const OceanSpectrum,
    out: *mut usize,
) -> OceanStatus {
    // SAFETY: forwarded from this function's contract.
    unsafe {
        spectrum_out("ocean_spectrum_wave_count", spectrum, out, |s| {
            s.waves().len()
        })
    }
}

fn wave_desc_to(w: &WaveDesc) -> OceanWaveDesc {
    OceanWaveDesc {
        amplitude: w.amplitude,
        wavelength: w.wavelength,
        direction_x: w.direction.x,
        direction_z: w.direction.y,
        phase: w.phase,
        depth: match w.depth {
            Depth::Deep => f64::INFINITY,
            Depth::Finite(d) => d,
        },
    }
}

/// Copies the waves into `out[0..n]`, shortest first, as `OceanWaveDesc`s that
/// `ocean_waves_create` accepts as they are: unit directions, phases in [0, 2 pi), deep water
/// (`depth` = `INFINITY`). `n` must equal the wave count exactly.
///
/// Returns `OCEAN_STATUS_NULL_POINTER` / `_MISALIGNED_POINTER` for a bad pointer (8-byte
/// alignment), `OCEAN_STATUS_LENGTH_MISMATCH` if `n` is not the wave count,
/// `OCEAN_STATUS_LENGTH_OVERFLOW` if `n * sizeof(OceanWaveDesc)` exceeds `PTRDIFF_MAX`. Nothing
/// is written on failure.
///
/// # Safety
///
/// `out` must point to `n` writable `OceanWaveDesc`s that no
/// other thread touches during the call.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn ocean_spectrum_waves(
    spectrum: *const OceanSpectrum,
    out: *mut OceanWaveDesc,
    n: usize,
) -> OceanStatus {
    guard("ocean_spectrum_waves", || {
        let s = borrow(spectrum, "spectrum")?;
        check_ptr(out.cast_const(), "out")?;
        byte_len::<OceanWaveDesc>(n, "out")?;
        let waves = s.spectrum.waves();
        check_len("n", n, waves.len(), "the spectrum's wave list")?;
        // SAFETY: non-NULL and aligned (checked), `n` elements whose byte size fits in isize
        // (checked), writable and untouched by others (caller's guarantee).
        let out = unsafe { core::slice::from_raw_parts_mut(out, n) };
        for (o, w) in out.iter_mut().zip(waves) {
            *o = wave_desc_to(w);
        }
        Ok(())
    })
}

/// Stores the unit wind direction (x, z) in `*out`: the x axis of the slope variances.
///
/// Returns `OCEAN_STATUS_NULL_POINTER` / `_MISALIGNED_POINTER` for a bad pointer; `*out` is
/// written only on success.
///
/// # Safety
///
/// `out` must be writable.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn ocean_spectrum_wind_direction(
    spectrum: *const OceanSpectrum,
    out: *mut OceanDVec2,
) -> OceanStatus {
    // SAFETY: forwarded from this function's contract.
    unsafe {
        spectrum_out("ocean_spectrum_wind_direction", spectrum, out, |s| {
            let w = s.wind();
            OceanDVec2 { x: w.x, z: w.y }
        })
    }
}

/// Stores the number of waves whose amplitude `params->max_steepness` clamped in `*out`.
///
/// Returns `OCEAN_STATUS_NULL_POINTER` / `_MISALIGNED_POINTER` for a bad pointer; `*out` is
/// written only on success.
///
/// # Safety
///
/// `out` must be writable.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn ocean_spectrum_clamped_count(
    spectrum: *const OceanSpectrum,
    out: *mut usize,
) -> OceanStatus {
    // SAFETY: forwarded from this function's contract.
    unsafe {
        spectrum_out("ocean_spectrum_clamped_count", spectrum, out, |s| {
            s.clamped()
        })
    }
}

/// Stores the sum of the amplitudes, metres, in `*out`: the largest height (and horizontal
/// displacement) the sum of the waves can reach, for bounds and culling margins.
///
/// Returns `OCEAN_STATUS_NULL_POINTER` / `_MISALIGNED_POINTER` for a bad pointer; `*out` is
/// written only on success.
///
/// # Safety
///
/// `out` must be writable.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn ocean_spectrum_max_amplitude(
    spectrum: *const OceanSpectrum,
    out: *mut f64,
) -> OceanStatus {
    // SAFETY: forwarded from this function's contract.
    unsafe {
        spectrum_out("ocean_spectrum_max_amplitude", spectrum, out, |s| {
            s.max_amplitude()
        })
    }
}

/// Stores the steepness sum, sum of k*A (dimensionless), in `*out`: below 1 the surface cannot
/// fold over itself, whatever the phases.
///
/// Returns `OCEAN_STATUS_NULL_POINTER` / `_MISALIGNED_POINTER` for a bad pointer; `*out` is
/// written only on success.
///
/// # Safety
///
/// `out` must be writable.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn ocean_spectrum_steepness_sum(
    spectrum: *const OceanSpectrum,
    out: *mut f64,
) -> OceanStatus {
    // SAFETY: forwarded from this function's contract.
    unsafe {
        spectrum_out("ocean_spectrum_steepness_sum", spectrum, out, |s| {
            s.steepness_sum()
        })
    }
}

/// Stores the mean height of the surface, metres (<= 0), in `*out`: a trochoid's mean height
/// over x is -k A^2 / 2 (its crests are sharper than its troughs), so the sea's mean level sits
/// sum(k A^2 / 2) below y = 0.
///
/// Returns `OCEAN_STATUS_NULL_POINTER` / `_MISALIGNED_POINTER` for a bad pointer; `*out` is
/// written only on success.
///
/// # Safety
///
/// `out` must be writable.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn ocean_spectrum_mean_height_shift(
    spectrum: *const OceanSpectrum,
    out: *mut f64,
) -> OceanStatus {
    // SAFETY: forwarded from this function's contract.
    unsafe {
        spectrum_out("ocean_spectrum_mean_height_shift", spectrum, out, |s| {
            s.mean_height_shift()
        })
    }
}

/// Stores the variance of the height about its mean, m^2, in `*out`:
/// sum(A^2 / 2 - (k A^2 / 2)^2) over the (independent) waves.
///
/// Returns `OCEAN_STATUS_NULL_POINTER` / `_MISALIGNED_POINTER` for a bad pointer; `*out` is
/// written only on success.
///
/// # Safety
///
/// `out` must be writable.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn ocean_spectrum_height_variance(
    spectrum: *const OceanSpectrum,
    out: *mut f64,
) -> OceanStatus {
    // SAFETY: forwarded from this function's contract.
    unsafe {
        spectrum_out("ocean_spectrum_height_variance", spectrum, out, |s| {
            s.height_variance()
        })
    }
}

/// Stores the slope variance of all the waves (Eq. 4 with w_r = 1) in `*out`: each wave of
/// steepness kA adds 1 - sqrt(1 - k^2 A^2) (Appendix A), shared between the axes as
/// cos^2 and sin^2 of its angle to the wind.
///
/// Returns `OCEAN_STATUS_NULL_POINTER` / `_MISALIGNED_POINTER` for a bad pointer; `*out` is
/// written only on success.
///
/// # Safety
///
/// `out` must be writable.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn ocean_spectrum_total_slope_variance(
    spectrum: *const OceanSpectrum,
    out: *mut OceanSlopeVariance,
) -> OceanStatus {
    // SAFETY: forwarded from this function's contract.
    unsafe {
        spectrum_out("ocean_spectrum_total_slope_variance", spectrum, out, |s| {
            OceanSlopeVariance::from_core(s.slope_variance())
        })
    }
}

/// Stores the slope variance of the waves a pixel does not resolve (Eq. 4) in `*out`.
///
/// Eq. 4 summed over every wave: a wave of wavenumber k, amplitude A and angle theta to the
/// wind adds (cos^2 theta, sin^2 theta) (1 - sqrt(1 - k^2 w_r^2 A^2)): the weight
/// w_r = 1 - w(n_min, n_max, lambda / l) scales the wave's amplitude inside the square root,
/// not its variance. l = `pixel_footprint` (metres, the pixel's size on the sea, from
/// `ocean_pixel_footprint`) and w(a, b, x) = 3 t^2 - 2 t^3, t = clamp((x - a)/(b - a), 0, 1):
/// waves shorter than n_min pixels are wholly in the BRDF, waves longer than n_max pixels
/// wholly in the normals. A footprint of 0 resolves every wave: the result is exactly (0, 0)
/// (each term is summed, not the total minus the resolved part, which leaves rounding). The
/// paper's thresholds are `OCEAN_FILTER_N_MIN` and `OCEAN_FILTER_N_MAX`.
///
/// Returns `OCEAN_STATUS_NULL_POINTER` / `_MISALIGNED_POINTER` for a bad pointer,
/// `OCEAN_STATUS_NON_FINITE` for a NaN or infinite argument, `OCEAN_STATUS_INVALID_ARGUMENT`
/// unless 0 < n_min < n_max <= 1e6 and `pixel_footprint` >= 0. `*out` is written only on
/// success.
///
/// # Safety
///
/// `out` must be writable.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn ocean_spectrum_slope_variance(
    spectrum: *const OceanSpectrum,
    n_min: f64,
    n_max: f64,
    pixel_footprint: f64,
    out: *mut OceanSlopeVariance,
) -> OceanStatus {
    guard("ocean_spectrum_slope_variance", || {
        let s = borrow(spectrum, "spectrum")?;
        check_ptr(out.cast_const(), "out")?;
        check_finite(
            "",
            &[
                ("n_min", n_min),
                ("n_max", n_max),
                ("pixel_footprint", pixel_footprint),
            ],
        )?;
        let filter = Filter::new(n_min, n_max)?;
        if pixel_footprint < 0.0 {
            return Err(Error::new(
                OceanStatus::InvalidArgument,
                format!(
                    "pixel_footprint must be >= 0 metres, got {}",
                    Num(pixel_footprint)
                ),
            ));
        }
        let v = s
            .spectrum
            .variance()
            .unresolved_direct(&filter, pixel_footprint);
        // SAFETY: forwarded from this function's contract.
        unsafe { write_out(out, "out", OceanSlopeVariance::from_core(v)) }
    })
}

/// The largest `max_distance` of `ocean_pixel_footprint`, metres: beyond the Moon's orbit,
/// and far enough below `DBL_MAX` that the footprint (a length between two hits this far
/// away) cannot overflow; at 1e154 m it did.
const MAX_FOOTPRINT_DISTANCE: f64 = 1e12;

/// Stores the footprint of a pixel on the sea at rest (y = 0), metres, in `*out`: the `l` of
/// Eq. 3 and 4 (pass it to `ocean_spectrum_slope_variance`).
///
/// The pixel at (`px`, `py`) (pixel units of a `width` x `height` viewport, origin at the
/// top-left corner, y down, pixel centres at half-integers: the centre of the top-left pixel is
/// (0.5, 0.5)) projects on the sea as an ellipse elongated towards the viewer; the footprint is
/// its longer axis: the larger of the distances between the sea hits of the rays through the
/// pixel's opposite edge midpoints, (px +- 0.5, py) and (px, py +- 0.5). Rays that go up, run
/// along the horizon or would meet the sea beyond `max_distance` metres (measured along the
/// ray from the near plane) are stopped there and projected onto the sea, so pixels at and
/// above the horizon get a large but finite footprint.
///
/// Returns `OCEAN_STATUS_NULL_POINTER` / `_MISALIGNED_POINTER` for a bad pointer,
/// `OCEAN_STATUS_EMPTY` if `width` or `height` is 0, `OCEAN_STATUS_NON_FINITE` for a NaN or
/// infinite argument or camera member (the message names it), `OCEAN_STATUS_INVALID_ARGUMENT`
/// for a camera out of its documented ranges (see `OceanCamera`), `max_distance` outside
/// (0, 1e12], or a
/// pixel whose rays do not start above the sea (the camera at or below y = 0). `*out` is
/// written only on success.
///
/// # Safety
///
/// `camera` must point to a readable `OceanCamera` and `out` be writable.
#[unsafe(no_mangle)]
#[allow(clippy::too_many_arguments)]
pub unsafe extern "C" fn ocean_pixel_footprint(
    camera: *const OceanCamera,
    width: u32,
    height: u32,
    px: f64,
    py: f64,
    max_distance: f64,
    out: *mut f64,
) -> OceanStatus {
    guard("ocean_pixel_footprint", || {
        check_ptr(camera, "camera")?;
        check_ptr(out.cast_const(), "out")?;
        if width == 0 || height == 0 {
            return Err(Error::new(
                OceanStatus::Empty,
                format!("the viewport is {width} x {height} pixels: both sizes must be >= 1"),
            ));
        }
        check_finite(
            "",
            &[("px", px), ("py", py), ("max_distance", max_distance)],
        )?;
        if !(max_distance > 0.0 && max_distance <= MAX_FOOTPRINT_DISTANCE) {
            return Err(Error::new(
                OceanStatus::InvalidArgument,
                format!(
                    "max_distance must be in (0, {}] metres, got {}",
                    Num(MAX_FOOTPRINT_DISTANCE),
                    Num(max_distance)
                ),
            ));
        }
        // SAFETY: forwarded from this function's contract.
        let cam = unsafe { read_camera(camera) }?;
        let l = pixel_footprint(
            &cam,
            f64::from(width),
            f64::from(height),
            DVec2::new(px, py),
            max_distance,
        )
        .ok_or_else(|| {
            Error::new(
                OceanStatus::InvalidArgument,
                format!(
                    "the rays of pixel ({px}, {py}) do not start above the sea (y > 0): the \
                     camera is at or below the sea, or its rays are undefined there"
                ),
            )
        })?;
        // SAFETY: forwarded from this function's contract.
        unsafe { write_out(out, "out", l) }
    })
}

crate::boundary::chain::extensible!(OceanSpectrumParams);

crate::boundary::handle::handles!(OceanSpectrum);

#[cfg(test)]
mod tests {
    use super::*;
    use core::f64::consts::TAU;

    #[test]
    fn filter_constants_are_the_papers() {
        assert_eq!(OCEAN_FILTER_N_MIN, Filter::PAPER.n_min());
        assert_eq!(OCEAN_FILTER_N_MAX, Filter::PAPER.n_max());
    }

    use crate::status::last_error;

    fn create(p: &OceanSpectrumParams) -> (OceanStatus, *mut OceanSpectrum) {
        let mut s = core::ptr::null_mut();
        // SAFETY: valid pointers.
        let st = unsafe { ocean_spectrum_create(p, &mut s) };
        (st, s)
    }

    fn defaults() -> OceanSpectrumParams {
        let mut p = OceanSpectrumParams::default();
        // SAFETY: `p` is writable.
        let st = unsafe { ocean_spectrum_params_default(&mut p) };
        assert_eq!(st, OceanStatus::Ok);
        p
    }

    #[test]
    fn waves_and_statistics_are_the_crates() {
        let p = OceanSpectrumParams {
            seed: 7,
            ..defaults()
        };
        let (st, s) = create(&p);
        assert_eq!(st, OceanStatus::Ok, "{}", last_error());
        let core = Spectrum::new(SpectrumParams {
            seed: 7,
            ..SpectrumParams::default()
        })
        .unwrap();
        let mut n = 0usize;
        // SAFETY: live handle, writable outputs of the right sizes.
        unsafe {
            assert_eq!(ocean_spectrum_wave_count(s, &mut n), OceanStatus::Ok);
            assert_eq!(n, 60);
            let mut waves = vec![OceanWaveDesc::default(); n];
            let st = ocean_spectrum_waves(s, waves.as_mut_ptr(), n);
            assert_eq!(st, OceanStatus::Ok, "{}", last_error());
            for (w, c) in waves.iter().zip(core.waves()) {
                assert_eq!(*w, wave_desc_to(c));
                assert!(w.depth == f64::INFINITY);
                assert!(TAU / w.wavelength * w.amplitude <= 0.5 + 1e-15);
            }
            let mut v = OceanSlopeVariance::default();
            let st = ocean_spectrum_slope_variance(s, 1.0, 2.5, 0.3, &mut v);
            assert_eq!(st, OceanStatus::Ok, "{}", last_error());
            let want = core.variance().unresolved_direct(&Filter::PAPER, 0.3);
            assert_eq!((v.sigma_x2, v.sigma_y2), (want.x, want.y));
            // A footprint of 0 resolves every wave: nothing is left, exactly (the total minus
            // the resolved part left 2.1e-18 here).
            let st = ocean_spectrum_slope_variance(s, 1.0, 2.5, 0.0, &mut v);
            assert_eq!(st, OceanStatus::Ok, "{}", last_error());
            assert_eq!((v.sigma_x2, v.sigma_y2), (0.0, 0.0));
            let mut m = 0.0;
            assert_eq!(ocean_spectrum_mean_height_shift(s, &mut m), OceanStatus::Ok);
            assert_eq!(m, core.mean_height_shift());
            ocean_spectrum_destroy(s);
        }
    }

    #[test]
    fn bad_parameters_are_refused_and_out_is_untouched() {
        for (p, status, needle) in [
            (
                OceanSpectrumParams {
                    wave_count: 0,
                    ..defaults()
                },
                OceanStatus::Empty,
                "wave_count",
            ),
            (
                OceanSpectrumParams {
                    wind_speed: f64::NAN,
                    ..defaults()
                },
                OceanStatus::NonFinite,
                "wind_speed",
            ),
            (
                OceanSpectrumParams {
                    wind_direction_x: 0.0,
                    ..defaults()
                },
                OceanStatus::InvalidArgument,
                "wind direction",
            ),
            (
                OceanSpectrumParams {
                    max_steepness: 1.5,
                    ..defaults()
                },
                OceanStatus::InvalidArgument,
                "max steepness",
            ),
        ] {
            let mut s = core::ptr::dangling_mut::<OceanSpectrum>();
            // SAFETY: valid pointers.
            let st = unsafe { ocean_spectrum_create(&p, &mut s) };
            assert_eq!(st, status, "{}", last_error());
            assert!(last_error().contains(needle), "{}", last_error());
            assert_eq!(s, core::ptr::dangling_mut::<OceanSpectrum>());
        }
    }

    #[test]
    fn a_camera_looking_straight_down_has_the_footprint_of_its_frustum() {
        // Perspective, eye at 10 m looking down: at the centre a pixel spans
        // 2 h tan(fov/2) / height metres.
        let view = ocean_core::camera::look_at(
            glam::DVec3::new(3.0, 10.0, 4.0),
            glam::DVec3::new(3.0, 0.0, 4.0),
            glam::DVec3::Z,
        )
        .unwrap();
        let cam = OceanCamera::from_camera(
            &ocean_core::Camera::new(
                view,
                ocean_core::Projection::Perspective {
                    fov_y: 1.0,
                    aspect: 2.0,
                    near: 0.1,
                    far: ocean_core::Far::Infinite,
                },
                ocean_core::camera::DepthConvention::NEG_ONE_TO_ONE,
            )
            .unwrap(),
        );
        let mut l = 0.0;
        // SAFETY: valid pointers.
        let st = unsafe { ocean_pixel_footprint(&cam, 200, 100, 100.0, 50.0, 1e4, &mut l) };
        assert_eq!(st, OceanStatus::Ok, "{}", last_error());
        let want = 2.0 * 10.0 * (0.5f64).tan() / 100.0;
        assert!((l - want).abs() < 1e-9 * want, "{l} vs {want}");
        // A pixel above the horizon stops at max_distance: at 5e254 m its footprint
        // overflowed to infinity behind success; the distance is now bounded.
        for far in [5.06e254, 1.0000001e12] {
            let mut l = -1.0;
            // SAFETY: valid pointers.
            let st = unsafe { ocean_pixel_footprint(&cam, 200, 100, 100.0, 5.0, far, &mut l) };
            assert_eq!(st, OceanStatus::InvalidArgument, "{far}");
            assert!(last_error().contains("max_distance"), "{}", last_error());
            assert_eq!(l, -1.0);
        }
        let mut l = -1.0;
        // SAFETY: valid pointers.
        let st = unsafe { ocean_pixel_footprint(&cam, 200, 100, 100.0, 5.0, 1e12, &mut l) };
        assert_eq!(st, OceanStatus::Ok, "{}", last_error());
        assert!(l.is_finite() && l > 0.0, "{l}");
    }
}
