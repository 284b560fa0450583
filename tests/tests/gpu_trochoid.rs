//! GPU/CPU parity of the trochoid displacement pass (`ocean_gpu::TrochoidPass`) against its CPU
//! twin `WaveSet::evaluate_grid`.
//!
//! Tolerances (ARCHITECTURE.md, "CPU and GPU twins"): heights within 1 mm RMS; normals within 0.1° as
//! the *maximum* angle over all points (the RMS angle is printed too). Both sides run the same
//! `f32` arithmetic (angle addition of per-row and per-column sines and cosines, then the same
//! sums) on the same sin/cos tables from `WaveSet::grid_sin_cos`, so the real differences are
//! the GPU's freedom to fuse multiply-adds and its approximate `sqrt` and division: micrometres
//! and thousandths of a degree, far inside the tolerances, which are the visual requirement.
//!
//! Run with `OCEAN_REQUIRE_GPU=1` to turn a missing adapter into a failure (CI does, on lavapipe
//! with `WGPU_BACKEND=vulkan` and on llvmpipe with `WGPU_BACKEND=gl`).

use glam::{DVec2, Vec3};
use ocean_core::{Depth, Grid, WaveDesc, WaveSet};
use ocean_gpu::{GpuContext, GpuError, TrochoidInput, TrochoidPass, TrochoidStats, TrochoidTarget};
use ocean_tests::{
    GridDiff, NORMAL_MAX_TOL_DEG, assert_parity, compare, gpu_context_or_skip, grid_256,
    realistic_waves,
};

fn cpu(waves: &WaveSet, grid: &Grid, t: f64) -> (Vec<Vec3>, Vec<Vec3>) {
    let n = grid.point_count().unwrap();
    let mut pos = vec![Vec3::ZERO; n];
    let mut nrm = vec![Vec3::ZERO; n];
    waves.evaluate_grid(grid, t, &mut pos, &mut nrm).unwrap();
    (pos, nrm)
}

/// GPU vs CPU on `grid` at `t`; returns the differences after asserting the tolerances.
fn parity(ctx: &GpuContext, pass: &TrochoidPass, grid: &Grid, t: f64, label: &str) -> GridDiff {
    let waves = realistic_waves();
    let gpu = pass.evaluate_grid(ctx, &waves, grid, t).unwrap();
    let (pos, nrm) = cpu(&waves, grid, t);
    let d = compare(&gpu.positions, &gpu.normals, &pos, &nrm);
    assert_parity(label, &d);
    // Every normal is unit length and points up (det J > 0 away from folds): a sanity check
    // that the comparison is not between two equally wrong outputs of zeros.
    assert!(gpu.normals.iter().all(|n| (n.length() - 1.0).abs() < 1e-5));
    let max_height = gpu
        .positions
        .iter()
        .map(|p| p.y.abs())
        .fold(0.0f32, f32::max);
    assert!(
        max_height > 1.0,
        "{label}: waves up to {:.2} m expected, got max |y| = {max_height} m",
        waves.max_amplitude()
    );
    if let Some(time) = gpu.gpu_time {
        println!("{label}: GPU time {:.3} ms", time.ms());
    }
    d
}

/// The parity cases: 256 × 256 at t = 0, 100 and 10⁶ s (each labelled in failures).
#[test]
fn parity_256_at_t_0_100_and_1e6() {
    let Some(ctx) = gpu_context_or_skip() else {
        return;
    };
    let pass = TrochoidPass::new(&ctx).unwrap();
    for t in [0.0, 100.0, 1e6] {
        parity(
            &ctx,
            &pass,
            &grid_256(DVec2::new(-64.0, -96.0)),
            t,
            &format!("256x256 t={t:e}"),
        );
    }
}

