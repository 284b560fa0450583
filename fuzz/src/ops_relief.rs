//! Operations on relief maps, cone maps, their mips and tracers (ocean-ffi/src/relief*.rs).
//! Shared by `c_abi_sequence` and `cone_params`, which runs these alone.

use std::ffi::{c_int, c_void};
use std::mem::offset_of;
use std::ptr::null_mut;

use ocean::{
    OCEAN_RELIEF_UNIFORMS_SIZE, OceanReliefConeParams, OceanReliefHit, OceanReliefMethod,
    OceanReliefPoint, OceanReliefProgress, OceanReliefRay, OceanReliefScene,
    ocean_relief_cone_params_default, ocean_relief_cones_create, ocean_relief_cones_encode,
    ocean_relief_cones_quantize, ocean_relief_cones_size, ocean_relief_cones_texels,
    ocean_relief_generate_encoded, ocean_relief_generate_texels, ocean_relief_map_create_f32,
    ocean_relief_map_create_u8, ocean_relief_map_create_u16, ocean_relief_map_depths,
    ocean_relief_map_downsample, ocean_relief_map_size, ocean_relief_mip_atlas_origin,
    ocean_relief_mip_atlas_size, ocean_relief_mip_level, ocean_relief_mips_copy_level,
    ocean_relief_mips_create, ocean_relief_mips_level_count, ocean_relief_mips_level_size,
    ocean_relief_normals, ocean_relief_quad_cones_create, ocean_relief_quad_cones_size,
    ocean_relief_quad_cones_texels, ocean_relief_quad_generate_texels, ocean_relief_quad_shadow,
    ocean_relief_quad_trace, ocean_relief_ray_from_view, ocean_relief_scene_default,
    ocean_relief_shadow, ocean_relief_trace, ocean_relief_uniforms,
};

use crate::call::camera;
use crate::call::{query, tweak, tweak_flag, tweak32};
use crate::check;
use crate::cmem::{CMem, enum_below};
use crate::finite::half_is_finite;
use crate::input::Input;
use crate::live::{Costly, Kind, Live, pick_or_null};

/// Height map side at most: cone generation is quadratic in the texel count.
pub const MAX_SIDE: u32 = 32;
/// Rays or points per trace at most.
const MAX_RAYS: usize = 8;

/// Heights of a `w × h` map as the three input types: a smooth bump with fuzzed texels.
fn heights(inp: &mut Input, w: u32, h: u32) -> Vec<f32> {
    let n = (w * h) as usize;
    let bump = |k: usize| {
        let (x, y) = ((k % w as usize) as f32, (k / w as usize) as f32);
        let d = ((x - w as f32 / 2.0).powi(2) + (y - h as f32 / 2.0).powi(2)).sqrt();
        (1.0 - d / w as f32).clamp(0.0, 1.0)
    };
    let raw = inp.u8() % 4 == 3;
    (0..n)
        .map(|k| {
            if raw || inp.u8() % 8 == 7 {
                inp.f32()
            } else {
                bump(k)
            }
        })
        .collect()
}

/// A side: a power of two up to [`MAX_SIDE`] mostly, else any value up to it, or 0 or huge
/// (refused before anything is read).
fn side(inp: &mut Input) -> u32 {
    match inp.u8() % 8 {
        5 if inp.bool() => MAX_SIDE,
        6 => inp.u32() % (MAX_SIDE + 1),
        7 => [0, 1, 4097, u32::MAX][inp.upto(3)],
        // 2 to 16; 32 (four times the cost of 16 and sixteen times 8) from the case above.
        _ => 2 << inp.upto(3),
    }
}

