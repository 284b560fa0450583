//! The ambient obscurance on the GPU (crate `ocean-gpu`'s `SaoPass`) on the library's own
//! headless device: the five passes of McGuire, Mara & Luebke (2012) on a depth buffer uploaded
//! from the caller, the obscurance read back into the caller's buffer. The GPU twin of
//! `ocean_sao_run`, with the same `OceanSao` set-up, buffers and statuses.
//!
//! An engine with its own OpenGL pipeline runs the exported GLSL of the same passes instead
//! (`ocean_shader_export` with the `sao_*` shaders and their binding tables).

use std::sync::{Mutex, MutexGuard, PoisonError};

use ocean_gpu::SaoPass;
use ocean_sao::SaoUniforms;

use crate::boundary::{borrow, check_block_out, destroy, write_block, write_handle};
use crate::gpu::OceanGpuContext;
use crate::sao::{OceanSao, buffers};
use crate::status::{Error, OceanStatus, guard};

/// The GPU ambient obscurance passes (opaque), with the textures they keep for the last image
/// size they ran at. Create with `ocean_sao_gpu_create` on a context, run with
/// `ocean_sao_gpu_run`, free with `ocean_sao_gpu_destroy`. It works only with the context it
/// was created on. Every call locks it, so any thread may use it, but calls on one handle run
/// one at a time.
pub struct OceanSaoGpu {
    /// `OceanGpuContext::id` of its context.
    context: u64,
    pass: Mutex<SaoPass>,
}

impl OceanSaoGpu {
    fn lock(&self) -> MutexGuard<'_, SaoPass> {
        // A panic inside a call (reported as OCEAN_STATUS_PANIC) poisons the lock; the pass
        // re-creates its textures whenever a run needs others, so it stays usable.
        self.pass.lock().unwrap_or_else(PoisonError::into_inner)
    }
}

const _: () = {
    const fn shareable<T: Send + Sync>() {}
    shareable::<OceanSaoGpu>();
};

/// Creates the GPU ambient obscurance passes on `ctx` and stores a new handle in `*out`.
///
/// Returns `OCEAN_STATUS_NULL_POINTER` / `_MISALIGNED_POINTER` for a bad pointer,
/// `OCEAN_STATUS_GPU_FAILURE` if the device cannot build the pipelines. On failure `*out` is
/// unchanged. Free the handle with `ocean_sao_gpu_destroy`.
///
/// # Safety
///
/// `ctx` must be a live context and `out` point to a writable pointer.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn ocean_sao_gpu_create(
    ctx: *const OceanGpuContext,
    out: *mut *mut OceanSaoGpu,
) -> OceanStatus {
    guard("ocean_sao_gpu_create", || {
        let c = borrow(ctx, "ctx")?;
        crate::boundary::check_ptr(out.cast_const(), "out")?;
        let pass = SaoPass::new(c.context())?;
        // SAFETY: forwarded from this function's contract.
        unsafe {
            write_handle(
                out,
                OceanSaoGpu {
                    context: c.id(),
                    pass: Mutex::new(pass),
                },
            )
        }
    })
}

/// Frees the handle. NULL does nothing; a handle of another kind or already destroyed frees nothing
/// and sets the last-error message (see the header's notes on handles).
#[unsafe(no_mangle)]
pub extern "C" fn ocean_sao_gpu_destroy(sao_gpu: *mut OceanSaoGpu) {
    destroy(sao_gpu, "ocean_sao_gpu_destroy", "sao_gpu");
}

