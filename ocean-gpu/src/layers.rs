//! The layered displacement pass: the GPU twin of [`ocean_core::evaluate_layers`], the
//! evaluation primitive of wave train boxes.
//!
//! A [`Layer`] is a wave set acting on a rectangle of the grid, its contribution at each point
//! of the rectangle multiplied by a complex amplitude μ = m·e^{iφ}, given as
//! `[m cos φ, m sin φ]`: the point's trains are evaluated with amplitude m·Aᵢ and phase θᵢ + φ
//! (wave-train-boxes Eq. 6-7: p = p₀ − Σ k̂ m A sin(θ + φ), y = Σ m A cos(θ + φ)). The factor m
//! carries what scales a box's waves locally (side smoothing, build-up envelope, land, shadow,
//! shoaling), the phase φ what shifts them (depth refraction, round waves). Layers add up where
//! they overlap; outside its rectangle a layer contributes nothing; an optional additive height
//! field (capillary noise, run-up) is added to every height last. The normals treat μ as
//! locally constant, as the CPU does. See the [`ocean_core::layers`] module documentation.
//!
//! The arithmetic is the CPU kernel's, in its order: per layer and wave, sin θ and cos θ by
//! angle addition of the host's row and column tables ([`ocean_core::WaveSet::grid_sin_cos`], phases
//! reduced in `f64`, so neither t = 10⁶ s nor 100 km from the origin degrades the result and
//! the GPU evaluates no sine or cosine), then
//!
//! m sin(θ + φ) = sin θ·(m cos φ) + cos θ·(m sin φ),  m cos(θ + φ) = cos θ·(m cos φ) − sin θ·(m sin φ),
//!
//! accumulated like the trochoid pass's waves, layer after layer, wave after wave; then the
//! height field, the position and the normal (same degenerate-normal rule). On Mesa's software
//! drivers the result is bit-identical to the CPU's.
//!
//! # Buffers
//!
//! Four storage buffers (the WebGPU downlevel per-stage limit) and a uniform block
//! (see `shaders/layers.wgsl`):
//!
//! | binding | contents |
//! |---------|----------|
//! | 0 | uniform [`LayersParams`]: grid size, layer count, dispatch width, height offset, spacing |
//! | 1 | storage, read: one [`LayerDesc`] per layer (its rectangle and word offsets into `data`) |
//! | 2 | storage, read: `data`, `f32` words: per layer its coefficients (8 words a wave) then its sin/cos tables restricted to its rectangle (rows, then columns; 2 words a pair), then each layer's modulation (2 words a rectangle point), then the height field (1 word a grid point) |
//! | 3, 4 | the output positions and normals of a [`TrochoidTarget`] (16 bytes a point, row-major) |
//!
//! The pass keeps its input buffers and rewrites them each run, growing them only when a run
//! needs more room than any before, so a frame loop allocates nothing on the GPU (nor on the
//! host) once its sizes are settled; [`LayersPass::stats`] shows it.

use std::sync::{Mutex, MutexGuard, PoisonError};

use ocean_core::{EvalError, Grid, GridRect, Layer, WaveSet};

pub use ocean_core::gpu_params::{LayerDesc, LayersParams};

use crate::readback::GpuTimer;
use crate::trochoid::{
    OUTPUT_STRIDE, WORKGROUP_SIZE, dispatch_shape, grow_inputs, input_buffer, output_bytes,
};
use crate::{GpuContext, GpuError, GridOutput, TrochoidTarget};

/// What one run of the pass evaluates: layers (and a height field) on a grid at a time; the
/// arguments of [`ocean_core::evaluate_layers`].
#[derive(Clone, Copy, Debug)]
pub struct LayersInput<'a> {
    /// The grid of rest positions.
    pub grid: &'a Grid,
    /// Time in seconds (`f64`: phases are reduced on the host, so any finite time works).
    pub time: f64,
    /// The layers, summed in order.
    pub layers: &'a [Layer<'a>],
    /// An additive height field, one value per grid point (row-major), or `None`.
    pub height: Option<&'a [f32]>,
}

