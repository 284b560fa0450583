//! Operations on spectra, the pixel footprint and the ocean draw data
//! (ocean-ffi/src/lighting_spectrum.rs, ocean-ffi/src/ocean_draw.rs).

use std::ptr::null_mut;

use ocean::{
    OCEAN_FRESNEL_TABLE_SIZE, OCEAN_SURFACE_UNIFORMS_SIZE, OceanDVec2, OceanSlopeVariance,
    OceanSpectrumParams, OceanSurfaceDrawParams, OceanWaterGridDesc, OceanWaveDesc,
    ocean_pixel_footprint, ocean_spectrum_clamped_count, ocean_spectrum_create,
    ocean_spectrum_height_variance, ocean_spectrum_max_amplitude, ocean_spectrum_mean_height_shift,
    ocean_spectrum_params_default, ocean_spectrum_slope_variance, ocean_spectrum_steepness_sum,
    ocean_spectrum_total_slope_variance, ocean_spectrum_wave_count, ocean_spectrum_waves,
    ocean_spectrum_wind_direction, ocean_surface_draw_params_default, ocean_surface_fresnel_texels,
    ocean_surface_uniforms, ocean_surface_wave_texels,
};

use crate::call::{camera, query, tweak, tweak_flag, tweak_u32};
use crate::check;
use crate::input::Input;
use crate::live::{Costly, Kind, Live, pick_or_null};

/// Waves per spectrum at most: the count is otherwise unbounded (include/ocean.h), and its
/// cost linear.
const MAX_WAVES: usize = 64;

/// `ocean_spectrum_create` with fuzzed parameters.
pub fn create(live: &mut Live, inp: &mut Input) {
    let mut p = OceanSpectrumParams::default();
    // SAFETY: `p` is a local.
    let st = unsafe { ocean_spectrum_params_default(&mut p) };
    check::status("ocean_spectrum_params_default", &(), st);
    for v in [
        &mut p.wind_speed,
        &mut p.wind_direction_x,
        &mut p.wind_direction_z,
        &mut p.min_wavelength,
        &mut p.max_wavelength,
        &mut p.max_steepness,
    ] {
        tweak(inp, v);
    }
    // Few waves mostly: each costs a tabulated spread sample (ocean-brdf/src/spectrum.rs),
    // and the default count would dominate the execution time.
    p.wave_count = match inp.u8() % 4 {
        3 => inp.upto(MAX_WAVES),
        _ => 1 + usize::from(inp.u8() % 8),
    };
    p.seed = if inp.bool() { inp.u64() } else { p.seed };
    if !live.afford(Costly::Spectrum) {
        return;
    }
    let mut out = null_mut();
    // SAFETY: `p` and `out` are locals.
    let st = unsafe { ocean_spectrum_create(&p, &mut out) };
    if check::status("ocean_spectrum_create", &p, st) {
        Live::push(&mut live.spectra, &mut live.dead, Kind::Spectrum, out);
    }
}

/// Every query of a spectrum; its waves into a buffer of the reported count (or a shorter
/// length); the slope variance with fuzzed filter bounds and footprint.
pub fn queries(live: &mut Live, inp: &mut Input) {
    let s = pick_or_null(inp, &live.spectra);
    let (n_min, n_max, footprint) = (inp.f64_near(1.0), inp.f64_near(2.5), inp.f64_near(0.1));
    // SAFETY: `s` is live or NULL; outputs are locals; `waves` holds `cap` >= `n` waves.
    unsafe {
        let count = query::<usize>("ocean_spectrum_wave_count", &(), |o| {
            ocean_spectrum_wave_count(s, o)
        });
        let cap = count.unwrap_or(inp.upto(4)).min(MAX_WAVES);
        let n = inp.len_within(cap);
        let mut waves = vec![OceanWaveDesc::default(); cap];
        let st = ocean_spectrum_waves(s, waves.as_mut_ptr(), n);
        check::outputs("ocean_spectrum_waves", &n, st, &waves[..n]);
        query::<OceanDVec2>("ocean_spectrum_wind_direction", &(), |o| {
            ocean_spectrum_wind_direction(s, o)
        });
        query::<usize>("ocean_spectrum_clamped_count", &(), |o| {
            ocean_spectrum_clamped_count(s, o)
        });
        query::<f64>("ocean_spectrum_max_amplitude", &(), |o| {
            ocean_spectrum_max_amplitude(s, o)
        });
        query::<f64>("ocean_spectrum_steepness_sum", &(), |o| {
            ocean_spectrum_steepness_sum(s, o)
        });
        query::<f64>("ocean_spectrum_mean_height_shift", &(), |o| {
            ocean_spectrum_mean_height_shift(s, o)
        });
        query::<f64>("ocean_spectrum_height_variance", &(), |o| {
            ocean_spectrum_height_variance(s, o)
        });
        query::<OceanSlopeVariance>("ocean_spectrum_total_slope_variance", &(), |o| {
            ocean_spectrum_total_slope_variance(s, o)
        });
        query::<OceanSlopeVariance>(
            "ocean_spectrum_slope_variance",
            &(n_min, n_max, footprint),
            |o| ocean_spectrum_slope_variance(s, n_min, n_max, footprint, o),
        );
    }
}

