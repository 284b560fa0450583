//! The wave model end to end: the paper's scenario 1, land, culling, queries, threads.

use glam::{DVec2, DVec3, Vec3};
use ocean_core::camera::{Camera, DepthConvention, Far, Projection};
use ocean_core::frustum::Frustum;
use ocean_wtb::effects::{Effects, Refraction};
use ocean_wtb::scene::{ActionKind, Scene, rectangles_overlap};
use ocean_wtb::{Terrain, WaterGrid, Wind};

use ocean_wtb::scenarios::{self, spec, steady_wind as wind};

fn sloping() -> (WaterGrid, Terrain) {
    scenarios::sloping(64).unwrap()
}

fn scenario_1() -> Scene {
    scenarios::scenario_1(64).unwrap()
}

fn island() -> Scene {
    scenarios::island(64).unwrap()
}

fn evaluate(scene: &mut Scene, t: f64) -> (Vec<Vec3>, Vec<Vec3>) {
    let n = scene.grid().len();
    let (mut p, mut q) = (vec![Vec3::ZERO; n], vec![Vec3::ZERO; n]);
    scene
        .frame(t, None)
        .unwrap()
        .evaluate(&mut p, &mut q)
        .unwrap();
    (p, q)
}

fn height_table(p: &[Vec3]) -> String {
    let mut out = String::new();
    for row in p.chunks(64) {
        for v in row {
            // Centimetres: far above f32 and platform-libm differences, fine enough to see waves.
            out += &format!("{:>5}", (v.y * 100.0).round() as i32);
        }
        out.push('\n');
    }
    out
}

#[test]
fn scenario_1_snapshot() {
    let mut s = scenario_1();
    let (p, _) = evaluate(&mut s, 12.0);
    insta::assert_snapshot!(height_table(&p));
}

#[test]
fn land_scenario_snapshot() {
    let mut s = island();
    let (p, _) = evaluate(&mut s, 7.5);
    insta::assert_snapshot!(height_table(&p));
}

#[test]
fn land_damps_and_shadows_then_recovers() {
    // Waves travel along +x. On the island the amplitude is zero; right behind it (the rays
    // that crossed land) it starts from zero and recovers linearly over 20 m (Fig. 5); rays
    // that missed the island keep their amplitude. Measured as the largest |y| over a period.
    let mut s = island();
    let id = s.box_ids().next().unwrap();
    let mut peak = vec![0.0f32; 64 * 64];
    for step in 0..40 {
        let (p, _) = evaluate(&mut s, step as f64 * 0.25);
        for (m, v) in peak.iter_mut().zip(&p) {
            *m = m.max(v.y.abs());
        }
    }
    let at = |x: usize, z: usize| peak[z * 64 + x];
    // On land: nothing.
    assert_eq!(at(32, 32), 0.0);
    // In the shadow, 2 m behind the island (x = 38), against open water at the same x.
    assert!(
        at(38, 32) < 0.25 * at(38, 8),
        "shadow {} vs open {}",
        at(38, 32),
        at(38, 8)
    );
    // Recovery: further behind the shadow is weaker (x = 58 is ~22 m behind the island's edge).
    assert!(
        at(58, 32) > 3.0 * at(38, 32),
        "recovered {} vs shadow {}",
        at(58, 32),
        at(38, 32)
    );
    // The action points of the ray through the island's centre: land starts, then ends.
    let actions = s.action_points(id).unwrap();
    let starts = actions
        .iter()
        .filter(|a| a.kind == ActionKind::LandStart)
        .count();
    let ends = actions
        .iter()
        .filter(|a| a.kind == ActionKind::LandEnd)
        .count();
    assert!(
        starts >= 7 && starts == ends,
        "{starts} land starts, {ends} ends"
    );
    assert!(actions.iter().any(|a| a.kind == ActionKind::Shallow));
}

