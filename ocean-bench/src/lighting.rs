//! `ocean bench lighting`: the lighting figures (performance and the paper's validation).
//!
//! 1. **CPU sea colour**: Algorithm 5.1 ([`sea_color_unchecked`], with the 512² sky map)
//!    evaluations per second on one thread and on all threads, over a fixed table of views,
//!    normals and variances.
//! 2. **Validation** (§7.2, Fig. 10): per-row mean radiance of the filtered model and of a
//!    constant-BRDF model against the detailed-geometry, perfect-mirror reference, for a calm
//!    (5 m/s) and an agitated (15 m/s) sea; `--plot FILE.png` draws the per-row curves like
//!    Fig. 10's right column. The Sun's term (the paper's Sun, 1/8000 of the hemisphere) is
//!    compared per row too, with the reference's standard error.
//! 3. **GPU renderer**: time per frame at 1280×720 and 1920×1080 for views 4 m, 1000 m and
//!    8000 m above the sea (the paper: 52, 87 and 130 fps at 1024×768 on a GeForce 8800 GTS),
//!    and the ratio of the 8000 m view to the 4 m view (target ≤ 0.4: the cost follows the
//!    resolved waves).

use std::path::Path;
use std::time::Instant;

use glam::{DVec2, DVec3};
use ocean_brdf::sea::sea_color_unchecked;
use ocean_brdf::validation::{RowMeans, ValidationParams, validate};
use ocean_brdf::{Lighting, SeaParams, SkyParams, SlopeVariance, SpectrumParams};
use ocean_core::rng::Pcg32;
use rayon::prelude::*;
use serde_json::{Value, json};

use crate::gpu::Bench;
use crate::options::BenchOptions;
use crate::plot::Canvas;
use crate::timing::{cpu_name, interleaved_medians};

/// Inputs per timed batch.
const BATCH: usize = 1 << 16;
/// The seas of the validation: wind speeds, m/s.
const SEAS: [f64; 2] = [5.0, 15.0];

pub fn lighting(args: &BenchOptions) -> Result<Value, String> {
    let cpu = cpu_figures(args.runs)?;
    let gpu = if args.no_gpu {
        Value::Null
    } else {
        match Bench::new() {
            Ok(bench) => gpu_figures(&bench, args.runs)?,
            Err(why) => json!({ "skipped": why }),
        }
    };
    let mut seas = Vec::new();
    let mut curves = Vec::new();
    for wind in SEAS {
        let params = ValidationParams {
            spectrum: SpectrumParams {
                wind_speed: wind,
                ..SpectrumParams::default()
            },
            ..ValidationParams::default()
        };
        let t = Instant::now();
        let rows = validate(&params).map_err(|e| e.to_string())?;
        seas.push(validation_summary(wind, &rows, t.elapsed().as_secs_f64()));
        curves.push((wind, rows));
    }
    let sun: Vec<Value> = curves
        .iter()
        .map(|(wind, rows)| sun_summary(*wind, rows))
        .collect();
    if let Some(path) = &args.plot {
        plot(&curves, path)?;
    }
    let doc = json!({
        "suite": "lighting",
        "cpu": cpu_name(),
        "threads": rayon::current_num_threads(),
        "sea_color": cpu,
        "gpu": gpu,
        "validation": seas,
        "sun_validation": Value::Array(sun),
    });
    Ok(doc)
}

/// The suite's tables.
pub fn print(doc: &Value) {
    print_table(doc);
    print_sun(doc);
}

/// Viewport sizes of the GPU figures.
const SIZES: [(u32, u32); 2] = [(1280, 720), (1920, 1080)];
/// Camera heights of the GPU figures, metres (the paper's 4, 1000 and 8000 m views).
const HEIGHTS: [f64; 3] = [4.0, 1000.0, 8000.0];
/// The 8000 m view's cost relative to the 4 m view's, at most (the lighting target).
const TARGET_FAR_RATIO: f64 = 0.4;

