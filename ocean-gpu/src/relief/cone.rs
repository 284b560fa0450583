//! Cone maps generated on the GPU: the twin of [`ocean_relief::ConeMap::generate`] and
//! [`ocean_relief::QuadConeMap::generate`] (`relief_cone.wgsl` explains the double-`f32` port of
//! the bound and the search).

use std::time::{Duration, Instant};

use ocean_relief::gpu_params::ConeGenUniforms;
use ocean_relief::{
    ConeMap, ConeParams, HeightMap, QuadConeMap, QuadReliefTexture, Quadrant, ReliefTexture,
};

use crate::readback::read_buffer_as;
use crate::{GpuContext, GpuError, shaders};

/// Wall-clock times of one [`ConeMapGenerator::generate_timed`] (or
/// [`ConeMapGenerator::generate_quad_timed`]) call, each pass waited for before the next is
/// submitted.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct ConeGenTimes {
    /// Cells and the min-depth pyramid (once, shared by a quadrant map's four layers).
    pub prepare: Duration,
    /// The branch-and-bound search of every apex cell (of every layer).
    pub search: Duration,
    /// Per-texel minima and the readback (of every layer).
    pub finish: Duration,
}

impl ConeGenTimes {
    /// The three together.
    pub fn total(&self) -> Duration {
        self.prepare + self.search + self.finish
    }
}

#[derive(Debug)]
struct Pass {
    pipeline: wgpu::ComputePipeline,
    layout: wgpu::BindGroupLayout,
}

/// Relaxed and conservative cone maps by the branch-and-bound of
/// [`ocean_relief::ConeMap::generate`], run as compute passes (`relief_cone.wgsl`): per cell the
/// bound's data, the min-depth pyramid level by level, one invocation per apex cell for the
/// search (an explicit stack of pyramid nodes), and the per-texel minima.
///
/// The result equals the CPU's up to the last bit of a value that lies within about 2⁻⁴⁴
/// (relative) of an `f32` boundary, where the CPU's `f64` and this pass's double-`f32`
/// arithmetic may round to different sides; every sign test decides exactly as the CPU does.
///
/// Quadrant cone maps ([`ocean_relief::quad`], §18.1: "four different radii for each
/// fragment") share the cells and the pyramid, which do not depend on the directions; the
/// search and the per-texel minima run once per layer with the vector boxes clipped to its
/// quadrant ([`ConeMapGenerator::generate_quad`]).
#[derive(Debug)]
pub struct ConeMapGenerator {
    cells: Pass,
    reduce: Pass,
    search: Pass,
    texels: Pass,
}

/// Workgroup side of every pass (`@workgroup_size(8, 8)`).
const GROUP: u32 = 8;

fn storage(binding: u32, read_only: bool) -> wgpu::BindGroupLayoutEntry {
    wgpu::BindGroupLayoutEntry {
        binding,
        visibility: wgpu::ShaderStages::COMPUTE,
        ty: wgpu::BindingType::Buffer {
            ty: wgpu::BufferBindingType::Storage { read_only },
            has_dynamic_offset: false,
            min_binding_size: None,
        },
        count: None,
    }
}

