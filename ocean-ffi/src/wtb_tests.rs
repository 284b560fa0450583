use super::*;
use crate::boundary::enums::read_poked;
use crate::boundary::{OceanNext, check_flag};
use crate::waves::OceanDVec2;
use crate::wtb_params::*;
use glam::DVec2;
use ocean_core::WaveError;
use ocean_core::camera::DepthConvention;
use ocean_wtb::WtbError;
use ocean_wtb::effects::Effects;
use ocean_wtb::scenarios;

use crate::status::last_error;
use crate::wtb_query::{
    OceanDrawnSample, OceanHeightSample, ocean_wtb_scene_heights_continuous,
    ocean_wtb_scene_heights_drawn,
};

const GRID: OceanWaterGridDesc = OceanWaterGridDesc {
    origin_x: 0.0,
    origin_z: 0.0,
    spacing: 1.0,
    nx: 64,
    nz: 64,
};

/// The default box is one a scene takes, with the wind and edges its documentation states.
#[test]
fn the_default_box_is_valid_and_as_documented() {
    let mut desc = OceanBoxDesc::default();
    // SAFETY: valid pointer.
    let st = unsafe { ocean_wtb_box_desc_default(&mut desc) };
    assert_eq!(st, OceanStatus::Ok);
    let mut wind = OceanWindDesc::default();
    // SAFETY: valid pointer.
    let st = unsafe { ocean_wtb_wind_desc_default(&mut wind) };
    assert_eq!(st, OceanStatus::Ok);
    assert_eq!(desc.wind, wind);
    assert_eq!((wind.speed, wind.width, wind.fetch), (10.0, 100.0, 200.0));
    assert_eq!((desc.smoothing, desc.has_recovery), (10.0, 0));

    let mut s = core::ptr::null_mut();
    // SAFETY: valid pointers, an open sea.
    let st = unsafe { ocean_wtb_scene_create(&GRID, core::ptr::null(), 0, &mut s) };
    assert_eq!(st, OceanStatus::Ok, "{}", last_error());
    let mut id = 0;
    // SAFETY: live scene, valid pointers.
    let st = unsafe { ocean_wtb_scene_add_box(s, &desc, core::ptr::null(), 0, &mut id) };
    assert_eq!(st, OceanStatus::Ok, "{}", last_error());
    ocean_wtb_scene_destroy(s);
}

/// The wind of `scenarios::steady_wind` in the C layout.
fn wind(speed: f64, dir: (f64, f64), origin: (f64, f64), width: f64, fetch: f64) -> OceanWindDesc {
    OceanWindDesc {
        next: OceanNext::NULL,
        speed,
        direction_x: dir.0,
        direction_z: dir.1,
        origin_x: origin.0,
        origin_z: origin.1,
        width,
        fetch,
        start: -1.0,
        build_up: 0.0,
        sustain: f64::INFINITY,
        decay: 0.0,
        seed: 0,
        trains: 1,
        reserved: 0,
    }
}

/// Scenario 1 of `ocean_wtb::scenarios` built through the C ABI.
fn scenario_1() -> *mut OceanWtbScene {
    let (grid, terrain) = scenarios::sloping(64).unwrap();
    let heights = terrain.heights().unwrap().to_vec();
    assert_eq!(grid.len(), heights.len());
    let mut s = core::ptr::null_mut();
    // SAFETY: valid pointers and lengths.
    let st = unsafe { ocean_wtb_scene_create(&GRID, heights.as_ptr(), heights.len(), &mut s) };
    assert_eq!(st, OceanStatus::Ok, "{}", last_error());
    let mut e = OceanEffects::default();
    // SAFETY: valid pointer.
    let st = unsafe { ocean_wtb_effects_default(&mut e) };
    assert_eq!(st, OceanStatus::Ok);
    e.shoaling = 0;
    // SAFETY: live scene, valid pointer.
    let st = unsafe { ocean_wtb_scene_set_effects(s, &e) };
    assert_eq!(st, OceanStatus::Ok);
    for (w, trains, seed) in [
        (wind(7.0, (1.0, 0.15), (-2.0, -4.0), 66.0, 70.0), 1, 11),
        (wind(5.0, (0.7, 1.0), (30.0, -30.0), 60.0, 90.0), 2, 12),
    ] {
        let desc = OceanBoxDesc {
            next: OceanNext::NULL,
            wind: OceanWindDesc { trains, seed, ..w },
            smoothing: 4.0,
            has_recovery: 0,
            reserved: 0,
            recovery: 0.0,
        };
        let mut id = u32::MAX;
        // SAFETY: live scene, valid pointers, no explicit trains.
        let st = unsafe { ocean_wtb_scene_add_box(s, &desc, core::ptr::null(), 0, &mut id) };
        assert_eq!(st, OceanStatus::Ok, "{}", last_error());
    }
    s
}