/// One of the three `ocean_relief_map_create_*`, on a small map.
pub fn map_create(live: &mut Live, inp: &mut Input) {
    let w = side(inp);
    let h = if inp.u8() % 8 == 7 { side(inp) } else { w };
    // A side above MAX_SIDE has no buffer behind it: pass at most MAX_SIDE² texels, and the
    // library must refuse the dimensions (or the length) before reading.
    let (bw, bh) = (w.min(MAX_SIDE), h.min(MAX_SIDE));
    let values = heights(inp, bw, bh);
    let len = inp.len_within(values.len());
    let edge = if inp.u8() % 8 == 7 {
        inp.u32()
    } else {
        inp.u32() % 2
    };
    let mut out = null_mut();
    let args = (w, h, edge, len);
    // SAFETY: each buffer holds `values.len()` >= `len` elements; `out` is a local.
    let st = unsafe {
        match inp.u8() % 3 {
            0 => {
                let range = if inp.u8() % 8 == 7 {
                    inp.u32()
                } else {
                    inp.u32() % 2
                };
                let st =
                    ocean_relief_map_create_f32(values.as_ptr(), len, w, h, edge, range, &mut out);
                check::status("ocean_relief_map_create_f32", &(args, range, values), st)
            }
            1 => {
                let v: Vec<u8> = values.iter().map(|h| (h * 255.0) as u8).collect();
                let st = ocean_relief_map_create_u8(v.as_ptr(), len, w, h, edge, &mut out);
                check::status("ocean_relief_map_create_u8", &(args, v), st)
            }
            _ => {
                let v: Vec<u16> = values.iter().map(|h| (h * 65535.0) as u16).collect();
                let st = ocean_relief_map_create_u16(v.as_ptr(), len, w, h, edge, &mut out);
                check::status("ocean_relief_map_create_u16", &(args, v), st)
            }
        }
    };
    if st {
        Live::push(&mut live.maps, &mut live.dead, Kind::ReliefMap, out);
    }
}

/// A map's size, depths and normals, and its downsampled map.
pub fn map_queries(live: &mut Live, inp: &mut Input) {
    let m = pick_or_null(inp, &live.maps);
    // SAFETY: `m` is live or NULL; outputs are locals or buffers of `cap` >= `len` floats.
    unsafe {
        let n = query::<u32>("ocean_relief_map_size", &(), |o| {
            ocean_relief_map_size(m, o)
        });
        let n = n.map_or(inp.upto(4), |n| n as usize);
        let cap = n * n;
        let len = inp.len_within(cap);
        let mut depths = vec![0f32; cap];
        let st = ocean_relief_map_depths(m, depths.as_mut_ptr(), len);
        check::outputs("ocean_relief_map_depths", &len, st, &depths);
        let depth = inp.f32_near(0.1);
        let len = inp.len_within(3 * cap);
        let mut xyz = vec![0f32; 3 * cap];
        let st = ocean_relief_normals(m, depth, xyz.as_mut_ptr(), len);
        check::outputs("ocean_relief_normals", &(depth, len), st, &xyz);
        let mut down = null_mut();
        let st = ocean_relief_map_downsample(m, &mut down);
        if check::status("ocean_relief_map_downsample", &(), st) {
            Live::push(&mut live.maps, &mut live.dead, Kind::ReliefMap, down);
        }
    }
}

/// What the progress callback is told: calls left before it cancels (`u32::MAX`: never).
struct Progress {
    calls_left: u32,
    last_done: usize,
}

/// The progress callback: checks that progress only grows and stays within the total, and
/// cancels when its budget of calls runs out.
extern "C" fn progress(user: *mut c_void, done: usize, total: usize) -> c_int {
    // SAFETY: `user` is the `Progress` that `with_progress` passes with the callback, alive and
    // not otherwise borrowed for the duration of the generating call.
    let p = unsafe { &mut *user.cast::<Progress>() };
    assert!(
        done <= total && done >= p.last_done,
        "relief progress went from {} to {done} of {total}",
        p.last_done
    );
    p.last_done = done;
    if p.calls_left == 0 {
        return 1;
    }
    p.calls_left = p.calls_left.saturating_sub(1);
    0
}

/// Calls `f` with no callback, or with [`progress`] set to cancel after a fuzzed number of
/// calls (or never).
fn with_progress<R>(inp: &mut Input, f: impl FnOnce(OceanReliefProgress, *mut c_void) -> R) -> R {
    let mut p = Progress {
        calls_left: match inp.u8() % 4 {
            3 => u32::from(inp.u8() % 4),
            _ => u32::MAX,
        },
        last_done: 0,
    };
    if inp.bool() {
        f(None, null_mut())
    } else {
        f(Some(progress), (&mut p as *mut Progress).cast())
    }
}

