//! The renderer's probes ([`OceanRenderer::probe_surface`], [`OceanRenderer::probe_sea_color`]):
//! compute passes that run the draw shaders' own functions on lists of inputs, so that the
//! parity tests compare what the GPU draws with its CPU twins in `ocean_brdf`.

use super::*;

/// What [`OceanRenderer::probe_surface`] reads back for one screen point: what the vertex stage
/// computes for a grid vertex there and what the fragment stage computes for a pixel centred
/// there (before interpolation). World coordinates.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SurfaceProbe {
    /// The rest position `(x, z)` the point's view ray meets ([`ocean_brdf::surface::sea_plane_hit`]).
    pub rest: DVec2,
    /// `L`, the grid-cell footprint: `cell_px` times the pixel footprint, metres.
    pub cell_footprint: f64,
    /// Eq. 2: the displaced position for `L`. Beyond the distance cap the vertex stage draws
    /// the point higher, on its pixel's ray (at most at the eye's height), so the sea reaches
    /// the horizon (`cap_lift` in `ocean.wgsl`); this is the position before that lift.
    pub position: DVec3,
    /// How many waves the vertex stage summed (those with `w_p > 0`).
    pub position_waves: u32,
    /// `l`, the pixel footprint ([`ocean_brdf::surface::pixel_footprint`]), metres.
    pub pixel_footprint: f64,
    /// Eq. 3: the unit normal at `rest` for `l`.
    pub normal: DVec3,
    /// Eq. 4: the slope variances of the waves `l` does not resolve.
    pub variance: SlopeVariance,
    /// How many waves the fragment stage summed (those with `w_n > 0`).
    pub normal_waves: u32,
    /// The fragment stage's geometry normal: Eq. 2's waves weighted by `w_p` for the grid-cell
    /// footprint `cell_px · l` at the pixel ([`ocean_brdf::PixelSurface::geometry_normal`]).
    pub geometry_normal: DVec3,
    /// The fragment stage's normal-only slope variances, weights `w_n − w_p` for `l` and
    /// `cell_px · l` ([`ocean_brdf::PixelSurface::normal_only`]).
    pub normal_only: SlopeVariance,
}

/// One input of [`OceanRenderer::probe_sea_color`]: what the fragment stages light, the
/// arguments of [`ocean_brdf::sea::sea_color_unchecked`] besides the lighting with the normal
/// made masking-aware first ([`ocean_brdf::sea::visible_normal`]), as
/// [`ocean_brdf::sea::pixel_color`] does.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SeaColorInput {
    /// Unit vector from the surface towards the viewer.
    pub v: DVec3,
    /// Unit filtered normal (a back-facing one is reflected, §3.2).
    pub n: DVec3,
    /// Horizontal wind direction `(x, z)`, any non-zero length.
    pub wind: DVec2,
    /// σ_x², σ_y² of the unresolved waves, ≥ 0.
    pub variance: SlopeVariance,
    /// Unit normal of the geometry (`n` itself, with `normal_only` zero, to light `n` as it is).
    pub geometry_normal: DVec3,
    /// σ_x², σ_y² of the waves in `n` and not in the geometry, ≥ 0.
    pub normal_only: SlopeVariance,
}

impl SeaColorInput {
    /// The input that lights the normal `n` as it is: geometry normal `n`, no normal-only
    /// slopes.
    pub fn plain(v: DVec3, n: DVec3, wind: DVec2, variance: SlopeVariance) -> Self {
        Self {
            v,
            n,
            wind,
            variance,
            geometry_normal: n,
            normal_only: SlopeVariance::default(),
        }
    }
}

/// The probe pipelines, built on first use.
#[derive(Debug)]
pub(super) struct ProbePipelines {
    pub(super) layout: wgpu::BindGroupLayout,
    pub(super) surface: wgpu::ComputePipeline,
    pub(super) sea_color: wgpu::ComputePipeline,
}

/// The probe's item count as `u32`, at least 1 and at most 2²² (64 × 65536 workgroups).
pub(super) fn probe_items(n: usize) -> Result<u32, GpuError> {
    const MAX: usize = 1 << 22;
    if n == 0 || n > MAX {
        return Err(invalid(
            "probe inputs",
            format!("{n} items; between 1 and {MAX} are accepted"),
        ));
    }
    Ok(n as u32)
}

