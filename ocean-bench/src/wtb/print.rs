//! The tables `ocean bench wtb` prints from its report.

use super::*;

/// The suite's tables.
pub fn print(doc: &Value) {
    print_wtb(doc);
}

fn num(v: &Value) -> f64 {
    v.as_f64().unwrap_or(f64::NAN)
}

fn print_wtb(r: &Value) {
    println!(
        "wtb: CPU {}, {} threads, kernel {}, {} rounds (fewer where stated); every time a median",
        r["cpu"].as_str().unwrap_or("?"),
        r["threads"],
        r["isa"].as_str().unwrap_or("?"),
        r["runs"]
    );
    println!();
    println!("1. Scenario 1 (2 boxes, 3 trains, phase-shift refraction), still boxes; medians");
    println!(
        "{:>6} {:>7} {:>11} {:>11} {:>11} {:>11} {:>9} {:>9}",
        "grid",
        "rounds",
        "prepare ms",
        "evaluate ms",
        "frame ms",
        "memory ms",
        "frame/mem",
        "ns/point"
    );
    for c in r["scenario_1"].as_array().into_iter().flatten() {
        println!(
            "{:>5}² {:>7} {:>11.3} {:>11.3} {:>11.3} {:>11.3} {:>9.2} {:>9.2}",
            c["side"].as_u64().unwrap_or(0),
            c["runs"].as_u64().unwrap_or(0),
            num(&c["prepare_ms"]),
            num(&c["evaluate_ms"]),
            num(&c["frame_ms"]),
            num(&c["memory_baseline_ms"]),
            num(&c["frame_over_baseline"]),
            num(&c["ns_per_point"]),
        );
    }
    println!(
        "   (prepare and evaluate are medians of their own; their sum need not be the frame median)"
    );
    println!();
    let s = &r["scaling"];
    println!(
        "2. Scaling (512² and 2048² interleaved again): t(2048²) / t(512²) = {:.3} / {:.3} ms = {:.2}",
        num(&s["t_2048_ms"]),
        num(&s["t_512_ms"]),
        num(&s["t2048_over_t512"])
    );
    println!();
    let c = &r["culling"];
    println!(
        "3. Culling, scenario 2 (7 boxes, 1 train each, refraction) at {}²:",
        c["side"]
    );
    println!(
        "   all visible {:.3} ms (prepare {:.3}, evaluate {:.3}); none visible {:.4} ms (prepare {:.4}, evaluate {:.4}); no frustum {:.3} ms; memory {:.4} ms",
        num(&c["all_visible_ms"]),
        num(&c["all_visible_prepare_ms"]),
        num(&c["all_visible_evaluate_ms"]),
        num(&c["none_visible_ms"]),
        num(&c["none_visible_prepare_ms"]),
        num(&c["none_visible_evaluate_ms"]),
        num(&c["no_frustum_ms"]),
        num(&c["memory_baseline_ms"]),
    );
    println!(
        "   none / all = {:.2}%  (memory baseline / all = {:.2}%)",
        100.0 * num(&c["none_over_all"]),
        100.0 * num(&c["baseline_over_all"])
    );
    println!(
        "   incremental (kept buffers): all visible {:.3} ms, none visible {:.4} ms, none / all = {:.2}%",
        num(&c["incremental_all_visible_ms"]),
        num(&c["incremental_none_visible_ms"]),
        100.0 * num(&c["incremental_none_over_all"]),
    );
    println!();
    println!("4. Effects on scenario 2 (7 boxes), each alone on top of basic Gerstner waves");
    for t in r["effects"].as_array().into_iter().flatten() {
        println!(
            "   {}²: steady state (still boxes) {} rounds; rebuild (every box moved every frame) {} rounds",
            t["side"], t["runs_steady"], t["runs_rebuild"]
        );
        println!(
            "   {:<32} {:>10} {:>10} {:>7} {:>11} {:>10} {:>7}",
            "effect", "steady ms", "cost ms", "ratio", "rebuild ms", "cost ms", "ratio"
        );
        for row in t["rows"].as_array().into_iter().flatten() {
            let opt = |k: &str, p: usize| {
                row[k]
                    .as_f64()
                    .map_or("-".to_string(), |v| format!("{v:.prec$}", prec = p))
            };
            println!(
                "   {:<32} {:>10.3} {:>10.3} {:>7.2} {:>11} {:>10} {:>7}",
                row["effect"].as_str().unwrap_or("?"),
                num(&row["steady_ms"]),
                num(&row["steady_cost_ms"]),
                num(&row["steady_ratio"]),
                opt("rebuild_ms", 3),
                opt("rebuild_cost_ms", 3),
                opt("rebuild_ratio", 2),
            );
        }
    }
    println!();
    let q = &r["queries"];
    println!(
        "5. Height queries, scenario 1 at {}², {} random points: {:.3e}/s on {} threads ({:.3e}/s per core); {:.3e}/s on 1 thread",
        q["side"],
        q["queries"],
        num(&q["per_s_threads"]),
        q["threads"],
        num(&q["per_s_per_core_threads"]),
        num(&q["per_s_single_thread"]),
    );
    println!(
        "   drawn (the frame's triangles), the same points: {:.3e}/s on {} threads, {:.3e}/s on 1 thread; largest |drawn − continuous| {:.2e} m",
        num(&q["drawn_per_s_threads"]),
        q["threads"],
        num(&q["drawn_per_s_single_thread"]),
        num(&q["max_drawn_minus_continuous_m"]),
    );
    println!(
        "   drawn on the whole mesh built once ({:.2} ms): {:.3e}/s on {} threads",
        num(&q["drawn_mesh_build_ms"]),
        num(&q["drawn_mesh_per_s_threads"]),
        q["threads"],
    );
    println!(
        "   {} above the {:.0e} m tolerance ({} of them within 1 m of the grid's edge); worst residual {:.2e} m",
        q["above_tolerance"],
        num(&q["tolerance_m"]),
        q["above_tolerance_within_1m_of_edge"],
        num(&q["worst_residual_m"]),
    );
    let g = &r["gpu"];
    println!();
    match g["device"].as_str() {
        Some(device) => {
            println!("6. GPU, scenario 1 through LayersPass on {device}:");
            for c in g["scenario_1"].as_array().into_iter().flatten() {
                println!(
                    "   {}²: kernel {} ms, upload + dispatch + wait {:.3} ms",
                    c["side"],
                    c["kernel_ms"]
                        .as_f64()
                        .map_or("-".to_string(), |v| format!("{v:.3}")),
                    num(&c["wall_ms"]),
                );
                let m = &c["march"];
                for (key, what) in [
                    ("cached", "still boxes, marches cached"),
                    ("remarched", "every box re-marched"),
                ] {
                    let f = &m[key];
                    println!(
                        "   {}², rays marched on the GPU (WtbMarchPass), {what}: plan + march + \
                         evaluation {:.3} ms (its layers pass {} ms; {} marches, {} reuses)",
                        c["side"],
                        num(&f["wall_ms"]),
                        f["layers_kernel_ms"]
                            .as_f64()
                            .map_or("-".to_string(), |v| format!("{v:.3}")),
                        f["marches"],
                        f["reuses"],
                    );
                }
            }
        }
        None => println!(
            "6. GPU: {}",
            g["unavailable"].as_str().unwrap_or("unavailable")
        ),
    }
    let k = &r["isa_kernels"];
    println!();
    println!(
        "7. Layers kernel per instruction set, scenario 1 at {}², one thread (outputs bit-identical: {}); memory baseline {:.3} ms",
        k["side"],
        k["bit_identical"],
        num(&k["memory_baseline_ms"])
    );
    for c in k["kernels"].as_array().into_iter().flatten() {
        println!(
            "   {:<9} {:>8.3} ms  {:>5.2}× the memory baseline  {:>5.2}× the portable kernel's speed",
            c["isa"].as_str().unwrap_or("?"),
            num(&c["ms"]),
            num(&c["over_memory_baseline"]),
            num(&c["speed_over_portable"]),
        );
    }
    println!();
    println!("Targets:");
    for t in r["targets"].as_array().into_iter().flatten() {
        println!(
            "   {:<48} {:>6} {:<14} measured {:>10.4}  {}",
            t["name"].as_str().unwrap_or("?"),
            t["kind"].as_str().unwrap_or("?"),
            t["target"].to_string(),
            num(&t["measured"]),
            if t["met"].as_bool() == Some(true) {
                "met"
            } else {
                "NOT MET"
            }
        );
    }
    println!("wall time {:.1} s", num(&r["wall_s"]));
}
