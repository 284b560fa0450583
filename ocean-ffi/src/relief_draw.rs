//! Relief mapping, the shader side: the uniform block of the exported `relief` draw shader, for
//! engines that draw relief-mapped quads in their own OpenGL (or Vulkan, Metal, D3D) pipeline
//! with `ocean_shader_export`.
//!
//! The block is the one `ocean_gpu::ReliefRenderer` draws with (`ocean_gpu::scene_uniforms`),
//! byte for byte, so a quad drawn by an engine with the exported GLSL traces the same rays with
//! the same arithmetic as the library's own renderer and its CPU twin (`ocean_relief_trace`).

use glam::DVec2;
use ocean_gpu::ReliefScene;
use ocean_relief::Method;
use ocean_relief::gpu_params::ReliefUniforms;

use core::mem::offset_of;

use crate::boundary::OceanNext;
use crate::boundary::{
    CheckedStruct, EnumField, check_block_out, check_chain, check_finite, check_flag, check_ptr,
    read_params_checked, write_block, write_out,
};
use crate::camera::{OceanCamera, read_camera};
use crate::lighting::{OceanIrradiance, finite_dvec3};
use crate::relief::edge_from;
use crate::relief_trace::{OceanReliefMethod, OceanReliefSearch, OceanReliefTracer, method_from};
use crate::status::{Error, OceanStatus, guard};
use crate::waves::OceanDVec3;

/// Size in bytes of the exported `relief` shader's uniform block `Relief` (binding 0, std140);
/// `ocean_relief_uniforms` writes it.
pub const OCEAN_RELIEF_UNIFORMS_SIZE: usize = 448;

const _: () = assert!(size_of::<ReliefUniforms>() == OCEAN_RELIEF_UNIFORMS_SIZE);

/// A relief-mapped polygon, how it is traced and how it is lit.
///
/// The quad is the rectangle with a corner at `origin` (texture coordinates (0, 0)) and edges
/// `edge_u` (along the texture's u) and `edge_v` (along v, the rows), spanning `tiles_u` and
/// `tiles_v` texture widths. Tangent space is the tracers': x along u, y along v, z =
/// edge_u x edge_v out of the polygon, towards its front; the relief lies `depth` world units
/// under it. The edges must be orthogonal and a texture width must have one world length along
/// both (relative tolerance 1e-6), so the relief is not sheared.
///
/// What is drawn is the convex polygon `corners` in the quad's plane: the whole quad, or a
/// triangle or quadrilateral of a mesh (its texture then continues beyond the quad's edges).
#[repr(C)]
#[derive(
    Clone, Copy, Debug, Default, PartialEq, bytemuck::NoUninit, bytemuck::CheckedBitPattern,
)]
pub struct OceanReliefScene {
    /// Extensions: NULL, or the first extension struct (see `OceanChain`); the `_default`
    /// function sets NULL.
    pub next: OceanNext,
    /// World position of the corner at texture coordinates (0, 0), metres.
    pub origin: OceanDVec3,
    /// World vector from `origin` along u to the next corner.
    pub edge_u: OceanDVec3,
    /// World vector from `origin` along v to the next corner.
    pub edge_v: OceanDVec3,
    /// Texture widths across `edge_u` (> 0).
    pub tiles_u: f64,
    /// Texture widths across `edge_v` (> 0).
    pub tiles_v: f64,
    /// Depth of the relief below the polygon, world units (>= 0).
    pub depth: f64,
    /// The tracer of the viewing ray and of the light ray.
    pub method: OceanReliefMethod,
    /// 1: trace the light ray for self-shadowing; 0: do not. Other values are refused.
    pub shadows: u32,
    /// How far (depth units) above a point the light ray must stop to shadow it, in [0, 1].
    pub shadow_bias: f32,
    /// World direction towards the (directional) light; any length but zero.
    pub light_dir: OceanDVec3,
    /// Light intensity (>= 0).
    pub light_intensity: f32,
    /// The light's linear colour, red, green, blue, multiplying `light_intensity` (each >= 0;
    /// the default: white, 1, 1, 1).
    pub light_color: [f32; 3],
    /// Linear albedo, red, green, blue (each >= 0).
    pub albedo: [f32; 3],
    /// Light that reaches every point whatever the light and shadows (>= 0).
    pub ambient: f32,
    /// The environment's irradiance E (`ocean_lighting_irradiance`), or all zero for none: the
    /// ambient term gains albedo E(n) / pi, a Lambertian surface's radiance under it, n the
    /// relief's normal at the hit in world space. `light_intensity` and `ambient` must then be
    /// in the same radiance units.
    pub sky: OceanIrradiance,
    /// The polygon drawn: corners `{s, t}`, the points `origin + s edge_u + t edge_v`,
    /// counter-clockwise seen from the front, convex, enclosing an area, each coordinate within
    /// 1e6; a triangle repeats its last corner. The default, `{0, 0}, {1, 0}, {1, 1}, {0, 1}`,
    /// is the whole quad; all zero (a zeroed struct) is refused.
    pub corners: [[f64; 2]; 4],
}

