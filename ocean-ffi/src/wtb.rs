//! Wave Train Boxes scenes (crate `ocean-wtb`, Yrjola & Larsson): a water grid over a terrain,
//! wind-driven boxes of Gerstner wave trains, switchable effects, a frame budget, evaluation of
//! the grid and batched height queries.

use core::mem::size_of;
use std::sync::{Mutex, MutexGuard, PoisonError};

use glam::Vec3;
use ocean_core::frustum::{Frustum, FrustumError};
use ocean_wtb::budget::{Budget, Selection};
use ocean_wtb::scene::{BoxId, Coverage, Scene};

use crate::boundary::{
    borrow, byte_len, check_disjoint, check_finite, check_len, check_ptr, check_time, destroy,
    read_in, read_params_checked, write_handle, write_out,
};
use crate::camera::{OceanCamera, read_camera};
use crate::status::{Error, OceanStatus, guard};
use crate::waves::{OceanVec3, OceanWaveDesc};
use crate::wtb_params::{
    OceanBoxDesc, OceanEffects, OceanFrameStats, OceanWaterGridDesc, box_spec, check_terrain_ptr,
    effects_from, stats_to, terrain, water_grid, wtb_error,
};

/// A Wave Train Boxes scene (opaque): water grid, terrain, boxes, effects and budget. Create
/// with `ocean_wtb_scene_create`, free with `ocean_wtb_scene_destroy`.
///
/// Every function taking an `OceanWtbScene *` may be called from several threads at once on the
/// same scene: a lock inside the scene serialises them (they do not run concurrently with each
/// other; evaluations and height queries spread their own work over the library's worker
/// threads). Destroying must not race with any other use.
pub struct OceanWtbScene {
    scene: Mutex<Scene>,
    /// What the buffers of `ocean_wtb_scene_evaluate_incremental` may hold besides rest.
    coverage: Mutex<Coverage>,
    /// The frame the last evaluation drew, which drawn height queries answer for.
    evaluated: Mutex<Option<Evaluated>>,
}

/// What the last successful evaluation drew: the instant, the view it culled by, and the
/// scene's revision then (the same three give the same grid, see `Scene::revision`).
#[derive(Clone, Copy, Debug)]
pub(crate) struct Evaluated {
    pub(crate) time: f64,
    pub(crate) view: Option<Frustum>,
    pub(crate) revision: u64,
}

impl OceanWtbScene {
    /// The record of the last evaluation.
    pub(crate) fn evaluated(&self) -> MutexGuard<'_, Option<Evaluated>> {
        self.evaluated
            .lock()
            .unwrap_or_else(PoisonError::into_inner)
    }

    pub(crate) fn lock(&self) -> MutexGuard<'_, Scene> {
        // A panic inside a call (a library bug, reported as OCEAN_STATUS_PANIC) poisons the
        // lock; the scene stays consistent, since every mutation replaces whole values.
        self.scene.lock().unwrap_or_else(PoisonError::into_inner)
    }
}

const _: () = {
    const fn shareable<T: Send + Sync>() {}
    shareable::<OceanWtbScene>();
};

/// The box with the caller's id.
fn box_id(scene: &Scene, id: u32) -> Result<BoxId, Error> {
    scene.box_ids().find(|b| b.get() == id).ok_or_else(|| {
        Error::new(
            OceanStatus::NotFound,
            format!("no box with id {id} in this scene (removed, never added, or another scene's)"),
        )
    })
}

