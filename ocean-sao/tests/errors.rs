//! Bad input: clear errors, never a panic or an out-of-bounds read.

mod common;

use common::{Render, perspective};
use ocean_core::{CameraError, DepthConvention, Far, Projection};
use ocean_sao::analytic::{AnalyticView, DepthFormat};
use ocean_sao::reference::ReferenceParams;
use ocean_sao::{
    BlurParams, DepthSource, Estimator, MAX_SIDE, MipFilter, NormalRejection, Sao, SaoError,
    SaoParams, Viewport, ZConstants, ZHierarchy,
};

fn sao(w: usize, h: usize, guard: usize) -> Sao {
    Sao::new(
        &perspective(w, h, Far::Infinite),
        DepthConvention::ZERO_TO_ONE,
        DepthSource::Window,
        Viewport::new(w, h, guard).unwrap(),
        SaoParams::default(),
    )
    .unwrap()
}

/// Sides must be in 2 ..= MAX_SIDE, and the guard band must leave an output; a huge guard
/// band does not overflow.
#[test]
fn sizes() {
    for (w, h) in [(0, 10), (10, 0), (1, 10), (MAX_SIDE + 1, 10)] {
        assert_eq!(
            Viewport::new(w, h, 0),
            Err(SaoError::ImageSize {
                width: w,
                height: h
            })
        );
    }
    assert!(Viewport::new(MAX_SIDE, 2, 0).is_ok());
    for g in [5, 6, usize::MAX] {
        assert_eq!(
            Viewport::new(10, 12, g),
            Err(SaoError::GuardBand {
                guard: g,
                width: 10,
                height: 12
            })
        );
    }
    assert!(Viewport::new(10, 12, 4).is_ok());
}

/// Buffers of the wrong size are refused before anything is written.
#[test]
fn buffer_sizes() {
    let s = sao(32, 24, 4);
    let mut ao = vec![7.0f32; 24 * 16];
    assert_eq!(
        s.run(&[0.5; 10], &mut ao),
        Err(SaoError::BufferSize {
            name: "depth",
            expected: 32 * 24,
            got: 10
        })
    );
    assert!(ao.iter().all(|&a| a == 7.0));
    let mut short = vec![0.0f32; 3];
    assert_eq!(
        s.run(&[0.5; 32 * 24], &mut short),
        Err(SaoError::BufferSize {
            name: "ao",
            expected: 24 * 16,
            got: 3
        })
    );
    assert_eq!(
        ZHierarchy::build(vec![-1.0; 5], 2, 2, MipFilter::RotatedGrid, 3),
        Err(SaoError::BufferSize {
            name: "z level 0",
            expected: 4,
            got: 5
        })
    );
}

/// NaN and infinite depth, and depth outside the convention's range, are reported with the
/// first offending pixel (row-major); the output is left untouched.
#[test]
fn bad_depth_values() {
    let s = sao(32, 24, 4);
    let mut ao = vec![7.0f32; 24 * 16];
    for (bad, at) in [
        (f32::NAN, 40),
        (f32::INFINITY, 41),
        (f32::NEG_INFINITY, 100),
    ] {
        let mut depth = vec![0.5f32; 32 * 24];
        depth[at] = bad;
        depth[at + 200] = 1.5;
        assert_eq!(
            s.run(&depth, &mut ao),
            Err(SaoError::DepthNotFinite {
                x: at % 32,
                y: at / 32
            })
        );
    }
    let mut depth = vec![0.5f32; 32 * 24];
    depth[77] = 1.0000001;
    assert!(matches!(
        s.run(&depth, &mut ao),
        Err(SaoError::DepthOutOfRange {
            x: 13,
            y: 2,
            min: 0.0,
            max: 1.0,
            ..
        })
    ));
    depth[77] = -0.25;
    assert!(matches!(
        s.run(&depth, &mut ao),
        Err(SaoError::DepthOutOfRange { x: 13, y: 2, .. })
    ));
    assert!(ao.iter().all(|&a| a == 7.0));
    // OpenGL NDC depth accepts [-1, 1]; its window depth only [0, 1].
    let gl = |source| {
        ZConstants::new(
            &perspective(4, 4, Far::Finite(50.0)),
            DepthConvention::NEG_ONE_TO_ONE,
            source,
        )
        .unwrap()
        .depth_range()
    };
    assert_eq!(gl(DepthSource::Ndc), (-1.0, 1.0));
    assert_eq!(gl(DepthSource::Window), (0.0, 1.0));
}

