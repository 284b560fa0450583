//! The depth of a multisampled (antialiased) frame for passes that read one depth per pixel.
//!
//! An antialiased frame rasterises its edges at [`MSAA_SAMPLES`] coverage samples per pixel
//! ([`crate::LightTargets`]); an ambient obscurance ([`crate::SaoPass`]) reconstructs one
//! position per pixel. [`DepthResolve`] writes each pixel's nearest sample
//! (`depth_resolve.wgsl`) into a single-sampled depth texture: along a silhouette every pixel
//! then takes the surface in front, where a fixed sample would alternate between the two
//! surfaces from pixel to pixel.

use ocean_core::DepthDirection;

use crate::light_targets::MSAA_SAMPLES;
use crate::pipeline::check_render_target;
use crate::{GpuContext, GpuError};

/// The depth resolve pass: two pipelines (forward and reversed depth) for one depth format.
#[derive(Debug)]
pub struct DepthResolve {
    format: wgpu::TextureFormat,
    layout: wgpu::BindGroupLayout,
    forward: wgpu::RenderPipeline,
    reversed: wgpu::RenderPipeline,
}

impl DepthResolve {
    /// The pass for multisampled and resolved depth textures of `format` (a format with a
    /// depth aspect and no stencil, such as `Depth32Float`).
    ///
    /// # Errors
    ///
    /// [`GpuError::InvalidInput`] for a format without depth or with stencil;
    /// [`GpuError::UnsuitableAdapter`] where multisampled targets do not work
    /// ([`GpuContext::supports_multisampled_light`]); [`GpuError::Wgpu`] for a device error.
    pub fn new(ctx: &GpuContext, format: wgpu::TextureFormat) -> Result<Self, GpuError> {
        if !format.has_depth_aspect() || format.has_stencil_aspect() {
            return Err(GpuError::InvalidInput {
                what: "format",
                reason: format!("{format:?}: the resolve reads and writes depth-only formats"),
            });
        }
        crate::light_targets::check_multisampling(ctx, MSAA_SAMPLES)?;
        let device = ctx.device();
        crate::scoped(device, || {
            let module = device.create_shader_module(wgpu::ShaderModuleDescriptor {
                label: Some("ocean depth resolve shader"),
                source: wgpu::ShaderSource::Wgsl(crate::shaders::DEPTH_RESOLVE_WGSL.into()),
            });
            let layout = device.create_bind_group_layout(&wgpu::BindGroupLayoutDescriptor {
                label: Some("ocean depth resolve bind group layout"),
                entries: &[wgpu::BindGroupLayoutEntry {
                    binding: 0,
                    visibility: wgpu::ShaderStages::FRAGMENT,
                    ty: wgpu::BindingType::Texture {
                        sample_type: wgpu::TextureSampleType::Float { filterable: false },
                        view_dimension: wgpu::TextureViewDimension::D2,
                        multisampled: true,
                    },
                    count: None,
                }],
            });
            let pipeline_layout = device.create_pipeline_layout(&wgpu::PipelineLayoutDescriptor {
                label: Some("ocean depth resolve pipeline layout"),
                bind_group_layouts: &[Some(&layout)],
                immediate_size: 0,
            });
            let pipeline = |entry_point| {
                device.create_render_pipeline(&wgpu::RenderPipelineDescriptor {
                    label: Some("ocean depth resolve"),
                    layout: Some(&pipeline_layout),
                    vertex: wgpu::VertexState {
                        module: &module,
                        entry_point: Some("resolve_vs"),
                        compilation_options: wgpu::PipelineCompilationOptions::default(),
                        buffers: &[],
                    },
                    primitive: wgpu::PrimitiveState::default(),
                    depth_stencil: Some(wgpu::DepthStencilState {
                        format,
                        depth_write_enabled: Some(true),
                        depth_compare: Some(wgpu::CompareFunction::Always),
                        stencil: wgpu::StencilState::default(),
                        bias: wgpu::DepthBiasState::default(),
                    }),
                    multisample: wgpu::MultisampleState::default(),
                    fragment: Some(wgpu::FragmentState {
                        module: &module,
                        entry_point: Some(entry_point),
                        compilation_options: wgpu::PipelineCompilationOptions::default(),
                        targets: &[],
                    }),
                    multiview_mask: None,
                    cache: None,
                })
            };
            Ok(Self {
                format,
                forward: pipeline("nearest_forward_fs"),
                reversed: pipeline("nearest_reversed_fs"),
                layout,
            })
        })
    }

    /// Records the resolve of `source` (the pass's format, [`MSAA_SAMPLES`] samples,
    /// `TEXTURE_BINDING`) into `target` (the same format and size, one sample,
    /// `RENDER_ATTACHMENT`), whose every pixel is written: the nearest of the pixel's samples
    /// in `direction` (the minimum for forward depth, the maximum for reversed).
    ///
    /// # Errors
    ///
    /// [`GpuError::InvalidResource`] for textures of another format, sample count or size, or
    /// without those usages; [`GpuError::Wgpu`] for a device error. Nothing is recorded on
    /// error.
    pub fn encode(
        &self,
        ctx: &GpuContext,
        encoder: &mut wgpu::CommandEncoder,
        source: &wgpu::TextureView,
        target: &wgpu::TextureView,
        direction: DepthDirection,
    ) -> Result<(), GpuError> {
        let s = source.texture();
        let size = (s.width(), s.height());
        let bad = |reason: String| GpuError::InvalidResource {
            what: "multisampled depth",
            reason,
        };
        if s.format() != self.format || s.sample_count() != MSAA_SAMPLES {
            return Err(bad(format!(
                "{:?} with {} samples; the resolve reads {:?} with {MSAA_SAMPLES}",
                s.format(),
                s.sample_count(),
                self.format
            )));
        }
        if !s.usage().contains(wgpu::TextureUsages::TEXTURE_BINDING) {
            return Err(bad("it lacks TEXTURE_BINDING usage".to_owned()));
        }
        check_render_target("resolved depth", target.texture(), self.format, size)?;
        let t = target.texture();
        if (t.width(), t.height()) != size {
            return Err(GpuError::InvalidResource {
                what: "resolved depth",
                reason: format!(
                    "{} x {}, the multisampled depth is {} x {}",
                    t.width(),
                    t.height(),
                    size.0,
                    size.1
                ),
            });
        }
        let device = ctx.device();
        crate::scoped(device, || {
            let group = device.create_bind_group(&wgpu::BindGroupDescriptor {
                label: Some("ocean depth resolve bind group"),
                layout: &self.layout,
                entries: &[wgpu::BindGroupEntry {
                    binding: 0,
                    resource: wgpu::BindingResource::TextureView(source),
                }],
            });
            let mut pass = encoder.begin_render_pass(&wgpu::RenderPassDescriptor {
                label: Some("ocean depth resolve"),
                color_attachments: &[],
                depth_stencil_attachment: Some(wgpu::RenderPassDepthStencilAttachment {
                    view: target,
                    depth_ops: Some(wgpu::Operations {
                        load: wgpu::LoadOp::Clear(0.0),
                        store: wgpu::StoreOp::Store,
                    }),
                    stencil_ops: None,
                }),
                timestamp_writes: None,
                occlusion_query_set: None,
                multiview_mask: None,
            });
            pass.set_pipeline(match direction {
                DepthDirection::Forward => &self.forward,
                DepthDirection::Reversed => &self.reversed,
            });
            pass.set_bind_group(0, &group, &[]);
            pass.draw(0..3, 0..1);
            Ok(())
        })
    }
}