/// The wrapper adds nothing to the arithmetic: grid and height queries equal
/// `ocean_wtb::scenarios::scenario_1` evaluated directly, bit for bit.
#[test]
fn matches_the_rust_scene_bit_for_bit() {
    let s = scenario_1();
    let mut direct = scenarios::scenario_1(64).unwrap();
    for t in [0.0, 3.25, 1.0e6] {
        let n = 64 * 64;
        let mut pos = vec![OceanVec3::default(); n];
        let mut nrm = pos.clone();
        let mut stats = OceanFrameStats::default();
        // SAFETY: n elements in each buffer.
        let st = unsafe {
            ocean_wtb_scene_evaluate(
                s,
                t,
                core::ptr::null(),
                pos.as_mut_ptr(),
                nrm.as_mut_ptr(),
                n,
                &mut stats,
            )
        };
        assert_eq!(st, OceanStatus::Ok, "{}", last_error());
        let frame = direct.frame(t, None).unwrap();
        let mut cp = vec![Vec3::ZERO; n];
        let mut cn = cp.clone();
        frame.evaluate(&mut cp, &mut cn).unwrap();
        let bits = |v: &[OceanVec3]| -> Vec<u32> {
            v.iter()
                .flat_map(|p| [p.x.to_bits(), p.y.to_bits(), p.z.to_bits()])
                .collect()
        };
        let cbits = |v: &[Vec3]| -> Vec<u32> {
            v.iter()
                .flat_map(|p| p.to_array().map(f32::to_bits))
                .collect()
        };
        assert_eq!(bits(&pos), cbits(&cp));
        assert_eq!(bits(&nrm), cbits(&cn));
        assert_eq!((stats.alive, stats.culled, stats.trains), (2, 0, 3));
        assert!(pos.iter().any(|p| p.y.abs() > 0.05), "no waves at t = {t}");

        let xz = [
            OceanDVec2 { x: 10.3, z: 20.7 },
            OceanDVec2 { x: 50.0, z: 5.5 },
        ];
        let mut out = [OceanHeightSample::default(); 2];
        // SAFETY: two elements each.
        let st =
            unsafe { ocean_wtb_scene_heights_continuous(s, t, xz.as_ptr(), 2, out.as_mut_ptr()) };
        assert_eq!(st, OceanStatus::Ok, "{}", last_error());
        for (q, o) in xz.iter().zip(&out) {
            let h = frame.continuous_height_at(DVec2::new(q.x, q.z)).unwrap();
            assert_eq!(o.height.to_bits(), h.height.to_bits());
            assert_eq!([o.rest.x, o.rest.z], h.rest.to_array());
            assert_eq!([o.normal.x, o.normal.y, o.normal.z], h.normal.to_array());
        }
    }
    ocean_wtb_scene_destroy(s);
}

