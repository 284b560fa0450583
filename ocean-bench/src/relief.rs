//! `ocean bench relief`: the figures of relief mapping by relaxed cone stepping on
//! ocean-relief's CPU code.
//!
//! 1. **Generation**: `ConeMap::generate` of relaxed cones capped at 1.0 (the book's cap) at
//!    256², 512² and 1024², on three wrapped maps (`ocean_relief::maps`): fBm value noise with
//!    6 octaves, smooth value noise with 2 octaves, round bumps; all threads of the rayon pool.
//!    Targets (on 2 cores): 512² in at most 2 s and 1024² in at most 10 s, checked against the
//!    slowest map's median. For scale, the book's brute-force listing at about
//!    15 s at 256² and an hour at 1024² on one core.
//! 2. **Oracle**: `ConeMap::brute_force` (every pair of cells, `Θ(N⁴)`) and `generate` on the
//!    fBm map at 128², timed in turn in the same rounds; their ratio, and whether the bits agree.
//! 3. **Progress**: `generate_with` (bands of rows with a report after each, what
//!    `ocean cone-map` and the C ABI's callback use) against `generate` on the fBm map at 512².
//! 4. **GPU generation**: `ocean_gpu::ConeMapGenerator` on the fBm map at each size (after a
//!    warm-up on a small map, since drivers compile the shader on the first dispatch), its
//!    output compared with the CPU's; next to it the quadrant cone map of the same map
//!    (`generate_quad`, §18.1: four layers, compared with `QuadConeMap::generate`) and the CPU's
//!    time for that. 1024² is skipped on software adapters (over a minute), and so are quadrant
//!    maps above 256² (four times the isotropic time). `--no-gpu` or a missing adapter leaves
//!    the reason in `gpu_generation`.
//! 5. **Tracers**: rays per second for each method of the accuracy table
//!    (`accuracy::Config::standard_entries`) on the fBm map at 256² (relief 0.1 texture widths
//!    deep, view 60° from the normal, 2¹⁸ rays with random starts and azimuths), on one thread
//!    and on all threads.
//! 6. **Accuracy**: `accuracy::table(&Config::standard(128, 4096))`, the table the tests print.
//! 7. **Level of detail** (GPU): a minified relief quad (the fBm map at 256², tiled 8 × 8 on a
//!    1 m quad 0.01 m deep, seen from 1.3 m at 50° from its normal, 256 × 256 pixels, so a
//!    pixel covers about 4 to 16 level-0 texels) drawn by `ReliefRenderer` with level 0 alone
//!    (`set_texture`) and with its 8 levels (`set_mips`, `ocean_relief::lod`): the median time
//!    of a draw with its readback, and the shimmer, the mean absolute change of the 8-bit green
//!    channel over the pixels on the quad in both frames when the quad moves by 0.002 m (about
//!    0.4 pixel); and the CPU time to generate level 0's cones against the whole chain's.
//!    `--no-gpu` or a missing adapter leaves the reason in `lod`.
//! 8. to 10. **Width**, **speed** and **steps** on the family of twelve map kinds:
//!    `relief_family.rs`.
//!
//! Times are medians of `--runs` runs. Generation runs are not preceded by a warm-up (each
//! takes 0.1 s or more, so no cache or thread wake-up effect shows); tracer runs are.

use std::time::Instant;

use ocean_relief::accuracy::{Config, Textures, adaptive_cone_steps, table};
use ocean_relief::maps::{bumps, to_map, value_noise};
use ocean_relief::{
    ConeMap, ConeParams, Edge, HeightMap, Method, QuadConeMap, Ray, ReliefMips, ReliefTexture,
};
use rayon::prelude::*;
use serde_json::{Value, json};

use crate::options::BenchOptions;
use crate::relief_family::rays;
use crate::timing::cpu_name;

/// Sides of figure 1.
const SIZES: [usize; 3] = [256, 512, 1024];
/// Targets of figure 1, seconds.
const TARGET_512_S: f64 = 2.0;
const TARGET_1024_S: f64 = 10.0;
/// Side of figure 2 (the oracle's largest, `MAX_BRUTE_SIDE`).
const ORACLE_SIDE: usize = ocean_relief::MAX_BRUTE_SIDE;
/// Rays of figure 5.
const TRACE_RAYS: usize = 1 << 18;
/// View angle of figure 5, degrees, and relief depth, texture widths.
const TRACE_ANGLE: f32 = 60.0;
const TRACE_DEPTH: f32 = 0.1;