pub(super) fn probe_pipelines(device: &wgpu::Device) -> Result<ProbePipelines, GpuError> {
    let entry = shaders::get("ocean_probe").ok_or_else(|| {
        GpuError::Shader(shaders::ShaderError::UnknownShader {
            name: "ocean_probe".to_owned(),
            available: String::new(),
        })
    })?;
    let module = device.create_shader_module(wgpu::ShaderModuleDescriptor {
        label: Some("ocean probe shader"),
        source: wgpu::ShaderSource::Wgsl(entry.source.into()),
    });
    let stages = wgpu::ShaderStages::COMPUTE;
    let [e0, e1, e2, e3, e6, e7, e8] = common_layout_entries(stages);
    let storage = |binding, read_only| wgpu::BindGroupLayoutEntry {
        binding,
        visibility: stages,
        ty: wgpu::BindingType::Buffer {
            ty: wgpu::BufferBindingType::Storage { read_only },
            has_dynamic_offset: false,
            min_binding_size: None,
        },
        count: None,
    };
    let layout = device.create_bind_group_layout(&wgpu::BindGroupLayoutDescriptor {
        label: Some("ocean probe bind group layout"),
        entries: &[
            e0,
            e1,
            e2,
            e3,
            e6,
            e7,
            e8,
            storage(4, true),
            storage(5, false),
        ],
    });
    let pipeline_layout = device.create_pipeline_layout(&wgpu::PipelineLayoutDescriptor {
        label: Some("ocean probe pipeline layout"),
        bind_group_layouts: &[Some(&layout)],
        immediate_size: 0,
    });
    let pipeline = |name| {
        device.create_compute_pipeline(&wgpu::ComputePipelineDescriptor {
            label: Some(name),
            layout: Some(&pipeline_layout),
            module: &module,
            entry_point: Some(name),
            compilation_options: wgpu::PipelineCompilationOptions::default(),
            cache: None,
        })
    };
    Ok(ProbePipelines {
        surface: pipeline("probe_surface"),
        sea_color: pipeline("probe_sea_color"),
        layout,
    })
}

/// Invocations per workgroup of the probe entry points (`@workgroup_size(64)`).
pub(super) const PROBE_WORKGROUP: u32 = 64;

impl OceanRenderer {
    /// Runs the vertex stage's and the fragment stage's surface functions at each of `pixels`
    /// (pixel coordinates of a `width × height` viewport, origin at the top-left corner, y down,
    /// pixel centres at half-integers; points outside the viewport, like the grid's margin, are
    /// allowed) for `camera` at `time`, and reads the results back in world coordinates: the
    /// GPU side of the renderer's geometry parity with [`ocean_brdf::surface`].
    ///
    /// # Errors
    ///
    /// As [`render`](Self::render) for the camera, time and viewport (lighting is not needed);
    /// [`GpuError::InvalidInput`] for no pixels, a non-finite one, or more than 2²² of them.
    #[allow(clippy::too_many_arguments)]
    pub fn probe_surface(
        &self,
        ctx: &GpuContext,
        camera: &Camera,
        time: f64,
        width: u32,
        height: u32,
        pixels: &[DVec2],
    ) -> Result<Vec<SurfaceProbe>, GpuError> {
        self.check_viewport(ctx, width, height)?;
        let items = probe_items(pixels.len())?;
        if !pixels.iter().all(|p| p.is_finite()) {
            return Err(invalid("probe pixels", "every pixel must be finite"));
        }
        let (u, phases, o) = self.frame(camera, time, width, height, items)?;
        let inputs: Vec<[f32; 4]> = pixels
            .iter()
            .map(|p| [p.x as f32, p.y as f32, 0.0, 0.0])
            .collect();
        let local_phases = self.local.phases(o, time);
        let out = self.run_probe(
            ctx,
            &u,
            Some((&phases, &local_phases)),
            &inputs,
            5 * items,
            true,
        )?;
        let v3 = |c: [f32; 4]| DVec3::new(c[0].into(), c[1].into(), c[2].into());
        Ok(out
            .chunks_exact(5)
            .take(pixels.len())
            .map(|c| {
                let p = DVec3::new(c[0][0].into(), c[0][1].into(), c[0][2].into());
                SurfaceProbe {
                    rest: o + DVec2::new(c[1][0].into(), c[1][1].into()),
                    cell_footprint: c[1][2].into(),
                    position: p + DVec3::new(o.x, 0.0, o.y),
                    position_waves: c[0][3] as u32,
                    pixel_footprint: c[1][3].into(),
                    normal: DVec3::new(c[2][0].into(), c[2][1].into(), c[2][2].into()),
                    variance: SlopeVariance {
                        x: c[3][0].into(),
                        y: c[3][1].into(),
                    },
                    normal_waves: c[2][3] as u32,
                    geometry_normal: v3(c[4]),
                    normal_only: SlopeVariance {
                        x: c[3][2].into(),
                        y: c[3][3].into(),
                    },
                }
            })
            .collect())
    }