/// Invalid and degenerate projections: ocean-core's checks, and `f32` collapse (a near plane of
/// 10⁻³⁰⁰ m is valid in `f64` but rounds Eq. 2's c₀ to 0).
#[test]
fn bad_projections() {
    let vp = Viewport::new(16, 16, 0).unwrap();
    let make = |p: Projection| {
        Sao::new(
            &p,
            DepthConvention::ZERO_TO_ONE,
            DepthSource::Window,
            vp,
            SaoParams::default(),
        )
    };
    let fov = Projection::Perspective {
        fov_y: 0.0,
        aspect: 1.0,
        near: 0.1,
        far: Far::Infinite,
    };
    assert_eq!(
        make(fov).err(),
        Some(SaoError::Camera(CameraError::FieldOfView(0.0)))
    );
    let nan = Projection::Perspective {
        fov_y: 1.0,
        aspect: f64::NAN,
        near: 0.1,
        far: Far::Infinite,
    };
    assert!(matches!(
        make(nan),
        Err(SaoError::Camera(CameraError::NotFinite { .. }))
    ));
    let box_ = Projection::Orthographic {
        left: 1.0,
        right: 1.0,
        bottom: 0.0,
        top: 1.0,
        near: 0.0,
        far: 1.0,
    };
    assert!(matches!(
        make(box_),
        Err(SaoError::Camera(CameraError::OrthoWidth { .. }))
    ));
    let tiny = Projection::Perspective {
        fov_y: 1.0,
        aspect: 1.0,
        near: 1e-300,
        far: Far::Infinite,
    };
    assert!(matches!(make(tiny), Err(SaoError::DegenerateProjection(_))));
    let thin = Projection::Perspective {
        fov_y: 1.0,
        aspect: 1.0,
        near: 1.0,
        far: Far::Finite(1.0 + 1e-12),
    };
    assert!(matches!(make(thin), Err(SaoError::DegenerateProjection(_))));
    let huge = Projection::Perspective {
        fov_y: 1e-300,
        aspect: 1.0,
        near: 0.1,
        far: Far::Infinite,
    };
    assert!(matches!(
        make(huge),
        Err(SaoError::Camera(_)) | Err(SaoError::DegenerateProjection(_))
    ));
}

/// Every parameter outside its documented range is refused with its name.
#[test]
fn bad_parameters() {
    let d = SaoParams::default();
    let vp = Viewport::new(16, 16, 0).unwrap();
    let make = |p: SaoParams| {
        Sao::new(
            &perspective(16, 16, Far::Infinite),
            DepthConvention::ZERO_TO_ONE,
            DepthSource::Window,
            vp,
            p,
        )
        .err()
    };
    let name = |e: Option<SaoError>| match e {
        Some(SaoError::OutOfRange { name, .. }) | Some(SaoError::NotFinite(name)) => name,
        other => panic!("{other:?}"),
    };
    assert_eq!(name(make(SaoParams { radius: 0.0, ..d })), "radius");
    assert_eq!(
        name(make(SaoParams {
            radius: f32::NAN,
            ..d
        })),
        "radius"
    );
    assert_eq!(name(make(SaoParams { radius: 1e5, ..d })), "radius");
    assert_eq!(name(make(SaoParams { samples: 0, ..d })), "samples");
    assert_eq!(name(make(SaoParams { samples: 65, ..d })), "samples");
    assert_eq!(
        name(make(SaoParams {
            spiral_turns: -1.0,
            ..d
        })),
        "spiral_turns"
    );
    assert_eq!(
        name(make(SaoParams {
            mip_switch_log2: 9,
            ..d
        })),
        "mip_switch_log2"
    );
    assert_eq!(name(make(SaoParams { max_mip: 14, ..d })), "max_mip");
    assert_eq!(name(make(SaoParams { epsilon: 0.0, ..d })), "epsilon");
    assert_eq!(name(make(SaoParams { z_min: 5.0, ..d })), "z_min");
    assert_eq!(
        name(make(SaoParams {
            quad_depth_threshold: Some(-1.0),
            ..d
        })),
        "quad_depth_threshold"
    );
    let rejection = Some(NormalRejection {
        max_incidence: std::f32::consts::FRAC_PI_2,
    });
    assert_eq!(
        name(make(SaoParams {
            normal_rejection: rejection,
            ..d
        })),
        "normal_rejection.max_incidence"
    );
    let eq1 = |sigma, beta, k| SaoParams {
        estimator: Estimator::Alchemy { sigma, beta, k },
        ..d
    };
    assert_eq!(name(make(eq1(-1.0, 0.0, 1.0))), "sigma");
    assert_eq!(name(make(eq1(1.0, 2.0, 1.0))), "beta");
    assert_eq!(name(make(eq1(1.0, 0.0, 0.0))), "k");
    let falloff = SaoParams {
        estimator: Estimator::Falloff {
            beta: 0.01,
            intensity: f32::INFINITY,
        },
        ..d
    };
    assert_eq!(name(make(falloff)), "intensity");
    let blur = |b: BlurParams| SaoParams { blur: b, ..d };
    assert_eq!(
        make(blur(BlurParams { taps: 8, ..d.blur })),
        Some(SaoError::EvenTaps(8))
    );
    assert_eq!(
        name(make(blur(BlurParams { taps: 0, ..d.blur }))),
        "blur.taps"
    );
    assert_eq!(
        name(make(blur(BlurParams { taps: 65, ..d.blur }))),
        "blur.taps"
    );
    assert_eq!(
        name(make(blur(BlurParams {
            stride: 0,
            ..d.blur
        }))),
        "blur.stride"
    );
    assert_eq!(
        name(make(blur(BlurParams {
            sigma: 0.0,
            ..d.blur
        }))),
        "blur.sigma"
    );
    assert_eq!(
        name(make(blur(BlurParams {
            depth_scale: f32::NAN,
            ..d.blur
        }))),
        "blur.depth_scale"
    );
    assert_eq!(
        ReferenceParams::from_params(
            &SaoParams {
                estimator: Estimator::ALCHEMY,
                ..d
            },
            4
        )
        .err(),
        Some(SaoError::UnsupportedFormat(
            "the references use the appendix falloff"
        ))
    );
}