fn err(e: impl std::fmt::Display) -> String {
    e.to_string()
}

fn median(mut v: Vec<f64>) -> f64 {
    v.sort_by(f64::total_cmp);
    v[v.len() / 2]
}

/// Up to three timed GPU generations (`runs`, at most 3): the median time in seconds, and
/// whether every result equals the CPU's `cpu`.
fn gpu_runs<T: PartialEq>(
    runs: u32,
    cpu: &T,
    mut generate: impl FnMut() -> Result<T, ocean_gpu::GpuError>,
) -> Result<(f64, bool), String> {
    let mut times = Vec::new();
    let mut identical = true;
    for _ in 0..runs.min(3) {
        let start = Instant::now();
        let cones = generate().map_err(err)?;
        times.push(start.elapsed().as_secs_f64());
        identical &= cones == *cpu;
    }
    Ok((median(times), identical))
}

fn seconds(f: impl FnOnce()) -> f64 {
    let start = Instant::now();
    f();
    start.elapsed().as_secs_f64()
}

/// The maps of figure 1 at side `n`.
fn maps(n: usize) -> Result<Vec<(&'static str, HeightMap)>, String> {
    [
        ("fBm 6 octaves", value_noise(n, 8, 6, 1)),
        ("smooth 2 octaves", value_noise(n, 4, 2, 2)),
        ("bumps", bumps(n, n / 8, n as f64 / 24.0, 3)),
    ]
    .into_iter()
    .map(|(name, h)| Ok((name, to_map(n, &h, Edge::Wrap).map_err(err)?)))
    .collect()
}

/// Figure 4: the GPU generator, at most 3 runs a size.
fn gpu_generation(runs: u32) -> Result<Value, String> {
    let ctx = ocean_gpu::GpuContext::headless().map_err(err)?;
    let generator = ocean_gpu::ConeMapGenerator::new(&ctx).map_err(err)?;
    let software = ctx
        .adapter_info()
        .is_some_and(|i| i.device_type == ocean_gpu::wgpu::DeviceType::Cpu);
    let params = ConeParams::relaxed(1.0).with_parts(0);
    // The GPU bounds whole cells (`ConeParams::parts` 0): its CPU twin is timed with the same.
    let warm = to_map(64, &value_noise(64, 8, 6, 1), Edge::Wrap).map_err(err)?;
    generator.generate(&ctx, &warm, params).map_err(err)?;
    generator.generate_quad(&ctx, &warm, params).map_err(err)?;
    let mut sizes = Vec::new();
    for n in SIZES {
        if software && n > 512 {
            sizes.push(json!({ "side": n, "skipped": "over a minute on a software adapter" }));
            continue;
        }
        let map = to_map(n, &value_noise(n, 8, 6, 1), Edge::Wrap).map_err(err)?;
        let cpu = ConeMap::generate(&map, params).map_err(err)?;
        let (seconds_gpu, identical) =
            gpu_runs(runs, &cpu, || generator.generate(&ctx, &map, params))?;
        let quad = if software && n > 256 {
            json!({ "skipped": "four times the isotropic time on a software adapter" })
        } else {
            let mut cpu_quad = None;
            let cpu_seconds = seconds(|| cpu_quad = Some(QuadConeMap::generate(&map, params)));
            let cpu_quad = cpu_quad.expect("timed").map_err(err)?;
            let (seconds, identical) = gpu_runs(runs, &cpu_quad, || {
                generator.generate_quad(&ctx, &map, params)
            })?;
            json!({
                "seconds": seconds,
                "identical_to_cpu": identical,
                "cpu_seconds": cpu_seconds,
            })
        };
        sizes.push(json!({
            "side": n,
            "map": "fBm 6 octaves",
            "seconds": seconds_gpu,
            "identical_to_cpu": identical,
            "quad": quad,
        }));
    }
    Ok(json!({
        "measured": true,
        "device": ctx.describe(),
        "software_adapter": software,
        "sizes": sizes,
    }))
}