/// 100 km from the origin at t = 10⁶ s the unreduced phases reach ~10⁵ rad, where an `f32`
/// phase would be off by ~0.01 rad (centimetres of height). Besides matching the CPU twin, the
/// GPU must match the all-`f64` reference `WaveSet::sample_f64` within 1 mm (every 97th point).
#[test]
fn parity_100_km_from_origin() {
    let Some(ctx) = gpu_context_or_skip() else {
        return;
    };
    let pass = TrochoidPass::new(&ctx).unwrap();
    let grid = grid_256(DVec2::new(100_000.0, -100_000.0));
    let t = 1e6;
    parity(&ctx, &pass, &grid, t, "256x256 at (100 km, -100 km), t=1e6");

    let waves = realistic_waves();
    let gpu = pass.evaluate_grid(&ctx, &waves, &grid, t).unwrap();
    let (nx, _) = grid.size;
    let mut worst = 0.0f64;
    let mut worst_deg = 0.0f64;
    for idx in (0..gpu.positions.len()).step_by(97) {
        let (i, j) = (idx % nx, idx / nx);
        // Spacings 0.5 and 0.75 are exact in f32 and f64: the same rest point on both paths.
        let rest = grid.origin + DVec2::new(i as f64 * 0.5, j as f64 * 0.75);
        let r = waves.sample_f64(rest, t).unwrap();
        let p = gpu.positions[idx].as_dvec3();
        let local = DVec2::new(i as f64 * 0.5, j as f64 * 0.75);
        let err = (p.y - r.displacement.y)
            .abs()
            .max((p.x - local.x - r.displacement.x).abs())
            .max((p.z - local.y - r.displacement.z).abs());
        worst = worst.max(err);
        worst_deg = worst_deg.max(ocean_tests::angle_deg(gpu.normals[idx], r.normal.as_vec3()));
    }
    println!(
        "100 km, t=1e6 vs f64 reference: max position error {worst:.3e} m, max normal angle {worst_deg:.3e} deg"
    );
    assert!(
        worst <= 1e-3,
        "max position error vs f64 reference {worst} m"
    );
    assert!(
        worst_deg <= NORMAL_MAX_TOL_DEG,
        "max normal angle vs f64 reference {worst_deg} deg"
    );
}

/// A pass capped at 8 workgroups per dimension folds the 58 workgroups of a 100 × 37 grid
/// (3700 points / 64, rounded up) into an 8 × 8 dispatch whose last 6 groups are idle: the
/// linear index must still cover every point exactly once (a wrong fold leaves zeros or
/// duplicated rows, far outside tolerance). A cap of 7 (49 < 58 groups) cannot hold it and
/// must be refused rather than silently skip points.
#[test]
fn folded_dispatch_covers_every_point() {
    let Some(ctx) = gpu_context_or_skip() else {
        return;
    };
    let pass = TrochoidPass::new(&ctx)
        .unwrap()
        .with_max_workgroups_per_dimension(8);
    let grid = Grid {
        origin: DVec2::new(3.0, -7.0),
        spacing: DVec2::new(1.25, 0.5),
        size: (100, 37),
    };
    parity(
        &ctx,
        &pass,
        &grid,
        42.0,
        "100x37 folded into an 8x8 dispatch",
    );
    let too_narrow = TrochoidPass::new(&ctx)
        .unwrap()
        .with_max_workgroups_per_dimension(7);
    assert!(matches!(
        too_narrow.evaluate_grid(&ctx, &realistic_waves(), &grid, 42.0),
        Err(GpuError::TooLarge {
            needed: 58,
            limit: 49,
            ..
        })
    ));
}

/// A grid with more workgroups than one dispatch dimension holds (65535): 2100 × 2000 points
/// = 65625 workgroups of 64, dispatched as 65535 × 2.
#[test]
fn grid_beyond_one_dispatch_dimension() {
    let Some(ctx) = gpu_context_or_skip() else {
        return;
    };
    let pass = TrochoidPass::new(&ctx).unwrap();
    let grid = Grid {
        origin: DVec2::new(-500.0, 250.0),
        spacing: DVec2::new(0.25, 0.25),
        size: (2100, 2000),
    };
    assert!(
        grid.point_count().unwrap().div_ceil(64) > 65535,
        "the grid must exceed one dispatch dimension"
    );
    let d = parity(&ctx, &pass, &grid, 7.5, "2100x2000 (65625 workgroups)");
    assert_eq!(d.points, 4_200_000);
}