/// Computes the obscurance of `depth` as `ocean_sao_run` does, on the GPU of `ctx`: the depth
/// buffer is uploaded, the five passes run (view-space z, Eq. 2; its MIP levels, Table 1; the
/// spiral samples, Eq. 6-10; the horizontal and vertical bilateral blurs, section 2.4) and the
/// obscurance is read back. `sao` gives the sizes, camera and parameters; `depth` and `ao` are
/// laid out and checked exactly as for `ocean_sao_run`. The result matches the CPU's within
/// 2/255 on at least 99.9% of the pixels (the library's parity tests).
///
/// Returns the statuses of `ocean_sao_run`, and `OCEAN_STATUS_INVALID_ARGUMENT` for a context
/// other than the one the handle was created on or an image larger than the device's largest
/// texture, `OCEAN_STATUS_GPU_FAILURE` for a device error. `ao` is written only on success, and
/// then wholly.
///
/// # Safety
///
/// `depth` point to `depth_len` readable
/// floats and `ao` to `ao_len` writable floats, neither touched by another thread during the
/// call.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn ocean_sao_gpu_run(
    sao_gpu: *const OceanSaoGpu,
    ctx: *const OceanGpuContext,
    sao: *const OceanSao,
    depth: *const f32,
    depth_len: usize,
    ao: *mut f32,
    ao_len: usize,
) -> OceanStatus {
    guard("ocean_sao_gpu_run", || {
        let g = borrow(sao_gpu, "sao_gpu")?;
        let c = borrow(ctx, "ctx")?;
        let s = borrow(sao, "sao")?;
        if g.context != c.id() {
            return Err(Error::new(
                OceanStatus::InvalidArgument,
                "`sao_gpu` was created on another context: pass the OceanGpuContext given to \
                 ocean_sao_gpu_create",
            ));
        }
        let v = s.sao().viewport();
        let want = v.output_len();
        let what = format!("the {} x {} AO image", v.output_width(), v.output_height());
        // SAFETY: forwarded from this function's contract.
        let b = unsafe { buffers(&s, depth, depth_len, (ao, ao_len, "ao", want, &what)) }?;
        let result = g.lock().evaluate(c.context(), s.sao(), b.depth)?;
        if result.len() != want {
            return Err(Error::new(
                OceanStatus::GpuFailure,
                format!("the GPU returned {} values for {want} pixels", result.len()),
            ));
        }
        // SAFETY: forwarded from this function's contract (checked in `buffers`).
        unsafe { b.write(&result) };
        Ok(())
    })
}

/// Size in bytes of the uniform block `Params` that every `sao_*` shader reads at binding 0
/// (std140); `ocean_sao_uniforms` writes it.
pub const OCEAN_SAO_UNIFORMS_SIZE: usize = 304;

const _: () = assert!(size_of::<SaoUniforms>() == OCEAN_SAO_UNIFORMS_SIZE);

/// Writes the uniform block of the exported `sao_*` shaders for `sao` into `out` (the
/// `OCEAN_SAO_UNIFORMS_SIZE` bytes of `Params`, std140, in the machine's byte order: upload
/// them as they are with `glBufferSubData`) and the number of z levels the passes build into
/// `*levels` (1 to 14).
///
/// For engines that run the passes in their own OpenGL 4.3 pipeline (`ocean_shader_export`
/// of `sao_z`, `sao_mip`, `sao_ao` and `sao_blur`, with their binding tables), every dispatch
/// in 8 x 8 workgroups over its output:
/// 1. `sao_z` `z_pass`: the depth texture (input size) to z level 0, an `r32f` texture of the
///    input size.
/// 2. `sao_mip` `downsample`, for each level l = 1 to levels - 1: level l - 1 to level l
///    (`r32f`, each side halved, rounded down, at least 1), one texture per level.
/// 3. `sao_ao` `ao`: the levels to the packed A and key (`r32ui`, output size).
/// 4. `sao_blur` `blur_horizontal`, then `blur_vertical`: packed to packed, the last one also
///    writing A (`r32f`, output size), with a memory barrier between the dispatches.
///
/// Returns `OCEAN_STATUS_NULL_POINTER` / `_MISALIGNED_POINTER` for a bad pointer,
/// `OCEAN_STATUS_LENGTH_MISMATCH` if `len` is not `OCEAN_SAO_UNIFORMS_SIZE`,
/// `OCEAN_STATUS_LENGTH_OVERFLOW` if `len` exceeds `PTRDIFF_MAX`. Nothing is written on
/// failure.
///
/// # Safety
///
/// `out` must point to `len` writable bytes and `levels` to a writable value, none touched by
/// another thread during the call.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn ocean_sao_uniforms(
    sao: *const OceanSao,
    out: *mut u8,
    len: usize,
    levels: *mut u32,
) -> OceanStatus {
    guard("ocean_sao_uniforms", || {
        let s = borrow(sao, "sao")?;
        crate::boundary::check_ptr(out.cast_const(), "out")?;
        crate::boundary::check_ptr(levels.cast_const(), "levels")?;
        check_block_out::<SaoUniforms>(out, len)?;
        let u = SaoUniforms::new(s.sao());
        // SAFETY: forwarded from this function's contract.
        unsafe { write_block(out, len, &u) }?;
        // SAFETY: non-NULL and aligned (checked), writable (caller's guarantee).
        unsafe { levels.write(u.levels()) };
        Ok(())
    })
}

