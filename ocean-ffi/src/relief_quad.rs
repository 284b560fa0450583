//! Relief mapping through quad-directional cone maps (ocean-relief's `quad` module; *GPU Gems 3*
//! §18.1's four cones per texel, relaxed as well as conservative): generation with the progress
//! callback of `relief.rs`, the 4-layer texture for upload, and the CPU tracer and shadow
//! queries that pick each ray's layer as the `relief_quad` shader does.
//!
//! A ray's horizontal direction never changes, so each texel keeps one cone per closed quadrant
//! of it: layer k = x_neg + 2 y_neg holds the cones valid for the rays with dir_x <= 0 (x_neg)
//! or >= 0 and dir_y <= 0 (y_neg) or >= 0. The tracer picks the layer once per ray from the
//! signs of (dir_x / dir_z, dir_y / dir_z) (a negative value the negative side, 0 and -0 the
//! positive one), then runs the isotropic tracer's arithmetic on it.

use core::ffi::c_void;

use ocean_relief::{HeightMap, QuadConeMap, QuadReliefTexture};

use crate::boundary::{
    borrow, check_len, check_ptr, destroy, read_params_checked, write_handle, write_out,
    write_slice,
};
use crate::relief::{
    OceanReliefConeParams, OceanReliefMap, OceanReliefProgress, params_from, with_progress,
};
use crate::relief_encode::texels;
use crate::relief_trace::{
    OceanReliefHit, OceanReliefMethod, OceanReliefPoint, OceanReliefRay, shadow_batch, trace_batch,
};
use crate::status::{Error, OceanStatus, guard};

/// Array layers of a quad-directional cone map: one per closed quadrant of the ray's horizontal
/// direction, layer k = x_neg + 2 y_neg (`OCEAN_RELIEF_QUAD_X_NEG`, `_Y_NEG`).
pub const OCEAN_RELIEF_QUAD_LAYERS: u32 = 4;
/// Layer bit of the quadrant of rays with dir_x < 0 (dir_x = 0 uses the other side).
pub const OCEAN_RELIEF_QUAD_X_NEG: u32 = 1;
/// Layer bit of the quadrant of rays with dir_y < 0 (dir_y = 0 uses the other side).
pub const OCEAN_RELIEF_QUAD_Y_NEG: u32 = 2;

const _: () = assert!(OCEAN_RELIEF_QUAD_LAYERS as usize == ocean_relief::Quadrant::ALL.len());
const _: () = assert!(
    OCEAN_RELIEF_QUAD_X_NEG as usize == ocean_relief::Quadrant::new(true, false).index()
        && OCEAN_RELIEF_QUAD_Y_NEG as usize == ocean_relief::Quadrant::new(false, true).index()
);

/// A quad-directional cone map together with the height map it was made for: what the CPU
/// quadrant tracer reads (opaque). Create with `ocean_relief_quad_cones_create`, free with
/// `ocean_relief_quad_cones_destroy`. Immutable and shareable between threads.
pub struct OceanReliefQuadCones {
    map: HeightMap,
    cones: QuadConeMap,
    texture: QuadReliefTexture,
}

const _: () = {
    const fn shareable<T: Send + Sync>() {}
    shareable::<OceanReliefQuadCones>();
};

/// The generator with the caller's callback.
fn generate_quad(
    map: &HeightMap,
    params: &OceanReliefConeParams,
    progress: OceanReliefProgress,
    user: *mut c_void,
) -> Result<QuadConeMap, Error> {
    let params = params_from(params)?;
    with_progress(progress, user, |report| match report {
        None => QuadConeMap::generate(map, params),
        Some(r) => QuadConeMap::generate_with(map, params, r),
    })
}

/// The 4-layer texture array, flattened: layer 0's N * N texels `[depth, c_0, D_0, E_0]`
/// row-major, then layers 1, 2 and 3.
fn quad_texels(map: &HeightMap, cones: &QuadConeMap) -> Vec<f32> {
    cones
        .layers()
        .iter()
        .flat_map(|layer| texels(map, layer))
        .collect()
}