/// Creates a scene: a water grid over a terrain, no boxes yet, the default effects
/// (`ocean_wtb_effects_default`) and no budget limit. Stores the new handle in `*out`.
///
/// `terrain_heights` holds one height per grid point, row-major (point (i, j) at j*nx + i):
/// the ground's height above the sea at rest, metres. A height < 0 is sea floor at depth
/// -height; a height >= 0 is land, where the water stays at rest. Pass NULL and 0 for an open
/// sea of infinite depth. Outside the grid the sea is deep. The heights are copied.
///
/// Returns `OCEAN_STATUS_NULL_POINTER` if `grid` or `out` is NULL, or `terrain_heights` is NULL
/// with `terrain_len` != 0; `OCEAN_STATUS_MISALIGNED_POINTER`; `OCEAN_STATUS_EMPTY` if `nx` or
/// `nz` is 0; `OCEAN_STATUS_LENGTH_OVERFLOW` if `nx * nz` overflows; `OCEAN_STATUS_NON_FINITE`
/// for a NaN or infinite origin, spacing or height; `OCEAN_STATUS_INVALID_ARGUMENT` for a side
/// outside 2 to 4096, a spacing outside [1e-3, 1e4] m or an origin beyond 1e9 m;
/// `OCEAN_STATUS_LENGTH_MISMATCH` if `terrain_len` != nx * nz. On failure `*out` is
/// unchanged. Free the scene with `ocean_wtb_scene_destroy`.
///
/// # Safety
///
/// `grid` must point to a readable `OceanWaterGridDesc`, `terrain_heights` be NULL or point to
/// `terrain_len` readable floats, and `out` point to a writable pointer; none is retained.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn ocean_wtb_scene_create(
    grid: *const OceanWaterGridDesc,
    terrain_heights: *const f32,
    terrain_len: usize,
    out: *mut *mut OceanWtbScene,
) -> OceanStatus {
    guard("ocean_wtb_scene_create", || {
        check_ptr(grid, "grid")?;
        check_terrain_ptr(terrain_heights, terrain_len)?;
        check_ptr(out.cast_const(), "out")?;
        // SAFETY: forwarded from this function's contract.
        let g = water_grid(&unsafe { read_in(grid, "grid") }?, "grid")?;
        // SAFETY: forwarded from this function's contract.
        let t = unsafe { terrain(&g, terrain_heights, terrain_len) }?;
        let scene = Scene::new(g, t)?;
        let coverage = Coverage::everything(scene.grid());
        let value = OceanWtbScene {
            scene: Mutex::new(scene),
            coverage: Mutex::new(coverage),
            evaluated: Mutex::new(None),
        };
        // SAFETY: forwarded from this function's contract.
        unsafe { write_handle(out, value) }
    })
}

/// Frees a scene and its boxes. Every destroy function follows the same rules: NULL does
/// nothing; a handle of another kind, one already destroyed or a value this library never
/// returned frees nothing and sets the last-error message (`OCEAN_STATUS_INVALID_HANDLE`'s
/// text); a live handle is unregistered at once (later calls with it are refused) and freed when
/// the last call using it on another thread returns. A successful destroy leaves the last-error
/// message alone.
#[unsafe(no_mangle)]
pub extern "C" fn ocean_wtb_scene_destroy(scene: *mut OceanWtbScene) {
    destroy(scene, "ocean_wtb_scene_destroy", "scene");
}

/// Replaces the scene's terrain (same format as in `ocean_wtb_scene_create`; NULL and 0 for a deep
/// sea). Every box's land, depth and refraction along its rays is recomputed at the next
/// evaluation.
///
/// Returns `OCEAN_STATUS_NULL_POINTER` / `_MISALIGNED_POINTER` for a bad pointer (or NULL with
/// a length), `OCEAN_STATUS_LENGTH_MISMATCH` if `terrain_len` != nx * nz,
/// `OCEAN_STATUS_NON_FINITE` for a NaN or infinite height (the message gives its index). On
/// failure the scene keeps its terrain.
///
/// # Safety
///
/// `terrain_heights` must be NULL or point to `terrain_len` readable floats.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn ocean_wtb_scene_set_terrain(
    scene: *mut OceanWtbScene,
    terrain_heights: *const f32,
    terrain_len: usize,
) -> OceanStatus {
    guard("ocean_wtb_scene_set_terrain", || {
        let scene = borrow(scene, "scene")?;
        let mut scene = scene.lock();
        let grid = *scene.grid();
        // SAFETY: forwarded from this function's contract.
        let t = unsafe { terrain(&grid, terrain_heights, terrain_len) }?;
        scene.set_terrain(t).map_err(Error::from)
    })
}

