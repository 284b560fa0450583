//! Wave Train Boxes scenes (crate `ocean-wtb`, Yrjola & Larsson): a water grid over a terrain,
//! wind-driven boxes of Gerstner wave trains, switchable effects, a frame budget, evaluation of
//! the grid and batched height queries.

use core::mem::size_of;
use std::sync::{Mutex, MutexGuard, PoisonError};

use glam::{DVec2, Vec3};
use ocean_core::frustum::{Frustum, FrustumError};
use ocean_core::{WaveDesc, WaveError};
use ocean_wtb::budget::{Budget, Selection};
use ocean_wtb::effects::{Beach, Effects, Irregular, Noise, Refraction};
use ocean_wtb::scene::{BoxId, BoxSpec, Coverage, FrameStats, Scene, rectangles_overlap};
use ocean_wtb::wind::MAX_EXPLICIT_TRAINS;
use ocean_wtb::{BoxFrame, Terrain, TrainSource, WaterGrid, Wind, WtbError};

use crate::boundary::OceanNext;
use crate::boundary::{
    CEnum, CheckedStruct, EnumField, borrow, byte_len, check_chain, check_disjoint, check_finite,
    check_flag, check_len, check_ptr, check_reserved, check_time, destroy, read_in, read_params,
    read_params_checked, write_handle, write_out,
};
use crate::camera::{OceanCamera, read_camera};
use crate::status::{Error, OceanStatus, guard};
use crate::waves::{OceanVec3, OceanWaveDesc, eval_error, wave_desc_in, wave_error};

/// The water grid of a scene: `nx * nz` points, point (i, j) resting at world
/// (origin_x + i*spacing, 0, origin_z + j*spacing), stored row-major at j*nx + i. The spacing is
/// the same along x and z (a box's internal frame steps by it along both of its axes).
#[repr(C)]
#[derive(Clone, Copy, Debug, Default, PartialEq, bytemuck::Zeroable, bytemuck::Pod)]
pub struct OceanWaterGridDesc {
    /// World x of point (0, 0), metres, finite, |origin_x| <= 1e9.
    pub origin_x: f64,
    /// World z of point (0, 0), metres, finite, |origin_z| <= 1e9.
    pub origin_z: f64,
    /// Distance between neighbouring points along x and z, metres, in [1e-3, 1e4].
    pub spacing: f64,
    /// Columns (along x), 2 to 4096.
    pub nx: usize,
    /// Rows (along z), 2 to 4096.
    pub nz: usize,
}

/// A wind, which creates one wave train box (paper section 2).
///
/// The box is the rectangle origin + a*u + b*v, a in [0, length], b in [0, width], with u the
/// unit wind direction and v = (-u.z, u.x) (u turned 90 degrees clockwise seen from above, so
/// for u = +x, v = +z): `origin` is the rear corner on the left when looking along the wind.
/// Its length grows from 0 to `fetch` during the build-up. Fully developed, the trains reach a
/// crest-to-trough height H = 0.21 speed^2 / 9.81 (Eq. 1): their amplitudes sum to H/2.
///
/// Lifecycle, with age = time - start: build-up for age in [0, build_up) (length and amplitude
/// grow linearly from 0), sustain for `sustain` seconds at full size, then decay for `decay`
/// seconds (amplitude falls linearly to 0); before `start` and after the decay the box does not
/// exist.
#[repr(C)]
#[derive(Clone, Copy, Debug, Default, PartialEq, bytemuck::Zeroable, bytemuck::Pod)]
pub struct OceanWindDesc {
    /// Extensions: NULL, or the first extension struct (see `OceanChain`); the `_default`
    /// function sets NULL.
    pub next: OceanNext,
    /// Wind speed, m/s, in (0, 100]. A zero wind is refused.
    pub speed: f64,
    /// x component of the direction the wind blows towards; with `direction_z` a finite,
    /// non-zero vector (normalised here).
    pub direction_x: f64,
    /// z component of the wind direction.
    pub direction_z: f64,
    /// World x of the box's origin corner, metres, |origin_x| <= 1e9.
    pub origin_x: f64,
    /// World z of the box's origin corner, metres, |origin_z| <= 1e9.
    pub origin_z: f64,
    /// Width across the wind, metres, in (0, 1e7] and at most 2^24 grid spacings.
    pub width: f64,
    /// Fetch: the full length along the wind, metres, in (0, 1e7] and at most 2^24 grid
    /// spacings.
    pub fetch: f64,
    /// Time the wind starts, seconds, finite.
    pub start: f64,
    /// Build-up duration, seconds, finite and >= 0.
    pub build_up: f64,
    /// Sustain duration, seconds, >= 0; `INFINITY` for a wind that never dies.
    pub sustain: f64,
    /// Decay duration, seconds, finite and >= 0.
    pub decay: f64,
    /// Seed of the documented wind-to-trains mapping (PCG32); the same seed gives the same
    /// trains on every platform.
    pub seed: u64,
    /// Number of wave trains the wind raises, 1 to 8 (ignored when explicit trains are given).
    pub trains: u32,
    /// Must be 0: room for a later member (the `_default` functions set it), and no padding
    /// the caller cannot see.
    pub reserved: u32,
}

/// A wave train box: its wind and its local parameters.
#[repr(C)]
#[derive(Clone, Copy, Debug, Default, PartialEq, bytemuck::Zeroable, bytemuck::Pod)]
pub struct OceanBoxDesc {
    /// Extensions: NULL, or the first extension struct (see `OceanChain`); the `_default`
    /// function sets NULL.
    pub next: OceanNext,
    /// The wind that raises the box.
    pub wind: OceanWindDesc,
    /// Width of the smoothing area along the box's edges, metres, finite and >= 0: the
    /// amplitude rises linearly from 0 on an edge to full at this distance inside (Fig. 4);
    /// 0 gives hard edges.
    pub smoothing: f64,
    /// 1: `recovery` is used; 0: the recovery distance is the default, two peak wavelengths.
    /// Other values are refused.
    pub has_recovery: u32,
    /// Must be 0: room for a later member (the `_default` functions set it), and no padding
    /// the caller cannot see.
    pub reserved: u32,
    /// Distance behind land over which the amplitude recovers linearly to full, metres, finite
    /// and >= 0 (0: at once). Read only when `has_recovery` is 1.
    pub recovery: f64,
}

