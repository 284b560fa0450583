//! Figures 8 and 9 of `ocean bench relief`: the cone generator on the family of twelve map kinds
//! (`ocean_relief::maps::family`: fBm, value noise, ridged noise, a ramp, a staircase, a cone,
//! pits, spheres, boxes, thin walls, pins and strokes), in both edge modes.
//!
//! 8. **Width**: at 128², relaxed cones capped at 1 (the book's cap), the generated plain cone
//!    of every texel against `W`, the widest valid one (`ocean_relief::widest`, sampled at 2×2
//!    points per cell and 64 directions, then refined by its local search): per map the mean of
//!    `generated / W`, the mean weighted by the texel's depth and the worst texel, with the
//!    default bound (`ConeParams::parts` 2); the means with `parts` 4 and 6 and with whole cells
//!    (`parts` 0, the GPU's). In wrap mode also
//!    the family means of conservative cones against the widest conservative ones, and of each
//!    layer of quadrant cone maps (relaxed and conservative, `ocean_relief::quad`) against the
//!    widest cone over that quadrant's directions (`widest::widest_quadrant`). Targets: family mean at least 0.95, every
//!    map at least 0.9.
//! 9. **Speed**: `ConeMap::generate` (default bound, cap 1) at 512² and 1024² on every map of
//!    the family with heights as `ocean cone-map` reads them for each storage: rounded to 8 bits
//!    (`u8`, which turns a smooth slope into a staircase of 256 steps) and to 16 bits (`f16`),
//!    one run each (they are long), all threads. Targets: 512² in at most 2 s and 1024² in at
//!    most 10 s on every map.
//! 10. **Steps**: how many relaxed cone steps (the tracer's step with the clearance and near cap,
//!     `ocean_relief::trace::step_length`, on the `f32` texture it reads) a ray needs to come
//!     within half a texel of its exact first hit (`ocean_relief::truth::first_hit`), measured
//!     along the ray's horizontal run, or to pass it (relaxed cones may enter the solid; the
//!     binary search then finishes): mean and 99th percentile over 2048 rays with random starts
//!     and azimuths, 60° and 80° from the normal, relief 0.1 texture widths deep, on the family
//!     at 128² (wrap), with the default bound and with whole cells (`parts` 0, what the cones
//!     were before it). A ray that needs more than 4096 steps counts 4096.

use std::time::Instant;

use glam::{Vec2, Vec3};
use ocean_core::rng::Pcg32;
use ocean_relief::maps::family;
use ocean_relief::trace::step_length;
use ocean_relief::truth::first_hit;
use ocean_relief::widest::{WidestParams, widest, widest_quadrant, width};
use ocean_relief::{
    ConeKind, ConeMap, ConeParams, Edge, HeightMap, QuadConeMap, Quadrant, Ray, ReliefTexture,
};
use serde_json::{Value, json};

