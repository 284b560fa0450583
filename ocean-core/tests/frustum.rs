//! Frustum extraction and culling tests, for every projection kind and depth convention.
//!
//! Shapes are built in view space (camera looking down -z), where "inside", "beyond the left
//! plane" and so on are obvious by construction, then moved to world space with the inverse of a
//! non-axis-aligned view matrix, so the planes under test are arbitrary world-space planes.

use std::f64::consts::PI;

use glam::{DMat4, DQuat, DVec3, Mat4};
use ocean_core::camera::{Camera, DepthConvention, DepthRange, Far, Projection};
use ocean_core::frustum::{Aabb, Containment, Frustum, FrustumError, Obb, PlaneId, Sphere};
use ocean_core::rng::Pcg32;

const FOV: f64 = PI / 3.0; // 60° vertical
const ASPECT: f64 = 16.0 / 9.0;
const NEAR: f64 = 0.1;
const FAR: f64 = 100.0;
const ORTHO_NEAR: f64 = 0.5;

const EYE: DVec3 = DVec3::new(3.0, 2.0, 5.0);
const TARGET: DVec3 = DVec3::new(10.0, 1.0, -20.0);

#[derive(Clone, Copy, Debug, PartialEq)]
enum Kind {
    Finite,
    Infinite,
    Ortho,
}

fn projection(kind: Kind) -> Projection {
    match kind {
        Kind::Finite | Kind::Infinite => Projection::Perspective {
            fov_y: FOV,
            aspect: ASPECT,
            near: NEAR,
            far: if kind == Kind::Finite {
                Far::Finite(FAR)
            } else {
                Far::Infinite
            },
        },
        Kind::Ortho => Projection::Orthographic {
            left: -10.0,
            right: 10.0,
            bottom: -5.0,
            top: 5.0,
            near: ORTHO_NEAR,
            far: FAR,
        },
    }
}

/// Every projection kind × every valid depth convention (reversed Z with [-1,1] is rejected by
/// `DepthConvention::new`, see the camera tests).
fn configs() -> Vec<(Kind, DepthConvention)> {
    let mut v = Vec::new();
    for kind in [Kind::Finite, Kind::Infinite, Kind::Ortho] {
        for conv in DepthConvention::ALL {
            v.push((kind, conv));
        }
    }
    v
}

fn near_of(kind: Kind) -> f64 {
    if kind == Kind::Ortho {
        ORTHO_NEAR
    } else {
        NEAR
    }
}

/// Half width and half height of the frustum cross-section at view distance `d`.
fn half_size(kind: Kind, d: f64) -> (f64, f64) {
    match kind {
        Kind::Ortho => (10.0, 5.0),
        _ => {
            let hh = d * (FOV / 2.0).tan();
            (hh * ASPECT, hh)
        }
    }
}

fn camera(kind: Kind, conv: DepthConvention) -> Camera {
    Camera::look_at(EYE, TARGET, DVec3::Y, projection(kind), conv).unwrap()
}

/// Whether a world point is inside the clip volume of `vp`, checked directly on clip coordinates:
/// -w <= x, y <= w and 0 <= z <= w or -w <= z <= w. `slack` widens the volume by slack·|w|.
fn clip_inside(vp: DMat4, conv: DepthConvention, p: DVec3, slack: f64) -> bool {
    let c = vp * p.extend(1.0);
    let e = slack * c.w.abs();
    let z_low = match conv.range() {
        DepthRange::ZeroToOne => 0.0,
        DepthRange::NegOneToOne => -c.w,
    };
    c.x >= -c.w - e
        && c.x <= c.w + e
        && c.y >= -c.w - e
        && c.y <= c.w + e
        && c.z >= z_low - e
        && c.z <= c.w + e
}

/// The test shapes around a view-space centre, moved to world space: a sphere of radius 0.5, a
/// world-axis-aligned cube of half size 0.5, and a cube of half size 0.5 rotated 0.7 rad about
/// (1, 1, 0.5) in view space. All fit in a ball of radius √3/2 ≈ 0.87 around the centre.
struct Shapes {
    point: DVec3,
    sphere: Sphere,
    aabb: Aabb,
    obb: Obb,
}

fn shapes(cam: &Camera, centre_view: DVec3) -> Shapes {
    let to_world = cam.view_f64().inverse();
    let c = to_world.transform_point3(centre_view);
    let rot = DQuat::from_axis_angle(DVec3::new(1.0, 1.0, 0.5).normalize(), 0.7);
    let axes = [DVec3::X, DVec3::Y, DVec3::Z].map(|a| to_world.transform_vector3(rot * a));
    Shapes {
        point: c,
        sphere: Sphere::new(c, 0.5).unwrap(),
        aabb: Aabb::new(c, DVec3::splat(0.5)).unwrap(),
        obb: Obb::new(c, axes, DVec3::splat(0.5)).unwrap(),
    }
}

