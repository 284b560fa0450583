//! GPU/CPU parity of the layered displacement pass (`ocean_gpu::LayersPass`) against its CPU
//! twin `ocean_core::evaluate_layers`: sums of wave sets each modulated by a complex amplitude
//! field μ = [m cos φ, m sin φ] over a grid rectangle (wave-train-boxes Eq. 6-7 with amplitude
//! m·A and phase θ + φ), plus an additive height field.
//!
//! Tolerances (ARCHITECTURE.md, "CPU and GPU twins"): heights within 1 mm RMS, horizontal positions
//! within 1 mm (max), normals within 0.1° as the *maximum* angle over all points. Both sides run
//! the same `f32` operations in the same order on the same sin/cos tables, so on Mesa's software
//! drivers the outputs are bit-identical (the tests print how many points are); real GPUs may
//! fuse multiply-adds and approximate `sqrt`, which stays far inside the tolerances.
//!
//! Run with `OCEAN_REQUIRE_GPU=1` to turn a missing adapter into a failure.

use std::f64::consts::TAU;

use glam::{DVec2, Vec3};
use ocean_core::{
    Depth, EvalError, Grid, GridRect, Layer, Modulation, WaveDesc, WaveSet, evaluate_layers,
};
use ocean_gpu::{
    GpuContext, GpuError, GridOutput, LayersInput, LayersPass, LayersStats, TrochoidPass,
    TrochoidTarget,
};
use ocean_tests::{
    GridDiff, assert_parity, compare, gpu_context_or_skip, grid_256, realistic_waves,
};

/// An owned layer: waves and modulation.
struct LayerData {
    waves: WaveSet,
    modulation: Modulation,
}

impl LayerData {
    /// A layer whose modulation varies in amplitude and phase over its rectangle: m from 0.1 to
    /// 1.1 and φ sweeping over more than a whole turn, both functions of the *grid* column and
    /// row (so a rectangle shifted by one point would be visibly off).
    fn varying(waves: WaveSet, rect: GridRect, seed: f64) -> Self {
        let mut modulation = Vec::with_capacity(rect.len());
        for r in 0..rect.nz {
            for c in 0..rect.nx {
                let (i, j) = ((rect.i0 + c) as f64, (rect.j0 + r) as f64);
                let m = 0.6 + 0.5 * (0.05 * i + seed).sin() * (0.031 * j - seed).cos();
                let phi = 0.021 * i - 0.017 * j + 1.3 * (0.043 * j + seed).sin();
                modulation.push([(m * phi.cos()) as f32, (m * phi.sin()) as f32]);
            }
        }
        Self {
            waves,
            modulation: Modulation::new(rect, modulation).unwrap(),
        }
    }

    /// μ = [1, 0] everywhere: the plain waves.
    fn unit(waves: WaveSet, rect: GridRect) -> Self {
        Self {
            waves,
            modulation: Modulation::unit(rect).unwrap(),
        }
    }

    fn layer(&self) -> Layer<'_> {
        Layer {
            waves: &self.waves,
            modulation: &self.modulation,
        }
    }
}

fn layers_of(data: &[LayerData]) -> Vec<Layer<'_>> {
    data.iter().map(LayerData::layer).collect()
}

fn rect(i0: usize, j0: usize, nx: usize, nz: usize) -> GridRect {
    GridRect { i0, j0, nx, nz }
}

/// A height field of a few centimetres (capillary-noise-like), one value per grid point.
fn height_field(grid: &Grid) -> Vec<f32> {
    let (nx, nz) = grid.size;
    (0..nz)
        .flat_map(|j| {
            (0..nx).map(move |i| (0.05 * (0.11 * i as f64 + 0.07 * j as f64).sin()) as f32)
        })
        .collect()
}

