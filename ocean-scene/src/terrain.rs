//! The island's terrain in `ocean render`: a height field (the wave train box scene's terrain,
//! [`crate::island`]) drawn as triangles, lit by the scene's Sun and sky, into the frame's split
//! light targets and depth (`terrain.wgsl`, `ocean_gpu::LightTargets`).
//!
//! Scene dressing rather than one of the library's techniques: the sea drawn over it (and the
//! wave trains that break on it) are the library's; the terrain only has to occlude, write the
//! depth the obscurance pass reads, and look like land.

use crate::SceneError;
use glam::{DMat4, DVec2, DVec3};
use ocean_brdf::{Irradiance, Lighting};
use ocean_core::Camera;
use ocean_gpu::wgpu::util::DeviceExt;
use ocean_gpu::{GpuContext, LightTargets, wgpu};

/// `terrain.wgsl`'s `Terrain` block (std140, 272 bytes).
#[repr(C)]
#[derive(Clone, Copy, bytemuck::Pod, bytemuck::Zeroable)]
pub(crate) struct Uniform {
    view_proj: [[f32; 4]; 4],
    origin: [f32; 4],
    counts: [u32; 4],
    sun_dir: [f32; 4],
    sun: [f32; 4],
    irradiance: [[f32; 4]; 9],
}

impl Uniform {
    /// The block for `camera`, `lighting`'s Sun and the environment's irradiance `sky`, with `origin` (a world point, whose position
    /// relative to the eye the block holds), `spacing` and `counts` as the entry points read them.
    pub(crate) fn new(
        camera: &Camera,
        lighting: &Lighting,
        sky_irradiance: &Irradiance,
        origin: DVec3,
        spacing: f64,
        counts: (u32, u32),
    ) -> Self {
        let eye = camera.eye();
        let view_proj = camera.view_projection_f64() * DMat4::from_translation(eye);
        let sky = lighting.sky();
        let o = origin - eye;
        Self {
            view_proj: view_proj.as_mat4().to_cols_array_2d(),
            origin: [o.x as f32, o.y as f32, o.z as f32, spacing as f32],
            counts: [counts.0, counts.1, 0, 0],
            sun_dir: rgb(sky.sun_direction(), 0.0),
            sun: rgb(sky.sun_radiance() * sky.sun_solid_angle(), 0.0),
            irradiance: sky_irradiance.gpu_rows(),
        }
    }
}

/// `terrain.wgsl` after the library's spherical-harmonic irradiance (`sh_irradiance`).
pub(crate) fn shader_source() -> String {
    format!(
        "{}{}",
        ocean_gpu::shaders::IRRADIANCE_WGSL,
        include_str!("terrain.wgsl")
    )
}

/// A height field ready to draw.
pub struct TerrainRenderer {
    pipeline: wgpu::RenderPipeline,
    bind_group: wgpu::BindGroup,
    uniform: wgpu::Buffer,
    indices: wgpu::Buffer,
    index_count: u32,
    /// World (x, z) of point (0, 0), spacing, points per row and rows.
    origin: DVec2,
    spacing: f64,
    size: (u32, u32),
}

fn rgb(v: DVec3, w: f32) -> [f32; 4] {
    [v.x as f32, v.y as f32, v.z as f32, w]
}