/// GPU time per frame of the ocean renderer (default spectrum: 60 waves from 2 cm to 30 m;
/// default lighting) at each size and height, the camera pitched 10° below the horizon with a
/// 60° vertical field of view, and the 8000 m / 4 m ratios.
fn gpu_figures(bench: &Bench, runs: u32) -> Result<Value, String> {
    use ocean_brdf::{Filter, FilteredSurface, Spectrum};
    use ocean_core::{Camera, DepthConvention, Far, Projection};
    use ocean_gpu::{OceanOptions, OceanRenderer};
    let e = |e: ocean_gpu::GpuError| e.to_string();
    let spectrum = Spectrum::new(SpectrumParams::default()).map_err(|e| e.to_string())?;
    let surface = FilteredSurface::new(&spectrum, Filter::PAPER).map_err(|e| e.to_string())?;
    let lighting =
        Lighting::new(SkyParams::default(), SeaParams::default()).map_err(|e| e.to_string())?;
    let ctx = bench.context();
    let mut renderer = OceanRenderer::new(ctx, OceanOptions::default()).map_err(e)?;
    renderer.set_surface(ctx, &surface).map_err(e)?;
    renderer.set_lighting(ctx, &lighting).map_err(e)?;
    let mut rows = Vec::new();
    for (w, h) in SIZES {
        let mut per_height = Vec::new();
        for height in HEIGHTS {
            let pitch = 10f64.to_radians();
            let camera = Camera::look_at(
                DVec3::new(0.0, height, 0.0),
                DVec3::new(0.0, height - pitch.sin(), -pitch.cos()),
                DVec3::Y,
                Projection::Perspective {
                    fov_y: 60f64.to_radians(),
                    aspect: w as f64 / h as f64,
                    near: 0.5,
                    far: Far::Infinite,
                },
                DepthConvention::ZERO_TO_ONE,
            )
            .map_err(|e| e.to_string())?;
            let mut r = bench.ocean(&renderer, &camera, (w, h), runs)?;
            r["height_m"] = json!(height);
            per_height.push(r);
        }
        let time = |i: usize| {
            per_height[i]["pass_ms"]
                .as_f64()
                .or_else(|| per_height[i]["wall_ms"].as_f64())
        };
        let ratio = match (time(2), time(0)) {
            (Some(far), Some(near)) if near > 0.0 => Some(far / near),
            _ => None,
        };
        rows.push(json!({
            "width": w,
            "height": h,
            "views": per_height,
            "ratio_8000_over_4": ratio,
            "target_ratio": TARGET_FAR_RATIO,
        }));
    }
    Ok(json!({ "adapter": bench.describe(), "frames": rows }))
}

/// Evaluations of Algorithm 5.1 per second, one thread and all threads.
fn cpu_figures(runs: u32) -> Result<Value, String> {
    let lighting =
        Lighting::new(SkyParams::default(), SeaParams::default()).map_err(|e| e.to_string())?;
    let map = lighting.sky_map(512).map_err(|e| e.to_string())?;
    let mut rng = Pcg32::new(4, 4);
    let inputs: Vec<(DVec3, DVec3, SlopeVariance)> = (0..BATCH)
        .map(|_| {
            let elevation = (0.5 + 88.5 * rng.next_f64()).to_radians();
            let azimuth = rng.next_f64() * std::f64::consts::TAU;
            let v = DVec3::new(
                elevation.cos() * azimuth.sin(),
                elevation.sin(),
                elevation.cos() * azimuth.cos(),
            );
            let tilt = (20.0 * rng.next_f64()).to_radians();
            let a = rng.next_f64() * std::f64::consts::TAU;
            let n = DVec3::new(tilt.sin() * a.cos(), tilt.cos(), tilt.sin() * a.sin());
            let s = 0.05 * rng.next_f64();
            (v, n, SlopeVariance { x: s, y: 0.5 * s })
        })
        .collect();
    let wind = DVec2::new(0.0, -1.0);
    let eval = |&(v, n, var): &(DVec3, DVec3, SlopeVariance)| {
        sea_color_unchecked(&lighting, &map, v, n, wind, var).total()
    };
    let mut one = || {
        std::hint::black_box(inputs.iter().map(eval).fold(DVec3::ZERO, |a, b| a + b));
    };
    let mut all = || {
        std::hint::black_box(
            inputs
                .par_iter()
                .map(eval)
                .reduce(|| DVec3::ZERO, |a, b| a + b),
        );
    };
    let [t1, tn] = interleaved_medians(runs, [&mut one, &mut all]);
    Ok(json!({
        "evaluations": BATCH,
        "single_thread_per_s": BATCH as f64 / (t1 * 1e-3),
        "all_threads_per_s": BATCH as f64 / (tn * 1e-3),
    }))
}