/// Depth refraction (paper section 2.1), for `OceanEffects::refraction`.
#[repr(u32)]
#[derive(
    Clone, Copy, Debug, Default, PartialEq, Eq, bytemuck::NoUninit, bytemuck::CheckedBitPattern,
)]
pub enum OceanRefraction {
    /// No depth-dependent phase.
    #[default]
    Off = 0,
    /// The paper's default: a depth-dependent phase lag accumulated along each wave ray, so
    /// fronts bend towards shallow water while the frequency never changes (Fig. 6).
    PhaseShift = 1,
    /// Each point runs at its depth's frequency from the dispersion relation (Eq. 4): waves
    /// slow down and queue up towards land as time passes (Fig. 7). Offered for comparison.
    Dispersion = 2,
}

impl CEnum for OceanRefraction {
    const REFUSAL: &'static str = "is not an OceanRefraction (0, 1 or 2)";
}

/// Irregular height along the box's width (Eq. 8):
/// A' = A (1 - scale sin(envelope_wavenumber (a - envelope_speed t)) sin(frequency b)), with
/// (a, b) the box's internal coordinates.
#[repr(C)]
#[derive(
    Clone, Copy, Debug, Default, PartialEq, bytemuck::NoUninit, bytemuck::CheckedBitPattern,
)]
pub struct OceanIrregular {
    /// 1: on; 0: off (the other members are then ignored). Other values are refused.
    pub enabled: u32,
    /// Must be 0: room for a later member (the `_default` functions set it), and no padding
    /// the caller cannot see.
    pub reserved: u32,
    /// Share of the amplitude, in [0, 1].
    pub scale: f64,
    /// Radians per metre across the box, finite and >= 0.
    pub frequency: f64,
    /// Wavenumber of the envelope along the box, radians per metre, finite and >= 0.
    pub envelope_wavenumber: f64,
    /// Speed of the envelope along the box, m/s, finite.
    pub envelope_speed: f64,
}

/// Capillary noise on every grid point, inside boxes or not (Eq. 9): y' = y + amplitude
/// sin(r t), with a rate r in [0, 1) hashed from the seed and the point's index, so it is
/// deterministic and independent of threads.
#[repr(C)]
#[derive(
    Clone, Copy, Debug, Default, PartialEq, bytemuck::NoUninit, bytemuck::CheckedBitPattern,
)]
pub struct OceanNoise {
    /// 1: on; 0: off (the other members are then ignored). Other values are refused.
    pub enabled: u32,
    /// Must be 0: room for a later member (the `_default` functions set it), and no padding
    /// the caller cannot see.
    pub reserved: u32,
    /// Amplitude, metres, finite and >= 0.
    pub amplitude: f64,
    /// Seed of the per-point rates.
    pub seed: u64,
}

/// Beach adjustments (end of paper section 2): the summed amplitude is capped at a share of
/// the local depth so troughs stay above the sea floor, and the water level rises near the
/// shore.
#[repr(C)]
#[derive(
    Clone, Copy, Debug, Default, PartialEq, bytemuck::NoUninit, bytemuck::CheckedBitPattern,
)]
pub struct OceanBeach {
    /// 1: on; 0: off (the other members are then ignored). Other values are refused.
    pub enabled: u32,
    /// Must be 0: room for a later member (the `_default` functions set it), and no padding
    /// the caller cannot see.
    pub reserved: u32,
    /// Largest share of the local depth the summed amplitude may take, in (0, 1].
    pub max_depth_share: f64,
    /// Extra water level at the shoreline, metres, finite and >= 0.
    pub run_up: f64,
    /// Depth at which the run-up has faded out, metres, finite and >= 0.
    pub run_up_depth: f64,
}

/// The switchable effects of paper section 2.1. `ocean_wtb_effects_default` fills in the library's
/// defaults (phase-shift refraction and shoaling on, everything else off).
#[repr(C)]
#[derive(
    Clone, Copy, Debug, Default, PartialEq, bytemuck::NoUninit, bytemuck::CheckedBitPattern,
)]
pub struct OceanEffects {
    /// Extensions: NULL, or the first extension struct (see `OceanChain`); the `_default`
    /// function sets NULL.
    pub next: OceanNext,
    /// Depth refraction (other values are refused).
    pub refraction: OceanRefraction,
    /// 1: shoaling on (Green's law: the amplitude grows as (D_ref/D)^(1/4) in water shallower
    /// than half a wavelength, at most 1.5 times); 0: off. Other values are refused.
    pub shoaling: u32,
    /// 1: round waves on (Eq. 10: fronts curve forward around the middle of each box); 0: off.
    /// Other values are refused.
    pub round_waves: u32,
    /// Must be 0: room for a later member (the `_default` functions set it), and no padding
    /// the caller cannot see.
    pub reserved: u32,
    /// Irregular height (Eq. 8).
    pub irregular: OceanIrregular,
    /// Capillary noise (Eq. 9).
    pub noise: OceanNoise,
    /// Beach adjustments.
    pub beach: OceanBeach,
}

/// What one evaluation ran.
#[repr(C)]
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct OceanFrameStats {
    /// Boxes alive at the frame's time.
    pub alive: usize,
    /// Of those, culled by the view frustum.
    pub culled: usize,
    /// Boxes whose static modulation (land, shoaling, refraction along the rays) was recomputed
    /// this frame because they are new, moved, grew, or the terrain or effects changed.
    pub rebuilt: usize,
    /// Wave trains evaluated, over all boxes.
    pub trains: usize,
    /// The budget's choice: at most this many trains per box (its largest); `SIZE_MAX` for all.
    pub max_trains: usize,
    /// The budget's choice: the effects that ran (a subset of those enabled).
    pub effects: OceanEffects,
    /// The cost model's estimate of the frame's work, seconds of one core.
    pub estimated_seconds: f64,
    /// Trains weighted down in the geometry by the scene's train filter (they span too few
    /// grid cells to be drawn whole; see `ocean_wtb_scene_set_train_filter`), those left out
    /// included.
    pub filtered_trains: usize,
    /// Of those, the trains left out entirely (shorter than the filter's `min_cells`).
    pub removed_trains: usize,
    /// The slope variance the geometry leaves out, sum over the filtered trains of
    /// ((1 - w_p) k A)^2 / 2: add it to the BRDF's roughness (where a box's modulation is at
    /// most 1, the variance of the missing slopes is at most this).
    pub filtered_slope_variance: f64,
}

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

