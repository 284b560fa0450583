//! Trochoid (Gerstner) wave sets: create, evaluate at points or on a grid, query, destroy.

use core::mem::{align_of, size_of};

use bytemuck::{Pod, Zeroable};
use glam::{DVec2, DVec3, Vec3};
use ocean_core::{Depth, EvalError, Grid, WaveDesc, WaveError, WaveSet};

use crate::boundary::{
    Num, borrow, byte_len, check_disjoint, check_finite, check_ptr, check_time, destroy, read_in,
    write_handle, write_out,
};
use crate::status::{Error, OceanStatus, guard};
use crate::waves_domain::Reach;

/// A 3D vector (metres for positions; unit length for normals), right-handed, y up.
///
/// The layout (three packed floats, 12 bytes) is that of GLM's `glm::vec3` and `float[3]` in
/// GLM's default configuration: an array of `glm::vec3` may be passed where an `OceanVec3` array
/// is taken (not with `GLM_FORCE_DEFAULT_ALIGNED_GENTYPES`, which pads it to 16 bytes).
#[repr(C)]
#[derive(Clone, Copy, Debug, Default, PartialEq, Pod, Zeroable)]
pub struct OceanVec3 {
    /// x, metres.
    pub x: f32,
    /// y (up), metres.
    pub y: f32,
    /// z, metres.
    pub z: f32,
}

/// A point on the sea plane y = 0 in double precision: world x and z in metres. World positions
/// cross the C ABI in double precision (a float resolves only 7.8 mm at 100 km).
///
/// The layout (two doubles, 16 bytes, 8-aligned) is that of GLM's `glm::dvec2` and `double[2]`;
/// the second member holds z, not y.
#[repr(C)]
#[derive(Clone, Copy, Debug, Default, PartialEq, Pod, Zeroable)]
pub struct OceanDVec2 {
    /// x, metres.
    pub x: f64,
    /// z, metres.
    pub z: f64,
}

/// A 3D vector in double precision. World-space vectors are right-handed with y up; the BRDF
/// functions take tangent-frame vectors (x along the wind, y across it, z along the normal), as
/// each function says.
///
/// The layout (three doubles, 24 bytes, 8-aligned) is that of GLM's `glm::dvec3` and
/// `double[3]`: an array of `glm::dvec3` may be passed where an `OceanDVec3` array is taken.
#[repr(C)]
#[derive(Clone, Copy, Debug, Default, PartialEq, bytemuck::Zeroable, bytemuck::Pod)]
pub struct OceanDVec3 {
    /// x.
    pub x: f64,
    /// y (up).
    pub y: f64,
    /// z.
    pub z: f64,
}

impl OceanDVec3 {
    pub(crate) fn from_dvec3(v: glam::DVec3) -> Self {
        Self {
            x: v.x,
            y: v.y,
            z: v.z,
        }
    }
}

const _: () = assert!(size_of::<OceanDVec2>() == size_of::<DVec2>());
const _: () = assert!(align_of::<OceanDVec2>() == align_of::<DVec2>());
const _: () = assert!(size_of::<OceanVec3>() == size_of::<Vec3>());
const _: () = assert!(align_of::<OceanVec3>() == align_of::<Vec3>());

/// One trochoid (Gerstner) wave train, as the caller describes it (Yrjola & Larsson Eq. 6, 7).
///
/// Every member must be finite, except `depth`, which may be `INFINITY` for deep water.
/// NaN anywhere, or an infinite amplitude, wavelength, direction, phase or a depth of
/// `-INFINITY`, gives `OCEAN_STATUS_NON_FINITE`.
#[repr(C)]
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct OceanWaveDesc {
    /// Amplitude A in metres (half the crest-to-trough height), >= 0. The steepness k*A with
    /// k = 2*pi/wavelength must be <= 1 (else `OCEAN_STATUS_TOO_STEEP`): A <= wavelength/(2*pi).
    pub amplitude: f64,
    /// Wavelength in metres, > 0.
    pub wavelength: f64,
    /// x component of the direction of travel on the sea plane; with `direction_z` any finite,
    /// non-zero vector (it is normalised).
    pub direction_x: f64,
    /// z component of the direction of travel.
    pub direction_z: f64,
    /// Phase shift in radians, finite.
    pub phase: f64,
    /// Water depth in metres, > 0, which sets the angular frequency by the dispersion relation
    /// omega = sqrt(g*k*tanh(k*depth)) (Eq. 4, g = 9.81 m/s^2); or `INFINITY` for deep water,
    /// omega = sqrt(g*k) (Eq. 5).
    pub depth: f64,
}

