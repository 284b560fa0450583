//! Relief mapping, part 2 of 2: the CPU tracers (linear + binary search, cone step mapping,
//! relaxed cone stepping + binary search) on batches of rays, and self-shadowing queries, over
//! an `OceanReliefCones` handle (`relief.rs`).
//!
//! The tracers are ocean-relief's `f32` code, the arithmetic a shader port copies: results are
//! bit-identical to `ocean_relief::Method::trace` and `ocean_relief::shadow::in_shadow`.

use glam::{Vec2, Vec3};
use ocean_core::parallel::for_rows;
use ocean_relief::trace::{BinarySearch, MAX_STEPS, Method, Ray};
use ocean_relief::{Hit, ReliefError};

use core::mem::offset_of;

use crate::boundary::OceanNext;
use crate::boundary::{
    CEnum, CheckedStruct, EnumField, Num, borrow, byte_len, check_disjoint, check_finite,
    check_ptr, input, read_params_checked, write_out, write_slice,
};
use crate::relief::{OceanReliefCones, relief_error};
use crate::status::{Error, OceanStatus, guard};

/// `OceanReliefMethod::method`: the tracer.
#[repr(u32)]
#[derive(
    Clone, Copy, Debug, Default, PartialEq, Eq, bytemuck::NoUninit, bytemuck::CheckedBitPattern,
)]
pub enum OceanReliefTracer {
    /// Linear search (Policarpo et al. 2005): `steps` equal depth steps, then `binary`
    /// bisections of the step that first went inside. Reads only the depth.
    #[default]
    Linear = 0,
    /// Cone step mapping (Dummer 2006): `steps` conservative cone steps, no refinement
    /// (`binary` is not read). Needs conservative cones.
    ConeStep = 1,
    /// Relaxed cone stepping (Listing 18-3): `steps` relaxed cone steps, then `binary`
    /// bisections as `search` says. Needs relaxed cones.
    Relaxed = 2,
}

impl CEnum for OceanReliefTracer {
    const REFUSAL: &'static str = "is not an OCEAN_RELIEF_TRACER_* value (0 to 2)";
}

/// `OceanReliefMethod::search`: how relaxed cone stepping refines its hit.
#[repr(u32)]
#[derive(
    Clone, Copy, Debug, Default, PartialEq, Eq, bytemuck::NoUninit, bytemuck::CheckedBitPattern,
)]
pub enum OceanReliefSearch {
    /// Bisect the last cone step (from the last point above the surface to the stop point)
    /// `binary` times (default).
    #[default]
    LastStep = 0,
    /// Listing 18-3's search, `binary` probes starting halfway from the entry point to the stop
    /// point (kept for comparison: less accurate).
    Book = 1,
    /// One budget of `steps + binary` fetches: cone steps while the ray is above the surface,
    /// then bisections of the last step with every fetch left.
    Shared = 2,
}

impl CEnum for OceanReliefSearch {
    const REFUSAL: &'static str = "is not an OCEAN_RELIEF_SEARCH_* value (0 to 2)";
}

/// The largest step count of each phase (`steps`, `binary`).
pub const OCEAN_RELIEF_MAX_STEPS: u32 = 4096;

const _: () = assert!(OCEAN_RELIEF_MAX_STEPS == MAX_STEPS);

/// Rays traced per parallel task.
const CHUNK: usize = 256;

/// A tracer and its step counts.
#[repr(C)]
#[derive(
    Clone, Copy, Debug, Default, PartialEq, Eq, bytemuck::NoUninit, bytemuck::CheckedBitPattern,
)]
pub struct OceanReliefMethod {
    /// Extensions: NULL, or the first extension struct (see `OceanChain`); the `_default`
    /// function sets NULL.
    pub next: OceanNext,
    /// `OCEAN_RELIEF_TRACER_LINEAR`, `_CONE_STEP` or `_RELAXED`; other values are refused.
    pub method: OceanReliefTracer,
    /// Linear steps, cone steps, or relaxed cone steps: 1 to `OCEAN_RELIEF_MAX_STEPS` (the
    /// book: 15 relaxed steps).
    pub steps: u32,
    /// Bisections, 0 to `OCEAN_RELIEF_MAX_STEPS` (the book: 6). Not read by cone step mapping.
    pub binary: u32,
    /// `OCEAN_RELIEF_SEARCH_*`: read only by relaxed cone stepping, but checked whatever the
    /// tracer (other values are refused).
    pub search: OceanReliefSearch,
}

