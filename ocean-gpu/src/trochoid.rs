//! The trochoid displacement pass: the GPU twin of [`ocean_core::WaveSet::evaluate_grid`].
//!
//! For each point of a [`Grid`] it sums the waves of a [`WaveSet`] (wave-train-boxes Eq. 6-7:
//! p = p₀ − Σ k̂ A sin θ, y = Σ A cos θ) and writes the displaced position and the unit normal
//! from the analytic derivatives, with the same `f32` arithmetic as the CPU kernel (the same
//! deterministic polynomial `sincos`, the same order of accumulation).
//!
//! Phases never reach the GPU unreduced: [`WaveSet::grid_phases`] forms every k·p₀ − ωt + Φ in
//! `f64` on the host and reduces it to [-π, π] as a per-row and a per-column table (the phase at
//! (i, j) is their sum), so the result does not degrade at t = 10⁶ s or 100 km from the origin.
//!
//! Output layout (see `shaders/trochoid.wgsl`): two buffers of `nx · nz` × 16 bytes, row-major
//! (point (i, j) at index `j · nx + i`); positions `(x, y, z, 1)` relative to the grid origin,
//! normals `(nx, ny, nz, 0)`; metres, right-handed, y up. Buffers made by
//! [`TrochoidTarget::new`] are also `VERTEX` buffers (`Float32x4`, or `Float32x3` with a
//! 16-byte stride) and `COPY_SRC`.

use glam::Vec3;
use ocean_core::{Grid, WaveSet};
use wgpu::util::DeviceExt;

use crate::readback::{GpuDuration, GpuTimer, read_buffer_as};
use crate::{GpuContext, GpuError, shaders};

/// Invocations per workgroup (`@workgroup_size(64)` in the WGSL).
pub const WORKGROUP_SIZE: u32 = 64;

/// Bytes per output element (one `vec4<f32>`).
pub const OUTPUT_STRIDE: u64 = 16;

/// The pass's uniform block, byte for byte the WGSL `Params` struct (32 bytes, std140).
#[repr(C)]
#[derive(Clone, Copy, Debug, Default, PartialEq, bytemuck::Pod, bytemuck::Zeroable)]
pub struct TrochoidParams {
    /// Columns (along x).
    pub nx: u32,
    /// Rows (along z).
    pub nz: u32,
    /// Number of waves.
    pub waves: u32,
    /// Index in the phase buffer of the first column phase: `waves · nz`.
    pub cols_offset: u32,
    /// Workgroups along x of the dispatch; the linear workgroup index is
    /// `workgroup_id.y · groups_x + workgroup_id.x`.
    pub groups_x: u32,
    /// Explicit padding, 0: keeps the struct at 32 bytes (a whole number of 16-byte std140
    /// rows) with no implicit padding, which `Pod` forbids.
    pub _pad: u32,
    /// Grid spacing along x, metres (`f32`, as the CPU kernel rounds it).
    pub spacing_x: f32,
    /// Grid spacing along z, metres.
    pub spacing_z: f32,
}

/// The dispatch shape for `groups` workgroups when one dimension holds at most `max_per_dim`:
/// `(x, y)` with `x · y ≥ groups`, `x ≤ max_per_dim`, folding into y only when needed.
pub fn dispatch_shape(groups: u32, max_per_dim: u32) -> Result<(u32, u32), GpuError> {
    let max = max_per_dim.max(1);
    if groups == 0 {
        return Ok((0, 0));
    }
    let x = groups.min(max);
    let y = groups.div_ceil(x);
    if y > max {
        return Err(GpuError::TooLarge {
            what: "trochoid dispatch (workgroups)",
            needed: u64::from(groups),
            limit: u64::from(max) * u64::from(max),
        });
    }
    Ok((x, y))
}

/// Output buffers for a grid: positions and normals, 16 bytes per point.
#[derive(Clone, Debug)]
pub struct TrochoidTarget {
    /// Positions `(x, y, z, 1)` relative to the grid origin.
    pub positions: wgpu::Buffer,
    /// Unit normals `(nx, ny, nz, 0)`.
    pub normals: wgpu::Buffer,
}

