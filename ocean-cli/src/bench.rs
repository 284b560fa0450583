//! `ocean bench`: the figures of each technique's performance targets (BENCHMARKS.md).
//!
//! Times are medians over repeated runs after a warm-up; every figure is measured in the same
//! run as the baseline it is compared with.

use std::f64::consts::TAU;
use std::time::Instant;

use clap::{Args, ValueEnum};
use glam::{DVec2, Vec3};
use ocean_core::parallel::rows_per_task;
use ocean_core::{Depth, Grid, WaveDesc, WaveSet};
use rayon::prelude::*;
use serde_json::{Value, json};

use crate::{bench_ffi, bench_gpu, bench_lighting, bench_relief, bench_sao, bench_wtb};

#[derive(Args)]
pub struct BenchArgs {
    /// Which suite to run.
    suite: Suite,
    /// Print one JSON document instead of a table.
    #[arg(long)]
    pub json: bool,
    /// Grid side length (points per side; `gerstner` only).
    #[arg(long, default_value_t = 1024, value_parser = clap::value_parser!(u32).range(8..=8192))]
    size: u32,
    /// Timed repetitions per figure (the median is reported).
    #[arg(long, default_value_t = 15, value_parser = clap::value_parser!(u32).range(1..=1000))]
    pub runs: u32,
    /// Skip the GPU figures.
    #[arg(long)]
    pub no_gpu: bool,
    /// `lighting` only: draw the validation's per-row curves (Fig. 10) into this PNG file.
    #[arg(long)]
    pub plot: Option<std::path::PathBuf>,
}

#[derive(Clone, Copy, ValueEnum)]
enum Suite {
    /// The trochoid (Gerstner) wave sum on a grid: CPU single-thread, all threads, GPU.
    Gerstner,
    /// Wave train boxes: scenario 1 from 64² to 2048², scaling, culling, effect
    /// costs, height queries.
    Wtb,
    /// Ocean lighting: CPU sea-colour evaluations and the paper's validation
    /// (Fig. 10) against a detailed-geometry reference.
    Lighting,
    /// Scalable ambient obscurance: GPU time against the radius, with and without the z
    /// hierarchy, per pass at four resolutions with guard bands, and the CPU reference.
    Sao,
    /// Relief mapping: relaxed cone-map generation at 256², 512² and 1024², the
    /// brute-force oracle at 128², progress overhead, GPU generation, CPU tracer rays per second
    /// per method, the level of detail's draw time and shimmer on the GPU, and the accuracy
    /// table.
    Relief,
    /// The C ABI's cost per call against the Rust call it wraps (batches of 1024: the wave sum,
    /// the scene's height query, the sea colour) and of an empty crossing (handle checks).
    Ffi,
    /// Every suite above in turn; with `--json`, one document holding each suite's report with
    /// the date and the machine.
    All,
}

/// A wave set of `n` deep-water trochoids, wavelengths in geometric progression from 0.5 m to
/// 60 m and steepness 0.1 each: the shape of the lighting paper's spectrum (n = 60) and of
/// the wave-train paper's scenario 1 (n = 3).
pub fn bench_waves(n: usize) -> WaveSet {
    WaveSet::from_descs(&bench_wave_descs(n)).expect("benchmark waves are valid")
}

/// The descriptions of [`bench_waves`].
pub fn bench_wave_descs(n: usize) -> Vec<WaveDesc> {
    (0..n)
        .map(|i| {
            let f = if n > 1 {
                i as f64 / (n - 1) as f64
            } else {
                0.0
            };
            let lambda = 0.5 * 120f64.powf(f);
            let angle = 2.399 * i as f64;
            WaveDesc {
                amplitude: 0.1 * lambda / TAU,
                wavelength: lambda,
                direction: DVec2::new(angle.cos(), angle.sin()),
                phase: i as f64,
                depth: Depth::Deep,
            }
        })
        .collect()
}

/// Milliseconds taken by one call of `f`.
fn once_ms(f: &mut impl FnMut()) -> f64 {
    let start = Instant::now();
    f();
    start.elapsed().as_secs_f64() * 1e3
}

/// Median of each of `fs` over `runs` rounds, after two warm-up rounds. The functions run in
/// turn within each round, so a slow spell of the machine (often a shared virtual machine)
/// hits all of them alike and their ratios stay meaningful.
pub fn interleaved_medians<const N: usize>(runs: u32, mut fs: [&mut dyn FnMut(); N]) -> [f64; N] {
    let mut times: [Vec<f64>; N] = std::array::from_fn(|_| Vec::new());
    for round in 0..runs + 2 {
        for (f, t) in fs.iter_mut().zip(times.iter_mut()) {
            // An untimed run first: each figure is then the steady state of a frame loop
            // that calls the same function again. Without it, a parallel run that follows a
            // single-threaded one pays for waking the idle pool threads and cores, which on a
            // virtual machine costs up to milliseconds.
            f();
            let ms = once_ms(f);
            if round >= 2 {
                t.push(ms);
            }
        }
    }
    times.map(|mut t| {
        t.sort_by(f64::total_cmp);
        t[t.len() / 2]
    })
}

