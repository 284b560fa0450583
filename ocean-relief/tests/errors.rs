//! Bad input: clear errors, never a panic.

use glam::{DVec3, Vec2, Vec3};
use ocean_core::{DepthConvention, Far, Projection};
use ocean_relief::check::{Channels, CheckParams, check};
use ocean_relief::occlusion::{occlusion_depth, view_distance};
use ocean_relief::relief::normals;
use ocean_relief::shadow::in_shadow;
use ocean_relief::trace::{BinarySearch, MAX_STEPS};
use ocean_relief::{
    ConeKind, ConeMap, ConeParams, Edge, HeightMap, HeightRange, MAX_BRUTE_SIDE, MAX_SIDE, Method,
    Ray, ReliefError, ReliefTexture, book, truth,
};

fn flat(n: usize) -> HeightMap {
    HeightMap::from_heights(n, n, &vec![0.5; n * n], Edge::Wrap, HeightRange::Refuse).unwrap()
}

/// Sides must be 2 ..= MAX_SIDE and equal; buffers must hold one value per texel.
#[test]
fn sizes() {
    for (w, h) in [
        (0, 0),
        (1, 1),
        (0, 8),
        (MAX_SIDE + 1, MAX_SIDE + 1),
        (usize::MAX, 4),
    ] {
        let e = HeightMap::from_heights(w, h, &[], Edge::Wrap, HeightRange::Refuse).unwrap_err();
        assert!(
            matches!(e, ReliefError::MapSize { width, height, min: 2, max: MAX_SIDE } if width == w && height == h),
            "{e:?}"
        );
    }
    assert_eq!(
        HeightMap::from_u8(8, 4, &[0; 32], Edge::Clamp).unwrap_err(),
        ReliefError::NotSquare {
            width: 8,
            height: 4
        }
    );
    assert_eq!(
        HeightMap::from_u16(4, 4, &[0; 15], Edge::Clamp).unwrap_err(),
        ReliefError::BufferSize {
            name: "heights",
            expected: 16,
            got: 15
        }
    );
    assert_eq!(
        HeightMap::from_depths(2, 2, &[0.0; 5], Edge::Clamp, HeightRange::Refuse).unwrap_err(),
        ReliefError::BufferSize {
            name: "depths",
            expected: 4,
            got: 5
        }
    );
}

/// NaN and infinite heights are refused with their position; heights outside [0, 1] are refused,
/// or normalised on request (min → 0, max → 1; a constant map → height 1).
#[test]
fn heights() {
    let mut h = vec![0.5f32; 16];
    h[6] = f32::NAN;
    assert_eq!(
        HeightMap::from_heights(4, 4, &h, Edge::Wrap, HeightRange::Normalize).unwrap_err(),
        ReliefError::HeightNotFinite { x: 2, y: 1 }
    );
    h[6] = f32::INFINITY;
    assert_eq!(
        HeightMap::from_heights(4, 4, &h, Edge::Wrap, HeightRange::Refuse).unwrap_err(),
        ReliefError::HeightNotFinite { x: 2, y: 1 }
    );
    h[6] = 1.5;
    assert_eq!(
        HeightMap::from_heights(4, 4, &h, Edge::Wrap, HeightRange::Refuse).unwrap_err(),
        ReliefError::HeightOutOfRange {
            x: 2,
            y: 1,
            value: 1.5
        }
    );
    h[3] = -2.0;
    let m = HeightMap::from_heights(4, 4, &h, Edge::Wrap, HeightRange::Normalize).unwrap();
    // Heights −2 .. 1.5: depth = (1.5 − h)/3.5.
    assert_eq!(m.depths()[3], 1.0);
    assert_eq!(m.depths()[6], 0.0);
    assert_eq!(m.depths()[0], ((1.5f64 - 0.5) / 3.5) as f32);
    let c = HeightMap::from_heights(2, 2, &[7.0; 4], Edge::Wrap, HeightRange::Normalize).unwrap();
    assert!(c.depths().iter().all(|&d| d == 0.0));
    // 8- and 16-bit inputs: depth = (max − v)/max.
    let m = HeightMap::from_u8(2, 2, &[0, 255, 51, 204], Edge::Wrap).unwrap();
    assert_eq!(m.depths(), &[1.0, 0.0, 204.0 / 255.0, 51.0 / 255.0]);
    let m = HeightMap::from_u16(2, 2, &[0, 65535, 0, 0], Edge::Wrap).unwrap();
    assert_eq!(&m.depths()[..2], &[1.0, 0.0]);
}

