//! Tests of the SAO C ABI: the wrapper adds nothing to ocean-sao's arithmetic, maps every error
//! to a status with a message, and never writes an output on failure.

use core::ffi::CStr;
use core::ptr::{null, null_mut};

use ocean_core::camera::{DepthConvention, Far, Projection};
use ocean_sao::analytic::{AnalyticView, DepthFormat};
use ocean_sao::{DepthSource, Estimator, MipFilter, NormalRejection, Sao, SaoError, SaoParams};

use super::*;
use crate::boundary::enums::Poked;
use crate::camera::{OceanCamera, OceanDepthConvention, projection_from_matrix};
use crate::sao_depth::OceanSaoDepth;

/// Input 72 x 56 with an 8 px guard band: output 56 x 40.
const W: u32 = 72;
const H: u32 = 56;
const G: u32 = 8;
const OUT_LEN: usize = ((W - 2 * G) * (H - 2 * G)) as usize;
const IN_LEN: usize = (W * H) as usize;

fn last_error() -> String {
    // SAFETY: a valid NUL-terminated string until the next status call; copied at once.
    unsafe { CStr::from_ptr(crate::ocean_last_error_message()) }
        .to_string_lossy()
        .into_owned()
}

fn convention_value(c: DepthConvention) -> OceanDepthConvention {
    if c == DepthConvention::ZERO_TO_ONE {
        OceanDepthConvention::ZeroToOne
    } else if c == DepthConvention::ZERO_TO_ONE_REVERSED {
        OceanDepthConvention::ZeroToOneReversed
    } else {
        OceanDepthConvention::NegOneToOne
    }
}

fn source_value(s: DepthSource) -> u32 {
    match s {
        DepthSource::Window => OceanSaoDepth::Window as u32,
        DepthSource::Ndc => OceanSaoDepth::Ndc as u32,
    }
}

/// What `ocean_sao_create` takes of the camera, as these tests vary it: the `OceanCamera` (the
/// identity view: SAO reads only the projection) and what the depth buffer holds.
#[derive(Clone, Copy, Debug)]
struct SaoCamera {
    camera: OceanCamera,
    depth_source: u32,
}

/// The camera of projection `p`, its matrix rounded to `f32` as a renderer's would be.
fn sao_camera(p: Projection, c: DepthConvention, s: DepthSource) -> SaoCamera {
    SaoCamera {
        camera: OceanCamera {
            view: glam::DMat4::IDENTITY.to_cols_array(),
            projection: p.matrix(c).unwrap().to_cols_array().map(f64::from),
            depth_convention: convention_value(c),
            reserved: 0,
        },
        depth_source: source_value(s),
    }
}

fn perspective(far: Far) -> Projection {
    Projection::Perspective {
        fov_y: 1.0,
        aspect: f64::from(W) / f64::from(H),
        near: 0.1,
        far,
    }
}

fn orthographic() -> Projection {
    let half_w = 3.0 * f64::from(W) / f64::from(H);
    Projection::Orthographic {
        left: -half_w,
        right: half_w,
        bottom: -3.0,
        top: 3.0,
        near: 0.05,
        far: 40.0,
    }
}

fn defaults() -> OceanSaoParams {
    let mut p = OceanSaoParams::default();
    // SAFETY: writable out.
    assert_eq!(unsafe { ocean_sao_params_default(&mut p) }, OceanStatus::Ok);
    p
}

/// Every non-default choice at once: Eq. 1 with k = 2, harmonic-mean MIPs, the normal
/// rejection, no quad filter, the paper's quad normals, a 9-tap blur with stride 2 and the
/// paper's depth-keyed weight.
fn custom() -> OceanSaoParams {
    OceanSaoParams {
        radius: 0.7,
        samples: 13,
        spiral_turns: 10.0,
        max_mip: 4,
        mip_filter: OceanSaoMipFilter::HarmonicMean,
        estimator: OceanSaoEstimator::Alchemy,
        alchemy_sigma: 0.4,
        alchemy_beta: 2.0e-3,
        alchemy_k: 2.0,
        quad_filter: 0,
        normal_rejection: 1,
        normal_max_incidence: 80f32.to_radians(),
        normals: OceanSaoNormals::Quad,
        blur: OceanSaoBlurParams {
            taps: 9,
            stride: 2,
            depth_scale: 2000.0,
            sigma: 2.0,
            weight: OceanSaoBlurWeight::Depth,
            world_extent: 0.0,
        },
        ..defaults()
    }
}

fn create(camera: &SaoCamera, params: &OceanSaoParams) -> *mut OceanSao {
    let mut s = null_mut();
    // SAFETY: valid pointers.
    let status =
        unsafe { ocean_sao_create(W, H, G, &camera.camera, camera.depth_source, params, &mut s) };
    assert_eq!(status, OceanStatus::Ok, "{}", last_error());
    assert!(!s.is_null());
    s
}

