//! The relief renderer's compute passes: the probe (one traced ray and shadow test per
//! `ReliefRay`, read back for the parity tests) and the copy of a draw's depth to memory.

use super::*;

/// One ray for [`ReliefRenderer::probe`]: the arguments of [`ocean_relief::Ray::from_view`]
/// and [`Method::trace`] for the viewing ray, of [`ocean_relief::shadow::in_shadow`] for a
/// shadow test, and the footprint the level of detail is chosen from.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct ReliefRay {
    /// Texture coordinates where the ray enters the relief.
    pub start: Vec2,
    /// Tangent-space view vector (`z < 0`), any length.
    pub view: Vec3,
    /// Relief depth, texture widths (`≥ 0`).
    pub depth_scale: f32,
    /// The point `(u, v, depth)` the shadow test is made for.
    pub point: Vec3,
    /// Tangent-space direction towards the light.
    pub light: Vec3,
    /// The shadow test's bias, in `[0, 1]`.
    pub bias: f32,
    /// The texture coordinates' screen derivatives `[du, dv]` (texture widths per pixel, as
    /// `dpdx(uv)` and `dpdy(uv)` in the draw pass): the probe reads the level
    /// [`ocean_relief::lod::mip_level`] picks for them, as a fragment does. Zero: level 0.
    pub footprint: [Vec2; 2],
}

/// What [`ReliefRenderer::probe`] reads back for one [`ReliefRay`].
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ReliefProbe {
    /// Where the viewing ray stopped and the fetches it spent (as [`Method::trace`] returns).
    pub hit: Hit,
    /// Whether [`ReliefRay::point`] is in shadow (as [`ocean_relief::shadow::in_shadow`]).
    pub shadow: bool,
    /// Where the light ray towards the point stopped: its depth and fetches (0 and 0 when the
    /// light is at or below the polygon's plane: no ray is traced).
    pub light_hit: (f32, u32),
    /// The mip level both rays read.
    pub level: u32,
}

#[derive(Debug)]
pub(super) struct ProbePipelines {
    trace: wgpu::ComputePipeline,
    trace_layout: wgpu::BindGroupLayout,
    copy_depth: wgpu::ComputePipeline,
    copy_layout: wgpu::BindGroupLayout,
}

