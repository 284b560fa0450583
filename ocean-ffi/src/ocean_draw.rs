//! The ocean renderer, the shader side: the uniform block and the textures of the exported
//! `ocean` draw shader, for engines that draw the sea in their own OpenGL (or Vulkan, Metal,
//! D3D) pipeline with `ocean_shader_export`: a water mesh of their own (a wave train box
//! scene evaluated on the CPU with `ocean_wtb_scene_evaluate`) lit by Algorithm 5.1 (Bruneton,
//! Neyret & Holzschuch 2010), the projected grid, the sky, and the composition of the mesh's
//! light with an ambient obscurance.
//!
//! The block is the one `ocean_gpu::OceanRenderer` draws with (`ocean_gpu::frame_uniform`),
//! byte for byte, and the textures hold the texels it uploads (`ocean_gpu::WaveTexels`,
//! `ocean_gpu::fresnel_table_texels`, the sky map of `ocean_lighting_sky_map_create`).

use ocean_brdf::{Filter, FilteredSurface};
use ocean_gpu::{MeshGrid, OceanOptions, WaveTexels};

use crate::boundary::OceanNext;
use crate::boundary::{
    borrow, byte_len, check_block_out, check_finite, check_len, check_ptr, check_time, read_in,
    read_params, write_block, write_out,
};
use crate::camera::{OceanCamera, read_camera};
use crate::lighting::{OceanLighting, brdf_error};
use crate::lighting_spectrum::{OCEAN_FILTER_N_MAX, OCEAN_FILTER_N_MIN, OceanSpectrum};
use crate::status::{Error, OceanStatus, guard};
use crate::waves_domain::Reach;
use crate::wtb_params::{OceanWaterGridDesc, water_grid};

/// Size in bytes of the exported `ocean` shader's uniform block `Frame` (binding 0, std140);
/// `ocean_surface_uniforms` writes it.
pub const OCEAN_SURFACE_UNIFORMS_SIZE: usize = 352;

/// Rows of the wave texture (binding 1 of the `ocean` shader): `ocean_surface_wave_texels`.
pub const OCEAN_WAVE_TEXTURE_ROWS: usize = 3;

/// Side of the effective Fresnel table texture (binding 6 of the `ocean` shader), texels:
/// `ocean_surface_fresnel_texels`.
pub const OCEAN_FRESNEL_TABLE_SIZE: usize = 33;

const _: () = assert!(size_of::<ocean_gpu::FrameUniform>() == OCEAN_SURFACE_UNIFORMS_SIZE);
const _: () = assert!(ocean_brdf::fresnel_table::FRESNEL_TABLE_SIZE == OCEAN_FRESNEL_TABLE_SIZE);

/// How the exported `ocean` shader draws: the parts of the uniform block that do not come from
/// the camera, the spectrum or the lighting. `ocean_surface_draw_params_default` fills in the
/// library's defaults (those of `ocean_renderer_options_default`, the paper's filter).
#[repr(C)]
#[derive(Clone, Copy, Debug, Default, PartialEq, bytemuck::Zeroable, bytemuck::Pod)]
pub struct OceanSurfaceDrawParams {
    /// Extensions: NULL, or the first extension struct (see `OceanChain`); the `_default`
    /// function sets NULL.
    pub next: OceanNext,
    /// N_min of the filter (paper section 7.1): a wave enters a pixel's normal once its
    /// wavelength spans this many pixels (a grid vertex's position: grid cells). > 0.
    pub n_min: f64,
    /// N_max of the filter: fully present from this many. In (n_min, 1e6].
    pub n_max: f64,
    /// Projected grid (`ocean_vs`): cell size, pixels, in [1, 256]. Unused by the mesh.
    pub cell_px: f64,
    /// Projected grid: margin beyond the viewport, a fraction of its size, in [0, 2]. Unused by
    /// the mesh.
    pub margin: f64,
    /// Distance cap of the view rays' hits on the sea plane, metres, in (0, 1e7]: pixel
    /// footprints (hence the filtering) are measured on the sea plane, and rays above the
    /// horizon stop there.
    pub max_distance: f64,
    /// Exposure of the tone mapping 1 - exp(-exposure * L), in (0, 1e6].
    pub exposure: f64,
    /// Level-0 size of the sky map texture the engine uploads (`ocean_lighting_sky_map_create`
    /// with this size), a power of two in [`OCEAN_SKY_MAP_MIN_SIZE`, `OCEAN_SKY_MAP_MAX_SIZE`].
    pub sky_map_size: u32,
    /// 1: the shader sRGB-encodes its colour (for a linear `GL_RGBA8` target); 0: it writes
    /// linear colour (for an sRGB target with `GL_FRAMEBUFFER_SRGB`). Other values are refused.
    pub srgb_encode: u32,
}