/// Side of figure 8.
pub const WIDTH_SIDE: usize = 128;
/// The finest subdivision figure 8 shows besides the default and 4.
const FINEST: u32 = 6;
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
        let (mut sum, mut sum_cells, mut sum_fine, mut least) = (0.0, 0.0, 0.0, f64::INFINITY);
        let (mut sum_finest, mut finest_least) = (0.0, f64::INFINITY);
        for (name, heights) in family(n) {
            let map =
                HeightMap::from_heights(n, n, &heights, edge, Default::default()).map_err(err)?;
            let w = widest(&map, ConeKind::Relaxed, 1.0, WidestParams::default()).map_err(err)?;
            let cones = ConeMap::generate(&map, params).map_err(err)?;
            let cells = ConeMap::generate(&map, params.with_parts(0)).map_err(err)?;
            let fine = ConeMap::generate(&map, params.with_parts(4)).map_err(err)?;
            let finest = ConeMap::generate(&map, params.with_parts(FINEST)).map_err(err)?;
            let r = width(&map, cones.ratios(), &w).map_err(err)?;
            let c = width(&map, cells.ratios(), &w).map_err(err)?;
            let f4 = width(&map, fine.ratios(), &w).map_err(err)?;
            let f6 = width(&map, finest.ratios(), &w).map_err(err)?;
            sum_fine += f4.mean;
            sum_finest += f6.mean;
            finest_least = finest_least.min(f6.mean);
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
                "parts_4_mean": f4.mean,
                "parts_6_mean": f6.mean,
            }));
        }
        let count = rows.len() as f64;
        let mean = sum / count;
        let others = if edge == Edge::Wrap {
            other_kinds(n)?
        } else {
            Value::Null
        };
        modes.push(json!({
            "edge": edge_name,
            "maps": rows,
            "family_mean": mean,
            "family_mean_whole_cells": sum_cells / count,
            "family_mean_parts_4": sum_fine / count,
            "family_mean_parts_6": sum_finest / count,
            "narrowest_map_mean_parts_6": finest_least,
            "narrowest_map_mean": least,
            "meets_target": mean >= TARGET_MEAN && least >= TARGET_EACH,
            "other_kinds": others,
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

/// Family means (default bound) of conservative cones and of the layers of quadrant cone maps,
/// relaxed and conservative, each against its own widest cone, on wrapped maps of side `n`.
fn other_kinds(n: usize) -> Result<Value, String> {
    let (mut conservative, mut quad_relaxed, mut quad_conservative) = (0.0, 0.0, 0.0);
    let maps = family(n);
    for (_, heights) in &maps {
        let map =
            HeightMap::from_heights(n, n, heights, Edge::Wrap, Default::default()).map_err(err)?;
        let p = ConeParams::conservative(1.0);
        let w = widest(&map, ConeKind::Conservative, 1.0, WidestParams::default()).map_err(err)?;
        let cones = ConeMap::generate(&map, p).map_err(err)?;
        conservative += width(&map, cones.ratios(), &w).map_err(err)?.mean;
        for (p, sum) in [
            (ConeParams::relaxed(1.0), &mut quad_relaxed),
            (p, &mut quad_conservative),
        ] {
            let quad = QuadConeMap::generate(&map, p).map_err(err)?;
            for q in Quadrant::ALL {
                let w =
                    widest_quadrant(&map, p.kind, 1.0, WidestParams::default(), q).map_err(err)?;
                *sum += width(&map, quad.layer(q).ratios(), &w).map_err(err)?.mean / 4.0;
            }
        }
    }
    let count = maps.len() as f64;
    Ok(json!({
        "conservative": conservative / count,
        "quad_relaxed": quad_relaxed / count,
        "quad_conservative": quad_conservative / count,
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

/// Side, rays, relief depth and step cap of figure 10.
const STEPS_SIDE: usize = 128;
const STEPS_RAYS: usize = 2048;
const STEPS_DEPTH: f32 = 0.1;
const STEPS_CAP: u32 = 4096;

/// Relaxed cone steps from the ray's entry until it is within half a texel (horizontally) of
/// `hit_z`, the depth of its exact first hit, or past it.
fn steps_to_hit(texture: &ReliefTexture, ray: &Ray, hit_z: f64, n: usize) -> u32 {
    let (dx, dy) = (ray.dir.x / ray.dir.z, ray.dir.y / ray.dir.z);
    let ratio = (dx * dx + dy * dy).sqrt();
    // Half a texel of horizontal run, in depth units along the ray.
    let tolerance = 0.5 / (n as f64 * f64::from(ratio));
    let mut p = [ray.start.x, ray.start.y, 0.0f32];
    for k in 0..STEPS_CAP {
        if f64::from(p[2]) >= hit_z - tolerance {
            return k;
        }
        let texel = texture.fetch(p[0], p[1]);
        let height = (texel[0] - p[2]).clamp(0.0, 1.0);
        let d = step_length(texel, height, ratio);
        p = [p[0] + dx * d, p[1] + dy * d, p[2] + d];
    }
    STEPS_CAP
}

/// Mean and 99th percentile of `steps`.
fn summary(mut steps: Vec<u32>) -> (f64, u32) {
    steps.sort_unstable();
    let mean = steps.iter().map(|&s| f64::from(s)).sum::<f64>() / steps.len() as f64;
    let p99 = steps[((steps.len() - 1) as f64 * 0.99).round() as usize];
    (mean, p99)
}

/// `count` rays at `angle` degrees from the normal, random starts and azimuths.
pub(crate) fn rays(count: usize, angle: f32, depth: f32) -> Result<Vec<Ray>, String> {
    let mut rng = Pcg32::new(11, 3);
    let (st, ct) = angle.to_radians().sin_cos();
    (0..count)
        .map(|_| {
            let start = Vec2::new(rng.next_f32(), rng.next_f32());
            let (sp, cp) = (std::f32::consts::TAU * rng.next_f32()).sin_cos();
            Ray::from_view(start, Vec3::new(st * cp, st * sp, -ct), depth).map_err(err)
        })
        .collect()
}

/// Figure 10.
pub fn steps_figure() -> Result<Value, String> {
    let n = STEPS_SIDE;
    let mut rows = Vec::new();
    for (name, heights) in family(n) {
        let map =
            HeightMap::from_heights(n, n, &heights, Edge::Wrap, Default::default()).map_err(err)?;
        let textures = [
            ConeParams::relaxed(1.0),
            ConeParams::relaxed(1.0).with_parts(0),
        ]
        .map(|p| {
            ConeMap::generate(&map, p)
                .and_then(|c| ReliefTexture::new(&map, &c))
                .map_err(err)
        });
        let [after, before] = textures;
        let (after, before) = (after?, before?);
        let mut row = json!({ "map": name });
        for angle in [60.0f32, 80.0] {
            let rays = rays(STEPS_RAYS, angle, STEPS_DEPTH)?;
            let hits: Vec<f64> = rays
                .iter()
                .map(|r| first_hit(&map, r).map(|h| h.z).map_err(err))
                .collect::<Result<_, _>>()?;
            for (texture, key) in [(&before, "before"), (&after, "after")] {
                let steps = rays
                    .iter()
                    .zip(&hits)
                    .map(|(r, &z)| steps_to_hit(texture, r, z, n))
                    .collect();
                let (mean, p99) = summary(steps);
                row[format!("{key}_{angle}_mean")] = json!(mean);
                row[format!("{key}_{angle}_p99")] = json!(p99);
            }
        }
        rows.push(row);
    }
    Ok(json!({
        "side": n,
        "rays": STEPS_RAYS,
        // The f32 constant, printed as the decimal it was written as.
        "relief_depth": (f64::from(STEPS_DEPTH) * 1000.0).round() / 1000.0,
        "tolerance_texels": 0.5,
        "maps": rows,
    }))
}

/// Prints figures 8 to 10 of `doc` (the suite's report).
pub fn print(doc: &Value) {
    let f = |v: &Value, digits: usize| {
        v.as_f64()
            .map_or_else(|| "-".to_owned(), |x| format!("{x:.digits$}"))
    };
    let w = &doc["width"];
    println!(
        "8. cone width at {0}² (relaxed, cap {1}): generated / widest valid, mean over texels \
         (depth-weighted; whole cells; parts 4; parts 6); worst texel",
        w["side"], w["max_ratio"]
    );
    for m in w["modes"].as_array().into_iter().flatten() {
        println!("   {}:", m["edge"].as_str().unwrap_or("?"));
        for r in m["maps"].as_array().into_iter().flatten() {
            println!(
                "     {:<12} {} ({}; {}; {}; {}), worst {} at {} depth {}",
                r["map"].as_str().unwrap_or("?"),
                f(&r["mean"], 3),
                f(&r["depth_weighted"], 3),
                f(&r["whole_cells_mean"], 3),
                f(&r["parts_4_mean"], 3),
                f(&r["parts_6_mean"], 3),
                f(&r["worst"], 3),
                r["worst_texel"],
                f(&r["worst_depth"], 2)
            );
        }
        println!(
            "     family mean {} (whole cells {}, parts 4 {}, parts 6 {}), narrowest map {} \
             (parts 6: {}) (targets {} and {}, default: {})",
            f(&m["family_mean"], 3),
            f(&m["family_mean_whole_cells"], 3),
            f(&m["family_mean_parts_4"], 3),
            f(&m["family_mean_parts_6"], 3),
            f(&m["narrowest_map_mean"], 3),
            f(&m["narrowest_map_mean_parts_6"], 3),
            w["target_family_mean"],
            w["target_each_map"],
            if m["meets_target"].as_bool() == Some(true) {
                "met"
            } else {
                "MISSED"
            }
        );
        let o = &m["other_kinds"];
        if !o.is_null() {
            println!(
                "     family means, each against its own widest cone: conservative {}, quadrant \
                 layers relaxed {}, conservative {}",
                f(&o["conservative"], 3),
                f(&o["quad_relaxed"], 3),
                f(&o["quad_conservative"], 3)
            );
        }
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
    let s = &doc["steps"];
    println!(
        "10. relaxed cone steps to half a texel of the hit, {}² wrap, {} rays, relief {} deep: \
         mean / p99, whole cells -> default bound",
        s["side"], s["rays"], s["relief_depth"]
    );
    println!("     {:<12} {:>27} {:>27}", "map", "60°", "80°");
    for r in s["maps"].as_array().into_iter().flatten() {
        let cell = |angle: &str| {
            format!(
                "{} / {} -> {} / {}",
                f(&r[format!("before_{angle}_mean")], 1),
                r[format!("before_{angle}_p99")],
                f(&r[format!("after_{angle}_mean")], 1),
                r[format!("after_{angle}_p99")]
            )
        };
        println!(
            "     {:<12} {:>27} {:>27}",
            r["map"].as_str().unwrap_or("?"),
            cell("60"),
            cell("80")
        );
    }
}