impl ReliefRenderer {
    fn probe_pipelines<'a>(
        &self,
        device: &wgpu::Device,
        probes: &'a mut [Option<ProbePipelines>; 2],
        layout: ReliefLayout,
    ) -> Result<&'a ProbePipelines, GpuError> {
        let probes = &mut probes[layout.index()];
        if probes.is_none() {
            let entry = shader_source(layout.probe_shader())?;
            *probes = Some(crate::scoped(device, || {
                let module = device.create_shader_module(wgpu::ShaderModuleDescriptor {
                    label: Some("ocean relief probe shader"),
                    source: wgpu::ShaderSource::Wgsl(entry.source.into()),
                });
                let compute = wgpu::ShaderStages::COMPUTE;
                let trace_layout =
                    device.create_bind_group_layout(&wgpu::BindGroupLayoutDescriptor {
                        label: Some("ocean relief probe layout"),
                        entries: &[
                            uniform_entry(0, compute),
                            relief_texture_entry(compute, layout),
                            storage_entry(2, true),
                            storage_entry(3, false),
                        ],
                    });
                let copy_layout =
                    device.create_bind_group_layout(&wgpu::BindGroupLayoutDescriptor {
                        label: Some("ocean relief depth copy layout"),
                        entries: &[
                            uniform_entry(0, compute),
                            storage_entry(3, false),
                            wgpu::BindGroupLayoutEntry {
                                binding: 4,
                                visibility: compute,
                                ty: wgpu::BindingType::Texture {
                                    sample_type: wgpu::TextureSampleType::Float {
                                        filterable: false,
                                    },
                                    view_dimension: wgpu::TextureViewDimension::D2,
                                    multisampled: false,
                                },
                                count: None,
                            },
                        ],
                    });
                let pipeline = |layout: &wgpu::BindGroupLayout, name| {
                    let pl = device.create_pipeline_layout(&wgpu::PipelineLayoutDescriptor {
                        label: Some(name),
                        bind_group_layouts: &[Some(layout)],
                        immediate_size: 0,
                    });
                    device.create_compute_pipeline(&wgpu::ComputePipelineDescriptor {
                        label: Some(name),
                        layout: Some(&pl),
                        module: &module,
                        entry_point: Some(name),
                        compilation_options: wgpu::PipelineCompilationOptions::default(),
                        cache: None,
                    })
                };
                Ok(ProbePipelines {
                    trace: pipeline(&trace_layout, "probe_trace"),
                    copy_depth: pipeline(&copy_layout, "copy_depth"),
                    trace_layout,
                    copy_layout,
                })
            })?);
        }
        probes
            .as_ref()
            .ok_or_else(|| GpuError::Wgpu("relief probe pipelines missing".to_owned()))
    }

    /// Copies a depth view into a buffer with `copy_depth` and reads it back.
    pub(super) fn read_depth(
        &self,
        ctx: &GpuContext,
        view: &wgpu::TextureView,
        width: u32,
        height: u32,
    ) -> Result<Vec<f32>, GpuError> {
        let device = ctx.device();
        let mut probes = lock(&self.probes);
        // copy_depth reads no relief texture: either module's serves.
        let p = self.probe_pipelines(device, &mut probes, ReliefLayout::Isotropic)?;
        let texels = u64::from(width) * u64::from(height);
        let limits = device.limits();
        let limit = limits
            .max_storage_buffer_binding_size
            .min(limits.max_buffer_size);
        if texels * 16 > limit {
            return Err(GpuError::TooLarge {
                what: "relief depth readback (bytes)",
                needed: texels * 16,
                limit,
            });
        }
        let out = crate::scoped(device, || {
            let u = ReliefUniforms {
                steps: [0, 0, 0, width],
                ..Default::default()
            };
            let uniform = uniform_buffer(ctx, "ocean relief depth copy uniform", &u);
            let out = device.create_buffer(&wgpu::BufferDescriptor {
                label: Some("ocean relief depth copy"),
                size: texels * 16,
                usage: wgpu::BufferUsages::STORAGE | wgpu::BufferUsages::COPY_SRC,
                mapped_at_creation: false,
            });
            let group = device.create_bind_group(&wgpu::BindGroupDescriptor {
                label: Some("ocean relief depth copy"),
                layout: &p.copy_layout,
                entries: &[
                    wgpu::BindGroupEntry {
                        binding: 0,
                        resource: uniform.as_entire_binding(),
                    },
                    wgpu::BindGroupEntry {
                        binding: 3,
                        resource: out.as_entire_binding(),
                    },
                    wgpu::BindGroupEntry {
                        binding: 4,
                        resource: wgpu::BindingResource::TextureView(view),
                    },
                ],
            });
            let mut encoder = device.create_command_encoder(&wgpu::CommandEncoderDescriptor {
                label: Some("ocean relief depth copy"),
            });
            {
                let mut pass = encoder.begin_compute_pass(&wgpu::ComputePassDescriptor {
                    label: Some("ocean relief depth copy"),
                    timestamp_writes: None,
                });
                pass.set_pipeline(&p.copy_depth);
                pass.set_bind_group(0, &group, &[]);
                pass.dispatch_workgroups(width.div_ceil(8), height.div_ceil(8), 1);
            }
            ctx.queue().submit([encoder.finish()]);
            Ok(out)
        })?;
        drop(probes);
        let v: Vec<[f32; 4]> = read_buffer_as(ctx, &out)?;
        Ok(v.into_iter().map(|t| t[0]).collect())
    }

    /// Runs the draw pass's tracer ([`Method::trace`] with `method`) and shadow test
    /// ([`ocean_relief::shadow::in_shadow`] with the same method) on the texture set by
    /// [`set_texture`](Self::set_texture), for each ray, and reads the results back: the GPU
    /// side of the tracers' parity tests. After
    /// [`set_quad_texture`](Self::set_quad_texture) its twins are
    /// [`QuadReliefTexture::trace`] and [`QuadReliefTexture::in_shadow`].
    ///
    /// # Errors
    ///
    /// [`GpuError::NotConfigured`] before `set_texture`; [`GpuError::Relief`] for a method the
    /// CPU tracer refuses; [`GpuError::InvalidInput`] for no rays or more than
    /// [`MAX_PROBE_RAYS`], or a ray the CPU refuses (non-finite values, a view vector with
    /// `z ≥ 0`, a negative depth scale, a bias outside `[0, 1]`).
    pub fn probe(
        &self,
        ctx: &GpuContext,
        method: &Method,
        rays: &[ReliefRay],
    ) -> Result<Vec<ReliefProbe>, GpuError> {
        let tex = self.texture_state()?;
        if rays.is_empty() || rays.len() > MAX_PROBE_RAYS {
            return Err(invalid(
                "probe rays",
                format!("{} rays: 1 to {MAX_PROBE_RAYS} are accepted", rays.len()),
            ));
        }
        let mut inputs = Vec::with_capacity(rays.len() * PROBE_ITEM_VEC4S);
        for (k, r) in rays.iter().enumerate() {
            let finite = r.start.is_finite()
                && r.view.is_finite()
                && r.depth_scale.is_finite()
                && r.point.is_finite()
                && r.light.is_finite()
                && r.bias.is_finite()
                && r.footprint.iter().all(|d| d.is_finite());
            if !finite || r.view.z >= 0.0 || r.depth_scale < 0.0 || !(0.0..=1.0).contains(&r.bias) {
                return Err(invalid(
                    "probe ray",
                    format!(
                        "ray {k}: values must be finite, view.z < 0, depth_scale >= 0 and bias \
                         in [0, 1]"
                    ),
                ));
            }
            inputs.push([r.start.x, r.start.y, r.depth_scale, r.bias]);
            inputs.push([r.view.x, r.view.y, r.view.z, 0.0]);
            inputs.push([r.point.x, r.point.y, r.point.z, 0.0]);
            inputs.push([r.light.x, r.light.y, r.light.z, 0.0]);
            let [du, dv] = r.footprint;
            inputs.push([du.x, du.y, dv.x, dv.y]);
        }
        let mut u = ReliefUniforms::default();
        u.set_texture(tex.size, tex.edge)?;
        u.set_levels(tex.levels)?;
        u.set_method(method)?;
        u.steps[3] = rays.len() as u32;
        let device = ctx.device();
        let mut probes = lock(&self.probes);
        let p = self.probe_pipelines(device, &mut probes, tex.layout)?;
        let out_size = rays.len() as u64 * 32;
        let limits = device.limits();
        let limit = limits
            .max_storage_buffer_binding_size
            .min(limits.max_buffer_size);
        let in_size = (rays.len() * PROBE_ITEM_VEC4S) as u64 * 16;
        if in_size > limit {
            return Err(GpuError::TooLarge {
                what: "relief probe buffers (bytes)",
                needed: in_size,
                limit,
            });
        }
        let out = crate::scoped(device, || {
            let buffer = |label, size: u64, usage| {
                device.create_buffer(&wgpu::BufferDescriptor {
                    label: Some(label),
                    size,
                    usage: usage | wgpu::BufferUsages::COPY_DST,
                    mapped_at_creation: false,
                })
            };
            let uniform = uniform_buffer(ctx, "ocean relief probe uniform", &u);
            let input = buffer(
                "ocean relief probe inputs",
                inputs.len() as u64 * 16,
                wgpu::BufferUsages::STORAGE,
            );
            let output = buffer(
                "ocean relief probe outputs",
                out_size,
                wgpu::BufferUsages::STORAGE | wgpu::BufferUsages::COPY_SRC,
            );
            let queue = ctx.queue();
            queue.write_buffer(&input, 0, bytemuck::cast_slice(&inputs));
            let entry = |binding, resource| wgpu::BindGroupEntry { binding, resource };
            let group = device.create_bind_group(&wgpu::BindGroupDescriptor {
                label: Some("ocean relief probe bind group"),
                layout: &p.trace_layout,
                entries: &[
                    entry(0, uniform.as_entire_binding()),
                    entry(1, wgpu::BindingResource::TextureView(&tex.view)),
                    entry(2, input.as_entire_binding()),
                    entry(3, output.as_entire_binding()),
                ],
            });
            let mut encoder = device.create_command_encoder(&wgpu::CommandEncoderDescriptor {
                label: Some("ocean relief probe"),
            });
            {
                let mut pass = encoder.begin_compute_pass(&wgpu::ComputePassDescriptor {
                    label: Some("ocean relief probe"),
                    timestamp_writes: None,
                });
                pass.set_pipeline(&p.trace);
                pass.set_bind_group(0, &group, &[]);
                pass.dispatch_workgroups((rays.len() as u32).div_ceil(PROBE_WORKGROUP), 1, 1);
            }
            queue.submit([encoder.finish()]);
            Ok(output)
        })?;
        drop(probes);
        let v: Vec<[f32; 4]> = read_buffer_as(ctx, &out)?;
        Ok(v.chunks_exact(2)
            .map(|c| ReliefProbe {
                hit: Hit {
                    pos: Vec3::new(c[0][0], c[0][1], c[0][2]),
                    fetches: c[0][3] as u32,
                },
                shadow: c[1][0] != 0.0,
                light_hit: (c[1][1], c[1][2] as u32),
                level: c[1][3] as u32,
            })
            .collect())
    }
}