/// Adds a wave train box raised by `desc->wind`, and stores its id in `*out_id`. Ids are never
/// reused within a scene.
///
/// The trains: with `n_trains` = 0 (`trains` is then ignored and may be NULL) the wind raises
/// `desc->wind.trains` trains by the library's seeded mapping (peak wavelength from the
/// Pierson-Moskowitz spectrum, the others spread within 30 degrees, amplitudes summing to H/2);
/// otherwise exactly the `n_trains` (at most 64) given trains are used, at full amplitude while
/// the wind is sustained (the wind then sets only the box and its lifecycle; each train's depth
/// sets its frequency, +INFINITY for deep water, and the terrain's depth effects apply on top).
///
/// Returns `OCEAN_STATUS_NULL_POINTER` / `_MISALIGNED_POINTER` for a bad pointer (`trains` is
/// checked only when `n_trains` > 0), `OCEAN_STATUS_NON_FINITE` for a NaN or infinite member
/// (`sustain` may be +INFINITY, a train's `depth` too), `OCEAN_STATUS_INVALID_ARGUMENT` for a
/// member out of range (zero wind speed, zero direction, width or fetch <= 0, negative
/// durations, `trains` outside 1 to 8, negative smoothing or recovery, `has_recovery` not 0 or
/// 1, more than 64 explicit trains, a box longer or wider than 2^24 grid spacings),
/// `OCEAN_STATUS_TOO_STEEP` if explicit trains have k*A > 1 each or a summed k*A above 1,
/// `OCEAN_STATUS_LENGTH_OVERFLOW` for an absurd `n_trains`, `OCEAN_STATUS_OUTSIDE_GRID` when
/// the box's rectangle at full fetch lies wholly outside the water grid. On failure nothing is
/// added and `*out_id` is unchanged.
///
/// # Safety
///
/// `desc` readable, `trains` NULL or `n_trains` readable
/// descriptions, `out_id` writable; nothing is retained.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn ocean_wtb_scene_add_box(
    scene: *mut OceanWtbScene,
    desc: *const OceanBoxDesc,
    trains: *const OceanWaveDesc,
    n_trains: usize,
    out_id: *mut u32,
) -> OceanStatus {
    guard("ocean_wtb_scene_add_box", || {
        let scene = borrow(scene, "scene")?;
        check_ptr(out_id.cast_const(), "out_id")?;
        let mut scene = scene.lock();
        let grid = *scene.grid();
        // SAFETY: forwarded from this function's contract.
        let spec = unsafe { box_spec(&grid, desc, trains, n_trains) }?;
        let id = scene.add_box(spec)?;
        // SAFETY: non-NULL and aligned (checked), writable (caller's guarantee).
        unsafe { out_id.write(id.get()) };
        Ok(())
    })
}

/// Replaces box `id`'s description (same arguments as `ocean_wtb_scene_add_box`): move or turn it
/// (a boat's wake), change its wind or trains. A moved box's action points along its rays are
/// recomputed at the next evaluation.
///
/// Returns `OCEAN_STATUS_NOT_FOUND` for an id that is not in the scene (removed, never issued)
/// and otherwise as `ocean_wtb_scene_add_box`. On failure the box is unchanged.
///
/// # Safety
///
/// As `ocean_wtb_scene_add_box`.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn ocean_wtb_scene_update_box(
    scene: *mut OceanWtbScene,
    id: u32,
    desc: *const OceanBoxDesc,
    trains: *const OceanWaveDesc,
    n_trains: usize,
) -> OceanStatus {
    guard("ocean_wtb_scene_update_box", || {
        let scene = borrow(scene, "scene")?;
        let mut scene = scene.lock();
        let grid = *scene.grid();
        // SAFETY: forwarded from this function's contract.
        let spec = unsafe { box_spec(&grid, desc, trains, n_trains) }?;
        let id = box_id(&scene, id)?;
        scene.update_box(id, spec).map_err(Error::from)
    })
}

/// Removes box `id`. Returns `OCEAN_STATUS_NOT_FOUND` for an id not in the scene (also when
/// it was removed already).
#[unsafe(no_mangle)]
pub extern "C" fn ocean_wtb_scene_remove_box(scene: *mut OceanWtbScene, id: u32) -> OceanStatus {
    guard("ocean_wtb_scene_remove_box", || {
        let scene = borrow(scene, "scene")?;
        let mut scene = scene.lock();
        let id = box_id(&scene, id)?;
        scene.remove_box(id).map_err(Error::from)
    })
}

/// Stores the number of boxes in the scene (alive at any time or not) in `*out_count`.
///
/// # Safety
///
/// `out_count` must be writable.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn ocean_wtb_scene_box_count(
    scene: *const OceanWtbScene,
    out_count: *mut usize,
) -> OceanStatus {
    guard("ocean_wtb_scene_box_count", || {
        let scene = borrow(scene, "scene")?;
        let count = scene.lock().box_ids().count();
        // SAFETY: forwarded from this function's contract.
        unsafe { write_out(out_count, "out_count", count) }
    })
}

