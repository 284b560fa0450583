//! Handle misuse: a destroyed handle used or destroyed again, a handle passed as another kind,
//! NULL handles. The C contract forbids the first three (include/ocean.h: "must be a live
//! handle"), and before ocean-ffi checks its handles they are undefined behaviour that
//! crashes, so `sequence.rs` runs these only when its `MISUSE` is on. Once ocean-ffi refuses
//! them, each must fail with a message, never succeed.

use std::ffi::c_void;

use ocean::{
    OceanStatus, ocean_lighting_sun_solid_angle, ocean_relief_cones_size, ocean_relief_map_size,
    ocean_relief_mips_level_count, ocean_relief_quad_cones_size, ocean_sao_describe,
    ocean_sky_map_level_count, ocean_spectrum_wave_count, ocean_waves_count,
    ocean_wtb_scene_box_count,
};

use crate::check;
use crate::input::Input;
use crate::live::{Kind, Live, destroy, pick};

const KINDS: [Kind; 10] = [
    Kind::Waves,
    Kind::Spectrum,
    Kind::Lighting,
    Kind::SkyMap,
    Kind::Scene,
    Kind::ReliefMap,
    Kind::Cones,
    Kind::QuadCones,
    Kind::Mips,
    Kind::Sao,
];

/// Calls a read-only query of `kind` on `handle`.
///
/// # Safety
///
/// `handle` must be a live handle of `kind`, or the misuse under test.
unsafe fn query_as(kind: Kind, handle: *mut c_void) -> OceanStatus {
    let mut n = 0usize;
    let mut k = 0u32;
    let mut f = 0f64;
    let mut info = ocean::OceanSaoInfo::default();
    // SAFETY: per this function's contract; every output is a local.
    unsafe {
        match kind {
            Kind::Waves => ocean_waves_count(handle.cast(), &mut n),
            Kind::Spectrum => ocean_spectrum_wave_count(handle.cast(), &mut n),
            Kind::Lighting => ocean_lighting_sun_solid_angle(handle.cast(), &mut f),
            Kind::SkyMap => ocean_sky_map_level_count(handle.cast(), &mut k),
            Kind::Scene => ocean_wtb_scene_box_count(handle.cast(), &mut n),
            Kind::ReliefMap => ocean_relief_map_size(handle.cast(), &mut k),
            Kind::Cones => ocean_relief_cones_size(handle.cast(), &mut k),
            Kind::QuadCones => ocean_relief_quad_cones_size(handle.cast(), &mut k),
            Kind::Mips => ocean_relief_mips_level_count(handle.cast(), &mut k),
            Kind::Sao => ocean_sao_describe(handle.cast(), &mut info),
        }
    }
}

/// One misuse operation.
pub fn misuse(live: &mut Live, inp: &mut Input) {
    let kind = KINDS[inp.upto(KINDS.len() - 1)];
    match inp.u8() % 4 {
        // Use after destroy.
        0 => {
            if let Some(&(k, h)) = pick(inp, &live.dead) {
                // SAFETY: the misuse under test: `h` was a handle of `k`, now destroyed.
                let st = unsafe { query_as(k, h) };
                check::status("use after destroy", &(k, kind), st);
                assert_ne!(st, OceanStatus::Ok, "a destroyed {k:?} handle was accepted");
            }
        }
        // A live handle of one kind passed as another.
        1 => {
            if let Some(h) = live.any_of(kind, inp) {
                let as_kind = KINDS[inp.upto(KINDS.len() - 1)];
                // SAFETY: the misuse under test when `as_kind` differs from `kind`; a
                // correct call otherwise.
                let st = unsafe { query_as(as_kind, h) };
                check::status("wrong-kind handle", &(kind, as_kind), st);
                if as_kind != kind {
                    assert_ne!(
                        st,
                        OceanStatus::Ok,
                        "a {kind:?} handle was accepted as {as_kind:?}"
                    );
                }
            }
        }
        // Double destroy (must be harmless), possibly as another kind.
        2 => {
            if let Some(&(k, h)) = pick(inp, &live.dead) {
                let as_kind = if inp.bool() { k } else { kind };
                // SAFETY: the misuse under test: `h` is already destroyed.
                unsafe { destroy(as_kind, h) };
            }
        }
        // NULL: destroy accepts it, queries refuse it.
        _ => {
            // SAFETY: NULL is documented as accepted by every destroy and refused by every
            // query (include/ocean.h).
            let st = unsafe {
                destroy(kind, std::ptr::null_mut());
                query_as(kind, std::ptr::null_mut())
            };
            check::status("NULL handle", &kind, st);
            assert_eq!(
                st,
                OceanStatus::NullPointer,
                "a NULL {kind:?} handle: {st:?}"
            );
        }
    }
}