/// A regular grid of rest positions on the sea plane: point (i, j), for i < nx and j < nz, rests
/// at world (origin_x + i*spacing_x, origin_z + j*spacing_z). Outputs are row-major: point (i, j)
/// is element j*nx + i.
#[repr(C)]
#[derive(Clone, Copy, Debug, Default, PartialEq, Pod, Zeroable)]
pub struct OceanGrid {
    /// World x of point (0, 0), metres, finite.
    pub origin_x: f64,
    /// World z of point (0, 0), metres, finite.
    pub origin_z: f64,
    /// Distance between columns along x, metres, finite and > 0.
    pub spacing_x: f64,
    /// Distance between rows along z, metres, finite and > 0.
    pub spacing_z: f64,
    /// Number of columns (along x), 1 to 2^24.
    pub nx: usize,
    /// Number of rows (along z), 1 to 2^24.
    pub nz: usize,
}

/// An immutable set of trochoid waves (opaque). Create with `ocean_waves_create`, free with
/// `ocean_waves_destroy`. A `const OceanWaves *` may be evaluated and queried from any number
/// of threads at once; destroying it must not race with any other use.
pub struct OceanWaves {
    set: WaveSet,
    /// What bounds its phases: checked before every evaluation.
    reach: Reach,
}

/// Points from which `ocean_waves_evaluate` splits the work over threads (the results are
/// bit-identical either way; below this the thread hand-off costs more than it saves).
const PARALLEL_POINTS: usize = 16 * 1024;

fn wave_desc(i: usize, d: &OceanWaveDesc) -> Result<WaveDesc, Error> {
    wave_desc_in("descs", i, d)
}

/// Converts element `i` of the caller's array `array` (named so in messages) to a core
/// description, refusing NaN and infinities (a depth of +INFINITY is deep water).
pub(crate) fn wave_desc_in(array: &str, i: usize, d: &OceanWaveDesc) -> Result<WaveDesc, Error> {
    let fields = [
        ("amplitude", d.amplitude),
        ("wavelength", d.wavelength),
        ("direction_x", d.direction_x),
        ("direction_z", d.direction_z),
        ("phase", d.phase),
    ];
    check_finite(&format!("{array}[{i}]."), &fields)?;
    let depth = if d.depth == f64::INFINITY {
        Depth::Deep
    } else if !d.depth.is_finite() {
        return Err(Error::new(
            OceanStatus::NonFinite,
            format!(
                "{array}[{i}].depth must be finite metres or +INFINITY (deep water), got {}",
                d.depth
            ),
        ));
    } else {
        Depth::Finite(d.depth)
    };
    Ok(WaveDesc {
        amplitude: d.amplitude,
        wavelength: d.wavelength,
        direction: DVec2::new(d.direction_x, d.direction_z),
        phase: d.phase,
        depth,
    })
}

pub(crate) fn wave_error(i: usize, e: WaveError) -> Error {
    let status = match e {
        WaveError::TooSteep(_) => OceanStatus::TooSteep,
        WaveError::Empty => OceanStatus::Empty,
        _ => OceanStatus::InvalidArgument,
    };
    Error::new(status, format!("descs[{i}]: {e}"))
}

pub(crate) fn eval_error(e: EvalError, positions: &str) -> Error {
    let status = match e {
        EvalError::Time(_) => OceanStatus::NonFinite,
        EvalError::Position { .. } => OceanStatus::NonFinite,
        EvalError::Empty => OceanStatus::Empty,
        _ => OceanStatus::InvalidArgument,
    };
    let message = match e {
        EvalError::Position { index } => format!("{positions}[{index}] is not finite"),
        e => e.to_string(),
    };
    Error::new(status, message)
}