impl CheckedStruct for OceanReliefMethod {
    const ENUM_FIELDS: &'static [EnumField] = &[
        EnumField::of::<OceanReliefTracer>("method", offset_of!(OceanReliefMethod, method)),
        EnumField::of::<OceanReliefSearch>("search", offset_of!(OceanReliefMethod, search)),
    ];
}

/// Stores the tracer that `ocean_relief_scene_default` draws with in `*out`: relaxed cone
/// stepping (Listing 18-3) with the book's 15 cone steps and 6 bisections, refining the last
/// step (`OCEAN_RELIEF_SEARCH_LAST_STEP`). Trace with a relaxed cone map.
///
/// Returns `OCEAN_STATUS_NULL_POINTER` (or `_MISALIGNED_POINTER`) for a bad `out`, which is
/// then left unchanged.
///
/// # Safety
///
/// `out` must be writable.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn ocean_relief_method_default(out: *mut OceanReliefMethod) -> OceanStatus {
    guard("ocean_relief_method_default", || {
        let method = OceanReliefMethod {
            next: OceanNext::NULL,
            method: OceanReliefTracer::Relaxed,
            steps: 15,
            binary: 6,
            search: OceanReliefSearch::LastStep,
        };
        // SAFETY: forwarded from this function's contract.
        unsafe { write_out(out, "out", method) }
    })
}

/// A point of the relief: texture coordinates and normalised depth (0 at the polygon, 1 at the
/// bottom of the relief).
#[repr(C)]
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct OceanReliefPoint {
    /// Texture coordinate u (texture widths; texel i's centre is at (i + 0.5)/N).
    pub u: f32,
    /// Texture coordinate v.
    pub v: f32,
    /// Depth, 0 at the polygon surface, 1 at the bottom.
    pub depth: f32,
}

/// A ray into the relief (section 18.2): it enters at texture coordinates (start_u, start_v)
/// at depth 0 and moves by (dir_x, dir_y) texture widths per dir_z of depth. Only the ratios
/// matter (the tracers divide by dir_z, as the book's `ray_dir /= ray_dir.z`), and they must
/// stay finite: a dir_z so small beside dir_x, dir_y that the run per unit depth overflows a
/// float is refused, and so is a ray whose |start| plus run to full depth exceeds 1e30 texture
/// widths (`ocean_relief::MAX_TEXCOORD`). `ocean_relief_ray_from_view` makes one from a
/// tangent-space view vector.
#[repr(C)]
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct OceanReliefRay {
    /// Entry point, texture coordinate u.
    pub start_u: f32,
    /// Entry point, texture coordinate v.
    pub start_v: f32,
    /// Direction along u.
    pub dir_x: f32,
    /// Direction along v.
    pub dir_y: f32,
    /// Direction in depth: positive (into the relief).
    pub dir_z: f32,
}

/// Where a tracer stopped.
#[repr(C)]
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct OceanReliefHit {
    /// The hit (the midpoint of the final bracket; for cone step mapping, and for a shared
    /// budget spent before the ray got inside, the last point known to be above the surface).
    pub pos: OceanReliefPoint,
    /// Texture fetches spent on the ray.
    pub fetches: u32,
}

pub(crate) fn method_from(m: &OceanReliefMethod) -> Result<Method, Error> {
    let range = |name: &str, v: u32, min: u32| -> Result<(), Error> {
        if v < min || v > MAX_STEPS {
            return Err(Error::new(
                OceanStatus::InvalidArgument,
                format!("method->{name} = {v} is outside {min} to {MAX_STEPS}"),
            ));
        }
        Ok(())
    };
    range("steps", m.steps, 1)?;
    Ok(match m.method {
        OceanReliefTracer::Linear => {
            range("binary", m.binary, 0)?;
            Method::Linear {
                linear: m.steps,
                binary: m.binary,
            }
        }
        OceanReliefTracer::ConeStep => Method::ConeStep { steps: m.steps },
        OceanReliefTracer::Relaxed => {
            range("binary", m.binary, 0)?;
            Method::Relaxed {
                cone: m.steps,
                binary: m.binary,
                search: match m.search {
                    OceanReliefSearch::LastStep => BinarySearch::LastStep,
                    OceanReliefSearch::Book => BinarySearch::Book,
                    OceanReliefSearch::Shared => BinarySearch::Shared,
                },
            }
        }
    })
}

