//! A caller's water mesh drawn by the ocean renderer (`mesh_vs`, `mesh_fs`) and its light
//! composed with an ambient obscurance (`sky_vs`, `compose_fs`): on wgpu, what an engine does
//! in its own pipeline with the exported shaders and `ocean_surface_uniforms`
//! (examples/cpp-glfw). [`OceanRenderer::render_mesh_image`] is a one-off (it allocates its
//! targets and waits for the GPU), for tests, tools and thumbnails.

use glam::DVec2;
use ocean_core::{Camera, DepthDirection};
use wgpu::util::DeviceExt;

use super::layers::{ComposeInputs, depth_state};
use super::{FrameUniform, MeshGrid, OceanRenderer, frame_uniform, invalid, write_waves};
use crate::light_targets::{RADIANCE_FORMAT, radiance_targets};
use crate::readback::read_texture;
use crate::{GpuContext, GpuError};

/// A water mesh: its grid and, per grid point `(i, j)` at element `j·nx + i`, the position
/// relative to the grid's point (0, 0) at rest and the unit normal (what
/// `ocean_wtb::Frame::evaluate` writes).
#[derive(Clone, Copy, Debug)]
pub struct MeshGeometry<'a> {
    /// The grid: origin, spacing, points per row and rows (at least 2 × 2 to draw cells).
    pub grid: MeshGrid,
    /// Positions, `nx · nz` of them, finite.
    pub positions: &'a [[f32; 3]],
    /// Unit normals, `nx · nz` of them, finite.
    pub normals: &'a [[f32; 3]],
}

impl MeshGeometry<'_> {
    fn check(&self) -> Result<usize, GpuError> {
        let g = &self.grid;
        if g.nx < 2 || g.nz < 2 {
            return Err(invalid(
                "mesh",
                format!("{} x {} points: drawing needs at least 2 x 2", g.nx, g.nz),
            ));
        }
        let n = u64::from(g.nx) * u64::from(g.nz);
        if n > u64::from(u32::MAX) {
            return Err(GpuError::TooLarge {
                what: "mesh points (32-bit indices)",
                needed: n,
                limit: u64::from(u32::MAX),
            });
        }
        let n = n as usize;
        for (what, v) in [("positions", self.positions), ("normals", self.normals)] {
            if v.len() != n {
                return Err(invalid(
                    "mesh",
                    format!("{} {what} for {} x {} points", v.len(), g.nx, g.nz),
                ));
            }
            if let Some(k) = v.iter().position(|p| !p.iter().all(|c| c.is_finite())) {
                return Err(invalid(
                    "mesh",
                    format!("{what}[{k}] = {:?} is not finite", v[k]),
                ));
            }
        }
        Ok(n)
    }

    /// Two triangles per cell, vertex `j·nx + i` for point `(i, j)`.
    fn indices(&self) -> Vec<u32> {
        let (nx, nz) = (self.grid.nx, self.grid.nz);
        let mut out = Vec::with_capacity((nx as usize - 1) * (nz as usize - 1) * 6);
        for j in 0..nz - 1 {
            for i in 0..nx - 1 {
                let a = j * nx + i;
                let c = a + nx;
                out.extend_from_slice(&[a, c, a + 1, a + 1, c, c + 1]);
            }
        }
        out
    }
}

