//! The GPU side of `ocean bench`: the same workloads on the headless wgpu device.

use std::time::Instant;

use ocean_core::{Grid, WaveSet};
use ocean_gpu::layers::LayersInput;
use ocean_gpu::trochoid::TrochoidInput;
use ocean_gpu::{GpuContext, GpuTimer, LayersPass, TrochoidPass, TrochoidTarget, WtbMarchPass};
use ocean_wtb::scene::{Frame, Scene};
use serde_json::{Value, json};

pub struct Bench {
    ctx: GpuContext,
    trochoid: TrochoidPass,
    layers: LayersPass,
}

impl Bench {
    /// The headless context (honouring `WGPU_BACKEND`) and the passes, or why there is none.
    pub fn new() -> Result<Self, String> {
        let ctx = GpuContext::headless().map_err(|e| e.to_string())?;
        let trochoid = TrochoidPass::new(&ctx).map_err(|e| e.to_string())?;
        let layers = LayersPass::new(&ctx).map_err(|e| e.to_string())?;
        Ok(Self {
            ctx,
            trochoid,
            layers,
        })
    }

    pub fn describe(&self) -> String {
        self.ctx.describe()
    }

    pub fn context(&self) -> &GpuContext {
        &self.ctx
    }

    /// Median GPU time of the trochoid pass (timestamps, when the adapter has them) and median
    /// wall time of upload + dispatch + wait, over `runs` runs after two warm-ups.
    pub fn gerstner(&self, set: &WaveSet, grid: &Grid, t: f64, runs: u32) -> Result<Value, String> {
        let e = |e: ocean_gpu::GpuError| e.to_string();
        let target = TrochoidTarget::new(&self.ctx, grid).map_err(e)?;
        let timer = GpuTimer::new(&self.ctx);
        let input = TrochoidInput {
            waves: set,
            grid,
            time: t,
        };
        let (mut kernel, mut wall) = self.timed(runs, timer.as_ref(), |_| {
            self.trochoid
                .run(&self.ctx, &input, &target, timer.as_ref())
        })?;
        Ok(json!({
            "kernel_ms": median(&mut kernel),
            "wall_ms": median(&mut wall),
            "timestamps": timer.is_some(),
        }))
    }

    /// The wave-train-box frame on the GPU: median GPU time of `LayersPass` (timestamps, when
    /// the adapter has them) and median wall time of upload + dispatch + wait, for the
    /// frame's layers and height field, over `runs` runs after two warm-ups.
    pub fn layers(&self, frame: &Frame<'_>, runs: u32) -> Result<Value, String> {
        let e = |e: ocean_gpu::GpuError| e.to_string();
        let grid = frame.grid().grid();
        let target = TrochoidTarget::new(&self.ctx, grid).map_err(e)?;
        let timer = GpuTimer::new(&self.ctx);
        let layers = frame.layers();
        let input = LayersInput {
            grid,
            time: frame.time(),
            layers: &layers,
            height: frame.height_field(),
        };
        let (mut kernel, mut wall) = self.timed(runs, timer.as_ref(), |_| {
            self.layers.run(&self.ctx, &input, &target, timer.as_ref())
        })?;
        Ok(json!({
            "points": grid.size.0 * grid.size.1,
            "kernel_ms": median(&mut kernel),
            "wall_ms": median(&mut wall),
            "timestamps": timer.is_some(),
        }))
    }

    /// The same frame with its rays marched on the GPU (`WtbMarchPass` from the scene's plan):
    /// median wall time of plan + march + evaluation (record, submit, wait), and the median
    /// GPU time of its layers pass (timestamps, when the adapter has them), over `runs` runs
    /// after two warm-ups. The CPU's share is the plan (culling, budget, one descriptor per
    /// ray); the GPU computes the height field (noise, run-up) itself.
    ///
    /// Two figures: `cached`, the steady state of still boxes (the pass reuses their marches;
    /// the marches over warm-ups and timed runs are counted: one per box, in the first
    /// warm-up), and `remarched`,
    /// every box marched again each frame (the cache cleared first), the cost of boxes that
    /// move every frame.
    pub fn march(&self, scene: &Scene, t: f64, runs: u32) -> Result<Value, String> {
        let e = |e: ocean_gpu::GpuError| e.to_string();
        let pass = WtbMarchPass::new(&self.ctx).map_err(e)?;
        let grid = *scene.grid();
        let target = TrochoidTarget::new(&self.ctx, grid.grid()).map_err(e)?;
        let timer = GpuTimer::new(&self.ctx);
        let figure = |remarch: bool| -> Result<Value, String> {
            let before = pass.stats();
            let (mut kernel, mut wall) = self.timed(runs, timer.as_ref(), |_| {
                if remarch {
                    pass.clear_cache();
                }
                let plan = scene.plan(t, None)?;
                let mut encoder = self.ctx.device().create_command_encoder(
                    &ocean_gpu::wgpu::CommandEncoderDescriptor {
                        label: Some("bench wtb march"),
                    },
                );
                pass.encode(
                    &self.ctx,
                    &mut encoder,
                    &grid,
                    scene.terrain(),
                    &plan,
                    &target,
                    timer.as_ref(),
                )?;
                if let Some(timer) = &timer {
                    timer.resolve(&mut encoder);
                }
                self.ctx.queue().submit([encoder.finish()]);
                Ok(())
            })?;
            let after = pass.stats();
            Ok(json!({
                "layers_kernel_ms": median(&mut kernel),
                "wall_ms": median(&mut wall),
                // Over the warm-ups and the timed runs.
                "marches": after.marches - before.marches,
                "reuses": after.reuses - before.reuses,
            }))
        };
        let cached = figure(false)?;
        let remarched = figure(true)?;
        Ok(json!({
            "points": grid.len(),
            "cached": cached,
            "remarched": remarched,
            "timestamps": timer.is_some(),
        }))
    }
}

