//! The trochoid displacement pass: the GPU twin of [`ocean_core::WaveSet::evaluate_grid`].
//!
//! For each point of a [`Grid`] it sums the waves of a [`WaveSet`] (wave-train-boxes Eq. 6-7:
//! p = p₀ − Σ k̂ A sin θ, y = Σ A cos θ) and writes the displaced position and the unit normal
//! from the analytic derivatives, with the same `f32` arithmetic as the CPU kernel (the same
//! angle-addition products, the same order of accumulation, the same degenerate-normal rule).
//!
//! Phases never reach the GPU unreduced, and the GPU evaluates no sine or cosine: the phase at
//! (i, j) is a row part R plus a column part C, which [`WaveSet::grid_sin_cos`] forms in `f64`
//! on the host, reduces to [-π, π] and turns into [sin, cos] tables (per wave and row, per wave
//! and column). The shader combines them as sin θ = sin R cos C + cos R sin C and
//! cos θ = cos R cos C − sin R sin C, exactly as the CPU kernel does, so the result neither
//! degrades at t = 10⁶ s or 100 km from the origin nor depends on the GPU's `sin`/`cos`.
//!
//! Inputs live in buffers the [`TrochoidPass`] keeps and rewrites each run (grown only when a
//! run needs more room), so a frame loop allocates nothing on the GPU in steady state.
//!
//! Output layout (see `shaders/trochoid.wgsl`): two buffers of `nx · nz` × 16 bytes, row-major
//! (point (i, j) at index `j · nx + i`); positions `(x, y, z, 1)` relative to the grid origin,
//! normals `(nx, ny, nz, 0)`; metres, right-handed, y up. Buffers made by
//! [`TrochoidTarget::new`] are also `VERTEX` buffers (`Float32x4`, or `Float32x3` with a
//! 16-byte stride) and `COPY_SRC`.

use std::sync::{Mutex, MutexGuard, PoisonError};

use glam::Vec3;
use ocean_core::{Grid, WaveCoeffs, WaveSet};

pub use ocean_core::gpu_params::TrochoidParams;

use crate::readback::{GpuDuration, GpuTimer, read_buffer_as};
use crate::{GpuContext, GpuError};

/// Invocations per workgroup (`@workgroup_size(64)` in the WGSL).
pub const WORKGROUP_SIZE: u32 = 64;

/// Bytes per output element (one `vec4<f32>`).
pub const OUTPUT_STRIDE: u64 = 16;

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
            what: "compute dispatch (workgroups)",
            needed: u64::from(groups),
            limit: u64::from(max) * u64::from(max),
        });
    }
    Ok((x, y))
}