/// Cone parameters, the oracles' size caps, and cone maps built from raw values; generators of
/// test maps accept a side of 0.
#[test]
fn cones() {
    for h in [
        ocean_relief::maps::boxes(0, 5, 1),
        ocean_relief::maps::bumps(0, 5, 2.0, 1),
        ocean_relief::maps::value_noise(0, 4, 2, 1),
        ocean_relief::maps::white_noise(0, 1),
        ocean_relief::maps::pins(0, 4, 1),
        ocean_relief::maps::thin_walls(0, 4),
    ] {
        assert!(h.is_empty());
    }
    let map = flat(8);
    for r in [0.0, -1.0, 65.0, f32::NAN, f32::INFINITY] {
        let e = ConeMap::generate(&map, ConeParams::relaxed(r)).unwrap_err();
        assert!(
            matches!(
                e,
                ReliefError::OutOfRange {
                    name: "max_ratio",
                    ..
                } | ReliefError::NotFinite("max_ratio")
            ),
            "{r}: {e:?}"
        );
    }
    let big = flat(MAX_BRUTE_SIDE + 1);
    assert!(matches!(
        ConeMap::brute_force(&big, ConeParams::default()).unwrap_err(),
        ReliefError::MapSize { .. }
    ));
    let big = flat(book::MAX_BOOK_SIDE + 1);
    assert!(matches!(
        book::listing_18_2(&big, 128).unwrap_err(),
        ReliefError::MapSize { .. }
    ));
    assert!(matches!(
        book::listing_18_2(&map, 1).unwrap_err(),
        ReliefError::OutOfRange {
            name: "search_steps",
            ..
        }
    ));
    assert!(matches!(
        ConeMap::from_ratios(2, Edge::Wrap, vec![0.5, -0.1, 0.2, 0.3]).unwrap_err(),
        ReliefError::OutOfRange { .. }
    ));
    assert!(matches!(
        ConeMap::from_ratios(2, Edge::Wrap, vec![0.5, f32::NAN, 0.2, 0.3]).unwrap_err(),
        ReliefError::NotFinite(_)
    ));
    assert!(matches!(
        ConeMap::from_ratios(2, Edge::Wrap, vec![0.5; 3]).unwrap_err(),
        ReliefError::BufferSize { .. }
    ));
    // A texture needs cones made for the same map.
    let other = ConeMap::from_ratios(4, Edge::Wrap, vec![0.5; 16]).unwrap();
    assert_eq!(
        ReliefTexture::new(&map, &other).unwrap_err(),
        ReliefError::Mismatch("cones")
    );
    let clamp = ConeMap::from_ratios(8, Edge::Clamp, vec![0.5; 64]).unwrap();
    assert_eq!(
        ReliefTexture::new(&map, &clamp).unwrap_err(),
        ReliefError::Mismatch("cones")
    );
    // The check: channel sizes and parameters.
    let cones = ConeMap::generate(&map, ConeParams::default()).unwrap();
    let mut ch = Channels::of(&cones);
    ch.size = 3;
    assert!(matches!(
        check(&map, ch, ConeKind::Relaxed, CheckParams::default()).unwrap_err(),
        ReliefError::BufferSize { .. }
    ));
    let bad = CheckParams {
        apexes: 0,
        ..CheckParams::default()
    };
    assert!(matches!(
        check(&map, Channels::of(&cones), ConeKind::Relaxed, bad).unwrap_err(),
        ReliefError::OutOfRange { .. }
    ));
    // The widest-cone oracle: its sampling and the local search's halvings (at most 40).
    let params = ocean_relief::widest::WidestParams::default();
    for bad in [
        ocean_relief::widest::WidestParams {
            apexes: 0,
            ..params
        },
        ocean_relief::widest::WidestParams {
            directions: 0,
            ..params
        },
        ocean_relief::widest::WidestParams {
            refine: 41,
            ..params
        },
    ] {
        assert!(
            matches!(
                ocean_relief::widest::widest(&map, ConeKind::Relaxed, 1.0, bad).unwrap_err(),
                ReliefError::OutOfRange { .. }
            ),
            "{bad:?}"
        );
    }
}

