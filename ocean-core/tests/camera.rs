//! Camera and projection tests. Every expected value is stated with the reason it is expected.

use std::f64::consts::PI;

use glam::{DMat4, DVec3, DVec4, Mat4, Vec3};
use ocean_core::camera::{
    Camera, CameraError, DepthConvention, DepthDirection, DepthRange, Far, Projection, look_at,
    look_to,
};

const FOV: f64 = PI / 3.0; // 60°
const ASPECT: f64 = 16.0 / 9.0;
const NEAR: f64 = 0.1;
const FAR: f64 = 100.0;

fn perspective(far: Far) -> Projection {
    Projection::Perspective {
        fov_y: FOV,
        aspect: ASPECT,
        near: NEAR,
        far,
    }
}

fn ortho() -> Projection {
    Projection::Orthographic {
        left: -10.0,
        right: 6.0,
        bottom: -5.0,
        top: 3.0,
        near: -2.0,
        far: 50.0,
    }
}

/// The three valid conventions with the NDC depth they must give at the near and far planes,
/// written out here (not taken from the library) because they are the definition:
/// forward [0,1]: near 0, far 1; reversed [0,1]: near 1, far 0; forward [-1,1]: near -1, far 1.
const CONVENTIONS: [(DepthConvention, f64, f64); 3] = [
    (DepthConvention::ZERO_TO_ONE, 0.0, 1.0),
    (DepthConvention::ZERO_TO_ONE_REVERSED, 1.0, 0.0),
    (DepthConvention::NEG_ONE_TO_ONE, -1.0, 1.0),
];

fn to_ndc(m: DMat4, p: DVec3) -> DVec3 {
    let c = m * p.extend(1.0);
    assert!(c.w > 0.0, "point {p} is behind the camera (w = {})", c.w);
    c.truncate() / c.w
}

fn assert_close(got: f64, want: f64, tol: f64, what: &str) {
    assert!(
        (got - want).abs() <= tol,
        "{what}: got {got}, want {want} (tolerance {tol})"
    );
}

/// Elementwise comparison with a tolerance relative to the larger of the two elements (and at
/// least `tol` absolute).
fn assert_mat_close(got: &[f64; 16], want: &[f64; 16], tol: f64, what: &str) {
    for i in 0..16 {
        let scale = got[i].abs().max(want[i].abs()).max(1.0);
        assert!(
            (got[i] - want[i]).abs() <= tol * scale,
            "{what}: element {i} (column {}, row {}) is {}, want {}",
            i / 4,
            i % 4,
            got[i],
            want[i]
        );
    }
}

fn f32_cols(m: Mat4) -> [f64; 16] {
    m.to_cols_array().map(f64::from)
}

#[test]
fn reversed_z_with_neg_one_to_one_is_rejected() {
    // Documented choice: reversed Z only helps in [0,1]; the pair is a configuration mistake.
    assert_eq!(
        DepthConvention::new(DepthRange::NegOneToOne, DepthDirection::Reversed),
        Err(CameraError::ReversedNegOneToOne)
    );
    assert_eq!(
        DepthConvention::new(DepthRange::ZeroToOne, DepthDirection::Reversed),
        Ok(DepthConvention::ZERO_TO_ONE_REVERSED)
    );
    assert_eq!(
        DepthConvention::new(DepthRange::NegOneToOne, DepthDirection::Forward),
        Ok(DepthConvention::NEG_ONE_TO_ONE)
    );
}