/// Drawn queries answer for the last evaluation, culling included, and refuse a scene
/// never evaluated or changed since; the answers are the Rust frame's, bit for bit.
#[test]
fn drawn_queries_need_an_evaluated_frame() {
    let s = scenario_1();
    let xz = [
        OceanDVec2 { x: 10.3, z: 20.7 },
        OceanDVec2 { x: -30.0, z: 5.5 },
    ];
    let marker = OceanDrawnSample {
        height: 7.0,
        ..OceanDrawnSample::default()
    };
    let mut out = [marker; 2];
    // SAFETY: live scene, two elements each.
    let query = |out: &mut [OceanDrawnSample; 2]| unsafe {
        ocean_wtb_scene_heights_drawn(s, xz.as_ptr(), 2, out.as_mut_ptr())
    };
    assert_eq!(query(&mut out), OceanStatus::NotEvaluated);
    assert!(
        last_error().contains("not been evaluated"),
        "{}",
        last_error()
    );
    assert_eq!(out, [marker; 2], "nothing written");
    let n = 64 * 64;
    let (mut pos, mut nrm) = (vec![OceanVec3::default(); n], vec![OceanVec3::default(); n]);
    // A view that sees no box: both are culled, and the drawn grid is at rest.
    let away = ocean_core::Camera::look_at(
        glam::DVec3::new(0.0, 10.0, -50.0),
        glam::DVec3::new(0.0, 10.0, -100.0),
        glam::DVec3::Y,
        ocean_core::Projection::Perspective {
            fov_y: 1.0,
            aspect: 1.0,
            near: 0.5,
            far: ocean_core::Far::Finite(100.0),
        },
        DepthConvention::ZERO_TO_ONE,
    )
    .unwrap();
    let away = crate::camera::OceanCamera::from_camera(&away);
    let mut evaluate = |camera: Option<&crate::camera::OceanCamera>| {
        // SAFETY: n elements in each buffer, a camera or NULL.
        let st = unsafe {
            ocean_wtb_scene_evaluate(
                s,
                4.5,
                camera.map_or(core::ptr::null(), |c| c as *const _),
                pos.as_mut_ptr(),
                nrm.as_mut_ptr(),
                n,
                core::ptr::null_mut(),
            )
        };
        assert_eq!(st, OceanStatus::Ok, "{}", last_error());
    };
    evaluate(None);
    assert_eq!(query(&mut out), OceanStatus::Ok, "{}", last_error());
    let mut direct = scenarios::scenario_1(64).unwrap();
    let frame = direct.frame(4.5, None).unwrap();
    let want = frame.drawn_height_at(DVec2::new(10.3, 20.7)).unwrap();
    assert_eq!(out[0], OceanDrawnSample::from(&want));
    assert!(out[0].covered == 1 && out[0].height != 0.0);
    assert_eq!(
        (out[1].covered, out[1].height),
        (0, 0.0),
        "off the grid: at rest"
    );
    evaluate(Some(&away));
    assert_eq!(query(&mut out), OceanStatus::Ok, "{}", last_error());
    assert_eq!(
        (out[0].covered, out[0].height),
        (1, 0.0),
        "culled: drawn at rest"
    );
    // Any change of the description needs a new evaluation.
    let st = ocean_wtb_scene_set_budget_unlimited(s);
    assert_eq!(st, OceanStatus::Ok);
    assert_eq!(query(&mut out), OceanStatus::NotEvaluated);
    assert!(last_error().contains("changed"), "{}", last_error());
    ocean_wtb_scene_destroy(s);
}

/// Misaligned pointers are refused before any access, and nothing is written.
#[test]
fn incremental_evaluation_matches_full_evaluation() {
    // Kept buffers updated by ocean_wtb_scene_evaluate_incremental must equal what
    // ocean_wtb_scene_evaluate writes, frame after frame, while culling switches every box off
    // (a view of the sky, column-major like GLM) and on again.
    let s = scenario_1();
    let n = 64 * 64;
    let sky = {
        let view = ocean_core::camera::look_at(
            glam::DVec3::new(32.0, 40.0, 32.0),
            glam::DVec3::new(32.0, 80.0, 32.0001),
            glam::DVec3::Z,
        )
        .unwrap();
        let proj = ocean_core::camera::Projection::Perspective {
            fov_y: 1.2,
            aspect: 1.0,
            near: 0.1,
            far: ocean_core::camera::Far::Finite(500.0),
        };
        OceanCamera::from_camera(
            &ocean_core::Camera::new(view, proj, DepthConvention::ZERO_TO_ONE).unwrap(),
        )
    };
    let mut kept = (vec![OceanVec3::default(); n], vec![OceanVec3::default(); n]);
    for (step, culled) in [false, true, true, false, true, false]
        .into_iter()
        .enumerate()
    {
        let vp: *const OceanCamera = if culled { &sky } else { core::ptr::null() };
        let t = 1.0 + step as f64;
        let mut full = (vec![OceanVec3::default(); n], vec![OceanVec3::default(); n]);
        let mut stats = OceanFrameStats::default();
        // SAFETY: live scene; buffers of n elements; 16 floats or NULL; stats writable.
        let (a, b) = unsafe {
            (
                ocean_wtb_scene_evaluate_incremental(
                    s,
                    t,
                    vp,
                    kept.0.as_mut_ptr(),
                    kept.1.as_mut_ptr(),
                    n,
                    &mut stats,
                ),
                ocean_wtb_scene_evaluate(
                    s,
                    t,
                    vp,
                    full.0.as_mut_ptr(),
                    full.1.as_mut_ptr(),
                    n,
                    core::ptr::null_mut(),
                ),
            )
        };
        assert_eq!(
            (a, b),
            (OceanStatus::Ok, OceanStatus::Ok),
            "{}",
            last_error()
        );
        assert_eq!(stats.culled, if culled { 2 } else { 0 });
        assert!(kept == full, "frame {step} differs");
    }
    // After a reset the next incremental call rewrites everything, even over garbage.
    kept.0.fill(OceanVec3 {
        x: 9.0,
        y: 9.0,
        z: 9.0,
    });
    assert_eq!(ocean_wtb_scene_reset_coverage(s), OceanStatus::Ok);
    let mut full = (vec![OceanVec3::default(); n], vec![OceanVec3::default(); n]);
    // SAFETY: as above.
    unsafe {
        ocean_wtb_scene_evaluate_incremental(
            s,
            9.0,
            &sky,
            kept.0.as_mut_ptr(),
            kept.1.as_mut_ptr(),
            n,
            core::ptr::null_mut(),
        );
        ocean_wtb_scene_evaluate(
            s,
            9.0,
            &sky,
            full.0.as_mut_ptr(),
            full.1.as_mut_ptr(),
            n,
            core::ptr::null_mut(),
        );
    }
    assert!(kept == full);
    let st = ocean_wtb_scene_reset_coverage(core::ptr::null_mut());
    assert_eq!(st, OceanStatus::NullPointer);
    ocean_wtb_scene_destroy(s);
}

