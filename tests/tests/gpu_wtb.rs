//! Wave train boxes on the GPU: every visible box of a frame becomes a modulated layer, and
//! `ocean_gpu::LayersPass` must draw the same water as `Frame::evaluate` on the CPU (issue 3:
//! heights within 1 mm RMS, normals within 0.1°) on the paper's scenarios, with land, shadows,
//! refraction, shoaling and every time-dependent effect.

use glam::Vec3;
use ocean_gpu::LayersPass;
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