#[test]
fn perspective_finite_near_far_and_edges_in_every_convention() {
    for (conv, near_ndc, far_ndc) in CONVENTIONS {
        let m = perspective(Far::Finite(FAR)).matrix_f64(conv).unwrap();
        // On the axis at the near and far planes: the ends of the depth range.
        assert_close(
            to_ndc(m, DVec3::new(0.0, 0.0, -NEAR)).z,
            near_ndc,
            1e-12,
            "near",
        );
        assert_close(
            to_ndc(m, DVec3::new(0.0, 0.0, -FAR)).z,
            far_ndc,
            1e-12,
            "far",
        );
        // At distance d the frustum's half height is d·tan(fov/2) and half width aspect times
        // that: those points are on the edges, NDC ±1.
        for d in [NEAR, 1.0, 37.0, FAR] {
            let hh = d * (FOV / 2.0).tan();
            let hw = hh * ASPECT;
            for (p, want) in [
                (DVec3::new(hw, 0.0, -d), DVec3::new(1.0, 0.0, f64::NAN)),
                (DVec3::new(-hw, 0.0, -d), DVec3::new(-1.0, 0.0, f64::NAN)),
                (DVec3::new(0.0, hh, -d), DVec3::new(0.0, 1.0, f64::NAN)),
                (DVec3::new(-hw, -hh, -d), DVec3::new(-1.0, -1.0, f64::NAN)),
            ] {
                let ndc = to_ndc(m, p);
                assert_close(ndc.x, want.x, 1e-12, "edge x");
                assert_close(ndc.y, want.y, 1e-12, "edge y");
            }
        }
        // Between the planes the depth is the closed form z_n + (z_f - z_n)·f(d - n)/(d(f - n))
        // (hyperbolic in d), e.g. at d = 1: f(d-n)/(d(f-n)) = 100·0.9/99.9.
        let t = FAR * (1.0 - NEAR) / (1.0 * (FAR - NEAR));
        assert_close(
            to_ndc(m, DVec3::new(0.0, 0.0, -1.0)).z,
            near_ndc + (far_ndc - near_ndc) * t,
            1e-12,
            "depth at d = 1",
        );
        // Depth is monotonic in distance: increasing for forward Z, decreasing for reversed.
        let mut prev = near_ndc;
        for i in 1..=100 {
            let d = NEAR + (FAR - NEAR) * i as f64 / 100.0;
            let z = to_ndc(m, DVec3::new(0.0, 0.0, -d)).z;
            assert!(
                (z - prev) * (far_ndc - near_ndc) > 0.0,
                "not monotonic at d = {d}"
            );
            prev = z;
        }
    }
}

#[test]
fn perspective_infinite_near_and_limit_in_every_convention() {
    for (conv, near_ndc, far_ndc) in CONVENTIONS {
        let proj = perspective(Far::Infinite);
        let m = proj.matrix_f64(conv).unwrap();
        assert_close(
            to_ndc(m, DVec3::new(0.0, 0.0, -NEAR)).z,
            near_ndc,
            1e-12,
            "near",
        );
        // With f → ∞ the depth is z_f + (z_n - z_f)·n/d: the distance to the limit shrinks as
        // n/d, so at d = 1e3, 1e6, 1e9 it is 1e-4, 1e-7, 1e-10 times |z_n - z_f|.
        for d in [1e3, 1e6, 1e9] {
            let z = to_ndc(m, DVec3::new(0.0, 0.0, -d)).z;
            let want = far_ndc + (near_ndc - far_ndc) * NEAR / d;
            assert_close(z, want, 1e-15, "infinite depth");
            assert!(
                (z - far_ndc).abs() <= 2.0 * NEAR / d + 1e-15,
                "not approaching the limit"
            );
        }
        // The closed-form helper gives the limit itself at -∞.
        assert_eq!(proj.ndc_depth(conv, f64::NEG_INFINITY), Ok(far_ndc));
        // x, y edges are the same as for a finite far plane.
        let hh = 500.0 * (FOV / 2.0).tan();
        let ndc = to_ndc(m, DVec3::new(hh * ASPECT, -hh, -500.0));
        assert_close(ndc.x, 1.0, 1e-12, "edge x");
        assert_close(ndc.y, -1.0, 1e-12, "edge y");
    }
}