/// Rays must point into the relief and reliefs must not be negatively deep; step counts must be
/// 1 ..= MAX_STEPS (binary 0 ..= MAX_STEPS).
#[test]
fn tracers() {
    let map = flat(8);
    let tex = ReliefTexture::new(
        &map,
        &ConeMap::generate(&map, ConeParams::default()).unwrap(),
    )
    .unwrap();
    let good = Ray::from_view(Vec2::new(0.5, 0.5), Vec3::new(0.3, 0.0, -0.9), 0.1).unwrap();
    for view in [
        Vec3::new(0.3, 0.0, 0.9),
        Vec3::new(1.0, 0.0, 0.0),
        Vec3::new(f32::NAN, 0.0, -1.0),
    ] {
        assert_eq!(
            Ray::from_view(Vec2::ZERO, view, 0.1).unwrap_err(),
            ReliefError::RayDirection
        );
    }
    assert_eq!(
        Ray::from_view(
            Vec2::new(f32::INFINITY, 0.0),
            Vec3::new(0.0, 0.0, -1.0),
            0.1
        )
        .unwrap_err(),
        ReliefError::RayDirection
    );
    assert!(matches!(
        Ray::from_view(Vec2::ZERO, Vec3::new(0.0, 0.0, -1.0), -0.1).unwrap_err(),
        ReliefError::OutOfRange { name: "depth", .. }
    ));
    let bad_rays = [
        Ray {
            start: Vec2::ZERO,
            dir: Vec3::new(0.0, 0.0, 0.0),
        },
        Ray {
            start: Vec2::ZERO,
            dir: Vec3::new(1.0, 0.0, -1.0),
        },
        Ray {
            start: Vec2::new(f32::NAN, 0.0),
            dir: Vec3::Z,
        },
    ];
    let methods = [
        Method::Linear {
            linear: 8,
            binary: 4,
        },
        Method::ConeStep { steps: 8 },
        Method::Relaxed {
            cone: 8,
            binary: 4,
            search: BinarySearch::Shared,
        },
    ];
    // A run per unit depth that overflows a float has its own error.
    let too_flat = Ray {
        start: Vec2::ZERO,
        dir: Vec3::new(f32::MAX, 0.0, 1e-30),
    };
    for m in &methods {
        assert_eq!(
            m.trace(&tex, &too_flat).unwrap_err(),
            ReliefError::RayTooFlat
        );
    }
    for ray in &bad_rays {
        for m in &methods {
            assert_eq!(
                m.trace(&tex, ray).unwrap_err(),
                ReliefError::RayDirection,
                "{ray:?} {m:?}"
            );
        }
        assert_eq!(
            truth::first_hit(&map, ray).unwrap_err(),
            ReliefError::RayDirection
        );
    }
    for m in [
        Method::Linear {
            linear: 0,
            binary: 4,
        },
        Method::ConeStep {
            steps: MAX_STEPS + 1,
        },
        Method::Relaxed {
            cone: 4,
            binary: MAX_STEPS + 1,
            search: BinarySearch::LastStep,
        },
    ] {
        assert!(
            matches!(
                m.trace(&tex, &good).unwrap_err(),
                ReliefError::OutOfRange { .. }
            ),
            "{m:?}"
        );
    }
    // Far away texture coordinates are fine (the texture tiles or clamps).
    let far = Ray {
        start: Vec2::new(-1.0e6, 3.0e7),
        dir: Vec3::new(0.5, 0.1, 1.0),
    };
    for m in &methods {
        assert!(m.trace(&tex, &far).unwrap().pos.is_finite());
    }
    assert!(matches!(
        truth::march(&map, &good, 0).unwrap_err(),
        ReliefError::OutOfRange { .. }
    ));
}