/// A layer whose modulation is already on the GPU (written there by another pass, such as
/// [`crate::WtbMarchPass`]'s ray march): `rect.len()` values `[m cos φ, m sin φ]` (8 bytes
/// each, row-major over `rect`) at byte `offset` of `modulation`, which needs
/// `wgpu::BufferUsages::COPY_SRC`. Unlike a host [`Layer`]'s, these values were not checked for
/// finiteness: the pass that wrote them answers for them.
#[derive(Clone, Copy, Debug)]
pub struct DeviceLayer<'a> {
    /// The waves.
    pub waves: &'a WaveSet,
    /// Where the layer acts.
    pub rect: GridRect,
    /// The buffer holding the modulation.
    pub modulation: &'a wgpu::Buffer,
    /// Byte offset of the first value (a multiple of 4).
    pub offset: u64,
}

/// Where [`LayersPass::encode_device`] finds the additive height field.
#[derive(Clone, Copy, Debug)]
pub enum HeightSource<'a> {
    /// On the host: one finite value per grid point, uploaded by `Queue::write_buffer`.
    Host(&'a [f32]),
    /// On the GPU: one `f32` per grid point from the buffer's start (it needs `COPY_SRC`),
    /// copied in `encoder` before the dispatch. Its values are not checked.
    Device(&'a wgpu::Buffer),
}

/// [`LayersInput`] over host or device layers.
struct Input<'a, L> {
    grid: &'a Grid,
    time: f64,
    layers: &'a [L],
    height: Option<&'a [f32]>,
    /// A height field already on the GPU (instead of `height`).
    device_height: Option<DeviceHeight<'a>>,
}

/// A height field on the GPU: its buffer's size, and the buffer (`None` to validate before the
/// buffer exists).
#[derive(Clone, Copy)]
struct DeviceHeight<'a> {
    size: u64,
    buffer: Option<&'a wgpu::Buffer>,
}

impl<'a> From<&LayersInput<'a>> for Input<'a, Layer<'a>> {
    fn from(i: &LayersInput<'a>) -> Self {
        Self {
            grid: i.grid,
            time: i.time,
            layers: i.layers,
            height: i.height,
            device_height: None,
        }
    }
}

impl<'a, L> Input<'a, L> {
    fn with_source(
        grid: &'a Grid,
        time: f64,
        layers: &'a [L],
        height: Option<HeightSource<'a>>,
    ) -> Self {
        let (height, device_height) = match height {
            None => (None, None),
            Some(HeightSource::Host(h)) => (Some(h), None),
            Some(HeightSource::Device(b)) => (
                None,
                Some(DeviceHeight {
                    size: b.size(),
                    buffer: Some(b),
                }),
            ),
        };
        Self {
            grid,
            time,
            layers,
            height,
            device_height,
        }
    }
}

/// What the pass reads of a layer besides its modulation's values.
trait LayerView {
    fn waves(&self) -> &WaveSet;
    fn rect(&self) -> GridRect;
}

impl LayerView for Layer<'_> {
    fn waves(&self) -> &WaveSet {
        self.waves
    }
    fn rect(&self) -> GridRect {
        Layer::rect(self)
    }
}

impl LayerView for DeviceLayer<'_> {
    fn waves(&self) -> &WaveSet {
        self.waves
    }
    fn rect(&self) -> GridRect {
        self.rect
    }
}

/// A layer's waves and rectangle without its modulation: what [`LayersPass::check_shapes`]
/// validates before a caller records the passes that will write the modulation.
pub(crate) struct LayerShape<'a> {
    pub(crate) waves: &'a WaveSet,
    pub(crate) rect: GridRect,
}