/// Builds a wave set from `n` wave descriptions and stores a new handle in `*out`.
///
/// The waves are summed as trochoids (Gerstner waves, Yrjola & Larsson Eq. 6, 7); see
/// `ocean_waves_evaluate` for the formula. Each description is validated: the last-error message
/// names the first bad one (`descs[i]`) and its bad member.
///
/// Returns `OCEAN_STATUS_NULL_POINTER` if `descs` or `out` is NULL, `OCEAN_STATUS_EMPTY` if
/// `n` is 0, `OCEAN_STATUS_LENGTH_OVERFLOW` if `n * sizeof(OceanWaveDesc)` exceeds
/// `PTRDIFF_MAX`, `OCEAN_STATUS_NON_FINITE` for NaN or infinite members (see `OceanWaveDesc`),
/// `OCEAN_STATUS_TOO_STEEP` if a wave has k*A > 1, `OCEAN_STATUS_INVALID_ARGUMENT` for other
/// out-of-range members (amplitude < 0, wavelength <= 0, zero direction, depth <= 0) and for
/// amplitudes that add up past 1e30 m (a displaced float position could overflow). On any
/// failure `*out` is left unchanged. Free the handle with `ocean_waves_destroy`.
///
/// # Safety
///
/// `descs` must point to `n` readable `OceanWaveDesc`s and `out` to a writable pointer; neither
/// is retained after the call.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn ocean_waves_create(
    descs: *const OceanWaveDesc,
    n: usize,
    out: *mut *mut OceanWaves,
) -> OceanStatus {
    guard("ocean_waves_create", || {
        check_ptr(descs, "descs")?;
        check_ptr(out, "out")?;
        if n == 0 {
            return Err(Error::new(
                OceanStatus::Empty,
                "`n` is 0: a wave set needs at least one wave",
            ));
        }
        byte_len::<OceanWaveDesc>(n, "descs")?;
        // SAFETY: `descs` is non-NULL and aligned (checked), `n * size_of` fits in isize
        // (checked), and the caller guarantees `n` readable descriptions that nothing writes
        // during the call.
        let descs = unsafe { core::slice::from_raw_parts(descs, n) };
        let mut waves = Vec::with_capacity(n);
        for (i, d) in descs.iter().enumerate() {
            waves.push(wave_desc(i, d)?.build().map_err(|e| wave_error(i, e))?);
        }
        let set = WaveSet::new(&waves).map_err(|e| wave_error(0, e))?;
        let reach = Reach::of(&set)?;
        // SAFETY: forwarded from this function's contract.
        unsafe { write_handle(out, OceanWaves { set, reach }) }
    })
}

/// Frees a wave set (see `ocean_wtb_scene_destroy` for the rules every destroy function follows).
#[unsafe(no_mangle)]
pub extern "C" fn ocean_waves_destroy(waves: *mut OceanWaves) {
    destroy(waves, "ocean_waves_destroy", "waves");
}