/// `count` waves from 2 m to 40 m long, steepness 0.03 each, spread over all directions.
fn swell(count: u32) -> WaveSet {
    let descs: Vec<WaveDesc> = (0..count)
        .map(|n| {
            let wavelength = 2.0 + 38.0 * f64::from(n) / f64::from(count.max(2) - 1);
            let angle = f64::from(n) * 2.4 + 0.3;
            WaveDesc {
                amplitude: 0.03 * wavelength / TAU,
                wavelength,
                direction: DVec2::new(angle.cos(), angle.sin()),
                phase: f64::from(n) * 0.9,
                depth: Depth::Deep,
            }
        })
        .collect();
    WaveSet::from_descs(&descs).unwrap()
}

fn cpu(
    grid: &Grid,
    t: f64,
    layers: &[Layer<'_>],
    height: Option<&[f32]>,
) -> (Vec<Vec3>, Vec<Vec3>) {
    let n = grid.point_count().unwrap();
    let mut pos = vec![Vec3::ZERO; n];
    let mut nrm = vec![Vec3::ZERO; n];
    evaluate_layers(grid, t, layers, height, &mut pos, &mut nrm).unwrap();
    (pos, nrm)
}

/// Points whose position and normal agree exactly (`==` per component).
fn identical(pos_a: &[Vec3], nrm_a: &[Vec3], pos_b: &[Vec3], nrm_b: &[Vec3]) -> usize {
    (0..pos_a.len())
        .filter(|&k| pos_a[k] == pos_b[k] && nrm_a[k] == nrm_b[k])
        .count()
}

fn assert_within(label: &str, d: &GridDiff, identical: usize) {
    println!("{label}: {identical} of {} points bit-identical", d.points);
    assert_parity(label, d);
}

/// GPU vs CPU; asserts the tolerances and returns the GPU output.
fn parity(
    ctx: &GpuContext,
    pass: &LayersPass,
    grid: &Grid,
    t: f64,
    layers: &[Layer<'_>],
    height: Option<&[f32]>,
    label: &str,
) -> GridOutput {
    let gpu = pass.evaluate(ctx, grid, t, layers, height).unwrap();
    let (pos, nrm) = cpu(grid, t, layers, height);
    let d = compare(&gpu.positions, &gpu.normals, &pos, &nrm);
    let same = identical(&gpu.positions, &gpu.normals, &pos, &nrm);
    assert_within(label, &d, same);
    assert!(
        gpu.normals.iter().all(|n| (n.length() - 1.0).abs() < 1e-5),
        "{label}: unit normals"
    );
    if let Some(time) = gpu.gpu_time {
        println!("{label}: GPU time {:.3} ms", time.ms());
    }
    gpu
}

/// Two overlapping layers with rectangles hanging at the grid's edges, plus a one-row layer
/// along the last row, each with spatially varying amplitude and phase:
///
/// - A: the realistic sea on columns 0..180, rows 0..150 (left and top edges);
/// - B: 12 swell waves on columns 100..256, rows 90..256 (right and bottom edges), overlapping
///   A on columns 100..180, rows 90..150;
/// - C: 3 swell waves on the whole last row (columns 0..256, row 255).
///
/// Columns 180..256 of rows 0..90 are covered by no layer: they must be at rest plus the
/// height field, normal +y.
fn edge_layers() -> Vec<LayerData> {
    vec![
        LayerData::varying(realistic_waves(), rect(0, 0, 180, 150), 0.0),
        LayerData::varying(swell(12), rect(100, 90, 156, 166), 1.7),
        LayerData::varying(swell(3), rect(0, 255, 256, 1), -0.4),
    ]
}

/// The parity cases: 256 × 256 at t = 0, 100 and 10⁶ s near the origin and at
/// t = 100 and 10⁶ s 100 km from it, with a height field.
#[test]
fn parity_overlapping_modulated_layers_with_height_field() {
    let Some(ctx) = gpu_context_or_skip() else {
        return;
    };
    let pass = LayersPass::new(&ctx).unwrap();
    let data = edge_layers();
    let layers = layers_of(&data);
    let cases = [
        (DVec2::new(-64.0, -96.0), 0.0),
        (DVec2::new(-64.0, -96.0), 100.0),
        (DVec2::new(-64.0, -96.0), 1e6),
        (DVec2::new(100_000.0, -100_000.0), 100.0),
        (DVec2::new(100_000.0, -100_000.0), 1e6),
    ];
    for (origin, t) in cases {
        let grid = grid_256(origin);
        let height = height_field(&grid);
        let label = format!("3 layers + height, 256x256 at {origin}, t={t:e}");
        let gpu = parity(&ctx, &pass, &grid, t, &layers, Some(&height), &label);

        // Not a comparison of two flat outputs: the realistic sea reaches metres.
        let max_height = gpu.positions.iter().map(|p| p.y.abs()).fold(0.0, f32::max);
        assert!(max_height > 1.0, "{label}: max |y| = {max_height} m");
        // The uncovered corner is exactly rest + height, normal +y.
        let (nx, _) = grid.size;
        for j in 0..90 {
            for i in 180..256 {
                let k = j * nx + i;
                let (x, z) = grid.local(i, j);
                assert_eq!(
                    gpu.positions[k],
                    Vec3::new(x, height[k], z),
                    "{label}: ({i}, {j})"
                );
                assert_eq!(gpu.normals[k], Vec3::Y, "{label}: ({i}, {j})");
            }
        }
        // The modulation matters: the same layers with μ = [1, 0] differ by decimetres, so a
        // pass that ignored (or misplaced) the modulation could not pass the parity check.
        let unit: Vec<LayerData> = data
            .iter()
            .map(|l| LayerData::unit(l.waves.clone(), l.modulation.rect()))
            .collect();
        let (upos, unrm) = cpu(&grid, t, &layers_of(&unit), Some(&height));
        let d = compare(&gpu.positions, &gpu.normals, &upos, &unrm);
        assert!(d.height_rms > 0.1, "{label}: modulation ineffective? {d}");
    }
}

/// A height field alone (no layer) and layers without a height field.
#[test]
fn height_only_and_layers_only() {
    let Some(ctx) = gpu_context_or_skip() else {
        return;
    };
    let pass = LayersPass::new(&ctx).unwrap();
    let grid = Grid {
        origin: DVec2::new(12.0, -3.0),
        spacing: DVec2::new(1.0, 0.5),
        size: (70, 45),
    };
    let height = height_field(&grid);
    let gpu = parity(&ctx, &pass, &grid, 5.0, &[], Some(&height), "height only");
    for (k, p) in gpu.positions.iter().enumerate() {
        let (x, z) = grid.local(k % 70, k / 70);
        assert_eq!(*p, Vec3::new(x, height[k], z));
    }
    assert!(gpu.normals.iter().all(|n| *n == Vec3::Y));
    let data = [LayerData::varying(
        realistic_waves(),
        rect(10, 5, 60, 40),
        0.3,
    )];
    parity(
        &ctx,
        &pass,
        &grid,
        5.0,
        &layers_of(&data),
        None,
        "layer only",
    );
}

/// One layer with μ = [1, 0] over the whole grid is the plain trochoid sum: the layers pass
/// must agree with the trochoid pass (and both with the CPU).
#[test]
fn unit_modulation_over_the_full_grid_equals_the_trochoid_pass() {
    let Some(ctx) = gpu_context_or_skip() else {
        return;
    };
    let layers_pass = LayersPass::new(&ctx).unwrap();
    let trochoid = TrochoidPass::new(&ctx).unwrap();
    let waves = realistic_waves();
    for (origin, t) in [
        (DVec2::new(-64.0, -96.0), 100.0),
        (DVec2::new(100_000.0, -100_000.0), 1e6),
    ] {
        let grid = grid_256(origin);
        let data = [LayerData::unit(waves.clone(), rect(0, 0, 256, 256))];
        let layers = layers_of(&data);
        let label = format!("unit layer vs trochoid pass at {origin}, t={t:e}");
        let a = layers_pass.evaluate(&ctx, &grid, t, &layers, None).unwrap();
        let b = trochoid.evaluate_grid(&ctx, &waves, &grid, t).unwrap();
        let d = compare(&a.positions, &a.normals, &b.positions, &b.normals);
        let same = identical(&a.positions, &a.normals, &b.positions, &b.normals);
        assert_within(&label, &d, same);
        let max_height = a.positions.iter().map(|p| p.y.abs()).fold(0.0, f32::max);
        assert!(max_height > 1.0, "{label}: max |y| = {max_height} m");
        parity(
            &ctx,
            &layers_pass,
            &grid,
            t,
            &layers,
            None,
            &format!("{label} (CPU)"),
        );
    }
}

/// A pass capped at 8 workgroups per dimension folds the 58 workgroups of a 100 × 37 grid into
/// an 8 × 8 dispatch; a cap of 7 cannot hold them and is refused.
#[test]
fn folded_dispatch_covers_every_point() {
    let Some(ctx) = gpu_context_or_skip() else {
        return;
    };
    let pass = LayersPass::new(&ctx)
        .unwrap()
        .with_max_workgroups_per_dimension(8);
    let grid = Grid {
        origin: DVec2::new(3.0, -7.0),
        spacing: DVec2::new(1.25, 0.5),
        size: (100, 37),
    };
    let data = [
        LayerData::varying(realistic_waves(), rect(0, 0, 100, 37), 0.0),
        LayerData::varying(swell(5), rect(30, 10, 70, 27), 0.9),
    ];
    let layers = layers_of(&data);
    let height = height_field(&grid);
    parity(
        &ctx,
        &pass,
        &grid,
        42.0,
        &layers,
        Some(&height),
        "100x37 folded into 8x8",
    );
    let narrow = LayersPass::new(&ctx)
        .unwrap()
        .with_max_workgroups_per_dimension(7);
    assert!(matches!(
        narrow.evaluate(&ctx, &grid, 42.0, &layers, Some(&height)),
        Err(GpuError::TooLarge {
            needed: 58,
            limit: 49,
            ..
        })
    ));
}

/// Every input the CPU refuses is refused with the same `EvalError` (as `GpuError::Eval`),
/// before anything is allocated or written; targets that do not fit are refused too; and the
/// pass still works afterwards.
#[test]
fn bad_input_is_an_error_not_a_panic() {
    let Some(ctx) = gpu_context_or_skip() else {
        return;
    };
    let pass = LayersPass::new(&ctx).unwrap();
    let grid = Grid {
        origin: DVec2::new(1.0, 2.0),
        spacing: DVec2::new(0.5, 0.5),
        size: (40, 30),
    };
    let waves = realistic_waves();
    let good = LayerData::varying(waves.clone(), rect(5, 5, 20, 10), 0.0);
    let height = height_field(&grid);
    let mut h_inf = height.clone();
    h_inf[611] = f32::NEG_INFINITY;
    let moved = |r: GridRect| Modulation::new(r, good.modulation.values().to_vec()).unwrap();
    let (right, down) = (moved(rect(21, 5, 20, 10)), moved(rect(5, 21, 20, 10)));
    let with = |modulation| Layer {
        waves: &waves,
        modulation,
    };
    let stats_before = pass.stats();

    /// What is wrong, and the arguments of `evaluate_layers`.
    type Case<'a> = (&'a str, Grid, f64, Vec<Layer<'a>>, Option<&'a [f32]>);
    let cases: Vec<Case<'_>> = vec![
        ("NaN time", grid, f64::NAN, vec![good.layer()], None),
        ("infinite time", grid, f64::INFINITY, vec![], Some(&height)),
        (
            "empty grid",
            Grid {
                size: (0, 30),
                ..grid
            },
            0.0,
            vec![],
            None,
        ),
        (
            "zero spacing",
            Grid {
                spacing: DVec2::new(0.5, 0.0),
                ..grid
            },
            0.0,
            vec![],
            None,
        ),
        (
            "rect past the right edge",
            grid,
            0.0,
            vec![with(&right)],
            None,
        ),
        (
            "rect past the bottom edge",
            grid,
            0.0,
            vec![with(&down)],
            None,
        ),
        (
            "height too short",
            grid,
            0.0,
            vec![good.layer()],
            Some(&height[..1199]),
        ),
        (
            "infinite height",
            grid,
            0.0,
            vec![good.layer()],
            Some(&h_inf),
        ),
    ];
    for (what, grid, t, layers, h) in &cases {
        let n = grid.size.0 * grid.size.1;
        let mut pos = vec![Vec3::ZERO; n];
        let mut nrm = vec![Vec3::ZERO; n];
        let cpu_err: EvalError =
            evaluate_layers(grid, *t, layers, *h, &mut pos, &mut nrm).expect_err(what);
        match pass.evaluate(&ctx, grid, *t, layers, *h) {
            // Compared as text: EvalError::Time(NaN) != itself under PartialEq.
            Err(GpuError::Eval(e)) => {
                assert_eq!(format!("{e:?}"), format!("{cpu_err:?}"), "{what}");
            }
            other => panic!("{what}: expected {cpu_err:?}, got {other:?}"),
        }
    }
    // Nothing was allocated for the refused inputs.
    assert_eq!(pass.stats(), stats_before);

    // Targets: too small, without STORAGE usage, aliased.
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
    let full = 40 * 30 * 16;
    let layers = [good.layer()];
    let input = LayersInput {
        grid: &grid,
        time: 0.0,
        layers: &layers,
        height: Some(&height),
    };
    let small = TrochoidTarget::from_buffers(buf(full, storage), buf(full - 16, storage));
    assert!(matches!(
        pass.run(&ctx, &input, &small, None),
        Err(GpuError::InvalidResource {
            what: "normals buffer",
            ..
        })
    ));
    let no_storage = TrochoidTarget::from_buffers(
        buf(full, ocean_gpu::wgpu::BufferUsages::VERTEX),
        buf(full, storage),
    );
    assert!(matches!(
        pass.run(&ctx, &input, &no_storage, None),
        Err(GpuError::InvalidResource {
            what: "positions buffer",
            ..
        })
    ));
    let same = buf(full, storage);
    let aliased = TrochoidTarget::from_buffers(same.clone(), same);
    assert!(pass.run(&ctx, &input, &aliased, None).is_err());
    // A grid beyond a 128 MiB storage binding (3000^2 points x 16 bytes = 144 MB).
    let huge = Grid {
        size: (3000, 3000),
        ..grid
    };
    assert!(matches!(
        pass.evaluate(&ctx, &huge, 0.0, &[], None),
        Err(GpuError::TooLarge { .. })
    ));
    assert_eq!(pass.stats(), stats_before);

    // Still correct after all that.
    parity(
        &ctx,
        &pass,
        &grid,
        0.0,
        &layers,
        Some(&height),
        "after refused inputs",
    );
}

