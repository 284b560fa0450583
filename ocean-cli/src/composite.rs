//! The obscurance of `ocean render`: Scalable Ambient Obscurance (McGuire, Mara & Luebke 2012,
//! `ocean_gpu::SaoPass`) over the frame's whole depth buffer (sea, island and rocks), applied
//! to the frame by a full-screen pass (`composite.wgsl`): the tone-mapped linear colour times
//! `1 − strength·(1 − A)`.
//!
//! The obscurance darkens the image where the sea meets the rocks and the island and in the
//! creases of the terrain. It multiplies the frame's whole light, not its ambient part alone:
//! the renderers write one display colour per pixel, so the Sun's direct light and glints are
//! dimmed too where A < 1 (the sea's light is mostly environment light, reflected sky and
//! refracted light, so there the difference is the glints').

use ocean_core::Camera;
use ocean_gpu::{GpuContext, GpuError, SaoPass, wgpu};
use ocean_sao::{DepthSource, Sao, SaoParams, Viewport};
use serde::Deserialize;

/// `[obscurance]`.
#[derive(Clone, Debug, Deserialize, PartialEq)]
#[serde(default, deny_unknown_fields)]
pub struct ObscuranceSection {
    /// Whether the pass runs.
    pub enabled: bool,
    /// World-space radius of the sampled ball, metres (the paper's r).
    pub radius: f64,
    /// Samples per pixel (the paper: 9).
    pub samples: u32,
    /// How much of the obscurance reaches the image, in [0, 1].
    pub strength: f64,
}

impl Default for ObscuranceSection {
    fn default() -> Self {
        Self {
            enabled: true,
            radius: 2.0,
            samples: 9,
            strength: 0.85,
        }
    }
}

impl ObscuranceSection {
    pub fn check(&self) -> Result<(), (&'static str, String)> {
        let range = |key, v: f64, min: f64, max: f64| {
            if !v.is_finite() || v < min || v > max {
                return Err((key, format!("= {v} is outside [{min}, {max}]")));
            }
            Ok(())
        };
        range("obscurance.radius", self.radius, 1e-3, 1e3)?;
        range("obscurance.samples", f64::from(self.samples), 1.0, 64.0)?;
        range("obscurance.strength", self.strength, 0.0, 1.0)
    }
}

#[repr(C)]
#[derive(Clone, Copy, bytemuck::Pod, bytemuck::Zeroable)]
struct Params {
    strength: [f32; 4],
}

/// The SAO passes and the composite pipeline for one image size.
pub struct Obscurance {
    pass: SaoPass,
    sao: Sao,
    pipeline: wgpu::RenderPipeline,
    layout: wgpu::BindGroupLayout,
    uniform: wgpu::Buffer,
}