impl OceanRenderer {
    /// Draws `mesh` seen by `camera` at `time` into a new `width × height` image with the
    /// renderer's surface (its waves filtered per pixel on top of the mesh) and lighting, and
    /// reads it back: tightly packed RGBA8 rows from the top, sRGB-encoded.
    ///
    /// Pass 1 (`mesh_vs`, `mesh_fs`) draws the mesh with depth into two `rgba16float` targets,
    /// the Sun's reflection and the ambient (sky and sea) light; pass 2 (`sky_vs`,
    /// `compose_fs`) writes each pixel's `display(direct + A · ambient)` where the mesh drew
    /// and the sky elsewhere. `obscurance` holds `A` per pixel (`width · height` values in
    /// `[0, 1]`, rows from the top; `None`: 1 everywhere, nothing occluded).
    ///
    /// Needs an 8-bit RGBA or BGRA [`super::OceanOptions::color_format`], as
    /// [`render_image`](Self::render_image). The frame's uniform block and phases are written
    /// into the renderer's own buffers, as [`render`](Self::render) does.
    ///
    /// # Errors
    ///
    /// As [`render_image`](Self::render_image), and [`GpuError::InvalidInput`] for a mesh
    /// with fewer than 2 × 2 points, other lengths than its grid's, non-finite values, or an
    /// obscurance of another length or with values outside `[0, 1]`.
    #[allow(clippy::too_many_arguments)]
    pub fn render_mesh_image(
        &self,
        ctx: &GpuContext,
        camera: &Camera,
        time: f64,
        mesh: &MeshGeometry<'_>,
        obscurance: Option<&[f32]>,
        width: u32,
        height: u32,
    ) -> Result<Vec<u8>, GpuError> {
        use wgpu::TextureFormat as F;
        let bgra = match self.options.color_format {
            F::Rgba8Unorm | F::Rgba8UnormSrgb => false,
            F::Bgra8Unorm | F::Bgra8UnormSrgb => true,
            other => {
                return Err(invalid(
                    "color_format",
                    format!(
                        "render_mesh_image reads back 8-bit RGBA or BGRA targets, not {other:?}"
                    ),
                ));
            }
        };
        self.check_viewport(ctx, width, height)?;
        self.lighting_set()?;
        let surface = self.surface.as_ref().ok_or(GpuError::NotConfigured {
            what: "ocean surface",
            call: "OceanRenderer::set_surface",
        })?;
        mesh.check()?;
        let pixels = width as usize * height as usize;
        let ones;
        let obscurance = match obscurance {
            Some(a) => {
                if a.len() != pixels || !a.iter().all(|v| (0.0..=1.0).contains(v)) {
                    return Err(invalid(
                        "obscurance",
                        format!("{width} x {height} values in [0, 1] are needed"),
                    ));
                }
                a
            }
            None => {
                ones = vec![1.0f32; pixels];
                &ones
            }
        };
        let mut u = frame_uniform(
            &self.options,
            surface,
            self.lighting.as_ref(),
            camera,
            time,
            (width, height),
            Some(&mesh.grid),
        )?;
        let eye = camera.eye();
        let o = DVec2::new(eye.x, eye.z);
        (u.local, u.local_counts) = self.local.uniform(o);
        let phases = surface.phases(o, time);
        let local_phases = self.local.phases(o, time);
        let indices = mesh.indices();
        let device = ctx.device();
        let direction = camera.depth().direction();
        let range = camera.depth().range();
        let clear_depth = range.window_depth(camera.depth().clear_depth()) as f32;
        let depth_format = self
            .options
            .depth_format
            .unwrap_or(wgpu::TextureFormat::Depth32Float);
        let color = crate::scoped(device, || {
            let queue = ctx.queue();
            queue.write_buffer(&self.uniform, 0, bytemuck::bytes_of::<FrameUniform>(&u));
            write_waves(ctx, &self.wave_texture, &phases, phases.len() as u32, 1);
            self.local.write_phases(ctx, &local_phases);
            let buffer = |label, contents: &[u8], usage| {
                device.create_buffer_init(&wgpu::util::BufferInitDescriptor {
                    label: Some(label),
                    contents,
                    usage,
                })
            };
            let positions = buffer(
                "ocean mesh positions",
                bytemuck::cast_slice(mesh.positions),
                wgpu::BufferUsages::VERTEX,
            );
            let normals = buffer(
                "ocean mesh normals",
                bytemuck::cast_slice(mesh.normals),
                wgpu::BufferUsages::VERTEX,
            );
            let index_buffer = buffer(
                "ocean mesh indices",
                bytemuck::cast_slice(&indices),
                wgpu::BufferUsages::INDEX,
            );
            let extent = wgpu::Extent3d {
                width,
                height,
                depth_or_array_layers: 1,
            };
            let target = |label, format, usage| {
                device.create_texture(&wgpu::TextureDescriptor {
                    label: Some(label),
                    size: extent,
                    mip_level_count: 1,
                    sample_count: 1,
                    dimension: wgpu::TextureDimension::D2,
                    format,
                    usage,
                    view_formats: &[],
                })
            };
            let attachment_and_read =
                wgpu::TextureUsages::RENDER_ATTACHMENT | wgpu::TextureUsages::TEXTURE_BINDING;
            let direct = target("ocean mesh direct", RADIANCE_FORMAT, attachment_and_read);
            let ambient = target("ocean mesh ambient", RADIANCE_FORMAT, attachment_and_read);
            let depth = target(
                "ocean mesh depth",
                depth_format,
                wgpu::TextureUsages::RENDER_ATTACHMENT,
            );
            let ao = target(
                "ocean mesh obscurance",
                wgpu::TextureFormat::R32Float,
                wgpu::TextureUsages::TEXTURE_BINDING | wgpu::TextureUsages::COPY_DST,
            );
            queue.write_texture(
                ao.as_image_copy(),
                bytemuck::cast_slice(obscurance),
                wgpu::TexelCopyBufferLayout {
                    offset: 0,
                    bytes_per_row: Some(4 * width),
                    rows_per_image: Some(height),
                },
                extent,
            );
            let color = target(
                "ocean mesh image",
                self.options.color_format,
                wgpu::TextureUsages::RENDER_ATTACHMENT | wgpu::TextureUsages::COPY_SRC,
            );
            let view = |t: &wgpu::Texture| t.create_view(&wgpu::TextureViewDescriptor::default());
            let (direct_view, ambient_view, ao_view) = (view(&direct), view(&ambient), view(&ao));
            let (depth_view, color_view) = (view(&depth), view(&color));

            let mesh_pipeline = self.mesh_pipeline(device, depth_format, direction);
            let compose = self.compose_pipeline(device, 1);
            let compose_group = self.compose_bind_group(
                device,
                &compose.layout,
                &ComposeInputs {
                    direct: &direct_view,
                    ambient: &ambient_view,
                    obscurance: &ao_view,
                },
                1,
            );

            let mut encoder = device.create_command_encoder(&wgpu::CommandEncoderDescriptor {
                label: Some("ocean mesh image"),
            });
            let clear = |view| {
                Some(wgpu::RenderPassColorAttachment {
                    view,
                    depth_slice: None,
                    resolve_target: None,
                    ops: wgpu::Operations {
                        load: wgpu::LoadOp::Clear(wgpu::Color::TRANSPARENT),
                        store: wgpu::StoreOp::Store,
                    },
                })
            };
            {
                let mut pass = encoder.begin_render_pass(&wgpu::RenderPassDescriptor {
                    label: Some("ocean mesh"),
                    color_attachments: &[clear(&direct_view), clear(&ambient_view)],
                    depth_stencil_attachment: Some(wgpu::RenderPassDepthStencilAttachment {
                        view: &depth_view,
                        depth_ops: Some(wgpu::Operations {
                            load: wgpu::LoadOp::Clear(clear_depth),
                            store: wgpu::StoreOp::Store,
                        }),
                        stencil_ops: None,
                    }),
                    timestamp_writes: None,
                    occlusion_query_set: None,
                    multiview_mask: None,
                });
                pass.set_pipeline(&mesh_pipeline);
                pass.set_bind_group(0, &self.bind_group, &[]);
                pass.set_vertex_buffer(0, positions.slice(..));
                pass.set_vertex_buffer(1, normals.slice(..));
                pass.set_index_buffer(index_buffer.slice(..), wgpu::IndexFormat::Uint32);
                pass.draw_indexed(0..indices.len() as u32, 0, 0..1);
            }
            {
                let mut pass = encoder.begin_render_pass(&wgpu::RenderPassDescriptor {
                    label: Some("ocean compose"),
                    color_attachments: &[clear(&color_view)],
                    depth_stencil_attachment: None,
                    timestamp_writes: None,
                    occlusion_query_set: None,
                    multiview_mask: None,
                });
                pass.set_pipeline(&compose.pipeline);
                pass.set_bind_group(0, &compose_group, &[]);
                pass.draw(0..3, 0..1);
            }
            queue.submit([encoder.finish()]);
            Ok(color)
        })?;
        let mut data = read_texture(ctx, &color, 0)?.data;
        if bgra {
            for px in data.chunks_exact_mut(4) {
                px.swap(0, 2);
            }
        }
        Ok(data)
    }

