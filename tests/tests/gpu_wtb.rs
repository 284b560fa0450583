//! Wave train boxes on the GPU: every visible box of a frame becomes a modulated layer, and
//! `ocean_gpu::LayersPass` must draw the same water as `Frame::evaluate` on the CPU (heights
//! within 1 mm RMS, normals within 0.1°) on the paper's scenarios, with land, shadows,
//! refraction, shoaling and every time-dependent effect.

use glam::Vec3;
use ocean_gpu::{LayersPass, WtbMarchPass};
use ocean_tests::{assert_parity, compare, gpu_context_or_skip};
use ocean_wtb::effects::{Effects, Irregular, Noise, Refraction};
use ocean_wtb::scenarios;
use ocean_wtb::scene::Scene;

fn check(pass: &LayersPass, ctx: &ocean_gpu::GpuContext, scene: &mut Scene, t: f64, label: &str) {
    let frame = scene.frame(t, None).unwrap();
    let n = frame.grid().len();
    let (mut pos, mut nrm) = (vec![Vec3::ZERO; n], vec![Vec3::ZERO; n]);
    frame.evaluate(&mut pos, &mut nrm).unwrap();
    let gpu = pass
        .evaluate(
            ctx,
            frame.grid().grid(),
            frame.time(),
            &frame.layers(),
            frame.height_field(),
        )
        .unwrap();
    // The scene must actually have waves for the comparison to mean anything.
    let top = pos.iter().map(|p| p.y.abs()).fold(0.0f32, f32::max);
    assert!(top > 0.1, "{label}: no waves ({top} m)");
    let d = compare(&gpu.positions, &gpu.normals, &pos, &nrm);
    assert_parity(&format!("{label}, |y| up to {top:.3} m"), &d);
}

#[test]
fn paper_scenarios_match_the_cpu() {
    let Some(ctx) = gpu_context_or_skip() else {
        return;
    };
    let pass = LayersPass::new(&ctx).unwrap();
    for n in [64, 256] {
        check(
            &pass,
            &ctx,
            &mut scenarios::scenario_1(n).unwrap(),
            12.0,
            &format!("scenario 1, {n}²"),
        );
        check(
            &pass,
            &ctx,
            &mut scenarios::scenario_2(n).unwrap(),
            3.5,
            &format!("scenario 2, {n}²"),
        );
        check(
            &pass,
            &ctx,
            &mut scenarios::island(n).unwrap(),
            1.0e5,
            &format!("island, {n}²"),
        );
    }
}

#[test]
fn every_effect_matches_the_cpu() {
    let Some(ctx) = gpu_context_or_skip() else {
        return;
    };
    let pass = LayersPass::new(&ctx).unwrap();
    let mut scene = scenarios::island(128).unwrap();
    scene
        .set_effects(Effects {
            refraction: Refraction::Dispersion,
            shoaling: true,
            irregular: Some(Irregular {
                scale: 0.4,
                frequency: 0.2,
                envelope_wavenumber: 0.05,
                envelope_speed: 3.0,
            }),
            noise: Some(Noise {
                amplitude: 0.02,
                seed: 99,
            }),
            round_waves: true,
            beach: Some(ocean_wtb::effects::Beach {
                max_depth_share: 0.6,
                run_up: 0.15,
                run_up_depth: 1.5,
            }),
        })
        .unwrap();
    for t in [0.0, 42.0, 1.0e6] {
        check(
            &pass,
            &ctx,
            &mut scene,
            t,
            &format!("island 128², every effect, t = {t}"),
        );
    }
}