/// The default cone parameters, fuzzed.
pub fn cone_params(inp: &mut Input) -> CMem<OceanReliefConeParams> {
    let mut p = OceanReliefConeParams::default();
    // SAFETY: `p` is a local.
    let st = unsafe { ocean_relief_cone_params_default(&mut p) };
    check::status("ocean_relief_cone_params_default", &(), st);
    if inp.bool() {
        p.kind = enum_below(inp, 2);
    }
    tweak32(inp, &mut p.max_ratio);
    let mut p = CMem::new(p);
    p.tweak_u32(inp, offset_of!(OceanReliefConeParams, kind));
    p
}

/// The side of a map (a query, 0 when it fails).
fn map_side(m: *const ocean::OceanReliefMap) -> usize {
    // SAFETY: `m` is live or NULL; the output is a local.
    unsafe {
        query::<u32>("ocean_relief_map_size", &(), |o| {
            ocean_relief_map_size(m, o)
        })
    }
    .map_or(0, |n| n as usize)
}

/// An encoding: one of the four mostly, else any value.
fn encoding(inp: &mut Input) -> u32 {
    if inp.u8() % 8 == 7 {
        inp.u32()
    } else {
        inp.u32() % 4
    }
}

/// Checks an encoded output of `len` elements of `encoding`'s type held in `buf`.
fn check_encoded(
    function: &str,
    args: &dyn crate::known::Args,
    st: ocean::OceanStatus,
    encoding: u32,
    buf: &[u32],
    len: usize,
) {
    let bytes: Vec<u8> = buf.iter().flat_map(|w| w.to_ne_bytes()).collect();
    let finite = match encoding {
        2 => bytes[..2 * len]
            .chunks_exact(2)
            .all(|b| half_is_finite(u16::from_ne_bytes([b[0], b[1]]))),
        3 => bytes[..4 * len]
            .chunks_exact(4)
            .all(|b| f32::from_ne_bytes([b[0], b[1], b[2], b[3]]).is_finite()),
        _ => true,
    };
    check::outputs(function, args, st, &[if finite { 0.0 } else { f32::NAN }]);
}

/// Cone maps of a map: a handle (plain or quad-directional), or texels or encoded channels
/// generated straight into a buffer.
pub fn cones_create(live: &mut Live, inp: &mut Input) {
    let m = pick_or_null(inp, &live.maps);
    let n = map_side(m);
    let params = cone_params(inp);
    if !live.afford(Costly::Cones) {
        return;
    }
    // SAFETY: `m` is live or NULL; `params` and `out` are locals; `user` is NULL or the
    // `Progress` of `with_progress`; each buffer holds `cap` >= `len` elements.
    unsafe {
        match inp.u8() % 5 {
            0 | 1 => {
                let mut out = null_mut();
                let st = with_progress(inp, |cb, user| {
                    ocean_relief_cones_create(m, params.as_ptr(), cb, user, &mut out)
                });
                if check::status("ocean_relief_cones_create", &params, st) {
                    Live::push(&mut live.cones, &mut live.dead, Kind::Cones, out);
                }
            }
            2 => {
                let mut out = null_mut();
                let st = with_progress(inp, |cb, user| {
                    ocean_relief_quad_cones_create(m, params.as_ptr(), cb, user, &mut out)
                });
                if check::status("ocean_relief_quad_cones_create", &params, st) {
                    Live::push(&mut live.quads, &mut live.dead, Kind::QuadCones, out);
                }
            }
            3 => {
                let quad = inp.bool();
                let cap = n * n * if quad { 16 } else { 4 };
                let len = inp.len_within(cap);
                let mut rgba = vec![0f32; cap];
                let st = with_progress(inp, |cb, user| {
                    if quad {
                        ocean_relief_quad_generate_texels(
                            m,
                            params.as_ptr(),
                            cb,
                            user,
                            rgba.as_mut_ptr(),
                            len,
                        )
                    } else {
                        ocean_relief_generate_texels(
                            m,
                            params.as_ptr(),
                            cb,
                            user,
                            rgba.as_mut_ptr(),
                            len,
                        )
                    }
                });
                let name = if quad {
                    "ocean_relief_quad_generate_texels"
                } else {
                    "ocean_relief_generate_texels"
                };
                check::outputs(name, &(params, len), st, &rgba);
            }
            _ => {
                let enc = encoding(inp);
                let cap = 3 * n * n;
                let len = inp.len_within(cap);
                let mut buf = vec![0u32; cap];
                let st = with_progress(inp, |cb, user| {
                    ocean_relief_generate_encoded(
                        m,
                        params.as_ptr(),
                        cb,
                        user,
                        enc,
                        buf.as_mut_ptr().cast(),
                        len,
                    )
                });
                check_encoded(
                    "ocean_relief_generate_encoded",
                    &(params, enc, len),
                    st,
                    enc,
                    &buf,
                    len,
                );
            }
        }
    }
}

