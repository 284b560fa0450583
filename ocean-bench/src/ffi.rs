//! `ocean bench ffi`: what the C ABI's boundary costs per call, against the Rust call it wraps,
//! in one run: the wave sum at 1024 points, the scene's continuous height query at 1024 points
//! and the sea colour of 1024 pixels, each with the same inputs and outputs on both sides, and
//! the cost of a call that does nothing but cross the boundary (`ocean_waves_count`: the panic
//! guard, the handle registry's lookup and the last-error bookkeeping).
//!
//! Both sides run interleaved ([`interleaved_medians`]) on one thread's worth of work: batches
//! of 1024 stay below the sizes at which either side splits work over threads.

use glam::{DVec2, DVec3, Vec2, Vec3};
use ocean::measure::{self, SeaColor, Waves};
use ocean::{
    OceanBoxDesc, OceanDVec2, OceanDVec3, OceanEffects, OceanHeightSample, OceanRefraction,
    OceanSeaColorInput, OceanSeaLight, OceanStatus, OceanVec3, OceanWaterGridDesc, OceanWaveDesc,
    OceanWindDesc,
};
use ocean_brdf::sea::sea_color;
use ocean_brdf::{Lighting, SeaParams, SkyParams, SlopeVariance};
use ocean_wtb::continuous::HeightSample;
use ocean_wtb::scenarios::scenario_1;
use serde_json::{Value, json};

use crate::options::BenchOptions;
use crate::timing::{bench_wave_descs, bench_waves, interleaved_medians};

/// Points or pixels per call: the batch size the overhead target is stated for.
const BATCH: usize = 1024;

/// Calls per timed sample: a sample of one call of a few microseconds would measure the clock.
const CALLS: usize = 64;

/// Calls per timed sample of the empty crossing.
const CROSSINGS: usize = 100_000;

fn ok(status: OceanStatus, what: &str) -> Result<(), String> {
    measure::check(status).map_err(|e| format!("{what}: {e}"))
}

/// One overhead row: the Rust and C medians per call, microseconds, and their ratio.
fn row(name: &str, rust_ms: f64, c_ms: f64) -> Value {
    let per = |ms: f64| ms * 1e3 / CALLS as f64;
    json!({
        "name": name,
        "batch": BATCH,
        "rust_us": per(rust_ms),
        "c_abi_us": per(c_ms),
        "overhead_percent": (c_ms / rust_ms - 1.0) * 100.0,
        "overhead_ns": (per(c_ms) - per(rust_ms)) * 1e3,
    })
}

/// The wave sum: `WaveSet::evaluate_points` against `ocean_waves_evaluate` on 60 waves.
fn waves(runs: u32) -> Result<(Value, Waves), String> {
    let set = bench_waves(60);
    let descs: Vec<OceanWaveDesc> = bench_wave_descs(60)
        .iter()
        .map(|d| OceanWaveDesc {
            amplitude: d.amplitude,
            wavelength: d.wavelength,
            direction_x: d.direction.x,
            direction_z: d.direction.y,
            phase: d.phase,
            depth: f64::INFINITY,
        })
        .collect();
    let handle = Waves::new(&descs)?;
    // One 64 m lattice cell of the C call (corner (0, 0)): its double world positions go
    // through the same float kernel call as the Rust one, so the bits must agree.
    let xz: Vec<Vec2> = (0..BATCH)
        .map(|i| Vec2::new((i % 32) as f32 * 1.7, (i / 32) as f32 * 1.9))
        .collect();
    let c_xz: Vec<OceanDVec2> = xz
        .iter()
        .map(|p| OceanDVec2 {
            x: f64::from(p.x),
            z: f64::from(p.y),
        })
        .collect();
    let (mut pos, mut nrm) = (vec![Vec3::ZERO; BATCH], vec![Vec3::ZERO; BATCH]);
    let (mut c_pos, mut c_nrm) = (
        vec![OceanDVec3::default(); BATCH],
        vec![OceanVec3::default(); BATCH],
    );
    let time = 12.5;
    let mut status = OceanStatus::Ok;
    let [rust, c] = interleaved_medians(
        runs,
        [
            &mut || {
                for _ in 0..CALLS {
                    set.evaluate_points(DVec2::ZERO, &xz, time, &mut pos, &mut nrm)
                        .expect("valid points");
                }
            },
            &mut || {
                for _ in 0..CALLS {
                    let s = handle.evaluate(&c_xz, time, &mut c_pos, &mut c_nrm);
                    if s != OceanStatus::Ok {
                        status = s;
                    }
                }
            },
        ],
    );
    ok(status, "ocean_waves_evaluate")?;
    // The same bits both ways: the comparison is of one computation.
    let same = pos
        .iter()
        .zip(&c_pos)
        .all(|(a, b)| f64::from(a.x) == b.x && f64::from(a.y) == b.y && f64::from(a.z) == b.z);
    if !same {
        return Err("ocean_waves_evaluate differs from WaveSet::evaluate_points".to_owned());
    }
    Ok((row("waves evaluate, 60 waves", rust, c), handle))
}