/// Stores the default draw parameters in `*out`: the paper's filter (`OCEAN_FILTER_N_MIN`,
/// `OCEAN_FILTER_N_MAX`), 8-pixel grid cells, a 10 % margin, a 50 km distance cap, exposure
/// `OCEAN_DEFAULT_EXPOSURE`, a 512 x 512 sky map, sRGB encoding by the shader.
///
/// Returns `OCEAN_STATUS_NULL_POINTER` (or `_MISALIGNED_POINTER`) for a bad `out`, which is
/// then left unchanged.
///
/// # Safety
///
/// `out` must be writable.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn ocean_surface_draw_params_default(
    out: *mut OceanSurfaceDrawParams,
) -> OceanStatus {
    guard("ocean_surface_draw_params_default", || {
        let d = OceanOptions::default();
        let p = OceanSurfaceDrawParams {
            next: OceanNext::NULL,
            n_min: OCEAN_FILTER_N_MIN,
            n_max: OCEAN_FILTER_N_MAX,
            cell_px: d.cell_px,
            margin: d.margin,
            max_distance: d.max_distance,
            exposure: d.exposure,
            sky_map_size: d.sky_map_size,
            srgb_encode: 1,
        };
        // SAFETY: forwarded from this function's contract.
        unsafe { write_out(out, "out", p) }
    })
}

/// The renderer's options and filter of `p`, checked.
fn params_from(p: &OceanSurfaceDrawParams) -> Result<(OceanOptions, Filter), Error> {
    check_finite(
        "params->",
        &[
            ("n_min", p.n_min),
            ("n_max", p.n_max),
            ("cell_px", p.cell_px),
            ("margin", p.margin),
            ("max_distance", p.max_distance),
            ("exposure", p.exposure),
        ],
    )?;
    let color_format = match p.srgb_encode {
        1 => ocean_gpu::wgpu::TextureFormat::Rgba8Unorm,
        0 => ocean_gpu::wgpu::TextureFormat::Rgba8UnormSrgb,
        v => {
            return Err(Error::new(
                OceanStatus::InvalidArgument,
                format!("params->srgb_encode = {v} is neither 0 nor 1"),
            ));
        }
    };
    let filter = Filter::new(p.n_min, p.n_max).map_err(|e| brdf_error("params: ", e))?;
    let options = OceanOptions {
        color_format,
        cell_px: p.cell_px,
        margin: p.margin,
        max_distance: p.max_distance,
        exposure: p.exposure,
        sky_map_size: p.sky_map_size,
        ..OceanOptions::default()
    };
    Ok((options, filter))
}

