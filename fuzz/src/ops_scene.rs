//! Operations on wave train box scenes (ocean-ffi/src/wtb.rs, ocean-ffi/src/wtb_query.rs).

use std::ffi::c_void;
use std::ptr::null_mut;

use ocean::{
    OceanBoxDesc, OceanCamera, OceanDVec2, OceanDrawnSample, OceanEffects, OceanFrameStats,
    OceanHeightSample, OceanStatus, OceanVec3, OceanWaterGridDesc, OceanWaveDesc, OceanWindDesc,
    OceanWtbScene, ocean_wtb_effects_default, ocean_wtb_scene_add_box, ocean_wtb_scene_box_count,
    ocean_wtb_scene_create, ocean_wtb_scene_evaluate, ocean_wtb_scene_heights_continuous,
    ocean_wtb_scene_heights_drawn, ocean_wtb_scene_remove_box, ocean_wtb_scene_set_budget_explicit,
    ocean_wtb_scene_set_budget_seconds, ocean_wtb_scene_set_budget_unlimited,
    ocean_wtb_scene_set_effects, ocean_wtb_scene_set_terrain, ocean_wtb_scene_set_train_filter,
    ocean_wtb_scene_update_box,
};

use crate::call::{camera, query, tweak, tweak_flag};
use crate::check;
use crate::cmem::CMem;
use crate::input::Input;
use crate::live::{Costly, Live, Scene, pick};
use crate::ops_waves::wave_desc;

// Declared here because ocean-ffi/src/lib.rs does not re-export them (the symbols exist and
// include/ocean.h declares them): a C caller reaches them, so the fuzzer calls them too. The
// scene is `void *` here: `OceanWtbScene` has no C layout (it is opaque), which the lint about
// foreign types would flag; a pointer is a pointer to the linker.
unsafe extern "C" {
    fn ocean_wtb_scene_evaluate_incremental(
        scene: *mut c_void,
        time: f64,
        camera: *const OceanCamera,
        out_pos: *mut OceanVec3,
        out_normal: *mut OceanVec3,
        n: usize,
        out_stats: *mut OceanFrameStats,
    ) -> OceanStatus;
    fn ocean_wtb_scene_reset_coverage(scene: *mut c_void) -> OceanStatus;
}

/// Grid side at most: every evaluation touches each point, and each box marches over them.
const MAX_SIDE: usize = 12;
/// Trains per box at most, and explicit trains passed to `_add_box`.
const MAX_TRAINS: u32 = 6;

/// The scene a call uses: a live one, or NULL one time in sixteen (`points` then 0).
fn scene_or_null(live: &mut Live, inp: &mut Input) -> Option<usize> {
    if inp.u8() % 16 == 15 || live.scenes.is_empty() {
        None
    } else {
        Some(inp.upto(live.scenes.len() - 1))
    }
}

fn handle(live: &Live, i: Option<usize>) -> *mut OceanWtbScene {
    i.map_or(null_mut(), |i| live.scenes[i].handle)
}

/// Terrain heights for `points` grid points (land above 0, sea floor below), fuzzed.
fn terrain(inp: &mut Input, points: usize) -> Vec<f32> {
    let base = -inp.f32_near(8.0);
    (0..points)
        .map(|k| {
            if inp.u8() % 8 == 7 {
                inp.f32()
            } else {
                base + (k % 7) as f32 * 0.5
            }
        })
        .collect()
}

/// `ocean_wtb_scene_create` on a small grid, with terrain or an open sea.
pub fn create(live: &mut Live, inp: &mut Input) {
    let mut grid = OceanWaterGridDesc {
        origin_x: -10.0,
        origin_z: -10.0,
        spacing: 2.0,
        nx: 2 + inp.upto(MAX_SIDE - 2),
        nz: 2 + inp.upto(MAX_SIDE - 2),
    };
    for v in [&mut grid.origin_x, &mut grid.origin_z, &mut grid.spacing] {
        tweak(inp, v);
    }
    if inp.u8() % 16 == 15 {
        grid.nx = inp.upto(3);
    }
    let points = grid.nx * grid.nz;
    let heights = if inp.bool() {
        terrain(inp, points)
    } else {
        Vec::new()
    };
    let len = inp.len_within(heights.len());
    let args = (grid, heights, len);
    let ptr = if args.1.is_empty() {
        std::ptr::null()
    } else {
        args.1.as_ptr()
    };
    let mut out = null_mut();
    // SAFETY: the grid is a local; `ptr` is NULL (with `len` 0) or points to `len` heights.
    let st = unsafe { ocean_wtb_scene_create(&args.0, ptr, len, &mut out) };
    if check::status("ocean_wtb_scene_create", &args, st) {
        live.push_scene(Scene {
            handle: out,
            points,
            boxes: Vec::new(),
            kept_pos: vec![OceanVec3::default(); points],
            kept_normal: vec![OceanVec3::default(); points],
        });
    }
}

