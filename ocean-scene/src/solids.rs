//! Plain solids of `ocean render` (the pier's posts): boxes drawn as triangles, Lambertian,
//! into the frame's split light targets and depth (`terrain.wgsl`'s `solid_vs`/`solid_fs`,
//! lit as the terrain is). One draw for every box: posts a pixel or two wide gain nothing from
//! relief mapping, and one relief draw each would cost a pass-worth of shader set-up per post
//! on a software adapter.

use glam::DVec3;
use ocean_brdf::{Irradiance, Lighting};
use ocean_core::Camera;
use ocean_gpu::wgpu::util::DeviceExt;
use ocean_gpu::{GpuContext, LightTargets, wgpu};

use crate::SceneError;
use crate::blocks::Block;
use crate::terrain::{Uniform, lit_pipeline};

/// One vertex: world position, unit normal, linear albedo.
#[repr(C)]
#[derive(Clone, Copy, bytemuck::Pod, bytemuck::Zeroable)]
struct Vertex {
    position: [f32; 3],
    normal: [f32; 3],
    albedo: [f32; 3],
}

/// Boxes ready to draw.
pub struct SolidRenderer {
    pipeline: wgpu::RenderPipeline,
    bind_group: wgpu::BindGroup,
    uniform: wgpu::Buffer,
    vertices: wgpu::Buffer,
    count: u32,
}

/// Two triangles per drawn face of each block, wound either way (drawn without culling).
fn triangles(blocks: &[Block]) -> Vec<Vertex> {
    let f = |v: DVec3| v.as_vec3().to_array();
    let mut out = Vec::new();
    for b in blocks {
        for q in b.quads() {
            let corners = [
                q.origin,
                q.origin + q.edge_u,
                q.origin + q.edge_v,
                q.origin + q.edge_u + q.edge_v,
            ];
            for k in [0, 1, 2, 2, 1, 3] {
                out.push(Vertex {
                    position: f(corners[k]),
                    normal: f(q.normal),
                    albedo: b.albedo,
                });
            }
        }
    }
    out
}

impl SolidRenderer {
    /// Uploads the faces of `blocks` (at least one face), for split light targets of
    /// `samples` samples per pixel and `Depth32Float` tested `Less` (WebGPU's forward range).
    ///
    /// # Errors
    ///
    /// A message when the blocks have no face to draw.
    pub fn new(ctx: &GpuContext, blocks: &[Block], samples: u32) -> Result<Self, SceneError> {
        let vertices = triangles(blocks);
        if vertices.is_empty() {
            return Err("solids: no face to draw".to_owned().into());
        }
        let device = ctx.device();
        let module = device.create_shader_module(wgpu::ShaderModuleDescriptor {
            label: Some("solids shader"),
            source: wgpu::ShaderSource::Wgsl(crate::terrain::shader_source().into()),
        });
        let uniform = device.create_buffer(&wgpu::BufferDescriptor {
            label: Some("solids uniform"),
            size: std::mem::size_of::<Uniform>() as u64,
            usage: wgpu::BufferUsages::UNIFORM | wgpu::BufferUsages::COPY_DST,
            mapped_at_creation: false,
        });
        let layout = device.create_bind_group_layout(&wgpu::BindGroupLayoutDescriptor {
            label: Some("solids bind group layout"),
            entries: &[wgpu::BindGroupLayoutEntry {
                binding: 0,
                visibility: wgpu::ShaderStages::VERTEX | wgpu::ShaderStages::FRAGMENT,
                ty: wgpu::BindingType::Buffer {
                    ty: wgpu::BufferBindingType::Uniform,
                    has_dynamic_offset: false,
                    min_binding_size: None,
                },
                count: None,
            }],
        });
        let bind_group = device.create_bind_group(&wgpu::BindGroupDescriptor {
            label: Some("solids bind group"),
            layout: &layout,
            entries: &[wgpu::BindGroupEntry {
                binding: 0,
                resource: uniform.as_entire_binding(),
            }],
        });
        let attributes = wgpu::vertex_attr_array![0 => Float32x3, 1 => Float32x3, 2 => Float32x3];
        let pipeline = lit_pipeline(
            ctx,
            "solids",
            &module,
            &layout,
            ("solid_vs", "solid_fs"),
            &[Some(wgpu::VertexBufferLayout {
                array_stride: std::mem::size_of::<Vertex>() as u64,
                step_mode: wgpu::VertexStepMode::Vertex,
                attributes: &attributes,
            })],
            samples,
        );
        let buffer = device.create_buffer_init(&wgpu::util::BufferInitDescriptor {
            label: Some("solids vertices"),
            contents: bytemuck::cast_slice(&vertices),
            usage: wgpu::BufferUsages::VERTEX,
        });
        Ok(Self {
            pipeline,
            bind_group,
            uniform,
            vertices: buffer,
            count: vertices.len() as u32,
        })
    }

    /// Records the solids seen by `camera` (WebGPU's forward depth range) under `lighting`
    /// into `targets` (loaded) as one render pass; the uniform block is written through the
    /// queue.
    pub fn draw(
        &self,
        ctx: &GpuContext,
        encoder: &mut wgpu::CommandEncoder,
        camera: &Camera,
        lighting: &Lighting,
        sky: &Irradiance,
        targets: &LightTargets<'_>,
    ) {
        let u = Uniform::new(camera, lighting, sky, DVec3::ZERO, 0.0, (0, 0));
        ctx.queue()
            .write_buffer(&self.uniform, 0, bytemuck::bytes_of(&u));
        let mut pass = encoder.begin_render_pass(&wgpu::RenderPassDescriptor {
            label: Some("solids"),
            color_attachments: &targets.color_attachments(),
            depth_stencil_attachment: Some(targets.depth_attachment()),
            timestamp_writes: None,
            occlusion_query_set: None,
            multiview_mask: None,
        });
        pass.set_pipeline(&self.pipeline);
        pass.set_bind_group(0, &self.bind_group, &[]);
        pass.set_vertex_buffer(0, self.vertices.slice(..));
        pass.draw(0..self.count, 0..1);
    }
}