#[test]
fn orthographic_box_in_every_convention() {
    // The box left -10, right 6, bottom -5, top 3, near -2 (behind the eye: allowed for
    // orthographic), far 50.
    for (conv, near_ndc, far_ndc) in CONVENTIONS {
        let m = ortho().matrix_f64(conv).unwrap();
        assert_eq!(m.row(3), DVec4::new(0.0, 0.0, 0.0, 1.0), "w must stay 1");
        // Corners of the box map to the corners of the NDC cube.
        let lbn = to_ndc(m, DVec3::new(-10.0, -5.0, 2.0));
        let rtf = to_ndc(m, DVec3::new(6.0, 3.0, -50.0));
        assert_close(lbn.x, -1.0, 1e-15, "left");
        assert_close(lbn.y, -1.0, 1e-15, "bottom");
        assert_close(lbn.z, near_ndc, 1e-15, "near");
        assert_close(rtf.x, 1.0, 1e-15, "right");
        assert_close(rtf.y, 1.0, 1e-15, "top");
        assert_close(rtf.z, far_ndc, 1e-15, "far");
        // The centre of the box maps to the middle of each range: depth is linear.
        let mid = to_ndc(m, DVec3::new(-2.0, -1.0, -24.0));
        assert_close(mid.x, 0.0, 1e-15, "centre x");
        assert_close(mid.y, 0.0, 1e-15, "centre y");
        assert_close(mid.z, 0.5 * (near_ndc + far_ndc), 1e-15, "centre depth");
    }
}

#[test]
fn matches_glam_where_glam_has_an_equivalent() {
    use glam::camera::rh::proj::{directx, opengl};
    use glam::dcamera::rh::proj::{directx as ddirectx, opengl as dopengl};
    let (fov, aspect, near, far) = (FOV as f32, ASPECT as f32, NEAR as f32, FAR as f32);
    let z01 = DepthConvention::ZERO_TO_ONE;
    let gl = DepthConvention::NEG_ONE_TO_ONE;
    let rev = DepthConvention::ZERO_TO_ONE_REVERSED;
    let p_fin = perspective(Far::Finite(FAR));
    let p_inf = perspective(Far::Infinite);
    let o = ortho();
    // f32: ours is the f64 matrix rounded once, glam's is computed in f32: a few ulps apart, well
    // within 1e-6 relative.
    let f32_cases: [(Mat4, Mat4, &str); 6] = [
        (
            p_fin.matrix(z01).unwrap(),
            directx::perspective(fov, aspect, near, far),
            "perspective_rh",
        ),
        (
            p_inf.matrix(z01).unwrap(),
            directx::perspective_infinite(fov, aspect, near),
            "perspective_infinite_rh",
        ),
        (
            p_inf.matrix(rev).unwrap(),
            directx::perspective_infinite_reverse(fov, aspect, near),
            "perspective_infinite_reverse_rh",
        ),
        (
            p_fin.matrix(gl).unwrap(),
            opengl::perspective(fov, aspect, near, far),
            "perspective_rh_gl",
        ),
        (
            o.matrix(z01).unwrap(),
            directx::orthographic(-10.0, 6.0, -5.0, 3.0, -2.0, 50.0),
            "orthographic_rh",
        ),
        (
            o.matrix(gl).unwrap(),
            opengl::orthographic(-10.0, 6.0, -5.0, 3.0, -2.0, 50.0),
            "orthographic_rh_gl",
        ),
    ];
    for (ours, glam, what) in f32_cases {
        assert_mat_close(&f32_cols(ours), &f32_cols(glam), 1e-6, what);
    }
    // f64: the same formulas in the same precision, so within a few ulps (1e-14 relative).
    let f64_cases: [(DMat4, DMat4, &str); 6] = [
        (
            p_fin.matrix_f64(z01).unwrap(),
            ddirectx::perspective(FOV, ASPECT, NEAR, FAR),
            "dperspective_rh",
        ),
        (
            p_inf.matrix_f64(z01).unwrap(),
            ddirectx::perspective_infinite(FOV, ASPECT, NEAR),
            "dperspective_infinite_rh",
        ),
        (
            p_inf.matrix_f64(rev).unwrap(),
            ddirectx::perspective_infinite_reverse(FOV, ASPECT, NEAR),
            "dperspective_infinite_reverse_rh",
        ),
        (
            p_fin.matrix_f64(gl).unwrap(),
            dopengl::perspective(FOV, ASPECT, NEAR, FAR),
            "dperspective_rh_gl",
        ),
        (
            o.matrix_f64(z01).unwrap(),
            ddirectx::orthographic(-10.0, 6.0, -5.0, 3.0, -2.0, 50.0),
            "dorthographic_rh",
        ),
        (
            o.matrix_f64(gl).unwrap(),
            dopengl::orthographic(-10.0, 6.0, -5.0, 3.0, -2.0, 50.0),
            "dorthographic_rh_gl",
        ),
    ];
    for (ours, glam, what) in f64_cases {
        assert_mat_close(&ours.to_cols_array(), &glam.to_cols_array(), 1e-14, what);
    }
}