#[test]
fn refraction_by_phase_shift_does_not_queue_but_dispersion_does() {
    // §2.1, Fig. 7. With a depth-dependent frequency ω(D) (Eq. 4) the phase difference between
    // shallow and deep water grows linearly with time, so crests pile up towards land: the
    // number of zero crossings along a ray in the shallow half keeps growing. The default phase
    // shift bends the fronts once and for all: the count stays what it is.
    let (grid, terrain) = sloping();
    let one = |refraction| {
        let mut s = Scene::new(grid, terrain.clone()).unwrap();
        s.set_effects(Effects {
            refraction,
            shoaling: false,
            ..Effects::default()
        })
        .unwrap();
        s.add_box(spec(wind(
            7.0,
            DVec2::X,
            DVec2::new(-2.0, -2.0),
            68.0,
            68.0,
            1,
            3,
        )))
        .unwrap();
        s
    };
    // Sign changes of y along row z = 32, x = 32..63 (15 m down to 1 m deep).
    let crossings = |s: &mut Scene, t: f64| {
        let (p, _) = evaluate(s, t);
        let row: Vec<f32> = (32..64).map(|x| p[32 * 64 + x].y).collect();
        row.windows(2)
            .filter(|w| (w[0] < 0.0) != (w[1] < 0.0))
            .count()
    };
    let mut shift = one(Refraction::PhaseShift);
    let mut disp = one(Refraction::Dispersion);
    let (s5, s60) = (crossings(&mut shift, 5.0), crossings(&mut shift, 60.0));
    let (d5, d60) = (crossings(&mut disp, 5.0), crossings(&mut disp, 60.0));
    println!("zero crossings at t = 5, 60 s: phase shift {s5}, {s60}; dispersion {d5}, {d60}");
    assert!(s60.abs_diff(s5) <= 1, "phase shift queued: {s5} -> {s60}");
    assert!(d60 >= 2 * d5 + 4, "dispersion did not queue: {d5} -> {d60}");
    // And at t = 0 the dispersion offset (ω∞ − ω(D))·t vanishes: it equals no refraction.
    let mut off = one(Refraction::Off);
    assert_eq!(evaluate(&mut disp, 0.0).0, evaluate(&mut off, 0.0).0);
}

#[test]
fn overlap_heights_and_culling() {
    let mut s = scenario_1();
    // A third, small box in the grid's far corner.
    s.add_box(spec(wind(
        6.0,
        DVec2::X,
        DVec2::new(50.0, 50.0),
        12.0,
        12.0,
        1,
        9,
    )))
    .unwrap();
    // The two boxes of scenario 1 overlap; a box far away overlaps neither.
    let frames: Vec<_> = [
        wind(
            7.0,
            DVec2::new(1.0, 0.15),
            DVec2::new(-2.0, -4.0),
            66.0,
            70.0,
            1,
            11,
        ),
        wind(
            5.0,
            DVec2::new(0.7, 1.0),
            DVec2::new(30.0, -30.0),
            60.0,
            90.0,
            2,
            12,
        ),
        wind(6.0, DVec2::X, DVec2::new(-400.0, 0.0), 12.0, 12.0, 1, 9),
    ]
    .iter()
    .map(|w| w.frame(3.0, 1.0).unwrap().unwrap())
    .collect();
    assert!(rectangles_overlap(&frames[0], &frames[1]));
    assert!(!rectangles_overlap(&frames[0], &frames[2]));
    let cam = |eye: DVec3, target: DVec3| {
        Camera::look_at(
            eye,
            target,
            DVec3::Z,
            Projection::Perspective {
                fov_y: 1.2,
                aspect: 1.0,
                near: 0.1,
                far: Far::Finite(500.0),
            },
            DepthConvention::ZERO_TO_ONE,
        )
        .unwrap()
    };
    // 12 m above the near corner looking straight down, the view covers about ±8 m around
    // (10, 10): the two large boxes reach there, the corner box (50..62) does not.
    let down = cam(DVec3::new(10.0, 12.0, 10.0), DVec3::new(10.0, 0.0, 10.0001));
    let f = s
        .frame(3.0, Some(&Frustum::from_camera(&down).unwrap()))
        .unwrap();
    assert_eq!((f.stats().alive, f.stats().culled), (3, 1));
    drop(f);
    // Looking straight up, every box is culled, and the grid is at rest.
    let up = cam(
        DVec3::new(32.0, 40.0, 32.0),
        DVec3::new(32.0, 80.0, 32.0001),
    );
    let f = s
        .frame(3.0, Some(&Frustum::from_camera(&up).unwrap()))
        .unwrap();
    assert_eq!(f.stats().culled, 3);
    let n = 64 * 64;
    let (mut p, mut q) = (vec![Vec3::ZERO; n], vec![Vec3::ZERO; n]);
    f.evaluate(&mut p, &mut q).unwrap();
    assert!(p.iter().all(|v| v.y == 0.0) && q.iter().all(|v| *v == Vec3::Y));
}