fn run(s: *const OceanSao, depth: &[f32]) -> Vec<f32> {
    let mut ao = vec![-1.0f32; OUT_LEN];
    // SAFETY: live handle, buffers of the given lengths.
    let status =
        unsafe { ocean_sao_run(s, depth.as_ptr(), depth.len(), ao.as_mut_ptr(), ao.len()) };
    assert_eq!(status, OceanStatus::Ok, "{}", last_error());
    assert_eq!(last_error(), "");
    ao
}

fn bits(v: &[f32]) -> Vec<u32> {
    v.iter().map(|x| x.to_bits()).collect()
}

/// The crease (floor meeting a wall) rendered exactly by ocean-sao's rasteriser.
fn crease_depth(p: Projection, c: DepthConvention, s: DepthSource) -> Vec<f32> {
    let view = AnalyticView::crease();
    let camera = view.camera(p, c).unwrap();
    view.scene
        .rasterise(&camera, W as usize, H as usize, s, DepthFormat::F32)
        .unwrap()
        .depth
}

#[test]
fn defaults_are_the_crate_defaults() {
    let p = defaults();
    assert_eq!(params_from(&p).unwrap(), SaoParams::default());
    // The estimator not chosen holds its own defaults.
    let alchemy = OceanSaoParams {
        estimator: OceanSaoEstimator::Alchemy,
        ..p
    };
    assert_eq!(params_from(&alchemy).unwrap().estimator, Estimator::ALCHEMY);
    assert_eq!(p.quad_filter, 1);
    assert_eq!(p.normal_rejection, 0);
    let rejecting = OceanSaoParams {
        normal_rejection: 1,
        ..p
    };
    assert_eq!(
        params_from(&rejecting).unwrap().normal_rejection,
        Some(NormalRejection {
            max_incidence: 85f32.to_radians()
        })
    );
    let custom = params_from(&custom()).unwrap();
    assert_eq!(custom.mip_filter, MipFilter::HarmonicMean);
    assert_eq!(custom.quad_depth_threshold, None);
    assert_eq!(
        custom.estimator,
        Estimator::Alchemy {
            sigma: 0.4,
            beta: 2.0e-3,
            k: 2.0
        }
    );
}

/// The C ABI's AO and view z are ocean-sao's, bit for bit, for the camera read from the
/// matrix: every projection kind, convention, depth source and two parameter sets. Against the
/// parameters the matrix was built from (before its f32 rounding) the AO agrees to 1/255.
#[test]
fn run_and_view_z_match_the_crate_bit_for_bit() {
    let mut runs = 0;
    let mut bit_identical_to_nominal = 0;
    for p in [
        perspective(Far::Finite(100.0)),
        perspective(Far::Infinite),
        orthographic(),
    ] {
        for c in DepthConvention::ALL {
            for s in [DepthSource::Window, DepthSource::Ndc] {
                let depth = crease_depth(p, c, s);
                let camera = sao_camera(p, c, s);
                let read = projection_from_matrix(&camera.camera.projection, c).unwrap();
                let viewport = Viewport::new(W as usize, H as usize, G as usize).unwrap();
                for params in [defaults(), custom()] {
                    let core_params = params_from(&params).unwrap();
                    let handle = create(&camera, &params);
                    let ao = run(handle, &depth);

                    let sao = Sao::new(&read, c, s, viewport, core_params).unwrap();
                    let mut expected = vec![0.0f32; OUT_LEN];
                    sao.run(&depth, &mut expected).unwrap();
                    assert_eq!(bits(&ao), bits(&expected), "{p:?} {c:?} {s:?}");
                    assert!(ao.iter().any(|&a| a < 0.9), "{p:?} {c:?} {s:?}: no crease");

                    let mut z = vec![0.0f32; IN_LEN];
                    // SAFETY: live handle, buffers of the given lengths.
                    let status = unsafe {
                        ocean_sao_view_z(handle, depth.as_ptr(), IN_LEN, z.as_mut_ptr(), IN_LEN)
                    };
                    assert_eq!(status, OceanStatus::Ok, "{}", last_error());
                    let expected_z = sao.z_constants().z_pass(&viewport, &depth).unwrap();
                    assert_eq!(bits(&z), bits(&expected_z));

                    let nominal = Sao::new(&p, c, s, viewport, core_params).unwrap();
                    let mut from_nominal = vec![0.0f32; OUT_LEN];
                    nominal.run(&depth, &mut from_nominal).unwrap();
                    let worst = ao
                        .iter()
                        .zip(&from_nominal)
                        .map(|(a, b)| (a - b).abs())
                        .fold(0.0f32, f32::max);
                    assert!(worst <= 1.0 / 255.0, "{p:?} {c:?} {s:?}: {worst}");
                    bit_identical_to_nominal += usize::from(worst == 0.0);
                    ocean_sao_destroy(handle);
                    runs += 1;
                }
            }
        }
    }
    assert_eq!(runs, 36);
    println!("{bit_identical_to_nominal} of {runs} runs bit-identical to the nominal parameters");
}