fn sum(c: DVec3) -> f64 {
    c.x + c.y + c.z
}

fn rel(a: f64, b: f64) -> f64 {
    (a - b).abs() / b
}

/// The Sun's term per row: the reference's mean and relative standard error, the model's and
/// the constant BRDF's relative errors (signed), and their bias, mean and worst over the rows
/// nearer and farther than 300 m.
fn sun_summary(wind: f64, rows: &[RowMeans]) -> Value {
    let err = |r: &RowMeans, m: DVec3| (sum(m) - sum(r.reference.sun)) / sum(r.reference.sun);
    let per_row: Vec<Value> = rows
        .iter()
        .map(|r| {
            json!({
                "row": r.row,
                "distance_m": r.distance,
                "reference": sum(r.reference.sun),
                "reference_error": sum(r.reference_sun_error) / sum(r.reference.sun),
                "model_error": err(r, r.model.sun),
                "constant_error": err(r, r.constant.sun),
            })
        })
        .collect();
    let stats = |near: bool, m: fn(&RowMeans) -> DVec3| {
        let e: Vec<f64> = rows
            .iter()
            .filter(|r| (r.distance < 300.0) == near)
            .map(|r| err(r, m(r)))
            .collect();
        let n = e.len().max(1) as f64;
        json!({
            "bias": e.iter().sum::<f64>() / n,
            "mean": e.iter().map(|x| x.abs()).sum::<f64>() / n,
            "worst": e.iter().fold(0.0f64, |w, x| w.max(x.abs())),
        })
    };
    json!({
        "wind_speed": wind,
        "sun_angular_radius": ocean_brdf::validation::PAPER_SUN_ANGULAR_RADIUS,
        "model_near": stats(true, |r| r.model.sun),
        "model_far": stats(false, |r| r.model.sun),
        "constant_near": stats(true, |r| r.constant.sun),
        "constant_far": stats(false, |r| r.constant.sun),
        "rows": per_row,
    })
}

/// Worst and mean relative errors per component and model.
fn validation_summary(wind: f64, rows: &[RowMeans], seconds: f64) -> Value {
    let stats = |pick: &dyn Fn(&RowMeans) -> (f64, f64), far_only: bool| {
        let errors: Vec<f64> = rows
            .iter()
            .filter(|r| !far_only || r.distance > 300.0)
            .map(|r| {
                let (m, reference) = pick(r);
                rel(m, reference)
            })
            .collect();
        let worst = errors.iter().copied().fold(0.0, f64::max);
        let mean = errors.iter().sum::<f64>() / errors.len().max(1) as f64;
        json!({ "worst": worst, "mean": mean })
    };
    json!({
        "wind_speed": wind,
        "rows": rows.len(),
        "nearest_m": rows.first().map(|r| r.distance),
        "farthest_m": rows.last().map(|r| r.distance),
        "seconds": seconds,
        "model": {
            "sky": stats(&|r| (sum(r.model.sky), sum(r.reference.sky)), false),
            "sea": stats(&|r| (sum(r.model.sea), sum(r.reference.sea)), false),
            "sky_beyond_300m": stats(&|r| (sum(r.model.sky), sum(r.reference.sky)), true),
            "sea_beyond_300m": stats(&|r| (sum(r.model.sea), sum(r.reference.sea)), true),
        },
        "constant_brdf": {
            "sky": stats(&|r| (sum(r.constant.sky), sum(r.reference.sky)), false),
            "sea": stats(&|r| (sum(r.constant.sea), sum(r.reference.sea)), false),
            "sky_beyond_300m": stats(&|r| (sum(r.constant.sky), sum(r.reference.sky)), true),
            "sea_beyond_300m": stats(&|r| (sum(r.constant.sea), sum(r.reference.sea)), true),
        },
    })
}