fn check_all(f: &Frustum, s: &Shapes, want: Containment, with_point: bool, what: &str) {
    assert_eq!(f.test_sphere(&s.sphere), want, "sphere {what}");
    assert_eq!(f.test_aabb(&s.aabb), want, "aabb {what}");
    assert_eq!(f.test_obb(&s.obb), want, "obb {what}");
    assert_eq!(
        f.test_obb(&Obb::from_aabb(&s.aabb)),
        want,
        "aabb as obb {what}"
    );
    if with_point {
        assert_eq!(f.test_point(s.point).unwrap(), want, "point {what}");
    }
}

#[test]
fn shapes_inside_outside_and_straddling_every_plane_for_every_projection() {
    use Containment::{Inside, Intersecting, Outside};
    for (kind, conv) in configs() {
        let cam = camera(kind, conv);
        let f = Frustum::from_camera(&cam).unwrap();
        let what = |case: &str| format!("{case}, {kind:?} {conv:?}");
        let (hw, hh) = half_size(kind, 10.0);
        let near = near_of(kind);

        // 10 m ahead on the axis: the section there is at least 11.5 m × 5.8 m, the shapes fit in
        // a 0.87 m ball, near ≤ 0.5 m, far = 100 m: inside every plane.
        check_all(
            &f,
            &shapes(&cam, DVec3::new(0.0, 0.0, -10.0)),
            Inside,
            true,
            &what("ahead"),
        );

        // 3 m beyond each side plane at depth 10 (the planes move by at most 0.09 m per metre of
        // depth, so the 0.87 m ball stays at least 1.2 m beyond): outside that plane.
        for (c, case) in [
            (DVec3::new(-hw - 3.0, 0.0, -10.0), "left"),
            (DVec3::new(hw + 3.0, 0.0, -10.0), "right"),
            (DVec3::new(0.0, -hh - 3.0, -10.0), "bottom"),
            (DVec3::new(0.0, hh + 3.0, -10.0), "top"),
        ] {
            check_all(
                &f,
                &shapes(&cam, c),
                Outside,
                true,
                &what(&format!("beyond {case}")),
            );
        }

        // 5 m behind the eye: beyond the near plane (d ≥ 0.1 or 0.5) for every kind.
        check_all(
            &f,
            &shapes(&cam, DVec3::new(0.0, 0.0, 5.0)),
            Outside,
            true,
            &what("behind"),
        );
        // 1000 m behind: the same.
        check_all(
            &f,
            &shapes(&cam, DVec3::new(0.0, 0.0, 1000.0)),
            Outside,
            true,
            &what("far behind"),
        );

        // 5 m beyond the far plane (d = 105): outside, unless the far plane is infinite; then it
        // is inside, and so is a shape 10⁶ m away.
        let beyond_far = if kind == Kind::Infinite {
            Inside
        } else {
            Outside
        };
        check_all(
            &f,
            &shapes(&cam, DVec3::new(0.0, 0.0, -105.0)),
            beyond_far,
            true,
            &what("beyond far"),
        );
        if kind == Kind::Infinite {
            check_all(
                &f,
                &shapes(&cam, DVec3::new(0.0, 0.0, -1e6)),
                Inside,
                true,
                &what("1e6 m"),
            );
        }

        // Centred on each plane: part of every shape is on each side, so Intersecting. (The
        // centre point itself is on the plane up to rounding, so it is not checked.)
        for (c, case) in [
            (DVec3::new(-hw, 0.0, -10.0), "across left"),
            (DVec3::new(hw, 0.0, -10.0), "across right"),
            (DVec3::new(0.0, -hh, -10.0), "across bottom"),
            (DVec3::new(0.0, hh, -10.0), "across top"),
            (DVec3::new(0.0, 0.0, -near), "across near"),
        ] {
            check_all(&f, &shapes(&cam, c), Intersecting, false, &what(case));
        }
        let across_far = if kind == Kind::Infinite {
            Inside
        } else {
            Intersecting
        };
        check_all(
            &f,
            &shapes(&cam, DVec3::new(0.0, 0.0, -FAR)),
            across_far,
            false,
            &what("across far"),
        );
    }
}