/// Floats of the texture array of a side-`n` map: 4 layers of N * N texels of 4 floats.
fn quad_len(n: usize) -> usize {
    16 * n * n
}

/// Generates the quad-directional cone map of `map` (one relaxed or conservative cone map per
/// quadrant of the ray's direction, see `OceanReliefConeParams`) and stores a handle that holds
/// it and a copy of the map in `*out`: what `ocean_relief_quad_trace` and
/// `ocean_relief_quad_shadow` read.
///
/// Each layer has the three channels of `ocean_relief_cones_create` (c, D, E, rounded down to
/// float, capped at `params->max_ratio`), valid for the rays of its quadrant through the
/// bilinear surface; every layer's cone is at least the isotropic one. The result is
/// bit-identical to `ocean_relief::QuadConeMap::generate` on every thread count, with or
/// without `progress`. It costs about four isotropic generations.
///
/// `progress` (may be NULL) is called as `OceanReliefProgress` describes, with `user`, except
/// that the work is four layers of rows: `total` is 4 N in wrap mode and 4 (N + 1) in clamp
/// mode, and there are still at most `OCEAN_RELIEF_PROGRESS_BANDS + 1` calls (each layer in
/// at most a quarter of the bands). A nonzero return cancels.
///
/// Returns `OCEAN_STATUS_NULL_POINTER` / `_MISALIGNED_POINTER` for a bad pointer,
/// `OCEAN_STATUS_NON_FINITE` for a NaN or infinite `max_ratio`, `OCEAN_STATUS_INVALID_ARGUMENT`
/// for an unknown kind or a `max_ratio` outside (0, `OCEAN_RELIEF_MAX_RATIO_LIMIT`],
/// `OCEAN_STATUS_CANCELLED` when the callback returned nonzero (the arguments are checked before
/// the first call). `*out` is written only on success.
///
/// # Safety
///
/// `params` readable, `out` writable; `progress`, if not NULL,
/// must be safe to call with `user` from this thread.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn ocean_relief_quad_cones_create(
    map: *const OceanReliefMap,
    params: *const OceanReliefConeParams,
    progress: OceanReliefProgress,
    user: *mut c_void,
    out: *mut *mut OceanReliefQuadCones,
) -> OceanStatus {
    guard("ocean_relief_quad_cones_create", || {
        let m = borrow(map, "map")?;
        check_ptr(params, "params")?;
        check_ptr(out.cast_const(), "out")?;
        // SAFETY: forwarded from this function's contract (the pointer checked above).
        let params = unsafe { read_params_checked(params, "params") }?;
        let cones = generate_quad(&m.map, &params, progress, user)?;
        let texture = QuadReliefTexture::new(&m.map, &cones)?;
        let handle = OceanReliefQuadCones {
            map: m.map.clone(),
            cones,
            texture,
        };
        // SAFETY: forwarded from this function's contract.
        unsafe { write_handle(out, handle) }
    })
}

/// Frees a quad-directional cone map. NULL does nothing; a handle of another kind or already
/// destroyed frees nothing and sets the last-error message (see the header's notes on handles).
#[unsafe(no_mangle)]
pub extern "C" fn ocean_relief_quad_cones_destroy(cones: *mut OceanReliefQuadCones) {
    destroy(cones, "ocean_relief_quad_cones_destroy", "cones");
}

/// Stores the side N of the quad-directional cone map (that of its height map), texels, in
/// `*out_size`.
///
/// Returns `OCEAN_STATUS_NULL_POINTER` / `_MISALIGNED_POINTER` for a bad pointer; `*out_size`
/// is written only on success.
///
/// # Safety
///
/// `out_size` must be writable.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn ocean_relief_quad_cones_size(
    cones: *const OceanReliefQuadCones,
    out_size: *mut u32,
) -> OceanStatus {
    guard("ocean_relief_quad_cones_size", || {
        let c = borrow(cones, "cones")?;
        // At most OCEAN_RELIEF_MAX_SIDE.
        let side = c.cones.size() as u32;
        // SAFETY: forwarded from this function's contract.
        unsafe { write_out(out_size, "out_size", side) }
    })
}