impl ConeMapGenerator {
    /// Compiles the passes on `ctx`'s device.
    ///
    /// # Errors
    ///
    /// [`GpuError::Wgpu`] if the device refuses an object (a backend that cannot translate the
    /// shader).
    pub fn new(ctx: &GpuContext) -> Result<Self, GpuError> {
        let entry = shaders::get("relief_cone").ok_or_else(|| {
            GpuError::Shader(shaders::ShaderError::UnknownShader {
                name: "relief_cone".to_owned(),
                available: String::new(),
            })
        })?;
        let device = ctx.device();
        crate::scoped(device, || {
            let module = device.create_shader_module(wgpu::ShaderModuleDescriptor {
                label: Some("ocean cone map shader"),
                source: wgpu::ShaderSource::Wgsl(entry.source.into()),
            });
            let uniform = wgpu::BindGroupLayoutEntry {
                binding: 0,
                visibility: wgpu::ShaderStages::COMPUTE,
                ty: wgpu::BindingType::Buffer {
                    ty: wgpu::BufferBindingType::Uniform,
                    has_dynamic_offset: false,
                    min_binding_size: wgpu::BufferSize::new(
                        std::mem::size_of::<ConeGenUniforms>() as u64
                    ),
                },
                count: None,
            };
            let pass = |name: &str, storages: &[(u32, bool)]| {
                let mut entries = vec![uniform];
                entries.extend(storages.iter().map(|&(b, ro)| storage(b, ro)));
                let layout = device.create_bind_group_layout(&wgpu::BindGroupLayoutDescriptor {
                    label: Some(name),
                    entries: &entries,
                });
                let pipeline_layout =
                    device.create_pipeline_layout(&wgpu::PipelineLayoutDescriptor {
                        label: Some(name),
                        bind_group_layouts: &[Some(&layout)],
                        immediate_size: 0,
                    });
                let pipeline = device.create_compute_pipeline(&wgpu::ComputePipelineDescriptor {
                    label: Some(name),
                    layout: Some(&pipeline_layout),
                    module: &module,
                    entry_point: Some(name),
                    compilation_options: wgpu::PipelineCompilationOptions::default(),
                    cache: None,
                });
                Pass { pipeline, layout }
            };
            Ok(Self {
                cells: pass("cells_pass", &[(1, true), (2, false)]),
                reduce: pass("reduce_pass", &[(3, true), (4, false)]),
                search: pass("search_pass", &[(3, true), (5, true), (6, false)]),
                texels: pass("texels_pass", &[(1, true), (7, true), (8, false)]),
            })
        })
    }

    /// The cone map of `map` with `params`, as [`ConeMap::generate`] computes it.
    ///
    /// # Errors
    ///
    /// [`GpuError::Relief`] for a `max_ratio` outside `(0, MAX_RATIO_LIMIT]`;
    /// [`GpuError::TooLarge`] when a buffer exceeds the device's storage-buffer limits (under
    /// [`wgpu::Limits::downlevel_defaults`], 128 MiB per binding, the cell buffer of 32 bytes
    /// per cell limits maps to 2048² texels in wrap mode and 2047² in clamp mode, which has one
    /// more cell per side); [`GpuError::Wgpu`] for a device error.
    pub fn generate(
        &self,
        ctx: &GpuContext,
        map: &HeightMap,
        params: ConeParams,
    ) -> Result<ConeMap, GpuError> {
        Ok(self.generate_timed(ctx, map, params)?.0)
    }

    /// The relief texture of `map` with cones generated by [`generate`](Self::generate).
    ///
    /// # Errors
    ///
    /// As [`generate`](Self::generate).
    pub fn relief_texture(
        &self,
        ctx: &GpuContext,
        map: &HeightMap,
        params: ConeParams,
    ) -> Result<ReliefTexture, GpuError> {
        let cones = self.generate(ctx, map, params)?;
        Ok(ReliefTexture::new(map, &cones)?)
    }

    /// [`generate`](Self::generate), with the wall-clock time of its stages.
    ///
    /// # Errors
    ///
    /// As [`generate`](Self::generate).
    pub fn generate_timed(
        &self,
        ctx: &GpuContext,
        map: &HeightMap,
        params: ConeParams,
    ) -> Result<(ConeMap, ConeGenTimes), GpuError> {
        let (mut layers, times) = self.run(ctx, map, params, &[None])?;
        let cones = layers
            .pop()
            .ok_or(GpuError::Relief(ocean_relief::ReliefError::Mismatch(
                "cone map layers",
            )))?;
        Ok((cones, times))
    }

    /// The quadrant cone map of `map` with `params`, as [`QuadConeMap::generate`] computes it:
    /// every layer under [`generate`](Self::generate)'s parity (equal to the CPU's up to the
    /// last bit of a value within about 2⁻⁴⁴ of an `f32` boundary).
    ///
    /// # Errors
    ///
    /// As [`generate`](Self::generate) (the buffers are those of one layer, reused by the
    /// next, so the size limits are the same).
    pub fn generate_quad(
        &self,
        ctx: &GpuContext,
        map: &HeightMap,
        params: ConeParams,
    ) -> Result<QuadConeMap, GpuError> {
        Ok(self.generate_quad_timed(ctx, map, params)?.0)
    }

