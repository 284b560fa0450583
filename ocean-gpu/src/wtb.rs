//! Wave train boxes marched on the GPU: the twin of `ocean_wtb::march::MarchBox::march` and
//! `MarchBox::time_modulation`, feeding [`LayersPass`].
//!
//! [`ocean_wtb::scene::Scene::plan`] does on the CPU what is cheap and sequential (the boxes'
//! lifecycles, frustum culling, the budget, one descriptor per wave ray); this pass does the
//! rest on the GPU, one invocation per wave ray for the march (paper §2: the rays are
//! independent), then per grid point for the land factor's smoothing, the time-dependent
//! effects, the height-only terms and the evaluation of every box's trains
//! (`shaders/wtb_march.wgsl`, `shaders/wtb_height.wgsl`, then the layers pass):
//!
//! | dispatch | over | does |
//! |---|---|---|
//! | `clear` | box rectangle | zero the modulation, land factor 0 on land and 1 elsewhere |
//! | `march` | wave rays | the quadrant scan (exact, the CPU's integers), land, recovery behind land (Fig. 5), shoaling, beach cap, side fades (Fig. 4), refraction lag (Fig. 6), round waves (Eq. 10) |
//! | `erode_x`, `erode_z`, `mean_x`, `mean_z` | box rectangle | the land factor's smoothing (`ocean_wtb::shore`) |
//! | `combine` | box rectangle | modulation · land factor, irregular height (Eq. 8), dispersion refraction (Eq. 4) |
//! | `height_field` | water grid | capillary noise (Eq. 9: the CPU's SplitMix64 rates, phases in exact turns) and the beach run-up |
//! | layers | water grid | every box's trains with its modulation, plus the height field |
//!
//! The traversal is the CPU's exactly (the same 64-bit integers, `ocean_wtb::FixedTraversal`),
//! so every grid point belongs to the same ray on both sides; the values differ by `f32`
//! rounding only. The dispersion option's phase (ω∞ − ω(D))·t is formed from an `f32` ω(D), so
//! it drifts from the CPU's by about 10⁻⁷·Δω·t rad (smoothly: no jitter, see the shader's
//! `turns`); at t = 1000 s that is below 10⁻⁴ rad. The noise rates are the CPU's `f32` values
//! in turns per second (`ocean_wtb::effects::noise_rate`), so the noise phase does not drift:
//! at t = 10⁶ s the heights stay within 10⁻⁶ m of the CPU's.
//!
//! ## What is kept between calls
//!
//! The pass caches the terrain and each box's static march (everything but `combine`), as the
//! CPU scene caches a still box's modulation: a box is marched again only when its
//! [`MarchBox`](ocean_wtb::march::MarchBox) or the terrain changes (a moving box, a growing
//! one, a new terrain), and an entry unused for [`KEEP_CALLS`] calls is dropped. A march runs
//! in a command buffer of its own, submitted during the call, so the cache never holds a march
//! recorded into an encoder the caller might drop; `combine` and the layers pass go into the
//! caller's encoder. [`WtbMarchPass::stats`] counts marches, reuses and allocations.
//!
//! The pass's buffers are reused from call to call and filled by `Queue::write_buffer`: submit
//! the encoder of one call before making the next.

mod cache;
mod height;
mod params;

use std::sync::{Mutex, MutexGuard, PoisonError};

use ocean_core::Grid;
use ocean_wtb::march::Plan;
use ocean_wtb::{Terrain, WaterGrid};

use crate::layers::{DeviceLayer, HeightSource, LayerShape};
use crate::readback::{GpuTimer, read_buffer_as};
use crate::trochoid::{WORKGROUP_SIZE, dispatch_shape};
use crate::{GpuContext, GpuError, GridOutput, LayersPass, TrochoidTarget};
use cache::{CachedBox, CachedTerrain, MarchCache, Need, PARAMS_SIZE, fits};
pub use cache::{KEEP_CALLS, WtbMarchStats};
use height::HeightBuffers;
pub use height::HeightParams;
use params::{BoxSetup, with_effects};
pub use params::{MAX_TIME, MarchParams};