/// Copies the quadrant relief texture into `rgba`: `len` = 16 N * N floats, the 4 layers of an
/// `RGBA32F` 2D texture array one after the other (layer k = x_neg + 2 y_neg, its N * N texels
/// row-major, `[depth, c_k, D_k, E_k]` per texel): upload with one `glTexSubImage3D` of depth
/// 4 into a `GL_TEXTURE_2D_ARRAY` and draw with the `relief_quad` shader. Exactly what the CPU
/// quadrant tracer reads.
///
/// Returns `OCEAN_STATUS_NULL_POINTER` / `_MISALIGNED_POINTER` for a bad pointer,
/// `OCEAN_STATUS_LENGTH_MISMATCH` if `len` is not 16 N * N. Nothing is written on failure.
///
/// # Safety
///
/// `rgba` must point to `len` writable floats that no other thread
/// touches during the call.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn ocean_relief_quad_cones_texels(
    cones: *const OceanReliefQuadCones,
    rgba: *mut f32,
    len: usize,
) -> OceanStatus {
    guard("ocean_relief_quad_cones_texels", || {
        let c = borrow(cones, "cones")?;
        check_ptr(rgba.cast_const(), "rgba")?;
        let n = c.cones.size();
        check_len(
            "len",
            len,
            quad_len(n),
            "the texture array (4 layers of 4 floats a texel)",
        )?;
        let t = quad_texels(&c.map, &c.cones);
        // SAFETY: forwarded from this function's contract.
        unsafe { write_slice(rgba, "rgba", &t) }
    })
}

/// Generates the quad-directional cone map of `map` straight into `rgba` (no handle): `len` =
/// 16 N * N floats, as `ocean_relief_quad_cones_texels` writes them. Arguments, callback and
/// statuses as `ocean_relief_quad_cones_create`, with `OCEAN_STATUS_LENGTH_MISMATCH` for a
/// `len` that is not 16 N * N (checked before any work). `rgba` is written only on success,
/// and then wholly.
///
/// # Safety
///
/// `params` readable, `rgba` point to `len` writable floats that
/// no other thread touches during the call; `progress`, if not NULL, must be safe to call with
/// `user` from this thread.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn ocean_relief_quad_generate_texels(
    map: *const OceanReliefMap,
    params: *const OceanReliefConeParams,
    progress: OceanReliefProgress,
    user: *mut c_void,
    rgba: *mut f32,
    len: usize,
) -> OceanStatus {
    guard("ocean_relief_quad_generate_texels", || {
        let m = borrow(map, "map")?;
        check_ptr(params, "params")?;
        check_ptr(rgba.cast_const(), "rgba")?;
        // The parameters before the length, as ocean_relief_generate_texels checks them.
        // SAFETY: forwarded from this function's contract (the pointer checked above).
        let params = unsafe { read_params_checked(params, "params") }?;
        params_from(&params)?;
        let n = m.map.size();
        check_len(
            "len",
            len,
            quad_len(n),
            "the texture array (4 layers of 4 floats a texel)",
        )?;
        let cones = generate_quad(&m.map, &params, progress, user)?;
        let t = quad_texels(&m.map, &cones);
        // SAFETY: forwarded from this function's contract.
        unsafe { write_slice(rgba, "rgba", &t) }
    })
}