#[test]
fn queries_agree_with_the_grid_within_1_mm() {
    // Query the world (x, z) where each interior grid point was displaced to: the answer must
    // be that grid point's height, within 1 mm (the query bound); the residual of the
    // horizontal inversion stays below its 0.1 mm tolerance.
    for mut s in [scenario_1(), island()] {
        let t = 9.25;
        let (p, q) = evaluate(&mut s, t);
        let f = s.frame(t, None).unwrap();
        let mut worst = 0.0f64;
        let mut worst_n = 0.0f64;
        let mut at = Vec::new();
        let mut expect = Vec::new();
        for z in (2..62).step_by(3) {
            for x in (2..62).step_by(3) {
                let k = z * 64 + x;
                at.push(DVec2::new(f64::from(p[k].x), f64::from(p[k].z)));
                expect.push((p[k].y, q[k]));
            }
        }
        let mut out = vec![
            ocean_wtb::scene::HeightSample {
                height: 0.0,
                normal: DVec3::Y,
                rest: DVec2::ZERO,
                residual: 0.0
            };
            at.len()
        ];
        f.continuous_heights(&at, &mut out).unwrap();
        for (o, (y, n)) in out.iter().zip(&expect) {
            assert!(o.residual <= ocean_wtb::scene::QUERY_TOLERANCE);
            worst = worst.max((o.height - f64::from(*y)).abs());
            worst_n = worst_n.max((o.normal - n.as_dvec3()).length());
        }
        println!("queries: worst height error {worst:e} m, normal {worst_n:e}");
        assert!(worst < 1e-3, "height error {worst} m");
        assert!(worst_n < 1e-3, "normal error {worst_n}");
    }
}

#[test]
fn batched_queries_equal_single_queries_bit_for_bit() {
    // Batches of 256 or more are answered in grid order, not the caller's: every answer must
    // still be the one `height_at` gives that point, at its own index, on any thread count.
    // The points are scattered at random over and around the 64 m grid (some outside it, where
    // the sea is at rest), so their grid order differs from the caller's.
    let mut s = island();
    let f = s.frame(6.5, None).unwrap();
    let mut rng = ocean_core::Pcg32::new(17, 5);
    let at: Vec<DVec2> = (0..1000)
        .map(|_| DVec2::new(rng.next_f64() * 80.0 - 8.0, rng.next_f64() * 80.0 - 8.0))
        .collect();
    let want: Vec<_> = at
        .iter()
        .map(|p| f.continuous_height_at(*p).unwrap())
        .collect();
    assert!(want.iter().any(|w| w.height != 0.0) && want.iter().any(|w| w.height == 0.0));
    let blank = ocean_wtb::scene::HeightSample {
        height: f64::NAN,
        normal: DVec3::ZERO,
        rest: DVec2::ZERO,
        residual: f64::NAN,
    };
    for n in [255, 256, 1000] {
        let mut out = vec![blank; n];
        f.continuous_heights(&at[..n], &mut out).unwrap();
        assert!(out == want[..n], "{n} queries, one thread");
        for threads in [1, 2, 8] {
            let pool = rayon::ThreadPoolBuilder::new()
                .num_threads(threads)
                .build()
                .unwrap();
            let mut out = vec![blank; n];
            pool.install(|| f.continuous_heights_par(&at[..n], &mut out))
                .unwrap();
            assert!(out == want[..n], "{n} queries, {threads} threads");
        }
    }
}