/// The entry points of `wtb_march.wgsl`, in dispatch order; the last, `combine`, runs every
/// call, the others only when a box is marched.
const ENTRIES: [&str; 7] = [
    "clear", "march", "erode_x", "erode_z", "mean_x", "mean_z", "combine",
];
/// Index of `combine` in [`ENTRIES`].
const COMBINE: usize = 6;

/// The evaluated grid and, per box of the plan, its modulation over its rectangle.
pub type MarchOutput = (GridOutput, Vec<Vec<[f32; 2]>>);

/// The ray march of wave train boxes and the evaluation of their grid on the GPU (see the
/// [module documentation](self)).
#[derive(Debug)]
pub struct WtbMarchPass {
    pipelines: Vec<wgpu::ComputePipeline>,
    layout: wgpu::BindGroupLayout,
    height_pipeline: wgpu::ComputePipeline,
    height_layout: wgpu::BindGroupLayout,
    layers: LayersPass,
    max_groups_per_dim: u32,
    cache: Mutex<MarchCache>,
}

impl WtbMarchPass {
    /// Builds the pipelines on `ctx`'s device.
    pub fn new(ctx: &GpuContext) -> Result<Self, GpuError> {
        let device = ctx.device();
        let (pipelines, layout) = crate::pipeline::compute_pipelines(
            device,
            "wtb_march",
            std::mem::size_of::<MarchParams>(),
            &ENTRIES,
        )?;
        // Uniform block, terrain (read), height field (written).
        let (mut height, height_layout) = crate::pipeline::compute_pipelines_with(
            device,
            "wtb_height",
            std::mem::size_of::<HeightParams>(),
            &[true, false],
            &["height_field"],
        )?;
        Ok(Self {
            pipelines,
            layout,
            height_pipeline: height.remove(0),
            height_layout,
            layers: LayersPass::new(ctx)?,
            max_groups_per_dim: device.limits().max_compute_workgroups_per_dimension,
            cache: Mutex::new(MarchCache::default()),
        })
    }

    /// The cache's counters.
    pub fn stats(&self) -> WtbMarchStats {
        self.lock_cache().stats
    }

    /// Releases every cached march and the terrain's buffer; the next call marches every box
    /// again.
    pub fn clear_cache(&self) {
        self.lock_cache().clear();
    }