#[test]
fn reversed_finite_and_reversed_ortho_are_the_forward_depth_flipped() {
    // glam has no finite reversed-Z or reversed orthographic matrix. Reversed [0,1] depth must be
    // 1 - (forward [0,1] depth) at every distance, because both are the unique depth functions of
    // their family through (near, z_n) and (far, z_f).
    for proj in [
        perspective(Far::Finite(FAR)),
        perspective(Far::Infinite),
        ortho(),
    ] {
        let fwd = proj.matrix_f64(DepthConvention::ZERO_TO_ONE).unwrap();
        let rev = proj
            .matrix_f64(DepthConvention::ZERO_TO_ONE_REVERSED)
            .unwrap();
        for d in [0.1, 0.5, 3.0, 17.0, 49.0] {
            let p = DVec3::new(0.3, -0.2, -d);
            let zf = to_ndc(fwd, p).z;
            let zr = to_ndc(rev, p).z;
            assert_close(zr, 1.0 - zf, 1e-12, "reversed = 1 - forward");
            // x and y do not depend on the depth convention.
            assert_eq!(to_ndc(fwd, p).truncate(), to_ndc(rev, p).truncate());
        }
    }
}

#[test]
fn ndc_depth_and_view_z_agree_with_the_matrix_and_invert_each_other() {
    for proj in [
        perspective(Far::Finite(FAR)),
        perspective(Far::Infinite),
        ortho(),
    ] {
        for (conv, _, _) in CONVENTIONS {
            let m = proj.matrix_f64(conv).unwrap();
            for d in [0.1, 0.25, 1.0, 10.0, 42.0, 99.0] {
                let z_view = -d;
                let by_matrix = to_ndc(m, DVec3::new(0.0, 0.0, z_view)).z;
                let closed = proj.ndc_depth(conv, z_view).unwrap();
                assert_close(closed, by_matrix, 1e-13, "ndc_depth vs matrix");
                let back = proj.view_z(conv, closed).unwrap();
                assert_close(back, z_view, 1e-9 * d, "view_z(ndc_depth(z)) = z");
            }
        }
    }
    // The far end of an infinite projection has no finite view z.
    let inf = perspective(Far::Infinite);
    assert_eq!(
        inf.view_z(DepthConvention::ZERO_TO_ONE, 1.0),
        Err(CameraError::AtInfinity)
    );
    assert_eq!(
        inf.view_z(DepthConvention::ZERO_TO_ONE_REVERSED, 0.0),
        Err(CameraError::AtInfinity)
    );
    // Perspective depth is undefined on the camera plane.
    assert_eq!(
        inf.ndc_depth(DepthConvention::ZERO_TO_ONE, 0.0),
        Err(CameraError::OnCameraPlane)
    );
}