    /// Runs the fragment stage's Algorithm 5.1 on each input with the current lighting and its
    /// sky map, the normal made masking-aware first (`visible_normal`), and reads the three
    /// terms back: the GPU side of the lighting parity with
    /// [`ocean_brdf::sea::sea_color_unchecked`] of [`ocean_brdf::sea::visible_normal`]. Inputs
    /// are rounded to `f32`.
    ///
    /// # Errors
    ///
    /// [`GpuError::NotConfigured`] before [`set_lighting`](Self::set_lighting);
    /// [`GpuError::InvalidInput`] for no inputs, more than 2²² of them, a direction that is not
    /// a finite unit vector (within 10⁻⁴), a zero or non-finite wind, or a negative or
    /// non-finite variance.
    pub fn probe_sea_color(
        &self,
        ctx: &GpuContext,
        inputs: &[SeaColorInput],
    ) -> Result<Vec<SeaLight>, GpuError> {
        self.lighting_set()?;
        let items = probe_items(inputs.len())?;
        let unit = |d: DVec3| d.is_finite() && (d.length() - 1.0).abs() <= 1e-4;
        for (i, s) in inputs.iter().enumerate() {
            let variance =
                |v: SlopeVariance| v.x.is_finite() && v.y.is_finite() && v.x >= 0.0 && v.y >= 0.0;
            let ok = unit(s.v)
                && unit(s.n)
                && unit(s.geometry_normal)
                && s.wind.is_finite()
                && s.wind != DVec2::ZERO
                && variance(s.variance)
                && variance(s.normal_only);
            if !ok {
                return Err(invalid(
                    "sea colour input",
                    format!(
                        "input {i} ({s:?}): v and the normals must be unit vectors, the wind non-zero, the variances finite and >= 0"
                    ),
                ));
            }
        }
        // Lighting only: the surface fields of a default surface state are unused by the probe.
        let placeholder = WaveTexels::default();
        let mut u = lighting_uniform(
            &self.options,
            self.surface.as_ref().unwrap_or(&placeholder),
            self.lighting.as_ref(),
        );
        u.probe[0] = items;
        let mut data = Vec::with_capacity(5 * inputs.len());
        for s in inputs {
            data.push(rgb(s.v, 0.0));
            data.push(rgb(s.n, 0.0));
            data.push([
                s.wind.x as f32,
                s.wind.y as f32,
                s.variance.x as f32,
                s.variance.y as f32,
            ]);
            data.push(rgb(s.geometry_normal, 0.0));
            data.push([s.normal_only.x as f32, s.normal_only.y as f32, 0.0, 0.0]);
        }
        let out = self.run_probe(ctx, &u, None, &data, 3 * items, false)?;
        let v = |c: [f32; 4]| DVec3::new(c[0].into(), c[1].into(), c[2].into());
        Ok(out
            .chunks_exact(3)
            .take(inputs.len())
            .map(|c| SeaLight {
                sun: v(c[0]),
                sky: v(c[1]),
                sea: v(c[2]),
            })
            .collect())
    }

