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
mod tests {
    use core::ptr::{null, null_mut};

    use glam::{DVec2, DVec3};
    use ocean_brdf::{Lighting, SeaParams, SkyParams, Spectrum, SpectrumParams};
    use ocean_core::Camera;

    use super::*;
    use ocean_core::camera::DepthConvention;

    use crate::status::last_error;

    /// An OpenGL camera 6 m above the sea, 100 km and 40 km from the origin, looking ahead
    /// and down.
    fn camera() -> (OceanCamera, Camera) {
        let eye = DVec3::new(1.0e5 + 2.0, 6.0, -4.0e4);
        let view =
            ocean_core::camera::look_at(eye, eye + DVec3::new(0.0, -1.0, -8.0), DVec3::Y).unwrap();
        let projection = ocean_core::Projection::Perspective {
            fov_y: 0.9,
            aspect: 1.5,
            near: 0.1,
            far: ocean_core::Far::Finite(2000.0),
        };
        let made = Camera::new(view, projection, DepthConvention::NEG_ONE_TO_ONE).unwrap();
        let desc = OceanCamera::from_camera(&made);
        // What the library reads back from the C layout (its matrices are made from the
        // parameters again).
        let camera = crate::camera::camera_from(&desc).unwrap();
        (desc, camera)
    }

    /// A camera whose projection mirrors x: refused.
    fn mirrored(mut c: OceanCamera) -> OceanCamera {
        c.projection[0] = -c.projection[0];
        c
    }

    /// A registered spectrum and lighting of the default parameters (never destroyed: the
    /// tests end with the process).
    fn handles() -> (*const OceanSpectrum, *const OceanLighting) {
        let spectrum = OceanSpectrum {
            spectrum: Spectrum::new(SpectrumParams::default()).unwrap(),
        };
        let lighting = OceanLighting {
            lighting: Lighting::new(SkyParams::default(), SeaParams::default()).unwrap(),
        };
        let (mut s, mut l) = (core::ptr::null_mut(), core::ptr::null_mut());
        // SAFETY: writable locals.
        unsafe {
            crate::boundary::write_handle(&mut s, spectrum).unwrap();
            crate::boundary::write_handle(&mut l, lighting).unwrap();
        }
        (s, l)
    }

    fn wave_count(spectrum: *const OceanSpectrum) -> usize {
        crate::boundary::borrow(spectrum, "spectrum")
            .unwrap()
            .spectrum
            .waves()
            .len()
    }

    fn default_params() -> OceanSurfaceDrawParams {
        let mut p = OceanSurfaceDrawParams::default();
        // SAFETY: writable out.
        let status = unsafe { ocean_surface_draw_params_default(&mut p) };
        assert_eq!(status, OceanStatus::Ok);
        p
    }

    fn mesh() -> OceanWaterGridDesc {
        OceanWaterGridDesc {
            origin_x: 1.0e5 - 30.0,
            origin_z: -4.0e4 - 60.0,
            spacing: 0.5,
            nx: 121,
            nz: 101,
        }
    }

    #[test]
    fn the_default_params_are_the_renderers() {
        let p = default_params();
        let (options, filter) = params_from(&p).unwrap();
        // The renderer's defaults with an rgba8unorm target (the shader sRGB-encodes), and the
        // paper's filter.
        assert_eq!(options, OceanOptions::default());
        assert_eq!(filter, Filter::PAPER);
        assert_eq!((p.srgb_encode, p.sky_map_size), (1, 512));
        // SAFETY: NULL is refused before any write.
        let status = unsafe { ocean_surface_draw_params_default(null_mut()) };
        assert_eq!(status, OceanStatus::NullPointer);
    }