/// The crate's ray for `rays[i]`, refusing non-finite members (`OCEAN_STATUS_NON_FINITE`) and a
/// direction that does not point into the relief.
fn ray_from(i: usize, r: &OceanReliefRay) -> Result<Ray, Error> {
    check_finite(
        &format!("rays[{i}]."),
        &[
            ("start_u", f64::from(r.start_u)),
            ("start_v", f64::from(r.start_v)),
            ("dir_x", f64::from(r.dir_x)),
            ("dir_y", f64::from(r.dir_y)),
            ("dir_z", f64::from(r.dir_z)),
        ],
    )?;
    if r.dir_z <= 0.0 {
        return Err(Error::new(
            OceanStatus::InvalidArgument,
            format!(
                "rays[{i}].dir_z = {} must be positive: the ray must point into the relief",
                r.dir_z
            ),
        ));
    }
    Ok(Ray {
        start: Vec2::new(r.start_u, r.start_v),
        dir: Vec3::new(r.dir_x, r.dir_y, r.dir_z),
    })
}

fn hit_out(h: &ocean_relief::Hit) -> OceanReliefHit {
    OceanReliefHit {
        pos: OceanReliefPoint {
            u: h.pos.x,
            v: h.pos.y,
            depth: h.pos.z,
        },
        fetches: h.fetches,
    }
}

/// Stores in `*out` the ray of the tangent-space view vector (view_x, view_y, view_z) (x along
/// u, y along v, z out of the polygon; view_z < 0 looking at it; any length) entering at
/// (start_u, start_v), for a relief `depth` texture widths deep: the direction
/// (depth view_x / -view_z, depth view_y / -view_z, 1). Rescaling the depth changes the ray,
/// never the cones (section 18.5).
///
/// Returns `OCEAN_STATUS_NULL_POINTER` / `_MISALIGNED_POINTER` for a bad `out`,
/// `OCEAN_STATUS_NON_FINITE` for a NaN or infinite argument, `OCEAN_STATUS_INVALID_ARGUMENT` if
/// view_z >= 0 or depth < 0. `*out` is written only on success.
///
/// # Safety
///
/// `out` must be writable.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn ocean_relief_ray_from_view(
    start_u: f32,
    start_v: f32,
    view_x: f32,
    view_y: f32,
    view_z: f32,
    depth: f32,
    out: *mut OceanReliefRay,
) -> OceanStatus {
    guard("ocean_relief_ray_from_view", || {
        check_ptr(out.cast_const(), "out")?;
        check_finite(
            "",
            &[
                ("start_u", f64::from(start_u)),
                ("start_v", f64::from(start_v)),
                ("view_x", f64::from(view_x)),
                ("view_y", f64::from(view_y)),
                ("view_z", f64::from(view_z)),
                ("depth", f64::from(depth)),
            ],
        )?;
        if view_z >= 0.0 {
            return Err(Error::new(
                OceanStatus::InvalidArgument,
                format!(
                    "view_z = {} must be negative: the view must look at the polygon",
                    Num(view_z)
                ),
            ));
        }
        let ray = Ray::from_view(
            Vec2::new(start_u, start_v),
            Vec3::new(view_x, view_y, view_z),
            depth,
        )?;
        let r = OceanReliefRay {
            start_u: ray.start.x,
            start_v: ray.start.y,
            dir_x: ray.dir.x,
            dir_y: ray.dir.y,
            dir_z: ray.dir.z,
        };
        // SAFETY: forwarded from this function's contract.
        unsafe { write_out(out, "out", r) }
    })
}

/// Traces `count` rays through `cones` with `method` and stores where each stopped in
/// `hits[i]`. Rays are traced in parallel on the library's threads; each result is
/// bit-identical to `ocean_relief::Method::trace` for that ray.
///
/// Cone step mapping assumes conservative cones and relaxed cone stepping relaxed ones (see
/// `OceanReliefConeParams::kind`); the other pairing runs but loses the guarantee that no
/// feature is stepped over. Linear search reads only the depths.
///
/// Returns `OCEAN_STATUS_NULL_POINTER` / `_MISALIGNED_POINTER` for a bad pointer (4-byte
/// alignment for the arrays), `OCEAN_STATUS_EMPTY` if `count` is 0,
/// `OCEAN_STATUS_LENGTH_OVERFLOW` if an array's byte size exceeds `PTRDIFF_MAX`,
/// `OCEAN_STATUS_NON_FINITE` for a NaN or infinite ray member, `OCEAN_STATUS_INVALID_ARGUMENT`
/// for an unknown method or search, a step count out of range, a ray with dir_z <= 0 (the
/// message names the first bad ray) or overlapping arrays. `hits` is written only on success,
/// and then wholly.
///
/// # Safety
///
/// `method` readable, `rays` point to `count` readable rays and
/// `hits` to `count` writable hits, neither touched by another thread during the call.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn ocean_relief_trace(
    cones: *const OceanReliefCones,
    method: *const OceanReliefMethod,
    rays: *const OceanReliefRay,
    count: usize,
    hits: *mut OceanReliefHit,
) -> OceanStatus {
    guard("ocean_relief_trace", || {
        let c = borrow(cones, "cones")?;
        let texture = c.texture();
        // SAFETY: forwarded from this function's contract.
        unsafe { trace_batch(method, rays, count, hits, |m, r| m.trace(texture, r)) }
    })
}

