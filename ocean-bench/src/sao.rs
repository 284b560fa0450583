//! `ocean bench sao`: the figures of Scalable Ambient Obscurance (McGuire, Mara & Luebke 2012)
//! on the GPU pass (`ocean_gpu::SaoPass`) and its CPU reference (`ocean_sao::Sao`).
//!
//! The scene is ocean-sao's analytic box in a room (`AnalyticView::box_in_room`), rasterised
//! exactly at each input size (reversed-Z `[0, 1]`, infinite far plane, `f32` depth, a 1 rad
//! vertical field of view over the whole input, guard band included) and uploaded once per
//! size as an `R32Float` depth texture; the parameters are `SaoParams::default()` (9 samples,
//! 7 turns, q' = 8, five MIP levels by rotated grid, the appendix's falloff, the plane-weighted
//! blur)
//! unless a figure changes one.
//!
//! 1. **Radius** (the paper's claim: the cost does not depend on the radius): GPU time at
//!    r = 0.25, 1, 4 and 16 m at 1920×1080 (guard band 192 px, as in Table 2), and the ratio of
//!    the slowest to the fastest (target ≤ 1.2).
//! 2. **MIP hierarchy** (Fig. 5): r = 4 m at 1920×1080 with the hierarchy and with every sample
//!    from level 0 (`max_mip = 0`), and the speed-up.
//! 3. **Passes** (Table 3): GPU time of each pass at 1280×720, 1920×1080, 2560×1600 and
//!    3840×2160 with guard bands of 128, 192, 256 and 384 px (Table 3's, and 384 for 4K: the
//!    same ~18% of the height), and the time per visible (output) pixel.
//! 4. **CPU reference**: `Sao::run` at 1920×1080 (guard band 192 px) on all threads.
//! 5. **Quality**: the paper's normals and blur against the defaults (plane-weighted blur,
//!    nearest-neighbour normals), each against the estimator's own 256-sample limit on the
//!    same depth buffer, on the box in a room and on boxes on a floor seen from 12° above,
//!    at 640×360: mean absolute error, MSE and correlation; and on the built-in scene of
//!    `ocean render`, its first frame's depth drawn on the GPU (skipped without a Vulkan
//!    adapter or with `--no-gpu`), against the estimator's limit on that depth buffer.
//!
//! GPU times come from timestamps around each pass where the adapter has them; otherwise each
//! pass is submitted on its own and its wall time (record, submit, wait) is taken, which
//! includes the submission's overhead. Every run also records the wall time of a whole frame
//! (one submission of the five passes, waited for). Figures 1 and 2 run their configurations in
//! turn within each round, so a slow spell of the machine hits them alike. Times are medians of
//! `--runs` runs after one warm-up run.
//!
//! The headless device has WebGPU's downlevel limits except `max_texture_dimension_2d`, which
//! is the adapter's own: the inputs with guard band reach 4608 × 2928 px, beyond the 2048 px of
//! the downlevel defaults.

use std::time::Instant;

use ocean_core::{Camera, DepthConvention, Far, Projection};
use ocean_gpu::{GpuContext, GpuError, SaoPass, SaoStage, SaoTimer, wgpu};
use ocean_sao::analytic::{AnalyticView, DepthFormat};
use ocean_sao::{DepthSource, Sao, SaoParams, Viewport};
use serde_json::{Value, json};

use crate::options::BenchOptions;
use crate::timing::cpu_name;

/// Radii of figure 1, metres.
const RADII: [f32; 4] = [0.25, 1.0, 4.0, 16.0];
/// Radius of figure 2, metres.
const MIP_RADIUS: f32 = 4.0;
/// Output size and guard band of figures 1, 2 and 4 (Table 2's).
const HD: (usize, usize, usize) = (1920, 1080, 192);
/// Output sizes and guard bands of figure 3.
const SIZES: [(usize, usize, usize); 4] = [
    (1280, 720, 128),
    (1920, 1080, 192),
    (2560, 1600, 256),
    (3840, 2160, 384),
];
/// Slowest over fastest radius, at most (the paper's claim, with a 20% margin).
const TARGET_RADIUS_RATIO: f64 = 1.2;
/// Vertical field of view of the whole input, radians.
const FOV_Y: f64 = 1.0;