/// Output buffers for a grid: positions and normals, 16 bytes per point. Both
/// [`TrochoidPass`] and [`LayersPass`](crate::LayersPass) write into them.
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

    pub(crate) fn check(&self, points: u64) -> Result<(), GpuError> {
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

pub(crate) fn output_bytes(device: &wgpu::Device, points: u64) -> Result<u64, GpuError> {
    let size = points * OUTPUT_STRIDE;
    let limits = device.limits();
    let limit = limits
        .max_storage_buffer_binding_size
        .min(limits.max_buffer_size);
    if size > limit {
        return Err(GpuError::TooLarge {
            what: "output buffer (16 bytes per grid point)",
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

/// The trochoid compute pipeline and the input buffers it reuses from run to run.
///
/// Create it once per device. Each [`encode`](Self::encode) writes the inputs (uniform block,
/// wave coefficients, sin/cos tables) with `Queue::write_buffer` into buffers the pass keeps,
/// growing them only when a run needs more waves or a larger grid than any before it, so a frame
/// loop allocates nothing on the GPU once its sizes are settled ([`stats`](Self::stats) shows it).
///
/// As with any wgpu renderer that owns its uniforms, the written inputs take effect at the
/// caller's next `Queue::submit`: one pass holds one set of inputs between two submits.
#[derive(Debug)]
pub struct TrochoidPass {
    pipeline: wgpu::ComputePipeline,
    layout: wgpu::BindGroupLayout,
    max_groups_per_dim: u32,
    /// The reusable inputs. A `Mutex` rather than `&mut self`, so one pass can be shared (for
    /// instance behind an `Arc`) like the wgpu objects it wraps; `encode` holds it while it
    /// writes and records.
    inputs: Mutex<Inputs>,
}

/// Counters and capacities of a [`TrochoidPass`]'s own GPU objects, to check that a frame loop
/// has reached a steady state (no counter moves from one frame to the next).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct TrochoidStats {
    /// Input buffers created so far: three in [`TrochoidPass::new`] (uniform block,
    /// coefficients, tables), then one each time the coefficients or the tables outgrow theirs.
    pub buffers_created: u64,
    /// Bind groups created so far: one per target seen (at most [`BIND_GROUP_CACHE`] are kept),
    /// and again for every target after an input buffer grew.
    pub bind_groups_created: u64,
    /// Waves the coefficient buffer holds.
    pub wave_capacity: u64,
    /// [sin, cos] pairs the table buffer holds; a run needs waves · (nx + nz).
    pub table_capacity: u64,
}

/// Bind groups a [`TrochoidPass`] keeps (the least recently used is evicted first): enough for
/// a few targets used in turn (levels of detail, double buffering) without rebuilding them every
/// frame. A cached bind group keeps its target's buffers alive until it is evicted.
pub const BIND_GROUP_CACHE: usize = crate::pipeline::BIND_GROUP_CACHE;

/// Initial capacity of the coefficient buffer, in waves.
const INITIAL_WAVES: u64 = 16;
/// Initial capacity of the table buffer, in [sin, cos] pairs (16 waves on a 128 x 128 grid).
const INITIAL_TABLE_PAIRS: u64 = 16 * 256;
/// Bytes of one wave's coefficients (WGSL `WaveCoeffs`).
const COEFF_STRIDE: u64 = std::mem::size_of::<WaveCoeffs>() as u64;
/// Bytes of one [sin, cos] pair (WGSL `vec2<f32>`).
const PAIR_STRIDE: u64 = 8;

/// The input buffers of a pass, with a host staging area for the tables and the bind groups
/// built on them.
#[derive(Debug)]
struct Inputs {
    params: wgpu::Buffer,
    coeffs: wgpu::Buffer,
    tables: wgpu::Buffer,
    /// Rows then columns, as uploaded to `tables`; kept to avoid a host allocation per run.
    scratch: Vec<[f32; 2]>,
    /// Least recently used first.
    bind_groups: crate::pipeline::BindGroupCache,
    stats: TrochoidStats,
}

/// Everything one dispatch needs besides the tables, checked on the host.
struct Prepared {
    params: TrochoidParams,
    groups: (u32, u32),
    points: u64,
    /// [sin, cos] pairs in the tables: waves · (nz + nx).
    table_pairs: u64,
    /// Largest binding the device allows, bytes.
    binding_limit: u64,
}

/// The size of a buffer that must hold `needed` bytes and now holds `current`: at least double,
/// so a slowly growing grid reallocates O(log n) times, but never past the binding limit (which
/// `needed` is known to respect).
pub(crate) fn grown_size(current: u64, needed: u64, limit: u64) -> u64 {
    needed.max(current.saturating_mul(2).min(limit))
}

/// Replaces each of `buffers` (a buffer, the bytes it must hold, its label) that is smaller than
/// it must be by a storage buffer of [`grown_size`]. Contents are not copied: every run rewrites
/// its inputs. The new buffers are created inside one error scope and installed only if all
/// succeed, so an out-of-memory failure leaves the old, valid ones. Returns which were
/// replaced; cached bind groups that refer to a replaced buffer must be dropped by the caller.
pub(crate) fn grow_inputs<const N: usize>(
    device: &wgpu::Device,
    mut buffers: [(&mut wgpu::Buffer, u64, &str); N],
    binding_limit: u64,
) -> Result<[bool; N], GpuError> {
    let grow = buffers.each_ref().map(|(b, needed, _)| *needed > b.size());
    if !grow.contains(&true) {
        return Ok(grow);
    }
    let mut new = crate::scoped(device, || {
        let mut new: [Option<wgpu::Buffer>; N] = std::array::from_fn(|_| None);
        for (k, (b, needed, label)) in buffers.iter().enumerate() {
            if grow[k] {
                let size = grown_size(b.size(), *needed, binding_limit);
                new[k] = Some(input_buffer(
                    device,
                    label,
                    size,
                    wgpu::BufferUsages::STORAGE,
                ));
            }
        }
        Ok(new)
    })?;
    for ((b, _, _), n) in buffers.iter_mut().zip(new.iter_mut()) {
        if let Some(n) = n.take() {
            **b = n;
        }
    }
    Ok(grow)
}

pub(crate) fn input_buffer(
    device: &wgpu::Device,
    label: &str,
    size: u64,
    usage: wgpu::BufferUsages,
) -> wgpu::Buffer {
    device.create_buffer(&wgpu::BufferDescriptor {
        label: Some(label),
        size,
        usage: usage | wgpu::BufferUsages::COPY_DST,
        mapped_at_creation: false,
    })
}

impl Inputs {
    fn new(device: &wgpu::Device) -> Self {
        let storage = wgpu::BufferUsages::STORAGE;
        Self {
            params: input_buffer(
                device,
                "ocean trochoid params",
                std::mem::size_of::<TrochoidParams>() as u64,
                wgpu::BufferUsages::UNIFORM,
            ),
            coeffs: input_buffer(
                device,
                "ocean trochoid coefficients",
                INITIAL_WAVES * COEFF_STRIDE,
                storage,
            ),
            tables: input_buffer(
                device,
                "ocean trochoid sin/cos tables",
                INITIAL_TABLE_PAIRS * PAIR_STRIDE,
                storage,
            ),
            scratch: Vec::new(),
            bind_groups: Default::default(),
            stats: TrochoidStats {
                buffers_created: 3,
                bind_groups_created: 0,
                wave_capacity: INITIAL_WAVES,
                table_capacity: INITIAL_TABLE_PAIRS,
            },
        }
    }

    /// Replaces the coefficient and table buffers that are too small for `p` (their contents
    /// are rewritten by every run, so nothing is copied). Cached bind groups refer to the old
    /// buffers and are dropped with them.
    fn reserve(&mut self, device: &wgpu::Device, p: &Prepared) -> Result<(), GpuError> {
        let waves = u64::from(p.params.waves);
        let [coeffs, tables] = grow_inputs(
            device,
            [
                (
                    &mut self.coeffs,
                    waves * COEFF_STRIDE,
                    "ocean trochoid coefficients",
                ),
                (
                    &mut self.tables,
                    p.table_pairs * PAIR_STRIDE,
                    "ocean trochoid sin/cos tables",
                ),
            ],
            p.binding_limit,
        )?;
        if coeffs {
            self.stats.wave_capacity = self.coeffs.size() / COEFF_STRIDE;
            self.stats.buffers_created += 1;
        }
        if tables {
            self.stats.table_capacity = self.tables.size() / PAIR_STRIDE;
            self.stats.buffers_created += 1;
        }
        if !coeffs && !tables {
            return Ok(());
        }
        self.bind_groups.clear();
        Ok(())
    }

    /// The bind group of the current input buffers and `target`, from the cache or new.
    fn bind_group(
        &mut self,
        device: &wgpu::Device,
        layout: &wgpu::BindGroupLayout,
        target: &TrochoidTarget,
        out_size: u64,
    ) -> wgpu::BindGroup {
        let (group, created) = self.bind_groups.get(
            device,
            layout,
            "ocean trochoid bind group",
            [&self.params, &self.coeffs, &self.tables],
            target,
            out_size,
        );
        if created {
            self.stats.bind_groups_created += 1;
        }
        group
    }
}

impl TrochoidPass {
    /// Builds the pipeline on `ctx`'s device.
    pub fn new(ctx: &GpuContext) -> Result<Self, GpuError> {
        let device = ctx.device();
        let (pipeline, layout) = crate::pipeline::displace_pipeline(
            device,
            "trochoid",
            std::mem::size_of::<TrochoidParams>(),
        )?;
        Ok(Self {
            pipeline,
            layout,
            max_groups_per_dim: device.limits().max_compute_workgroups_per_dimension,
            inputs: Mutex::new(Inputs::new(device)),
        })
    }

    /// Caps the workgroups per dispatch dimension below the device limit (at least 1), so the
    /// folding of large grids into two dimensions can be exercised on small ones.
    pub fn with_max_workgroups_per_dimension(mut self, max: u32) -> Self {
        self.max_groups_per_dim = max.clamp(1, self.max_groups_per_dim);
        self
    }

    /// The counters and capacities of the pass's own buffers and bind groups.
    pub fn stats(&self) -> TrochoidStats {
        self.lock_inputs().stats
    }

    /// The inputs, also after a panic in another thread: every field is replaced whole, so a
    /// poisoned lock still guards consistent buffers.
    fn lock_inputs(&self) -> MutexGuard<'_, Inputs> {
        self.inputs.lock().unwrap_or_else(PoisonError::into_inner)
    }

    /// Checks sizes against the shader's u32 indices and the device limits; time is checked
    /// by [`WaveSet::grid_sin_cos`].
    fn prepare(
        &self,
        ctx: &GpuContext,
        waves: &WaveSet,
        grid: &Grid,
    ) -> Result<Prepared, GpuError> {
        let points = grid.point_count()? as u64;
        let (nx, nz) = grid.size;
        let w = waves.coeffs().len() as u64;
        let too_large = |what, needed: u64, limit: u64| GpuError::TooLarge {
            what,
            needed,
            limit,
        };
        let u32max = u64::from(u32::MAX);
        // The shader indexes points and tables with u32.
        if points > u32max {
            return Err(too_large("grid points (u32 index)", points, u32max));
        }
        let table_pairs = w * (nz as u64 + nx as u64);
        if table_pairs > u32max {
            return Err(too_large(
                "sin/cos table entries (u32 index)",
                table_pairs,
                u32max,
            ));
        }
        let limits = ctx.device().limits();
        let binding_limit = limits
            .max_storage_buffer_binding_size
            .min(limits.max_buffer_size);
        let coeff_bytes = w * COEFF_STRIDE;
        if coeff_bytes > binding_limit {
            return Err(too_large(
                "wave coefficient buffer (bytes)",
                coeff_bytes,
                binding_limit,
            ));
        }
        if table_pairs * PAIR_STRIDE > binding_limit {
            return Err(too_large(
                "sin/cos table buffer (bytes)",
                table_pairs * PAIR_STRIDE,
                binding_limit,
            ));
        }
        output_bytes(ctx.device(), points)?;
        let groups = points.div_ceil(u64::from(WORKGROUP_SIZE));
        let groups = dispatch_shape(
            u32::try_from(groups).map_err(|_| too_large("workgroups", groups, u32max))?,
            self.max_groups_per_dim,
        )?;
        Ok(Prepared {
            params: TrochoidParams {
                nx: nx as u32,
                nz: nz as u32,
                waves: w as u32,
                cols_offset: (w * nz as u64) as u32,
                groups_x: groups.0,
                _pad: 0,
                spacing_x: grid.spacing.x as f32,
                spacing_z: grid.spacing.y as f32,
            },
            groups,
            points,
            table_pairs,
            binding_limit,
        })
    }

    /// Uploads the inputs (waves, grid, time) and records the dispatch into the caller's
    /// `encoder`. `timer`, if given, timestamps the pass (call [`GpuTimer::resolve`] on the
    /// encoder afterwards).
    ///
    /// The inputs go into the pass's own buffers by `Queue::write_buffer`, so they reach the GPU
    /// with the caller's next `Queue::submit`, ahead of the commands submitted then. Hence
    /// submit between two `encode` calls on the same pass: both dispatches of a doubly encoded
    /// pass would see the inputs of the second call (use one pass per dispatch to evaluate
    /// several inputs in one submission). [`run`](Self::run) submits for you.
    ///
    /// The buffers grow when a run needs more than any run before; otherwise nothing is
    /// allocated on the GPU, and the bind group for `target` comes from a small cache
    /// (see [`TrochoidStats`]).
    ///
    /// Nothing is written or recorded if an argument is invalid.
    pub fn encode(
        &self,
        ctx: &GpuContext,
        encoder: &mut wgpu::CommandEncoder,
        input: &TrochoidInput<'_>,
        target: &TrochoidTarget,
        timer: Option<&GpuTimer>,
    ) -> Result<(), GpuError> {
        let waves = input.waves;
        let p = self.prepare(ctx, waves, input.grid)?;
        target.check(p.points)?;
        let device = ctx.device();
        let mut guard = self.lock_inputs();
        let inputs = &mut *guard;
        // Tables first: a bad time fails here, before anything is written to the GPU.
        inputs.scratch.clear();
        inputs.scratch.resize(p.table_pairs as usize, [0.0; 2]);
        let (rows, cols) = inputs.scratch.split_at_mut(p.params.cols_offset as usize);
        waves.grid_sin_cos(input.grid, input.time, rows, cols)?;
        inputs.reserve(device, &p)?;
        let recorded = crate::scoped(device, || {
            let queue = ctx.queue();
            queue.write_buffer(&inputs.params, 0, bytemuck::bytes_of(&p.params));
            queue.write_buffer(&inputs.coeffs, 0, bytemuck::cast_slice(waves.coeffs()));
            queue.write_buffer(&inputs.tables, 0, bytemuck::cast_slice(&inputs.scratch));
            let bind_group =
                inputs.bind_group(device, &self.layout, target, p.points * OUTPUT_STRIDE);
            let mut pass = encoder.begin_compute_pass(&wgpu::ComputePassDescriptor {
                label: Some("ocean trochoid"),
                timestamp_writes: timer.map(GpuTimer::compute_pass_writes),
            });
            pass.set_pipeline(&self.pipeline);
            pass.set_bind_group(0, &bind_group, &[]);
            pass.dispatch_workgroups(p.groups.0, p.groups.1, 1);
            Ok(())
        });
        if recorded.is_err() {
            // A bind group created under a validation error is invalid: never reuse it.
            inputs.bind_groups.clear();
        }
        recorded
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
        submit(ctx, "ocean trochoid", timer, |encoder| {
            self.encode(ctx, encoder, input, target, timer)
        })
    }

    /// Evaluates `grid` at time `t` on the GPU and reads the result back: the GPU twin of
    /// [`WaveSet::evaluate_grid`] (same layout, positions relative to `grid.origin`), with the
    /// pass's GPU time when the device supports timestamps.
    ///
    /// A one-off query: it allocates the output and readback buffers each call and waits for
    /// the GPU. A frame loop keeps a [`TrochoidTarget`] and calls [`run`](Self::run) or
    /// [`encode`](Self::encode).
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
        target.read(ctx, grid.point_count()?, timer.as_ref())
    }
}

/// Records a pass with `record` into a new encoder, resolves `timer`'s queries, and submits:
/// the `run` of every pass.
pub(crate) fn submit(
    ctx: &GpuContext,
    label: &str,
    timer: Option<&GpuTimer>,
    record: impl FnOnce(&mut wgpu::CommandEncoder) -> Result<(), GpuError>,
) -> Result<(), GpuError> {
    let mut encoder = ctx
        .device()
        .create_command_encoder(&wgpu::CommandEncoderDescriptor { label: Some(label) });
    record(&mut encoder)?;
    if let Some(timer) = timer {
        timer.resolve(&mut encoder);
    }
    crate::scoped(ctx.device(), || {
        ctx.queue().submit([encoder.finish()]);
        Ok(())
    })
}

impl TrochoidTarget {
    /// Reads the first `n` points back (positions and normals, as `Vec3`) with the pass's GPU
    /// time from `timer`: the one-off readback of every pass's `evaluate`. Waits for the GPU.
    pub fn read(
        &self,
        ctx: &GpuContext,
        n: usize,
        timer: Option<&GpuTimer>,
    ) -> Result<GridOutput, GpuError> {
        let to_vec3 = |v: Vec<[f32; 4]>| -> Vec<Vec3> {
            v.into_iter()
                .take(n)
                .map(|p| Vec3::new(p[0], p[1], p[2]))
                .collect()
        };
        let positions = to_vec3(read_buffer_as(ctx, &self.positions)?);
        let normals = to_vec3(read_buffer_as(ctx, &self.normals)?);
        let gpu_time = match timer {
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
        let b = crate::shaders::get("trochoid").unwrap().bindings().unwrap();
        assert_eq!(b[0].size as usize, std::mem::size_of::<TrochoidParams>());
        assert_eq!(b[0].members.last().unwrap().offset, 28);
    }

    #[test]
    fn buffers_grow_geometrically_up_to_the_binding_limit() {
        // At least double, so n growing by one each run reallocates O(log n) times.
        assert_eq!(grown_size(4096, 4104, 1 << 27), 8192);
        // A jump past double takes exactly what is needed.
        assert_eq!(grown_size(4096, 100_000, 1 << 27), 100_000);
        // Doubling stops at the limit; what is needed (<= limit, checked before) always fits.
        assert_eq!(grown_size(100 << 20, (100 << 20) + 8, 128 << 20), 128 << 20);
        assert_eq!(grown_size(u64::MAX / 2 + 1, 16, 1 << 27), 1 << 27);
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