/// The pass writes into the caller's buffers through the caller's encoder, on the caller's
/// device (here the headless one, wrapped again with `from_device` as a wgpu program would).
#[test]
fn caller_buffers_and_encoder() {
    let Some(headless) = gpu_context_or_skip() else {
        return;
    };
    let ctx = GpuContext::from_device(headless.device().clone(), headless.queue().clone());
    let pass = TrochoidPass::new(&ctx).unwrap();
    let waves = realistic_waves();
    let grid = Grid {
        origin: DVec2::ZERO,
        spacing: DVec2::new(2.0, 2.0),
        size: (33, 17),
    };
    let n = grid.point_count().unwrap() as u64;
    let make = |usage| {
        ctx.device()
            .create_buffer(&ocean_gpu::wgpu::BufferDescriptor {
                label: Some("caller buffer"),
                // 3 spare points at the end must stay untouched (zero).
                size: (n + 3) * 16,
                usage,
                mapped_at_creation: false,
            })
    };
    let usage = ocean_gpu::wgpu::BufferUsages::STORAGE | ocean_gpu::wgpu::BufferUsages::COPY_SRC;
    let target = TrochoidTarget::from_buffers(make(usage), make(usage));
    let mut encoder = ctx
        .device()
        .create_command_encoder(&ocean_gpu::wgpu::CommandEncoderDescriptor { label: None });
    let input = TrochoidInput {
        waves: &waves,
        grid: &grid,
        time: 3.0,
    };
    pass.encode(&ctx, &mut encoder, &input, &target, None)
        .unwrap();
    ctx.queue().submit([encoder.finish()]);

    let pos: Vec<[f32; 4]> = ocean_gpu::readback::read_buffer_as(&ctx, &target.positions).unwrap();
    let nrm: Vec<[f32; 4]> = ocean_gpu::readback::read_buffer_as(&ctx, &target.normals).unwrap();
    assert_eq!(pos.len() as u64, n + 3);
    assert!(pos[n as usize..].iter().all(|p| *p == [0.0; 4]));
    // The w components follow the documented layout: 1 for positions, 0 for normals.
    assert!(pos[..n as usize].iter().all(|p| p[3] == 1.0));
    assert!(nrm[..n as usize].iter().all(|p| p[3] == 0.0));
    let v3 = |v: &[[f32; 4]]| -> Vec<Vec3> {
        v[..n as usize]
            .iter()
            .map(|p| Vec3::new(p[0], p[1], p[2]))
            .collect()
    };
    let (cpos, cnrm) = cpu(&waves, &grid, 3.0);
    assert_parity(
        "caller buffers 33x17",
        &compare(&v3(&pos), &v3(&nrm), &cpos, &cnrm),
    );
}