fn err(e: impl std::fmt::Display) -> String {
    e.to_string()
}

/// The box in a room, rasterised at `w × h` plus a guard band of `guard` px on every side.
struct Frame {
    camera: ocean_core::Camera,
    viewport: Viewport,
    depth: Vec<f32>,
}

impl Frame {
    fn new((w, h, guard): (usize, usize, usize)) -> Result<Self, String> {
        let (iw, ih) = (w + 2 * guard, h + 2 * guard);
        let view = AnalyticView::box_in_room();
        let projection = Projection::Perspective {
            fov_y: FOV_Y,
            aspect: iw as f64 / ih as f64,
            near: 0.1,
            far: Far::Infinite,
        };
        let camera = view
            .camera(projection, DepthConvention::ZERO_TO_ONE_REVERSED)
            .map_err(err)?;
        let raster = view
            .scene
            .rasterise(&camera, iw, ih, DepthSource::Window, DepthFormat::F32)
            .map_err(err)?;
        Ok(Self {
            camera,
            viewport: Viewport::new(iw, ih, guard).map_err(err)?,
            depth: raster.depth,
        })
    }

    fn sao(&self, params: SaoParams) -> Result<Sao, String> {
        Sao::from_camera(&self.camera, DepthSource::Window, self.viewport, params).map_err(err)
    }

    fn visible_pixels(&self) -> usize {
        self.viewport.output_len()
    }
}

/// One timed run: each pass's wall time (one submission each), its timestamps where the
/// adapter writes them, and the wall time of a whole frame.
#[derive(Clone, Copy, Debug)]
struct Run {
    wall: [f64; 5],
    stamps: Option<[f64; 5]>,
    frame_wall: f64,
}

/// The GPU side: a device with the adapter's texture size limit, the pass, its timers.
struct Gpu {
    ctx: GpuContext,
    pass: SaoPass,
    timer: Option<SaoTimer>,
    /// Whether the pass times come from the timestamps (else from the per-pass wall times).
    trust_stamps: bool,
}

impl Gpu {
    /// The headless context (`WGPU_BACKEND` and `WGPU_POWER_PREF` select the adapter,
    /// software adapters accepted): the downlevel limits but the adapter's largest 2D texture.
    fn new() -> Result<Self, String> {
        let ctx = GpuContext::headless().map_err(err)?;
        let pass = SaoPass::new(&ctx).map_err(err)?;
        let timer = SaoTimer::new(&ctx);
        // Software rasterisers: lavapipe writes timestamps that do not bracket the work
        // (measured: 0.04 to 0.18 ms for the sample pass of a 1920×1080 frame that takes 520 to
        // 680 ms), so their pass times are wall times; the timestamps are still reported.
        let software = ctx
            .adapter_info()
            .is_some_and(|i| i.device_type == wgpu::DeviceType::Cpu);
        let trust_stamps = timer.is_some() && !software;
        Ok(Self {
            ctx,
            pass,
            timer,
            trust_stamps,
        })
    }

    /// `frame`'s depth as an `R32Float` texture.
    fn upload(&self, frame: &Frame) -> Result<wgpu::Texture, String> {
        let device = self.ctx.device();
        let (w, h) = (
            frame.viewport.input_width() as u32,
            frame.viewport.input_height() as u32,
        );
        let max = device.limits().max_texture_dimension_2d;
        if w.max(h) > max {
            return Err(format!("{w} x {h} exceeds the adapter's {max} px textures"));
        }
        let texture = device.create_texture(&wgpu::TextureDescriptor {
            label: Some("bench sao depth"),
            size: wgpu::Extent3d {
                width: w,
                height: h,
                depth_or_array_layers: 1,
            },
            mip_level_count: 1,
            sample_count: 1,
            dimension: wgpu::TextureDimension::D2,
            format: wgpu::TextureFormat::R32Float,
            usage: wgpu::TextureUsages::TEXTURE_BINDING | wgpu::TextureUsages::COPY_DST,
            view_formats: &[],
        });
        self.ctx.queue().write_texture(
            texture.as_image_copy(),
            bytemuck::cast_slice(&frame.depth),
            wgpu::TexelCopyBufferLayout {
                offset: 0,
                bytes_per_row: Some(4 * w),
                rows_per_image: Some(h),
            },
            texture.size(),
        );
        self.ctx.wait_idle().map_err(err)?;
        Ok(texture)
    }

