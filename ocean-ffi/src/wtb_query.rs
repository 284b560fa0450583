//! Height queries on a wave train box scene: the drawn surface and the continuous one, and
//! the train filter that decides which trains the drawn grid carries.

use glam::DVec2;
use ocean_wtb::TrainFilter;
use ocean_wtb::scene::{DrawnSample, HeightSample};

use crate::boundary::{borrow, byte_len, check_disjoint, check_ptr, check_time};
use crate::status::{Error, OceanStatus, guard};
use crate::waves::{OceanDVec2, OceanDVec3};
use crate::wtb::OceanWtbScene;

/// The answer of a drawn height query at world (x, z): the triangle of the evaluated grid's
/// mesh that lies over it.
#[repr(C)]
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct OceanDrawnSample {
    /// Height of the triangle over the query, metres above the sea at rest; 0 where no
    /// triangle lies over it (`covered` is 0).
    pub height: f64,
    /// The triangle's unit normal, on its upper side (+y where `covered` is 0).
    pub normal: OceanDVec3,
    /// The vertex normals of the triangle blended by the barycentric weights and normalised:
    /// what a renderer interpolating the grid's normals shades the point with.
    pub shading_normal: OceanDVec3,
    /// World (x, z) of the rest position the mesh carries to the query (the triangle's rest
    /// vertices blended by the same weights); the query itself where `covered` is 0.
    pub rest: OceanDVec2,
    /// Barycentric weights of the query on the triangle's three vertices, in the order given
    /// by `upper` (each in [0, 1] up to rounding, summing to 1).
    pub weights: [f64; 3],
    /// The cell's first grid point: column i and row j.
    pub cell_i: u32,
    /// See `cell_i`.
    pub cell_j: u32,
    /// 0: the lower triangle (i, j), (i+1, j), (i, j+1); 1: the upper triangle (i+1, j),
    /// (i+1, j+1), (i, j+1).
    pub upper: u32,
    /// 1 where a triangle lies over the query, 0 over the sea at rest (off the mesh).
    pub covered: u32,
}

impl From<&DrawnSample> for OceanDrawnSample {
    fn from(s: &DrawnSample) -> Self {
        let v = |v: glam::DVec3| OceanDVec3 {
            x: v.x,
            y: v.y,
            z: v.z,
        };
        let t = s.triangle;
        Self {
            height: s.height,
            normal: v(s.normal),
            shading_normal: v(s.shading_normal),
            rest: OceanDVec2 {
                x: s.rest.x,
                z: s.rest.y,
            },
            weights: t.map_or([0.0; 3], |t| t.weights),
            cell_i: t.map_or(0, |t| t.cell[0]),
            cell_j: t.map_or(0, |t| t.cell[1]),
            upper: t.map_or(0, |t| u32::from(t.upper)),
            covered: u32::from(t.is_some()),
        }
    }
}

/// The answer of a continuous height query at world (x, z).
#[repr(C)]
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct OceanHeightSample {
    /// Water height there, metres above the sea at rest.
    pub height: f64,
    /// Unit surface normal there.
    pub normal: OceanDVec3,
    /// World (x, z) of the rest position whose displaced point lies over the query.
    pub rest: OceanDVec2,
    /// Horizontal distance between that displaced point and the query, metres: the query
    /// iterates until it is at most the library's tolerance (10 micrometres) or 16 Newton
    /// steps have run.
    pub residual: f64,
}

/// Checks the query points `xz[..n]` and an output array of `n` elements of `out_size`
/// bytes at `out`, and copies the points.
///
/// # Safety
///
/// `xz` must be NULL, misaligned, or point to `n` readable `OceanDVec2`s; `out` must be NULL,
/// misaligned, or point to `n * out_size` bytes.
unsafe fn query_points(
    xz: *const OceanDVec2,
    n: usize,
    out: *const u8,
    out_bytes: Result<usize, Error>,
) -> Result<Vec<DVec2>, Error> {
    check_ptr(xz, "xz")?;
    if n == 0 {
        return Err(Error::new(
            OceanStatus::Empty,
            "`n` is 0: no points to query",
        ));
    }
    let in_bytes = byte_len::<OceanDVec2>(n, "xz")?;
    check_disjoint((xz.cast::<u8>(), in_bytes, "xz"), (out, out_bytes?, "out"))?;
    // SAFETY: non-NULL and aligned (checked), the byte size fits in isize (checked), `n`
    // readable elements (caller's guarantee), disjoint from `out` (checked).
    let src = unsafe { core::slice::from_raw_parts(xz, n) };
    if let Some(k) = src
        .iter()
        .position(|p| !(p.x.is_finite() && p.z.is_finite()))
    {
        return Err(Error::new(
            OceanStatus::NonFinite,
            format!("xz[{k}] = ({}, {}) is not finite", src[k].x, src[k].z),
        ));
    }
    Ok(src.iter().map(|p| DVec2::new(p.x, p.z)).collect())
}