#[test]
fn threads_give_identical_bits() {
    let mut s = island();
    let (p1, q1) = evaluate(&mut s, 4.0);
    let f = s.frame(4.0, None).unwrap();
    for threads in [1, 2, 8] {
        let pool = rayon::ThreadPoolBuilder::new()
            .num_threads(threads)
            .build()
            .unwrap();
        let (mut p, mut q) = (vec![Vec3::ZERO; 4096], vec![Vec3::ZERO; 4096]);
        pool.install(|| f.evaluate_par(&mut p, &mut q)).unwrap();
        assert!(p == p1 && q == q1, "{threads} threads");
    }
}

#[test]
fn still_boxes_are_cached_and_moving_boxes_rebuilt() {
    let mut s = scenario_1();
    assert_eq!(s.frame(1.0, None).unwrap().stats().rebuilt, 2);
    assert_eq!(s.frame(2.0, None).unwrap().stats().rebuilt, 0);
    let id = s.box_ids().next().unwrap();
    let moved = spec(wind(
        7.0,
        DVec2::new(1.0, 0.15),
        DVec2::new(-1.0, -4.0),
        66.0,
        70.0,
        1,
        11,
    ));
    s.update_box(id, moved).unwrap();
    assert_eq!(s.frame(3.0, None).unwrap().stats().rebuilt, 1);
    s.remove_box(id).unwrap();
    assert!(s.remove_box(id).is_err());
    assert!(s.frame(f64::NAN, None).is_err());
}

#[test]
fn bad_input_is_refused() {
    let mut s = scenario_1();
    // Zero wind, NaN width, a box far outside the grid, negative smoothing.
    let ok = wind(6.0, DVec2::X, DVec2::ZERO, 20.0, 20.0, 1, 1);
    for bad in [
        Wind { speed: 0.0, ..ok },
        Wind {
            width: f64::NAN,
            ..ok
        },
        Wind {
            origin: DVec2::new(1.0e5, 0.0),
            ..ok
        },
        Wind {
            direction: DVec2::ZERO,
            ..ok
        },
    ] {
        assert!(s.add_box(spec(bad)).is_err(), "{bad:?}");
    }
    assert!(matches!(
        s.add_box(spec(Wind {
            origin: DVec2::new(-500.0, -500.0),
            ..ok
        })),
        Err(ocean_wtb::WtbError::OutsideGrid)
    ));
    assert!(
        s.add_box(ocean_wtb::scene::BoxSpec {
            smoothing: -1.0,
            ..spec(ok)
        })
        .is_err()
    );
    // Terrain of another grid.
    let other = WaterGrid::new(DVec2::ZERO, 1.0, 32, 32).unwrap();
    assert!(s.set_terrain(Terrain::deep(&other)).is_err());
    // A budget that is not a time.
    assert!(
        s.set_budget(ocean_wtb::budget::Budget::Seconds(f64::NAN))
            .is_err()
    );
    // Output buffers of the wrong size: an error, nothing written.
    let f = s.frame(1.0, None).unwrap();
    let (mut p, mut q) = (vec![Vec3::splat(5.0); 100], vec![Vec3::splat(5.0); 100]);
    assert!(f.evaluate(&mut p, &mut q).is_err());
    assert!(p.iter().all(|v| *v == Vec3::splat(5.0)));
    assert!(f.continuous_height_at(DVec2::new(f64::NAN, 0.0)).is_err());
    // The scene still works.
    assert_eq!(s.box_ids().count(), 2);
}