    fn submit(
        &mut self,
        record: impl FnOnce(&mut Self, &mut wgpu::CommandEncoder) -> Result<(), GpuError>,
    ) -> Result<f64, String> {
        let start = Instant::now();
        let mut encoder =
            self.ctx
                .device()
                .create_command_encoder(&wgpu::CommandEncoderDescriptor {
                    label: Some("bench sao"),
                });
        record(self, &mut encoder).map_err(err)?;
        self.ctx.queue().submit([encoder.finish()]);
        self.ctx.wait_idle().map_err(err)?;
        Ok(start.elapsed().as_secs_f64() * 1e3)
    }

    /// One run of every pass of `sao` on `depth`: a whole frame (timestamped where the adapter
    /// can), then each pass in a submission of its own.
    fn run(&mut self, sao: &Sao, depth: &wgpu::Texture) -> Result<Run, String> {
        let frame_wall = self.submit(|g, encoder| {
            g.pass
                .encode(&g.ctx, encoder, sao, depth, g.timer.as_ref())?;
            if let Some(t) = &g.timer {
                t.resolve(encoder);
            }
            Ok(())
        })?;
        let stamps = match &self.timer {
            Some(timer) => {
                let times = timer.read(&self.ctx).map_err(err)?;
                let mut stamps = [0.0; 5];
                for (p, stage) in stamps.iter_mut().zip(SaoStage::ALL) {
                    *p = times
                        .get(stage)
                        .ok_or("a timestamp pair went backwards")?
                        .ms();
                }
                Some(stamps)
            }
            None => None,
        };
        let mut wall = [0.0; 5];
        for (p, stage) in wall.iter_mut().zip(SaoStage::ALL) {
            *p = self.submit(|g, encoder| {
                g.pass
                    .encode_stage(&g.ctx, encoder, sao, depth, stage, None)
            })?;
        }
        Ok(Run {
            wall,
            stamps,
            frame_wall,
        })
    }

    /// The pass times of `r` this adapter's figures use.
    fn passes(&self, r: &Run) -> [f64; 5] {
        match r.stamps {
            Some(s) if self.trust_stamps => s,
            _ => r.wall,
        }
    }

    /// Medians over `runs` rounds (after one warm-up round) of each of `configs`, run in turn
    /// within each round.
    fn medians(
        &mut self,
        configs: &[(&Sao, &wgpu::Texture)],
        runs: u32,
    ) -> Result<Vec<Run>, String> {
        let mut all: Vec<Vec<Run>> = vec![Vec::new(); configs.len()];
        for round in 0..=runs {
            for (c, out) in configs.iter().zip(all.iter_mut()) {
                let r = self.run(c.0, c.1)?;
                if round > 0 {
                    out.push(r);
                }
            }
        }
        Ok(all
            .into_iter()
            .map(|rs| Run {
                wall: std::array::from_fn(|i| median(rs.iter().map(|r| r.wall[i]))),
                stamps: rs
                    .iter()
                    .map(|r| r.stamps)
                    .collect::<Option<Vec<_>>>()
                    .map(|st| std::array::from_fn(|i| median(st.iter().map(|s| s[i])))),
                frame_wall: median(rs.iter().map(|r| r.frame_wall)),
            })
            .collect())
    }