/// Traces `count` rays through the quad-directional cone map `cones` with `method` and stores
/// where each stopped in `hits[i]`: each ray reads the layer of its direction's quadrant (the
/// module documentation), chosen once, then runs `ocean_relief_trace`'s tracer on it (with
/// conservative quadrant cones, cone step mapping is QDCSM, section 18.1). Each result is
/// bit-identical to `ocean_relief::QuadReliefTexture::trace` and to the `relief_quad` shader's
/// tracer on the texels of `ocean_relief_quad_cones_texels`.
///
/// Arguments, checks and statuses as `ocean_relief_trace`. `hits` is written only on success,
/// and then wholly.
///
/// # Safety
///
/// `method` readable, `rays` point to `count` readable rays and
/// `hits` to `count` writable hits, neither touched by another thread during the call.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn ocean_relief_quad_trace(
    cones: *const OceanReliefQuadCones,
    method: *const OceanReliefMethod,
    rays: *const OceanReliefRay,
    count: usize,
    hits: *mut OceanReliefHit,
) -> OceanStatus {
    guard("ocean_relief_quad_trace", || {
        let c = borrow(cones, "cones")?;
        let texture = &c.texture;
        // SAFETY: forwarded from this function's contract.
        unsafe { trace_batch(method, rays, count, hits, |m, r| texture.trace(m, r)) }
    })
}

/// `ocean_relief_shadow` through the quad-directional cone map `cones`: the light ray towards
/// each point reads the layer of its own direction's quadrant. Arguments, checks and statuses
/// as `ocean_relief_shadow`; each answer equals `ocean_relief::QuadReliefTexture::in_shadow`'s.
/// `in_shadow` is written only on success, and then wholly.
///
/// # Safety
///
/// `method` readable, `points` point to `count` readable points
/// and `in_shadow` to `count` writable bytes, neither touched by another thread during the
/// call.
#[unsafe(no_mangle)]
#[allow(clippy::too_many_arguments)]
pub unsafe extern "C" fn ocean_relief_quad_shadow(
    cones: *const OceanReliefQuadCones,
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
    guard("ocean_relief_quad_shadow", || {
        let c = borrow(cones, "cones")?;
        let texture = &c.texture;
        // SAFETY: forwarded from this function's contract.
        unsafe {
            shadow_batch(
                method,
                points,
                count,
                [light_x, light_y, light_z],
                depth_scale,
                bias,
                in_shadow,
                |m, p, l| texture.in_shadow(m, p, l, depth_scale, bias),
            )
        }
    })
}

crate::boundary::handle::handles!(OceanReliefQuadCones);

#[cfg(test)]
mod tests {
    use core::ptr::null_mut;

    use glam::{Vec2, Vec3};
    use ocean_relief::maps::{boxes, to_map};
    use ocean_relief::trace::BinarySearch;
    use ocean_relief::{ConeParams, Edge, Method, Ray};

    use super::*;
    use crate::relief::{OceanReliefConeKind, ocean_relief_map_create_f32};
    use crate::relief_trace::{OceanReliefSearch, OceanReliefTracer};
    use crate::status::last_error;

    const N: u32 = 32;