/// Evaluates the wave set at `n` rest points at `time` seconds.
///
/// For rest point p0 = (`xz[i].x`, 0, `xz[i].z`) (world metres) writes the displaced surface point
/// to `out_pos[i]` and the unit surface normal to `out_normal[i]` (right-handed, y up):
///
/// ```text
/// theta_w    = k_w . p0 - omega_w * time + phase_w
/// out_pos    = p0 + sum_w (-khat_w.x A_w sin(theta_w), A_w cos(theta_w), -khat_w.z A_w sin(theta_w))
/// out_normal = normalize(d out_pos/dz x d out_pos/dx)
/// ```
///
/// with k_w = (2*pi/wavelength) * khat_w, khat_w the normalised direction and omega_w from the
/// dispersion relation (see `OceanWaveDesc`). Rest positions and outputs are world coordinates
/// in double precision: each point is evaluated relative to the corner of its 64 m lattice cell
/// (a float offset below 64 m, resolved to 4 µm) with the phases formed in double precision
/// (`ocean_core::WaveSet::evaluate_world`, the same evaluation for Rust callers),
/// so the answer is as precise 100 km from the origin as at it, and a point gives the same bits
/// in any batch. Large `time` values (10^6 s) do not jitter either. The arithmetic is
/// bit-identical on every platform and thread count; large batches are split over a global
/// worker pool.
///
/// Returns `OCEAN_STATUS_NULL_POINTER` if any pointer is NULL, `OCEAN_STATUS_MISALIGNED_POINTER`
/// if one is not aligned to its type (8 bytes for `xz` and `out_pos`, 4 for `out_normal`),
/// `OCEAN_STATUS_EMPTY` if `n` is 0, `OCEAN_STATUS_LENGTH_OVERFLOW` if
/// `n * sizeof(OceanDVec3)` exceeds `PTRDIFF_MAX`,
/// `OCEAN_STATUS_INVALID_ARGUMENT` if any two of the three arrays overlap,
/// `OCEAN_STATUS_NON_FINITE` if `time` or a coordinate of `xz` is NaN or infinite (the message
/// gives the first bad index), `OCEAN_STATUS_INVALID_ARGUMENT` if a phase leaves the domain
/// where double precision resolves it: |omega * time| of the fastest wave or |k * x| (or
/// |k * z|) of the shortest wave above 1e15 rad (far beyond it the results would be NaN).
/// Nothing is written on failure.
///
/// # Safety
///
/// `xz` must point to `n` readable `OceanDVec2`s, `out_pos` to `n` writable `OceanDVec3`s and
/// `out_normal` to `n` writable `OceanVec3`s, none of them modified by another thread during
/// the call.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn ocean_waves_evaluate(
    waves: *const OceanWaves,
    xz: *const OceanDVec2,
    n: usize,
    time: f64,
    out_pos: *mut OceanDVec3,
    out_normal: *mut OceanVec3,
) -> OceanStatus {
    guard("ocean_waves_evaluate", || {
        let waves = borrow(waves, "waves")?;
        check_ptr(xz, "xz")?;
        check_ptr(out_pos, "out_pos")?;
        check_ptr(out_normal, "out_normal")?;
        if n == 0 {
            return Err(Error::new(
                OceanStatus::Empty,
                "`n` is 0: no points to evaluate",
            ));
        }
        let in_bytes = byte_len::<OceanDVec2>(n, "xz")?;
        let pos_bytes = byte_len::<OceanDVec3>(n, "out_pos")?;
        let nrm_bytes = byte_len::<OceanVec3>(n, "out_normal")?;
        let ranges = [
            (xz.cast::<u8>(), in_bytes, "xz"),
            (out_pos.cast_const().cast::<u8>(), pos_bytes, "out_pos"),
            (
                out_normal.cast_const().cast::<u8>(),
                nrm_bytes,
                "out_normal",
            ),
        ];
        check_disjoint(ranges[0], ranges[1])?;
        check_disjoint(ranges[0], ranges[2])?;
        check_disjoint(ranges[1], ranges[2])?;
        check_time(time)?;
        // SAFETY: every pointer is non-NULL and aligned, every byte size fits in isize, and the
        // three ranges are pairwise disjoint (all checked above); the caller guarantees that they
        // hold `n` elements each, readable (`xz`) or writable (outputs), untouched by others.
        let (xz, pos, nrm) = unsafe {
            (
                core::slice::from_raw_parts(xz, n),
                core::slice::from_raw_parts_mut(out_pos, n),
                core::slice::from_raw_parts_mut(out_normal, n),
            )
        };
        let world: &[DVec2] = bytemuck::cast_slice(xz);
        if let Some(i) = world.iter().position(|p| !p.is_finite()) {
            return Err(Error::new(
                OceanStatus::NonFinite,
                format!(
                    "xz[{i}] = ({}, {}) is not finite",
                    Num(world[i].x),
                    Num(world[i].y)
                ),
            ));
        }
        waves.reach.check_time(time)?;
        waves.reach.check_points("xz", world)?;
        let pos: &mut [DVec3] = bytemuck::cast_slice_mut(pos);
        let nrm: &mut [Vec3] = bytemuck::cast_slice_mut(nrm);
        if n >= PARALLEL_POINTS {
            waves.set.evaluate_world_par(world, time, pos, nrm)
        } else {
            waves.set.evaluate_world(world, time, pos, nrm)
        }
        .map_err(|e| eval_error(e, "xz"))
    })
}