/// The error of a crate call as a status, with the crate's message (`?` converts).
impl From<WtbError> for Error {
    fn from(e: WtbError) -> Self {
        wtb_error("", e)
    }
}

/// The status of an `ocean-wtb` error, and its message prefixed with `context`.
pub(crate) fn wtb_error(context: &str, e: WtbError) -> Error {
    let status = match e {
        WtbError::NotFinite(_) | WtbError::TerrainNotFinite { .. } => OceanStatus::NonFinite,
        WtbError::TooSteep { .. } => OceanStatus::TooSteep,
        WtbError::Wave { index, source } => return wave_error(index, source),
        WtbError::UnknownBox(_) => OceanStatus::NotFound,
        WtbError::OutsideGrid => OceanStatus::OutsideGrid,
        // The scene evaluates its own grid points: an `EvalError` there names none of the
        // caller's arguments, and the checks of boxes and effects are meant to exclude it.
        WtbError::Eval(ocean_core::EvalError::Position { index }) => {
            return Error::new(
                OceanStatus::InvalidArgument,
                format!(
                    "{context}the evaluation gave a non-finite value at water grid point {index}: \
                     a box's or an effect's parameters drive it out of range"
                ),
            );
        }
        WtbError::Eval(e) => return eval_error(e, "xz"),
        _ => OceanStatus::InvalidArgument,
    };
    Error::new(status, format!("{context}{e}"))
}

/// Explicit trains: errors name `trains[i]`.
fn trains_error(e: WtbError) -> Error {
    match e {
        WtbError::Wave { index, source } => {
            let status = match source {
                WaveError::TooSteep(_) => OceanStatus::TooSteep,
                _ => OceanStatus::InvalidArgument,
            };
            Error::new(status, format!("trains[{index}]: {source}"))
        }
        e => wtb_error("trains: ", e),
    }
}

impl CheckedStruct for OceanEffects {
    const ENUM_FIELDS: &'static [EnumField] = &[EnumField::of::<OceanRefraction>(
        "refraction",
        core::mem::offset_of!(OceanEffects, refraction),
    )];
}

fn refraction_from(v: OceanRefraction) -> Refraction {
    match v {
        OceanRefraction::Off => Refraction::Off,
        OceanRefraction::PhaseShift => Refraction::PhaseShift,
        OceanRefraction::Dispersion => Refraction::Dispersion,
    }
}

fn effects_from(e: &OceanEffects, name: &str) -> Result<Effects, Error> {
    let refraction = refraction_from(e.refraction);
    let shoaling = check_flag(&format!("{name}->shoaling"), e.shoaling)?;
    let round_waves = check_flag(&format!("{name}->round_waves"), e.round_waves)?;
    check_reserved(&format!("{name}->reserved"), e.reserved)?;
    let irregular_on = check_flag(&format!("{name}->irregular.enabled"), e.irregular.enabled)?;
    check_reserved(&format!("{name}->irregular.reserved"), e.irregular.reserved)?;
    let irregular = if irregular_on {
        let p = &e.irregular;
        check_finite(
            &format!("{name}->irregular."),
            &[
                ("scale", p.scale),
                ("frequency", p.frequency),
                ("envelope_wavenumber", p.envelope_wavenumber),
                ("envelope_speed", p.envelope_speed),
            ],
        )?;
        Some(Irregular {
            scale: p.scale,
            frequency: p.frequency,
            envelope_wavenumber: p.envelope_wavenumber,
            envelope_speed: p.envelope_speed,
        })
    } else {
        None
    };
    let noise_on = check_flag(&format!("{name}->noise.enabled"), e.noise.enabled)?;
    check_reserved(&format!("{name}->noise.reserved"), e.noise.reserved)?;
    let noise = if noise_on {
        check_finite(
            &format!("{name}->noise."),
            &[("amplitude", e.noise.amplitude)],
        )?;
        Some(Noise {
            amplitude: e.noise.amplitude,
            seed: e.noise.seed,
        })
    } else {
        None
    };
    let beach_on = check_flag(&format!("{name}->beach.enabled"), e.beach.enabled)?;
    check_reserved(&format!("{name}->beach.reserved"), e.beach.reserved)?;
    let beach = if beach_on {
        let b = &e.beach;
        check_finite(
            &format!("{name}->beach."),
            &[
                ("max_depth_share", b.max_depth_share),
                ("run_up", b.run_up),
                ("run_up_depth", b.run_up_depth),
            ],
        )?;
        Some(Beach {
            max_depth_share: b.max_depth_share,
            run_up: b.run_up,
            run_up_depth: b.run_up_depth,
        })
    } else {
        None
    };
    Ok(Effects {
        refraction,
        shoaling,
        irregular,
        noise,
        round_waves,
        beach,
    })
}

fn effects_to(e: &Effects) -> OceanEffects {
    let refraction = match e.refraction {
        Refraction::Off => OceanRefraction::Off,
        Refraction::PhaseShift => OceanRefraction::PhaseShift,
        Refraction::Dispersion => OceanRefraction::Dispersion,
    };
    OceanEffects {
        next: OceanNext::NULL,
        refraction,
        shoaling: u32::from(e.shoaling),
        round_waves: u32::from(e.round_waves),
        reserved: 0,
        irregular: e
            .irregular
            .map_or_else(OceanIrregular::default, |p| OceanIrregular {
                enabled: 1,
                reserved: 0,
                scale: p.scale,
                frequency: p.frequency,
                envelope_wavenumber: p.envelope_wavenumber,
                envelope_speed: p.envelope_speed,
            }),
        noise: e.noise.map_or_else(OceanNoise::default, |n| OceanNoise {
            enabled: 1,
            reserved: 0,
            amplitude: n.amplitude,
            seed: n.seed,
        }),
        beach: e.beach.map_or_else(OceanBeach::default, |b| OceanBeach {
            enabled: 1,
            reserved: 0,
            max_depth_share: b.max_depth_share,
            run_up: b.run_up,
            run_up_depth: b.run_up_depth,
        }),
    }
}

