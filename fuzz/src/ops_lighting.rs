//! Operations on lightings, sky maps and the sea colour, and the free BRDF functions
//! (ocean-ffi/src/lighting.rs, ocean-ffi/src/lighting_brdf.rs).

use std::ptr::null_mut;

use ocean::{
    OceanDVec2, OceanDVec3, OceanIrradiance, OceanRgb, OceanSeaColorInput, OceanSeaLight,
    OceanSeaParams, OceanSkyParams, ocean_effective_fresnel_fit, ocean_effective_fresnel_integral,
    ocean_effective_fresnel_table, ocean_lighting_below_horizon_radiance, ocean_lighting_create,
    ocean_lighting_environment_radiance, ocean_lighting_irradiance, ocean_lighting_sea_radiance,
    ocean_lighting_sky_irradiance, ocean_lighting_sky_map_create, ocean_lighting_sun_radiance,
    ocean_lighting_sun_solid_angle, ocean_linear_to_srgb, ocean_ross_brdf, ocean_schlick,
    ocean_sea_color, ocean_sea_color_batch, ocean_sea_params_default, ocean_sky_map_copy_level,
    ocean_sky_map_level_count, ocean_sky_map_level_info, ocean_sky_params_default,
    ocean_sun_radiance, ocean_tone_map,
};

use crate::call::{query, tweak};
use crate::check;
use crate::input::Input;
use crate::live::{Costly, Kind, Live, pick_or_null};

/// A direction: a plausible one (mostly upwards, unnormalised) with fuzzed components.
pub fn dvec3(inp: &mut Input) -> OceanDVec3 {
    let mut v = OceanDVec3 {
        x: 0.3,
        y: 0.8,
        z: -0.5,
    };
    for c in [&mut v.x, &mut v.y, &mut v.z] {
        if inp.u8() % 2 == 1 {
            *c = inp.f64();
        }
    }
    v
}

fn rgb(inp: &mut Input, v: &mut OceanRgb) {
    for c in [&mut v.r, &mut v.g, &mut v.b] {
        tweak(inp, c);
    }
}

/// The default sky and sea with fields fuzzed.
fn params(inp: &mut Input) -> (OceanSkyParams, OceanSeaParams) {
    let mut sky = OceanSkyParams::default();
    let mut sea = OceanSeaParams::default();
    // SAFETY: both outputs are locals.
    unsafe {
        check::status(
            "ocean_sky_params_default",
            &(),
            ocean_sky_params_default(&mut sky),
        );
        check::status(
            "ocean_sea_params_default",
            &(),
            ocean_sea_params_default(&mut sea),
        );
    }
    if inp.bool() {
        sky.sun_direction = dvec3(inp);
    }
    rgb(inp, &mut sky.sun_irradiance);
    rgb(inp, &mut sky.zenith_radiance);
    for c in [
        &mut sky.cie.a,
        &mut sky.cie.b,
        &mut sky.cie.c,
        &mut sky.cie.d,
        &mut sky.cie.e,
        &mut sky.sun_angular_radius,
    ] {
        tweak(inp, c);
    }
    rgb(inp, &mut sea.albedo);
    tweak(inp, &mut sea.fresnel_r);
    (sky, sea)
}

/// The sky and sea `l` was made of, if it is a live lighting.
pub fn lighting_args(
    live: &Live,
    l: *mut ocean::OceanLighting,
) -> Option<(OceanSkyParams, OceanSeaParams)> {
    live.lighting_args
        .iter()
        .find(|(h, _)| *h == l)
        .map(|&(_, a)| a)
}

/// `ocean_lighting_create` with fuzzed sky and sea (either may be NULL).
pub fn create(live: &mut Live, inp: &mut Input) {
    let args = params(inp);
    let (null_sky, null_sea) = (inp.u8() % 32 == 31, inp.u8() % 32 == 31);
    let sky: *const OceanSkyParams = if null_sky { std::ptr::null() } else { &args.0 };
    let sea: *const OceanSeaParams = if null_sea { std::ptr::null() } else { &args.1 };
    if !live.afford(Costly::Lighting) {
        return;
    }
    let mut out = null_mut();
    // SAFETY: `sky` and `sea` are NULL or point to `args`; `out` is a local.
    let st = unsafe { ocean_lighting_create(sky, sea, &mut out) };
    if check::status("ocean_lighting_create", &args, st) {
        Live::push(&mut live.lightings, &mut live.dead, Kind::Lighting, out);
        live.lighting_args.retain(|(h, _)| *h != out);
        live.lighting_args.push((out, args));
    }
}