/// Evaluates the wave set on every point of `grid` at `time` seconds, on a global worker pool.
///
/// Writes `grid->nx * grid->nz` positions and unit normals, row-major (point (i, j) at index
/// j*nx + i), by the formula of `ocean_waves_evaluate`. The positions are relative to the grid
/// origin: `out_pos[j*nx + i]` is the displaced point minus (origin_x, 0, origin_z), about
/// (i*spacing_x, y, j*spacing_z). The origin stays in double precision, so a grid 100 km from
/// the world origin is as precise as one at it; add the origin back in double precision, or put
/// it in the model matrix (camera-relative rendering). The result is bit-identical for every
/// thread count and platform.
///
/// Returns `OCEAN_STATUS_NULL_POINTER` if any pointer is NULL,
/// `OCEAN_STATUS_MISALIGNED_POINTER` if one is misaligned, `OCEAN_STATUS_EMPTY` if `nx` or `nz`
/// is 0, `OCEAN_STATUS_LENGTH_OVERFLOW` if `nx * nz` overflows or `nx * nz * sizeof(OceanVec3)`
/// exceeds `PTRDIFF_MAX`, `OCEAN_STATUS_INVALID_ARGUMENT` if the output arrays overlap, a
/// spacing is <= 0, `nx` or `nz` exceeds 2^24, the grid's extent does not fit in a float, or
/// a phase leaves 1e15 rad (as in `ocean_waves_evaluate`, for `time` and the grid's farthest
/// corner), `OCEAN_STATUS_NON_FINITE` if `time`, the origin or a spacing is NaN or infinite.
/// Nothing is written on failure.
///
/// # Safety
///
/// `grid` must point to a readable `OceanGrid`, and `out_pos` and
/// `out_normal` to `nx * nz` writable `OceanVec3`s each, untouched by other threads during the
/// call.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn ocean_waves_evaluate_grid(
    waves: *const OceanWaves,
    grid: *const OceanGrid,
    time: f64,
    out_pos: *mut OceanVec3,
    out_normal: *mut OceanVec3,
) -> OceanStatus {
    guard("ocean_waves_evaluate_grid", || {
        let waves = borrow(waves, "waves")?;
        check_ptr(grid, "grid")?;
        check_ptr(out_pos, "out_pos")?;
        check_ptr(out_normal, "out_normal")?;
        // SAFETY: forwarded from this function's contract.
        let g = unsafe { read_in(grid, "grid") }?;
        if g.nx == 0 || g.nz == 0 {
            return Err(Error::new(
                OceanStatus::Empty,
                format!("grid is {} x {}: both sizes must be >= 1", g.nx, g.nz),
            ));
        }
        let n = g.nx.checked_mul(g.nz).ok_or_else(|| {
            Error::new(
                OceanStatus::LengthOverflow,
                format!("grid point count {} x {} overflows size_t", g.nx, g.nz),
            )
        })?;
        let out_bytes = byte_len::<OceanVec3>(n, "out_pos")?;
        check_time(time)?;
        let members = [
            ("origin_x", g.origin_x),
            ("origin_z", g.origin_z),
            ("spacing_x", g.spacing_x),
            ("spacing_z", g.spacing_z),
        ];
        check_finite("grid->", &members)?;
        let core_grid = Grid {
            origin: DVec2::new(g.origin_x, g.origin_z),
            spacing: DVec2::new(g.spacing_x, g.spacing_z),
            size: (g.nx, g.nz),
        };
        // Spacing <= 0 and sides above 2^24 are refused here, before any slice is made.
        core_grid
            .point_count()
            .map_err(|e| eval_error(e, "grid->origin"))?;
        // After the side limit: a 2^24 + 1 point grid is refused for its side, not reported as
        // outputs that overlap because the caller's buffers are sized for a valid grid.
        check_disjoint(
            (out_pos.cast_const().cast::<u8>(), out_bytes, "out_pos"),
            (
                out_normal.cast_const().cast::<u8>(),
                out_bytes,
                "out_normal",
            ),
        )?;
        waves.reach.check_time(time)?;
        waves.reach.check_grid("grid", &core_grid)?;
        // SAFETY: both pointers are non-NULL and aligned, the byte size fits in isize and the
        // ranges are disjoint (all checked above); the caller guarantees `n` writable elements
        // in each, untouched by others during the call.
        let (pos, nrm) = unsafe {
            (
                core::slice::from_raw_parts_mut(out_pos, n),
                core::slice::from_raw_parts_mut(out_normal, n),
            )
        };
        waves
            .set
            .evaluate_grid_par(
                &core_grid,
                time,
                bytemuck::cast_slice_mut(pos),
                bytemuck::cast_slice_mut(nrm),
            )
            .map_err(|e| eval_error(e, "grid->origin"))
    })
}

/// Stores the number of waves in the set (>= 1) in `*out_count`.
///
/// Returns `OCEAN_STATUS_NULL_POINTER` (or `_MISALIGNED_POINTER`) for a bad `waves` or
/// `out_count`; `*out_count` is written only on success.
///
/// # Safety
///
/// `out_count` must be writable.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn ocean_waves_count(
    waves: *const OceanWaves,
    out_count: *mut usize,
) -> OceanStatus {
    guard("ocean_waves_count", || {
        let waves = borrow(waves, "waves")?;
        // SAFETY: forwarded from this function's contract.
        unsafe { write_out(out_count, "out_count", waves.set.waves().len()) }
    })
}