#[test]
fn misaligned_pointers_are_refused() {
    let s = scenario_1();
    let mut storage = [0u64; 64];
    let base = storage.as_mut_ptr().cast::<u8>();
    let bad_vec3 = base.wrapping_add(1).cast::<OceanVec3>();
    let good = base.wrapping_add(256).cast::<OceanVec3>();
    // SAFETY: refused before any access.
    let st = unsafe {
        ocean_wtb_scene_evaluate(
            s,
            0.0,
            core::ptr::null(),
            bad_vec3,
            good,
            4096,
            core::ptr::null_mut(),
        )
    };
    assert_eq!(st, OceanStatus::MisalignedPointer);
    assert!(last_error().contains("out_pos"), "{}", last_error());
    let bad_stats = base.wrapping_add(4).cast::<OceanFrameStats>();
    let mut pos = vec![OceanVec3::default(); 4096];
    let mut nrm = pos.clone();
    // SAFETY: refused before any access.
    let st = unsafe {
        ocean_wtb_scene_evaluate(
            s,
            0.0,
            core::ptr::null(),
            pos.as_mut_ptr(),
            nrm.as_mut_ptr(),
            4096,
            bad_stats,
        )
    };
    assert_eq!(st, OceanStatus::MisalignedPointer);
    assert!(pos.iter().chain(&nrm).all(|p| *p == OceanVec3::default()));
    let bad_xz = base.wrapping_add(4).cast::<OceanDVec2>().cast_const();
    let mut out = [OceanHeightSample::default(); 1];
    // SAFETY: refused before any access.
    let st = unsafe { ocean_wtb_scene_heights_continuous(s, 0.0, bad_xz, 1, out.as_mut_ptr()) };
    assert_eq!(st, OceanStatus::MisalignedPointer);
    let bad_scene = base.wrapping_add(4).cast::<OceanWtbScene>();
    let st = ocean_wtb_scene_remove_box(bad_scene, 0);
    // A handle is an id, never an address: a pointer into the caller's memory is not one.
    assert_eq!(st, OceanStatus::InvalidHandle);
    assert!(
        storage.iter().all(|&v| v == 0),
        "a refused call wrote memory"
    );
    ocean_wtb_scene_destroy(bad_scene);
    ocean_wtb_scene_destroy(s);
}

/// Error statuses of the mapping that the C test cannot reach by a single bad member.
#[test]
fn error_mapping() {
    let e = wtb_error("x: ", WtbError::UnknownBox(3));
    assert_eq!(e.status, OceanStatus::NotFound);
    let e = wtb_error("", WtbError::OutsideGrid);
    assert_eq!(e.status, OceanStatus::OutsideGrid);
    let e = wtb_error("", WtbError::TerrainNotFinite { index: 7 });
    assert_eq!(e.status, OceanStatus::NonFinite);
    let e = trains_error(WtbError::TooSteep {
        total: 1.2,
        max: 1.0,
    });
    assert_eq!(e.status, OceanStatus::TooSteep);
    let e = trains_error(WtbError::Wave {
        index: 2,
        source: WaveError::TooSteep(1.5),
    });
    assert_eq!(
        (e.status, e.message.starts_with("trains[2]")),
        (OceanStatus::TooSteep, true)
    );
    // Flags and enums accept exactly their documented values.
    assert!(
        check_flag("f", 2).is_err() && check_flag("f", 1).unwrap() && !check_flag("f", 0).unwrap()
    );
    let at = core::mem::offset_of!(OceanEffects, refraction);
    let e = read_poked(&OceanEffects::default(), "effects", at, 3).unwrap_err();
    assert_eq!(
        e.message,
        "effects->refraction = 3 is not an OceanRefraction (0, 1 or 2)"
    );
    // The defaults round-trip through the C layout.
    let d = effects_to(&Effects::default());
    assert_eq!(effects_from(&d, "e").unwrap(), Effects::default());
}