/// Enables and parameterises the effects (a budget may run fewer of them).
///
/// Returns `OCEAN_STATUS_NULL_POINTER` / `_MISALIGNED_POINTER`, `OCEAN_STATUS_NON_FINITE` for a
/// NaN or infinite parameter of an enabled effect, `OCEAN_STATUS_INVALID_ARGUMENT` for an
/// unknown refraction, a flag other than 0 or 1, or a parameter out of its range (see
/// `OceanEffects`). On failure the scene keeps its effects.
///
/// # Safety
///
/// `effects` must be readable.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn ocean_wtb_scene_set_effects(
    scene: *mut OceanWtbScene,
    effects: *const OceanEffects,
) -> OceanStatus {
    guard("ocean_wtb_scene_set_effects", || {
        let scene = borrow(scene, "scene")?;
        // SAFETY: forwarded from this function's contract.
        let e = effects_from(
            &unsafe { read_params_checked(effects, "effects") }?,
            "effects",
        )?;
        scene
            .lock()
            .set_effects(e)
            .map_err(|e| wtb_error("effects: ", e))
    })
}

/// Removes any budget limit: every enabled train and effect runs (the default).
#[unsafe(no_mangle)]
pub extern "C" fn ocean_wtb_scene_set_budget_unlimited(scene: *mut OceanWtbScene) -> OceanStatus {
    guard("ocean_wtb_scene_set_budget_unlimited", || {
        let scene = borrow(scene, "scene")?;
        scene
            .lock()
            .set_budget(Budget::Unlimited)
            .map_err(Error::from)
    })
}

/// Limits each evaluation to about `seconds` of estimated work (paper section 2.3): culling
/// first, then trains rank by rank (every visible box's largest train, then its second, ...),
/// then the effects in the order refraction, shoaling, round waves, irregular height, beach,
/// and the noise last, each admitted while the estimate fits. `OceanFrameStats` reports the
/// choice.
///
/// Returns `OCEAN_STATUS_NON_FINITE` for a NaN or infinite `seconds`,
/// `OCEAN_STATUS_INVALID_ARGUMENT` for a negative one; the budget is then unchanged.
#[unsafe(no_mangle)]
pub extern "C" fn ocean_wtb_scene_set_budget_seconds(
    scene: *mut OceanWtbScene,
    seconds: f64,
) -> OceanStatus {
    guard("ocean_wtb_scene_set_budget_seconds", || {
        let scene = borrow(scene, "scene")?;
        check_finite("", &[("seconds", seconds)])?;
        scene
            .lock()
            .set_budget(Budget::Seconds(seconds))
            .map_err(Error::from)
    })
}

/// Fixes each evaluation's work explicitly: at most `max_trains` trains per box (its largest;
/// `SIZE_MAX` for all, 0 for none) and exactly the effects in `*effects` (validated as in
/// `ocean_wtb_scene_set_effects`), whatever the effects enabled with `ocean_wtb_scene_set_effects`.
///
/// # Safety
///
/// `effects` must be readable.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn ocean_wtb_scene_set_budget_explicit(
    scene: *mut OceanWtbScene,
    max_trains: usize,
    effects: *const OceanEffects,
) -> OceanStatus {
    guard("ocean_wtb_scene_set_budget_explicit", || {
        let scene = borrow(scene, "scene")?;
        // SAFETY: forwarded from this function's contract.
        let e = effects_from(
            &unsafe { read_params_checked(effects, "effects") }?,
            "effects",
        )?;
        scene
            .lock()
            .set_budget(Budget::Explicit(Selection {
                max_trains,
                effects: e,
            }))
            .map_err(|e| wtb_error("effects: ", e))
    })
}

/// The frustum of the caller's camera, read (copied) before any output is touched; none for
/// NULL.
///
/// # Safety
///
/// `camera` must be NULL, misaligned, or point to a readable `OceanCamera`.
unsafe fn frustum(camera: *const OceanCamera) -> Result<Option<Frustum>, Error> {
    if camera.is_null() {
        return Ok(None);
    }
    // SAFETY: forwarded from this function's contract.
    let camera = unsafe { read_camera(camera) }?;
    Frustum::from_view_projection(camera.view_projection_f64(), camera.depth())
        .map(Some)
        .map_err(|e| {
            let status = match e {
                FrustumError::NotFinite(_) => OceanStatus::NonFinite,
                _ => OceanStatus::InvalidArgument,
            };
            Error::new(status, format!("camera: no frustum: {e}"))
        })
}