/// The pass keeps its input buffers: runs of the same size allocate nothing and reuse the bind
/// group; more layers grow the descriptor buffer, more data (waves, rectangles, height) the
/// data buffer, each once; smaller runs afterwards fit and must not read leftovers. Every run
/// uses a new time and is compared with the CPU, so a stale or misplaced upload fails.
#[test]
fn repeated_runs_reuse_and_grow_the_input_buffers() {
    let Some(ctx) = gpu_context_or_skip() else {
        return;
    };
    let pass = LayersPass::new(&ctx).unwrap();
    let small = Grid {
        origin: DVec2::new(-20.0, 35.0),
        spacing: DVec2::new(0.5, 0.75),
        size: (48, 40),
    };
    let big = Grid {
        origin: DVec2::new(1.0e4, -3.0e3),
        spacing: DVec2::new(0.5, 0.5),
        size: (300, 200),
    };
    let small_target = TrochoidTarget::new(&ctx, &small).unwrap();
    let big_target = TrochoidTarget::new(&ctx, &big).unwrap();
    let small_height = height_field(&small);
    let big_height = height_field(&big);

    // One layer, 6 waves on 30 x 20: 48 + 600 + 1200 words, + 1920 of height = 3768 words.
    let one = vec![LayerData::varying(
        realistic_waves(),
        rect(10, 12, 30, 20),
        0.2,
    )];
    // Nine layers (more than the initial 8 descriptors), 10 x 10 each: 9 x 488 + 1920 words.
    let nine: Vec<LayerData> = (0..9)
        .map(|k| LayerData::varying(realistic_waves(), rect(4 * k, 3 * k, 10, 10), k as f64))
        .collect();
    // Two large layers on the big grid: far more than the initial 16384 words.
    let large = vec![
        LayerData::varying(realistic_waves(), rect(0, 0, 200, 150), 0.0),
        LayerData::varying(swell(20), rect(120, 60, 180, 140), 1.0),
    ];

    let mut time = 0.0;
    let mut run =
        |data: &[LayerData], grid: &Grid, height: &[f32], target: &TrochoidTarget| -> LayersStats {
            time += 1.75;
            let layers = layers_of(data);
            let input = LayersInput {
                grid,
                time,
                layers: &layers,
                height: Some(height),
            };
            pass.run(&ctx, &input, target, None).unwrap();
            let n = grid.point_count().unwrap();
            let v3 = |v: Vec<[f32; 4]>| -> Vec<Vec3> {
                v[..n].iter().map(|p| Vec3::new(p[0], p[1], p[2])).collect()
            };
            let pos = v3(ocean_gpu::readback::read_buffer_as(&ctx, &target.positions).unwrap());
            let nrm = v3(ocean_gpu::readback::read_buffer_as(&ctx, &target.normals).unwrap());
            let (cpos, cnrm) = cpu(grid, time, &layers, Some(height));
            let label = format!(
                "{} layers, {}x{}, t={time}",
                data.len(),
                grid.size.0,
                grid.size.1
            );
            let same = identical(&pos, &nrm, &cpos, &cnrm);
            assert_within(&label, &compare(&pos, &nrm, &cpos, &cnrm), same);
            pass.stats()
        };

    let fresh = pass.stats();
    assert_eq!(fresh.buffers_created, 3, "uniforms, descriptors, data");
    assert_eq!(fresh.bind_groups_created, 0);
    let first = run(&one, &small, &small_height, &small_target);
    assert_eq!(
        first,
        LayersStats {
            bind_groups_created: 1,
            ..fresh
        }
    );
    for _ in 0..3 {
        assert_eq!(
            run(&one, &small, &small_height, &small_target),
            first,
            "steady state"
        );
    }

    // Nine layers outgrow the descriptors only.
    let more = run(&nine, &small, &small_height, &small_target);
    assert_eq!(more.buffers_created, first.buffers_created + 1);
    assert!(more.layer_capacity >= 9, "{more:?}");
    assert_eq!(more.data_capacity, first.data_capacity);
    assert_eq!(more.bind_groups_created, first.bind_groups_created + 1);
    assert_eq!(
        run(&nine, &small, &small_height, &small_target),
        more,
        "steady state"
    );

    // The large layers and the big grid's height outgrow the data only.
    let grown = run(&large, &big, &big_height, &big_target);
    assert_eq!(grown.buffers_created, more.buffers_created + 1);
    assert_eq!(grown.layer_capacity, more.layer_capacity);
    assert!(grown.data_capacity >= 60_000 + 2 * 30_000, "{grown:?}");
    assert_eq!(
        run(&large, &big, &big_height, &big_target),
        grown,
        "steady state"
    );

    // Back to smaller inputs, alternating targets: after one bind group for the small target
    // (the growth dropped the cache), nothing more is created, and leftovers are not read.
    let both = run(&one, &small, &small_height, &small_target);
    assert_eq!(both.bind_groups_created, grown.bind_groups_created + 1);
    assert_eq!(both.buffers_created, grown.buffers_created);
    for _ in 0..2 {
        assert_eq!(run(&large, &big, &big_height, &big_target), both);
        assert_eq!(run(&nine, &small, &small_height, &small_target), both);
        assert_eq!(run(&one, &small, &small_height, &small_target), both);
    }
}