/// Answers `n` height queries at world (x, z) = `xz[k]` on the **drawn** surface, into
/// `out[k]`: the triangles of the grid that the last `ocean_wtb_scene_evaluate` or
/// `ocean_wtb_scene_evaluate_incremental` wrote, culling included (a culled box's water is drawn at
/// rest, and answered at rest). This is the surface to float objects on where the grid is what
/// is drawn.
///
/// The mesh: each cell (i, j)-(i+1, j+1) of the grid is split along the diagonal from
/// (i+1, j) to (i, j+1) into the lower triangle (i, j), (i+1, j), (i, j+1) and the upper
/// triangle (i+1, j), (i+1, j+1), (i, j+1), counter-clockwise seen from above, over the
/// evaluated positions (index j*nx + i, relative to the grid origin). The answer is the height
/// of the triangle over (x, z), exact to double rounding of those float vertices (the library's
/// tests compare it with an independent intersection of the same triangles: within 1e-14 m).
/// Where the mesh folds over itself (crests steeper than the trochoid's limit) the highest
/// triangle is taken. Where no triangle lies over the point (beyond the grid, or past an edge
/// the waves pull inwards) the sea is at rest: height 0, normal +y, `covered` 0.
///
/// The vertices are recomputed around the queries with the evaluation's own kernel, bit for bit
/// what it wrote; the caller's buffers are not read. A batch spread over the whole grid costs
/// about one evaluation of the grid; it is spread over the library's worker threads, and the
/// answers do not depend on their number.
///
/// Returns `OCEAN_STATUS_NULL_POINTER` / `_MISALIGNED_POINTER` (8-byte alignment),
/// `OCEAN_STATUS_EMPTY` if `n` is 0, `OCEAN_STATUS_LENGTH_OVERFLOW` if
/// `n * sizeof(OceanDrawnSample)` exceeds `PTRDIFF_MAX`, `OCEAN_STATUS_INVALID_ARGUMENT` if `xz`
/// and `out` overlap, `OCEAN_STATUS_NON_FINITE` for a NaN or infinite coordinate (the message
/// gives the first bad index), `OCEAN_STATUS_NOT_EVALUATED` if the scene was never evaluated or
/// changed since its last evaluation (evaluate it again). Nothing is written on failure.
///
/// # Safety
///
/// `xz` `n` readable `OceanDVec2`s and `out` `n` writable
/// `OceanDrawnSample`s, untouched by other threads during the call.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn ocean_wtb_scene_heights_drawn(
    scene: *const OceanWtbScene,
    xz: *const OceanDVec2,
    n: usize,
    out: *mut OceanDrawnSample,
) -> OceanStatus {
    guard("ocean_wtb_scene_heights_drawn", || {
        let scene = borrow(scene, "scene")?;
        check_ptr(out.cast_const(), "out")?;
        let out_bytes = byte_len::<OceanDrawnSample>(n, "out");
        // SAFETY: forwarded from this function's contract.
        let at = unsafe { query_points(xz, n, out.cast_const().cast(), out_bytes) }?;
        let mut samples = vec![DrawnSample::default(); n];
        {
            let mut s = scene.lock();
            let Some(e) = *scene.evaluated() else {
                return Err(Error::new(
                    OceanStatus::NotEvaluated,
                    "the scene has not been evaluated: drawn heights answer for the grid the \
                     last ocean_wtb_scene_evaluate (or _incremental) wrote; call it first",
                ));
            };
            if e.revision != s.revision() {
                return Err(Error::new(
                    OceanStatus::NotEvaluated,
                    "the scene changed since its last evaluation (a box, the terrain, the \
                     effects, the budget or the train filter): evaluate it again before \
                     querying the drawn surface",
                ));
            }
            let frame = s.frame(e.time, e.view.as_ref())?;
            frame.drawn_heights_par(&at, &mut samples)?;
        }
        // SAFETY: non-NULL and aligned (checked), byte size fits (checked), `n` writable
        // elements (caller's guarantee), disjoint from `xz` (checked, and not read any more).
        let dst = unsafe { core::slice::from_raw_parts_mut(out, n) };
        for (d, s) in dst.iter_mut().zip(&samples) {
            *d = s.into();
        }
        Ok(())
    })
}