pub(crate) fn stats_to(s: &FrameStats) -> OceanFrameStats {
    let selection = s.selection.unwrap_or(Selection {
        max_trains: usize::MAX,
        effects: Effects::default(),
    });
    OceanFrameStats {
        alive: s.alive,
        culled: s.culled,
        rebuilt: s.rebuilt,
        trains: s.trains,
        max_trains: selection.max_trains,
        effects: effects_to(&selection.effects),
        estimated_seconds: s.estimated_ns * 1e-9,
        filtered_trains: s.filtered_trains,
        removed_trains: s.removed_trains,
        filtered_slope_variance: s.filtered_slope_variance,
    }
}

/// Reads and validates a grid description.
/// The water grid described by `g`, checked; messages name it `name` (the argument).
pub(crate) fn water_grid(g: &OceanWaterGridDesc, name: &str) -> Result<WaterGrid, Error> {
    if g.nx == 0 || g.nz == 0 {
        return Err(Error::new(
            OceanStatus::Empty,
            format!("{name} is {} x {}: both sizes must be >= 2", g.nx, g.nz),
        ));
    }
    g.nx.checked_mul(g.nz).ok_or_else(|| {
        Error::new(
            OceanStatus::LengthOverflow,
            format!("{name} point count {} x {} overflows size_t", g.nx, g.nz),
        )
    })?;
    check_finite(
        &format!("{name}->"),
        &[
            ("origin_x", g.origin_x),
            ("origin_z", g.origin_z),
            ("spacing", g.spacing),
        ],
    )?;
    WaterGrid::new(DVec2::new(g.origin_x, g.origin_z), g.spacing, g.nx, g.nz)
        .map_err(|e| wtb_error(&format!("{name}: "), e))
}

/// The pointer checks of [`terrain`], which `ocean_wtb_scene_create` makes before the grid's
/// counts and values (the header's error order): NULL with a length, or misaligned.
fn check_terrain_ptr(heights: *const f32, len: usize) -> Result<(), Error> {
    if heights.is_null() {
        if len != 0 {
            return Err(Error::new(
                OceanStatus::NullPointer,
                format!(
                    "`terrain_heights` is NULL but `terrain_len` is {len} (pass NULL and 0 for \
                     a deep sea)"
                ),
            ));
        }
        return Ok(());
    }
    check_ptr(heights, "terrain_heights")
}

/// A terrain from the caller's heights: NULL with length 0 is deep sea.
///
/// # Safety
///
/// `heights` must be NULL or point to `len` readable floats.
unsafe fn terrain(grid: &WaterGrid, heights: *const f32, len: usize) -> Result<Terrain, Error> {
    check_terrain_ptr(heights, len)?;
    if heights.is_null() {
        return Ok(Terrain::deep(grid));
    }
    byte_len::<f32>(len, "terrain_heights")?;
    check_len(
        "terrain_len",
        len,
        grid.len(),
        &format!(
            "the {} x {} water grid (one height per point, row-major)",
            grid.nx(),
            grid.nz()
        ),
    )?;
    // SAFETY: non-NULL and aligned (checked), the byte size fits in isize (checked), and the
    // caller guarantees `len` readable floats that nobody writes during the call.
    let h = unsafe { core::slice::from_raw_parts(heights, len) };
    Terrain::from_slice(grid, h).map_err(|e| wtb_error("terrain_heights: ", e))
}

/// Reads a box description and its explicit trains, and checks them against the scene's grid.
///
/// # Safety
///
/// `desc` must be NULL, misaligned or readable; `trains` NULL, misaligned or `n_trains`
/// readable descriptions.
unsafe fn box_spec(
    grid: &WaterGrid,
    desc: *const OceanBoxDesc,
    trains: *const OceanWaveDesc,
    n_trains: usize,
) -> Result<BoxSpec, Error> {
    check_ptr(desc, "desc")?;
    if n_trains > 0 {
        check_ptr(trains, "trains")?;
    }
    // SAFETY: forwarded from this function's contract.
    let d = unsafe { read_params(desc, "desc") }?;
    let w = &d.wind;
    // SAFETY: forwarded from this function's contract (the extensions of the wind are
    // readable as the box's are).
    unsafe { check_chain(w, "desc->wind.next") }?;
    check_finite(
        "desc->wind.",
        &[
            ("speed", w.speed),
            ("direction_x", w.direction_x),
            ("direction_z", w.direction_z),
            ("origin_x", w.origin_x),
            ("origin_z", w.origin_z),
            ("width", w.width),
            ("fetch", w.fetch),
            ("start", w.start),
            ("build_up", w.build_up),
            ("decay", w.decay),
        ],
    )?;
    if w.sustain.is_nan() || w.sustain == f64::NEG_INFINITY {
        return Err(Error::new(
            OceanStatus::NonFinite,
            format!(
                "desc->wind.sustain must be finite seconds or +INFINITY (never dies), got {}",
                w.sustain
            ),
        ));
    }
    check_reserved("desc->wind.reserved", w.reserved)?;
    check_finite("desc->", &[("smoothing", d.smoothing)])?;
    let has_recovery = check_flag("desc->has_recovery", d.has_recovery)?;
    check_reserved("desc->reserved", d.reserved)?;
    let recovery = if has_recovery {
        check_finite("desc->", &[("recovery", d.recovery)])?;
        Some(d.recovery)
    } else {
        None
    };
    if w.speed == 0.0 {
        return Err(Error::new(
            OceanStatus::InvalidArgument,
            "desc->wind.speed is 0: a wind that does not blow raises no waves (speed in [0.1, 100] m/s)",
        ));
    }
    let wind = Wind {
        speed: w.speed,
        direction: DVec2::new(w.direction_x, w.direction_z),
        origin: DVec2::new(w.origin_x, w.origin_z),
        width: w.width,
        fetch: w.fetch,
        start: w.start,
        build_up: w.build_up,
        sustain: w.sustain,
        decay: w.decay,
        seed: w.seed,
        trains: w.trains,
    };
    let explicit = if n_trains == 0 {
        None
    } else {
        check_ptr(trains, "trains")?;
        byte_len::<OceanWaveDesc>(n_trains, "trains")?;
        if n_trains > MAX_EXPLICIT_TRAINS {
            return Err(Error::new(
                OceanStatus::InvalidArgument,
                format!("`n_trains` is {n_trains}: a box takes at most {MAX_EXPLICIT_TRAINS}"),
            ));
        }
        // SAFETY: non-NULL and aligned (checked), the byte size fits in isize (checked), and the
        // caller guarantees `n_trains` readable descriptions that nobody writes during the call.
        let src = unsafe { core::slice::from_raw_parts(trains, n_trains) };
        let descs: Vec<WaveDesc> = src
            .iter()
            .enumerate()
            .map(|(i, t)| wave_desc_in("trains", i, t))
            .collect::<Result<_, _>>()?;
        Some(descs)
    };
    wind.validate().map_err(|e| wtb_error("desc->wind: ", e))?;
    check_reaches_grid(grid, &wind)?;
    let source = match explicit {
        None => TrainSource::FromWind,
        Some(descs) => {
            let source = TrainSource::Explicit(descs);
            source.resolve(&wind).map_err(trains_error)?;
            source
        }
    };
    Ok(BoxSpec {
        wind,
        trains: source,
        smoothing: d.smoothing,
        recovery,
    })
}