#[test]
fn describe_reports_sizes_planes_and_constants() {
    for (p, c, ortho, far) in [
        (
            perspective(Far::Finite(100.0)),
            DepthConvention::NEG_ONE_TO_ONE,
            0,
            100.0,
        ),
        (
            perspective(Far::Infinite),
            DepthConvention::ZERO_TO_ONE_REVERSED,
            0,
            f64::INFINITY,
        ),
        (orthographic(), DepthConvention::ZERO_TO_ONE, 1, 40.0),
    ] {
        let camera = sao_camera(p, c, DepthSource::Window);
        let handle = create(&camera, &defaults());
        let mut info = OceanSaoInfo::default();
        // SAFETY: live handle, writable out.
        let status = unsafe { ocean_sao_describe(handle, &mut info) };
        assert_eq!(status, OceanStatus::Ok, "{}", last_error());
        let read = projection_from_matrix(&camera.camera.projection, c).unwrap();
        let sao = Sao::new(
            &read,
            c,
            DepthSource::Window,
            Viewport::new(W as usize, H as usize, G as usize).unwrap(),
            SaoParams::default(),
        )
        .unwrap();
        assert_eq!(
            (
                info.input_width,
                info.input_height,
                info.guard,
                info.output_width,
                info.output_height
            ),
            (W, H, G, W - 2 * G, H - 2 * G)
        );
        assert_eq!(info.orthographic, ortho);
        assert!((info.near - p.near()).abs() <= 1.0e-6 * p.near().abs());
        if far.is_finite() {
            assert!((info.far - far).abs() <= 1.0e-3 * far, "{}", info.far);
        } else {
            assert_eq!(info.far, f64::INFINITY);
        }
        let z = sao.z_constants();
        assert_eq!(info.z_constants, z.c);
        assert_eq!(
            (info.near_depth, info.far_depth),
            (z.near_depth, z.far_depth)
        );
        assert_eq!(
            info.pixels_per_metre,
            sao.projection_info().pixels_per_metre
        );
        ocean_sao_destroy(handle);
    }
    let mut info = OceanSaoInfo::default();
    // SAFETY: refused before any access.
    let status = unsafe { ocean_sao_describe(null(), &mut info) };
    assert_eq!(status, OceanStatus::NullPointer);
    assert_eq!(info, OceanSaoInfo::default());
}

#[test]
fn every_sao_error_has_a_fitting_status() {
    let cases = [
        (
            SaoError::Camera(ocean_core::camera::CameraError::NotFinite {
                name: "near",
                value: f64::NAN,
            }),
            OceanStatus::NonFinite,
        ),
        (
            SaoError::Camera(ocean_core::camera::CameraError::Near(-1.0)),
            OceanStatus::InvalidArgument,
        ),
        (
            SaoError::DegenerateProjection("Eq. 2 constants"),
            OceanStatus::InvalidArgument,
        ),
        (
            SaoError::ImageSize {
                width: 0,
                height: 5,
            },
            OceanStatus::Empty,
        ),
        (
            SaoError::ImageSize {
                width: 5,
                height: 0,
            },
            OceanStatus::Empty,
        ),
        (
            SaoError::ImageSize {
                width: 1,
                height: 5,
            },
            OceanStatus::InvalidArgument,
        ),
        (
            SaoError::GuardBand {
                guard: 3,
                width: 6,
                height: 6,
            },
            OceanStatus::InvalidArgument,
        ),
        (
            SaoError::BufferSize {
                name: "ao",
                expected: 4,
                got: 3,
            },
            OceanStatus::InvalidArgument,
        ),
        (
            SaoError::DepthNotFinite { x: 1, y: 2 },
            OceanStatus::NonFinite,
        ),
        (
            SaoError::DepthOutOfRange {
                x: 1,
                y: 2,
                value: 2.0,
                min: 0.0,
                max: 1.0,
            },
            OceanStatus::InvalidArgument,
        ),
        (SaoError::NotFinite("radius"), OceanStatus::NonFinite),
        (
            SaoError::OutOfRange {
                name: "samples",
                value: 0.0,
                min: 1.0,
                max: 64.0,
            },
            OceanStatus::InvalidArgument,
        ),
        (
            SaoError::UnsupportedFormat("x"),
            OceanStatus::InvalidArgument,
        ),
        (SaoError::EvenTaps(8), OceanStatus::InvalidArgument),
    ];
    for (e, status) in cases {
        let err = sao_error("ctx: ", e);
        assert_eq!(err.status, status, "{e:?}");
        assert_eq!(err.message, format!("ctx: {e}"));
    }
}

#[path = "sao_tests/refusals.rs"]
mod refusals;
