//! What every suite measures with: the benchmark wave sets, medians over interleaved rounds,
//! the memory baseline of a grid, and the machine and date a report names.

use std::f64::consts::TAU;
use std::time::Instant;

use glam::{DVec2, Vec3};
use ocean_core::parallel::rows_per_task;
use ocean_core::{Depth, WaveDesc, WaveSet};
use rayon::prelude::*;

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

/// The UTC calendar date of `t` as YYYY-MM-DD (the proleptic Gregorian calendar, from the days
/// since 1970-01-01 by Howard Hinnant's `civil_from_days`).
pub fn utc_date(t: std::time::SystemTime) -> String {
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