/// Every query of a lighting, the environment radiance in a fuzzed direction.
pub fn queries(live: &mut Live, inp: &mut Input) {
    let l = pick_or_null(inp, &live.lightings);
    let dir = dvec3(inp);
    // What `l` was made of, reported with its outputs.
    let made_of = lighting_args(live, l);
    // SAFETY: `l` is live or NULL; every output is a local.
    unsafe {
        query::<OceanRgb>("ocean_lighting_sky_irradiance", &made_of, |o| {
            ocean_lighting_sky_irradiance(l, o)
        });
        // One time in four: the irradiance is an integration over the sky, costly for a
        // fuzz execution and independent of anything but the lighting.
        if inp.u8() % 4 == 3 {
            query::<OceanIrradiance>("ocean_lighting_irradiance", &made_of, |o| {
                ocean_lighting_irradiance(l, o)
            });
        }
        query::<OceanRgb>("ocean_lighting_sea_radiance", &made_of, |o| {
            ocean_lighting_sea_radiance(l, o)
        });
        query::<OceanRgb>("ocean_lighting_below_horizon_radiance", &made_of, |o| {
            ocean_lighting_below_horizon_radiance(l, o)
        });
        query::<OceanRgb>("ocean_lighting_sun_radiance", &made_of, |o| {
            ocean_lighting_sun_radiance(l, o)
        });
        query::<f64>("ocean_lighting_sun_solid_angle", &made_of, |o| {
            ocean_lighting_sun_solid_angle(l, o)
        });
        query::<OceanRgb>(
            "ocean_lighting_environment_radiance",
            &(made_of, dir),
            |o| ocean_lighting_environment_radiance(l, dir, o),
        );
    }
}

/// `ocean_lighting_sky_map_create` of a small size (or any size that must be refused).
pub fn sky_map_create(live: &mut Live, inp: &mut Input) {
    let l = pick_or_null(inp, &live.lightings);
    let size = match inp.u8() % 8 {
        6 => inp.u32(),
        7 => inp.u32() % 64,
        _ => 4 << inp.upto(3),
    };
    // Sizes above 32 cost too much per execution; the range check is what matters there.
    let size = if (33..=4096).contains(&size) {
        32
    } else {
        size
    };
    if !live.afford(Costly::SkyMap) {
        return;
    }
    let mut out = null_mut();
    // SAFETY: `l` is live or NULL; `out` is a local.
    let st = unsafe { ocean_lighting_sky_map_create(l, size, &mut out) };
    let made_of = lighting_args(live, l);
    if check::status("ocean_lighting_sky_map_create", &(made_of, size), st) {
        Live::push(&mut live.sky_maps, &mut live.dead, Kind::SkyMap, out);
        live.sky_map_args.retain(|(h, _)| *h != out);
        live.sky_map_args.push((out, made_of));
    }
}

/// The levels of a sky map: count, sizes, and a copy of one into a buffer of the reported size
/// (or a shorter length).
pub fn sky_map_levels(live: &mut Live, inp: &mut Input) {
    let m = pick_or_null(inp, &live.sky_maps);
    let made_of = live
        .sky_map_args
        .iter()
        .find(|(h, _)| *h == m)
        .and_then(|&(_, a)| a);
    // SAFETY: `m` is live or NULL; outputs are locals; `rgba` holds `len` floats at least.
    unsafe {
        let count = query::<u32>("ocean_sky_map_level_count", &(), |o| {
            ocean_sky_map_level_count(m, o)
        });
        let level = match count {
            Some(c) if inp.u8() % 8 != 7 => inp.upto(c as usize) as u32,
            _ => inp.u32(),
        };
        let size = query::<u32>("ocean_sky_map_level_info", &level, |o| {
            ocean_sky_map_level_info(m, level, o)
        });
        let cap = size.map_or(inp.upto(64), |s| (s as usize).pow(2) * 4);
        let len = inp.len_within(cap);
        let mut rgba = vec![0f32; cap];
        let st = ocean_sky_map_copy_level(m, level, rgba.as_mut_ptr(), len);
        check::outputs(
            "ocean_sky_map_copy_level",
            &(made_of, level, len),
            st,
            &rgba,
        );
    }
}