impl LayerView for LayerShape<'_> {
    fn waves(&self) -> &WaveSet {
        self.waves
    }
    fn rect(&self) -> GridRect {
        self.rect
    }
}

/// Counters and capacities of a [`LayersPass`]'s own GPU objects, to check that a frame loop
/// has reached a steady state (no counter moves from one frame to the next).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct LayersStats {
    /// Input buffers created so far: three in [`LayersPass::new`] (uniform block, layer
    /// descriptors, data), then one each time the descriptors or the data outgrow theirs.
    pub buffers_created: u64,
    /// Bind groups created so far: one per target seen (at most [`BIND_GROUP_CACHE`] are
    /// kept), and again for every target after an input buffer grew.
    pub bind_groups_created: u64,
    /// Layers the descriptor buffer holds.
    pub layer_capacity: u64,
    /// `f32` words the data buffer holds (coefficients, tables, modulation, height).
    pub data_capacity: u64,
}

/// Bind groups a [`LayersPass`] keeps (least recently used evicted first).
pub const BIND_GROUP_CACHE: usize = crate::pipeline::BIND_GROUP_CACHE;

/// Initial capacity of the descriptor buffer, in layers.
const INITIAL_LAYERS: u64 = 8;
/// Initial capacity of the data buffer, in words (64 KiB).
const INITIAL_DATA_WORDS: u64 = 16 * 1024;
/// Bytes of one [`LayerDesc`].
const DESC_STRIDE: u64 = std::mem::size_of::<LayerDesc>() as u64;
/// Bytes of one data word.
const WORD: u64 = 4;
/// Words of one wave's coefficients.
const COEFF_WORDS: u64 = (std::mem::size_of::<ocean_core::WaveCoeffs>() / 4) as u64;