/// A cone map's size, texels, encodings, quantised copy and mips (and their levels).
pub fn cones_queries(live: &mut Live, inp: &mut Input) {
    let c = pick_or_null(inp, &live.cones);
    // SAFETY: `c` is live or NULL; outputs are locals or buffers of `cap` >= `len` elements.
    unsafe {
        let n = query::<u32>("ocean_relief_cones_size", &(), |o| {
            ocean_relief_cones_size(c, o)
        })
        .map_or(inp.upto(4), |n| n as usize);
        let cap = 4 * n * n;
        let len = inp.len_within(cap);
        let mut rgba = vec![0f32; cap];
        let st = ocean_relief_cones_texels(c, rgba.as_mut_ptr(), len);
        check::outputs("ocean_relief_cones_texels", &len, st, &rgba);

        let enc = encoding(inp);
        let cap = 3 * n * n;
        let len = inp.len_within(cap);
        let mut buf = vec![0u32; cap];
        let st = ocean_relief_cones_encode(c, enc, buf.as_mut_ptr().cast(), len);
        check_encoded("ocean_relief_cones_encode", &(enc, len), st, enc, &buf, len);

        match inp.u8() % 3 {
            0 => {
                let enc = encoding(inp);
                let mut out = null_mut();
                let st = ocean_relief_cones_quantize(c, enc, &mut out);
                if check::status("ocean_relief_cones_quantize", &enc, st) {
                    Live::push(&mut live.cones, &mut live.dead, Kind::Cones, out);
                }
            }
            1 if live.afford(Costly::Cones) => {
                let rule = if inp.u8() % 8 == 7 {
                    inp.u32()
                } else {
                    inp.u32() % 2
                };
                let mut out = null_mut();
                let st = ocean_relief_mips_create(c, rule, &mut out);
                if check::status("ocean_relief_mips_create", &rule, st) {
                    Live::push(&mut live.mips, &mut live.dead, Kind::Mips, out);
                }
            }
            _ => {
                let mips = pick_or_null(inp, &live.mips);
                let count = query::<u32>("ocean_relief_mips_level_count", &(), |o| {
                    ocean_relief_mips_level_count(mips, o)
                });
                let level = match count {
                    Some(k) if inp.u8() % 8 != 7 => inp.upto(k as usize) as u32,
                    _ => inp.u32(),
                };
                let side = query::<u32>("ocean_relief_mips_level_size", &level, |o| {
                    ocean_relief_mips_level_size(mips, level, o)
                })
                .map_or(inp.upto(4), |s| s as usize);
                let enc = encoding(inp);
                let cap = 3 * side * side;
                let len = inp.len_within(cap);
                let mut buf = vec![0u32; cap];
                let st =
                    ocean_relief_mips_copy_level(mips, level, enc, buf.as_mut_ptr().cast(), len);
                check_encoded(
                    "ocean_relief_mips_copy_level",
                    &(level, enc, len),
                    st,
                    enc,
                    &buf,
                    len,
                );
            }
        }
    }
}

/// A tracer: one of the three methods and searches mostly, fuzzed step counts.
fn method(inp: &mut Input) -> CMem<OceanReliefMethod> {
    let mut m = OceanReliefMethod {
        method: enum_below(inp, 3),
        steps: 1 + inp.u32() % 64,
        binary: inp.u32() % 16,
        search: enum_below(inp, 3),
        ..Default::default()
    };
    for v in [&mut m.steps, &mut m.binary] {
        if inp.u8() % 16 == 15 {
            *v = inp.u32();
        }
    }
    let mut m = CMem::new(m);
    for at in [
        offset_of!(OceanReliefMethod, method),
        offset_of!(OceanReliefMethod, search),
    ] {
        if inp.u8() % 16 == 15 {
            m.poke_bytes(at, &inp.u32().to_ne_bytes());
        }
    }
    m
}