fn sea_input(inp: &mut Input) -> OceanSeaColorInput {
    let mut i = OceanSeaColorInput {
        v: dvec3(inp),
        n: OceanDVec3 {
            x: 0.1,
            y: 1.0,
            z: 0.05,
        },
        wind: OceanDVec2 { x: 1.0, z: 0.0 },
        sigma_x2: 0.004,
        sigma_y2: 0.003,
    };
    for c in [
        &mut i.n.x,
        &mut i.n.y,
        &mut i.n.z,
        &mut i.wind.x,
        &mut i.wind.z,
        &mut i.sigma_x2,
        &mut i.sigma_y2,
    ] {
        tweak(inp, c);
    }
    i
}

/// `ocean_sea_color` and `ocean_sea_color_batch` with fuzzed views, normals and roughness.
pub fn sea_color(live: &mut Live, inp: &mut Input) {
    let l = pick_or_null(inp, &live.lightings);
    let m = pick_or_null(inp, &live.sky_maps);
    let one = sea_input(inp);
    let made_of = lighting_args(live, l);
    // SAFETY: `l` and `m` are live or NULL; outputs are locals; `batch` and `out` hold `k`
    // >= `n` elements.
    unsafe {
        query::<OceanSeaLight>("ocean_sea_color", &(made_of, one), |o| {
            ocean_sea_color(l, m, one.v, one.n, one.wind, one.sigma_x2, one.sigma_y2, o)
        });
        let k = (1 + inp.upto(4)) % 5;
        let batch: Vec<OceanSeaColorInput> = (0..k).map(|_| sea_input(inp)).collect();
        let n = inp.len_within(k);
        let mut out = vec![OceanSeaLight::default(); k];
        let st = ocean_sea_color_batch(l, m, batch.as_ptr(), n, out.as_mut_ptr());
        check::outputs("ocean_sea_color_batch", &(made_of, batch, n), st, &out);
    }
}

/// The free BRDF functions with fuzzed directions and parameters.
pub fn brdf(inp: &mut Input) {
    let (v, l) = (dvec3(inp), dvec3(inp));
    let (sx, sy, r) = (inp.f64_near(0.004), inp.f64_near(0.003), inp.f64_near(0.02));
    let (l_sun, omega) = (inp.f64_near(100.0), inp.f64_near(6.8e-5));
    let (cos, sigma) = (inp.f64_near(0.5), inp.f64_near(0.1));
    let radiance = OceanRgb {
        r: inp.f64_near(0.1),
        g: inp.f64_near(0.1),
        b: inp.f64_near(0.1),
    };
    let exposure = inp.f64_near(8.0);
    let linear = inp.f64_near(0.5);
    // SAFETY: every output is a local.
    unsafe {
        query::<f64>("ocean_ross_brdf", &(v, l, sx, sy, r), |o| {
            ocean_ross_brdf(v, l, sx, sy, r, o)
        });
        query::<f64>(
            "ocean_sun_radiance",
            &(v, l, sx, sy, l_sun, omega, r),
            |o| ocean_sun_radiance(v, l, sx, sy, l_sun, omega, r, o),
        );
        query::<f64>("ocean_schlick", &(cos, r), |o| ocean_schlick(cos, r, o));
        query::<f64>("ocean_effective_fresnel_fit", &(cos, sigma, r), |o| {
            ocean_effective_fresnel_fit(cos, sigma, r, o)
        });
        query::<f64>("ocean_effective_fresnel_table", &(cos, sigma, r), |o| {
            ocean_effective_fresnel_table(cos, sigma, r, o)
        });
        query::<f64>("ocean_effective_fresnel_integral", &(v, sx, sy, r), |o| {
            ocean_effective_fresnel_integral(v, sx, sy, r, o)
        });
        query::<OceanRgb>("ocean_tone_map", &(radiance, exposure), |o| {
            ocean_tone_map(radiance, exposure, o)
        });
        query::<f64>("ocean_linear_to_srgb", &linear, |o| {
            ocean_linear_to_srgb(linear, o)
        });
    }
}

/// Destroys one lighting or one sky map.
pub fn destroy(live: &mut Live, inp: &mut Input) {
    if inp.bool() {
        if !live.lightings.is_empty() {
            let i = inp.upto(live.lightings.len() - 1);
            Live::kill(&mut live.lightings, &mut live.dead, Kind::Lighting, i);
        }
    } else if !live.sky_maps.is_empty() {
        let i = inp.upto(live.sky_maps.len() - 1);
        Live::kill(&mut live.sky_maps, &mut live.dead, Kind::SkyMap, i);
    }
}
