//! The sea drawn into split light targets ([`crate::LightTargets`]) and the frame composed from
//! them with an ambient obscurance: the path of a renderer that draws other objects beside the
//! sea and runs an obscurance pass over the whole depth buffer (`ocean render` does).
//!
//! `ocean_vs`/`ocean_layers_fs` draw the projected grid as [`OceanRenderer::render`] does, with
//! Algorithm 5.1's terms split: the Sun's reflection (Eq. 15) is direct light, the sky's
//! reflection (Eq. 21) and the refracted light (Eq. 28) ambient. `sky_vs`/`compose_fs` then
//! write `display(direct + A · ambient)` where something drew and the sky elsewhere.

use ocean_core::{Camera, DepthDirection};

use super::{OceanRenderer, common_layout_entries, invalid, lock};
use crate::light_targets::{
    LightTargets, MSAA_SAMPLES, RADIANCE_FORMAT, check_input, check_multisampling, multisample,
    radiance_targets,
};
use crate::{GpuContext, GpuError};

/// Bindings of `compose_fs`'s inputs (ocean.wgsl), and of `compose_ms_fs`'s multisampled
/// direct and ambient radiances.
pub(super) const DIRECT_BINDING: u32 = 9;
pub(super) const AMBIENT_BINDING: u32 = 10;
pub(super) const OBSCURANCE_BINDING: u32 = 11;
pub(super) const DIRECT_MS_BINDING: u32 = 12;
pub(super) const AMBIENT_MS_BINDING: u32 = 13;

/// The composition's inputs: the split light of a frame and its obscurance.
///
/// The radiances have one sample per pixel, or both [`crate::MSAA_SAMPLES`]: an antialiased
/// frame, which [`OceanRenderer::compose`] resolves (each sample tone-mapped, then averaged).
#[derive(Clone, Copy, Debug)]
pub struct ComposeInputs<'a> {
    /// Direct radiance ([`RADIANCE_FORMAT`], `TEXTURE_BINDING`).
    pub direct: &'a wgpu::TextureView,
    /// Ambient radiance ([`RADIANCE_FORMAT`], `TEXTURE_BINDING`); alpha 0 where nothing drew.
    pub ambient: &'a wgpu::TextureView,
    /// The obscurance A per pixel (`R32Float`, `TEXTURE_BINDING`, one sample per pixel,
    /// 1 = unoccluded; values are clamped to `[0, 1]`), such as [`crate::SaoPass::ao_view`].
    pub obscurance: &'a wgpu::TextureView,
}

impl ComposeInputs<'_> {
    /// Samples per pixel of the radiances: 1 or [`MSAA_SAMPLES`], the same for both, and one
    /// for the obscurance.
    fn sample_count(&self) -> Result<u32, GpuError> {
        let samples = self.ambient.texture().sample_count();
        let direct = self.direct.texture().sample_count();
        let obscurance = self.obscurance.texture().sample_count();
        if (samples != 1 && samples != MSAA_SAMPLES) || direct != samples {
            return Err(GpuError::InvalidResource {
                what: "direct and ambient light",
                reason: format!(
                    "{direct} and {samples} samples per pixel: both 1 or both {MSAA_SAMPLES}"
                ),
            });
        }
        if obscurance != 1 {
            return Err(GpuError::InvalidResource {
                what: "obscurance",
                reason: format!("{obscurance} samples per pixel, 1 is read"),
            });
        }
        Ok(samples)
    }
}

/// The compose pipeline and its bind group layout (the renderer's bindings and 9–11).
#[derive(Debug)]
pub(crate) struct ComposePipeline {
    pub(super) pipeline: wgpu::RenderPipeline,
    pub(super) layout: wgpu::BindGroupLayout,
}