/// `ocean_pixel_footprint` of a fuzzed camera, viewport and pixel.
pub fn pixel_footprint(inp: &mut Input) {
    let cam = camera(inp);
    let (w, h) = (inp.u32(), inp.u32());
    let (px, py, max) = (inp.f64_near(100.0), inp.f64_near(100.0), inp.f64_near(1e3));
    let args = (cam, w, h, px, py, max);
    // SAFETY: the camera and the output are locals.
    unsafe {
        query::<f64>("ocean_pixel_footprint", &args, |o| {
            ocean_pixel_footprint(args.0.as_ptr(), w, h, px, py, max, o)
        });
    }
}

/// The ocean's draw data: uniforms (bytes, not checked for finiteness: they mix integers and
/// floats), wave texels and the Fresnel table.
pub fn draw_data(live: &mut Live, inp: &mut Input) {
    let cam = camera(inp);
    let s = pick_or_null(inp, &live.spectra);
    let l = pick_or_null(inp, &live.lightings);
    let mut params = OceanSurfaceDrawParams::default();
    // SAFETY: `params` is a local.
    let st = unsafe { ocean_surface_draw_params_default(&mut params) };
    check::status("ocean_surface_draw_params_default", &(), st);
    for v in [
        &mut params.n_min,
        &mut params.n_max,
        &mut params.cell_px,
        &mut params.margin,
        &mut params.max_distance,
        &mut params.exposure,
    ] {
        tweak(inp, v);
    }
    tweak_u32(inp, &mut params.sky_map_size);
    tweak_flag(inp, &mut params.srgb_encode);
    let mut mesh = OceanWaterGridDesc {
        origin_x: -50.0,
        origin_z: -50.0,
        spacing: 1.0,
        nx: 100,
        nz: 100,
    };
    for v in [&mut mesh.origin_x, &mut mesh.origin_z, &mut mesh.spacing] {
        tweak(inp, v);
    }
    if inp.u8() % 4 == 3 {
        mesh.nx = inp.upto(usize::from(u16::MAX));
        mesh.nz = if inp.bool() {
            usize::MAX
        } else {
            inp.upto(300)
        };
    }
    let null_mesh = inp.bool();
    let time = inp.f64_near(10.0);
    let (w, h) = (inp.u32(), inp.u32());
    let len = inp.len_within(OCEAN_SURFACE_UNIFORMS_SIZE);
    let mut bytes = vec![0u8; OCEAN_SURFACE_UNIFORMS_SIZE];
    let args = (cam, params, mesh, null_mesh, time, w, h, len);
    let mesh_ptr: *const OceanWaterGridDesc = if null_mesh { std::ptr::null() } else { &args.2 };
    // SAFETY: `s` and `l` are live or NULL; the camera, parameters and mesh are locals;
    // `bytes` holds `len` bytes at least.
    let st = unsafe {
        ocean_surface_uniforms(
            args.0.as_ptr(),
            s,
            l,
            &args.1,
            mesh_ptr,
            time,
            w,
            h,
            bytes.as_mut_ptr(),
            len,
        )
    };
    check::status("ocean_surface_uniforms", &args, st);

    // SAFETY: `s` is live or NULL; the output is a local.
    let count = unsafe {
        query::<usize>("ocean_spectrum_wave_count", &(), |o| {
            ocean_spectrum_wave_count(s, o)
        })
    };
    let cap = count.unwrap_or(inp.upto(4)).min(MAX_WAVES) * 12;
    let n = inp.len_within(cap);
    let mut texels = vec![0f32; cap];
    // SAFETY: `texels` holds `cap` >= `n` floats.
    let st = unsafe { ocean_surface_wave_texels(args.0.as_ptr(), s, time, texels.as_mut_ptr(), n) };
    check::outputs("ocean_surface_wave_texels", &(args.0, time, n), st, &texels);

    let table = OCEAN_FRESNEL_TABLE_SIZE.pow(2);
    let n = inp.len_within(table);
    let mut fresnel = vec![0f32; table];
    // SAFETY: `fresnel` holds `table` >= `n` floats.
    let st = unsafe { ocean_surface_fresnel_texels(fresnel.as_mut_ptr(), n) };
    check::outputs("ocean_surface_fresnel_texels", &n, st, &fresnel);
}

/// Destroys one spectrum.
pub fn destroy(live: &mut Live, inp: &mut Input) {
    if !live.spectra.is_empty() {
        let i = inp.upto(live.spectra.len() - 1);
        Live::kill(&mut live.spectra, &mut live.dead, Kind::Spectrum, i);
    }
}