    /// The mesh pipeline: the renderer's layout, depth tested in the camera's direction and
    /// written, two radiance targets.
    fn mesh_pipeline(
        &self,
        device: &wgpu::Device,
        depth_format: wgpu::TextureFormat,
        direction: DepthDirection,
    ) -> wgpu::RenderPipeline {
        let attribute = |location| {
            [wgpu::VertexAttribute {
                format: wgpu::VertexFormat::Float32x3,
                offset: 0,
                shader_location: location,
            }]
        };
        let (position, normal) = (attribute(0), attribute(1));
        let buffers = [
            Some(wgpu::VertexBufferLayout {
                array_stride: 12,
                step_mode: wgpu::VertexStepMode::Vertex,
                attributes: &position,
            }),
            Some(wgpu::VertexBufferLayout {
                array_stride: 12,
                step_mode: wgpu::VertexStepMode::Vertex,
                attributes: &normal,
            }),
        ];
        device.create_render_pipeline(&wgpu::RenderPipelineDescriptor {
            label: Some("ocean mesh pipeline"),
            layout: Some(&self.pipeline_layout),
            vertex: wgpu::VertexState {
                module: &self.module,
                entry_point: Some("mesh_vs"),
                compilation_options: wgpu::PipelineCompilationOptions::default(),
                buffers: &buffers,
            },
            primitive: wgpu::PrimitiveState {
                topology: wgpu::PrimitiveTopology::TriangleList,
                // Steep waves can turn cells over: no culling.
                cull_mode: None,
                ..Default::default()
            },
            depth_stencil: Some(depth_state(depth_format, direction)),
            multisample: wgpu::MultisampleState::default(),
            fragment: Some(wgpu::FragmentState {
                module: &self.module,
                entry_point: Some("mesh_fs"),
                compilation_options: wgpu::PipelineCompilationOptions::default(),
                targets: &radiance_targets(),
            }),
            multiview_mask: None,
            cache: None,
        })
    }
}