crate::boundary::handle::handles!(OceanSaoGpu);

#[cfg(test)]
mod tests {
    use core::ptr::null_mut;

    use ocean_core::camera::{DepthConvention, Far, Projection};
    use ocean_sao::DepthSource;
    use ocean_sao::analytic::{AnalyticView, DepthFormat};

    use super::*;
    use crate::camera::OceanCamera;
    use crate::camera::OceanDepthConvention;
    use crate::gpu::{ocean_gpu_context_create, ocean_gpu_context_destroy};
    use crate::sao::{
        ocean_sao_create, ocean_sao_destroy, ocean_sao_params_default, ocean_sao_run,
    };
    use crate::sao_depth::OceanSaoDepth;

    const W: u32 = 96;
    const H: u32 = 64;
    const G: u32 = 8;

    use crate::status::last_error;

    fn context() -> Option<*mut OceanGpuContext> {
        let mut ctx = null_mut();
        // SAFETY: writable out.
        let s = unsafe { ocean_gpu_context_create(&mut ctx) };
        if s == OceanStatus::NoAdapter
            && std::env::var("OCEAN_REQUIRE_GPU").map_or(true, |v| v.trim() != "1")
        {
            eprintln!("SKIPPED: {}", last_error());
            return None;
        }
        assert_eq!(s, OceanStatus::Ok, "{}", last_error());
        Some(ctx)
    }