impl Bench {
    /// The ocean renderer: median GPU time of the render pass (timestamps, when the
    /// adapter has them) and median wall time of record + submit + wait, for one frame of
    /// `surface` under `lighting` seen by `camera` at `size`, over `runs` runs after two
    /// warm-ups. Colour and depth are cleared by a separate pass before each timed one.
    pub fn ocean(
        &self,
        renderer: &ocean_gpu::OceanRenderer,
        camera: &ocean_core::Camera,
        size: (u32, u32),
        runs: u32,
    ) -> Result<Value, String> {
        let device = self.ctx.device();
        let extent = ocean_gpu::wgpu::Extent3d {
            width: size.0,
            height: size.1,
            depth_or_array_layers: 1,
        };
        let texture = |format, label| {
            device.create_texture(&ocean_gpu::wgpu::TextureDescriptor {
                label: Some(label),
                size: extent,
                mip_level_count: 1,
                sample_count: 1,
                dimension: ocean_gpu::wgpu::TextureDimension::D2,
                format,
                usage: ocean_gpu::wgpu::TextureUsages::RENDER_ATTACHMENT,
                view_formats: &[],
            })
        };
        let options = renderer.options();
        let depth_format = options
            .depth_format
            .ok_or("the bench needs a depth format")?;
        let color = texture(options.color_format, "bench colour").create_view(&Default::default());
        let depth = texture(depth_format, "bench depth").create_view(&Default::default());
        let clear_depth = camera.depth().clear_depth() as f32;
        let timer = GpuTimer::new(&self.ctx);
        let (mut pass_ms, mut wall) = self.timed(runs, timer.as_ref(), |i| {
            let mut encoder = device.create_command_encoder(&Default::default());
            encoder.begin_render_pass(&ocean_gpu::wgpu::RenderPassDescriptor {
                label: Some("bench clear"),
                color_attachments: &[Some(ocean_gpu::wgpu::RenderPassColorAttachment {
                    view: &color,
                    depth_slice: None,
                    resolve_target: None,
                    ops: ocean_gpu::wgpu::Operations {
                        load: ocean_gpu::wgpu::LoadOp::Clear(ocean_gpu::wgpu::Color::BLACK),
                        store: ocean_gpu::wgpu::StoreOp::Store,
                    },
                })],
                depth_stencil_attachment: Some(ocean_gpu::wgpu::RenderPassDepthStencilAttachment {
                    view: &depth,
                    depth_ops: Some(ocean_gpu::wgpu::Operations {
                        load: ocean_gpu::wgpu::LoadOp::Clear(clear_depth),
                        store: ocean_gpu::wgpu::StoreOp::Store,
                    }),
                    stencil_ops: None,
                }),
                timestamp_writes: None,
                occlusion_query_set: None,
                multiview_mask: None,
            });
            let t = 10.0 + i as f64 / 60.0;
            match &timer {
                Some(timer) => renderer.render_timed(
                    &self.ctx,
                    &mut encoder,
                    camera,
                    t,
                    &color,
                    Some(&depth),
                    size,
                    timer,
                )?,
                None => renderer.render(
                    &self.ctx,
                    &mut encoder,
                    camera,
                    t,
                    &color,
                    Some(&depth),
                    size,
                )?,
            }
            self.ctx.queue().submit([encoder.finish()]);
            Ok(())
        })?;
        Ok(json!({
            "pass_ms": median(&mut pass_ms),
            "wall_ms": median(&mut wall),
            "timestamps": timer.is_some(),
        }))
    }
}

impl Bench {
    /// Runs `record` (which records and submits one run; its argument is the run's index)
    /// `runs + 2` times, waiting for the GPU after each, and returns the GPU times that `timer`
    /// read (empty without timestamps) and the wall times, in ms, of all but the first two.
    fn timed(
        &self,
        runs: u32,
        timer: Option<&GpuTimer>,
        mut record: impl FnMut(u32) -> Result<(), ocean_gpu::GpuError>,
    ) -> Result<(Vec<f64>, Vec<f64>), String> {
        let e = |e: ocean_gpu::GpuError| e.to_string();
        let mut gpu_ms = Vec::new();
        let mut wall = Vec::new();
        for i in 0..runs + 2 {
            let start = Instant::now();
            record(i).map_err(e)?;
            self.ctx.wait_idle().map_err(e)?;
            let elapsed = start.elapsed().as_secs_f64() * 1e3;
            let gpu = match timer {
                Some(timer) => timer.read(&self.ctx).map_err(e)?,
                None => None,
            };
            if i >= 2 {
                wall.push(elapsed);
                if let Some(d) = gpu {
                    gpu_ms.push(d.ms());
                }
            }
        }
        Ok((gpu_ms, wall))
    }
}

fn median(v: &mut [f64]) -> Option<f64> {
    if v.is_empty() {
        return None;
    }
    v.sort_by(f64::total_cmp);
    Some(v[v.len() / 2])
}