    /// The quadrant relief texture of `map` with cones generated by
    /// [`generate_quad`](Self::generate_quad), for [`crate::ReliefRenderer::set_quad_texture`].
    ///
    /// # Errors
    ///
    /// As [`generate`](Self::generate).
    pub fn quad_relief_texture(
        &self,
        ctx: &GpuContext,
        map: &HeightMap,
        params: ConeParams,
    ) -> Result<QuadReliefTexture, GpuError> {
        let cones = self.generate_quad(ctx, map, params)?;
        Ok(QuadReliefTexture::new(map, &cones)?)
    }

    /// [`generate_quad`](Self::generate_quad), with the wall-clock time of its stages (the
    /// search and finish times summed over the four layers).
    ///
    /// # Errors
    ///
    /// As [`generate`](Self::generate).
    pub fn generate_quad_timed(
        &self,
        ctx: &GpuContext,
        map: &HeightMap,
        params: ConeParams,
    ) -> Result<(QuadConeMap, ConeGenTimes), GpuError> {
        let (layers, times) = self.run(ctx, map, params, &Quadrant::ALL.map(Some))?;
        let layers: [ConeMap; 4] = layers.try_into().map_err(|_| {
            GpuError::Relief(ocean_relief::ReliefError::Mismatch("quadrant layers"))
        })?;
        Ok((QuadConeMap::from_layers(layers)?, times))
    }