/// Side, levels and tiling of figure 7.
const LOD_SIDE: usize = 256;
const LOD_LEVELS: usize = 8;
const LOD_TILES: f64 = 8.0;
const LOD_IMAGE: u32 = 256;

/// Figure 7: a minified relief quad with level 0 alone and with its mip levels.
fn gpu_lod(runs: u32) -> Result<Value, String> {
    use glam::{DVec2, DVec3};
    use ocean_core::{Camera, DepthConvention, Far, Projection};
    use ocean_gpu::{GpuContext, ReliefRenderer, ReliefScene};

    let map = to_map(LOD_SIDE, &value_noise(LOD_SIDE, 8, 6, 1), Edge::Wrap).map_err(err)?;
    let params = ConeParams::relaxed(1.0);
    let mut level0 = None;
    let level0_s = seconds(|| level0 = Some(ConeMap::generate(&map, params)));
    let texture = ReliefTexture::new(&map, &level0.expect("timed").map_err(err)?).map_err(err)?;
    let mut mips = None;
    let mips_s = seconds(|| mips = Some(ReliefMips::generate(&map, params, LOD_LEVELS)));
    let mips = mips.expect("timed").map_err(err)?;

    let ctx = GpuContext::headless().map_err(err)?;
    let eye = DVec3::new(
        0.0,
        1.3 * 50f64.to_radians().cos(),
        1.3 * 50f64.to_radians().sin(),
    );
    let camera = Camera::look_at(
        eye,
        DVec3::ZERO,
        DVec3::Y,
        Projection::Perspective {
            fov_y: 0.9,
            aspect: 1.0,
            near: 0.1,
            far: Far::Finite(10.0),
        },
        DepthConvention::ZERO_TO_ONE,
    )
    .map_err(err)?;
    let scene = ReliefScene {
        origin: DVec3::new(-0.5, 0.0, 0.5),
        edge_u: DVec3::X,
        edge_v: DVec3::NEG_Z,
        tiles: DVec2::splat(LOD_TILES),
        depth: 0.01,
        ..Default::default()
    };
    let moved = ReliefScene {
        origin: scene.origin + DVec3::new(0.002, 0.0, 0.0),
        ..scene
    };
    let clear = ocean_gpu::relief::window_depth(&camera, camera.depth().clear_depth()) as f32;
    let measure = |renderer: &ReliefRenderer| -> Result<Value, String> {
        let draw = || renderer.render_image(&ctx, &camera, &scene, LOD_IMAGE, LOD_IMAGE);
        draw().map_err(err)?;
        let mut times = Vec::new();
        for _ in 0..runs.max(3) {
            times.push(seconds(|| {
                let _ = draw();
            }));
        }
        let a = draw().map_err(err)?;
        let b = renderer
            .render_image(&ctx, &camera, &moved, LOD_IMAGE, LOD_IMAGE)
            .map_err(err)?;
        let (mut sum, mut pixels) = (0u64, 0u64);
        for k in 0..a.depth.len() {
            if a.depth[k] != clear && b.depth[k] != clear {
                sum += u64::from(a.rgba[4 * k + 1].abs_diff(b.rgba[4 * k + 1]));
                pixels += 1;
            }
        }
        Ok(json!({
            "seconds": median(times),
            "shimmer": sum as f64 / pixels.max(1) as f64,
            "pixels": pixels,
        }))
    };
    let mut renderer = ReliefRenderer::new(&ctx, Default::default()).map_err(err)?;
    renderer.set_texture(&ctx, &texture).map_err(err)?;
    let single = measure(&renderer)?;
    renderer.set_mips(&ctx, &mips).map_err(err)?;
    let chain = measure(&renderer)?;
    Ok(json!({
        "measured": true,
        "device": ctx.describe(),
        "side": LOD_SIDE,
        "levels": LOD_LEVELS,
        "tiles": LOD_TILES,
        "image": LOD_IMAGE,
        "level0": single,
        "mips": chain,
        "cpu_generate_level0_seconds": level0_s,
        "cpu_generate_mips_seconds": mips_s,
    }))
}