#[test]
fn planes_are_unit_and_where_the_projection_puts_them() {
    // Camera at the origin looking down -z, so the planes are in view space and known in closed
    // form. For every convention the planes must be the same, with Near and Far labelled by
    // distance (not by depth value): the reversed-Z swap happens inside the extraction.
    let tx = (FOV / 2.0).tan() * ASPECT; // tan of the horizontal half angle
    let ty = (FOV / 2.0).tan();
    let (sx, cx) = (tx / (1.0 + tx * tx).sqrt(), 1.0 / (1.0 + tx * tx).sqrt());
    let (sy, cy) = (ty / (1.0 + ty * ty).sqrt(), 1.0 / (1.0 + ty * ty).sqrt());
    for (kind, conv) in configs() {
        let cam = Camera::new(DMat4::IDENTITY, projection(kind), conv).unwrap();
        let f = Frustum::from_camera(&cam).unwrap();
        for p in f.planes() {
            assert!((p.normal.length() - 1.0).abs() < 1e-14, "normal not unit");
        }
        // (plane, expected inward unit normal, expected d), each derived in its comment.
        let want: Vec<(PlaneId, DVec3, f64)> = match kind {
            Kind::Ortho => vec![
                (PlaneId::Left, DVec3::X, 10.0),         // x ≥ -10
                (PlaneId::Right, -DVec3::X, 10.0),       // x ≤ 10
                (PlaneId::Bottom, DVec3::Y, 5.0),        // y ≥ -5
                (PlaneId::Top, -DVec3::Y, 5.0),          // y ≤ 5
                (PlaneId::Near, -DVec3::Z, -ORTHO_NEAR), // -z ≥ 0.5
                (PlaneId::Far, DVec3::Z, FAR),           // -z ≤ 100
            ],
            _ => {
                // Left: x ≥ -d·tx = z·tx ⇔ x - tx·z ≥ 0 ⇔ normal (1, 0, -tx)/√(1 + tx²) =
                // (cx, 0, -sx), d = 0 (through the eye); the others by symmetry. Near: -z ≥ 0.1.
                // Far: -z ≤ 100.
                let mut v = vec![
                    (PlaneId::Left, DVec3::new(cx, 0.0, -sx), 0.0),
                    (PlaneId::Right, DVec3::new(-cx, 0.0, -sx), 0.0),
                    (PlaneId::Bottom, DVec3::new(0.0, cy, -sy), 0.0),
                    (PlaneId::Top, DVec3::new(0.0, -cy, -sy), 0.0),
                    (PlaneId::Near, -DVec3::Z, -NEAR),
                ];
                if kind == Kind::Finite {
                    v.push((PlaneId::Far, DVec3::Z, FAR));
                }
                v
            }
        };
        for (id, n, d) in want {
            let p = f
                .plane(id)
                .unwrap_or_else(|| panic!("{id:?} missing, {kind:?} {conv:?}"));
            assert!(
                (p.normal - n).length() < 1e-12 && (p.d - d).abs() < 1e-9,
                "{id:?} of {kind:?} {conv:?} is {p:?}, want normal {n}, d {d}"
            );
        }
        assert_eq!(
            f.has_far_plane(),
            kind != Kind::Infinite,
            "{kind:?} {conv:?}"
        );
        assert_eq!(f.planes().len(), if kind == Kind::Infinite { 5 } else { 6 });
        if kind == Kind::Infinite {
            assert_eq!(f.plane(PlaneId::Far), None);
        }
    }
}

#[test]
fn outside_near_a_corner_is_reported_intersecting() {
    // The documented false positive: a 45°-rotated flat box just past the top-left edge of a
    // perspective frustum at d = 10. Its centre is 0.55 m beyond both the left and the top plane
    // (in x and y), its half diagonal towards the corner is 0.6 m < 0.55·√2 = 0.78 m, so no point
    // of it is inside; but its extent along each plane normal (≈ 0.6·√2 = 0.85 m) exceeds the
    // 0.55 m, so no single plane separates it. Expected: Intersecting. The sampling below proves
    // that the box really is outside.
    let conv = DepthConvention::ZERO_TO_ONE;
    let cam = Camera::new(DMat4::IDENTITY, projection(Kind::Finite), conv).unwrap();
    let f = Frustum::from_camera(&cam).unwrap();
    let (hw, hh) = half_size(Kind::Finite, 10.0);
    let b = Obb::from_rotation(
        DVec3::new(-hw - 0.55, hh + 0.55, -10.0),
        DQuat::from_rotation_z(PI / 4.0),
        DVec3::new(0.6, 0.6, 0.01),
    )
    .unwrap();
    let vp = cam.view_projection_f64();
    for i in 0..=40 {
        for j in 0..=40 {
            for k in 0..=4 {
                let t = DVec3::new(
                    i as f64 / 20.0 - 1.0,
                    j as f64 / 20.0 - 1.0,
                    k as f64 / 2.0 - 1.0,
                );
                assert!(
                    !clip_inside(vp, conv, b.point(t), 0.0),
                    "box is not outside at {t}"
                );
            }
        }
    }
    assert_eq!(f.test_obb(&b), Containment::Intersecting);
}