/// The continuous height query of scenario 1 (128², two boxes): `Frame::continuous_heights_par`
/// against `ocean_wtb_scene_heights_continuous`.
fn heights(runs: u32) -> Result<Value, String> {
    let n = 128;
    let mut scene = scenario_1(n).map_err(|e| e.to_string())?;
    let c_scene = c_scenario_1(n)?;
    let at: Vec<DVec2> = (0..BATCH)
        .map(|i| DVec2::new(3.0 + (i % 32) as f64 * 3.9, 5.0 + (i / 32) as f64 * 3.7))
        .collect();
    let c_at: Vec<OceanDVec2> = at.iter().map(|p| OceanDVec2 { x: p.x, z: p.y }).collect();
    let mut samples = vec![HeightSample::default(); BATCH];
    let mut c_samples = vec![OceanHeightSample::default(); BATCH];
    let time = 30.0;
    let mut status = OceanStatus::Ok;
    let [rust, c] = interleaved_medians(
        runs,
        [
            &mut || {
                for _ in 0..CALLS {
                    let frame = scene.frame(time, None).expect("a valid time");
                    frame
                        .continuous_heights_par(&at, &mut samples)
                        .expect("valid points");
                }
            },
            &mut || {
                for _ in 0..CALLS {
                    let s = c_scene.heights_continuous(time, &c_at, &mut c_samples);
                    if s != OceanStatus::Ok {
                        status = s;
                    }
                }
            },
        ],
    );
    ok(status, "ocean_wtb_scene_heights_continuous")?;
    if samples
        .iter()
        .zip(&c_samples)
        .any(|(a, b)| a.height != b.height)
    {
        return Err("the C scene answers differently from scenario 1".to_owned());
    }
    Ok(row("scene heights (continuous), scenario 1", rust, c))
}

/// Scenario 1 built through the C ABI, box for box (`ocean_wtb::scenarios::scenario_1`).
fn c_scenario_1(n: usize) -> Result<measure::Scene, String> {
    let (grid, terrain) = ocean_wtb::scenarios::sloping(n).map_err(|e| e.to_string())?;
    let heights = terrain.heights().ok_or("scenario 1 has a terrain")?;
    let desc = OceanWaterGridDesc {
        origin_x: grid.origin().x,
        origin_z: grid.origin().y,
        spacing: grid.spacing(),
        nx: grid.nx(),
        nz: grid.nz(),
    };
    let effects = OceanEffects {
        refraction: OceanRefraction::PhaseShift,
        shoaling: 0,
        ..measure::effects_default()?
    };
    let s = n as f64 / 64.0;
    let winds = [
        (
            7.0,
            (1.0, 0.15),
            (-2.0 * s, -4.0 * s),
            66.0 * s,
            70.0 * s,
            1,
            11,
        ),
        (
            5.0,
            (0.7, 1.0),
            (30.0 * s, -30.0 * s),
            60.0 * s,
            90.0 * s,
            2,
            12,
        ),
    ];
    let boxes: Vec<OceanBoxDesc> = winds
        .iter()
        .map(
            |&(speed, (dx, dz), (ox, oz), width, fetch, trains, seed)| OceanBoxDesc {
                wind: OceanWindDesc {
                    speed,
                    direction_x: dx,
                    direction_z: dz,
                    origin_x: ox,
                    origin_z: oz,
                    width,
                    fetch,
                    start: -1.0,
                    build_up: 0.0,
                    sustain: f64::INFINITY,
                    decay: 0.0,
                    seed,
                    trains,
                    ..Default::default()
                },
                smoothing: 4.0,
                ..Default::default()
            },
        )
        .collect();
    measure::Scene::new(&desc, heights, &effects, &boxes)
}