/// Figure 1.
fn generation(runs: u32) -> Result<Value, String> {
    let params = ConeParams::relaxed(1.0);
    let mut sizes = Vec::new();
    for n in SIZES {
        let mut rows = Vec::new();
        let mut worst = 0.0f64;
        for (name, map) in maps(n)? {
            let mut times = Vec::new();
            let mut mean = 0.0;
            for _ in 0..runs {
                let mut cones = None;
                times.push(seconds(|| cones = Some(ConeMap::generate(&map, params))));
                let cones = cones.expect("timed").map_err(err)?;
                mean = cones.ratios().iter().map(|&r| f64::from(r)).sum::<f64>()
                    / cones.ratios().len() as f64;
            }
            let s = median(times);
            worst = worst.max(s);
            rows.push(json!({ "map": name, "seconds": s, "mean_ratio": mean }));
        }
        let target = match n {
            512 => Some(TARGET_512_S),
            1024 => Some(TARGET_1024_S),
            _ => None,
        };
        sizes.push(json!({
            "side": n,
            "maps": rows,
            "slowest_seconds": worst,
            "target_max_seconds": target,
            "meets_target": target.map(|t| worst <= t),
        }));
    }
    Ok(json!({
        "kind": "relaxed",
        "max_ratio": params.max_ratio,
        "edge": "wrap",
        "sizes": sizes,
    }))
}

/// Figure 2.
fn oracle(runs: u32) -> Result<Value, String> {
    let n = ORACLE_SIDE;
    let map = to_map(n, &value_noise(n, 8, 6, 1), Edge::Wrap).map_err(err)?;
    let params = ConeParams::relaxed(1.0);
    let (mut fast_t, mut brute_t) = (Vec::new(), Vec::new());
    let mut identical = true;
    for _ in 0..runs {
        let (mut fast, mut brute) = (None, None);
        fast_t.push(seconds(|| fast = Some(ConeMap::generate(&map, params))));
        brute_t.push(seconds(|| brute = Some(ConeMap::brute_force(&map, params))));
        let (fast, brute) = (fast.expect("timed"), brute.expect("timed"));
        identical &= fast.map_err(err)? == brute.map_err(err)?;
    }
    let (fast, brute) = (median(fast_t), median(brute_t));
    Ok(json!({
        "side": n,
        "map": "fBm 6 octaves",
        "brute_force_seconds": brute,
        "generate_seconds": fast,
        "brute_over_generate": brute / fast,
        "identical_bits": identical,
    }))
}

/// Figure 3.
fn progress_overhead(runs: u32) -> Result<Value, String> {
    let n = 512;
    let map = to_map(n, &value_noise(n, 8, 6, 1), Edge::Wrap).map_err(err)?;
    let params = ConeParams::relaxed(1.0);
    let (mut plain, mut banded) = (Vec::new(), Vec::new());
    let mut reports = 0usize;
    for _ in 0..runs {
        plain.push(seconds(|| {
            let _ = std::hint::black_box(ConeMap::generate(&map, params));
        }));
        reports = 0;
        banded.push(seconds(|| {
            let _ = std::hint::black_box(ConeMap::generate_with(
                &map,
                params,
                &mut |_: usize, _: usize| {
                    reports += 1;
                    true
                },
            ));
        }));
    }
    let (plain, banded) = (median(plain), median(banded));
    Ok(json!({
        "side": n,
        "map": "fBm 6 octaves",
        "generate_seconds": plain,
        "generate_with_progress_seconds": banded,
        "reports": reports,
        "overhead": banded / plain - 1.0,
    }))
}