/// Stores the steepness sum, sum over the waves of k*A (dimensionless), in `*out_steepness`.
///
/// While it is <= 1 the summed surface can never fold over itself; above 1 crests may fold where
/// the waves align (allowed, since each wave alone is at most a cusp). Returns
/// `OCEAN_STATUS_NULL_POINTER` (or `_MISALIGNED_POINTER`) for a bad argument; the output is
/// written only on success.
///
/// # Safety
///
/// `out_steepness` must be writable.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn ocean_waves_steepness_sum(
    waves: *const OceanWaves,
    out_steepness: *mut f64,
) -> OceanStatus {
    guard("ocean_waves_steepness_sum", || {
        let waves = borrow(waves, "waves")?;
        // SAFETY: forwarded from this function's contract.
        unsafe { write_out(out_steepness, "out_steepness", waves.set.steepness_sum()) }
    })
}

/// Stores the sum of the amplitudes, in metres, in `*out_amplitude`: the largest height above
/// (and depth below) y = 0 and the largest horizontal displacement any point can reach; use it
/// for bounding volumes and culling margins. Returns `OCEAN_STATUS_NULL_POINTER` (or
/// `_MISALIGNED_POINTER`) for a bad argument; the output is written only on success.
///
/// # Safety
///
/// `out_amplitude` must be writable.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn ocean_waves_max_amplitude(
    waves: *const OceanWaves,
    out_amplitude: *mut f64,
) -> OceanStatus {
    guard("ocean_waves_max_amplitude", || {
        let waves = borrow(waves, "waves")?;
        // SAFETY: forwarded from this function's contract.
        unsafe { write_out(out_amplitude, "out_amplitude", waves.set.max_amplitude()) }
    })
}

const _: () = {
    const fn shareable<T: Send + Sync>() {}
    shareable::<OceanWaves>();
};

#[cfg(test)]
mod tests {
    use super::*;

    use crate::status::last_error;

    const DESCS: [OceanWaveDesc; 2] = [
        OceanWaveDesc {
            amplitude: 0.5,
            wavelength: 12.0,
            direction_x: 1.0,
            direction_z: 0.5,
            phase: 0.3,
            depth: f64::INFINITY,
        },
        OceanWaveDesc {
            amplitude: 0.2,
            wavelength: 5.0,
            direction_x: -0.4,
            direction_z: 1.0,
            phase: -1.0,
            depth: 2.5,
        },
    ];

    fn create() -> *mut OceanWaves {
        let mut w = core::ptr::null_mut();
        // SAFETY: valid array and out pointer.
        let s = unsafe { ocean_waves_create(DESCS.as_ptr(), DESCS.len(), &mut w) };
        assert_eq!(s, OceanStatus::Ok, "{}", last_error());
        w
    }

    fn core_set() -> WaveSet {
        WaveSet::from_descs(&[
            WaveDesc {
                amplitude: 0.5,
                wavelength: 12.0,
                direction: DVec2::new(1.0, 0.5),
                phase: 0.3,
                depth: Depth::Deep,
            },
            WaveDesc {
                amplitude: 0.2,
                wavelength: 5.0,
                direction: DVec2::new(-0.4, 1.0),
                phase: -1.0,
                depth: Depth::Finite(2.5),
            },
        ])
        .unwrap()
    }