    /// The cache, also after a panic in another thread: a call that fails clears it, and every
    /// entry is replaced whole.
    fn lock_cache(&self) -> MutexGuard<'_, MarchCache> {
        self.cache.lock().unwrap_or_else(PoisonError::into_inner)
    }

    /// Records the boxes' time-dependent modulation, the height field (capillary noise, Eq. 9,
    /// and the beach run-up: the twin of `ocean_wtb::scene::Frame::height_field`) and the
    /// grid's evaluation into `encoder`, writing the water grid's positions and normals into
    /// `target`, after marching (in a submit of its own) every box whose march is not cached.
    /// Returns the boxes' modulation buffers, in the plan's order (the cache's own: valid until
    /// the next call; the parity tests read them).
    ///
    /// # Errors
    ///
    /// [`GpuError::Wtb`] for a terrain of another grid or a box the grid cannot hold,
    /// [`GpuError::Eval`] for a time outside `[0, 2³⁶)` s, the layers pass's errors (a
    /// `target` too small, a grid beyond the device's limits); nothing is recorded, submitted
    /// or cached then.
    #[allow(clippy::too_many_arguments)]
    pub fn encode(
        &self,
        ctx: &GpuContext,
        encoder: &mut wgpu::CommandEncoder,
        grid: &WaterGrid,
        terrain: &Terrain,
        plan: &Plan,
        target: &TrochoidTarget,
        timer: Option<&GpuTimer>,
    ) -> Result<Vec<wgpu::Buffer>, GpuError> {
        if terrain.grid() != grid {
            return Err(GpuError::Wtb(ocean_wtb::WtbError::TerrainSize {
                expected: grid.len(),
                got: terrain.grid().len(),
            }));
        }
        if !(0.0..MAX_TIME).contains(&plan.t) {
            return Err(GpuError::Eval(ocean_core::EvalError::Time(plan.t)));
        }
        let shapes: Vec<LayerShape<'_>> = plan
            .boxes
            .iter()
            .map(|b| LayerShape {
                waves: &b.waves,
                rect: b.march.rect,
            })
            .collect();
        let points = grid.len() as u64;
        let height_groups = dispatch_shape(
            u32::try_from(points.div_ceil(u64::from(WORKGROUP_SIZE))).map_err(|_| {
                GpuError::TooLarge {
                    what: "water grid points",
                    needed: points,
                    limit: u64::from(u32::MAX),
                }
            })?,
            self.max_groups_per_dim,
        )?;
        let height = HeightParams::new(plan, terrain, height_groups.0);
        self.layers
            .check_shapes(ctx, grid.grid(), plan.t, &shapes, height.is_some(), target)?;
        let mut cache = self.lock_cache();
        // Decide every box's work before changing anything, so that a refused box leaves the
        // cache as it was.
        let terrain_same = cache.has_terrain(terrain);
        let mut claimed = vec![false; cache.boxes.len()];
        let mut needs = Vec::with_capacity(plan.boxes.len());
        for b in &plan.boxes {
            let (reuse, lend) = cache.lookup(b.id, &b.march, terrain_same, &claimed);
            let need = match reuse {
                Some(n) => Need::Reuse(n),
                None => Need::March(
                    lend,
                    Box::new(BoxSetup::new(
                        grid,
                        terrain,
                        &b.march,
                        self.max_groups_per_dim,
                    )?),
                ),
            };
            if let Some(n) = reuse.or(lend) {
                claimed[n] = true;
            }
            needs.push(need);
        }
        let result = crate::scoped(ctx.device(), || {
            self.record(
                ctx,
                encoder,
                &mut cache,
                grid,
                terrain,
                plan,
                needs,
                height.map(|p| (p, height_groups)),
                target,
                timer,
            )
        });
        if result.is_err() {
            cache.clear();
        }
        result
    }

    /// The mutating half of [`encode`](Self::encode), inside its error scopes.
    #[allow(clippy::too_many_arguments)]
    fn record(
        &self,
        ctx: &GpuContext,
        encoder: &mut wgpu::CommandEncoder,
        cache: &mut MarchCache,
        grid: &WaterGrid,
        terrain: &Terrain,
        plan: &Plan,
        needs: Vec<Need>,
        height: Option<(HeightParams, (u32, u32))>,
        target: &TrochoidTarget,
        timer: Option<&GpuTimer>,
    ) -> Result<Vec<wgpu::Buffer>, GpuError> {
        let device = ctx.device();
        let queue = ctx.queue();
        cache.calls += 1;
        let now = cache.calls;
        let mut created = 0u64;
        let mut buffer = |label: &str, size: u64, usage| {
            created += 1;
            device.create_buffer(&wgpu::BufferDescriptor {
                label: Some(label),
                size: size.max(16),
                usage,
                mapped_at_creation: false,
            })
        };
        let storage = wgpu::BufferUsages::STORAGE | wgpu::BufferUsages::COPY_DST;
        if !cache.has_terrain(terrain) {
            let bytes = 4 * terrain.heights().map_or(1, |h| h.len()) as u64;
            let reuse = cache
                .terrain
                .take()
                .map(|t| t.buffer)
                .filter(|b| b.size() == bytes.max(16));
            let terrain_buffer =
                reuse.unwrap_or_else(|| buffer("ocean wtb terrain", bytes, storage));
            if let Some(h) = terrain.heights() {
                queue.write_buffer(&terrain_buffer, 0, bytemuck::cast_slice(h));
            }
            cache.terrain = Some(CachedTerrain {
                terrain: terrain.clone(),
                buffer: terrain_buffer,
            });
            cache.stats.terrain_uploads += 1;
            // Every march read the old terrain, and the height pass's bind group holds its
            // buffer.
            for e in &mut cache.boxes {
                e.march = None;
            }
            cache.height = None;
        }
        let terrain_buffer = cache
            .terrain
            .as_ref()
            .map(|t| t.buffer.clone())
            .expect("the terrain was just cached");
        let mut marches = device.create_command_encoder(&wgpu::CommandEncoderDescriptor {
            label: Some("ocean wtb march"),
        });
        let mut order = Vec::with_capacity(needs.len());
        for (need, b) in needs.into_iter().zip(&plan.boxes) {
            let n = match need {
                Need::Reuse(n) => {
                    cache.stats.reuses += 1;
                    n
                }
                Need::March(lend, setup) => {
                    let setup = *setup;
                    let old = lend.map(|n| &cache.boxes[n]);
                    let keep = old.filter(|e| fits(e, &setup));
                    let (uniform, statics, work, modulation) = match keep {
                        Some(e) => (
                            e.uniform.clone(),
                            e.statics.clone(),
                            e.work.clone(),
                            e.modulation.clone(),
                        ),
                        None => (
                            buffer(
                                "ocean wtb march params",
                                PARAMS_SIZE,
                                wgpu::BufferUsages::UNIFORM | wgpu::BufferUsages::COPY_DST,
                            ),
                            buffer(
                                "ocean wtb march statics",
                                4 * setup.statics.len() as u64,
                                storage,
                            ),
                            buffer(
                                "ocean wtb march work",
                                16 * setup.points,
                                wgpu::BufferUsages::STORAGE,
                            ),
                            buffer(
                                "ocean wtb modulation",
                                8 * setup.points,
                                wgpu::BufferUsages::STORAGE | wgpu::BufferUsages::COPY_SRC,
                            ),
                        ),
                    };
                    queue.write_buffer(&statics, 0, bytemuck::cast_slice(&setup.statics));
                    queue.write_buffer(
                        &uniform,
                        0,
                        bytemuck::bytes_of(&with_effects(&setup.params, plan)),
                    );
                    let bind_group = bind_group(
                        device,
                        &self.layout,
                        &[&uniform, &statics, &terrain_buffer, &work, &modulation],
                    );
                    {
                        let mut pass = marches.begin_compute_pass(&wgpu::ComputePassDescriptor {
                            label: Some("ocean wtb march"),
                            timestamp_writes: None,
                        });
                        pass.set_bind_group(0, &bind_group, &[]);
                        for (k, pipeline) in self.pipelines[..COMBINE].iter().enumerate() {
                            let filter = (2..6).contains(&k);
                            if filter && setup.params.radius == 0 {
                                continue;
                            }
                            let (gx, gy) = if k == 1 {
                                setup.ray_groups
                            } else {
                                setup.groups
                            };
                            pass.set_pipeline(pipeline);
                            pass.dispatch_workgroups(gx, gy, 1);
                        }
                    }
                    let entry = CachedBox {
                        id: b.id,
                        march: Some(b.march.clone()),
                        setup,
                        uniform,
                        statics,
                        work,
                        modulation,
                        bind_group,
                        last_used: now,
                    };
                    cache.stats.marches += 1;
                    match lend {
                        Some(n) => {
                            cache.boxes[n] = entry;
                            n
                        }
                        None => {
                            cache.boxes.push(entry);
                            cache.boxes.len() - 1
                        }
                    }
                }
            };
            order.push(n);
        }
        // The marches reach the queue before anything the caller submits with `encoder`.
        queue.submit([marches.finish()]);
        {
            let mut pass = encoder.begin_compute_pass(&wgpu::ComputePassDescriptor {
                label: Some("ocean wtb combine"),
                timestamp_writes: None,
            });
            pass.set_pipeline(&self.pipelines[COMBINE]);
            for &n in &order {
                let e = &mut cache.boxes[n];
                e.last_used = now;
                queue.write_buffer(
                    &e.uniform,
                    0,
                    bytemuck::bytes_of(&with_effects(&e.setup.params, plan)),
                );
                pass.set_bind_group(0, &e.bind_group, &[]);
                pass.dispatch_workgroups(e.setup.groups.0, e.setup.groups.1, 1);
            }
        }
        let height_field = match height {
            Some((params, groups)) => {
                let points = grid.len() as u64;
                let reuse = cache.height.take().filter(|h| h.points == points);
                let h = match reuse {
                    Some(h) => h,
                    None => {
                        let uniform = buffer(
                            "ocean wtb height params",
                            std::mem::size_of::<HeightParams>() as u64,
                            wgpu::BufferUsages::UNIFORM | wgpu::BufferUsages::COPY_DST,
                        );
                        let output = buffer(
                            "ocean wtb height field",
                            4 * points,
                            wgpu::BufferUsages::STORAGE | wgpu::BufferUsages::COPY_SRC,
                        );
                        let bind_group = bind_group(
                            device,
                            &self.height_layout,
                            &[&uniform, &terrain_buffer, &output],
                        );
                        HeightBuffers {
                            uniform,
                            output,
                            bind_group,
                            points,
                        }
                    }
                };
                queue.write_buffer(&h.uniform, 0, bytemuck::bytes_of(&params));
                let mut pass = encoder.begin_compute_pass(&wgpu::ComputePassDescriptor {
                    label: Some("ocean wtb height field"),
                    timestamp_writes: None,
                });
                pass.set_pipeline(&self.height_pipeline);
                pass.set_bind_group(0, &h.bind_group, &[]);
                pass.dispatch_workgroups(groups.0, groups.1, 1);
                drop(pass);
                let output = h.output.clone();
                cache.height = Some(h);
                Some(output)
            }
            None => None,
        };
        cache.stats.buffers_created += created;
        let modulations: Vec<wgpu::Buffer> = order
            .iter()
            .map(|&n| cache.boxes[n].modulation.clone())
            .collect();
        let layers: Vec<DeviceLayer<'_>> = plan
            .boxes
            .iter()
            .zip(&modulations)
            .map(|(b, m)| DeviceLayer {
                waves: &b.waves,
                rect: b.march.rect,
                modulation: m,
                offset: 0,
            })
            .collect();
        self.layers.encode_device(
            ctx,
            encoder,
            grid.grid(),
            plan.t,
            &layers,
            height_field.as_ref().map(HeightSource::Device),
            target,
            timer,
        )?;
        cache.evict();
        Ok(modulations)
    }

    /// Marches and evaluates `plan` and reads the grid back (positions relative to the grid's
    /// origin, as `Frame::evaluate`), with every box's modulation over its rectangle: a query
    /// that allocates its output and waits, for tests and tools (the marches are cached as in
    /// [`encode`](Self::encode)).
    ///
    /// # Errors
    ///
    /// As [`encode`](Self::encode).
    pub fn evaluate(
        &self,
        ctx: &GpuContext,
        grid: &WaterGrid,
        terrain: &Terrain,
        plan: &Plan,
    ) -> Result<MarchOutput, GpuError> {
        let g: &Grid = grid.grid();
        let target = TrochoidTarget::new(ctx, g)?;
        let timer = GpuTimer::new(ctx);
        let mut modulations = Vec::new();
        crate::trochoid::submit(ctx, "ocean wtb", timer.as_ref(), |encoder| {
            modulations =
                self.encode(ctx, encoder, grid, terrain, plan, &target, timer.as_ref())?;
            Ok(())
        })?;
        let out = target.read(ctx, g.point_count()?, timer.as_ref())?;
        let mut mus = Vec::with_capacity(modulations.len());
        for (m, b) in modulations.iter().zip(&plan.boxes) {
            let mut v: Vec<[f32; 2]> = read_buffer_as(ctx, m)?;
            v.truncate(b.march.rect.len());
            mus.push(v);
        }
        Ok((out, mus))
    }
}

/// A bind group of `buffers` at bindings 0, 1, 2, ….
fn bind_group(
    device: &wgpu::Device,
    layout: &wgpu::BindGroupLayout,
    buffers: &[&wgpu::Buffer],
) -> wgpu::BindGroup {
    let entries: Vec<wgpu::BindGroupEntry<'_>> = buffers
        .iter()
        .enumerate()
        .map(|(binding, b)| wgpu::BindGroupEntry {
            binding: binding as u32,
            resource: b.as_entire_binding(),
        })
        .collect();
    device.create_bind_group(&wgpu::BindGroupDescriptor {
        label: Some("ocean wtb bind group"),
        layout,
        entries: &entries,
    })
}
