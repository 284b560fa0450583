//! The call-sequence interpreter of `c_abi_sequence` and `cone_params`: each input is a
//! program, one operation per step (its first byte chooses which), on a table of live handles
//! that is emptied at the end.

use crate::input::Input;
use crate::live::Live;
use crate::{misuse, ops_lighting, ops_relief, ops_sao, ops_scene, ops_spectrum, ops_waves};

/// Handle misuse (use after destroy, a handle of another kind, double destroy, NULL handles;
/// `misuse.rs`): ocean-ffi's handle registry answers each with OCEAN_STATUS_INVALID_HANDLE
/// (or, for NULL, OCEAN_STATUS_NULL_POINTER), which the harness's invariants accept.
pub const MISUSE: bool = true;

/// Steps per input at most: keeps one execution short whatever the input's length.
const MAX_STEPS: usize = 24;

type Op = fn(&mut Live, &mut Input);

/// Every operation of `c_abi_sequence`.
const ALL: &[Op] = &[
    ops_waves::create,
    ops_waves::evaluate,
    ops_waves::evaluate_grid,
    ops_waves::queries,
    ops_waves::destroy,
    ops_spectrum::create,
    ops_spectrum::queries,
    |_, inp| ops_spectrum::pixel_footprint(inp),
    ops_spectrum::draw_data,
    ops_spectrum::destroy,
    ops_lighting::create,
    ops_lighting::queries,
    ops_lighting::sky_map_create,
    ops_lighting::sky_map_levels,
    ops_lighting::sea_color,
    |_, inp| ops_lighting::brdf(inp),
    ops_lighting::destroy,
    ops_scene::create,
    ops_scene::set_terrain,
    ops_scene::boxes,
    ops_scene::settings,
    ops_scene::evaluate,
    ops_scene::heights,
    ops_scene::destroy,
    ops_relief::map_create,
    ops_relief::map_queries,
    ops_relief::cones_create,
    ops_relief::cones_queries,
    ops_relief::quad_queries,
    ops_relief::trace,
    |_, inp| ops_relief::helpers(inp),
    ops_relief::destroy,
    ops_sao::create,
    ops_sao::run,
    ops_sao::destroy,
    misuse_if_enabled,
];

/// The relief operations alone, for `cone_params`.
const RELIEF: &[Op] = &[
    ops_relief::map_create,
    ops_relief::map_queries,
    ops_relief::cones_create,
    ops_relief::cones_queries,
    ops_relief::quad_queries,
    ops_relief::trace,
    |_, inp| ops_relief::helpers(inp),
    ops_relief::destroy,
    misuse_if_enabled,
];

fn misuse_if_enabled(live: &mut Live, inp: &mut Input) {
    if MISUSE {
        misuse::misuse(live, inp);
    }
}

fn run(ops: &[Op], data: &[u8], first: Option<Op>) {
    let mut inp = Input::new(data);
    let mut live = Live::default();
    if let Some(op) = first {
        op(&mut live, &mut inp);
    }
    let mut steps = 0;
    while steps < MAX_STEPS && !inp.is_empty() {
        // Byte 0 is no operation (and no step), so that zero padding after an operation's
        // parameters is harmless in hand-written seeds; operation k is byte k + 1.
        let b = usize::from(inp.u8());
        if b == 0 {
            continue;
        }
        ops[(b - 1) % ops.len()](&mut live, &mut inp);
        steps += 1;
    }
    drop(live);
    // A successful call clears the thread's last-error message (ocean-ffi/src/status.rs), so
    // that no allocation outlives the input: libFuzzer re-runs every input that ends with more
    // allocations than frees to look for leaks, which would otherwise be most of them.
    let mut sky = ocean::OceanSkyParams::default();
    // SAFETY: `sky` is a local.
    let st = unsafe { ocean::ocean_sky_params_default(&mut sky) };
    assert_eq!(st, ocean::OceanStatus::Ok);
}

/// `c_abi_sequence`: any operation at each step.
pub fn c_abi_sequence(data: &[u8]) {
    run(ALL, data, None);
}

/// `cone_params`: a height map first (so that the generators always have one), then relief
/// operations.
pub fn cone_params(data: &[u8]) {
    run(RELIEF, data, Some(ops_relief::map_create));
}