    fn timing(&self) -> &'static str {
        match (self.trust_stamps, self.timer.is_some()) {
            (true, _) => "timestamps",
            (false, true) => {
                "wall time per pass, one submission each (a software adapter: its timestamps, \
                 reported under \"timestamps\", are not used; lavapipe's were measured not to \
                 bracket the work)"
            }
            (false, false) => "wall time per pass, one submission each (no timestamps)",
        }
    }

    /// The figures of one run: the pass times used, the per-pass wall times, the timestamps.
    fn run_json(&self, r: &Run) -> Value {
        let stages = |t: &[f64; 5]| {
            let mut m = serde_json::Map::new();
            for (stage, v) in SaoStage::ALL.iter().zip(t) {
                m.insert(format!("{}_ms", stage.name()), json!(v));
            }
            m.insert("total_ms".into(), json!(t.iter().sum::<f64>()));
            Value::Object(m)
        };
        let mut v = stages(&self.passes(r));
        v["frame_wall_ms"] = json!(r.frame_wall);
        v["wall_per_pass"] = stages(&r.wall);
        v["timestamps"] = r.stamps.as_ref().map_or(Value::Null, stages);
        v
    }
}

fn median(v: impl Iterator<Item = f64>) -> f64 {
    let mut v: Vec<f64> = v.collect();
    v.sort_by(f64::total_cmp);
    v[v.len() / 2]
}

/// Figures 1 and 2 (they share the r = 4 m run with the hierarchy).
fn radius_and_mips(gpu: &mut Gpu, runs: u32) -> Result<(Value, Value), String> {
    let frame = Frame::new(HD)?;
    let depth = gpu.upload(&frame)?;
    let mut saos: Vec<Sao> = RADII
        .iter()
        .map(|&radius| {
            frame.sao(SaoParams {
                radius,
                ..SaoParams::default()
            })
        })
        .collect::<Result<_, _>>()?;
    saos.push(frame.sao(SaoParams {
        radius: MIP_RADIUS,
        max_mip: 0,
        ..SaoParams::default()
    })?);
    let configs: Vec<(&Sao, &wgpu::Texture)> = saos.iter().map(|s| (s, &depth)).collect();
    let runs = gpu.medians(&configs, runs)?;
    let total = |r: &Run| gpu.passes(r).iter().sum::<f64>();
    let ao = |r: &Run| gpu.passes(r)[2];
    let by_radius = &runs[..RADII.len()];
    let (lo, hi) = by_radius
        .iter()
        .map(total)
        .fold((f64::INFINITY, 0.0f64), |(lo, hi), t| {
            (lo.min(t), hi.max(t))
        });
    let (ao_lo, ao_hi) = by_radius
        .iter()
        .map(ao)
        .fold((f64::INFINITY, 0.0f64), |(lo, hi), t| {
            (lo.min(t), hi.max(t))
        });
    let cases: Vec<Value> = RADII
        .iter()
        .zip(by_radius)
        .map(|(r, run)| {
            let mut v = gpu.run_json(run);
            v["radius_m"] = json!(r);
            v
        })
        .collect();
    let radius = json!({
        "size": [HD.0, HD.1],
        "guard": HD.2,
        "cases": cases,
        "max_over_min": hi / lo,
        "meets_target": hi / lo <= TARGET_RADIUS_RATIO,
        "ao_pass_max_over_min": ao_hi / ao_lo,
        "target_max_over_min": TARGET_RADIUS_RATIO,
    });
    let with = RADII
        .iter()
        .position(|&r| r == MIP_RADIUS)
        .map(|i| runs[i])
        .ok_or("the MIP radius is one of the radii")?;
    let without = runs[RADII.len()];
    let mips = json!({
        "size": [HD.0, HD.1],
        "guard": HD.2,
        "radius_m": MIP_RADIUS,
        "with_hierarchy": gpu.run_json(&with),
        "level_0_only": gpu.run_json(&without),
        "speedup": total(&without) / total(&with),
        "ao_pass_speedup": ao(&without) / ao(&with),
    });
    Ok((radius, mips))
}

/// Figure 3.
fn passes(gpu: &mut Gpu, runs: u32) -> Result<Value, String> {
    let mut rows = Vec::new();
    for size in SIZES {
        let frame = Frame::new(size)?;
        let mut row = match gpu.upload(&frame) {
            Ok(depth) => {
                let sao = frame.sao(SaoParams::default())?;
                let r = gpu.medians(&[(&sao, &depth)], runs)?[0];
                let mut v = gpu.run_json(&r);
                let total = gpu.passes(&r).iter().sum::<f64>();
                v["ns_per_visible_pixel"] = json!(total * 1e6 / frame.visible_pixels() as f64);
                v
            }
            Err(why) => json!({ "skipped": why }),
        };
        row["size"] = json!([size.0, size.1]);
        row["guard"] = json!(size.2);
        row["input_pixels"] = json!(frame.viewport.input_len());
        row["visible_pixels"] = json!(frame.visible_pixels());
        rows.push(row);
    }
    Ok(Value::Array(rows))
}