    /// The bytes are `ocean_gpu::frame_uniform`'s block, the one `OceanRenderer` draws with
    /// (whose parity with the CPU twins the GPU tests check), plus the mesh.
    #[test]
    fn the_block_is_the_renderers() {
        let (desc, camera) = camera();
        let (spectrum, lighting) = handles();
        let p = default_params();
        let m = mesh();
        let mut out = [0xAAu8; OCEAN_SURFACE_UNIFORMS_SIZE + 4];
        // SAFETY: readable inputs, live handles, `out` holds `len` writable bytes.
        let status = unsafe {
            ocean_surface_uniforms(
                &desc,
                spectrum,
                lighting,
                &p,
                &m,
                12.5,
                96,
                64,
                out.as_mut_ptr(),
                OCEAN_SURFACE_UNIFORMS_SIZE,
            )
        };
        assert_eq!(status, OceanStatus::Ok, "{}", last_error());
        let surface = FilteredSurface::new(
            &crate::boundary::borrow(spectrum, "spectrum")
                .unwrap()
                .spectrum,
            Filter::PAPER,
        )
        .unwrap();
        let mesh_grid = MeshGrid {
            origin: DVec2::new(m.origin_x, m.origin_z),
            spacing: 0.5,
            nx: 121,
            nz: 101,
        };
        let want = ocean_gpu::frame_uniform(
            &OceanOptions::default(),
            &WaveTexels::new(&surface),
            Some(
                &crate::boundary::borrow(lighting, "lighting")
                    .unwrap()
                    .lighting,
            ),
            &camera,
            12.5,
            (96, 64),
            Some(&mesh_grid),
        )
        .unwrap();
        assert_eq!(
            &out[..OCEAN_SURFACE_UNIFORMS_SIZE],
            bytemuck::bytes_of(&want)
        );
        assert_eq!(out[OCEAN_SURFACE_UNIFORMS_SIZE..], [0xAA; 4]);
        let u: ocean_gpu::FrameUniform =
            bytemuck::pod_read_unaligned(&out[..OCEAN_SURFACE_UNIFORMS_SIZE]);
        // The mesh's origin relative to the eye, (1e5 − 30, −4e4 − 60) − (1e5 + 2, −4e4) and
        // −6 m down, exact in f32; its spacing and sides.
        assert_eq!(u.mesh_grid, [-32.0, -6.0, -60.0, 0.5]);
        assert_eq!(u.mesh_counts, [121, 101, 0, 0]);
        // The spectrum's 60 waves, sRGB encoding; the Sun from the lighting (not zero).
        assert_eq!(u.counts[2..], [60, 1]);
        assert!(u.sun_radiance[..3].iter().all(|&c| c > 0.0));
        // Without a mesh the mesh fields are zero and nothing else changes.
        let mut no_mesh = [0u8; OCEAN_SURFACE_UNIFORMS_SIZE];
        // SAFETY: as above, `mesh` NULL.
        let status = unsafe {
            ocean_surface_uniforms(
                &desc,
                spectrum,
                lighting,
                &p,
                null(),
                12.5,
                96,
                64,
                no_mesh.as_mut_ptr(),
                no_mesh.len(),
            )
        };
        assert_eq!(status, OceanStatus::Ok, "{}", last_error());
        let v: ocean_gpu::FrameUniform = bytemuck::pod_read_unaligned(&no_mesh);
        assert_eq!(
            v,
            ocean_gpu::FrameUniform {
                mesh_grid: [0.0; 4],
                mesh_counts: [0; 4],
                ..u
            }
        );
    }

    #[test]
    fn wave_and_fresnel_texels_are_the_renderers() {
        let (desc, camera) = camera();
        let (spectrum, _) = handles();
        let n = wave_count(spectrum);
        let mut out = vec![f32::NAN; 12 * n];
        // SAFETY: readable inputs, `out` holds `len` writable floats.
        let status = unsafe {
            ocean_surface_wave_texels(&desc, spectrum, 3.0e5, out.as_mut_ptr(), out.len())
        };
        assert_eq!(status, OceanStatus::Ok, "{}", last_error());
        let surface = FilteredSurface::new(
            &crate::boundary::borrow(spectrum, "spectrum")
                .unwrap()
                .spectrum,
            Filter::PAPER,
        )
        .unwrap();
        let want = WaveTexels::new(&surface).frame_texels(&camera, 3.0e5);
        assert_eq!(out, bytemuck::cast_slice::<[f32; 4], f32>(&want));
        // Row 0's phases: each θ₀ in [−π, π], k·o − ωt + Φ modulo 2π.
        let o = DVec2::new(camera.eye().x, camera.eye().z);
        for (i, w) in surface.wave_set().waves().iter().enumerate() {
            let theta = f64::from(out[4 * i + 3]);
            let d = (w.phase_at(o, 3.0e5) - theta) / core::f64::consts::TAU;
            assert!((d - d.round()).abs() < 1e-6, "wave {i}: {d}");
        }

        let mut table = vec![f32::NAN; 33 * 33];
        // SAFETY: `table` holds `len` writable floats.
        let status = unsafe { ocean_surface_fresnel_texels(table.as_mut_ptr(), table.len()) };
        assert_eq!(status, OceanStatus::Ok, "{}", last_error());
        // On the σ_v = 0 column the sea is smooth and Schlick's F exact: D vanishes there, to
        // the rounding of the table's quadrature (below 2e-15). Every texel is the f64 table
        // rounded to f32.
        assert!((0..33).all(|i| table[33 * i].abs() < 2e-15));
        let exact = ocean_brdf::fresnel_table::FRESNEL_TABLE;
        assert!(table.iter().zip(exact.iter()).all(|(&t, &e)| t == e as f32));
    }