impl TrochoidTarget {
    /// Allocates buffers for `grid` with `STORAGE | VERTEX | COPY_SRC` usage.
    pub fn new(ctx: &GpuContext, grid: &Grid) -> Result<Self, GpuError> {
        let n = grid.point_count()? as u64;
        let size = output_bytes(ctx.device(), n)?;
        let device = ctx.device();
        crate::scoped(device, || {
            let make = |label| {
                device.create_buffer(&wgpu::BufferDescriptor {
                    label: Some(label),
                    size,
                    usage: wgpu::BufferUsages::STORAGE
                        | wgpu::BufferUsages::VERTEX
                        | wgpu::BufferUsages::COPY_SRC,
                    mapped_at_creation: false,
                })
            };
            Ok(Self {
                positions: make("ocean trochoid positions"),
                normals: make("ocean trochoid normals"),
            })
        })
    }

    /// Uses the caller's buffers (each needs `STORAGE` usage and at least 16 bytes per point;
    /// checked when the pass runs).
    pub fn from_buffers(positions: wgpu::Buffer, normals: wgpu::Buffer) -> Self {
        Self { positions, normals }
    }

    fn check(&self, points: u64) -> Result<(), GpuError> {
        let need = points * OUTPUT_STRIDE;
        for (what, b) in [
            ("positions buffer", &self.positions),
            ("normals buffer", &self.normals),
        ] {
            if !b.usage().contains(wgpu::BufferUsages::STORAGE) {
                return Err(GpuError::InvalidResource {
                    what,
                    reason: "needs STORAGE usage".to_owned(),
                });
            }
            if b.size() < need {
                return Err(GpuError::InvalidResource {
                    what,
                    reason: format!(
                        "{} bytes, the grid needs {need} ({points} points x 16)",
                        b.size()
                    ),
                });
            }
        }
        if self.positions == self.normals {
            return Err(GpuError::InvalidResource {
                what: "normals buffer",
                reason: "must differ from the positions buffer".to_owned(),
            });
        }
        Ok(())
    }
}

fn output_bytes(device: &wgpu::Device, points: u64) -> Result<u64, GpuError> {
    let size = points * OUTPUT_STRIDE;
    let limits = device.limits();
    let limit = limits
        .max_storage_buffer_binding_size
        .min(limits.max_buffer_size);
    if size > limit {
        return Err(GpuError::TooLarge {
            what: "trochoid output buffer (16 bytes per grid point)",
            needed: size,
            limit,
        });
    }
    Ok(size)
}

/// What one run of the pass evaluates: a wave set on a grid at a time.
#[derive(Clone, Copy, Debug)]
pub struct TrochoidInput<'a> {
    /// The waves.
    pub waves: &'a WaveSet,
    /// The grid of rest positions.
    pub grid: &'a Grid,
    /// Time in seconds (`f64`: phases are reduced on the host, so any finite time works).
    pub time: f64,
}

/// Positions and normals read back from the GPU.
#[derive(Clone, Debug, PartialEq)]
pub struct GridOutput {
    /// Positions relative to the grid origin, row-major.
    pub positions: Vec<Vec3>,
    /// Unit normals, row-major.
    pub normals: Vec<Vec3>,
    /// GPU time of the compute pass, when the device supports timestamps.
    pub gpu_time: Option<GpuDuration>,
}

/// The trochoid compute pipeline, created once per device.
#[derive(Debug)]
pub struct TrochoidPass {
    pipeline: wgpu::ComputePipeline,
    layout: wgpu::BindGroupLayout,
    max_groups_per_dim: u32,
}

/// Everything one dispatch needs, built on the host.
struct Prepared {
    params: TrochoidParams,
    groups: (u32, u32),
    phases: Vec<f32>,
    points: u64,
}