impl OceanRenderer {
    /// Records the sea seen by `camera` at `time` into split light targets: the projected grid
    /// of [`render`](Self::render) with its light split into the Sun's reflection (direct) and
    /// the sky's reflection plus the refracted light (ambient), linear radiance, alpha 1, depth
    /// tested and written in the camera's direction. The sky is not drawn:
    /// [`compose`](Self::compose) fills the pixels nothing drew.
    ///
    /// Needs a renderer with a [`super::OceanOptions::depth_format`]; the targets are loaded
    /// (clear them first, see [`LightTargets`]). The frame's uniform block and phases are
    /// written through the queue, as for [`render`](Self::render).
    ///
    /// # Errors
    ///
    /// As [`render`](Self::render), and [`GpuError::InvalidInput`] for a renderer without a
    /// depth format.
    pub fn render_layers(
        &self,
        ctx: &GpuContext,
        encoder: &mut wgpu::CommandEncoder,
        camera: &Camera,
        time: f64,
        targets: &LightTargets<'_>,
        size: (u32, u32),
    ) -> Result<(), GpuError> {
        let Some(depth_format) = self.options.depth_format else {
            return Err(invalid(
                "depth_format",
                "render_layers draws with depth: create the renderer with a depth format",
            ));
        };
        self.check_viewport(ctx, size.0, size.1)?;
        let samples = targets.check(depth_format, size)?;
        check_multisampling(ctx, samples)?;
        let (u, phases, o) = self.frame(camera, time, size.0, size.1, 0)?;
        let local_phases = self.local.phases(o, time);
        self.lighting_set()?;
        let device = ctx.device();
        let direction = camera.depth().direction();
        let pipeline = self.layer_pipeline(device, depth_format, (direction, samples))?;
        let (indices, index_count) = self.grid_index_buffer(ctx, &u)?;
        crate::scoped(device, || {
            self.write_frame(ctx, &u, &phases, &local_phases);
            let mut pass = encoder.begin_render_pass(&wgpu::RenderPassDescriptor {
                label: Some("ocean layers"),
                color_attachments: &targets.color_attachments(),
                depth_stencil_attachment: Some(targets.depth_attachment()),
                timestamp_writes: None,
                occlusion_query_set: None,
                multiview_mask: None,
            });
            pass.set_viewport(0.0, 0.0, size.0 as f32, size.1 as f32, 0.0, 1.0);
            pass.set_scissor_rect(0, 0, size.0, size.1);
            pass.set_bind_group(0, &self.bind_group, &[]);
            pass.set_pipeline(&pipeline);
            pass.set_index_buffer(indices.slice(..), wgpu::IndexFormat::Uint32);
            pass.draw_indexed(0..index_count, 0, 0..1);
            Ok(())
        })
    }