/// A pipeline that draws lit triangles into the frame's split light targets (direct, ambient:
/// `ocean_gpu::RADIANCE_FORMAT`) and its depth (`Depth32Float`, less, written), with `samples`
/// samples per pixel: the terrain's and the solids' (`terrain.wgsl`'s entry points `entries`).
pub(crate) fn lit_pipeline(
    ctx: &GpuContext,
    label: &str,
    module: &wgpu::ShaderModule,
    layout: &wgpu::BindGroupLayout,
    entries: (&str, &str),
    buffers: &[Option<wgpu::VertexBufferLayout<'_>>],
    samples: u32,
) -> wgpu::RenderPipeline {
    let device = ctx.device();
    let pipeline_layout = device.create_pipeline_layout(&wgpu::PipelineLayoutDescriptor {
        label: Some(&format!("{label} pipeline layout")),
        bind_group_layouts: &[Some(layout)],
        immediate_size: 0,
    });
    device.create_render_pipeline(&wgpu::RenderPipelineDescriptor {
        label: Some(label),
        layout: Some(&pipeline_layout),
        vertex: wgpu::VertexState {
            module,
            entry_point: Some(entries.0),
            compilation_options: wgpu::PipelineCompilationOptions::default(),
            buffers,
        },
        primitive: wgpu::PrimitiveState::default(),
        depth_stencil: Some(wgpu::DepthStencilState {
            format: wgpu::TextureFormat::Depth32Float,
            depth_write_enabled: Some(true),
            depth_compare: Some(wgpu::CompareFunction::Less),
            stencil: wgpu::StencilState::default(),
            bias: wgpu::DepthBiasState::default(),
        }),
        multisample: wgpu::MultisampleState {
            count: samples,
            ..wgpu::MultisampleState::default()
        },
        fragment: Some(wgpu::FragmentState {
            module,
            entry_point: Some(entries.1),
            compilation_options: wgpu::PipelineCompilationOptions::default(),
            targets: &[
                Some(ocean_gpu::RADIANCE_FORMAT.into()),
                Some(ocean_gpu::RADIANCE_FORMAT.into()),
            ],
        }),
        multiview_mask: None,
        cache: None,
    })
}

impl TerrainRenderer {
    /// Uploads `heights` (row-major, `size.0` per row, metres above the sea at rest) of a grid
    /// whose point (0, 0) is at world `(x, z)` = `origin`, `spacing` metres apart, for split
    /// light targets of `samples` samples per pixel and `Depth32Float`, depth tested `Less`
    /// (WebGPU's forward range).
    ///
    /// # Errors
    ///
    /// A message for a grid that is not at least 2 × 2 or whose side exceeds the device's
    /// largest texture, or a height count that does not match.
    pub fn new(
        ctx: &GpuContext,
        heights: &[f32],
        size: (usize, usize),
        origin: DVec2,
        spacing: f64,
        samples: u32,
    ) -> Result<Self, SceneError> {
        let device = ctx.device();
        let side = device.limits().max_texture_dimension_2d as usize;
        let (nx, nz) = size;
        if nx < 2 || nz < 2 || nx > side || nz > side || heights.len() != nx * nz {
            return Err(format!(
                "terrain: a {nx} x {nz} grid with {} heights (at least 2 x 2, at most {side} a side, one height per point)",
                heights.len()
            )
            .into());
        }
        let module = device.create_shader_module(wgpu::ShaderModuleDescriptor {
            label: Some("terrain shader"),
            source: wgpu::ShaderSource::Wgsl(shader_source().into()),
        });
        let texture = device.create_texture_with_data(
            ctx.queue(),
            &wgpu::TextureDescriptor {
                label: Some("terrain heights"),
                size: wgpu::Extent3d {
                    width: nx as u32,
                    height: nz as u32,
                    depth_or_array_layers: 1,
                },
                mip_level_count: 1,
                sample_count: 1,
                dimension: wgpu::TextureDimension::D2,
                format: wgpu::TextureFormat::R32Float,
                usage: wgpu::TextureUsages::TEXTURE_BINDING,
                view_formats: &[],
            },
            wgpu::util::TextureDataOrder::LayerMajor,
            bytemuck::cast_slice(heights),
        );
        let uniform = device.create_buffer(&wgpu::BufferDescriptor {
            label: Some("terrain uniform"),
            size: std::mem::size_of::<Uniform>() as u64,
            usage: wgpu::BufferUsages::UNIFORM | wgpu::BufferUsages::COPY_DST,
            mapped_at_creation: false,
        });
        let stages = wgpu::ShaderStages::VERTEX | wgpu::ShaderStages::FRAGMENT;
        let layout = device.create_bind_group_layout(&wgpu::BindGroupLayoutDescriptor {
            label: Some("terrain bind group layout"),
            entries: &[
                wgpu::BindGroupLayoutEntry {
                    binding: 0,
                    visibility: stages,
                    ty: wgpu::BindingType::Buffer {
                        ty: wgpu::BufferBindingType::Uniform,
                        has_dynamic_offset: false,
                        min_binding_size: None,
                    },
                    count: None,
                },
                wgpu::BindGroupLayoutEntry {
                    binding: 1,
                    visibility: wgpu::ShaderStages::VERTEX,
                    ty: wgpu::BindingType::Texture {
                        sample_type: wgpu::TextureSampleType::Float { filterable: false },
                        view_dimension: wgpu::TextureViewDimension::D2,
                        multisampled: false,
                    },
                    count: None,
                },
            ],
        });
        let view = texture.create_view(&wgpu::TextureViewDescriptor::default());
        let bind_group = device.create_bind_group(&wgpu::BindGroupDescriptor {
            label: Some("terrain bind group"),
            layout: &layout,
            entries: &[
                wgpu::BindGroupEntry {
                    binding: 0,
                    resource: uniform.as_entire_binding(),
                },
                wgpu::BindGroupEntry {
                    binding: 1,
                    resource: wgpu::BindingResource::TextureView(&view),
                },
            ],
        });
        let pipeline = lit_pipeline(
            ctx,
            "terrain",
            &module,
            &layout,
            ("terrain_vs", "terrain_fs"),
            &[],
            samples,
        );
        // Two triangles per cell.
        let mut index = Vec::with_capacity((nx - 1) * (nz - 1) * 6);
        for j in 0..nz as u32 - 1 {
            for i in 0..nx as u32 - 1 {
                let a = j * nx as u32 + i;
                let b = a + nx as u32;
                index.extend_from_slice(&[a, b, a + 1, a + 1, b, b + 1]);
            }
        }
        let indices = device.create_buffer_init(&wgpu::util::BufferInitDescriptor {
            label: Some("terrain indices"),
            contents: bytemuck::cast_slice(&index),
            usage: wgpu::BufferUsages::INDEX,
        });
        Ok(Self {
            pipeline,
            bind_group,
            uniform,
            indices,
            index_count: index.len() as u32,
            origin,
            spacing,
            size: (nx as u32, nz as u32),
        })
    }

    /// Records the terrain seen by `camera` (WebGPU's forward depth range) under `lighting`
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
        let u = Uniform::new(
            camera,
            lighting,
            sky,
            DVec3::new(self.origin.x, 0.0, self.origin.y),
            self.spacing,
            self.size,
        );
        ctx.queue()
            .write_buffer(&self.uniform, 0, bytemuck::bytes_of(&u));
        let mut pass = encoder.begin_render_pass(&wgpu::RenderPassDescriptor {
            label: Some("island terrain"),
            color_attachments: &targets.color_attachments(),
            depth_stencil_attachment: Some(targets.depth_attachment()),
            timestamp_writes: None,
            occlusion_query_set: None,
            multiview_mask: None,
        });
        pass.set_pipeline(&self.pipeline);
        pass.set_bind_group(0, &self.bind_group, &[]);
        pass.set_index_buffer(self.indices.slice(..), wgpu::IndexFormat::Uint32);
        pass.draw_indexed(0..self.index_count, 0, 0..1);
    }
}