/// The memory baseline of a grid `nx` points wide: writing the same output buffers once, with
/// the same threads and task partition as the grid evaluations, so a ratio to it isolates the
/// cost of the arithmetic.
pub fn memory_baseline(nx: usize, pos: &mut [Vec3], nrm: &mut [Vec3]) {
    let task = nx * rows_per_task(nx);
    pos.par_chunks_mut(task)
        .zip(nrm.par_chunks_mut(task))
        .enumerate()
        .for_each(|(j, (p, q))| {
            p.fill(Vec3::splat(j as f32));
            q.fill(Vec3::Y);
        });
    std::hint::black_box((pos, nrm));
}

impl Suite {
    /// Every suite, in the order of `ocean bench all`.
    const ALL: [Suite; 6] = [
        Suite::Gerstner,
        Suite::Wtb,
        Suite::Lighting,
        Suite::Sao,
        Suite::Relief,
        Suite::Ffi,
    ];

    fn name(self) -> &'static str {
        match self {
            Suite::Gerstner => "gerstner",
            Suite::Wtb => "wtb",
            Suite::Lighting => "lighting",
            Suite::Sao => "sao",
            Suite::Relief => "relief",
            Suite::Ffi => "ffi",
            Suite::All => "all",
        }
    }

    /// Runs the suite and returns its report.
    fn report(self, args: &BenchArgs) -> Result<Value, String> {
        match self {
            Suite::Gerstner => gerstner(args),
            Suite::Wtb => bench_wtb::wtb(args),
            Suite::Lighting => bench_lighting::lighting(args),
            Suite::Sao => bench_sao::sao(args),
            Suite::Relief => bench_relief::relief(args),
            Suite::Ffi => bench_ffi::ffi(args),
            Suite::All => Err("`all` is not one suite".to_owned()),
        }
    }

    /// Prints a report of this suite as tables.
    fn print(self, doc: &Value) {
        match self {
            Suite::Gerstner => print_gerstner(doc),
            Suite::Wtb => bench_wtb::print(doc),
            Suite::Lighting => bench_lighting::print(doc),
            Suite::Sao => bench_sao::print(doc),
            Suite::Relief => bench_relief::print(doc),
            Suite::Ffi => bench_ffi::print(doc),
            Suite::All => {}
        }
    }
}

pub fn run(args: &BenchArgs) -> Result<(), String> {
    let json = |v: &Value| serde_json::to_string_pretty(v).map_err(|e| e.to_string());
    if !matches!(args.suite, Suite::All) {
        let doc = args.suite.report(args)?;
        if args.json {
            println!("{}", json(&doc)?);
        } else {
            args.suite.print(&doc);
        }
        return Ok(());
    }
    let started = std::time::Instant::now();
    let mut suites = serde_json::Map::new();
    for suite in Suite::ALL {
        if crate::interrupt::requested() {
            return Err(crate::interrupt::MESSAGE.to_owned());
        }
        let t = std::time::Instant::now();
        let doc = suite.report(args)?;
        if !args.json {
            println!("== {} ({:.1} s)", suite.name(), t.elapsed().as_secs_f64());
            suite.print(&doc);
            println!();
        }
        suites.insert(suite.name().to_owned(), doc);
    }
    if args.json {
        let doc = json!({
            "suite": "all",
            "date": utc_date(std::time::SystemTime::now()),
            "cpu": cpu_name(),
            "threads": rayon::current_num_threads(),
            "os": std::env::consts::OS,
            "wall_s": started.elapsed().as_secs_f64(),
            "suites": suites,
        });
        println!("{}", json(&doc)?);
    }
    Ok(())
}

/// The UTC calendar date of `t` as YYYY-MM-DD (the proleptic Gregorian calendar, from the days
/// since 1970-01-01 by Howard Hinnant's `civil_from_days`).
fn utc_date(t: std::time::SystemTime) -> String {
    let secs = t
        .duration_since(std::time::UNIX_EPOCH)
        .map_or(0, |d| d.as_secs());
    let z = (secs / 86_400) as i64 + 719_468;
    let era = z.div_euclid(146_097);
    let doe = z.rem_euclid(146_097);
    let yoe = (doe - doe / 1460 + doe / 36_524 - doe / 146_096) / 365;
    let doy = doe - (365 * yoe + yoe / 4 - yoe / 100);
    let mp = (5 * doy + 2) / 153;
    let day = doy - (153 * mp + 2) / 5 + 1;
    let month = if mp < 10 { mp + 3 } else { mp - 9 };
    let year = yoe + era * 400 + i64::from(month <= 2);
    format!("{year:04}-{month:02}-{day:02}")
}