/// A ray entering the relief: from a fuzzed point, into the surface (dir_z > 0) mostly.
fn ray(inp: &mut Input) -> OceanReliefRay {
    let mut r = OceanReliefRay {
        start_u: 0.5,
        start_v: 0.5,
        dir_x: 0.3,
        dir_y: -0.2,
        dir_z: 1.0,
    };
    for v in [
        &mut r.start_u,
        &mut r.start_v,
        &mut r.dir_x,
        &mut r.dir_y,
        &mut r.dir_z,
    ] {
        tweak32(inp, v);
    }
    r
}

fn point(inp: &mut Input) -> OceanReliefPoint {
    OceanReliefPoint {
        u: inp.f32_near(0.5),
        v: inp.f32_near(0.5),
        depth: inp.f32_near(0.5),
    }
}

/// `ocean_relief_trace` / `_shadow` (plain or quad-directional) with fuzzed rays and points.
pub fn trace(live: &mut Live, inp: &mut Input) {
    let quad = inp.bool();
    let plain = pick_or_null(inp, &live.cones);
    let four = pick_or_null(inp, &live.quads);
    let m = method(inp);
    let k = (1 + inp.upto(MAX_RAYS)) % (MAX_RAYS + 1);
    let count = inp.len_within(k);
    // SAFETY: the handles are live or NULL; `m` is a local; the arrays hold `k` >= `count`
    // elements each.
    unsafe {
        if inp.bool() {
            let rays: Vec<OceanReliefRay> = (0..k).map(|_| ray(inp)).collect();
            let mut hits = vec![OceanReliefHit::default(); k];
            let (name, st) = if quad {
                let st = ocean_relief_quad_trace(
                    four,
                    m.as_ptr(),
                    rays.as_ptr(),
                    count,
                    hits.as_mut_ptr(),
                );
                ("ocean_relief_quad_trace", st)
            } else {
                let st =
                    ocean_relief_trace(plain, m.as_ptr(), rays.as_ptr(), count, hits.as_mut_ptr());
                ("ocean_relief_trace", st)
            };
            check::outputs(name, &(m, rays, count), st, &hits);
        } else {
            let points: Vec<OceanReliefPoint> = (0..k).map(|_| point(inp)).collect();
            let light = [inp.f32_near(0.5), inp.f32_near(0.5), inp.f32_near(1.0)];
            let (scale, bias) = (inp.f32_near(0.1), inp.f32_near(1e-3));
            let mut shadow = vec![0u8; k];
            let (name, st) = if quad {
                let st = ocean_relief_quad_shadow(
                    four,
                    m.as_ptr(),
                    points.as_ptr(),
                    count,
                    light[0],
                    light[1],
                    light[2],
                    scale,
                    bias,
                    shadow.as_mut_ptr(),
                );
                ("ocean_relief_quad_shadow", st)
            } else {
                let st = ocean_relief_shadow(
                    plain,
                    m.as_ptr(),
                    points.as_ptr(),
                    count,
                    light[0],
                    light[1],
                    light[2],
                    scale,
                    bias,
                    shadow.as_mut_ptr(),
                );
                ("ocean_relief_shadow", st)
            };
            check::status(name, &(m, points, count, light, scale, bias), st);
            if st == ocean::OceanStatus::Ok {
                assert!(
                    shadow[..count].iter().all(|&s| s <= 1),
                    "{name} wrote a shadow flag other than 0 or 1: {shadow:?}"
                );
            }
        }
    }
}

/// The quad-directional cone map's size and texels.
pub fn quad_queries(live: &mut Live, inp: &mut Input) {
    let q = pick_or_null(inp, &live.quads);
    // SAFETY: `q` is live or NULL; outputs are locals or a buffer of `cap` >= `len` floats.
    unsafe {
        let n = query::<u32>("ocean_relief_quad_cones_size", &(), |o| {
            ocean_relief_quad_cones_size(q, o)
        })
        .map_or(inp.upto(4), |n| n as usize);
        let cap = 16 * n * n;
        let len = inp.len_within(cap);
        let mut rgba = vec![0f32; cap];
        let st = ocean_relief_quad_cones_texels(q, rgba.as_mut_ptr(), len);
        check::outputs("ocean_relief_quad_cones_texels", &len, st, &rgba);
    }
}