fn method_to(m: &Method) -> OceanReliefMethod {
    let [method, search, steps, binary] = ocean_relief::gpu_params::method_codes(m);
    // ocean-relief's codes are the header's enumerators (a mismatch panics, inside the guard).
    OceanReliefMethod {
        next: OceanNext::NULL,
        method: bytemuck::checked::cast(method),
        steps,
        binary,
        search: bytemuck::checked::cast(search),
    }
}

impl CheckedStruct for OceanReliefScene {
    const ENUM_FIELDS: &'static [EnumField] = &[
        EnumField::of::<OceanReliefTracer>(
            "method.method",
            offset_of!(OceanReliefScene, method) + offset_of!(OceanReliefMethod, method),
        ),
        EnumField::of::<OceanReliefSearch>(
            "method.search",
            offset_of!(OceanReliefScene, method) + offset_of!(OceanReliefMethod, search),
        ),
    ];
}

fn scene_from(s: &OceanReliefScene) -> Result<ReliefScene, Error> {
    let shadows = check_flag("scene->shadows", s.shadows)?;
    check_finite(
        "scene->",
        &[
            ("tiles_u", s.tiles_u),
            ("tiles_v", s.tiles_v),
            ("depth", s.depth),
            ("shadow_bias", f64::from(s.shadow_bias)),
            ("light_intensity", f64::from(s.light_intensity)),
            ("light_color[0]", f64::from(s.light_color[0])),
            ("light_color[1]", f64::from(s.light_color[1])),
            ("light_color[2]", f64::from(s.light_color[2])),
            ("albedo[0]", f64::from(s.albedo[0])),
            ("albedo[1]", f64::from(s.albedo[1])),
            ("albedo[2]", f64::from(s.albedo[2])),
            ("ambient", f64::from(s.ambient)),
            ("corners[0][0]", s.corners[0][0]),
            ("corners[0][1]", s.corners[0][1]),
            ("corners[1][0]", s.corners[1][0]),
            ("corners[1][1]", s.corners[1][1]),
            ("corners[2][0]", s.corners[2][0]),
            ("corners[2][1]", s.corners[2][1]),
            ("corners[3][0]", s.corners[3][0]),
            ("corners[3][1]", s.corners[3][1]),
        ],
    )?;
    Ok(ReliefScene {
        origin: finite_dvec3("scene->origin", &s.origin)?,
        edge_u: finite_dvec3("scene->edge_u", &s.edge_u)?,
        edge_v: finite_dvec3("scene->edge_v", &s.edge_v)?,
        tiles: DVec2::new(s.tiles_u, s.tiles_v),
        depth: s.depth,
        method: method_from(&s.method)?,
        shadows,
        shadow_bias: s.shadow_bias,
        light_dir: finite_dvec3("scene->light_dir", &s.light_dir)?,
        light_intensity: s.light_intensity,
        light_color: s.light_color,
        albedo: s.albedo,
        ambient: s.ambient,
        sky: s.sky.irradiance("scene->sky")?,
        corners: s.corners.map(DVec2::from_array),
    })
}

