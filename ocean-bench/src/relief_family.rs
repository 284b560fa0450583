//! Figures 8 and 9 of `ocean bench relief`: the cone generator on the family of twelve map kinds
//! (`ocean_relief::maps::family`: fBm, value noise, ridged noise, a ramp, a staircase, a cone,
//! pits, spheres, boxes, thin walls, pins and strokes), in both edge modes.
//!
//! 8. **Width**: at 128², relaxed cones capped at 1 (the book's cap), the generated plain cone
//!    of every texel against `W`, the widest valid one (`ocean_relief::widest`, sampled at 2×2
//!    points per cell and 64 directions): per map the mean of `generated / W`, the mean weighted
//!    by the texel's depth and the worst texel, with the default bound (`ConeParams::parts` 4)
//!    and with whole cells (`parts` 0, the GPU's). Targets: family mean at least 0.95, every
//!    map at least 0.9.
//! 9. **Speed**: `ConeMap::generate` (default bound, cap 1) at 512² and 1024² on every map of
//!    the family with heights as `ocean cone-map` reads them for each storage: rounded to 8 bits
//!    (`u8`, which turns a smooth slope into a staircase of 256 steps) and to 16 bits (`f16`),
//!    one run each (they are long), all threads. Targets: 512² in at most 2 s and 1024² in at
//!    most 10 s on every map.

use std::time::Instant;

use ocean_relief::maps::family;
use ocean_relief::widest::{WidestParams, widest, width};
use ocean_relief::{ConeKind, ConeMap, ConeParams, Edge, HeightMap};
use serde_json::{Value, json};

/// Side of figure 8.
pub const WIDTH_SIDE: usize = 128;
/// Targets of figure 8.
const TARGET_MEAN: f64 = 0.95;
const TARGET_EACH: f64 = 0.9;
/// Sides and targets (seconds) of figure 9.
const SPEED: [(usize, f64); 2] = [(512, 2.0), (1024, 10.0)];

fn err(e: impl std::fmt::Display) -> String {
    e.to_string()
}

const EDGES: [(Edge, &str); 2] = [(Edge::Wrap, "wrap"), (Edge::Clamp, "clamp")];

/// Figure 8.
pub fn width_figure() -> Result<Value, String> {
    let n = WIDTH_SIDE;
    let params = ConeParams::relaxed(1.0);
    let mut modes = Vec::new();
    for (edge, edge_name) in EDGES {
        let mut rows = Vec::new();
        let (mut sum, mut sum_cells, mut least) = (0.0, 0.0, f64::INFINITY);
        for (name, heights) in family(n) {
            let map =
                HeightMap::from_heights(n, n, &heights, edge, Default::default()).map_err(err)?;
            let w = widest(&map, ConeKind::Relaxed, 1.0, WidestParams::default()).map_err(err)?;
            let cones = ConeMap::generate(&map, params).map_err(err)?;
            let cells = ConeMap::generate(&map, params.with_parts(0)).map_err(err)?;
            let r = width(&map, cones.ratios(), &w).map_err(err)?;
            let c = width(&map, cells.ratios(), &w).map_err(err)?;
            sum += r.mean;
            sum_cells += c.mean;
            least = least.min(r.mean);
            rows.push(json!({
                "map": name,
                "mean": r.mean,
                "depth_weighted": r.depth_weighted,
                "worst": r.worst.generated / r.worst.widest,
                "worst_texel": [r.worst.i, r.worst.j],
                "worst_depth": r.worst.depth,
                "worst_generated": r.worst.generated,
                "worst_widest": r.worst.widest,
                "whole_cells_mean": c.mean,
                "whole_cells_depth_weighted": c.depth_weighted,
            }));
        }
        let count = rows.len() as f64;
        let mean = sum / count;
        modes.push(json!({
            "edge": edge_name,
            "maps": rows,
            "family_mean": mean,
            "family_mean_whole_cells": sum_cells / count,
            "narrowest_map_mean": least,
            "meets_target": mean >= TARGET_MEAN && least >= TARGET_EACH,
        }));
    }
    Ok(json!({
        "side": n,
        "max_ratio": params.max_ratio,
        "parts": params.parts,
        "target_family_mean": TARGET_MEAN,
        "target_each_map": TARGET_EACH,
        "modes": modes,
    }))
}