/// `ocean_wtb_scene_set_terrain` with heights for the scene's grid (or a shorter length).
pub fn set_terrain(live: &mut Live, inp: &mut Input) {
    let i = scene_or_null(live, inp);
    let points = i.map_or(inp.upto(4), |i| live.scenes[i].points);
    let heights = terrain(inp, points);
    let len = inp.len_within(points);
    let s = handle(live, i);
    // SAFETY: `s` is live or NULL; `heights` holds `points` >= `len` floats.
    let st = unsafe { ocean_wtb_scene_set_terrain(s, heights.as_ptr(), len) };
    check::status("ocean_wtb_scene_set_terrain", &(heights, len), st);
}

/// A wind over the grid with fields fuzzed.
fn box_desc(inp: &mut Input) -> OceanBoxDesc {
    let mut w = OceanWindDesc {
        speed: 8.0,
        direction_x: 1.0,
        direction_z: 0.2,
        origin_x: -12.0,
        origin_z: -12.0,
        width: 20.0,
        fetch: 20.0,
        start: 0.0,
        build_up: 4.0,
        sustain: if inp.bool() { f64::INFINITY } else { 30.0 },
        decay: 5.0,
        seed: u64::from(inp.u8()),
        trains: 1 + inp.upto(MAX_TRAINS as usize - 1) as u32,
        ..Default::default()
    };
    for v in [
        &mut w.speed,
        &mut w.direction_x,
        &mut w.direction_z,
        &mut w.origin_x,
        &mut w.origin_z,
        &mut w.width,
        &mut w.fetch,
        &mut w.start,
        &mut w.build_up,
        &mut w.sustain,
        &mut w.decay,
    ] {
        tweak(inp, v);
    }
    if inp.u8() % 16 == 15 {
        w.trains = inp.u32().min(64);
    }
    let mut b = OceanBoxDesc {
        wind: w,
        smoothing: 2.0,
        has_recovery: 0,
        recovery: 10.0,
        ..Default::default()
    };
    tweak(inp, &mut b.smoothing);
    tweak_flag(inp, &mut b.has_recovery);
    tweak(inp, &mut b.recovery);
    b
}

/// A box's optional explicit trains: none (the wind makes them) or a few fuzzed waves.
fn trains(inp: &mut Input) -> Vec<OceanWaveDesc> {
    if inp.bool() {
        Vec::new()
    } else {
        (0..inp.upto(MAX_TRAINS as usize))
            .map(|_| wave_desc(inp))
            .collect()
    }
}

/// `ocean_wtb_scene_add_box`, `_update_box` (of a known or unknown id) or `_remove_box`.
pub fn boxes(live: &mut Live, inp: &mut Input) {
    let i = scene_or_null(live, inp);
    let s = handle(live, i);
    let known = i.map(|i| live.scenes[i].boxes.clone()).unwrap_or_default();
    let id = match pick(inp, &known) {
        Some(&id) if inp.u8() % 8 != 7 => id,
        _ => inp.u32(),
    };
    match inp.u8() % 4 {
        0 | 1 => {
            let args = (box_desc(inp), trains(inp));
            let n = inp.len_within(args.1.len());
            let ptr = if args.1.is_empty() {
                std::ptr::null()
            } else {
                args.1.as_ptr()
            };
            let mut out = 0u32;
            // SAFETY: `s` is live or NULL; the description is a local; `ptr` is NULL (with
            // `n` 0) or points to `n` trains at least.
            let st = unsafe { ocean_wtb_scene_add_box(s, &args.0, ptr, n, &mut out) };
            if check::status("ocean_wtb_scene_add_box", &(args, n), st)
                && let Some(i) = i
            {
                live.scenes[i].boxes.push(out);
            }
        }
        2 => {
            let args = (id, box_desc(inp), trains(inp));
            let n = inp.len_within(args.2.len());
            let ptr = if args.2.is_empty() {
                std::ptr::null()
            } else {
                args.2.as_ptr()
            };
            // SAFETY: as for `_add_box`.
            let st = unsafe { ocean_wtb_scene_update_box(s, id, &args.1, ptr, n) };
            check::status("ocean_wtb_scene_update_box", &(args, n), st);
        }
        _ => {
            let st = ocean_wtb_scene_remove_box(s, id);
            check::status("ocean_wtb_scene_remove_box", &id, st);
        }
    }
    // SAFETY: `s` is live or NULL; the output is a local.
    unsafe {
        query::<usize>("ocean_wtb_scene_box_count", &(), |o| {
            ocean_wtb_scene_box_count(s, o)
        });
    }
}