/// The handle-free helpers: rays from a view, mip atlas layout and level, draw uniforms.
pub fn helpers(inp: &mut Input) {
    let (u, v) = (inp.f32_near(0.5), inp.f32_near(0.5));
    let view = [inp.f32_near(0.3), inp.f32_near(0.2), inp.f32_near(-1.0)];
    let depth = inp.f32_near(0.1);
    let (size, levels, level) = (inp.u32(), inp.u32(), inp.u32());
    let d = [inp.f32_near(1e-2), inp.f32(), inp.f32(), inp.f32_near(1e-2)];
    // SAFETY: every output is a local.
    unsafe {
        query::<OceanReliefRay>("ocean_relief_ray_from_view", &(u, v, view, depth), |o| {
            ocean_relief_ray_from_view(u, v, view[0], view[1], view[2], depth, o)
        });
        query::<(u32, u32)>("ocean_relief_mip_atlas_size", &(size, levels), |o| {
            ocean_relief_mip_atlas_size(size, levels, &mut (*o).0, &mut (*o).1)
        });
        query::<(u32, u32)>("ocean_relief_mip_atlas_origin", &(size, level), |o| {
            ocean_relief_mip_atlas_origin(size, level, &mut (*o).0, &mut (*o).1)
        });
        query::<u32>("ocean_relief_mip_level", &(d, size, levels), |o| {
            ocean_relief_mip_level(d[0], d[1], d[2], d[3], size, levels, o)
        });
    }
    let cam = camera(inp);
    let mut method_mem = None;
    let mut scene = OceanReliefScene::default();
    // SAFETY: `scene` is a local.
    let st = unsafe { ocean_relief_scene_default(&mut scene) };
    check::status("ocean_relief_scene_default", &(), st);
    for v in [
        &mut scene.origin.x,
        &mut scene.edge_u.z,
        &mut scene.edge_v.x,
        &mut scene.tiles_u,
        &mut scene.depth,
        &mut scene.light_dir.y,
        &mut scene.corners[1][0],
    ] {
        tweak(inp, v);
    }
    tweak32(inp, &mut scene.shadow_bias);
    tweak32(inp, &mut scene.ambient);
    tweak_flag(inp, &mut scene.shadows);
    if inp.u8() % 4 == 3 {
        method_mem = Some(method(inp));
    }
    let edge = inp.u32() % 3;
    let srgb = inp.flag();
    let cap = OCEAN_RELIEF_UNIFORMS_SIZE;
    let len = inp.len_within(cap);
    let mut bytes = vec![0u8; cap];
    let mut scene = CMem::new(scene);
    if let Some(m) = method_mem {
        scene.poke_bytes(offset_of!(OceanReliefScene, method), m.bytes());
    }
    let args = (cam, scene, size, edge, levels, srgb, len);
    // SAFETY: the camera and scene are locals; `bytes` holds `cap` >= `len` bytes.
    let st = unsafe {
        ocean_relief_uniforms(
            args.0.as_ptr(),
            args.1.as_ptr(),
            size,
            edge,
            levels,
            srgb,
            bytes.as_mut_ptr(),
            len,
        )
    };
    check::status("ocean_relief_uniforms", &args, st);
}

/// Destroys one relief handle of a fuzzed kind.
pub fn destroy(live: &mut Live, inp: &mut Input) {
    match inp.u8() % 4 {
        0 if !live.maps.is_empty() => {
            let i = inp.upto(live.maps.len() - 1);
            Live::kill(&mut live.maps, &mut live.dead, Kind::ReliefMap, i);
        }
        1 if !live.cones.is_empty() => {
            let i = inp.upto(live.cones.len() - 1);
            Live::kill(&mut live.cones, &mut live.dead, Kind::Cones, i);
        }
        2 if !live.quads.is_empty() => {
            let i = inp.upto(live.quads.len() - 1);
            Live::kill(&mut live.quads, &mut live.dead, Kind::QuadCones, i);
        }
        3 if !live.mips.is_empty() => {
            let i = inp.upto(live.mips.len() - 1);
            Live::kill(&mut live.mips, &mut live.dead, Kind::Mips, i);
        }
        _ => {}
    }
}