/// Stores the default scene in `*out`: a unit quad in the xz plane facing +y (u along +x, v
/// along -z), all of it drawn, one tile, 0.1 deep; relaxed cone stepping with 15 cone steps and 6 bisections of
/// the last step; self-shadowing with a bias of 0.02; a white light from (1, 2, 1), grey albedo
/// 0.8, ambient 0.2, no sky.
///
/// Returns `OCEAN_STATUS_NULL_POINTER` (or `_MISALIGNED_POINTER`) for a bad `out`, which is
/// then left unchanged.
///
/// # Safety
///
/// `out` must be writable.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn ocean_relief_scene_default(out: *mut OceanReliefScene) -> OceanStatus {
    guard("ocean_relief_scene_default", || {
        let d = ReliefScene::default();
        let s = OceanReliefScene {
            next: OceanNext::NULL,
            origin: OceanDVec3::from_dvec3(d.origin),
            edge_u: OceanDVec3::from_dvec3(d.edge_u),
            edge_v: OceanDVec3::from_dvec3(d.edge_v),
            tiles_u: d.tiles.x,
            tiles_v: d.tiles.y,
            depth: d.depth,
            method: method_to(&d.method),
            shadows: u32::from(d.shadows),
            shadow_bias: d.shadow_bias,
            light_dir: OceanDVec3::from_dvec3(d.light_dir),
            light_intensity: d.light_intensity,
            light_color: d.light_color,
            albedo: d.albedo,
            ambient: d.ambient,
            sky: OceanIrradiance::default(),
            corners: d.corners.map(|c| c.to_array()),
        };
        // SAFETY: forwarded from this function's contract.
        unsafe { write_out(out, "out", s) }
    })
}

