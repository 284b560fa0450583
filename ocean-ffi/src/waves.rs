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

crate::boundary::handle::handles!(OceanWaves);

#[cfg(test)]
#[path = "waves_tests.rs"]
mod tests;
