//! Times cone-map generation (all three channels) at 256², 512² and 1024² on three maps, with
//! the book's cap (1.0) and an unclamped one (4.0). Threads: `RAYON_NUM_THREADS` (default: all
//! cores). `cargo run --release -p ocean-relief --example timing [sides…]`.

use std::time::Instant;

use ocean_relief::maps::{bumps, to_map, value_noise, white_noise};
use ocean_relief::{ConeMap, ConeParams, Edge};

fn main() {
    let sizes: Vec<usize> = std::env::args()
        .skip(1)
        .filter_map(|a| a.parse().ok())
        .collect();
    let sizes = if sizes.is_empty() {
        vec![256, 512, 1024]
    } else {
        sizes
    };
    println!("threads: {}", rayon::current_num_threads());
    for &n in &sizes {
        let maps = [
            ("fBm 6 oct", value_noise(n, 8, 6, 1)),
            ("smooth 2 oct", value_noise(n, 4, 2, 2)),
            ("white noise", white_noise(n, 1)),
            ("bumps", bumps(n, n / 8, n as f64 / 24.0, 3)),
        ];
        for (name, h) in maps {
            let map = to_map(n, &h, Edge::Wrap).expect("map");
            for (kind, params) in [
                ("relaxed cap 1", ConeParams::relaxed(1.0)),
                ("relaxed cap 4", ConeParams::relaxed(4.0)),
                ("conservative 1", ConeParams::conservative(1.0)),
            ] {
                let t = Instant::now();
                let cones = ConeMap::generate(&map, params).expect("cones");
                let s = t.elapsed().as_secs_f64();
                let mean = cones.ratios().iter().map(|&r| f64::from(r)).sum::<f64>()
                    / cones.ratios().len() as f64;
                println!("{n:5}² {name:13} {kind:15} {s:7.3} s   mean ratio {mean:.4}");
            }
        }
    }
}