/// The rays marched on the GPU (`WtbMarchPass`, one invocation per wave ray) against the CPU's
/// march: every box's modulation value by value, then the evaluated grid (1 mm RMS, 0.1°).
///
/// The ownership of grid points by rays is exact on both sides (the same integers), so the
/// values differ by f32 rounding only: of the ray's refraction lag (kept reduced to [−π, π], a
/// few 10⁻⁷ rad a step), of the shoaling and side-fade factors (10⁻⁷), and of the land factor's
/// box mean (f32 sums of at most 2r + 1 terms against the CPU's f64 prefix sums); measured at
/// most 9·10⁻⁶ on lavapipe, so MODULATION_TOL = 2·10⁻⁵. With dispersion refraction the phase
/// (ω∞ − ω(D))·t takes ω(D) from f32 arithmetic (a few ulps of ω∞ ≈ 1 rad/s), so the tolerance
/// grows by DISPERSION_DRIFT = 4·10⁻⁷ rad/s times t.
fn check_march(
    pass: &WtbMarchPass,
    ctx: &ocean_gpu::GpuContext,
    scene: &mut Scene,
    t: f64,
    label: &str,
) {
    const MODULATION_TOL: f32 = 2e-5;
    const DISPERSION_DRIFT: f64 = 4e-7;
    let plan = scene.plan(t, None).unwrap();
    let tol = if plan.effects.refraction == Refraction::Dispersion {
        MODULATION_TOL + (DISPERSION_DRIFT * t) as f32
    } else {
        MODULATION_TOL
    };
    let grid = *scene.grid();
    let terrain = scene.terrain().clone();
    let frame = scene.frame(t, None).unwrap();
    let (gpu, mus) = pass.evaluate(ctx, &grid, &terrain, &plan).unwrap();
    let layers = frame.layers();
    assert_eq!(mus.len(), layers.len(), "{label}: boxes");
    let mut worst = 0.0f32;
    for (n, (gpu_mu, layer)) in mus.iter().zip(&layers).enumerate() {
        let cpu_mu = layer.modulation.values();
        assert_eq!(gpu_mu.len(), cpu_mu.len(), "{label}: box {n} size");
        for (q, (g, c)) in gpu_mu.iter().zip(cpu_mu).enumerate() {
            let d = (g[0] - c[0]).abs().max((g[1] - c[1]).abs());
            assert!(
                d <= tol,
                "{label}: box {n} point {q}: GPU {g:?} CPU {c:?} (tolerance {tol:e})"
            );
            worst = worst.max(d);
        }
    }
    let n = grid.len();
    let (mut pos, mut nrm) = (vec![Vec3::ZERO; n], vec![Vec3::ZERO; n]);
    frame.evaluate(&mut pos, &mut nrm).unwrap();
    let top = pos.iter().map(|p| p.y.abs()).fold(0.0f32, f32::max);
    assert!(top > 0.1, "{label}: no waves ({top} m)");
    let d = compare(&gpu.positions, &gpu.normals, &pos, &nrm);
    assert_parity(
        &format!("{label}, GPU march, modulation within {worst:.1e}"),
        &d,
    );
}

#[test]
fn rays_marched_on_the_gpu_match_the_cpu() {
    let Some(ctx) = gpu_context_or_skip() else {
        return;
    };
    let pass = WtbMarchPass::new(&ctx).unwrap();
    for n in [64, 256] {
        check_march(
            &pass,
            &ctx,
            &mut scenarios::scenario_1(n).unwrap(),
            12.0,
            &format!("scenario 1, {n}²"),
        );
        check_march(
            &pass,
            &ctx,
            &mut scenarios::scenario_2(n).unwrap(),
            3.5,
            &format!("scenario 2, {n}²"),
        );
        check_march(
            &pass,
            &ctx,
            &mut scenarios::island(n).unwrap(),
            1.0e5,
            &format!("island, {n}²"),
        );
    }
    // Every effect. The dispersion option's phase comes from an f32 ω(D) on the GPU and drifts
    // from the CPU's by about 10⁻⁷·Δω·t (see `ocean_gpu::wtb`): it is compared up to t = 1000 s,
    // and the long-run times with every other effect.
    let mut scene = scenarios::island(128).unwrap();
    let mut effects = Effects {
        refraction: Refraction::Dispersion,
        shoaling: true,
        irregular: Some(Irregular {
            scale: 0.4,
            frequency: 0.2,
            envelope_wavenumber: 0.05,
            envelope_speed: 3.0,
        }),
        noise: Some(Noise {
            amplitude: 0.02,
            seed: 99,
        }),
        round_waves: true,
        beach: Some(ocean_wtb::effects::Beach {
            max_depth_share: 0.6,
            run_up: 0.15,
            run_up_depth: 1.5,
        }),
    };
    scene.set_effects(effects).unwrap();
    for t in [0.0, 42.0, 1000.0] {
        check_march(
            &pass,
            &ctx,
            &mut scene,
            t,
            &format!("island 128², every effect, t = {t}"),
        );
    }
    effects.refraction = Refraction::PhaseShift;
    scene.set_effects(effects).unwrap();
    for t in [42.0, 1.0e6] {
        check_march(
            &pass,
            &ctx,
            &mut scene,
            t,
            &format!("island 128², phase-shift refraction and every other effect, t = {t}"),
        );
    }
}

#[test]
fn the_gpu_march_refuses_bad_input_before_recording() {
    let Some(ctx) = gpu_context_or_skip() else {
        return;
    };
    let pass = WtbMarchPass::new(&ctx).unwrap();
    let scene = scenarios::scenario_1(64).unwrap();
    let grid = *scene.grid();
    let plan = scene.plan(12.0, None).unwrap();
    // A terrain made for another grid: the model's own error, with both sizes.
    let other = scenarios::scenario_1(32).unwrap().terrain().clone();
    match pass.evaluate(&ctx, &grid, &other, &plan) {
        Err(ocean_gpu::GpuError::Wtb(ocean_wtb::WtbError::TerrainSize { expected, got })) => {
            assert_eq!((expected, got), (64 * 64, 32 * 32));
        }
        other => panic!("terrain of another grid: {:?}", other.map(|_| ())),
    }
    // Times outside [0, 2³⁶) s, where the dispersion phase's exact split does not reach.
    for t in [-1.0, ocean_gpu::wtb::MAX_TIME] {
        let mut plan = scene.plan(12.0, None).unwrap();
        plan.t = t;
        assert!(
            matches!(
                pass.evaluate(&ctx, &grid, scene.terrain(), &plan),
                Err(ocean_gpu::GpuError::Eval(ocean_core::EvalError::Time(_)))
            ),
            "t = {t}"
        );
    }
}