/// The body of `ocean_relief_trace` after the handle: every check, then `trace` on each ray in
/// parallel, then the hits written.
///
/// # Safety
///
/// As `ocean_relief_trace`'s `method`, `rays`, `count` and `hits`.
pub(crate) unsafe fn trace_batch(
    method: *const OceanReliefMethod,
    rays: *const OceanReliefRay,
    count: usize,
    hits: *mut OceanReliefHit,
    trace: impl Fn(&Method, &Ray) -> Result<Hit, ReliefError> + Sync,
) -> Result<(), Error> {
    check_ptr(method, "method")?;
    check_ptr(rays, "rays")?;
    check_ptr(hits.cast_const(), "hits")?;
    if count == 0 {
        return Err(Error::new(OceanStatus::Empty, "`count` is 0: no rays"));
    }
    let in_bytes = byte_len::<OceanReliefRay>(count, "rays")?;
    let out_bytes = byte_len::<OceanReliefHit>(count, "hits")?;
    check_disjoint(
        (rays.cast::<u8>(), in_bytes, "rays"),
        (hits.cast_const().cast::<u8>(), out_bytes, "hits"),
    )?;
    // SAFETY: forwarded from this function's contract (the pointer checked above).
    let method = method_from(&unsafe { read_params_checked(method, "method") }?)?;
    // SAFETY: forwarded from this function's contract (pointer, size and overlap checked).
    let rays = unsafe { input(rays, count, "rays") }?;
    let rays = rays
        .iter()
        .enumerate()
        .map(|(i, r)| ray_from(i, r))
        .collect::<Result<Vec<_>, _>>()?;
    let mut results = vec![Ok(OceanReliefHit::default()); count];
    for_rows(&mut results, CHUNK, |j, part| {
        for (k, out) in part.iter_mut().enumerate() {
            *out = trace(&method, &rays[j * CHUNK + k]).map(|h| hit_out(&h));
        }
    });
    let out = results
        .into_iter()
        .enumerate()
        .map(|(i, r)| r.map_err(|e| relief_error(&format!("rays[{i}]: "), e)))
        .collect::<Result<Vec<_>, _>>()?;
    // SAFETY: forwarded from this function's contract (checked above).
    unsafe { write_slice(hits, "hits", &out) }
}

/// For each of `count` surface points, whether the light from the tangent-space direction
/// (light_x, light_y, light_z) (towards the light; light_z > 0 above the polygon; any length)
/// is blocked before it reaches the point, for a relief `depth_scale` texture widths deep:
/// the light ray is traced from where it enters the relief towards the point with `method`,
/// and the point is in shadow (1 in `in_shadow[i]`, else 0) when the ray stops more than `bias`
/// (depth units, in [0, 1]) above it; the bias absorbs the tracer's final bracket, or a point
/// shadows itself (a few times the last step over 2^binary works). A light at or below the
/// polygon's plane (light_z <= 0) leaves every point in shadow, and so does a light so close
/// above it (light_z = FLT_TRUE_MIN beside a unit light_x) that its run per unit depth
/// overflows a float. Points are processed in
/// parallel; each answer equals `ocean_relief::shadow::in_shadow`'s.
///
/// Returns `OCEAN_STATUS_NULL_POINTER` / `_MISALIGNED_POINTER` for a bad pointer,
/// `OCEAN_STATUS_EMPTY` if `count` is 0, `OCEAN_STATUS_LENGTH_OVERFLOW` for an array whose byte
/// size exceeds `PTRDIFF_MAX`, `OCEAN_STATUS_NON_FINITE` for a NaN or infinite light, depth
/// scale, bias or point member, `OCEAN_STATUS_INVALID_ARGUMENT` for a bad method, a negative
/// `depth_scale`, a `bias` outside [0, 1], or overlapping arrays. `in_shadow` is written only
/// on success, and then wholly.
///
/// # Safety
///
/// `method` readable, `points` point to `count` readable points
/// and `in_shadow` to `count` writable bytes, neither touched by another thread during the
/// call.
#[unsafe(no_mangle)]
#[allow(clippy::too_many_arguments)]
pub unsafe extern "C" fn ocean_relief_shadow(
    cones: *const OceanReliefCones,
    method: *const OceanReliefMethod,
    points: *const OceanReliefPoint,
    count: usize,
    light_x: f32,
    light_y: f32,
    light_z: f32,
    depth_scale: f32,
    bias: f32,
    in_shadow: *mut u8,
) -> OceanStatus {
    guard("ocean_relief_shadow", || {
        let c = borrow(cones, "cones")?;
        let texture = c.texture();
        let light = [light_x, light_y, light_z];
        // SAFETY: forwarded from this function's contract.
        unsafe {
            shadow_batch(
                method,
                points,
                count,
                light,
                depth_scale,
                bias,
                in_shadow,
                |m, p, l| ocean_relief::shadow::in_shadow(texture, m, p, l, depth_scale, bias),
            )
        }
    })
}