/// Output size and guard band of figure 5.
const QUALITY: (usize, usize, usize) = (640, 360, 32);

/// Figure 5: the final A of the paper's normals and blur (`SaoParams::paper`) and of the
/// defaults against the estimator's own limit on the same depth buffer (ocean-sao's
/// `reference::screen_obscurance`: the same falloff, 256 exact-depth samples over Eq. 5's disk
/// per pixel), over the geometry pixels: mean absolute error, MSE and correlation.
fn quality(no_gpu: bool) -> Result<Value, String> {
    use ocean_sao::analytic::{CameraRays, NO_FACE};
    use ocean_sao::reference::{self, ReferenceParams};
    let (w, h, guard) = QUALITY;
    let (iw, ih) = (w + 2 * guard, h + 2 * guard);
    let views = [
        AnalyticView::box_in_room(),
        AnalyticView::boxes(12f64.to_radians(), 25f64.to_radians(), 4.5),
    ];
    let mut rows = Vec::new();
    for view in views {
        let projection = Projection::Perspective {
            fov_y: FOV_Y,
            aspect: iw as f64 / ih as f64,
            near: 0.1,
            far: Far::Infinite,
        };
        let camera = view
            .camera(projection, DepthConvention::ZERO_TO_ONE_REVERSED)
            .map_err(err)?;
        let raster = view
            .scene
            .rasterise(&camera, iw, ih, DepthSource::Window, DepthFormat::F32)
            .map_err(err)?;
        let viewport = Viewport::new(iw, ih, guard).map_err(err)?;
        let rays = CameraRays::new(&camera, iw, ih).map_err(err)?;
        let rp = ReferenceParams::from_params(&SaoParams::default(), 16).map_err(err)?;
        let disk = reference::screen_obscurance(&view.scene, &rays, &viewport, &rp);
        let geometry = |i: usize| raster.face[(i / w + guard) * iw + i % w + guard] != NO_FACE;
        let cases = blur_cases(&camera, viewport, &raster.depth, &disk, geometry)?;
        rows.push(json!({ "scene": view.name, "cases": cases }));
    }
    rows.push(if no_gpu {
        json!({ "scene": "built-in", "skipped": "--no-gpu" })
    } else {
        match built_in_quality() {
            Ok(cases) => json!({ "scene": "built-in", "cases": cases }),
            Err(why) => json!({ "scene": "built-in", "skipped": why }),
        }
    });
    Ok(json!({ "size": [w, h], "guard": guard, "reference_samples": 256, "scenes": rows }))
}

/// Figure 5 on the built-in scene's own depth: the first frame of `ocean render`'s scene at
/// the figure's size plus its guard band, drawn on the GPU (Vulkan, one sample), its depth read
/// back in `f32`; the reference is the estimator's limit on that depth buffer
/// (`reference::buffer_obscurance`: 256 samples over Eq. 5's disk, occluders and normals from
/// the buffer's own texels).
fn built_in_quality() -> Result<Vec<Value>, String> {
    use ocean_sao::analytic::CameraRays;
    use ocean_sao::reference::{self, ReferenceParams};
    let (w, h, guard) = QUALITY;
    let (iw, ih) = (w + 2 * guard, h + 2 * guard);
    let mut scene = ocean_scene::SceneDescription::parse(ocean_scene::DEFAULT_SCENE, "built-in")
        .map_err(|e| e.to_string())?;
    scene.render.width = iw as u32;
    scene.render.height = ih as u32;
    let (camera, depth) = ocean_scene::renderer::scene_depth(&scene).map_err(|e| e.to_string())?;
    let viewport = Viewport::new(iw, ih, guard).map_err(err)?;
    let rays = CameraRays::new(&camera, iw, ih).map_err(err)?;
    let rp = ReferenceParams::from_params(&SaoParams::default(), 16).map_err(err)?;
    let positions = reference::view_positions(&camera, &depth, iw, ih);
    let limit = reference::buffer_obscurance(&positions, &rays, &viewport, &rp);
    let geometry = |i: usize| positions[(i / w + guard) * iw + i % w + guard].is_some();
    blur_cases(&camera, viewport, &depth, &limit, geometry)
}