/// Writes the uniform block of the exported `ocean` draw shader for one frame of `width` x
/// `height` pixels seen by `camera` at `time` seconds into `out` (the
/// `OCEAN_SURFACE_UNIFORMS_SIZE` bytes of `Frame`, std140, in the machine's byte order: upload
/// them as they are with `glBufferSubData`): the spectrum's waves filtered by `params->n_min`
/// and `n_max` (their texture: `ocean_surface_wave_texels` for the same camera and time), the
/// Sun, sky and sea of `lighting`, and, when `mesh` is not NULL, the water mesh that `mesh_vs`
/// draws (a wave train box scene's grid: pass the `OceanWaterGridDesc` it was created with).
/// `camera` is an `OceanCamera` above the sea (eye y > 0); its projection's aspect P11/P00
/// should be width / height. Positions in the block are relative to the camera's eye
/// (subtracted here in double precision, with the waves' phases reduced per frame), so a sea
/// far from the world origin does not jitter.
///
/// To draw a mesh with its ambient light obscured (`ocean_shader_export` of `ocean`, GLSL 3.30
/// core; assign bindings by the names in its binding table: `glUniformBlockBinding` for the
/// blocks `Frame_block_0Vertex` and `Frame_block_0Fragment`, `glUniform1i` texture units for
/// the samplers `_group_0_binding_<b>_vs` / `_fs`):
/// - binding 0: this block, a uniform buffer;
/// - binding 1: the wave texture, `GL_RGBA32F`, wave count x `OCEAN_WAVE_TEXTURE_ROWS`, one
///   level, the texels of `ocean_surface_wave_texels` (refreshed every frame);
/// - bindings 2 and 3: the sky map, `GL_RGBA16F` (or `GL_RGBA32F`), `params->sky_map_size`
///   square with every level of `ocean_sky_map_copy_level`, sampled with linear min, mag and
///   mip filtering and clamp-to-edge (the sampler of binding 3 is folded into binding 2's);
/// - binding 6: the effective Fresnel table, `GL_R32F`, `OCEAN_FRESNEL_TABLE_SIZE` square, the
///   texels of `ocean_surface_fresnel_texels`;
/// - bindings 7 and 8: local waves, never read when none are set (as here): any complete
///   `GL_RG32F` 2D array texture and `GL_RGBA32F` 2D texture;
/// - pass 1, `mesh_vs` + `mesh_fs`: attribute 0 the positions and attribute 1 the normals that
///   `ocean_wtb_scene_evaluate` writes (3 floats each, point (i, j) at vertex j * nx + i), drawn as
///   indexed `GL_TRIANGLES` over the grid's cells, depth test `GL_LESS` (`GL_GREATER`
///   reversed) with writes, no culling, into two colour targets of linear radiance: location 0
///   the Sun's reflection, location 1 the sky's reflection plus the refracted light, both
///   `GL_RGBA32F` cleared to 0 (alpha 1 marks the pixels the mesh covers);
/// - an ambient obscurance over pass 1's depth (the exported `sao_*` shaders,
///   `ocean_sao_uniforms`; the depth buffer holds window depth, `OCEAN_SAO_DEPTH_WINDOW`), with
///   no guard band, so that its output covers the viewport pixel for pixel;
/// - pass 2, `sky_vs` + `compose_fs`: 3 vertices, no vertex buffer, no depth test, with
///   bindings 9 and 10 the two targets of pass 1 and binding 11 the obscurance (`GL_R32F`, 1
///   unoccluded): each pixel becomes the tone-mapped Sun term plus the obscured ambient terms
///   where the mesh drew, the sky elsewhere.
///
/// The projected grid (`ocean_vs` + `ocean_fs`, the `OceanRenderer`'s sea) and the sky alone
/// (`sky_vs` + `sky_fs`) draw from the same block. The exported GLSL's clip space is OpenGL's
/// with y flipped (naga's convention, as wgpu's GL backend): image row 0 is the top row, so an
/// image read back with `glReadPixels` is upright, and a frame shown in a window is blitted
/// with its rows reversed.
///
/// Returns `OCEAN_STATUS_NULL_POINTER` / `_MISALIGNED_POINTER` for a bad pointer (`mesh` may be
/// NULL), `OCEAN_STATUS_EMPTY` if `width` or `height` is 0 or the mesh has a side of 0,
/// `OCEAN_STATUS_NON_FINITE` for a NaN or infinite `time`, parameter, camera or mesh member,
/// `OCEAN_STATUS_INVALID_ARGUMENT` for a parameter, camera or mesh outside its documented
/// ranges (the message names it) or a camera not above the sea,
/// `OCEAN_STATUS_LENGTH_MISMATCH` if `len` is not `OCEAN_SURFACE_UNIFORMS_SIZE`,
/// `OCEAN_STATUS_LENGTH_OVERFLOW` if `len` exceeds `PTRDIFF_MAX`. A `time` whose phase leaves
/// the domain of `ocean_waves_evaluate` (|omega t| of the fastest wave above 1e15 rad) is
/// `OCEAN_STATUS_INVALID_ARGUMENT`.
///
/// # Safety
///
/// `camera`, `params` and `mesh` (unless NULL) must be readable, and `out` point to `len`
/// writable bytes that no other thread touches during the call.
#[unsafe(no_mangle)]
#[allow(clippy::too_many_arguments)]
pub unsafe extern "C" fn ocean_surface_uniforms(
    camera: *const OceanCamera,
    spectrum: *const OceanSpectrum,
    lighting: *const OceanLighting,
    params: *const OceanSurfaceDrawParams,
    mesh: *const OceanWaterGridDesc,
    time: f64,
    width: u32,
    height: u32,
    out: *mut u8,
    len: usize,
) -> OceanStatus {
    guard("ocean_surface_uniforms", || {
        let s = borrow(spectrum, "spectrum")?;
        let l = borrow(lighting, "lighting")?;
        check_ptr(camera, "camera")?;
        check_ptr(params, "params")?;
        if !mesh.is_null() {
            check_ptr(mesh, "mesh")?;
        }
        check_block_out::<ocean_gpu::FrameUniform>(out, len)?;
        // SAFETY: forwarded from this function's contract.
        let camera = unsafe { read_camera(camera) }?;
        // SAFETY: forwarded from this function's contract.
        let (options, filter) = params_from(&unsafe { read_params(params, "params") }?)?;
        let mesh = if mesh.is_null() {
            None
        } else {
            // SAFETY: forwarded from this function's contract.
            let g = water_grid(&unsafe { read_in(mesh, "mesh") }?, "mesh")?;
            Some(MeshGrid {
                origin: g.origin(),
                spacing: g.spacing(),
                // A water grid's sides are at most 4096.
                nx: g.nx() as u32,
                nz: g.nz() as u32,
            })
        };
        check_time(time)?;
        Reach::of_spectrum(&s.spectrum)?.check_time(time)?;
        if width == 0 || height == 0 {
            return Err(Error::new(
                OceanStatus::Empty,
                format!("the viewport is {width} x {height} pixels: both sizes must be >= 1"),
            ));
        }
        let surface = FilteredSurface::new(&s.spectrum, filter)?;
        let u = ocean_gpu::frame_uniform(
            &options,
            &WaveTexels::new(&surface),
            Some(&l.lighting),
            &camera,
            time,
            (width, height),
            mesh.as_ref(),
        )?;
        // SAFETY: forwarded from this function's contract.
        unsafe { write_block(out, len, &u) }?;
        Ok(())
    })
}