#[test]
fn random_obbs_are_never_wrongly_outside_and_inside_is_exact() {
    // For random OBBs around each frustum, sample a 9×9×9 grid of points in the box (corners,
    // edges and faces included) and check them against the clip volume with the matrix itself.
    // Any sample inside ⇒ the box intersects the frustum ⇒ the test must not say Outside.
    // Inside ⇒ every sample must be inside (1e-9 relative slack for rounding).
    let mut rng = Pcg32::new(2024, 7);
    for (kind, conv) in configs() {
        let cam = camera(kind, conv);
        let f = Frustum::from_camera(&cam).unwrap();
        let vp = cam.view_projection_f64();
        let to_world = cam.view_f64().inverse();
        let d_max = if kind == Kind::Infinite { 150.0 } else { FAR };
        let mut counts = [0usize; 3];
        for _ in 0..1500 {
            let d = rng.uniform_f64(-5.0, d_max * 1.1).unwrap();
            let (hw, hh) = half_size(kind, d.max(NEAR));
            let centre_view = DVec3::new(
                hw * rng.uniform_f64(-1.5, 1.5).unwrap(),
                hh * rng.uniform_f64(-1.5, 1.5).unwrap(),
                -d,
            );
            let (a, b) = rng.normal_pair();
            let (c, e) = rng.normal_pair();
            let rot = DQuat::from_xyzw(a, b, c, e).normalize();
            let half = DVec3::new(
                rng.uniform_f64(0.02, 4.0).unwrap(),
                rng.uniform_f64(0.02, 4.0).unwrap(),
                rng.uniform_f64(0.02, 4.0).unwrap(),
            );
            let axes = [DVec3::X, DVec3::Y, DVec3::Z].map(|v| to_world.transform_vector3(rot * v));
            let obb = Obb::new(to_world.transform_point3(centre_view), axes, half).unwrap();
            let result = f.test_obb(&obb);
            let mut any_inside = false;
            let mut all_inside = true;
            for i in 0..9 {
                for j in 0..9 {
                    for k in 0..9 {
                        let t = DVec3::new(i as f64, j as f64, k as f64) / 4.0 - 1.0;
                        let p = obb.point(t);
                        any_inside |= clip_inside(vp, conv, p, 0.0);
                        all_inside &= clip_inside(vp, conv, p, 1e-9);
                    }
                }
            }
            if any_inside {
                assert_ne!(result, Containment::Outside, "{obb:?} {kind:?} {conv:?}");
            }
            if result == Containment::Inside {
                assert!(all_inside, "{obb:?} said Inside, {kind:?} {conv:?}");
            }
            counts[result as usize] += 1;
        }
        // The distribution must exercise all three answers (else the test proves little): at
        // least 5% of 1500 each.
        assert!(
            counts.iter().all(|&n| n >= 75),
            "{kind:?} {conv:?}: {counts:?}"
        );
    }
}

#[test]
fn f32_matrices_and_rounding_to_infinity() {
    // The f32 path gives the same planes up to f32 rounding of the matrix. Side and near planes:
    // within 1e-6 (a few f32 ulps). The far plane is row3 - row2, two rows of size ~1 whose
    // difference has size n/(f - n) ≈ 1e-3: the f32 rounding (6e-8) is amplified ~1000×, so
    // within 1e-4 (the documented cost of extracting planes from an f32 matrix).
    let conv = DepthConvention::ZERO_TO_ONE;
    let cam = camera(Kind::Finite, conv);
    let f64f = Frustum::from_camera(&cam).unwrap();
    let f32f = Frustum::from_view_projection_f32(cam.view_projection().unwrap(), conv).unwrap();
    for (id, (a, b)) in PlaneId::ALL
        .iter()
        .zip(f64f.planes().iter().zip(f32f.planes()))
    {
        let tol = if *id == PlaneId::Far { 1e-4 } else { 1e-6 };
        let dn = (a.normal - b.normal).length();
        let dd = (a.d - b.d).abs() / a.d.abs().max(1.0);
        assert!(
            dn < tol && dd < 10.0 * tol,
            "{id:?}: normal off by {dn}, d by {dd}"
        );
    }
    // far/near = 1e9: in f32 the depth row rounds to that of an infinite projection (-f/(f-n)
    // rounds to -1), so the far plane is degenerate and dropped, as documented; in f64 it stays.
    let deep = Projection::Perspective {
        fov_y: 1.0,
        aspect: 1.0,
        near: 0.1,
        far: Far::Finite(1e8),
    };
    let m32: Mat4 = deep.matrix(conv).unwrap();
    assert_eq!(m32.z_axis.z, -1.0);
    assert!(
        !Frustum::from_view_projection_f32(m32, conv)
            .unwrap()
            .has_far_plane()
    );
    assert!(
        Frustum::from_view_projection(deep.matrix_f64(conv).unwrap(), conv)
            .unwrap()
            .has_far_plane()
    );
}