#[test]
fn look_at_maps_eye_target_and_up_as_documented() {
    let eye = DVec3::new(3.0, 2.0, 5.0);
    let target = DVec3::new(10.0, 1.0, -20.0);
    let v = look_at(eye, target, DVec3::Y).unwrap();
    // The eye goes to the origin of view space.
    assert!(v.transform_point3(eye).length() < 1e-12);
    // The target is straight ahead: on the -z axis at its distance.
    let dist = (target - eye).length();
    let t = v.transform_point3(target);
    assert!(
        (t - DVec3::new(0.0, 0.0, -dist)).length() < 1e-12,
        "target -> {t}"
    );
    // A point straight above the eye (world up) has view y > 0 and x = 0, since the view's
    // right axis is horizontal (perpendicular to world up).
    let above = v.transform_point3(eye + DVec3::Y);
    assert!(above.y > 0.0 && above.x.abs() < 1e-12, "above -> {above}");
    // The rotation is orthonormal (rigid view): R·Rᵀ = I.
    let r = glam::DMat3::from_mat4(v);
    assert!((r * r.transpose()).abs_diff_eq(glam::DMat3::IDENTITY, 1e-14));
    // look_to with the direction gives the same matrix.
    assert_eq!(look_to(eye, target - eye, DVec3::Y).unwrap(), v);
    // And it matches glam's right-handed look-at (f32 within 1e-6, f64 within 1e-14).
    let glam32 = glam::camera::rh::view::look_at_mat4(eye.as_vec3(), target.as_vec3(), Vec3::Y);
    assert_mat_close(
        &f32_cols(v.as_mat4()),
        &f32_cols(glam32),
        1e-6,
        "look_at_rh",
    );
    let glam64 = glam::dcamera::rh::view::look_at_mat4(eye, target, DVec3::Y);
    assert_mat_close(
        &v.to_cols_array(),
        &glam64.to_cols_array(),
        1e-14,
        "dlook_at_rh",
    );
}

#[test]
fn camera_round_trips_world_to_ndc_and_back() {
    let eye = DVec3::new(100.0, 20.0, -300.0);
    let target = DVec3::new(120.0, 0.0, -350.0);
    for proj in [
        perspective(Far::Finite(FAR)),
        perspective(Far::Infinite),
        ortho(),
    ] {
        for (conv, _, far_ndc) in CONVENTIONS {
            let cam = Camera::look_at(eye, target, DVec3::Y, proj, conv).unwrap();
            assert!((cam.eye() - eye).length() < 1e-10);
            for p in [
                target,
                DVec3::new(110.0, 15.0, -320.0),
                DVec3::new(101.0, 19.0, -302.0),
            ] {
                let ndc = cam.world_to_ndc(p).expect("in front of the camera");
                let back = cam.ndc_to_world(ndc).unwrap();
                assert!((back - p).length() < 1e-9, "{p} -> {ndc} -> {back}");
            }
            // The f32 matrix is the f64 one rounded.
            assert_eq!(
                cam.view_projection().unwrap(),
                cam.view_projection_f64().as_mat4()
            );
            if matches!(
                proj,
                Projection::Perspective {
                    far: Far::Infinite,
                    ..
                }
            ) {
                // The far limit of an infinite projection is at infinity.
                assert_eq!(
                    cam.ndc_to_world(DVec3::new(0.0, 0.0, far_ndc)),
                    Err(CameraError::AtInfinity)
                );
            }
            if matches!(proj, Projection::Perspective { .. }) {
                // A point behind the eye has w < 0: no NDC.
                assert_eq!(cam.world_to_ndc(eye - (target - eye)), None);
            }
        }
    }
}