/// Evaluates the whole water grid at `time` seconds into the caller's buffers.
///
/// For grid point (i, j), element j*nx + i of `out_pos` receives its displaced position
/// **relative to the grid origin** (rest position (i*spacing, 0, j*spacing), so float precision
/// does not degrade far from the world origin; add (origin_x, 0, origin_z) for world space),
/// and `out_normal` the unit surface normal (right-handed, y up). Each frame is recomputed from
/// the rest state (the paper's frame independence): any time may be evaluated in any order.
/// Boxes that are alive at `time` add their trains, modulated by land (zero on land, recovering
/// behind it), depth (shoaling, refraction), the side smoothing and the enabled effects; grid
/// points on land stay exactly at rest.
///
/// `camera`: NULL for no culling, or the camera the frame is drawn with (`OceanCamera`). A box
/// whose bounding box (raised by the maximum heights of all boxes that overlap it) lies wholly
/// outside its frustum is skipped: its
/// points stay at rest in this frame. Height queries never cull.
///
/// `n` must equal nx * nz. `out_stats`, when not NULL, receives what ran.
///
/// Returns `OCEAN_STATUS_NULL_POINTER` / `_MISALIGNED_POINTER` for a bad pointer (4-byte
/// alignment for OceanVec3, 8 for the camera and stats), `OCEAN_STATUS_EMPTY` if `n`
/// is 0, `OCEAN_STATUS_LENGTH_OVERFLOW` if `n * sizeof(OceanVec3)` exceeds `PTRDIFF_MAX`,
/// `OCEAN_STATUS_LENGTH_MISMATCH` if `n` != nx * nz, `OCEAN_STATUS_INVALID_ARGUMENT` if the
/// outputs overlap or the camera is not one `OceanCamera` accepts, `OCEAN_STATUS_NON_FINITE`
/// for a NaN or infinite `time` or matrix element. Nothing is written on failure.
///
/// # Safety
///
/// `camera` NULL or a readable `OceanCamera`, `out_pos` and
/// `out_normal` `n` writable `OceanVec3`s each, `out_stats` NULL or writable; no other thread
/// may touch the buffers during the call.
#[unsafe(no_mangle)]
#[allow(clippy::too_many_arguments)]
pub unsafe extern "C" fn ocean_wtb_scene_evaluate(
    scene: *mut OceanWtbScene,
    time: f64,
    camera: *const OceanCamera,
    out_pos: *mut OceanVec3,
    out_normal: *mut OceanVec3,
    n: usize,
    out_stats: *mut OceanFrameStats,
) -> OceanStatus {
    // SAFETY: forwarded from this function's contract.
    unsafe {
        evaluate(
            "ocean_wtb_scene_evaluate",
            false,
            scene,
            time,
            camera,
            out_pos,
            out_normal,
            n,
            out_stats,
        )
    }
}

/// `ocean_wtb_scene_evaluate` for buffers kept from frame to frame (an engine's vertex buffers):
/// only the part of the grid that the visible boxes cover now, or covered at the previous call,
/// is written, with exactly the values `ocean_wtb_scene_evaluate` would write; the rest of the
/// buffers already holds the sea at rest. A frame in which no box is visible, after one with
/// none either, writes nothing.
///
/// Pass the same two buffers to every call. The first call after `ocean_wtb_scene_create` or
/// `ocean_wtb_scene_reset_coverage` writes the whole grid. With noise or run-up enabled the whole
/// grid changes and is written every time. Arguments, statuses and safety as for
/// `ocean_wtb_scene_evaluate`.
///
/// # Safety
///
/// As `ocean_wtb_scene_evaluate`.
#[unsafe(no_mangle)]
#[allow(clippy::too_many_arguments)]
pub unsafe extern "C" fn ocean_wtb_scene_evaluate_incremental(
    scene: *mut OceanWtbScene,
    time: f64,
    camera: *const OceanCamera,
    out_pos: *mut OceanVec3,
    out_normal: *mut OceanVec3,
    n: usize,
    out_stats: *mut OceanFrameStats,
) -> OceanStatus {
    // SAFETY: forwarded from this function's contract.
    unsafe {
        evaluate(
            "ocean_wtb_scene_evaluate_incremental",
            true,
            scene,
            time,
            camera,
            out_pos,
            out_normal,
            n,
            out_stats,
        )
    }
}