/// The checks of [`ocean_core::evaluate_layers`], in its order and with its errors (the output
/// slices it also checks are the pass's target here, checked separately): a finite time, a
/// valid grid, every rectangle inside the grid (the modulations' values were checked when they
/// were built), one finite height per grid point. Returns the grid's point count.
pub fn validate_layers(
    grid: &Grid,
    t: f64,
    layers: &[Layer<'_>],
    height: Option<&[f32]>,
) -> Result<usize, EvalError> {
    validate(grid, t, layers, height)
}

fn validate<L: LayerView>(
    grid: &Grid,
    t: f64,
    layers: &[L],
    height: Option<&[f32]>,
) -> Result<usize, EvalError> {
    if !t.is_finite() {
        return Err(EvalError::Time(t));
    }
    let n = grid.point_count()?;
    for layer in layers {
        if !layer.rect().fits(grid.size) {
            return Err(EvalError::Grid("layer rectangle outside the grid"));
        }
    }
    if let Some(h) = height {
        if h.len() != n {
            return Err(EvalError::Grid(
                "height field must hold one value per grid point",
            ));
        }
        if let Some(index) = h.iter().position(|v| !v.is_finite()) {
            return Err(EvalError::Position { index });
        }
    }
    Ok(n)
}

/// The layered displacement compute pipeline and the input buffers it reuses from run to run:
/// the GPU twin of [`ocean_core::evaluate_layers`] (see the [module documentation](self)).
///
/// Create it once per device. Each [`encode`](Self::encode) writes the inputs (uniform block,
/// layer descriptors, and one data buffer with every layer's wave coefficients, sin/cos tables
/// and modulation, and the height field) with `Queue::write_buffer` into buffers the pass
/// keeps, growing them only when a run needs more than any run before.
///
/// As with [`TrochoidPass`](crate::TrochoidPass), the written inputs take effect at the
/// caller's next `Queue::submit`: one pass holds one set of inputs between two submits.
#[derive(Debug)]
pub struct LayersPass {
    pipeline: wgpu::ComputePipeline,
    layout: wgpu::BindGroupLayout,
    max_groups_per_dim: u32,
    /// The reusable inputs, behind a `Mutex` so one pass can be shared like the wgpu objects
    /// it wraps; `encode` holds it while it writes and records.
    inputs: Mutex<Inputs>,
}

impl LayersPass {
    /// Builds the pipeline on `ctx`'s device.
    pub fn new(ctx: &GpuContext) -> Result<Self, GpuError> {
        let device = ctx.device();
        let (pipeline, layout) = crate::pipeline::displace_pipeline(
            device,
            "layers",
            std::mem::size_of::<LayersParams>(),
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
    pub fn stats(&self) -> LayersStats {
        self.lock_inputs().stats
    }

    /// Checks layers of these shapes, with a device height field of one value per grid point
    /// or none, as [`encode_device`](Self::encode_device) will (the input, the device's
    /// limits, `target`), recording nothing: for a caller that records other passes first and
    /// must not leave them behind when the layers are refused.
    pub(crate) fn check_shapes(
        &self,
        ctx: &GpuContext,
        grid: &Grid,
        time: f64,
        layers: &[LayerShape<'_>],
        device_height: bool,
        target: &TrochoidTarget,
    ) -> Result<(), GpuError> {
        let points = grid.point_count()? as u64;
        let input = Input {
            grid,
            time,
            layers,
            height: None,
            device_height: device_height.then_some(DeviceHeight {
                size: 4 * points,
                buffer: None,
            }),
        };
        let p = self.prepare(ctx, &input)?;
        target.check(p.points)
    }

    /// The inputs, also after a panic in another thread: every field is replaced whole, so a
    /// poisoned lock still guards consistent buffers.
    fn lock_inputs(&self) -> MutexGuard<'_, Inputs> {
        self.inputs.lock().unwrap_or_else(PoisonError::into_inner)
    }

    /// Validates the input as the CPU does, then checks sizes against the shader's u32 indices
    /// and the device limits.
    fn prepare<L: LayerView>(
        &self,
        ctx: &GpuContext,
        input: &Input<'_, L>,
    ) -> Result<Prepared, GpuError> {
        let grid = input.grid;
        let points = validate(grid, input.time, input.layers, input.height)? as u64;
        let (nx, nz) = grid.size;
        let too_large = |what, needed: u64, limit: u64| GpuError::TooLarge {
            what,
            needed,
            limit,
        };
        let u32max = u64::from(u32::MAX);
        if points > u32max {
            return Err(too_large("grid points (u32 index)", points, u32max));
        }
        let layer_count = input.layers.len() as u64;
        let (mut scratch_words, mut modulation_words) = (0u64, 0u64);
        for layer in input.layers {
            let r = layer.rect();
            let w = layer.waves().coeffs().len() as u64;
            // Rectangles lie inside the grid (validated), so these products stay far below
            // u64::MAX.
            scratch_words += w * COEFF_WORDS + 2 * w * (r.nz as u64 + r.nx as u64);
            modulation_words += 2 * r.len() as u64;
        }
        let has_height = input.height.is_some() || input.device_height.is_some();
        if let Some(d) = input.device_height
            && d.size < 4 * points
        {
            return Err(too_large(
                "device height field (bytes: one f32 per grid point)",
                4 * points,
                d.size,
            ));
        }
        let height_words = if has_height { points } else { 0 };
        let data_words = scratch_words + modulation_words + height_words;
        // The shader indexes `data` with u32 word offsets.
        if data_words > u32max {
            return Err(too_large(
                "layer data words (u32 index)",
                data_words,
                u32max,
            ));
        }
        let limits = ctx.device().limits();
        let binding_limit = limits
            .max_storage_buffer_binding_size
            .min(limits.max_buffer_size);
        if data_words * WORD > binding_limit {
            return Err(too_large(
                "layer data buffer (coefficients, tables, modulation, height; bytes)",
                data_words * WORD,
                binding_limit,
            ));
        }
        if layer_count * DESC_STRIDE > binding_limit {
            return Err(too_large(
                "layer descriptor buffer (bytes)",
                layer_count * DESC_STRIDE,
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
            params: LayersParams {
                nx: nx as u32,
                nz: nz as u32,
                layers: layer_count as u32,
                groups_x: groups.0,
                has_height: u32::from(has_height),
                height: if has_height {
                    (scratch_words + modulation_words) as u32
                } else {
                    0
                },
                spacing_x: grid.spacing.x as f32,
                spacing_z: grid.spacing.y as f32,
            },
            groups,
            points,
            scratch_words,
            data_words,
            binding_limit,
        })
    }

    /// Uploads the inputs and records the dispatch into the caller's `encoder`; `timer`, if
    /// given, timestamps the pass (call [`GpuTimer::resolve`] on the encoder afterwards).
    ///
    /// The input is checked as [`ocean_core::evaluate_layers`] checks it (the same
    /// [`EvalError`]s, as [`GpuError::Eval`]), then against the device's limits and `target`;
    /// nothing is written or recorded if anything is invalid.
    ///
    /// The inputs go into the pass's own buffers by `Queue::write_buffer`, so they reach the
    /// GPU with the caller's next `Queue::submit`: submit between two `encode` calls on the
    /// same pass ([`run`](Self::run) submits for you). The buffers grow when a run needs more
    /// than any run before; otherwise nothing is allocated, and the bind group for `target`
    /// comes from a small cache (see [`LayersStats`]).
    pub fn encode(
        &self,
        ctx: &GpuContext,
        encoder: &mut wgpu::CommandEncoder,
        input: &LayersInput<'_>,
        target: &TrochoidTarget,
        timer: Option<&GpuTimer>,
    ) -> Result<(), GpuError> {
        let input = Input::from(input);
        self.encode_with(
            ctx,
            encoder,
            &input,
            target,
            timer,
            |queue, _, data, layer, at| {
                // Modulation straight from the caller's slices (no host copy).
                queue.write_buffer(data, at, bytemuck::cast_slice(layer.modulation.values()));
            },
        )
    }

    /// [`encode`](Self::encode) for layers whose modulations are already on the GPU: each is
    /// copied into the pass's data buffer by a buffer copy recorded in `encoder` before the
    /// dispatch, so a pass that wrote it earlier in the same `encoder` (or an earlier submit)
    /// feeds this one without a round trip through the host.
    ///
    /// # Errors
    ///
    /// As [`encode`](Self::encode); also [`GpuError::TooLarge`] when a layer's modulation
    /// extends past the end of its buffer or its offset is not a multiple of 4.
    #[allow(clippy::too_many_arguments)]
    pub fn encode_device(
        &self,
        ctx: &GpuContext,
        encoder: &mut wgpu::CommandEncoder,
        grid: &Grid,
        time: f64,
        layers: &[DeviceLayer<'_>],
        height: Option<HeightSource<'_>>,
        target: &TrochoidTarget,
        timer: Option<&GpuTimer>,
    ) -> Result<(), GpuError> {
        for layer in layers {
            let bytes = 8 * layer.rect.len() as u64;
            let end = layer.offset.checked_add(bytes);
            if layer.offset % 4 != 0 || end.is_none_or(|e| e > layer.modulation.size()) {
                return Err(GpuError::TooLarge {
                    what: "device layer modulation (bytes past the buffer's start)",
                    needed: end.unwrap_or(u64::MAX),
                    limit: layer.modulation.size(),
                });
            }
        }
        let input = Input::with_source(grid, time, layers, height);
        self.encode_with(
            ctx,
            encoder,
            &input,
            target,
            timer,
            |_, enc, data, layer, at| {
                enc.copy_buffer_to_buffer(
                    layer.modulation,
                    layer.offset,
                    data,
                    at,
                    8 * layer.rect.len() as u64,
                );
            },
        )
    }

    /// The body of both `encode`s: `upload(queue, encoder, data, layer, byte offset)` puts a
    /// layer's modulation into the data buffer.
    fn encode_with<L: LayerView>(
        &self,
        ctx: &GpuContext,
        encoder: &mut wgpu::CommandEncoder,
        input: &Input<'_, L>,
        target: &TrochoidTarget,
        timer: Option<&GpuTimer>,
        upload: impl Fn(&wgpu::Queue, &mut wgpu::CommandEncoder, &wgpu::Buffer, &L, u64),
    ) -> Result<(), GpuError> {
        let p = self.prepare(ctx, input)?;
        target.check(p.points)?;
        let device = ctx.device();
        let mut guard = self.lock_inputs();
        let inputs = &mut *guard;
        inputs.stage(input, &p)?;
        inputs.reserve(device, &p)?;
        let recorded = crate::scoped(device, || {
            let queue = ctx.queue();
            queue.write_buffer(&inputs.params, 0, bytemuck::bytes_of(&p.params));
            if !inputs.desc_scratch.is_empty() {
                queue.write_buffer(&inputs.descs, 0, bytemuck::cast_slice(&inputs.desc_scratch));
            }
            if !inputs.scratch.is_empty() {
                queue.write_buffer(&inputs.data, 0, bytemuck::cast_slice(&inputs.scratch));
            }
            for (layer, desc) in input.layers.iter().zip(&inputs.desc_scratch) {
                if layer.rect().is_empty() {
                    continue;
                }
                upload(
                    queue,
                    encoder,
                    &inputs.data,
                    layer,
                    u64::from(desc.modulation) * WORD,
                );
            }
            if let Some(h) = input.height {
                queue.write_buffer(
                    &inputs.data,
                    u64::from(p.params.height) * WORD,
                    bytemuck::cast_slice(h),
                );
            }
            if let Some(b) = input.device_height.and_then(|d| d.buffer) {
                encoder.copy_buffer_to_buffer(
                    b,
                    0,
                    &inputs.data,
                    u64::from(p.params.height) * WORD,
                    p.points * WORD,
                );
            }
            let bind_group =
                inputs.bind_group(device, &self.layout, target, p.points * OUTPUT_STRIDE);
            let mut pass = encoder.begin_compute_pass(&wgpu::ComputePassDescriptor {
                label: Some("ocean layers"),
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
        input: &LayersInput<'_>,
        target: &TrochoidTarget,
        timer: Option<&GpuTimer>,
    ) -> Result<(), GpuError> {
        crate::trochoid::submit(ctx, "ocean layers", timer, |encoder| {
            self.encode(ctx, encoder, input, target, timer)
        })
    }

    /// Evaluates `layers` (plus `height`) on `grid` at time `t` on the GPU and reads the result
    /// back: the GPU twin of [`ocean_core::evaluate_layers`] (same layout, positions relative
    /// to `grid.origin`), with the pass's GPU time when the device supports timestamps.
    ///
    /// A one-off query: it allocates the output and readback buffers each call and waits for
    /// the GPU. A frame loop keeps a [`TrochoidTarget`] and calls [`run`](Self::run) or
    /// [`encode`](Self::encode).
    pub fn evaluate(
        &self,
        ctx: &GpuContext,
        grid: &Grid,
        t: f64,
        layers: &[Layer<'_>],
        height: Option<&[f32]>,
    ) -> Result<GridOutput, GpuError> {
        let input = LayersInput {
            grid,
            time: t,
            layers,
            height,
        };
        // Validate before allocating the target, so bad input costs no GPU allocation.
        self.prepare(ctx, &Input::from(&input))?;
        let target = TrochoidTarget::new(ctx, grid)?;
        let timer = GpuTimer::new(ctx);
        self.run(ctx, &input, &target, timer.as_ref())?;
        target.read(ctx, grid.point_count()?, timer.as_ref())
    }
}

mod upload;
use upload::{Inputs, Prepared};

#[cfg(test)]
mod tests;
