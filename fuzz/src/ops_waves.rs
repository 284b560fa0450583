//! Operations on Gerstner wave sets (`ocean_waves_*`, ocean-ffi/src/waves.rs).

use std::ptr::null_mut;

use ocean::{
    OceanDVec2, OceanDVec3, OceanGrid, OceanVec3, OceanWaveDesc, ocean_waves_count,
    ocean_waves_create, ocean_waves_evaluate, ocean_waves_evaluate_grid, ocean_waves_max_amplitude,
    ocean_waves_steepness_sum,
};

use crate::call::{query, tweak};
use crate::check;
use crate::input::Input;
use crate::live::{Kind, Live, pick_or_null};

/// Points per evaluation at most: enough for every code path, cheap per execution.
const MAX_POINTS: usize = 16;

/// A wave: a gentle one (amplitude 0.5 m, wavelength 20 m) with fields fuzzed, the depth
/// infinite (deep water, allowed) one time in four.
pub fn wave_desc(inp: &mut Input) -> OceanWaveDesc {
    let mut w = OceanWaveDesc {
        amplitude: 0.5,
        wavelength: 20.0,
        direction_x: 1.0,
        direction_z: 0.3,
        phase: 0.7,
        depth: if inp.u8().is_multiple_of(4) {
            f64::INFINITY
        } else {
            30.0
        },
    };
    for v in [
        &mut w.amplitude,
        &mut w.wavelength,
        &mut w.direction_x,
        &mut w.direction_z,
        &mut w.phase,
        &mut w.depth,
    ] {
        tweak(inp, v);
    }
    w
}

/// `ocean_waves_create` with 0 to 6 waves and a length up to that count.
pub fn create(live: &mut Live, inp: &mut Input) {
    let n = (1 + inp.upto(6)) % 7;
    let descs: Vec<OceanWaveDesc> = (0..n).map(|_| wave_desc(inp)).collect();
    let len = inp.len_within(n);
    let null = n == 0 && inp.bool();
    let args = (descs, len, null);
    let ptr = if null {
        std::ptr::null()
    } else {
        args.0.as_ptr()
    };
    let mut out = null_mut();
    // SAFETY: `ptr` is NULL or points to `args.0`, which holds at least `len` descriptions;
    // `out` is a local.
    let st = unsafe { ocean_waves_create(ptr, len, &mut out) };
    if check::status("ocean_waves_create", &args, st) {
        Live::push(&mut live.waves, &mut live.dead, Kind::Waves, out);
    }
}

/// `ocean_waves_evaluate` at up to [`MAX_POINTS`] points and a fuzzed time.
pub fn evaluate(live: &mut Live, inp: &mut Input) {
    let waves = pick_or_null(inp, &live.waves);
    let m = (1 + inp.upto(MAX_POINTS)) % (MAX_POINTS + 1);
    let xz: Vec<OceanDVec2> = (0..m)
        .map(|_| OceanDVec2 {
            x: f64::from(inp.f32_near(50.0)) - 50.0,
            z: f64::from(inp.f32_near(50.0)) - 50.0,
        })
        .collect();
    let n = inp.len_within(m);
    let time = inp.f64_near(10.0);
    let args = (xz, n, time);
    let mut pos = vec![OceanDVec3::default(); m];
    let mut normal = vec![OceanVec3::default(); m];
    // SAFETY: `waves` is live or NULL; `xz`, `pos` and `normal` hold `m` >= `n` elements each
    // and do not overlap.
    let st = unsafe {
        ocean_waves_evaluate(
            waves,
            args.0.as_ptr(),
            n,
            time,
            pos.as_mut_ptr(),
            normal.as_mut_ptr(),
        )
    };
    check::outputs("ocean_waves_evaluate", &args, st, &(pos, normal));
}

/// `ocean_waves_evaluate_grid` on a grid of at most [`MAX_POINTS`] points, or one whose point
/// count overflows (which must be refused before anything is written).
pub fn evaluate_grid(live: &mut Live, inp: &mut Input) {
    let waves = pick_or_null(inp, &live.waves);
    let overflow = inp.u8() % 16 == 15;
    let (nx, nz) = if overflow {
        (usize::MAX / 2 + inp.upto(3), 2 + inp.upto(3))
    } else {
        ((1 + inp.upto(4)) % 5, (1 + inp.upto(4)) % 5)
    };
    let mut grid = OceanGrid {
        origin_x: -10.0,
        origin_z: -10.0,
        spacing_x: 1.0,
        spacing_z: 2.0,
        nx,
        nz,
    };
    for v in [
        &mut grid.origin_x,
        &mut grid.origin_z,
        &mut grid.spacing_x,
        &mut grid.spacing_z,
    ] {
        tweak(inp, v);
    }
    let time = inp.f64_near(10.0);
    let points = if overflow { 1 } else { nx * nz };
    let mut pos = vec![OceanVec3::default(); points];
    let mut normal = vec![OceanVec3::default(); points];
    let args = (grid, time);
    // SAFETY: `waves` is live or NULL; `pos` and `normal` hold nx * nz points each, or the
    // count overflows and the library must refuse it before writing.
    let st = unsafe {
        ocean_waves_evaluate_grid(waves, &args.0, time, pos.as_mut_ptr(), normal.as_mut_ptr())
    };
    if overflow {
        assert_ne!(
            st,
            ocean::OceanStatus::Ok,
            "ocean_waves_evaluate_grid accepted an overflowing grid {grid:?}"
        );
    }
    check::outputs("ocean_waves_evaluate_grid", &args, st, &(pos, normal));
}

/// The three scalar queries of a wave set.
pub fn queries(live: &mut Live, inp: &mut Input) {
    let waves = pick_or_null(inp, &live.waves);
    let args = ();
    // SAFETY: `waves` is live or NULL, each output a local.
    unsafe {
        query("ocean_waves_count", &args, |o| ocean_waves_count(waves, o));
        query("ocean_waves_steepness_sum", &args, |o| {
            ocean_waves_steepness_sum(waves, o)
        });
        query("ocean_waves_max_amplitude", &args, |o| {
            ocean_waves_max_amplitude(waves, o)
        });
    }
}

/// Destroys one wave set.
pub fn destroy(live: &mut Live, inp: &mut Input) {
    if !live.waves.is_empty() {
        let i = inp.upto(live.waves.len() - 1);
        Live::kill(&mut live.waves, &mut live.dead, Kind::Waves, i);
    }
}