fn print_sun(doc: &Value) {
    println!(
        "Sun's term per row (the paper's Sun, 1/8000 of the hemisphere), relative error \
         bias / mean / worst, rows nearer and farther than 300 m:"
    );
    for s in doc["sun_validation"].as_array().into_iter().flatten() {
        let f = |k: &str, w: &str| s[k][w].as_f64().unwrap_or(f64::NAN) * 100.0;
        let ref_error = |near: bool| {
            let e: Vec<f64> = s["rows"]
                .as_array()
                .into_iter()
                .flatten()
                .filter(|r| (r["distance_m"].as_f64().unwrap_or(0.0) < 300.0) == near)
                .filter_map(|r| r["reference_error"].as_f64())
                .collect();
            e.iter().sum::<f64>() / e.len().max(1) as f64 * 100.0
        };
        println!(
            "  wind {} m/s: model near {:+.1} / {:.1} / {:.1} %, far {:+.1} / {:.1} / {:.1} %; \
             constant BRDF far {:+.1} / {:.1} / {:.1} %; reference error per row, mean: near \
             {:.1} %, far {:.1} %",
            s["wind_speed"],
            f("model_near", "bias"),
            f("model_near", "mean"),
            f("model_near", "worst"),
            f("model_far", "bias"),
            f("model_far", "mean"),
            f("model_far", "worst"),
            f("constant_far", "bias"),
            f("constant_far", "mean"),
            f("constant_far", "worst"),
            ref_error(true),
            ref_error(false),
        );
    }
}

fn print_table(doc: &Value) {
    println!(
        "ocean bench lighting — {} ({} threads)",
        doc["cpu"], doc["threads"]
    );
    let c = &doc["sea_color"];
    println!(
        "sea colour (Algorithm 5.1, CPU): {:.2} M/s on 1 thread, {:.2} M/s on all",
        c["single_thread_per_s"].as_f64().unwrap_or(0.0) / 1e6,
        c["all_threads_per_s"].as_f64().unwrap_or(0.0) / 1e6
    );
    let g = &doc["gpu"];
    if let Some(why) = g["skipped"].as_str() {
        println!("GPU: skipped ({why})");
    } else if let Some(frames) = g["frames"].as_array() {
        println!(
            "GPU renderer on {}: frame time (render pass), ms",
            g["adapter"]
        );
        for f in frames {
            let views = f["views"].as_array().cloned().unwrap_or_default();
            let cell = |v: &Value| {
                v["pass_ms"]
                    .as_f64()
                    .map(|t| format!("{t:.2}"))
                    .unwrap_or_else(|| {
                        format!("{:.2} (wall)", v["wall_ms"].as_f64().unwrap_or(f64::NAN))
                    })
            };
            println!(
                "  {}×{}: 4 m {}  1000 m {}  8000 m {}  ratio 8000/4 m {:.2} (target ≤ {})",
                f["width"],
                f["height"],
                views.first().map(cell).unwrap_or_default(),
                views.get(1).map(cell).unwrap_or_default(),
                views.get(2).map(cell).unwrap_or_default(),
                f["ratio_8000_over_4"].as_f64().unwrap_or(f64::NAN),
                f["target_ratio"]
            );
        }
    }
    println!("validation (Fig. 10), relative error of the row means, worst / mean:");
    for s in doc["validation"].as_array().into_iter().flatten() {
        println!(
            "  wind {} m/s, {} rows {:.0}–{:.0} m ({:.1} s):",
            s["wind_speed"],
            s["rows"],
            s["nearest_m"].as_f64().unwrap_or(0.0),
            s["farthest_m"].as_f64().unwrap_or(0.0),
            s["seconds"].as_f64().unwrap_or(0.0)
        );
        for (name, key) in [("model", "model"), ("constant BRDF", "constant_brdf")] {
            let m = &s[key];
            let f = |k: &str, w: &str| m[k][w].as_f64().unwrap_or(f64::NAN) * 100.0;
            println!(
                "    {name:14} sky {:5.1} / {:4.1} %  sea {:5.1} / {:4.1} %  beyond 300 m: sky {:5.1} / {:4.1} %  sea {:5.1} / {:4.1} %",
                f("sky", "worst"),
                f("sky", "mean"),
                f("sea", "worst"),
                f("sea", "mean"),
                f("sky_beyond_300m", "worst"),
                f("sky_beyond_300m", "mean"),
                f("sea_beyond_300m", "worst"),
                f("sea_beyond_300m", "mean"),
            );
        }
    }
}