/// The default effects with fields fuzzed.
fn effects(inp: &mut Input) -> CMem<OceanEffects> {
    let mut e = OceanEffects::default();
    // SAFETY: `e` is a local.
    let st = unsafe { ocean_wtb_effects_default(&mut e) };
    check::status("ocean_wtb_effects_default", &(), st);
    for f in [
        &mut e.shoaling,
        &mut e.round_waves,
        &mut e.irregular.enabled,
        &mut e.noise.enabled,
        &mut e.beach.enabled,
    ] {
        tweak_flag(inp, f);
    }
    for v in [
        &mut e.irregular.scale,
        &mut e.irregular.frequency,
        &mut e.irregular.envelope_wavenumber,
        &mut e.irregular.envelope_speed,
        &mut e.noise.amplitude,
        &mut e.beach.max_depth_share,
        &mut e.beach.run_up,
        &mut e.beach.run_up_depth,
    ] {
        tweak(inp, v);
    }
    e.noise.seed = u64::from(inp.u8());
    let mut e = CMem::new(e);
    e.tweak_u32(inp, std::mem::offset_of!(OceanEffects, refraction));
    e
}

/// Effects, budgets and the train filter.
pub fn settings(live: &mut Live, inp: &mut Input) {
    let i = scene_or_null(live, inp);
    let s = handle(live, i);
    // SAFETY: `s` is live or NULL; the effects are locals.
    unsafe {
        match inp.u8() % 5 {
            0 => {
                let e = effects(inp);
                let st = ocean_wtb_scene_set_effects(s, e.as_ptr());
                check::status("ocean_wtb_scene_set_effects", &e, st);
            }
            1 => {
                let st = ocean_wtb_scene_set_budget_unlimited(s);
                check::status("ocean_wtb_scene_set_budget_unlimited", &(), st);
            }
            2 => {
                let seconds = inp.f64_near(1e-3);
                let st = ocean_wtb_scene_set_budget_seconds(s, seconds);
                check::status("ocean_wtb_scene_set_budget_seconds", &seconds, st);
            }
            3 => {
                let max = if inp.bool() { usize::MAX } else { inp.upto(8) };
                let e = effects(inp);
                let st = ocean_wtb_scene_set_budget_explicit(s, max, e.as_ptr());
                check::status("ocean_wtb_scene_set_budget_explicit", &(max, e), st);
            }
            _ => {
                let (lo, hi) = (inp.f64_near(2.0), inp.f64_near(4.0));
                let st = ocean_wtb_scene_set_train_filter(s, lo, hi);
                check::status("ocean_wtb_scene_set_train_filter", &(lo, hi), st);
            }
        }
    }
}