/// Writes the wave texture of the exported `ocean` shader (binding 1) for one frame seen by
/// `camera` at `time` seconds into `out`: `OCEAN_WAVE_TEXTURE_ROWS` rows of wave count
/// (`ocean_spectrum_wave_count`) RGBA float texels, row 0 first, one column per wave, longest
/// first; `len` counts floats and must be exactly 12 * wave count. Upload it as a `GL_RGBA32F`
/// texture of wave count x 3 texels every frame, with the block of `ocean_surface_uniforms` for
/// the same camera and time.
///
/// Row 0 holds (wavelength, k_x, k_z, phase at the eye's horizontal position o, k.o - omega t +
/// phi reduced modulo 2 pi in double precision); row 1 (A, A k_x/|k|, A k_z/|k|, 0); row 2
/// (k A, the squared cosine of the wave's angle to the wind, and the slope variances along and
/// across the wind of this wave and every shorter one, Eq. 4 with w_r = 1, summed in double
/// precision). Only row 0 changes between frames. The texels do not depend on the filter.
///
/// Returns `OCEAN_STATUS_NULL_POINTER` / `_MISALIGNED_POINTER` for a bad pointer (4-byte
/// alignment for `out`), `OCEAN_STATUS_NON_FINITE` for a NaN or infinite `time` or camera
/// member, `OCEAN_STATUS_INVALID_ARGUMENT` for a camera outside its documented ranges,
/// `OCEAN_STATUS_LENGTH_MISMATCH` for a `len` other than 12 * wave count,
/// `OCEAN_STATUS_LENGTH_OVERFLOW` if `len * sizeof(float)`
/// exceeds `PTRDIFF_MAX`. A `time` whose phase
/// leaves the domain of `ocean_waves_evaluate` (|omega t| of the fastest wave above 1e15 rad)
/// is `OCEAN_STATUS_INVALID_ARGUMENT`. Nothing is written on failure.
///
/// # Safety
///
/// `camera` must be readable, `spectrum` a live handle, and `out` point to `len` writable
/// floats that no other thread touches during the call.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn ocean_surface_wave_texels(
    camera: *const OceanCamera,
    spectrum: *const OceanSpectrum,
    time: f64,
    out: *mut f32,
    len: usize,
) -> OceanStatus {
    guard("ocean_surface_wave_texels", || {
        let s = borrow(spectrum, "spectrum")?;
        check_ptr(camera, "camera")?;
        check_ptr(out.cast_const(), "out")?;
        byte_len::<f32>(len, "out")?;
        // SAFETY: forwarded from this function's contract.
        let camera = unsafe { read_camera(camera) }?;
        check_time(time)?;
        Reach::of_spectrum(&s.spectrum)?.check_time(time)?;
        // The filter only orders the waves (longest first), the same for every filter.
        let surface = FilteredSurface::new(&s.spectrum, Filter::PAPER)?;
        let waves = WaveTexels::new(&surface);
        let want = 4 * OCEAN_WAVE_TEXTURE_ROWS * waves.wave_count();
        check_len(
            "len",
            len,
            want,
            &format!("the texture of {} waves (floats)", waves.wave_count()),
        )?;
        let texels = waves.frame_texels(&camera, time);
        // SAFETY: non-NULL and 4-aligned (checked), `len` floats whose byte size fits in isize
        // (checked), writable and untouched by others (caller's guarantee).
        let dst = unsafe { core::slice::from_raw_parts_mut(out, len) };
        dst.copy_from_slice(bytemuck::cast_slice(&texels));
        Ok(())
    })
}