/// Writes the uniform block of the exported `relief` draw shader for one draw of `scene` seen
/// by `camera` into `out` (the `OCEAN_RELIEF_UNIFORMS_SIZE` bytes of `Relief`, std140, in the
/// machine's byte order: upload them as they are with `glBufferSubData`), for a relief texture
/// of side `size` (2 to `OCEAN_RELIEF_MAX_SIDE`), edge mode `edge` (`OCEAN_RELIEF_EDGE_WRAP` or
/// `_CLAMP`, as the cones were generated) and `levels` mip levels (1 to log2 `size` for a
/// power-of-two side, else 1; see binding 1 below). With `srgb_encode` = 1
/// the shader writes sRGB-encoded colour (for a linear `GL_RGBA8` target); with 0 it writes
/// linear colour (for an sRGB target with `GL_FRAMEBUFFER_SRGB`).
///
/// Positions in the block are relative to the camera's eye (the subtraction happens here, in
/// double precision), so quads far from the world origin do not jitter.
///
/// To draw (`ocean_shader_export` of `relief`, entry points `relief_vs` and `relief_fs`, with
/// its binding table):
/// - binding 0: this block, a uniform buffer;
/// - binding 1: the relief texture, `GL_RGBA32F`, `size` x `size`, the texels of
///   `ocean_relief_cones_texels` (`[depth, c, D, E]`, row v = 0 first). The shader reads it with
///   `texelFetch` and filters by hand (bilinear, with the edge mode), so no sampler state
///   matters. With `levels` = 1 it reads level 0 only. With more, the texture is the atlas of
///   `ocean_relief_mip_atlas_size` (one texture level, (`size` + `size` / 2) x `size`): level l
///   (side `size` >> l, placed at `ocean_relief_mip_atlas_origin`) holds the texels of the map
///   `ocean_relief_map_downsample` made l times from level 0's, with its own cones
///   (`ocean_relief_cones_create` on that map: cones of level 0 do not fit a coarser surface),
///   and each fragment reads the one level `ocean_relief_mip_level` picks from its texture
///   coordinates' screen derivatives, chosen once before the tracer's loops;
/// - for a quad-directional cone map (`ocean_relief_quad_cones_create`), export `relief_quad`
///   instead: the same block (this function, unchanged), and binding 1 is a
///   `GL_TEXTURE_2D_ARRAY`, `GL_RGBA32F`, `size` x `size` x 4 layers, the texels of
///   `ocean_relief_quad_cones_texels`; each ray reads the layer of its direction's quadrant.
///   With `levels` > 1 every layer is an atlas as above, of that layer's texels at each level;
/// - draw 6 vertices as `GL_TRIANGLES` with no vertex buffer (an empty vertex array object);
/// - depth test `GL_LESS` (`GL_GREATER` for a reversed-Z camera) with depth writes: the fragment
///   stage writes the hit point's depth to `gl_FragDepth`, so the relief occludes and is
///   occluded correctly. Cull nothing or the back faces (the front faces `edge_u x edge_v`).
///
/// The exported GLSL's clip space is OpenGL's (naga flips y and maps z to [-1, 1]); the depth
/// it writes is the window depth for `glDepthRange(0, 1)`.
///
/// Returns `OCEAN_STATUS_NULL_POINTER` / `_MISALIGNED_POINTER` for a bad pointer,
/// `OCEAN_STATUS_NON_FINITE` for a NaN or infinite member, `OCEAN_STATUS_INVALID_ARGUMENT` for
/// a camera, scene, method, size or edge the description above refuses (the message names
/// it), `OCEAN_STATUS_LENGTH_MISMATCH` if `len` is not `OCEAN_RELIEF_UNIFORMS_SIZE`,
/// `OCEAN_STATUS_LENGTH_OVERFLOW` if `len` exceeds `PTRDIFF_MAX`.
///
/// # Safety
///
/// `camera` and `scene` must be readable, and `out` point to `len` writable bytes that no
/// other thread touches during the call.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn ocean_relief_uniforms(
    camera: *const OceanCamera,
    scene: *const OceanReliefScene,
    size: u32,
    edge: u32,
    levels: u32,
    srgb_encode: u32,
    out: *mut u8,
    len: usize,
) -> OceanStatus {
    guard("ocean_relief_uniforms", || {
        check_ptr(camera, "camera")?;
        check_ptr(scene, "scene")?;
        check_block_out::<ReliefUniforms>(out, len)?;
        // SAFETY: forwarded from this function's contract.
        let camera = unsafe { read_camera(camera) }?;
        // SAFETY: forwarded from this function's contract.
        let scene = unsafe { read_params_checked(scene, "scene") }?;
        // SAFETY: as above (the method's extensions are readable as the scene's are).
        unsafe { check_chain(&scene.method, "scene->method.next") }?;
        let scene = scene_from(&scene)?;
        let edge = edge_from(edge)?;
        let srgb_encode = check_flag("srgb_encode", srgb_encode)?;
        let u = ocean_gpu::scene_uniforms(
            &camera,
            &scene,
            size as usize,
            edge,
            levels as usize,
            srgb_encode,
        )?;
        // SAFETY: forwarded from this function's contract.
        unsafe { write_block(out, len, &u) }?;
        Ok(())
    })
}

crate::boundary::chain::extensible!(OceanReliefScene);

#[cfg(test)]
mod tests {
    use core::ptr::{null, null_mut};

    use glam::DVec3;
    use ocean_core::Camera;

    use super::*;
    use ocean_core::camera::DepthConvention;

    use crate::status::last_error;

    /// `ocean_relief_method_default` (CPU part of the library) is the tracer of the default
    /// scene (whose defaults are the GPU renderer's).
    #[test]
    fn the_default_method_is_the_default_scenes() {
        let mut scene = OceanReliefScene::default();
        // SAFETY: valid pointer.
        let st = unsafe { ocean_relief_scene_default(&mut scene) };
        assert_eq!(st, OceanStatus::Ok);
        let mut method = OceanReliefMethod::default();
        // SAFETY: valid pointer.
        let st = unsafe { crate::relief_trace::ocean_relief_method_default(&mut method) };
        assert_eq!(st, OceanStatus::Ok);
        assert_eq!(method, scene.method);
    }