impl TrochoidPass {
    /// Builds the pipeline on `ctx`'s device.
    pub fn new(ctx: &GpuContext) -> Result<Self, GpuError> {
        let device = ctx.device();
        let entry = shaders::get("trochoid").ok_or_else(|| {
            GpuError::Shader(shaders::ShaderError::UnknownShader {
                name: "trochoid".to_owned(),
                available: String::new(),
            })
        })?;
        crate::scoped(device, || {
            let module = device.create_shader_module(wgpu::ShaderModuleDescriptor {
                label: Some("ocean trochoid.wgsl"),
                source: wgpu::ShaderSource::Wgsl(entry.source.into()),
            });
            let storage = |binding, read_only| wgpu::BindGroupLayoutEntry {
                binding,
                visibility: wgpu::ShaderStages::COMPUTE,
                ty: wgpu::BindingType::Buffer {
                    ty: wgpu::BufferBindingType::Storage { read_only },
                    has_dynamic_offset: false,
                    min_binding_size: None,
                },
                count: None,
            };
            let layout = device.create_bind_group_layout(&wgpu::BindGroupLayoutDescriptor {
                label: Some("ocean trochoid bind group layout"),
                entries: &[
                    wgpu::BindGroupLayoutEntry {
                        binding: 0,
                        visibility: wgpu::ShaderStages::COMPUTE,
                        ty: wgpu::BindingType::Buffer {
                            ty: wgpu::BufferBindingType::Uniform,
                            has_dynamic_offset: false,
                            min_binding_size: wgpu::BufferSize::new(std::mem::size_of::<
                                TrochoidParams,
                            >()
                                as u64),
                        },
                        count: None,
                    },
                    storage(1, true),
                    storage(2, true),
                    storage(3, false),
                    storage(4, false),
                ],
            });
            let pipeline_layout = device.create_pipeline_layout(&wgpu::PipelineLayoutDescriptor {
                label: Some("ocean trochoid pipeline layout"),
                bind_group_layouts: &[Some(&layout)],
                immediate_size: 0,
            });
            let pipeline = device.create_compute_pipeline(&wgpu::ComputePipelineDescriptor {
                label: Some("ocean trochoid pipeline"),
                layout: Some(&pipeline_layout),
                module: &module,
                entry_point: Some("displace"),
                compilation_options: wgpu::PipelineCompilationOptions::default(),
                cache: None,
            });
            Ok(Self {
                pipeline,
                layout,
                max_groups_per_dim: device.limits().max_compute_workgroups_per_dimension,
            })
        })
    }

    /// Caps the workgroups per dispatch dimension below the device limit (at least 1), so the
    /// folding of large grids into two dimensions can be exercised on small ones.
    pub fn with_max_workgroups_per_dimension(mut self, max: u32) -> Self {
        self.max_groups_per_dim = max.clamp(1, self.max_groups_per_dim);
        self
    }

    fn prepare(
        &self,
        ctx: &GpuContext,
        waves: &WaveSet,
        grid: &Grid,
        t: f64,
    ) -> Result<Prepared, GpuError> {
        let points = grid.point_count()?;
        let (nx, nz) = grid.size;
        let w = waves.coeffs().len();
        let mut rows = vec![0.0f32; w * nz];
        let mut cols = vec![0.0f32; w * nx];
        waves.grid_phases(grid, t, &mut rows, &mut cols)?;
        let too_large = |what, needed: u64, limit: u64| GpuError::TooLarge {
            what,
            needed,
            limit,
        };
        let u32max = u64::from(u32::MAX);
        // The shader indexes points and phase tables with u32.
        if points as u64 > u32max {
            return Err(too_large("grid points (u32 index)", points as u64, u32max));
        }
        let phase_count = (rows.len() + cols.len()) as u64;
        if phase_count > u32max {
            return Err(too_large(
                "phase table entries (u32 index)",
                phase_count,
                u32max,
            ));
        }
        let limits = ctx.device().limits();
        let binding_limit = limits
            .max_storage_buffer_binding_size
            .min(limits.max_buffer_size);
        let coeff_bytes = std::mem::size_of_val(waves.coeffs()) as u64;
        if coeff_bytes > binding_limit {
            return Err(too_large(
                "wave coefficient buffer (bytes)",
                coeff_bytes,
                binding_limit,
            ));
        }
        if phase_count * 4 > binding_limit {
            return Err(too_large(
                "phase table buffer (bytes)",
                phase_count * 4,
                binding_limit,
            ));
        }
        output_bytes(ctx.device(), points as u64)?;
        let groups = (points as u64).div_ceil(u64::from(WORKGROUP_SIZE));
        let groups = dispatch_shape(
            u32::try_from(groups).map_err(|_| too_large("workgroups", groups, u32max))?,
            self.max_groups_per_dim,
        )?;
        let mut phases = rows;
        phases.extend_from_slice(&cols);
        Ok(Prepared {
            params: TrochoidParams {
                nx: nx as u32,
                nz: nz as u32,
                waves: w as u32,
                cols_offset: (w * nz) as u32,
                groups_x: groups.0,
                _pad: 0,
                spacing_x: grid.spacing.x as f32,
                spacing_z: grid.spacing.y as f32,
            },
            groups,
            phases,
            points: points as u64,
        })
    }