/// Shadows, occlusion and normals check their inputs.
#[test]
fn shading() {
    let map = flat(8);
    let tex = ReliefTexture::new(
        &map,
        &ConeMap::generate(&map, ConeParams::default()).unwrap(),
    )
    .unwrap();
    let m = Method::Relaxed {
        cone: 8,
        binary: 4,
        search: BinarySearch::Shared,
    };
    let p = Vec3::new(0.5, 0.5, 0.5);
    assert_eq!(
        in_shadow(&tex, &m, Vec3::NAN, Vec3::Z, 0.1, 0.0).unwrap_err(),
        ReliefError::RayDirection
    );
    assert!(matches!(
        in_shadow(&tex, &m, p, Vec3::Z, 0.1, -1.0).unwrap_err(),
        ReliefError::OutOfRange { .. }
    ));
    assert_eq!(
        view_distance(0.5, Vec3::new(0.0, 0.0, 1.0), 1.0).unwrap_err(),
        ReliefError::RayDirection
    );
    let proj = Projection::Perspective {
        fov_y: 1.0,
        aspect: 1.0,
        near: 0.1,
        far: Far::Finite(100.0),
    };
    assert_eq!(
        occlusion_depth(
            &proj,
            DepthConvention::ZERO_TO_ONE,
            DVec3::ZERO,
            DVec3::ZERO,
            1.0
        )
        .unwrap_err(),
        ReliefError::RayDirection
    );
    // A hit on the camera plane: the projection's own error.
    let e = occlusion_depth(
        &proj,
        DepthConvention::ZERO_TO_ONE,
        DVec3::new(0.0, 0.0, -1.0),
        DVec3::Z,
        1.0,
    )
    .unwrap_err();
    assert!(matches!(e, ReliefError::Camera(_)), "{e:?}");
    assert!(matches!(
        normals(&map, f32::NAN).unwrap_err(),
        ReliefError::NotFinite("depth")
    ));
}

/// Rays whose arithmetic would leave a float: refused with a reason, never a non-finite hit
/// behind success. A light just above the plane shadows every point, as one on the plane does.
#[test]
fn rays_and_lights_at_the_edges_of_a_float() {
    use ocean_relief::MAX_TEXCOORD;
    let map = flat(8);
    let tex = ReliefTexture::new(
        &map,
        &ConeMap::generate(&map, ConeParams::default()).unwrap(),
    )
    .unwrap();
    let method = Method::ConeStep { steps: 16 };
    // Start at FLT_MAX: once gave an infinite hit.
    let far = Ray {
        start: Vec2::new(f32::MAX, 0.5),
        dir: Vec3::new(0.3, 0.1, 1.0),
    };
    let e = method.trace(&tex, &far).unwrap_err();
    assert!(matches!(e, ReliefError::OutOfRange { .. }), "{e}");
    // Within the limit the hit is finite.
    let near = Ray {
        start: Vec2::new((MAX_TEXCOORD * 0.5) as f32, 0.5),
        dir: Vec3::new(0.3, 0.1, 1.0),
    };
    let hit = method.trace(&tex, &near).unwrap();
    assert!(hit.pos.is_finite(), "{hit:?}");
    // A direction whose run per unit depth overflows: its own error, not "not positive".
    let flat_ray = Ray {
        start: Vec2::new(0.5, 0.5),
        dir: Vec3::new(1.0, 0.0, f32::from_bits(1)),
    };
    assert_eq!(
        method.trace(&tex, &flat_ray).unwrap_err(),
        ReliefError::RayTooFlat
    );
    // light_z = FLT_TRUE_MIN: in shadow, like light_z = 0 (it was refused as invalid).
    let point = Vec3::new(0.5, 0.5, 0.5);
    for z in [f32::from_bits(1), 0.0] {
        let light = Vec3::new(1.0, 0.0, z);
        assert!(
            in_shadow(&tex, &method, point, light, 0.1, 0.01).unwrap(),
            "{z}"
        );
    }
}