/// Forgets what `ocean_wtb_scene_evaluate_incremental` wrote: its next call writes the whole grid.
/// Call it before passing other buffers.
///
/// Returns `OCEAN_STATUS_NULL_POINTER` or `OCEAN_STATUS_MISALIGNED_POINTER` for a bad handle.
#[unsafe(no_mangle)]
pub extern "C" fn ocean_wtb_scene_reset_coverage(scene: *mut OceanWtbScene) -> OceanStatus {
    guard("ocean_wtb_scene_reset_coverage", || {
        let scene = borrow(scene, "scene")?;
        let grid = *scene.lock().grid();
        *scene
            .coverage
            .lock()
            .unwrap_or_else(PoisonError::into_inner) = Coverage::everything(&grid);
        Ok(())
    })
}

/// The body of `ocean_wtb_scene_evaluate` and `ocean_wtb_scene_evaluate_incremental`.
///
/// # Safety
///
/// As `ocean_wtb_scene_evaluate`.
#[allow(clippy::too_many_arguments)]
unsafe fn evaluate(
    name: &'static str,
    incremental: bool,
    scene: *mut OceanWtbScene,
    time: f64,
    camera: *const OceanCamera,
    out_pos: *mut OceanVec3,
    out_normal: *mut OceanVec3,
    n: usize,
    out_stats: *mut OceanFrameStats,
) -> OceanStatus {
    guard(name, || {
        let scene_handle = borrow(scene, "scene")?;
        let scene = &*scene_handle;
        if !camera.is_null() {
            check_ptr(camera, "camera")?;
        }
        check_ptr(out_pos.cast_const(), "out_pos")?;
        check_ptr(out_normal.cast_const(), "out_normal")?;
        if !out_stats.is_null() {
            check_ptr(out_stats.cast_const(), "out_stats")?;
        }
        if n == 0 {
            return Err(Error::new(
                OceanStatus::Empty,
                "`n` is 0: it must be the grid's point count nx * nz",
            ));
        }
        let bytes = byte_len::<OceanVec3>(n, "out_pos")?;
        let pos_range = (out_pos.cast_const().cast::<u8>(), bytes, "out_pos");
        let nrm_range = (out_normal.cast_const().cast::<u8>(), bytes, "out_normal");
        check_disjoint(pos_range, nrm_range)?;
        if !out_stats.is_null() {
            let stats_range = (
                out_stats.cast_const().cast::<u8>(),
                size_of::<OceanFrameStats>(),
                "out_stats",
            );
            check_disjoint(pos_range, stats_range)?;
            check_disjoint(nrm_range, stats_range)?;
        }
        check_time(time)?;
        // SAFETY: forwarded from this function's contract.
        let view = unsafe { frustum(camera) }?;
        let mut coverage = scene
            .coverage
            .lock()
            .unwrap_or_else(PoisonError::into_inner);
        let mut scene = scene.lock();
        let grid = *scene.grid();
        check_len(
            "n",
            n,
            grid.len(),
            &format!("the {} x {} water grid", grid.nx(), grid.nz()),
        )?;
        let frame = scene.frame(time, view.as_ref())?;
        // SAFETY: both pointers are non-NULL and aligned, the byte size fits in isize and the
        // ranges are disjoint (all checked above); the caller guarantees `n` writable elements
        // in each, untouched by others during the call.
        let (pos, nrm) = unsafe {
            (
                core::slice::from_raw_parts_mut(out_pos, n),
                core::slice::from_raw_parts_mut(out_normal, n),
            )
        };
        let pos: &mut [Vec3] = bytemuck::cast_slice_mut(pos);
        let nrm: &mut [Vec3] = bytemuck::cast_slice_mut(nrm);
        if incremental {
            frame.evaluate_incremental(&mut coverage, pos, nrm)?;
        } else {
            frame.evaluate_par(pos, nrm)?;
        }
        let stats = stats_to(frame.stats());
        *scene_handle.evaluated() = Some(Evaluated {
            time,
            view,
            revision: scene.revision(),
        });
        if !out_stats.is_null() {
            // SAFETY: non-NULL and aligned (checked), writable and disjoint from the outputs
            // (checked; the slices above are no longer used).
            unsafe { out_stats.write(stats) };
        }
        Ok(())
    })
}

crate::boundary::handle::handles!(OceanWtbScene);

#[cfg(test)]
#[path = "wtb_tests.rs"]
mod tests;