/// The final A of the paper's blur and of the defaults on window `depth` seen by `camera`,
/// each against `limit` over the output pixels `geometry` selects: MAE, MSE, correlation.
fn blur_cases(
    camera: &Camera,
    viewport: Viewport,
    depth: &[f32],
    limit: &[f32],
    geometry: impl Fn(usize) -> bool + Copy,
) -> Result<Vec<Value>, String> {
    let mut cases = Vec::new();
    for (name, params) in [
        ("paper", SaoParams::paper()),
        ("defaults", SaoParams::default()),
    ] {
        let sao = Sao::from_camera(camera, DepthSource::Window, viewport, params).map_err(err)?;
        let mut ao = vec![0.0f32; viewport.output_len()];
        sao.run(depth, &mut ao).map_err(err)?;
        let c = ocean_sao::reference::compare(&ao, limit, geometry);
        cases.push(json!({
            "blur": name,
            "mae": mae(&ao, limit, geometry, c.pixels),
            "mse": c.mse,
            "correlation": c.correlation,
            "pixels": c.pixels,
        }));
    }
    Ok(cases)
}

/// Mean absolute difference over the `pixels` pixels `keep` selects.
fn mae(a: &[f32], b: &[f32], keep: impl Fn(usize) -> bool, pixels: usize) -> f64 {
    a.iter()
        .zip(b)
        .enumerate()
        .filter(|&(i, _)| keep(i))
        .map(|(_, (a, b))| f64::from((a - b).abs()))
        .sum::<f64>()
        / pixels.max(1) as f64
}

/// Figure 4.
fn cpu_reference(runs: u32) -> Result<Value, String> {
    let frame = Frame::new(HD)?;
    let sao = frame.sao(SaoParams::default())?;
    let mut ao = vec![0.0f32; frame.visible_pixels()];
    let mut times = Vec::new();
    for round in 0..=runs {
        let start = Instant::now();
        sao.run(&frame.depth, &mut ao).map_err(err)?;
        if round > 0 {
            times.push(start.elapsed().as_secs_f64() * 1e3);
        }
    }
    Ok(json!({
        "size": [HD.0, HD.1],
        "guard": HD.2,
        "threads": rayon::current_num_threads(),
        "ms": median(times.into_iter()),
    }))
}

pub fn sao(args: &BenchOptions) -> Result<Value, String> {
    let runs = args.runs;
    let gpu_doc = if args.no_gpu {
        json!({ "skipped": "--no-gpu" })
    } else {
        match Gpu::new() {
            Ok(mut gpu) => {
                let (radius, mips) = radius_and_mips(&mut gpu, runs)?;
                let passes = passes(&mut gpu, runs)?;
                json!({
                    "adapter": gpu.ctx.describe(),
                    "timing": gpu.timing(),
                    "radius": radius,
                    "mip_hierarchy": mips,
                    "passes": passes,
                })
            }
            Err(why) => json!({ "skipped": why }),
        }
    };
    let doc = json!({
        "suite": "sao",
        "cpu": cpu_name(),
        "threads": rayon::current_num_threads(),
        "scene": "box_in_room",
        "runs": runs,
        "gpu": gpu_doc,
        "cpu_reference": cpu_reference(runs)?,
        "quality": quality(args.no_gpu)?,
    });
    Ok(doc)
}

/// The suite's tables.
pub fn print(doc: &Value) {
    print_table(doc);
}

fn ms(v: &Value) -> String {
    v.as_f64()
        .map_or_else(|| "-".to_owned(), |t| format!("{t:.3}"))
}