/// Figure 5.
fn tracers(runs: u32) -> Result<Value, String> {
    let n = 256;
    let map = to_map(n, &value_noise(n, 8, 6, 1), Edge::Wrap).map_err(err)?;
    let entries = Config::standard_entries();
    let textures = Textures::new(&map, 4.0, &entries).map_err(err)?;
    let rays = rays(TRACE_RAYS, TRACE_ANGLE, TRACE_DEPTH)?;
    let mut rows = Vec::new();
    for entry in entries {
        let mut method = entry.method;
        if entry.adaptive
            && let Method::Relaxed { cone, .. } = &mut method
        {
            *cone = adaptive_cone_steps(*cone, TRACE_ANGLE);
        }
        let trace = |r: &Ray| textures.trace(entry.cones, &method, r);
        trace(&rays[0]).map_err(err)?;
        let single = || {
            let mut sum = 0.0f32;
            for r in &rays {
                sum += trace(r).map_or(0.0, |h| h.pos.z);
            }
            std::hint::black_box(sum);
        };
        let threads = || {
            let sum: f32 = rays
                .par_chunks(1024)
                .map(|c| {
                    c.iter()
                        .map(|r| trace(r).map_or(0.0, |h| h.pos.z))
                        .sum::<f32>()
                })
                .sum();
            std::hint::black_box(sum);
        };
        let (mut t1, mut tn) = (Vec::new(), Vec::new());
        for round in 0..=runs {
            let (a, b) = (seconds(single), seconds(threads));
            if round > 0 {
                t1.push(a);
                tn.push(b);
            }
        }
        let (t1, tn) = (median(t1), median(tn));
        rows.push(json!({
            "method": entry.name,
            "fetches_per_ray": method.fetches(),
            "rays_per_s_single_thread": TRACE_RAYS as f64 / t1,
            "rays_per_s_all_threads": TRACE_RAYS as f64 / tn,
        }));
    }
    Ok(json!({
        "side": n,
        "map": "fBm 6 octaves",
        "rays": TRACE_RAYS,
        "angle_deg": TRACE_ANGLE,
        // The f32 constant, printed as the decimal it was written as.
        "relief_depth": (f64::from(TRACE_DEPTH) * 1000.0).round() / 1000.0,
        "cone_cap": 4.0,
        "methods": rows,
    }))
}

pub fn relief(args: &BenchOptions) -> Result<Value, String> {
    let runs = args.runs;
    let accuracy = table(&Config::standard(128, 4096).map_err(err)?).map_err(err)?;
    let doc = json!({
        "suite": "relief",
        "cpu": cpu_name(),
        "threads": rayon::current_num_threads(),
        "runs": runs,
        "generation": generation(runs)?,
        "oracle": oracle(runs)?,
        "progress": progress_overhead(runs)?,
        "gpu_generation": if args.no_gpu {
            json!({ "measured": false, "reason": "skipped (--no-gpu)" })
        } else {
            gpu_generation(runs).unwrap_or_else(|e| json!({ "measured": false, "reason": e }))
        },
        "tracers": tracers(runs)?,
        "width": crate::relief_family::width_figure()?,
        "family_speed": crate::relief_family::speed_figure()?,
        "steps": crate::relief_family::steps_figure()?,
        "lod": if args.no_gpu {
            json!({ "measured": false, "reason": "skipped (--no-gpu)" })
        } else {
            gpu_lod(runs).unwrap_or_else(|e| json!({ "measured": false, "reason": e }))
        },
        "accuracy": accuracy.rows.iter().map(|r| json!({
            "map": r.map,
            "depth_texels": r.depth_texels,
            "angle_deg": r.angle,
            "method": r.method,
            "fetches": r.fetches,
            "over_one_texel": r.over_one,
            "mean_error_texels": r.mean,
            "overshoots": r.overshoots,
            "rays": r.rays,
        })).collect::<Vec<_>>(),
    });
    let mut doc = doc;
    doc["accuracy_table"] = Value::from(accuracy.to_string());
    Ok(doc)
}

/// The suite's tables.
pub fn print(doc: &Value) {
    print_table(doc);
    crate::relief_family::print(doc);
    println!(
        "\naccuracy (128² maps, 4096 rays a row):\n{}",
        doc["accuracy_table"].as_str().unwrap_or("-")
    );
}