/// Fails with `OCEAN_STATUS_OUTSIDE_GRID` when the box's rectangle at its full fetch cannot
/// touch the water grid's rectangle (a separating-axis test; touching counts as reaching).
fn check_reaches_grid(grid: &WaterGrid, wind: &Wind) -> Result<(), Error> {
    let s = grid.spacing();
    let full =
        BoxFrame::new(wind.origin, wind.direction, wind.fetch, wind.width, s).map_err(|e| {
            wtb_error(
                "desc->wind: the box at full fetch, in units of the grid spacing: ",
                e,
            )
        })?;
    let extent = grid.max_corner() - grid.origin();
    let whole = BoxFrame::new(grid.origin(), DVec2::X, extent.x, extent.y, s)
        .map_err(|e| wtb_error("grid: ", e))?;
    if rectangles_overlap(&full, &whole) {
        return Ok(());
    }
    let (o, u, v) = (
        full.origin(),
        full.u() * full.length(),
        full.v() * full.width(),
    );
    let (lo, hi) = (grid.origin(), grid.max_corner());
    Err(Error::new(
        OceanStatus::OutsideGrid,
        format!(
            "the box (corners ({:.3}, {:.3}), ({:.3}, {:.3}), ({:.3}, {:.3}), ({:.3}, {:.3}) at \
             full fetch) lies wholly outside the water grid [{}, {}] x [{}, {}]: it could never \
             move a point",
            o.x,
            o.y,
            (o + u).x,
            (o + u).y,
            (o + u + v).x,
            (o + u + v).y,
            (o + v).x,
            (o + v).y,
            lo.x,
            hi.x,
            lo.y,
            hi.y
        ),
    ))
}

/// The box with the caller's id.
fn box_id(scene: &Scene, id: u32) -> Result<BoxId, Error> {
    scene.box_ids().find(|b| b.get() == id).ok_or_else(|| {
        Error::new(
            OceanStatus::NotFound,
            format!("no box with id {id} in this scene (removed, never added, or another scene's)"),
        )
    })
}

/// Stores the library's default effects in `*out`: refraction `OCEAN_REFRACTION_PHASE_SHIFT`,
/// shoaling on, round waves, irregular height, noise and beach off (as a new scene has them).
///
/// Returns `OCEAN_STATUS_NULL_POINTER` (or `_MISALIGNED_POINTER`) for a bad `out`, which is
/// then left unchanged.
///
/// # Safety
///
/// `out` must be writable.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn ocean_wtb_effects_default(out: *mut OceanEffects) -> OceanStatus {
    guard("ocean_wtb_effects_default", || {
        // SAFETY: forwarded from this function's contract.
        unsafe { write_out(out, "out", effects_to(&Effects::default())) }
    })
}

/// The wind of `ocean_wtb_wind_desc_default`: 10 m/s (the spectrum's default wind, so H =
/// 0.21 * 10^2 / 9.81 = 2.14 m fully developed, Eq. 1) blowing towards +x from the origin over a
/// box 100 m wide with a fetch of 200 m; fully grown at once and never dying (start 0, no
/// build-up, sustain `INFINITY`, no decay); seed 0 and 3 trains.
pub(crate) const DEFAULT_WIND: OceanWindDesc = OceanWindDesc {
    next: OceanNext::NULL,
    speed: 10.0,
    direction_x: 1.0,
    direction_z: 0.0,
    origin_x: 0.0,
    origin_z: 0.0,
    width: 100.0,
    fetch: 200.0,
    start: 0.0,
    build_up: 0.0,
    sustain: f64::INFINITY,
    decay: 0.0,
    seed: 0,
    trains: 3,
    reserved: 0,
};

/// Stores a valid wind in `*out`: 10 m/s (H = 2.14 m fully developed, Eq. 1) towards +x from
/// the origin, a box 100 m wide with a fetch of 200 m, full from time 0 and never dying
/// (`sustain` = `INFINITY`), seed 0, 3 trains. Set at least the origin, direction and extent
/// for your grid.
///
/// Returns `OCEAN_STATUS_NULL_POINTER` (or `_MISALIGNED_POINTER`) for a bad `out`, which is
/// then left unchanged.
///
/// # Safety
///
/// `out` must be writable.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn ocean_wtb_wind_desc_default(out: *mut OceanWindDesc) -> OceanStatus {
    guard("ocean_wtb_wind_desc_default", || {
        // SAFETY: forwarded from this function's contract.
        unsafe { write_out(out, "out", DEFAULT_WIND) }
    })
}