    #[test]
    fn bad_input_is_refused_and_nothing_is_written() {
        let (desc, _) = camera();
        let (spectrum, lighting) = handles();
        let good = default_params();
        let m = mesh();
        let call = |desc: &OceanCamera,
                    p: &OceanSurfaceDrawParams,
                    m: *const OceanWaterGridDesc,
                    time: f64,
                    size: (u32, u32),
                    len: usize| {
            let mut out = [7u8; 400];
            // SAFETY: readable inputs, live handles, `out` holds at least `len` bytes.
            let status = unsafe {
                ocean_surface_uniforms(
                    desc,
                    spectrum,
                    lighting,
                    p,
                    m,
                    time,
                    size.0,
                    size.1,
                    out.as_mut_ptr(),
                    len,
                )
            };
            assert!(out.iter().all(|&b| b == 7), "written on failure");
            (status, last_error())
        };
        let with = |f: &dyn Fn(&mut OceanSurfaceDrawParams)| {
            let mut p = good;
            f(&mut p);
            call(&desc, &p, &m, 0.0, (8, 8), 352)
        };
        let with_mesh = |f: &dyn Fn(&mut OceanWaterGridDesc)| {
            let mut g = m;
            f(&mut g);
            call(&desc, &good, &g, 0.0, (8, 8), 352)
        };
        let below = {
            let eye = DVec3::new(0.0, -1.0, 0.0);
            let view =
                ocean_core::camera::look_at(eye, DVec3::new(0.0, -1.0, -5.0), DVec3::Y).unwrap();
            OceanCamera {
                view: view.to_cols_array(),
                ..desc
            }
        };
        let cases: [(OceanStatus, &str, (OceanStatus, String)); 14] = [
            (
                OceanStatus::LengthMismatch,
                "holds exactly 352",
                call(&desc, &good, &m, 0.0, (8, 8), 351),
            ),
            (
                OceanStatus::LengthMismatch,
                "holds exactly 352",
                call(&desc, &good, &m, 0.0, (8, 8), 353),
            ),
            (
                OceanStatus::Empty,
                "0 x 8",
                call(&desc, &good, &m, 0.0, (0, 8), 352),
            ),
            (
                OceanStatus::NonFinite,
                "time",
                call(&desc, &good, &m, f64::NAN, (8, 8), 352),
            ),
            (
                OceanStatus::InvalidArgument,
                "above the sea",
                call(&below, &good, &m, 0.0, (8, 8), 352),
            ),
            (
                OceanStatus::InvalidArgument,
                "camera",
                call(&mirrored(desc), &good, &m, 0.0, (8, 8), 352),
            ),
            (
                OceanStatus::InvalidArgument,
                "srgb_encode",
                with(&|p| p.srgb_encode = 2),
            ),
            (
                OceanStatus::NonFinite,
                "params->exposure",
                with(&|p| p.exposure = f64::INFINITY),
            ),
            (
                OceanStatus::InvalidArgument,
                "params",
                with(&|p| p.n_max = 0.5),
            ),
            (
                OceanStatus::InvalidArgument,
                "sky_map_size",
                with(&|p| p.sky_map_size = 100),
            ),
            (
                OceanStatus::InvalidArgument,
                "cell_px",
                with(&|p| p.cell_px = 0.5),
            ),
            (
                OceanStatus::Empty,
                "mesh is 0 x 101",
                with_mesh(&|g| g.nx = 0),
            ),
            (
                OceanStatus::NonFinite,
                "mesh->spacing",
                with_mesh(&|g| g.spacing = f64::NAN),
            ),
            (
                OceanStatus::InvalidArgument,
                "mesh",
                with_mesh(&|g| g.spacing = 0.0),
            ),
        ];
        for (status, text, (got, message)) in cases {
            assert_eq!(got, status, "{text}: {message}");
            assert!(message.contains(text), "{text}: {message}");
        }
        let mut out = [0u8; 352];
        // SAFETY: NULL pointers are refused before anything is read or written.
        unsafe {
            let o = out.as_mut_ptr();
            assert_eq!(
                ocean_surface_uniforms(null(), spectrum, lighting, &good, &m, 0.0, 8, 8, o, 352,),
                OceanStatus::NullPointer
            );
            assert_eq!(
                ocean_surface_uniforms(&desc, null(), lighting, &good, &m, 0.0, 8, 8, o, 352,),
                OceanStatus::NullPointer
            );
            assert_eq!(
                ocean_surface_uniforms(&desc, spectrum, null(), &good, &m, 0.0, 8, 8, o, 352,),
                OceanStatus::NullPointer
            );
            assert_eq!(
                ocean_surface_uniforms(&desc, spectrum, lighting, null(), &m, 0.0, 8, 8, o, 352,),
                OceanStatus::NullPointer
            );
            assert_eq!(
                ocean_surface_uniforms(
                    &desc,
                    spectrum,
                    lighting,
                    &good,
                    &m,
                    0.0,
                    8,
                    8,
                    null_mut(),
                    352,
                ),
                OceanStatus::NullPointer
            );
        }

        // The texel functions: wrong lengths, NaN time, NULL.
        let n = wave_count(spectrum);
        let mut texels = vec![7.0f32; 12 * n + 1];
        // SAFETY: `texels` holds at least `len` writable floats; NULL is refused.
        unsafe {
            let t = texels.as_mut_ptr();
            assert_eq!(
                ocean_surface_wave_texels(&desc, spectrum, 0.0, t, 12 * n + 1),
                OceanStatus::LengthMismatch
            );
            assert!(last_error().contains(&format!("exactly {}", 12 * n)));
            assert_eq!(
                ocean_surface_wave_texels(&desc, spectrum, f64::INFINITY, t, 12 * n),
                OceanStatus::NonFinite
            );
            assert_eq!(
                ocean_surface_wave_texels(&desc, null(), 0.0, t, 12 * n),
                OceanStatus::NullPointer
            );
            assert_eq!(
                ocean_surface_wave_texels(&desc, spectrum, 0.0, null_mut(), 12 * n),
                OceanStatus::NullPointer
            );
            assert_eq!(
                ocean_surface_fresnel_texels(t, 33 * 32),
                OceanStatus::LengthMismatch
            );
            assert!(last_error().contains("exactly 1089"));
            assert_eq!(
                ocean_surface_fresnel_texels(null_mut(), 1089),
                OceanStatus::NullPointer
            );
        }
        assert!(texels.iter().all(|&t| t == 7.0), "written on failure");
    }

    #[test]
    fn a_time_past_the_phase_limit_is_refused() {
        // time = DBL_MAX gave a NaN phase texel (omega t overflowed) behind success.
        let (desc, _) = camera();
        let (spectrum, _) = handles();
        let n = wave_count(spectrum);
        let mut out = vec![-1.0f32; 12 * n];
        for time in [f64::MAX, 1e300, -1e20] {
            // SAFETY: readable inputs, `out` holds `len` writable floats.
            let s = unsafe {
                ocean_surface_wave_texels(&desc, spectrum, time, out.as_mut_ptr(), out.len())
            };
            assert_eq!(s, OceanStatus::InvalidArgument, "{time}");
            assert!(last_error().contains("`time`"), "{}", last_error());
            assert!(out.iter().all(|&v| v == -1.0), "written on failure");
        }
        // SAFETY: as above.
        let s =
            unsafe { ocean_surface_wave_texels(&desc, spectrum, 1e9, out.as_mut_ptr(), out.len()) };
        assert_eq!(s, OceanStatus::Ok, "{}", last_error());
        assert!(out.iter().all(|v| v.is_finite()));
    }
}