    /// A camera 3 m above and 2 m beside a quad far from the origin, looking at it, in OpenGL's
    /// depth convention (the block folds it into WebGPU's).
    fn camera() -> (OceanCamera, Camera) {
        let eye = DVec3::new(1.0e5 + 2.0, 3.0, -4.0e4);
        let view =
            ocean_core::camera::look_at(eye, DVec3::new(1.0e5, 0.0, -4.0e4), DVec3::Y).unwrap();
        let projection = ocean_core::Projection::Perspective {
            fov_y: 0.9,
            aspect: 1.5,
            near: 0.05,
            far: ocean_core::Far::Finite(500.0),
        };
        let made = Camera::new(view, projection, DepthConvention::NEG_ONE_TO_ONE).unwrap();
        let desc = OceanCamera::from_camera(&made);
        // What the library reads back from the C layout.
        let camera = crate::camera::camera_from(&desc).unwrap();
        (desc, camera)
    }

    fn default_scene() -> OceanReliefScene {
        let mut s = OceanReliefScene::default();
        // SAFETY: writable out.
        let status = unsafe { ocean_relief_scene_default(&mut s) };
        assert_eq!(status, OceanStatus::Ok);
        s
    }

    fn scene() -> OceanReliefScene {
        let mut s = default_scene();
        s.origin = OceanDVec3 {
            x: 1.0e5 - 0.5,
            y: 0.0,
            z: -4.0e4 + 0.5,
        };
        s.method = OceanReliefMethod {
            next: OceanNext::NULL,
            method: OceanReliefTracer::Linear,
            steps: 20,
            binary: 5,
            search: OceanReliefSearch::LastStep,
        };
        s.tiles_u = 2.0;
        s.tiles_v = 2.0;
        s
    }

    #[test]
    fn the_default_scene_is_the_renderers() {
        assert_eq!(
            scene_from(&default_scene()).unwrap(),
            ReliefScene::default()
        );
        // SAFETY: NULL is refused before any write.
        let status = unsafe { ocean_relief_scene_default(null_mut()) };
        assert_eq!(status, OceanStatus::NullPointer);
    }