    /// Dispatches a probe entry point (`surface`: `probe_surface`, else `probe_sea_color`) over
    /// `u.probe[0]` items with its own uniform, input and output buffers, and reads back
    /// `outputs` vec4s. `phases`, if given, is the wave texture's phase row for the frame (the
    /// probe then reads the surface's waves with these phases; otherwise the renderer's wave
    /// texture, which `probe_sea_color` does not read).
    pub(super) fn run_probe(
        &self,
        ctx: &GpuContext,
        u: &FrameUniform,
        phases: Option<FramePhases<'_>>,
        inputs: &[[f32; 4]],
        outputs: u32,
        surface: bool,
    ) -> Result<Vec<[f32; 4]>, GpuError> {
        let device = ctx.device();
        let mut probes = lock(&self.probes);
        if probes.is_none() {
            *probes = Some(crate::scoped(device, || probe_pipelines(device))?);
        }
        let Some(p) = probes.as_ref() else {
            return Err(GpuError::Wgpu("ocean probe pipelines missing".to_owned()));
        };
        let out_size = u64::from(outputs) * 16;
        let limits = device.limits();
        let limit = limits
            .max_storage_buffer_binding_size
            .min(limits.max_buffer_size);
        if out_size > limit || inputs.len() as u64 * 16 > limit {
            return Err(GpuError::TooLarge {
                what: "probe buffers (bytes)",
                needed: out_size.max(inputs.len() as u64 * 16),
                limit,
            });
        }
        let output = crate::scoped(device, || {
            let buffer = |label, size: u64, usage| {
                device.create_buffer(&wgpu::BufferDescriptor {
                    label: Some(label),
                    size,
                    usage: usage | wgpu::BufferUsages::COPY_DST,
                    mapped_at_creation: false,
                })
            };
            let uniform = buffer(
                "ocean probe uniform",
                std::mem::size_of::<FrameUniform>() as u64,
                wgpu::BufferUsages::UNIFORM,
            );
            let input = buffer(
                "ocean probe inputs",
                inputs.len() as u64 * 16,
                wgpu::BufferUsages::STORAGE,
            );
            let output = buffer(
                "ocean probe outputs",
                out_size,
                wgpu::BufferUsages::STORAGE | wgpu::BufferUsages::COPY_SRC,
            );
            let queue = ctx.queue();
            queue.write_buffer(&uniform, 0, bytemuck::bytes_of(u));
            queue.write_buffer(&input, 0, bytemuck::cast_slice(inputs));
            // The surface probe reads a wave texture of its own, so that probing never changes
            // the phases a `render` recorded but not yet submitted will see.
            let probe_local = phases.map(|(_, local)| self.local.view_with_phases(ctx, local));
            let probe_waves = match (phases, self.surface.as_ref()) {
                (Some((phases, _)), Some(surface)) => {
                    let n = phases.len();
                    let mut texels = surface.texels().to_vec();
                    texels[..n].copy_from_slice(phases);
                    let texture = wave_texture(device, n as u32);
                    write_waves(ctx, &texture, &texels, n as u32, WAVE_ROWS);
                    Some(texture.create_view(&wgpu::TextureViewDescriptor::default()))
                }
                _ => None,
            };
            let entry = |binding, resource| wgpu::BindGroupEntry { binding, resource };
            let group = device.create_bind_group(&wgpu::BindGroupDescriptor {
                label: Some("ocean probe bind group"),
                layout: &p.layout,
                entries: &[
                    entry(0, uniform.as_entire_binding()),
                    entry(
                        1,
                        wgpu::BindingResource::TextureView(
                            probe_waves.as_ref().unwrap_or(&self.wave_view),
                        ),
                    ),
                    entry(2, wgpu::BindingResource::TextureView(&self.sky_view)),
                    entry(3, wgpu::BindingResource::Sampler(&self.sampler)),
                    entry(4, input.as_entire_binding()),
                    entry(5, output.as_entire_binding()),
                    entry(
                        FRESNEL_BINDING,
                        wgpu::BindingResource::TextureView(&self.fresnel_view),
                    ),
                    entry(
                        LOCAL_FIELDS_BINDING,
                        wgpu::BindingResource::TextureView(&self.local.fields_view),
                    ),
                    entry(
                        LOCAL_TRAINS_BINDING,
                        wgpu::BindingResource::TextureView(
                            probe_local.as_ref().unwrap_or(&self.local.trains_view),
                        ),
                    ),
                ],
            });
            let mut encoder = device.create_command_encoder(&wgpu::CommandEncoderDescriptor {
                label: Some("ocean probe"),
            });
            {
                let mut pass = encoder.begin_compute_pass(&wgpu::ComputePassDescriptor {
                    label: Some("ocean probe"),
                    timestamp_writes: None,
                });
                pass.set_pipeline(if surface { &p.surface } else { &p.sea_color });
                pass.set_bind_group(0, &group, &[]);
                pass.dispatch_workgroups(u.probe[0].div_ceil(PROBE_WORKGROUP), 1, 1);
            }
            queue.submit([encoder.finish()]);
            Ok(output)
        })?;
        read_buffer_as(ctx, &output)
    }
}