    /// The crease scene, reversed-Z [0, 1] with an infinite far plane, through the C ABI on
    /// the CPU and on the GPU: the parity bound (2/255 on 99.9% of the pixels), and a handle
    /// refused on a context it was not made on, with `ao` untouched.
    #[test]
    fn the_gpu_run_matches_the_cpu_run() {
        let Some(ctx) = context() else { return };
        let projection = Projection::Perspective {
            fov_y: 1.0,
            aspect: f64::from(W) / f64::from(H),
            near: 0.1,
            far: Far::Infinite,
        };
        let convention = DepthConvention::ZERO_TO_ONE_REVERSED;
        let view = AnalyticView::crease();
        let camera = view.camera(projection, convention).unwrap();
        let depth = view
            .scene
            .rasterise(
                &camera,
                W as usize,
                H as usize,
                DepthSource::Window,
                DepthFormat::F32,
            )
            .unwrap()
            .depth;
        let sao_camera = OceanCamera {
            view: glam::DMat4::IDENTITY.to_cols_array(),
            projection: camera
                .projection_matrix()
                .unwrap()
                .to_cols_array()
                .map(f64::from),
            depth_convention: OceanDepthConvention::ZeroToOneReversed,
            reserved: 0,
        };
        let mut params = core::mem::MaybeUninit::uninit();
        // SAFETY: writable out.
        let status = unsafe { ocean_sao_params_default(params.as_mut_ptr()) };
        assert_eq!(status, OceanStatus::Ok);
        // SAFETY: written by the call above.
        let params = unsafe { params.assume_init() };
        let mut sao = null_mut();
        // SAFETY: valid pointers.
        let status = unsafe {
            ocean_sao_create(
                W,
                H,
                G,
                &sao_camera,
                OceanSaoDepth::Window as u32,
                &params,
                &mut sao,
            )
        };
        assert_eq!(status, OceanStatus::Ok, "{}", last_error());
        let mut gpu = null_mut();
        // SAFETY: live context, writable out.
        let status = unsafe { ocean_sao_gpu_create(ctx, &mut gpu) };
        assert_eq!(status, OceanStatus::Ok, "{}", last_error());

        let n = ((W - 2 * G) * (H - 2 * G)) as usize;
        let (mut cpu_ao, mut gpu_ao) = (vec![-1.0f32; n], vec![-1.0f32; n]);
        // SAFETY: live handles, buffers of the given lengths.
        let status =
            unsafe { ocean_sao_run(sao, depth.as_ptr(), depth.len(), cpu_ao.as_mut_ptr(), n) };
        assert_eq!(status, OceanStatus::Ok, "{}", last_error());
        // SAFETY: live handles, buffers of the given lengths.
        let status = unsafe {
            ocean_sao_gpu_run(
                gpu,
                ctx,
                sao,
                depth.as_ptr(),
                depth.len(),
                gpu_ao.as_mut_ptr(),
                n,
            )
        };
        assert_eq!(status, OceanStatus::Ok, "{}", last_error());
        let far = cpu_ao
            .iter()
            .zip(&gpu_ao)
            .filter(|(c, g)| (*c - *g).abs() > 2.0 / 255.0)
            .count();
        assert!(
            far as f64 <= 0.001 * n as f64,
            "{far} of {n} pixels differ by more than 2/255"
        );
        // The scene has a crease: some pixels must be darkened, or the comparison is empty.
        assert!(cpu_ao.iter().any(|&a| a < 0.5));

        // The uniform block the GLSL export reads: the bytes SaoPass uploads.
        let mut block = vec![0xAAu8; OCEAN_SAO_UNIFORMS_SIZE + 4];
        let mut levels = 0u32;
        // SAFETY: live handle, writable buffers.
        let status = unsafe {
            ocean_sao_uniforms(
                sao,
                block.as_mut_ptr(),
                OCEAN_SAO_UNIFORMS_SIZE,
                &mut levels,
            )
        };
        assert_eq!(status, OceanStatus::Ok, "{}", last_error());
        let want = SaoUniforms::new(crate::boundary::borrow(sao, "sao").unwrap().sao());
        assert_eq!(&block[..OCEAN_SAO_UNIFORMS_SIZE], bytemuck::bytes_of(&want));
        assert_eq!(block[OCEAN_SAO_UNIFORMS_SIZE..], [0xAA; 4]);
        assert_eq!(levels, want.levels());
        assert!((1..=14).contains(&levels));
        // Any other length, one byte more or less: refused, nothing written.
        for len in [OCEAN_SAO_UNIFORMS_SIZE - 1, OCEAN_SAO_UNIFORMS_SIZE + 1] {
            let mut other = vec![7u8; OCEAN_SAO_UNIFORMS_SIZE + 1];
            let mut untouched = 99u32;
            // SAFETY: live handle, `other` holds at least `len` writable bytes.
            let status =
                unsafe { ocean_sao_uniforms(sao, other.as_mut_ptr(), len, &mut untouched) };
            assert_eq!(status, OceanStatus::LengthMismatch, "{len}");
            assert!(
                last_error().contains("holds exactly 304"),
                "{}",
                last_error()
            );
            assert!(other.iter().all(|&b| b == 7) && untouched == 99);
        }
        // SAFETY: live handle; NULL is refused before anything is read or written.
        let status = unsafe { ocean_sao_uniforms(sao, null_mut(), 0, &mut levels) };
        assert_eq!(status, OceanStatus::NullPointer);

        // Another context: refused, nothing written.
        let Some(other) = context() else { return };
        let mut untouched = vec![-1.0f32; n];
        // SAFETY: live handles, buffers of the given lengths.
        let status = unsafe {
            ocean_sao_gpu_run(
                gpu,
                other,
                sao,
                depth.as_ptr(),
                depth.len(),
                untouched.as_mut_ptr(),
                n,
            )
        };
        assert_eq!(status, OceanStatus::InvalidArgument);
        assert!(last_error().contains("another context"), "{}", last_error());
        assert!(untouched.iter().all(|&v| v == -1.0));
        ocean_sao_gpu_destroy(gpu);
        ocean_sao_destroy(sao);
        ocean_gpu_context_destroy(other);
        ocean_gpu_context_destroy(ctx);
    }
}