    /// Uploads the inputs (waves, grid, time) and records the dispatch into the caller's
    /// `encoder`; the uploads reach the GPU with the caller's next submit, ahead of the
    /// encoder's commands. `timer`, if given, timestamps the pass (call [`GpuTimer::resolve`]
    /// on the encoder afterwards).
    ///
    /// Each call allocates three small input buffers (uniforms, coefficients, phase tables:
    /// 32 + 32·waves + 4·waves·(nx + nz) bytes); they live as long as the recorded commands.
    ///
    /// Nothing is recorded if an argument is invalid.
    pub fn encode(
        &self,
        ctx: &GpuContext,
        encoder: &mut wgpu::CommandEncoder,
        input: &TrochoidInput<'_>,
        target: &TrochoidTarget,
        timer: Option<&GpuTimer>,
    ) -> Result<(), GpuError> {
        let waves = input.waves;
        let p = self.prepare(ctx, waves, input.grid, input.time)?;
        target.check(p.points)?;
        let device = ctx.device();
        crate::scoped(device, || {
            let init = |label, contents: &[u8], usage| {
                device.create_buffer_init(&wgpu::util::BufferInitDescriptor {
                    label: Some(label),
                    contents,
                    usage,
                })
            };
            let params = init(
                "ocean trochoid params",
                bytemuck::bytes_of(&p.params),
                wgpu::BufferUsages::UNIFORM,
            );
            let coeffs = init(
                "ocean trochoid coefficients",
                bytemuck::cast_slice(waves.coeffs()),
                wgpu::BufferUsages::STORAGE,
            );
            let phases = init(
                "ocean trochoid phases",
                bytemuck::cast_slice(&p.phases),
                wgpu::BufferUsages::STORAGE,
            );
            let out_size = wgpu::BufferSize::new(p.points * OUTPUT_STRIDE);
            let bind_group = device.create_bind_group(&wgpu::BindGroupDescriptor {
                label: Some("ocean trochoid bind group"),
                layout: &self.layout,
                entries: &[
                    wgpu::BindGroupEntry {
                        binding: 0,
                        resource: params.as_entire_binding(),
                    },
                    wgpu::BindGroupEntry {
                        binding: 1,
                        resource: coeffs.as_entire_binding(),
                    },
                    wgpu::BindGroupEntry {
                        binding: 2,
                        resource: phases.as_entire_binding(),
                    },
                    wgpu::BindGroupEntry {
                        binding: 3,
                        resource: wgpu::BindingResource::Buffer(wgpu::BufferBinding {
                            buffer: &target.positions,
                            offset: 0,
                            size: out_size,
                        }),
                    },
                    wgpu::BindGroupEntry {
                        binding: 4,
                        resource: wgpu::BindingResource::Buffer(wgpu::BufferBinding {
                            buffer: &target.normals,
                            offset: 0,
                            size: out_size,
                        }),
                    },
                ],
            });
            let mut pass = encoder.begin_compute_pass(&wgpu::ComputePassDescriptor {
                label: Some("ocean trochoid"),
                timestamp_writes: timer.map(GpuTimer::compute_pass_writes),
            });
            pass.set_pipeline(&self.pipeline);
            pass.set_bind_group(0, &bind_group, &[]);
            pass.dispatch_workgroups(p.groups.0, p.groups.1, 1);
            Ok(())
        })
    }