/// The body of `ocean_relief_shadow` after the handle: every check, then `shadow` (method,
/// point, light) on each point in parallel, then the answers written.
///
/// # Safety
///
/// As `ocean_relief_shadow`'s `method`, `points`, `count` and `in_shadow`.
#[allow(clippy::too_many_arguments)]
pub(crate) unsafe fn shadow_batch(
    method: *const OceanReliefMethod,
    points: *const OceanReliefPoint,
    count: usize,
    [light_x, light_y, light_z]: [f32; 3],
    depth_scale: f32,
    bias: f32,
    in_shadow: *mut u8,
    shadow: impl Fn(&Method, Vec3, Vec3) -> Result<bool, ReliefError> + Sync,
) -> Result<(), Error> {
    check_ptr(method, "method")?;
    check_ptr(points, "points")?;
    check_ptr(in_shadow.cast_const(), "in_shadow")?;
    if count == 0 {
        return Err(Error::new(OceanStatus::Empty, "`count` is 0: no points"));
    }
    let in_bytes = byte_len::<OceanReliefPoint>(count, "points")?;
    let out_bytes = byte_len::<u8>(count, "in_shadow")?;
    check_disjoint(
        (points.cast::<u8>(), in_bytes, "points"),
        (in_shadow.cast_const(), out_bytes, "in_shadow"),
    )?;
    // SAFETY: forwarded from this function's contract (the pointer checked above).
    let method = method_from(&unsafe { read_params_checked(method, "method") }?)?;
    check_finite(
        "",
        &[
            ("light_x", f64::from(light_x)),
            ("light_y", f64::from(light_y)),
            ("light_z", f64::from(light_z)),
            ("depth_scale", f64::from(depth_scale)),
            ("bias", f64::from(bias)),
        ],
    )?;
    if depth_scale < 0.0 {
        return Err(Error::new(
            OceanStatus::InvalidArgument,
            format!("depth_scale = {} must be >= 0", Num(depth_scale)),
        ));
    }
    if !(0.0..=1.0).contains(&bias) {
        return Err(Error::new(
            OceanStatus::InvalidArgument,
            format!("bias = {} is outside [0, 1]", Num(bias)),
        ));
    }
    // SAFETY: forwarded from this function's contract (pointer, size and overlap checked).
    let points = unsafe { input(points, count, "points") }?;
    for (i, p) in points.iter().enumerate() {
        check_finite(
            &format!("points[{i}]."),
            &[
                ("u", f64::from(p.u)),
                ("v", f64::from(p.v)),
                ("depth", f64::from(p.depth)),
            ],
        )?;
    }
    let light = Vec3::new(light_x, light_y, light_z);
    let mut results = vec![Ok(0u8); count];
    for_rows(&mut results, CHUNK, |j, part| {
        for (k, out) in part.iter_mut().enumerate() {
            let p = points[j * CHUNK + k];
            *out = shadow(&method, Vec3::new(p.u, p.v, p.depth), light).map(u8::from);
        }
    });
    let out = results
        .into_iter()
        .enumerate()
        .map(|(i, r)| r.map_err(|e| relief_error(&format!("points[{i}]: "), e)))
        .collect::<Result<Vec<_>, _>>()?;
    // SAFETY: forwarded from this function's contract (checked above).
    unsafe { write_slice(in_shadow, "in_shadow", &out) }
}

crate::boundary::chain::extensible!(OceanReliefMethod);