/// The sea colour of 1024 pixels: `ocean_brdf::sea::sea_color` in a loop against
/// `ocean_sea_color_batch` (which validates every input before it writes).
fn sea_colour(runs: u32) -> Result<Value, String> {
    let lighting =
        Lighting::new(SkyParams::default(), SeaParams::default()).map_err(|e| e.to_string())?;
    let map = lighting.sky_map(64).map_err(|e| e.to_string())?;
    let c_lighting = SeaColor::new(64)?;
    let inputs: Vec<(DVec3, DVec3)> = (0..BATCH)
        .map(|i| {
            let a = i as f64 * 0.0061;
            (
                DVec3::new(a.cos() * 0.8, -0.3 - 0.2 * (a * 3.0).sin(), a.sin() * 0.8).normalize(),
                DVec3::new(0.05 * (a * 7.0).sin(), 1.0, 0.05 * (a * 5.0).cos()).normalize(),
            )
        })
        .collect();
    let variance = SlopeVariance { x: 0.01, y: 0.006 };
    let wind = DVec2::new(1.0, 0.2);
    let c_inputs: Vec<OceanSeaColorInput> = inputs
        .iter()
        .map(|(v, n)| OceanSeaColorInput {
            v: OceanDVec3 {
                x: v.x,
                y: v.y,
                z: v.z,
            },
            n: OceanDVec3 {
                x: n.x,
                y: n.y,
                z: n.z,
            },
            wind: OceanDVec2 {
                x: wind.x,
                z: wind.y,
            },
            sigma_x2: variance.x,
            sigma_y2: variance.y,
        })
        .collect();
    let mut out = Vec::with_capacity(BATCH);
    let mut c_out = vec![OceanSeaLight::default(); BATCH];
    let mut status = OceanStatus::Ok;
    let [rust, c] = interleaved_medians(
        runs,
        [
            &mut || {
                for _ in 0..CALLS {
                    out.clear();
                    for (v, n) in &inputs {
                        out.push(
                            sea_color(&lighting, &map, *v, *n, wind, variance)
                                .expect("valid inputs"),
                        );
                    }
                    std::hint::black_box(&out);
                }
            },
            &mut || {
                for _ in 0..CALLS {
                    let s = c_lighting.batch(&c_inputs, &mut c_out);
                    if s != OceanStatus::Ok {
                        status = s;
                    }
                }
            },
        ],
    );
    ok(status, "ocean_sea_color_batch")?;
    Ok(row("sea colour batch, 64² sky map", rust, c))
}

/// The empty crossing: `ocean_waves_count` (guard, registry lookup, last-error clear) against
/// reading the count in Rust; nanoseconds per call.
fn crossing(runs: u32, handle: &Waves) -> Result<Value, String> {
    let set = bench_waves(60);
    let (mut rust_total, mut c_total) = (0usize, 0usize);
    let mut status = OceanStatus::Ok;
    let [rust, c] = interleaved_medians(
        runs,
        [
            &mut || {
                for _ in 0..CROSSINGS {
                    rust_total = rust_total.wrapping_add(std::hint::black_box(&set).waves().len());
                }
            },
            &mut || {
                for _ in 0..CROSSINGS {
                    let (s, n) = std::hint::black_box(handle).count();
                    if s != OceanStatus::Ok {
                        status = s;
                    }
                    c_total = c_total.wrapping_add(n);
                }
            },
        ],
    );
    std::hint::black_box((rust_total, c_total));
    ok(status, "ocean_waves_count")?;
    let ns = |ms: f64| ms * 1e6 / CROSSINGS as f64;
    Ok(json!({
        "name": "empty crossing (ocean_waves_count)",
        "rust_ns": ns(rust),
        "c_abi_ns": ns(c),
        "overhead_ns": ns(c) - ns(rust),
    }))
}

/// Runs the suite.
pub fn ffi(args: &BenchOptions) -> Result<Value, String> {
    let (waves_row, handle) = waves(args.runs)?;
    let heights_row = heights(args.runs)?;
    let sea_row = sea_colour(args.runs)?;
    let crossing_row = crossing(args.runs, &handle)?;
    Ok(json!({
        "batch": BATCH,
        "calls_per_sample": CALLS,
        "rows": [waves_row, heights_row, sea_row],
        "crossing": crossing_row,
    }))
}

/// Prints the suite's table.
pub fn print(doc: &Value) {
    println!("C ABI against the Rust call, batches of {BATCH} (median per call):");
    println!(
        "  {:<44} {:>10} {:>10} {:>10} {:>9}",
        "call", "Rust µs", "C ABI µs", "extra ns", "overhead"
    );
    for r in doc["rows"].as_array().into_iter().flatten() {
        println!(
            "  {:<44} {:>10.2} {:>10.2} {:>10.0} {:>8.2}%",
            r["name"].as_str().unwrap_or(""),
            r["rust_us"].as_f64().unwrap_or(f64::NAN),
            r["c_abi_us"].as_f64().unwrap_or(f64::NAN),
            r["overhead_ns"].as_f64().unwrap_or(f64::NAN),
            r["overhead_percent"].as_f64().unwrap_or(f64::NAN),
        );
    }
    let c = &doc["crossing"];
    println!(
        "  {}: {:.1} ns per call ({:.1} ns in Rust)",
        c["name"].as_str().unwrap_or(""),
        c["c_abi_ns"].as_f64().unwrap_or(f64::NAN),
        c["rust_ns"].as_f64().unwrap_or(f64::NAN),
    );
}