#[test]
fn bad_input_is_an_error_not_a_panic() {
    let Some(ctx) = gpu_context_or_skip() else {
        return;
    };
    let pass = TrochoidPass::new(&ctx).unwrap();
    let waves = realistic_waves();
    let grid = grid_256(DVec2::ZERO);
    // Non-finite time.
    assert!(matches!(
        pass.evaluate_grid(&ctx, &waves, &grid, f64::NAN),
        Err(GpuError::Eval(_))
    ));
    // Empty grid, zero spacing.
    let empty = Grid {
        size: (0, 4),
        ..grid
    };
    assert!(matches!(
        pass.evaluate_grid(&ctx, &waves, &empty, 0.0),
        Err(GpuError::Eval(_))
    ));
    let flat = Grid {
        spacing: DVec2::new(0.0, 1.0),
        ..grid
    };
    assert!(matches!(
        pass.evaluate_grid(&ctx, &waves, &flat, 0.0),
        Err(GpuError::Eval(_))
    ));
    // More points than a 128 MiB storage binding holds at 16 bytes each (3000^2 * 16 = 144 MB).
    let huge = Grid {
        size: (3000, 3000),
        ..grid
    };
    assert!(matches!(
        pass.evaluate_grid(&ctx, &waves, &huge, 0.0),
        Err(GpuError::TooLarge { .. })
    ));
    // Caller buffers: too small, or without STORAGE usage.
    let buf = |size, usage| {
        ctx.device()
            .create_buffer(&ocean_gpu::wgpu::BufferDescriptor {
                label: None,
                size,
                usage,
                mapped_at_creation: false,
            })
    };
    let storage = ocean_gpu::wgpu::BufferUsages::STORAGE;
    let full = 256 * 256 * 16;
    let input = TrochoidInput {
        waves: &waves,
        grid: &grid,
        time: 0.0,
    };
    let small = TrochoidTarget::from_buffers(buf(full, storage), buf(full - 16, storage));
    let err = pass.run(&ctx, &input, &small, None).unwrap_err();
    assert!(
        matches!(
            err,
            GpuError::InvalidResource {
                what: "normals buffer",
                ..
            }
        ),
        "{err}"
    );
    let no_storage = TrochoidTarget::from_buffers(
        buf(full, ocean_gpu::wgpu::BufferUsages::VERTEX),
        buf(full, storage),
    );
    let err = pass.run(&ctx, &input, &no_storage, None).unwrap_err();
    assert!(
        matches!(
            err,
            GpuError::InvalidResource {
                what: "positions buffer",
                ..
            }
        ),
        "{err}"
    );
    let same = buf(full, storage);
    let aliased = TrochoidTarget::from_buffers(same.clone(), same);
    assert!(pass.run(&ctx, &input, &aliased, None).is_err());
}

/// GPU timing is reported exactly when the device has timestamp queries (lavapipe does; wgpu's
/// GL backend does not), and is a positive duration.
#[test]
fn gpu_time_present_iff_timestamps_supported() {
    let Some(ctx) = gpu_context_or_skip() else {
        return;
    };
    let pass = TrochoidPass::new(&ctx).unwrap();
    let out = pass
        .evaluate_grid(&ctx, &realistic_waves(), &grid_256(DVec2::ZERO), 1.0)
        .unwrap();
    println!(
        "timestamps supported: {}; GPU time: {:?}",
        ctx.supports_timestamps(),
        out.gpu_time.map(|d| d.ms())
    );
    assert_eq!(out.gpu_time.is_some(), ctx.supports_timestamps());
    if let Some(d) = out.gpu_time {
        assert!(d.ns > 0.0, "a 65536-point pass takes time, got {} ns", d.ns);
    }
}

/// 40 waves (more than the pass's initial room for 16), 2 m to 80 m long, each of steepness
/// 0.02 (Σ k·A = 0.8, no folds), spread over all directions.
fn forty_waves() -> WaveSet {
    let descs: Vec<WaveDesc> = (0..40)
        .map(|n| {
            let wavelength = 2.0 + 78.0 * f64::from(n) / 39.0;
            let angle = f64::from(n) * 2.4;
            WaveDesc {
                amplitude: 0.02 * wavelength / std::f64::consts::TAU,
                wavelength,
                direction: DVec2::new(angle.cos(), angle.sin()),
                phase: f64::from(n) * 0.7,
                depth: Depth::Deep,
            }
        })
        .collect();
    WaveSet::from_descs(&descs).unwrap()
}