#[test]
fn a_time_budget_drops_effects_then_trains() {
    // §2.3: work is admitted trains first, effects after: a budget a little below the full
    // cost drops the refraction but keeps all three trains of scenario 1; a budget too small
    // for any train leaves only the base (the grid at rest).
    let mut s = scenario_1();
    let full = s.frame(1.0, None).unwrap().stats().estimated_ns;
    assert_eq!(s.frame(1.0, None).unwrap().stats().trains, 3);
    s.set_budget(ocean_wtb::budget::Budget::Seconds(0.9 * full * 1e-9))
        .unwrap();
    let f = s.frame(1.0, None).unwrap();
    let sel = f.stats().selection.unwrap();
    assert_eq!(
        (f.stats().trains, sel.effects.refraction),
        (3, Refraction::Off)
    );
    assert!(f.stats().estimated_ns <= 0.9 * full);
    drop(f);
    s.set_budget(ocean_wtb::budget::Budget::Seconds(1e-9))
        .unwrap();
    let f = s.frame(1.0, None).unwrap();
    assert_eq!(f.stats().trains, 0);
    let (mut p, mut q) = (vec![Vec3::ZERO; 4096], vec![Vec3::ZERO; 4096]);
    f.evaluate(&mut p, &mut q).unwrap();
    assert!(p.iter().all(|v| v.y == 0.0));
}

#[test]
fn any_grid_spacing_gives_the_same_sea() {
    // The model is in metres: the same wind over the same terrain sampled 0.5 m, 1 m or 2 m
    // apart (grids covering the same 63 m square, from an origin off zero) must put the same
    // waves at the points the three grids share (every 2 m). Smoothing, land recovery and
    // shoaling depend on a point's position only; the refraction lag is summed along each ray
    // with the grid's own step, so it differs slightly between spacings.
    let origin = DVec2::new(-17.0, 5.0);
    let make = |spacing: f64| {
        let n = (63.0 / spacing) as usize + 1;
        let grid = WaterGrid::new(origin, spacing, n, n).unwrap();
        let terrain = Terrain::from_fn(&grid, |p| -(25.0 - 0.3 * (p.x - origin.x)) as f32).unwrap();
        let mut s = Scene::new(grid, terrain).unwrap();
        s.add_box(spec(wind(
            7.0,
            DVec2::new(1.0, 0.3),
            origin + DVec2::new(-3.0, -6.0),
            70.0,
            75.0,
            2,
            4,
        )))
        .unwrap();
        s
    };
    let heights = |mut s: Scene, step: usize| {
        let n = s.grid().nx();
        let (mut p, mut q) = (vec![Vec3::ZERO; n * n], vec![Vec3::ZERO; n * n]);
        s.frame(8.0, None)
            .unwrap()
            .evaluate(&mut p, &mut q)
            .unwrap();
        // Every 2 m: every `step`-th point of every `step`-th row.
        (0..n)
            .step_by(step)
            .flat_map(|j| (0..n).step_by(step).map(move |i| (i, j)))
            .map(|(i, j)| p[j * n + i].y)
            .collect::<Vec<f32>>()
    };
    let coarse = heights(make(2.0), 1);
    let medium = heights(make(1.0), 2);
    let fine = heights(make(0.5), 4);
    assert_eq!(coarse.len(), medium.len());
    assert_eq!(coarse.len(), fine.len());
    let top = coarse.iter().fold(0.0f32, |m, v| m.max(v.abs()));
    assert!(top > 0.2, "waves present: {top}");
    let worst = |a: &[f32], b: &[f32]| {
        a.iter()
            .zip(b)
            .map(|(x, y)| (x - y).abs())
            .fold(0.0f32, f32::max)
    };
    // A centimetre bounds the refraction's discretisation difference.
    assert!(
        worst(&coarse, &medium) < 0.01,
        "2 m vs 1 m: {}",
        worst(&coarse, &medium)
    );
    assert!(
        worst(&medium, &fine) < 0.01,
        "1 m vs 0.5 m: {}",
        worst(&medium, &fine)
    );
}