    /// The bytes are `ocean_gpu::scene_uniforms`' block, the one `ReliefRenderer` draws with
    /// (whose parity with the CPU tracers the GPU tests check), with the eye subtracted in f64.
    #[test]
    fn the_block_is_the_renderers() {
        let (desc, camera) = camera();
        let mut s = scene();
        // A sky whose irradiance grows with the normal's y: E(n) = 3 + 2 n_y (red).
        s.sky.k[0].r = 3.0 / 0.282_094_791_773_878_14;
        s.sky.k[2].r = 2.0 / 0.488_602_511_902_919_9;
        // A triangle reaching beyond the quad, counter-clockwise.
        s.corners = [[0.0, 0.0], [1.5, 0.25], [0.5, 1.0], [0.5, 1.0]];
        let mut out = [0xAAu8; OCEAN_RELIEF_UNIFORMS_SIZE + 4];
        // SAFETY: readable inputs, `out` holds `len` writable bytes.
        let status = unsafe {
            ocean_relief_uniforms(
                &desc,
                &s,
                128,
                crate::relief::OceanReliefEdge::Clamp as u32,
                7,
                1,
                out.as_mut_ptr(),
                OCEAN_RELIEF_UNIFORMS_SIZE,
            )
        };
        assert_eq!(status, OceanStatus::Ok, "{}", last_error());
        let want = ocean_gpu::scene_uniforms(
            &camera,
            &scene_from(&s).unwrap(),
            128,
            ocean_relief::Edge::Clamp,
            7,
            true,
        )
        .unwrap();
        assert_eq!(
            &out[..OCEAN_RELIEF_UNIFORMS_SIZE],
            bytemuck::bytes_of(&want)
        );
        assert_eq!(out[OCEAN_RELIEF_UNIFORMS_SIZE..], [0xAA; 4]);
        let u: ReliefUniforms = bytemuck::pod_read_unaligned(&out[..OCEAN_RELIEF_UNIFORMS_SIZE]);
        // The corner relative to the eye: (1e5 − 0.5, 0, −4e4 + 0.5) − (1e5 + 2, 3, −4e4), exact in f32.
        assert_eq!(u.quad_origin, [-2.5, -3.0, 0.5, 0.0]);
        // Texture side, clamp (1), linear search (0) with 20 + 5 steps, shadows + sRGB flags.
        assert_eq!(u.trace, [128, 1, 0, 0]);
        assert_eq!(u.steps[..3], [20, 5, 3]);
        // One texture width is 0.5 m: the 0.1 m relief is 0.2 texture widths, 25.6 texels.
        assert_eq!((u.tangent[3], u.normal[3]), (0.2, 25.6));
        // The level count, 128 down to 2: 7 levels.
        assert_eq!(u.shading[3], 7.0);
        assert_eq!(u.polygon, [[0.0, 0.0, 1.5, 0.25], [0.5, 1.0, 0.5, 1.0]]);
        // The sky's rows are E/π: a white Lambertian surface's radiance.
        let pi = std::f64::consts::PI;
        assert_eq!(
            u.irradiance[0],
            [(3.0 / 0.282_094_791_773_878_14 / pi) as f32, 0.0, 0.0, 0.0]
        );
        assert_eq!(
            u.irradiance[2],
            [(2.0 / 0.488_602_511_902_919_9 / pi) as f32, 0.0, 0.0, 0.0]
        );
        assert!(
            u.irradiance[3..]
                .iter()
                .chain(&u.irradiance[1..2])
                .all(|r| *r == [0.0; 4])
        );
    }

