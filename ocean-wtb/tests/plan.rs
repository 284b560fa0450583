//! `Scene::plan` describes exactly what `Scene::frame` evaluates: the same boxes in the same
//! order, the same trains, and a march whose result (with the frame's time-dependent effects) is
//! the frame's modulation bit for bit. A GPU twin that marches from the plan therefore has the
//! CPU frame as its oracle.

use ocean_wtb::effects::{Beach, Effects, Irregular, Refraction};
use ocean_wtb::scenarios;
use ocean_wtb::scene::Scene;

fn check(scene: &mut Scene, t: f64, label: &str) {
    let plan = scene.plan(t, None).unwrap();
    let grid = *scene.grid();
    let terrain = scene.terrain().clone();
    let frame = scene.frame(t, None).unwrap();
    let layers = frame.layers();
    assert!(!layers.is_empty(), "{label}: no layers");
    assert_eq!(plan.boxes.len(), layers.len(), "{label}: box count");
    assert_eq!(plan.stats.trains, frame.stats().trains, "{label}: trains");
    for (n, (b, layer)) in plan.boxes.iter().zip(&layers).enumerate() {
        assert_eq!(b.march.rect, layer.rect(), "{label}: box {n} rectangle");
        assert_eq!(
            b.waves.coeffs(),
            layer.waves.coeffs(),
            "{label}: box {n} waves"
        );
        let (mu, _) = b.march.march(&grid, &terrain).unwrap();
        let mu = mu.unwrap();
        let timed = b
            .march
            .time_modulation(&grid, &terrain, &mu, &plan.effects, t)
            .unwrap();
        let mu = timed.as_ref().unwrap_or(&mu);
        assert_eq!(
            mu.values(),
            layer.modulation.values(),
            "{label}: box {n} modulation"
        );
    }
}

#[test]
fn the_plan_is_the_frame_without_its_march() {
    check(&mut scenarios::scenario_1(64).unwrap(), 12.0, "scenario 1");
    check(&mut scenarios::scenario_2(64).unwrap(), 3.5, "scenario 2");
    let mut island = scenarios::island(96).unwrap();
    check(&mut island, 40.0, "island");
    island
        .set_effects(Effects {
            refraction: Refraction::Dispersion,
            shoaling: true,
            irregular: Some(Irregular {
                scale: 0.4,
                frequency: 0.2,
                envelope_wavenumber: 0.05,
                envelope_speed: 3.0,
            }),
            noise: None,
            round_waves: true,
            beach: Some(Beach {
                max_depth_share: 0.6,
                run_up: 0.15,
                run_up_depth: 1.5,
            }),
        })
        .unwrap();
    check(&mut island, 40.0, "island, every effect");
}