#[test]
fn invalid_parameters_are_errors() {
    let z01 = DepthConvention::ZERO_TO_ONE;
    let persp = |fov_y, aspect, near, far| Projection::Perspective {
        fov_y,
        aspect,
        near,
        far,
    };
    let f = Far::Finite(FAR);
    let cases: [(Projection, CameraError); 12] = [
        (
            persp(f64::NAN, 1.0, 0.1, f),
            CameraError::NotFinite {
                name: "fov_y",
                value: f64::NAN,
            },
        ),
        (persp(0.0, 1.0, 0.1, f), CameraError::FieldOfView(0.0)),
        (persp(PI, 1.0, 0.1, f), CameraError::FieldOfView(PI)),
        (persp(-1.0, 1.0, 0.1, f), CameraError::FieldOfView(-1.0)),
        (persp(1.0, 0.0, 0.1, f), CameraError::Aspect(0.0)),
        (persp(1.0, -2.0, 0.1, f), CameraError::Aspect(-2.0)),
        (persp(1.0, 1.0, 0.0, f), CameraError::Near(0.0)),
        (
            persp(1.0, 1.0, -1.0, Far::Infinite),
            CameraError::Near(-1.0),
        ),
        (
            persp(1.0, 1.0, 1.0, Far::Finite(1.0)),
            CameraError::FarNotBeyondNear {
                near: 1.0,
                far: 1.0,
            },
        ),
        (
            persp(1.0, 1.0, 1.0, Far::Finite(f64::INFINITY)),
            CameraError::NotFinite {
                name: "far",
                value: f64::INFINITY,
            },
        ),
        (
            Projection::Orthographic {
                left: 1.0,
                right: 1.0,
                bottom: 0.0,
                top: 1.0,
                near: 0.0,
                far: 1.0,
            },
            CameraError::OrthoWidth {
                left: 1.0,
                right: 1.0,
            },
        ),
        (
            Projection::Orthographic {
                left: 0.0,
                right: 1.0,
                bottom: 2.0,
                top: 1.0,
                near: 0.0,
                far: 1.0,
            },
            CameraError::OrthoHeight {
                bottom: 2.0,
                top: 1.0,
            },
        ),
    ];
    for (proj, want) in cases {
        let got = proj.matrix_f64(z01).unwrap_err();
        // NaN != NaN, so compare NotFinite by name.
        match (got, want) {
            (CameraError::NotFinite { name: a, .. }, CameraError::NotFinite { name: b, .. }) => {
                assert_eq!(a, b)
            }
            _ => assert_eq!(got, want, "{proj:?}"),
        }
        assert!(proj.matrix(z01).is_err());
    }
    // Ortho far <= near, and a width that overflows.
    let o = Projection::Orthographic {
        left: 0.0,
        right: 1.0,
        bottom: 0.0,
        top: 1.0,
        near: 5.0,
        far: 5.0,
    };
    assert_eq!(
        o.matrix_f64(z01),
        Err(CameraError::FarNotBeyondNear {
            near: 5.0,
            far: 5.0
        })
    );
    let huge = Projection::Orthographic {
        left: -f64::MAX,
        right: f64::MAX,
        bottom: 0.0,
        top: 1.0,
        near: 0.0,
        far: 1.0,
    };
    assert!(matches!(
        huge.matrix_f64(z01),
        Err(CameraError::NotFinite {
            name: "right - left",
            ..
        })
    ));
    // Valid in f64 but not in f32: cot(fov/2) ≈ 2e300 overflows f32.
    let tiny_fov = persp(1e-300, 1.0, 0.1, Far::Infinite);
    assert!(tiny_fov.matrix_f64(z01).is_ok());
    assert_eq!(
        tiny_fov.matrix(z01),
        Err(CameraError::NotRepresentableInF32)
    );

    // View errors.
    let e = DVec3::new(1.0, 2.0, 3.0);
    assert_eq!(look_at(e, e, DVec3::Y), Err(CameraError::EyeEqualsTarget));
    assert_eq!(
        look_at(e, e + DVec3::Y, DVec3::Y),
        Err(CameraError::UpParallelToView)
    );
    assert_eq!(
        look_at(e, e - DVec3::Y * 3.0, DVec3::Y),
        Err(CameraError::UpParallelToView)
    );
    assert_eq!(
        look_at(e, DVec3::ZERO, DVec3::ZERO),
        Err(CameraError::UpParallelToView)
    );
    assert!(matches!(
        look_at(DVec3::new(f64::NAN, 0.0, 0.0), DVec3::ZERO, DVec3::Y),
        Err(CameraError::NotFinite { name: "eye", .. })
    ));
    assert!(matches!(
        look_at(DVec3::splat(-f64::MAX), DVec3::splat(f64::MAX), DVec3::Y),
        Err(CameraError::NotFinite {
            name: "target - eye",
            ..
        })
    ));
    // A singular view matrix.
    assert_eq!(
        Camera::new(DMat4::ZERO, perspective(Far::Infinite), z01),
        Err(CameraError::Singular)
    );
    // Unprojecting NaN.
    let cam = Camera::new(DMat4::IDENTITY, ortho(), z01).unwrap();
    assert!(matches!(
        cam.ndc_to_world(DVec3::new(f64::NAN, 0.0, 0.0)),
        Err(CameraError::NotFinite { name: "ndc", .. })
    ));
}