/// A still box is marched once and its march reused (the paper's action points, cached while
/// the box is still); moving a box re-marches that box alone, a new terrain re-marches every
/// box, and each of those frames still matches the CPU (`check_march`'s tolerances).
#[test]
fn the_gpu_march_is_cached_while_boxes_are_still() {
    let Some(ctx) = gpu_context_or_skip() else {
        return;
    };
    let pass = WtbMarchPass::new(&ctx).unwrap();
    let mut scene = scenarios::scenario_1(64).unwrap();
    let ids: Vec<_> = scene.box_ids().collect();
    assert_eq!(ids.len(), 2);

    check_march(&pass, &ctx, &mut scene, 12.0, "scenario 1, first call");
    let first = pass.stats();
    assert_eq!(
        (first.marches, first.reuses, first.terrain_uploads),
        (2, 0, 1)
    );
    assert_eq!(first.cached_boxes, 2);
    // Terrain 1 + 4 per box.
    assert_eq!(first.buffers_created, 9);

    // Still boxes: the same marches at other times, nothing allocated.
    for t in [12.5, 100.0] {
        check_march(
            &pass,
            &ctx,
            &mut scene,
            t,
            &format!("scenario 1, t = {t}, cached"),
        );
    }
    let still = pass.stats();
    assert_eq!((still.marches, still.reuses), (2, 4));
    assert_eq!(still.buffers_created, first.buffers_created);
    assert_eq!(still.terrain_uploads, 1);

    // The same plan twice gives the same bits.
    let plan = scene.plan(100.0, None).unwrap();
    let a = pass
        .evaluate(&ctx, scene.grid(), scene.terrain(), &plan)
        .unwrap();
    let b = pass
        .evaluate(&ctx, scene.grid(), scene.terrain(), &plan)
        .unwrap();
    assert_eq!(a.0.positions, b.0.positions);
    assert_eq!(a.1, b.1);
    let before_move = pass.stats();

    // The second box moves 3 m along x (a boat's wake): it alone is marched again, into its
    // own buffers (the same size of rectangle).
    // Scenario 1's second box (at 64², scale 1) with its origin 3 m further along x.
    let moved = scenarios::spec(scenarios::steady_wind(
        5.0,
        glam::DVec2::new(0.7, 1.0),
        glam::DVec2::new(33.0, -30.0),
        60.0,
        90.0,
        2,
        12,
    ));
    scene.update_box(ids[1], moved).unwrap();
    check_march(
        &pass,
        &ctx,
        &mut scene,
        100.0,
        "scenario 1, second box moved",
    );
    let after_move = pass.stats();
    assert_eq!(after_move.marches, before_move.marches + 1);
    assert_eq!(after_move.reuses, before_move.reuses + 1);
    assert_eq!(after_move.cached_boxes, 2);

    // Another terrain on the same grid (the floor 2 m shallower): every box is marched again
    // over it, and the terrain's buffer (the same size) is rewritten, not replaced.
    let grid = *scene.grid();
    let shallower: Vec<f32> = scene
        .terrain()
        .heights()
        .unwrap()
        .iter()
        .map(|h| h + 2.0)
        .collect();
    scene
        .set_terrain(ocean_wtb::Terrain::from_heights(&grid, shallower).unwrap())
        .unwrap();
    check_march(&pass, &ctx, &mut scene, 100.0, "scenario 1, new terrain");
    let new_terrain = pass.stats();
    assert_eq!(new_terrain.marches, after_move.marches + 2);
    assert_eq!(new_terrain.terrain_uploads, 2);
    assert_eq!(new_terrain.buffers_created, after_move.buffers_created);

    // A refused call (a target made for a smaller grid) records, submits and caches nothing,
    // even with a box moved back, whose march it would otherwise have rebuilt.
    scene
        .update_box(
            ids[1],
            scenarios::spec(scenarios::steady_wind(
                5.0,
                glam::DVec2::new(0.7, 1.0),
                glam::DVec2::new(30.0, -30.0),
                60.0,
                90.0,
                2,
                12,
            )),
        )
        .unwrap();
    let plan = scene.plan(100.0, None).unwrap();
    let small = ocean_core::Grid::centred(glam::DVec2::ZERO, 1.0, 32);
    let target = ocean_gpu::TrochoidTarget::new(&ctx, &small).unwrap();
    let mut encoder = ctx
        .device()
        .create_command_encoder(&ocean_gpu::wgpu::CommandEncoderDescriptor { label: None });
    let refused = pass.encode(
        &ctx,
        &mut encoder,
        &grid,
        scene.terrain(),
        &plan,
        &target,
        None,
    );
    assert!(refused.is_err(), "a target of 32² points for a 64² grid");
    assert_eq!(pass.stats(), new_terrain);
}