    /// The wrapper adds nothing to the arithmetic: its outputs are the core's, bit for bit, for
    /// points (each relative to the corner of its 64 m cell, in double precision) and grids
    /// (origin-relative), on both sides of the parallel threshold; and a point gives the same
    /// bits alone as in a batch.
    #[test]
    fn matches_the_core_bit_for_bit() {
        let w = create();
        let set = core_set();
        for n in [5, PARALLEL_POINTS + 3] {
            let xz: Vec<OceanDVec2> = (0..n)
                .map(|i| OceanDVec2 {
                    x: (i % 97) as f64 * 1.5 - 60.0,
                    z: (i / 97) as f64 * 0.75 - 20.0,
                })
                .collect();
            let mut pos = vec![OceanDVec3::default(); n];
            let mut nrm = vec![OceanVec3::default(); n];
            // SAFETY: n elements in each buffer.
            let s = unsafe {
                ocean_waves_evaluate(w, xz.as_ptr(), n, 42.5, pos.as_mut_ptr(), nrm.as_mut_ptr())
            };
            assert_eq!(s, OceanStatus::Ok, "{}", last_error());
            for (i, p) in xz.iter().enumerate().step_by(if n > 100 { 257 } else { 1 }) {
                let world = DVec2::new(p.x, p.z);
                let corner = (world / 64.0).floor() * 64.0;
                let (mut cp, mut cn) = ([Vec3::ZERO], [Vec3::ZERO]);
                set.evaluate_points(
                    corner,
                    &[(world - corner).as_vec2()],
                    42.5,
                    &mut cp,
                    &mut cn,
                )
                .unwrap();
                let want = [
                    corner.x + f64::from(cp[0].x),
                    f64::from(cp[0].y),
                    corner.y + f64::from(cp[0].z),
                ];
                assert_eq!([pos[i].x, pos[i].y, pos[i].z], want, "point {i}");
                assert_eq!(
                    [nrm[i].x, nrm[i].y, nrm[i].z],
                    cn[0].to_array(),
                    "point {i}"
                );
                let (mut one, mut one_n) = ([OceanDVec3::default()], [OceanVec3::default()]);
                // SAFETY: one element in each buffer.
                let s = unsafe {
                    ocean_waves_evaluate(w, p, 1, 42.5, one.as_mut_ptr(), one_n.as_mut_ptr())
                };
                assert_eq!(s, OceanStatus::Ok);
                assert_eq!((one[0], one_n[0]), (pos[i], nrm[i]), "point {i} alone");
            }
        }

        let g = OceanGrid {
            origin_x: 5000.5,
            origin_z: -123.25,
            spacing_x: 0.5,
            spacing_z: 0.25,
            nx: 19,
            nz: 7,
        };
        let mut pos = vec![OceanVec3::default(); 19 * 7];
        let mut nrm = pos.clone();
        // SAFETY: nx * nz elements in each buffer.
        let s =
            unsafe { ocean_waves_evaluate_grid(w, &g, 8.0, pos.as_mut_ptr(), nrm.as_mut_ptr()) };
        assert_eq!(s, OceanStatus::Ok, "{}", last_error());
        let grid = Grid {
            origin: DVec2::new(5000.5, -123.25),
            spacing: DVec2::new(0.5, 0.25),
            size: (19, 7),
        };
        let mut cp = vec![Vec3::ZERO; 19 * 7];
        let mut cn = cp.clone();
        set.evaluate_grid(&grid, 8.0, &mut cp, &mut cn).unwrap();
        assert!(
            pos.iter()
                .zip(&cp)
                .all(|(a, b)| [a.x, a.y, a.z] == b.to_array())
        );
        assert!(
            nrm.iter()
                .zip(&cn)
                .all(|(a, b)| [a.x, a.y, a.z] == b.to_array())
        );
        ocean_waves_destroy(w);
    }

    /// 100 km from the origin a point is as precise as at it: within 0.1 mm of the f64
    /// reference (`WaveSet::sample_f64`, rest position plus displacement) at (10, 20) and at
    /// (1e5 + 10, -4e4 + 20). Rest positions rounded to floats there (a float resolves 7.8 mm
    /// at 1e5 m) were off by up to 3.9 mm.
    #[test]
    fn far_from_the_origin_a_point_is_as_precise_as_near_it() {
        let w = create();
        let set = core_set();
        for base in [DVec2::ZERO, DVec2::new(1.0e5, -4.0e4)] {
            let rest: Vec<DVec2> = (0..200)
                .map(|i| base + DVec2::new(10.0 + 0.37 * i as f64, 20.0 - 0.2311 * i as f64))
                .collect();
            let xz: Vec<OceanDVec2> = rest.iter().map(|p| OceanDVec2 { x: p.x, z: p.y }).collect();
            let mut pos = vec![OceanDVec3::default(); xz.len()];
            let mut nrm = vec![OceanVec3::default(); xz.len()];
            // SAFETY: as many elements in each buffer as points.
            let s = unsafe {
                ocean_waves_evaluate(
                    w,
                    xz.as_ptr(),
                    xz.len(),
                    42.5,
                    pos.as_mut_ptr(),
                    nrm.as_mut_ptr(),
                )
            };
            assert_eq!(s, OceanStatus::Ok, "{}", last_error());
            let worst = rest
                .iter()
                .zip(&pos)
                .map(|(r, p)| {
                    let d = set.sample_f64(*r, 42.5).unwrap().displacement;
                    let want = glam::DVec3::new(r.x + d.x, d.y, r.y + d.z);
                    (glam::DVec3::new(p.x, p.y, p.z) - want).abs().max_element()
                })
                .fold(0.0, f64::max);
            assert!(worst < 1e-4, "{base}: worst error {worst} m");
        }
        ocean_waves_destroy(w);
    }