fn print_table(doc: &Value) {
    let f = |v: &Value, digits: usize| {
        v.as_f64()
            .map_or_else(|| "-".to_owned(), |x| format!("{x:.digits$}"))
    };
    println!(
        "ocean bench relief — CPU {} ({} threads); medians of {} runs",
        doc["cpu"].as_str().unwrap_or("?"),
        doc["threads"],
        doc["runs"]
    );
    let g = &doc["generation"];
    println!(
        "1. relaxed cone-map generation (cap {}, wrap), seconds:",
        g["max_ratio"]
    );
    for s in g["sizes"].as_array().into_iter().flatten() {
        let maps: Vec<String> = s["maps"]
            .as_array()
            .into_iter()
            .flatten()
            .map(|m| {
                format!(
                    "{} {}",
                    m["map"].as_str().unwrap_or("?"),
                    f(&m["seconds"], 3)
                )
            })
            .collect();
        let target = match s["target_max_seconds"].as_f64() {
            Some(t) => format!(
                "; slowest {} (target <= {t}: {})",
                f(&s["slowest_seconds"], 3),
                if s["meets_target"].as_bool() == Some(true) {
                    "met"
                } else {
                    "MISSED"
                }
            ),
            None => String::new(),
        };
        println!("   {0:>4}²: {1}{target}", s["side"], maps.join(", "));
    }
    let o = &doc["oracle"];
    println!(
        "2. oracle at {0}²: brute force {1} s, generate {2} s, ratio {3}, identical bits: {4}",
        o["side"],
        f(&o["brute_force_seconds"], 3),
        f(&o["generate_seconds"], 4),
        f(&o["brute_over_generate"], 1),
        o["identical_bits"]
    );
    let p = &doc["progress"];
    println!(
        "3. progress at {0}²: generate {1} s, with {2} reports {3} s (overhead {4}%)",
        p["side"],
        f(&p["generate_seconds"], 3),
        p["reports"],
        f(&p["generate_with_progress_seconds"], 3),
        p["overhead"]
            .as_f64()
            .map_or_else(|| "-".to_owned(), |x| format!("{:.1}", 100.0 * x))
    );
    let g = &doc["gpu_generation"];
    match g["device"].as_str() {
        Some(device) => {
            println!("4. GPU generation on {device}, fBm map:");
            for c in g["sizes"].as_array().into_iter().flatten() {
                match c["skipped"].as_str() {
                    Some(why) => println!("   {}²: skipped ({why})", c["side"]),
                    None => {
                        let q = &c["quad"];
                        let quad = match q["skipped"].as_str() {
                            Some(why) => format!("skipped ({why})"),
                            None => format!(
                                "{} s (CPU {} s), identical to the CPU: {}",
                                f(&q["seconds"], 3),
                                f(&q["cpu_seconds"], 3),
                                q["identical_to_cpu"]
                            ),
                        };
                        println!(
                            "   {}²: {} s, identical to the CPU: {}; quadrant map {quad}",
                            c["side"],
                            f(&c["seconds"], 3),
                            c["identical_to_cpu"]
                        );
                    }
                }
            }
        }
        None => println!(
            "4. GPU generation: not measured ({})",
            g["reason"].as_str().unwrap_or("?")
        ),
    }
    let t = &doc["tracers"];
    println!(
        "5. CPU tracers, {}² {}, {} rays at {}°, relief {} deep: rays/s",
        t["side"],
        t["map"].as_str().unwrap_or("?"),
        t["rays"],
        t["angle_deg"],
        t["relief_depth"]
    );
    println!(
        "   {:<20} {:>8} {:>14} {:>14}",
        "method", "fetches", "1 thread", "all threads"
    );
    for m in t["methods"].as_array().into_iter().flatten() {
        println!(
            "   {:<20} {:>8} {:>14.3e} {:>14.3e}",
            m["method"].as_str().unwrap_or("?"),
            m["fetches_per_ray"],
            m["rays_per_s_single_thread"].as_f64().unwrap_or(f64::NAN),
            m["rays_per_s_all_threads"].as_f64().unwrap_or(f64::NAN)
        );
    }
    let l = &doc["lod"];
    match l["device"].as_str() {
        Some(device) => {
            println!(
                "7. level of detail on {device}: {}² map tiled {} x {}, {} x {} image",
                l["side"], l["tiles"], l["tiles"], l["image"], l["image"]
            );
            for (key, what) in [("level0", "level 0 only"), ("mips", "8 levels")] {
                let r = &l[key];
                println!(
                    "   {what:<13} draw + readback {} ms, shimmer {} (mean |Δ green| over {} pixels, quad moved 0.4 px)",
                    f(&(r["seconds"].as_f64().unwrap_or(f64::NAN) * 1e3).into(), 1),
                    f(&r["shimmer"], 2),
                    r["pixels"]
                );
            }
            println!(
                "   CPU cones: level 0 {} s, all levels {} s",
                f(&l["cpu_generate_level0_seconds"], 3),
                f(&l["cpu_generate_mips_seconds"], 3)
            );
        }
        None => println!(
            "7. level of detail: not measured ({})",
            l["reason"].as_str().unwrap_or("?")
        ),
    }
}