/// Stores a valid box in `*out`: the wind of `ocean_wtb_wind_desc_default`, edges smoothed
/// over 10 m (Fig. 4), and the default recovery behind land (two peak wavelengths:
/// `has_recovery` = 0).
///
/// Returns `OCEAN_STATUS_NULL_POINTER` (or `_MISALIGNED_POINTER`) for a bad `out`, which is
/// then left unchanged.
///
/// # Safety
///
/// `out` must be writable.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn ocean_wtb_box_desc_default(out: *mut OceanBoxDesc) -> OceanStatus {
    guard("ocean_wtb_box_desc_default", || {
        let desc = OceanBoxDesc {
            next: OceanNext::NULL,
            wind: DEFAULT_WIND,
            smoothing: 10.0,
            has_recovery: 0,
            reserved: 0,
            recovery: 0.0,
        };
        // SAFETY: forwarded from this function's contract.
        unsafe { write_out(out, "out", desc) }
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

#[cfg(test)]
mod tests {
    use super::*;
    use crate::boundary::enums::read_poked;
    use crate::waves::OceanDVec2;
    use ocean_core::camera::DepthConvention;
    use ocean_wtb::scenarios;

    use crate::status::last_error;
    use crate::wtb_query::{
        OceanDrawnSample, OceanHeightSample, ocean_wtb_scene_heights_continuous,
        ocean_wtb_scene_heights_drawn,
    };

    const GRID: OceanWaterGridDesc = OceanWaterGridDesc {
        origin_x: 0.0,
        origin_z: 0.0,
        spacing: 1.0,
        nx: 64,
        nz: 64,
    };

    /// The default box is one a scene takes, with the wind and edges its documentation states.
    #[test]
    fn the_default_box_is_valid_and_as_documented() {
        let mut desc = OceanBoxDesc::default();
        // SAFETY: valid pointer.
        let st = unsafe { ocean_wtb_box_desc_default(&mut desc) };
        assert_eq!(st, OceanStatus::Ok);
        let mut wind = OceanWindDesc::default();
        // SAFETY: valid pointer.
        let st = unsafe { ocean_wtb_wind_desc_default(&mut wind) };
        assert_eq!(st, OceanStatus::Ok);
        assert_eq!(desc.wind, wind);
        assert_eq!((wind.speed, wind.width, wind.fetch), (10.0, 100.0, 200.0));
        assert_eq!((desc.smoothing, desc.has_recovery), (10.0, 0));

        let mut s = core::ptr::null_mut();
        // SAFETY: valid pointers, an open sea.
        let st = unsafe { ocean_wtb_scene_create(&GRID, core::ptr::null(), 0, &mut s) };
        assert_eq!(st, OceanStatus::Ok, "{}", last_error());
        let mut id = 0;
        // SAFETY: live scene, valid pointers.
        let st = unsafe { ocean_wtb_scene_add_box(s, &desc, core::ptr::null(), 0, &mut id) };
        assert_eq!(st, OceanStatus::Ok, "{}", last_error());
        ocean_wtb_scene_destroy(s);
    }

    /// The wind of `scenarios::steady_wind` in the C layout.
    fn wind(
        speed: f64,
        dir: (f64, f64),
        origin: (f64, f64),
        width: f64,
        fetch: f64,
    ) -> OceanWindDesc {
        OceanWindDesc {
            next: OceanNext::NULL,
            speed,
            direction_x: dir.0,
            direction_z: dir.1,
            origin_x: origin.0,
            origin_z: origin.1,
            width,
            fetch,
            start: -1.0,
            build_up: 0.0,
            sustain: f64::INFINITY,
            decay: 0.0,
            seed: 0,
            trains: 1,
            reserved: 0,
        }
    }

    /// Scenario 1 of `ocean_wtb::scenarios` built through the C ABI.
    fn scenario_1() -> *mut OceanWtbScene {
        let (grid, terrain) = scenarios::sloping(64).unwrap();
        let heights = terrain.heights().unwrap().to_vec();
        assert_eq!(grid.len(), heights.len());
        let mut s = core::ptr::null_mut();
        // SAFETY: valid pointers and lengths.
        let st = unsafe { ocean_wtb_scene_create(&GRID, heights.as_ptr(), heights.len(), &mut s) };
        assert_eq!(st, OceanStatus::Ok, "{}", last_error());
        let mut e = OceanEffects::default();
        // SAFETY: valid pointer.
        let st = unsafe { ocean_wtb_effects_default(&mut e) };
        assert_eq!(st, OceanStatus::Ok);
        e.shoaling = 0;
        // SAFETY: live scene, valid pointer.
        let st = unsafe { ocean_wtb_scene_set_effects(s, &e) };
        assert_eq!(st, OceanStatus::Ok);
        for (w, trains, seed) in [
            (wind(7.0, (1.0, 0.15), (-2.0, -4.0), 66.0, 70.0), 1, 11),
            (wind(5.0, (0.7, 1.0), (30.0, -30.0), 60.0, 90.0), 2, 12),
        ] {
            let desc = OceanBoxDesc {
                next: OceanNext::NULL,
                wind: OceanWindDesc { trains, seed, ..w },
                smoothing: 4.0,
                has_recovery: 0,
                reserved: 0,
                recovery: 0.0,
            };
            let mut id = u32::MAX;
            // SAFETY: live scene, valid pointers, no explicit trains.
            let st = unsafe { ocean_wtb_scene_add_box(s, &desc, core::ptr::null(), 0, &mut id) };
            assert_eq!(st, OceanStatus::Ok, "{}", last_error());
        }
        s
    }

    /// The wrapper adds nothing to the arithmetic: grid and height queries equal
    /// `ocean_wtb::scenarios::scenario_1` evaluated directly, bit for bit.
    #[test]
    fn matches_the_rust_scene_bit_for_bit() {
        let s = scenario_1();
        let mut direct = scenarios::scenario_1(64).unwrap();
        for t in [0.0, 3.25, 1.0e6] {
            let n = 64 * 64;
            let mut pos = vec![OceanVec3::default(); n];
            let mut nrm = pos.clone();
            let mut stats = OceanFrameStats::default();
            // SAFETY: n elements in each buffer.
            let st = unsafe {
                ocean_wtb_scene_evaluate(
                    s,
                    t,
                    core::ptr::null(),
                    pos.as_mut_ptr(),
                    nrm.as_mut_ptr(),
                    n,
                    &mut stats,
                )
            };
            assert_eq!(st, OceanStatus::Ok, "{}", last_error());
            let frame = direct.frame(t, None).unwrap();
            let mut cp = vec![Vec3::ZERO; n];
            let mut cn = cp.clone();
            frame.evaluate(&mut cp, &mut cn).unwrap();
            let bits = |v: &[OceanVec3]| -> Vec<u32> {
                v.iter()
                    .flat_map(|p| [p.x.to_bits(), p.y.to_bits(), p.z.to_bits()])
                    .collect()
            };
            let cbits = |v: &[Vec3]| -> Vec<u32> {
                v.iter()
                    .flat_map(|p| p.to_array().map(f32::to_bits))
                    .collect()
            };
            assert_eq!(bits(&pos), cbits(&cp));
            assert_eq!(bits(&nrm), cbits(&cn));
            assert_eq!((stats.alive, stats.culled, stats.trains), (2, 0, 3));
            assert!(pos.iter().any(|p| p.y.abs() > 0.05), "no waves at t = {t}");

            let xz = [
                OceanDVec2 { x: 10.3, z: 20.7 },
                OceanDVec2 { x: 50.0, z: 5.5 },
            ];
            let mut out = [OceanHeightSample::default(); 2];
            // SAFETY: two elements each.
            let st = unsafe {
                ocean_wtb_scene_heights_continuous(s, t, xz.as_ptr(), 2, out.as_mut_ptr())
            };
            assert_eq!(st, OceanStatus::Ok, "{}", last_error());
            for (q, o) in xz.iter().zip(&out) {
                let h = frame.continuous_height_at(DVec2::new(q.x, q.z)).unwrap();
                assert_eq!(o.height.to_bits(), h.height.to_bits());
                assert_eq!([o.rest.x, o.rest.z], h.rest.to_array());
                assert_eq!([o.normal.x, o.normal.y, o.normal.z], h.normal.to_array());
            }
        }
        ocean_wtb_scene_destroy(s);
    }

    /// Drawn queries answer for the last evaluation, culling included, and refuse a scene
    /// never evaluated or changed since; the answers are the Rust frame's, bit for bit.
    #[test]
    fn drawn_queries_need_an_evaluated_frame() {
        let s = scenario_1();
        let xz = [
            OceanDVec2 { x: 10.3, z: 20.7 },
            OceanDVec2 { x: -30.0, z: 5.5 },
        ];
        let marker = OceanDrawnSample {
            height: 7.0,
            ..OceanDrawnSample::default()
        };
        let mut out = [marker; 2];
        // SAFETY: live scene, two elements each.
        let query = |out: &mut [OceanDrawnSample; 2]| unsafe {
            ocean_wtb_scene_heights_drawn(s, xz.as_ptr(), 2, out.as_mut_ptr())
        };
        assert_eq!(query(&mut out), OceanStatus::NotEvaluated);
        assert!(
            last_error().contains("not been evaluated"),
            "{}",
            last_error()
        );
        assert_eq!(out, [marker; 2], "nothing written");
        let n = 64 * 64;
        let (mut pos, mut nrm) = (vec![OceanVec3::default(); n], vec![OceanVec3::default(); n]);
        // A view that sees no box: both are culled, and the drawn grid is at rest.
        let away = ocean_core::Camera::look_at(
            glam::DVec3::new(0.0, 10.0, -50.0),
            glam::DVec3::new(0.0, 10.0, -100.0),
            glam::DVec3::Y,
            ocean_core::Projection::Perspective {
                fov_y: 1.0,
                aspect: 1.0,
                near: 0.5,
                far: ocean_core::Far::Finite(100.0),
            },
            DepthConvention::ZERO_TO_ONE,
        )
        .unwrap();
        let away = crate::camera::OceanCamera::from_camera(&away);
        let mut evaluate = |camera: Option<&crate::camera::OceanCamera>| {
            // SAFETY: n elements in each buffer, a camera or NULL.
            let st = unsafe {
                ocean_wtb_scene_evaluate(
                    s,
                    4.5,
                    camera.map_or(core::ptr::null(), |c| c as *const _),
                    pos.as_mut_ptr(),
                    nrm.as_mut_ptr(),
                    n,
                    core::ptr::null_mut(),
                )
            };
            assert_eq!(st, OceanStatus::Ok, "{}", last_error());
        };
        evaluate(None);
        assert_eq!(query(&mut out), OceanStatus::Ok, "{}", last_error());
        let mut direct = scenarios::scenario_1(64).unwrap();
        let frame = direct.frame(4.5, None).unwrap();
        let want = frame.drawn_height_at(DVec2::new(10.3, 20.7)).unwrap();
        assert_eq!(out[0], OceanDrawnSample::from(&want));
        assert!(out[0].covered == 1 && out[0].height != 0.0);
        assert_eq!(
            (out[1].covered, out[1].height),
            (0, 0.0),
            "off the grid: at rest"
        );
        evaluate(Some(&away));
        assert_eq!(query(&mut out), OceanStatus::Ok, "{}", last_error());
        assert_eq!(
            (out[0].covered, out[0].height),
            (1, 0.0),
            "culled: drawn at rest"
        );
        // Any change of the description needs a new evaluation.
        let st = ocean_wtb_scene_set_budget_unlimited(s);
        assert_eq!(st, OceanStatus::Ok);
        assert_eq!(query(&mut out), OceanStatus::NotEvaluated);
        assert!(last_error().contains("changed"), "{}", last_error());
        ocean_wtb_scene_destroy(s);
    }

    /// Misaligned pointers are refused before any access, and nothing is written.
    #[test]
    fn incremental_evaluation_matches_full_evaluation() {
        // Kept buffers updated by ocean_wtb_scene_evaluate_incremental must equal what
        // ocean_wtb_scene_evaluate writes, frame after frame, while culling switches every box off
        // (a view of the sky, column-major like GLM) and on again.
        let s = scenario_1();
        let n = 64 * 64;
        let sky = {
            let view = ocean_core::camera::look_at(
                glam::DVec3::new(32.0, 40.0, 32.0),
                glam::DVec3::new(32.0, 80.0, 32.0001),
                glam::DVec3::Z,
            )
            .unwrap();
            let proj = ocean_core::camera::Projection::Perspective {
                fov_y: 1.2,
                aspect: 1.0,
                near: 0.1,
                far: ocean_core::camera::Far::Finite(500.0),
            };
            OceanCamera::from_camera(
                &ocean_core::Camera::new(view, proj, DepthConvention::ZERO_TO_ONE).unwrap(),
            )
        };
        let mut kept = (vec![OceanVec3::default(); n], vec![OceanVec3::default(); n]);
        for (step, culled) in [false, true, true, false, true, false]
            .into_iter()
            .enumerate()
        {
            let vp: *const OceanCamera = if culled { &sky } else { core::ptr::null() };
            let t = 1.0 + step as f64;
            let mut full = (vec![OceanVec3::default(); n], vec![OceanVec3::default(); n]);
            let mut stats = OceanFrameStats::default();
            // SAFETY: live scene; buffers of n elements; 16 floats or NULL; stats writable.
            let (a, b) = unsafe {
                (
                    ocean_wtb_scene_evaluate_incremental(
                        s,
                        t,
                        vp,
                        kept.0.as_mut_ptr(),
                        kept.1.as_mut_ptr(),
                        n,
                        &mut stats,
                    ),
                    ocean_wtb_scene_evaluate(
                        s,
                        t,
                        vp,
                        full.0.as_mut_ptr(),
                        full.1.as_mut_ptr(),
                        n,
                        core::ptr::null_mut(),
                    ),
                )
            };
            assert_eq!(
                (a, b),
                (OceanStatus::Ok, OceanStatus::Ok),
                "{}",
                last_error()
            );
            assert_eq!(stats.culled, if culled { 2 } else { 0 });
            assert!(kept == full, "frame {step} differs");
        }
        // After a reset the next incremental call rewrites everything, even over garbage.
        kept.0.fill(OceanVec3 {
            x: 9.0,
            y: 9.0,
            z: 9.0,
        });
        assert_eq!(ocean_wtb_scene_reset_coverage(s), OceanStatus::Ok);
        let mut full = (vec![OceanVec3::default(); n], vec![OceanVec3::default(); n]);
        // SAFETY: as above.
        unsafe {
            ocean_wtb_scene_evaluate_incremental(
                s,
                9.0,
                &sky,
                kept.0.as_mut_ptr(),
                kept.1.as_mut_ptr(),
                n,
                core::ptr::null_mut(),
            );
            ocean_wtb_scene_evaluate(
                s,
                9.0,
                &sky,
                full.0.as_mut_ptr(),
                full.1.as_mut_ptr(),
                n,
                core::ptr::null_mut(),
            );
        }
        assert!(kept == full);
        let st = ocean_wtb_scene_reset_coverage(core::ptr::null_mut());
        assert_eq!(st, OceanStatus::NullPointer);
        ocean_wtb_scene_destroy(s);
    }

    #[test]
    fn misaligned_pointers_are_refused() {
        let s = scenario_1();
        let mut storage = [0u64; 64];
        let base = storage.as_mut_ptr().cast::<u8>();
        let bad_vec3 = base.wrapping_add(1).cast::<OceanVec3>();
        let good = base.wrapping_add(256).cast::<OceanVec3>();
        // SAFETY: refused before any access.
        let st = unsafe {
            ocean_wtb_scene_evaluate(
                s,
                0.0,
                core::ptr::null(),
                bad_vec3,
                good,
                4096,
                core::ptr::null_mut(),
            )
        };
        assert_eq!(st, OceanStatus::MisalignedPointer);
        assert!(last_error().contains("out_pos"), "{}", last_error());
        let bad_stats = base.wrapping_add(4).cast::<OceanFrameStats>();
        let mut pos = vec![OceanVec3::default(); 4096];
        let mut nrm = pos.clone();
        // SAFETY: refused before any access.
        let st = unsafe {
            ocean_wtb_scene_evaluate(
                s,
                0.0,
                core::ptr::null(),
                pos.as_mut_ptr(),
                nrm.as_mut_ptr(),
                4096,
                bad_stats,
            )
        };
        assert_eq!(st, OceanStatus::MisalignedPointer);
        assert!(pos.iter().chain(&nrm).all(|p| *p == OceanVec3::default()));
        let bad_xz = base.wrapping_add(4).cast::<OceanDVec2>().cast_const();
        let mut out = [OceanHeightSample::default(); 1];
        // SAFETY: refused before any access.
        let st = unsafe { ocean_wtb_scene_heights_continuous(s, 0.0, bad_xz, 1, out.as_mut_ptr()) };
        assert_eq!(st, OceanStatus::MisalignedPointer);
        let bad_scene = base.wrapping_add(4).cast::<OceanWtbScene>();
        let st = ocean_wtb_scene_remove_box(bad_scene, 0);
        // A handle is an id, never an address: a pointer into the caller's memory is not one.
        assert_eq!(st, OceanStatus::InvalidHandle);
        assert!(
            storage.iter().all(|&v| v == 0),
            "a refused call wrote memory"
        );
        ocean_wtb_scene_destroy(bad_scene);
        ocean_wtb_scene_destroy(s);
    }

    /// Error statuses of the mapping that the C test cannot reach by a single bad member.
    #[test]
    fn error_mapping() {
        let e = wtb_error("x: ", WtbError::UnknownBox(3));
        assert_eq!(e.status, OceanStatus::NotFound);
        let e = wtb_error("", WtbError::OutsideGrid);
        assert_eq!(e.status, OceanStatus::OutsideGrid);
        let e = wtb_error("", WtbError::TerrainNotFinite { index: 7 });
        assert_eq!(e.status, OceanStatus::NonFinite);
        let e = trains_error(WtbError::TooSteep {
            total: 1.2,
            max: 1.0,
        });
        assert_eq!(e.status, OceanStatus::TooSteep);
        let e = trains_error(WtbError::Wave {
            index: 2,
            source: WaveError::TooSteep(1.5),
        });
        assert_eq!(
            (e.status, e.message.starts_with("trains[2]")),
            (OceanStatus::TooSteep, true)
        );
        // Flags and enums accept exactly their documented values.
        assert!(
            check_flag("f", 2).is_err()
                && check_flag("f", 1).unwrap()
                && !check_flag("f", 0).unwrap()
        );
        let at = core::mem::offset_of!(OceanEffects, refraction);
        let e = read_poked(&OceanEffects::default(), "effects", at, 3).unwrap_err();
        assert_eq!(
            e.message,
            "effects->refraction = 3 is not an OceanRefraction (0, 1 or 2)"
        );
        // The defaults round-trip through the C layout.
        let d = effects_to(&Effects::default());
        assert_eq!(effects_from(&d, "e").unwrap(), Effects::default());
    }
}

crate::boundary::chain::extensible!(OceanEffects, OceanWindDesc, OceanBoxDesc);