    /// Misaligned pointers (which C code cannot even form without undefined behaviour, but
    /// other languages' FFIs can pass) are refused before any access.
    #[test]
    fn misaligned_pointers_are_refused() {
        let w = create();
        let mut storage = [0u64; 32]; // 8-aligned, so base + 4 is not
        let xz = [OceanDVec2::default(); 4];
        let base = storage.as_mut_ptr().cast::<u8>();
        // Four bytes past an 8-aligned address: misaligned for double structs. Never
        // dereferenced.
        let bad_out = base.wrapping_add(4).cast::<OceanDVec3>();
        let good_pos = base.wrapping_add(128).cast::<OceanDVec3>();
        let good_nrm = base.wrapping_add(200).cast::<OceanVec3>();
        // SAFETY: the library refuses the misaligned pointer before touching any buffer.
        let s = unsafe { ocean_waves_evaluate(w, xz.as_ptr(), 4, 0.0, bad_out, good_nrm) };
        assert_eq!(s, OceanStatus::MisalignedPointer);
        assert!(last_error().contains("out_pos"), "{}", last_error());
        let bad_in = base.wrapping_add(4).cast::<OceanDVec2>().cast_const();
        // SAFETY: as above.
        let s = unsafe { ocean_waves_evaluate(w, bad_in, 4, 0.0, good_pos, good_nrm) };
        assert_eq!(s, OceanStatus::MisalignedPointer);
        let mut count = 0usize;
        let bad_handle = base.wrapping_add(4).cast::<OceanWaves>().cast_const();
        // SAFETY: as above.
        let s = unsafe { ocean_waves_count(bad_handle, &mut count) };
        // A handle is an id, never an address: a pointer into the caller's memory is not one.
        assert_eq!(s, OceanStatus::InvalidHandle);
        assert!(
            storage.iter().all(|&v| v == 0),
            "a refused call wrote memory"
        );
        ocean_waves_destroy(bad_handle.cast_mut());
        ocean_waves_destroy(w);
    }

    /// Partly overlapping arrays (not only identical pointers) are refused: creating `&` and
    /// `&mut` slices over them would be undefined behaviour.
    #[test]
    fn overlapping_buffers_are_refused() {
        let w = create();
        // 10 double positions (240 bytes): room for 4 positions and 8 normals after them.
        let mut buf = vec![OceanDVec3::default(); 10];
        let xz = [OceanDVec2::default(); 4];
        let p = buf.as_mut_ptr();
        let normals_at = |bytes: usize| p.cast::<u8>().wrapping_add(bytes).cast::<OceanVec3>();
        // out_normal starts inside out_pos's 4 elements (96 bytes).
        // SAFETY: refused before any access; the buffer holds 240 bytes anyway.
        let s = unsafe { ocean_waves_evaluate(w, xz.as_ptr(), 4, 0.0, p, normals_at(84)) };
        assert_eq!(s, OceanStatus::InvalidArgument);
        // Adjacent, non-overlapping ranges are fine.
        // SAFETY: bytes 0..96 and 96..144 of a 240-byte buffer.
        let s = unsafe { ocean_waves_evaluate(w, xz.as_ptr(), 4, 0.0, p, normals_at(96)) };
        assert_eq!(s, OceanStatus::Ok, "{}", last_error());
        // Input overlapping an output.
        let xz_alias = p.wrapping_add(8).cast::<OceanDVec2>().cast_const();
        // SAFETY: refused before any access (1 point = 16 bytes inside element 8).
        let s =
            unsafe { ocean_waves_evaluate(w, xz_alias, 1, 0.0, p.wrapping_add(8), normals_at(0)) };
        assert_eq!(s, OceanStatus::InvalidArgument);
        ocean_waves_destroy(w);
    }

    #[test]
    fn depth_infinity_is_deep_water_and_other_non_finite_depths_are_refused() {
        // depth = +INFINITY must give the same wave as the core's Depth::Deep.
        let deep = wave_desc(0, &DESCS[0]).unwrap();
        assert_eq!(deep.depth, Depth::Deep);
        for (d, status) in [
            (f64::NAN, OceanStatus::NonFinite),
            (f64::NEG_INFINITY, OceanStatus::NonFinite),
        ] {
            let desc = OceanWaveDesc {
                depth: d,
                ..DESCS[0]
            };
            assert_eq!(wave_desc(0, &desc).unwrap_err().status, status);
        }
        let mut w = core::ptr::null_mut();
        let desc = OceanWaveDesc {
            depth: -1.0,
            ..DESCS[1]
        };
        // SAFETY: valid pointers.
        let s = unsafe { ocean_waves_create(&desc, 1, &mut w) };
        assert_eq!(s, OceanStatus::InvalidArgument);
        assert!(w.is_null());
        assert!(last_error().contains("depth"), "{}", last_error());
    }
}