    /// Records, submits and returns: the pass writes into `target` (timed when `timer` is
    /// given; read it with [`GpuTimer::read`]).
    pub fn run(
        &self,
        ctx: &GpuContext,
        input: &TrochoidInput<'_>,
        target: &TrochoidTarget,
        timer: Option<&GpuTimer>,
    ) -> Result<(), GpuError> {
        let mut encoder = ctx
            .device()
            .create_command_encoder(&wgpu::CommandEncoderDescriptor {
                label: Some("ocean trochoid"),
            });
        self.encode(ctx, &mut encoder, input, target, timer)?;
        if let Some(timer) = timer {
            timer.resolve(&mut encoder);
        }
        crate::scoped(ctx.device(), || {
            ctx.queue().submit([encoder.finish()]);
            Ok(())
        })
    }

    /// Evaluates `grid` at time `t` on the GPU and reads the result back: the GPU twin of
    /// [`WaveSet::evaluate_grid`] (same layout, positions relative to `grid.origin`), with the
    /// pass's GPU time when the device supports timestamps.
    pub fn evaluate_grid(
        &self,
        ctx: &GpuContext,
        waves: &WaveSet,
        grid: &Grid,
        t: f64,
    ) -> Result<GridOutput, GpuError> {
        let target = TrochoidTarget::new(ctx, grid)?;
        let timer = GpuTimer::new(ctx);
        let input = TrochoidInput {
            waves,
            grid,
            time: t,
        };
        self.run(ctx, &input, &target, timer.as_ref())?;
        let n = grid.point_count()?;
        let to_vec3 = |v: Vec<[f32; 4]>| -> Vec<Vec3> {
            v.into_iter()
                .take(n)
                .map(|p| Vec3::new(p[0], p[1], p[2]))
                .collect()
        };
        let positions = to_vec3(read_buffer_as(ctx, &target.positions)?);
        let normals = to_vec3(read_buffer_as(ctx, &target.normals)?);
        let gpu_time = match &timer {
            Some(t) => t.read(ctx)?,
            None => None,
        };
        Ok(GridOutput {
            positions,
            normals,
            gpu_time,
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn params_match_the_wgsl_struct_size() {
        // WGSL `Params`: five u32, one u32 pad, two f32 = 32 bytes (a multiple of 16, as
        // uniform blocks require).
        assert_eq!(std::mem::size_of::<TrochoidParams>(), 32);
        let b = shaders::get("trochoid").unwrap().bindings().unwrap();
        assert_eq!(b[0].size as usize, std::mem::size_of::<TrochoidParams>());
        assert_eq!(b[0].members.last().unwrap().offset, 28);
    }

    #[test]
    fn dispatch_folds_past_the_dimension_limit() {
        // Below the limit: one row of workgroups.
        assert_eq!(dispatch_shape(1024, 65535).unwrap(), (1024, 1));
        assert_eq!(dispatch_shape(65535, 65535).unwrap(), (65535, 1));
        // One past: two rows; the 65534 surplus groups of the second row exit on the bounds check.
        assert_eq!(dispatch_shape(65536, 65535).unwrap(), (65535, 2));
        // 4096 x 4096 grid = 262144 groups of 64: 5 rows of 65535.
        assert_eq!(dispatch_shape(262_144, 65535).unwrap(), (65535, 5));
        // Small cap: 10 groups at most 4 wide -> 4 x 3 (12 >= 10, the last 2 groups idle).
        assert_eq!(dispatch_shape(10, 4).unwrap(), (4, 3));
        assert_eq!(dispatch_shape(0, 3).unwrap(), (0, 0));
        // More than max^2 groups cannot be dispatched in two dimensions: 10 > 3 x 3.
        assert!(matches!(
            dispatch_shape(10, 3),
            Err(GpuError::TooLarge {
                needed: 10,
                limit: 9,
                ..
            })
        ));
        assert_eq!(dispatch_shape(9, 3).unwrap(), (3, 3));
    }
}