#[test]
fn incremental_evaluation_equals_full_evaluation_frame_after_frame() {
    // Persistent buffers updated incrementally must hold, after every frame, exactly what a full
    // evaluation writes, while boxes appear, leave the view, come back, move and disappear.
    let mut s = scenario_1();
    s.add_box(spec(wind(
        6.0,
        DVec2::X,
        DVec2::new(50.0, 50.0),
        12.0,
        12.0,
        1,
        9,
    )))
    .unwrap();
    let cam = |eye: DVec3, target: DVec3| {
        let c = Camera::look_at(
            eye,
            target,
            DVec3::Z,
            Projection::Perspective {
                fov_y: 1.2,
                aspect: 1.0,
                near: 0.1,
                far: Far::Finite(500.0),
            },
            DepthConvention::ZERO_TO_ONE,
        )
        .unwrap();
        Frustum::from_camera(&c).unwrap()
    };
    let near_corner = cam(DVec3::new(10.0, 12.0, 10.0), DVec3::new(10.0, 0.0, 10.0001));
    let sky = cam(
        DVec3::new(32.0, 40.0, 32.0),
        DVec3::new(32.0, 80.0, 32.0001),
    );
    let n = 64 * 64;
    let mut coverage = ocean_wtb::scene::Coverage::everything(s.grid());
    let (mut p, mut q) = (vec![Vec3::splat(7.0); n], vec![Vec3::splat(7.0); n]);
    let ids: Vec<_> = s.box_ids().collect();
    for (step, view) in [
        None,
        Some(&near_corner),
        Some(&sky),
        Some(&sky),
        None,
        Some(&near_corner),
        None,
    ]
    .into_iter()
    .enumerate()
    {
        if step == 5 {
            let moved = spec(wind(
                6.0,
                DVec2::X,
                DVec2::new(40.0, 45.0),
                12.0,
                12.0,
                1,
                9,
            ));
            s.update_box(ids[2], moved).unwrap();
        }
        if step == 6 {
            s.remove_box(ids[0]).unwrap();
        }
        let t = 1.0 + step as f64;
        let f = s.frame(t, view).unwrap();
        f.evaluate_incremental(&mut coverage, &mut p, &mut q)
            .unwrap();
        let (mut fp, mut fq) = (vec![Vec3::ZERO; n], vec![Vec3::ZERO; n]);
        f.evaluate(&mut fp, &mut fq).unwrap();
        assert!(
            p == fp && q == fq,
            "frame {step} differs from a full evaluation"
        );
        if step == 3 {
            // Two frames in a row with every box culled: nothing is covered any more.
            assert_eq!(coverage.rect(), None);
        }
    }
}

#[test]
fn effects_that_would_make_heights_non_finite_are_refused() {
    use ocean_wtb::effects::{
        Beach, Irregular, MAX_EFFECT_HEIGHT, MAX_EFFECT_SPEED, MAX_EFFECT_WAVENUMBER, Noise,
    };
    let (grid, terrain) = sloping();
    let mut s = Scene::new(grid, terrain).unwrap();
    let noise = |amplitude| Effects {
        noise: Some(Noise { amplitude, seed: 1 }),
        ..Effects::default()
    };
    let irregular = |frequency, envelope_speed| Effects {
        irregular: Some(Irregular {
            scale: 0.5,
            frequency,
            envelope_wavenumber: 0.1,
            envelope_speed,
        }),
        ..Effects::default()
    };
    let beach = |run_up| Effects {
        beach: Some(Beach {
            max_depth_share: 0.5,
            run_up,
            run_up_depth: 2.0,
        }),
        ..Effects::default()
    };
    // A noise of 1e300 m once gave NaN heights behind success.
    for bad in [
        noise(1e300),
        noise(MAX_EFFECT_HEIGHT * 1.0001),
        irregular(1e300, 1.0),
        irregular(MAX_EFFECT_WAVENUMBER * 2.0, 1.0),
        irregular(1.0, -MAX_EFFECT_SPEED * 2.0),
        beach(1e300),
    ] {
        let e = s.set_effects(bad).unwrap_err();
        assert!(e.to_string().contains("is outside"), "{e}");
    }
    for good in [
        noise(MAX_EFFECT_HEIGHT),
        irregular(MAX_EFFECT_WAVENUMBER, MAX_EFFECT_SPEED),
        beach(MAX_EFFECT_HEIGHT),
    ] {
        s.set_effects(good).unwrap();
        s.add_box(spec(wind(
            10.0,
            DVec2::X,
            DVec2::new(5.0, 5.0),
            40.0,
            60.0,
            2,
            3,
        )))
        .unwrap();
        let (p, n) = evaluate(&mut s, 3.0);
        assert!(p.iter().chain(&n).all(|v| v.is_finite()), "{good:?}");
    }
}