    /// The wrapper adds nothing to the crate's arithmetic: the texture array is
    /// `QuadReliefTexture::texels` flattened, and every hit and shadow answer is bit-identical
    /// to `QuadReliefTexture::trace` / `in_shadow`, on rays of every azimuth (all four layers)
    /// over boxes in wrap mode.
    #[test]
    fn outputs_are_the_crates_bit_for_bit() {
        let h = boxes(N as usize, 8, 3);
        let mut map = null_mut();
        // SAFETY: valid pointers and lengths.
        let s = unsafe { ocean_relief_map_create_f32(h.as_ptr(), h.len(), N, N, 0, 0, &mut map) };
        assert_eq!(s, OceanStatus::Ok, "{}", last_error());
        let p = OceanReliefConeParams {
            next: crate::boundary::OceanNext::NULL,
            kind: OceanReliefConeKind::Relaxed,
            max_ratio: 2.0,
        };
        let mut cones = null_mut();
        // SAFETY: live handle, valid pointers; no callback.
        let s = unsafe { ocean_relief_quad_cones_create(map, &p, None, null_mut(), &mut cones) };
        assert_eq!(s, OceanStatus::Ok, "{}", last_error());

        let crate_map = to_map(N as usize, &h, Edge::Wrap).unwrap();
        let quad = QuadConeMap::generate(&crate_map, ConeParams::relaxed(2.0)).unwrap();
        let tex = QuadReliefTexture::new(&crate_map, &quad).unwrap();
        let mut texels = vec![-1.0f32; quad_len(N as usize)];
        // SAFETY: live handle, buffer of the given length.
        let s = unsafe { ocean_relief_quad_cones_texels(cones, texels.as_mut_ptr(), texels.len()) };
        assert_eq!(s, OceanStatus::Ok, "{}", last_error());
        let want: Vec<f32> = tex.texels().into_iter().flatten().collect();
        assert_eq!(
            texels.iter().map(|v| v.to_bits()).collect::<Vec<_>>(),
            want.iter().map(|v| v.to_bits()).collect::<Vec<_>>()
        );
        // Straight into a buffer: the same texels.
        let mut direct = vec![-1.0f32; texels.len()];
        // SAFETY: live handle, valid pointers, buffer of the given length; no callback.
        let s = unsafe {
            ocean_relief_quad_generate_texels(
                map,
                &p,
                None,
                null_mut(),
                direct.as_mut_ptr(),
                direct.len(),
            )
        };
        assert_eq!(s, OceanStatus::Ok, "{}", last_error());
        assert_eq!(direct, texels);

        let m = OceanReliefMethod {
            next: crate::boundary::OceanNext::NULL,
            method: OceanReliefTracer::Relaxed,
            steps: 20,
            binary: 6,
            search: OceanReliefSearch::Shared,
        };
        let method = Method::Relaxed {
            cone: 20,
            binary: 6,
            search: BinarySearch::Shared,
        };
        let rays: Vec<OceanReliefRay> = (0..64)
            .map(|k| {
                let phi = k as f32 * 0.37;
                OceanReliefRay {
                    start_u: (k as f32 * 0.13).fract(),
                    start_v: (k as f32 * 0.29).fract(),
                    dir_x: 0.3 * phi.cos(),
                    dir_y: 0.3 * phi.sin(),
                    dir_z: 1.0,
                }
            })
            .collect();
        let mut hits = vec![OceanReliefHit::default(); rays.len()];
        // SAFETY: live handle, arrays of `count` elements.
        let s = unsafe {
            ocean_relief_quad_trace(cones, &m, rays.as_ptr(), rays.len(), hits.as_mut_ptr())
        };
        assert_eq!(s, OceanStatus::Ok, "{}", last_error());
        let mut layers = [0; 4];
        let mut points = Vec::new();
        for (r, h) in rays.iter().zip(&hits) {
            let ray = Ray {
                start: Vec2::new(r.start_u, r.start_v),
                dir: Vec3::new(r.dir_x, r.dir_y, r.dir_z),
            };
            layers[QuadReliefTexture::quadrant(&ray).unwrap().index()] += 1;
            let c = tex.trace(&method, &ray).unwrap();
            assert_eq!(
                [h.pos.u, h.pos.v, h.pos.depth].map(f32::to_bits),
                c.pos.to_array().map(f32::to_bits)
            );
            assert_eq!(h.fetches, c.fetches);
            points.push(h.pos);
        }
        assert!(layers.iter().all(|&k| k > 0), "{layers:?}");
        let light = Vec3::new(-0.4, 0.7, 0.5);
        let mut shadow = vec![7u8; points.len()];
        // SAFETY: live handle, arrays of `count` elements.
        let s = unsafe {
            ocean_relief_quad_shadow(
                cones,
                &m,
                points.as_ptr(),
                points.len(),
                light.x,
                light.y,
                light.z,
                0.2,
                0.02,
                shadow.as_mut_ptr(),
            )
        };
        assert_eq!(s, OceanStatus::Ok, "{}", last_error());
        for (p, &sh) in points.iter().zip(&shadow) {
            let want = tex
                .in_shadow(&method, Vec3::new(p.u, p.v, p.depth), light, 0.2, 0.02)
                .unwrap();
            assert_eq!(sh, u8::from(want));
        }
        {
            ocean_relief_quad_cones_destroy(cones);
            crate::relief::ocean_relief_map_destroy(map);
        }
    }
}