fn gerstner(args: &BenchArgs) -> Result<Value, String> {
    let side = args.size as usize;
    let n = side * side;
    let grid = Grid::centred(DVec2::new(100.0, -40.0), 0.25, side);
    let threads = rayon::current_num_threads();
    let mut pos = vec![Vec3::ZERO; n];
    let mut nrm = vec![Vec3::ZERO; n];
    let t = 1234.5;

    let baseline = |pos: &mut [Vec3], nrm: &mut [Vec3]| memory_baseline(side, pos, nrm);

    let gpu = if args.no_gpu {
        Err("skipped (--no-gpu)".to_string())
    } else {
        bench_gpu::Bench::new()
    };

    let mut cases = Vec::new();
    for waves in [3usize, 60] {
        let set = bench_waves(waves);
        // One buffer pair per measurement, so none of them finds the others' data in cache.
        let (mut bp, mut bn) = (pos.clone(), nrm.clone());
        let (mut tp, mut tn) = (pos.clone(), nrm.clone());
        let [baseline_ms, single_ms, threads_ms] = interleaved_medians(
            args.runs,
            [
                &mut || baseline(&mut bp, &mut bn),
                &mut || {
                    set.evaluate_grid(&grid, t, &mut pos, &mut nrm)
                        .expect("valid grid")
                },
                &mut || {
                    set.evaluate_grid_par(&grid, t, &mut tp, &mut tn)
                        .expect("valid grid")
                },
            ],
        );
        let evals = (n * waves) as f64;
        let per_core_single = evals / (single_ms * 1e-3);
        let per_core_threads = evals / (threads_ms * 1e-3) / threads as f64;
        let gpu_case = match &gpu {
            Ok(g) => g.gerstner(&set, &grid, t, args.runs),
            Err(e) => Err(e.clone()),
        };
        cases.push(json!({
            "waves": waves,
            "points": n,
            "cpu_single_ms": single_ms,
            "cpu_threads_ms": threads_ms,
            "threads": threads,
            "memory_baseline_ms": baseline_ms,
            "threads_over_baseline": threads_ms / baseline_ms,
            "evals_per_s_per_core_single": per_core_single,
            "evals_per_s_per_core_threads": per_core_threads,
            "gpu": match gpu_case {
                Ok(v) => v,
                Err(e) => json!({ "unavailable": e }),
            },
        }));
    }
    let report = json!({
        "suite": "gerstner",
        "grid": [side, side],
        "cpu": cpu_name(),
        "gpu_device": match &gpu { Ok(g) => Value::from(g.describe()), Err(_) => Value::Null },
        "cases": cases,
        "targets": {
            "3_waves_threads_over_baseline_max": 2.5,
            "60_waves_evals_per_s_per_core_min": 3.0e8,
        },
    });
    Ok(report)
}

fn print_gerstner(r: &Value) {
    println!(
        "gerstner: {}x{} grid, CPU {}, {} threads",
        r["grid"][0],
        r["grid"][1],
        r["cpu"].as_str().unwrap_or("?"),
        r["cases"][0]["threads"]
    );
    match r["gpu_device"].as_str() {
        Some(d) => println!("GPU: {d}"),
        None => println!(
            "GPU: {}",
            r["cases"][0]["gpu"]["unavailable"]
                .as_str()
                .unwrap_or("none")
        ),
    }
    println!(
        "{:>6} {:>12} {:>12} {:>12} {:>10} {:>16} {:>12}",
        "waves", "1 thread ms", "threads ms", "memory ms", "thr/mem", "evals/s/core", "GPU ms"
    );
    for c in r["cases"].as_array().into_iter().flatten() {
        let gpu = c["gpu"]["kernel_ms"]
            .as_f64()
            .or(c["gpu"]["wall_ms"].as_f64())
            .map_or("-".to_string(), |v| format!("{v:.3}"));
        println!(
            "{:>6} {:>12.3} {:>12.3} {:>12.3} {:>10.2} {:>16.3e} {:>12}",
            c["waves"],
            c["cpu_single_ms"].as_f64().unwrap_or(f64::NAN),
            c["cpu_threads_ms"].as_f64().unwrap_or(f64::NAN),
            c["memory_baseline_ms"].as_f64().unwrap_or(f64::NAN),
            c["threads_over_baseline"].as_f64().unwrap_or(f64::NAN),
            c["evals_per_s_per_core_single"]
                .as_f64()
                .unwrap_or(f64::NAN),
            gpu
        );
    }
    println!(
        "targets: 3 waves threads/memory <= 2.5; 60 waves >= 3.0e8 evaluations/s/core (single thread)"
    );
}

/// The CPU model from /proc/cpuinfo where there is one.
pub fn cpu_name() -> String {
    std::fs::read_to_string("/proc/cpuinfo")
        .ok()
        .and_then(|s| {
            s.lines()
                .find(|l| l.starts_with("model name"))
                .and_then(|l| l.split(':').nth(1))
                .map(|m| m.trim().to_string())
        })
        .unwrap_or_else(|| std::env::consts::ARCH.to_string())
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Dates around the epoch, a leap day and a century rule (2000 is leap, 2100 is not).
    #[test]
    fn utc_dates() {
        let at = |s: u64| utc_date(std::time::UNIX_EPOCH + std::time::Duration::from_secs(s));
        assert_eq!(at(0), "1970-01-01");
        assert_eq!(at(86_399), "1970-01-01");
        assert_eq!(at(951_782_400), "2000-02-29");
        assert_eq!(at(1_795_392_000), "2026-11-23");
        assert_eq!(at(4_107_542_400), "2100-03-01");
    }
}