impl Obscurance {
    /// For `camera`'s projection (it must not change between frames) over a `width × height`
    /// depth buffer, compositing into `color_format` targets (sRGB-encoded values unless the
    /// format is an sRGB one).
    ///
    /// # Errors
    ///
    /// A message for parameters SAO refuses or a device error.
    pub fn new(
        ctx: &GpuContext,
        section: &ObscuranceSection,
        camera: &Camera,
        size: (u32, u32),
        color_format: wgpu::TextureFormat,
    ) -> Result<Self, String> {
        let params = SaoParams {
            radius: section.radius as f32,
            samples: section.samples,
            spiral_turns: ocean_sao::spiral::default_spiral_turns(section.samples) as f32,
            ..SaoParams::default()
        };
        let viewport = Viewport::new(size.0 as usize, size.1 as usize, 0)
            .map_err(|e| format!("obscurance: {e}"))?;
        let sao = Sao::from_camera(camera, DepthSource::Window, viewport, params)
            .map_err(|e| format!("obscurance: {e}"))?;
        let pass = SaoPass::new(ctx).map_err(|e| e.to_string())?;
        let device = ctx.device();
        let module = device.create_shader_module(wgpu::ShaderModuleDescriptor {
            label: Some("composite shader"),
            source: wgpu::ShaderSource::Wgsl(include_str!("composite.wgsl").into()),
        });
        let texture = |binding| wgpu::BindGroupLayoutEntry {
            binding,
            visibility: wgpu::ShaderStages::FRAGMENT,
            ty: wgpu::BindingType::Texture {
                sample_type: wgpu::TextureSampleType::Float { filterable: false },
                view_dimension: wgpu::TextureViewDimension::D2,
                multisampled: false,
            },
            count: None,
        };
        let layout = device.create_bind_group_layout(&wgpu::BindGroupLayoutDescriptor {
            label: Some("composite bind group layout"),
            entries: &[
                wgpu::BindGroupLayoutEntry {
                    binding: 0,
                    visibility: wgpu::ShaderStages::FRAGMENT,
                    ty: wgpu::BindingType::Buffer {
                        ty: wgpu::BufferBindingType::Uniform,
                        has_dynamic_offset: false,
                        min_binding_size: None,
                    },
                    count: None,
                },
                texture(1),
                texture(2),
            ],
        });
        let pipeline_layout = device.create_pipeline_layout(&wgpu::PipelineLayoutDescriptor {
            label: Some("composite pipeline layout"),
            bind_group_layouts: &[Some(&layout)],
            immediate_size: 0,
        });
        let pipeline = device.create_render_pipeline(&wgpu::RenderPipelineDescriptor {
            label: Some("composite"),
            layout: Some(&pipeline_layout),
            vertex: wgpu::VertexState {
                module: &module,
                entry_point: Some("composite_vs"),
                compilation_options: wgpu::PipelineCompilationOptions::default(),
                buffers: &[],
            },
            primitive: wgpu::PrimitiveState::default(),
            depth_stencil: None,
            multisample: wgpu::MultisampleState::default(),
            fragment: Some(wgpu::FragmentState {
                module: &module,
                entry_point: Some("composite_fs"),
                compilation_options: wgpu::PipelineCompilationOptions::default(),
                targets: &[Some(color_format.into())],
            }),
            multiview_mask: None,
            cache: None,
        });
        let uniform = device.create_buffer(&wgpu::BufferDescriptor {
            label: Some("composite params"),
            size: std::mem::size_of::<Params>() as u64,
            usage: wgpu::BufferUsages::UNIFORM | wgpu::BufferUsages::COPY_DST,
            mapped_at_creation: false,
        });
        let p = Params {
            strength: [
                section.strength as f32,
                if color_format.is_srgb() { 0.0 } else { 1.0 },
                0.0,
                0.0,
            ],
        };
        ctx.queue()
            .write_buffer(&uniform, 0, bytemuck::bytes_of(&p));
        Ok(Self {
            pass,
            sao,
            pipeline,
            layout,
            uniform,
        })
    }

    /// Records SAO over `depth` (`Depth32Float` with `TEXTURE_BINDING`) and the composite of
    /// `color` (read) into `out`.
    ///
    /// # Errors
    ///
    /// The SAO pass's errors (a depth texture of another size or usage).
    pub fn encode(
        &mut self,
        ctx: &GpuContext,
        encoder: &mut wgpu::CommandEncoder,
        depth: &wgpu::Texture,
        color: &wgpu::TextureView,
        out: &wgpu::TextureView,
    ) -> Result<(), GpuError> {
        self.pass.encode(ctx, encoder, &self.sao, depth, None)?;
        let Some(ao) = self.pass.ao_view() else {
            return Err(GpuError::NotConfigured {
                what: "SAO output",
                call: "SaoPass::encode",
            });
        };
        let device = ctx.device();
        let group = device.create_bind_group(&wgpu::BindGroupDescriptor {
            label: Some("composite bind group"),
            layout: &self.layout,
            entries: &[
                wgpu::BindGroupEntry {
                    binding: 0,
                    resource: self.uniform.as_entire_binding(),
                },
                wgpu::BindGroupEntry {
                    binding: 1,
                    resource: wgpu::BindingResource::TextureView(color),
                },
                wgpu::BindGroupEntry {
                    binding: 2,
                    resource: wgpu::BindingResource::TextureView(ao),
                },
            ],
        });
        let mut pass = encoder.begin_render_pass(&wgpu::RenderPassDescriptor {
            label: Some("composite"),
            color_attachments: &[Some(wgpu::RenderPassColorAttachment {
                view: out,
                depth_slice: None,
                resolve_target: None,
                ops: wgpu::Operations {
                    load: wgpu::LoadOp::Clear(wgpu::Color::BLACK),
                    store: wgpu::StoreOp::Store,
                },
            })],
            depth_stencil_attachment: None,
            timestamp_writes: None,
            occlusion_query_set: None,
            multiview_mask: None,
        });
        pass.set_pipeline(&self.pipeline);
        pass.set_bind_group(0, &group, &[]);
        pass.draw(0..3, 0..1);
        Ok(())
    }
}