#[test]
fn bad_inputs_are_errors() {
    let conv = DepthConvention::ZERO_TO_ONE;
    assert_eq!(
        Frustum::from_view_projection(DMat4::ZERO, conv),
        Err(FrustumError::Degenerate(PlaneId::Left))
    );
    let mut nan = DMat4::IDENTITY;
    nan.x_axis.x = f64::NAN;
    assert!(matches!(
        Frustum::from_view_projection(nan, conv),
        Err(FrustumError::NotFinite(_))
    ));
    // Rows 0, 1 = x, y; row 2 = (0, 0, 0, 2); row 3 = (0, 0, 0, 1). The forward [0,1] near plane
    // is row 2 alone, which has no normal: only a far plane may degenerate, so Degenerate(Near).
    let bad_near = DMat4::from_cols_array(&[
        1.0, 0.0, 0.0, 0.0, //
        0.0, 1.0, 0.0, 0.0, //
        0.0, 0.0, 0.0, 0.0, //
        0.0, 0.0, 2.0, 1.0,
    ]);
    assert_eq!(
        Frustum::from_view_projection(bad_near, conv),
        Err(FrustumError::Degenerate(PlaneId::Near))
    );
    // Row 2 = (0, 0, 0, -1), row 3 = (0, 0, -1, 0), reversed [0,1]: the far plane is row 2 alone,
    // a plane with no normal and d < 0 that nothing satisfies (not an infinite far plane).
    let bad_far = DMat4::from_cols_array(&[
        1.0, 0.0, 0.0, 0.0, //
        0.0, 1.0, 0.0, 0.0, //
        0.0, 0.0, 0.0, -1.0, //
        0.0, 0.0, -1.0, 0.0,
    ]);
    assert_eq!(
        Frustum::from_view_projection(bad_far, DepthConvention::ZERO_TO_ONE_REVERSED),
        Err(FrustumError::Degenerate(PlaneId::Far))
    );
    let f = Frustum::from_camera(&camera(Kind::Finite, conv)).unwrap();
    assert!(matches!(
        f.test_point(DVec3::new(0.0, f64::NAN, 0.0)),
        Err(FrustumError::NotFinite(_))
    ));

    assert_eq!(
        Sphere::new(DVec3::ZERO, -1.0),
        Err(FrustumError::Negative {
            name: "radius",
            value: -1.0
        })
    );
    assert!(matches!(
        Sphere::new(DVec3::ZERO, f64::NAN),
        Err(FrustumError::NotFinite(_))
    ));
    assert_eq!(
        Aabb::new(DVec3::ZERO, DVec3::new(1.0, -0.5, 1.0)),
        Err(FrustumError::Negative {
            name: "half_extents",
            value: -0.5
        })
    );
    assert_eq!(
        Aabb::from_min_max(DVec3::ONE, DVec3::ZERO),
        Err(FrustumError::MinAboveMax)
    );
    let b = Aabb::from_min_max(DVec3::new(-1.0, 0.0, 2.0), DVec3::new(3.0, 1.0, 2.0)).unwrap();
    assert_eq!(b.centre(), DVec3::new(1.0, 0.5, 2.0));
    assert_eq!(b.half_extents(), DVec3::new(2.0, 0.5, 0.0));
    assert_eq!(
        Obb::new(DVec3::ZERO, [DVec3::X, DVec3::X, DVec3::Z], DVec3::ONE),
        Err(FrustumError::AxesNotOrthonormal)
    );
    assert_eq!(
        Obb::new(
            DVec3::ZERO,
            [DVec3::X * 2.0, DVec3::Y, DVec3::Z],
            DVec3::ONE
        ),
        Err(FrustumError::AxesNotOrthonormal)
    );
    assert_eq!(
        Obb::from_rotation(
            DVec3::ZERO,
            DQuat::from_xyzw(0.0, 0.0, 0.0, 0.0),
            DVec3::ONE
        ),
        Err(FrustumError::ZeroRotation)
    );
}
