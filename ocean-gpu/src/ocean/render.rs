//! Drawing a frame: the render entry points of [`OceanRenderer`], the frame's uniform and phase
//! uploads, and the draw pipelines per depth configuration.

use super::*;

impl OceanRenderer {
    /// Records the sky (if [`OceanOptions::draw_sky`]) and the sea seen by `camera` at `time`
    /// into `encoder`, drawing into the top-left `size` = `(width, height)` pixels of `color`
    /// (and `depth`, required exactly when [`OceanOptions::depth_format`] is set), whose
    /// contents are kept (load) and whose formats must be the options'. Depth is tested and
    /// written in the camera's direction (forward: `Less`; reversed: `Greater`).
    ///
    /// The frame's uniform block and phases are written through the queue (see the type's
    /// documentation); the caller submits `encoder`.
    ///
    /// # Errors
    ///
    /// [`GpuError::NotConfigured`] before [`set_surface`](Self::set_surface) and
    /// [`set_lighting`](Self::set_lighting); [`GpuError::InvalidInput`] for a non-finite time,
    /// an empty or oversized viewport, a camera not above the sea (`eye.y ≤ 0`), or targets that
    /// do not fit; [`GpuError::Wgpu`] for a device error. Nothing is recorded on error.
    #[allow(clippy::too_many_arguments)]
    pub fn render(
        &self,
        ctx: &GpuContext,
        encoder: &mut wgpu::CommandEncoder,
        camera: &Camera,
        time: f64,
        color: &wgpu::TextureView,
        depth: Option<&wgpu::TextureView>,
        size: (u32, u32),
    ) -> Result<(), GpuError> {
        self.record(ctx, encoder, camera, time, color, depth, size, None, None)
    }

    /// [`render`](Self::render) with the render pass timed by `timer` (its beginning and end
    /// timestamps, resolved into the timer after the pass; read them with
    /// [`GpuTimer::read`] once the encoder is submitted).
    ///
    /// # Errors
    ///
    /// As [`render`](Self::render).
    #[allow(clippy::too_many_arguments)]
    pub fn render_timed(
        &self,
        ctx: &GpuContext,
        encoder: &mut wgpu::CommandEncoder,
        camera: &Camera,
        time: f64,
        color: &wgpu::TextureView,
        depth: Option<&wgpu::TextureView>,
        size: (u32, u32),
        timer: &GpuTimer,
    ) -> Result<(), GpuError> {
        self.record(
            ctx,
            encoder,
            camera,
            time,
            color,
            depth,
            size,
            None,
            Some(timer),
        )?;
        timer.resolve(encoder);
        Ok(())
    }