/// The three methods' values of one component for a row: reference, model, constant BRDF.
type Pick = fn(&RowMeans) -> [f64; 3];

/// Fig. 10's right column: for each sea (one band of panels) and component (Sun, sky,
/// refracted light), the row means against the row, far rows at the top: reference black (for
/// the Sun, grey lines at ± its standard error), model red, constant BRDF blue; each panel
/// scaled to its largest value.
fn plot(curves: &[(f64, Vec<RowMeans>)], path: &Path) -> Result<(), String> {
    const PANEL_W: usize = 320;
    const PANEL_H: usize = 280;
    const MARGIN: f64 = 12.0;
    let comps: [(&str, Pick); 3] = [
        ("sun", |r| {
            [sum(r.reference.sun), sum(r.model.sun), sum(r.constant.sun)]
        }),
        ("sky", |r| {
            [sum(r.reference.sky), sum(r.model.sky), sum(r.constant.sky)]
        }),
        ("sea", |r| {
            [sum(r.reference.sea), sum(r.model.sea), sum(r.constant.sea)]
        }),
    ];
    let colours = [[0, 0, 0], [200, 30, 30], [30, 60, 200]];
    let sun_band =
        |r: &RowMeans, side: f64| sum(r.reference.sun) + side * sum(r.reference_sun_error);
    let mut canvas = Canvas::new(PANEL_W * comps.len(), PANEL_H * curves.len(), [255; 3]);
    for (band, (_, rows)) in curves.iter().enumerate() {
        for (col, (_, pick)) in comps.iter().enumerate() {
            let (x0, y0) = (
                (col * PANEL_W) as f64 + MARGIN,
                (band * PANEL_H) as f64 + MARGIN,
            );
            let (w, h) = (PANEL_W as f64 - 2.0 * MARGIN, PANEL_H as f64 - 2.0 * MARGIN);
            canvas.rect(x0, y0, x0 + w, y0 + h, [160; 3]);
            let mut max = rows.iter().flat_map(pick).fold(f64::MIN_POSITIVE, f64::max);
            if col == 0 {
                max = rows.iter().map(|r| sun_band(r, 1.0)).fold(max, f64::max);
            }
            let n = rows.len().max(2) as f64 - 1.0;
            if col == 0 {
                for side in [-1.0, 1.0] {
                    let point = |i: usize| {
                        let v = sun_band(&rows[i], side).max(0.0) / max;
                        (x0 + v * w, y0 + h - i as f64 / n * h)
                    };
                    for i in 1..rows.len() {
                        let (a, b) = (point(i - 1), point(i));
                        canvas.line(a.0, a.1, b.0, b.1, [170; 3]);
                    }
                }
            }
            for (k, colour) in colours.iter().enumerate() {
                // rows[0] is the nearest: bottom of the panel.
                let point = |i: usize| {
                    let v = pick(&rows[i])[k] / max;
                    (x0 + v * w, y0 + h - i as f64 / n * h)
                };
                for i in 1..rows.len() {
                    let (a, b) = (point(i - 1), point(i));
                    canvas.line(a.0, a.1, b.0, b.1, *colour);
                }
            }
        }
    }
    canvas.write_png(path)
}