    #[test]
    fn bad_input_is_refused_and_nothing_is_written() {
        let (desc, _) = camera();
        let good = scene();
        let call_levels =
            |desc: &OceanCamera, s: &OceanReliefScene, size, edge, levels, srgb, len| {
                let mut out = [7u8; 500];
                // SAFETY: readable inputs, `out` holds at least `len` writable bytes.
                let status = unsafe {
                    ocean_relief_uniforms(desc, s, size, edge, levels, srgb, out.as_mut_ptr(), len)
                };
                assert!(out.iter().all(|&b| b == 7), "written on failure");
                (status, last_error())
            };
        let call = |desc: &OceanCamera, s: &OceanReliefScene, size, edge, srgb, len| {
            call_levels(desc, s, size, edge, 1, srgb, len)
        };
        let with = |f: &dyn Fn(&mut OceanReliefScene)| {
            let mut s = good;
            f(&mut s);
            call(&desc, &s, 64, 0, 0, 448)
        };
        let cases: [(OceanStatus, &str, (OceanStatus, String)); 19] = [
            // 64 texels hold 6 levels (64 down to 2); a side that is not a power of two, one.
            (
                OceanStatus::InvalidArgument,
                "mip levels",
                call_levels(&desc, &good, 64, 0, 0, 0, 448),
            ),
            (
                OceanStatus::InvalidArgument,
                "mip levels",
                call_levels(&desc, &good, 64, 0, 7, 0, 448),
            ),
            (
                OceanStatus::InvalidArgument,
                "mip levels",
                call_levels(&desc, &good, 48, 0, 2, 0, 448),
            ),
            (
                OceanStatus::LengthMismatch,
                "holds exactly 448",
                call(&desc, &good, 64, 0, 0, 447),
            ),
            (
                OceanStatus::LengthMismatch,
                "holds exactly 448",
                call(&desc, &good, 64, 0, 0, 449),
            ),
            (
                OceanStatus::InvalidArgument,
                "size",
                call(&desc, &good, 1, 0, 0, 448),
            ),
            (
                OceanStatus::InvalidArgument,
                "edge",
                call(&desc, &good, 64, 2, 0, 448),
            ),
            (
                OceanStatus::InvalidArgument,
                "srgb_encode",
                call(&desc, &good, 64, 0, 2, 448),
            ),
            (
                OceanStatus::NonFinite,
                "scene->edge_u.y",
                with(&|s| s.edge_u.y = f64::NAN),
            ),
            (
                OceanStatus::NonFinite,
                "scene->light_color[1]",
                with(&|s| s.light_color[1] = f32::NAN),
            ),
            (
                OceanStatus::NonFinite,
                "scene->sky.k[4]",
                with(&|s| s.sky.k[4].g = f64::INFINITY),
            ),
            (
                OceanStatus::InvalidArgument,
                "orthogonal",
                with(&|s| {
                    s.edge_v = OceanDVec3 {
                        x: 1.0,
                        y: 0.0,
                        z: -1.0,
                    }
                }),
            ),
            (
                OceanStatus::InvalidArgument,
                "method->steps",
                with(&|s| s.method.steps = 0),
            ),
            (
                OceanStatus::InvalidArgument,
                "light direction",
                with(&|s| s.light_dir = OceanDVec3::default()),
            ),
            (
                OceanStatus::InvalidArgument,
                "shadows",
                with(&|s| s.shadows = 2),
            ),
            (
                OceanStatus::NonFinite,
                "scene->corners[2][1]",
                with(&|s| s.corners[2][1] = f64::NAN),
            ),
            // A zeroed polygon, and the quad's corners clockwise (its back).
            (
                OceanStatus::InvalidArgument,
                "enclose no area",
                with(&|s| s.corners = [[0.0; 2]; 4]),
            ),
            (
                OceanStatus::InvalidArgument,
                "enclose no area",
                with(&|s| s.corners.reverse()),
            ),
            (
                OceanStatus::InvalidArgument,
                "camera",
                call(
                    &OceanCamera {
                        projection: {
                            let mut p = desc.projection;
                            p[0] = -p[0];
                            p
                        },
                        ..desc
                    },
                    &good,
                    64,
                    0,
                    0,
                    448,
                ),
            ),
        ];
        for (status, text, (got, message)) in cases {
            assert_eq!(got, status, "{text}: {message}");
            assert!(message.contains(text), "{text}: {message}");
        }
        // An unknown search, from C memory.
        let at = offset_of!(OceanReliefScene, method) + offset_of!(OceanReliefMethod, search);
        let bad = crate::boundary::enums::Poked::new(&good, at, 7);
        let mut out = [7u8; 448];
        // SAFETY: readable inputs, `out` holds 448 writable bytes.
        let got = unsafe {
            ocean_relief_uniforms(&desc, bad.as_ptr(), 64, 0, 1, 0, out.as_mut_ptr(), 448)
        };
        let message = last_error();
        assert!(out.iter().all(|&b| b == 7), "written on failure");
        assert_eq!(got, OceanStatus::InvalidArgument, "{message}");
        assert!(
            message.contains("scene->method.search = 7 is not an OCEAN_RELIEF_SEARCH_* value"),
            "{message}"
        );
        let mut out = [0u8; 448];
        // SAFETY: NULL pointers are refused before anything is read or written.
        unsafe {
            assert_eq!(
                ocean_relief_uniforms(null(), &good, 64, 0, 1, 0, out.as_mut_ptr(), 448,),
                OceanStatus::NullPointer
            );
            assert_eq!(
                ocean_relief_uniforms(&desc, null(), 64, 0, 1, 0, out.as_mut_ptr(), 448,),
                OceanStatus::NullPointer
            );
            assert_eq!(
                ocean_relief_uniforms(&desc, &good, 64, 0, 1, 0, null_mut(), 448),
                OceanStatus::NullPointer
            );
        }
    }
}
