//! The C descriptions of a wave-train-box scene (water grid, wind, box, effects, frame
//! counters), their `_default` functions and their conversions to `ocean-wtb`'s types.

use glam::DVec2;
use ocean_core::{WaveDesc, WaveError};
use ocean_wtb::budget::Selection;
use ocean_wtb::effects::{Beach, Effects, Irregular, Noise, Refraction};
use ocean_wtb::scene::{BoxSpec, FrameStats, rectangles_overlap};
use ocean_wtb::wind::MAX_EXPLICIT_TRAINS;
use ocean_wtb::{BoxFrame, Terrain, TrainSource, WaterGrid, Wind, WtbError};

use crate::boundary::OceanNext;
use crate::boundary::{
    CEnum, CheckedStruct, EnumField, byte_len, check_chain, check_finite, check_flag, check_len,
    check_ptr, check_reserved, read_params, write_out,
};
use crate::status::{Error, OceanStatus, guard};
use crate::waves::{OceanWaveDesc, eval_error, wave_desc_in, wave_error};

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
pub(crate) fn trains_error(e: WtbError) -> Error {
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

pub(crate) fn refraction_from(v: OceanRefraction) -> Refraction {
    match v {
        OceanRefraction::Off => Refraction::Off,
        OceanRefraction::PhaseShift => Refraction::PhaseShift,
        OceanRefraction::Dispersion => Refraction::Dispersion,
    }
}

pub(crate) fn effects_from(e: &OceanEffects, name: &str) -> Result<Effects, Error> {
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

pub(crate) fn effects_to(e: &Effects) -> OceanEffects {
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
pub(crate) fn check_terrain_ptr(heights: *const f32, len: usize) -> Result<(), Error> {
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
pub(crate) unsafe fn terrain(
    grid: &WaterGrid,
    heights: *const f32,
    len: usize,
) -> Result<Terrain, Error> {
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
pub(crate) unsafe fn box_spec(
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
pub(crate) fn check_reaches_grid(grid: &WaterGrid, wind: &Wind) -> Result<(), Error> {
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

crate::boundary::chain::extensible!(OceanEffects, OceanWindDesc, OceanBoxDesc);