    /// Cells and pyramid once, then the search and the texels for each sector in turn (`None`:
    /// every direction), one cone map per sector.
    fn run(
        &self,
        ctx: &GpuContext,
        map: &HeightMap,
        params: ConeParams,
        sectors: &[Option<Quadrant>],
    ) -> Result<(Vec<ConeMap>, ConeGenTimes), GpuError> {
        let n = map.size();
        let (base, nodes) = ConeGenUniforms::new(n, map.edge(), params)?;
        let nc = base.grid[1] as u64;
        let levels = base.pyramid[1];
        let device = ctx.device();
        let limits = device.limits();
        let limit = limits
            .max_storage_buffer_binding_size
            .min(limits.max_buffer_size);
        let texels = (n * n) as u64;
        for (what, bytes) in [
            ("cone map cells (bytes)", nc * nc * 32),
            ("cone map pyramid (bytes)", nodes.max(1) * 24),
            ("cone map cell cones (bytes)", nc * nc * 16),
            ("cone map texels (bytes)", texels * 16),
        ] {
            if bytes > limit {
                return Err(GpuError::TooLarge {
                    what,
                    needed: bytes,
                    limit,
                });
            }
        }
        let groups = |side: u64| (side as u32).div_ceil(GROUP);
        let wait = || -> Result<(), GpuError> {
            device.poll(wgpu::PollType::wait_indefinitely())?;
            Ok(())
        };
        let start = Instant::now();
        let (uniforms, sector_uniforms, depths, cells, pyramid, cones, out) =
            crate::scoped(device, || {
                let buffer = |label: &str, size: u64, usage| {
                    device.create_buffer(&wgpu::BufferDescriptor {
                        label: Some(label),
                        size,
                        usage,
                        mapped_at_creation: false,
                    })
                };
                let storage = wgpu::BufferUsages::STORAGE;
                let uniform = |label: &str, u: &ConeGenUniforms| {
                    let b = buffer(
                        label,
                        std::mem::size_of::<ConeGenUniforms>() as u64,
                        wgpu::BufferUsages::UNIFORM | wgpu::BufferUsages::COPY_DST,
                    );
                    ctx.queue().write_buffer(&b, 0, bytemuck::bytes_of(u));
                    b
                };
                let uniforms: Vec<wgpu::Buffer> = (0..levels)
                    .map(|level| {
                        let mut u = base;
                        u.pyramid[2] = level;
                        uniform("ocean cone map uniform", &u)
                    })
                    .collect();
                // The search and texel passes of each sector read its own block.
                let sector_uniforms: Vec<wgpu::Buffer> = sectors
                    .iter()
                    .map(|&sector| {
                        uniform("ocean cone map sector uniform", &base.with_sector(sector))
                    })
                    .collect();
                let depths = buffer(
                    "ocean cone map depths",
                    texels * 4,
                    storage | wgpu::BufferUsages::COPY_DST,
                );
                ctx.queue()
                    .write_buffer(&depths, 0, bytemuck::cast_slice(map.depths()));
                let cells = buffer("ocean cone map cells", nc * nc * 32, storage);
                let pyramid = buffer("ocean cone map pyramid", nodes.max(1) * 24, storage);
                let cones = buffer("ocean cone map cell cones", nc * nc * 16, storage);
                let out = buffer(
                    "ocean cone map texels",
                    texels * 16,
                    storage | wgpu::BufferUsages::COPY_SRC,
                );
                Ok((
                    uniforms,
                    sector_uniforms,
                    depths,
                    cells,
                    pyramid,
                    cones,
                    out,
                ))
            })?;
        let group = |pass: &Pass, uniform: &wgpu::Buffer, entries: &[(u32, &wgpu::Buffer)]| {
            let mut all = vec![wgpu::BindGroupEntry {
                binding: 0,
                resource: uniform.as_entire_binding(),
            }];
            all.extend(entries.iter().map(|&(binding, b)| wgpu::BindGroupEntry {
                binding,
                resource: b.as_entire_binding(),
            }));
            device.create_bind_group(&wgpu::BindGroupDescriptor {
                label: Some("ocean cone map"),
                layout: &pass.layout,
                entries: &all,
            })
        };
        let run = |label: &str, pass: &Pass, bind: &wgpu::BindGroup, x: u32, y: u32| {
            crate::scoped(device, || {
                let mut encoder = device
                    .create_command_encoder(&wgpu::CommandEncoderDescriptor { label: Some(label) });
                {
                    let mut cp = encoder.begin_compute_pass(&wgpu::ComputePassDescriptor {
                        label: Some(label),
                        timestamp_writes: None,
                    });
                    cp.set_pipeline(&pass.pipeline);
                    cp.set_bind_group(0, bind, &[]);
                    cp.dispatch_workgroups(x, y, 1);
                }
                ctx.queue().submit([encoder.finish()]);
                Ok(())
            })
        };
        let u0 = &uniforms[0];
        let b = crate::scoped(device, || {
            Ok(group(&self.cells, u0, &[(1, &depths), (2, &cells)]))
        })?;
        run(
            "ocean cone map cells",
            &self.cells,
            &b,
            groups(nc),
            groups(nc),
        )?;
        for level in 1..levels {
            let side = u64::from(base.level_side(level));
            let b = crate::scoped(device, || {
                Ok(group(
                    &self.reduce,
                    &uniforms[level as usize],
                    &[(3, &cells), (4, &pyramid)],
                ))
            })?;
            run(
                "ocean cone map pyramid",
                &self.reduce,
                &b,
                groups(side),
                groups(side),
            )?;
        }
        wait()?;
        let prepared = Instant::now();
        let (mut search_time, mut finish_time) = (Duration::ZERO, Duration::ZERO);
        let mut maps = Vec::with_capacity(sectors.len());
        // One sector after another through the same cell-cone and texel buffers: each pass is
        // waited for before the next is submitted (the times), and the texels are read back
        // before the next sector's search overwrites them.
        for u in &sector_uniforms {
            let started = Instant::now();
            let b = crate::scoped(device, || {
                Ok(group(
                    &self.search,
                    u,
                    &[(3, &cells), (5, &pyramid), (6, &cones)],
                ))
            })?;
            run(
                "ocean cone map search",
                &self.search,
                &b,
                groups(nc),
                groups(nc),
            )?;
            wait()?;
            let searched = Instant::now();
            let b = crate::scoped(device, || {
                Ok(group(
                    &self.texels,
                    u,
                    &[(1, &depths), (7, &cones), (8, &out)],
                ))
            })?;
            run(
                "ocean cone map texels",
                &self.texels,
                &b,
                groups(n as u64),
                groups(n as u64),
            )?;
            let v: Vec<[f32; 4]> = read_buffer_as(ctx, &out)?;
            let mut channels: [Vec<f32>; 3] = std::array::from_fn(|_| Vec::with_capacity(n * n));
            for t in &v {
                for (c, ch) in channels.iter_mut().enumerate() {
                    ch.push(t[c + 1]);
                }
            }
            let [c, d, e] = channels;
            maps.push(ConeMap::from_channels(n, map.edge(), c, d, e)?);
            let done = Instant::now();
            search_time += searched - started;
            finish_time += done - searched;
        }
        Ok((
            maps,
            ConeGenTimes {
                prepare: prepared - start,
                search: search_time,
                finish: finish_time,
            },
        ))
    }
}
