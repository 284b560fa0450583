//! `ocean bench gerstner`: the trochoid (Gerstner) wave sum on a grid, on the CPU with one
//! thread and with all, and on the GPU, against the memory baseline.

use glam::{DVec2, Vec3};
use ocean_core::Grid;
use serde_json::{Value, json};

use crate::options::BenchOptions;
use crate::timing::{bench_waves, cpu_name, interleaved_medians, memory_baseline};

pub(crate) fn gerstner(args: &BenchOptions) -> Result<Value, String> {
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
        crate::gpu::Bench::new()
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

pub(crate) fn print(r: &Value) {
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