/// The map of `heights` as `ocean cone-map` reads it for the 8-bit (`bits` 8) or 16-bit
/// storage: heights rounded to that many bits.
fn quantized(n: usize, heights: &[f32], edge: Edge, bits: u32) -> Result<HeightMap, String> {
    if bits == 8 {
        let v: Vec<u8> = heights.iter().map(|&h| (h * 255.0).round() as u8).collect();
        HeightMap::from_u8(n, n, &v, edge).map_err(err)
    } else {
        let v: Vec<u16> = heights
            .iter()
            .map(|&h| (h * 65535.0).round() as u16)
            .collect();
        HeightMap::from_u16(n, n, &v, edge).map_err(err)
    }
}

/// Figure 9.
pub fn speed_figure() -> Result<Value, String> {
    let params = ConeParams::relaxed(1.0);
    let mut sizes = Vec::new();
    for (n, target) in SPEED {
        let mut rows = Vec::new();
        let mut slowest = 0.0f64;
        for (name, heights) in family(n) {
            let mut row = json!({ "map": name });
            for (edge, edge_name) in EDGES {
                for (bits, storage) in [(8, "u8"), (16, "f16")] {
                    let map = quantized(n, &heights, edge, bits)?;
                    let start = Instant::now();
                    ConeMap::generate(&map, params).map_err(err)?;
                    let s = start.elapsed().as_secs_f64();
                    slowest = slowest.max(s);
                    row[format!("{edge_name}_{storage}_seconds")] = json!(s);
                }
            }
            rows.push(row);
        }
        sizes.push(json!({
            "side": n,
            "maps": rows,
            "slowest_seconds": slowest,
            "target_max_seconds": target,
            "meets_target": slowest <= target,
        }));
    }
    Ok(json!({ "max_ratio": params.max_ratio, "parts": params.parts, "sizes": sizes }))
}

/// Prints figures 8 and 9 of `doc` (the suite's report).
pub fn print(doc: &Value) {
    let f = |v: &Value, digits: usize| {
        v.as_f64()
            .map_or_else(|| "-".to_owned(), |x| format!("{x:.digits$}"))
    };
    let w = &doc["width"];
    println!(
        "8. cone width at {0}² (relaxed, cap {1}): generated / widest valid, mean over texels \
         (depth-weighted; with whole cells); worst texel",
        w["side"], w["max_ratio"]
    );
    for m in w["modes"].as_array().into_iter().flatten() {
        println!("   {}:", m["edge"].as_str().unwrap_or("?"));
        for r in m["maps"].as_array().into_iter().flatten() {
            println!(
                "     {:<12} {} ({}; {}), worst {} at {} depth {}",
                r["map"].as_str().unwrap_or("?"),
                f(&r["mean"], 3),
                f(&r["depth_weighted"], 3),
                f(&r["whole_cells_mean"], 3),
                f(&r["worst"], 3),
                r["worst_texel"],
                f(&r["worst_depth"], 2)
            );
        }
        println!(
            "     family mean {} (whole cells {}), narrowest map {} (targets {} and {}: {})",
            f(&m["family_mean"], 3),
            f(&m["family_mean_whole_cells"], 3),
            f(&m["narrowest_map_mean"], 3),
            w["target_family_mean"],
            w["target_each_map"],
            if m["meets_target"].as_bool() == Some(true) {
                "met"
            } else {
                "MISSED"
            }
        );
    }
    let s = &doc["family_speed"];
    println!("9. generation on the family, seconds (wrap u8 / f16, clamp u8 / f16):");
    for size in s["sizes"].as_array().into_iter().flatten() {
        println!(
            "   {}²: slowest {} (target <= {}: {})",
            size["side"],
            f(&size["slowest_seconds"], 2),
            size["target_max_seconds"],
            if size["meets_target"].as_bool() == Some(true) {
                "met"
            } else {
                "MISSED"
            }
        );
        for r in size["maps"].as_array().into_iter().flatten() {
            println!(
                "     {:<12} {} / {}, {} / {}",
                r["map"].as_str().unwrap_or("?"),
                f(&r["wrap_u8_seconds"], 2),
                f(&r["wrap_f16_seconds"], 2),
                f(&r["clamp_u8_seconds"], 2),
                f(&r["clamp_f16_seconds"], 2)
            );
        }
    }
}