/// Answers `n` height queries at world (x, z) = `xz[k]` and `time` seconds on the
/// **continuous** surface, into `out[k]`: the model between grid points (the same boxes, depth,
/// land, effects, budget and train filter as `ocean_wtb_scene_evaluate`, but never culled), the
/// limit of an ever finer grid, and what a renderer evaluating the trains per vertex of a
/// view-dependent grid approaches. The modulation and the height field are bilinear between
/// grid points; the surface is the image of the grid's rectangle, beyond which (and where an
/// edge is pulled inwards) the sea is at rest. Any time may be asked, evaluated or not: the
/// model needs no evaluation.
///
/// Against the drawn mesh it differs inside cells by the triangles' linear interpolation of the
/// trains, about A (1 - cos(pi s / lambda)) for a train of amplitude A and wavelength lambda on
/// a grid of spacing s (a few millimetres for the paper's scenarios; the train filter keeps
/// trains shorter than a few cells out of both). Gerstner waves move points sideways, so the
/// rest position whose displaced point lies over the query is found by Newton's method to a
/// horizontal residual of at most 10 micrometres or for at most 16 steps (see
/// `OceanHeightSample::residual`), then the height and normal are taken there. The library's
/// tests hold it within 5 micrometres of a forward double-precision evaluation of the model.
///
/// Statuses as `ocean_wtb_scene_heights_drawn`, without `OCEAN_STATUS_NOT_EVALUATED`, plus
/// `OCEAN_STATUS_NON_FINITE` for a NaN or infinite `time`. Nothing is written on failure.
///
/// # Safety
///
/// `xz` `n` readable `OceanDVec2`s and `out` `n` writable
/// `OceanHeightSample`s, untouched by other threads during the call.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn ocean_wtb_scene_heights_continuous(
    scene: *const OceanWtbScene,
    time: f64,
    xz: *const OceanDVec2,
    n: usize,
    out: *mut OceanHeightSample,
) -> OceanStatus {
    guard("ocean_wtb_scene_heights_continuous", || {
        let scene = borrow(scene, "scene")?;
        check_ptr(out.cast_const(), "out")?;
        let out_bytes = byte_len::<OceanHeightSample>(n, "out");
        // SAFETY: forwarded from this function's contract.
        let at = unsafe { query_points(xz, n, out.cast_const().cast(), out_bytes) }?;
        check_time(time)?;
        let mut samples = vec![HeightSample::default(); n];
        {
            let mut s = scene.lock();
            let frame = s.frame(time, None)?;
            frame.continuous_heights_par(&at, &mut samples)?;
        }
        // SAFETY: as in `ocean_wtb_scene_heights_drawn`.
        let dst = unsafe { core::slice::from_raw_parts_mut(out, n) };
        for (d, s) in dst.iter_mut().zip(&samples) {
            *d = OceanHeightSample {
                height: s.height,
                normal: OceanDVec3 {
                    x: s.normal.x,
                    y: s.normal.y,
                    z: s.normal.z,
                },
                rest: OceanDVec2 {
                    x: s.rest.x,
                    z: s.rest.y,
                },
                residual: s.residual,
            };
        }
        Ok(())
    })
}

/// Sets which trains the grid's geometry carries: each train's amplitude is weighted by
/// w = smoothstep((lambda / spacing - min_cells) / (max_cells - min_cells)), 0 below
/// `min_cells` grid cells per wavelength (the train is left out), 1 above `max_cells`, as the
/// lighting paper filters its waves on a grid cell (Bruneton et al. section 3.2). What the
/// geometry loses is reported by `OceanFrameStats` (`filtered_trains`, `removed_trains`,
/// `filtered_slope_variance`) for the BRDF's roughness. The default is 2 and 4 cells: below 2
/// (Nyquist) a mesh aliases a train, at 4 it still cuts 29 % off its crests between vertices.
/// Pass 0 and 0 to keep every train whole. Both height queries see the same filtered trains.
///
/// Returns `OCEAN_STATUS_NON_FINITE` for a NaN or infinite threshold,
/// `OCEAN_STATUS_INVALID_ARGUMENT` unless 0 <= `min_cells` < `max_cells` <= 1e6 (or both 0);
/// nothing changes then.
#[unsafe(no_mangle)]
pub extern "C" fn ocean_wtb_scene_set_train_filter(
    scene: *mut OceanWtbScene,
    min_cells: f64,
    max_cells: f64,
) -> OceanStatus {
    guard("ocean_wtb_scene_set_train_filter", || {
        let scene = borrow(scene, "scene")?;
        let filter = if min_cells == 0.0 && max_cells == 0.0 {
            None
        } else {
            Some(TrainFilter::new(min_cells, max_cells)?)
        };
        scene.lock().set_train_filter(filter);
        Ok(())
    })
}