    /// Records the composition of a frame into `out` (the options' colour format, cleared
    /// and written whole): `display(direct + A · ambient)` (tone-mapped, encoded as
    /// [`render`](Self::render) encodes) where the ambient alpha is non-zero, and the sky
    /// (as [`render`](Self::render) draws it) elsewhere. With multisampled radiances each
    /// sample is composed so and tone-mapped, and a pixel is the mean of its samples' display
    /// values (the image a supersampled render shows, which a resolve of the radiances before
    /// the tone map is not at edges against bright light).
    ///
    /// It reads the frame's uniform block (camera and lighting) that the last
    /// [`render_layers`](Self::render_layers) (or [`render`](Self::render)) wrote: record
    /// both into the same submission.
    ///
    /// # Errors
    ///
    /// [`GpuError::InvalidInput`] for an empty or oversized viewport;
    /// [`GpuError::InvalidResource`] for inputs of other formats, without `TEXTURE_BINDING`,
    /// or smaller than the viewport, or an `out` that does not fit; [`GpuError::Wgpu`] for a
    /// device error.
    pub fn compose(
        &self,
        ctx: &GpuContext,
        encoder: &mut wgpu::CommandEncoder,
        inputs: &ComposeInputs<'_>,
        out: &wgpu::TextureView,
        size: (u32, u32),
    ) -> Result<(), GpuError> {
        self.check_viewport(ctx, size.0, size.1)?;
        let samples = inputs.sample_count()?;
        check_multisampling(ctx, samples)?;
        check_input("direct light", inputs.direct, RADIANCE_FORMAT, size)?;
        check_input("ambient light", inputs.ambient, RADIANCE_FORMAT, size)?;
        check_input(
            "obscurance",
            inputs.obscurance,
            wgpu::TextureFormat::R32Float,
            size,
        )?;
        crate::pipeline::check_render_target(
            "composed colour target",
            out.texture(),
            self.options.color_format,
            size,
        )?;
        let device = ctx.device();
        let (pipeline, layout) = {
            let mut compose = lock(&self.compose);
            let built = match compose.iter().find(|(n, _)| *n == samples) {
                Some((_, c)) => c,
                None => {
                    let c = crate::scoped(device, || Ok(self.compose_pipeline(device, samples)))?;
                    compose.push((samples, c));
                    &compose[compose.len() - 1].1
                }
            };
            (built.pipeline.clone(), built.layout.clone())
        };
        crate::scoped(device, || {
            let group = self.compose_bind_group(device, &layout, inputs, samples);
            let mut pass = encoder.begin_render_pass(&wgpu::RenderPassDescriptor {
                label: Some("ocean compose"),
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
            pass.set_viewport(0.0, 0.0, size.0 as f32, size.1 as f32, 0.0, 1.0);
            pass.set_scissor_rect(0, 0, size.0, size.1);
            pass.set_pipeline(&pipeline);
            pass.set_bind_group(0, &group, &[]);
            pass.draw(0..3, 0..1);
            Ok(())
        })
    }

    /// The bind group of `compose_fs` (or `compose_ms_fs` for multisampled radiances): the
    /// renderer's resources and `inputs`.
    pub(super) fn compose_bind_group(
        &self,
        device: &wgpu::Device,
        layout: &wgpu::BindGroupLayout,
        inputs: &ComposeInputs<'_>,
        samples: u32,
    ) -> wgpu::BindGroup {
        let (direct, ambient) = radiance_bindings(samples);
        let entry = |binding, resource| wgpu::BindGroupEntry { binding, resource };
        let tex = wgpu::BindingResource::TextureView;
        device.create_bind_group(&wgpu::BindGroupDescriptor {
            label: Some("ocean compose bind group"),
            layout,
            entries: &[
                entry(0, self.uniform.as_entire_binding()),
                entry(1, tex(&self.wave_view)),
                entry(2, tex(&self.sky_view)),
                entry(3, wgpu::BindingResource::Sampler(&self.sampler)),
                entry(super::FRESNEL_BINDING, tex(&self.fresnel_view)),
                entry(super::LOCAL_FIELDS_BINDING, tex(&self.local.fields_view)),
                entry(super::LOCAL_TRAINS_BINDING, tex(&self.local.trains_view)),
                entry(direct, tex(inputs.direct)),
                entry(ambient, tex(inputs.ambient)),
                entry(OBSCURANCE_BINDING, tex(inputs.obscurance)),
            ],
        })
    }

    /// The split-light sea pipeline for a depth direction and a sample count, built on first
    /// use.
    fn layer_pipeline(
        &self,
        device: &wgpu::Device,
        depth_format: wgpu::TextureFormat,
        key: (DepthDirection, u32),
    ) -> Result<wgpu::RenderPipeline, GpuError> {
        let (direction, samples) = key;
        let mut pipelines = lock(&self.layer_pipelines);
        if let Some((_, p)) = pipelines.iter().find(|(k, _)| *k == key) {
            return Ok(p.clone());
        }
        let pipeline = crate::scoped(device, || {
            Ok(
                device.create_render_pipeline(&wgpu::RenderPipelineDescriptor {
                    label: Some("ocean layers pipeline"),
                    layout: Some(&self.pipeline_layout),
                    vertex: wgpu::VertexState {
                        module: &self.module,
                        entry_point: Some("ocean_vs"),
                        compilation_options: wgpu::PipelineCompilationOptions::default(),
                        buffers: &[],
                    },
                    primitive: wgpu::PrimitiveState {
                        topology: wgpu::PrimitiveTopology::TriangleList,
                        // Waves can turn cells over: no culling.
                        cull_mode: None,
                        ..Default::default()
                    },
                    depth_stencil: Some(depth_state(depth_format, direction)),
                    multisample: multisample(samples),
                    fragment: Some(wgpu::FragmentState {
                        module: &self.module,
                        entry_point: Some("ocean_layers_fs"),
                        compilation_options: wgpu::PipelineCompilationOptions::default(),
                        targets: &radiance_targets(),
                    }),
                    multiview_mask: None,
                    cache: None,
                }),
            )
        })?;
        pipelines.push((key, pipeline.clone()));
        Ok(pipeline)
    }

    /// The compose pipeline for radiances of `samples` samples per pixel (`sky_vs`, then
    /// `compose_fs` with bindings 9–11 added, or `compose_ms_fs` with 11–13; no depth).
    pub(super) fn compose_pipeline(&self, device: &wgpu::Device, samples: u32) -> ComposePipeline {
        let stages = wgpu::ShaderStages::VERTEX | wgpu::ShaderStages::FRAGMENT;
        let input = |binding, multisampled| wgpu::BindGroupLayoutEntry {
            binding,
            visibility: stages,
            ty: wgpu::BindingType::Texture {
                sample_type: wgpu::TextureSampleType::Float { filterable: false },
                view_dimension: wgpu::TextureViewDimension::D2,
                multisampled,
            },
            count: None,
        };
        let (direct, ambient) = radiance_bindings(samples);
        let mut entries = common_layout_entries(stages).to_vec();
        entries.extend([
            input(direct, samples > 1),
            input(ambient, samples > 1),
            input(OBSCURANCE_BINDING, false),
        ]);
        let layout = device.create_bind_group_layout(&wgpu::BindGroupLayoutDescriptor {
            label: Some("ocean compose bind group layout"),
            entries: &entries,
        });
        let pipeline_layout = device.create_pipeline_layout(&wgpu::PipelineLayoutDescriptor {
            label: Some("ocean compose pipeline layout"),
            bind_group_layouts: &[Some(&layout)],
            immediate_size: 0,
        });
        let pipeline = device.create_render_pipeline(&wgpu::RenderPipelineDescriptor {
            label: Some("ocean compose pipeline"),
            layout: Some(&pipeline_layout),
            vertex: wgpu::VertexState {
                module: &self.module,
                entry_point: Some("sky_vs"),
                compilation_options: wgpu::PipelineCompilationOptions::default(),
                buffers: &[],
            },
            primitive: wgpu::PrimitiveState::default(),
            depth_stencil: None,
            multisample: wgpu::MultisampleState::default(),
            fragment: Some(wgpu::FragmentState {
                module: &self.module,
                entry_point: Some(if samples > 1 {
                    "compose_ms_fs"
                } else {
                    "compose_fs"
                }),
                compilation_options: wgpu::PipelineCompilationOptions::default(),
                targets: &[Some(self.options.color_format.into())],
            }),
            multiview_mask: None,
            cache: None,
        });
        ComposePipeline { pipeline, layout }
    }
}

/// The bindings of the direct and ambient radiances for `samples` samples per pixel.
fn radiance_bindings(samples: u32) -> (u32, u32) {
    if samples > 1 {
        (DIRECT_MS_BINDING, AMBIENT_MS_BINDING)
    } else {
        (DIRECT_BINDING, AMBIENT_BINDING)
    }
}

/// Depth tested (forward: `Less`, reversed: `Greater`) and written.
pub(super) fn depth_state(
    format: wgpu::TextureFormat,
    direction: DepthDirection,
) -> wgpu::DepthStencilState {
    wgpu::DepthStencilState {
        format,
        depth_write_enabled: Some(true),
        depth_compare: Some(match direction {
            DepthDirection::Forward => wgpu::CompareFunction::Less,
            DepthDirection::Reversed => wgpu::CompareFunction::Greater,
        }),
        stencil: wgpu::StencilState::default(),
        bias: wgpu::DepthBiasState::default(),
    }
}