/// The pass keeps its input buffers: runs of the same size allocate nothing and reuse the
/// bind group, larger grids or more waves grow the buffers once, and every run is correct
/// (a stale upload, a table read at the wrong offset or a leftover coefficient from a larger
/// set would be centimetres off). Each run uses a new time, so a run that saw the previous
/// run's inputs would fail the comparison.
#[test]
fn repeated_runs_reuse_and_grow_the_input_buffers() {
    let Some(ctx) = gpu_context_or_skip() else {
        return;
    };
    let pass = TrochoidPass::new(&ctx).unwrap();
    let six = realistic_waves();
    let forty = forty_waves();
    let small = Grid {
        origin: DVec2::new(-20.0, 35.0),
        spacing: DVec2::new(0.5, 0.75),
        size: (48, 40),
    };
    let big = Grid {
        origin: DVec2::new(1.0e4, -3.0e3),
        spacing: DVec2::new(0.5, 0.5),
        size: (600, 400),
    };
    let small_target = TrochoidTarget::new(&ctx, &small).unwrap();
    let big_target = TrochoidTarget::new(&ctx, &big).unwrap();
    let mut time = 0.0;
    let mut run = |waves: &WaveSet, grid: &Grid, target: &TrochoidTarget| -> TrochoidStats {
        time += 1.75;
        let input = TrochoidInput { waves, grid, time };
        pass.run(&ctx, &input, target, None).unwrap();
        let n = grid.point_count().unwrap();
        let v3 = |v: Vec<[f32; 4]>| -> Vec<Vec3> {
            v[..n].iter().map(|p| Vec3::new(p[0], p[1], p[2])).collect()
        };
        let pos = v3(ocean_gpu::readback::read_buffer_as(&ctx, &target.positions).unwrap());
        let nrm = v3(ocean_gpu::readback::read_buffer_as(&ctx, &target.normals).unwrap());
        let (cpos, cnrm) = cpu(waves, grid, time);
        let label = format!(
            "{} waves, {}x{}, t={time}",
            waves.waves().len(),
            grid.size.0,
            grid.size.1
        );
        assert_parity(&label, &compare(&pos, &nrm, &cpos, &cnrm));
        pass.stats()
    };

    let fresh = pass.stats();
    assert_eq!(fresh.buffers_created, 3, "uniforms, coefficients, tables");
    assert_eq!(fresh.bind_groups_created, 0);
    // 6 waves x (48 + 40) = 528 pairs fit the initial tables: only a bind group is made.
    let first = run(&six, &small, &small_target);
    assert_eq!(
        first,
        TrochoidStats {
            bind_groups_created: 1,
            ..fresh
        }
    );
    for _ in 0..3 {
        assert_eq!(run(&six, &small, &small_target), first, "steady state");
    }

    // 6 x (600 + 400) = 6000 pairs outgrow the tables (one new buffer), not the coefficients.
    let grown = run(&six, &big, &big_target);
    assert_eq!(grown.buffers_created, first.buffers_created + 1);
    assert_eq!(grown.wave_capacity, first.wave_capacity);
    assert!(grown.table_capacity >= 6000, "{grown:?}");
    assert_eq!(run(&six, &big, &big_target), grown, "steady state");
    // Growing dropped the small target's bind group; after one rebuild both targets are
    // cached and alternating between them allocates nothing.
    let both = run(&six, &small, &small_target);
    assert_eq!(both.bind_groups_created, grown.bind_groups_created + 1);
    assert_eq!(both.buffers_created, grown.buffers_created);
    for _ in 0..2 {
        assert_eq!(run(&six, &big, &big_target), both);
        assert_eq!(run(&six, &small, &small_target), both);
    }

    // 40 waves outgrow the coefficients (40 x (48 + 40) = 3520 pairs still fit the tables),
    // then 40 x 1000 pairs the tables.
    let more = run(&forty, &small, &small_target);
    assert_eq!(more.buffers_created, both.buffers_created + 1);
    assert!(more.wave_capacity >= 40, "{more:?}");
    assert_eq!(more.table_capacity, both.table_capacity);
    let most = run(&forty, &big, &big_target);
    assert_eq!(most.buffers_created, more.buffers_created + 1);
    assert!(most.table_capacity >= 40_000, "{most:?}");
    assert_eq!(run(&forty, &big, &big_target), most, "steady state");
    // Back to fewer waves and a smaller grid: the buffers are large enough and the leftover
    // coefficients and table entries past the new sizes must not be read.
    assert_eq!(run(&six, &big, &big_target), most);
    let last = run(&six, &small, &small_target);
    assert_eq!(last.buffers_created, most.buffers_created);
    assert_eq!(run(&six, &small, &small_target), last, "steady state");
}