/// `ocean_wtb_scene_evaluate` (or the incremental variant into the scene's kept buffers, or a
/// coverage reset) at a fuzzed time, with or without a culling camera.
pub fn evaluate(live: &mut Live, inp: &mut Input) {
    let i = scene_or_null(live, inp);
    let s = handle(live, i);
    let points = i.map_or(inp.upto(4), |i| live.scenes[i].points);
    let n = inp.len_within(points);
    let time = inp.f64_near(10.0);
    let cam = if inp.bool() { Some(camera(inp)) } else { None };
    let with_stats = inp.bool();
    let mut stats = OceanFrameStats::default();
    let stats_ptr: *mut OceanFrameStats = if with_stats { &mut stats } else { null_mut() };
    let cam_ptr: *const OceanCamera = cam.as_ref().map_or(std::ptr::null(), CMem::as_ptr);
    let args = (n, time, cam);
    if !live.afford(Costly::SceneEvaluate) {
        return;
    }
    match (inp.u8() % 4, i) {
        (3, Some(i)) => {
            let sc = &mut live.scenes[i];
            // SAFETY: the kept buffers hold `points` >= `n` elements each and do not overlap;
            // `cam_ptr` is NULL or a local camera; `stats_ptr` NULL or a local.
            let st = unsafe {
                ocean_wtb_scene_evaluate_incremental(
                    s.cast(),
                    time,
                    cam_ptr,
                    sc.kept_pos.as_mut_ptr(),
                    sc.kept_normal.as_mut_ptr(),
                    n,
                    stats_ptr,
                )
            };
            check::outputs(
                "ocean_wtb_scene_evaluate_incremental",
                &args,
                st,
                &(&sc.kept_pos[..], &sc.kept_normal[..]),
            );
        }
        (2, _) => {
            // SAFETY: `s` is live or NULL.
            let st = unsafe { ocean_wtb_scene_reset_coverage(s.cast()) };
            check::status("ocean_wtb_scene_reset_coverage", &(), st);
        }
        _ => {
            let mut pos = vec![OceanVec3::default(); points];
            let mut normal = vec![OceanVec3::default(); points];
            // SAFETY: `pos` and `normal` hold `points` >= `n` elements each and do not
            // overlap; `cam_ptr` is NULL or a local camera; `stats_ptr` NULL or a local.
            let st = unsafe {
                ocean_wtb_scene_evaluate(
                    s,
                    time,
                    cam_ptr,
                    pos.as_mut_ptr(),
                    normal.as_mut_ptr(),
                    n,
                    stats_ptr,
                )
            };
            check::outputs("ocean_wtb_scene_evaluate", &args, st, &(pos, normal));
        }
    }
    if with_stats {
        // Checked apart, so that the known NaN of the one (fuzz/src/known.rs) leaves the
        // other checked.
        check::outputs(
            "ocean_wtb_scene_evaluate (estimated_seconds)",
            &args,
            OceanStatus::Ok,
            &stats.estimated_seconds,
        );
        check::outputs(
            "ocean_wtb_scene_evaluate (filtered_slope_variance)",
            &args,
            OceanStatus::Ok,
            &stats.filtered_slope_variance,
        );
    }
}

/// `ocean_wtb_scene_heights_drawn` and `_continuous` at fuzzed points.
pub fn heights(live: &mut Live, inp: &mut Input) {
    let i = scene_or_null(live, inp);
    let s = handle(live, i);
    let k = (1 + inp.upto(8)) % 9;
    let xz: Vec<OceanDVec2> = (0..k)
        .map(|_| OceanDVec2 {
            x: inp.f64_near(20.0) - 10.0,
            z: inp.f64_near(20.0) - 10.0,
        })
        .collect();
    let n = inp.len_within(k);
    let time = inp.f64_near(10.0);
    let args = (xz, n, time);
    if inp.bool() {
        let mut out = vec![OceanDrawnSample::default(); k];
        // SAFETY: `s` is live or NULL; `xz` and `out` hold `k` >= `n` elements.
        let st = unsafe { ocean_wtb_scene_heights_drawn(s, args.0.as_ptr(), n, out.as_mut_ptr()) };
        check::outputs("ocean_wtb_scene_heights_drawn", &args, st, &out);
    } else {
        let mut out = vec![OceanHeightSample::default(); k];
        // SAFETY: as above.
        let st = unsafe {
            ocean_wtb_scene_heights_continuous(s, time, args.0.as_ptr(), n, out.as_mut_ptr())
        };
        check::outputs("ocean_wtb_scene_heights_continuous", &args, st, &out);
    }
}

/// Destroys one scene.
pub fn destroy(live: &mut Live, inp: &mut Input) {
    if !live.scenes.is_empty() {
        let i = inp.upto(live.scenes.len() - 1);
        live.kill_scene(i);
    }
}
