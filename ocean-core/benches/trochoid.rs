//! Trochoid wave-sum benchmarks: grid evaluation, single- and multi-threaded.
//!
//! `ocean bench gerstner` prints the Gerstner figures (with a memory baseline and the GPU); this
//! criterion suite tracks the CPU kernel alone across changes.

use std::f64::consts::TAU;
use std::hint::black_box;

use criterion::{BenchmarkId, Criterion, Throughput, criterion_group, criterion_main};
use glam::{DVec2, Vec3};
use ocean_core::{Depth, Grid, WaveDesc, WaveSet};

/// `n` waves, wavelengths in geometric progression from 0.5 m to 60 m, steepness 0.1 each.
fn waves(n: usize) -> WaveSet {
    let descs: Vec<WaveDesc> = (0..n)
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
        .collect();
    WaveSet::from_descs(&descs).expect("valid waves")
}

fn grid(c: &mut Criterion) {
    let side = 512;
    let grid = Grid::centred(DVec2::ZERO, 0.5, side);
    let n = side * side;
    let mut pos = vec![Vec3::ZERO; n];
    let mut nrm = vec![Vec3::ZERO; n];
    let mut group = c.benchmark_group("trochoid_grid_512");
    for count in [3usize, 60] {
        let set = waves(count);
        group.throughput(Throughput::Elements((n * count) as u64));
        group.bench_with_input(BenchmarkId::new("single", count), &set, |b, set| {
            b.iter(|| set.evaluate_grid(&grid, black_box(12.5), &mut pos, &mut nrm))
        });
        group.bench_with_input(BenchmarkId::new("parallel", count), &set, |b, set| {
            b.iter(|| set.evaluate_grid_par(&grid, black_box(12.5), &mut pos, &mut nrm))
        });
    }
    group.finish();
}

criterion_group!(benches, grid);
criterion_main!(benches);