fn print_table(doc: &Value) {
    println!(
        "ocean bench sao — box in a room; CPU {} ({} threads); medians of {} runs",
        doc["cpu"].as_str().unwrap_or("?"),
        doc["threads"],
        doc["runs"]
    );
    let g = &doc["gpu"];
    if let Some(why) = g["skipped"].as_str() {
        println!("GPU: skipped ({why})");
    } else {
        println!(
            "GPU: {} — {}",
            g["adapter"].as_str().unwrap_or("?"),
            g["timing"].as_str().unwrap_or("?")
        );
        let r = &g["radius"];
        println!(
            "1. radius at {}x{} (guard {}): total ms",
            r["size"][0], r["size"][1], r["guard"]
        );
        for c in r["cases"].as_array().into_iter().flatten() {
            println!(
                "   r = {:>5} m: {:>10}  (ao pass {}, frame wall {})",
                c["radius_m"],
                ms(&c["total_ms"]),
                ms(&c["ao_ms"]),
                ms(&c["frame_wall_ms"])
            );
        }
        println!(
            "   slowest / fastest: {:.3} (ao pass {:.3}); target <= {}",
            r["max_over_min"].as_f64().unwrap_or(f64::NAN),
            r["ao_pass_max_over_min"].as_f64().unwrap_or(f64::NAN),
            r["target_max_over_min"]
        );
        let m = &g["mip_hierarchy"];
        println!(
            "2. r = {} m: with the hierarchy {} ms, level 0 only {} ms: speed-up {:.2} (ao pass {:.2})",
            m["radius_m"],
            ms(&m["with_hierarchy"]["total_ms"]),
            ms(&m["level_0_only"]["total_ms"]),
            m["speedup"].as_f64().unwrap_or(f64::NAN),
            m["ao_pass_speedup"].as_f64().unwrap_or(f64::NAN)
        );
        println!(
            "3. {:>10} {:>5} {:>10} {:>9} {:>9} {:>9} {:>9} {:>9} {:>9} {:>10}",
            "size",
            "guard",
            "input px",
            "z",
            "mips",
            "ao",
            "blur h",
            "blur v",
            "total",
            "ns/vis px"
        );
        for p in g["passes"].as_array().into_iter().flatten() {
            let size = format!("{}x{}", p["size"][0], p["size"][1]);
            if let Some(why) = p["skipped"].as_str() {
                println!("   {size:>10} skipped: {why}");
                continue;
            }
            println!(
                "   {:>10} {:>5} {:>10} {:>9} {:>9} {:>9} {:>9} {:>9} {:>9} {:>10}",
                size,
                p["guard"],
                p["input_pixels"],
                ms(&p["z_ms"]),
                ms(&p["mips_ms"]),
                ms(&p["ao_ms"]),
                ms(&p["blur_h_ms"]),
                ms(&p["blur_v_ms"]),
                ms(&p["total_ms"]),
                ms(&p["ns_per_visible_pixel"])
            );
        }
    }
    let c = &doc["cpu_reference"];
    println!(
        "4. CPU reference at {}x{} (guard {}), {} threads: {} ms",
        c["size"][0],
        c["size"][1],
        c["guard"],
        c["threads"],
        ms(&c["ms"])
    );
    let q = &doc["quality"];
    println!(
        "5. against the estimator's {}-sample limit at {}x{} (guard {}): MAE, MSE, correlation",
        q["reference_samples"], q["size"][0], q["size"][1], q["guard"]
    );
    for s in q["scenes"].as_array().into_iter().flatten() {
        if let Some(why) = s["skipped"].as_str() {
            println!(
                "   {:>12}: skipped ({why})",
                s["scene"].as_str().unwrap_or("?")
            );
        }
        for c in s["cases"].as_array().into_iter().flatten() {
            println!(
                "   {:>12} {:>9}: {:.4}  {:.5}  {:.4}",
                s["scene"].as_str().unwrap_or("?"),
                c["blur"].as_str().unwrap_or("?"),
                c["mae"].as_f64().unwrap_or(f64::NAN),
                c["mse"].as_f64().unwrap_or(f64::NAN),
                c["correlation"].as_f64().unwrap_or(f64::NAN)
            );
        }
    }
}