/// Writes the effective Fresnel table texture of the exported `ocean` shader (binding 6) into
/// `out`: `OCEAN_FRESNEL_TABLE_SIZE` rows of as many floats, `len` exactly 33 * 33. Element
/// 33 i + j (texel (j, i): column j, row i) holds the roughness correction
/// D = M - (1 - cos theta_v)^5 of Eq. 24 at cos theta_v = (i/32)^2 and sigma_v = (j/32)^2, the
/// table behind `ocean_effective_fresnel_table`, rounded to float. Upload it as a `GL_R32F`
/// texture of 33 x 33 texels once.
///
/// Returns `OCEAN_STATUS_NULL_POINTER` / `_MISALIGNED_POINTER` for a bad `out`,
/// `OCEAN_STATUS_LENGTH_MISMATCH` for a `len` other than 33 * 33. Nothing is written on
/// failure.
///
/// # Safety
///
/// `out` must point to `len` writable floats that no other thread touches during the call.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn ocean_surface_fresnel_texels(out: *mut f32, len: usize) -> OceanStatus {
    guard("ocean_surface_fresnel_texels", || {
        check_ptr(out.cast_const(), "out")?;
        byte_len::<f32>(len, "out")?;
        let texels = ocean_gpu::fresnel_table_texels();
        check_len("len", len, texels.len(), "the table (floats)")?;
        // SAFETY: non-NULL and 4-aligned (checked), `len` (= 1089) floats, writable and
        // untouched by others (caller's guarantee).
        unsafe { core::slice::from_raw_parts_mut(out, len) }.copy_from_slice(&texels);
        Ok(())
    })
}

crate::boundary::chain::extensible!(OceanSurfaceDrawParams);

#[cfg(test)]
#[path = "ocean_draw_tests.rs"]
mod tests;