    /// Renders the sea and the sky seen by `camera` at `time` into a new `width × height`
    /// image and reads it back: tightly packed RGBA8 rows from the top, sRGB-encoded.
    ///
    /// Needs an 8-bit RGBA or BGRA [`OceanOptions::color_format`] (sRGB or not); creates its
    /// own colour target (cleared to black) and, if [`OceanOptions::depth_format`] is set, its
    /// own depth target (cleared to the camera's far end). A one-off: it allocates per call and
    /// waits for the GPU.
    ///
    /// # Errors
    ///
    /// As [`render`](Self::render), and [`GpuError::InvalidInput`] for another colour format
    /// or a size beyond the device's largest texture.
    pub fn render_image(
        &self,
        ctx: &GpuContext,
        camera: &Camera,
        time: f64,
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
                    format!("render_image reads back 8-bit RGBA or BGRA targets, not {other:?}"),
                ));
            }
        };
        self.check_viewport(ctx, width, height)?;
        // Everything that can fail on the inputs fails here, before anything is allocated.
        self.frame(camera, time, width, height, 0)?;
        self.lighting_set()?;
        let device = ctx.device();
        let extent = wgpu::Extent3d {
            width,
            height,
            depth_or_array_layers: 1,
        };
        let (color, depth) = crate::scoped(device, || {
            let color = device.create_texture(&wgpu::TextureDescriptor {
                label: Some("ocean image"),
                size: extent,
                mip_level_count: 1,
                sample_count: 1,
                dimension: wgpu::TextureDimension::D2,
                format: self.options.color_format,
                usage: wgpu::TextureUsages::RENDER_ATTACHMENT | wgpu::TextureUsages::COPY_SRC,
                view_formats: &[],
            });
            let depth = self.options.depth_format.map(|format| {
                device.create_texture(&wgpu::TextureDescriptor {
                    label: Some("ocean image depth"),
                    size: extent,
                    mip_level_count: 1,
                    sample_count: 1,
                    dimension: wgpu::TextureDimension::D2,
                    format,
                    usage: wgpu::TextureUsages::RENDER_ATTACHMENT,
                    view_formats: &[],
                })
            });
            Ok((color, depth))
        })?;
        let color_view = color.create_view(&wgpu::TextureViewDescriptor::default());
        let depth_view = depth
            .as_ref()
            .map(|d| d.create_view(&wgpu::TextureViewDescriptor::default()));
        let mut encoder = device.create_command_encoder(&wgpu::CommandEncoderDescriptor {
            label: Some("ocean image"),
        });
        let range = camera.depth().range();
        let clear_depth = range.window_depth(camera.depth().clear_depth()) as f32;
        self.record(
            ctx,
            &mut encoder,
            camera,
            time,
            &color_view,
            depth_view.as_ref(),
            (width, height),
            Some(clear_depth),
            None,
        )?;
        crate::scoped(device, || {
            ctx.queue().submit([encoder.finish()]);
            Ok(())
        })?;
        let mut data = read_texture(ctx, &color, 0)?.data;
        if bgra {
            for px in data.chunks_exact_mut(4) {
                px.swap(0, 2);
            }
        }
        Ok(data)
    }

    pub(super) fn lighting_set(&self) -> Result<(), GpuError> {
        match self.lighting {
            Some(_) => Ok(()),
            None => Err(GpuError::NotConfigured {
                what: "ocean lighting",
                call: "OceanRenderer::set_lighting",
            }),
        }
    }

    pub(super) fn check_viewport(
        &self,
        ctx: &GpuContext,
        width: u32,
        height: u32,
    ) -> Result<(), GpuError> {
        let max = ctx.device().limits().max_texture_dimension_2d;
        if width == 0 || height == 0 || width > max || height > max {
            return Err(invalid(
                "viewport",
                format!("{width} x {height}: each side must be in [1, {max}]"),
            ));
        }
        Ok(())
    }

    /// The uniform block and the wave texture's phase row for one frame ([`frame_uniform`] with
    /// the renderer's options, surface, lighting and local waves). Also returns `o`, the eye's
    /// horizontal position.
    pub(super) fn frame(
        &self,
        camera: &Camera,
        time: f64,
        width: u32,
        height: u32,
        probe_items: u32,
    ) -> Result<(FrameUniform, Vec<[f32; 4]>, DVec2), GpuError> {
        let surface = self.surface.as_ref().ok_or(GpuError::NotConfigured {
            what: "ocean surface",
            call: "OceanRenderer::set_surface",
        })?;
        let mut u = frame_uniform(
            &self.options,
            surface,
            self.lighting.as_ref(),
            camera,
            time,
            (width, height),
            None,
        )?;
        let eye = camera.eye();
        let o = DVec2::new(eye.x, eye.z);
        u.probe[0] = probe_items;
        (u.local, u.local_counts) = self.local.uniform(o);
        Ok((u, surface.phases(o, time), o))
    }

    /// Validates the targets against the options and the viewport.
    pub(super) fn check_targets(
        &self,
        color: &wgpu::TextureView,
        depth: Option<&wgpu::TextureView>,
        size: (u32, u32),
    ) -> Result<(), GpuError> {
        let fits = |what, t, format| crate::pipeline::check_render_target(what, t, format, size);
        fits("colour target", color.texture(), self.options.color_format)?;
        match (self.options.depth_format, depth) {
            (Some(format), Some(d)) => fits("depth target", d.texture(), format),
            (None, None) => Ok(()),
            (Some(_), None) => Err(GpuError::InvalidResource {
                what: "depth target",
                reason: "the renderer was created with a depth format: pass a depth view"
                    .to_owned(),
            }),
            (None, Some(_)) => Err(GpuError::InvalidResource {
                what: "depth target",
                reason: "the renderer was created without a depth format".to_owned(),
            }),
        }
    }

    /// [`render`](Self::render), clearing the targets first when `clear_depth` is given (to
    /// black and to that depth).
    #[allow(clippy::too_many_arguments)]
    pub(super) fn record(
        &self,
        ctx: &GpuContext,
        encoder: &mut wgpu::CommandEncoder,
        camera: &Camera,
        time: f64,
        color: &wgpu::TextureView,
        depth: Option<&wgpu::TextureView>,
        size: (u32, u32),
        clear_depth: Option<f32>,
        timer: Option<&GpuTimer>,
    ) -> Result<(), GpuError> {
        self.check_viewport(ctx, size.0, size.1)?;
        self.check_targets(color, depth, size)?;
        let (u, phases, o) = self.frame(camera, time, size.0, size.1, 0)?;
        let local_phases = self.local.phases(o, time);
        self.lighting_set()?;
        let device = ctx.device();
        let key = self
            .options
            .depth_format
            .map(|_| camera.depth().direction());
        let mut pipelines = lock(&self.pipelines);
        if !pipelines.iter().any(|p| p.key == key) {
            let p = crate::scoped(device, || Ok(self.draw_pipelines(device, key)))?;
            pipelines.push(p);
        }
        let Some(p) = pipelines.iter().find(|p| p.key == key) else {
            return Err(GpuError::Wgpu("ocean pipelines missing".to_owned()));
        };
        let (indices, index_count) = self.grid_index_buffer(ctx, &u)?;
        crate::scoped(device, || {
            self.write_frame(ctx, &u, &phases, &local_phases);
            let load_color = match clear_depth {
                Some(_) => wgpu::LoadOp::Clear(wgpu::Color::BLACK),
                None => wgpu::LoadOp::Load,
            };
            let mut pass = encoder.begin_render_pass(&wgpu::RenderPassDescriptor {
                label: Some("ocean"),
                color_attachments: &[Some(wgpu::RenderPassColorAttachment {
                    view: color,
                    depth_slice: None,
                    resolve_target: None,
                    ops: wgpu::Operations {
                        load: load_color,
                        store: wgpu::StoreOp::Store,
                    },
                })],
                depth_stencil_attachment: depth.map(|view| {
                    wgpu::RenderPassDepthStencilAttachment {
                        view,
                        depth_ops: Some(wgpu::Operations {
                            load: match clear_depth {
                                Some(d) => wgpu::LoadOp::Clear(d),
                                None => wgpu::LoadOp::Load,
                            },
                            store: wgpu::StoreOp::Store,
                        }),
                        stencil_ops: None,
                    }
                }),
                timestamp_writes: timer.map(GpuTimer::render_pass_writes),
                occlusion_query_set: None,
                multiview_mask: None,
            });
            pass.set_viewport(0.0, 0.0, size.0 as f32, size.1 as f32, 0.0, 1.0);
            pass.set_scissor_rect(0, 0, size.0, size.1);
            pass.set_bind_group(0, &self.bind_group, &[]);
            if self.options.draw_sky {
                pass.set_pipeline(&p.sky);
                pass.draw(0..3, 0..1);
            }
            pass.set_pipeline(&p.ocean);
            pass.set_index_buffer(indices.slice(..), wgpu::IndexFormat::Uint32);
            pass.draw_indexed(0..index_count, 0, 0..1);
            Ok(())
        })
    }

    /// The index buffer of the projected grid of frame `u` (built when the grid's size changes)
    /// and its index count.
    pub(super) fn grid_index_buffer(
        &self,
        ctx: &GpuContext,
        u: &FrameUniform,
    ) -> Result<(wgpu::Buffer, u32), GpuError> {
        let (nx, ny) = (u.counts[0], u.counts[1]);
        let mut indices = lock(&self.indices);
        if indices.as_ref().is_none_or(|i| i.size != (nx, ny)) {
            *indices = Some(grid_indices(ctx, nx, ny)?);
        }
        match indices.as_ref() {
            Some(grid) => Ok((grid.buffer.clone(), grid.count)),
            None => Err(GpuError::Wgpu("ocean grid indices missing".to_owned())),
        }
    }

    /// Writes a frame's uniform block and phases (they take effect at the next submit).
    pub(super) fn write_frame(
        &self,
        ctx: &GpuContext,
        u: &FrameUniform,
        phases: &[[f32; 4]],
        local_phases: &[[f32; 4]],
    ) {
        ctx.queue()
            .write_buffer(&self.uniform, 0, bytemuck::bytes_of(u));
        write_waves(ctx, &self.wave_texture, phases, phases.len() as u32, 1);
        self.local.write_phases(ctx, local_phases);
    }

    /// The sky and sea pipelines for a depth direction (`None`: no depth buffer).
    pub(super) fn draw_pipelines(
        &self,
        device: &wgpu::Device,
        key: Option<DepthDirection>,
    ) -> DrawPipelines {
        let depth = |write: bool| {
            let format = self.options.depth_format?;
            let reversed = key == Some(DepthDirection::Reversed);
            // The sky lies on the far plane: it passes where nothing nearer was drawn and
            // writes no depth; the sea tests and writes.
            let compare = match (write, reversed) {
                (true, false) => wgpu::CompareFunction::Less,
                (true, true) => wgpu::CompareFunction::Greater,
                (false, false) => wgpu::CompareFunction::LessEqual,
                (false, true) => wgpu::CompareFunction::GreaterEqual,
            };
            Some(wgpu::DepthStencilState {
                format,
                depth_write_enabled: Some(write),
                depth_compare: Some(compare),
                stencil: wgpu::StencilState::default(),
                bias: wgpu::DepthBiasState::default(),
            })
        };
        let pipeline = |label, vs, fs, depth_stencil| {
            device.create_render_pipeline(&wgpu::RenderPipelineDescriptor {
                label: Some(label),
                layout: Some(&self.pipeline_layout),
                vertex: wgpu::VertexState {
                    module: &self.module,
                    entry_point: Some(vs),
                    compilation_options: wgpu::PipelineCompilationOptions::default(),
                    buffers: &[],
                },
                primitive: wgpu::PrimitiveState {
                    topology: wgpu::PrimitiveTopology::TriangleList,
                    // Waves can turn cells over: no culling.
                    cull_mode: None,
                    ..Default::default()
                },
                depth_stencil,
                multisample: wgpu::MultisampleState::default(),
                fragment: Some(wgpu::FragmentState {
                    module: &self.module,
                    entry_point: Some(fs),
                    compilation_options: wgpu::PipelineCompilationOptions::default(),
                    targets: &[Some(self.options.color_format.into())],
                }),
                multiview_mask: None,
                cache: None,
            })
        };
        DrawPipelines {
            key,
            sky: pipeline("ocean sky pipeline", "sky_vs", "sky_fs", depth(false)),
            ocean: pipeline("ocean sea pipeline", "ocean_vs", "ocean_fs", depth(true)),
        }
    }
}