/// Extreme but valid input runs to completion with A in [0, 1]: the largest radius (most
/// samples land off the image and are skipped, Eq. 5 is clamped), a 2×2 image, an all-sky and an
/// all-near-plane buffer, and depths within an ulp of an infinite far plane (z clamped to the
/// sky sentinel instead of overflowing).
#[test]
fn extreme_but_valid() {
    let r = Render::standard(AnalyticView::box_in_room(), (48, 40, 4));
    let st = r.stages(SaoParams {
        radius: 1e4,
        max_mip: 13,
        ..SaoParams::default()
    });
    assert!(st.ao.iter().all(|a| (0.0..=1.0).contains(a)));
    let small = sao(2, 2, 0);
    let mut ao = vec![0.0; 4];
    small.run(&[0.25, 0.5, 0.75, 1.0], &mut ao).unwrap();
    assert!(ao.iter().all(|a| (0.0..=1.0).contains(a)));
    let s = sao(32, 24, 4);
    let mut ao = vec![0.0; 24 * 16];
    s.run(&[1.0; 32 * 24], &mut ao).unwrap();
    assert!(ao.iter().all(|&a| a == 1.0), "sky passes through");
    s.run(&[0.0; 32 * 24], &mut ao).unwrap();
    assert!(
        ao.iter().all(|&a| a == 1.0),
        "a plane facing the camera is unoccluded"
    );
    let almost = vec![f32::from_bits(1.0f32.to_bits() - 1); 32 * 24];
    s.run(&almost, &mut ao).unwrap();
    assert!(ao.iter().all(|a| (0.0..=1.0).contains(a)));
    let reversed = Sao::new(
        &perspective(32, 24, Far::Infinite),
        DepthConvention::ZERO_TO_ONE_REVERSED,
        DepthSource::Window,
        Viewport::new(32, 24, 4).unwrap(),
        SaoParams::default(),
    )
    .unwrap();
    reversed
        .run(&vec![f32::from_bits(1); 32 * 24], &mut ao)
        .unwrap();
    assert!(ao.iter().all(|a| (0.0..=1.0).contains(a)));
}

/// The test rasteriser refuses 24-bit fixed point for OpenGL NDC depth (fixed point holds
/// window depth in [0, 1]).
#[test]
fn rasteriser_formats() {
    let view = AnalyticView::crease();
    let camera = view
        .camera(
            perspective(8, 8, Far::Infinite),
            DepthConvention::NEG_ONE_TO_ONE,
        )
        .unwrap();
    assert!(matches!(
        view.scene
            .rasterise(&camera, 8, 8, DepthSource::Ndc, DepthFormat::Unorm24),
        Err(SaoError::UnsupportedFormat(_))
    ));
    assert!(
        view.scene
            .rasterise(&camera, 8, 8, DepthSource::Window, DepthFormat::Unorm24)
            .is_ok()
    );
    assert!(
        view.scene
            .rasterise(&camera, 1, 8, DepthSource::Window, DepthFormat::F32)
            .is_err()
    );
}
