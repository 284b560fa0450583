//! Operations on the CPU scalable ambient obscurance (ocean-ffi/src/sao.rs,
//! ocean-ffi/src/camera.rs). The GPU variant (`ocean_sao_gpu_*`) is left out: no GPU.

use std::ptr::null_mut;

use std::mem::offset_of;

use ocean::{
    OceanSaoBlurParams, OceanSaoInfo, OceanSaoParams, ocean_sao_create, ocean_sao_describe,
    ocean_sao_params_default, ocean_sao_run, ocean_sao_view_z,
};

use crate::call::{camera, query, tweak_flag, tweak_u32, tweak32};
use crate::check;
use crate::cmem::CMem;
use crate::input::Input;
use crate::live::{Costly, Kind, Live, pick_or_null};

/// Image side at most: the passes cost samples × pixels.
const MAX_SIDE: u32 = 16;
/// Samples per pixel at most (more are valid but slow, not different).
const MAX_SAMPLES: u32 = 32;

/// What the depth buffer holds: window or NDC depth, or any value.
fn depth_source(inp: &mut Input) -> u32 {
    let mut v = inp.u32() % 2;
    tweak_u32(inp, &mut v);
    v
}

/// The default parameters with fields fuzzed.
fn params(inp: &mut Input) -> CMem<OceanSaoParams> {
    let mut p = OceanSaoParams::default();
    // SAFETY: `p` is a local.
    let st = unsafe { ocean_sao_params_default(&mut p) };
    check::status("ocean_sao_params_default", &(), st);
    for v in [
        &mut p.radius,
        &mut p.spiral_turns,
        &mut p.falloff_beta,
        &mut p.falloff_intensity,
        &mut p.alchemy_sigma,
        &mut p.alchemy_beta,
        &mut p.alchemy_k,
        &mut p.epsilon,
        &mut p.quad_depth_threshold,
        &mut p.normal_max_incidence,
        &mut p.z_min,
        &mut p.blur.depth_scale,
        &mut p.blur.sigma,
        &mut p.blur.world_extent,
    ] {
        tweak32(inp, v);
    }
    for v in [
        &mut p.samples,
        &mut p.mip_switch_log2,
        &mut p.max_mip,
        &mut p.blur.taps,
        &mut p.blur.stride,
    ] {
        tweak_u32(inp, v);
    }
    p.samples = p.samples.min(MAX_SAMPLES);
    p.blur.taps = p.blur.taps.min(2 * MAX_SIDE + 1);
    tweak_flag(inp, &mut p.quad_filter);
    tweak_flag(inp, &mut p.normal_rejection);
    let mut p = CMem::new(p);
    for at in [
        offset_of!(OceanSaoParams, mip_filter),
        offset_of!(OceanSaoParams, estimator),
        offset_of!(OceanSaoParams, normals),
        offset_of!(OceanSaoParams, blur) + offset_of!(OceanSaoBlurParams, weight),
    ] {
        p.tweak_u32(inp, at);
    }
    p
}

/// `ocean_sao_create` for a small image.
pub fn create(live: &mut Live, inp: &mut Input) {
    let (w, h) = (
        inp.u32().wrapping_add(8) % (MAX_SIDE + 1),
        inp.u32().wrapping_add(8) % (MAX_SIDE + 1),
    );
    let guard = if inp.u8() % 8 == 7 {
        inp.u32()
    } else {
        inp.u32() % 4
    };
    let args = (w, h, guard, camera(inp), depth_source(inp), params(inp));
    if !live.afford(Costly::Sao) {
        return;
    }
    let mut out = null_mut();
    // SAFETY: the camera, parameters and `out` are locals.
    let st = unsafe {
        ocean_sao_create(
            w,
            h,
            guard,
            args.3.as_ptr(),
            args.4,
            args.5.as_ptr(),
            &mut out,
        )
    };
    if check::status("ocean_sao_create", &args, st) {
        Live::push(&mut live.saos, &mut live.dead, Kind::Sao, out);
    }
}

/// `ocean_sao_describe`, then `ocean_sao_run` or `_view_z` on a fuzzed depth buffer of the
/// described size (or shorter lengths).
pub fn run(live: &mut Live, inp: &mut Input) {
    let s = pick_or_null(inp, &live.saos);
    // SAFETY: `s` is live or NULL; the output is a local.
    let info =
        unsafe { query::<OceanSaoInfo>("ocean_sao_describe", &(), |o| ocean_sao_describe(s, o)) };
    let (input, output) = info.map_or((inp.upto(4), inp.upto(4)), |i| {
        (
            (i.input_width * i.input_height) as usize,
            (i.output_width * i.output_height) as usize,
        )
    });
    let base = inp.f32_near(0.9).clamp(0.0, 1.0);
    let depth: Vec<f32> = (0..input)
        .map(|k| match inp.u8() % 8 {
            6 => inp.f32(),
            7 => 1.0,
            _ => base + (k % 5) as f32 * 1e-3,
        })
        .collect();
    let depth_len = inp.len_within(input);
    // SAFETY: `s` is live or NULL; `depth` holds `input` >= `depth_len` floats and the output
    // buffers their capacities >= their lengths.
    unsafe {
        if inp.bool() {
            let ao_len = inp.len_within(output);
            let mut ao = vec![0f32; output];
            let st = ocean_sao_run(s, depth.as_ptr(), depth_len, ao.as_mut_ptr(), ao_len);
            let args = (depth, depth_len, ao_len);
            if check::outputs("ocean_sao_run", &args, st, &ao) {
                assert!(
                    ao.iter().all(|a| (0.0..=1.0).contains(a)),
                    "ocean_sao_run wrote a visibility outside [0, 1]: {ao:?} for {args:?}"
                );
            }
        } else {
            let z_len = inp.len_within(input);
            let mut z = vec![0f32; input];
            let st = ocean_sao_view_z(s, depth.as_ptr(), depth_len, z.as_mut_ptr(), z_len);
            check::outputs("ocean_sao_view_z", &(depth, depth_len, z_len), st, &z);
        }
    }
}

/// Destroys one SAO set-up.
pub fn destroy(live: &mut Live, inp: &mut Input) {
    if !live.saos.is_empty() {
        let i = inp.upto(live.saos.len() - 1);
        Live::kill(&mut live.saos, &mut live.dead, Kind::Sao, i);
    }
}
